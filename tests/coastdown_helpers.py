"""Reference run-downs shared by the coast-down tests (kernels, analysis, api)."""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from bearingheat.kernels.coastdown import rolling_bearing_M0_schaeffler


def integrate_rundown(torque, I, n0, dt, sigma, seed, fraction=0.95):
    """Reference run-down from solve_ivp (independent of the package's integrator), with noise."""
    def rhs(_, w):
        return [-torque(w[0]) / I]
    stop = lambda _, w: w[0]  # noqa: E731
    stop.terminal = True
    sol = solve_ivp(rhs, (0.0, 1e5), [n0 * math.pi / 30], events=stop, rtol=1e-11, atol=1e-12, dense_output=True)
    t_stop = float(sol.t_events[0][0])
    t = np.arange(0.0, fraction * t_stop, dt)
    n = sol.sol(t)[0] * 30 / math.pi + np.random.default_rng(seed).normal(0.0, sigma, t.size)
    return t, n, t_stop


def spindle_torque(f0, M1, nu, dM, z):
    return lambda w: z * (rolling_bearing_M0_schaeffler(w * 30 / math.pi, nu, dM, f0) + M1) / 1000.0
