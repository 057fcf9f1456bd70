"""The Parquet files of a fleet, as ``bearingheat calc FOLDER --dask`` reads them: which files, their columns
in one type each, and the pieces they are computed in.

A fleet is a folder of Parquet files (every ``*.parquet`` in it) or a glob
pattern. Its files must have the same columns (in any order; an index pandas
stored in a file counts as its columns, :func:`bearingheat.io.arrow.without_index`);
a column may differ in type between the files where one type holds every
file's values unchanged (:func:`common_type`). All of it is checked from the
files' footers, before any work. A file is computed in pieces of its row groups
(:data:`PIECE_BYTES`), each read with the fleet's columns in their order and
types (:func:`read_piece`).
"""
from __future__ import annotations

import glob
import json
import os
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as parquet

from bearingheat.errors import InputError
from bearingheat.io.arrow import is_text_type, without_index

__all__ = ["is_dataset", "dataset_files", "fleet_schema", "common_type", "fleet_pieces", "read_piece",
           "PIECE_BYTES"]

#: uncompressed bytes of a Parquet file's row groups computed as one piece (one part of the results): dask's
#: own default block size of read_parquet
PIECE_BYTES = 256 * 2**20


def is_dataset(text: str) -> bool:
    """True when an INPUT names a folder or a glob pattern (``*``, ``?``, ``[``) rather than one file (a file
    that exists is a file, whatever its name holds: ``supports [v2].csv``)."""
    path = Path(text)
    return path.is_dir() or (not path.is_file() and any(mark in text for mark in "*?["))


def dataset_files(text: str) -> list[str]:
    """The Parquet files of a folder (every ``*.parquet`` in it) or of a glob pattern, sorted, or the one file
    ``text`` names when it exists (whatever its name holds: ``supports [v2].parquet`` is no pattern);
    :class:`InputError` when there are none or some matched file is no Parquet file."""
    folder = Path(text)
    if folder.is_file():
        found = [text]
    else:
        found = sorted(str(p) for p in folder.glob("*.parquet")) if folder.is_dir() else sorted(glob.glob(text))
    if not found:
        where = "no *.parquet in the folder" if folder.is_dir() else "the pattern matches nothing"
        raise InputError(f"{text}: no Parquet files ({where})")
    others = [f for f in found if not f.lower().endswith(".parquet") or not os.path.isfile(f)]
    if others:
        raise InputError(f"{others[0]}: --dask reads Parquet files (.parquet) only")
    return found


def fleet_pieces(path: str) -> list[tuple[str, list[int]]]:
    """The pieces a Parquet file is computed in: runs of its row groups of up to :data:`PIECE_BYTES` (one piece
    of no row groups for a file without rows)."""
    try:
        metadata = parquet.ParquetFile(path).metadata
    except (pa.ArrowInvalid, OSError) as exc:
        raise InputError(f"{path}: not a readable .parquet table ({exc})") from exc
    pieces: list[tuple[str, list[int]]] = []
    groups: list[int] = []
    size = 0
    for group in range(metadata.num_row_groups):
        grown = size + metadata.row_group(group).total_byte_size
        if groups and grown > PIECE_BYTES:
            pieces.append((path, groups))
            groups, grown = [], metadata.row_group(group).total_byte_size
        groups.append(group)
        size = grown
    pieces.append((path, groups))
    return pieces


def fleet_schema(files: list[str]) -> pa.Schema:
    """The columns of a fleet's files, in the first file's order, each in one type that holds every file's values
    unchanged (:func:`common_type`); :class:`InputError` naming the file, the column and both types where there is
    none. A column Parquet holds without a type in some file (the null type of a column all blank, or of text
    columns of a file without rows) takes the type the other files give it."""
    schemas = [_file_schema(path) for path in files]
    _check_same_columns(files, schemas)
    fields = []
    for field in schemas[0]:
        kind, origin = field.type, files[0]
        for path, schema in zip(files, schemas):
            other = schema.field(field.name).type
            if pa.types.is_null(other) or other == kind:
                continue
            if pa.types.is_null(kind):
                kind, origin = other, path
                continue
            common = common_type(kind, other)
            if common is None:
                raise InputError(f"{path}: column {field.name!r} holds {_described(other)} where {origin} holds "
                                 f"{_described(kind)}; every file of a fleet needs each column in one type")
            kind = common
        fields.append(field.with_type(kind))
    return pa.schema(fields, metadata=schemas[0].metadata)


def _file_schema(path: str) -> pa.Schema:
    """The columns of a Parquet file as calc reads them (an index pandas stored in it as columns,
    :func:`bearingheat.io.arrow.without_index`), from its footer."""
    try:
        return without_index(parquet.read_schema(path).empty_table()).schema
    except (pa.ArrowInvalid, OSError) as exc:  # as read_arrow_table names a damaged file of the single-file path
        raise InputError(f"{path}: not a readable .parquet table ({exc})") from exc


def _holds(source: pa.DataType, target: pa.DataType) -> bool:
    """True when every value of ``source`` is a value of ``target`` (whole numbers as floats up to 2**53: the
    cast of each piece refuses a larger one)."""
    types = pa.types
    if source == target:
        return True
    if types.is_integer(source):
        if types.is_floating(target) or types.is_decimal(target):
            return True
        if types.is_signed_integer(target):
            return target.bit_width >= source.bit_width + types.is_unsigned_integer(source)
        return types.is_unsigned_integer(target) and types.is_unsigned_integer(source) and \
            target.bit_width >= source.bit_width
    if types.is_floating(source):
        return types.is_floating(target) and target.bit_width >= source.bit_width
    if types.is_decimal(source):
        return types.is_decimal(target)
    if types.is_timestamp(source):
        return types.is_timestamp(target) and source.tz == target.tz
    if types.is_duration(source):
        return types.is_duration(target)
    return False


def common_type(a: pa.DataType, b: pa.DataType) -> pa.DataType | None:
    """The Arrow type that holds the values of the types ``a`` and ``b`` unchanged (whole numbers and decimals as
    numbers, text of any kind as text, times at the finer unit), or None when there is none (numbers and text,
    logical values and numbers, times with and without a time zone ...)."""
    if a == b:
        return a
    if is_text_type(a) and is_text_type(b) and not (pa.types.is_dictionary(a) and pa.types.is_dictionary(b)):
        return pa.large_string()
    try:
        common = pa.unify_schemas([pa.schema([pa.field("x", a)]), pa.schema([pa.field("x", b)])],
                                  promote_options="permissive").field("x").type
    except (pa.ArrowTypeError, pa.ArrowInvalid, pa.ArrowNotImplementedError):
        return None
    if pa.types.is_dictionary(common):
        return common if a.value_type == b.value_type else None
    return common if _holds(a, common) and _holds(b, common) else None


def _described(kind: pa.DataType) -> str:
    """An Arrow type in words, with its name: 'text (large_string)', 'whole numbers (int64)'."""
    types = pa.types
    words = next((word for test, word in (
        (is_text_type, "text"), (types.is_integer, "whole numbers"), (types.is_floating, "numbers"),
        (types.is_decimal, "decimal numbers"), (types.is_boolean, "logical values"), (types.is_timestamp, "times"),
        (types.is_date, "dates"), (types.is_duration, "durations")) if test(kind)), None)
    return f"{words} ({kind})" if words else str(kind)


def _without_pandas_columns(metadata: dict | None, names: set[str]) -> dict | None:
    """Schema metadata without pandas' description of the columns ``names`` (their type was changed: pandas
    would rebuild them in the type the file held)."""
    if not metadata or b"pandas" not in metadata or not names:
        return metadata
    described = json.loads(metadata[b"pandas"])
    described["columns"] = [c for c in described.get("columns", []) if c.get("field_name") not in names]
    return {**metadata, b"pandas": json.dumps(described).encode()}


def read_piece(path: str, groups: list[int], schema: pa.Schema) -> pa.Table:
    """The rows of the row groups ``groups`` of a Parquet file (its columns without rows when there are none),
    with the fleet's columns of ``schema``, in their order and their types (an index pandas stored in the file
    as columns, :func:`bearingheat.io.arrow.without_index`)."""
    try:
        source = parquet.ParquetFile(path)
        if groups:
            offset = sum(source.metadata.row_group(group).num_rows for group in range(groups[0]))
            table = without_index(source.read_row_groups(groups), offset)
        else:
            table = without_index(source.schema_arrow.empty_table())
    except (pa.ArrowInvalid, OSError) as exc:  # (a file damaged or replaced since its footer was read)
        raise InputError(f"{path}: not a readable .parquet table ({exc})") from exc
    table = table.select(schema.names)
    changed = {field.name for field, have in zip(schema, table.schema) if field.type != have.type}
    if not changed:
        return table
    columns = []
    for field in schema:
        column = table.column(field.name)
        if field.name in changed:
            try:
                column = column.cast(field.type)
            except (pa.ArrowInvalid, pa.ArrowNotImplementedError) as exc:
                raise InputError(f"{path}: column {field.name!r}: its {_described(column.type)} cannot all be held as "
                                 f"{_described(field.type)}, the type of the fleet's other files ({exc})") from exc
        columns.append(column)
    fields = [f.with_metadata(table.schema.field(f.name).metadata) for f in schema]
    return pa.Table.from_arrays(columns, schema=pa.schema(fields, metadata=_without_pandas_columns(
        table.schema.metadata, changed)))


def _check_same_columns(files: list[str], schemas: list[pa.Schema]) -> None:
    """Every file of a fleet has the columns of the first (in any order): :class:`InputError` naming the first
    file that differs and how."""
    first = schemas[0].names
    for path, schema in zip(files[1:], schemas[1:]):
        names = schema.names
        if set(names) != set(first):
            lacks = [n for n in first if n not in names]
            extra = [n for n in names if n not in first]
            how = "; ".join(part for part in (f"lacks {', '.join(map(repr, lacks))}" if lacks else "",
                                              f"has {', '.join(map(repr, extra))} besides" if extra else "") if part)
            raise InputError(f"{path}: its columns differ from those of {files[0]} ({how}); every file of a "
                             "fleet needs the same columns")
