"""Kernels of the DP11A lab rig (the DP11A manual): loads and the closed forms of tasks 1-3 against a general solver."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from bearingheat.kernels.lab import lab_loads, least_squares_line, load_fit, reduced_friction_coefficient, speed_fit


def test_loads_of_seed_000():
    # Fa = 9.81 Q cos(beta), Fr = 9.81 Q sin(beta): axial at 0 deg, radial at 90 deg
    assert lab_loads(1.0, 0.0) == (9.81, 0.0)
    Fa, Fr = lab_loads(2.0, 90.0)
    assert Fa == pytest.approx(0.0, abs=1e-14) and Fr == 19.62
    Fa, Fr = lab_loads(np.array([0.5, 2.0]), np.array([45.0, 45.0]))
    np.testing.assert_allclose(Fa, Fr, rtol=1e-15)


def slope_rounding(T, N):
    """Absolute rounding noise of a least-squares slope of T on N, closed form or SVD.

    The seed's closed form takes the difference m·ΣT·N − ΣT·ΣN of two sums of
    size m²·max|T|·max|N|, each good to about m·eps, over m²·var(N); the
    general solver is no worse. When the true slope is 0 (equal torques)
    both sides are this noise, so a relative tolerance alone cannot hold.
    """
    N = np.asarray(N, dtype=float)
    return 10 * len(N) * np.finfo(float).eps * np.max(np.abs(T)) * np.max(np.abs(N)) / np.var(N)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.01, 10.0), min_size=3, max_size=8), st.floats(2000.0, 3000.0), st.floats(5, 30))
@example(torques=[9.0, 9.0, 9.0], n0=2000.0, dm=5.0)  # equal torques: slope 0, both sides rounding noise
def test_closed_forms_agree_with_lstsq_property(torques, n0, dm):
    T = np.array(torques)
    n = n0 + 100.0 * np.arange(len(T))
    f0, TF = speed_fit(T, n, dm)
    slope, intercept = least_squares_line(n ** (2 / 3), T)
    assert f0 * dm ** 3 == pytest.approx(slope, rel=1e-9, abs=1e-12)
    assert TF == pytest.approx(intercept, rel=1e-9, abs=1e-9)
    P0 = 5.0 + 5.0 * np.arange(len(T))
    mu = reduced_friction_coefficient(T, P0, dm)
    mu_ls, _ = least_squares_line(P0 * dm / 2, T, through_origin=True)
    assert mu == pytest.approx(mu_ls, rel=1e-12)
    f, T0 = load_fit(T, P0, 2227.0, dm)
    slope, intercept = least_squares_line(P0 ** 1.55, T)
    to_f = 2227.0 ** 0.55 / dm
    assert f == pytest.approx(slope * to_f, rel=1e-9, abs=slope_rounding(T, P0 ** 1.55) * to_f)


def test_exact_data_give_the_parameters_back():
    n = np.array([2400.0, 2600.0, 2800.0, 3000.0])
    f0, TF = speed_fit(3e-8 * 20 ** 3 * n ** (2 / 3) + 0.02, n, 20.0)
    assert f0 == pytest.approx(3e-8, rel=1e-10) and TF == pytest.approx(0.02, rel=1e-9)
    P0 = np.array([4.905, 9.81, 19.62])
    assert reduced_friction_coefficient(0.0015 * P0 * 12 / 2, P0, 12.0) == pytest.approx(0.0015, rel=1e-14)
