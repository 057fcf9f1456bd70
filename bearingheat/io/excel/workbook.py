"""The Excel bridge: read supports from a workbook, run calc, write the results back.

:func:`calc_workbook` reads a sheet of supports (:mod:`.reader`), runs
:func:`bearingheat.calc.table.calc` on it, and writes a results sheet
(:mod:`.writer`), optionally with live Excel formulas (:mod:`.formulas`),
into a copy of the workbook, into the workbook itself (``in_place``, refused
when that would lose content, :mod:`.safety`) or into a CSV. Input it cannot
use raises :class:`~bearingheat.errors.ExcelError` with a message that cites
the cell, e.g. ``Supports!F2: column 'Fr [kg]': kilogram is a mass, not a
force; for kilogram-force write kgf``; a bad value in one row is reported in
that row (``Supports!F7: 'abc' is not a number for Fr [kN]``).

>>> run = calc_workbook("spreadsheets/gearbox_shaft_example.xlsx")   # no output: nothing is written
>>> run.info.sheet, len(run.result), run.output
('Supports', 6, None)
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.calc.models import DEFAULT_MODEL
from bearingheat.calc.table import calc
from bearingheat.calc.thermal import DEFAULT_SPEED_FACTOR_METHOD
from bearingheat.errors import ExcelError, F2ChartError, InputError
from bearingheat.io.excel.formulas import live_formulas
from bearingheat.io.excel.reader import EXCEL_SUFFIXES, SheetInfo, contract_name, open_workbook, read_sheet
from bearingheat.io.excel.safety import refuse_lossy_rewrite, unsupported_content
from bearingheat.io.excel.writer import atomic_save, fill_sheet, install_sheet, result_table, results_sheet_name
from bearingheat.io.tables import write_csv

__all__ = ["calc_workbook", "WorkbookRun"]


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
        letter = info.letters.get(header) or info.letters.get(contract_name(header) or "")
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
                  model: str = DEFAULT_MODEL, n_per_method: str = DEFAULT_SPEED_FACTOR_METHOD, f2_chart=None,
                  effects=None, keep_vba: bool = True,
                  progress=None) -> WorkbookRun:
    """Run calc on a sheet of supports and write a results sheet.

    ``output`` (a new .xlsx/.xlsm) gets a copy of the workbook plus the
    results sheet; ``in_place=True`` writes the results sheet into ``path``
    itself (atomically, refused when that would drop content). With neither,
    nothing is written. ``formulas=True`` writes live Excel formulas for
    P1, M0, M1, M2, MR and NR. ``progress`` (e.g.
    :class:`bearingheat.io.console.Progress`) is advanced while the sheets
    are read and written. Raises :class:`ExcelError` for unusable input
    (:class:`~bearingheat.errors.WorkbookContentError` when ``in_place``
    would lose content).
    """
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
    workbook = open_workbook(source, keep_vba=vba)
    if in_place:
        refuse_lossy_rewrite(source, workbook, option="--in-place", keep_vba=keep_vba)
    table, info = read_sheet(workbook, source, sheet, progress=progress)
    if not len(table):
        raise ExcelError(f"sheet {info.sheet!r}: no supports under the header (row {info.header_row})")
    try:
        result = calc(table, model=model, n_per_method=n_per_method, units=info.units, cell=info.cell,
                      f2_chart=f2_chart, effects=effects)
    except F2ChartError as exc:
        raise ExcelError(str(exc)) from exc
    except InputError as exc:
        raise _input_error(exc, info) from exc
    _mark_uncached(result, info)
    dropped: list[str] = []
    results_sheet = None
    if target is not None and target.suffix.lower() == ".csv":
        write_csv(result, target)
    elif writes_workbook:
        if not in_place:
            dropped = unsupported_content(source, workbook, keep_vba=vba)
        results_sheet = results_sheet_name(info.sheet)
        out_table = result_table(result, table, info)
        formula_text = None
        if formulas:
            out_table, formula_text = live_formulas(out_table, table, info, result)
        ws = install_sheet(workbook, results_sheet, after=info.sheet)
        fill_sheet(ws, out_table, units={"row": "-"}, formulas=formula_text, progress=progress)
        ws.sheet_properties.tabColor = "44546A"
        atomic_save(workbook, target)
    return WorkbookRun(result, info, target, results_sheet, dropped)
