"""Read a run-down record (``t [unit]``, ``n [unit]`` columns of a CSV) as pint Quantities."""
from __future__ import annotations

import csv
import io
import math

import numpy as np

from bearingheat.calc.contract import parse_header
from bearingheat.errors import InputError
from bearingheat.io.tables import read_text, separator, sniff_format
from bearingheat.units import parse_unit, ureg

__all__ = ["read_rundown"]


#: the largest magnitude a time or speed reading may have (1e9 s is 30 years; 1e9 1/min no shaft turns so fast)
_LARGEST = 1e9


def read_rundown(path, *, sep: str | None = None, decimal: str | None = None):
    """Read a run-down CSV into (t Quantity array, n Quantity array).

    One column ``t [UNIT]`` (a time unit) and one column ``n [UNIT]`` (a shaft
    speed), one sample a row; other columns are ignored. The separator (``,``,
    ``;`` or tab) and the decimal mark are found from the file unless given
    (:func:`bearingheat.io.tables.sniff_format`). An unreadable file, a
    missing column or a cell that is not a number raises
    :class:`~bearingheat.errors.InputError`; an unknown unit
    :class:`~bearingheat.errors.UnitError`.
    """
    try:
        text = read_text(path)
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror}") from exc
    sep, sniffed = sniff_format(text, separator(sep))
    decimal = decimal or sniffed
    rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=sep))
    while rows and not rows[0]:
        rows.pop(0)
    if not rows:
        raise InputError(f"{path}: empty file")
    header = rows[0]
    found = {}
    for col, name in enumerate(header):
        key, unit_text = parse_header(name, strict=False)
        if key in ("t", "n") and unit_text is not None:
            found[key] = (col, name.strip(), unit_text)
    for key, example in (("t", "t [s]"), ("n", "n [1/min]")):
        if key not in found:
            raise InputError(f"{path}: no column '{example}' (a '{key} [unit]' column); columns are: "
                             f"{', '.join(repr(h) for h in header)}")
    out = {}
    for key, (col, name, unit_text) in found.items():
        unit = parse_unit(unit_text, name=f"column '{name}'")
        values = []
        for line, row in enumerate(rows[1:], start=2):
            if not row:
                continue
            cell = row[col].strip() if col < len(row) else ""
            try:
                value = float(cell.replace(",", ".") if decimal == "," else cell)
            except ValueError:
                raise InputError(f"{path} line {line}, column '{name}': {cell!r} is not a number") from None
            if not math.isfinite(value) or abs(value) > _LARGEST:  # (1e300 made the rest of the run-down look flat)
                raise InputError(f"{path} line {line}, column '{name}': {cell!r} is not a plausible reading (not "
                                 f"finite, or beyond {_LARGEST:g})")
            values.append(value)
        out[key] = ureg().Quantity(np.array(values), unit)
    return out["t"], out["n"]
