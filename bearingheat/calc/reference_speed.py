"""The thermal reference speed n_θr of catalogue bearings, row by row (ISO 15312 reference conditions).

:func:`thermal_reference_speed_details` computes n_θr of every row of a
calc frame with the quantities behind it; rows with the same bearing and
geometry are computed once and broadcast (a table of many operating points
of few bearings costs a few bearings). :mod:`bearingheat.calc.thermal`
builds the heat balance on it.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np
import pandas as pd

from bearingheat.calc.supports import coded_categorical, first_rows, group_codes, number_column, text_column
from bearingheat.catalogue.friction import ResolvedBearing, resolve
from bearingheat.catalogue.thermal import THERMAL_KIND, THERMAL_KINDS, method_refusal, reference_conditions
from bearingheat.errors import DesignationError
from bearingheat.kernels import friction
from bearingheat.kernels.thermal import (HEAT_FLOW_AREA, balance_root, heat_flow_area, reference_heat_flux_density,
                                         torque_coefficients)

__all__ = ["PAIR_REASON", "REFERENCE_KEYS", "thermal_reference_speed_details", "thermal_reference_speed_rows"]

PAIR_REASON = ("n_thr: the heat balance of a bearing pair is not in the sources (ISO 15312 and the Schaeffler "
               "catalogue define A_r, the reference conditions and n_thr for single bearings); MR and NR are the "
               "pair's; give the two bearings as single rows for their heat balance")
#: the columns n_θr depends on: rows equal in these have the same details
REFERENCE_KEYS = ("designation", "type", "series", "arrangement", "d", "D", "B", "T", "d1", "D1", "C0")


def _resolve_rows(frame: pd.DataFrame) -> list[tuple[ResolvedBearing | None, str]]:
    """Per row: (ResolvedBearing or None, reason)."""
    designations = text_column(frame, "designation")
    types = text_column(frame, "type")
    series = text_column(frame, "series")
    out: list[tuple[ResolvedBearing | None, str]] = []
    for des, typ, ser in zip(designations, types, series):
        try:
            out.append((resolve(des, typ, ser), ""))
        except DesignationError as exc:
            out.append((None, str(exc)))
    return out


def thermal_reference_speed_details(frame: pd.DataFrame, *, f0_scale=1.0, f1_scale=1.0) -> pd.DataFrame:
    """Thermal reference speed of every row with the quantities behind it (see :func:`_details`); each distinct
    combination of the :data:`REFERENCE_KEYS` columns is computed once. ``f0_scale`` and ``f1_scale`` (per row
    or one number) scale the table coefficients, for the uncertainty bands."""
    keys = [c for c in REFERENCE_KEYS if c in frame.columns]
    if np.ndim(f0_scale) or np.ndim(f1_scale) or f0_scale != 1.0 or f1_scale != 1.0:
        return _details(frame, f0_scale, f1_scale)
    if not keys or len(frame) < 2:
        return _details(frame)
    codes = group_codes(frame, keys)
    first = first_rows(codes)
    if len(first) == len(frame):
        return _details(frame)
    distinct = _details(frame.iloc[first])
    # spread to the rows: numbers by their codes, texts as categoricals of the distinct rows' texts
    return pd.DataFrame({name: coded_categorical(codes, column.tolist()) if column.dtype.kind in "OUT"
                         or isinstance(column.dtype, pd.StringDtype) else column.to_numpy()[codes]
                         for name, column in distinct.items()}, index=frame.index, copy=False)


def _details(frame: pd.DataFrame, f0_scale=1.0, f1_scale=1.0) -> pd.DataFrame:
    """Thermal reference speed of every row with the quantities behind it.

    ``frame`` is in catalogue units with columns ``designation`` (or
    ``type`` and ``series``), ``d``, ``D``, ``B``, ``T`` (total width of
    tapered roller bearings), ``C0`` [mm, N]. Returns a DataFrame with the
    same index: ``n_thr`` [1/min], ``kind``, ``A_r`` [mm²] and ``q_r``
    [W/mm²] (wherever the geometry allows, even without C0), ``f0``, ``f1``, ``P1`` [N], ``M1`` [N·mm], ``regime``
    ('nu*n >= 2000' or 'nu*n < 2000') and ``reason`` ('' where n_thr was
    computed, otherwise why not). Never raises for a bad row.

    Reference conditions: 20 °C ambient, 70 °C outer ring, oil bath with
    ν = 12 mm²/s (radial) or 24 mm²/s (thrust), load P1 = 0.05·C0 (radial)
    or Fa = 0.02·C0 (thrust), f0 = oil-bath value, f1 at load/C0 of the
    reference load.
    """
    n_rows = len(frame)
    resolved = _resolve_rows(frame)
    d = number_column(frame, "d").copy()       # filled from the designation below
    D = number_column(frame, "D")
    B = number_column(frame, "B").copy()
    T = number_column(frame, "T")
    d1 = number_column(frame, "d1")
    D1 = number_column(frame, "D1")
    C0 = number_column(frame, "C0")
    reason = [r for _, r in resolved]
    arrangement = text_column(frame, "arrangement")
    kind = np.array([""] * n_rows, dtype=object)
    f0 = np.full(n_rows, np.nan)
    f1_a = np.full(n_rows, np.nan)
    f1_x = np.full(n_rows, np.nan)
    geometry_ok = np.zeros(n_rows, dtype=bool)
    for i, (res, _) in enumerate(resolved):
        if res is None:
            continue
        entry = res.entry
        if np.isnan(d[i]) and res.designation is not None and res.designation.bore is not None:
            d[i] = res.designation.bore
        if np.isnan(B[i]) and res.designation is not None and res.designation.width is not None:
            B[i] = res.designation.width
        refusal = method_refusal(entry.bearing_type, res.seal)
        if refusal:
            reason[i] = f"n_thr: {refusal}"
            continue
        if arrangement[i] == "paired":
            reason[i] = PAIR_REASON
            continue
        kind[i] = THERMAL_KIND[entry.bearing_type]
        checks: tuple[tuple[str, float, str, Callable[[float], bool], str], ...] = (
            ("d", d[i], "the bore d gives dM = (d + D)/2", lambda v: v > 0, "must be > 0"),
            ("D", D[i], "the outside diameter D gives dM = (d + D)/2 and A_r", lambda v: v > d[i],
             f"must be larger than d = {d[i]:g} mm"),
        )
        area_columns = {"B": (B[i], "width"), "T": (T[i], "total width"),
                        "d1": (d1[i], "outside diameter d1 of the shaft washer"),
                        "D1": (D1[i], "bore D1 of the housing washer")}
        needed = HEAT_FLOW_AREA[kind[i]][2]
        formula = HEAT_FLOW_AREA[kind[i]][1]
        absent = [c for c in needed if np.isnan(area_columns[c][0])]
        if len(absent) > 1:
            reason[i] = (f"{' and '.join(c + ' [mm]' for c in absent)}: missing; the heat flow area A_r = {formula} "
                         f"of {entry.label.split(' series')[0]}s needs them (HR 1, p. 64); the friction torque is "
                         "computed without them")
            continue
        for width in needed:
            value, what = area_columns[width]
            checks += ((width, value, f"the heat flow area A_r = {formula} needs the {what}",
                        lambda v: v > 0, "must be > 0"),)
        for column, value, why, ok, condition in checks:
            if np.isnan(value):
                reason[i] = f"{column} [mm]: missing; {why}"
                break
            if not ok(value):
                reason[i] = f"{column} [mm]: {value:g} {condition}"
                break
        if reason[i]:
            continue
        geometry_ok[i] = True
        f0_oil = entry.f0_oil
        if math.isnan(f0_oil):
            reason[i] = f"n_thr: {entry.label} has no oil-bath f0 in the Schaeffler catalogue (the table prints a dash)"
            continue
        f0[i] = friction.f0_needle(f0_oil, B[i], d[i]) if entry.f0_basis == "B/(33+d)" else f0_oil
        f1_a[i], f1_x[i] = entry.f1_a, entry.f1_x
        if np.isnan(C0[i]):
            reason[i] = "C0 [N]: missing; the reference load is a fraction of C0"
        elif not C0[i] > 0:
            reason[i] = f"C0 [N]: {C0[i]:g} must be > 0"
    usable = np.array([r == "" for r in reason], dtype=bool)
    A_r = np.full(n_rows, np.nan)
    q_r = np.full(n_rows, np.nan)
    load_ratio = np.full(n_rows, np.nan)
    nu_ref = np.full(n_rows, np.nan)
    for k in THERMAL_KINDS:
        rows = geometry_ok & (kind == k)
        if not rows.any():
            continue
        ref = reference_conditions(k)
        A_r[rows] = heat_flow_area(k, d[rows], D[rows], B[rows], T[rows], d1[rows], D1[rows])
        q_r[rows] = reference_heat_flux_density(k, A_r[rows])
        load_ratio[rows] = ref.load_ratio
        nu_ref[rows] = ref.nu
    dM = friction.mean_diameter(d, D)
    P1 = load_ratio * C0
    f0 = f0 * f0_scale
    with np.errstate(invalid="ignore"):
        f1 = friction.f1_from_load_ratio(f1_a, f1_x, load_ratio) * f1_scale
        M1 = friction.load_dependent_torque(f1, P1, dM)
        c_high, c_low = torque_coefficients(f0, dM)
        x, _, _, low = balance_root(c_high, c_low, M1, nu_ref, q_r * A_r, 1.0)
    n_thr = np.where(usable, x, np.nan)
    return pd.DataFrame({
        "n_thr": n_thr, "kind": kind, "A_r": A_r, "q_r": q_r,
        "f0": np.where(usable, f0, np.nan), "f1": np.where(usable, f1, np.nan),
        "P1": np.where(usable, P1, np.nan), "M1": np.where(usable, M1, np.nan),
        "regime": np.where(usable, np.where(low, "nu*n < 2000", "nu*n >= 2000"), ""),
        "reason": reason,
    }, index=frame.index)


def thermal_reference_speed_rows(frame: pd.DataFrame) -> pd.Series:
    """Thermal reference speed n_θr [1/min] of every row of ``frame`` (catalogue units).

    Columns: ``designation`` (or ``type`` + ``series``), ``d``, ``D``,
    ``B``, ``T`` (total width, tapered roller bearings; NaN otherwise),
    ``C0`` [mm, N]. Returns a float Series named ``n_thr`` with the index of
    ``frame``; rows that cannot be computed are NaN (no exception), and
    ``result.attrs['reason']`` is a Series of messages with the same index
    ('' where n_thr was computed). :func:`thermal_reference_speed_details`
    gives A_r, q_r, f0, f1, P1 and M1 as well.
    """
    details = thermal_reference_speed_details(frame)
    out = details["n_thr"].astype(float).rename("n_thr")
    out.attrs["reason"] = details["reason"].astype(object).rename("reason")
    return out
