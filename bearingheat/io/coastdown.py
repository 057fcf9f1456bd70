"""Read a run-down record (``t [unit]``, ``n [unit]`` columns of a CSV) as pint Quantities."""
from __future__ import annotations

import csv

import numpy as np

from bearingheat.calc.contract import parse_header
from bearingheat.errors import InputError
from bearingheat.units import parse_unit, ureg

__all__ = ["read_rundown"]


def read_rundown(path):
    """Read a run-down CSV into (t Quantity array, n Quantity array).

    One column ``t [UNIT]`` (a time unit) and one column ``n [UNIT]`` (a shaft
    speed), one sample a row; other columns are ignored. An unreadable file, a
    missing column or a cell that is not a number raises
    :class:`~bearingheat.errors.InputError`; an unknown unit
    :class:`~bearingheat.errors.UnitError`.
    """
    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            rows = list(csv.reader(handle))
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror}") from exc
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
            cell = row[col].strip() if col < len(row) else ""
            try:
                values.append(float(cell))
            except ValueError:
                raise InputError(f"{path} line {line}, column '{name}': {cell!r} is not a number") from None
        out[key] = ureg().Quantity(np.array(values), unit)
    return out["t"], out["n"]
