"""Duty cycles: several operating cases of one support, weighted by their time shares.

A calc table holds a duty cycle when it has a ``support`` column: the rows
of one support are its cases (``case`` names them), each with a
``time_share`` (fractions summing to 1 per support) or a ``duration``
[h] (any time unit; the shares are the durations over their sum).
:func:`duty_cycle` turns calc's results into one row per support:

- ``MR_mean [N*mm]``, ``NR_mean [W]``: the time-weighted means Σ sᵢ·xᵢ;
- ``energy_per_hour [W*h]``: the energy lost in one hour of the cycle,
  NR_mean × 1 h (``energy [W*h]`` over the whole cycle where durations are
  given);
- ``T_op_max [degC]`` and ``T_op_max_case``: the hottest case (with the
  heat balance);
- ``n_per_margin_min`` and ``n_per_margin_case``: the lowest n_per/n and
  its case (with the heat balance; below 1 the support runs too fast for
  its heat balance in that case);
- ``status`` and ``message``: 'error' where a case of the support is in
  error (its means are then NaN: without that case they would be wrong),
  'warning' where one has a warning.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pandas as pd

from bearingheat.calc.contract import output_header
from bearingheat.calc.supports import number_column, text_column
from bearingheat.calc.conversion import blank_cell, to_catalogue_units
from bearingheat.errors import DutyCycleError

__all__ = ["SHARE_TOLERANCE", "DUTY_UNITS", "support_headers", "has_duty_cycle", "duty_cycle"]

#: the shares of a support must sum to 1 within this (0.1 %)
SHARE_TOLERANCE = 1e-3
#: the summary's columns -> unit ('' for text)
DUTY_UNITS = {"support": "", "designation": "", "cases": "1", "MR_mean": "N*mm", "NR_mean": "W",
              "energy_per_hour": "W*h", "energy": "W*h", "T_op_max": "degC", "T_op_max_case": "",
              "n_per_margin_min": "1", "n_per_margin_case": "", "status": "", "message": ""}


def support_headers(headers) -> list:
    """The headers among ``headers`` that name the ``support`` column of a duty cycle (with any unit text), the
    only columns :func:`has_duty_cycle` looks at; a table without them has no duty cycle.

    >>> support_headers(["id", "support", "n [rpm]"])
    ['support']
    """
    return [h for h in headers if str(h).split("[")[0].strip() == "support"]


def has_duty_cycle(table: pd.DataFrame) -> bool:
    """True when the table (calc input or output) has a ``support`` column that names a support in some row. A
    column left entirely blank (the template's unused one, or a CSV written from a workbook) is no duty cycle, in
    a CSV as in a workbook; a table without rows (its headers only) is judged by its headers.

    >>> has_duty_cycle(pd.DataFrame({"support": ["A"], "n [rpm]": [1000]}))
    True
    >>> has_duty_cycle(pd.DataFrame({"support": [None, " "], "n [rpm]": [1000, 2000]}))
    False
    """
    headers = support_headers(table.columns)
    if not headers or len(table) == 0:
        return bool(headers)
    return any(not all(blank_cell(value) for value in pd.unique(table[h].to_numpy(dtype=object))) for h in headers)


def _shares(frame: pd.DataFrame, supports: np.ndarray, cases: list[str]) -> tuple[np.ndarray, np.ndarray | None]:
    """Each row's time share (and its duration [h] where durations are given), checked per support."""
    # a column left all blank (a template's unused one) counts as absent
    has_share, has_duration = (name in frame.columns and not np.isnan(number_column(frame, name)).all()
                               for name in ("time_share", "duration"))
    if has_share == has_duration:
        raise DutyCycleError("a duty cycle needs one of the columns 'time_share' (fractions summing to 1 per "
                             "support) or 'duration [h]'" + (", not both" if has_share else ""))
    name = "time_share" if has_share else "duration"
    values = number_column(frame, name)
    for i in np.flatnonzero(~(values >= 0)):  # NaN or negative
        what = "blank or not a number" if np.isnan(values[i]) else f"{values[i]:g}, negative"
        raise DutyCycleError(f"support {supports[i]!r}, case {cases[i]!r}: {name} is {what}; give "
                             + ("a fraction from 0 to 1" if has_share else "a time >= 0"))
    totals = pd.Series(values).groupby(supports, sort=False).transform("sum").to_numpy()
    if has_share:
        off = np.abs(totals - 1.0) > SHARE_TOLERANCE
        if off.any():
            first = supports[np.flatnonzero(off)[0]]
            rows = supports == first
            raise DutyCycleError(f"support {first!r}: the time_share values of its cases "
                                 f"({', '.join(f'{c} {v:g}' for c, v in zip(np.array(cases)[rows], values[rows]))}) "
                                 f"sum to {totals[rows][0]:g}, not 1 (within {SHARE_TOLERANCE:.1%})")
        return values, None
    zero = totals <= 0
    if zero.any():
        raise DutyCycleError(f"support {supports[np.flatnonzero(zero)[0]]!r}: its durations sum to 0 h")
    return values / totals, values


def duty_cycle(results: pd.DataFrame, cell: Callable[[str, int], str] | None = None) -> pd.DataFrame:
    """One row per support of calc's results: time-weighted means and the worst case (see the module).

    Parameters
    ----------
    results : pandas.DataFrame
        The output of :func:`bearingheat.calc` on a table with ``support``,
        ``case`` (optional: the row's position names it) and ``time_share``
        or ``duration [h]`` columns.
    cell : callable, optional
        (column, row position) -> where a message names a row, such as
        'Supports!J7' (a workbook); without it 'row 3' (the table's third row).

    Returns
    -------
    pandas.DataFrame
        Columns ``support``, ``designation``, ``cases``, ``MR_mean [N*mm]``,
        ``NR_mean [W]``, ``energy_per_hour [W*h]`` (``energy [W*h]`` with
        durations), ``T_op_max [degC]``, ``T_op_max_case``,
        ``n_per_margin_min``, ``n_per_margin_case`` (the last four with the
        heat balance's columns), ``status`` and ``message``, in the order the
        supports first appear.

    Raises
    ------
    bearingheat.errors.DutyCycleError
        No ``support`` column; neither or both of ``time_share`` and
        ``duration``; a blank or negative share; shares of a support that do
        not sum to 1 within 0.1 %; a support whose rows name different
        designations.

    Examples
    --------
    >>> results = pd.DataFrame({"support": ["A", "A"], "case": ["low", "high"], "time_share": [0.75, 0.25],
    ...                         "designation": ["6208", "6208"], "n [rpm]": [1000, 3000],
    ...                         "MR [N*mm]": [100.0, 140.0], "NR [W]": [10.47, 43.98],
    ...                         "status": ["ok", "ok"], "message": ["", ""]})
    >>> duty_cycle(results)[["support", "MR_mean [N*mm]", "NR_mean [W]"]]
      support  MR_mean [N*mm]  NR_mean [W]
    0       A           110.0     18.8475
    """
    if not has_duty_cycle(results):
        raise DutyCycleError("no 'support' column: a duty cycle names the physical bearing of each row in "
                             "'support' and its cases in 'case'")
    frame = to_catalogue_units(results).frame
    supports = np.array(text_column(frame, "support"), dtype=object)
    blank = np.flatnonzero(pd.isna(supports))
    if len(blank):
        where = cell("support", int(blank[0])) if cell is not None else f"row {blank[0] + 1}"
        raise DutyCycleError(f"{where}: support is blank; every row of a duty cycle names its support")
    cases = [c if c is not None else (cell("case", i) if cell is not None else f"row {i + 1}")
             for i, c in enumerate(text_column(frame, "case"))]
    shares, durations = _shares(frame, supports, cases)
    designations = np.array(text_column(frame, "designation"), dtype=object)
    grouped = pd.DataFrame({"support": supports, "designation": designations}).groupby("support", sort=False)
    differing = grouped["designation"].nunique(dropna=False)
    if (differing > 1).any():
        name = differing.index[np.flatnonzero(differing.to_numpy() > 1)[0]]
        named = pd.unique(designations[supports == name])
        raise DutyCycleError(f"support {name!r}: its rows name different bearings in 'designation' "
                             f"({', '.join(map(str, named))}); one support is one bearing")
    weighted = {"MR_mean": _column(results, "MR"), "NR_mean": _column(results, "NR")}
    parts = pd.DataFrame({"support": supports, **{k: shares * v for k, v in weighted.items()}})
    summary = parts.groupby("support", sort=False).sum(min_count=1)
    out = pd.DataFrame({"support": summary.index.to_numpy(dtype=object)})
    out["designation"] = grouped["designation"].first().to_numpy()
    out["cases"] = grouped.size().to_numpy()
    out[output_header("MR_mean", DUTY_UNITS["MR_mean"])] = summary["MR_mean"].to_numpy()
    out[output_header("NR_mean", DUTY_UNITS["NR_mean"])] = summary["NR_mean"].to_numpy()
    out[output_header("energy_per_hour", "W*h")] = summary["NR_mean"].to_numpy() * 1.0  # NR_mean [W] × 1 h
    if durations is not None:
        energy = pd.Series(durations * weighted["NR_mean"]).groupby(supports, sort=False).sum(min_count=1)
        out[output_header("energy", "W*h")] = energy.to_numpy()
    codes = pd.factorize(pd.Series(supports, dtype=object))[0]
    if output_header("T_op", "degC") in results.columns:
        T_op = _column(results, "T_op", "degC")
        out[output_header("T_op_max", "degC")], out["T_op_max_case"] = _extreme(T_op, codes, cases, np.nanargmax)
    if output_header("n_per", "1/min") in results.columns:
        margin = _column(results, "n_per", "1/min") / number_column(frame, "n")
        out["n_per_margin_min"], out["n_per_margin_case"] = _extreme(margin, codes, cases, np.nanargmin)
    out["status"], out["message"] = _status(results, codes, cases, len(out))
    failed = out["status"].to_numpy() == "error"  # a mean without one of its cases would be wrong: none
    out.loc[failed, [c for c in out.columns if c.startswith(("MR_mean", "NR_mean", "energy"))]] = np.nan
    return out


def _column(results: pd.DataFrame, name: str, unit: str | None = None) -> np.ndarray:
    header = output_header(name, unit) if unit is not None else output_header(name)
    return pd.to_numeric(results[header], errors="coerce").to_numpy(dtype=float)


def _extreme(values: np.ndarray, codes: np.ndarray, cases: list[str], pick) -> tuple[np.ndarray, list]:
    """Per support, the extreme value (``pick``: nanargmax or nanargmin) and the case it occurs in."""
    best, where = np.full(codes.max() + 1, np.nan), [""] * (codes.max() + 1)
    for code in range(codes.max() + 1):  # one pass per support, not per row
        rows = np.flatnonzero(codes == code)
        finite = rows[np.isfinite(values[rows])]
        if len(finite):
            i = finite[pick(values[finite])]
            best[code], where[code] = values[i], cases[i]
    return best, where


def _status(results: pd.DataFrame, codes: np.ndarray, cases: list[str], count: int) -> tuple[list, list]:
    """Per support: 'error' naming the cases in error, else 'warning' naming those with warnings, else 'ok'."""
    status = results["status"].to_numpy(dtype=object)
    out_status, out_message = ["ok"] * count, [""] * count
    for level, text in (("warning", "case(s) with a warning: {}"),
                        ("error", "case(s) in error, so the support has no means: {}")):
        for code in np.unique(codes[status == level]):
            named = [cases[i] for i in np.flatnonzero((codes == code) & (status == level))]
            out_status[code], out_message[code] = level, text.format(", ".join(named))
    return out_status, out_message
