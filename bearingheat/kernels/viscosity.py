"""Lubricant viscosity against temperature: ASTM D341 (Walther), ISO VG grades, ASTM D2270 viscosity index.

Kernels take floats, arrays or Series: ν [mm²/s], temperatures [°C]
(converted to kelvin inside as T + 273.15).
:func:`bearingheat.api.viscosity.oil_viscosity` is the unit-aware entry
point (pint Quantities in and out).

ASTM D341 (Walther)::

    log10 log10(ν + 0.7) = A − B·log10(T),   T [K] = θ [°C] + 273.15

Two points (ν1 at θ1, ν2 at θ2) fix A and B. The equation holds for
ν >= 2 mm²/s; below that, and below the pour point of the oil, a value is
an extrapolation and is reported as a warning.

An ISO VG grade gives ν40 (the ISO 3448 mid-point); ν100 follows from an
assumed viscosity index by ASTM D2270. The default VI is 95, the mineral oil
of the viscosity-temperature diagrams of rolling bearing catalogues; pass
another VI where the oil's data sheet gives it.

>>> round(viscosity_from_two_points(404.0, 40.0, 28.0, 100.0, 60.0), 2)
132.13
>>> round(iso_vg_viscosity(68, 40.0), 2)
68.0
"""
from __future__ import annotations

import math

import numpy as np

from bearingheat.catalogue.viscosity import d2270_table, iso_vg_grades
from bearingheat.kernels._series import series_aware

__all__ = [
    "KELVIN_OFFSET",
    "WALTHER_SHIFT",
    "MIN_VISCOSITY",
    "DEFAULT_VISCOSITY_INDEX",
    "walther_constants",
    "walther_viscosity",
    "walther_temperature",
    "viscosity_from_two_points",
    "iso_vg_nu40",
    "d2270_L_H",
    "viscosity_index_astm_d2270",
    "nu100_from_viscosity_index",
    "iso_vg_viscosity",
    "viscosity_range_messages",
]

#: θ [°C] + 273.15 = T [K] (ASTM D341)
KELVIN_OFFSET = 273.15
#: the 0.7 of log10 log10(ν + 0.7) (ASTM D341)
WALTHER_SHIFT = 0.7
#: log2(10), for powers of ten through exp2
_LOG2_10 = math.log2(10.0)
#: ASTM D341 without its correction terms holds for ν >= 2 mm²/s
MIN_VISCOSITY = 2.0
#: assumed viscosity index of an oil given by its ISO VG grade (mineral oil, bearing catalogue ν-T diagrams)
DEFAULT_VISCOSITY_INDEX = 95.0


def _loglog(nu):
    return np.log10(np.log10(np.asarray(nu, dtype=float) + WALTHER_SHIFT))


def _log_kelvin(theta):
    return np.log10(np.asarray(theta, dtype=float) + KELVIN_OFFSET)


@series_aware
def walther_constants(nu1, theta1, nu2, theta2):
    """(A, B) of log10 log10(ν + 0.7) = A − B·log10(T) through two points (ASTM D341).

    ν1, ν2 [mm²/s] at θ1, θ2 [°C] (θ1 != θ2).

    >>> A, B = walther_constants(68.0, 40.0, 8.79, 100.0)
    >>> round(A, 4), round(B, 4)
    (9.2493, 3.6002)
    """
    y1, y2 = _loglog(nu1), _loglog(nu2)
    x1, x2 = _log_kelvin(theta1), _log_kelvin(theta2)
    with np.errstate(divide="ignore", invalid="ignore"):
        B = (y1 - y2) / (x2 - x1)
    A = y1 + B * x1
    return A, B


@series_aware
def walther_viscosity(A, B, theta):
    """ν = 10^(10^(A − B·log10(T))) − 0.7 [mm²/s] at θ [°C] (ASTM D341).

    >>> round(walther_viscosity(9.2493, 3.6002, 40.0), 1)
    68.0
    """
    exponent = np.asarray(A, dtype=float) - np.asarray(B, dtype=float) * _log_kelvin(theta)
    with np.errstate(over="ignore"):
        # 10^y as 2^(y·log2 10): exp2 is a third faster than power (the heat balance evaluates ν(T) some 18 times
        # a row); a few units in the last place (the log stays log10: A − B·log10 T cancels ~30-fold)
        return np.exp2(np.exp2(exponent * _LOG2_10) * _LOG2_10) - WALTHER_SHIFT


@series_aware
def walther_temperature(A, B, nu):
    """θ [°C] at which ν(θ) = ``nu`` [mm²/s] on the Walther line (ASTM D341): the inverse of
    :func:`walther_viscosity`, T = 10^((A − log10 log10(ν + 0.7))/B) K.

    B > 0 (ν falls as θ rises). ν below 0.3 mm²/s, where log10(ν + 0.7) is negative, gives NaN (0.3: inf);
    ν = inf gives absolute zero.

    >>> round(walther_temperature(9.2493, 3.6002, 68.0), 2)
    40.0
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.power(10.0, (np.asarray(A, dtype=float) - _loglog(nu)) / np.asarray(B, dtype=float)) \
            - KELVIN_OFFSET


@series_aware
def viscosity_from_two_points(nu1, theta1, nu2, theta2, theta):
    """ν [mm²/s] at θ [°C] from ν1 at θ1 and ν2 at θ2 (ASTM D341, Walther).

    Checks:

    >>> round(viscosity_from_two_points(404.0, 40.0, 28.0, 100.0, 60.0), 2)
    132.13
    >>> round(viscosity_from_two_points(68.0, 40.0, 14.85, 80.0, 100.0), 2)
    8.79
    >>> round(viscosity_from_two_points(32.0, 40.0, 5.4, 100.0, 80.0), 2)
    8.53
    """
    A, B = walther_constants(nu1, theta1, nu2, theta2)
    return walther_viscosity(A, B, theta)


# ---- ISO VG grades and the viscosity index -----------------------------------------------------

@series_aware
def iso_vg_nu40(grade):
    """Mid-point ν40 [mm²/s] of ISO VG grades (ISO 3448); NaN for a number that is no grade.

    >>> iso_vg_nu40(46)
    46.0
    >>> iso_vg_nu40(47)
    nan
    """
    grades = iso_vg_grades()
    values = np.asarray(grade, dtype=float)
    out = np.full(values.shape, np.nan)
    for g, nu40 in grades.items():
        out = np.where(values == g, nu40, out)
    return out


@series_aware
def d2270_L_H(nu100):
    """L and H of ASTM D2270 [mm²/s]: table 1 (linear interpolation) up to ν100 = 70, its formulas above.

    Above ν100 = 70 mm²/s (ASTM D2270): L = 0.8353·ν100² + 14.67·ν100 − 216,
    H = 0.1684·ν100² + 11.85·ν100 − 97. Table 1 starts at ν100 = 2 mm²/s;
    below it np.interp holds the first row (the viscosity index is NaN there).

    >>> L, H = d2270_L_H(8.8)
    >>> round(L, 3), round(H, 3)
    (118.5, 68.79)
    """
    nu100 = np.asarray(nu100, dtype=float)
    grid, L_table, H_table = d2270_table()
    L = np.where(nu100 <= 70.0, np.interp(nu100, grid, L_table),
                 0.8353 * nu100 ** 2 + 14.67 * nu100 - 216.0)
    H = np.where(nu100 <= 70.0, np.interp(nu100, grid, H_table),
                 0.1684 * nu100 ** 2 + 11.85 * nu100 - 97.0)
    return L, H


@series_aware
def viscosity_index_astm_d2270(nu40, nu100):
    """Viscosity index VI [-] from ν40 and ν100 [mm²/s] (ASTM D2270, unrounded).

    VI = 100·(L − ν40)/(L − H) where ν40 >= H; above VI 100
    VI = (10^N − 1)/0.00715 + 100 with N = (log H − log ν40)/log ν100.
    Defined for ν100 >= 2 mm²/s (NaN below).

    >>> round(viscosity_index_astm_d2270(73.3, 8.86))   # ASTM D2270 example, VI 92
    92
    >>> round(viscosity_index_astm_d2270(22.83, 5.05))  # ASTM D2270 example, VI 156
    156
    """
    nu40 = np.asarray(nu40, dtype=float)
    nu100 = np.asarray(nu100, dtype=float)
    L, H = d2270_L_H(nu100)
    with np.errstate(divide="ignore", invalid="ignore"):
        low = 100.0 * (L - nu40) / (L - H)
        N = (np.log10(H) - np.log10(nu40)) / np.log10(nu100)
        high = (np.power(10.0, N) - 1.0) / 0.00715 + 100.0
    return np.where(nu100 < MIN_VISCOSITY, np.nan, np.where(nu40 >= H, low, high))


@series_aware
def nu100_from_viscosity_index(nu40, VI):
    """ν100 [mm²/s] of an oil with ν40 [mm²/s] and viscosity index VI (inverse of ASTM D2270).

    Vectorised bisection on ν100 in [2 mm²/s, ν40]; VI rises with ν100 at
    fixed ν40. NaN where no ν100 >= 2 mm²/s gives that VI.

    >>> round(nu100_from_viscosity_index(73.3, viscosity_index_astm_d2270(73.3, 8.86)), 6)
    8.86
    """
    nu40 = np.asarray(nu40, dtype=float)
    VI = np.asarray(VI, dtype=float)
    nu40, VI = np.broadcast_arrays(nu40, VI)
    lo = np.full(nu40.shape, MIN_VISCOSITY)
    hi = nu40.copy()
    with np.errstate(invalid="ignore"):
        ok = (viscosity_index_astm_d2270(nu40, lo) <= VI) & (viscosity_index_astm_d2270(nu40, hi) >= VI)
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            below = viscosity_index_astm_d2270(nu40, mid) < VI
            lo = np.where(below, mid, lo)
            hi = np.where(below, hi, mid)
    return np.where(ok, 0.5 * (lo + hi), np.nan)


@series_aware
def iso_vg_viscosity(grade, theta, VI=DEFAULT_VISCOSITY_INDEX):
    """ν [mm²/s] at θ [°C] of an ISO VG grade with viscosity index VI (default 95).

    ν40 is the ISO 3448 mid-point, ν100 follows from VI (ASTM D2270), and
    ASTM D341 joins the two points. NaN for a number that is no ISO VG grade.

    >>> round(iso_vg_viscosity(68, 100.0), 2)   # D2270 table 1 by hand: VI 94.2 at 8.5, 96.8 at 8.6 mm^2/s
    8.53
    >>> round(iso_vg_viscosity(68, 70.0), 1), round(iso_vg_viscosity(68, 70.0, VI=140), 1)
    (19.9, 22.7)
    """
    nu40 = iso_vg_nu40(grade)
    nu100 = nu100_from_viscosity_index(nu40, VI)
    return viscosity_from_two_points(nu40, 40.0, nu100, 100.0, theta)


def viscosity_range_messages(nu, theta, pour_point=np.nan) -> np.ndarray:
    """Warnings ('' where in range) for values outside ASTM D341: ν < 2 mm²/s or θ below the pour point.

    >>> viscosity_range_messages(np.array([1.5, 30.0]), np.array([150.0, 40.0])).tolist()
    ['nu = 1.5 mm^2/s at 150 degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)', '']
    >>> viscosity_range_messages(900.0, -20.0, pour_point=-15.0).tolist()
    ['-20 degC is below the pour point -15 degC: nu = 900 mm^2/s is an extrapolation']
    """
    nu, theta, pour = np.broadcast_arrays(np.atleast_1d(np.asarray(nu, dtype=float)),
                                          np.atleast_1d(np.asarray(theta, dtype=float)),
                                          np.atleast_1d(np.asarray(pour_point, dtype=float)))
    out = []
    for v, t, p in zip(nu.ravel(), theta.ravel(), pour.ravel()):
        if not math.isnan(p) and t < p:
            out.append(f"{t:g} degC is below the pour point {p:g} degC: nu = {v:.4g} mm^2/s is an extrapolation")
        elif v < MIN_VISCOSITY:
            out.append(f"nu = {v:.4g} mm^2/s at {t:g} degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)")
        else:
            out.append("")
    return np.array(out, dtype=object).reshape(nu.shape)
