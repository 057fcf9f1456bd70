"""Viscosity against temperature (issue 3): ASTM D341, ISO VG grades, ASTM D2270."""
from __future__ import annotations

import re
import warnings

import numpy as np
import pandas as pd
import pint
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingheat.tables_io import load_table, table_units
from bearingheat.units import UnitError
from bearingheat.viscosity import (
    DEFAULT_VISCOSITY_INDEX,
    ViscosityRangeWarning,
    iso_vg_grades,
    iso_vg_nu40,
    iso_vg_viscosity,
    nu100_from_viscosity_index,
    oil_viscosity,
    viscosity_from_two_points,
    viscosity_index_astm_d2270,
    viscosity_model_rows,
    viscosity_range_messages,
    walther_constants,
    walther_viscosity,
)

u = pint.get_application_registry()


@pytest.mark.parametrize("nu1, t1, nu2, t2, t, expected", [
    (404.0, 40.0, 28.0, 100.0, 60.0, 132.13),
    (68.0, 40.0, 14.85, 80.0, 100.0, 8.79),
    (32.0, 40.0, 5.4, 100.0, 80.0, 8.53),
])
def test_published_checks(nu1, t1, nu2, t2, t, expected):
    assert viscosity_from_two_points(nu1, t1, nu2, t2, t) == pytest.approx(expected, abs=0.005)


def test_walther_line_passes_through_both_points_and_uses_kelvin():
    A, B = walther_constants(68.0, 40.0, 14.85, 80.0)
    assert walther_viscosity(A, B, 40.0) == pytest.approx(68.0, rel=1e-12)
    assert walther_viscosity(A, B, 80.0) == pytest.approx(14.85, rel=1e-12)
    # first principles: log10 log10(nu + 0.7) is linear in log10(T / K)
    for theta in (20.0, 60.0, 120.0):
        nu = walther_viscosity(A, B, theta)
        assert np.log10(np.log10(nu + 0.7)) == pytest.approx(A - B * np.log10(theta + 273.15), rel=1e-12)


@settings(max_examples=100, deadline=None)
@given(st.floats(10.0, 1000.0), st.floats(0.05, 0.5), st.floats(-10.0, 140.0), st.floats(0.5, 20.0))
def test_viscosity_falls_with_temperature(nu40, ratio, theta, step):
    nu100 = max(2.0, nu40 * ratio)
    if nu100 >= nu40:
        return
    hot = viscosity_from_two_points(nu40, 40.0, nu100, 100.0, theta + step)
    cold = viscosity_from_two_points(nu40, 40.0, nu100, 100.0, theta)
    assert hot < cold


def test_scalar_array_series_agree():
    theta = pd.Series([30.0, 60.0, 90.0], index=list("abc"))
    series = viscosity_from_two_points(68.0, 40.0, 8.6, 100.0, theta)
    array = viscosity_from_two_points(68.0, 40.0, 8.6, 100.0, theta.to_numpy())
    scalars = [viscosity_from_two_points(68.0, 40.0, 8.6, 100.0, t) for t in theta]
    assert series.index.equals(theta.index)
    np.testing.assert_array_equal(series.to_numpy(), array)
    np.testing.assert_allclose(array, scalars, rtol=1e-15)


# ---- ISO VG grades and the viscosity index -----------------------------------------------------

def test_iso_vg_table_reads_back():
    table = load_table("iso_vg_grades")
    assert table["grade"].tolist() == [2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000,
                                       1500, 2200, 3200]
    assert table["nu40"].tolist() == [2.2, 3.2, 4.6, 6.8, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680,
                                      1000, 1500, 2200, 3200]
    np.testing.assert_allclose(table["nu40_min"], 0.9 * table["nu40"], rtol=1e-9)
    np.testing.assert_allclose(table["nu40_max"], 1.1 * table["nu40"], rtol=1e-9)
    assert table_units("iso_vg_grades")["nu40"] == "mm^2/s"
    assert all("ISO 3448" in s for s in table["source"])


def test_astm_d2270_table_reads_back():
    table = load_table("astm_d2270_viscosity_index")
    assert len(table) == 311
    rows = table.set_index("nu100")[["L", "H"]]
    assert rows.loc[2.0].tolist() == [7.994, 6.394]
    assert rows.loc[8.8].tolist() == [118.5, 68.79]
    assert rows.loc[20.0].tolist() == [493.2, 229.5]
    assert rows.loc[70.0].tolist() == [4905.0, 1558.0]
    assert table["nu100"].is_monotonic_increasing and table["L"].is_monotonic_increasing
    assert (table["L"] > table["H"]).all()


def test_d2270_formulas_above_70_meet_the_table():
    # ASTM D2270 switches from table 1 to formulas above nu100 = 70 mm^2/s
    L70 = 0.8353 * 70 ** 2 + 14.67 * 70 - 216
    H70 = 0.1684 * 70 ** 2 + 11.85 * 70 - 97
    assert L70 == pytest.approx(4905, rel=2e-3) and H70 == pytest.approx(1558, rel=2e-3)


def test_viscosity_index_examples():
    assert round(viscosity_index_astm_d2270(73.3, 8.86)) == 92     # ASTM D2270 example (VI <= 100)
    assert round(viscosity_index_astm_d2270(22.83, 5.05)) == 156   # ASTM D2270 example (VI > 100)
    assert np.isnan(viscosity_index_astm_d2270(10.0, 1.9))


@pytest.mark.parametrize("grade", [10, 32, 68, 220, 1000])
@pytest.mark.parametrize("VI", [60.0, 95.0, 140.0])
def test_nu100_from_vi_round_trips(grade, VI):
    nu40 = iso_vg_nu40(grade)
    nu100 = nu100_from_viscosity_index(nu40, VI)
    assert viscosity_index_astm_d2270(nu40, nu100) == pytest.approx(VI, abs=1e-8)


def test_iso_vg_default_viscosity_index_and_override():
    assert DEFAULT_VISCOSITY_INDEX == 95.0
    assert iso_vg_viscosity(68, 40.0) == pytest.approx(68.0, rel=1e-12)
    nu100 = iso_vg_viscosity(68, 100.0)
    assert viscosity_index_astm_d2270(68.0, nu100) == pytest.approx(95.0, abs=1e-8)
    assert iso_vg_viscosity(68, 80.0, VI=140.0) > iso_vg_viscosity(68, 80.0)
    assert np.isnan(iso_vg_nu40(47))
    assert iso_vg_grades()[3200] == 3200.0


# ---- range warnings and the unit-aware entry point ------------------------------------------------

def test_range_messages():
    messages = viscosity_range_messages(np.array([1.5, 30.0, 900.0]), np.array([150.0, 40.0, -20.0]),
                                        np.array([np.nan, np.nan, -15.0]))
    assert messages.tolist() == [
        "nu = 1.5 mm^2/s at 150 degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)",
        "",
        "-20 degC is below the pour point -15 degC: nu = 900 mm^2/s is an extrapolation",
    ]


def test_oil_viscosity_units_and_warning():
    a = oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"), nu100=28 * u.cSt)
    b = oil_viscosity(u.Quantity(333.15, "K"), nu40=4.04e-4 * u("m^2/s"), nu100=0.28 * u.St)
    assert a.units == u("mm^2/s").units
    assert a.magnitude == pytest.approx(b.magnitude, rel=1e-9)
    with pytest.warns(ViscosityRangeWarning, match=re.escape(
            "nu = 1.402 mm^2/s at 200 degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)")):
        oil_viscosity(u.Quantity(200, "degC"), nu40=32 * u("mm^2/s"), nu100=5.4 * u("mm^2/s"))
    with pytest.warns(ViscosityRangeWarning, match=re.escape("-30 degC is below the pour point -24 degC")):
        oil_viscosity(u.Quantity(-30, "degC"), iso_vg=68, pour_point=u.Quantity(-24, "degC"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        oil_viscosity(u.Quantity(70, "degC"), iso_vg=68, viscosity_index=140)


def test_oil_viscosity_errors():
    with pytest.raises(ValueError, match=re.escape(
            "oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got nu40 only)")):
        oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"))
    with pytest.raises(ValueError, match=re.escape(
            "oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got nu40, nu100, iso_vg)")):
        oil_viscosity(u.Quantity(60, "degC"), nu40=68 * u("mm^2/s"), nu100=8 * u("mm^2/s"), iso_vg=68)
    with pytest.raises(ValueError, match=re.escape(
            "iso_vg: 70 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, "
            "220, 320, 460, 680, 1000, 1500, 2200, 3200")):
        oil_viscosity(u.Quantity(60, "degC"), iso_vg=70)
    with pytest.raises(UnitError, match=re.escape(
            "temperature: 60 delta_degree_Celsius is a temperature difference; give an absolute temperature "
            "(degC, K)")):
        oil_viscosity(u.Quantity(60, "delta_degC"), iso_vg=68)


def test_viscosity_model_rows_problems():
    frame = pd.DataFrame({"nu40": [68.0, 68.0, np.nan, 8.0, np.nan, 68.0, np.nan],
                          "nu100": [8.6, np.nan, np.nan, 9.0, np.nan, 8.6, np.nan],
                          "iso_vg": [np.nan, np.nan, 47.0, np.nan, 68.0, 68.0, np.nan],
                          "VI": [np.nan, np.nan, np.nan, np.nan, -5000.0, np.nan, 95.0]})
    A, B, problems = viscosity_model_rows(frame)
    assert not np.isnan(A[0])
    assert np.isnan(A[1:]).all()
    assert problems == [
        (1, "error", "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line (ASTM D341)"),
        (2, "error", "iso_vg: 47 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, "
                     "150, 220, 320, 460, 680, 1000, 1500, 2200, 3200"),
        (3, "error", "nu40 [mm^2/s]: 8 must be larger than nu100 = 9"),
        (4, "error", "VI: -5000 cannot be reached by ISO VG 68 with nu100 >= 2 mm^2/s (ASTM D2270)"),
        (5, "error", "iso_vg: give either iso_vg or nu40 and nu100, not both"),
        (6, "error", "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"),
    ]
