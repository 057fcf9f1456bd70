"""The units row under a header, as the Excel template has it (and a CSV saved from it): one rule for both readers.

A table may name its units in a row of their own under a header of bare
names (``d``, ``Fr``; row 2 of the template's sheet 'Supports') instead of
in the headers (``d [mm]``). The row is told from a first row of data by its
dimensional columns (those of the column contract with a unit): they hold no
number and at least one unit text.

>>> looks_like_units_row(["-", "mm", "kN"], ["designation", "d", "Fr"])
(True, [])
>>> looks_like_units_row(["6208", "40", "kN"], ["designation", "d", "Fr"])
(False, [])
>>> looks_like_units_row(["-", "mm", "KNN"], ["designation", "d", "Fr"])
(True, [(2, "Fr: unknown unit 'KNN'")])
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from bearingheat.calc.contract import input_units, parse_header
from bearingheat.errors import InputError, UnitError
from bearingheat.units import convert_column, parse_unit

__all__ = ["looks_like_units_row", "unit_contradicts_header", "is_number", "NO_UNIT"]

#: a units-row cell that names no unit (a text column's, a dimensionless one's)
NO_UNIT = "-"


def is_number(value: object) -> bool:
    """Whether a cell holds a number (a workbook's int or float; a logical value TRUE is none)."""
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def looks_like_units_row(values: Sequence[object], names: Sequence[str | None]) -> tuple[bool, list[tuple[int, str]]]:
    """(whether the row under the header holds units, the cells of it that are no unit: (position, why)).

    ``values`` are the row's cells (numbers as a workbook holds them, or text as a CSV does), ``names`` the
    contract name of each column (None for a column the contract does not know). The row holds units when
    its dimensional columns hold no numbers and at least one unit text; a text there that is no unit
    ('KNN') is then a typo in the units row, not a sign of a row of supports."""
    known = input_units()
    saw_unit = False
    unknown: list[tuple[int, str]] = []
    for position, (value, name) in enumerate(zip(values, names)):
        if name is None or known.get(name, "") in ("", "1"):
            continue
        if is_number(value):
            return False, []
        text = "" if value is None else str(value).strip()
        if not text or text == NO_UNIT:
            continue
        try:
            float(text)
            return False, []
        except ValueError:
            pass
        try:
            parse_unit(text, name=name)
        except UnitError as exc:
            unknown.append((position, str(exc)))
            continue
        saw_unit = True
    return saw_unit, unknown if saw_unit else []


def unit_contradicts_header(header: str, unit: str) -> bool:
    """Whether the units row's ``unit`` says another unit than the one written in ``header`` ('n [rpm]' over
    '1/min' does not: one unit spelled two ways gives the same numbers). A header without a unit, or a units
    cell of '-', contradicts nothing."""
    try:
        name, header_unit = parse_header(header)
    except InputError:
        return False
    if header_unit is None or unit == NO_UNIT:
        return False
    target = input_units().get(name, "")
    try:
        if target in ("", "1"):
            return parse_unit(header_unit, name=header) != parse_unit(unit, name=header)
        points = np.array([0.0, 1.0])
        return not bool(np.allclose(convert_column(points, header_unit, target, name=header)[0],
                                    convert_column(points, unit, target, name=header)[0], rtol=1e-12, atol=0.0))
    except UnitError:
        return True
