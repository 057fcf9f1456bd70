"""A fleet of supports in Parquet files, computed on a Dask cluster: ``bearingheat calc FOLDER --dask -o OUT``.

The input is a folder of Parquet files (every ``*.parquet`` in it) or a glob
pattern (``'fleet/*.parquet'``), each file with the ``name [unit]`` headers
calc reads. Each file is one piece of work (a big one a run of its row groups
per piece, :data:`PIECE_BYTES`), read and computed on a worker as the
single-file path computes a file (:func:`bearingheat.io.pipeline.calc_block`,
a block of rows at a time), and written as one part of a Parquet dataset: a
folder with one part file per piece. Every part has the same columns, those of
the Dask path (:func:`bearingheat.calc.distributed.result_layout`: every
result column of the contract), in the same types: the input columns as the
files hold them, the results as the single-file path writes them, each
column's unit as field metadata. The cluster is a
:class:`distributed.LocalCluster` of worker processes (one thread each) unless
a scheduler address names an existing ``dask.distributed`` cluster. Dask is an
optional extra (``pip install 'bearingheat[dask]'``) and is imported only
inside the functions here.
"""
from __future__ import annotations

import contextlib
import glob
import json
import os
import re
import shutil
import tempfile
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as parquet

from bearingheat.calc.distributed import result_layout
from bearingheat.errors import InputError
from bearingheat.io.arrow import parquet_writer, without_index
from bearingheat.io.pipeline import ROWS_PER_BLOCK, calc_block, load_options

__all__ = ["dataset_files", "fleet_schema", "common_type", "is_dataset", "check_dataset_target", "calc_dataset", "dask_client", "local_cluster",
           "dataset_columns", "read_dataset_columns", "WORKER_MMAP_THRESHOLD", "PIECE_BYTES"]


def is_dataset(text: str) -> bool:
    """True when an INPUT names a folder or a glob pattern (``*``, ``?``, ``[``) rather than one file (a file
    that exists is a file, whatever its name holds: ``supports [v2].csv``)."""
    path = Path(text)
    return path.is_dir() or (not path.is_file() and any(mark in text for mark in "*?["))


def dataset_files(text: str) -> list[str]:
    """The Parquet files of a folder (every ``*.parquet`` in it) or of a glob pattern, sorted; :class:`InputError`
    when there are none or some matched file is no Parquet file."""
    folder = Path(text)
    found = sorted(str(p) for p in folder.glob("*.parquet")) if folder.is_dir() else sorted(glob.glob(text))
    if not found:
        where = "no *.parquet in the folder" if folder.is_dir() else "the pattern matches nothing"
        raise InputError(f"{text}: no Parquet files ({where})")
    others = [f for f in found if not f.lower().endswith(".parquet") or not os.path.isfile(f)]
    if others:
        raise InputError(f"{others[0]}: --dask reads Parquet files (.parquet) only")
    return found


@contextlib.contextmanager
def dask_client(scheduler: str | None = None, workers: int | None = None):
    """A :class:`distributed.Client` of the cluster at ``scheduler``, or of a new local cluster of ``workers``
    worker processes with one thread each (default: one per CPU core), closed on exit."""
    try:
        from distributed import Client
    except ImportError as exc:
        raise InputError("--dask needs Dask: pip install 'bearingheat[dask]'") from exc
    if scheduler is not None:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise InputError(f"--scheduler {scheduler}: no Dask scheduler answers there ({exc})") from exc
        with client:
            yield client
        return
    with local_cluster(workers) as cluster, Client(cluster) as client:
        yield client


#: glibc's mmap threshold of the workers. dask.distributed starts its workers with MALLOC_TRIM_THRESHOLD_=65536,
#: which also switches off glibc's growing mmap threshold: every array above 128 kB is then mapped and unmapped
#: again, and calc ran half as fast in a worker (measured: 0.47 s against 0.24 s for 25 000 rows). Arrays up to
#: 16 MiB come from the heap again with this (0.25 s); dask's trimming of freed memory stays.
WORKER_MMAP_THRESHOLD = 16 * 2**20

#: uncompressed bytes of a Parquet file's row groups computed as one piece (one part of the results): dask's
#: own default block size of read_parquet
PIECE_BYTES = 256 * 2**20


@contextlib.contextmanager
def local_cluster(workers: int | None = None):
    """A :class:`distributed.LocalCluster` of ``workers`` worker processes (default one per CPU core), one thread
    each, with the workers' allocator set for calc (:data:`WORKER_MMAP_THRESHOLD`); closed on exit."""
    import dask
    from distributed import LocalCluster

    environ = {"distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": WORKER_MMAP_THRESHOLD}
    with dask.config.set(environ), LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                                processes=True, dashboard_address=None) as cluster:
        yield cluster


#: the files of a Parquet dataset Dask writes (its parts and metadata), the only ones --force removes
_DATASET_FILE = re.compile(r"^(part\.\d+\.parquet|_metadata|_common_metadata)$")


def check_dataset_target(target, files: list[str], *, force: bool) -> Path:
    """The folder a dataset of results goes to, checked before any work: not a file name with a table suffix,
    not holding (or above) the input files, empty or (with ``force``) holding only a dataset's own files."""
    target = Path(target)
    if target.suffix.lower() in (".csv", ".parquet", ".arrow", ".feather", ".xlsx", ".xlsm"):
        raise InputError(f"-o {target}: --dask writes a folder of Parquet parts; give a folder name")
    real = target.resolve()
    if any(real == Path(f).resolve().parent or real in Path(f).resolve().parents for f in files):
        raise InputError(f"-o {target} holds the input files; give another folder")
    if target.exists() and not target.is_dir():
        raise InputError(f"-o {target} is a file; give a folder for the Parquet dataset")
    if target.exists() and any(target.iterdir()):
        if not force:
            raise InputError(f"-o {target} exists; give --force to replace it")
        others = sorted(p.name for p in target.iterdir() if not _DATASET_FILE.match(p.name))
        if others:
            raise InputError(f"-o {target} holds {others[0]!r}, which is no part of a Parquet dataset; --force "
                             "replaces only a dataset's own parts: give another folder")
    return target


def clear_dataset(target: Path) -> None:
    """Remove the parts and metadata of an earlier dataset in ``target`` (and nothing else)."""
    for path in target.iterdir():
        if _DATASET_FILE.match(path.name):
            path.unlink()


def _pieces(path: str) -> list[tuple[str, list[int]]]:
    """The pieces a Parquet file is computed in: runs of its row groups of up to :data:`PIECE_BYTES` (one piece
    of no row groups for a file without rows)."""
    metadata = parquet.ParquetFile(path).metadata
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
    return without_index(parquet.read_schema(path).empty_table()).schema


def _text(kind: pa.DataType) -> bool:
    return pa.types.is_string(kind) or pa.types.is_large_string(kind) or (
        pa.types.is_dictionary(kind) and _text(kind.value_type))


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
    if _text(a) and _text(b) and not (pa.types.is_dictionary(a) and pa.types.is_dictionary(b)):
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
        (_text, "text"), (types.is_integer, "whole numbers"), (types.is_floating, "numbers"),
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


def _read_piece(path: str, groups: list[int], schema: pa.Schema) -> pa.Table:
    """The rows of the row groups ``groups`` of a Parquet file (its columns without rows when there are none),
    with the fleet's columns of ``schema``, in their order and their types (an index pandas stored in the file
    as columns, :func:`bearingheat.io.arrow.without_index`)."""
    source = parquet.ParquetFile(path)
    if groups:
        offset = sum(source.metadata.row_group(group).num_rows for group in range(groups[0]))
        table = without_index(source.read_row_groups(groups), offset)
    else:
        table = without_index(source.schema_arrow.empty_table())
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


def _results_schema(source: pa.Table, options: dict, layout: dict) -> pa.Schema:
    """The Arrow schema of every part: what :func:`calc_block` makes of a piece without rows (the input's own
    types, the layout's for the results), each field's unit as metadata."""
    return calc_block(source.to_pandas(), source, options, layout=layout).schema


def _calc_piece(path: str, groups: list[int], columns: pa.Schema, part: str, schema: pa.Schema, layout: dict,
                options: dict) -> int:
    """calc of one piece of a Parquet file, a block of :data:`ROWS_PER_BLOCK` rows at a time as the single-file
    path computes (:func:`bearingheat.io.pipeline.calc_block`), its input ``columns`` those of the fleet
    (:func:`fleet_schema`), written to the part file ``part`` in ``schema``; returns the rows written."""
    table = _read_piece(path, groups, columns)
    with parquet_writer(part, schema) as writer:
        for start in range(0, max(table.num_rows, 1), ROWS_PER_BLOCK):
            source = table.slice(start, ROWS_PER_BLOCK)
            writer.write_table(calc_block(source.to_pandas(), source, options, layout=layout).cast(schema))
    return table.num_rows


def calc_dataset(files: list[str], target, *, overwrite: bool = False, **options) -> Path:
    """calc of every row of the Parquet ``files`` on the current Dask scheduler, written as the Parquet dataset
    folder ``target``; ``options`` go to calc. Returns the folder.

    Each file is computed in pieces of its row groups (one piece per file up to :data:`PIECE_BYTES`), a block of
    rows at a time as the single-file path computes it, and each piece becomes one part file: every column of
    the Dask path's layout (:func:`bearingheat.calc.distributed.result_layout`), the input columns in the types
    the files hold them, the results in the types the single-file path writes.
    """
    import dask

    target = check_dataset_target(target, files, force=overwrite)
    columns = fleet_schema(files)
    options = load_options(options)  # the charts read here, once: a worker need not see the client's files
    layout = result_layout(columns.names)
    schema = _results_schema(columns.empty_table(), options, layout)
    pieces = [piece for path in files for piece in _pieces(path)]
    # written beside the target first: an earlier dataset is replaced only once every part is written
    staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.bearingheat-", suffix=".tmp", dir=target.parent))
    try:
        shared = dask.delayed(options, traverse=False)  # one key: sent to each worker once, not in every task
        tasks = [dask.delayed(_calc_piece, pure=False)(path, groups, columns, str(staging / f"part.{i}.parquet"),
                                                      schema, layout, shared)
                 for i, (path, groups) in enumerate(pieces)]
        dask.compute(*tasks)
        target.mkdir(exist_ok=True)
        clear_dataset(target)
        for part in sorted(staging.iterdir()):
            os.replace(part, target / part.name)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return target


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


def dataset_columns(target) -> list[str]:
    """The column names of a Parquet dataset folder (from its first part)."""
    return parquet.read_schema(min(Path(target).glob("*.parquet"))).names


def read_dataset_columns(target, columns: list[str]) -> pa.Table:
    """The named columns of a Parquet dataset folder, as one Arrow table (the parts in their order)."""
    return parquet.read_table(str(target), columns=columns)
