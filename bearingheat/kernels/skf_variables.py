"""Kernels of the SKF friction model: Grr and Gsl of tables 2a and 2b, one function per published formula.

Grr and Gsl are the "geometric and load-dependent variables" of the
rolling and sliding frictional moments (Mrr = Grr·(ν·n)^0.6, Msl =
Gsl·μsl; :mod:`bearingheat.kernels.skf`). Catalogue units: dm [mm],
Fr, Fa, C0 [N], n [1/min], ν [mm²/s]; R1..R4, S1..S5 are the empirical
constants of tables 3, 3a..3g for exactly these units.

References
----------
SKF General Catalogue 6000 RU, chapter «Трение», pp. 91-92 (tables 2a, 2b)
("6000"); SKF «Подшипники качения» PUB BU/P1 10000/3 RU (2017), pp. 104-105
("10000/3"), which prints the same formulas.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from bearingheat.kernels._series import series_aware

__all__ = [
    "deep_groove_contact_angle",
    "grr_deep_groove_ball",
    "gsl_deep_groove_ball",
    "grr_angular_contact_ball",
    "gsl_angular_contact_ball",
    "grr_self_aligning_ball",
    "gsl_self_aligning_ball",
    "grr_cylindrical_roller",
    "gsl_cylindrical_roller",
    "grr_tapered_roller",
    "gsl_tapered_roller",
    "grr_spherical_roller",
    "gsl_spherical_roller",
    "grr_carb",
    "gsl_carb",
    "grr_thrust_ball",
    "gsl_thrust_ball",
    "grr_thrust_cylindrical_roller",
    "gsl_thrust_cylindrical_roller",
    "grr_spherical_roller_thrust",
    "gsl_spherical_roller_thrust",
    "rolling_sliding_variables",
    "G_VARIABLES",
    "SPEED_DEPENDENT_GSL",
]

#: exponents below this are clipped: e^-700 ~ 1e-304 is zero for every torque, and numpy is slow on subnormals
_EXP_FLOOR = -700.0


def _f(x):
    return np.asarray(x, dtype=float)


#: x^a from the cube root c = x^(1/3), for the exponents of table 2 that are thirds
_THIRDS = {1.0 / 3.0: lambda x, c: c, 4.0 / 3.0: lambda x, c: x * c, 5.0 / 3.0: lambda x, c: x * c * c}


def _pow(x, a):
    """x^a for x >= 0 and a scalar exponent, as exp(a·ln x): a third faster than np.power on large arrays.

    0^a is 0 for a > 0 and inf for a < 0, as with np.power; the relative
    difference to np.power is of the order of 1e-15. The powers 1/3, 4/3
    and 5/3 of table 2 use np.cbrt (one ulp, a third of the time of exp and ln).
    """
    x = _f(x)
    if x.ndim == 0 or np.ndim(a) != 0:
        return np.power(x, a)
    if a in _THIRDS:
        return _THIRDS[a](x, np.cbrt(x))
    with np.errstate(divide="ignore"):
        out = np.log(x)
    out *= a
    return np.exp(out, out=out)


def _ln_power(a, x, p):
    """ln(a·x^p) = ln a + p·ln x for x >= 0, a > 0 (-inf where x = 0): Grr in logarithms."""
    x = _f(x)
    with np.errstate(divide="ignore"):
        out = np.log(x)
    if out.ndim == 0:
        return p * out + np.log(a)
    out *= p
    out += np.log(a)
    return out


def _cube(x):
    x = _f(x)
    return x * x * x



# ---- Grr and Gsl, table 2a (radial) and 2b (thrust): 6000 pp. 91-92, 10000/3 pp. 104-105 ------------

@series_aware
def deep_groove_contact_angle(Fa, C0):
    """αF = 24.6·(Fa/C0)^0.24 [deg] of a deep groove ball bearing under axial load (6000 p. 91; 10000/3 p. 104).

    Fa, C0 [N]; Fa > 0.

    >>> round(deep_groove_contact_angle(500.0, 7800.0), 3)
    12.723
    """
    return 24.6 * _pow(_f(Fa) / C0, 0.24)


def _sin_alpha(alpha_F, Fa):
    """sin αF where Fa > 0, 1 where Fa = 0 (the axial terms are 0 there whatever αF is).

    αF = 24.6·(Fa/C0)^0.24 stays below 24.6° while Fa <= C0: there the sine is
    its Taylor series to x^11 (error below 1e-13, a third of the time of
    np.sin); larger angles use np.sin.
    """
    x = np.radians(alpha_F)
    if np.ndim(x) and np.nanmax(x, initial=0.0) <= 0.5236:   # 30°
        x2 = np.square(x)
        s = np.multiply(x2, -1.0 / 39916800.0)
        for coefficient in (1.0 / 362880.0, -1.0 / 5040.0, 1.0 / 120.0, -1.0 / 6.0):
            s += coefficient
            s *= x2
        s += 1.0
        s *= x
    else:
        with np.errstate(invalid="ignore"):
            s = np.sin(x)
    if np.ndim(s):
        np.copyto(s, 1.0, where=~(_f(Fa) > 0))
        return s
    return np.where(_f(Fa) > 0, s, 1.0)


def _ln_grr_deep_groove_ball(R1, R2, dm, Fr, Fa, sin_alpha):
    return _ln_power(_f(R1) * np.power(dm, 1.96), _f(Fr) + _f(R2) * Fa / sin_alpha, 0.54)


def _gsl_deep_groove_ball(S1, S2, dm, Fr, Fa, sin_alpha):
    Fr = _f(Fr)
    Fa = _f(Fa)
    dm = _f(dm)
    inner = Fa * Fa
    inner *= inner
    inner *= _f(S2) * np.power(dm, 1.5)
    inner /= sin_alpha                                      # S2·dm^1.5/sin αF·Fa^4
    Fr2 = Fr * Fr
    inner += Fr2 * Fr2 * Fr
    root = _pow(inner, 1.0 / 3.0)                           # (Fr^5)^(1/3) = Fr^(5/3) where Fa = 0
    return _f(S1) * np.where(Fa > 0, np.power(dm, -0.145), np.power(dm, -0.26)) * root


@series_aware
def grr_deep_groove_ball(R1, R2, dm, Fr, Fa, alpha_F):
    """Grr of deep groove ball bearings (table 2a; 6000 p. 91, 10000/3 p. 104).

    Fa = 0: Grr = R1·dm^1.96·Fr^0.54; Fa > 0: Grr = R1·dm^1.96·(Fr + R2/sin αF·Fa)^0.54.
    dm [mm], Fr, Fa [N], αF [deg] (:func:`deep_groove_contact_angle`; ignored where Fa = 0).

    >>> round(grr_deep_groove_ball(3.9e-7, 1.7, 38.5, 1000.0, 0.0, float("nan")), 6)  # 6205
    0.020824
    """
    return np.exp(_ln_grr_deep_groove_ball(R1, R2, dm, Fr, Fa, _sin_alpha(alpha_F, Fa)))


@series_aware
def gsl_deep_groove_ball(S1, S2, dm, Fr, Fa, alpha_F):
    """Gsl of deep groove ball bearings (table 2a; 6000 p. 91, 10000/3 p. 104).

    Fa = 0: Gsl = S1·dm^-0.26·Fr^(5/3); Fa > 0: Gsl = S1·dm^-0.145·(Fr^5 + S2·dm^1.5/sin αF·Fa^4)^(1/3).
    The two printed forms differ in the power of dm, so Gsl steps as Fa leaves 0 (kept as printed).

    >>> round(gsl_deep_groove_ball(3.23e-3, 36.5, 38.5, 1000.0, 0.0, float("nan")), 3)
    125.021
    """
    return _gsl_deep_groove_ball(S1, S2, dm, Fr, Fa, _sin_alpha(alpha_F, Fa))


def _ln_grr_angular_contact_ball(R1, R2, R3, dm, Fr, Fa, n):
    Fg = _f(R3) * np.power(dm, 4) * np.square(n)
    return _ln_power(_f(R1) * np.power(dm, 1.97), _f(Fr) + Fg + _f(R2) * Fa, 0.54)


@series_aware
def grr_angular_contact_ball(R1, R2, R3, dm, Fr, Fa, n):
    """Grr = R1·dm^1.97·(Fr + Fg + R2·Fa)^0.54, Fg = R3·dm^4·n² (table 2a; 6000 p. 91, 10000/3 p. 104).

    Single and double row angular contact and four-point contact ball
    bearings; Fa is the external axial load [N], n [1/min].

    >>> round(grr_angular_contact_ball(5.03e-7, 1.97, 1.90e-12, 38.5, 1000.0, 500.0, 3000.0), 5)
    0.04075
    """
    return np.exp(_ln_grr_angular_contact_ball(R1, R2, R3, dm, Fr, Fa, n))


@series_aware
def gsl_angular_contact_ball(S1, S2, S3, dm, Fr, Fa, n):
    """Gsl = S1·dm^0.26·((Fr + Fg)^(4/3) + S2·Fa^(4/3)), Fg = S3·dm^4·n² (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(gsl_angular_contact_ball(1.30e-2, 0.68, 1.91e-12, 38.5, 1000.0, 500.0, 3000.0), 3)
    443.518
    """
    Fg = _f(S3) * np.power(dm, 4) * np.square(n)
    return _f(S1) * np.power(dm, 0.26) * (_pow(_f(Fr) + Fg, 4.0 / 3.0) + _f(S2) * _pow(Fa, 4.0 / 3.0))


def _ln_grr_self_aligning_ball(R1, R2, R3, dm, Fr, Fa, n):
    Fg = _f(R3) * np.power(dm, 3.5) * np.square(n)
    return _ln_power(_f(R1) * np.square(dm), _f(Fr) + Fg + _f(R2) * Fa, 0.54)


@series_aware
def grr_self_aligning_ball(R1, R2, R3, dm, Fr, Fa, n):
    """Grr = R1·dm²·(Fr + Fg + R2·Fa)^0.54, Fg = R3·dm^3.5·n² (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(grr_self_aligning_ball(3.25e-7, 6.51, 2.43e-12, 38.5, 1000.0, 100.0, 3000.0), 5)
    0.02639
    """
    return np.exp(_ln_grr_self_aligning_ball(R1, R2, R3, dm, Fr, Fa, n))


@series_aware
def gsl_self_aligning_ball(S1, S2, S3, dm, Fr, Fa, n):
    """Gsl = S1·dm^-0.12·((Fr + Fg)^(4/3) + S2·Fa^(4/3)), Fg = S3·dm^3.5·n² (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(gsl_self_aligning_ball(4.36e-3, 9.33, 2.43e-12, 38.5, 1000.0, 100.0, 3000.0), 3)
    40.609
    """
    Fg = _f(S3) * np.power(dm, 3.5) * np.square(n)
    return _f(S1) * np.power(dm, -0.12) * (_pow(_f(Fr) + Fg, 4.0 / 3.0) + _f(S2) * _pow(Fa, 4.0 / 3.0))


def _ln_grr_cylindrical_roller(R1, dm, Fr):
    return _ln_power(_f(R1) * np.power(dm, 2.41), Fr, 0.31)


@series_aware
def grr_cylindrical_roller(R1, dm, Fr):
    """Grr = R1·dm^2.41·Fr^0.31 (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(grr_cylindrical_roller(1.09e-6, 46.0, 5000.0), 5)
    0.15537
    """
    return np.exp(_ln_grr_cylindrical_roller(R1, dm, Fr))


@series_aware
def gsl_cylindrical_roller(S1, S2, dm, Fr, Fa):
    """Gsl = S1·dm^0.9·Fa + S2·dm·Fr (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(gsl_cylindrical_roller(0.16, 0.0015, 46.0, 5000.0, 0.0), 3)
    345.0
    """
    return _f(S1) * np.power(dm, 0.9) * Fa + _f(S2) * _f(dm) * Fr


def _ln_grr_tapered_roller(R1, R2, dm, Fr, Fa, Y):
    axial = np.where(_f(Fa) > 0, _f(R2) * _f(Y) * Fa, 0.0)
    return _ln_power(_f(R1) * np.power(dm, 2.38), _f(Fr) + axial, 0.31)


@series_aware
def grr_tapered_roller(R1, R2, dm, Fr, Fa, Y):
    """Grr = R1·dm^2.38·(Fr + R2·Y·Fa)^0.31 (table 2a; 6000 p. 91, 10000/3 p. 104).

    Y: the catalogue axial load factor of a single row bearing; Fa: the external axial load [N].

    >>> round(grr_tapered_roller(1.76e-6, 10.9, 38.5, 4000.0, 1000.0, 1.6), 5)
    0.22993
    """
    return np.exp(_ln_grr_tapered_roller(R1, R2, dm, Fr, Fa, Y))


@series_aware
def gsl_tapered_roller(S1, S2, dm, Fr, Fa, Y):
    """Gsl = S1·dm^0.82·(Fr + S2·Y·Fa) (table 2a; 6000 p. 91, 10000/3 p. 104).

    >>> round(gsl_tapered_roller(0.017, 2, 38.5, 4000.0, 1000.0, 1.6), 2)
    2442.64
    """
    axial = np.where(_f(Fa) > 0, _f(S2) * _f(Y) * Fa, 0.0)
    return _f(S1) * np.power(dm, 0.82) * (_f(Fr) + axial)


def _ln_grr_spherical_roller(R1, R2, R3, R4, dm, Fr, Fa):
    return np.minimum(_ln_power(_f(R1) * np.power(dm, 1.85), _f(Fr) + _f(R2) * Fa, 0.54),
                      _ln_power(_f(R3) * np.power(dm, 2.3), _f(Fr) + _f(R4) * Fa, 0.31))


@series_aware
def grr_spherical_roller(R1, R2, R3, R4, dm, Fr, Fa):
    """Grr of spherical roller bearings (table 2a; 6000 p. 91, 10000/3 p. 104; worked example 6000 p. 104).

    Grr.e = R1·dm^1.85·(Fr + R2·Fa)^0.54, Grr.l = R3·dm^2.3·(Fr + R4·Fa)^0.31;
    Grr = Grr.e if Grr.e < Grr.l, else Grr.l.

    >>> round(grr_spherical_roller(1.6e-6, 5.84, 2.81e-6, 5.8, 60.0, 2990.0, 100.0), 4)  # 22208 E: 0,26
    0.2585
    """
    return np.exp(_ln_grr_spherical_roller(R1, R2, R3, R4, dm, Fr, Fa))


@series_aware
def gsl_spherical_roller(S1, S2, S3, S4, dm, Fr, Fa):
    """Gsl of spherical roller bearings (table 2a; 6000 p. 91, 10000/3 p. 104; worked example 6000 p. 104).

    Gsl.e = S1·dm^0.25·(Fr^4 + S2·Fa^4)^(1/3), Gsl.l = S3·dm^0.94·(Fr^3 + S4·Fa^3)^(1/3);
    Gsl = Gsl.e if Gsl.e < Gsl.l, else Gsl.l (compared as cubes: one cube root).

    >>> round(gsl_spherical_roller(3.62e-3, 508, 8.8e-3, 117, 60.0, 2990.0, 100.0), 1)  # 22208 E: 434
    434.1
    """
    shape = np.broadcast_shapes(*(np.shape(v) for v in (S1, S2, S3, S4, dm, Fr, Fa)))
    Fr = np.broadcast_to(_f(Fr), shape or (1,))
    Fa = np.broadcast_to(_f(Fa), shape or (1,))
    Fr2 = Fr * Fr
    Fa2 = Fa * Fa
    Fa3 = Fa2 * Fa
    Fa2 *= Fa2
    Fa2 *= _f(S2)                                          # S2·Fa^4
    e3 = Fr2 * Fr2
    e3 += Fa2
    e3 *= _cube(_f(S1) * np.power(dm, 0.25))
    Fa3 *= _f(S4)                                          # S4·Fa^3
    Fr2 *= Fr
    Fr2 += Fa3
    Fr2 *= _cube(_f(S3) * np.power(dm, 0.94))              # Gsl.l cubed
    np.minimum(e3, Fr2, out=e3)
    return _pow(e3, 1.0 / 3.0).reshape(shape)


def _ln_grr_carb(R1, R2, dm, Fr):
    R1 = _f(R1)
    R2 = _f(R2)
    Fr = _f(Fr)
    limit = np.power(np.power(R2, 1.85) * np.power(dm, 0.78) / np.power(R1, 1.85), 2.35)
    light = Fr < limit
    with np.errstate(divide="ignore"):
        return (np.where(light, np.log(R1 * np.power(dm, 1.97)), np.log(R2 * np.power(dm, 2.37)))
                + np.where(light, 0.54, 0.31) * np.log(Fr))


@series_aware
def grr_carb(R1, R2, dm, Fr):
    """Grr of CARB toroidal roller bearings (table 2a; 6000 p. 91, 10000/3 p. 104).

    Fr < (R2^1.85·dm^0.78/R1^1.85)^2.35: Grr = R1·dm^1.97·Fr^0.54; otherwise Grr = R2·dm^2.37·Fr^0.31.
    The printed limit is used as printed (it is close to, not exactly at, the load where the branches meet).

    >>> round(grr_carb(1.17e-6, 2.08e-6, 60.0, 3000.0), 5)
    0.28105
    """
    return np.exp(_ln_grr_carb(R1, R2, dm, Fr))


@series_aware
def gsl_carb(S1, S2, dm, Fr):
    """Gsl of CARB toroidal roller bearings (table 2a; 6000 p. 91, 10000/3 p. 104).

    Fr < (S2·dm^1.24/S1)^1.5: Gsl = S1·dm^-0.19·Fr^(5/3); otherwise Gsl = S2·dm^1.05·Fr.

    >>> round(gsl_carb(1.32e-3, 0.8e-2, 60.0, 3000.0), 2)
    378.38
    """
    S1 = _f(S1)
    S2 = _f(S2)
    Fr = _f(Fr)
    limit = np.power(S2 * np.power(dm, 1.24) / S1, 1.5)
    return np.where(Fr < limit, S1 * np.power(dm, -0.19) * _pow(Fr, 5.0 / 3.0), S2 * np.power(dm, 1.05) * Fr)


def _ln_grr_thrust_ball(R1, dm, Fa):
    return _ln_power(_f(R1) * np.power(dm, 1.83), Fa, 0.54)


@series_aware
def grr_thrust_ball(R1, dm, Fa):
    """Grr = R1·dm^1.83·Fa^0.54 (table 2b; 6000 p. 92, 10000/3 p. 105).

    >>> round(grr_thrust_ball(1.03e-6, 33.5, 2000.0), 5)
    0.03857
    """
    return np.exp(_ln_grr_thrust_ball(R1, dm, Fa))


@series_aware
def gsl_thrust_ball(S1, dm, Fa):
    """Gsl = S1·dm^0.05·Fa^(4/3) (table 2b; 6000 p. 92, 10000/3 p. 105).

    >>> round(gsl_thrust_ball(1.6e-2, 33.5, 2000.0), 2)
    480.56
    """
    return _f(S1) * np.power(dm, 0.05) * _pow(Fa, 4.0 / 3.0)


def _ln_grr_thrust_cylindrical_roller(R1, dm, Fa):
    return _ln_power(_f(R1) * np.power(dm, 2.38), Fa, 0.31)


@series_aware
def grr_thrust_cylindrical_roller(R1, dm, Fa):
    """Grr = R1·dm^2.38·Fa^0.31 (table 2b; 6000 p. 92, 10000/3 p. 105).

    >>> round(grr_thrust_cylindrical_roller(2.25e-6, 33.5, 6000.0), 5)
    0.14224
    """
    return np.exp(_ln_grr_thrust_cylindrical_roller(R1, dm, Fa))


@series_aware
def gsl_thrust_cylindrical_roller(S1, dm, Fa):
    """Gsl = S1·dm^0.62·Fa (table 2b; 6000 p. 92, 10000/3 p. 105).

    >>> round(gsl_thrust_cylindrical_roller(0.154, 33.5, 6000.0), 1)
    8150.8
    """
    return _f(S1) * np.power(dm, 0.62) * Fa


def _ln_grr_spherical_roller_thrust(R1, R2, R3, R4, dm, Fr, Fa):
    return np.minimum(_ln_power(_f(R1) * np.power(dm, 1.96), _f(Fr) + _f(R2) * Fa, 0.54),
                      _ln_power(_f(R3) * np.power(dm, 2.39), _f(Fr) + _f(R4) * Fa, 0.31))


@series_aware
def grr_spherical_roller_thrust(R1, R2, R3, R4, dm, Fr, Fa):
    """Grr of spherical roller thrust bearings (table 2b; 6000 p. 92, 10000/3 p. 105).

    Grr.e = R1·dm^1.96·(Fr + R2·Fa)^0.54, Grr.l = R3·dm^2.39·(Fr + R4·Fa)^0.31;
    Grr = Grr.e if Grr.e < Grr.l, else Grr.l.

    >>> round(grr_spherical_roller_thrust(1.25e-6, 1.67, 2.15e-6, 2.86, 95.0, 0.0, 20000.0), 4)
    2.6066
    """
    return np.exp(_ln_grr_spherical_roller_thrust(R1, R2, R3, R4, dm, Fr, Fa))


@series_aware
def gsl_spherical_roller_thrust(S1, S2, S3, S4, S5, dm, Fr, Fa, n, nu):
    """Gsl of spherical roller thrust bearings (table 2b; 6000 p. 92, 10000/3 p. 105).

    Gsl.e = S1·dm^-0.35·(Fr^(5/3) + S2·Fa^(5/3)), Gsl.l = S3·dm^0.89·(Fr + Fa);
    Gsr = Gsl.e if Gsl.e < Gsl.l, else Gsl.l; Gf = S4·dm^0.76·(Fr + S5·Fa);
    Gsl = Gsr + Gf/e^(10^-6·(n·ν)^1.4·dm). n [1/min], ν [mm²/s].

    >>> round(gsl_spherical_roller_thrust(6.42e-3, 0.21, 0.04, 0.2, 0.54, 95.0, 0.0, 20000.0, 1000.0, 20.0), 2)
    4035.84
    """
    Fr = _f(Fr)
    Fa = _f(Fa)
    dm = _f(dm)
    e = _f(S1) * np.power(dm, -0.35) * (_pow(Fr, 5.0 / 3.0) + _f(S2) * _pow(Fa, 5.0 / 3.0))
    low = _f(S3) * np.power(dm, 0.89) * (Fr + Fa)
    Gf = _f(S4) * np.power(dm, 0.76) * (Fr + _f(S5) * Fa)
    return np.minimum(e, low) + Gf * np.exp(np.maximum(-1e-6 * _pow(_f(n) * nu, 1.4) * dm, _EXP_FLOOR))


# ---- the registry of table 2 rows (keys: bearingheat.catalogue.skf.FORMULA_FAMILY values) ----------------

def _deep_groove(c, dm, Fr, Fa, n, nu, C0, Y):
    with np.errstate(invalid="ignore", divide="ignore"):
        sin_alpha = _sin_alpha(deep_groove_contact_angle(Fa, C0), Fa)
    return (_ln_grr_deep_groove_ball(c["R1"], c["R2"], dm, Fr, Fa, sin_alpha),
            _gsl_deep_groove_ball(c["S1"], c["S2"], dm, Fr, Fa, sin_alpha))


def _angular(c, dm, Fr, Fa, n, nu, C0, Y):
    return (_ln_grr_angular_contact_ball(c["R1"], c["R2"], c["R3"], dm, Fr, Fa, n),
            gsl_angular_contact_ball(c["S1"], c["S2"], c["S3"], dm, Fr, Fa, n))


def _self_aligning(c, dm, Fr, Fa, n, nu, C0, Y):
    return (_ln_grr_self_aligning_ball(c["R1"], c["R2"], c["R3"], dm, Fr, Fa, n),
            gsl_self_aligning_ball(c["S1"], c["S2"], c["S3"], dm, Fr, Fa, n))


def _cylindrical(c, dm, Fr, Fa, n, nu, C0, Y):
    return _ln_grr_cylindrical_roller(c["R1"], dm, Fr), gsl_cylindrical_roller(c["S1"], c["S2"], dm, Fr, Fa)


def _tapered(c, dm, Fr, Fa, n, nu, C0, Y):
    return (_ln_grr_tapered_roller(c["R1"], c["R2"], dm, Fr, Fa, Y),
            gsl_tapered_roller(c["S1"], c["S2"], dm, Fr, Fa, Y))


def _spherical(c, dm, Fr, Fa, n, nu, C0, Y):
    return (_ln_grr_spherical_roller(c["R1"], c["R2"], c["R3"], c["R4"], dm, Fr, Fa),
            gsl_spherical_roller(c["S1"], c["S2"], c["S3"], c["S4"], dm, Fr, Fa))


def _carb(c, dm, Fr, Fa, n, nu, C0, Y):
    return _ln_grr_carb(c["R1"], c["R2"], dm, Fr), gsl_carb(c["S1"], c["S2"], dm, Fr)


def _thrust_ball(c, dm, Fr, Fa, n, nu, C0, Y):
    return _ln_grr_thrust_ball(c["R1"], dm, Fa), gsl_thrust_ball(c["S1"], dm, Fa)


def _thrust_cylindrical(c, dm, Fr, Fa, n, nu, C0, Y):
    return _ln_grr_thrust_cylindrical_roller(c["R1"], dm, Fa), gsl_thrust_cylindrical_roller(c["S1"], dm, Fa)


def _spherical_thrust(c, dm, Fr, Fa, n, nu, C0, Y):
    return (_ln_grr_spherical_roller_thrust(c["R1"], c["R2"], c["R3"], c["R4"], dm, Fr, Fa),
            gsl_spherical_roller_thrust(c["S1"], c["S2"], c["S3"], c["S4"], c["S5"], dm, Fr, Fa, n, nu))


#: formula family (row of table 2a/2b) -> f(constants, dm, Fr, Fa, n, nu, C0, Y) -> (ln Grr, Gsl)
_LN_G: dict[str, Callable] = {
    "deep_groove_ball": _deep_groove,
    "angular_contact_ball": _angular,
    "self_aligning_ball": _self_aligning,
    "cylindrical_roller": _cylindrical,
    "tapered_roller": _tapered,
    "spherical_roller": _spherical,
    "carb": _carb,
    "thrust_ball": _thrust_ball,
    "thrust_cylindrical_roller": _thrust_cylindrical,
    "spherical_roller_thrust": _spherical_thrust,
}


def _with_grr(ln_g):
    def variables(constants, dm, Fr, Fa, n, nu, C0=np.nan, Y=np.nan):
        ln_grr, Gsl = ln_g(constants, dm, Fr, Fa, n, nu, C0, Y)
        return np.exp(ln_grr), Gsl
    return variables


#: formula family (row of table 2a/2b; the values of bearingheat.catalogue.skf.FORMULA_FAMILY)
#: -> f(constants, dm, Fr, Fa, n, nu, C0, Y) -> (Grr, Gsl)
G_VARIABLES: dict[str, Callable] = {family: _with_grr(ln_g) for family, ln_g in _LN_G.items()}
#: families whose Gsl depends on the speed (Fg of ball bearings, Gf of spherical roller thrust bearings)
SPEED_DEPENDENT_GSL = frozenset({"angular_contact_ball", "self_aligning_ball", "spherical_roller_thrust"})


@series_aware
def rolling_sliding_variables(family, constants, dm, Fr, Fa, n, nu, C0=np.nan, Y=np.nan):
    """(Grr, Gsl) of one row of table 2a/2b; ``constants`` maps R1..R4, S1..S5 to numbers or arrays.

    >>> Grr, Gsl = rolling_sliding_variables("spherical_roller", dict(R1=1.6e-6, R2=5.84, R3=2.81e-6, R4=5.8,
    ...     S1=3.62e-3, S2=508, S3=8.8e-3, S4=117), 60.0, 2990.0, 100.0, 3500.0, 68.0)
    >>> round(Grr, 3), round(Gsl, 1)
    (0.258, 434.1)
    """
    return G_VARIABLES[family](constants, dm, Fr, Fa, n, nu, C0, Y)
