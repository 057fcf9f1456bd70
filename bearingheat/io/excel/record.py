"""What bearingheat wrote on its results sheet, so that a re-run replaces nothing the designer typed there.

A re-run writes the results sheet anew. A note typed beside the results, a
sign-off line below them, a conditional format or a validation of the
designer's would be thrown away. So each results sheet bearingheat writes
gets a record, a hidden defined name beside its marks (:mod:`.ownership`)::

    _bearingheat_record_1    "A1:O5 3f9c0d2a71b4e8c6"

the range of the cells it wrote and a digest of what they hold: every cell
with a value (numbers to 6 significant digits, text as text whether inline
or shared, a formula as a formula whatever its text and cached value, as
Excel and LibreOffice may rewrite both), the tab colour and the numbers of
conditional format rules, validations and merged ranges. Opening and saving
the workbook in Excel or LibreOffice keeps the digest; an edit changes it.
The record of a sheet being written is made as its cells are written
(:class:`WrittenCells`); :func:`read_cells` reads an existing sheet at a re-run.
:func:`foreign_edit` finds the first cell outside the range that holds a
value (named in the refusal) or tells that the digest differs. A results
sheet of an earlier bearingheat has no record: its range is taken from the
sheet itself (the header row's last column, the last row of column A, which
holds the input row of every support), so cells beyond the table are still
found; edits inside it cannot be told from bearingheat's own cells.

>>> value = record_value("A1:O5", "3f9c0d2a71b4e8c6")
>>> value, parse_record(value)
('"A1:O5 3f9c0d2a71b4e8c6"', ('A1:O5', '3f9c0d2a71b4e8c6'))
>>> print(parse_record("#REF!"))
None
"""
from __future__ import annotations

import hashlib
import html
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import SupportsFloat

from openpyxl.utils import column_index_from_string, get_column_letter, range_boundaries


__all__ = ["RECORD_MARK", "record_value", "parse_record", "SheetCells", "WrittenCells", "read_cells", "foreign_edit",
           "shared_strings", "record_names", "number_text"]

RECORD_MARK = "_bearingheat_record_"


def record_value(cells: str, digest: str) -> str:
    """The defined name's value: a text constant (Excel keeps a name's text as it is)."""
    return f'"{cells} {digest}"'


def parse_record(value: str | None) -> tuple[str, str] | None:
    """(range, digest) of a record's value; None for a value that is no record."""
    match = re.fullmatch(r'\s*=?"([A-Z]+\d+:[A-Z]+\d+) ([0-9a-f]{16})"\s*', value or "")
    return (match.group(1), match.group(2)) if match else None


@dataclass
class SheetCells:
    """The cells with a value of a worksheet part, in document order: (column, row, kind, value) with kind 'n'
    (number), 't' (text), 'b' (boolean), 'e' (error), 'f' (formula, no value); and what else the digest holds."""

    cells: list[tuple[int, int, str, str]]
    extras: str

    @property
    def extent(self) -> str:
        """The range from A1 to the last column and row holding a value."""
        if not self.cells:
            return "A1:A1"
        return f"A1:{get_column_letter(max(c for c, *_ in self.cells))}{max(r for _, r, *_ in self.cells)}"

    def digest(self, cells: str) -> str:
        """The digest of what the sheet holds inside ``cells`` (a range)."""
        low_col, low_row, high_col, high_row = range_boundaries(cells)
        return _digest(self.extras, (f"{col},{row},{kind},{value}\n" for col, row, kind, value in self.cells
                                     if low_col <= col <= high_col and low_row <= row <= high_row))

    def outside(self, cells: str) -> Iterator[tuple[str, str]]:
        """(address, value) of each cell with a value outside ``cells``, row by row."""
        low_col, low_row, high_col, high_row = range_boundaries(cells)
        for col, row, kind, value in sorted(self.cells, key=lambda c: (c[1], c[0])):
            if not (low_col <= col <= high_col and low_row <= row <= high_row):
                yield f"{get_column_letter(col)}{row}", ("a formula" if kind == "f" else value)

    def table_extent(self) -> str:
        """The range of a results sheet without a record: the header row's columns down to the last row of
        column A (the input row of each support)."""
        last_col = max([c for c, r, *_ in self.cells if r == 1], default=1)
        last_row = max([r for c, r, *_ in self.cells if c == 1], default=1)
        return f"A1:{get_column_letter(last_col)}{max(last_row, 2)}"


class WrittenCells:
    """The record of a worksheet part while it is written (:func:`bearingheat.io.excel.sheetxml.results_sheet_xml`):
    each cell with a value added in document order as :func:`read_cells` would find it, so that :attr:`extent` and
    :meth:`digest` equal those of the part read back (``read_cells(part).extent``, ``.digest(extent)``), without
    reading it (about 1 s for 10 000 supports)."""

    def __init__(self) -> None:
        self._lines: list[str] = []
        self.last_column = self.last_row = 0
        self.extras = sheet_extras("", 0)

    def add(self, column: int, row: int, kind: str, value: str) -> None:
        """A cell of ``kind`` 'n' (``value``: :func:`number_text`), 't', 'b', 'e' or 'f' (value '')."""
        self._lines.append(f"{column},{row},{kind},{value}\n")
        if column > self.last_column:
            self.last_column = column
        if row > self.last_row:
            self.last_row = row

    @property
    def extent(self) -> str:
        return f"A1:{get_column_letter(self.last_column)}{self.last_row}" if self._lines else "A1:A1"

    def digest(self) -> str:
        return _digest(self.extras, ["".join(self._lines)])

    def record(self) -> str:
        """The value of the sheet's record (:func:`record_value`)."""
        return record_value(self.extent, self.digest())


def sheet_extras(tab: str, rules: int, validations: int = 0, merged: int = 0) -> str:
    """What the digest holds beside the cells: the tab colour's attributes ('rgb="FF44546A"', sorted) and the
    numbers of conditional format rules, validations and merged ranges."""
    return f"tab {tab}; rules {rules}; validations {validations}; merged {merged}\n"


def _digest(extras: str, lines: Iterable[str]) -> str:
    sha = hashlib.sha256(extras.encode())
    for line in lines:
        sha.update(line.encode("utf-8", "surrogatepass"))
    return sha.hexdigest()[:16]


def number_text(value: SupportsFloat) -> str:
    """A number as the record holds it: 6 significant digits (:func:`_number`).

    >>> number_text(138.47817095928783), number_text(3), number_text(1e-07)
    ('138.478', '3', '1e-07')
    """
    return format(float(value), ".6g")


def _number(text: str) -> str:
    """A number to 6 significant digits: Excel writes 17 digits, openpyxl 16, bearingheat the shortest repr, so the
    last bit may differ after a save; a rounding boundary falls between two such neighbours once in about 1e10
    cells, while an edit of a result changes its first digits."""
    try:
        return number_text(float(text))
    except ValueError:
        return text


# the parts of a worksheet the record reads, as regular expressions on its text: a sheet of 10 000 supports
# has 150 000 cells, which an XML parser visits ten times slower (a cell never holds another cell)
# a cell's address and kind read by lookaheads in its start tag, whatever the order of its attributes: one match a
# cell, no search of its attributes afterwards
_CELL_PARTS = re.compile(r'<(?:\w+:)?c\b(?=[^>]*?\br="([A-Z]{1,3})(\d+)")(?=(?:[^>]*?\bt="(\w+)")?)[^>]*?'
                         r"(?:/>|>(.*?)</(?:\w+:)?c>)", re.DOTALL)
_VALUE = re.compile(r"<(?:\w+:)?v>([^<]*)</(?:\w+:)?v>")
_TEXT = re.compile(r"<(?:\w+:)?t(?:\s[^>]*)?>([^<]*)</(?:\w+:)?t>|<(?:\w+:)?t\s*/>")
_PHONETIC = re.compile(r"<(?:\w+:)?rPh\b.*?</(?:\w+:)?rPh>", re.DOTALL)
_FORMULA = re.compile(r"<(?:\w+:)?f[\s>/]")
_TAB = re.compile(r"<(?:\w+:)?tabColor\b([^>]*?)/?>")


def _texts(inner: str) -> str:
    if inner.startswith("<is><t>") and inner.endswith("</t></is>") and inner.count("<") == 4:  # bearingheat's
        plain = inner[7:-9]
        return html.unescape(plain) if "&" in plain else plain
    return html.unescape("".join(_TEXT.findall(_PHONETIC.sub("", inner))))


def read_cells(data: bytes, shared: list[str] | None = None) -> SheetCells:
    """The cells of the worksheet part ``data`` (``shared``: the workbook's shared strings)."""
    text = data.decode("utf-8", "replace")
    shared = shared or []
    cells: list[tuple[int, int, str, str]] = []
    columns: dict[str, int] = {}
    for letters, row, kind, inner in _CELL_PARTS.findall(text):  # (a cell without r: no address, left out)
        if not inner:
            continue
        if not kind and inner.startswith("<v>") and inner.endswith("</v>"):  # most cells: a number, inline here
            cell: tuple[str, str] | None = ("n", _number(inner[3:-4]))
        elif inner.startswith(("<f>", "<f ")):  # a formula first (what bearingheat's live sheets hold)
            cell = ("f", "")
        else:
            cell = _cell(kind or "n", inner, shared)
        if cell is not None:
            col = columns.get(letters)
            if col is None:
                col = columns[letters] = column_index_from_string(letters)
            cells.append((col, int(row), *cell))
    tab = _TAB.search(text)
    tab_text = ",".join(sorted(_ATTRIBUTE_ANY.findall(tab.group(1)))) if tab else ""
    counts = [len(re.findall(rf"<(?:\w+:)?{tag}\b", text)) if tag in text else 0
              for tag in ("cfRule", "dataValidation", "mergeCell")]
    return SheetCells(cells, sheet_extras(tab_text, *counts))


_ATTRIBUTE_ANY = re.compile(r'(\w+="[^"]*")')


def _cell(kind: str, inner: str, shared: list[str]) -> tuple[str, str] | None:
    """A cell that is not a plain number or a formula first (those :func:`read_cells` takes itself)."""
    if "f" in inner and _FORMULA.search(inner):  # (the substring test first: most cells hold no formula)
        return "f", ""
    if kind == "inlineStr":
        text = _texts(inner)
        return ("t", text) if text else None
    value = _VALUE.search(inner)
    if value is None:
        return None
    if kind == "s":
        index = int(value.group(1)) if value.group(1).strip().isdigit() else -1
        text = shared[index] if 0 <= index < len(shared) else ""
        return ("t", text) if text else None
    if kind in ("str", "e", "b"):
        return ("t" if kind == "str" else kind), html.unescape(value.group(1))
    return "n", _number(value.group(1))


def foreign_edit(cells: SheetCells, recorded: tuple[str, str] | None) -> tuple[str, str | None] | None:
    """What the designer added to a results sheet: (address, value) of the first cell with a value outside what
    bearingheat wrote, (range, None) when the cells inside it differ from the record; None when the sheet is as
    bearingheat wrote it (without a record: nothing outside the table)."""
    extent = recorded[0] if recorded is not None else cells.table_extent()
    first = next(cells.outside(extent), None)
    if first is not None:
        return first
    if recorded is not None and cells.digest(extent) != recorded[1]:
        return extent, None
    return None


def shared_strings(data: bytes | None) -> list[str]:
    """The texts of ``xl/sharedStrings.xml`` (rich text joined, phonetic guides left out)."""
    if data is None:
        return []
    return [_texts(inner) for inner in re.findall(r"<(?:\w+:)?si>(.*?)</(?:\w+:)?si>|<(?:\w+:)?si/>",
                                                   data.decode("utf-8", "replace"), re.DOTALL)]


def record_names(names: Iterable[tuple[str, str]]) -> dict[int, tuple[str, str] | None]:
    """{k: (range, digest)} of the records among (defined name, value) pairs."""
    out: dict[int, tuple[str, str] | None] = {}
    for name, value in names:
        match = re.fullmatch(rf"{RECORD_MARK}(\d+)", name or "", re.IGNORECASE)
        if match is not None:
            out[int(match.group(1))] = parse_record(value)
    return out
