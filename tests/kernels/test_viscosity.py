"""Viscosity against temperature (issue 3): ASTM D341, ISO VG grades, ASTM D2270."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingheat.catalogue.viscosity import iso_vg_grades
from bearingheat.kernels.viscosity import (
    DEFAULT_VISCOSITY_INDEX,
    d2270_L_H,
    iso_vg_nu40,
    iso_vg_viscosity,
    nu100_from_viscosity_index,
    viscosity_from_two_points,
    viscosity_index_astm_d2270,
    viscosity_range_messages,
    walther_constants,
    walther_temperature,
    walther_viscosity,
)


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


@settings(max_examples=300, deadline=None)
@given(st.floats(10.0, 1000.0), st.floats(0.05, 0.5), st.floats(-30.0, 200.0))
def test_walther_viscosity_is_the_printed_formula_to_the_last_digits(nu40, ratio, theta):
    """ν = 10^(10^(A − B·log10 T)) − 0.7 written with Python's own powers of ten (the kernel takes them as
    powers of two)."""
    A, B = walther_constants(nu40, 40.0, max(2.0, nu40 * ratio), 100.0)
    printed = 10.0 ** (10.0 ** (A - B * np.log10(theta + 273.15))) - 0.7
    assert walther_viscosity(A, B, theta) == pytest.approx(printed, rel=1e-14)


@settings(max_examples=300, deadline=None)
@given(st.floats(10.0, 1000.0), st.floats(0.05, 0.5), st.floats(-30.0, 200.0))
def test_walther_temperature_is_the_inverse_of_walther_viscosity(nu40, ratio, theta):
    A, B = walther_constants(nu40, 40.0, max(2.0, nu40 * ratio), 100.0)
    # back to θ within 1e-12 K or so (10^5 random cases: 7.7e-13 K at most); the bound leaves room
    assert walther_temperature(A, B, walther_viscosity(A, B, theta)) == pytest.approx(theta, abs=1e-9)


def test_walther_temperature_at_the_ends():
    A, B = walther_constants(68.0, 40.0, 8.6, 100.0)
    assert walther_temperature(A, B, 68.0) == pytest.approx(40.0, abs=1e-12)
    assert walther_temperature(A, B, np.inf) == -273.15 and np.isnan(walther_temperature(A, B, 0.1))


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

def test_d2270_formulas_above_70_meet_the_table():
    # ASTM D2270 switches from table 1 to formulas above nu100 = 70 mm^2/s
    L70 = 0.8353 * 70 ** 2 + 14.67 * 70 - 216
    H70 = 0.1684 * 70 ** 2 + 11.85 * 70 - 97
    assert L70 == pytest.approx(4905, rel=2e-3) and H70 == pytest.approx(1558, rel=2e-3)


def test_d2270_L_H_interpolates_table_1_and_uses_the_formulas_above_70():
    assert d2270_L_H(8.8) == (118.5, 68.79)
    L, H = d2270_L_H(np.array([80.0]))
    assert L[0] == pytest.approx(0.8353 * 80 ** 2 + 14.67 * 80 - 216, rel=1e-15)
    assert H[0] == pytest.approx(0.1684 * 80 ** 2 + 11.85 * 80 - 97, rel=1e-15)


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


# ---- range messages ---------------------------------------------------------------------------------

def test_range_messages():
    messages = viscosity_range_messages(np.array([1.5, 30.0, 900.0]), np.array([150.0, 40.0, -20.0]),
                                        np.array([np.nan, np.nan, -15.0]))
    assert messages.tolist() == [
        "nu = 1.5 mm^2/s at 150 degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)",
        "",
        "-20 degC is below the pour point -15 degC: nu = 900 mm^2/s is an extrapolation",
    ]
