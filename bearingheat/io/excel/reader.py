"""Read supports from a workbook: the header row, the units row, the cells each value came from.

A designer's sheet has a header row (``designation``, ``d``, ``Fr`` ...) and,
under it, an optional units row (``mm``, ``kN``, ``lbf``, ``1/min``, ``U/min``
...). A unit may also sit in the header itself (``Fr [kN]``). Everything else
is the column contract of ``bearingheat calc`` (:mod:`bearingheat.calc.contract`).

- :func:`read_supports` -> (DataFrame, :class:`SheetInfo`): the rows of the
  input sheet (empty rows skipped) and where each value came from.
- :func:`with_units`: plain columns + units -> pint-pandas columns.

Formula cells are read as the values a spreadsheet program saved for them
(:func:`_cached_values`; a 0 that a script such as XlsxWriter stored is no such value, :func:`_unsaved_zeros`),
and a row of formulas that show an empty text is blank. Headers calc would misread (named like a result column,
or renamed by an Excel table: 'D2') are refused. Messages cite cells, e.g.
``Supports!F2: unit 'kN' contradicts the header 'Fr [N]'; keep one of them``.

>>> supports, info = read_supports("spreadsheets/gearbox_shaft_example.xlsx")
>>> info.sheet, info.units["Fr"], info.cell("Fr", 0)
('Supports', 'kN', 'Supports!F3')
>>> len(supports)
6
"""
from __future__ import annotations

import os
import re
import warnings
import zipfile
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any
from xml.etree import ElementTree

import numpy as np
import pandas as pd
from lxml import etree
from openpyxl import load_workbook
from openpyxl.utils import column_index_from_string, get_column_letter
from openpyxl.utils.exceptions import InvalidFileException
from openpyxl.workbook import Workbook
from openpyxl.worksheet.worksheet import Worksheet

from bearingheat.calc.contract import input_units, parse_header, result_column
from bearingheat.errors import ExcelError, InputError
from bearingheat.io.excel.opc import MAIN, parse_part, workbook_part
from bearingheat.io.excel.ownership import read_marks, sheet_ref
from bearingheat.io.excel.rows import filled_rows, take_ambiguous_texts, totals_rows
from bearingheat.io.files import EXCEL_SUFFIXES
from bearingheat.io.units_row import is_number, looks_like_units_row, unit_contradicts_header
from bearingheat.units import parse_unit, quantity

if TYPE_CHECKING:
    from bearingheat.io.console import Progress

__all__ = [
    "SheetInfo",
    "read_supports",
    "read_sheet",
    "open_workbook",
    "with_units",
    "contract_name",
    "defined_name_values",
    "DEFAULT_SHEET",
    "RESULTS_SHEET",
    "EXCEL_SUFFIXES",
    "stored_cells",
]

#: the input sheet of the template; its results go to RESULTS_SHEET
DEFAULT_SHEET = "Supports"
RESULTS_SHEET = "Results"
#: the header row is searched for in the first rows of a sheet (title rows may sit above it)
HEADER_SEARCH_ROWS = 20
_TEXT_UNITS = ("", "-")

#: (row, column) of a cell covered by a merge -> (the merge's value, its first row, its first column)
MergedCells = dict[tuple[int, int], tuple[object, int, int]]


@dataclass
class SheetInfo:
    """Where the rows of :func:`read_supports` came from.

    ``units`` maps a header to the unit of its units row; ``letters`` a
    header and its contract name to the column letter; ``rows`` gives the
    worksheet row of each DataFrame row; ``formula_cells`` lists the input
    cells that hold formulas (with the cached value that was read).
    """

    path: Path
    sheet: str
    header_row: int
    units_row: int | None
    units: dict[str, str]
    letters: dict[str, str]
    rows: list[int]
    headers: dict[str, str] = field(default_factory=dict)
    formula_cells: dict[tuple[str, int], str] = field(default_factory=dict)
    uncached: list[tuple[int, str, str]] = field(default_factory=list)
    #: number cells holding text that reads two ways ('3.000': 3 or 3000; :mod:`.rows`), (position, header, text):
    #: read as blank
    ambiguous: list[tuple[int, str, str]] = field(default_factory=list)
    #: worksheet rows of supports that are hidden on the sheet (by hand or by a filter): computed like the others
    hidden_rows: list[int] = field(default_factory=list)
    #: the totals rows of Excel tables among the rows (row, table name): no supports, so not read (:mod:`.rows`)
    totals_rows: list[tuple[int, str]] = field(default_factory=list)
    #: the rows from the units row (the header row without one) down with something in a column of ``headers``,
    #: as Excel's COUNTIFS(range, "") tells them from blank rows (a cell of spaces is something, a formula that
    #: shows "" is not): the count the check of --formulas compares with (:func:`.freshness.unread_rows_check`, :func:`.rows.filled_rows`)
    filled_rows: int = 0

    @property
    def last_title_row(self) -> int:
        """The last row above the supports: the units row, or the header row of a sheet without one."""
        return self.units_row if self.units_row is not None else self.header_row

    @property
    def sheet_ref(self) -> str:
        """The sheet's name as formulas and messages write it (:func:`bearingheat.io.excel.ownership.sheet_ref`)."""
        return sheet_ref(self.sheet)

    def cell(self, column: str, position: int) -> str:
        """``cell('Fr', 4)`` -> ``'Supports!F7'``: the cell of a column (header or contract name) in row ``position``."""
        row = self.rows[position]
        letter = self.letters.get(column)
        if letter is None:
            return f"{self.sheet_ref} row {row}"
        return f"{self.sheet_ref}!{letter}{row}"

    def unit_of(self, name: str) -> str | None:
        """The unit the sheet gives a contract column (header or units row), None without one."""
        header = self.headers.get(name)
        if header is None:
            return None
        unit = parse_header(header)[1]
        return unit if unit is not None else self.units.get(header)


def _text(value: object) -> str:
    return "" if value is None else str(value).strip()


def _as_text_value(value: object) -> object:
    """A text-column cell as the user sees it: 6208 typed as a number is the designation '6208'."""
    if is_number(value):
        if isinstance(value, float) and value.is_integer():
            return str(int(value))
        return str(value)
    if isinstance(value, str):
        return value.strip() or None
    return value


def open_workbook(path: str | os.PathLike[str], *, keep_vba: bool = False, read_only: bool = False,
                  data_only: bool = False) -> Workbook:
    """The workbook at ``path`` (external links kept); :class:`ExcelError` when it is not a readable workbook.

    The warnings openpyxl gives while loading (they name what it will drop)
    are kept on the workbook for :func:`bearingheat.io.excel.safety.unsupported_content`.
    """
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            workbook = load_workbook(path, keep_vba=keep_vba, read_only=read_only, data_only=data_only,
                                     keep_links=True)
    except (zipfile.BadZipFile, InvalidFileException, KeyError, OSError) as exc:
        raise ExcelError(f"{path}: not a readable Excel workbook ({exc})") from exc
    except (etree.XMLSyntaxError, ElementTree.ParseError) as exc:  # (openpyxl parses with lxml where it can)
        raise ExcelError(f"{path}: damaged workbook, a part is not well-formed XML ({exc})") from exc
    workbook._bearingheat_load_warnings = [str(w.message) for w in caught]
    return workbook


def _known_names() -> set[str]:
    return set(input_units())


def _merged_header_values(ws: Worksheet, header_search: int) -> MergedCells:
    """Cells covered by a vertical merge near the top of the sheet -> the merge's value."""
    covered: MergedCells = {}
    for merged in ws.merged_cells.ranges:
        if merged.min_row > header_search + 1:
            continue
        value = ws.cell(merged.min_row, merged.min_col).value
        for row in range(merged.min_row, merged.max_row + 1):
            for col in range(merged.min_col, merged.max_col + 1):
                covered[(row, col)] = (value, merged.min_row, merged.min_col)
    return covered


def _header_texts(ws: Worksheet, row: int, max_col: int, merged: MergedCells) -> list[str]:
    texts = []
    for col in range(1, max_col + 1):
        value = ws.cell(row, col).value
        if (row, col) in merged:
            value, top, left = merged[(row, col)]
            if left != col:  # a horizontal merge names its first column only
                value = None
        texts.append(_text(value))
    return texts


def _find_header_row(ws: Worksheet, max_col: int, merged: MergedCells) -> int:
    known = _known_names()
    best_row, best_count = 0, 0
    for row in range(1, min(ws.max_row, HEADER_SEARCH_ROWS) + 1):
        count = 0
        for text in _header_texts(ws, row, max_col, merged):
            if not text:
                continue
            try:
                name, _ = parse_header(text)
            except InputError:
                continue
            count += name in known
        if count > best_count:
            best_row, best_count = row, count
    if best_count < 2:
        raise ExcelError(
            f"sheet {ws.title!r}: no header row in rows 1-{HEADER_SEARCH_ROWS}; a header row names the columns, "
            "e.g. designation, d, D, n, Fr, nu (docs/excel.md lists them)")
    return best_row


def defined_name_values(workbook: Workbook) -> list[tuple[str, str | None]]:
    """(name, value) of each workbook-scoped defined name of an openpyxl workbook: what :mod:`.ownership` reads
    bearingheat's marks from."""
    return [(name, defined.attr_text) for name, defined in workbook.defined_names.items()]


def _choose_sheet(workbook: Workbook, sheet: str | None, path: Path) -> str:
    names = workbook.sheetnames
    if sheet is not None:
        if sheet not in names:
            raise ExcelError(f"{path.name} has no sheet {sheet!r}; its sheets are {', '.join(names)}")
        return sheet
    if DEFAULT_SHEET in names:
        return DEFAULT_SHEET
    owned = {results for results, _ in read_marks(defined_name_values(workbook)).values() if results is not None}
    for name in names:
        ws = workbook[name]
        if (name in owned or name.endswith(RESULTS_SHEET) or name.endswith("results")
                or ws.sheet_state != "visible"):
            continue
        try:
            _find_header_row(ws, _used_columns(ws, HEADER_SEARCH_ROWS + 1),
                             _merged_header_values(ws, HEADER_SEARCH_ROWS))
        except ExcelError:
            continue
        return name
    raise ExcelError(f"{path.name}: no sheet has a header row of supports (designation, d, D, n, Fr, nu ...); "
                     "name the sheet with --sheet")


def read_supports(path: str | os.PathLike[str], sheet: str | None = None, *,
                  progress: Progress | None = None) -> tuple[pd.DataFrame, SheetInfo]:
    """Supports of one sheet: a DataFrame (one row per non-empty sheet row) and its :class:`SheetInfo`.

    ``sheet`` defaults to 'Supports', else the first visible sheet with a
    header row. Headers keep the user's text (trailing spaces removed);
    units come from the units row (``info.units``) or the header
    (``Fr [kN]``). Text columns of the contract hold strings, numeric
    columns floats where every value is a number (else the raw values, so
    that calc can name the cell that is not a number). A formula cell with
    no value saved by a spreadsheet program is listed in ``info.uncached``,
    a number cell holding text that reads two ways ('3.000': 3 or 3000) in
    ``info.ambiguous``; both are read as blank.
    """
    path = Path(path)
    if not path.is_file():
        raise ExcelError(f"{path}: no such file")
    workbook = open_workbook(path)
    return read_sheet(workbook, path, sheet, progress=progress)


def read_sheet(workbook: Workbook, path: Path, sheet: str | None, *,
               progress: Progress | None = None) -> tuple[pd.DataFrame, SheetInfo]:
    """:func:`read_supports` on a workbook already open (``progress``: an object with start, update, finish)."""
    name = _choose_sheet(workbook, sheet, path)
    ws = workbook[name]
    max_col = _used_columns(ws, HEADER_SEARCH_ROWS + 1)
    merged = _merged_header_values(ws, HEADER_SEARCH_ROWS)
    try:
        header_row = _find_header_row(ws, max_col, merged)
    except ExcelError:
        if sheet is None or ws.max_row < 1:
            raise
        header_row = 1  # a sheet named on purpose: its first row is the header
    texts = _header_texts(ws, header_row, max_col, merged)
    columns: list[tuple[int, str]] = []  # (column index, header)
    seen: dict[str, str] = {}
    for col, text in enumerate(texts, start=1):
        if not text:
            continue
        if text in seen:
            raise ExcelError(f"{sheet_ref(ws.title)}!{get_column_letter(col)}{header_row}: column {text!r} appears "
                             f"twice (also in column {seen[text]})")
        seen[text] = get_column_letter(col)
        columns.append((col, text))
    names = [contract_name(text) for _, text in columns]
    _refuse_header_clashes(ws.title, header_row, columns, names)

    # units row: under the header, unless its cells belong to the header's merged cells
    units: dict[str, str] = {}
    units_row = None
    candidate = header_row + 1
    raw_units: list[object] = []
    for col, _ in columns:
        if (candidate, col) in merged and merged[(candidate, col)][1] <= header_row:
            raw_units.append(None)
        else:
            raw_units.append(ws.cell(candidate, col).value)
    is_units, unknown = looks_like_units_row(raw_units, names)
    if unknown:
        position, why = unknown[0]
        raise ExcelError(f"{sheet_ref(ws.title)}!{get_column_letter(columns[position][0])}{candidate}: {why} in the "
                         "units row; write a unit such as kN, N, rpm, mm^2/s (docs/excel.md lists them)")
    if is_units:
        units_row = candidate
        for (col, header), value in zip(columns, raw_units):
            text = _text(value)
            if text:
                units[header] = text
        _check_units(ws.title, units_row, columns, units)
    first_data = (units_row or header_row) + 1

    letters: dict[str, str] = {}
    contract_headers: dict[str, str] = {}
    for (col, header), contract in zip(columns, names):
        letters[header] = get_column_letter(col)
        if contract is not None:
            letters.setdefault(contract, get_column_letter(col))
            contract_headers.setdefault(contract, header)

    wanted = [col for col, _ in columns]
    _refuse_merged_data(ws, [col for (col, _), name in zip(columns, names) if name is not None], first_data)
    data: list[list] = [[] for _ in columns]
    rows: list[int] = []
    formula_cells: dict[tuple[str, int], str] = {}
    positions = {col: i for i, col in enumerate(wanted)}
    used = _used_rows(ws, positions, first_data)
    every_row = used
    totals = totals_rows(ws, set(wanted), first_data)
    skipped = [(row, totals[row]) for row in used if row in totals]
    used = {row: row_cells for row, row_cells in used.items() if row not in totals}
    if progress is not None:
        progress.start(len(used), f"reading {ws.title}")
    for count, (row, row_cells) in enumerate(used.items(), start=1):
        values = [None] * len(wanted)
        blank = True
        for i, cell in row_cells:
            value = cell.value
            if cell.data_type == "f":
                formula_cells[(columns[i][1], cell.row)] = str(value)
            elif isinstance(value, str) and not value.strip():
                value = None
            values[i] = value
            blank = blank and value is None
        if not blank:
            rows.append(row)
            for i, value in enumerate(values):
                data[i].append(value)
        if progress is not None and count % 500 == 0:
            progress.update(count)
    if progress is not None:
        progress.finish()

    uncached: list[tuple[int, str, str]] = []
    cached: dict[tuple[str, int], Any] = {}
    if formula_cells:
        cached = _cached_values(path, ws.title, formula_cells, letters)
        for key in _unsaved_zeros(path, workbook, cached):
            cached[key] = None
        position_of_row = {row: i for i, row in enumerate(rows)}
        col_index = {header: i for i, (_, header) in enumerate(columns)}
        for (header, row), formula in formula_cells.items():
            data[col_index[header]][position_of_row[row]] = cached.get((header, row))
        # a row of formulas that show "" (=IF(Data!A5="","",Data!A5) down a pre-filled sheet) is as blank as an
        # empty row: only its cached values tell, so blank rows are dropped once they are filled in
        keep = [i for i, row in enumerate(rows) if any(
            (header, row) in formula_cells if value is None else not (isinstance(value, str) and not value.strip())
            for value, (_, header) in zip((column[i] for column in data), columns))]
        if len(keep) < len(rows):
            dropped = set(rows) - {rows[i] for i in keep}
            rows = [rows[i] for i in keep]
            data = [[column[i] for i in keep] for column in data]
            formula_cells = {key: formula for key, formula in formula_cells.items() if key[1] not in dropped}
        position_of_row = {row: i for i, row in enumerate(rows)}
        for (header, row), formula in formula_cells.items():
            if data[col_index[header]][position_of_row[row]] is None:
                uncached.append((position_of_row[row], header, formula))

    read = [header in contract_headers.values() for _, header in columns]
    filled = filled_rows(stored_cells(ws), every_row, read, cached, columns, first_data - 1)
    known = input_units()
    ambiguous = take_ambiguous_texts(columns, [n is not None and known[n] not in _TEXT_UNITS for n in names], data)
    frame_columns: dict[str, pd.Series] = {}
    for (col, header), contract, values in zip(columns, names, data):
        if contract is not None and known[contract] in _TEXT_UNITS:
            text_values = [_as_text_value(v) for v in values]
            every = bool(text_values) and all(isinstance(t, str) for t in text_values)
            frame_columns[header] = pd.Series(text_values) if every else pd.Series(text_values, dtype=object)
        else:
            frame_columns[header] = _numeric_if_possible(values)
    table = pd.DataFrame(frame_columns, index=pd.RangeIndex(len(rows)))
    dimensions = ws.row_dimensions
    hidden = [row for row in rows if row in dimensions and dimensions[row].hidden]
    info = SheetInfo(path=path, sheet=ws.title, header_row=header_row, units_row=units_row, units=units,
                     letters=letters, rows=rows, headers=contract_headers, formula_cells=formula_cells,
                     uncached=uncached, ambiguous=ambiguous, hidden_rows=hidden, totals_rows=skipped,
                     filled_rows=filled)
    return table, info


#: Excel renames a table header that repeats another one without regard to letter case: 'd' and 'D' -> 'D2'
_RENAMED = re.compile(r"^(?P<base>.*?\D)(?P<digits>\d+)$")


def _renamed_duplicate(header: str, name: str | None, present: set[str]) -> str | None:
    """The contract header an Excel table made ``header`` of by appending digits ('D2', 'D [mm]2' -> 'D'; 'd2'
    beside a 'd' -> 'D'), None for any other header (d1, D1, f0 and nu40 are contract names of their own)."""
    if name is not None:
        return None
    match = _RENAMED.match(header)
    if match is None:
        return None
    text, digits = match.group("base"), match.group("digits")
    for split in range(len(digits)):  # 'nu402' is nu40 + 2 or nu + 402: the longest contract name wins
        base = (text + digits[:split]).strip()
        try:
            found, _ = parse_header(base)
        except InputError:
            continue
        alike = sorted((known for known in _known_names() if known.casefold() == found.casefold()),
                       key=lambda known: (known in present, known != found))
        if alike:  # the one of the names alike the sheet lacks: the column Excel renamed
            return alike[0]
    return None


def _refuse_header_clashes(sheet: str, header_row: int, columns: list[tuple[int, str]],
                           names: list[str | None]) -> None:
    """:class:`ExcelError` naming the header cell of a column calc would misread: one named like a result column
    (calc writes that column: the designer's 'status' would be hidden or overwritten by ok/error), one that is a
    contract header renamed by an Excel table ('D2': the D typed there would be passed through unread and the
    catalogue's D used instead)."""
    present = {name for name in names if name is not None}
    for (col, header), name in zip(columns, names):
        where = f"{sheet_ref(sheet)}!{get_column_letter(col)}{header_row}"
        written = result_column(header)
        if written is not None:
            raise ExcelError(f"{where}: {header!r} is a column calc writes; rename it (e.g. "
                             f"'{written} (design)')")
        meant = _renamed_duplicate(header, name, present)
        if meant is not None:
            raise ExcelError(
                f"{where}: header {header!r} looks like {meant!r} renamed by Excel, which renames a table header "
                "that repeats another one without regard to letter case ('d' and 'D' -> 'D2'); calc would not "
                f"read it and would take {meant} as not given. Make the headers differ beyond letter case (e.g. "
                "'d' and 'D [mm]', mm under d in the units row), or convert the table to a range")


def _recalculates_on_load(path: Path) -> bool:
    """Whether the workbook's calcPr asks for a full recalculation on load (fullCalcOnLoad), read from the file:
    openpyxl reports the flag set for a workbook without calcPr."""
    with zipfile.ZipFile(path) as archive:
        part = workbook_part(archive)
        try:
            root = parse_part(archive.read(part), part, path)
        except KeyError:
            return False
    calc = root.find(f"{{{MAIN}}}calcPr")
    return calc is not None and calc.get("fullCalcOnLoad") in ("1", "true")


def _unsaved_zeros(path: Path, workbook: Workbook, cached: dict[tuple[str, int], Any]) -> set[tuple[str, int]]:
    """The formula cells whose cached 0 no spreadsheet program computed: they have no saved value.

    A script writing with XlsxWriter (and the like) stores 0 for every formula it is given no value for and asks
    for a full recalculation on load (calcPr fullCalcOnLoad): Fr =1.6*2 would be read as 0. Excel and
    LibreOffice drop that flag when they save, so with it a cached 0 is distrusted. bearingheat sets the flag
    too when it writes results into a workbook (its ownership marks say so) and leaves the input sheet's cached
    values as they were: there a 0 is trusted unless every formula caches 0 (a script's workbook that
    bearingheat wrote results into)."""
    zeros = {key for key, value in cached.items() if is_number(value) and value == 0}
    if not zeros or not _recalculates_on_load(path):
        return set()
    if read_marks(defined_name_values(workbook)) and len(zeros) < len(cached):
        return set()
    return zeros


def _refuse_merged_data(ws: Worksheet, columns: list[int], first_data: int) -> None:
    """:class:`ExcelError` for merged cells among the supports' rows in the contract's ``columns``: the sheet shows
    their value in every cell, but only the first cell holds it, so the other rows would read as blank (a load of
    0). A column calc does not read is only passed through, so merged notes there are left alone."""
    wanted = set(columns)
    for merged in ws.merged_cells.ranges:
        top = max(merged.min_row, first_data)
        if merged.max_row < first_data:
            continue
        inside = sum(merged.min_col <= col <= merged.max_col for col in wanted)
        cells = (merged.max_row - top + 1) * inside
        first_inside = merged.min_row >= first_data and merged.min_col in wanted
        if cells - first_inside > 0:
            raise ExcelError(f"{sheet_ref(ws.title)}!{merged.coord}: merged cells among the rows of supports; the "
                             f"sheet shows their value on every row, but only {get_column_letter(merged.min_col)}"
                             f"{merged.min_row} holds it, so the other rows would read as blank. Unmerge them and "
                             "give each row its own value")


def stored_cells(ws: Worksheet) -> dict[tuple[int, int], Any]:
    """The cells a worksheet holds, {(row, column): cell}: openpyxl keeps them sparse, so this costs nothing
    for a stray cell far down (the row 1 048 576 of a mistyped Ctrl+Down)."""
    return ws._cells


def _used_columns(ws: Worksheet, rows: int) -> int:
    """The last column with a value in the first ``rows`` rows (at least 1)."""
    return max([col for (row, col), cell in stored_cells(ws).items() if row <= rows and cell.value is not None]
               + [1])


def _used_rows(ws: Worksheet, columns: dict[int, int], first: int) -> dict[int, list[tuple[int, Any]]]:
    """{row: [(position of the column, cell), ...]} of the rows from ``first`` on with a value in ``columns``
    ({column index: position}), in row order.

    Only the used range of the contract's columns is read: a stray value far
    down (row 1 048 576) costs one row, not a million.
    """
    rows: dict[int, list[tuple[int, Any]]] = {}
    for (row, col), cell in stored_cells(ws).items():
        if row >= first and col in columns and cell.value is not None:
            rows.setdefault(row, []).append((columns[col], cell))
    return dict(sorted(rows.items()))


def contract_name(header: str) -> str | None:
    """The contract column a header names ('Fr [kN]' -> 'Fr'), None for a column outside the contract."""
    try:
        name, _ = parse_header(header)
    except InputError:
        return None
    return name if name in _known_names() else None


def _check_units(sheet: str, units_row: int, columns: Iterable[tuple[int, str]], units: dict[str, str]) -> None:
    """A unit in the header and a different one in the units row: refuse rather than guess."""
    for col, header in columns:
        if header in units and unit_contradicts_header(header, units[header]):
            raise ExcelError(f"{sheet_ref(sheet)}!{get_column_letter(col)}{units_row}: unit {units[header]!r} "
                             f"contradicts the header {header!r}; keep one of them")


def _numeric_if_possible(values: list[Any]) -> pd.Series:
    present = [v for v in values if v is not None]
    if present and all(is_number(v) for v in present):
        if len(present) == len(values) and all(isinstance(v, int) for v in present):
            return pd.Series(values, dtype="int64")
        return pd.Series([np.nan if v is None else float(v) for v in values], dtype=float)
    if present and all(isinstance(v, str) for v in present) and len(present) == len(values):
        return pd.Series(values)
    return pd.Series(values, dtype=object)


def _cached_values(path: Path, sheet: str, cells: dict[tuple[str, int], str],
                   letters: dict[str, str]) -> dict[tuple[str, int], Any]:
    """The values a spreadsheet program saved for formula cells (None where it saved none; '' where it saved an
    empty text, as Excel and LibreOffice do for a formula such as ="" or =IF(..., "", ...): a blank cell)."""
    workbook = open_workbook(path, read_only=True, data_only=True)
    try:
        wanted: dict[int, list[tuple[str, int]]] = {}
        for header, row in cells:
            wanted.setdefault(row, []).append((header, column_index_from_string(letters[header]) - 1))
        first, last = min(wanted), max(wanted)
        width = max(col for entries in wanted.values() for _, col in entries) + 1
        out: dict[tuple[str, int], Any] = {}
        rows = workbook[sheet].iter_rows(min_row=first, max_row=last, max_col=width)
        for row, row_cells in enumerate(rows, start=first):
            for header, col in wanted.get(row, ()):
                cell = row_cells[col] if col < len(row_cells) else None
                value = getattr(cell, "value", None)
                # t="str" with an empty <v>: a saved empty text (openpyxl reads it as None, as a value never saved)
                out[(header, row)] = "" if value is None and getattr(cell, "data_type", None) == "str" else value
        return out
    finally:
        workbook.close()


def with_units(table: pd.DataFrame, units: dict[str, str]) -> pd.DataFrame:
    """Columns with a unit in ``units`` (not '-' or '1') become pint-pandas columns of that unit.

    The inverse of :func:`write_results` for a DataFrame with pint columns::

        write_results(frame, "supports.xlsx", sheet="Supports")
        table, info = read_supports("supports.xlsx", sheet="Supports")
        with_units(table, info.units)      # equals frame

    Without pint-pandas the columns stay floats with the unit in
    ``attrs['unit']`` (:func:`bearingheat.units.quantity`).
    """
    out = table.copy()
    for header, unit in units.items():
        if header not in out.columns or unit in ("-", "1", ""):
            continue
        out[header] = quantity(out[header].astype(float), str(parse_unit(unit, name=header)))
    return out
