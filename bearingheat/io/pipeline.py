"""calc on a large table file: read it once, compute a block of rows at a time, keep the results as Arrow.

``bearingheat calc big.csv -o out.parquet`` on 10^6 rows held the input,
calc's working arrays for every row at once and the results as pandas
objects: 1.8 GB at the peak. Here calc runs on blocks of
:data:`ROWS_PER_BLOCK` rows; each block's results become an Arrow table
(numbers as they are, text compactly) and calc's working arrays are freed
before the next block. A progress bar (:class:`bearingheat.io.console.Progress`)
advances block by block.

Every row is computed as in one call of calc on the whole table (calc has no
coupling between rows), so the results are the same. calc writes a result
column only where the table needs it (``Fa/A`` where a row carries M2, the
SKF model's columns where a row uses it), so blocks may differ in their
columns: the results have the union of them, in calc's order, missing where
a block had no such column (as calc leaves them missing for rows that do not
need them).
"""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import pandas as pd
import pyarrow as pa

from bearingheat.calc.contract import CONTRACT, output_header
from bearingheat.calc.distributed import calc_partition
from bearingheat.calc.table import calc
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.catalogue.vm_chart import VMChart
from bearingheat.io.arrow import ARROW_SUFFIXES, arrow_column, read_arrow_table, user_metadata, with_unit
from bearingheat.io.csv_reader import RowLines, read_source
from bearingheat.io.tables import calc_passing_through

__all__ = ["ROWS_PER_BLOCK", "calc_file", "calc_block", "load_options", "ordered_union"]

#: rows calc computes at a time (5*10^4 rows of calc's working arrays take some 75 MB; 10^6 rows in blocks of
#: 25 000 / 50 000 / 100 000 / 200 000 rows peaked at 0.70 / 0.75 / 0.84 / 0.96 GB in the same time)
ROWS_PER_BLOCK = 50_000


def ordered_union(orders: list[list[str]], tie_break: Sequence[str] = ()) -> list[str]:
    """One column order that keeps the order of every block's columns (a topological order of the 'comes
    before' pairs of all blocks); columns no block orders between them go by ``tie_break``, then by first
    appearance.

    >>> ordered_union([["id", "MR", "status"], ["id", "MR", "Fa/A", "status"], ["id", "MR", "M_rr", "status"]])
    ['id', 'MR', 'Fa/A', 'M_rr', 'status']
    """
    first_seen: dict[str, int] = {}
    after: dict[str, set[str]] = {}
    waiting: dict[str, int] = {}
    for order in orders:
        for name in order:
            first_seen.setdefault(name, len(first_seen))
            after.setdefault(name, set())
            waiting.setdefault(name, 0)
        for before, name in zip(order, order[1:]):
            if name not in after[before]:
                after[before].add(name)
                waiting[name] += 1
    rank = {name: i for i, name in enumerate(tie_break)}

    def key(name: str) -> tuple[int, int]:
        return rank.get(name, len(rank)), first_seen[name]

    ready = sorted((name for name, count in waiting.items() if count == 0), key=key)
    union: list[str] = []
    while ready:
        name = ready.pop(0)
        union.append(name)
        for follower in after[name]:
            waiting[follower] -= 1
            if waiting[follower] == 0:
                ready.append(follower)
        ready.sort(key=key)
    return union


def _contract_order() -> list[str]:
    """The result headers in the column contract's order, to place columns no block orders between them."""
    return [output_header(c.name) for c in CONTRACT if c.kind == "output"] + ["status", "message"]


def _concat(blocks: list[pa.Table]) -> pa.Table:
    """The blocks' results as one Arrow table: the union of their columns (:func:`ordered_union`), each of one
    type (a column all missing in a block takes the type of the others), missing where a block lacks it."""
    if len(blocks) == 1:
        return blocks[0]
    names = ordered_union([b.column_names for b in blocks], tie_break=_contract_order())
    fields = {}
    for name in names:
        present = [b.schema.field(name) for b in blocks if name in b.column_names]
        kinds = [f.type for f in present if not pa.types.is_null(f.type)]
        kind = kinds[0] if kinds else pa.null()
        for other in kinds[1:]:
            if other != kind:
                kind = pa.unify_schemas([pa.schema([pa.field(name, kind)]), pa.schema([pa.field(name, other)])],
                                        promote_options="permissive").field(name).type
        fields[name] = pa.field(name, kind, metadata=present[0].metadata)
    schema = pa.schema([fields[n] for n in names], metadata=blocks[0].schema.metadata)
    tables = []
    for block in blocks:
        columns = [block.column(n).cast(fields[n].type) if n in block.column_names
                   else pa.nulls(block.num_rows, fields[n].type) for n in names]
        tables.append(pa.Table.from_arrays(columns, schema=schema))
    return pa.concat_tables(tables)


def load_options(options: dict) -> dict:
    """calc's options with the files it would read on every call read once (the f2 and VM charts, a coefficients
    CSV): the objects, not their paths."""
    options = dict(options)
    if isinstance(options.get("f2_chart"), str):
        options["f2_chart"] = F2Chart.from_csv(options["f2_chart"])
    if isinstance(options.get("vm_chart"), str):
        options["vm_chart"] = VMChart.from_csv(options["vm_chart"])
    if isinstance(options.get("coefficients"), str):
        options["coefficients"] = pd.read_csv(options["coefficients"])
    return options


def _block_table(result: pd.DataFrame, block: pd.DataFrame, source: pa.Table | None) -> pa.Table:
    """One block's results as Arrow: a column calc passed through unchanged is the input's own Arrow column
    (no copy), the others are converted; each field with its unit as metadata, beside the metadata the input's
    field of that name has; the input's schema metadata without pandas' (:func:`user_metadata`)."""
    arrays, fields = [], []
    for name in result.columns:
        values = result[name]
        known = source is not None and name in source.column_names
        same = known and name in block.columns and values.equals(block[name])
        column = source.column(name) if source is not None and same else arrow_column(values)
        arrays.append(column)
        metadata = source.schema.field(name).metadata if source is not None and known else None
        fields.append(with_unit(pa.field(str(name), column.type, metadata=metadata)))
    return pa.Table.from_arrays(arrays, schema=pa.schema(
        fields, metadata=user_metadata(source.schema) if source is not None else None))


def calc_block(block: pd.DataFrame, source: pa.Table | None, options: dict, *, mark: str = ".",
               lines: RowLines | None = None, layout: dict | None = None) -> pa.Table:
    """calc of one block of rows (``block``, read from the Arrow table ``source`` or None) as Arrow.

    Columns calc cannot read the header of are set aside and put back in their places, row messages cite
    ``lines`` (:func:`bearingheat.io.tables.calc_passing_through`); with a ``layout``
    (:func:`bearingheat.calc.distributed.result_layout`) the block gets every column of it, as a partition of the
    Dask path does (an empty block: the input's columns and the layout's, nothing computed).
    """
    if layout is None:
        result = calc_passing_through(block, lines, lambda usable: calc(usable, decimal=mark, **options))
    else:
        result = calc_passing_through(block, lines, lambda usable: calc_partition(usable, calc, layout,
                                                                                  {**options, "decimal": mark}))
    return _block_table(result, block, source)


def _read(path, sep: str | None, decimal: str | None) -> tuple[pa.Table | pd.DataFrame, RowLines | None, str]:
    """The input table (Arrow where pyarrow read it), the file line of each row and the decimal mark (CSV)."""
    if Path(path).suffix.lower() in ARROW_SUFFIXES:
        return read_arrow_table(path), None, "."
    source = read_source(path, sep=sep, decimal=decimal)
    return source.table, source.lines, source.decimal


def calc_file(path, *, sep: str | None = None, decimal: str | None = None, progress=None,
              rows_per_block: int = ROWS_PER_BLOCK, **options) -> pa.Table:
    """:func:`bearingheat.calc.table.calc` on a CSV, Parquet or Arrow/Feather file of supports, a block of rows
    at a time; the results as one Arrow table (the columns of calc's results, units as field metadata).

    Row messages of a CSV cite the file's rows (:func:`bearingheat.io.tables.cite_rows`); columns calc does not
    know pass through. ``progress`` (``start``, ``update``, ``finish``) is advanced block by block; ``options``
    go to calc. A table calc cannot use at all raises its :class:`~bearingheat.errors.InputError`.
    """
    table, lines, mark = _read(path, sep, decimal)
    rows = table.num_rows if isinstance(table, pa.Table) else len(table)
    options = load_options(options)
    blocks = []
    if progress is not None:
        progress.start(rows, "calc")
    for start in range(0, rows, rows_per_block):
        stop = min(start + rows_per_block, rows)
        source: pa.Table | None = None
        if isinstance(table, pa.Table):
            source = table.slice(start, stop - start)
            block = source.to_pandas()
        else:
            block = table.iloc[start:stop]
        blocks.append(calc_block(block, source, options, mark=mark,
                                 lines=lines[start:stop] if lines is not None else None))
        del block
        if progress is not None:
            progress.update(stop)
    if progress is not None:
        progress.finish()
    return _concat(blocks)
