"""The DataFrame API: the ``bearingheat calc`` column contract on pandas.

Input columns are headed ``name [unit]`` where the unit is any pint unit of
the right dimension (``Fr [kN]``, ``n [rpm]``, ``n [Hz]``, ``nu [cSt]``).
The columns, their catalogue units and meanings are the column contract,
:mod:`bearingheat.calc.contract`; each row's friction model is the
``model`` column or the ``model`` argument (:mod:`bearingheat.calc.models`).

Result columns: the model's results (``f0``, ``f1``, ``P0 [N]``, ``P1 [N]``,
``M0 [N*mm]``, ``M1 [N*mm]``, ``M2 [N*mm]``, ``MR [N*mm]``, ``NR [W]`` for
the catalogue model), ``status`` (ok | warning | error) and ``message``;
``Fa/A`` and ``nu*n*dM [mm^3/(s*min)]`` when a row carries M2. Extensions
(the heat balance, contact checks) add their own columns when their inputs
are present.

A bad row gets ``status = error`` and a message naming the column and the
value; the other rows are still computed. Input that cannot be used at all
(a required column missing, a unit of the wrong dimension) raises
:class:`~bearingheat.errors.InputError`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd

from bearingheat.calc import contact, thermal
from bearingheat.calc.contract import PLAIN_TYPES, input_units, output_header, output_units, parse_header
from bearingheat.calc.messages import Labels
from bearingheat.calc.models import DEFAULT_MODEL, M2_REPORT_UNITS, PLAIN_REPORT_UNITS, RESULT_UNITS, \
    compute_supports
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import InputError, UnitError
from bearingheat.units import convert_column

__all__ = ["calc", "to_catalogue_units", "require_columns", "Extension", "EXTENSIONS"]


@dataclass(frozen=True)
class Extension:
    """A calc extension: it reads and writes the contract columns of its ``owner``.

    ``prepare(frame) -> (frame, problems)`` runs before the friction model,
    ``extend(frame, results) -> (columns, problems)`` after it; problems
    are (row position, 'error' | 'warning', message).
    """

    owner: str
    prepare: Callable
    extend: Callable


#: the extensions in the order their columns are written; keys are the contract owners
EXTENSIONS: dict[str, Extension] = {e.owner: e for e in (
    Extension("contact", contact.prepare, contact.extend),
    Extension("thermal", thermal.prepare, thermal.extend),
)}


@dataclass
class _Converted:
    frame: pd.DataFrame            # contract names, catalogue units
    labels: Labels
    row_errors: list[list[str]]


def _convert_column(values: pd.Series, header: str, unit_text: str | None, target: str,
                    cell: Callable[[str, int], str] | None, name: str,
                    errors: list[list[str]]) -> tuple[np.ndarray, float]:
    """Numbers of one column in the catalogue unit, and the catalogue units per user unit (NaN for an
    absolute temperature, which has no single factor); cells that are no numbers become row errors."""
    numeric = pd.to_numeric(values, errors="coerce").to_numpy(dtype=float)
    raw = values.to_numpy(dtype=object)
    for i, (num, cell_value) in enumerate(zip(numeric, raw)):
        if np.isnan(num) and not _blank(cell_value):
            where = f"{cell(name, i)}: " if cell else ""
            errors[i].append(f"{where}{cell_value!r} is not a number for {header}")
    try:
        return convert_column(numeric, unit_text, target, name=name, header=header)
    except UnitError as exc:
        raise InputError(f"column {header!r}: {exc}") from exc


def _blank(value) -> bool:
    return value is None or (isinstance(value, float) and math.isnan(value)) or str(value).strip() == ""


def to_catalogue_units(table: pd.DataFrame, *, units: dict[str, str] | None = None,
                       cell: Callable[[str, int], str] | None = None) -> _Converted:
    """Contract columns of ``table`` in catalogue units (unknown columns are passed through untouched).

    ``units`` maps a header to a unit typed in a separate units row (Excel);
    a unit in the header itself wins.
    """
    known = input_units()
    errors: list[list[str]] = [[] for _ in range(len(table))]
    columns: dict[str, np.ndarray | list] = {}
    headers: dict[str, tuple[str, float]] = {}
    for header in table.columns:
        name, unit_text = parse_header(header)
        if unit_text is None and units is not None:
            unit_text = units.get(header)
        if name not in known:
            continue
        if name in columns:
            raise InputError(f"column {header!r}: {name} appears twice")
        target = known[name]
        display = f"{name} [{unit_text}]" if unit_text not in (None, "", "-", "1") else name
        if target == "":
            columns[name] = [None if _blank(v) else str(v).strip() for v in table[header]]
            continue
        columns[name], factor = _convert_column(table[header], display, unit_text, target, cell, name, errors)
        headers[name] = (display, factor)
    frame = pd.DataFrame(columns, index=table.index)
    return _Converted(frame, Labels(headers, cell), errors)


def require_columns(frame: pd.DataFrame) -> None:
    """Raise :class:`InputError` naming the first required column the frame (contract names) lacks."""
    have = set(frame.columns)
    types = frame["type"] if "type" in have else pd.Series([None] * len(frame), index=frame.index)
    rolling = ~types.fillna("").astype(str).str.lower().isin(PLAIN_TYPES)
    if "n" not in have:
        raise InputError("missing column: 'n [1/min]' (any n unit of the right dimension)")
    if not rolling.any():
        return
    if "designation" not in have and not {"type", "series"} <= have:
        raise InputError("missing column: 'designation' (or 'type' and 'series')")
    for name in ("D", "nu"):
        if name not in have:
            unit = input_units()[name]
            raise InputError(f"missing column: '{name} [{unit}]' (any {name} unit of the right dimension)")
    if "lubrication" not in have and "f0" not in have:
        raise InputError("missing column: 'lubrication' (grease, oil_mist, oil_bath or circulating_oil)")


def calc(table: pd.DataFrame, *, model: str = DEFAULT_MODEL, f2_chart: F2Chart | str | None = None,
         units: dict[str, str] | None = None, cell: Callable[[str, int], str] | None = None,
         effects=None) -> pd.DataFrame:
    """Run the friction model (and its extensions) on a table of supports.

    Returns the input columns followed by the result columns. ``model`` is
    the friction model of rows whose ``model`` cell is blank (a name of
    :data:`bearingheat.calc.models.MODELS`; an unknown name raises
    :class:`~bearingheat.errors.ModelError`). ``effects`` is an optional
    fitted extension of the model (``bearingheat diagnose``) applied to MR
    and NR.

    >>> import pandas as pd
    >>> rows = pd.DataFrame({"designation": ["6205", "NU206-E"], "d [mm]": [25, 30], "D [mm]": [52, 62],
    ...                      "C0 [kN]": [7.8, 36], "lubrication": ["oil_bath", "grease"],
    ...                      "n [rpm]": [3000, 1500], "Fr [kN]": [2, 5], "nu [mm^2/s]": [12, 20]})
    >>> out = calc(rows)
    >>> out[["MR [N*mm]", "NR [W]", "status"]].round(3)
       MR [N*mm]  NR [W] status
    0     47.535  14.932     ok
    1     81.217  12.757     ok
    """
    if isinstance(f2_chart, str):
        f2_chart = F2Chart.from_csv(f2_chart)
    converted = to_catalogue_units(table, units=units, cell=cell)
    frame = converted.frame
    extra_problems: list[tuple[int, str, str]] = []
    for ext in EXTENSIONS.values():
        frame, problems = ext.prepare(frame)
        extra_problems.extend(problems)
    require_columns(frame)
    results = compute_supports(frame.reset_index(drop=True), f2_chart=f2_chart, labels=converted.labels,
                               model=model)
    results.index = table.index
    _merge_row_messages(results, converted.row_errors, "error")
    for position, level, message in extra_problems:
        _add_message(results, position, level, message)
    if effects is not None:
        effects.apply(frame, results)
    extension_columns = []
    for ext in EXTENSIONS.values():
        columns, problems = ext.extend(frame, results)
        for position, level, message in problems:
            _add_message(results, position, level, message)
        extension_columns.append((columns, output_units(owner=ext.owner)))
    return _assemble(table, results, extension_columns)


def _merge_row_messages(results: pd.DataFrame, row_messages: list[list[str]], level: str) -> None:
    for position, messages in enumerate(row_messages):
        for message in messages:
            _add_message(results, position, level, message)


def _add_message(results: pd.DataFrame, position: int, level: str, message: str) -> None:
    row = results.index[position]
    current = results.at[row, "message"]
    results.at[row, "message"] = f"{current}; {message}" if current else message
    if level == "error":
        results.at[row, "status"] = "error"
        results.loc[row, [c for c in RESULT_UNITS]] = np.nan
    elif results.at[row, "status"] == "ok":
        results.at[row, "status"] = "warning"


def _assemble(table: pd.DataFrame, results: pd.DataFrame, extension_columns) -> pd.DataFrame:
    out = table.copy()
    for name, unit in RESULT_UNITS.items():
        out[output_header(name, unit)] = results[name].to_numpy()
    for name, unit in {**M2_REPORT_UNITS, **PLAIN_REPORT_UNITS}.items():
        if name in results.columns:
            out[output_header(name, unit)] = results[name].to_numpy()
    failed = (results["status"] == "error").to_numpy()
    for columns, units in extension_columns:
        for name in columns.columns:
            values = columns[name].to_numpy()
            if values.dtype.kind == "f":
                values = np.where(failed, np.nan, values)
            out[output_header(name, units.get(name, ""))] = values
    out["status"] = results["status"].to_numpy()
    out["message"] = results["message"].to_numpy()
    return out
