"""What a sheet of a table shows, column by column: the layout both writers render.

:func:`sheet_layout` gives the header row, the units row, each column's
named style (:mod:`bearingheat.io.excel.style`), number format and width,
and the heights of rows with a long message. openpyxl's writer
(:func:`bearingheat.io.excel.writer.fill_sheet`) and the worksheet part of
the package edit (:func:`bearingheat.io.excel.sheetxml.results_sheet_xml`)
render the same layout. Units come from pint-pandas dtypes, a units
mapping, or ``name [unit]`` headers (:func:`split_header`).
"""
from __future__ import annotations

import datetime
import math
from collections.abc import Iterable
from collections.abc import Set as AbstractSet
from dataclasses import dataclass

import numpy as np
import pandas as pd

from bearingheat.calc.contract import parse_header
from bearingheat.errors import InputError
from bearingheat.io.excel import style as st
from bearingheat.io.excel.style import number_format

__all__ = ["SheetLayout", "sheet_layout", "split_header", "message_heights", "MESSAGE_WIDTH", "LINE_HEIGHT"]


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


#: the number formats of a column of dates, and of dates with times
DATE_FORMAT, DATETIME_FORMAT = "yyyy-mm-dd", "yyyy-mm-dd hh:mm:ss"


def _date_format(values: np.ndarray) -> str | None:
    """:data:`DATE_FORMAT` for a column of dates, :data:`DATETIME_FORMAT` where some have a time of day, None for
    a column that is not all dates (missing cells aside).

    >>> import datetime
    >>> _date_format(np.array([datetime.date(2024, 5, 1), None], dtype=object))
    'yyyy-mm-dd'
    """
    present = [v for v in values if v is not None and not (isinstance(v, float) and math.isnan(v)) and v is not pd.NaT]
    if not present or not all(isinstance(v, datetime.date) for v in present):  # (a datetime is a date)
        return None
    timed = any(isinstance(v, datetime.datetime) and v.time() != datetime.time(0) for v in present)
    return DATETIME_FORMAT if timed else DATE_FORMAT


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
        dates = _date_format(values)
        if dates is not None:  # a column of dates: Excel dates with a date format, whichever writer
            formats[-1] = dates
        magnitudes.append(values)
        sample = [len(str(v)) for v in values[:200] if isinstance(v, str)]
        width = min(max([len(str(name)), len(str(unit)), 6] + sample) + 2, 40)
        widths.append(MESSAGE_WIDTH if name == "message" else width)
    heights = message_heights(table["message"]) if "message" in table.columns else {}
    return SheetLayout(headers, unit_row, styles, magnitudes, widths, inputs, formats, heights)


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


