"""Write results to a workbook: a header row, a units row, one styled row per support.

- :func:`write_results`: a DataFrame as a sheet of a new or existing
  workbook (refused when a rewrite would lose content, see
  :mod:`bearingheat.io.excel.safety`, or replace a sheet of the designer's).
- :func:`write_results_workbook`: the results of a CSV calc as a new workbook.
- :func:`atomic_save`: save through a temporary file, so a failure leaves
  the target as it was.

Units come from pint-pandas dtypes, a units mapping, or ``name [unit]``
headers (:func:`split_header`); cells take the named styles of
:mod:`bearingheat.io.excel.style`.
"""
from __future__ import annotations

import math
import os
from collections.abc import Iterable, Sequence
from collections.abc import Set as AbstractSet
from copy import copy
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd
from openpyxl import Workbook
from openpyxl.cell.cell import Cell
from openpyxl.formatting.rule import FormulaRule
from openpyxl.utils import get_column_letter
from openpyxl.workbook.defined_name import DefinedName
from openpyxl.worksheet.worksheet import Worksheet

from bearingheat.calc.contract import input_units, parse_header
from bearingheat.errors import ExcelError, InputError
from bearingheat.io.excel import style as st
from bearingheat.io.excel.freshness import ConditionalRule
from bearingheat.io.excel.ownership import TABLE_MARK, mark_value, table_mark_slots, written_sheets
from bearingheat.io.excel.reader import (DEFAULT_SHEET, EXCEL_SUFFIXES, RESULTS_SHEET, SheetInfo, contract_name,
                                         defined_name_values, open_workbook)
from bearingheat.io.excel.printing import PrintSetup
from bearingheat.io.excel.style import number_format
from bearingheat.io.excel.safety import refuse_lossy_rewrite
from bearingheat.io.files import atomic_write

if TYPE_CHECKING:
    from bearingheat.io.console import Progress

__all__ = [
    "write_results",
    "write_results_workbook",
    "atomic_save",
    "split_header",
    "results_sheet_name",
    "result_table",
    "install_sheet",
    "fill_sheet",
]


def results_sheet_name(input_sheet: str) -> str:
    """'Results' for the template's 'Supports' sheet, else '<sheet> results' (at most 31 characters)."""
    if input_sheet == DEFAULT_SHEET:
        return RESULTS_SHEET
    return f"{input_sheet[:23]} results"


def _column_style(unit: str) -> str:
    """Numbers with a unit get the number format of the unit; coefficients (unit 1) and text stay as they are."""
    return st.RESULT if unit in ("-", "", "1") else st.RESULT_NUMBER


def _column_format(unit: str, is_input: bool) -> str | None:
    """The number format of a column (:func:`bearingheat.io.excel.style.number_format`), None: the style's own."""
    return None if is_input or unit in ("-", "", "1") else number_format(unit)


#: the width of the message column (its text wraps), and about how many characters fill one of its lines
MESSAGE_WIDTH = 60
_MESSAGE_LINE = 66
#: the height of one line of text [pt]
LINE_HEIGHT = 15.0


def message_heights(messages: Iterable[object]) -> dict[int, float]:
    """Row position -> height [pt] of the rows whose message takes more than one line of the message column.

    >>> message_heights(["", "short", "x" * 140])
    {2: 45.0}
    """
    out: dict[int, float] = {}
    for position, text in enumerate(messages):
        lines = math.ceil(len(text) / _MESSAGE_LINE) if isinstance(text, str) else 1
        if lines > 1:
            out[position] = LINE_HEIGHT * lines
    return out


def _cell_value(value: object) -> object:
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


@dataclass
class SheetLayout:
    """What a results sheet shows, column by column: header, unit, style name, number format (None: the
    style's; formula cells: General), values and width; and the heights of rows with a long message."""

    headers: list[str]
    units: list[str]
    styles: list[str]
    values: list[np.ndarray]
    widths: list[float]
    input_columns: list[bool]
    formats: list[str | None]
    heights: dict[int, float]

    def formula_format(self, column: int) -> str:
        """The number format of a formula cell of ``column`` (coefficients and text: General)."""
        return self.formats[column] or "General"


def sheet_layout(table: pd.DataFrame, units: dict[str, str] | None = None,
                 input_columns: AbstractSet[str] = frozenset()) -> SheetLayout:
    """The header row, units row, cell style and width of every column of ``table`` (values as objects)."""
    headers: list[str] = []
    unit_row: list[str] = []
    styles: list[str] = []
    magnitudes: list[np.ndarray] = []
    widths: list[float] = []
    inputs: list[bool] = []
    formats: list[str | None] = []
    for header in table.columns:
        column = table[header]
        name, unit = split_header(header, column, units)
        headers.append(name)
        unit_row.append(unit)
        if str(column.dtype).startswith("pint["):
            column = pd.Series(column.pint.magnitude, index=column.index)
        inputs.append(header in input_columns)
        styles.append(st.INPUT if header in input_columns else
                      st.MESSAGE if name == "message" else _column_style(unit))
        formats.append(_column_format(unit, header in input_columns))
        values = column.to_numpy(dtype=object)
        magnitudes.append(values)
        sample = [len(str(v)) for v in values[:200] if isinstance(v, str)]
        width = min(max([len(str(name)), len(str(unit)), 6] + sample) + 2, 40)
        widths.append(MESSAGE_WIDTH if name == "message" else width)
    heights = message_heights(table["message"]) if "message" in table.columns else {}
    return SheetLayout(headers, unit_row, styles, magnitudes, widths, inputs, formats, heights)


def fill_sheet(ws: Worksheet, table: pd.DataFrame, *, units: dict[str, str] | None = None,
               input_columns: AbstractSet[str] = frozenset(), formulas: dict[tuple[str, int], str] | None = None,
               progress: Progress | None = None, rules: Sequence[ConditionalRule] = (),
               print_setup: PrintSetup | None = None, hidden_columns: Sequence[str] = ()) -> None:
    """Header row, units row, one row per table row; named styles; frozen panes and widths.

    Text values are written as text, also when they begin with '=' (they
    never become formulas); only ``formulas`` are formulas (a status formula
    keeps the colour of calc's status). ``rules`` are conditional formats
    (:class:`bearingheat.io.excel.freshness.ConditionalRule`),
    ``print_setup`` a :class:`bearingheat.io.excel.printing.PrintSetup`;
    ``hidden_columns`` are grouped and collapsed (the helper columns of the
    formulas: a designer opens them with the outline's + button).
    ``progress`` is an object with start, update and finish
    (:class:`bearingheat.io.console.Progress`), or None.
    """
    register = st.register_styles
    register(ws.parent)
    formulas = formulas or {}
    layout = sheet_layout(table, units, set(input_columns))
    headers, styles, magnitudes = layout.headers, layout.styles, layout.values
    ws.append(headers)
    ws.append(layout.units)
    for col, is_input in enumerate(layout.input_columns, start=1):
        ws.cell(1, col).style = st.HEADER_INPUT if is_input else st.HEADER_RESULT
        ws.cell(2, col).style = st.UNITS if is_input else st.UNITS_RESULT
        ws.column_dimensions[get_column_letter(col)].width = layout.widths[col - 1]
    status_col = list(table.columns).index("status") if "status" in table.columns else None
    columns = list(table.columns)
    formula_cols = {header: columns.index(header) for header in {header for header, _ in formulas}}
    if progress is not None:
        progress.start(len(table), f"writing {ws.title}")
    n_cols = len(headers)
    keys = {(name, fmt) for name, fmt in zip(styles, layout.formats)} | {(name, None) for name in st.STATUS.values()} \
        | {(st.FORMULA, layout.formula_format(c)) for c in range(n_cols)} | {(st.RESULT, None)}
    style_arrays = _style_arrays(ws, keys)
    column_styles = [style_arrays[key] for key in zip(styles, layout.formats)]
    status_styles = {status: style_arrays[(name, None)] for status, name in st.STATUS.items()}
    formula_styles = {c: style_arrays[(st.FORMULA, layout.formula_format(c))] for c in range(n_cols)}
    for position in range(len(table)):
        row = []
        for c in range(n_cols):
            cell = Cell(ws, value=_cell_value(magnitudes[c][position]))
            if c == status_col:
                cell._style = copy(status_styles.get(str(cell.value), style_arrays[(st.RESULT, None)]))
            else:
                cell._style = copy(column_styles[c])
            if cell.data_type == "f":  # text that begins with '=': text, as it was in the input
                cell.data_type = "s"
                cell._style.quotePrefix = 1
            row.append(cell)
        for header, c in formula_cols.items():
            text = formulas.get((header, position))
            if text is not None:
                row[c].value = text
                if c != status_col:
                    row[c]._style = copy(formula_styles[c])
        ws.append(row)
        if progress is not None and position % 500 == 0:
            progress.update(position)
    if progress is not None:
        progress.finish()
    ws.freeze_panes = "A3"
    for position, height in layout.heights.items():
        ws.row_dimensions[position + 3].height = height
    for header in hidden_columns:
        dimension = ws.column_dimensions[get_column_letter(list(table.columns).index(header) + 1)]
        dimension.outline_level, dimension.hidden = 1, True
    if hidden_columns:
        ws.sheet_format.outlineLevelCol = 1
    for rule in rules:
        ws.conditional_formatting.add(rule.sqref, FormulaRule(formula=[rule.formula],
                                                              font=copy(st.DIFFERENTIAL[rule.dxf])))
    if print_setup is not None:
        print_setup.apply(ws)


def _style_arrays(ws: Worksheet, keys: Iterable[tuple[str, str | None]]) -> dict[tuple[str, str | None], Any]:
    """(named style, number format or None) -> the style array of a cell that has it (copied onto many cells)."""
    arrays: dict[tuple[str, str | None], Any] = {}
    for name, fmt in keys:
        probe = Cell(ws)
        probe.style = name
        if fmt is not None:
            probe.number_format = fmt
        arrays[(name, fmt)] = probe._style
    return arrays


def _unit_text(unit: object) -> str:
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


def result_table(result: pd.DataFrame, table: pd.DataFrame, info: SheetInfo) -> pd.DataFrame:
    """The columns of the results sheet: the input row, id/designation (support, case, type and series where
    the sheet gives them), then every result column."""
    out = pd.DataFrame({"row": pd.Series(info.rows, dtype="int64", index=result.index)})
    for header in table.columns:
        name = contract_name(header)
        if name in ("id", "designation") or (name in ("support", "case", "type", "series")
                                             and table[header].notna().any()):
            out[header] = result[header]
    for header in result.columns:
        if header not in table.columns or contract_name(header) in ("f0", "f1"):
            if header in out.columns:
                continue
            out[header] = result[header]
    return out


def install_sheet(workbook: Workbook, name: str, after: str | None = None) -> Worksheet:
    """A fresh sheet ``name``: an existing one of that name is replaced at its place."""
    if name in workbook.sheetnames:
        index = workbook.sheetnames.index(name)
        workbook.remove(workbook[name])
        return workbook.create_sheet(name, index)
    index = workbook.sheetnames.index(after) + 1 if after in workbook.sheetnames else None
    return workbook.create_sheet(name, index)


def atomic_save(workbook: Workbook, path: Path) -> None:
    """Save to a temporary file in the target's folder, then rename it over the target.

    :func:`bearingheat.io.files.atomic_write`: a failure while saving leaves
    the target as it was (and no temporary file behind); the target keeps
    its permission bits; a symbolic link is written through.
    """
    atomic_write(path, lambda temp: workbook.save(temp))


def write_results(results: pd.DataFrame, path: str | os.PathLike[str], *, sheet: str = RESULTS_SHEET,
                  units: dict[str, str] | None = None, input_columns: Iterable[str] = (),
                  formulas: dict[tuple[str, int], str] | None = None) -> Path:
    """Write ``results`` as sheet ``sheet`` of the workbook ``path`` (header row, units row, one row each).

    A new workbook is created when ``path`` does not exist; in an existing
    workbook the sheet is added, or replaced where bearingheat wrote it
    (a results sheet, one of its companions, or a sheet of an earlier
    ``write_results``: :mod:`.ownership`), and every other sheet kept. A
    sheet of that name (compared without case, as Excel does) that the
    designer made is never replaced: :class:`ExcelError`, the file
    unchanged. Refused as well when the workbook holds content openpyxl
    would drop (:func:`bearingheat.io.excel.safety.unsupported_content`).
    The sheet is marked as bearingheat's (a hidden defined name
    ``_bearingheat_table_<k>``). The write is atomic. Units come from
    pint-pandas dtypes, ``units``, or ``name [unit]`` headers; ``formulas``
    maps (column, row position) to formula text written instead of the
    value.
    """
    path = Path(path)
    if path.suffix.lower() not in EXCEL_SUFFIXES:
        raise ExcelError(f"{path}: an Excel workbook ends in .xlsx or .xlsm")
    if path.exists():
        workbook = open_workbook(path, keep_vba=path.suffix.lower() == ".xlsm")
        written = written_sheets(defined_name_values(workbook))
        present = next((name for name in workbook.sheetnames if name.casefold() == sheet.casefold()), None)
        if present is not None and present.casefold() not in written:
            raise ExcelError(f"{path}: sheet {present!r} is not a sheet bearingheat wrote (it has no bearingheat "
                             "mark), so it is kept; the file is unchanged. Write the table to a sheet of another "
                             "name")
        refuse_lossy_rewrite(path, workbook, option="write_results")
        ws = install_sheet(workbook, present if present is not None else sheet)  # (a sheet keeps its own name)
    else:
        if path.suffix.lower() == ".xlsm":
            raise ExcelError(f"{path}: a new workbook is written as .xlsx (a .xlsm needs its macros)")
        workbook = Workbook()
        ws = workbook.active
        ws.title = sheet
        written = {}
    if ws.title.casefold() not in written:  # (a results sheet or a table keeps the mark it has)
        slot = 1 + max(table_mark_slots(workbook.defined_names), default=0)
        workbook.defined_names[f"{TABLE_MARK}{slot}"] = DefinedName(f"{TABLE_MARK}{slot}", hidden=True,
                                                                    attr_text=mark_value(ws.title))
    fill_sheet(ws, results, units=units, input_columns=set(input_columns), formulas=formulas)
    atomic_save(workbook, path)
    return path


def write_results_workbook(result: pd.DataFrame, path: str | os.PathLike[str],
                           source: str | os.PathLike[str] | None = None, duty: pd.DataFrame | None = None) -> Path:
    """Results of a CSV calc as a new workbook: one 'Results' sheet, input columns styled as inputs, printed
    with the name of the CSV ``source`` in the page header (:class:`bearingheat.io.excel.printing.PrintSetup`);
    a duty cycle summary (:func:`bearingheat.calc.duty.duty_cycle`) as the sheet 'Duty cycle'.

    Raises :class:`ExcelError` unless ``path`` ends in .xlsx.
    """
    path = Path(path)
    if path.suffix.lower() != ".xlsx":
        raise ExcelError(f"{path}: results of a CSV are written to a new .xlsx workbook")
    known = input_units()
    inputs = [h for h in result.columns
              if contract_name(h) in known and contract_name(h) not in ("f0", "f1")
              and h not in ("status", "message")]
    workbook = Workbook()
    ws = workbook.active
    ws.title = RESULTS_SHEET
    titles = max([list(result.columns).index(h) + 1 for h in ("id", "designation") if h in result.columns] + [1])
    setup = PrintSetup.of(Path(source).name if source is not None else path.name, "", supports=len(result),
                          title_columns=titles)
    fill_sheet(ws, result, input_columns=set(inputs), print_setup=setup)
    if duty is not None:
        summary = workbook.create_sheet("Duty cycle")
        fill_sheet(summary, duty)
        summary.sheet_properties.tabColor = "44546A"
    atomic_save(workbook, path)
    return path

