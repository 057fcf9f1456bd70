"""Kernels of DU/DP bushings and thrust washers (the DU/DP bushing handbook): formulas, life, derating, sizing, power loss."""
from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, strategies as st

from bearingheat.errors import NoStandardSizeError, OutsideMethodError
from bearingheat.kernels import bushing as bu


# ----------------------------------------------------------------- formulas from first principles
def test_sliding_speed_of_the_seed_test_bushing():
    # The DU/DP bushing handbook: 15.9 mm bore at 750, 1500, 3000 1/min 'corresponds to 0.625, 1.25 and 2.5 m/s'
    np.testing.assert_allclose(bu.sliding_speed(15.9, np.array([750.0, 1500.0, 3000.0])), [0.625, 1.25, 2.5],
                               rtol=1e-3)


def test_length_from_pV_gives_back_K():
    F, n, d, K = 3000.0, 400.0, 30.0, 0.55
    length = bu.bushing_length_pV_du_dp(F, n, K)
    assert bu.bearing_pressure(F, d, length) * bu.sliding_speed(d, n) == pytest.approx(K, rel=1e-12)


def test_length_formula_in_seed_units_600K_agrees_with_SI():
    # seed: l [mm] = pi*n*P/(600*K), P [kgf], K [kgf/cm^2*m/s]
    P_kgf, n, K_seed = 200.0, 400.0, 5.65
    seed_units = math.pi * n * P_kgf / (600.0 * K_seed)
    si = bu.bushing_length_pV_du_dp(P_kgf * 9.80665, n, K_seed * bu.KGF_PER_CM2)
    assert si == pytest.approx(seed_units, rel=1e-12)


def test_thrust_washer_formulas_in_seed_units_agree_with_SI():
    P_kgf, n, K_seed, d, p_seed = 150.0, 300.0, 4.25, 20.0, 565.0
    b_seed = n * P_kgf / (600.0 * K_seed)                              # (D - d)/2 = nP/(600 pV)
    D_seed = math.sqrt(d ** 2 + 400.0 * P_kgf / (p_seed * math.pi))    # D = sqrt(d^2 + 400P/([p] pi))
    assert bu.thrust_washer_width_pV_du_dp(P_kgf * 9.80665, n, K_seed * bu.KGF_PER_CM2) == pytest.approx(b_seed)
    assert bu.thrust_washer_outer_diameter_pressure_du_dp(
        P_kgf * 9.80665, d, p_seed * bu.KGF_PER_CM2) == pytest.approx(D_seed)


def test_thrust_washer_width_gives_back_K_at_mean_diameter():
    F, n, d, K = 2000.0, 500.0, 25.0, 0.4
    D = d + 2 * bu.thrust_washer_width_pV_du_dp(F, n, K)
    p = 4 * F / (math.pi * (D ** 2 - d ** 2))
    assert p * bu.sliding_speed((D + d) / 2, n) == pytest.approx(K, rel=1e-12)


# ----------------------------------------------------------------- life and derating
def test_life_line_passes_through_the_seed_points():
    assert bu.life_hours_du_dp_fig86(3.6 * bu.KGF_PER_CM2) == pytest.approx(1000.0, rel=1e-12)
    assert bu.life_hours_du_dp_fig86(18.0 * bu.KGF_PER_CM2) == pytest.approx(200.0, rel=1e-12)
    assert bu.FIG86_SLOPE == pytest.approx(-1.0, abs=1e-12)


@given(st.floats(min_value=0.36, max_value=1.76))
def test_life_is_monotone_and_inverts(pv):
    life = bu.life_hours_du_dp_fig86(pv)
    assert bu.pV_for_life_du_dp_fig86(life) == pytest.approx(pv, rel=1e-9)
    assert bu.life_hours_du_dp_fig86(pv * 1.001) < life


def test_life_outside_two_point_fit_message():
    with pytest.raises(OutsideMethodError, match=re.escape(
            "pV = 0.1 N/mm²*m/s is outside the two-point fit of the DU/DP bushing handbook fig. 86 "
            "(0.353 to 1.765 N/mm²*m/s, i.e. 3.6 to 18 kgf/cm²*m/s)")):
        bu.life_hours_du_dp_fig86(0.1)
    assert bu.life_hours_du_dp_fig86(0.1, extrapolate=True) == pytest.approx(3530.4, rel=1e-4)


def test_temperature_factor_values_and_continuity():
    T = np.array([-200.0, 20.0, 120.0, 120.0 + 1e-9, 200.0, 280.0])
    np.testing.assert_allclose(bu.temperature_factor_du_dp(T), [1, 1, 1, 1, 0.75, 0.5], atol=1e-9)
    series = bu.temperature_factor_du_dp(pd.Series([100.0, 200.0], index=["a", "b"]))
    assert list(series) == [1.0, 0.75] and list(series.index) == ["a", "b"]


def test_temperature_outside_range_message():
    with pytest.raises(OutsideMethodError, match=re.escape(
            "T = 300 °C is outside the range of the DU/DP bushing handbook table 25 (-200 to +280 °C)")):
        bu.temperature_factor_du_dp(300.0)


def test_friction_ranges_of_the_seed():
    low, high = bu.friction_coefficient_range_du_dp(np.array([0.05, 0.1, 0.15, 0.2, 5.0, 5.1, 0.04]))
    np.testing.assert_array_equal(low, [0.05, 0.05, 0.05, 0.1, 0.1, np.nan, np.nan])
    np.testing.assert_array_equal(high, [0.1, 0.1, 0.2, 0.2, 0.2, np.nan, np.nan])


# ----------------------------------------------------------------- sizing
def test_size_bushing_worked_example():
    # F = 2 kN, n = 500 1/min, d = 25 mm, soft shaft, constant load, 1000 h: K = 5.65 kgf/cm^2*m/s
    out = bu.size_bushing_kernel(2000.0, 500.0, 25.0, 5.65 * bu.KGF_PER_CM2, 565 * bu.KGF_PER_CM2,
                                 [20, 30, 50, 100])
    assert out["l_pV [mm]"] == pytest.approx(math.pi * 500 * 2000 / (60000 * 0.554076), rel=1e-5)
    assert out["governing"] == "pV"
    assert out["l_standard [mm]"] == 100.0
    assert out["p [N/mm^2]"] == pytest.approx(0.8)
    assert (out["N_low [W]"], out["N_high [W]"]) == pytest.approx((0.1 * 2000 * 0.654498, 0.2 * 2000 * 0.654498),
                                                                  rel=1e-5)


def test_size_bushing_lengthened_from_pressure():
    # [p] governs when V < K/[p]: slow (V = 0.063 m/s), heavy, hardened oscillating K = 11.7 kgf/cm^2*m/s
    out = bu.size_bushing_kernel(50000.0, 60.0, 20.0, 11.7 * bu.KGF_PER_CM2, 141 * bu.KGF_PER_CM2)
    assert out["governing"] == "pressure"
    assert out["l_pV [mm]"] == pytest.approx(136.90, rel=1e-4)
    assert out["l_required [mm]"] == pytest.approx(50000 / (13.8274 * 20), rel=1e-4)
    assert out["p [N/mm^2]"] == pytest.approx(141 * bu.KGF_PER_CM2)


def test_size_bushing_below_minimum_speed_is_sized_with_a_note():
    """The handbook: bushings 'may be chosen smaller than calculated' where V < 0.05 m/s; the calculated size
    stands, as a conservative one (V = pi*25*20/60000 = 0.02618 m/s; l = pi*n*F/(60000*K))."""
    out = bu.size_bushing_kernel(2000.0, 20.0, 25.0, 0.55, 55.0)
    assert out["l_pV [mm]"] == pytest.approx(math.pi * 20 * 2000 / (60000 * 0.55), rel=1e-12)
    assert out["size_note"] == ("V = 0.02618 m/s is below 0.05 m/s: the DU/DP bushing handbook allows a smaller size "
                                "than calculated there (the size is conservative)")
    assert math.isnan(out["N_low [W]"])  # no friction band below 0.05 m/s


def test_size_bushing_above_maximum_speed_is_sized_with_a_note():
    out = bu.size_bushing_kernel(2000.0, 16000.0, 25.0, 0.55, 55.0)
    assert out["l_pV [mm]"] == pytest.approx(math.pi * 16000 * 2000 / (60000 * 0.55), rel=1e-12)
    assert out["size_note"] == ("n = 16000 1/min is above 15 000 1/min: the DU/DP bushing handbook allows a smaller "
                                "size than calculated there (the size is conservative)")
    assert bu.size_bushing_kernel(2000.0, 500.0, 25.0, 0.55, 55.0)["size_note"] == ""


def test_no_standard_length_large_enough_message():
    with pytest.raises(NoStandardSizeError, match=re.escape(
            "no standard length >= 94.5 mm in the list (20, 30, 50 mm)")):
        bu.size_bushing_kernel(2000.0, 500.0, 25.0, 5.65 * bu.KGF_PER_CM2, 55.0, [20, 30, 50])


# ----------------------------------------------------------------- calc kernel
def test_power_loss_kernel_with_f_given_and_not_given():
    out = bu.plain_bushing_power_loss(20.0, 20.0, 1000.0, 1000.0, f=0.12)
    V = math.pi * 20 * 1000 / 60000
    assert (out.p, out.V, out.power, out.status, out.message) == (2.5, pytest.approx(V), pytest.approx(0.12 * 1000 * V),
                                                                  "ok", "")
    default = bu.plain_bushing_power_loss(20.0, 20.0, 1000.0, 1000.0)
    assert default.power == pytest.approx(0.2 * 1000 * V)
    assert default.status == "warning"
    assert default.message == ("f not given: N uses f = 0.2, the high end of the DU/DP bushing handbook's range 0.1-0.2 "
                               "at V = 1.05 m/s (conservative)")


def test_power_loss_kernel_errors_per_row():
    out = bu.plain_bushing_power_loss(np.array([20.0, 20.0, -1.0, 30.0, 20.0]), 20.0, 1000.0,
                                      np.array([20000.0, 10.0, 100.0, 4000.0, 1000.0]))
    # n = 20 000 1/min at d = 20 mm is V = 20.9 m/s: no friction band, so f is needed (not the speed limit of
    # the sizing, which only makes a size conservative)
    assert list(out.status) == ["error", "error", "error", "error", "warning"]
    assert list(out.message[:4]) == [
        "V = 20.94 m/s is above 5 m/s: the DU/DP bushing handbook gives no friction coefficient there; give f_plain",
        "V = 0.01047 m/s is below 0.05 m/s: the DU/DP bushing handbook gives no friction coefficient there; give f_plain",
        "d = -1 mm: expected a bushing bore > 0 mm",
        "V = 6.283 m/s is above 5 m/s: the DU/DP bushing handbook gives no friction coefficient there; give f_plain",
    ]
    assert np.isnan(out.power[:4]).all() and np.isnan(out.p[2])


def test_power_loss_kernel_outside_the_bands_with_f_given():
    """With f given, a row below 0.05 m/s or above 15 000 1/min is computed: N = f*F*V."""
    out = bu.plain_bushing_power_loss(np.array([20.0, 2.0]), 20.0, 1000.0, np.array([10.0, 16000.0]), f=0.15)
    V = np.pi * np.array([20.0, 2.0]) * np.array([10.0, 16000.0]) / 60000
    assert list(out.status) == ["ok", "ok"] and list(out.message) == ["", ""]
    np.testing.assert_allclose(out.power, 0.15 * 1000 * V, rtol=1e-12)


def test_power_loss_kernel_scalar_array_series_agree():
    d = [20.0, 25.0, 30.0]
    n = [500.0, 1000.0, 2000.0]
    scalar = [bu.plain_bushing_power_loss(a, 20.0, 800.0, b).power for a, b in zip(d, n)]
    array = bu.plain_bushing_power_loss(np.array(d), 20.0, 800.0, np.array(n)).power
    series = bu.plain_bushing_power_loss(pd.Series(d, index=[3, 4, 5]), 20.0, 800.0, pd.Series(n, index=[3, 4, 5]))
    np.testing.assert_allclose(array, scalar)
    np.testing.assert_allclose(series.power.to_numpy(), scalar)
    assert list(series.power.index) == [3, 4, 5] and list(series.status) == ["warning"] * 3
