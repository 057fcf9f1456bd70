"""Kernels of the effect candidates (kernels/effects.py)."""
from __future__ import annotations

import numpy as np

from bearingheat.kernels.effects import heated_total_torque


def test_heated_torque_solves_its_own_balance():
    R, f0, nu, n, dM, load = 0.7, 2.0, 30.0, np.array([1000.0, 4000.0]), 50.0, 40.0
    M = heated_total_torque(R, f0, nu, n, dM, load)
    nu_hot = nu * np.exp(-0.03 * R * M * n / 9550)
    np.testing.assert_allclose(M, load + f0 * (nu_hot * n) ** (2 / 3) * dM ** 3 * 1e-7, rtol=1e-10)
