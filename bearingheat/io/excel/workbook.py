"""The Excel bridge: read supports from a workbook, run calc, write the results back.

:func:`calc_workbook` reads a sheet of supports (:mod:`.reader`), runs
:func:`bearingheat.calc.table.calc` on it, and writes a results sheet
(:mod:`.writer`), optionally with live Excel formulas (:mod:`.formulas`),
into the workbook itself (``in_place``: a surgical edit of the package
that keeps every other part byte for byte, :mod:`.package`), into a copy
(the same edit written to a new file; openpyxl writes the copy where the
edit is refused) or into a CSV. Input it cannot
use raises :class:`~bearingheat.errors.ExcelError` with a message that cites
the cell, e.g. ``Supports!F2: column 'Fr [kg]': kilogram is a mass, not a
force; for kilogram-force write kgf``; a bad value in one row is reported in
that row (``Supports!F7: 'abc' is not a number for Fr [kN]``).

>>> run = calc_workbook("spreadsheets/gearbox_shaft_example.xlsx")   # no output: nothing is written
>>> run.info.sheet, len(run.result), run.output
('Supports', 6, None)
"""
from __future__ import annotations

import contextlib
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from openpyxl.workbook import Workbook
from openpyxl.workbook.defined_name import DefinedName

from bearingheat.calc.contract import columns, parse_header, readable_header
from bearingheat.calc.duty import duty_cycle, has_duty_cycle
from bearingheat.calc.models import DEFAULT_MODEL
from bearingheat.calc.table import calc
from bearingheat.calc.thermal import DEFAULT_SPEED_FACTOR_METHOD, DEFAULT_VISCOSITY_AT
from bearingheat.errors import (ExcelError, F2ChartError, InputError, SheetContentError, VMChartError,
                               WorkbookContentError)
from bearingheat.io.excel.ownership import (COMPANION_MARKS, INPUT_MARK, RESULTS_MARK, choose_companion_sheet,
                                            choose_results_sheet, mark_value, read_companions, read_marks)
from bearingheat.io.excel.opc import Package, open_package
from bearingheat.io.excel.package import InPlaceResult, write_results_in_place
from bearingheat.io.excel.reader import (EXCEL_SUFFIXES, SheetInfo, contract_name, defined_name_values,
                                         open_workbook, read_sheet)
from bearingheat.io.excel.rows import ambiguous_text_message
from bearingheat.io.excel.safety import unsupported_content
from bearingheat.io.excel.template import is_placeholder
from bearingheat.io.excel.sheets import ResultsSheets, results_sheets
from bearingheat.io.excel.writer import atomic_save, fill_sheet, install_sheet
from bearingheat.io.files import WorkbookLock, safe_output, workbook_lock
from bearingheat.io.tables import calc_passing_through, write_csv

if TYPE_CHECKING:
    from bearingheat.analysis.effects import FittedEffect
    from bearingheat.catalogue.f2chart import F2Chart
    from bearingheat.catalogue.vm_chart import VMChart
    from bearingheat.io.console import Progress

__all__ = ["calc_workbook", "WorkbookRun"]

#: the input columns of a duty cycle (support, case, time_share, duration)
DUTY_COLUMNS = columns(owner="duty")


def _mark_unread(result: pd.DataFrame, info: SheetInfo) -> None:
    """Rows with a cell the reader could not take fail with a message naming the cell: a formula cell that has no
    saved value, a number typed as text that reads two ways ('3.000', :func:`.reader.ambiguous_text_message`)."""
    numeric = [c for c in result.columns if c not in ("status", "message")
               and c not in info.letters and pd.api.types.is_float_dtype(result[c].dtype)]
    unread: dict[int, list[tuple[str, str]]] = {}
    for position, header, formula in info.uncached:
        unread.setdefault(position, []).append((info.letters[header], (
            f"{info.cell(header, position)}: formula {formula} has no saved value (the file was never opened and "
            "saved in a spreadsheet program); open it in Excel or LibreOffice, save it, and run again")))
    for position, header, text in info.ambiguous:
        unread.setdefault(position, []).append((info.letters[header],
                                                ambiguous_text_message(info.cell(header, position), text)))
    for position, found in unread.items():
        text = "; ".join(message for _, message in sorted(found, key=lambda item: (len(item[0]), item[0])))
        row = result.index[position]
        current = str(result.at[row, "message"] or "")
        result.at[row, "message"] = f"{text}; {current}" if current else text
        result.at[row, "status"] = "error"
        result.loc[row, numeric] = np.nan


def _duty_cycle(result: pd.DataFrame, info: SheetInfo) -> pd.DataFrame | None:
    """The duty cycle summary of a sheet whose ``support`` column holds supports (None without one).

    The template has the columns of a duty cycle whether a designer uses
    them or not: an empty one counts as absent. The units of the units row
    go into the headers, as calc's functions read them.
    """
    empty = [header for name in DUTY_COLUMNS if (header := info.headers.get(name)) in result.columns
             and result[header].isna().all()]
    result = result.drop(columns=empty)
    if not has_duty_cycle(result):
        return None
    named = {header: f"{header} [{unit}]" for header, unit in info.units.items()
             if unit not in ("", "-", "1") and "[" not in header and header in result.columns}
    return duty_cycle(result.rename(columns=named), cell=info.cell)


def _units_in_headers(result: pd.DataFrame, info: SheetInfo) -> pd.DataFrame:
    """The results with the units of the units row in the input headers ('Fr' over kN -> 'Fr [kN]'): a CSV has no
    units row, and without them its numbers would have no unit (calc refuses 'd' without one when it is read
    back)."""
    named = {}
    for header, unit in info.units.items():
        # (text columns have none, dimensionless ones need none; a header with its own unit keeps it)
        if unit in ("", "-", "1") or header not in result.columns or parse_header(header, strict=False)[1]:
            continue
        written = f"{header} [{unit}]"
        if readable_header(written) and written not in result.columns:
            named[header] = written
    return result.rename(columns=named) if named else result


def _input_error(exc: Exception, info: SheetInfo) -> ExcelError:
    """An InputError of calc with the cell of the column it names."""
    message = str(exc)
    match = re.match(r"column '(?P<header>.+?)'(?P<lookalike>: | looks like )", message)
    if match:
        header = match.group("header")
        letter = info.letters.get(header) or info.letters.get(contract_name(header) or "")
        if letter is not None:
            # the header's cell, or the units row's where the unit the message is about was typed there (calc
            # names such a column 'Fr [kg]', which no header of the sheet is); a header that looks like another
            # column ('Arrangement') is its header cell
            typed_below = (info.units.get(header) if header in info.letters else True) \
                and match.group("lookalike") == ": "
            row = info.units_row if info.units_row and typed_below else info.header_row
            return ExcelError(f"{info.sheet_ref}!{letter}{row}: {message}")
    return ExcelError(f"sheet {info.sheet!r} (header row {info.header_row}): {message}")


@dataclass
class WorkbookRun:
    """What :func:`calc_workbook` did: the results, where they went, what was left out, what to tell the user.

    ``notes`` are sentences for the user, e.g. that a sheet of theirs named
    'Results' was kept and the results went to 'Results (2)'; ``companions``
    the further sheets written by role ('snapshot': the hidden copy of the
    inputs of ``formulas=True``, 'duty': the duty cycle summary); ``duty``
    the duty cycle summary of a table with a ``support`` column
    (:func:`bearingheat.calc.duty.duty_cycle`), None without one.
    """

    result: pd.DataFrame
    info: SheetInfo
    output: Path | None
    results_sheet: str | None
    dropped: list[str]
    notes: list[str] = field(default_factory=list)
    companions: dict[str, str] = field(default_factory=dict)
    duty: pd.DataFrame | None = None

    def csv_table(self) -> pd.DataFrame:
        """The results as a CSV holds them: the units of the units row in the input headers ('Fr [kN]')."""
        return _units_in_headers(self.result, self.info)


def _mark_results_sheet(workbook: Workbook, input_sheet: str, placeholders: list[str], roles: dict[str, str]
                        ) -> tuple[str, str | None, dict[str, str]]:
    """(results sheet name, note, companion sheets by role) for an openpyxl workbook (the -o copy), with their
    ownership marks set; ``roles`` maps the companions' roles to the names they take when new."""
    names = workbook.defined_names
    pairs = defined_name_values(workbook)
    marks, owned = read_marks(pairs), read_companions(pairs)
    name, _, note = choose_results_sheet(workbook.sheetnames, marks, input_sheet, placeholders=placeholders)
    present = {s.casefold() for s in workbook.sheetnames} | {name.casefold()}
    k = next((k for k, (results, source) in marks.items()
              if results is not None and results.casefold() == name.casefold() and source == input_sheet), None)
    for j, (results, _) in marks.items():
        if results is None or results.casefold() not in present:
            for prefix in (RESULTS_MARK, INPUT_MARK):
                names.pop(f"{prefix}{j}", None)
    k = k if k is not None else 1 + max(list(marks) + list(owned) + [0])
    companions: dict[str, str] = {}
    for role, base in roles.items():
        companions[role], _ = choose_companion_sheet(workbook.sheetnames, owned.get(k, {}).get(role), base,
                                                     [name, input_sheet, *companions.values()])
    marked = [(RESULTS_MARK, name), (INPUT_MARK, input_sheet)]
    marked += [(COMPANION_MARKS[role], sheet) for role, sheet in companions.items()]
    for prefix, sheet in marked:
        names[f"{prefix}{k}"] = DefinedName(f"{prefix}{k}", attr_text=mark_value(sheet), hidden=True)
    return name, note, companions


def calc_workbook(path: str | os.PathLike[str], output: str | os.PathLike[str] | None = None, *,
                  sheet: str | None = None, in_place: bool = False, formulas: bool = False,
                  model: str = DEFAULT_MODEL, n_per_method: str = DEFAULT_SPEED_FACTOR_METHOD,
                  f2_chart: F2Chart | str | None = None, vm_chart: VMChart | str | None = None,
                  effects: FittedEffect | None = None, keep_vba: bool = True,
                  progress: Progress | None = None, viscosity_at: str = DEFAULT_VISCOSITY_AT) -> WorkbookRun:
    """Run calc on a sheet of supports and write a results sheet.

    ``in_place=True`` writes the results sheet into ``path`` itself as a
    surgical edit of the package (:mod:`.package`: every other part of the
    file is kept byte for byte; refused when that cannot be done), holding
    the workbook's lock (:func:`bearingheat.io.files.workbook_lock`) from
    the read to the atomic rename. ``output`` (a new .xlsx or .xlsm) gets
    the file that edit would make of the workbook; where the edit is
    refused, or an .xlsm is written as .xlsx, a copy written by openpyxl
    (``WorkbookRun.dropped`` names what it lacks); a .csv output gets the
    results table (the units of the units row in its input headers: 'Fr [kN]'). With neither, nothing is
    written.
    A results sheet replaces only a results sheet that bearingheat marked as
    its own (:mod:`.ownership`). ``formulas=True`` writes live Excel
    formulas for P1, M0, M1, M2, MR and NR. ``progress`` (e.g.
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
    if output is not None and target is not None and target.resolve() == source.resolve():
        raise ExcelError(f"-o {output} is the input workbook; use --in-place to write into it")
    if formulas and target is None:
        raise ExcelError("--formulas writes a workbook: give -o OUTPUT.xlsx or --in-place")
    if formulas and effects is not None:
        raise ExcelError("--formulas cannot express the fitted effect of --effects; use one of them")
    if target is not None and target.suffix.lower() not in EXCEL_SUFFIXES + (".csv",):
        raise ExcelError(f"{target}: write the results to .xlsx, .xlsm or .csv")
    if formulas and target is not None and target.suffix.lower() == ".csv":
        raise ExcelError("--formulas needs an Excel output (.xlsx), not a CSV")
    if target is not None and target.suffix.lower() == ".xlsm" and source.suffix.lower() != ".xlsm":
        raise ExcelError(f"{target}: only a .xlsm input can be written as .xlsm")
    with contextlib.ExitStack() as stack:
        edit = None
        if in_place:
            safe_output(source, force=True)  # a read-only workbook, or one with other hard links, is refused
            lock = stack.enter_context(workbook_lock(source))
            package = open_package(source)
            edit = package, lock
            if not keep_vba and package.find("xl/vbaProject.bin") is not None:
                raise WorkbookContentError(
                    f"{source}: --in-place keeps every part of the workbook, its VBA macros too; keep_vba=False "
                    "would drop them; the file is unchanged. Write the results to a new workbook with "
                    "-o OUTPUT.xlsx instead")
        return _run(source, target, edit, sheet=sheet, formulas=formulas, model=model,
                    n_per_method=n_per_method, f2_chart=f2_chart, vm_chart=vm_chart, effects=effects,
                    keep_vba=keep_vba,
                    progress=progress, viscosity_at=viscosity_at)


def _package_to_copy(source: Path, target: Path, keep_vba: bool) -> Package | None:
    """The package of ``source`` when the ``-o`` copy can be a surgical edit of it (:mod:`.package`: every part
    kept byte for byte), None when openpyxl writes the copy instead: a workbook saved as another kind (an .xlsm
    to .xlsx, whose main part's content type differs), one whose macros are to be left out (``keep_vba``
    false), one the package edit refuses (signed, encrypted, Strict Open XML ...)."""
    if source.suffix.lower() != target.suffix.lower():
        return None
    try:
        package = open_package(source)
    except ExcelError:  # (openpyxl read it: a refusal of the package edit, not a damaged file)
        return None
    if not keep_vba and package.find("xl/vbaProject.bin") is not None:
        return None
    return package


def _package_edit(source: Path, target: Path, edit: tuple[Package, WorkbookLock] | None, keep_vba: bool,
                  info: SheetInfo, sheets: ResultsSheets, placeholders: list[str], progress: Progress | None
                  ) -> InPlaceResult | None:
    """The results sheets written by the surgical package edit (:mod:`.package`): into the workbook (``edit``:
    its package and lock) or into the copy ``target``; None where openpyxl is to write the copy instead
    (:func:`_package_to_copy`, or a refusal of the edit that does not hold for openpyxl's copy)."""
    package, lock = edit if edit is not None else (_package_to_copy(source, target, keep_vba), None)
    if package is None:
        return None
    try:
        return write_results_in_place(package, info.sheet, sheets.table, lock=lock,
                                      target=None if edit is not None else target, units={"row": "-"},
                                      formulas=sheets.formulas, progress=progress, placeholders=placeholders,
                                      rules=sheets.rules, print_setup=sheets.print_setup,
                                      companions=sheets.companions, hidden_columns=sheets.hidden_columns,
                                      footer=sheets.footer)
    except WorkbookContentError as exc:
        if edit is not None:
            raise
        if isinstance(exc, SheetContentError):  # openpyxl replaces that sheet too: the copy would lose it as well
            raise SheetContentError(f"{source}: -o {target} refused, {exc.why}; nothing was written",
                                    exc.why) from exc
        return None  # (a signed or structure-protected workbook ...: openpyxl writes the copy)


def _run(source: Path, target: Path | None, edit: tuple[Package, WorkbookLock] | None, *, sheet: str | None,
         formulas: bool, model: str, n_per_method: str, f2_chart: F2Chart | str | None,
         vm_chart: VMChart | str | None, effects: FittedEffect | None,
         keep_vba: bool, progress: Progress | None, viscosity_at: str = DEFAULT_VISCOSITY_AT) -> WorkbookRun:
    """Read, calc and write (the checks of :func:`calc_workbook` done; ``edit``: the package and its lock, for
    in-place)."""
    writes_workbook = target is not None and target.suffix.lower() in EXCEL_SUFFIXES
    vba = keep_vba and edit is None and target is not None and target.suffix.lower() == ".xlsm"
    workbook = open_workbook(source, keep_vba=vba)
    table, info = read_sheet(workbook, source, sheet, progress=progress)
    if not len(table):
        raise ExcelError(f"sheet {info.sheet!r}: no supports under the header (row {info.header_row})")
    try:
        # a column whose header is no 'name [unit]' ('remark [see note]]') is passed through, as from a CSV
        result = calc_passing_through(table, None, lambda usable: calc(
            usable, model=model, n_per_method=n_per_method, units=info.units, cell=info.cell, f2_chart=f2_chart,
            vm_chart=vm_chart, effects=effects, viscosity_at=viscosity_at))
    except (F2ChartError, VMChartError) as exc:
        raise ExcelError(str(exc)) from exc
    except InputError as exc:
        raise _input_error(exc, info) from exc
    _mark_unread(result, info)
    duty = _duty_cycle(result, info)
    dropped: list[str] = []
    notes: list[str] = []
    companions: dict[str, str] = {}
    results_sheet = None
    if target is not None and target.suffix.lower() == ".csv":
        write_csv(_units_in_headers(result, info), target)  # a CSV has no units row
    elif target is not None and writes_workbook:
        sheets = results_sheets(source, workbook, table, info, result, formulas=formulas, model=model, duty=duty)
        placeholders = [ws.title for ws in workbook.worksheets if is_placeholder(ws)]
        done = _package_edit(source, target, edit, keep_vba, info, sheets, placeholders, progress)
        if done is not None:
            results_sheet, notes, companions = done.sheet, done.notes, done.companions
        else:
            dropped = unsupported_content(source, workbook, keep_vba=vba)
            results_sheet, note, companions = _mark_results_sheet(workbook, info.sheet, placeholders,
                                                                  {c.role: c.base for c in sheets.companions})
            notes = [note] if note else []
            ws = install_sheet(workbook, results_sheet, after=info.sheet)
            fill_sheet(ws, sheets.table, units={"row": "-"}, formulas=sheets.formulas(companions), progress=progress,
                       rules=sheets.rules, print_setup=sheets.print_setup, hidden_columns=sheets.hidden_columns,
                       footer=sheets.footer)
            ws.sheet_properties.tabColor = "44546A"
            after = results_sheet
            for companion in sheets.companions:
                companion.fill(install_sheet(workbook, companions[companion.role], after=after))
                after = companions[companion.role]
            atomic_save(workbook, target)
    if info.hidden_rows:  # not silently: a hidden row is a support like the others to calc
        notes.insert(0, _hidden_note(info))
    notes[:0] = [f"row {row} of sheet {info.sheet!r} is the totals row of the Excel table {table!r}, not a "
                 "support: it was left out" for row, table in info.totals_rows]
    return WorkbookRun(result, info, target, results_sheet, dropped, notes, companions, duty)


def _hidden_note(info: SheetInfo) -> str:
    """The note that rows of supports are hidden on the sheet (by hand or by a filter) and were computed."""
    shown = ", ".join(map(str, info.hidden_rows[:10])) + (", ..." if len(info.hidden_rows) > 10 else "")
    rows, are, them = ("row", "is", "it") if len(info.hidden_rows) == 1 else ("rows", "are", "them")
    return (f"{rows} {shown} of sheet {info.sheet!r} {are} hidden (by hand or by a filter) and computed like the "
            f"others; delete {them} to leave {them} out")
