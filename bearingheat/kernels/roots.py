"""Vectorised bracketed roots: the heat balance of friction models without a closed speed law.

The catalogue friction model has M0 ∝ (ν·n)^(2/3), so its heat balance
N_R(n) = Q has a closed root (:mod:`bearingheat.kernels.thermal`). A model
without such a law is solved here: every row at once, by bisection on a
bracket [low, high] where the function changes sign, refined by the
Illinois variant of regula falsi, which keeps the bracket and converges
superlinearly for the smooth, monotone balances of friction power against
heat carried away.

References
----------
Dowell, M.; Jarratt, P. (1971): A modified regula falsi method for computing
the root of an equation. BIT 11, 168-174 (the Illinois algorithm).
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
    ``rtol`` times the magnitude of x, or f is exactly 0. ``f_low`` and
    ``f_high``, where the caller has them, are f at the ends (not evaluated
    again).

    >>> x, status = bracketed_root(lambda x: x ** 3 - 8.0, np.array([0.0, 3.0]), np.array([10.0, 10.0]))
    >>> np.round(x, 12).tolist(), status.tolist()
    ([2.0, nan], [0, 1])
    """
    a = np.array(low, dtype=float, copy=True)
    b = np.array(high, dtype=float, copy=True)
    a, b = np.broadcast_arrays(a, b)
    a, b = a.copy(), b.copy()
    fa = np.array(func(a) if f_low is None else np.broadcast_to(f_low, a.shape), dtype=float)
    fb = np.array(func(b) if f_high is None else np.broadcast_to(f_high, b.shape), dtype=float)
    status = np.where(np.isnan(fa) | np.isnan(fb), 2,
                      np.where((fa > 0) & (fb > 0), 1, np.where((fa < 0) & (fb < 0), -1, 0)))
    x = np.where(fa == 0, a, np.where(fb == 0, b, np.nan))
    active = (status == 0) & np.isnan(x)
    side = np.zeros(a.shape, dtype=int)  # which end stayed last time (Illinois halving)
    # a, b, fa, fb, x and side are this function's own arrays: each step writes into them where rows move
    for _ in range(iterations):
        if not active.any():
            break
        with np.errstate(invalid="ignore", divide="ignore"):
            c = np.where(fb != fa, b - fb * (b - a) / (fb - fa), 0.5 * (a + b))
        # a secant step onto (or past) an end would not narrow the bracket: where an end is already the root to
        # within rounding, the secant keeps landing on it and the other end crept up on it by halving (46
        # steps of the heat balance); a step of half the tolerance inside the end closes the bracket at once
        tol = 0.5 * rtol * np.fmax(np.abs(a), np.abs(b))
        inner_low, inner_high = np.fmin(a, b) + tol, np.fmax(a, b) - tol
        c = np.where(~np.isfinite(c) | (inner_low >= inner_high), 0.5 * (a + b),
                     np.minimum(np.maximum(c, inner_low), inner_high))
        # f at c for the rows still searching (the others keep their ends: their value is never read)
        fc = np.asarray(func(np.where(active, c, a)), dtype=float)
        exact = active & (fc == 0)
        np.copyto(x, c, where=exact)
        same_as_a = np.sign(fc) == np.sign(fa)
        # replace the end whose sign c shares; halve the value kept at the other end when it stays twice
        moving = active & ~exact
        move_a = moving & same_as_a
        move_b = moving & ~same_as_a
        np.divide(fb, 2.0, out=fb, where=move_a & (side == -1))
        np.divide(fa, 2.0, out=fa, where=move_b & (side == 1))
        np.copyto(a, c, where=move_a)
        np.copyto(fa, fc, where=move_a)
        np.copyto(b, c, where=move_b)
        np.copyto(fb, fc, where=move_b)
        np.copyto(side, -1, where=move_a)
        np.copyto(side, 1, where=move_b)
        done = moving & (np.abs(b - a) <= rtol * np.fmax(np.abs(a), np.abs(b)))
        if done.any():
            np.copyto(x, np.where(np.abs(fa) <= np.abs(fb), a, b), where=done)
        active &= ~(exact | done)
    x = np.where(active, np.where(np.abs(fa) <= np.abs(fb), a, b), x)
    return np.where(status == 0, x, np.nan), status
