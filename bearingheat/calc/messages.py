"""Row messages of a calculation: which rows fail a check, and how a message names a column and a value."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from bearingheat.calc.contract import input_units

__all__ = ["Problem", "Labels", "at"]


@dataclass
class Problem:
    """Rows that fail one check, and how to word it for row i."""

    mask: np.ndarray
    level: str  # 'error' or 'warning'
    message: Callable[[int], str]


@dataclass
class Labels:
    """How messages name a column and show its value: the user's header and unit."""

    headers: dict[str, tuple[str, float]] = field(default_factory=dict)

    #: optional (column, row position) -> cell reference such as 'Supports!F7'
    cell: Callable[[str, int], str] | None = None

    def name(self, column: str, row: int | None = None) -> str:
        if column in self.headers:
            header = self.headers[column][0]
        else:
            unit = input_units().get(column, "")
            header = f"{column} [{unit}]" if unit not in ("", "1") else column
        if self.cell is not None and row is not None:
            return f"{self.cell(column, row)} {header}"
        return header

    def subset(self, rows: np.ndarray) -> Labels:
        """The labels of the rows at positions ``rows`` of the table, as a table of their own (row k of the
        subset is named as row ``rows[k]`` of the table)."""
        if self.cell is None:
            return self
        cell, positions = self.cell, np.asarray(rows)
        return Labels(self.headers, lambda column, k: cell(column, int(positions[k])))

    def value(self, column: str, value: float) -> str:
        factor = self.headers.get(column, (None, 1.0))[1]
        return f"{value / factor:g}"


def at(value, i):
    """Element i of a per-row array, or the value itself when it is one constant for all rows."""
    return value if np.ndim(value) == 0 else value[i]
