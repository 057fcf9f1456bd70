"""Kernels of the catalogue friction model (the Schaeffler catalogue, pp. 64-70).

Plain floats, numpy arrays or pandas Series in catalogue units:
d, D, dM [mm]; F, Fr, Fa, P0, P1, C0 [N]; n [1/min]; ν [mm²/s];
M [N·mm]; N_R [W]. No units are checked here: :mod:`bearingheat.api` is
the unit boundary.

References
----------
The Schaeffler catalogue: Schaeffler, "Трение и нагрев" (friction and heating), catalogue
pp. 64-70, after ISO 15312. The DP11A manual: SSAU lab manual (2016), table 1.
"""
from __future__ import annotations

import numpy as np

from bearingheat.kernels._series import series_aware

__all__ = [
    "REGIME_LIMIT",
    "LOW_REGIME_FACTOR",
    "mean_diameter",
    "speed_dependent_torque",
    "load_dependent_torque",
    "axial_load_torque",
    "axial_load_parameter",
    "power_loss",
    "total_torque",
    "static_equivalent_load",
    "f1_from_load_ratio",
    "f0_needle",
    "P1_RULES",
    "effective_load",
    "catalogue_friction_torque",
]

#: ν·n [mm²/s · 1/min] at which M0 changes formula (the Schaeffler catalogue, p. 64).
REGIME_LIMIT = 2000.0
#: Constant replacing (ν·n)^(2/3) below the limit (the Schaeffler catalogue, p. 64).
LOW_REGIME_FACTOR = 160.0


@series_aware
def mean_diameter(d, D):
    """dM = (d + D)/2 [mm] (the Schaeffler catalogue, p. 64).

    >>> mean_diameter(25, 52)
    38.5
    """
    return (np.asarray(d, dtype=float) + D) / 2.0


@series_aware
def speed_dependent_torque(f0, nu, n, dM):
    """Speed-dependent friction torque M0 [N·mm] (the Schaeffler catalogue, p. 64).

    .. math::
        M_0 = f_0 (\\nu n)^{2/3} d_M^3 10^{-7}  \\quad (\\nu n \\ge 2000)

        M_0 = f_0 \\cdot 160 \\cdot d_M^3 10^{-7}  \\quad (\\nu n < 2000)

    f0 [-]; ν [mm²/s] operating viscosity (base oil of a grease);
    n [1/min] >= 0; dM [mm]. At ν·n = 2000 the printed formulas step from
    160 to 2000^(2/3) = 158.74, a drop of 0.79 %; this kernel keeps that
    step exactly as the catalogue prints it.

    >>> round(speed_dependent_torque(2.0, 12.0, 3000.0, 38.5), 4)  # 6205 in an oil bath
    12.4436
    >>> round(speed_dependent_torque(2.0, 0.5, 3000.0, 38.5), 4)   # ν·n = 1500 < 2000
    1.8261
    """
    nu_n = np.asarray(nu, dtype=float) * np.asarray(n, dtype=float)
    root = np.cbrt(nu_n)  # (ν·n)^(2/3) as the cube root squared (power(x, 2/3) agrees to 2e-15)
    factor = np.where(nu_n >= REGIME_LIMIT, root * root, LOW_REGIME_FACTOR)
    dM = np.asarray(dM, dtype=float)
    return np.asarray(f0, dtype=float) * factor * (dM * dM * dM) * 1e-7  # dM³ as products: power() is a libm call


@series_aware
def load_dependent_torque(f1, load, dM):
    """Load-dependent friction torque M1 = f1·F·dM or f1·P1·dM [N·mm] (the Schaeffler catalogue, p. 64).

    ``load`` is F (Fr of radial, Fa of thrust needle and cylindrical roller
    bearings) or P1 (ball, tapered and spherical roller bearings) in N.

    >>> round(load_dependent_torque(0.0003, 5000.0, 46.0), 3)  # NU206-E at Fr = 5 kN
    69.0
    """
    return np.asarray(f1, dtype=float) * load * dM


@series_aware
def axial_load_torque(f2, Fa, dM):
    """Axial-load torque of a radial cylindrical roller bearing M2 = f2·Fa·dM [N·mm] (the Schaeffler catalogue, p. 69).

    >>> axial_load_torque(0.005, 1000.0, 40.0)
    200.0
    """
    return np.asarray(f2, dtype=float) * Fa * dM


@series_aware
def axial_load_parameter(kB, dM):
    """A = kB·1e-3·dM^2.1 [-] (the Schaeffler catalogue, p. 69), the divisor of Fa in the f2 charts.

    >>> round(axial_load_parameter(15, 46.0), 3)  # NJ206-E
    46.546
    """
    return np.asarray(kB, dtype=float) * 1e-3 * np.power(dM, 2.1)


@series_aware
def power_loss(MR, n):
    """Friction power loss N_R = M_R·n/9550 [W] with M_R [N·mm] and n [1/min] (the Schaeffler catalogue, p. 64).

    >>> round(power_loss(100.0, 3000.0), 4)
    31.4136
    """
    return np.asarray(MR, dtype=float) * n / 9550.0


@series_aware
def total_torque(M0, M1, M2=0.0):
    """M_R = M0 + M1 (+ M2 for axially loaded cylindrical roller bearings) [N·mm] (the Schaeffler catalogue, pp. 64, 69)."""
    return np.asarray(M0, dtype=float) + M1 + M2


@series_aware
def static_equivalent_load(Fr, Fa, X0, Y0):
    """P0 = max(X0·Fr + Y0·Fa, Fr) [N] (the DP11A manual, p. 5 and table 1).

    Where Fa = 0 the result is Fr whatever X0 and Y0 are (X0 <= 1), so a
    NaN Y0 does not spread into rows without axial load.

    >>> static_equivalent_load(1000.0, 500.0, 0.6, 0.5)
    1000.0
    >>> static_equivalent_load(1000.0, 1500.0, 0.6, 0.5)
    1350.0
    """
    Fr = np.asarray(Fr, dtype=float)
    Fa = np.asarray(Fa, dtype=float)
    combined = np.asarray(X0, dtype=float) * Fr + np.asarray(Y0, dtype=float) * Fa
    return np.where(Fa > 0.0, np.fmax(combined, Fr), Fr)


@series_aware
def f1_from_load_ratio(a, x, ratio):
    """f1 = a·ratio^x [-], ratio = P0/C0 or Fa/C0 (the Schaeffler catalogue tables, pp. 66-68); x = 0 gives f1 = a.

    >>> round(f1_from_load_ratio(0.0009, 0.5, 0.05), 8)  # 62 series at P0/C0 = 0.05
    0.00020125
    """
    a = np.asarray(a, dtype=float)
    x = np.asarray(x, dtype=float)
    ratio = np.asarray(ratio, dtype=float)
    powered = np.ones(np.broadcast_shapes(x.shape, ratio.shape))  # x = 0: f1 = a·1 = a, whatever the ratio
    square_root = x == 0.5  # the ball bearing rows of the tables: sqrt is exact and several times faster than power
    np.sqrt(ratio, out=powered, where=square_root)
    np.power(ratio, x, out=powered, where=~square_root & (x != 0.0))
    powered += 0.0  # sqrt(-0.0) is -0.0, power(-0.0, 0.5) is +0.0: the sign of power
    return a * powered


@series_aware
def f0_needle(value, B, d):
    """f0 = value·B/(33 + d) for NKI, NK, NAO, RNO, K, HK, BK, HN (the Schaeffler catalogue, p. 66).

    value is 12/18 (NK...), 24/36 (HK, BK) or 30/45 (HN) for grease/oil;
    B and d [mm] are the width and the bore (shaft) diameter.

    >>> round(f0_needle(24, 16, 20), 5)  # HK2016, grease
    7.24528
    """
    return np.asarray(value, dtype=float) * B / (33.0 + np.asarray(d, dtype=float))


# ---- P1 rules (the Schaeffler catalogue, p. 68) -------------------------------------------------------------

def _radial_ball(Fr, Fa, Y, e):
    return 3.3 * Fa - 0.1 * Fr


def _angular_single(Fr, Fa, Y, e):
    return Fa - 0.1 * Fr


def _angular_paired(Fr, Fa, Y, e):
    return 1.4 * Fa - 0.1 * Fr


def _four_point(Fr, Fa, Y, e):
    return 1.5 * Fa + 3.6 * Fr


def _tapered_single(Fr, Fa, Y, e):
    return np.fmax(2.0 * Y * Fa, Fr)


def _tapered_paired(Fr, Fa, Y, e):
    return np.fmax(1.21 * Y * Fa, Fr)


def _spherical(Fr, Fa, Y, e):
    Fr = np.asarray(Fr, dtype=float)
    Fa = np.asarray(Fa, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        high_axial = (Fr <= 0.0) | (Fa > e * Fr)
        axial_form = 1.6 * Fa / e
        radial_form = Fr * (1.0 + 0.6 * np.power(np.where(Fr > 0.0, Fa / (e * Fr), 0.0), 3))
    return np.where(Fa <= 0.0, Fr, np.where(high_axial, axial_form, radial_form))


#: rule name -> (function(Fr, Fa, Y, e) before the "P1 >= Fr" rule, formula, catalogue values it needs)
P1_RULES = {
    "radial_ball": (_radial_ball, "3.3·Fa − 0.1·Fr", ()),
    "angular_single": (_angular_single, "Fa − 0.1·Fr", ()),
    "angular_paired": (_angular_paired, "1.4·Fa − 0.1·Fr", ()),
    "angular_double_row": (_angular_paired, "1.4·Fa − 0.1·Fr", ()),
    "four_point": (_four_point, "1.5·Fa + 3.6·Fr", ()),
    "tapered_single": (_tapered_single, "max(2·Y·Fa, Fr)", ("Y",)),
    "tapered_paired": (_tapered_paired, "max(1.21·Y·Fa, Fr)", ("Y",)),
    "spherical": (_spherical, "1.6·Fa/e if Fa/Fr > e, else Fr·(1 + 0.6·(Fa/(e·Fr))³)", ("e",)),
}


@series_aware
def effective_load(rule, Fr, Fa, Y=np.nan, e=np.nan):
    """P1 [N] by the named rule of the Schaeffler catalogue p. 68, then "if P1 < Fr use Fr".

    ``rule`` is a key of :data:`P1_RULES` (a string, or an array of strings
    for rows of several types).

    >>> effective_load("radial_ball", 2000.0, 1000.0)
    3100.0
    >>> effective_load("tapered_single", 4000.0, 1000.0, Y=1.6)
    4000.0
    >>> round(effective_load("spherical", 10000.0, 1000.0, e=0.25), 1)
    10384.0
    """
    Fr = np.asarray(Fr, dtype=float)
    if np.ndim(rule) == 0:
        raw = P1_RULES[str(rule)][0](Fr, Fa, Y, e)
        return np.fmax(raw, Fr)
    rules = np.asarray(rule, dtype=object)
    shape = np.broadcast_shapes(rules.shape, np.shape(Fr), np.shape(Fa), np.shape(Y), np.shape(e))
    rules = np.broadcast_to(rules, shape)
    out = np.full(shape, np.nan)
    args = [np.broadcast_to(np.asarray(v, dtype=float), shape) for v in (Fr, Fa, Y, e)]
    for name in set(rules.ravel().tolist()):
        mask = rules == name
        func = P1_RULES[name][0]
        out[mask] = func(*(a[mask] for a in args))
    return np.fmax(out, args[0])


@series_aware
def catalogue_friction_torque(f0, f1, load, dM, nu, n, f2=0.0, Fa=0.0):
    """Total friction torque M_R = M0 + M1 + M2 [N·mm] for resolved coefficients.

    The array kernel behind every friction calculation: f0 and f1 already
    taken from the tables, ``load`` is F or P1 [N], f2 and Fa only for
    axially loaded cylindrical roller bearings.

    >>> round(catalogue_friction_torque(2.0, 0.0002, 1000.0, 38.5, 12.0, 3000.0), 4)
    20.1436
    """
    return (speed_dependent_torque(f0, nu, n, dM) + load_dependent_torque(f1, load, dM)
            + axial_load_torque(f2, Fa, dM))
