"""Ball bearing contact: contact angle from clearance, Hertz contact of the races,
stiffness characteristic C*, working contact angle under axial load, minimum axial load.

Source: seed 001, В.А. Зайцев, В.А. Воронкин, «Расчёт осевых усилий и рабочих
углов контакта подшипников качения при оценке их качества на стендах»
(ФГУП «НПП ВНИИЭМ», 2009). The static load factors X0, Y0 come from seed 000,
table 1 (``tables/static_load_factors.csv``).

Kernels take plain floats, numpy arrays or pandas Series in catalogue units
(mm, N, 1/min, angles in degrees), broadcast, and give a Series back when a
Series goes in. NaN inputs (a row without geometry) give NaN out. Bad values
raise :class:`ContactInputError` (a ValueError) naming the value and, for an
array or Series, its element or row.

The seed works in kgf and cm; here every kernel is in N and mm. The seed's
constants are kept as typed and converted once:

* ``0.592e-4 (cm²/kgf)^(2/3)`` -- the Hertz compliance of two steel bodies,
  ``(3(1 - ν²)/E)^(2/3) / 2`` with E = 2.08e5 N/mm² (2.12e6 kgf/cm²), ν = 0.3;
  in mm and N it is :data:`HERTZ_COMPLIANCE_MM_N` = 2.784e-4 (mm²/N)^(2/3).
* ``5.75e-12 kgf·min²/mm⁴`` -- the gyroscopic-sliding constant,
  ρπ/(240 μ)·(2π/60)² with ρ = 7.85 g/cm³ and a friction coefficient μ = 0.02.

The worked example of the seed, bearing 4-1006095 (5 × 13 × 4 mm), at
Fa = 2 kgf:

>>> C = stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16)
>>> round(C / KGF)                       # seed: 7792 kgf (table readings of 2K/(μπ))
7803
>>> alpha = working_contact_angle(2 * KGF, C, 12.0)
>>> degrees_to_dms(alpha)                # seed: 14°28′ (exact root at its C* = 7792 kgf: 14°28′04″)
'14°27′57″'
>>> round(axial_displacement_ratio(alpha, 12.0), 5)   # seed: 0.04448
0.04443
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearingheat.errors import ContactInputError

__all__ = [
    "KGF",
    "HERTZ_COMPLIANCE_CM_KGF",
    "HERTZ_COMPLIANCE_MM_N",
    "GYROSCOPIC_CONSTANT_KGF",
    "ContactInputError",
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
    "working_contact_angle",
    "series_coefficients",
    "series_start",
    "newton_increment",
    "SeriesIterate",
    "series_iterates",
    "working_contact_angle_series",
    "minimum_axial_load",
    "y0_for_contact_angle",
    "x0_for_contact_angle",
    "degrees_to_dms",
    "BallContact",
    "ball_bearing_contact",
    "contact_angle_from_clearance",
]

KGF = 9.80665
"""Newtons per kilogram-force (standard gravity)."""

HERTZ_COMPLIANCE_CM_KGF = 0.592e-4
"""Seed 001 constant in c = 0.592e-4·(2K/μπ)·(d_w·Σρ)^(1/3), unit (cm²/kgf)^(2/3).

Hertz: δ = (2K/μπ)·(3(1-ν²)/E)^(2/3)·Q^(2/3)·Σρ^(1/3)/2 for two bodies of one
steel, so δ/d_w = c·(Q/d_w²)^(2/3) with c = (2K/μπ)·k·(d_w·Σρ)^(1/3) and
k = (3(1-ν²)/E)^(2/3)/2. E = 2.08e5 N/mm² = 2.121e6 kgf/cm², ν = 0.3 give
k = 0.5916e-4 (cm²/kgf)^(2/3).
"""

HERTZ_COMPLIANCE_MM_N = HERTZ_COMPLIANCE_CM_KGF * (100.0 / KGF) ** (2.0 / 3.0)
"""The same constant in (mm²/N)^(2/3): 1 cm²/kgf = 100 mm² / 9.80665 N (≈ 2.784e-4)."""

GYROSCOPIC_CONSTANT_KGF = 5.75e-12
"""Seed 001 constant of the minimum axial load, kgf·min²/mm⁴ (d_w, D0 in mm, n in 1/min)."""

_DEG = math.pi / 180.0


# --------------------------------------------------------------------------- helpers
def _broadcast(*values):
    """Float arrays of one broadcast shape, and the index of the first Series among the inputs."""
    index = next((v.index for v in values if isinstance(v, pd.Series)), None)
    arrays = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in values])
    return [np.array(a, dtype=float) for a in arrays], index


def _out(result, index):
    result = np.asarray(result, dtype=float)
    if index is not None:
        return pd.Series(result.reshape(len(index)), index=index)
    return float(result) if result.ndim == 0 else result


def _refuse(bad, index, template: str, **values):
    """Raise ContactInputError for the first element where ``bad`` holds (NaN never counts as bad)."""
    bad = np.asarray(bad, dtype=bool)
    if not bad.any():
        return
    flat = int(np.flatnonzero(bad.ravel())[0])
    cells = {k: np.broadcast_to(np.asarray(v, dtype=float), bad.shape).ravel()[flat] for k, v in values.items()}
    message = template.format(**cells)
    if bad.ndim == 0:
        raise ContactInputError(message)
    if index is not None:
        row = index[flat]
        raise ContactInputError(f"{message} (row {row})", row)
    position = np.unravel_index(flat, bad.shape)
    row = position[0] if len(position) == 1 else tuple(int(p) for p in position)
    raise ContactInputError(f"{message} (element {row})", row)


def _check_ball(d_w, index):
    _refuse(d_w <= 0, index, "d_w = {d_w:g} mm: the ball diameter must be positive", d_w=d_w)


def _check_groove_sum(r_i, r_o, d_w, index):
    total = r_i + r_o
    _refuse(total <= d_w, index,
            "impossible geometry: r_i + r_o = {total:g} mm must exceed d_w = {d_w:g} mm",
            total=total, d_w=d_w)


def _check_grooves(r_i, r_o, d_w, index):
    _check_groove_sum(r_i, r_o, d_w, index)
    half = d_w / 2.0
    _refuse(r_i <= half, index,
            "impossible geometry: r_i = {r:g} mm must exceed d_w/2 = {half:g} mm (groove narrower than the ball)",
            r=r_i, half=half)
    _refuse(r_o <= half, index,
            "impossible geometry: r_o = {r:g} mm must exceed d_w/2 = {half:g} mm (groove narrower than the ball)",
            r=r_o, half=half)


def _check_pitch(d_m, d_w, index, name="d_m"):
    _refuse(d_m <= d_w, index,
            "impossible geometry: pitch diameter " + name + " = {d_m:g} mm must exceed d_w = {d_w:g} mm",
            d_m=d_m, d_w=d_w)


def _check_alpha0(alpha0, index):
    _refuse((alpha0 < 0) | (alpha0 >= 90), index,
            "alpha0 = {a:g} deg must lie in [0, 90) deg", a=alpha0)


def _check_balls(z, index):
    _refuse((z < 1) | (z != np.round(z)), index,
            "z = {z:g}: the number of balls must be a whole number of at least 1", z=z)


# --------------------------------------------------------------------------- initial contact angle
def initial_contact_angle(e, r_i, r_o, d_w):
    """Initial contact angle from the mean radial clearance [deg] (seed 001, p. 1).

    α0 = arccos[1 − e / (2(r_i + r_o − d_w))]

    e: mean radial clearance [mm] (catalogue value of the clearance group);
    r_i, r_o: groove radii of the inner and outer ring [mm]; d_w: ball
    diameter [mm]. Valid for 0 ≤ e ≤ 2(r_i + r_o − d_w) (α0 up to 90°).

    >>> round(initial_contact_angle(0.01, 1.05, 1.16, 2.0), 4)
    12.5279
    """
    (e, r_i, r_o, d_w), index = _broadcast(e, r_i, r_o, d_w)
    _check_ball(d_w, index)
    _check_groove_sum(r_i, r_o, d_w, index)
    _refuse(e < 0, index, "e = {e:g} mm: the radial clearance must not be negative", e=e)
    span = 2.0 * (r_i + r_o - d_w)
    _refuse(e > span, index,
            "e = {e:g} mm exceeds 2*(r_i + r_o - d_w) = {span:g} mm: the contact angle would pass 90 deg",
            e=e, span=span)
    return _out(np.degrees(np.arccos(1.0 - e / span)), index)


def initial_contact_angle_052(e, d_w):
    """Initial contact angle for groove radii r_i = r_o = 0.52·d_w [deg] (seed 001, p. 1).

    α0 = arccos(1 − 12.5·e/d_w), the case r_i + r_o − d_w = 0.04·d_w of
    :func:`initial_contact_angle`. e, d_w in mm; valid for 0 ≤ e ≤ 0.08·d_w.

    >>> round(initial_contact_angle_052(0.01, 2.0), 4)
    20.3641
    """
    (e, d_w), index = _broadcast(e, d_w)
    _check_ball(d_w, index)
    _refuse(e < 0, index, "e = {e:g} mm: the radial clearance must not be negative", e=e)
    _refuse(e > 0.08 * d_w, index,
            "e = {e:g} mm exceeds 0.08*d_w = {span:g} mm: the contact angle would pass 90 deg",
            e=e, span=0.08 * d_w)
    return _out(np.degrees(np.arccos(1.0 - 12.5 * e / d_w)), index)


# --------------------------------------------------------------------------- Hertz contact
class RaceCurvatures(NamedTuple):
    """Curvature sums Σρ [1/mm] and auxiliaries cos τ = F(ρ) [1] of the inner and outer contact."""

    sum_rho_i: Any
    sum_rho_o: Any
    cos_tau_i: Any
    cos_tau_o: Any


def race_curvatures(d_w, d_m, alpha0, r_i, r_o) -> RaceCurvatures:
    """Curvature sums and auxiliaries of the ball–race contacts (seed 001, p. 2).

    With γ = d_w·cos α0 / d_m and the groove conformities f = r/d_w:

    Σρ_i = (1/d_w)·[4 − 1/f_i + 2γ/(1 − γ)],  cos τ_i = [1/f_i + 2γ/(1 − γ)] / (d_w·Σρ_i)

    Σρ_o = (1/d_w)·[4 − 1/f_o − 2γ/(1 + γ)],  cos τ_o = [1/f_o − 2γ/(1 + γ)] / (d_w·Σρ_o)

    This is the seed's form in T/(d_w cos α0) with the groove-centre diameters
    T_i = d_m + (2r_i − d_w)·cos α0 and T_o = d_m − (2r_o − d_w)·cos α0 (the
    seed's T_в = d_1 + 2r_в, T_н = D_1 − 2r_н) and its "± 2ξ − 1" read as
    "± (2ξ − 1)". d_w, d_m, r_i, r_o in mm, α0 in degrees.

    >>> rc = race_curvatures(2.0, 8.7355, 12.0, 1.05, 1.16)
    >>> [round(v, 7) for v in rc]           # seed: 1.3361919, 0.9549594, 0.9287242, 0.7111268
    [1.336192, 0.9549594, 0.9287242, 0.7111269]
    """
    (d_w, d_m, alpha0, r_i, r_o), index = _broadcast(d_w, d_m, alpha0, r_i, r_o)
    _check_ball(d_w, index)
    _check_grooves(r_i, r_o, d_w, index)
    _check_pitch(d_m, d_w, index)
    _check_alpha0(alpha0, index)
    gamma = d_w * np.cos(alpha0 * _DEG) / d_m
    inner_rolling = 2.0 * gamma / (1.0 - gamma)
    outer_rolling = 2.0 * gamma / (1.0 + gamma)
    sum_i = (4.0 - d_w / r_i + inner_rolling) / d_w
    sum_o = (4.0 - d_w / r_o - outer_rolling) / d_w
    cos_i = (d_w / r_i + inner_rolling) / (d_w * sum_i)
    cos_o = (d_w / r_o - outer_rolling) / (d_w * sum_o)
    return RaceCurvatures(*(_out(v, index) for v in (sum_i, sum_o, cos_i, cos_o)))


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
    coefficient of the seed (Harris's δ*). The seed reads these from a table
    (seed 001, p. 3: μν = 1.52, 2K/μπ = 0.63 at cos τ = 0.9287; μν = 1.17,
    0.852 at 0.7111). Valid for 0 ≤ cos τ < 1 (dimensionless).

    >>> h = hertz_coefficients(0.9287242)
    >>> round(h.mu * h.nu, 2), round(h.deflection, 4)
    (1.52, 0.6283)
    """
    (cos_tau,), index = _broadcast(cos_tau)
    _refuse((cos_tau < 0) | (cos_tau >= 1), index, "cos_tau = {c:g} must lie in [0, 1)", c=cos_tau)
    m = np.vectorize(_parameter_for, otypes=[float])(cos_tau)
    kappa = 1.0 / np.sqrt(1.0 - m)
    big_e = ellipe(m)
    mu = np.cbrt(2.0 * kappa**2 * big_e / np.pi)
    nu = np.cbrt(2.0 * big_e / (np.pi * kappa))
    deflection = 2.0 * ellipk(m) / (np.pi * mu)
    return HertzCoefficients(*(_out(v, index) for v in (kappa, mu, nu, deflection)))


def race_compliance(d_w, sum_rho, deflection):
    """Compliance c of one ball–race contact [(mm²/N)^(2/3)] (seed 001, p. 2).

    c = k·(2K/μπ)·(d_w·Σρ)^(1/3), k = :data:`HERTZ_COMPLIANCE_MM_N` (the seed's
    0.592e-4 (cm²/kgf)^(2/3)); the normal approach is δ = c·d_w·(Q/d_w²)^(2/3).
    d_w in mm, Σρ in 1/mm, 2K/(μπ) dimensionless.

    >>> round(race_compliance(2.0, 1.3361919, 0.63) / (100 / KGF) ** (2 / 3), 9)  # seed: 0.5176e-4 (cm²/kgf)^(2/3)
    5.1756e-05
    """
    (d_w, sum_rho, deflection), index = _broadcast(d_w, sum_rho, deflection)
    return _out(HERTZ_COMPLIANCE_MM_N * deflection * np.cbrt(d_w * sum_rho), index)


def stiffness_characteristic(z, d_w, d_m, alpha0, r_i, r_o, *, deflection_coefficients=None):
    """Stiffness ("force") characteristic C* of the bearing [N] (seed 001, p. 2).

    C* = (ξ / (c_o + c_i))^(3/2)·z·d_w²,  ξ = r_i/d_w + r_o/d_w − 1,
    c from :func:`race_compliance` with Σρ, cos τ from :func:`race_curvatures`
    and 2K/(μπ) from :func:`hertz_coefficients`. z balls; d_w, d_m (pitch
    diameter), r_i, r_o in mm; α0 in degrees.

    ``deflection_coefficients=(inner, outer)`` replaces the exact 2K/(μπ) by
    given values, e.g. the seed's table readings (0.63, 0.852).

    >>> round(stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16,
    ...                                deflection_coefficients=(0.63, 0.852)) / KGF)   # seed: 7792 kgf
    7792
    """
    (z, d_w, d_m, alpha0, r_i, r_o), index = _broadcast(z, d_w, d_m, alpha0, r_i, r_o)
    _check_balls(z, index)
    curv = race_curvatures(d_w, d_m, alpha0, r_i, r_o)
    if deflection_coefficients is None:
        deflection_i = hertz_coefficients(curv.cos_tau_i).deflection
        deflection_o = hertz_coefficients(curv.cos_tau_o).deflection
    else:
        deflection_i, deflection_o = deflection_coefficients
    c_i = race_compliance(d_w, curv.sum_rho_i, deflection_i)
    c_o = race_compliance(d_w, curv.sum_rho_o, deflection_o)
    xi = (r_i + r_o) / d_w - 1.0
    return _out((xi / (np.asarray(c_o) + np.asarray(c_i))) ** 1.5 * z * d_w**2, index)


# --------------------------------------------------------------------------- working contact angle
def _deformation_term(alpha_rad, alpha0_rad):
    """cos α0 / cos α − 1 without cancellation near α = α0."""
    return 2.0 * np.sin((alpha_rad + alpha0_rad) / 2.0) * np.sin((alpha_rad - alpha0_rad) / 2.0) / np.cos(alpha_rad)


def axial_load_at_angle(alpha, alpha0, C_star):
    """Axial load that turns the contact angle from α0 to α [N] (seed 001, p. 2).

    Fa = C*·(cos α0 / cos α − 1)^(3/2)·sin α, α ≥ α0 in degrees, C* in N.

    >>> round(axial_load_at_angle(14.467, 12.0, 7792.0), 3)   # kgf in, kgf out
    1.999
    """
    (alpha, alpha0, C_star), index = _broadcast(alpha, alpha0, C_star)
    _check_alpha0(alpha0, index)
    _refuse((alpha < alpha0) | (alpha >= 90), index,
            "alpha = {a:g} deg must lie in [alpha0, 90) deg = [{a0:g}, 90) deg", a=alpha, a0=alpha0)
    a, a0 = alpha * _DEG, alpha0 * _DEG
    return _out(C_star * _deformation_term(a, a0) ** 1.5 * np.sin(a), index)


def axial_displacement_ratio(alpha, alpha0):
    """Dimensionless axial displacement ξ_a of the rings [1] (seed 001, p. 2).

    tg α = tg α0 + ξ_a / cos α0, so ξ_a = (tg α − tg α0)·cos α0. The axial
    displacement is δ_a = ξ_a·(r_i + r_o − d_w). Angles in degrees.

    >>> round(axial_displacement_ratio(14.4670, 12.0), 5)
    0.04445
    """
    (alpha, alpha0), index = _broadcast(alpha, alpha0)
    a, a0 = alpha * _DEG, alpha0 * _DEG
    return _out((np.tan(a) - np.tan(a0)) * np.cos(a0), index)


def _check_load(Fa, C_star, index):
    _refuse(Fa < 0, index, "Fa = {Fa:g} N: the axial load must not be negative", Fa=Fa)
    _refuse(C_star <= 0, index, "C_star = {C:g} N: the stiffness characteristic must be positive", C=C_star)


def _solve_angle(load_ratio_23: float, alpha0_rad: float) -> float:
    if math.isnan(load_ratio_23) or math.isnan(alpha0_rad):
        return math.nan
    if load_ratio_23 == 0.0:
        return alpha0_rad

    def residual(x):
        a = alpha0_rad + x
        return _deformation_term(a, alpha0_rad) * math.sin(a) ** (2.0 / 3.0) - load_ratio_23

    # residual(0) < 0 and residual -> +inf as alpha -> 90 deg; it increases in between.
    return alpha0_rad + brentq(residual, 0.0, math.pi / 2.0 - alpha0_rad, xtol=1e-15, maxiter=200)


def working_contact_angle(Fa, C_star, alpha0):
    """Working contact angle under the axial load Fa [deg] (seed 001, p. 2), by Brent's bracketing method.

    Solves Fa = C*·(cos α0 / cos α − 1)^(3/2)·sin α for α in [α0, 90°), written
    as (cos α0 / cos α − 1)·sin^(2/3) α = (Fa/C*)^(2/3), which increases
    monotonically in α. Fa, C* in N (any one force unit for both); α0 in
    degrees, 0 ≤ α0 < 90°. Fa = 0 gives α0.

    >>> round(working_contact_angle(2.0, 7792.0, 12.0), 4)     # kgf in; seed: 14°28′
    14.467
    """
    (Fa, C_star, alpha0), index = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star, index)
    _check_alpha0(alpha0, index)
    ratio = (Fa / C_star) ** (2.0 / 3.0)
    alpha = np.vectorize(_solve_angle, otypes=[float])(ratio, alpha0 * _DEG)
    return _out(np.where(Fa == 0, alpha0, np.degrees(alpha)), index)


def _check_series_alpha0(alpha0, index):
    _check_alpha0(alpha0, index)
    _refuse(alpha0 == 0, index,
            "alpha0 = {a:g} deg: the series method of seed 001 needs alpha0 > 0 "
            "(no expansion in powers of x at alpha0 = 0); use working_contact_angle", a=alpha0)


def series_coefficients(Fa, C_star, alpha0):
    """Coefficients a_0..a_4 of f(x) = Σ a_k x^k, α = α0 + x [rad] (seed 001, p. 2).

    f(x) = [cos α0 / cos(α0 + x) − 1]·sin^(2/3)(α0 + x) − (Fa/C*)^(2/3);
    a_0 = −(Fa/C*)^(2/3), a_1 = sin^(2/3)α0·tg α0,
    a_2 = ½·sin^(2/3)α0·(sec²α0 + tg²α0 + 4/3),
    a_3 = (1/9)·sin^(2/3)α0·(1.5 tg α0 + 2 ctg α0 + 9 sec²α0 tg α0),
    a_4 = (1/9)·sin^(2/3)α0·[(4/9 − sec²α0 + ½ sec⁴α0)·ctg²α0 + 4.375 sec⁴α0
    + 4.25 sec²α0 tg²α0 + 0.375 tg⁴α0]. Requires α0 > 0 (degrees).

    >>> [round(a, 4) for a in series_coefficients(0.0, 1.0, 12.0)]
    [0.0, 0.0746, 0.4253, 0.4573, 0.1472]
    """
    (Fa, C_star, alpha0), index = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star, index)
    _check_series_alpha0(alpha0, index)
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
    return tuple(_out(c, index) for c in coefficients)


def series_start(Fa, C_star, alpha0):
    """Quadratic start x_0 ≈ α − α0 [rad] (seed 001, p. 2), the root of a_0 + a_1 x + a_2 x² = 0.

    x_0 = (3/2)·sin 2α0 / (6 + cos²α0)·[√(1 + (2/3)·(6 + cos²α0)/sin²α0·(Fa/(C*·sin α0))^(2/3)) − 1]

    (the seed prints sin²α0 in the prefactor: OCR damage of sin 2α0, see
    docs/contact.md). Fa, C* in one force unit; α0 > 0 in degrees.

    >>> round(series_start(2.0, 7792.0, 12.0), 7)    # seed: 0.0433985, which needs C* = 7793.0
    0.0434016
    """
    (Fa, C_star, alpha0), index = _broadcast(Fa, C_star, alpha0)
    _check_load(Fa, C_star, index)
    _check_series_alpha0(alpha0, index)
    a0r = alpha0 * _DEG
    sin2, cos2 = np.sin(a0r) ** 2, np.cos(a0r) ** 2
    load = (Fa / (C_star * np.sin(a0r))) ** (2.0 / 3.0)
    x0 = 1.5 * np.sin(2.0 * a0r) / (6.0 + cos2) * (np.sqrt(1.0 + 2.0 / 3.0 * (6.0 + cos2) / sin2 * load) - 1.0)
    return _out(x0, index)


def newton_increment(Fa, C_star, alpha0, x):
    """Newton correction of x = α − α0 [rad] (seed 001, p. 2): x_{k+1} = x_k + Δx_k.

    Δx_k = [(Fa/Fa_k)^(2/3) − 1] / [tg α_k + (2/3)·ctg α_k + sin α_k/(cos α0 − cos α_k)],
    α_k = α0 + x_k, Fa_k = C*·(cos α0/cos α_k − 1)^(3/2)·sin α_k. The
    denominator is (2/3)·d ln Fa/dα. Requires x > 0 (or Fa = 0, giving 0).

    >>> x0 = series_start(2.0, 7792.0, 12.0)
    >>> round(x0 + newton_increment(2.0, 7792.0, 12.0, x0), 7)   # seed: 0.0430573; exact root 0.0430678
    0.0430694
    """
    (Fa, C_star, alpha0, x), index = _broadcast(Fa, C_star, alpha0, x)
    _check_load(Fa, C_star, index)
    _check_series_alpha0(alpha0, index)
    _refuse((x <= 0) & (Fa > 0), index, "x = {x:g} rad: the Newton step needs alpha_k > alpha0", x=x)
    a0r = alpha0 * _DEG
    ak = a0r + x
    with np.errstate(divide="ignore", invalid="ignore"):
        load_k = C_star * _deformation_term(ak, a0r) ** 1.5 * np.sin(ak)
        slope = np.tan(ak) + 2.0 / 3.0 / np.tan(ak) + np.sin(ak) / (np.cos(a0r) - np.cos(ak))
        step = ((Fa / load_k) ** (2.0 / 3.0) - 1.0) / slope
    return _out(np.where(Fa == 0, 0.0, step), index)


class SeriesIterate(NamedTuple):
    """One row of the seed's iteration table: x_k [rad], α [deg], ξ_a, Fa_k [force], Δ [%]."""

    k: int
    x: Any
    alpha: Any
    xi_a: Any
    load: Any
    deviation_percent: Any


def series_iterates(Fa, C_star, alpha0, newton_steps: int = 1) -> list[SeriesIterate]:
    """The seed's iteration table: x_0 from :func:`series_start`, then ``newton_steps`` Newton steps.

    Row k holds x_k, α = α0 + x_k [deg], ξ_a at α, the load Fa_k at α and
    Δ_k = (Fa_k − Fa)/Fa·100 [%] (seed 001, p. 3). Fa, C* in one force unit.

    >>> rows = series_iterates(2.0, 7792.0, 12.0, newton_steps=1)
    >>> [(round(r.x, 7), round(r.load, 3)) for r in rows]    # seed: (0.0433985, 2.029), (0.0430573, 2.001)
    [(0.0434016, 2.028), (0.0430694, 2.0)]
    """
    if int(newton_steps) != newton_steps or newton_steps < 0:
        raise ContactInputError(f"newton_steps = {newton_steps!r} must be a whole number >= 0")
    x = series_start(Fa, C_star, alpha0)
    rows = []
    for k in range(int(newton_steps) + 1):
        if k:
            x = x + newton_increment(Fa, C_star, alpha0, x)
        alpha = alpha0 + x * (180.0 / math.pi)
        load = axial_load_at_angle(alpha, alpha0, C_star)
        with np.errstate(divide="ignore", invalid="ignore"):
            deviation = (load - Fa) / Fa * 100.0
        rows.append(SeriesIterate(k, x, alpha, axial_displacement_ratio(alpha, alpha0), load, deviation))
    return rows


def working_contact_angle_series(Fa, C_star, alpha0, newton_steps: int = 2):
    """Working contact angle by the seed's series start and Newton steps [deg] (seed 001, p. 2).

    Same equation as :func:`working_contact_angle`; α0 > 0 required. The step
    is Newton's method on Fa^(2/3), so it converges quadratically: two steps
    give a fraction of an arc second for the seed's loads (x small against α0);
    α0 = 2° with Fa/C* = 0.01 (α ≈ 23°) needs six.

    >>> round(working_contact_angle_series(2.0, 7792.0, 12.0), 6) == round(working_contact_angle(2.0, 7792.0, 12.0), 6)
    True
    """
    return series_iterates(Fa, C_star, alpha0, newton_steps)[-1].alpha


# --------------------------------------------------------------------------- minimum axial load
def minimum_axial_load(z, d_w, d_pitch, n, alpha):
    """Minimum axial load against gyroscopic sliding of the balls [N] (seed 001, p. 1).

    Fa_min = 5.75e-12·z·d_w³·D0·n²·sin²α·[1 − (d_w/D0)²·cos²α] kgf, times 9.80665 N/kgf.

    z balls, d_w ball diameter [mm], D0 = ``d_pitch`` pitch diameter [mm],
    n inner-ring speed [1/min], α contact angle [deg] (the seed takes α0 from
    the clearance; the working angle under Fa gives the larger, stricter value).
    The constant is ρπ/(240μ)·(2π/60)²/g for ρ = 7.85 g/cm³ and μ = 0.02: the
    gyroscopic moment J·ω_ball·ω_cage·sin α of a ball (J = m·d_w²/10, cage at
    n/2) held by the friction μ·Q·d_w of its two contacts. NaN inputs give NaN.

    >>> round(minimum_axial_load(7, 2.0, 8.7355, 30000, 12.0) / KGF, 4)   # kgf
    0.1039
    """
    (z, d_w, d_pitch, n, alpha), index = _broadcast(z, d_w, d_pitch, n, alpha)
    _check_balls(z, index)
    _check_ball(d_w, index)
    _check_pitch(d_pitch, d_w, index, name="D0")
    _refuse(n < 0, index, "n = {n:g} 1/min: the speed must not be negative", n=n)
    _refuse((alpha < 0) | (alpha > 90), index, "alpha = {a:g} deg must lie in [0, 90] deg", a=alpha)
    a = alpha * _DEG
    load_kgf = (GYROSCOPIC_CONSTANT_KGF * z * d_w**3 * d_pitch * n**2 * np.sin(a) ** 2
                * (1.0 - (d_w / d_pitch) ** 2 * np.cos(a) ** 2))
    return _out(load_kgf * KGF, index)


# --------------------------------------------------------------------------- static load factors
@functools.lru_cache(maxsize=None)
def _angular_contact_factors() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    from bearingheat.tables_io import load_table

    table = load_table("static_load_factors")
    rows = table[table["bearing_type"] == "angular_contact_ball"].sort_values("contact_angle")
    return (rows["contact_angle"].to_numpy(float), rows["X0"].to_numpy(float), rows["Y0"].to_numpy(float))


def _interpolate_factor(alpha, column: int, name: str):
    angles = _angular_contact_factors()[0]
    values = _angular_contact_factors()[column]
    (alpha,), index = _broadcast(alpha)
    lo, hi = angles[0], angles[-1]
    _refuse((alpha < lo) | (alpha > hi), index,
            "alpha = {a:g} deg is outside the contact angles of seed 000 table 1 "
            f"({lo:g} to {hi:g} deg); {name} is not extrapolated", a=alpha)
    return _out(np.interp(alpha, angles, values), index)


def y0_for_contact_angle(alpha):
    """Axial static load factor Y0 of a single-row angular contact ball bearing [1].

    Linear interpolation in α [deg] between the rows of seed 000, table 1
    (α = 18°, 20°, 26°, 30°, 36°: Y0 = 0.43, 0.42, 0.37, 0.33, 0.28); refused
    outside 18°–36°. NaN gives NaN.

    >>> y0_for_contact_angle(28.0)
    0.35
    """
    return _interpolate_factor(alpha, 2, "Y0")


def x0_for_contact_angle(alpha):
    """Radial static load factor X0 of a single-row angular contact ball bearing [1] (0.5 in 18°–36°).

    Same interpolation and range as :func:`y0_for_contact_angle` (seed 000, table 1).

    >>> x0_for_contact_angle(20.0)
    0.5
    """
    return _interpolate_factor(alpha, 1, "X0")


def degrees_to_dms(alpha_deg: float) -> str:
    """An angle in degrees as ``D°M′S″``, seconds rounded.

    >>> degrees_to_dms(14.4670)
    '14°28′01″'
    """
    total = round(abs(float(alpha_deg)) * 3600.0)
    deg, rest = divmod(total, 3600)
    minutes, seconds = divmod(rest, 60)
    sign = "-" if alpha_deg < 0 and total else ""
    return f"{sign}{deg}°{minutes:02d}′{seconds:02d}″"


# --------------------------------------------------------------------------- unit-aware API
@dataclass(frozen=True)
class BallContact:
    """Contact of one ball bearing (Quantities). ``Fa_min`` needs n; it uses α0 (the seed's rule),
    ``Fa_min_at_alpha`` the working angle under Fa."""

    alpha0: Any
    alpha: Any
    Fa: Any
    xi_a: Any
    delta_a: Any
    C_star: Any
    sum_rho_i: Any
    sum_rho_o: Any
    cos_tau_i: Any
    cos_tau_o: Any
    deflection_i: Any
    deflection_o: Any
    n: Any = None
    Fa_min: Any = None
    Fa_min_at_alpha: Any = None

    # key of to_dict() -> (attribute, unit)
    _KEYS = {
        "alpha0 [deg]": ("alpha0", "deg"),
        "Fa [N]": ("Fa", "N"),
        "alpha [deg]": ("alpha", "deg"),
        "xi_a": ("xi_a", ""),
        "delta_a [mm]": ("delta_a", "mm"),
        "C_star [N]": ("C_star", "N"),
        "sum_rho_i [1/mm]": ("sum_rho_i", "1/mm"),
        "sum_rho_o [1/mm]": ("sum_rho_o", "1/mm"),
        "cos_tau_i": ("cos_tau_i", ""),
        "cos_tau_o": ("cos_tau_o", ""),
        "2K/(mu*pi)_i": ("deflection_i", ""),
        "2K/(mu*pi)_o": ("deflection_o", ""),
        "n [1/min]": ("n", "1/min"),
        "Fa_min [N]": ("Fa_min", "N"),
        "Fa_min at alpha [N]": ("Fa_min_at_alpha", "N"),
    }

    def to_dict(self) -> dict[str, Any]:
        """Magnitudes under keys carrying their unit, e.g. ``'alpha [deg]'``; keys of absent values left out."""
        result = {}
        for key, (attribute, unit) in self._KEYS.items():
            value = getattr(self, attribute)
            if value is None:
                continue
            mag = value.to(unit).magnitude if unit else value.to("dimensionless").magnitude
            result[key] = mag.tolist() if isinstance(mag, np.ndarray) else float(mag)
        return result


def _angle_deg(value, name: str):
    from bearingheat.units import UnitError, magnitude

    if getattr(value, "unitless", False):
        raise UnitError(f"{name}: {value.magnitude!r} has no unit; write it as an angle, e.g. {value.magnitude!r} deg")
    return magnitude(value, "deg", name)


def _count(value, name: str):
    from bearingheat.units import UnitError

    if hasattr(value, "units"):
        if not value.unitless:
            raise UnitError(f"{name}: {value} must be a plain number of balls, without a unit")
        value = value.magnitude
    return value


def contact_angle_from_clearance(clearance, r_i, r_o, d_w):
    """Initial contact angle α0 (Quantity in degrees) from the mean radial clearance.

    Unit-aware form of :func:`initial_contact_angle`: lengths are Quantities.

    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> round(contact_angle_from_clearance(10 * u.um, 1.05 * u.mm, 1.16 * u.mm, 2 * u.mm).to('deg').magnitude, 4)
    12.5279
    """
    from bearingheat.units import magnitude, quantity

    e = magnitude(clearance, "mm", "clearance")
    ri, ro, dw = (magnitude(q, "mm", nm) for q, nm in ((r_i, "r_i"), (r_o, "r_o"), (d_w, "d_w")))
    return quantity(initial_contact_angle(e, ri, ro, dw), "deg")


def ball_bearing_contact(*, z, d_w, d_m, r_i, r_o, alpha0=None, clearance=None, Fa=None, n=None) -> BallContact:
    """Contact angles, stiffness and minimum axial load of a ball bearing (seed 001), unit-aware.

    z: number of balls (plain number); d_w ball diameter, d_m pitch diameter,
    r_i, r_o groove radii: lengths; exactly one of alpha0 (angle) or clearance
    (mean radial clearance, length); Fa axial load (force, default 0: α = α0);
    n inner-ring speed (1/min, rpm, Hz, rad/s), optional, for the minimum
    axial load. Returns a :class:`BallContact` of Quantities.

    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> r = ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
    ...                          alpha0=12 * u.deg, Fa=2 * u.kgf, n=3000 * u.rpm)
    >>> round(r.C_star.to('kgf').magnitude), degrees_to_dms(r.alpha.to('deg').magnitude), round(r.xi_a.magnitude, 5)
    (7803, '14°27′57″', 0.04443)
    >>> r.Fa_min.to('mN')
    <Quantity(10.19..., 'millinewton')>
    """
    from bearingheat.units import magnitude, quantity, speed_rpm

    if (alpha0 is None) == (clearance is None):
        raise ContactInputError("give exactly one of alpha0 (an angle) or clearance (the mean radial clearance)")
    count = _count(z, "z")
    dw, dm, ri, ro = (magnitude(q, "mm", nm) for q, nm in ((d_w, "d_w"), (d_m, "d_m"), (r_i, "r_i"), (r_o, "r_o")))
    if alpha0 is not None:
        angle0 = _angle_deg(alpha0, "alpha0")
    else:
        angle0 = initial_contact_angle(magnitude(clearance, "mm", "clearance"), ri, ro, dw)
    load = 0.0 if Fa is None else magnitude(Fa, "N", "Fa")

    curv = race_curvatures(dw, dm, angle0, ri, ro)
    hertz_i, hertz_o = hertz_coefficients(curv.cos_tau_i), hertz_coefficients(curv.cos_tau_o)
    c_star = stiffness_characteristic(count, dw, dm, angle0, ri, ro,
                                      deflection_coefficients=(hertz_i.deflection, hertz_o.deflection))
    angle = working_contact_angle(load, c_star, angle0)
    xi_a = axial_displacement_ratio(angle, angle0)
    speed = fa_min = fa_min_working = None
    if n is not None:
        rpm = speed_rpm(n, "n")
        speed = quantity(rpm, "1/min")
        fa_min = quantity(minimum_axial_load(count, dw, dm, rpm, angle0), "N")
        fa_min_working = quantity(minimum_axial_load(count, dw, dm, rpm, angle), "N")
    return BallContact(
        alpha0=quantity(angle0, "deg"),
        alpha=quantity(angle, "deg"),
        Fa=quantity(load, "N"),
        xi_a=quantity(xi_a, "dimensionless"),
        delta_a=quantity(xi_a * (ri + ro - dw), "mm"),
        C_star=quantity(c_star, "N"),
        sum_rho_i=quantity(curv.sum_rho_i, "1/mm"),
        sum_rho_o=quantity(curv.sum_rho_o, "1/mm"),
        cos_tau_i=quantity(curv.cos_tau_i, "dimensionless"),
        cos_tau_o=quantity(curv.cos_tau_o, "dimensionless"),
        deflection_i=quantity(hertz_i.deflection, "dimensionless"),
        deflection_o=quantity(hertz_o.deflection, "dimensionless"),
        n=speed,
        Fa_min=fa_min,
        Fa_min_at_alpha=fa_min_working,
    )
