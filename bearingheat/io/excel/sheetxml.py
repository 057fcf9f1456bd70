"""The results sheet as SpreadsheetML, written directly (the worksheet part of ``calc --in-place``).

:func:`results_sheet_xml` renders the same sheet as
:func:`bearingheat.io.excel.writer.fill_sheet` (a header row, a units row,
one styled row per support, frozen panes, column widths, the tab colour),
as the bytes of a worksheet part (ECMA-376 Part 1, 18.3 ``worksheet``):

- text is an inline string (``t="inlineStr"``), so ``sharedStrings.xml``
  stays untouched, and text is always text: a name beginning with ``=``
  gets Excel's quote prefix and never becomes a formula;
- numbers are written with Python's shortest round-trip repr; a missing,
  NaN or infinite value is an empty cell;
- formulas of ``calc --formulas`` are ``<f>`` elements without a cached
  value, and the workbook is told to recalculate on load
  (:mod:`bearingheat.io.excel.package`).
"""
from __future__ import annotations

import datetime
import functools
import math
import re
from collections.abc import Callable
from collections.abc import Set as AbstractSet
from xml.sax.saxutils import escape

import numpy as np
import pandas as pd
from openpyxl.utils import coordinate_to_tuple, get_column_letter
from openpyxl.utils.datetime import CALENDAR_WINDOWS_1900, to_excel

from bearingheat.io.excel import style as st
from bearingheat.io.excel.layout import sheet_layout
from bearingheat.io.excel.record import WrittenCells, number_text, sheet_extras

__all__ = ["results_sheet_xml", "cells_sheet_xml", "xstring", "TAB_COLOR", "DEFAULT_MARGINS"]

TAB_COLOR = "FF44546A"
_HEAD = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n'
         '<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main" '
         'xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships">')
_INVALID = re.compile("[\x00-\x08\x0b\x0c\x0d\x0e-\x1f\ufffe\uffff]")
_ESCAPE_LOOKALIKE = re.compile(r"_(x[0-9A-Fa-f]{4}_)")
_SURROGATE = re.compile("[\ud800-\udfff]")
#: text a spreadsheet would read as a formula when the cell is edited
_FORMULA_START = ("=", "+", "-", "@")
DEFAULT_MARGINS = '<pageMargins left="0.7" right="0.7" top="0.75" bottom="0.75" header="0.3" footer="0.3"/>'


@functools.lru_cache(maxsize=1 << 16)  # a sheet repeats its texts (designations, statuses, messages)
def _st_xstring(text: str) -> str:
    """Text as an ST_Xstring: '_xHHHH_' look-alikes and characters XML 1.0 cannot hold escaped (what a reader of
    the part, :func:`bearingheat.io.excel.record.read_cells`, finds in it)."""
    text = _ESCAPE_LOOKALIKE.sub(r"_x005F_\1", text)
    text = _INVALID.sub(lambda m: f"_x{ord(m.group()):04X}_", text)
    return _SURROGATE.sub("\ufffd", text)  # a lone surrogate cannot be written as UTF-8


@functools.lru_cache(maxsize=1 << 16)
def xstring(text: str) -> str:
    """Text as an ST_Xstring in XML: '_xHHHH_' look-alikes and characters XML 1.0 cannot hold escaped, then &<>.

    >>> xstring("a<b & _x0041_ \\x01")
    'a&lt;b &amp; _x005F_x0041_ _x0001_'
    >>> xstring("lone \\ud800 surrogate") == "lone \\N{REPLACEMENT CHARACTER} surrogate"
    True
    """
    return escape(_st_xstring(text))


def _number(value) -> str | None:
    if isinstance(value, (bool, np.bool_)):
        return None
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    value = float(value)
    if not math.isfinite(value):
        return None
    text = repr(value)
    return text[:-2] if text.endswith(".0") else text


#: what a cell holds for the record of the sheet (:class:`bearingheat.io.excel.record.WrittenCells`): (kind, value),
#: None for a cell without a value
Recorded = tuple[str, str] | None


def _cell(ref: str, value, style: int, quote_style: Callable[[], int], epoch: datetime.datetime = CALENDAR_WINDOWS_1900
          ) -> tuple[str, Recorded]:
    """One <c> element: number, boolean, date (its serial number of the workbook's ``epoch``, as Excel stores
    dates), inline text or an empty styled cell (also for empty text, as openpyxl writes it); and what it holds
    for the record."""
    if value is None or value is pd.NA or value is pd.NaT or (isinstance(value, str) and value == ""):
        return f'<c r="{ref}" s="{style}"/>', None
    if isinstance(value, datetime.date):  # (a datetime and a pd.Timestamp are dates)
        if isinstance(value, datetime.datetime) and value.tzinfo is not None:
            value = value.replace(tzinfo=None)  # Excel has no time zones: the wall-clock time, as openpyxl writes
        serial = to_excel(value, epoch)
        return f'<c r="{ref}" s="{style}"><v>{_number(serial)}</v></c>', ("n", number_text(serial))
    if isinstance(value, (bool, np.bool_)):
        return f'<c r="{ref}" s="{style}" t="b"><v>{int(bool(value))}</v></c>', ("b", str(int(bool(value))))
    if isinstance(value, (int, float, np.integer, np.floating)):
        number = _number(value)
        if number is None:
            return f'<c r="{ref}" s="{style}"/>', None
        return f'<c r="{ref}" s="{style}"><v>{number}</v></c>', ("n", number_text(value))
    text = str(value)
    if text.startswith(_FORMULA_START) and len(text) > 1:
        style = quote_style()
    space = ' xml:space="preserve"' if text != text.strip() or "\n" in text else ""
    return (f'<c r="{ref}" s="{style}" t="inlineStr"><is><t{space}>{xstring(text)}</t></is></c>',
            ("t", _st_xstring(text)))


#: the worksheet elements after sheetData that a results sheet may have, in CT_Worksheet order
_AFTER_DATA = ("sheetProtection", "conditionalFormatting", "printOptions", "pageMargins", "pageSetup", "headerFooter",
               "rowBreaks")


def results_sheet_xml(table: pd.DataFrame, style_index: Callable[..., int], *, units: dict[str, str] | None = None,
                      formulas: dict[tuple[str, int], str] | None = None, kept: dict[str, str] | None = None,
                      print_setup=None, rules=(), dxf_index: Callable[[str], int] | None = None,
                      progress=None, title: str = "Results", hidden_columns=(),
                      input_columns: AbstractSet[str] = frozenset(), tab_color: str | None = TAB_COLOR,
                      epoch: datetime.datetime = CALENDAR_WINDOWS_1900, written: WrittenCells | None = None,
                      footer: dict[str, str] | None = None) -> bytes:
    """The worksheet part of a results sheet.

    ``style_index(name, quote=False, number_format=None)`` gives the cellXfs
    index of a named style of :mod:`bearingheat.io.excel.style`
    (:meth:`bearingheat.io.excel.stylesheet.StyleSheet.index`).
    ``formulas`` maps (column, row position) to formula text ('=...'); a
    status formula keeps the colour of calc's status. ``kept`` holds the
    print setup and protection XML of the sheet this one replaces by element
    name (sheetProtection, printOptions, pageMargins, pageSetup,
    headerFooter, pageSetUpPr); ``print_setup`` (a
    :class:`bearingheat.io.excel.printing.PrintSetup`) fills in what is not
    kept. ``rules`` are conditional formats
    (:class:`bearingheat.io.excel.freshness.ConditionalRule`), ``dxf_index``
    gives their differential formats' indices. ``hidden_columns`` are grouped
    and collapsed. ``input_columns`` are styled as inputs (as
    :func:`bearingheat.io.excel.writer.fill_sheet` styles them), ``tab_color``
    is the tab's colour (ARGB; None: the workbook's default), ``epoch`` the
    workbook's date system (1900, or 1904 of a workbook so saved) for its
    date cells. ``progress``: an object with start, update, finish.
    ``written`` (a :class:`bearingheat.io.excel.record.WrittenCells`) is
    given every cell with a value as it is written: the sheet's record,
    without reading the part back. ``footer`` maps the addresses of cells
    below the table to formulas ('A10': the check of
    :func:`bearingheat.io.excel.freshness.unread_rows_check`).
    """
    formulas = formulas or {}
    kept = dict(kept or {})
    layout = sheet_layout(table, units, input_columns)
    n_cols, n_rows = len(layout.headers), len(table)
    letters = [get_column_letter(c) for c in range(1, n_cols + 1)]
    column_styles = [style_index(name, number_format=fmt) if fmt else style_index(name)
                     for name, fmt in zip(layout.styles, layout.formats)]
    formula_styles = [style_index(st.FORMULA, number_format=layout.formula_format(c)) for c in range(n_cols)]
    styles = {name: style_index(name) for name in set(st.STATUS.values()) | {st.RESULT}}
    # the header and units rows: an input column's as the input sheet's (fill_sheet's styles)
    title_styles = [(st.HEADER_INPUT, st.UNITS) if is_input else (st.HEADER_RESULT, st.UNITS_RESULT)
                    for is_input in layout.input_columns]
    quoted: dict[str, int] = {}

    def quote_of(name: str) -> Callable[[], int]:
        def index() -> int:
            if name not in quoted:
                quoted[name] = style_index(name, quote=True)
            return quoted[name]
        return index

    columns = list(table.columns)
    status_col = columns.index("status") if "status" in columns else None
    formula_cols = {columns.index(header): header for header in {header for header, _ in formulas}}
    below = sorted(((coordinate_to_tuple(address), text) for address, text in (footer or {}).items()))
    last_row = max([n_rows + 2] + [row for (row, _), _ in below])
    last = f"{letters[-1]}{last_row}" if n_cols else "A1"
    setup = dict(print_setup.xml()) if print_setup is not None else {}
    if "pageSetup" in kept:  # the designer's page setup: fit to pages only where it says so
        setup["pageSetUpPr"] = ""
    setup.update(kept)
    page_pr = setup.pop("pageSetUpPr", "")
    tab = f'<tabColor rgb="{tab_color}"/>' if tab_color else ""
    sheet_pr = f"<sheetPr>{tab}{page_pr}</sheetPr>" if tab or page_pr else ""
    parts = [_HEAD, sheet_pr, f'<dimension ref="A1:{last}"/>',
             '<sheetViews><sheetView workbookViewId="0"><pane ySplit="2" topLeftCell="A3" '
             'activePane="bottomLeft" state="frozen"/><selection pane="bottomLeft" activeCell="A3" sqref="A3"/>'
             '</sheetView></sheetViews>',
             '<sheetFormatPr defaultRowHeight="15"' + (' outlineLevelCol="1"/>' if hidden_columns else "/>")]
    hidden = {columns.index(header) + 1 for header in hidden_columns}
    if n_cols:
        parts.append("<cols>" + "".join(f'<col min="{c}" max="{c}" width="{w:g}" customWidth="1"'
                                        + (' hidden="1" outlineLevel="1"/>' if c in hidden else "/>")
                                        for c, w in enumerate(layout.widths, start=1)) + "</cols>")
    parts.append("<sheetData>")
    record = written.add if written is not None else None
    if written is not None:
        written.extras = sheet_extras(f'rgb="{tab_color}"' if tab_color else "", len(rules))
    for row, texts in ((1, layout.headers), (2, layout.units)):
        names = [pair[row - 1] for pair in title_styles]
        title_cells = []
        for c in range(n_cols):
            xml, entry = _cell(f"{letters[c]}{row}", texts[c], style_index(names[c]), quote_of(names[c]))
            title_cells.append(xml)
            if entry is not None and record is not None:
                record(c + 1, row, *entry)
        parts.append(f'<row r="{row}">{"".join(title_cells)}</row>')
    if progress is not None:
        progress.start(n_rows, f"writing {title}")
    column_quotes = [quote_of(name) for name in layout.styles]
    for position in range(n_rows):
        row = position + 3
        cells = []
        for c in range(n_cols):
            ref = f"{letters[c]}{row}"
            value = layout.values[c][position]
            if isinstance(value, (float, np.floating)) and math.isnan(value):
                value = None
            if c in formula_cols and (formula_cols[c], position) in formulas:
                text = formulas[(formula_cols[c], position)].removeprefix("=")
                style = styles[st.STATUS.get(str(value), st.RESULT)] if c == status_col else formula_styles[c]
                cells.append(f'<c r="{ref}" s="{style}"><f>{escape(text)}</f></c>')
                if record is not None:
                    record(c + 1, row, "f", "")
                continue
            if c == status_col:
                name = st.STATUS.get(str(value), st.RESULT)
                xml, entry = _cell(ref, value, styles[name], quote_of(name))
            else:
                xml, entry = _cell(ref, value, column_styles[c], column_quotes[c], epoch)
            cells.append(xml)
            if entry is not None and record is not None:
                record(c + 1, row, *entry)
        height = layout.heights.get(position)
        size = f' ht="{height:g}" customHeight="1"' if height else ""
        parts.append(f'<row r="{row}"{size}>{"".join(cells)}</row>')
        if progress is not None and position % 500 == 0:
            progress.update(position)
    if progress is not None:
        progress.finish()
    for row in sorted({row for (row, _), _ in below}):
        cells = []
        for (_, col), text in (item for item in below if item[0][0] == row):
            cells.append(f'<c r="{get_column_letter(col)}{row}"><f>{escape(text.removeprefix("="))}</f></c>')
            if record is not None:
                record(col, row, "f", "")
        parts.append(f'<row r="{row}">{"".join(cells)}</row>')
    parts.append("</sheetData>")
    if rules:
        if dxf_index is None:
            raise ValueError("results_sheet_xml: conditional formats need dxf_index")
        setup["conditionalFormatting"] = "".join(
            f'<conditionalFormatting sqref="{rule.sqref}"><cfRule type="expression" dxfId="{dxf_index(rule.dxf)}" '
            f'priority="{k}"><formula>{escape(rule.formula)}</formula></cfRule></conditionalFormatting>'
            for k, rule in enumerate(rules, start=1))
    setup.setdefault("pageMargins", DEFAULT_MARGINS)
    parts.extend(setup[name] for name in _AFTER_DATA if setup.get(name))
    parts.append("</worksheet>")
    return "".join(parts).encode("utf-8")


def cells_sheet_xml(cells: list[tuple[int, int, object]], style: int, quote_style: Callable[[], int]) -> bytes:
    """The worksheet part of a sheet of plain cells (row, column index, value), e.g. the hidden copy of the
    inputs of :mod:`bearingheat.io.excel.freshness`: numbers, booleans and text (text always as text)."""
    by_row: dict[int, list[tuple[int, object]]] = {}
    for row, col, value in cells:
        by_row.setdefault(row, []).append((col, value))
    parts = [_HEAD, '<sheetData>']
    for row in sorted(by_row):
        entries = "".join(_cell(f"{get_column_letter(col)}{row}", value, style, quote_style)[0]
                          for col, value in sorted(by_row[row], key=lambda item: item[0]))
        parts.append(f'<row r="{row}">{entries}</row>')
    parts.append("</sheetData>")
    parts.append(DEFAULT_MARGINS)
    parts.append("</worksheet>")
    return "".join(parts).encode("utf-8")
