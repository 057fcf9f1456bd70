"""Kernels of the DP11A lab rig of the DP11A manual: loads and the closed forms of the three processing tasks.

The DP11A manual pp. 11-13:

* loads: Fa = 9.81·Q·cos β, Fr = 9.81·Q·sin β [N];
* task 1, reduced friction coefficient for each speed:
  μ = 2·ΣT·P0/(d·ΣP0²), the least-squares slope of T = μ·P0·d/2 through the origin;
* task 2, for each β: T = f0·dm³·n^(2/3) + T_F, least squares on N = n^(2/3);
* task 3, for each speed: T = T0 + f·P0·(P0/C0)^c·dm, least squares on
  N = P0^(1+c), c = 0.55 for radial ball bearings.

The closed forms of the DP11A manual are implemented as printed and checked against
a general least-squares solver (:func:`least_squares_line`). Note that the
The DP11A manual f0 has no 10^-7 and no viscosity: T0 = f0·dm³·n^(2/3); the Schaeffler catalogue
catalogue f0 of the same bearing is f0·1e7/ν^(2/3) (:func:`catalogue_f0_equivalent`).

Units: Q [kg], β [deg], n [1/min], T [N·mm], P0, C0 [N], d, dm [mm],
ν [mm²/s]. Processing a table of readings is :mod:`bearingheat.analysis.lab`.
"""
from __future__ import annotations

import numpy as np

from bearingheat.catalogue.lab import LOAD_EXPONENT_RADIAL

__all__ = [
    "GRAVITY",
    "lab_loads",
    "reduced_friction_coefficient",
    "speed_fit",
    "load_fit",
    "least_squares_line",
    "catalogue_f0_equivalent",
]

#: g used by the DP11A manual p. 12 [m/s²]
GRAVITY = 9.81


def lab_loads(Q, beta):
    """(Fa, Fr) [N] of a weight Q [kg] on the spindle inclined at β [deg] (the DP11A manual, p. 12).

    Fa = 9.81·Q·cos β, Fr = 9.81·Q·sin β; β from 0 (axial) to 90° (radial).

    >>> [round(v, 4) for v in lab_loads(2.0, 30.0)]
    [16.9914, 9.81]
    """
    Q = np.asarray(Q, dtype=float)
    b = np.radians(np.asarray(beta, dtype=float))
    Fa, Fr = GRAVITY * Q * np.cos(b), GRAVITY * Q * np.sin(b)
    if np.ndim(Fa) == 0:
        return float(Fa), float(Fr)
    return Fa, Fr


def reduced_friction_coefficient(T, P0, d):
    """μ = 2·ΣT·P0/(d·ΣP0²) [-] (the DP11A manual, task 1, item 5); T [N·mm], P0 [N], d [mm].

    The least-squares slope of T = μ·P0·d/2 through the origin, over the
    readings of one speed (at least one reading with P0 > 0).

    >>> round(reduced_friction_coefficient([0.1, 0.2], [10.0, 20.0], 12.0), 8)
    0.00166667
    """
    T = np.asarray(T, dtype=float)
    P0 = np.asarray(P0, dtype=float)
    return float(2.0 * np.sum(T * P0) / (d * np.sum(P0 * P0)))


def _closed_form_line(T, N):
    """Slope and intercept of T = slope·N + intercept by the sums printed in the DP11A manual."""
    T = np.asarray(T, dtype=float)
    N = np.asarray(N, dtype=float)
    m = len(T)
    den = m * np.sum(N * N) - np.sum(N) ** 2
    slope = (m * np.sum(T * N) - np.sum(T) * np.sum(N)) / den
    intercept = (np.sum(T) * np.sum(N * N) - np.sum(T * N) * np.sum(N)) / den
    return float(slope), float(intercept)


def speed_fit(T, n, dm):
    """(f0, T_F) of T = f0·dm³·n^(2/3) + T_F by the closed forms of the DP11A manual task 2, N = n^(2/3).

    f0 in N·mm/(mm³·min^(-2/3)) as the DP11A manual defines it (no 1e-7, no ν); T_F [N·mm].
    T [N·mm] and n [1/min] of one weight and inclination, at least two distinct speeds.

    >>> n = np.array([2400.0, 2600.0, 2800.0, 3000.0])
    >>> f0, TF = speed_fit(2e-8 * 20**3 * n**(2/3) + 0.03, n, 20.0)
    >>> round(f0 * 1e8, 10), round(TF, 12)
    (2.0, 0.03)
    """
    slope, intercept = _closed_form_line(T, np.power(np.asarray(n, dtype=float), 2.0 / 3.0))
    return slope / dm ** 3, intercept


def load_fit(T, P0, C0, dm, c=LOAD_EXPONENT_RADIAL):
    """(f, T0) of T = T0 + f·P0·(P0/C0)^c·dm by the closed forms of the DP11A manual task 3, N = P0^(1+c).

    T [N·mm], P0 and C0 [N], dm [mm] of one speed and inclination, at least two
    distinct loads; c = 0.55 for radial ball bearings (the DP11A manual, table 2).

    >>> P0 = np.array([4.9, 9.81, 19.62])
    >>> f, T0 = load_fit(0.05 + 0.0009 * P0 * (P0 / 2227)**0.55 * 20, P0, 2227.0, 20.0)
    >>> round(f, 12), round(T0, 12)
    (0.0009, 0.05)
    """
    slope, intercept = _closed_form_line(T, np.power(np.asarray(P0, dtype=float), 1.0 + c))
    return slope * C0 ** c / dm, intercept


def least_squares_line(x, y, *, through_origin: bool = False) -> tuple[float, float]:
    """(slope, intercept) of y = slope·x + intercept by a general solver (numpy lstsq, SVD).

    The reference the DP11A manual's closed forms are checked against; any units.

    >>> [round(v, 12) for v in least_squares_line([1.0, 2.0, 3.0], [3.0, 5.0, 7.0])]
    [2.0, 1.0]
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    A = x[:, None] if through_origin else np.column_stack([x, np.ones_like(x)])
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    slope = float(coef[0])
    intercept = 0.0 if through_origin else float(coef[1])
    return slope, intercept


def catalogue_f0_equivalent(f0_dp11a, nu):
    """The Schaeffler catalogue f0 equal to a the DP11A manual f0 at viscosity ν [mm²/s] (ν·n >= 2000): f0·1e7/ν^(2/3).

    Equating T0 = f0·dm³·n^(2/3) (the DP11A manual) with M0 = f0'·(ν·n)^(2/3)·dm³·1e-7
    (the Schaeffler catalogue, p. 64).

    >>> round(float(catalogue_f0_equivalent(1e-7, 8.0)), 6)
    0.25
    """
    return np.asarray(f0_dp11a, dtype=float) * 1e7 / np.power(np.asarray(nu, dtype=float), 2.0 / 3.0)
