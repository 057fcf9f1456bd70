"""Kernels of self-lubricating DU/DP bushings and thrust washers: pV sizing, life, friction loss (the DU/DP bushing handbook).

The DU/DP bushing handbook works in kgf/cm² and m/s; its formulas were lost in the OCR and are
rebuilt here from the definitions

    p = F / (d·l)               [N/mm²]   (load over the projected area)
    V = π·d·n / 60 000          [m/s]     (d in mm, n in 1/min)

so that for a cylindrical bushing p·V = π·n·F / (60 000·l): the bore cancels
and the length follows from an admissible K = pV alone. In the handbook's units
(F in kgf, K in kgf/cm²·m/s, l in mm) the same formula reads
l = π·n·F / (600·K) — the OCR's 'боок' is '600K'.

Unit conversion used throughout: 1 kgf/cm² = 9.80665 N / 100 mm²
= 0.0980665 N/mm² (MPa), so 1 kgf/cm²·m/s = 0.0980665 N/mm²·m/s
(:data:`~bearingheat.catalogue.bushing.KGF_PER_CM2`, with the admissible pV
and pressure tables in :mod:`bearingheat.catalogue.bushing`).

Kernels take plain floats or numpy arrays in catalogue units: F [N],
d, l, D [mm], n [1/min], p [N/mm²], V [m/s], K = pV [N/mm²·m/s], T [°C],
life [h], power [W]. The unit-aware :func:`~bearingheat.api.bushing.size_bushing`
and :func:`~bearingheat.api.bushing.size_thrust_washer` are in :mod:`bearingheat.api.bushing`.

>>> round(KGF_PER_CM2, 7)
0.0980665
>>> round(bushing_length_pV_du_dp(F=1000.0, n=300.0, K=0.5), 3)
31.416
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from bearingheat.catalogue.bushing import KGF_PER_CM2
from bearingheat.errors import BushingInputError, NoStandardSizeError, OutsideMethodError
from bearingheat.kernels._series import series_aware

__all__ = [
    "KGF_PER_CM2",
    "SPEED_MIN",
    "N_MAX",
    "sliding_speed",
    "bearing_pressure",
    "bushing_length_pV_du_dp",
    "bushing_length_pressure_du_dp",
    "thrust_washer_width_pV_du_dp",
    "thrust_washer_outer_diameter_pressure_du_dp",
    "oscillating_speed_du_dp",
    "life_hours_du_dp_fig86",
    "pV_for_life_du_dp_fig86",
    "temperature_factor_du_dp",
    "friction_coefficient_range_du_dp",
    "PlainBushingLoss",
    "plain_bushing_power_loss",
    "size_bushing_kernel",
    "size_thrust_washer_kernel",
]

#: Below this sliding speed [m/s] the DU/DP bushing handbook allows smaller bushings than its sizing gives, and its
#: friction bands begin.
SPEED_MIN = 0.05
#: Above this shaft speed [1/min] the DU/DP bushing handbook allows smaller bushings than its sizing gives.
N_MAX = 15000.0

#: Fig. 86 of the DU/DP bushing handbook: pV = 3.6 kgf/cm²·m/s gives 1000 h, pV = 18 gives 200 h.
FIG86_POINTS = ((3.6 * KGF_PER_CM2, 1000.0), (18.0 * KGF_PER_CM2, 200.0))
#: Slope of lg(life) against lg(pV) through the two points (exactly −1: lg 5 / lg 5).
FIG86_SLOPE = math.log(FIG86_POINTS[1][1] / FIG86_POINTS[0][1]) / math.log(FIG86_POINTS[1][0] / FIG86_POINTS[0][0])

#: Temperature range of table 25 and the derating (the DU/DP bushing handbook): valid −200 to +280 °C,
#: full capacity up to +120 °C, about half at +280 °C.
T_MIN, T_DERATE, T_MAX = -200.0, 120.0, 280.0

#: Default friction coefficients of the DU/DP bushing handbook ('Трение подшипников'):
#: (V from, V to) [m/s] -> (f low, f high).
FRICTION_BANDS = {
    (0.05, 0.1): (0.05, 0.1),  # low speeds, high specific loads
    (0.2, 5.0): (0.1, 0.2),    # the common range, p = 1-100 kgf/cm²
}


# --------------------------------------------------------------------------- definitions
def sliding_speed(d, n):
    """Sliding speed V = π·d·n / 60 000 [m/s] at diameter d [mm] and speed n [1/min].

    >>> round(sliding_speed(15.9, 3000.0), 3)
    2.498
    """
    return math.pi * d * n / 60000.0


def bearing_pressure(F, d, l):
    """Specific load on the projected area p = F / (d·l) [N/mm²]; F [N], d and l [mm].

    >>> bearing_pressure(1000.0, 20.0, 25.0)
    2.0
    """
    return F / (d * l)


def bushing_length_pV_du_dp(F, n, K):
    """Bushing length from the admissible pV, the DU/DP bushing handbook step 2: l = π·n·F / (60 000·K) [mm].

    F [N] radial load, n [1/min], K [N/mm²·m/s]. From K = p·V with
    p = F/(d·l) and V = π·d·n/60 000; d cancels. Seed units: l = π·n·F/(600·K)
    with F [kgf] and K [kgf/cm²·m/s].

    >>> round(bushing_length_pV_du_dp(1000.0, 300.0, 0.5), 3)
    31.416
    """
    return math.pi * n * F / (60000.0 * K)


def bushing_length_pressure_du_dp(F, d, p_adm):
    """Bushing length from the admissible pressure, the DU/DP bushing handbook step 3: l = F / ([p]·d) [mm].

    >>> round(bushing_length_pressure_du_dp(20000.0, 20.0, 27.65), 2)
    36.17
    """
    return F / (p_adm * d)


def thrust_washer_width_pV_du_dp(F, n, K):
    """Radial width b = (D − d)/2 of a thrust washer from pV, the DU/DP bushing handbook: b = n·F / (60 000·K) [mm].

    F [N] axial load, n [1/min], K [N/mm²·m/s]. p = F/(π(D² − d²)/4) on the
    ring and V = π·n·(D + d)/2/60 000 at the mean diameter give
    p·V = n·F/(60 000·b). Seed units: (D − d)/2 = n·F/(600·K).

    >>> round(thrust_washer_width_pV_du_dp(1000.0, 300.0, 0.5), 3)
    10.0
    """
    return n * F / (60000.0 * K)


def thrust_washer_outer_diameter_pressure_du_dp(F, d, p_adm):
    """Outer diameter of a thrust washer from [p], the DU/DP bushing handbook: D = sqrt(d² + 4·F/(π·[p])) [mm].

    Seed units: D = sqrt(d² + 400·F/(π·[p])) with F [kgf], [p] [kgf/cm²].

    >>> round(float(thrust_washer_outer_diameter_pressure_du_dp(5000.0, 20.0, 5.0)), 2)
    40.91
    """
    return np.sqrt(np.square(d) + 4.0 * F / (math.pi * p_adm))


def oscillating_speed_du_dp(cycles_per_min, amplitude_rev):
    """Equivalent speed n [1/min] of an oscillating shaft, the DU/DP bushing handbook step 2.

    n = cycles per minute × amplitude in fractions of one revolution (as the
    handbook says; whether its 'amplitude' is the half or the full swing is not
    stated — give the angle swept in one direction per cycle).

    >>> oscillating_speed_du_dp(60.0, 0.25)
    15.0
    """
    return cycles_per_min * amplitude_rev


# --------------------------------------------------------------------------- life and derating
def _outside(values, low, high):
    values = np.asarray(values, dtype=float)
    return bool(np.any(~((values >= low) & (values <= high))))


def life_hours_du_dp_fig86(pV, extrapolate=False):
    """Life [h] of a DU bushing against pV [N/mm²·m/s], the DU/DP bushing handbook fig. 86.

    A straight line in log-log coordinates through the handbook's two points
    (3.6 kgf/cm²·m/s → 1000 h, 18 kgf/cm²·m/s → 200 h): a two-point fit whose
    slope is exactly −1, so life·pV = 3600 h·kgf/cm²·m/s = 353.04 h·N/mm²·m/s.
    Valid between the points (0.353 to 1.765 N/mm²·m/s); outside them an
    :class:`OutsideMethodError` is raised unless ``extrapolate=True``.
    Test bushing: DU, bore 15.9 mm, unhardened steel shaft.

    >>> round(life_hours_du_dp_fig86(3.6 * KGF_PER_CM2), 6)
    1000.0
    >>> round(life_hours_du_dp_fig86(1.0), 1)
    353.0
    """
    (pv1, life1), (pv2, _) = FIG86_POINTS
    if not extrapolate and _outside(pV, pv1 * (1 - 1e-12), pv2 * (1 + 1e-12)):
        raise OutsideMethodError(
            f"pV = {_fmt(pV)} N/mm²*m/s is outside the two-point fit of the DU/DP bushing handbook fig. 86 "
            f"({pv1:.4g} to {pv2:.4g} N/mm²*m/s, i.e. 3.6 to 18 kgf/cm²*m/s)"
        )
    return life1 * np.power(np.divide(pV, pv1), FIG86_SLOPE) if np.ndim(pV) else \
        float(life1 * (pV / pv1) ** FIG86_SLOPE)


def pV_for_life_du_dp_fig86(life, extrapolate=False):
    """pV [N/mm²·m/s] giving ``life`` [h] on the fig. 86 line (inverse of :func:`life_hours_du_dp_fig86`).

    >>> round(pV_for_life_du_dp_fig86(200.0) / KGF_PER_CM2, 6)
    18.0
    """
    (pv1, life1), (_, life2) = FIG86_POINTS
    if not extrapolate and _outside(life, life2 * (1 - 1e-12), life1 * (1 + 1e-12)):
        raise OutsideMethodError(
            f"life = {_fmt(life)} h is outside the two-point fit of the DU/DP bushing handbook fig. 86 ({life2:g} to {life1:g} h)"
        )
    return pv1 * np.power(np.divide(life, life1), 1.0 / FIG86_SLOPE) if np.ndim(life) else \
        float(pv1 * (life / life1) ** (1.0 / FIG86_SLOPE))


@series_aware
def temperature_factor_du_dp(T):
    """Derating factor of the admissible pV with temperature T [°C], the DU/DP bushing handbook.

    1 from −200 °C to +120 °C, then falling linearly to 0.5 at +280 °C (the
    handbook says 'gradually' and 'about half'; linear is our reading).
    Outside −200 to +280 °C an :class:`OutsideMethodError` is raised.

    >>> temperature_factor_du_dp(100.0), temperature_factor_du_dp(200.0), temperature_factor_du_dp(280.0)
    (1.0, 0.75, 0.5)
    """
    if _outside(T, T_MIN, T_MAX):
        raise OutsideMethodError(
            f"T = {_fmt(T)} °C is outside the range of the DU/DP bushing handbook table 25 ({T_MIN:g} to +{T_MAX:g} °C)"
        )
    return 1.0 - 0.5 * np.clip((np.asarray(T, dtype=float) - T_DERATE) / (T_MAX - T_DERATE), 0.0, 1.0)


def friction_coefficient_range_du_dp(V):
    """Default friction coefficient range (low, high) of DU at sliding speed V [m/s], the DU/DP bushing handbook.

    0.05–0.1 at 0.05–0.1 m/s (high loads); 0.1–0.2 at 0.2–5 m/s. Between
    0.1 and 0.2 m/s the handbook is silent and the envelope of both bands,
    0.05–0.2, is returned. Outside 0.05–5 m/s: NaN (no data in the handbook).

    >>> friction_coefficient_range_du_dp(np.array([0.07, 0.15, 1.0, 6.0]))
    (array([0.05, 0.05, 0.1 ,  nan]), array([0.1, 0.2, 0.2, nan]))
    """
    V_arr = np.asarray(V, dtype=float)
    low = np.full(V_arr.shape, np.nan)
    high = np.full(V_arr.shape, np.nan)
    for (v_from, v_to), (f_low, f_high) in FRICTION_BANDS.items():
        inside = (V_arr >= v_from) & (V_arr <= v_to)
        low = np.where(inside, f_low, low)
        high = np.where(inside, f_high, high)
    gap = (V_arr > 0.1) & (V_arr < 0.2)
    low = np.where(gap, 0.05, low)
    high = np.where(gap, 0.2, high)
    if V_arr.ndim == 0:
        return float(low), float(high)
    return low, high


def _fmt(value) -> str:
    arr = np.atleast_1d(np.asarray(value, dtype=float))
    return f"{arr[0]:.4g}" if arr.size == 1 else "[" + ", ".join(f"{v:.4g}" for v in arr) + "]"


# --------------------------------------------------------------------------- calc kernel
class PlainBushingLoss(NamedTuple):
    """Per-row result of :func:`plain_bushing_power_loss` (arrays, or Series for Series input)."""

    p: Any        # [N/mm²]
    V: Any        # [m/s]
    pV: Any       # [N/mm²·m/s]
    f_low: Any    # default range of the DU/DP bushing handbook at V
    f_high: Any
    f_used: Any   # f given, else f_high
    power: Any    # N = f·F·V [W]; NaN on error rows
    status: Any   # 'ok', 'warning' or 'error'
    message: Any  # '' when ok


def plain_bushing_power_loss(d, B, F, n, f=np.nan) -> PlainBushingLoss:
    """Friction power loss of plain (DU/DP) bushings, row by row, for ``calc`` (the DU/DP bushing handbook).

    d [mm] bore, B [mm] bushing length, F [N] radial load, n [1/min],
    f [1] friction coefficient (NaN = not given; calc's column f_plain, which the messages name). Returns p = F/(d·B)
    [N/mm²], V = π·d·n/60 000 [m/s], pV, the DU/DP bushing handbook's default f range at V,
    and N = f·F·V [W]. Without f, N uses the high end of the range (a
    conservative estimate) and the row status is 'warning'. Outside
    0.05-5 m/s the handbook gives no f: without f such a row is an error
    (N = NaN). Inputs broadcast; a Series in gives Series out.

    >>> out = plain_bushing_power_loss(np.array([20.0, 20.0]), 20.0, 1000.0, np.array([1000.0, 10.0]))
    >>> out.power.round(2), list(out.status)
    (array([209.44,    nan]), ['warning', 'error'])
    >>> out.message[1]
    'V = 0.01047 m/s is below 0.05 m/s: the DU/DP bushing handbook gives no friction coefficient there; give f_plain'
    """
    series = _first_series((d, B, F, n, f))
    d_a, B_a, F_a, n_a, f_a = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (d, B, F, n, f)))
    shape = d_a.shape
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.array(F_a / (d_a * B_a), dtype=float)
        V = np.array(math.pi * d_a * n_a / 60000.0, dtype=float)
    f_low, f_high = (np.array(np.broadcast_to(x, shape), dtype=float) for x in friction_coefficient_range_du_dp(V))
    given = np.isfinite(f_a)
    f_used = np.where(given, f_a, f_high)
    power = f_used * F_a * V
    status = np.full(shape, "ok", dtype=object)
    message = np.full(shape, "", dtype=object)
    for k in np.ndindex(shape):
        problem, bad_input = _row_problem(d_a[k], B_a[k], F_a[k], n_a[k], f_a[k], V[k])
        if problem:
            status[k], message[k] = "error", problem
            power[k] = np.nan
            if bad_input:
                p[k] = V[k] = np.nan
        elif not given[k]:
            status[k] = "warning"
            message[k] = (f"f not given: N uses f = {f_high[k]:g}, the high end of the DU/DP bushing handbook's range "
                          f"{f_low[k]:g}-{f_high[k]:g} at V = {V[k]:.3g} m/s (conservative)")
    fields = dict(p=p, V=V, pV=p * V, f_low=f_low, f_high=f_high, f_used=f_used, power=power,
                  status=status, message=message)
    if series is not None:
        fields = {k: type(series)(v, index=series.index) for k, v in fields.items()}
    elif not shape:
        fields = {k: (v.item() if hasattr(v, "item") else v) for k, v in fields.items()}
    return PlainBushingLoss(**fields)


def _first_series(values):
    """The first pandas Series among ``values``, else None.

    Duck-typed on a non-callable ``index`` attribute (a list's ``index`` is a
    method), so that the kernels need no pandas of their own: the results are
    built with the input's own Series type.
    """
    for value in values:
        index = getattr(value, "index", None)
        if index is not None and not callable(index):
            return value
    return None


def _row_problem(d, B, F, n, f, V) -> tuple[str, bool]:
    """(message, whether an input value itself is invalid); ('', False) for a usable row."""
    checks = (
        (d > 0, f"d = {d:g} mm: expected a bushing bore > 0 mm"),
        (B > 0, f"B = {B:g} mm: expected a bushing length > 0 mm"),
        (F >= 0, f"F = {F:g} N: expected a radial load >= 0 N"),
        (n >= 0, f"n = {n:g} 1/min: expected a speed >= 0 1/min"),
        (math.isnan(f) or 0 < f < 1, f"f = {f:g}: expected a friction coefficient between 0 and 1"),
        # the friction bands span 0.05-5 m/s (the DU/DP bushing handbook, 'Трение подшипников'): outside, f is needed
        (not math.isnan(f) or V >= SPEED_MIN,
         f"V = {V:.4g} m/s is below {SPEED_MIN:g} m/s: the DU/DP bushing handbook gives no friction coefficient "
         "there; give f_plain"),
        (not math.isnan(f) or V <= 5.0,
         f"V = {V:.4g} m/s is above 5 m/s: the DU/DP bushing handbook gives no friction coefficient there; give f_plain"),
    )
    for position, (ok, text) in enumerate(checks):
        if not ok:  # NaN inputs fail every comparison and land here too
            return text, position < 5
    return "", False


# --------------------------------------------------------------------------- sizing kernels
def _check_duty(F, n, d):
    for name, value, unit, rule in (("F", F, "N", "> 0"), ("n", n, "1/min", "> 0"), ("d", d, "mm", "> 0")):
        if not (math.isfinite(value) and value > 0):
            raise BushingInputError(f"{name} = {value:g} {unit}: expected a value {rule} {unit}")


def _size_note(V, n) -> str:
    """'' inside the range the sizing is made for, else why the size is conservative: 'bushings and thrust washers
    may be chosen smaller than calculated where V is below 0.05 m/s or n above 15 000 1/min' (the DU/DP bushing
    handbook)."""
    reasons = ([f"V = {V:.4g} m/s is below {SPEED_MIN:g} m/s"] if V < SPEED_MIN else []) + \
              ([f"n = {n:g} 1/min is above 15 000 1/min"] if n > N_MAX else [])
    if not reasons:
        return ""
    return (f"{' and '.join(reasons)}: the DU/DP bushing handbook allows a smaller size than calculated there "
            "(the size is conservative)")


def _round_up(required, standard, what):
    if standard is None:
        return float("nan")
    values = sorted(float(s) for s in standard)
    if any(not (math.isfinite(s) and s > 0) for s in values):
        raise BushingInputError(f"standard {what}s: {values}; expected positive values in mm")
    larger = [s for s in values if s >= required * (1 - 1e-12)]
    if not larger:
        raise NoStandardSizeError(f"no standard {what} >= {required:.4g} mm in the list "
                         f"({', '.join(f'{s:g}' for s in values)} mm)")
    return larger[0]


def _loss_and_life(F, V, pV, f):
    f_low, f_high = friction_coefficient_range_du_dp(V)  # NaN outside 0.05-5 m/s
    if f is not None:
        f_low = f_high = f
    try:
        life = life_hours_du_dp_fig86(pV)
        life_note = "fig. 86 two-point fit"
    except OutsideMethodError as exc:
        life, life_note = float("nan"), str(exc)
    return {"f_low": f_low, "f_high": f_high, "N_low [W]": f_low * F * V, "N_high [W]": f_high * F * V,
            "life_fig86 [h]": life, "life_note": life_note}


def size_bushing_kernel(F, n, d, K, p_adm, standard_lengths=None, f=None) -> dict[str, Any]:
    """Length of a cylindrical DU bushing by the DU/DP bushing handbook steps 1-4 (catalogue units).

    F [N] radial load, n [1/min] (oscillation: see :func:`oscillating_speed_du_dp`),
    d [mm] bore, K [N/mm²·m/s] admissible pV (already derated), p_adm [N/mm²]
    admissible pressure, standard_lengths [mm] (optional list), f optional
    friction coefficient.

    >>> out = size_bushing_kernel(2000.0, 500.0, 25.0, 0.5541, 27.655, [10, 15, 20, 25, 30, 40, 50, 60, 80, 100])
    >>> round(out["l_pV [mm]"], 2), round(out["l_p [mm]"], 2), out["governing"], out["l_standard [mm]"]
    (94.5, 2.89, 'pV', 100.0)
    """
    _check_duty(F, n, d)
    for name, value, unit in (("K", K, "N/mm²*m/s"), ("[p]", p_adm, "N/mm²")):
        if not (math.isfinite(value) and value > 0):
            raise BushingInputError(f"{name} = {value:g} {unit}: expected a value > 0")
    V = sliding_speed(d, n)
    l_pv = bushing_length_pV_du_dp(F, n, K)
    l_p = bushing_length_pressure_du_dp(F, d, p_adm)
    governing = "pV" if l_pv >= l_p else "pressure"
    required = max(l_pv, l_p)
    standard = _round_up(required, standard_lengths, "length")
    length = standard if math.isfinite(standard) else required
    p = bearing_pressure(F, d, length)
    out = {"kind": "bushing", "F [N]": F, "n [1/min]": n, "d [mm]": d, "K [N/mm^2*m/s]": K, "p_adm [N/mm^2]": p_adm,
           "V [m/s]": V, "l_pV [mm]": l_pv, "p_at_l_pV [N/mm^2]": bearing_pressure(F, d, l_pv), "l_p [mm]": l_p,
           "governing": governing, "l_required [mm]": required, "l_standard [mm]": standard,
           "p [N/mm^2]": p, "pV [N/mm^2*m/s]": p * V, "size_note": _size_note(V, n)}
    out.update(_loss_and_life(F, V, p * V, f))
    return out


def size_thrust_washer_kernel(F, n, d, K, p_adm, standard_diameters=None, f=None) -> dict[str, Any]:
    """Outer diameter of a DU thrust washer by the DU/DP bushing handbook (catalogue units).

    F [N] axial load, n [1/min], d [mm] inner diameter, K [N/mm²·m/s],
    p_adm [N/mm²], standard_diameters [mm] optional list of outer diameters.
    V and pV are taken at the mean diameter (D + d)/2.

    >>> out = size_thrust_washer_kernel(2000.0, 500.0, 25.0, 0.4168, 55.408)
    >>> round(out["b_pV [mm]"], 2), round(out["D_required [mm]"], 2), out["governing"]
    (39.99, 104.97, 'pV')
    """
    _check_duty(F, n, d)
    for name, value, unit in (("K", K, "N/mm²*m/s"), ("[p]", p_adm, "N/mm²")):
        if not (math.isfinite(value) and value > 0):
            raise BushingInputError(f"{name} = {value:g} {unit}: expected a value > 0")
    width = thrust_washer_width_pV_du_dp(F, n, K)
    D_pv = d + 2.0 * width
    D_p = float(thrust_washer_outer_diameter_pressure_du_dp(F, d, p_adm))
    governing = "pV" if D_pv >= D_p else "pressure"
    required = max(D_pv, D_p)
    standard = _round_up(required, standard_diameters, "outer diameter")
    D = standard if math.isfinite(standard) else required
    V = sliding_speed(0.5 * (D + d), n)
    p = 4.0 * F / (math.pi * (D * D - d * d))
    out = {"kind": "thrust_washer", "F [N]": F, "n [1/min]": n, "d [mm]": d, "K [N/mm^2*m/s]": K,
           "p_adm [N/mm^2]": p_adm, "b_pV [mm]": width, "D_pV [mm]": D_pv, "D_p [mm]": D_p, "governing": governing,
           "D_required [mm]": required, "D_standard [mm]": standard, "V [m/s]": V, "p [N/mm^2]": p,
           "pV [N/mm^2*m/s]": p * V, "size_note": _size_note(V, n)}
    out.update(_loss_and_life(F, V, p * V, f))
    return out
