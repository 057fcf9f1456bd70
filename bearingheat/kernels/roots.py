"""Vectorised bracketed roots: the heat balance of friction models without a closed speed law.

The catalogue friction model has M0 ∝ (ν·n)^(2/3), so its heat balance
N_R(n) = Q has a closed root (:mod:`bearingheat.kernels.thermal`). A model
without such a law, and the operating temperature with ν(T) from oil data,
are solved here: every row at once, on a bracket [low, high] where the
function changes sign, by Chandrupatla's method. It keeps the bracket;
its first step is the secant of the ends (the root of a straight line at
once), each later one an inverse quadratic interpolation through the last
three points where Chandrupatla's test finds that safe (the interpolation
stays monotone between them), else a bisection. So it converges
superlinearly on the smooth, monotone balances of friction power against
heat carried away (10-11 steps on the heat balance with ν(T), 16 with the
Illinois regula falsi used before) and like bisection where the function
is rough.

References
----------
Chandrupatla, T. R. (1997): A new hybrid quadratic/bisection algorithm for
finding the zero of a nonlinear function without using derivatives.
Advances in Engineering Software 28 (3), 145-149.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

__all__ = ["bracketed_root"]


def bracketed_root(func: Callable[[np.ndarray], np.ndarray], low, high, *, rtol: float = 1e-12,
                   iterations: int = 200, f_low=None, f_high=None) -> tuple[np.ndarray, np.ndarray]:
    """Roots of ``func`` (one per row) inside [low, high], and a status per row.

    ``func`` takes an array of x (one per row) and returns f(x) per row.
    Returns (x, status): status 0 where a root was found, +1 where f > 0 at
    both ends, -1 where f < 0 at both ends, 2 where f is NaN at an end (x
    is NaN wherever status is not 0). A root at an end of the bracket is
    returned as it is. Converged when the bracket is narrower than
    ``rtol`` times the magnitude of x (the end where f is nearer 0 is
    returned), or f is exactly 0. ``f_low`` and ``f_high``, where the
    caller has them, are f at the ends (not evaluated again).

    >>> x, status = bracketed_root(lambda x: x ** 3 - 8.0, np.array([0.0, 3.0]), np.array([10.0, 10.0]))
    >>> np.round(x, 12).tolist(), status.tolist()
    ([2.0, nan], [0, 1])
    """
    a, b = np.broadcast_arrays(np.asarray(low, dtype=float), np.asarray(high, dtype=float))  # (never written)
    fa = np.array(func(a) if f_low is None else np.broadcast_to(f_low, a.shape), dtype=float)
    fb = np.array(func(b) if f_high is None else np.broadcast_to(f_high, b.shape), dtype=float)
    status = np.where(np.isnan(fa) | np.isnan(fb), 2,
                      np.where((fa > 0) & (fb > 0), 1, np.where((fa < 0) & (fb < 0), -1, 0)))
    x = np.where(fa == 0, a, np.where(fb == 0, b, np.nan))
    active = (status == 0) & np.isnan(x)
    # a: the newest point, b: the other end of the bracket, c: the end given up last (Chandrupatla's notation);
    # the first step is the secant of the ends (a straight line's root at once), the later ones interpolate
    # through three points
    c, fc = a, fa
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        t = _step_inside(fa / (fa - fb), a, b, rtol)
        for _ in range(iterations):
            if not active.any():
                break
            trial = a + t * (b - a)
            # f at the trial point for the rows still searching (the others keep their ends: never read)
            ft = np.asarray(func(np.where(active, trial, a)), dtype=float)
            exact = active & (ft == 0)
            x = np.where(exact, trial, x)
            # the trial point replaces the end whose sign it shares; the other end stays
            keeps_b = np.sign(ft) == np.sign(fa)
            c, fc = np.where(keeps_b, a, b), np.where(keeps_b, fa, fb)
            b, fb = np.where(keeps_b, b, a), np.where(keeps_b, fb, fa)
            a, fa = trial, ft
            done = active & ~exact & (np.abs(b - a) <= rtol * np.fmax(np.abs(a), np.abs(b)))
            if done.any():
                x = np.where(done, np.where(np.abs(fa) <= np.abs(fb), a, b), x)
            active &= ~(exact | done)
            # inverse quadratic interpolation through (a, b, c) where the three points allow it, else bisection
            xi = (a - b) / (c - b)
            phi = (fa - fb) / (fc - fb)
            quadratic = (phi * phi < xi) & ((1.0 - phi) * (1.0 - phi) < 1.0 - xi)
            t_quadratic = (fa / (fb - fa) * fc / (fb - fc)
                           + (c - a) / (b - a) * fa / (fc - fa) * fb / (fc - fb))
            t = _step_inside(np.where(quadratic, t_quadratic, 0.5), a, b, rtol)
    x = np.where(active, np.where(np.abs(fa) <= np.abs(fb), a, b), x)
    return np.where(status == 0, x, np.nan), status


def _step_inside(t, a, b, rtol: float) -> np.ndarray:
    """The step ``t`` (a fraction of the way from a to b) kept at least half the tolerance inside both ends: a
    point on (or past) an end would not narrow the bracket. A step that is not a number bisects."""
    width = np.abs(b - a)
    t_min = np.fmin(0.5 * rtol * np.fmax(np.abs(a), np.abs(b)) / width, 0.5)
    return np.where(np.isfinite(t), np.clip(t, t_min, 1.0 - t_min), 0.5)
