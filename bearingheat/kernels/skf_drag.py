"""Kernels of the SKF friction model: the drag losses of an oil bath, both catalogue editions.

Mdrag of SKF 6000 (VM·Kball·dm^5·n², 10·VM·Kroll·B·dm^4·n²) and of SKF
10000/3 (with Cw, ft, Rs and its limits on ν). Catalogue units: d, D, dm,
B, H [mm]; n [1/min]; ν [mm²/s]; Mdrag [N·mm]. VM is read by the user off
the diagram of the edition (6000 diagram 2, p. 99; 10000/3 diagram 4, p. 112).

References
----------
SKF General Catalogue 6000 RU, chapter «Трение», pp. 98-100 ("6000");
SKF «Подшипники качения» PUB BU/P1 10000/3 RU (2017), pp. 110-112 ("10000/3").
"""
from __future__ import annotations

import numpy as np

from bearingheat.kernels._series import series_aware

__all__ = [
    "ball_drag_constant",
    "roller_drag_constant",
    "drag_torque_ball_6000",
    "drag_torque_roller_6000",
    "drag_width_factor",
    "immersion_angle",
    "immersion_factor",
    "drag_area_factor",
    "drag_reduced_area",
    "drag_viscous_term",
    "drag_torque_ball_10000",
    "drag_torque_roller_10000",
    "drag_viscosity_limit",
    "DRAG_VISCOSITY_LIMITS",
]

#: ν [mm²/s] above which the 10000/3 drag formula is not valid: H <= D/2 and H > D/2 (10000/3 p. 110)
DRAG_VISCOSITY_LIMITS = (500.0, 250.0)


def _f(x):
    return np.asarray(x, dtype=float)


@series_aware
def ball_drag_constant(irw, Kz, d, D):
    """Kball = irw·Kz·(d + D)/(D − d)·10^-12 [-] (6000 p. 99; 10000/3 p. 110).

    >>> ball_drag_constant(1, 3.1, 25.0, 52.0)
    8.840740740740742e-12
    """
    d = _f(d)
    return _f(irw) * Kz * (d + D) / (_f(D) - d) * 1e-12


@series_aware
def roller_drag_constant(KL, Kz, d, D):
    """Kroll = KL·Kz·(d + D)/(D − d)·10^-12 [-] (6000 p. 99; 10000/3 p. 110; worked example p. 105).

    >>> round(roller_drag_constant(0.8, 5.5, 40.0, 80.0) * 1e12, 6)  # 22208 E: 13,2·10^-12
    13.2
    """
    d = _f(d)
    return _f(KL) * Kz * (d + D) / (_f(D) - d) * 1e-12


@series_aware
def drag_torque_ball_6000(VM, K_ball, dm, n):
    """Mdrag = VM·Kball·dm^5·n² [N·mm] of ball bearings in an oil bath (6000 p. 99).

    VM from diagram 2 (6000 p. 99, red curve) at H/dm; valid up to the
    bearing's reference speed (p. 99).

    >>> round(drag_torque_ball_6000(1e-4, 8.840740740740742e-12, 38.5, 3000.0), 4)
    0.673
    """
    return _f(VM) * K_ball * np.power(dm, 5) * np.square(n)


@series_aware
def drag_torque_roller_6000(VM, K_roll, B, dm, n):
    """Mdrag = 10·VM·Kroll·B·dm^4·n² [N·mm] of roller bearings in an oil bath (6000 p. 99; example p. 105).

    B [mm]: the inner ring width. VM from diagram 2 (blue curve).

    >>> round(drag_torque_roller_6000(0.3e-4, 13.2e-12, 23.0, 60.0, 3500.0), 2)  # 22208 E: 14,5
    14.46
    """
    return 10.0 * _f(VM) * K_roll * B * np.power(dm, 4) * np.square(n)


@series_aware
def drag_width_factor(KL, B, dm):
    """Cw = 2.789·10^-10·lD³ − 2.786·10^-4·lD² + 0.0195·lD + 0.6439, lD = 5·KL·B/dm [-] (10000/3 p. 111).

    >>> round(drag_width_factor(0.8, 23.0, 60.0), 5)
    0.67314
    """
    lD = 5.0 * _f(KL) * B / dm
    return 2.789e-10 * lD ** 3 - 2.786e-4 * lD ** 2 + 0.0195 * lD + 0.6439


@series_aware
def immersion_angle(H, dm):
    """t = 2·arccos((0.6·dm − H)/(0.6·dm)) [rad]; H > 1.2·dm counts as H = 1.2·dm (10000/3 p. 111).

    H [mm] the oil level above the lowest contact point of the outer ring raceway (fig. 2, p. 112).

    >>> round(immersion_angle(2.5, 60.0), 4)
    0.7497
    """
    dm = _f(dm)
    level = np.clip(H, 0.0, 1.2 * dm)
    return 2.0 * np.arccos((0.6 * dm - level) / (0.6 * dm))


@series_aware
def immersion_factor(t):
    """ft = sin(0.5·t) for 0 <= t <= π, 1 for π < t <= 2π [-] (10000/3 p. 111).

    The text prints π < t < 2π; t = 2π (H >= 1.2·dm) takes 1, the limit from below.

    >>> round(immersion_factor(0.7497), 4), immersion_factor(4.0)
    (0.3661, 1.0)
    """
    t = _f(t)
    return np.where(t <= np.pi, np.sin(0.5 * t), 1.0)


@series_aware
def drag_area_factor(Kz, d, D):
    """fA = 0.05·Kz·(D + d)/(D − d) [-] (10000/3 p. 111).

    >>> drag_area_factor(5.5, 40.0, 80.0)
    0.825
    """
    D = _f(D)
    return 0.05 * _f(Kz) * (D + d) / (D - d)


@series_aware
def drag_reduced_area(dm, t, f_A):
    """Rs = 0.36·dm²·(t − sin t)·fA [mm²] (10000/3 p. 111).

    >>> round(drag_reduced_area(60.0, 0.7497, 0.825), 2)
    73.02
    """
    t = _f(t)
    return 0.36 * np.square(dm) * (t - np.sin(t)) * f_A


@series_aware
def drag_viscous_term(n, nu, dm, f_t, R_s):
    """1.093·10^-7·n²·dm³·(n·dm²·ft/ν)^-1.379·Rs [N·mm], the second drag term of 10000/3 (p. 110).

    It is 0 where n = 0 or Rs = 0 (no oil: t = 0), its limit there.

    >>> round(drag_viscous_term(3500.0, 68.0, 60.0, 0.3662, 73.02), 4)
    4.591
    """
    n = _f(n)
    R_s = _f(R_s)
    live = (n > 0) & (R_s > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        value = 1.093e-7 * np.square(n) * np.power(dm, 3) * np.power(n * np.square(dm) * f_t / nu, -1.379) * R_s
    return np.where(live, value, 0.0)


@series_aware
def drag_torque_ball_10000(VM, K_ball, dm, n, nu, H, Kz, d, D):
    """Mdrag = 0.4·VM·Kball·dm^5·n² + 1.093·10^-7·n²·dm³·(n·dm²·ft/ν)^-1.379·Rs [N·mm] (10000/3 p. 110).

    Ball bearings in an oil bath; VM from diagram 4 (10000/3 p. 112) at
    H/dm; valid for ν <= 500 mm²/s (H <= D/2) or ν <= 250 mm²/s (H > D/2),
    a large reservoir, a horizontal shaft and a rotating inner ring.

    >>> round(drag_torque_ball_10000(1e-4, 8.840740740740742e-12, 38.5, 3000.0, 12.0, 5.0, 3.1, 25.0, 52.0), 4)
    0.4653
    """
    t = immersion_angle(H, dm)
    viscous = drag_viscous_term(n, nu, dm, immersion_factor(t), drag_reduced_area(dm, t, drag_area_factor(Kz, d, D)))
    return 0.4 * _f(VM) * K_ball * np.power(dm, 5) * np.square(n) + viscous


@series_aware
def drag_torque_roller_10000(VM, K_roll, B, dm, n, nu, H, Kz, KL, d, D):
    """Mdrag = 4·VM·Kroll·Cw·B·dm^4·n² + 1.093·10^-7·n²·dm³·(n·dm²·ft/ν)^-1.379·Rs [N·mm] (10000/3 p. 110).

    Roller bearings in an oil bath; B [mm] the bearing width (T of tapered
    roller bearings, the height of thrust bearings); Cw from
    :func:`drag_width_factor`; limits as :func:`drag_torque_ball_10000`.

    >>> round(drag_torque_roller_10000(0.3e-4, 13.2e-12, 23.0, 60.0, 3500.0, 68.0, 2.5, 5.5, 0.8, 40.0, 80.0), 3)
    8.485
    """
    t = immersion_angle(H, dm)
    viscous = drag_viscous_term(n, nu, dm, immersion_factor(t), drag_reduced_area(dm, t, drag_area_factor(Kz, d, D)))
    Cw = drag_width_factor(KL, B, dm)
    return 4.0 * _f(VM) * K_roll * Cw * B * np.power(dm, 4) * np.square(n) + viscous


@series_aware
def drag_viscosity_limit(H, D):
    """The largest ν [mm²/s] of the 10000/3 drag formula: 500 for H <= D/2, 250 for H > D/2 (10000/3 p. 110).

    >>> drag_viscosity_limit(10.0, 80.0), drag_viscosity_limit(50.0, 80.0)
    (500.0, 250.0)
    """
    return np.where(_f(H) <= 0.5 * _f(D), DRAG_VISCOSITY_LIMITS[0], DRAG_VISCOSITY_LIMITS[1])
