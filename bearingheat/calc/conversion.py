"""The unit boundary of calc's tables: a table's contract columns in catalogue units, their cells checked.

:func:`to_catalogue_units` reads each contract column of a table headed ``name [unit]`` (or with a units row,
Excel): numbers in the column's unit converted to the catalogue unit (:func:`bearingheat.units.convert_column`),
text columns as categoricals of their cleaned texts, cells that are no numbers, logical values, dates and
out-of-range values as row messages that name the cell; a header that writes its unit another way is refused.
:func:`bearingheat.calc.table.calc` runs the friction model and the extensions on what it returns.
"""
from __future__ import annotations

import datetime
import math
import re
from collections import defaultdict
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field
from typing import Any, Callable, NamedTuple

import numpy as np
import pandas as pd

from bearingheat.calc.contract import (LABEL_COLUMNS, input_units, parse_header, range_problems, readable_header,
                                      result_column)
from bearingheat.calc.messages import Labels
from bearingheat.calc.supports import column_codes, per_distinct, text_categorical
from bearingheat.errors import InputError, UnitError
from bearingheat.units import convert_column

__all__ = ["to_catalogue_units", "ConvertedTable", "refuse_result_columns", "not_a_number", "with_decimal_point",
           "blank_cell", "numbers_of", "row_numbers", "row_number", "row_name",
           "lookalike_column", "Lookalike",
           "results_spelled_otherwise"]


@dataclass
class ConvertedTable:
    """A table's contract columns in catalogue units, how messages name them, and the cells' own problems.

    ``errors_by_row`` and ``warnings_by_row`` hold the messages of the rows that have them only (row
    position -> messages in column order); ``row_errors`` and ``row_warnings`` are the same as one list
    per row.
    """

    frame: pd.DataFrame            # contract names, catalogue units
    labels: Labels
    errors_by_row: dict[int, list[str]] = field(default_factory=dict)
    warnings_by_row: dict[int, list[str]] = field(default_factory=dict)

    @property
    def row_errors(self) -> list[list[str]]:
        return [self.errors_by_row.get(i, []) for i in range(len(self.frame))]

    @property
    def row_warnings(self) -> list[list[str]]:
        return [self.warnings_by_row.get(i, []) for i in range(len(self.frame))]


def _convert_column(values: pd.Series, header: str, unit_text: str | None, target: str,
                    cell: Callable[[str, int], str] | None, name: str,
                    errors: defaultdict[int, list[str]], warnings: defaultdict[int, list[str]],
                    decimal: str = ".") -> tuple[np.ndarray, float]:
    """Numbers of one column in the catalogue unit, and the catalogue units per user unit (NaN for an
    absolute temperature, which has no single factor). Cells that are no numbers, logical values,
    non-finite numbers and numbers outside the contract's valid range become row errors; numbers outside
    its plausible range become row warnings."""
    if pd.api.types.is_bool_dtype(values.dtype):
        logical = np.ones(len(values), dtype=bool)
    elif values.dtype == object:  # a mixed column: True/False cells among numbers
        logical = _logical_cells(values)
    else:
        logical = np.zeros(len(values), dtype=bool)
    if isinstance(values.dtype, np.dtype) and values.dtype.kind in "iuf":  # numpy numbers (to_numeric would copy)
        numeric = values.to_numpy(dtype=float)
    elif values.dtype.kind in "mM":  # dates or durations (pandas would give their nanoseconds): no numbers
        values = pd.Series(values.to_numpy(dtype=object), index=values.index, dtype=object).where(values.notna())
        numeric = np.full(len(values), np.nan)
    else:
        given = values.where(~logical, np.nan) if logical.any() else values
        if decimal == ",":  # '3,2' is 3.2 and '1.480' no number (each distinct text looked at once)
            given = pd.Series(per_distinct(given, with_decimal_point), index=values.index, dtype=object)
        numeric = pd.to_numeric(given, errors="coerce").to_numpy(dtype=float)

    def where(i):
        return f"{cell(name, i)}: " if cell else ""

    not_given = np.isnan(numeric)
    missing = np.flatnonzero(not_given) if not_given.any() else np.zeros(0, dtype=np.intp)
    if values.dtype.kind == "f" or not len(missing):  # a missing number is a blank cell
        blank = np.ones(len(missing), dtype=bool)
    else:
        blank = per_distinct(values.iloc[missing], blank_cell).astype(bool)
    for i in missing[~blank | logical[missing]].tolist():  # cells that are no numbers; blank cells are not given
        raw = values.iloc[i]
        raw = raw.item() if isinstance(raw, np.generic) else raw  # as typed: True, not np.True_
        if logical[i]:
            errors[i].append(f"{where(i)}{raw!r} is a logical value, not a number for {header}")
        elif not blank_cell(raw):
            errors[i].append(f"{where(i)}{not_a_number(raw, header, decimal, shown=_as_typed(raw))}")
    try:
        converted, factor = convert_column(numeric, unit_text, target, name=name, header=header, copy=False)
    except UnitError as exc:
        raise InputError(f"column {header!r}: {exc}") from exc
    if np.shares_memory(converted, numeric) and not converted.flags.owndata:  # a view of the user's table
        converted = converted.view()
        converted.flags.writeable = False  # calc never writes into the user's numbers: read, not copied
    shown_unit = {"1": "", "delta_degC": "K"}.get(target, target)

    def describe(i):
        value = f"{numeric[i]:g}" if factor == 1.0 or np.isinf(numeric[i]) else \
            f"{numeric[i]:g} ({converted[i]:g} {shown_unit})".replace(" )", ")")
        return f"{where(i)}{header}: {value}"

    found_errors, found_warnings = range_problems(name, converted, describe)
    for i, message in found_errors:
        errors[i].append(message)
    for i, message in found_warnings:
        warnings[i].append(message)
    return converted, factor


#: decimal mark -> the other mark, which in a number typed as text says the mark was taken wrongly
_DECIMAL_MARKS = {".": ",", ",": "."}


def not_a_number(value, header: str, decimal: str = ".", shown=None) -> str:
    """The message of a cell that is no number (``shown``: the cell as the message shows it, else ``value``), with
    the decimal mark where a text holds the other mark."""
    mark = f" (the decimal mark is {decimal!r})" if isinstance(value, str) and _DECIMAL_MARKS[decimal] in value else ""
    return f"{(value if shown is None else shown)!r} is not a number for {header}{mark}"


def with_decimal_point(value):
    """A text number with a decimal comma as pandas reads numbers ('3,2' -> '3.2'); text with a point is no
    number then (None: '1.480' is no 1.48); numbers and blanks as they are."""
    if not isinstance(value, str):
        return value
    return None if "." in value else value.replace(",", ".")


def row_numbers(table: pd.DataFrame) -> np.ndarray | None:
    """The row numbers messages cite for a table: the file's line of each row of a CSV
    (``attrs['lines']``, read by :func:`bearingheat.io.tables.read_table`, as calc cites them); None where the
    source has no lines (a DataFrame, Parquet): then a row is its position + 1."""
    lines = table.attrs.get("lines")
    return None if lines is None or len(lines) != len(table) else np.fromiter(lines, dtype=np.int64, count=len(table))


def row_number(rows: np.ndarray | None, position: int) -> int:
    """The number of the row at ``position`` (:func:`row_numbers`)."""
    return int(rows[position]) if rows is not None else position + 1


def row_name(rows: np.ndarray | None, position: int) -> str:
    """How a message names the row at ``position``: 'row 5' for the file's line 5 (:func:`row_number`)."""
    return f"row {row_number(rows, position)}"


def numbers_of(values: pd.Series, decimal: str = ".") -> np.ndarray:
    """The cells of a column as numbers, text read with the file's decimal mark (``attrs['decimal']``,
    '.' or ','); cells that are no numbers are NaN (each distinct text looked at once)."""
    if decimal == "," and not pd.api.types.is_numeric_dtype(values.dtype):
        values = pd.Series(per_distinct(values, with_decimal_point), index=values.index, dtype=object)
    return pd.to_numeric(values, errors="coerce").to_numpy(dtype=float)


def _as_typed(value):
    """A cell as a message shows it: a date or time (a date typed into a number cell) as the sheet's text."""
    if isinstance(value, datetime.datetime) and value.time() == datetime.time(0):
        return value.date().isoformat()
    return value.isoformat() if isinstance(value, (datetime.date, datetime.time)) else value


def _is_logical(value) -> bool:
    return isinstance(value, (bool, np.bool_))


_LOGICAL = np.frompyfunc(_is_logical, 1, 1)


def _logical_cells(values: pd.Series) -> np.ndarray:
    """Which cells of an object column hold a logical value (True, False). Distinct values are hashed once, but
    True == 1 and False == 0 hash alike, so the cells of a distinct value equal to 0 or 1 are looked at one by
    one (an Excel TRUE among loads of 1 kN, a load of 0 among FALSE)."""
    codes, uniques = column_codes(values)
    logical = np.zeros(len(values), dtype=bool)
    cells = values.to_numpy(dtype=object)
    for code, unique in enumerate(uniques):
        if isinstance(unique, (bool, np.bool_, int, float, np.number)) and unique in (0, 1):
            rows = np.flatnonzero(codes == code)
            logical[rows] = _LOGICAL(cells[rows]).astype(bool)
    return logical


def _text_cell(value) -> str:
    """A text cell as typed: a whole number that a numeric column made a float (62.0 of a column of series
    with a blank cell) reads as the integer it was ('62')."""
    if isinstance(value, (float, np.floating)) and float(value).is_integer():
        return str(int(value))
    return str(value).strip()


def blank_cell(value) -> bool:
    """Whether a cell is blank: None, NaN or only spaces."""
    return value is None or (isinstance(value, float) and math.isnan(value)) or str(value).strip() == ""


def to_catalogue_units(table: pd.DataFrame, *, units: dict[str, str] | None = None,
                       cell: Callable[[str, int], str] | None = None, decimal: str = ".") -> ConvertedTable:
    """Contract columns of ``table`` in catalogue units (unknown columns are passed through untouched).

    ``units`` maps a header to a unit typed in a separate units row (Excel);
    a unit in the header itself wins. ``decimal`` is the decimal mark of
    numbers typed as text ('.' or ',').
    """
    known = input_units()
    _refuse_lookalikes(table.columns, known)
    errors: defaultdict[int, list[str]] = defaultdict(list)  # only the rows that have messages
    warnings: defaultdict[int, list[str]] = defaultdict(list)
    columns: dict[str, np.ndarray | pd.Series] = {}
    headers: dict[str, tuple[str, float]] = {}
    seen: set[str] = set()
    for header in table.columns:
        name, unit_text = parse_header(header)
        if unit_text is None and units is not None:
            unit_text = units.get(header)
        if name not in known:
            continue
        if name in seen:
            raise InputError(f"column {header!r}: {name} appears twice")
        seen.add(name)
        if name in LABEL_COLUMNS:  # passed through as typed (the output keeps the input columns)
            continue
        target = known[name]
        display = f"{name} [{unit_text}]" if unit_text not in (None, "", "-", "1") else name
        if target == "":
            columns[name] = pd.Series(text_categorical(table[header], lambda v: None if blank_cell(v) else _text_cell(v)),
                                      index=table.index)
            continue
        columns[name], factor = _convert_column(table[header], display, unit_text, target, cell, name, errors,
                                                warnings, decimal)
        headers[name] = (display, factor)
    # the arrays are calc's own (converted, or copied below): the frame takes them as they are, not stacked into
    # one block (a copy of every column, 0.08 s for 14 columns of 10^6 rows)
    frame = pd.DataFrame(columns, index=table.index, copy=False)
    return ConvertedTable(frame, Labels(headers, cell), dict(errors), dict(warnings))


#: a header that writes its unit another way than 'name [unit]': 'Fr (kN)', 'Fr, kN', 'Fr/kN', 'Fr in kN'
_OTHER_UNIT_FORM = re.compile(r"^\s*(\w+)\s*(?:\((.+)\)|,\s*(.+)|/\s*(.+)|\s+in\s+(.+))\s*$")


class Lookalike(NamedTuple):
    """A header that is not read but looks like a column the table lacks: the column ``meant`` and the header
    ``written`` to name it with."""

    header: Any
    meant: str
    written: str

    def message(self, reading: str, consequence: str) -> str:
        """The refusal: the header, the column it looks like, ``reading`` ('calc would not read': who does not read
        it from the header), the header to write and ``consequence``, what becomes of the table as it is."""
        return (f"column {self.header!r} looks like {self.meant!r}, which {reading} from it: name it "
                f"{self.written!r} (headers are 'name [unit]', the name in its own letters); as it is, {consequence}")


def lookalike_column(headers, known: Mapping[str, str], *, never_missed: Collection[str] = (),
                     text_in_other_form: bool = False) -> Lookalike | None:
    """The first header that is not read but looks like a column of ``known`` (name -> unit, '' for a text column)
    the table lacks, or None: the unit written another way ('Fr (kN)', :data:`_OTHER_UNIT_FORM`) or the name in
    other letter case ('FR', 'fr [kN]', 'Arrangement'; names of two or more letters).

    A column of ``never_missed`` (a label, only passed through) is not looked for. A text column written in the
    other-unit form ('Model (old)') is a note, not a lookalike, unless ``text_in_other_form`` (diagnose's
    ``group``: 'group (run)' would leave the rows grouped by operating point instead of by the labels).

    >>> lookalike_column(["Fr (kN)", "n [1/min]"], {"Fr": "N", "n": "1/min"})
    Lookalike(header='Fr (kN)', meant='Fr', written='Fr [kN]')
    >>> lookalike_column(["Group (run)"], {"group": ""}) is None, lookalike_column(["Group (run)"], {"group": ""},
    ...                                                                            text_in_other_form=True)
    (True, Lookalike(header='Group (run)', meant='group', written='group'))
    """
    names = {}
    for header in headers:
        try:
            names[header] = parse_header(header)
        except InputError:
            names[header] = (str(header), None)
    present = {name for name, _ in names.values()}
    missing = {name: unit for name, unit in known.items() if name not in present and name not in never_missed}
    numeric = {name: unit for name, unit in missing.items() if unit != ""}
    exact = missing if text_in_other_form else numeric
    by_case = {name.casefold(): name for name in missing if len(name) > 1}
    for header, (name, unit) in names.items():
        if name in known:
            continue
        other_form = _OTHER_UNIT_FORM.match(name)
        base, typed = (other_form.group(1), next(g for g in other_form.groups()[1:] if g)) if other_form \
            else (name, unit)
        meant = base if base in exact else by_case.get(base.casefold()) if len(base) > 1 else None
        if meant is None or (other_form and meant not in exact):  # ('Model (old)' is a note, not a unit)
            continue
        written = f"{meant} [{(typed or numeric[meant]).strip()}]" if meant in numeric else meant
        return Lookalike(header, meant, written)
    return None


def _refuse_lookalikes(headers, known: dict[str, str]) -> None:
    """:class:`InputError` for a header that is not read but looks like a column the table lacks
    (:func:`lookalike_column`). Such a column would be passed through and its loads taken as 0, its values as
    absent, or a paired arrangement computed as a single bearing. (A label column is only passed through: 'ID'
    beside it loses nothing.)"""
    found = lookalike_column(headers, known, never_missed=LABEL_COLUMNS)
    if found is not None:
        raise InputError(found.message("calc would not read",
                                       f"the table would be computed as if {found.meant} were not given"))


#: the status values calc writes
_STATUSES = frozenset({"ok", "warning", "error"})


def _calc_results(table: pd.DataFrame) -> bool:
    """Whether ``table`` is a results table of calc (a CSV it wrote, read back to be computed again, or some of its
    columns): a status column holding only what calc writes."""
    if "status" not in table.columns:
        return False
    given = table["status"].dropna()  # (each distinct text looked at once)
    return bool(per_distinct(given, lambda value: isinstance(value, str) and value.strip() in _STATUSES)
                .astype(bool).all())


def refuse_result_columns(table: pd.DataFrame) -> None:
    """:class:`InputError` for a column named like a result of calc ('status', 'message', 'MR [N*mm]'): calc writes
    that column, so a designer's own (a status of released/draft) would be replaced in the output by calc's. A
    results table of calc itself (:func:`_calc_results`) is computed again: its result columns are calc's."""
    clashes = [(header, written) for header in table.columns if readable_header(header)
               and (written := result_column(header)) is not None]
    if clashes and not _calc_results(table):
        header, written = clashes[0]
        raise InputError(f"column {header!r} is a column calc writes; rename it (e.g. '{written} (design)')")


def results_spelled_otherwise(inputs, results) -> dict:
    """Input header -> result header, for an input column that is a result column of calc (among the headers
    ``results``) with its unit written another way: ``f0 [1]`` or ``f0 [-]`` for f0, which the contract names bare
    as every dimensionless column (the template's units row writes 1 for them, :func:`to_catalogue_units` reads
    both), or ``MR [N*m]`` of a results table computed again. calc writes the result once, in that column's place
    and under its own header; an input headed as the result is replaced in place already.

    >>> results_spelled_otherwise(["designation", "f0 [1]", "f1", "MR [N*m]"], ["f0", "f1", "MR [N*mm]"])
    {'f0 [1]': 'f0', 'MR [N*m]': 'MR [N*mm]'}
    """
    by_name: dict[str, str] = {}
    for header in results:
        by_name.setdefault(parse_header(header, strict=False)[0], header)
    given = set(inputs)
    found: dict = {}
    for header in inputs:
        written = by_name.get(parse_header(header, strict=False)[0])
        if written is not None and written not in given and written not in found.values():
            found[header] = written
    return found
