"""Cell styles and column layout shared by the template, the results sheet and the example workbook.

Input cells are pale yellow (the designer types there), result cells grey,
live-formula cells pale green; header rows are bold with a dark fill for
results. The styles are registered as named styles so a designer sees
them by name in Excel's style gallery ("bearingheat input", ...).
"""
from __future__ import annotations

from openpyxl.styles import Alignment, Border, Font, NamedStyle, PatternFill, Side

__all__ = ["STYLE_NAMES", "register_styles", "INPUT", "UNITS", "HEADER_INPUT", "HEADER_OPTIONAL",
           "HEADER_RESULT", "UNITS_RESULT", "RESULT", "RESULT_NUMBER", "FORMULA", "MESSAGE", "STATUS", "THREE_DIGITS",
           "NUMBER_FORMATS", "number_format", "DIFFERENTIAL", "STALE", "RECALCULATE"]

_THIN = Side(style="thin", color="BFBFBF")
_BOX = Border(left=_THIN, right=_THIN, top=_THIN, bottom=_THIN)

INPUT = "bearingheat input"
UNITS = "bearingheat units"
HEADER_INPUT = "bearingheat header"
HEADER_OPTIONAL = "bearingheat header optional"
HEADER_RESULT = "bearingheat result header"
UNITS_RESULT = "bearingheat result units"
RESULT = "bearingheat result"
RESULT_NUMBER = "bearingheat result number"
FORMULA = "bearingheat formula"
#: the message column: its text wraps
MESSAGE = "bearingheat message"
#: status value -> style of its cell
STATUS = {"ok": "bearingheat status ok", "warning": "bearingheat status warning",
          "error": "bearingheat status error"}

#: at least three significant digits and no more decimals than that (138, 21.5, 7.11, 0.35)
THREE_DIGITS = "[>=100]0;[>=10]0.0;0.00"
#: number format of a result column by its unit: speeds and loads as integers, torques and powers to three
#: significant digits, temperatures and viscosities to one decimal; coefficients (unit 1) stay General
NUMBER_FORMATS = {"1/min": "0", "N": "0", "N*mm": THREE_DIGITS, "W": THREE_DIGITS, "W*h": THREE_DIGITS,
                  "degC": "0.0", "delta_degC": "0.0", "mm^2/s": "0.0", "mm": "0.0", "mm^3/(s*min)": "0",
                  "h": "0.0"}


def number_format(unit: str) -> str:
    """The number format of a result column of unit ``unit`` ('0.00' for units without their own).

    >>> number_format("1/min"), number_format("N*mm"), number_format("m/s")
    ('0', '[>=100]0;[>=10]0.0;0.00', '0.00')
    """
    return NUMBER_FORMATS.get(unit, "0.00")


#: differential formats of the conditional formats (dxf): results a changed input made stale are struck through
#: in grey; the status that asks for a recalculation is bold orange
STALE = "stale"
RECALCULATE = "recalculate"
DIFFERENTIAL = {STALE: Font(strike=True, color="808080"), RECALCULATE: Font(bold=True, color="C65911")}


def _definitions() -> list[NamedStyle]:
    def style(name, fill=None, font=None, number_format="General", wrap=False, align=None):
        return NamedStyle(
            name=name, font=font or Font(name="Calibri", size=11),
            fill=PatternFill("solid", fgColor=fill) if fill else PatternFill(),
            border=_BOX, number_format=number_format,
            alignment=Alignment(wrap_text=wrap, horizontal=align, vertical="top"),
        )

    bold = Font(name="Calibri", size=11, bold=True)
    return [
        style(INPUT, fill="FFF2CC"),
        style(UNITS, fill="FFF9E5", font=Font(name="Calibri", size=11, italic=True, color="7F6000"),
              align="center"),
        style(HEADER_INPUT, fill="FFD966", font=bold, align="center"),
        style(HEADER_OPTIONAL, fill="FFE699", font=Font(name="Calibri", size=11, bold=True, color="595959"),
              align="center"),
        style(HEADER_RESULT, fill="44546A", font=Font(name="Calibri", size=11, bold=True, color="FFFFFF"),
              align="center"),
        style(UNITS_RESULT, fill="D6DCE4", font=Font(name="Calibri", size=11, italic=True, color="44546A"),
              align="center"),
        style(RESULT, fill="EDEDED"),
        style(RESULT_NUMBER, fill="EDEDED", number_format="0.00"),
        style(FORMULA, fill="E2EFDA", number_format="0.00"),
        style(MESSAGE, fill="EDEDED", wrap=True),
        style(STATUS["ok"], fill="EDEDED", font=Font(name="Calibri", size=11, color="375623")),
        style(STATUS["warning"], fill="EDEDED", font=Font(name="Calibri", size=11, bold=True, color="C65911")),
        style(STATUS["error"], fill="EDEDED", font=Font(name="Calibri", size=11, bold=True, color="C00000")),
    ]


STYLE_NAMES = [s.name for s in _definitions()]


def style_column(dimension, name: str) -> None:
    """Give a whole column the fill, font and border of a named style (cells typed later look the same)."""
    definition = next(s for s in _definitions() if s.name == name)
    dimension.fill = definition.fill
    dimension.font = definition.font
    dimension.border = definition.border


def register_styles(workbook) -> None:
    """Add the bearingheat named styles to ``workbook`` (those it lacks)."""
    have = set(workbook.named_styles)
    for definition in _definitions():
        if definition.name not in have:
            workbook.add_named_style(definition)
