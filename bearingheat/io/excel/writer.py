"""Write results to a workbook: a header row, a units row, one styled row per support.

- :func:`write_results`: a DataFrame as a sheet of a new or existing
  workbook (an existing one is edited part by part, every other part kept
  byte for byte: :mod:`bearingheat.io.excel.package`; a sheet of the
  designer's is never replaced).
- :func:`write_results_workbook`: the results of a CSV calc as a new workbook.
- :func:`atomic_save`: save through a temporary file, so a failure leaves
  the target as it was.

Units come from pint-pandas dtypes, a units mapping, or ``name [unit]``
headers (:func:`bearingheat.io.excel.layout.split_header`); cells take the
named styles of :mod:`bearingheat.io.excel.style`.
"""
from __future__ import annotations

import math
import os
from collections.abc import Iterable, Sequence
from collections.abc import Set as AbstractSet
from copy import copy
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

from bearingheat.calc.contract import input_units
from bearingheat.errors import ExcelError
from bearingheat.io.excel import style as st
from bearingheat.io.excel.freshness import ConditionalRule
from bearingheat.io.excel.layout import sheet_layout
from bearingheat.io.excel.ownership import TABLE_MARK, mark_value, sheet_name_problem
from bearingheat.io.excel.opc import open_package
from bearingheat.io.excel.package import write_table_in_place
from bearingheat.io.excel.reader import DEFAULT_SHEET, EXCEL_SUFFIXES, RESULTS_SHEET, SheetInfo, contract_name
from bearingheat.io.excel.printing import PrintSetup
from bearingheat.io.files import atomic_write, workbook_lock

if TYPE_CHECKING:
    from bearingheat.io.console import Progress

__all__ = [
    "write_results",
    "write_results_workbook",
    "atomic_save",
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


def fill_sheet(ws: Worksheet, table: pd.DataFrame, *, units: dict[str, str] | None = None,
               input_columns: AbstractSet[str] = frozenset(), formulas: dict[tuple[str, int], str] | None = None,
               progress: Progress | None = None, rules: Sequence[ConditionalRule] = (),
               print_setup: PrintSetup | None = None, hidden_columns: Sequence[str] = (),
               footer: dict[str, str] | None = None) -> None:
    """Header row, units row, one row per table row; named styles; frozen panes and widths.

    Text values are written as text, also when they begin with '=' (they
    never become formulas); only ``formulas`` are formulas (a status formula
    keeps the colour of calc's status). ``rules`` are conditional formats
    (:class:`bearingheat.io.excel.freshness.ConditionalRule`),
    ``print_setup`` a :class:`bearingheat.io.excel.printing.PrintSetup`;
    ``hidden_columns`` are grouped and collapsed (the helper columns of the
    formulas: a designer opens them with the outline's + button). ``footer``
    maps the addresses of cells below the table to formulas (the check of
    :func:`bearingheat.io.excel.freshness.unread_rows_check`).
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
    for address, text in (footer or {}).items():
        ws[address] = text
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


def result_table(result: pd.DataFrame, table: pd.DataFrame, info: SheetInfo) -> pd.DataFrame:
    """The columns of the results sheet: the input row, id/designation (support and case where the sheet gives
    them), every result column, then type and series where the sheet gives them.

    type and series are at the end: a designer fills them in later, and a column added before the results
    would move every result one letter on, under the designer's formulas that read them by letter
    (=SUM(Results!K3:K5))."""
    out = pd.DataFrame({"row": pd.Series(info.rows, dtype="int64", index=result.index)})
    given = [h for h in table.columns if contract_name(h) in ("id", "designation") or (
        contract_name(h) in ("support", "case", "type", "series") and table[h].notna().any())]
    for header in given:
        if contract_name(header) not in ("type", "series"):
            out[header] = result[header]
    for header in result.columns:
        if header not in table.columns or contract_name(header) in ("f0", "f1"):
            if header in out.columns:
                continue
            out[header] = result[header]
    for header in given:
        if contract_name(header) in ("type", "series"):
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

    A new workbook is created when ``path`` does not exist. An existing
    workbook is edited as ``calc --in-place`` edits it
    (:func:`bearingheat.io.excel.package.write_table_in_place`): only this
    sheet and what registers it are written, every other part (sheets,
    charts, images, pivot tables, macros ...) is kept byte for byte. The
    sheet is added after the last one, or replaced where bearingheat wrote
    it (a results sheet, one of its companions, or a sheet of an earlier
    ``write_results``: :mod:`.ownership`). A sheet of that name (compared
    without case, as Excel does) that the designer made is never replaced:
    :class:`ExcelError`, the file unchanged; so is a workbook the edit
    cannot keep whole (:class:`~bearingheat.errors.WorkbookContentError`:
    signed, encrypted, a protected structure ...) and one that Excel,
    LibreOffice or another bearingheat run has open
    (:func:`bearingheat.io.files.workbook_lock`). The sheet is marked as
    bearingheat's (a hidden defined name ``_bearingheat_table_<k>``). The
    write is atomic. Units come from pint-pandas dtypes, ``units``, or
    ``name [unit]`` headers; ``input_columns`` are styled as inputs;
    ``formulas`` maps (column, row position) to formula text written
    instead of the value (the workbook recalculates when opened).
    """
    path = Path(path)
    if path.suffix.lower() not in EXCEL_SUFFIXES:
        raise ExcelError(f"{path}: an Excel workbook ends in .xlsx or .xlsm")
    problem = sheet_name_problem(sheet)
    if problem is not None:
        raise ExcelError(f"{path}: sheet name {sheet!r} {problem}; nothing was written")
    if path.exists():
        with workbook_lock(path) as lock:
            write_table_in_place(open_package(path, action="write_results"), sheet, results, lock=lock,
                                 units=units, input_columns=set(input_columns), formulas=formulas)
        return path
    if path.suffix.lower() == ".xlsm":
        raise ExcelError(f"{path}: a new workbook is written as .xlsx (a .xlsm needs its macros)")
    workbook = Workbook()
    ws = workbook.active
    ws.title = sheet
    workbook.defined_names[f"{TABLE_MARK}1"] = DefinedName(f"{TABLE_MARK}1", hidden=True,
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

