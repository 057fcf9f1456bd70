"""Rows and cells of an input sheet that are not what they look like to the reader (:mod:`.reader`).

- :func:`totals_rows`: the totals row of an Excel table (Insert > Table;
  Table Design > Total Row) sits under the supports and holds their sums:
  it is no support.
- :func:`take_ambiguous_texts`: a number typed as text with groups of three
  digits after '.' or ',' ('3.000') is 3 with a decimal mark and 3000 with a
  thousands separator, and a workbook has no decimal mark of its own (a CSV
  file has) to say which: it is not read (:func:`ambiguous_text_message`).
- :func:`filled_rows`: the rows with something in the columns calc read, as
  Excel's COUNTIFS counts them: the count the check of ``--formulas`` for
  supports without results compares with
  (:func:`bearingheat.io.excel.freshness.unread_rows_check`).
"""
from __future__ import annotations

import re
from typing import Any

from openpyxl.utils import range_boundaries
from openpyxl.worksheet.worksheet import Worksheet

__all__ = ["totals_rows", "take_ambiguous_texts", "ambiguous_text_message", "filled_rows"]

#: a number typed as text with groups of three digits after '.' or ',' ('3.000', '12,500', '1.234.567'): a
#: decimal mark or a thousands separator of another locale, which a workbook cell does not tell ('0.500' is 0.5
#: either way: no thousands group begins with 0)
_GROUPED = re.compile(r"[+-]?[1-9][0-9]{0,2}(?:[.,][0-9]{3})+")


def totals_rows(ws: Worksheet, columns: set[int], first_data: int) -> dict[int, str]:
    """{row: table name} of the totals rows of the sheet's Excel tables that lie among the rows of supports
    (from ``first_data``) in ``columns``: the last ``totalsRowCount`` rows of the table's range (ECMA-376 Part 1,
    18.5.1.2; ``totalsRowShown`` only tells whether the row was ever shown)."""
    rows: dict[int, str] = {}
    for table in ws.tables.values():
        count = table.totalsRowCount or 0
        min_col, _, max_col, max_row = range_boundaries(table.ref)
        if count and any(min_col <= col <= max_col for col in columns):
            rows.update((row, table.displayName) for row in range(max(max_row - count + 1, first_data), max_row + 1))
    return rows


def take_ambiguous_texts(columns: list[tuple[int, str]], numbers: list[bool], data: list[list]
                         ) -> list[tuple[int, str, str]]:
    """The text cells of the number columns (``numbers``: which of ``columns`` hold numbers) that read two ways
    ('3.000': 3 with a decimal point, 3000 with a thousands separator), as (row position, header, text) in the
    order of the rows; each is blanked in ``data`` (its columns of values), where calc would read '3.000' as 3."""
    found = []
    for (_, header), number, values in zip(columns, numbers, data):
        if not number:
            continue
        for position, value in enumerate(values):
            if isinstance(value, str) and _GROUPED.fullmatch(value.strip()):
                found.append((position, header, value))
                values[position] = None
    return sorted(found)


def ambiguous_text_message(cell: str, text: str) -> str:
    """The message of the number cell ``cell`` holding text such as '3.000' (:func:`take_ambiguous_texts`)."""
    marks = sorted(set(re.findall(r"[.,]", text)))
    which = (f"its {marks[0]!r} may be a decimal mark or a thousands separator" if len(marks) == 1 else
             f"its {marks[0]!r} and {marks[1]!r} may be decimal marks or thousands separators")
    return f"{cell}: {text!r} is a number stored as text, and {which}; type the number into the cell as a number"


def filled_rows(cells: dict[tuple[int, int], Any], used: dict[int, list[tuple[int, Any]]], counted: list[bool],
                cached: dict[tuple[str, int], Any], columns: list[tuple[int, str]], first: int) -> int:
    """:attr:`bearingheat.io.excel.reader.SheetInfo.filled_rows`: the rows from ``first`` (the units row, or the
    header row without one) down with something in a column whose position in ``columns`` is ``counted``, as
    COUNTIFS(range, "") tells them from blank rows: a cell of spaces is something, a formula that shows "" is not.
    ``cells`` are the sheet's cells by (row, column), ``used`` the rows under ``first`` with a value
    ({row: [(position, cell)]}), ``cached`` the saved values of formula cells by (header, row) (a formula without
    one counts: recalculated, it shows something)."""
    def something(position: int, cell: Any) -> bool:
        if cell is None:
            return False
        if cell.data_type == "f":
            return cached.get((columns[position][1], cell.row)) != ""
        return cell.value is not None and cell.value != ""

    title = any(something(position, cells.get((first, col)))
                for position, ((col, _), counts) in enumerate(zip(columns, counted)) if counts)
    return int(title) + sum(any(counted[position] and something(position, cell) for position, cell in row_cells)
                            for row_cells in used.values())
