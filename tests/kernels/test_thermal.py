"""Heat balance kernels (issue 3): heat flow area, heat carried away, friction power, the exact roots f_n."""
from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from bearingheat.kernels.friction import power_loss
from bearingheat.kernels.thermal import (
    balance_speed,
    default_heat_transfer_coefficient,
    friction_power,
    heat_flow_area,
    oil_heat_flow,
    permissible_speed_factor,
    reference_heat_flux_density,
    seat_heat_flow,
    speed_factor_catalogue_approximation,
    speed_factor_exact,
)


# ---- heat flow area and heat carried away ------------------------------------------------------

def test_heat_flow_area_formulas():
    assert heat_flow_area("radial", 25, 52, B=15) == pytest.approx(math.pi * 15 * 77)
    assert heat_flow_area("tapered", 25, 52, T=16.25) == pytest.approx(math.pi * 16.25 * 77)
    assert heat_flow_area("thrust", 25, 42) == pytest.approx(math.pi / 2 * (42 ** 2 - 25 ** 2))


def test_heat_flux_density_branches_meet_at_the_limit():
    for kind, q in (("radial", 0.016), ("thrust", 0.020)):
        assert reference_heat_flux_density(kind, 50000.0) == q
        assert reference_heat_flux_density(kind, 50000.0 * (1 + 1e-12)) == pytest.approx(q, rel=1e-9)
    assert reference_heat_flux_density("radial", 100000.0) == pytest.approx(0.016 * 2 ** -0.34, rel=1e-12)
    assert reference_heat_flux_density("thrust", 100000.0) == pytest.approx(0.020 * 2 ** -0.16, rel=1e-12)


def test_default_k_q_inside_catalogue_range():
    k_q = default_heat_transfer_coefficient("radial", 20000.0)  # W/(mm^2 K)
    assert k_q == pytest.approx(0.016 / 50)
    assert 0.2e-3 <= k_q <= 1.0e-3  # catalogue 0.2..1.0e-6 kW/(mm^2 K) for seats up to 25 000 mm^2


def test_seat_and_oil_heat_flows():
    assert seat_heat_flow(3.2e-4, 3628.5, 50.0) == pytest.approx(58.056)
    assert oil_heat_flow(2.0, 5.0) == pytest.approx(0.0286e3 * 2.0 * 5.0)


def test_friction_power_is_the_exact_form_of_the_catalogue_power_loss():
    # one power formula in the heat balance: (pi n / 30) 1e-3 M; the catalogue prints M n / 9550
    assert friction_power(100.0, 3000.0) == pytest.approx(math.pi * 3000.0 / 30.0 * 1e-3 * 100.0, rel=1e-15)
    assert friction_power(100.0, 3000.0) / power_loss(100.0, 3000.0) == pytest.approx(math.pi * 9550 / 30000,
                                                                                     rel=1e-15)


# ---- speed factor f_n ------------------------------------------------------------------------------

def test_speed_factor_exact_matches_brentq():
    rng = np.random.default_rng(5)
    k_L = 10 ** rng.uniform(-3, 2, 200)
    k_P = 10 ** rng.uniform(-3, 2, 200)
    f_n = speed_factor_exact(k_L, k_P)
    for kl, kp, f in zip(k_L, k_P, f_n):
        root = brentq(lambda x: kl * x ** (5 / 3) + kp * x - 1.0, 1e-9, 1e9, xtol=1e-15, rtol=1e-14)
        assert f == pytest.approx(root, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-4, 1e3), st.floats(1e-4, 1e3))
def test_speed_factor_exact_satisfies_the_equation(k_L, k_P):
    f = speed_factor_exact(k_L, k_P)
    assert k_L * f ** (5 / 3) + k_P * f == pytest.approx(1.0, rel=1e-13)


def test_speed_factor_exact_edge_cases():
    assert speed_factor_exact(0.0, 0.5) == pytest.approx(2.0, rel=1e-15)
    assert speed_factor_exact(1.0, 0.0) == pytest.approx(1.0, rel=1e-15)
    assert speed_factor_exact(0.0, 0.0) == math.inf
    assert math.isnan(speed_factor_exact(-1.0, 0.5))


def test_speed_factor_scalar_array_series_agree():
    k_L = pd.Series([0.2, 0.9, 3.0], index=["x", "y", "z"])
    k_P = pd.Series([0.1, 0.05, 2.0], index=["x", "y", "z"])
    series = speed_factor_exact(k_L, k_P)
    array = speed_factor_exact(k_L.to_numpy(), k_P.to_numpy())
    scalars = [speed_factor_exact(a, b) for a, b in zip(k_L, k_P)]
    assert series.index.equals(k_L.index)
    np.testing.assert_array_equal(series.to_numpy(), array)
    np.testing.assert_array_equal(array, scalars)


def test_catalogue_approximation_against_exact_root():
    grid = np.logspace(-2, 1, 61)
    k_L, k_P = np.meshgrid(grid, grid)
    exact = speed_factor_exact(k_L, k_P)
    approximate = speed_factor_catalogue_approximation(k_L, k_P)
    deviation = np.abs(approximate / exact - 1.0)
    assert deviation.max() < 0.06          # worst corner k_L = 0.01, k_P = 10: 5.7 %
    assert np.percentile(deviation, 95) < 0.021
    assert speed_factor_catalogue_approximation(0.5, 0.5) == pytest.approx(1.0, abs=0.01)


def test_catalogue_approximation_refuses_outside_its_range():
    with pytest.raises(ValueError, match=re.escape(
            "k_P: 12 is outside 0.01 <= k_P <= 10, the range of the catalogue approximation of f_n; "
            "use speed_factor_exact")):
        speed_factor_catalogue_approximation(np.array([0.5, 0.5]), np.array([1.0, 12.0]))


def test_n_per_does_not_depend_on_which_n_thr_scales_f_n():
    # n_per = n_thr * f_n(k_L(n_thr), k_P(n_thr)) is the speed where friction heat = Q, whatever n_thr is
    args = dict(f0=2.0, nu=20.0, dM=38.5, load_torque=35.0, Q=58.0)
    n_a = 14416.0 * permissible_speed_factor(14416.0, **args)
    n_b = 14400.0 * permissible_speed_factor(14400.0, **args)
    assert n_a == pytest.approx(n_b, rel=1e-13)
    assert n_a == pytest.approx(balance_speed(**args), rel=1e-13)


def test_low_regime_uses_the_constant_M0():
    # nu*n < 2000: M0 = f0*160*dM^3*1e-7, so (pi n/30) 1e-3 (M0 + M1) = Q is linear in n
    f0, nu, dM, M1, Q = 2.0, 0.2, 100.0, 50.0, 50.0
    M0 = f0 * 160 * dM ** 3 * 1e-7
    n_expected = Q / (math.pi / 30 * 1e-3 * (M0 + M1))
    assert nu * n_expected < 2000
    assert balance_speed(f0, nu, dM, M1, Q) == pytest.approx(n_expected, rel=1e-14)
    n_thr = 5000.0
    assert n_thr * permissible_speed_factor(n_thr, f0, nu, dM, M1, Q) == pytest.approx(n_expected, rel=1e-14)


def test_balance_speed_is_continuous_and_rising_in_the_heat():
    Q = np.linspace(1.0, 500.0, 400)
    n = balance_speed(2.0, 12.0, 38.5, 3.0, Q)
    assert np.all(np.diff(n) > 0)


def test_regime_step_with_two_roots_takes_the_lower_speed():
    # the catalogue M0 steps down by 0.79 % at nu*n = 2000; a heat flow between the two sides has two roots
    f0, nu, dM, M1 = 2.0, 1.0, 100.0, 0.0
    n_switch = 2000.0 / nu
    K = math.pi / 30 * 1e-3
    c = f0 * dM ** 3 * 1e-7
    Q = 0.5 * (K * n_switch * c * 160.0 + K * n_switch * c * 2000.0 ** (2 / 3))
    n = balance_speed(f0, nu, dM, M1, Q)
    assert n < n_switch
    assert n == pytest.approx(Q / (K * c * 160.0), rel=1e-14)
