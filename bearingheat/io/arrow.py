"""Parquet and Arrow (Feather) tables of supports, read and written with pyarrow.

The columns keep their ``name [unit]`` headers, so a table's columns
round-trip through any of the formats unchanged, values and dtypes (a pandas
frame is written with pandas' description of its columns: nullable numbers,
logical values, categories and times come back as they were). The index is
not written, as ``to_csv(index=False)`` does not write it; an index pandas
stored in a file it wrote comes back as columns (:func:`without_index`). A Parquet or Arrow file also carries
each column's unit as field metadata (key ``unit``; '' for text and
dimensionless numbers), so tools that read the schema see the units
without parsing headers; the metadata a file had of its own (a field's
``description``, the schema's ``source`` ...) is kept beside it. Files are written atomically
(:func:`bearingheat.io.files.atomic_write`).

>>> import tempfile, pathlib
>>> frame = pd.DataFrame({"id": ["a"], "Fr [kN]": [2.5]})
>>> path = pathlib.Path(tempfile.mkdtemp()) / "t.parquet"
>>> _ = write_arrow(frame, path)
>>> read_arrow(path).equals(frame), column_units(path)
(True, {'id': '', 'Fr [kN]': 'kN'})
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.feather as feather
import pyarrow.parquet as parquet

from bearingheat.calc.contract import parse_header
from bearingheat.errors import InputError
from bearingheat.io.csv_reader import refuse_duplicate_columns
from bearingheat.io.files import atomic_write

__all__ = ["ARROW_SUFFIXES", "read_arrow", "read_arrow_table", "write_arrow", "arrow_table", "arrow_column",
           "column_units", "unit_of", "parquet_writer", "without_index", "with_unit", "user_metadata",
           "is_text_type"]


def is_text_type(kind: pa.DataType) -> bool:
    """True for an Arrow type of text: string, large_string, or a dictionary of them (a pandas category of text,
    a Parquet column read with its dictionary)."""
    return pa.types.is_string(kind) or pa.types.is_large_string(kind) or (
        pa.types.is_dictionary(kind) and is_text_type(kind.value_type))


def _text_fields(schema: pa.Schema) -> list[str]:
    return [field.name for field in schema if is_text_type(field.type)]


def _write_parquet(table: pa.Table, path) -> None:
    """Parquet with dictionary encoding for the text columns only: their cells repeat (designations, status),
    the numbers seldom do, and trying a dictionary on each number column first took a third of the write
    (10^6 rows x 36 columns: 0.42 s against 0.63 s, 91 MB against 89 MB)."""
    parquet.write_table(table, path, use_dictionary=_text_fields(table.schema))


def parquet_writer(path, schema: pa.Schema) -> parquet.ParquetWriter:
    """A Parquet writer of tables of ``schema`` to ``path``, encoded as :func:`write_arrow` encodes (dictionaries
    for the text columns only); a table written is a row group."""
    return parquet.ParquetWriter(path, schema, use_dictionary=_text_fields(schema))


#: suffix -> (read a pyarrow table from a path, write one to a path)
_FORMATS = {
    ".parquet": (parquet.read_table, _write_parquet),
    ".arrow": (feather.read_table, lambda table, path: feather.write_feather(table, path)),
    ".feather": (feather.read_table, lambda table, path: feather.write_feather(table, path)),
}
#: the suffixes this module reads and writes
ARROW_SUFFIXES = tuple(_FORMATS)


def _format(path: Path):
    try:
        return _FORMATS[path.suffix.lower()]
    except KeyError:
        raise InputError(f"{path}: {path.suffix or 'no suffix'} is not one of {', '.join(ARROW_SUFFIXES)}") from None


def unit_of(header: str) -> str:
    """The unit of a ``name [unit]`` header ('' for text, dimensionless columns and headers calc cannot read)."""
    try:
        unit = parse_header(header)[1]
    except InputError:
        return ""
    return unit or ""


def without_index(table: pa.Table, offset: int = 0) -> pa.Table:
    """``table`` with the index pandas stored in it (``to_parquet`` keeps a frame's index) made plain columns:
    a named index (``df.set_index('id')``) comes back as columns, first, as ``reset_index()`` puts them; an
    unnamed one (the row labels pandas keeps, which ``to_csv(index=False)`` leaves out) is dropped. pandas'
    description of the columns is kept (their dtypes), without the index. ``offset`` is the position of the
    table's first row in its file (a named index of row numbers is stored as its start and step only)."""
    described = table.schema.pandas_metadata
    if not described or not described.get("index_columns"):
        return table
    entries = {entry.get("field_name"): entry for entry in described.get("columns", [])}
    stored = [c for c in described["index_columns"] if isinstance(c, str) and c in table.column_names]
    named = [c for c in stored if entries.get(c, {}).get("name") is not None]
    ranges = [r for r in described["index_columns"] if isinstance(r, dict) and r.get("kind") == "range"
              and r.get("name") is not None and str(r["name"]) not in table.column_names]
    columns = [table.column(c) for c in named]
    names = list(named)
    for index in ranges:  # a named range of row numbers: its values, from the table's place in the file
        first = index["start"] + offset * index["step"]
        columns.append(pa.array(np.arange(first, first + table.num_rows * index["step"], index["step"],
                                          dtype=np.int64)))  # (numpy's arange: no Python int per row)
        names.append(str(index["name"]))
    others = [c for c in table.column_names if c not in stored]
    described = {**described, "index_columns": [],
                 "columns": [e for e in described.get("columns", []) if e.get("field_name") in names + others]}
    fields = [pa.field(n, c.type) for n, c in zip(names[len(named):], columns[len(named):])]
    schema = pa.schema([*(table.schema.field(c) for c in named), *fields, *(table.schema.field(c) for c in others)],
                       metadata={**(table.schema.metadata or {}), b"pandas": json.dumps(described).encode()})
    return pa.Table.from_arrays([*columns, *(table.column(c) for c in others)], schema=schema)


def read_arrow_table(path) -> pa.Table:
    """The table of a Parquet or Arrow/Feather file as Arrow (an index pandas stored in it as columns,
    :func:`without_index`); :class:`InputError` for a damaged or empty one."""
    path = Path(path)
    read, _ = _format(path)
    try:
        refuse_duplicate_columns(path, _column_names(path))  # (read would fail on them without saying so)
        table = read(path)
    except (pa.ArrowInvalid, OSError) as exc:
        raise InputError(f"{path}: not a readable {path.suffix} table ({exc})") from exc
    if table.num_rows == 0:
        raise InputError(f"{path}: no rows")
    return without_index(table)


def _column_names(path: Path) -> list[str]:
    """The column names of a Parquet or Arrow/Feather file, from its schema (the table is not read)."""
    if path.suffix.lower() == ".parquet":
        return parquet.read_schema(path).names
    try:
        with pa.memory_map(str(path)) as source:
            return pa.ipc.open_file(source).schema.names
    except pa.ArrowInvalid:  # a Feather version 1 file: no IPC schema (the read below reads it)
        return []


def read_arrow(path) -> pd.DataFrame:
    """The table of a Parquet or Arrow/Feather file as a DataFrame (text as pandas strings, blanks as NaN)."""
    return read_arrow_table(path).to_pandas()


def arrow_column(values: pd.Series) -> pa.Array:
    """One pandas column as Arrow; a column of mixed cells (numbers and text from a workbook) as text, each cell
    as pandas' CSV writer would write it (``str(cell)``), missing cells missing."""
    try:
        return pa.array(values, from_pandas=True)
    except (pa.ArrowInvalid, pa.ArrowTypeError):
        cells = values.to_numpy(dtype=object)
        missing = pd.isna(values).to_numpy()
        return pa.array([None if gone else str(cell) for cell, gone in zip(cells, missing)], type=pa.string())


def _pandas_metadata(frame: pd.DataFrame) -> dict:
    """pandas' description of ``frame``'s columns (their dtypes: Int64, boolean, category, a time zone ...) as
    Arrow schema metadata, without the index, so that ``to_pandas`` rebuilds the same dtypes; taken from the
    frame without rows (a column of mixed cells, written as text, is then described as text)."""
    try:
        return pa.Schema.from_pandas(frame.iloc[:0], preserve_index=False).metadata or {}
    except (pa.ArrowInvalid, pa.ArrowTypeError, pa.ArrowNotImplementedError, ValueError, TypeError):
        return {}


def arrow_table(frame: pd.DataFrame | pa.Table) -> pa.Table:
    """``frame`` as an Arrow table (no index column), each field with its unit as metadata (key ``unit``); a
    pandas frame also with pandas' description of its columns, so that :func:`read_arrow` gives their dtypes
    back."""
    if isinstance(frame, pa.Table):
        table = frame
    else:
        headers = [str(h) for h in frame.columns]
        table = pa.Table.from_arrays([arrow_column(frame.iloc[:, i]) for i in range(frame.shape[1])], names=headers)
        table = table.replace_schema_metadata(_pandas_metadata(frame))
    fields = [with_unit(table.schema.field(i)) for i in range(table.num_columns)]
    return table.cast(pa.schema(fields, metadata=table.schema.metadata))


def with_unit(field: pa.Field) -> pa.Field:
    """``field`` with its unit as metadata (key ``unit``), beside the metadata it has (a user's ``description``
    ...)."""
    return field.with_metadata({**(field.metadata or {}), b"unit": unit_of(field.name).encode()})


def user_metadata(schema: pa.Schema) -> dict | None:
    """A table's schema metadata that also describes a table of other columns made from it (calc's results):
    the user's keys (``source``, ``description`` ...), without pandas' description of the input frame."""
    if not schema.metadata:
        return None
    return {key: value for key, value in schema.metadata.items() if key != b"pandas"} or None


def write_arrow(frame: pd.DataFrame | pa.Table, path) -> Path:
    """Write ``frame`` (pandas or Arrow) as Parquet or Arrow/Feather (by the suffix), with each column's unit as
    field metadata."""
    path = Path(path)
    _, write = _format(path)
    try:
        table = arrow_table(frame)
    except (pa.ArrowInvalid, pa.ArrowTypeError) as exc:
        raise InputError(f"{path}: the table cannot be written as {path.suffix} ({exc})") from exc
    return atomic_write(path, lambda temp: write(table, temp))


def column_units(path) -> dict[str, str]:
    """Column -> unit of a file written by :func:`write_arrow` (from its field metadata)."""
    path = Path(path)
    schema = parquet.read_schema(path) if path.suffix.lower() == ".parquet" else feather.read_table(path).schema
    return {f.name: (f.metadata or {}).get(b"unit", b"").decode() for f in schema}
