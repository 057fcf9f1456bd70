"""Robust statistics of deviations along a series of sizes: scale, outliers, a change point, median intervals.

The reference speed audit (:mod:`bearingheat.analysis.audit`) uses them to
decide which series of a catalogue deviate from the tables, where a series
splits into size classes, which single rows are misprints, and how sure the
coefficient a series implies is. Nothing here knows about bearings: values
come with a position (the bore d) and, where rounding matters, with the
lowest and highest value each could really have.

* :func:`robust_scale`: 1.4826·MAD, the standard deviation of a normal
  sample estimated so that a few wild values do not move it.
* :func:`consistent_scale`: the scale of the group medians that agree with
  zero, found by clipping the groups that do not (iterated to a fixed point).
* :func:`local_residuals`: each value minus the median of its neighbours by
  position, so a smooth trend along the series is not mistaken for a
  misprint.
* :func:`change_point`: the single split of a series sorted by position that
  minimises the sum of absolute deviations from the two medians (an L1 cost,
  robust to a misprinted row).
* :func:`median_interval`: the distribution-free (order statistic) interval
  of a median, widened for values that are only known within bounds.
"""
from __future__ import annotations

import math

import numpy as np
from scipy import stats

__all__ = [
    "CONFIDENCE",
    "MAD_TO_SIGMA",
    "robust_scale",
    "consistent_scale",
    "local_residuals",
    "change_point",
    "median_interval",
]

#: two-sided confidence level of the audits' intervals (coefficients, implied f0 of a group)
CONFIDENCE = 0.95
#: 1/Φ⁻¹(3/4): MAD·1.4826 estimates the standard deviation of a normal sample
MAD_TO_SIGMA = 1.0 / stats.norm.ppf(0.75)


def robust_scale(values) -> float:
    """1.4826·median(|x − median(x)|) of the finite values; NaN for none.

    >>> round(robust_scale([1.0, 2.0, 3.0, 4.0, 100.0]), 4)
    1.4826
    """
    x = np.asarray(values, dtype=float)
    x = x[np.isfinite(x)]
    if len(x) == 0:
        return math.nan
    return float(MAD_TO_SIGMA * np.median(np.abs(x - np.median(x))))


def consistent_scale(medians, *, z: float, floor: float, min_groups: int) -> tuple[float, np.ndarray]:
    """Scale of the group medians that agree with 0, and which groups those are.

    Starts from all groups, takes σ = 1.4826·median(|m|) (the MAD about
    zero, the value the medians would have if the tables were right), keeps
    the groups with |m| <= z·σ and repeats until the kept set no longer
    changes. σ is at least ``floor``; with fewer than ``min_groups`` groups
    (or kept groups) it is ``floor``, estimated from no group, and the kept
    mask is all False. Returns (σ, kept mask: the groups σ was estimated from).

    >>> sigma, kept = consistent_scale([0.001, -0.002, 0.003, 0.0, -0.001, 0.15, -0.2], z=5, floor=0.001,
    ...                                min_groups=3)
    >>> round(sigma, 4), kept.tolist()
    (0.0015, [True, True, True, True, True, False, False])
    >>> consistent_scale([-0.175, -0.154], z=5, floor=0.002, min_groups=5)[1].tolist()   # too few: the floor
    [False, False]
    """
    m = np.asarray(medians, dtype=float)
    kept = np.isfinite(m)
    too_few = (floor, np.zeros(len(m), dtype=bool))
    for _ in range(len(m) + 1):
        if kept.sum() < min_groups:
            return too_few
        sigma = max(floor, float(MAD_TO_SIGMA * np.median(np.abs(m[kept]))))
        now = np.isfinite(m) & (np.abs(m) <= z * sigma)
        if np.array_equal(now, kept):
            break
        kept = now
    if kept.sum() < min_groups:
        return too_few
    return sigma, kept


def local_residuals(values, positions, *, neighbours: int = 3) -> np.ndarray:
    """Each value minus the median of the values at the ``neighbours`` nearest distinct positions on each side.

    Rows at the same position (variants of one size) are neighbours of each
    other's neighbours but not of themselves, so a misprint shared by two
    variants still stands out. NaN values give NaN and are nobody's
    neighbour.

    >>> local_residuals([0.10, 0.11, 0.12, 0.50, 0.14, 0.15, 0.16], [1, 2, 3, 4, 5, 6, 7]).round(3).tolist()
    [-0.02, -0.02, -0.02, 0.37, -0.01, -0.0, 0.01]
    """
    x = np.asarray(values, dtype=float)
    pos = np.asarray(positions, dtype=float)
    out = np.full(len(x), np.nan)
    good = np.isfinite(x) & np.isfinite(pos)
    distinct = np.unique(pos[good])
    rank = np.searchsorted(distinct, pos)
    for i in np.flatnonzero(good):
        near = good & (np.abs(rank - rank[i]) <= neighbours) & (rank != rank[i])
        if near.any():
            out[i] = x[i] - np.median(x[near])
    return out


def change_point(values, positions, *, min_size: int) -> int | None:
    """Index k of the best split of a series sorted by position into values[:k] and values[k:], or None.

    The split lies between two distinct positions, leaves at least
    ``min_size`` values on each side and minimises Σ|x − median| over both
    sides. ``values`` must be sorted by ``positions`` and finite.

    >>> change_point([0.2, 0.21, 0.19, 0.2, 0.2, 0.0, 0.01, -0.01, 0.0, 0.0, 0.01], range(11), min_size=3)
    5
    """
    x = np.asarray(values, dtype=float)
    pos = np.asarray(positions, dtype=float)
    best, best_cost = None, math.inf
    for k in range(min_size, len(x) - min_size + 1):
        if pos[k] == pos[k - 1]:
            continue
        left, right = x[:k], x[k:]
        cost = np.abs(left - np.median(left)).sum() + np.abs(right - np.median(right)).sum()
        if cost < best_cost - 1e-15:
            best, best_cost = k, cost
    return best


def median_interval(values, low=None, high=None, *, confidence: float = 0.95) -> tuple[float, float, float, float]:
    """(median, lower, upper, coverage) of the median of ``values``, each known only within [low, high].

    The distribution-free interval of a median is [x_(j), x_(n+1−j)] with
    the largest j for which P(B < j) <= (1 − confidence)/2, B ~ Bin(n, ½);
    its coverage is 1 − 2·P(B < j). Where each true value is only known to
    lie in [low_i, high_i] (a rounded catalogue value), the j-th smallest
    true value is at least the j-th smallest ``low`` and the j-th largest at
    most the j-th largest ``high``, so [low_(j), high_(n+1−j)] holds the
    interval of the true values. With too few values for ``confidence``
    (n <= 5 for 95 %) the interval is [min low, max high] and the coverage
    says how much less it is.

    >>> med, lo, hi, cover = median_interval(np.arange(1.0, 12.0))
    >>> med, lo, hi, round(cover, 4)
    (6.0, 2.0, 10.0, 0.9883)
    """
    x = np.asarray(values, dtype=float)
    lo_v = x if low is None else np.asarray(low, dtype=float)
    hi_v = x if high is None else np.asarray(high, dtype=float)
    good = np.isfinite(x) & np.isfinite(lo_v) & np.isfinite(hi_v)
    x, lo_v, hi_v = x[good], np.sort(lo_v[good]), np.sort(hi_v[good])
    n = len(x)
    if n == 0:
        return math.nan, math.nan, math.nan, math.nan
    alpha = (1.0 - confidence) / 2.0
    j = 1
    while j < n // 2 + 1 and stats.binom.cdf(j, n, 0.5) <= alpha:   # P(B <= j) = P(B < j + 1)
        j += 1
    coverage = 1.0 - 2.0 * stats.binom.cdf(j - 1, n, 0.5)
    return float(np.median(x)), float(lo_v[j - 1]), float(hi_v[n - j]), float(coverage)
