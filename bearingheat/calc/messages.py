"""Row messages of a calculation: which rows fail a check, and how a message names a column and a value."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Callable, Iterable

import numpy as np
import pandas as pd

from bearingheat.calc.contract import input_units

__all__ = ["Problem", "Labels", "at", "STATUS_LEVELS", "OK", "WARNING", "ERROR", "status_column", "status_codes",
           "with_texts", "row_status", "bearing_load"]

#: a message that begins with a column's name (and its unit): 'T [mm]: ...', 'lubrication: ...'
_LEADING_COLUMN = re.compile(r"^(\w+)(?: \[[^\]]*\])?:")
#: a row's status in calc's ``status`` column, by its code (the order of severity)
STATUS_LEVELS = ("ok", "warning", "error")
OK, WARNING, ERROR = range(3)


@dataclass
class Problem:
    """Rows that fail one check, and how to word it for row i (``column``: the input a 'missing' check names)."""

    mask: np.ndarray
    level: str  # 'error' or 'warning'
    message: Callable[[int], str]
    column: str = ""


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

    def cite(self, message: str, row: int) -> str:
        """``message`` with the cell of ``row`` before it where it begins with an input column (``'lubrication:
        ...'``, ``'T [mm]: ...'``) and names no cell yet: ``'Supports!I7 lubrication: ...'``; as it is without
        cells (a CSV) or for any other beginning.

        >>> Labels(cell=lambda column, row: f"Supports!X{row + 3}").cite("lubrication: missing", 4)
        'Supports!X7 lubrication: missing'
        >>> Labels().cite("lubrication: missing", 4), Labels(cell=str).cite("n_thr: no oil-bath f0", 4)
        ('lubrication: missing', 'n_thr: no oil-bath f0')
        """
        if self.cell is None:
            return message
        found = _LEADING_COLUMN.match(message)
        if found is None or found.group(1) not in input_units():
            return message
        return f"{self.cell(found.group(1), row)} {message}"

    def value(self, column: str, value: float) -> str:
        factor = self.headers.get(column, (None, 1.0))[1]
        return f"{value / factor:g}"


def at(value, i):
    """Element i of a per-row array, or the value itself when it is one constant for all rows."""
    return value if np.ndim(value) == 0 else value[i]


def bearing_load(labels: Labels, row: int, Fr: float, Fa: float, bearings: float) -> tuple[str, str]:
    """(the column, the words) a minimum-load warning names a row's load by: Fa where it exceeds each bearing's
    share of Fr (``bearings``: 2 for a pair), else Fr with that share, 'Fr [kN]: 0.28 (0.14 on each bearing of the
    pair)'. A blank Fr (NaN) is named as 0."""
    Fr = 0.0 if math.isnan(Fr) else Fr  # (math: np.isnan of one number costs a microsecond)
    if Fa > Fr / bearings:
        return "Fa", f"{labels.name('Fa', row)}: {labels.value('Fa', Fa)}"
    each = f" ({labels.value('Fr', Fr / bearings)} on each bearing of the pair)" if bearings > 1 else ""
    return "Fr", f"{labels.name('Fr', row)}: {labels.value('Fr', Fr)}{each}"


def status_column(codes: np.ndarray) -> pd.Categorical:
    """The status of every row (codes OK, WARNING, ERROR) as the categorical calc keeps until it writes its
    result: a comparison reads one byte a row, not a Python string."""
    return pd.Categorical.from_codes(np.asarray(codes, dtype=np.int8), categories=pd.Index(STATUS_LEVELS))


def status_codes(column: pd.Series) -> np.ndarray:
    """OK, WARNING or ERROR of every row of a status column (:func:`status_column`, or text)."""
    if isinstance(column.dtype, pd.CategoricalDtype) and tuple(column.cat.categories) == STATUS_LEVELS:
        return column.cat.codes.to_numpy()
    cells = column.to_numpy(dtype=object)
    return np.select([cells == STATUS_LEVELS[ERROR], cells == STATUS_LEVELS[WARNING]], [ERROR, WARNING],
                     OK).astype(np.int8)


def with_texts(column: pd.Series | pd.Categorical, rows: Iterable[int], texts: Iterable[str]) -> pd.Categorical:
    """A text column (categorical, or cells) as a categorical, with the cells at positions ``rows`` replaced by
    ``texts``; the other rows keep their codes (no Python object per row; the new texts are hashed once)."""
    cells = column.array if isinstance(column, pd.Series) else column
    cells = cells if isinstance(cells, pd.Categorical) else pd.Categorical(np.asarray(cells, dtype=object))
    rows = np.fromiter(rows, dtype=np.intp)
    new_codes, new_texts = pd.factorize(np.fromiter(texts, dtype=object, count=len(rows)), use_na_sentinel=False)
    code_of = {text: k for k, text in enumerate(cells.categories)}  # a text the column has keeps its category
    known = np.fromiter((code_of.get(text, -1) for text in new_texts), dtype=np.intp, count=len(new_texts))
    unknown = known < 0
    categories = cells.categories.append(pd.Index(new_texts[unknown], dtype=object))
    known[unknown] = len(cells.categories) + np.arange(np.count_nonzero(unknown))
    codes = cells.codes.astype(np.int32)
    codes[rows] = known[new_codes]
    return pd.Categorical.from_codes(codes, categories=categories)


def row_status(size: int, warnings_by_row: dict[int, list[str]], errors_by_row: dict[int, list[str]],
               silent: Iterable[int] = ()) -> tuple[pd.Categorical, pd.Categorical]:
    """(status, message) of ``size`` rows from the messages of the rows that have some: a row with errors is
    'error' and shows only them, a row with warnings 'warning'; the messages of a row are joined by '; '. The
    ``silent`` rows are errors whose message is told elsewhere: 'error', with their other errors only."""
    codes = np.zeros(size, dtype=np.int8)
    texts: dict[int, str] = {}
    for i in silent:
        codes[i], texts[i] = ERROR, ""
    for level, by_row in ((WARNING, warnings_by_row), (ERROR, errors_by_row)):  # an error replaces the warnings
        for i, found in by_row.items():
            if found and codes[i] <= level:
                codes[i], texts[i] = level, "; ".join(found)
    empty = pd.Categorical.from_codes(np.zeros(size, dtype=np.int8), categories=pd.Index([""], dtype=object))
    return status_column(codes), with_texts(empty, texts.keys(), texts.values())
