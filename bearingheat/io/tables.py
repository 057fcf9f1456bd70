"""CSV tables of supports: read one for calc, write its results.

A CSV of supports has one header row of ``name [unit]`` columns (the column
contract, :mod:`bearingheat.calc.contract`) and one row per support. Spaces
after the commas are ignored.
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd

from bearingheat.errors import InputError

__all__ = ["read_csv", "read_table", "write_csv"]


def read_csv(path) -> pd.DataFrame:
    """The table of a CSV file; :class:`InputError` when it is not a readable CSV (the message names the file)."""
    path = Path(path)
    try:
        return pd.read_csv(path, skipinitialspace=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise InputError(f"{path}: not a readable CSV ({exc})") from exc


def read_table(path, sheet: str | None = None) -> pd.DataFrame:
    """A CSV or xlsx file of measurements or readings as a DataFrame (first sheet unless ``sheet``).

    A missing or unreadable file raises :class:`InputError` naming it.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    if sheet and path.suffix.lower() not in (".xlsx", ".xlsm"):
        raise InputError("--sheet applies to Excel workbooks only")
    try:
        if path.suffix.lower() in (".xlsx", ".xlsm"):
            return pd.read_excel(path, sheet_name=sheet or 0)
        return pd.read_csv(path, skipinitialspace=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError, ValueError) as exc:
        raise InputError(f"{path}: not a readable table ({exc})") from exc


def write_csv(result: pd.DataFrame, path) -> Path:
    """Write calc results as a CSV (headers ``name [unit]``, no index column)."""
    path = Path(path)
    result.to_csv(path, index=False)
    return path
