"""The Excel bridge: read supports from a workbook, run calc, write the results back.

A designer's sheet has a header row (``designation``, ``d``, ``Fr`` ...) and,
under it, an optional units row (``mm``, ``kN``, ``lbf``, ``1/min``, ``U/min``
...). A unit may also sit in the header itself (``Fr [kN]``). Everything else
is the column contract of ``bearingheat calc`` (:mod:`bearingheat.frame`).

- :func:`read_supports` -> (DataFrame, :class:`SheetInfo`): the rows of the
  input sheet (empty rows skipped) and where each value came from.
- :func:`write_results`: a DataFrame as a sheet with a header and a units row.
- :func:`calc_workbook`: read, calculate, write a results sheet (optionally
  with live Excel formulas, see :mod:`bearingheat.excel_formulas`).
- :func:`with_units`: plain columns + units -> pint-pandas columns.

Messages cite cells, e.g. ``Supports!F7: 'abc' is not a number for Fr [kN]``.

>>> supports, info = read_supports("spreadsheets/gearbox_shaft_example.xlsx")
>>> info.sheet, info.units["Fr"], info.cell("Fr", 0)
('Supports', 'kN', 'Supports!F3')
>>> len(supports)
6
"""
from __future__ import annotations

import math
import os
import re
import sys
import tempfile
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.frame import InputError, input_units, parse_header
from bearingheat.units import UnitError, parse_unit
from bearingheat.errors import ExcelError

__all__ = [
    "ExcelError",
    "SheetInfo",
    "read_supports",
    "write_results",
    "calc_workbook",
    "with_units",
    "run_calc_workbook",
    "write_results_workbook",
    "results_sheet_name",
    "DEFAULT_SHEET",
    "RESULTS_SHEET",
]

#: the input sheet of the template; its results go to RESULTS_SHEET
DEFAULT_SHEET = "Supports"
RESULTS_SHEET = "Results"
#: the header row is searched for in the first rows of a sheet (title rows may sit above it)
HEADER_SEARCH_ROWS = 20
#: sheets at least this long get a progress bar (when stderr is a terminal)
PROGRESS_MIN_ROWS = 2000
EXCEL_SUFFIXES = (".xlsx", ".xlsm")
_TEXT_UNITS = ("", "-")




# ---------------------------------------------------------------------------------------------
# reading


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

    @property
    def sheet_ref(self) -> str:
        return _ref(self.sheet)

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


def _text(value) -> str:
    return "" if value is None else str(value).strip()


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _as_text_value(value):
    """A text-column cell as the user sees it: 6208 typed as a number is the designation '6208'."""
    if _is_number(value):
        if isinstance(value, float) and value.is_integer():
            return str(int(value))
        return str(value)
    if isinstance(value, str):
        return value.strip() or None
    return value


def _open_workbook(path: Path, *, keep_vba: bool = False, read_only: bool = False, data_only: bool = False):
    import zipfile

    from openpyxl import load_workbook
    from openpyxl.utils.exceptions import InvalidFileException

    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            workbook = load_workbook(path, keep_vba=keep_vba, read_only=read_only, data_only=data_only,
                                     keep_links=True)
    except (zipfile.BadZipFile, InvalidFileException, KeyError, OSError) as exc:
        raise ExcelError(f"{path}: not a readable Excel workbook ({exc})") from exc
    workbook._bearingheat_load_warnings = [str(w.message) for w in caught]
    return workbook


def _known_names() -> set[str]:
    return set(input_units())


def _merged_header_values(ws, header_search: int) -> dict[tuple[int, int], object]:
    """Cells covered by a vertical merge near the top of the sheet -> the merge's value."""
    covered: dict[tuple[int, int], object] = {}
    for merged in ws.merged_cells.ranges:
        if merged.min_row > header_search + 1:
            continue
        value = ws.cell(merged.min_row, merged.min_col).value
        for row in range(merged.min_row, merged.max_row + 1):
            for col in range(merged.min_col, merged.max_col + 1):
                covered[(row, col)] = (value, merged.min_row, merged.min_col)
    return covered


def _header_texts(ws, row: int, max_col: int, merged) -> list[str]:
    texts = []
    for col in range(1, max_col + 1):
        value = ws.cell(row, col).value
        if (row, col) in merged:
            value, top, left = merged[(row, col)]
            if left != col:  # a horizontal merge names its first column only
                value = None
        texts.append(_text(value))
    return texts


def _find_header_row(ws, max_col: int, merged) -> int:
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


def _looks_like_units_row(values: list, names: list[str | None]) -> bool:
    """The row under the header holds units when its dimensional columns hold unit texts and no numbers."""
    known = input_units()
    saw_unit = False
    for value, name in zip(values, names):
        if name is None or known.get(name, "") in ("", "1"):
            continue
        if _is_number(value):
            return False
        text = _text(value)
        if not text or text == "-":
            continue
        try:
            float(text)
            return False
        except ValueError:
            pass
        try:
            parse_unit(text, name=name)
        except UnitError:
            return False
        saw_unit = True
    return saw_unit


def _choose_sheet(workbook, sheet: str | None, path: Path) -> str:
    names = workbook.sheetnames
    if sheet is not None:
        if sheet not in names:
            raise ExcelError(f"{path.name} has no sheet {sheet!r}; its sheets are {', '.join(names)}")
        return sheet
    if DEFAULT_SHEET in names:
        return DEFAULT_SHEET
    for name in names:
        ws = workbook[name]
        if name.endswith(RESULTS_SHEET) or name.endswith("results") or ws.sheet_state != "visible":
            continue
        try:
            _find_header_row(ws, min(ws.max_column, 200), _merged_header_values(ws, HEADER_SEARCH_ROWS))
        except ExcelError:
            continue
        return name
    raise ExcelError(f"{path.name}: no sheet has a header row of supports (designation, d, D, n, Fr, nu ...); "
                     "name the sheet with --sheet")


def read_supports(path, sheet: str | None = None, *, progress=None) -> tuple[pd.DataFrame, SheetInfo]:
    """Supports of one sheet: a DataFrame (one row per non-empty sheet row) and its :class:`SheetInfo`.

    ``sheet`` defaults to 'Supports', else the first visible sheet with a
    header row. Headers keep the user's text (trailing spaces removed);
    units come from the units row (``info.units``) or the header
    (``Fr [kN]``). Text columns of the contract hold strings, numeric
    columns floats where every value is a number (else the raw values, so
    that calc can name the cell that is not a number). A formula cell with
    no value saved by a spreadsheet program is listed in ``info.uncached``.
    """
    path = Path(path)
    if not path.is_file():
        raise ExcelError(f"{path}: no such file")
    workbook = _open_workbook(path)
    return _read_sheet(workbook, path, sheet, progress=progress)


def _read_sheet(workbook, path: Path, sheet: str | None, *, progress=None) -> tuple[pd.DataFrame, SheetInfo]:
    from openpyxl.utils import get_column_letter

    name = _choose_sheet(workbook, sheet, path)
    ws = workbook[name]
    max_col = ws.max_column
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
            raise ExcelError(f"{_ref(ws.title)}!{get_column_letter(col)}{header_row}: column {text!r} appears twice "
                             f"(also in column {seen[text]})")
        seen[text] = get_column_letter(col)
        columns.append((col, text))
    names = [_contract_name(text) for _, text in columns]

    # units row: under the header, unless its cells belong to the header's merged cells
    units: dict[str, str] = {}
    units_row = None
    candidate = header_row + 1
    raw_units = []
    for col, _ in columns:
        if (candidate, col) in merged and merged[(candidate, col)][1] <= header_row:
            raw_units.append(None)
        else:
            raw_units.append(ws.cell(candidate, col).value)
    if _looks_like_units_row(raw_units, names):
        units_row = candidate
        for (col, header), value in zip(columns, raw_units):
            text = _text(value)
            if text:
                units[header] = text
        _check_units(ws.title, header_row, units_row, columns, units)
    first_data = (units_row or header_row) + 1

    letters: dict[str, str] = {}
    contract_headers: dict[str, str] = {}
    for (col, header), contract in zip(columns, names):
        letters[header] = get_column_letter(col)
        if contract is not None:
            letters.setdefault(contract, get_column_letter(col))
            contract_headers.setdefault(contract, header)

    wanted = [col for col, _ in columns]
    data: list[list] = [[] for _ in columns]
    rows: list[int] = []
    formula_cells: dict[tuple[str, int], str] = {}
    total = max(ws.max_row - first_data + 1, 0)
    if progress is not None:
        progress.start(total, f"reading {ws.title}")
    positions = {col: i for i, col in enumerate(wanted)}
    max_wanted = max(wanted) if wanted else 1
    for count, row_cells in enumerate(ws.iter_rows(min_row=first_data, max_col=max_wanted), start=1):
        values = [None] * len(wanted)
        blank = True
        for cell in row_cells:
            i = positions.get(cell.column)
            if i is None:
                continue
            value = cell.value
            if cell.data_type == "f":
                formula_cells[(columns[i][1], cell.row)] = str(value)
            elif isinstance(value, str) and not value.strip():
                value = None
            values[i] = value
            blank = blank and value is None
        if not blank:
            rows.append(row_cells[0].row)
            for i, value in enumerate(values):
                data[i].append(value)
        if progress is not None and count % 500 == 0:
            progress.update(count)
    if progress is not None:
        progress.finish()

    uncached: list[tuple[int, str, str]] = []
    if formula_cells:
        cached = _cached_values(path, ws.title, formula_cells, letters)
        position_of_row = {row: i for i, row in enumerate(rows)}
        col_index = {header: i for i, (_, header) in enumerate(columns)}
        for (header, row), formula in formula_cells.items():
            value = cached.get((header, row))
            data[col_index[header]][position_of_row[row]] = value
            if value is None:
                uncached.append((position_of_row[row], header, formula))

    known = input_units()
    frame_columns = {}
    for (col, header), contract, values in zip(columns, names, data):
        if contract is not None and known[contract] in _TEXT_UNITS:
            texts = [_as_text_value(v) for v in values]
            every = bool(texts) and all(isinstance(t, str) for t in texts)
            frame_columns[header] = pd.Series(texts) if every else pd.Series(texts, dtype=object)
        else:
            frame_columns[header] = _numeric_if_possible(values)
    table = pd.DataFrame(frame_columns, index=pd.RangeIndex(len(rows)))
    info = SheetInfo(path=path, sheet=ws.title, header_row=header_row, units_row=units_row, units=units,
                     letters=letters, rows=rows, headers=contract_headers, formula_cells=formula_cells,
                     uncached=uncached)
    return table, info


def _ref(sheet: str) -> str:
    """A sheet name as Excel writes it in a reference: Supports, 'Shaft 1', 'Q1''s loads'."""
    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.]*", sheet) and not re.fullmatch(r"[A-Za-z]{1,3}[0-9]+", sheet):
        return sheet
    return "'" + sheet.replace("'", "''") + "'"


def _contract_name(header: str) -> str | None:
    try:
        name, _ = parse_header(header)
    except InputError:
        return None
    return name if name in _known_names() else None


def _check_units(sheet: str, header_row: int, units_row: int, columns, units: dict[str, str]) -> None:
    """A unit in the header and a different one in the units row: refuse rather than guess."""
    from openpyxl.utils import get_column_letter

    for col, header in columns:
        if header not in units:
            continue
        try:
            _, header_unit = parse_header(header)
        except InputError:
            continue
        if header_unit is None or units[header] == "-":
            continue
        try:
            same = parse_unit(header_unit, name=header) == parse_unit(units[header], name=header)
        except UnitError:
            same = False
        if not same:
            raise ExcelError(f"{_ref(sheet)}!{get_column_letter(col)}{units_row}: unit {units[header]!r} contradicts "
                             f"the header {header!r}; keep one of them")


def _numeric_if_possible(values: list) -> pd.Series:
    present = [v for v in values if v is not None]
    if present and all(_is_number(v) for v in present):
        if len(present) == len(values) and all(isinstance(v, int) for v in present):
            return pd.Series(values, dtype="int64")
        return pd.Series([np.nan if v is None else float(v) for v in values], dtype=float)
    if present and all(isinstance(v, str) for v in present) and len(present) == len(values):
        return pd.Series(values)
    return pd.Series(values, dtype=object)


def _cached_values(path: Path, sheet: str, cells: dict[tuple[str, int], str], letters: dict[str, str]) -> dict:
    """The values a spreadsheet program saved for formula cells (None where it saved none)."""
    from openpyxl.utils import column_index_from_string

    workbook = _open_workbook(path, read_only=True, data_only=True)
    try:
        wanted: dict[int, list[tuple[str, int]]] = {}
        for header, row in cells:
            wanted.setdefault(row, []).append((header, column_index_from_string(letters[header]) - 1))
        first, last = min(wanted), max(wanted)
        width = max(col for entries in wanted.values() for _, col in entries) + 1
        out = {}
        rows = workbook[sheet].iter_rows(min_row=first, max_row=last, max_col=width, values_only=True)
        for row, values in enumerate(rows, start=first):
            for header, col in wanted.get(row, ()):
                out[(header, row)] = values[col] if col < len(values) else None
        return out
    finally:
        workbook.close()


# ---------------------------------------------------------------------------------------------
# units of a DataFrame


def _unit_text(unit) -> str:
    """A pint unit as typed in a units row: 'kN', 'rpm', 'mm^2/s'."""
    return format(unit, "~C").replace("**", "^")


def split_header(header: str, values: pd.Series | None = None, units: dict[str, str] | None = None) -> tuple[str, str]:
    """(name, unit text) of a DataFrame column for a header row and a units row.

    The unit comes from a pint-pandas dtype, from ``units``, from a
    ``name [unit]`` header; '-' marks text, '1' a plain number.
    """
    if values is not None and str(values.dtype).startswith("pint["):
        return str(header), _unit_text(values.pint.units)
    if units is not None and header in units:
        return str(header), units[header]
    try:
        name, unit = parse_header(header)
    except InputError:
        name, unit = str(header), None
    if unit is not None:
        return name, unit
    if values is not None and (pd.api.types.is_numeric_dtype(values.dtype) and not pd.api.types.is_bool_dtype(values.dtype)):
        return name, "1"
    return name, "-"


def with_units(table: pd.DataFrame, units: dict[str, str]) -> pd.DataFrame:
    """Columns with a unit in ``units`` (not '-' or '1') become pint-pandas columns of that unit.

    The inverse of :func:`write_results` for a DataFrame with pint columns::

        write_results(frame, "supports.xlsx", sheet="Supports")
        table, info = read_supports("supports.xlsx", sheet="Supports")
        with_units(table, info.units)      # equals frame
    """
    import pint_pandas  # noqa: F401  (registers the pint[...] dtype)

    out = table.copy()
    for header, unit in units.items():
        if header not in out.columns or unit in ("-", "1", ""):
            continue
        pint_unit = parse_unit(unit, name=header)
        out[header] = out[header].astype(float).astype(f"pint[{pint_unit}]")
    return out


# ---------------------------------------------------------------------------------------------
# progress


class Progress:
    """A one-line progress bar on a terminal stream; silent when disabled.

    Enabled when ``enabled`` is true and the stream is a terminal; each
    stage (reading, writing) draws its own bar and ends it with a newline,
    for sheets of at least :data:`PROGRESS_MIN_ROWS` rows.
    """

    def __init__(self, stream=None, enabled: bool = True, width: int = 30):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.width = width
        self.total = 0
        self.label = ""
        self.active = False

    def start(self, total: int, label: str) -> None:
        self.total, self.label = total, label
        self.active = self.enabled and total >= PROGRESS_MIN_ROWS
        self.update(0)

    def update(self, done: int) -> None:
        if not self.active:
            return
        done = min(done, self.total)
        filled = int(self.width * done / self.total) if self.total else self.width
        bar = "#" * filled + "-" * (self.width - filled)
        self.stream.write(f"\r{self.label:<24} [{bar}] {done}/{self.total}")
        self.stream.flush()

    def finish(self) -> None:
        if not self.active:
            return
        self.update(self.total)
        self.stream.write("\n")
        self.stream.flush()
        self.active = False


# ---------------------------------------------------------------------------------------------
# writing


def results_sheet_name(input_sheet: str) -> str:
    """'Results' for the template's 'Supports' sheet, else '<sheet> results' (at most 31 characters)."""
    if input_sheet == DEFAULT_SHEET:
        return RESULTS_SHEET
    return f"{input_sheet[:23]} results"


def _column_style(unit: str) -> str:
    """Numbers with a unit get two decimals; coefficients (unit 1) and text stay as they are."""
    from bearingheat import excel_style as st

    return st.RESULT if unit in ("-", "", "1") else st.RESULT_NUMBER


def _cell_value(value):
    if value is None:
        return None
    if isinstance(value, (float, np.floating)):
        return None if math.isnan(value) else float(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (np.bool_,)):
        return bool(value)
    if value is pd.NA or value is pd.NaT:
        return None
    return value


def _fill_sheet(ws, table: pd.DataFrame, *, units: dict[str, str] | None = None,
                input_columns: set[str] = frozenset(), formulas: dict[tuple[str, int], str] | None = None,
                progress: Progress | None = None) -> None:
    """Header row, units row, one row per table row; named styles; frozen panes and widths."""
    from copy import copy

    from openpyxl.cell.cell import Cell
    from openpyxl.utils import get_column_letter

    from bearingheat import excel_style as st

    register = st.register_styles
    register(ws.parent)
    formulas = formulas or {}
    headers, unit_row, styles, magnitudes = [], [], [], []
    for header in table.columns:
        column = table[header]
        name, unit = split_header(header, column, units)
        headers.append(name)
        unit_row.append(unit)
        if str(column.dtype).startswith("pint["):
            column = pd.Series(column.pint.magnitude, index=column.index)
        if header in input_columns:
            styles.append(st.INPUT)
        else:
            styles.append(_column_style(unit))
        magnitudes.append(column.to_numpy(dtype=object))
    ws.append(headers)
    ws.append(unit_row)
    for col, header in enumerate(table.columns, start=1):
        is_input = header in input_columns
        ws.cell(1, col).style = st.HEADER_INPUT if is_input else st.HEADER_RESULT
        ws.cell(2, col).style = st.UNITS if is_input else st.UNITS_RESULT
        sample = [len(str(v)) for v in magnitudes[col - 1][:200] if isinstance(v, str)]
        width = min(max([len(str(headers[col - 1])), len(str(unit_row[col - 1])), 8] + sample) + 2, 40)
        if headers[col - 1] == "message":
            width = 80
        ws.column_dimensions[get_column_letter(col)].width = width
    status_col = list(table.columns).index("status") if "status" in table.columns else None
    formula_cols = {}
    for (header, position) in formulas:
        formula_cols.setdefault(header, list(table.columns).index(header))
    if progress is not None:
        progress.start(len(table), f"writing {ws.title}")
    n_cols = len(headers)
    style_arrays = _style_arrays(ws, set(styles) | set(st.STATUS.values()) | {st.FORMULA, st.RESULT})
    column_styles = [style_arrays[name] for name in styles]
    status_styles = {status: style_arrays[name] for status, name in st.STATUS.items()}
    formula_style = style_arrays[st.FORMULA]
    for position in range(len(table)):
        row = []
        for c in range(n_cols):
            cell = Cell(ws, value=_cell_value(magnitudes[c][position]))
            if c == status_col:
                cell._style = copy(status_styles.get(str(cell.value), style_arrays[st.RESULT]))
            else:
                cell._style = copy(column_styles[c])
            row.append(cell)
        for header, c in formula_cols.items():
            text = formulas.get((header, position))
            if text is not None:
                row[c].value = text
                row[c]._style = copy(formula_style)
        ws.append(row)
        if progress is not None and position % 500 == 0:
            progress.update(position)
    if progress is not None:
        progress.finish()
    ws.freeze_panes = "A3"


def _style_arrays(ws, names) -> dict:
    """Named style -> the style array of a cell that has it (copied onto many cells at once)."""
    from openpyxl.cell.cell import Cell

    arrays = {}
    for name in names:
        probe = Cell(ws)
        probe.style = name
        arrays[name] = probe._style
    return arrays


def _result_table(result: pd.DataFrame, table: pd.DataFrame, info: SheetInfo) -> pd.DataFrame:
    """The columns of the results sheet: the input row, id/designation, then every result column."""
    out = pd.DataFrame({"row": pd.Series(info.rows, dtype="int64", index=result.index)})
    for header in table.columns:
        name = _contract_name(header)
        if name in ("id", "designation") or (name in ("type", "series") and table[header].notna().any()):
            out[header] = result[header]
    for header in result.columns:
        if header not in table.columns or _contract_name(header) in ("f0", "f1"):
            if header in out.columns:
                continue
            out[header] = result[header]
    return out


def _install_sheet(workbook, name: str, after: str | None = None):
    """A fresh sheet ``name``: an existing one of that name is replaced at its place."""
    if name in workbook.sheetnames:
        index = workbook.sheetnames.index(name)
        workbook.remove(workbook[name])
        return workbook.create_sheet(name, index)
    index = workbook.sheetnames.index(after) + 1 if after in workbook.sheetnames else None
    return workbook.create_sheet(name, index)


def atomic_save(workbook, path: Path) -> None:
    """Save to a temporary file in the target's folder, then rename it over the target.

    A failure while saving leaves the target as it was (and no temporary
    file behind); the target keeps its permission bits.
    """
    path = Path(path)
    handle, temp_name = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=path.suffix, dir=path.parent)
    os.close(handle)
    try:
        workbook.save(temp_name)
        if path.exists():
            os.chmod(temp_name, path.stat().st_mode & 0o7777)
        os.replace(temp_name, path)
    except BaseException:
        if os.path.exists(temp_name):
            os.unlink(temp_name)
        raise


def write_results(results: pd.DataFrame, path, *, sheet: str = RESULTS_SHEET, units: dict[str, str] | None = None,
                  input_columns=(), formulas: dict[tuple[str, int], str] | None = None) -> Path:
    """Write ``results`` as sheet ``sheet`` of the workbook ``path`` (header row, units row, one row each).

    A new workbook is created when ``path`` does not exist; in an existing
    workbook the sheet is added (or replaced) and every other sheet kept,
    refused when the workbook holds content openpyxl would drop
    (:func:`bearingheat.excel_safety.unsupported_content`). The write is
    atomic. Units come from pint-pandas dtypes, ``units``, or ``name
    [unit]`` headers; ``formulas`` maps (column, row position) to formula
    text written instead of the value.
    """
    from openpyxl import Workbook

    from bearingheat.excel_safety import refuse_lossy_rewrite

    path = Path(path)
    if path.suffix.lower() not in EXCEL_SUFFIXES:
        raise ExcelError(f"{path}: an Excel workbook ends in .xlsx or .xlsm")
    if path.exists():
        workbook = _open_workbook(path, keep_vba=path.suffix.lower() == ".xlsm")
        refuse_lossy_rewrite(path, workbook, option="write_results")
        ws = _install_sheet(workbook, sheet)
    else:
        if path.suffix.lower() == ".xlsm":
            raise ExcelError(f"{path}: a new workbook is written as .xlsx (a .xlsm needs its macros)")
        workbook = Workbook()
        ws = workbook.active
        ws.title = sheet
    _fill_sheet(ws, results, units=units, input_columns=set(input_columns), formulas=formulas)
    atomic_save(workbook, path)
    return path


def write_results_workbook(result: pd.DataFrame, path) -> Path:
    """Results of a CSV calc as a new workbook: one 'Results' sheet, input columns styled as inputs."""
    from openpyxl import Workbook

    path = Path(path)
    if path.suffix.lower() != ".xlsx":
        from bearingheat.cli import UsageError

        raise UsageError(f"{path}: results of a CSV are written to a new .xlsx workbook")
    known = input_units()
    inputs = [h for h in result.columns
              if _contract_name(h) in known and _contract_name(h) not in ("f0", "f1")
              and h not in ("status", "message")]
    workbook = Workbook()
    ws = workbook.active
    ws.title = RESULTS_SHEET
    _fill_sheet(ws, result, input_columns=set(inputs))
    atomic_save(workbook, path)
    return path


# ---------------------------------------------------------------------------------------------
# calc on a workbook


def _mark_uncached(result: pd.DataFrame, info: SheetInfo) -> None:
    """Rows with a formula cell that has no saved value fail with a message naming the cell."""
    numeric = [c for c in result.columns if c not in ("status", "message")
               and c not in info.letters and pd.api.types.is_float_dtype(result[c].dtype)]
    for position, header, formula in info.uncached:
        where = f"{info.sheet_ref}!{info.letters[header]}{info.rows[position]}"
        text = (f"{where}: formula {formula} has no saved value (the file was never opened and saved in a "
                "spreadsheet program); open it in Excel or LibreOffice, save it, and run again")
        row = result.index[position]
        current = result.at[row, "message"]
        result.at[row, "message"] = f"{text}; {current}" if current else text
        result.at[row, "status"] = "error"
        result.loc[row, numeric] = np.nan


def _input_error(exc: Exception, info: SheetInfo) -> ExcelError:
    """An InputError of calc with the cell of the column it names."""
    message = str(exc)
    match = re.match(r"column '(?P<header>.+?)': ", message)
    if match:
        header = match.group("header")
        letter = info.letters.get(header) or info.letters.get(_contract_name(header) or "")
        if letter is not None:
            return ExcelError(f"{info.sheet_ref}!{letter}{info.units_row or info.header_row}: {message}")
    return ExcelError(f"sheet {info.sheet!r} (header row {info.header_row}): {message}")


@dataclass
class WorkbookRun:
    """What :func:`calc_workbook` did: the results, where they went, what was left out."""

    result: pd.DataFrame
    info: SheetInfo
    output: Path | None
    results_sheet: str | None
    dropped: list[str]


def calc_workbook(path, output=None, *, sheet: str | None = None, in_place: bool = False, formulas: bool = False,
                  f2_chart=None, effects=None, keep_vba: bool = True, progress: Progress | None = None) -> WorkbookRun:
    """Run calc on a sheet of supports and write a results sheet.

    ``output`` (a new .xlsx/.xlsm) gets a copy of the workbook plus the
    results sheet; ``in_place=True`` writes the results sheet into ``path``
    itself (atomically, refused when that would drop content). With neither,
    nothing is written. ``formulas=True`` writes live Excel formulas for
    P1, M0, M1, M2, MR and NR. Raises :class:`ExcelError` for unusable input.
    """
    from bearingheat.excel_safety import refuse_lossy_rewrite, unsupported_content
    from bearingheat.f2chart import F2ChartError
    from bearingheat.frame import calc

    source = Path(path)
    if not source.is_file():
        raise ExcelError(f"{source}: no such file")
    target = Path(output) if output is not None else (source if in_place else None)
    if in_place and output is not None:
        raise ExcelError("give either --in-place or -o OUTPUT, not both")
    if output is not None and target.resolve() == source.resolve():
        raise ExcelError(f"-o {output} is the input workbook; use --in-place to write into it")
    if formulas and target is None:
        raise ExcelError("--formulas writes a workbook: give -o OUTPUT.xlsx or --in-place")
    if formulas and effects is not None:
        raise ExcelError("--formulas cannot express the fitted effect of --effects; use one of them")
    if target is not None and target.suffix.lower() not in EXCEL_SUFFIXES + (".csv",):
        raise ExcelError(f"{target}: write the results to .xlsx, .xlsm or .csv")
    if formulas and target.suffix.lower() == ".csv":
        raise ExcelError("--formulas needs an Excel output (.xlsx), not a CSV")
    if target is not None and target.suffix.lower() == ".xlsm" and source.suffix.lower() != ".xlsm":
        raise ExcelError(f"{target}: only a .xlsm input can be written as .xlsm")
    writes_workbook = target is not None and target.suffix.lower() in EXCEL_SUFFIXES
    vba = keep_vba and writes_workbook and target.suffix.lower() == ".xlsm"
    workbook = _open_workbook(source, keep_vba=vba)
    if in_place:
        refuse_lossy_rewrite(source, workbook, option="--in-place", keep_vba=keep_vba)
    table, info = _read_sheet(workbook, source, sheet, progress=progress)
    if not len(table):
        raise ExcelError(f"sheet {info.sheet!r}: no supports under the header (row {info.header_row})")
    try:
        result = calc(table, units=info.units, cell=info.cell, f2_chart=f2_chart, effects=effects)
    except F2ChartError as exc:
        raise ExcelError(str(exc)) from exc
    except InputError as exc:
        raise _input_error(exc, info) from exc
    _mark_uncached(result, info)
    dropped: list[str] = []
    results_sheet = None
    if target is not None and target.suffix.lower() == ".csv":
        result.to_csv(target, index=False)
    elif writes_workbook:
        if not in_place:
            dropped = unsupported_content(source, workbook, keep_vba=vba)
        results_sheet = results_sheet_name(info.sheet)
        out_table = _result_table(result, table, info)
        formula_text = None
        if formulas:
            from bearingheat.excel_formulas import live_formulas

            out_table, formula_text = live_formulas(out_table, table, info, result)
        ws = _install_sheet(workbook, results_sheet, after=info.sheet)
        _fill_sheet(ws, out_table, units={"row": "-"}, formulas=formula_text, progress=progress)
        ws.sheet_properties.tabColor = "44546A"
        atomic_save(workbook, target)
    return WorkbookRun(result, info, target, results_sheet, dropped)


def run_calc_workbook(args) -> int:
    """``bearingheat calc IN.xlsx ...``: exit 0 (rows ok), 1 (some row in error); UsageError for exit 2."""
    from bearingheat.cli import UsageError
    from bearingheat.cli.calc import _load_effects, print_summary

    progress = Progress(enabled=not args.quiet)
    try:
        run = calc_workbook(args.input, args.output, sheet=args.sheet, in_place=args.in_place,
                            formulas=args.formulas, f2_chart=args.f2_chart, effects=_load_effects(args.effects),
                            progress=progress)
    except ExcelError as exc:
        raise UsageError(str(exc)) from exc
    if not args.quiet:
        where = None
        if run.output is not None:
            where = f"{run.output}" + (f", sheet {run.results_sheet!r}" if run.results_sheet else "")
        print_summary(run.result, where)
        if run.dropped:
            print(f"note: {run.output} lacks the {', '.join(run.dropped)} of {args.input} (openpyxl cannot copy "
                  f"them); {args.input} is unchanged", file=sys.stderr)
    return 1 if (run.result["status"] == "error").any() else 0


def _main(argv: list[str] | None = None) -> int:
    import argparse

    from bearingheat.excel_template import regenerate

    parser = argparse.ArgumentParser(prog="python -m bearingheat.excel",
                                     description="Regenerate the committed template and example workbooks.")
    parser.add_argument("--regenerate", metavar="FOLDER", required=True,
                        help="write template.xlsx and gearbox_shaft_example.xlsx into FOLDER")
    parser.add_argument("--example-csv", default="examples/gearbox_shaft.csv",
                        help="the supports of the example workbook (default: %(default)s)")
    args = parser.parse_args(argv)
    for written in regenerate(args.regenerate, example_csv=args.example_csv):
        print(f"wrote {written}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(_main())
