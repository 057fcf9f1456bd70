"""Lazy, cached loading of the coefficient tables in ``tables/``.

Every table is a CSV with a header row, a units row under it (a pint unit,
``1`` for a dimensionless number, ``-`` for a text column) and a ``source`` column naming the source, table
and row it was typed from. The tables ship inside the wheel as the
subpackage ``bearingheat.tables``.
"""
from __future__ import annotations

import csv
import functools
import io
from importlib import resources

import pandas as pd

__all__ = ["load_table", "table_units", "table_names"]


def table_names() -> list[str]:
    """Names (without ``.csv``) of every shipped table."""
    folder = resources.files("bearingheat.tables")
    return sorted(p.name[:-4] for p in folder.iterdir() if p.name.endswith(".csv"))


@functools.lru_cache(maxsize=None)
def _read(name: str) -> tuple[pd.DataFrame, dict[str, str]]:
    path = resources.files("bearingheat.tables").joinpath(f"{name}.csv")
    if not path.is_file():
        raise KeyError(f"no table {name!r}; shipped tables: {', '.join(table_names())}")
    text = path.read_text(encoding="utf-8")
    reader = csv.reader(io.StringIO(text))
    header = next(reader)
    units = next(reader)
    if len(units) != len(header):
        raise ValueError(f"table {name}: the units row has {len(units)} cells for {len(header)} columns")
    if "source" not in header:
        raise ValueError(f"table {name}: no 'source' column")
    body = list(reader)
    frame = pd.DataFrame(body, columns=header)
    numeric = [col for col, unit in zip(header, units) if unit != "-"]
    for col in numeric:
        frame[col] = pd.to_numeric(frame[col].replace("", float("nan")), errors="raise")
    return frame, dict(zip(header, units))


def load_table(name: str) -> pd.DataFrame:
    """A copy of table ``name`` with numeric columns parsed (blank -> NaN)."""
    return _read(name)[0].copy()


def table_units(name: str) -> dict[str, str]:
    """Column -> unit string from the table's units row."""
    return dict(_read(name)[1])
