"""Kernels of the SKF four-component friction model, one function per published formula.

M = φish·φrs·Mrr + Msl + Mseal + Mdrag, with Mrr = Grr·(ν·n)^0.6 and
Msl = Gsl·μsl. Plain floats, numpy arrays or pandas Series in catalogue
units: d, D, dm, B, H, d_s [mm]; Fr, Fa, C0 [N]; n [1/min]; ν [mm²/s];
M [N·mm]; N_R [W]. The geometry constants R1..R4, S1..S5, Kz, KL, KS1,
KS2, β are empirical numbers defined for exactly these units
(:mod:`bearingheat.catalogue.skf` reads them from ``tables/skf_*.csv``).
No units are checked here.

References
----------
SKF General Catalogue 6000 RU, chapter «Трение», pp. 87-105 ("6000").
SKF «Подшипники качения» PUB BU/P1 10000/3 RU, August 2017, pp. 97-114
("10000/3"); its drag formula replaces the 6000 one when ``skf_edition``
is 10000. Where the two print the same formula both pages are named.

Grr and Gsl of tables 2a and 2b live in :mod:`bearingheat.kernels.skf_variables`,
the drag formulas in :mod:`bearingheat.kernels.skf_drag`; this module
re-exports them, so ``bearingheat.kernels.skf`` is the whole model.
"""
from __future__ import annotations

import numpy as np

from bearingheat.kernels import friction
from bearingheat.kernels._series import series_aware
from bearingheat.kernels.skf_drag import (
    DRAG_VISCOSITY_LIMITS,
    ball_drag_constant,
    roller_drag_constant,
    drag_torque_ball_6000,
    drag_torque_roller_6000,
    drag_width_factor,
    immersion_angle,
    immersion_factor,
    drag_area_factor,
    drag_reduced_area,
    drag_viscous_term,
    drag_torque_ball_10000,
    drag_torque_roller_10000,
    drag_viscosity_limit,
)
from bearingheat.kernels.skf_variables import (
    deep_groove_contact_angle,
    grr_deep_groove_ball,
    gsl_deep_groove_ball,
    grr_angular_contact_ball,
    gsl_angular_contact_ball,
    grr_self_aligning_ball,
    gsl_self_aligning_ball,
    grr_cylindrical_roller,
    gsl_cylindrical_roller,
    grr_tapered_roller,
    gsl_tapered_roller,
    grr_spherical_roller,
    gsl_spherical_roller,
    grr_carb,
    gsl_carb,
    grr_thrust_ball,
    gsl_thrust_ball,
    grr_thrust_cylindrical_roller,
    gsl_thrust_cylindrical_roller,
    grr_spherical_roller_thrust,
    gsl_spherical_roller_thrust,
    rolling_sliding_variables,
    G_VARIABLES,
    SPEED_DEPENDENT_GSL,
)
from bearingheat.kernels.skf_variables import _LN_G, _EXP_FLOOR, _f, _pow

__all__ = [
    "PHI_ISH_COEFFICIENT",
    "PHI_BL_COEFFICIENT",
    "DRAG_VISCOSITY_LIMITS",
    "deep_groove_contact_angle",
    "grr_deep_groove_ball", "gsl_deep_groove_ball",
    "grr_angular_contact_ball", "gsl_angular_contact_ball",
    "grr_self_aligning_ball", "gsl_self_aligning_ball",
    "grr_cylindrical_roller", "gsl_cylindrical_roller",
    "grr_tapered_roller", "gsl_tapered_roller",
    "grr_spherical_roller", "gsl_spherical_roller",
    "grr_carb", "gsl_carb",
    "grr_thrust_ball", "gsl_thrust_ball",
    "grr_thrust_cylindrical_roller", "gsl_thrust_cylindrical_roller",
    "grr_spherical_roller_thrust", "gsl_spherical_roller_thrust",
    "G_VARIABLES",
    "SPEED_DEPENDENT_GSL",
    "rolling_sliding_variables",
    "rolling_torque",
    "sliding_torque",
    "inlet_shear_heating_factor",
    "kinematic_replenishment_factor",
    "boundary_weighting_factor",
    "sliding_coefficient",
    "seal_torque",
    "seal_count_factor",
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
    "total_torque",
    "starting_torque",
    "power_loss",
    "skf_friction_torque",
]

#: φish = 1/(1 + 1.84e-9·(n·dm)^1.28·ν^0.64) (6000 p. 97; 10000/3 p. 101)
PHI_ISH_COEFFICIENT = 1.84e-9
#: φbl = 1/e^(2.6e-8·(n·ν)^1.4·dm) (6000 p. 101; 10000/3 p. 103)
PHI_BL_COEFFICIENT = 2.6e-8


# ---- the four components and their factors ------------------------------------------------------

@series_aware
def rolling_torque(Grr, nu, n):
    """Mrr = Grr·(ν·n)^0.6 [N·mm] (6000 p. 90; worked example p. 104).

    ν [mm²/s] (base oil viscosity of a grease), n [1/min]. The 10000/3
    edition (p. 100) writes the factors φish·φrs into Mrr; here Mrr is the
    6000 quantity before them, as in the worked example.

    >>> round(rolling_torque(0.26, 68.0, 3500.0))  # 22208 E: 437
    437
    """
    return _f(Grr) * _pow(_f(nu) * n, 0.6)


@series_aware
def sliding_torque(Gsl, mu_sl):
    """Msl = Gsl·μsl [N·mm] (6000 p. 90; 10000/3 p. 103).

    >>> sliding_torque(434.0, 0.05)  # 22208 E: 21,7
    21.7
    """
    return _f(Gsl) * mu_sl


@series_aware
def inlet_shear_heating_factor(n, nu, dm):
    """φish = 1/(1 + 1.84·10^-9·(n·dm)^1.28·ν^0.64) [-] (6000 p. 97; 10000/3 p. 101).

    n [1/min], ν [mm²/s], dm [mm].

    >>> round(inlet_shear_heating_factor(3500.0, 68.0, 60.0), 3)  # 22208 E: ≈ 0,85
    0.849
    """
    n = _f(n)
    # (n·dm)^1.28·ν^0.64 = dm^1.28·(n²·ν)^0.64: one power of an array
    return 1.0 / (1.0 + PHI_ISH_COEFFICIENT * np.power(dm, 1.28) * _pow(n * n * nu, 0.64))


@series_aware
def kinematic_replenishment_factor(K_rs, Kz, nu, n, d, D):
    """φrs = 1/e^(Krs·ν·n·(d + D)·sqrt(Kz/(2·(D − d)))) [-] (6000 p. 98; 10000/3 p. 102).

    Krs: 3·10^-8 oil jet and low-level oil bath, 6·10^-8 grease and oil-air;
    Krs = 0 gives φrs = 1 (no starvation: an oil bath above the centre of
    the lowest rolling element). Kz: table 5. ν [mm²/s], n [1/min], d, D [mm].

    >>> round(kinematic_replenishment_factor(3e-8, 5.5, 68.0, 3500.0, 40.0, 80.0), 3)  # 22208 E: ≈ 0,8
    0.799
    """
    d = _f(d)
    D = _f(D)
    return np.exp(np.maximum(-_f(K_rs) * nu * n * (d + D) * np.sqrt(_f(Kz) / (2.0 * (D - d))), _EXP_FLOOR))


@series_aware
def boundary_weighting_factor(n, nu, dm):
    """φbl = 1/e^(2.6·10^-8·(n·ν)^1.4·dm) [-] (6000 p. 101; 10000/3 p. 103).

    >>> round(boundary_weighting_factor(100.0, 10.0, 60.0), 4)
    0.9756
    """
    return np.exp(np.maximum(-PHI_BL_COEFFICIENT * _pow(_f(n) * nu, 1.4) * dm, _EXP_FLOOR))


@series_aware
def sliding_coefficient(phi_bl, mu_bl, mu_EHL):
    """μsl = φbl·μbl + (1 − φbl)·μEHL [-] (6000 p. 100; 10000/3 p. 103).

    >>> round(sliding_coefficient(0.5, 0.15, 0.05), 3)
    0.1
    """
    phi_bl = _f(phi_bl)
    return phi_bl * mu_bl + (1.0 - phi_bl) * mu_EHL


@series_aware
def seal_torque(KS1, d_s, beta, KS2):
    """Mseal = KS1·ds^β + KS2 [N·mm] of a bearing sealed on both sides (6000 p. 90, table 4 p. 96; 10000/3 p. 109).

    d_s [mm] the seal counterface diameter; where KS1 = 0 (RZ, RSL up to
    D = 25 mm) Mseal = KS2 whatever d_s is.

    >>> round(seal_torque(0.028, 30.0, 2.25, 2.0), 3)  # 6205-2RSH, d2 about 30 mm
    60.977
    """
    KS1 = _f(KS1)
    with np.errstate(invalid="ignore"):
        term = KS1 * np.power(d_s, beta)
    return np.where(KS1 == 0.0, 0.0, term) + KS2


@series_aware
def seal_count_factor(seals, one_seal_factor):
    """The share of Mseal for 0, 1 or 2 seals: 0, the row's one-seal factor, 1 [-] (6000 p. 90; 10000/3 p. 109).

    One seal gives 0,5 Mseal; RSL seals of bearings with D > 25 mm keep
    the full Mseal whatever the number of seals (factor 1 in table 4's row).

    >>> seal_count_factor(1, 0.5), seal_count_factor(1, 1.0), seal_count_factor(2, 0.5)
    (0.5, 1.0, 1.0)
    """
    seals = _f(seals)
    return np.where(seals >= 2, 1.0, np.where(seals == 1, one_seal_factor, 0.0))


# ---- totals ------------------------------------------------------------------------------------

@series_aware
def total_torque(phi_ish, phi_rs, M_rr, M_sl, M_seal=0.0, M_drag=0.0):
    """M = φish·φrs·Mrr + Msl + Mseal + Mdrag [N·mm] (6000 p. 96; 10000/3 p. 99).

    >>> round(total_torque(0.85, 0.8, 437.0, 21.7, 0.0, 14.5), 1)  # 22208 E: the printed chain; 334 printed
    333.4
    """
    return _f(phi_ish) * phi_rs * M_rr + M_sl + M_seal + M_drag


@series_aware
def starting_torque(M_sl_start, M_seal=0.0):
    """Mstart = Msl + Mseal [N·mm] at zero speed with μsl = μbl, ambient 20 to 30 °C (6000 p. 103; 10000/3 p. 114).

    The catalogue warns that tapered roller bearings of series 313, 322 B,
    323 B and T7FC may start up to four times higher, spherical roller
    thrust bearings up to eight times.

    >>> starting_torque(65.1, 2.0)
    67.1
    """
    return _f(M_sl_start) + M_seal


@series_aware
def power_loss(M, n):
    """Power loss NR = 1.05·10^-4·M·n [W] (6000 p. 103; 10000/3 p. 114), M [N·mm], n [1/min].

    Computed as M·n/9550 with the catalogue model's kernel
    (:func:`bearingheat.kernels.friction.power_loss`), so both models give
    the same NR for the same M; the printed factor 1.05·10^-4 is 0.27 %
    larger than 1/9550 = 1.0471·10^-4 (2π/60000 = 1.0472·10^-4).

    >>> round(power_loss(334.0, 3500.0), 1)
    122.4
    """
    return friction.power_loss(M, n)


def _sliding_coefficient_of(log_x, dm, mu_bl, mu_EHL):
    """μsl = μEHL + φbl·(μbl − μEHL), φbl = e^(-2.6e-8·e^(1.4·ln(ν·n))·dm), from ln(ν·n) (overwritten).

    The exponent 2.6e-8·(ν·n)^1.4·dm is capped at 46: beyond it φbl < 1e-20,
    φbl·(μbl − μEHL) is below half an ulp of μEHL and μsl equals μEHL to the
    last bit, and the cap keeps e^-x out of numpy's slow subnormal range.
    Every row is computed (measured: cheaper than gathering the mixed-film
    rows even when 5 % of them are).
    """
    log_x *= 1.4
    arg = np.minimum(log_x, np.log(46.0 / (PHI_BL_COEFFICIENT * dm)), out=log_x)
    np.exp(arg, out=arg)
    arg *= -PHI_BL_COEFFICIENT * dm
    phi_bl = np.exp(arg, out=arg)
    phi_bl *= mu_bl - mu_EHL
    phi_bl += mu_EHL
    return phi_bl


@series_aware
def skf_friction_torque(family, constants, d, D, Fr, Fa, n, nu, *, Kz, mu_EHL, K_rs, mu_bl=0.15, mu_sl=np.nan,
                        M_seal=0.0, M_drag=0.0, C0=np.nan, Y=np.nan):
    """Total friction torque M [N·mm] of the SKF model for resolved constants: the array kernel of the model.

    ``constants``: R1..R4, S1..S5 of the bearing (table 3); Kz (table 5),
    μEHL, Krs as in :mod:`bearingheat.catalogue.skf`; ``mu_sl`` fixes μsl
    where it is a number (NaN: μsl from φbl); Mseal and Mdrag come from
    :func:`seal_torque` and the drag kernels. Arrays of one length or scalars.

    >>> c = dict(R1=1.6e-6, R2=5.84, R3=2.81e-6, R4=5.8, S1=3.62e-3, S2=508, S3=8.8e-3, S4=117)
    >>> round(skf_friction_torque("spherical_roller", c, 40.0, 80.0, 2990.0, 100.0, 3500.0, 68.0, Kz=5.5,
    ...       mu_EHL=0.05, K_rs=3e-8, mu_sl=0.05, M_drag=14.46), 1)
    331.1
    """
    d = _f(d)
    D = _f(D)
    dm = (d + D) * 0.5
    ln_grr, Gsl = _LN_G[family](constants, dm, Fr, Fa, n, nu, C0, Y)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (d, D, Fr, Fa, n, nu, C0, Y, mu_sl, M_seal, M_drag,
                                                        K_rs, Kz, *constants.values())))
    n = _f(n)
    x = np.broadcast_to(_f(nu), shape or (1,)) * n        # ν·n, an array of the rows' shape
    with np.errstate(divide="ignore"):
        log_x = np.log(x)
        log_n = np.log(n)                                 # one value where the speed is one value
    # Grr·(ν·n)^0.6·φrs = e^(ln Grr + 0.6·ln(ν·n) − k·ν·n), k = Krs·(d + D)·sqrt(Kz/(2(D − d)))
    k = _f(K_rs) * (d + D) * np.sqrt(_f(Kz) / (2.0 * (D - d)))
    rolling = np.multiply(log_x, 0.6)
    rolling -= k * x
    rolling += ln_grr
    np.exp(rolling, out=rolling)
    # φish: (n·dm)^1.28·ν^0.64 = dm^1.28·e^(0.64·(ln n + ln(ν·n)))
    ish = np.add(log_n, log_x)
    ish *= 0.64
    np.exp(ish, out=ish)
    ish *= PHI_ISH_COEFFICIENT * np.power(dm, 1.28)
    ish += 1.0
    rolling /= ish
    mu_sl = _f(mu_sl)
    if mu_sl.ndim == 0 and not np.isnan(mu_sl):
        mu = mu_sl
    else:
        mu = _sliding_coefficient_of(log_x, dm, _f(mu_bl), _f(mu_EHL))
        if mu_sl.ndim:
            mu = np.where(np.isnan(mu_sl), mu, mu_sl)
    if np.ndim(Gsl) == rolling.ndim and np.shape(Gsl) == rolling.shape:
        Gsl *= mu                                         # Gsl is the family kernel's own new array
        rolling += Gsl
    else:
        rolling += Gsl * mu
    if np.ndim(M_seal) or M_seal != 0.0:
        rolling += M_seal
    if np.ndim(M_drag) or M_drag != 0.0:
        rolling += M_drag
    return rolling.reshape(shape)
