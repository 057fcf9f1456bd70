"""Kernels of the ball bearing contact: contact angle from clearance, Hertz contact of the races,
stiffness characteristic C*, working contact angle under axial load, minimum axial load.

Source: В.А. Зайцев, В.А. Воронкин, «Расчёт осевых усилий и рабочих
углов контакта подшипников качения при оценке их качества на стендах»
(ФГУП «НПП ВНИИЭМ», 2009). The static load factors X0, Y0 of the DP11A manual, table 1
are looked up in :mod:`bearingheat.catalogue.contact`; the unit-aware
:func:`~bearingheat.api.contact.ball_bearing_contact` is in :mod:`bearingheat.api.contact`.

Kernels take plain floats, numpy arrays or pandas Series in catalogue units
(mm, N, 1/min, angles in degrees), broadcast, and give a Series back when a
Series goes in (:func:`~bearingheat.kernels._series.series_aware`). NaN inputs
(a row without geometry) give NaN out. Bad values raise
:class:`~bearingheat.errors.ContactInputError` (a ValueError) naming the value
and, for an array or Series, its element or row.

The paper works in kgf and cm; here every kernel is in N and mm. The paper's
constants are kept as typed and converted once:

* ``0.592e-4 (cm²/kgf)^(2/3)`` -- the Hertz compliance of two steel bodies,
  ``(3(1 - ν²)/E)^(2/3) / 2`` with E = 2.08e5 N/mm² (2.12e6 kgf/cm²), ν = 0.3;
  in mm and N it is :data:`HERTZ_COMPLIANCE_MM_N` = 2.784e-4 (mm²/N)^(2/3).
* ``5.75e-12 kgf·min²/mm⁴`` -- the gyroscopic-sliding constant,
  ρπ/(240 μ)·(2π/60)² with ρ = 7.85 g/cm³ and a friction coefficient μ = 0.02.

The worked example of the paper, bearing 4-1006095 (5 × 13 × 4 mm), at
Fa = 2 kgf:

>>> C = stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16)
>>> round(C / KGF)                       # paper: 7792 kgf (table readings of 2K/(μπ))
7803
>>> alpha = working_contact_angle(2 * KGF, C, 12.0)
>>> degrees_to_dms(alpha)                # paper: 14°28′ (exact root at its C* = 7792 kgf: 14°28′04″)
'14°27′57″'
>>> round(axial_displacement_ratio(alpha, 12.0), 5)   # paper: 0.04448
0.04443
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearingheat.errors import ContactInputError
from bearingheat.kernels._contact_refusals import (SERIES_ALPHA0_MIN, SERIES_LOAD_RATIO_MAX, SERIES_MAX_NEWTON_STEPS,
                                                   SERIES_TOLERANCE_RAD, _ball_refusal, _balls_refusal, _broadcast,
                                                   _check_alpha0, _check_ball, _check_balls,
                                                   _check_deflection_coefficients, _check_grooves, _check_load,
                                                   _check_outer_groove, _check_pitch, _check_series_range,
                                                   _check_working_angle, _kernel,
                                                   _pitch_refusal, _refuse)
from bearingheat.kernels._series import series_aware

__all__ = [
    "KGF",
    "HERTZ_COMPLIANCE_CM_KGF",
    "HERTZ_COMPLIANCE_MM_N",
    "GYROSCOPIC_CONSTANT_KGF",
    "minimum_axial_load_rows",
    "initial_contact_angle",
    "initial_contact_angle_052",
    "RaceCurvatures",
    "race_curvatures",
    "HertzCoefficients",
    "hertz_coefficients",
    "race_compliance",
    "stiffness_characteristic",
    "axial_load_at_angle",
    "axial_displacement_ratio",
    "axial_displacement",
    "working_contact_angle",
    "series_coefficients",
    "series_start",
    "newton_increment",
    "SeriesIterate",
    "series_iterates",
    "SERIES_ALPHA0_MIN",
    "SERIES_LOAD_RATIO_MAX",
    "SERIES_TOLERANCE_RAD",
    "SERIES_MAX_NEWTON_STEPS",
    "working_contact_angle_series",
    "minimum_axial_load",
    "degrees_to_dms",
]

KGF = 9.80665
"""Newtons per kilogram-force (standard gravity)."""

HERTZ_COMPLIANCE_CM_KGF = 0.592e-4
"""Zaitsev & Voronkin constant in c = 0.592e-4·(2K/μπ)·(d_w·Σρ)^(1/3), unit (cm²/kgf)^(2/3).

Hertz: δ = (2K/μπ)·(3(1-ν²)/E)^(2/3)·Q^(2/3)·Σρ^(1/3)/2 for two bodies of one
steel, so δ/d_w = c·(Q/d_w²)^(2/3) with c = (2K/μπ)·k·(d_w·Σρ)^(1/3) and
k = (3(1-ν²)/E)^(2/3)/2. E = 2.08e5 N/mm² = 2.121e6 kgf/cm², ν = 0.3 give
k = 0.5916e-4 (cm²/kgf)^(2/3).
"""

HERTZ_COMPLIANCE_MM_N = HERTZ_COMPLIANCE_CM_KGF * (100.0 / KGF) ** (2.0 / 3.0)
"""The same constant in (mm²/N)^(2/3): 1 cm²/kgf = 100 mm² / 9.80665 N (≈ 2.784e-4)."""

GYROSCOPIC_CONSTANT_KGF = 5.75e-12
"""Zaitsev & Voronkin constant of the minimum axial load, kgf·min²/mm⁴ (d_w, D0 in mm, n in 1/min)."""

_DEG = math.pi / 180.0
_ROUNDING = 1e-12  # relative rounding of a clearance typed at its limit (420 um in mm: 0.42000000000000004)


# --------------------------------------------------------------------------- initial contact angle
@_kernel
def initial_contact_angle(e, r_i, r_o, d_w):
    """Initial contact angle from the mean radial clearance [deg] (Zaitsev & Voronkin, p. 1).

    α0 = arccos[1 − e / (2(r_i + r_o − d_w))]

    e: mean radial clearance [mm] (catalogue value of the clearance group);
    r_i, r_o: groove radii of the inner and outer ring [mm]; d_w: ball
    diameter [mm]. Valid for 0 ≤ e ≤ 2(r_i + r_o − d_w) (α0 up to 90°).

    >>> round(initial_contact_angle(0.01, 1.05, 1.16, 2.0), 4)
    12.5279
    """
    e, r_i, r_o, d_w = _broadcast(e, r_i, r_o, d_w)
    _check_ball(d_w)
    _check_grooves(r_i, r_o, d_w)
    _refuse(e < 0, "e = {e:g} mm: the radial clearance must not be negative", e=e)
    span = 2.0 * (r_i + r_o - d_w)
    _refuse(e > span * (1.0 + _ROUNDING),  # (the limit itself is valid: 90 deg; its float may round either way)
            "e = {e:g} mm exceeds 2*(r_i + r_o - d_w) = {span:g} mm: the contact angle would pass 90 deg",
            e=e, span=span)
    return np.degrees(np.arccos(1.0 - np.minimum(e / span, 1.0)))  # (at the limit: 90 deg, not 90 + 1e-14)


@_kernel
def initial_contact_angle_052(e, d_w):
    """Initial contact angle for groove radii r_i = r_o = 0.52·d_w [deg] (Zaitsev & Voronkin, p. 1).

    α0 = arccos(1 − 12.5·e/d_w), the case r_i + r_o − d_w = 0.04·d_w of
    :func:`initial_contact_angle`. e, d_w in mm; valid for 0 ≤ e ≤ 0.08·d_w.

    >>> round(initial_contact_angle_052(0.01, 2.0), 4)
    20.3641
    """
    e, d_w = _broadcast(e, d_w)
    _check_ball(d_w)
    _refuse(e < 0, "e = {e:g} mm: the radial clearance must not be negative", e=e)
    _refuse(e > 0.08 * d_w * (1.0 + _ROUNDING),
            "e = {e:g} mm exceeds 0.08*d_w = {span:g} mm: the contact angle would pass 90 deg",
            e=e, span=0.08 * d_w)
    return np.degrees(np.arccos(1.0 - np.minimum(12.5 * e / d_w, 1.0)))


# --------------------------------------------------------------------------- Hertz contact
class RaceCurvatures(NamedTuple):
    """Curvature sums Σρ [1/mm] and auxiliaries cos τ = F(ρ) [1] of the inner and outer contact."""

    sum_rho_i: Any
    sum_rho_o: Any
    cos_tau_i: Any
    cos_tau_o: Any


def race_curvatures(d_w, d_m, alpha0, r_i, r_o) -> RaceCurvatures:
    """Curvature sums and auxiliaries of the ball–race contacts (Zaitsev & Voronkin, p. 2).

    With γ = d_w·cos α0 / d_m and the groove conformities f = r/d_w:

    Σρ_i = (1/d_w)·[4 − 1/f_i + 2γ/(1 − γ)],  cos τ_i = [1/f_i + 2γ/(1 − γ)] / (d_w·Σρ_i)

    Σρ_o = (1/d_w)·[4 − 1/f_o − 2γ/(1 + γ)],  cos τ_o = [1/f_o − 2γ/(1 + γ)] / (d_w·Σρ_o)

    This is the paper's form in T/(d_w cos α0) with the groove-centre diameters
    T_i = d_m + (2r_i − d_w)·cos α0 and T_o = d_m − (2r_o − d_w)·cos α0 (the
    paper's T_в = d_1 + 2r_в, T_н = D_1 − 2r_н) and its "± 2ξ − 1" read as
    "± (2ξ − 1)". d_w, d_m, r_i, r_o in mm, α0 in degrees. cos τ_o ≥ 0 needs r_o no larger than the
    outer race's radius along the rolling direction, (d_m + d_w·cos α0)/(2·cos α0); a larger r_o is refused.

    >>> rc = race_curvatures(2.0, 8.7355, 12.0, 1.05, 1.16)
    >>> [round(v, 7) for v in rc]           # paper: 1.3361919, 0.9549594, 0.9287242, 0.7111268
    [1.336192, 0.9549594, 0.9287242, 0.7111269]
    """
    return RaceCurvatures(*_race_curvatures(d_w, d_m, alpha0, r_i, r_o))


@_kernel
def _race_curvatures(d_w, d_m, alpha0, r_i, r_o):
    d_w, d_m, alpha0, r_i, r_o = _broadcast(d_w, d_m, alpha0, r_i, r_o)
    _check_ball(d_w)
    _check_grooves(r_i, r_o, d_w)
    _check_pitch(d_m, d_w)
    _check_alpha0(alpha0)
    _check_outer_groove(d_w, d_m, alpha0, r_o)
    gamma = d_w * np.cos(alpha0 * _DEG) / d_m
    inner_rolling = 2.0 * gamma / (1.0 - gamma)
    outer_rolling = 2.0 * gamma / (1.0 + gamma)
    sum_i = (4.0 - d_w / r_i + inner_rolling) / d_w
    sum_o = (4.0 - d_w / r_o - outer_rolling) / d_w
    cos_i = (d_w / r_i + inner_rolling) / (d_w * sum_i)
    cos_o = (d_w / r_o - outer_rolling) / (d_w * sum_o)
    return sum_i, sum_o, cos_i, cos_o


class HertzCoefficients(NamedTuple):
    """Hertz coefficients of one contact: ellipticity κ = a/b, μ (= a*), ν (= b*), and 2K/(μπ) (= δ*)."""

    kappa: Any
    mu: Any
    nu: Any
    deflection: Any


def _auxiliary_of_parameter(m):
    """cos τ = F(ρ) as a function of the parameter m = e² = 1 − 1/κ² of the contact ellipse."""
    big_e = ellipe(m)
    return ((2.0 - m) * big_e - 2.0 * (1.0 - m) * ellipk(m)) / (m * big_e)


_M_LOW = 1e-12
_M_HIGH = 1.0 - 1e-15


def _parameter_for(cos_tau: float) -> float:
    if math.isnan(cos_tau):
        return math.nan
    if cos_tau <= _auxiliary_of_parameter(_M_LOW):
        return 0.0  # circular contact (κ = 1)
    return brentq(lambda m: _auxiliary_of_parameter(m) - cos_tau, _M_LOW, _M_HIGH, xtol=1e-16, maxiter=200)


def hertz_coefficients(cos_tau) -> HertzCoefficients:
    """Hertz coefficients from the auxiliary cos τ = F(ρ), exact from the complete elliptic integrals.

    κ solves F(ρ) = [(κ² + 1)·E(m) − 2K(m)] / [(κ² − 1)·E(m)] with m = 1 − 1/κ²;
    then μ = (2κ²E/π)^(1/3), ν = (2E/(πκ))^(1/3) and 2K/(μπ) is the deflection
    coefficient of the paper (Harris's δ*). The paper reads these from a table
    (Zaitsev & Voronkin, p. 3: μν = 1.52, 2K/μπ = 0.63 at cos τ = 0.9287; μν = 1.17,
    0.852 at 0.7111). Valid for 0 ≤ cos τ < 1 (dimensionless).

    >>> h = hertz_coefficients(0.9287242)
    >>> round(h.mu * h.nu, 2), round(h.deflection, 4)
    (1.52, 0.6283)
    """
    return HertzCoefficients(*_hertz_coefficients(cos_tau))


@_kernel
def _hertz_coefficients(cos_tau):
    (cos_tau,) = _broadcast(cos_tau)
    _refuse((cos_tau < 0) | (cos_tau >= 1), "cos_tau = {c:g} must lie in [0, 1)", c=cos_tau)
    m = np.vectorize(_parameter_for, otypes=[float])(cos_tau)
    kappa = 1.0 / np.sqrt(1.0 - m)
    big_e = ellipe(m)
    mu = np.cbrt(2.0 * kappa**2 * big_e / np.pi)
    nu = np.cbrt(2.0 * big_e / (np.pi * kappa))
    deflection = 2.0 * ellipk(m) / (np.pi * mu)
    return kappa, mu, nu, deflection


@_kernel
def race_compliance(d_w, sum_rho, deflection):
    """Compliance c of one ball–race contact [(mm²/N)^(2/3)] (Zaitsev & Voronkin, p. 2).

    c = k·(2K/μπ)·(d_w·Σρ)^(1/3), k = :data:`HERTZ_COMPLIANCE_MM_N` (the paper's
    0.592e-4 (cm²/kgf)^(2/3)); the normal approach is δ = c·d_w·(Q/d_w²)^(2/3).
    d_w in mm, Σρ in 1/mm, 2K/(μπ) dimensionless.

    >>> round(race_compliance(2.0, 1.3361919, 0.63) / (100 / KGF) ** (2 / 3), 9)  # paper: 0.5176e-4 (cm²/kgf)^(2/3)
    5.1756e-05
    """
    d_w, sum_rho, deflection = _broadcast(d_w, sum_rho, deflection)
    return HERTZ_COMPLIANCE_MM_N * deflection * np.cbrt(d_w * sum_rho)


@_kernel
def stiffness_characteristic(z, d_w, d_m, alpha0, r_i, r_o, *, deflection_coefficients=None):
    """Stiffness ("force") characteristic C* of the bearing [N] (Zaitsev & Voronkin, p. 2).

    C* = (ξ / (c_o + c_i))^(3/2)·z·d_w²,  ξ = r_i/d_w + r_o/d_w − 1,
    c from :func:`race_compliance` with Σρ, cos τ from :func:`race_curvatures`
    and 2K/(μπ) from :func:`hertz_coefficients`. z balls; d_w, d_m (pitch
    diameter), r_i, r_o in mm; α0 in degrees.

    ``deflection_coefficients=(inner, outer)`` replaces the exact 2K/(μπ) by
    given values, e.g. the paper's table readings (0.63, 0.852); each must lie in (0, 1] (1 for a
    circular contact).

    >>> round(stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16,
    ...                                deflection_coefficients=(0.63, 0.852)) / KGF)   # paper: 7792 kgf
    7792
    """
    z, d_w, d_m, alpha0, r_i, r_o = _broadcast(z, d_w, d_m, alpha0, r_i, r_o)
    _check_balls(z)
    curv = race_curvatures(d_w, d_m, alpha0, r_i, r_o)
    if deflection_coefficients is None:
        deflection_i = hertz_coefficients(curv.cos_tau_i).deflection
        deflection_o = hertz_coefficients(curv.cos_tau_o).deflection
    else:
        deflection_i, deflection_o = deflection_coefficients
        _check_deflection_coefficients(deflection_i, deflection_o)
    c_i = race_compliance(d_w, curv.sum_rho_i, deflection_i)
    c_o = race_compliance(d_w, curv.sum_rho_o, deflection_o)
    xi = (r_i + r_o) / d_w - 1.0
    return (xi / (np.asarray(c_o) + np.asarray(c_i))) ** 1.5 * z * d_w**2


# --------------------------------------------------------------------------- working contact angle
def _cosine_drop(alpha0_rad, x_rad):
    """cos α0 − cos(α0 + x) = 2·sin(α0 + x/2)·sin(x/2), x = α − α0 [rad]: from the increment itself, without the
    cancellation of the difference, and exact for an x below the spacing of floats at α0."""
    return 2.0 * np.sin(alpha0_rad + x_rad / 2.0) * np.sin(x_rad / 2.0)


def _deformation_term(alpha0_rad, x_rad):
    """cos α0 / cos(α0 + x) − 1 [1] (:func:`_cosine_drop` over cos(α0 + x)), x = α − α0 [rad]."""
    return _cosine_drop(alpha0_rad, x_rad) / np.cos(alpha0_rad + x_rad)


def _angle_function(alpha0_rad, x_rad):
    """(cos α0 / cos(α0 + x) − 1)·sin^(2/3)(α0 + x) = (Fa/C*)^(2/3) at the angle α0 + x (Zaitsev & Voronkin, p. 2)."""
    return _deformation_term(alpha0_rad, x_rad) * np.sin(alpha0_rad + x_rad) ** (2.0 / 3.0)


@_kernel
def axial_load_at_angle(alpha, alpha0, C_star):
    """Axial load that turns the contact angle from α0 to α [N] (Zaitsev & Voronkin, p. 2).

    Fa = C*·(cos α0 / cos α − 1)^(3/2)·sin α, α ≥ α0 in degrees, C* in N.

    >>> round(axial_load_at_angle(14.467, 12.0, 7792.0), 3)   # kgf in, kgf out
    1.999
    """
    alpha, alpha0, C_star = _broadcast(alpha, alpha0, C_star)
    _check_working_angle(alpha, alpha0)
    return _load_at_increment(C_star, alpha0, (alpha - alpha0) * _DEG)


@series_aware
def _load_at_increment(C_star, alpha0, x):
    """Fa = C*·(cos α0/cos(α0 + x) − 1)^(3/2)·sin(α0 + x) [force of C*] from x = α − α0 [rad], α0 [deg]: the load of an
    iterate x_k of the series method, exact also where α0 + x rounds to α0 in degrees."""
    C_star, alpha0, x = _broadcast(C_star, alpha0, x)
    a0r = alpha0 * _DEG
    return C_star * _deformation_term(a0r, x) ** 1.5 * np.sin(a0r + x)


@_kernel
def axial_displacement_ratio(alpha, alpha0):
    """Dimensionless axial displacement ξ_a of the rings [1] (Zaitsev & Voronkin, p. 2).

    tg α = tg α0 + ξ_a / cos α0, so ξ_a = (tg α − tg α0)·cos α0. The axial
    displacement is δ_a = ξ_a·(r_i + r_o − d_w). Angles in degrees, valid for
    0 ≤ α0 ≤ α < 90° (the axial load turns the angle up from α0; ξ_a grows
    without bound towards 90°).

    >>> round(axial_displacement_ratio(14.4670, 12.0), 5)
    0.04445
    """
    alpha, alpha0 = _broadcast(alpha, alpha0)
    _check_working_angle(alpha, alpha0)
    a, a0 = alpha * _DEG, alpha0 * _DEG
    return (np.tan(a) - np.tan(a0)) * np.cos(a0)


@_kernel
def axial_displacement(xi_a, r_i, r_o, d_w):
    """Axial displacement of the rings δ_a = ξ_a·(r_i + r_o − d_w) [mm] (Zaitsev & Voronkin, p. 2).

    ξ_a from :func:`axial_displacement_ratio` [1]; groove radii r_i, r_o and
    ball diameter d_w [mm]; r_i + r_o − d_w is the distance of the groove
    centres at zero clearance.

    >>> round(axial_displacement(0.04443, 1.05, 1.16, 2.0), 6)
    0.00933
    """
    xi_a, r_i, r_o, d_w = _broadcast(xi_a, r_i, r_o, d_w)
    return xi_a * (r_i + r_o - d_w)


def _solve_increment(load_ratio_23: float, alpha0_rad: float) -> float:
    """x = α − α0 [rad] of the working angle (so that α = α0 + x is never below α0 in floating point)."""
    if math.isnan(load_ratio_23) or math.isnan(alpha0_rad):
        return math.nan
    if load_ratio_23 == 0.0:
        return 0.0

    def residual(x):
        return _angle_function(alpha0_rad, x) - load_ratio_23

    # residual(0) < 0 and residual -> +inf as alpha -> 90 deg; it increases in between.
    return brentq(residual, 0.0, math.pi / 2.0 - alpha0_rad, xtol=1e-15, maxiter=200)


@_kernel
def working_contact_angle(Fa, C_star, alpha0):
    """Working contact angle under the axial load Fa [deg] (Zaitsev & Voronkin, p. 2), by Brent's bracketing method.

    Solves Fa = C*·(cos α0 / cos α − 1)^(3/2)·sin α for α in [α0, 90°), written
    as (cos α0 / cos α − 1)·sin^(2/3) α = (Fa/C*)^(2/3), which increases
    monotonically in α. Fa, C* in N (any one force unit for both); α0 in
    degrees, 0 ≤ α0 < 90°. Fa = 0 gives α0. Fa and C* must be finite, Fa/C* at most 1e6 (α is then
    within 0.01° of 90°).

    >>> round(working_contact_angle(2.0, 7792.0, 12.0), 4)     # kgf in; paper: 14°28′
    14.4677
    """
    Fa, C_star, alpha0 = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star)
    _check_alpha0(alpha0)
    ratio = (Fa / C_star) ** (2.0 / 3.0)
    x = np.vectorize(_solve_increment, otypes=[float])(ratio, alpha0 * _DEG)
    return alpha0 + np.degrees(x)


def _check_series_alpha0(alpha0):
    _check_alpha0(alpha0)
    _refuse(alpha0 == 0,
            "alpha0 = {a:g} deg: the series method of Zaitsev & Voronkin needs alpha0 > 0 "
            "(no expansion in powers of x at alpha0 = 0); use working_contact_angle", a=alpha0)


@_kernel
def series_coefficients(Fa, C_star, alpha0):
    """Coefficients a_0..a_4 of f(x) = Σ a_k x^k, α = α0 + x [rad] (Zaitsev & Voronkin, p. 2).

    f(x) = [cos α0 / cos(α0 + x) − 1]·sin^(2/3)(α0 + x) − (Fa/C*)^(2/3);
    a_0 = −(Fa/C*)^(2/3), a_1 = sin^(2/3)α0·tg α0,
    a_2 = ½·sin^(2/3)α0·(sec²α0 + tg²α0 + 4/3),
    a_3 = (1/9)·sin^(2/3)α0·(1.5 tg α0 + 2 ctg α0 + 9 sec²α0 tg α0),
    a_4 = (1/9)·sin^(2/3)α0·[(4/9 − sec²α0 + ½ sec⁴α0)·ctg²α0 + 4.375 sec⁴α0
    + 4.25 sec²α0 tg²α0 + 0.375 tg⁴α0]. Requires α0 > 0 (degrees).

    >>> [round(a, 4) for a in series_coefficients(0.0, 1.0, 12.0)]
    [0.0, 0.0746, 0.4253, 0.4573, 0.1472]
    """
    Fa, C_star, alpha0 = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star)
    _check_series_alpha0(alpha0)
    a0r = alpha0 * _DEG
    s23 = np.sin(a0r) ** (2.0 / 3.0)
    t, ct, sec2 = np.tan(a0r), 1.0 / np.tan(a0r), 1.0 / np.cos(a0r) ** 2
    coefficients = (
        -((Fa / C_star) ** (2.0 / 3.0)),
        s23 * t,
        0.5 * s23 * (sec2 + t**2 + 4.0 / 3.0),
        s23 / 9.0 * (1.5 * t + 2.0 * ct + 9.0 * sec2 * t),
        s23 / 9.0 * ((4.0 / 9.0 - sec2 + 0.5 * sec2**2) * ct**2 + 4.375 * sec2**2
                     + 4.25 * sec2 * t**2 + 0.375 * t**4),
    )
    return coefficients


@_kernel
def series_start(Fa, C_star, alpha0):
    """Quadratic start x_0 ≈ α − α0 [rad] (Zaitsev & Voronkin, p. 2), the root of a_0 + a_1 x + a_2 x² = 0.

    x_0 = (3/2)·sin 2α0 / (6 + cos²α0)·[√(1 + (2/3)·(6 + cos²α0)/sin²α0·(Fa/(C*·sin α0))^(2/3)) − 1]

    (the paper prints sin²α0 in the prefactor: OCR damage of sin 2α0, see
    docs/contact.md). Fa, C* in one force unit; α0 > 0 in degrees.

    >>> round(series_start(2.0, 7792.0, 12.0), 7)    # paper: 0.0433985, which needs C* = 7793.0
    0.0434016
    """
    Fa, C_star, alpha0 = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star)
    _check_series_alpha0(alpha0)
    a0r = alpha0 * _DEG
    sin2, cos2 = np.sin(a0r) ** 2, np.cos(a0r) ** 2
    load = (Fa / (C_star * np.sin(a0r))) ** (2.0 / 3.0)
    root_argument = 2.0 / 3.0 * (6.0 + cos2) / sin2 * load
    # √(1 + u) − 1 written u/(√(1 + u) + 1): the same number without the cancellation that gave x0 = 0 for u < 1e-16
    x0 = 1.5 * np.sin(2.0 * a0r) / (6.0 + cos2) * root_argument / (np.sqrt(1.0 + root_argument) + 1.0)
    return x0


@_kernel
def newton_increment(Fa, C_star, alpha0, x):
    """Newton correction of x = α − α0 [rad] (Zaitsev & Voronkin, p. 2): x_{k+1} = x_k + Δx_k.

    Δx_k = [(Fa/Fa_k)^(2/3) − 1] / [tg α_k + (2/3)·ctg α_k + sin α_k/(cos α0 − cos α_k)],
    α_k = α0 + x_k, Fa_k = C*·(cos α0/cos α_k − 1)^(3/2)·sin α_k. The
    denominator is (2/3)·d ln Fa/dα. Requires x > 0 (or Fa = 0, giving 0).

    >>> x0 = series_start(2.0, 7792.0, 12.0)
    >>> round(x0 + newton_increment(2.0, 7792.0, 12.0, x0), 7)   # paper: 0.0430573; exact root 0.0430689
    0.0430694
    """
    Fa, C_star, alpha0, x = _broadcast(Fa, C_star, alpha0, x)
    _check_load(Fa, C_star)
    _check_series_alpha0(alpha0)
    _refuse((x <= 0) & (Fa > 0), "x = {x:g} rad: the Newton step needs alpha_k > alpha0", x=x)
    a0r = alpha0 * _DEG
    ak = a0r + x
    with np.errstate(divide="ignore", invalid="ignore"):
        # (Fa/Fa_k)^(2/3) as (Fa/C*)^(2/3) over the angle function: Fa_k itself underflows at a tiny load
        load_ratio_23 = (Fa / C_star) ** (2.0 / 3.0) / _angle_function(a0r, x)
        # cos α0 − cos α_k without the cancellation of a small x (0 below x ≈ 1e-16)
        slope = np.tan(ak) + 2.0 / 3.0 / np.tan(ak) + np.sin(ak) / _cosine_drop(a0r, x)
        step = (load_ratio_23 - 1.0) / slope
    return np.where(Fa == 0, 0.0, step)


class SeriesIterate(NamedTuple):
    """One row of the paper's iteration table: x_k [rad], α [deg], ξ_a, Fa_k [force], Δ [%]."""

    k: int
    x: Any
    alpha: Any
    xi_a: Any
    load: Any
    deviation_percent: Any


def series_iterates(Fa, C_star, alpha0, newton_steps: int = 1) -> list[SeriesIterate]:
    """The paper's iteration table: x_0 from :func:`series_start`, then ``newton_steps`` Newton steps.

    Row k holds x_k, α = α0 + x_k [deg], ξ_a at α, the load Fa_k at α and
    Δ_k = (Fa_k − Fa)/Fa·100 [%] (Zaitsev & Voronkin, p. 3). Fa, C* in one force unit. Fa = 0 gives
    x = 0, α = α0 and Δ = 0 in every row. The range of :func:`working_contact_angle_series`.

    >>> rows = series_iterates(2.0, 7792.0, 12.0, newton_steps=1)
    >>> [(round(r.x, 7), round(r.load, 3)) for r in rows]    # paper: (0.0433985, 2.029), (0.0430573, 2.001)
    [(0.0434016, 2.028), (0.0430694, 2.0)]
    """
    if int(newton_steps) != newton_steps or newton_steps < 0:
        raise ContactInputError(f"newton_steps = {newton_steps!r} must be a whole number >= 0")
    x = _series_start_in_range(Fa, C_star, alpha0)
    rows = []
    for k in range(int(newton_steps) + 1):
        if k:
            x = x + newton_increment(Fa, C_star, alpha0, x)
        alpha = alpha0 + x * (180.0 / math.pi)
        load = _load_at_increment(C_star, alpha0, x)
        rows.append(SeriesIterate(k, x, alpha, axial_displacement_ratio(alpha, alpha0), load,
                                  _deviation_percent(load, Fa)))
    return rows


@_kernel
def _series_start_in_range(Fa, C_star, alpha0):
    """:func:`series_start` where the series method converges, refused (naming the row of a Series) outside its range."""
    Fa, C_star, alpha0 = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star)
    _check_series_alpha0(alpha0)
    _check_series_range(Fa, C_star, alpha0)
    return series_start(Fa, C_star, alpha0)


@series_aware
def _deviation_percent(load, Fa):
    """Δ = (Fa_k − Fa)/Fa·100 [%] (Zaitsev & Voronkin, p. 3), 0 where Fa = 0: the iterates stay at α0 there
    (x_0 = 0, Newton step 0), so Fa_k = 0 = Fa exactly, for a scalar Fa as for an array."""
    load, Fa = _broadcast(load, Fa)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(Fa == 0, 0.0, (load - Fa) / Fa * 100.0)


@_kernel
def working_contact_angle_series(Fa, C_star, alpha0):
    """Working contact angle by the paper's series start and Newton steps [deg] (Zaitsev & Voronkin, p. 2).

    Same equation as :func:`working_contact_angle`. The step is Newton's method on Fa^(2/3): from the quadratic
    start x_0 it is repeated until a step is at most :data:`SERIES_TOLERANCE_RAD` = 1e-12 rad (2e-7″), at most
    :data:`SERIES_MAX_NEWTON_STEPS` = 20 steps. Two steps, the paper's "k = 2", give a fraction of an arc second at
    its loads (Fa/C* = 2.6e-4 at α0 = 12°: 2e-7″), but 0.60° too much at α0 = 2°, Fa/C* = 0.01 (α = 23.11°),
    which takes six.

    Range: α0 from :data:`SERIES_ALPHA0_MIN` = 0.5° to 90°, Fa/C* from 0 to :data:`SERIES_LOAD_RATIO_MAX` = 0.01,
    where the steps come below the tolerance within eight; outside it the series method is refused (at α0 = 0.1°,
    Fa/C* = 0.009 or at α0 = 5°, Fa/C* = 0.4 its Newton steps leave [α0, 90°) and give NaN), and
    :func:`working_contact_angle` solves any load. Fa, C* in one force unit, α0 in degrees.

    >>> round(working_contact_angle_series(2.0, 7792.0, 12.0), 6) == round(working_contact_angle(2.0, 7792.0, 12.0), 6)
    True
    """
    Fa, C_star, alpha0 = _broadcast(Fa, C_star, alpha0)
    x = _series_start_in_range(Fa, C_star, alpha0)
    for _ in range(SERIES_MAX_NEWTON_STEPS):
        step = newton_increment(Fa, C_star, alpha0, x)
        x = x + step
        if not (np.abs(step) > SERIES_TOLERANCE_RAD).any():  # (NaN rows, without geometry, count as converged)
            break
    else:
        _refuse(np.abs(step) > SERIES_TOLERANCE_RAD,
                "Fa = {Fa:g} N with C_star = {C:g} N, alpha0 = {a0:g} deg: the Newton steps of the series method did "
                f"not come below {SERIES_TOLERANCE_RAD:g} rad in {SERIES_MAX_NEWTON_STEPS} steps; use "
                "working_contact_angle", Fa=Fa, C=C_star, a0=alpha0)
    return alpha0 + np.degrees(x)


# --------------------------------------------------------------------------- minimum axial load
@_kernel
def minimum_axial_load(z, d_w, d_pitch, n, alpha):
    """Minimum axial load against gyroscopic sliding of the balls [N] (Zaitsev & Voronkin, p. 1).

    Fa_min = 5.75e-12·z·d_w³·D0·n²·sin²α·[1 − (d_w/D0)²·cos²α] kgf, times 9.80665 N/kgf.

    z balls, d_w ball diameter [mm], D0 = ``d_pitch`` pitch diameter [mm],
    n inner-ring speed [1/min], α contact angle [deg] (the paper takes α0 from
    the clearance; the working angle under Fa gives the larger, stricter value).
    The constant is ρπ/(240μ)·(2π/60)²/g for ρ = 7.85 g/cm³ and μ = 0.02: the
    gyroscopic moment J·ω_ball·ω_cage·sin α of a ball (J = m·d_w²/10, cage at
    n/2) held by the friction μ·Q·d_w of its two contacts. NaN inputs give NaN.

    >>> round(minimum_axial_load(7, 2.0, 8.7355, 30000, 12.0) / KGF, 4)   # kgf
    0.1039
    """
    z, d_w, d_pitch, n, alpha = _broadcast(z, d_w, d_pitch, n, alpha)
    for bad, template, values in _minimum_axial_load_refusals(z, d_w, d_pitch, n, alpha):
        _refuse(bad, template, **values)
    return _minimum_axial_load(z, d_w, d_pitch, n, alpha)


def _minimum_axial_load_refusals(z, d_w, d_pitch, n, alpha):
    return [_balls_refusal(z), _ball_refusal(d_w), _pitch_refusal(d_pitch, d_w, name="D0"),
            (n < 0, "n = {n:g} 1/min: the speed must not be negative", {"n": n}),
            (np.isinf(n), "n = {n:g} 1/min: the speed must be finite", {"n": n}),
            ((alpha < 0) | (alpha > 90), "alpha = {a:g} deg must lie in [0, 90] deg", {"a": alpha})]


def minimum_axial_load_rows(z, d_w, d_pitch, n, alpha) -> tuple[np.ndarray, np.ndarray]:
    """:func:`minimum_axial_load` of many rows in one call, each row refused on its own: (Fa_min [N], reason),
    Fa_min NaN and the reason the message :func:`minimum_axial_load` would raise where a row is refused ('' where
    it is not). The messages are built for the refused rows only.

    >>> Fa_min, reasons = minimum_axial_load_rows([7, 0], 2.0, 8.7355, 30000, 12.0)
    >>> np.round(Fa_min / KGF, 4).tolist(), reasons.tolist()
    ([0.1039, nan], ['', 'z = 0: the number of balls must be a whole number of at least 1'])
    """
    z, d_w, d_pitch, n, alpha = _broadcast(z, d_w, d_pitch, n, alpha)
    reasons = np.full(z.shape, "", dtype=object)
    for bad, template, values in _minimum_axial_load_refusals(z, d_w, d_pitch, n, alpha):
        for i in np.flatnonzero(np.asarray(bad, dtype=bool) & (reasons == "")):  # the first refusal of a row
            reasons[i] = template.format(**{k: np.broadcast_to(v, z.shape)[i] for k, v in values.items()})
    refused = reasons != ""
    with np.errstate(invalid="ignore"):
        return np.where(refused, np.nan, _minimum_axial_load(z, d_w, d_pitch, n, alpha)), reasons


def _minimum_axial_load(z, d_w, d_pitch, n, alpha):
    a = alpha * _DEG
    load_kgf = (GYROSCOPIC_CONSTANT_KGF * z * d_w**3 * d_pitch * n**2 * np.sin(a) ** 2
                * (1.0 - (d_w / d_pitch) ** 2 * np.cos(a) ** 2))
    return load_kgf * KGF


# --------------------------------------------------------------------------- display
def degrees_to_dms(alpha_deg: float) -> str:
    """An angle in degrees as ``D°M′S″``, seconds rounded; NaN and infinite angles are refused.

    >>> degrees_to_dms(14.4670)
    '14°28′01″'
    """
    if not math.isfinite(float(alpha_deg)):
        raise ContactInputError(f"alpha = {float(alpha_deg):g} deg: only a finite angle can be written in degrees, "
                                "minutes and seconds")
    total = round(abs(float(alpha_deg)) * 3600.0)
    deg, rest = divmod(total, 3600)
    minutes, seconds = divmod(rest, 60)
    sign = "-" if alpha_deg < 0 and total else ""
    return f"{sign}{deg}°{minutes:02d}′{seconds:02d}″"
