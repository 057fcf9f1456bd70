"""``bh.calc`` on a Dask DataFrame: calc on every partition, lazily, with one fixed set of result columns.

calc writes a result column only where a table needs it (``Fa/A`` where a
row carries M2, the heat-balance columns where their inputs are present, the
SKF model's columns where a row uses it). A Dask DataFrame needs the same
columns in every partition, known before any partition is computed, so the
distributed calc writes **every** result column of the column contract
(:mod:`bearingheat.calc.contract`), in contract order after the input
columns, then ``status`` and ``message``: NaN (numbers) or missing (text,
in pandas' own text dtype) where pandas calc would leave the column out. An
empty partition gives an empty frame of those columns. Dask is an optional extra
(``pip install 'bearingheat[dask]'``) and is imported only here.
"""
from __future__ import annotations

from typing import Any, Callable

import numpy as np
import pandas as pd

from bearingheat.calc.contract import CONTRACT, TEXT_DTYPE, output_header
from bearingheat.calc.conversion import results_spelled_otherwise

__all__ = ["is_dask_frame", "result_layout", "calc_partition", "calc_dask"]


def is_dask_frame(table: Any) -> bool:
    """True for a Dask DataFrame (told by its type's module, without importing dask)."""
    return type(table).__module__.split(".")[0] == "dask" and hasattr(table, "map_partitions")


def result_layout(input_columns) -> dict[str, Any]:
    """Header -> dtype of the distributed calc's output: the input columns as they are, every contract result
    (float, or text for the text results), ``status`` and ``message``."""
    layout: dict[str, Any] = {}
    for c in CONTRACT:
        if c.kind == "output" and c.owner != "table":
            layout[output_header(c.name)] = TEXT_DTYPE if c.unit == "" and c.name not in ("f0", "f1") else np.float64
    layout["status"] = TEXT_DTYPE
    layout["message"] = TEXT_DTYPE
    return layout


def calc_partition(part: pd.DataFrame, calc: Callable, layout: dict[str, Any], options: dict) -> pd.DataFrame:
    """``calc`` of one partition, its results reindexed to ``layout`` (after the partition's own columns; an input
    column that is a result headed another way, ``f0 [1]``, in its place under the result's header as calc writes
    it), in one new frame of calc's own arrays (no copy of the partition, no column inserted one by one)."""
    out = calc(part, **options) if len(part) else part
    spelled = results_spelled_otherwise(part.columns, layout)
    columns: dict[str, Any] = {}
    for header in part.columns:
        written = spelled.get(header, header)
        columns[written] = out[written] if written in out.columns else out[header]  # (an empty partition: as is)
    for header, dtype in layout.items():
        if header not in out.columns:  # a column pandas calc leaves out of this partition: NaN or missing text
            columns[header] = pd.Series(np.nan if dtype == np.float64 else None, index=out.index, dtype=dtype)
        else:
            columns[header] = out[header] if out[header].dtype == dtype else out[header].astype(dtype)
    return pd.DataFrame(columns, index=out.index, copy=False)


def calc_dask(table, calc: Callable, **options):
    """A lazy Dask DataFrame of ``calc``'s results (:func:`bearingheat.calc.table.calc`), partition by partition
    (see the module for the columns)."""
    layout = result_layout(table.columns)
    meta = calc_partition(table._meta, calc, layout, options)  # noqa: SLF001 (dask's empty frame of the schema)
    return table.map_partitions(calc_partition, calc, layout, options, meta=meta)
