"""What a replaced results sheet changes for the rest of the workbook: columns that moved, and who reads them.

A designer's formula such as ``=SUM(Results!K3:K5)`` on a Summary sheet
names a column of the results sheet by its letter. When a re-run writes
the columns in another order (an optional label column such as ``type``
filled in since), the same letters hold another quantity, and nothing in
the workbook would show it. :func:`moved_columns` compares the header row
of the sheet being replaced with the new one; :func:`readers_of` finds the
formulas of the other sheets, the defined names and the charts that refer
to the results sheet, so that the run's note can name them.

>>> moved_columns(["row", "id", "MR", "NR"], ["row", "id", "type", "MR", "NR"])
['MR (C -> D)', 'NR (D -> E)']
>>> moved_columns(["row", "id", "MR"], ["row", "id", "MR", "type"])
[]
>>> reference_pattern("Results").search("=SUM(results!K3:K5)") is not None
True
>>> reference_pattern("Results").search("=SUM(MyResults!K3:K5)") is None
True
"""
from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from openpyxl.utils import get_column_letter

from bearingheat.io.excel import record
from bearingheat.io.excel.opc import MAIN, Package, parse_part
from bearingheat.io.excel.ownership import sheet_ref

__all__ = ["moved_columns", "header_row", "reference_pattern", "readers_of", "note"]

_M = f"{{{MAIN}}}"
#: at most this many moved columns or readers are named in a note
_SHOWN = 8


def moved_columns(old: Sequence[str | None], new: Sequence[str]) -> list[str]:
    """The headers of ``old`` that sit in another column of ``new`` (or are gone), as 'MR (K -> M)'."""
    where: dict[str, int] = {}
    for index, header in enumerate(new):
        where.setdefault(header, index)
    out = []
    for index, title in enumerate(old):
        if title is None or title == "" or where.get(title) == index:
            continue
        target = where.get(title)
        letter = get_column_letter(index + 1)
        out.append(f"{title} ({letter} -> {get_column_letter(target + 1)})" if target is not None
                   else f"{title} ({letter}, gone)")
    return out


def header_row(cells: record.SheetCells) -> list[str | None]:
    """The texts of row 1 of a sheet read by :func:`bearingheat.io.excel.record.read_cells`, by column (inline
    strings, shared strings, numbers)."""
    texts = {col: value for col, row, kind, value in cells.cells if row == 1}
    return [texts.get(c) for c in range(1, max(texts, default=0) + 1)]


def reference_pattern(sheet: str) -> re.Pattern[str]:
    """A reference to ``sheet`` in a formula: ``Results!``, ``'Results'!`` (without case, as Excel compares)."""
    quoted = re.escape(sheet.replace("'", "''"))
    return re.compile(rf"(?<![\w.'])(?:{re.escape(sheet)}|'{quoted}')!", re.IGNORECASE)


def readers_of(package: Package, sheet: str, sheets: Iterable[tuple[str, str]],
               names: Iterable[tuple[str, str]], skip: Iterable[str] = ()) -> list[str]:
    """Who reads ``sheet`` by reference: 'Summary!B1' (a formula of another sheet), 'the name total_MR', 'a chart
    (xl/charts/chart1.xml)'. ``sheets`` are (name, part) of the workbook's sheets, ``names`` its defined names
    (name, value), ``skip`` the parts not to search (bearingheat's own sheets)."""
    pattern = reference_pattern(sheet)
    skipped = {part.lower() for part in skip}
    found: list[str] = []
    for name, value in names:
        if pattern.search(value or "") and not name.lower().startswith(("_bearingheat_", "_xlnm.")):
            found.append(f"the name {name}")
    for name, part in sheets:
        if part.lower() in skipped:
            continue
        data = package.read(part)
        if data is None or not pattern.search(data.decode("utf-8", "replace")):
            continue
        for cell in parse_part(data, part, package.path).iter(_M + "c"):
            formula = cell.find(_M + "f")
            if formula is not None and formula.text and pattern.search(formula.text):
                found.append(f"{sheet_ref(name)}!{cell.get('r')}")
    for part in package.names():
        if re.match(r"^xl/charts/chart\d*\.xml$", part, re.IGNORECASE):
            text = (package.read(part) or b"").decode("utf-8", "replace")
            if any(pattern.search(f) for f in re.findall(r"<c:f>([^<]*)</c:f>", text)):
                found.append(f"a chart ({part})")
    return found


def note(sheet: str, moved: list[str], readers: list[str]) -> str:
    """The run's note on the columns of ``sheet`` that moved and the references that may now read others."""
    shown = ", ".join(moved[:_SHOWN]) + (f" and {len(moved) - _SHOWN} more" if len(moved) > _SHOWN else "")
    text = f"the columns of sheet {sheet!r} changed since the last run: {shown}"
    if readers:
        who = ", ".join(readers[:_SHOWN]) + (f" and {len(readers) - _SHOWN} more" if len(readers) > _SHOWN else "")
        text += f"; {who} refer to sheet {sheet!r} and may now read other quantities: check them"
    return text
