"""Parquet and Arrow (Feather) tables of supports, read and written with pyarrow.

The columns keep their ``name [unit]`` headers, so a table round-trips
through any of the formats unchanged. A Parquet or Arrow file also carries
each column's unit as field metadata (key ``unit``; '' for text and
dimensionless numbers), so tools that read the schema see the units
without parsing headers. Files are written atomically
(:func:`bearingheat.io.files.atomic_write`).

>>> import tempfile, pathlib
>>> frame = pd.DataFrame({"id": ["a"], "Fr [kN]": [2.5]})
>>> path = pathlib.Path(tempfile.mkdtemp()) / "t.parquet"
>>> _ = write_arrow(frame, path)
>>> read_arrow(path).equals(frame), column_units(path)
(True, {'id': '', 'Fr [kN]': 'kN'})
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd
import pyarrow as pa
import pyarrow.feather as feather
import pyarrow.parquet as parquet

from bearingheat.calc.contract import parse_header
from bearingheat.errors import InputError
from bearingheat.io.files import atomic_write

__all__ = ["ARROW_SUFFIXES", "read_arrow", "write_arrow", "column_units"]

#: suffix -> (read a pyarrow table from a path, write one to a path)
_FORMATS = {
    ".parquet": (parquet.read_table, lambda table, path: parquet.write_table(table, path)),
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


def _unit_of(header: str) -> str:
    try:
        unit = parse_header(header)[1]
    except InputError:
        return ""
    return unit or ""


def read_arrow(path) -> pd.DataFrame:
    """The table of a Parquet or Arrow/Feather file as a DataFrame (text as pandas strings, blanks as NaN)."""
    path = Path(path)
    read, _ = _format(path)
    try:
        table = read(path)
    except (pa.ArrowInvalid, OSError) as exc:
        raise InputError(f"{path}: not a readable {path.suffix} table ({exc})") from exc
    frame = table.to_pandas()
    if len(frame) == 0:
        raise InputError(f"{path}: no rows")
    return frame


def write_arrow(frame: pd.DataFrame, path) -> Path:
    """Write ``frame`` as Parquet or Arrow/Feather (by the suffix), with each column's unit as field metadata."""
    path = Path(path)
    _, write = _format(path)
    try:
        table = pa.Table.from_pandas(frame, preserve_index=False)
    except (pa.ArrowInvalid, pa.ArrowTypeError) as exc:
        raise InputError(f"{path}: the table cannot be written as {path.suffix} ({exc})") from exc
    fields = [table.schema.field(i).with_metadata({"unit": _unit_of(str(name))})
              for i, name in enumerate(table.column_names)]
    table = table.cast(pa.schema(fields, metadata=table.schema.metadata))
    return atomic_write(path, lambda temp: write(table, temp))


def column_units(path) -> dict[str, str]:
    """Column -> unit of a file written by :func:`write_arrow` (from its field metadata)."""
    path = Path(path)
    schema = parquet.read_schema(path) if path.suffix.lower() == ".parquet" else feather.read_table(path).schema
    return {f.name: (f.metadata or {}).get(b"unit", b"").decode() for f in schema}
