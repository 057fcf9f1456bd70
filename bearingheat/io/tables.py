"""CSV tables of supports: read one for calc, write its results.

A CSV of supports has one header row of ``name [unit]`` columns (the column
contract, :mod:`bearingheat.calc.contract`) and one row per support. Spaces
after the commas are ignored.
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd

from bearingheat.errors import InputError

__all__ = ["read_csv", "write_csv"]


def read_csv(path) -> pd.DataFrame:
    """The table of a CSV file; :class:`InputError` when it is not a readable CSV (the message names the file)."""
    path = Path(path)
    try:
        return pd.read_csv(path, skipinitialspace=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise InputError(f"{path}: not a readable CSV ({exc})") from exc


def write_csv(result: pd.DataFrame, path) -> Path:
    """Write calc results as a CSV (headers ``name [unit]``, no index column)."""
    path = Path(path)
    result.to_csv(path, index=False)
    return path
