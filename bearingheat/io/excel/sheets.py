"""What ``calc`` writes into a workbook: the results sheet and its companions, ready for either writer.

:func:`results_sheets` gathers, for one input sheet, the results sheet's
table (:func:`bearingheat.io.excel.writer.result_table`), its formulas (the
live formulas of :mod:`.formulas` and the status formulas of the live check
of :mod:`.freshness`, which name the inputs' copy and so are made once its
name is known), the check below the table that the input sheet has no
support without results (:func:`.freshness.unread_rows_check`), its
conditional formats and its print setup (:mod:`.printing`), and the
companion sheets: the hidden copy of the inputs
(``--formulas``) and the duty cycle summary (a table that has one). Each
companion can fill an openpyxl worksheet (the ``-o`` copy) or render its
worksheet part (``--in-place``, :func:`bearingheat.io.excel.package.write_results_in_place`).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from bearingheat.io.excel import style as st
from bearingheat.io.excel.formulas import live_formulas
from bearingheat.io.excel.freshness import (ConditionalRule, conditional_rules, freshness_check, snapshot_base,
                                            unread_rows_check)
from bearingheat.io.excel.ownership import read_companions, read_marks
from bearingheat.io.excel.printing import PrintSetup
from bearingheat.io.excel.reader import defined_name_values
from bearingheat.io.excel.sheetxml import cells_sheet_xml, results_sheet_xml
from bearingheat.io.excel.writer import fill_sheet, result_table

__all__ = ["ResultsSheets", "CellsSheet", "TableSheet", "results_sheets", "duty_base"]

#: the columns a printed page repeats at its left: up to the last of these that the results sheet has
_TITLE_COLUMNS = ("row", "id", "designation")


def duty_base(input_sheet: str) -> str:
    """The name of the duty cycle summary of ``input_sheet``: 'Duty cycle', or '<sheet> duty cycle'."""
    return "Duty cycle" if input_sheet == "Supports" else f"{input_sheet[:20]} duty cycle"


@dataclass
class CellsSheet:
    """A companion sheet of plain cells (row, column index, value), e.g. the hidden copy of the inputs."""

    role: str
    base: str
    cells: list[tuple[int, int, object]]
    hidden: bool = True

    def fill(self, ws) -> None:
        for row, col, value in self.cells:
            cell = ws.cell(row, col)
            cell.value = value.item() if hasattr(value, "item") else value
            if cell.data_type == "f":  # text that looks like a formula stays text
                cell.data_type = "s"
                cell.quotePrefix = True
        ws.sheet_state = "hidden" if self.hidden else "visible"

    def render(self, styles) -> bytes:
        return cells_sheet_xml(self.cells, 0, lambda: styles.index(st.RESULT, quote=True))


@dataclass
class TableSheet:
    """A companion sheet of a table with a header and a units row, e.g. the duty cycle summary."""

    role: str
    base: str
    table: pd.DataFrame
    hidden: bool = False

    def fill(self, ws) -> None:
        fill_sheet(ws, self.table)
        ws.sheet_properties.tabColor = "44546A"

    def render(self, styles) -> bytes:
        return results_sheet_xml(self.table, styles.index, dxf_index=styles.dxf, title=self.base)


@dataclass
class ResultsSheets:
    """The results sheet of one input sheet and its companions (module docstring)."""

    table: pd.DataFrame
    print_setup: PrintSetup
    rules: list[ConditionalRule] = field(default_factory=list)
    companions: list = field(default_factory=list)
    cell_formulas: dict[tuple[str, int], str] = field(default_factory=dict)
    status_formulas: Callable[[str], list[str]] | None = None
    hidden_columns: list[str] = field(default_factory=list)
    #: formulas of cells below the table by address: the check that no support lacks results
    footer: dict[str, str] = field(default_factory=dict)

    def formulas(self, names: dict[str, str]) -> dict[tuple[str, int], str]:
        """The formulas of the results sheet, the companions named by role as ``names`` says."""
        out = dict(self.cell_formulas)
        if self.status_formulas is not None:
            out.update((("status", i), text) for i, text in enumerate(self.status_formulas(names["snapshot"])))
        return out


def results_sheets(source: Path, workbook, table: pd.DataFrame, info, result: pd.DataFrame, *, formulas: bool,
                   model: str, duty: pd.DataFrame | None = None) -> ResultsSheets:
    """The sheets calc writes for the input sheet ``info.sheet`` of ``workbook`` (openpyxl, read from
    ``source``): with ``formulas``, live formulas and the live check; ``duty`` a duty cycle summary."""
    out_table = result_table(result, table, info)
    sheets = ResultsSheets(out_table, PrintSetup.of(source.name, info.sheet, supports=len(out_table),
                                                    title_columns=_title_columns(list(out_table.columns))))
    if formulas:
        live = live_formulas(out_table, table, info, result, model=model)
        check = freshness_check(workbook[info.sheet], table, info, result["status"].tolist(), live.every)
        sheets.table, sheets.cell_formulas = live.table, live.formulas
        sheets.status_formulas = check.status_formulas
        sheets.hidden_columns = live.collapsed
        sheets.rules = conditional_rules(list(live.table.columns), live.live_columns, len(live.table))
        sheets.companions.append(CellsSheet("snapshot", snapshot_base(info.sheet), check.snapshot))
        unread = unread_rows_check(info, len(live.table))
        if unread is not None:
            address, formula, rule = unread
            sheets.footer[address] = formula
            sheets.rules.append(rule)
    if duty is not None:
        sheets.companions.append(TableSheet("duty", duty_base(info.sheet), duty))
    sheets.companions += _emptied_companions(workbook, info.sheet, {c.role for c in sheets.companions})
    return sheets


#: what an emptied companion sheet says, by role (its numbers would be stale beside the new results)
_EMPTIED = {
    "duty": "No duty cycle: the last run of calc on {sheet!r} found none (no support, case and time_share columns), "
            "so this summary is empty; its earlier numbers would not match the results.",
    "snapshot": "No live formulas: the last run of calc on {sheet!r} wrote numbers (without --formulas), so this copy "
                "of the inputs is empty.",
}


def _emptied_companions(workbook, input_sheet: str, written: set[str]) -> list[CellsSheet]:
    """The companion sheets an earlier run wrote for ``input_sheet`` that this run does not write (a duty cycle
    since removed from the sheet, a run without --formulas after one with): each is written again holding only
    a note, under its mark, so that no stale numbers stay beside the new results."""
    pairs = defined_name_values(workbook)
    marks, owned = read_marks(pairs), read_companions(pairs)
    present = {name.casefold() for name in workbook.sheetnames}
    emptied = []
    for k, (results, source) in marks.items():
        if source != input_sheet or results is None or results.casefold() not in present:
            continue
        for role, sheet in owned.get(k, {}).items():
            if role in written or role not in _EMPTIED or sheet is None or sheet.casefold() not in present:
                continue
            hidden = next(ws.sheet_state != "visible" for ws in workbook.worksheets
                          if ws.title.casefold() == sheet.casefold())
            base = duty_base(input_sheet) if role == "duty" else snapshot_base(input_sheet)
            emptied.append(CellsSheet(role, base, [(1, 1, _EMPTIED[role].format(sheet=input_sheet))], hidden))
    return emptied


def _title_columns(columns: list[str]) -> int:
    present = [columns.index(name) + 1 for name in _TITLE_COLUMNS if name in columns]
    return max(present + [1])
