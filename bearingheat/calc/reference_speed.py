"""The thermal reference speed n_θr of catalogue bearings, row by row (ISO 15312 reference conditions).

:func:`thermal_reference_speed_details` computes n_θr of every row of a
calc frame with the quantities behind it; rows with the same bearing and
geometry are computed once and broadcast (a table of many operating points
of few bearings costs a few bearings). :mod:`bearingheat.calc.thermal`
builds the heat balance on it.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from bearingheat.calc.supports import (coded_categorical, distinct_keys, fill_blank, first_rows, group_rows,
                                       number_column, printed_size, text_codes, text_column)
from bearingheat.catalogue.friction import ResolvedBearing, resolve
from bearingheat.catalogue.thermal import (CONTACT_SEAL_REASON, SEAL_FRICTION_REASON, THERMAL_KIND, THERMAL_KINDS,
                                           method_refusal, reference_conditions)
from bearingheat.errors import DesignationError
from bearingheat.kernels import friction
from bearingheat.kernels.thermal import (HEAT_FLOW_AREA, balance_root, default_heat_transfer_coefficient,
                                         heat_flow_area, reference_heat_flux_density, torque_coefficients)

__all__ = ["PAIR_REASON", "SEAL_FRICTION", "seal_friction_rows", "REFERENCE_KEYS", "thermal_reference_speed_details",
           "thermal_reference_speed_rows"]

PAIR_REASON = ("n_thr: the heat balance of a bearing pair is not in the sources (ISO 15312 and the Schaeffler "
               "catalogue define A_r, the reference conditions and n_thr for single bearings); MR and NR are the "
               "pair's; give the two bearings as single rows for their heat balance")
#: the hidden column of the rows with contact seals whose friction results hold the seal friction (the SKF model's
#: M_seal > 0): their heat balance applies, their n_θr does not (set by :mod:`bearingheat.calc.thermal`)
SEAL_FRICTION = "_seal_friction"


def seal_friction_rows(frame: pd.DataFrame) -> np.ndarray:
    """The rows the hidden column :data:`SEAL_FRICTION` marks (none where the frame has no such column)."""
    return frame[SEAL_FRICTION].to_numpy(dtype=bool) if SEAL_FRICTION in frame.columns else np.zeros(len(frame), bool)


#: the columns n_θr depends on: rows equal in these (and in SEAL_FRICTION) have the same details
REFERENCE_KEYS = ("designation", "type", "series", "arrangement", "d", "D", "B", "T", "d1", "D1", "C0")


def _resolved_keys(frame: pd.DataFrame) -> tuple[np.ndarray, list[tuple[ResolvedBearing | None, str]]]:
    """Per row the code of its (designation, type, series), and per code (ResolvedBearing or None, the reason
    it did not resolve): each distinct bearing is resolved once."""
    codes, keys = distinct_keys([text_codes(frame, name) for name in ("designation", "type", "series")])
    resolved: list[tuple[ResolvedBearing | None, str]] = []
    for designation, bearing_type, series in keys:
        try:
            resolved.append((resolve(designation, bearing_type, series), ""))
        except DesignationError as exc:
            resolved.append((None, str(exc)))
    return codes, resolved


def thermal_reference_speed_details(frame: pd.DataFrame, *, f0_scale=1.0, f1_scale=1.0,
                                    names: Sequence[str] | None = None) -> pd.DataFrame:
    """Thermal reference speed of every row with the quantities behind it (see :func:`_details`); each distinct
    combination of the :data:`REFERENCE_KEYS` columns (and :data:`SEAL_FRICTION`) is computed once. ``f0_scale``
    and ``f1_scale`` (per row or one number) scale the table coefficients, for the uncertainty bands. ``names``:
    the columns wanted (all where None)."""
    keys = [c for c in REFERENCE_KEYS if c in frame.columns]

    def chosen(details: pd.DataFrame) -> pd.DataFrame:
        return details if names is None else details[list(names)]

    if np.ndim(f0_scale) or np.ndim(f1_scale) or f0_scale != 1.0 or f1_scale != 1.0:
        return chosen(_details(frame, f0_scale, f1_scale))
    if not keys or len(frame) < 2:
        return chosen(_details(frame))
    codes, first = group_rows(frame, keys)  # (the bearing groups' own codes: SEAL_FRICTION is no bearing input)
    if SEAL_FRICTION in frame.columns:
        codes = pd.factorize(codes * 2 + seal_friction_rows(frame))[0]
        first = first_rows(codes)
    if len(first) == len(frame):
        return chosen(_details(frame))
    distinct = chosen(_details(frame.iloc[first]))
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
    [W/mm²] (wherever the geometry allows, even without C0), ``k_q_ref``
    [W/(mm²·K)] (the heat balance's default k_q, on every row of a kind),
    ``f0``, ``f1``, ``P1`` [N], ``M1`` [N·mm], ``regime`` ('nu*n >= 2000'
    or 'nu*n < 2000') and ``reason`` ('' where n_thr was computed,
    otherwise why not). Never raises for a bad row.

    Reference conditions: 20 °C ambient, 70 °C outer ring, oil bath with
    ν = 12 mm²/s (radial) or 24 mm²/s (thrust), load P1 = 0.05·C0 (radial)
    or Fa = 0.02·C0 (thrust), f0 = oil-bath value, f1 at load/C0 of the
    reference load.
    """
    n_rows = len(frame)
    codes, resolved = _resolved_keys(frame)
    entries = [res.entry if res is not None else None for res, _ in resolved]
    ok = np.array([res is not None for res, _ in resolved], dtype=bool)[codes]
    # the bore and width printed in the designation fill blank cells
    designations = [res.designation if res is not None else None for res, _ in resolved]
    d = fill_blank(number_column(frame, "d"), np.array([printed_size(p, "bore") for p in designations])[codes])
    D = number_column(frame, "D")
    B = fill_blank(number_column(frame, "B"), np.array([printed_size(p, "width") for p in designations])[codes])
    T = number_column(frame, "T")
    d1 = number_column(frame, "d1")
    D1 = number_column(frame, "D1")
    C0 = number_column(frame, "C0")
    # each row's reason is the first of these checks it fails, in this order (rows that fail none have '')
    reason = np.array([why for _, why in resolved], dtype=object)[codes]
    open_rows = ok.copy()

    def refuse(mask, text):
        """Rows still open where ``mask`` holds get a reason: ``text(i)`` built for each such row (a number in
        it), else ``text`` (one text, or a text per row)."""
        rows = np.flatnonzero(open_rows & mask)
        if callable(text):
            for i in rows.tolist():
                reason[i] = text(i)
        else:
            reason[rows] = text if isinstance(text, str) else text[rows]
        open_rows[rows] = False

    refusals = np.array([_refusal(res) for res, _ in resolved], dtype=object)[codes]
    # a sealed bearing with its seal friction in the results: the geometry of its heat balance is worked out, and
    # only n_thr refused (after the geometry checks, which say what its balance lacks)
    sealed = np.array([res is not None and method_refusal(res.entry.bearing_type, res.seal) == CONTACT_SEAL_REASON
                       for res, _ in resolved], dtype=bool)[codes]
    with_seal_friction = sealed & seal_friction_rows(frame)
    refuse(refusals.astype(bool) & ~with_seal_friction, refusals)
    refuse(np.asarray(text_column(frame, "arrangement"), dtype=object) == "paired", PAIR_REASON)
    kinds_of_key = np.array([THERMAL_KIND.get(e.bearing_type) or "" if e is not None else "" for e in entries],
                            dtype=object)
    kind = np.where(open_rows, kinds_of_key[codes], "").astype(object)
    labels = [e.label if e is not None else "" for e in entries]
    area_columns = {"B": (B, "width"), "T": (T, "total width"), "d1": (d1, "outside diameter d1 of the shaft washer"),
                    "D1": (D1, "bore D1 of the housing washer")}
    checks: dict[str, list] = {k: [] for k in THERMAL_KINDS}  # kind -> its rows' checks after d and D, in order
    for k in THERMAL_KINDS:
        of_kind = open_rows & (kind == k)
        if not of_kind.any():
            continue
        formula, needed = HEAT_FLOW_AREA[k][1], HEAT_FLOW_AREA[k][2]
        absent = np.array([np.isnan(area_columns[c][0]) for c in needed], dtype=bool).reshape(len(needed), n_rows)
        several = of_kind & (absent.sum(axis=0) > 1)
        refuse(several, lambda i, needed=needed, absent=absent, formula=formula: (
            f"{' and '.join(c + ' [mm]' for c, gone in zip(needed, absent[:, i]) if gone)}: missing; the heat flow "
            f"area A_r = {formula} of {labels[codes[i]].split(' series')[0]}s needs them (HR 1, p. 64); the "
            "friction torque is computed without them"))
        checks[k] = [(c, area_columns[c][0], f"the heat flow area A_r = {formula} needs the {area_columns[c][1]}")
                     for c in needed]
    refuse(np.isnan(d), "d [mm]: missing; the bore d gives dM = (d + D)/2")
    with np.errstate(invalid="ignore"):
        refuse(~(d > 0), lambda i: f"d [mm]: {d[i]:g} must be > 0")
        refuse(np.isnan(D), "D [mm]: missing; the outside diameter D gives dM = (d + D)/2 and A_r")
        refuse(~(D > d), lambda i: f"D [mm]: {D[i]:g} must be larger than d = {d[i]:g} mm")
        for k, kind_checks in checks.items():
            for column, values, why in kind_checks:
                refuse((kind == k) & np.isnan(values), f"{column} [mm]: missing; {why}")
                refuse((kind == k) & ~(values > 0), lambda i, c=column, v=values: f"{c} [mm]: {v[i]:g} must be > 0")
    geometry_ok = open_rows.copy()
    refuse(with_seal_friction, f"n_thr: {SEAL_FRICTION_REASON}")
    f0_oil = np.array([e.f0_oil if e is not None else np.nan for e in entries], dtype=float)[codes]
    refuse(np.isnan(f0_oil), lambda i: f"n_thr: {labels[codes[i]]} has no oil-bath f0 in the Schaeffler catalogue "
                                       "(the table prints a dash)")
    needle = np.array([e is not None and e.f0_basis == "B/(33+d)" for e in entries], dtype=bool)[codes]
    with np.errstate(invalid="ignore", divide="ignore"):
        f0 = np.where(open_rows, np.where(needle, friction.f0_needle(f0_oil, B, d), f0_oil), np.nan)
    f1_a = np.where(open_rows, np.array([e.f1_a if e is not None else np.nan for e in entries])[codes], np.nan)
    f1_x = np.where(open_rows, np.array([e.f1_x if e is not None else np.nan for e in entries])[codes], np.nan)
    refuse(np.isnan(C0), "C0 [N]: missing; the reference load is a fraction of C0")
    with np.errstate(invalid="ignore"):
        refuse(~(C0 > 0), lambda i: f"C0 [N]: {C0[i]:g} must be > 0")
    usable = ~reason.astype(bool)
    A_r = np.full(n_rows, np.nan)
    q_r = np.full(n_rows, np.nan)
    load_ratio = np.full(n_rows, np.nan)
    nu_ref = np.full(n_rows, np.nan)
    k_q_ref = np.full(n_rows, np.nan)
    for k in THERMAL_KINDS:
        of_kind = kind == k
        rows = geometry_ok & of_kind
        if rows.any():
            ref = reference_conditions(k)
            A_r[rows] = heat_flow_area(k, d[rows], D[rows], B[rows], T[rows], d1[rows], D1[rows])
            q_r[rows] = reference_heat_flux_density(k, A_r[rows])
            load_ratio[rows] = ref.load_ratio
            nu_ref[rows] = ref.nu
        if of_kind.any():  # the heat balance's default k_q, q_r/Δθ of the reference conditions, on every row of
            # the kind (NaN A_r included: the heat balance skips such rows)
            k_q_ref[of_kind] = default_heat_transfer_coefficient(k, A_r[of_kind])
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
        "n_thr": n_thr, "kind": kind, "A_r": A_r, "q_r": q_r, "k_q_ref": k_q_ref,
        "f0": np.where(usable, f0, np.nan), "f1": np.where(usable, f1, np.nan),
        "P1": np.where(usable, P1, np.nan), "M1": np.where(usable, M1, np.nan),
        "regime": np.where(usable, np.where(low, "nu*n < 2000", "nu*n >= 2000"), ""),
        "reason": reason,
    }, index=frame.index)


def _refusal(res: ResolvedBearing | None) -> str:
    """'n_thr: why' where the thermal method does not apply to a resolved bearing ('' otherwise)."""
    if res is None:
        return ""
    why = method_refusal(res.entry.bearing_type, res.seal)
    return f"n_thr: {why}" if why else ""


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
