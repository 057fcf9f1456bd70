"""CSV tables of supports: read one for calc, write its results.

Reading (:mod:`bearingheat.io.csv_reader`): a CSV of supports has one
header row of ``name [unit]`` columns (the column contract,
:mod:`bearingheat.calc.contract`) and one row per support; the separator
(``,``, ``;`` or tab) and the decimal mark are found from the file as a
spreadsheet program saves it, or set by ``sep`` and ``decimal``. Spaces
after the separators are ignored.

Writing (:mod:`bearingheat.io.csv_writer`): the text of pandas'
``to_csv``, built in Arrow arrays. Text the spreadsheet would turn into a
formula (a cell starting with ``=``, ``+``, ``-``, ``@``, tab or carriage
return, the OWASP rule for CSV injection) is written with a leading
apostrophe by :func:`write_csv`; numbers such as ``-3.2`` stay numbers.
Parquet and Arrow/Feather (:mod:`bearingheat.io.arrow`) are the other
formats of :data:`TABLE_WRITERS`.

>>> import io
>>> text = "id;d [mm];n [1/min]\\nspindle rear;40;1500,5\\n"
>>> sniff_format(text)
(';', ',')
>>> escape_formulas(pd.DataFrame({"note": ["=1+1", "-3.2", "ok"], "x": [-1.0, 2.0, 3.0]}))["note"].tolist()
["'=1+1", '-3.2', 'ok']
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd
import pyarrow as pa

from bearingheat.calc.contract import readable_header
from bearingheat.calc.table import calc
from bearingheat.errors import InputError
from bearingheat.io.arrow import ARROW_SUFFIXES, read_arrow, write_arrow
from bearingheat.io.csv_reader import SEPARATORS, RowLines, read_source, read_text, separator, sniff_format
from bearingheat.io.csv_writer import escape_cell, write_csv_text
from bearingheat.io.files import atomic_write

__all__ = ["read_csv", "read_table", "read_text", "write_csv", "sniff_format", "escape_formulas", "escape_cell",
           "calc_csv", "calc_passing_through", "cite_rows", "set_aside", "RowLines", "separator", "SEPARATORS",
           "TABLE_WRITERS", "write_table", "check_table_suffix"]


def _read_frame(path, *, sep: str | None, decimal: str | None, what: str) -> pd.DataFrame:
    """A CSV file as a DataFrame; ``attrs['lines']`` holds the file line number of each row."""
    source = read_source(path, sep=sep, decimal=decimal, what=what)
    table = source.table.to_pandas() if isinstance(source.table, pa.Table) else source.table
    table.attrs["lines"] = source.lines
    table.attrs["source"] = str(path)
    table.attrs["decimal"] = source.decimal
    return table


def read_csv(path, *, sep: str | None = None, decimal: str | None = None) -> pd.DataFrame:
    """The table of a CSV file of supports; :class:`InputError` when it is not a readable CSV (the message
    names the file and the cause).

    The separator and decimal mark are found from the file unless given
    (:func:`sniff_format`); a column named twice is refused by its name;
    columns the contract does not know are read as text and passed through
    untouched. ``attrs['lines']`` holds the file line number of each row
    (the header is line 1), for :func:`cite_rows`; ``attrs['decimal']`` the
    decimal mark (calc's ``decimal``, for numbers left as text).
    """
    return _read_frame(path, sep=sep, decimal=decimal, what="supports")


def read_table(path, sheet: str | None = None, *, sep: str | None = None, decimal: str | None = None
               ) -> pd.DataFrame:
    """A CSV or xlsx file of measurements or readings as a DataFrame (first sheet unless ``sheet``).

    A missing or unreadable file raises :class:`InputError` naming it; a CSV
    is read as :func:`read_csv` reads it. ``attrs['lines']`` holds the row
    number of each row in the file (a CSV's line, a sheet's row; none for
    Parquet and Arrow, which have no rows to cite).
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    if sheet and path.suffix.lower() not in (".xlsx", ".xlsm"):
        raise InputError("--sheet applies to Excel workbooks only")
    if path.suffix.lower() in ARROW_SUFFIXES:
        return read_arrow(path)
    if path.suffix.lower() not in (".xlsx", ".xlsm"):
        return _read_frame(path, sep=sep, decimal=decimal, what="rows")
    try:
        table = pd.read_excel(path, sheet_name=sheet or 0)
    except ValueError as exc:  # a missing sheet, an unreadable cell
        raise InputError(f"{path}: not a readable table ({exc})") from exc
    if len(table) == 0:
        raise InputError(f"{path}: no rows (only a header row)")
    # the sheet's row numbers (header in row 1, blank rows kept as rows), as calc's messages name a workbook's
    # cells ('Sheet1!E3')
    table.attrs["lines"] = RowLines(np.arange(2, len(table) + 2))
    return table


def cite_rows(result: pd.DataFrame, lines: list[int] | RowLines | None) -> pd.DataFrame:
    """Begin each row message with where the row is in the file: ``row 7 (id "spindle rear"): ...``.

    ``lines`` are the file line numbers of the rows (``read_csv(...).attrs['lines']``); rows without a
    message are left as they are. Returns ``result`` (changed in place).
    """
    if lines is None or "message" not in result.columns or len(lines) != len(result):
        return result
    flagged = np.flatnonzero((result["message"].fillna("") != "").to_numpy())  # vectorised: no str accessor per row
    messages = result["message"].to_numpy(dtype=object, copy=True)
    if len(flagged) == 0:  # only the rows with a message are visited
        return result
    ids = result["id"].to_numpy(dtype=object) if "id" in result.columns else None
    for position in flagged:
        who = ids[position] if ids is not None else None
        label = f' (id "{str(who).strip()}")' if isinstance(who, str) and who.strip() else ""
        messages[position] = f"row {lines[position]}{label}: {messages[position]}"
    result["message"] = messages
    return result


def set_aside(table: pd.DataFrame) -> tuple[pd.DataFrame, list[tuple[int, str, pd.Series]]]:
    """Columns whose header calc cannot read (brackets that are no ``name [unit]``), taken out to be put back."""
    extras = [(position, header, table[header]) for position, header in enumerate(table.columns)
              if not readable_header(header)]
    if extras:
        table = table.drop(columns=[header for _, header, _ in extras])
    return table, extras


def calc_csv(path, *, sep: str | None = None, decimal: str | None = None, **options) -> pd.DataFrame:
    """:func:`bearingheat.calc.table.calc` on a CSV file of supports, its row messages citing the file's rows
    (or on a Parquet or Arrow/Feather file, by its suffix).

    Columns the contract does not know are passed through untouched, even
    with brackets that are no unit in their names; ``options`` go to calc.
    """
    if Path(path).suffix.lower() in ARROW_SUFFIXES:  # a binary table: no separators, no file lines to cite
        table, lines, mark = read_arrow(path), None, "."
    else:
        table = read_csv(path, sep=sep, decimal=decimal)
        lines, mark = table.attrs.get("lines"), table.attrs["decimal"]
    return calc_passing_through(table, lines, lambda usable: calc(usable, decimal=mark, **options))


def calc_passing_through(table: pd.DataFrame, lines: list[int] | RowLines | None,
                         compute: Callable[[pd.DataFrame], pd.DataFrame]) -> pd.DataFrame:
    """``compute`` (calc, or calc of a partition) of ``table`` with the columns whose header calc cannot read set
    aside (:func:`set_aside`) and put back in their places, row messages citing ``lines`` (:func:`cite_rows`).

    A column named like a result of calc ('status', 'MR [N*mm]') is refused by calc
    (:func:`bearingheat.calc.conversion.refuse_result_columns`).
    """
    usable, extras = set_aside(table)
    result = compute(usable)
    for position, header, values in extras:
        result.insert(position, header, values.array)
    return cite_rows(result, lines)


def escape_formulas(frame: pd.DataFrame) -> pd.DataFrame:
    """A copy of ``frame`` whose text cells and headers are escaped by :func:`escape_cell` (numbers untouched)."""
    out = frame.copy()
    for column in out.columns:
        if not (pd.api.types.is_numeric_dtype(out[column].dtype) or pd.api.types.is_bool_dtype(out[column].dtype)):
            out[column] = out[column].map(escape_cell)
    out.columns = [escape_cell(c) for c in out.columns]
    return out


def write_csv(result: pd.DataFrame | pa.Table, path, *, escape: bool = True) -> Path:
    """Write calc results (pandas or Arrow) as a CSV (headers ``name [unit]``, no index column), atomically.

    The text is the one of pandas' ``to_csv(index=False)``, built in Arrow
    arrays (:mod:`bearingheat.io.csv_writer`: 10^6 rows of results in about
    4 s where ``to_csv`` took 25 s). Text cells that would be formulas in a
    spreadsheet are escaped (:func:`escape_cell`) unless ``escape=False``.
    The file is replaced atomically
    (:func:`bearingheat.io.files.atomic_write`): a failure leaves the old
    file. Returns the file written (the real file when ``path`` is a
    symbolic link).
    """
    def write(temp):
        with open(temp, "wb") as stream:
            write_csv_text(result, stream, escape=escape)
    return atomic_write(path, write)


#: output suffix -> writer(result, path, escape) of the table formats (workbooks are written by io.excel)
TABLE_WRITERS = {
    ".csv": lambda result, path, escape: write_csv(result, path, escape=escape),
    **{suffix: (lambda result, path, escape: write_arrow(result, path)) for suffix in ARROW_SUFFIXES},
}


def check_table_suffix(path, also: tuple[str, ...] = ()) -> None:
    """Raise :class:`InputError` when ``path`` has no suffix of :data:`TABLE_WRITERS` (or of ``also``)."""
    suffix = Path(path).suffix.lower()
    accepted = (*TABLE_WRITERS, *also)
    if suffix not in accepted:
        raise InputError(f"{path}: cannot write a {suffix or 'file without suffix'}; the output formats are "
                         f"{', '.join(accepted)}")


def write_table(result: pd.DataFrame, path, *, escape: bool = True) -> Path:
    """Write a results table in the format of the suffix of ``path`` (:data:`TABLE_WRITERS`), atomically.

    ``escape`` applies to CSV (:func:`write_csv`); Parquet and Arrow hold text as text.
    """
    check_table_suffix(path)
    return TABLE_WRITERS[Path(path).suffix.lower()](result, path, escape)
