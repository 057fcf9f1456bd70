"""The DataFrame API: the ``bearingheat calc`` column contract on pandas.

Input columns are headed ``name [unit]`` where the unit is any pint unit of
the right dimension (``Fr [kN]``, ``n [rpm]``, ``n [Hz]``, ``nu [cSt]``):

=================  ==========  =====================================================
column             unit        meaning
=================  ==========  =====================================================
id                 text        the user's label of the support
designation        text        e.g. 6205-2Z, NU206-E, 30205-A (or give type and series)
type, series       text        explicit table row, e.g. deep_groove_ball / 62
d, D, B            length      bore, outside diameter, width
C0                 force       static load rating
Y, e, X0, Y0       1           catalogue factors (override the tables)
alpha              angle       working contact angle of angular contact ball bearings
arrangement        text        single (default) or paired
f0, f1, f2         1           coefficient overrides
lubrication        text        grease, oil_mist, oil_bath, circulating_oil
n                  1/time      shaft speed (Hz = rev/s; rad/s is divided by 2π)
Fr, Fa             force       radial and axial load (blank = 0)
nu                 area/time   operating viscosity (base oil for grease)
=================  ==========  =====================================================

Result columns: ``f0``, ``f1``, ``P0 [N]``, ``P1 [N]``, ``M0 [N*mm]``,
``M1 [N*mm]``, ``M2 [N*mm]``, ``MR [N*mm]``, ``NR [W]``, ``status``
(ok | warning | error), ``message``; ``Fa/A`` and ``nu*n*dM [mm^3/(s*min)]``
when a row carries M2. Extensions (the heat balance, contact checks, plain
bushings) add their own columns when their inputs are present.

A bad row gets ``status = error`` and a message naming the column and the
value; the other rows are still computed. Input that cannot be used at all
(a required column missing, a unit of the wrong dimension) raises
:class:`InputError`.
"""
from __future__ import annotations

import importlib
import math
import re
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd
import pint

from bearingheat.f2chart import F2Chart
from bearingheat.model import (INPUT_UNITS, M2_REPORT_UNITS, PLAIN_REPORT_UNITS, PLAIN_TYPES, RESULT_UNITS, Labels,
                               compute_supports)
from bearingheat.units import UnitError, parse_unit, speed_rpm, ureg
from bearingheat.errors import InputError

__all__ = ["InputError", "calc", "parse_header", "EXTENSIONS", "input_units", "output_header"]




#: modules that add inputs and result columns to calc; each defines INPUT_UNITS, OUTPUT_UNITS,
#: prepare(frame) -> (frame, problems) and extend(frame, results) -> (columns, problems),
#: where problems are (row position, 'error' | 'warning', message).
EXTENSIONS: list[str] = [
    "bearingheat.contact_calc",
    "bearingheat.thermal_calc",
]

_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]+?)\s*(?:\[\s*(?P<unit>[^\]]*?)\s*\])?\s*$")
_OUTPUT_NAMES = {"Fa_over_A": "Fa/A", "nu_n_dM": "nu*n*dM", "p_plain": "p", "V_plain": "V"}


def _extensions():
    return [importlib.import_module(path) for path in EXTENSIONS]


def input_units() -> dict[str, str]:
    """Every input column calc reads (with its extensions) -> its catalogue unit."""
    units = dict(INPUT_UNITS)
    for ext in _extensions():
        units.update(ext.INPUT_UNITS)
    return units


def parse_header(header, *, strict: bool = True) -> tuple[str, str | None]:
    """``'Fr [kN] '`` -> ``('Fr', 'kN')``; ``'id'`` -> ``('id', None)``.

    A header that is not ``name [unit]`` raises :class:`InputError`, or with
    ``strict=False`` comes back whole as a name without a unit.

    >>> parse_header(' n [U/min] ')
    ('n', 'U/min')
    >>> parse_header('a] b', strict=False)
    ('a] b', None)
    """
    match = _HEADER.match(str(header))
    if not match:
        if not strict:
            return str(header).strip(), None
        raise InputError(f"column {header!r}: cannot read the header; write it as 'name [unit]'")
    return match.group("name").strip(), match.group("unit")


def output_header(name: str, unit: str) -> str:
    shown = _OUTPUT_NAMES.get(name, name)
    return shown if unit in ("", "1") else f"{shown} [{unit}]"


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
    if target == "1":
        if unit_text in (None, "", "-", "1"):
            return numeric, 1.0
        one = ureg().Quantity(1.0, parse_unit(unit_text, name=header))
        if not one.dimensionless:
            raise InputError(f"column {header!r}: {name} is dimensionless, {unit_text!r} is not")
        factor = float(one.to("dimensionless").magnitude)
        return numeric * factor, factor
    if unit_text is None or unit_text.strip() in ("", "-"):
        raise InputError(f"column {header!r}: needs a unit, e.g. '{name} [{target}]'")
    try:
        unit = parse_unit(unit_text, name=header)
        if target == "1/min":
            try:
                factor = float(speed_rpm(ureg().Quantity(1.0, unit), header))
            except UnitError as exc:
                raise UnitError(f"{unit_text} is not a shaft speed; expected revolutions per time "
                                "(1/min, rpm, Hz) or an angular speed (rad/s)") from exc
            return numeric * factor, factor
        one = ureg().Quantity(1.0, unit)
        if one._is_multiplicative and ureg().Quantity(1.0, target)._is_multiplicative:
            factor = float(_to(one, target, header))
            return numeric * factor, factor
        # an absolute temperature (K, degC, degF): offset conversion of the whole column
        return np.asarray(_to(ureg().Quantity(numeric, unit), target, header), dtype=float), math.nan
    except UnitError as exc:
        raise InputError(f"column {header!r}: {exc}") from exc


def _to(q: pint.Quantity, target: str, header: str):
    try:
        return q.to(target).magnitude
    except pint.errors.DimensionalityError as exc:
        if q.dimensionality == ureg().kg.dimensionality and target == "N":
            raise UnitError(f"{q.units} is a mass, not a force; for kilogram-force write kgf") from exc
        raise UnitError(f"unit {q.units} cannot be converted to {target}") from exc


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


def _require(frame: pd.DataFrame) -> None:
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
            unit = INPUT_UNITS[name]
            raise InputError(f"missing column: '{name} [{unit}]' (any {name} unit of the right dimension)")
    if "lubrication" not in have and "f0" not in have:
        raise InputError("missing column: 'lubrication' (grease, oil_mist, oil_bath or circulating_oil)")


def calc(table: pd.DataFrame, *, f2_chart: F2Chart | str | None = None, units: dict[str, str] | None = None,
         cell: Callable[[str, int], str] | None = None, effects=None) -> pd.DataFrame:
    """Run the friction model (and its extensions) on a table of supports.

    Returns the input columns followed by the result columns. ``effects``
    is an optional fitted extension of the model (``bearingheat diagnose``)
    applied to MR and NR.

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
    for ext in _extensions():
        frame, problems = ext.prepare(frame)
        extra_problems.extend(problems)
    _require(frame)
    results = compute_supports(frame.reset_index(drop=True), f2_chart=f2_chart, labels=converted.labels)
    results.index = table.index
    _merge_row_messages(results, converted.row_errors, "error")
    for position, level, message in extra_problems:
        _add_message(results, position, level, message)
    if effects is not None:
        effects.apply(frame, results)
    extension_columns = []
    for ext in _extensions():
        columns, problems = ext.extend(frame, results)
        for position, level, message in problems:
            _add_message(results, position, level, message)
        extension_columns.append((columns, ext.OUTPUT_UNITS))
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
