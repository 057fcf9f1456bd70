"""The tables against a catalogue's own thermal reference speeds (the second audit of ``bearingheat audit``).

:func:`audit_reference_speeds` computes the thermal reference speed n_θr
of every bearing of a catalogue list from the tables
(:func:`bearingheat.calc.thermal.thermal_reference_speed_details`),
compares it with the published value and backs out the f0 (and f1) that
would reproduce the published value, within the catalogue's rounding of
speeds (:func:`rounding_step`, :func:`implied_coefficients`).
:func:`classify_reference_speeds` pools each series over its seal and
shield variants, splits it into size classes where only some sizes
deviate, lists single misprinted rows as outliers and flags the groups
that deviate systematically (:data:`SYSTEMATIC_RULE`), with the median
implied f0 of each group and its 95 % interval. The robust statistics
are :mod:`bearingheat.analysis.deviations`.
"""
from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import pandas as pd

from bearingheat.analysis.deviations import (CONFIDENCE, change_point, consistent_scale, local_residuals,
                                             median_interval, robust_scale)
from bearingheat.analysis.passthrough import unread_columns
from bearingheat.calc.contract import parse_header, readable_header
from bearingheat.calc.conversion import numbers_of, row_name, row_numbers
from bearingheat.calc.thermal import thermal_reference_speed_details
from bearingheat.catalogue.bearings import bearing
from bearingheat.catalogue.designation import parse_designation
from bearingheat.catalogue.friction import resolve
from bearingheat.catalogue.thermal import reference_conditions
from bearingheat.errors import AuditError, DesignationError, UnitError
from bearingheat.kernels import friction
from bearingheat.kernels.thermal import POWER_PER_TORQUE_SPEED, torque_coefficients
from bearingheat.units import convert_column

__all__ = [
    "SYSTEMATIC_RULE",
    "ROUNDING_STEPS",
    "REFERENCE_SPEED_COLUMNS",
    "GROUP_COLUMNS",
    "ReferenceSpeedAudit",
    "SKIPPED_WITHOUT_SPEED",
    "audit_reference_speeds",
    "rounding_step",
    "implied_coefficients",
    "classify_reference_speeds",
    "series_deviation_summary",
]

#: a group deviates systematically when its median deviation is beyond SYSTEMATIC_Z robust scales of the
#: median deviations of the series that agree with the tables, and SYSTEMATIC_SAME_SIGN of its bearings
#: (at least SYSTEMATIC_MIN_ROWS, outliers left out) deviate in the same direction
SYSTEMATIC_Z = 5.0
SYSTEMATIC_SAME_SIGN = 0.8
SYSTEMATIC_MIN_ROWS = 5
#: the scale is never taken below this [1] (so the threshold is at least SYSTEMATIC_Z·SCALE_FLOOR), and is
#: SCALE_FLOOR where fewer than MIN_CONSISTENT series agree with the tables
SCALE_FLOOR = 0.002
MIN_CONSISTENT = 5
#: a size class has at least this many bearings
CLASS_MIN_ROWS = 5
#: a bearing is an outlier when its deviation differs from its neighbours' by more than OUTLIER_Z robust
#: scales of such differences in its class, and by more than the systematic threshold plus one rounding
#: step of its published speed (relative)
OUTLIER_Z = 6.0
#: a group's implied f0 is too spread to be one table value beyond this multiple of the typical spread of the
#: groups that agree with the tables (same family)
SPREAD_FACTOR = 4.0
#: HR 1 (2006) rounds its speeds by magnitude: (below this speed [1/min], to this step [1/min])
ROUNDING_STEPS = ((500.0, 5.0), (2500.0, 10.0), (5000.0, 50.0), (25000.0, 100.0), (math.inf, 500.0))
SYSTEMATIC_RULE = (
    f"a group (a series over all its variants, or a size class of it) deviates systematically when at least "
    f"{SYSTEMATIC_MIN_ROWS} bearings (outliers left out) have a median of n_thr(tables)/n_thr(published) - 1 "
    f"beyond {SYSTEMATIC_Z:g} sigma, sigma being the robust scale (1.4826 MAD about 0, at least "
    f"{SCALE_FLOOR:.1%}) of the medians of the series that agree with the tables, and at least "
    f"{SYSTEMATIC_SAME_SIGN:.0%} of them deviate in the same direction; a series splits into size classes at a "
    f"change point in bore when one class agrees and the other deviates (at least {CLASS_MIN_ROWS} bearings "
    f"each); a bearing is an outlier when it differs from its neighbours by more than {OUTLIER_Z:g} robust "
    f"scales of such differences and more than the threshold plus one rounding step of its speed"
)
#: accepted names of the published thermal reference speed column (first match wins)
REFERENCE_SPEED_COLUMNS = ("n_thr", "n_B", "n_theta_r", "n_θr", "n_ref", "nthr")
#: the rows the audit skips (not row errors): a blank published speed where the catalogue prints none
SKIPPED_WITHOUT_SPEED = ("bearings with no published n_thr where catalogues print none (Schaeffler HR 1: '–'): "
                         "those with contact seals, to which the thermal method (ISO 15312, DIN 732) does not "
                         "apply, and those the bearing table holds without one (HR 1's 70..-B, 718..-B, NU19..); "
                         "not audited")


# ---------------------------------------------------------------------------------------------
# Catalogue thermal reference speeds
# ---------------------------------------------------------------------------------------------

_GEOMETRY_UNITS = {"d": "mm", "D": "mm", "B": "mm", "T": "mm", "C0": "N", "Y": "1", "e": "1", "Y0": "1"}
#: accepted names of the column that names a bearing's variant (seal, shield) in a catalogue list
VARIANT_COLUMNS = ("shield", "seal", "variant")


#: what each column of a list that must be positive holds, for the messages
_POSITIVE = {"d": "the bore d", "D": "the outside diameter D", "B": "the width B", "T": "the total width T",
             "C0": "the static load rating C0", "n": "a published speed"}


def _blank(values: pd.Series) -> np.ndarray:
    """Where a column's cells are empty or spaces only."""
    return values.isna().to_numpy() | values.astype(str).str.strip().eq("").to_numpy()


def _convert(values: pd.Series, header: str, unit_text: str | None, target: str, problems: list[list[str]], *,
             decimal: str = ".", positive: str | None = None, required: bool | np.ndarray = False) -> np.ndarray:
    """A catalogue-list column in the catalogue unit (units.convert_column); AuditError naming the column.

    Each cell that is text but no number ('abc', '5 600', '5,5' where the
    decimal mark is '.') adds a problem to its row; so does, where
    ``positive`` names what the column holds, a number that is not finite
    and > 0, and, where ``required`` (True, or a mask of the rows), a blank
    cell. Such a cell is NaN.
    """
    numbers = numbers_of(values, decimal)  # ('3,2' is 3.2 and '1.480' no number with a decimal comma, as calc reads)
    raw = values.to_numpy(dtype=object)
    blank = _blank(values)
    expected = f" ({positive} must be a finite number > 0)" if positive else ""
    for i in np.flatnonzero(np.isnan(numbers) & ~blank).tolist():
        problems[i].append(f"{str(raw[i]).strip()!r} is not a number for {header}{expected}")
    for i in np.flatnonzero(blank & required).tolist():
        problems[i].append(f"{header} is blank{expected}")
    try:
        converted = convert_column(numbers, unit_text, target, name=header, header=header)[0]
    except UnitError as exc:
        raise AuditError(f"column {header!r}: {exc}") from exc
    converted = np.array(converted, dtype=float)
    if positive:
        with np.errstate(invalid="ignore"):
            out_of_range = ~np.isnan(converted) & ~(np.isfinite(converted) & (converted > 0))
        for i in np.flatnonzero(out_of_range).tolist():
            problems[i].append(f"{header} = {numbers[i]:g} is outside the expected range{expected}")
            converted[i] = np.nan
    return converted


def _row_names(table: pd.DataFrame, names: np.ndarray) -> list[str]:
    """'row 5 (624-2Z)' of each row: the file line where the table was read from a CSV (``attrs['lines']``,
    as calc cites rows), else the row's position counting from 1."""
    rows = row_numbers(table)
    return [f"{row_name(rows, i)} ({name})" if name else row_name(rows, i)
            for i, name in enumerate(names)]


def rounding_step(n: npt.ArrayLike, steps: Sequence[tuple[float, float]] = ROUNDING_STEPS) -> np.ndarray:
    """Rounding step [1/min] of each published speed: the step of its magnitude, or a finer one its digits show.

    ``steps`` is a ladder of (upper limit, step) [1/min]: a speed below the
    first limit is rounded to the first step, and so on (HR 1: 5 below 500,
    10 below 2500, 50 below 5000, 100 below 25000, 500 above). A speed that
    is not a multiple of its step was rounded more finely: the largest step
    of the ladder (or 1) that divides it is taken. 0 for a speed that is
    not a whole number (taken as exact), NaN for NaN.

    >>> rounding_step([57000, 23400, 18900, 4350, 2260, 980, 455]).tolist()
    [500.0, 100.0, 100.0, 50.0, 10.0, 10.0, 5.0]
    """
    n = np.asarray(n, dtype=float)
    limits = np.array([limit for limit, _ in steps], dtype=float)
    sizes = np.array([size for _, size in steps], dtype=float)
    finite = np.isfinite(n)
    cap = np.full(n.shape, np.nan)
    cap[finite] = sizes[np.minimum(np.searchsorted(limits, n[finite], side="right"), len(sizes) - 1)]
    step = np.where(finite, 0.0, np.nan)
    for size in sorted(set(sizes) | {1.0}, reverse=True):
        with np.errstate(invalid="ignore"):
            ratio = n / size
            fits = finite & (step == 0.0) & (size <= cap) & np.isclose(ratio, np.round(ratio), rtol=0, atol=1e-9)
        step[fits] = size
    return step


def implied_coefficients(details: pd.DataFrame, d: npt.ArrayLike, D: npt.ArrayLike,
                         n: npt.ArrayLike) -> dict[str, np.ndarray]:
    """f0 (holding the table's f1) and f1 (holding the table's f0) that make ``n`` the thermal reference speed.

    ``details`` are the rows of :func:`bearingheat.calc.thermal.thermal_reference_speed_details`;
    d, D [mm]; n [1/min]. At the reference the friction power equals the
    reference heat flow: (π·n/30)·1e-3·(M0 + M1) = q_r·A_r with
    M0 = f0·(ν·n)^(2/3)·dM³·1e-7 (ν·n >= 2000; 160·f0·dM³·1e-7 below) and
    M1 = f1·P1·dM, so

        f0 = (q_r·A_r/((π·n/30)·1e-3) − M1) / (M0/f0),   f1 = (q_r·A_r/((π·n/30)·1e-3) − M0) / (P1·dM).

    Both fall as n rises. Returns {'f0': ..., 'f1': ...} (NaN where the
    row has no n_thr).
    """
    kinds = details["kind"].to_numpy(dtype=object)
    nu = np.array([reference_conditions(k).nu if k else np.nan for k in kinds], dtype=float)
    dM = friction.mean_diameter(np.asarray(d, dtype=float), np.asarray(D, dtype=float))
    per_f0_high, per_f0_low = torque_coefficients(1.0, dM)
    n = np.asarray(n, dtype=float)
    usable = details["n_thr"].notna().to_numpy()
    with np.errstate(divide="ignore", invalid="ignore"):
        torque = (details["q_r"] * details["A_r"]).to_numpy(dtype=float) / (POWER_PER_TORQUE_SPEED * n)
        nu_n = nu * n
        m0_per_f0 = np.where(nu_n >= friction.REGIME_LIMIT, per_f0_high * np.power(nu_n, 2.0 / 3.0), per_f0_low)
        f0 = (torque - details["M1"].to_numpy(dtype=float)) / m0_per_f0
        f1 = (torque - details["f0"].to_numpy(dtype=float) * m0_per_f0) / (details["P1"].to_numpy(dtype=float) * dM)
    return {"f0": np.where(usable, f0, np.nan), "f1": np.where(usable, f1, np.nan)}


def _printed_without_speed(designations: pd.Series) -> np.ndarray:
    """Where a designation names contact seals (6205-2RSR, 7205-B-2RS-TVP) or is, as printed, a bearing the bearing
    table holds without n_thr (7004-B-TVP); False where it is neither or does not resolve. Each distinct designation
    is looked up once."""
    codes, uniques = pd.factorize(designations)
    without = [_contact_sealed(str(text)) or _table_without_speed(str(text)) for text in uniques]
    return np.array(without, dtype=bool)[codes] if len(codes) else np.zeros(0, dtype=bool)


def _contact_sealed(text: str) -> bool:
    try:
        return parse_designation(text).seal == "contact"
    except DesignationError:
        return False


def _table_without_speed(text: str) -> bool:
    try:
        entry = bearing(text)
    except DesignationError:
        return False
    return entry.match == "exact" and math.isnan(entry.n_thr)


def _text(table: pd.DataFrame, columns: dict[str, str], names: Iterable[str]) -> np.ndarray | None:
    for name in names:
        if name in columns:
            return table[columns[name]].astype(str).str.strip().replace({"nan": ""}).to_numpy(dtype=object)
    return None


def _series_names(table: pd.DataFrame, columns: dict[str, str],
                  frame: pd.DataFrame) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(family, series, variant, bore) of each row: the list's columns where given, else the designation's."""
    family, series = _text(table, columns, ("family",)), _text(table, columns, ("series",))
    variant = _text(table, columns, VARIANT_COLUMNS)
    d = frame["d"].to_numpy(dtype=float).copy()
    fam_out, ser_out, var_out = [], [], []
    for i in range(len(frame)):
        try:
            res = resolve(frame["designation"].iat[i] if "designation" in frame else None,
                          frame["type"].iat[i] if "type" in frame else None,
                          frame["series"].iat[i] if "series" in frame else None)
        except DesignationError:
            res = None
        if np.isnan(d[i]) and res is not None and res.designation is not None and res.designation.bore:
            d[i] = res.designation.bore
        if family is not None and series is not None:
            fam_out.append(family[i])
            ser_out.append(series[i])
        elif res is not None:
            fam_out.append(res.entry.bearing_type)
            ser_out.append(res.entry.series)
        else:
            fam_out.append("unresolved")
            ser_out.append("")
        var_out.append((variant[i] or "open") if variant is not None else (res.seal if res is not None else "open"))
    return np.array(fam_out, dtype=object), np.array(ser_out, dtype=object), np.array(var_out, dtype=object), d


def audit_reference_speeds(table: pd.DataFrame, *, speed_column: str | None = None,
                           rounding_steps: Sequence[tuple[float, float]] = ROUNDING_STEPS) -> pd.DataFrame:
    """n_θr from the tables against the published n_θr, and the f0 and f1 it implies, for each bearing of a list.

    ``table`` has unit headers: ``designation`` (or ``type`` and ``series``
    of the Schaeffler catalogue tables), ``d``, ``D``, ``B``, ``T`` (tapered), ``C0``
    and the published speed (``n_thr``, ``n_B``, ... see
    :data:`REFERENCE_SPEED_COLUMNS`, or ``speed_column``). Optional
    ``family`` and ``series`` name the series (else the designation's type
    and series); an optional ``shield`` (``seal``, ``variant``) column
    names the variant, which is pooled with the open bearings of its series.
    A bearing whose designation names contact seals, or that the bearing
    table (Schaeffler HR 1, 2006) holds without n_thr (7004-B-TVP,
    71810-B-TVH: HR 1 prints '–'), and whose published speed is blank is
    skipped, not a row error: the catalogue prints no n_thr for it
    (:data:`SKIPPED_WITHOUT_SPEED`); ``result.attrs['skipped']`` names these
    rows ('row 93 (6205-2RSR)').

    Returns one row per bearing that is not skipped: ``designation``, ``family``, ``series``,
    ``series_key`` ('family series'), ``variant``, ``d``, ``D`` [mm],
    ``n_thr_published``, ``rounding_step`` (:func:`rounding_step`),
    ``n_thr_tables`` [1/min], ``deviation`` [1] (tables/published − 1),
    ``f0_table``, ``f0_implied`` with ``f0_implied_low``/``_high`` (at the
    published speed ± half a rounding step), the same for ``f1`` and
    ``reason`` ('' where n_thr was computed, otherwise 'row 5 (624-2Z): '
    and why not: the row is the file line where the table was read from a
    CSV, else its position from 1). A cell that is text but no number, a
    published speed that is blank or not finite and > 0, and a d, D, B, T
    or C0 that is not finite and > 0 leave the row uncomputed, its reason
    naming the column, the value and the expected range. The list's other
    columns (a page, a remark, a header that is no ``name [unit]``) follow,
    as typed, as calc passes them through. Group the rows with
    :func:`classify_reference_speeds`.
    """
    columns: dict[str, str] = {}
    units: dict[str, str | None] = {}
    for header in table.columns:
        if not readable_header(header):  # ('remark [see note]]': passed through, as calc passes it)
            continue
        name, unit = parse_header(header)
        columns.setdefault(name, header)
        units.setdefault(name, unit)
    wanted = [speed_column] if speed_column else list(REFERENCE_SPEED_COLUMNS)
    published_name = next((c for c in wanted if c in columns), None)
    if published_name is None:
        raise AuditError("missing column: the published thermal reference speed, e.g. 'n_thr [1/min]' "
                         f"(accepted names: {', '.join(wanted)})")
    if "designation" not in columns and not {"type", "series"} <= set(columns):
        raise AuditError("missing column: 'designation' (or 'type' and 'series')")
    frame = pd.DataFrame(index=table.index)
    if "designation" in columns:
        frame["designation"] = table[columns["designation"]].astype(str).str.strip()
    else:
        frame["type"] = table[columns["type"]].astype(str).str.strip()
        frame["series"] = table[columns["series"]].astype(str).str.strip()
    problems: list[list[str]] = [[] for _ in range(len(table))]
    decimal = str(table.attrs.get("decimal", "."))
    for name, target in _GEOMETRY_UNITS.items():
        if name in columns:
            frame[name] = _convert(table[columns[name]], columns[name], units[name], target, problems,
                                   decimal=decimal, positive=_POSITIVE.get(name))
        elif name in ("d", "D", "C0"):
            raise AuditError(f"missing column: '{name} [{target}]'")
        else:
            frame[name] = np.nan
    published_cells = table[columns[published_name]]
    # a blank speed of a bearing with contact seals, or of one HR 1 prints without a speed, is what the catalogue
    # prints: skipped, not a row error (only the rows with a blank speed are looked up in the bearing table: a
    # designation it does not hold costs the search for close matches)
    skipped = _blank(published_cells)
    if "designation" in frame and skipped.any():
        skipped[skipped] = _printed_without_speed(frame["designation"][skipped])
    else:
        skipped[:] = False
    published = _convert(published_cells, columns[published_name], units[published_name], "1/min",
                         problems, decimal=decimal, positive=_POSITIVE["n"], required=~skipped)
    in_error = np.array([bool(p) for p in problems], dtype=bool)
    # a row with a bad cell is not computed (a bore that is no number is not taken from the designation)
    frame.loc[in_error, [c for c in _GEOMETRY_UNITS if c in frame.columns]] = np.nan
    details = thermal_reference_speed_details(frame)
    computed = details["n_thr"].to_numpy(dtype=float)
    family, series, variant, bore = _series_names(table, columns, frame)
    step = rounding_step(published, rounding_steps)
    with np.errstate(divide="ignore", invalid="ignore"):
        deviation = computed / published - 1.0
    out = pd.DataFrame({
        "designation": frame["designation"] if "designation" in frame else frame["type"] + " " + frame["series"],
        "family": family, "series": series,
        "series_key": [f"{f} {s}".strip() for f, s in zip(family, series)],
        "variant": variant, "d": bore, "D": frame["D"].to_numpy(dtype=float),
        "n_thr_published": published, "rounding_step": step, "n_thr_tables": computed, "deviation": deviation,
    }, index=table.index)
    out["f0_table"] = details["f0"].to_numpy(dtype=float)
    out["f1_table"] = details["f1"].to_numpy(dtype=float)
    for when, speed in (("", published), ("_low", published + step / 2.0), ("_high", published - step / 2.0)):
        implied = implied_coefficients(details, bore, out["D"], speed)
        out["f0_implied" + when] = implied["f0"]
        out["f1_implied" + when] = implied["f1"]
    out = out[[c for c in out.columns if not c.startswith("f1")] + [c for c in out.columns if c.startswith("f1")]]
    computed_columns = ["n_thr_tables", "deviation"] + [c for c in out.columns if "_implied" in c]
    out.loc[in_error, computed_columns] = np.nan
    reason = np.where(in_error, ["; ".join(p) for p in problems], details["reason"].to_numpy(dtype=object))
    named = _row_names(table, out["designation"].astype(str).to_numpy(dtype=object))
    out["reason"] = [f"{who}: {why}" if why else "" for who, why in zip(named, reason)]
    # the columns not read (a page, a remark), kept after the audit's own as calc keeps them
    variant_column = next((name for name in VARIANT_COLUMNS if name in columns), None)
    read = [columns[name] for name in (published_name, "designation", "series", "family", variant_column,
                                       *_GEOMETRY_UNITS, *(() if "designation" in columns else ("type",)))
            if name in columns]
    kept = unread_columns(table, read, {*out.columns, *CLASSIFIED_COLUMNS},
                          "the reference speed audit writes into reference_speeds.csv", AuditError)
    result = pd.concat([out, kept.set_axis(out.index)], axis=1) if len(kept.columns) else out
    result = result[~skipped]
    result.attrs["skipped"] = [name for name, skip in zip(named, skipped) if skip]
    return result


# ---- groups: series, size classes, outliers, flags ------------------------------------------

@dataclass
class ReferenceSpeedAudit:
    """The reference speed audit of a catalogue list, grouped (:func:`classify_reference_speeds`).

    ``bearings``: the rows of :func:`audit_reference_speeds` with ``group``
    (the series key, plus the bore range of its size class where the series
    splits), ``subgroup`` ('' or 'd 45-140 mm'), ``local_deviation`` (the
    deviation minus that of its neighbours by bore) and ``outlier``.
    ``groups``: one row per series and, where it splits, per size class
    (see :data:`GROUP_COLUMNS`). ``scale`` is the robust scale σ of the
    medians of the consistent series, ``threshold`` = SYSTEMATIC_Z·σ the
    median deviation beyond which a group deviates, ``consistent`` how
    many series gave σ (0 where σ is SCALE_FLOOR because fewer than
    MIN_CONSISTENT series agree), ``series`` how many series have a
    computed median deviation. ``skipped`` names the rows of the list that
    :func:`audit_reference_speeds` skipped (:data:`SKIPPED_WITHOUT_SPEED`).
    """

    bearings: pd.DataFrame
    groups: pd.DataFrame
    scale: float
    threshold: float
    consistent: int
    series: int = 0
    skipped: tuple[str, ...] = ()

    @property
    def flagged(self) -> pd.DataFrame:
        """The groups that deviate systematically."""
        return self.groups[self.groups["systematic"]]

    @property
    def outliers(self) -> pd.DataFrame:
        """The bearings whose published speed is off their own series (misprints?)."""
        return self.bearings[self.bearings["outlier"]]

    @property
    def not_computed(self) -> list[str]:
        """Why each row whose n_thr was not computed was not (its ``reason``; a row error), in the list's order."""
        return [r for r in self.bearings["reason"] if isinstance(r, str) and r]


#: the columns :func:`classify_reference_speeds` adds to each bearing
CLASSIFIED_COLUMNS = ("group", "subgroup", "local_deviation", "outlier")

#: columns of :attr:`ReferenceSpeedAudit.groups`
GROUP_COLUMNS = (
    "group", "family", "series", "subgroup", "variants", "d_min", "d_max", "bearings", "computed", "outliers",
    "median_deviation", "min_deviation", "max_deviation", "share_above", "z", "systematic",
    "f0_table", "f0_implied", "f0_implied_low", "f0_implied_high", "f0_spread", "single_f0",
    "f1_table", "f1_implied", "f1_implied_low", "f1_implied_high", "interval_coverage", "note")


def _deviates(dev: np.ndarray, threshold: float) -> bool:
    """A group's deviations are systematic: enough rows, the median beyond the threshold, the signs agree."""
    if len(dev) < SYSTEMATIC_MIN_ROWS:
        return False
    median = float(np.median(dev))
    same_side = float(np.mean(dev > 0) if median > 0 else np.mean(dev < 0))
    return abs(median) > threshold and same_side >= SYSTEMATIC_SAME_SIGN


def _size_split(dev: np.ndarray, d: np.ndarray, threshold: float) -> int | None:
    """Where a series (sorted by bore) splits into a size class that agrees and one that deviates, else None."""
    k = change_point(dev, d, min_size=CLASS_MIN_ROWS)
    if k is None:
        return None
    left, right = dev[:k], dev[k:]
    off = (_deviates(left, threshold), _deviates(right, threshold))
    agrees = (abs(np.median(left)) <= threshold, abs(np.median(right)) <= threshold)
    step = abs(np.median(left) - np.median(right))
    if ((off[0] and agrees[1]) or (off[1] and agrees[0])) and step > threshold:
        return k
    return None


def _bore_range(d: np.ndarray) -> str:
    return f"d {np.nanmin(d):g}-{np.nanmax(d):g} mm"


def classify_reference_speeds(rows: pd.DataFrame, *, confidence: float = CONFIDENCE) -> ReferenceSpeedAudit:
    """Group the bearings of :func:`audit_reference_speeds` by series and size class; flag, mark outliers.

    1. **Scale.** σ = 1.4826·MAD about 0 of the median deviations of the
       series that agree with the tables, clipped at SYSTEMATIC_Z·σ and
       iterated (:func:`~bearingheat.analysis.deviations.consistent_scale`);
       σ >= SCALE_FLOOR; with fewer than MIN_CONSISTENT series, σ = SCALE_FLOOR.
    2. **Size classes.** Each series (all its variants, sorted by bore) is
       cut at its best change point (L1,
       :func:`~bearingheat.analysis.deviations.change_point`, at least
       CLASS_MIN_ROWS bearings a side); the cut stands when one side
       agrees with the tables and the other deviates systematically.
    3. **Outliers.** Within each class, a bearing whose deviation differs
       from the median of its neighbours (3 bores either side) by more
       than OUTLIER_Z times the robust scale of these differences, and by
       more than SYSTEMATIC_Z·σ plus one rounding step of its speed
       (relative), is an outlier: listed, and left out of its group's
       statistics.
    4. **Flags.** :data:`SYSTEMATIC_RULE` on each class, and on a series
       that does not split.
    5. **Implied coefficients.** The median of the bearings' implied f0
       (f1) with the order-statistic interval of the median
       (:func:`~bearingheat.analysis.deviations.median_interval`), each
       bearing's value known within ± half a rounding step of its speed.
       ``f0_spread`` is the robust relative spread of the bearings'
       implied f0; ``single_f0`` is False where it exceeds SPREAD_FACTOR
       times the typical spread of the groups of the same family that
       agree with the tables: the catalogue then did not use one f0 for
       the group, and the median is only a summary.

    Steps 1 and 2 use the scale of step 1 throughout; a series has at most
    one change point.
    """
    bearings = rows.copy()
    dev_all = bearings["deviation"].to_numpy(dtype=float)
    keys = bearings["series_key"].to_numpy(dtype=object)
    bore = bearings["d"].to_numpy(dtype=float) if "d" in bearings else np.full(len(bearings), np.nan)
    series_keys = list(dict.fromkeys(keys))
    whole_medians = [np.nanmedian(dev_all[keys == k]) if np.isfinite(dev_all[keys == k]).any() else np.nan
                     for k in series_keys]
    sigma, kept = consistent_scale(whole_medians, z=SYSTEMATIC_Z, floor=SCALE_FLOOR, min_groups=MIN_CONSISTENT)
    threshold = SYSTEMATIC_Z * sigma
    with np.errstate(divide="ignore", invalid="ignore"):
        # a bearing and its neighbours are each off by up to half a rounding step
        rounding = np.nan_to_num(bearings["rounding_step"].to_numpy(dtype=float)
                                 / bearings["n_thr_published"].to_numpy(dtype=float)) \
            if "rounding_step" in bearings else np.zeros(len(bearings))
    group = keys.copy()
    subgroup = np.array([""] * len(bearings), dtype=object)
    local = np.full(len(bearings), np.nan)
    outlier = np.zeros(len(bearings), dtype=bool)
    classes: dict[str, list[np.ndarray]] = {}
    for key in series_keys:
        members = np.flatnonzero((keys == key) & np.isfinite(dev_all))
        members = members[np.argsort(bore[members], kind="stable")]
        parts = [members]
        if np.isfinite(bore[members]).all():
            k = _size_split(dev_all[members], bore[members], threshold)
            if k is not None:
                parts = [members[:k], members[k:]]
        classes[key] = parts
        for part in parts:
            local[part] = local_residuals(dev_all[part], bore[part])
            spread = robust_scale(local[part])
            floor = threshold + rounding[part]
            outlier[part] = np.abs(local[part]) > (np.maximum(OUTLIER_Z * spread, floor) if np.isfinite(spread)
                                                   else floor)
            if len(parts) > 1:
                label = _bore_range(bore[part])
                subgroup[part] = label
                group[part] = f"{key} {label}"
    for name, values in zip(CLASSIFIED_COLUMNS, (group, subgroup, local, outlier)):
        bearings[name] = values
    records = []
    for key in series_keys:
        in_series = keys == key
        parts = classes[key]
        split = len(parts) > 1
        records.append(_group_record(bearings, in_series, "", threshold, sigma, confidence,
                                     flag=not split))
        if split:
            for part in parts:
                mask = np.zeros(len(bearings), dtype=bool)
                mask[part] = True
                records.append(_group_record(bearings, mask, subgroup[part[0]], threshold, sigma, confidence,
                                             flag=True))
    groups = pd.DataFrame(records, columns=list(GROUP_COLUMNS))
    _judge_spread(groups, split=[len(classes[k]) > 1 for k in series_keys])
    return ReferenceSpeedAudit(bearings, groups, sigma, threshold, int(np.sum(kept)),
                               int(np.isfinite(np.asarray(whole_medians, dtype=float)).sum()),
                               tuple(rows.attrs.get("skipped", ())))


def _judge_spread(groups: pd.DataFrame, split: list[bool]) -> None:
    """``single_f0`` and the note of the groups whose implied f0 spreads more than one table value explains.

    The reference is the median ``f0_spread`` of the groups that agree with
    the tables (size classes, and series that do not split) in the same
    family where it has at least two, otherwise in all families: how well
    one f0 reproduces a series when the catalogue did use one.
    """
    whole_split = np.zeros(len(groups), dtype=bool)
    whole = np.flatnonzero(groups["subgroup"] == "")
    whole_split[whole[np.array(split, dtype=bool)]] = True
    reference = (groups["median_deviation"].notna()
                 & ~groups["systematic"] & ~whole_split & (groups["computed"] >= SYSTEMATIC_MIN_ROWS)
                 & groups["note"].eq("") & groups["f0_spread"].notna())
    overall = float(groups.loc[reference, "f0_spread"].median()) if reference.any() else math.nan
    single = np.ones(len(groups), dtype=bool)
    spreads = groups["f0_spread"].to_numpy(dtype=float)
    for i in range(len(groups)):
        same = reference & (groups["family"] == groups["family"].iat[i])
        typical = float(groups.loc[same, "f0_spread"].median()) if same.sum() >= 2 else overall
        spread = spreads[i]
        if np.isfinite(typical) and np.isfinite(spread) and spread > SPREAD_FACTOR * typical:
            single[i] = False
            if groups["systematic"].iat[i]:
                groups.loc[groups.index[i], "note"] = _join(
                    str(groups["note"].iat[i]), f"implied f0 spreads {spread:.1%} (series that agree: {typical:.1%}): "
                    "no single f0 reproduces the group; the median is a summary")
    groups["single_f0"] = single


def _join(*parts: str) -> str:
    return "; ".join(p for p in parts if p)


def _group_record(bearings: pd.DataFrame, mask: np.ndarray, subgroup: str, threshold: float, sigma: float,
                  confidence: float, *, flag: bool) -> dict:
    """One row of the groups table: the bearings of ``mask`` (outliers left out of the statistics)."""
    part = bearings[mask]
    first = part.iloc[0]
    use = part[np.isfinite(part["deviation"].to_numpy(dtype=float)) & ~part["outlier"].to_numpy(dtype=bool)]
    dev = use["deviation"].to_numpy(dtype=float)
    record = {"group": f"{first['series_key']} {subgroup}".strip(), "family": first["family"],
              "series": first["series"], "subgroup": subgroup,
              "variants": ", ".join(dict.fromkeys(part["variant"].astype(str))),
              "d_min": float(part["d"].min()), "d_max": float(part["d"].max()),
              "bearings": len(part), "computed": int(np.isfinite(part["deviation"]).sum()),
              "outliers": int(part["outlier"].sum()), "note": ""}
    if len(dev) == 0:
        return {**record, "systematic": False, "single_f0": True}
    median = float(np.median(dev))
    systematic = flag and _deviates(dev, threshold)
    f0 = median_interval(use["f0_implied"], use["f0_implied_low"], use["f0_implied_high"], confidence=confidence)
    f1 = median_interval(use["f1_implied"], use["f1_implied_low"], use["f1_implied_high"], confidence=confidence)
    implied = use["f0_implied"].to_numpy(dtype=float)
    record.update(
        median_deviation=median, min_deviation=float(dev.min()), max_deviation=float(dev.max()),
        share_above=float(np.mean(dev > 0)), z=median / sigma, systematic=bool(systematic),
        f0_table=float(np.nanmedian(use["f0_table"])) if use["f0_table"].notna().any() else math.nan,
        f0_implied=f0[0], f0_implied_low=f0[1], f0_implied_high=f0[2],
        f0_spread=robust_scale(implied) / abs(f0[0]) if np.isfinite(implied).sum() >= 2 else math.nan,
        f1_table=float(np.nanmedian(use["f1_table"])) if use["f1_table"].notna().any() else math.nan,
        f1_implied=f1[0], f1_implied_low=f1[1], f1_implied_high=f1[2], interval_coverage=f0[3])
    if len(dev) < SYSTEMATIC_MIN_ROWS:
        record["note"] = f"{len(dev)} bearing{'s' if len(dev) != 1 else ''}: too few to judge"
    elif not flag and _deviates(dev, threshold):
        record["note"] = "the deviation lies in one size class"
    elif systematic and f1[2] <= 0:
        record["note"] = "no positive f1 reproduces the published speeds: the change is in f0"
    return record


def series_deviation_summary(rows: pd.DataFrame) -> pd.DataFrame:
    """The groups of :func:`classify_reference_speeds`: per series and size class, with the systematic flag.

    >>> rows = pd.DataFrame({"series_key": ["a"] * 6, "deviation": [0.2, 0.21, 0.19, 0.2, 0.22, 0.18]})
    >>> s = series_deviation_summary(rows)
    >>> bool(s.loc[0, "systematic"]), round(float(s.loc[0, "median_deviation"]), 3)
    (True, 0.2)
    """
    return classify_reference_speeds(_with_defaults(rows)).groups


def _with_defaults(rows: pd.DataFrame) -> pd.DataFrame:
    """A bare table of ``series_key`` and ``deviation`` completed with the columns the grouping reads."""
    out = rows.copy()
    defaults = {"family": out["series_key"], "series": "", "variant": "open", "d": np.nan}
    for name, value in defaults.items():
        if name not in out:
            out[name] = value
    for name in ("f0_table", "f0_implied", "f0_implied_low", "f0_implied_high",
                 "f1_table", "f1_implied", "f1_implied_low", "f1_implied_high"):
        if name not in out:
            out[name] = np.nan
    return out
