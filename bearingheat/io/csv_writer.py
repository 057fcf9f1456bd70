"""CSV text of a results table, built column by column in Arrow arrays.

pandas' ``DataFrame.to_csv`` formats every number in Python: 25 s for
10^6 rows of calc results on the 2-core build machine. pyarrow's own CSV
writer takes 2 s but quotes every text cell and writes 40.0 as ``40``.
This module writes the text pandas wrote, in about the time of pyarrow's
writer: each column is turned into text with pyarrow's compute functions,
the columns are joined into lines and the lines' bytes are written as one
buffer, a block of rows at a time.

The text is the one of ``to_csv(index=False)``: numbers in their shortest
form that reads back to the same value, a float with a whole value with
``.0`` (``40.0``), missing cells empty, ``True``/``False``, and quotes only
around the text that needs them (a comma, a quote or a line break; quotes
inside doubled), as Python's csv module does; times, dates and durations in
pandas' own forms (``2024-01-01``, ``2024-01-01 00:00:00+01:00``,
``0 days 01:00:00``: those few columns are written by ``to_csv`` itself). One difference: floats below
1e-4 may be written as ``0.00001`` where Python writes ``1e-05`` (the same
number).

Text a spreadsheet would run as a formula (a cell starting with ``=``,
``+``, ``-``, ``@``, tab or carriage return, the OWASP rule for CSV
injection) gets a leading apostrophe (:func:`escape_cell`); numbers such as
``-3.2`` stay numbers.

>>> import io
>>> frame = pd.DataFrame({"id": ["a", "b, c", "=1+1"], "x [mm]": [40.0, 0.1, float("nan")], "n": [1, 2, 3]})
>>> out = io.BytesIO()
>>> write_csv_text(frame, out)
>>> print(out.getvalue().decode())
id,x [mm],n
a,40.0,1
"b, c",0.1,2
'=1+1,,3
<BLANKLINE>
"""
from __future__ import annotations

import re
from typing import BinaryIO

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc

from bearingheat.io.arrow import arrow_table

__all__ = ["escape_cell", "escape_text", "write_csv_text", "FORMULA_START", "ROWS_PER_BLOCK"]

#: a text cell starting with one of these is run as a formula by a spreadsheet (OWASP, CSV injection)
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_NUMBER = re.compile(r"^\s*[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\s*$")
#: a cell with one of these is quoted (the separator is ',')
_NEEDS_QUOTES = r'[,"\r\n]'
#: rows turned into text at a time (bounds the memory of the text to a few tens of MB)
ROWS_PER_BLOCK = 100_000


def escape_cell(value):
    """``value`` with a leading apostrophe when it is text a spreadsheet would read as a formula."""
    if isinstance(value, str) and value.startswith(FORMULA_START) and not _NUMBER.match(value):
        return "'" + value
    return value


def escape_text(text: pa.Array) -> pa.Array:
    """An Arrow text array with :func:`escape_cell` applied; only the cells that start as a formula would (a
    few, usually) are looked at in Python."""
    starts = None
    for lead in FORMULA_START:
        hit = pc.starts_with(text, lead)
        starts = hit if starts is None else pc.or_(starts, hit)
    positions = np.flatnonzero(pc.fill_null(starts, False).to_numpy(zero_copy_only=False))
    if len(positions) == 0:
        return text
    cells = pc.take(text, pa.array(positions)).to_pylist()
    escaped = [escape_cell(cell) for cell in cells]
    changed = [i for i, (old, new) in enumerate(zip(cells, escaped)) if old != new]
    if not changed:
        return text
    mask = np.zeros(len(text), dtype=bool)
    mask[positions[changed]] = True
    return pc.replace_with_mask(text, pa.array(mask), pa.array([escaped[i] for i in changed], type=text.type))


def _quoted(text: pa.Array) -> pa.Array:
    """Text cells as csv.QUOTE_MINIMAL writes them: in quotes (inner quotes doubled) where they need them."""
    needs = pc.fill_null(pc.match_substring_regex(text, _NEEDS_QUOTES), False)
    if not pc.any(needs).as_py():
        return text
    wrapped = pc.binary_join_element_wise('"', pc.replace_substring(text, '"', '""'), '"', "")
    return pc.if_else(needs, wrapped, text)


def _float_text(values: pa.Array) -> pa.Array:
    """Floats as Python's repr writes them: the shortest form that reads back to the same value, a whole value
    with '.0'. pyarrow writes the same digits; outside 1e-4 <= |x| < 1e10 it chooses between fixed and
    exponent notation otherwise, so those (few) cells are written by Python."""
    numbers = values.to_numpy(zero_copy_only=False)  # missing cells are NaN here
    values = pc.if_else(pc.is_nan(values), pa.scalar(None, values.type), values)  # NaN is written empty
    text = pc.cast(values, pa.string())
    size = np.abs(numbers)
    with np.errstate(invalid="ignore"):
        whole = np.isfinite(size) & (np.floor(size) == size) & (size < 1e10)  # pyarrow writes 40.0 as '40'
        other = np.isfinite(size) & (size != 0) & ((size < 1e-4) | (size >= 1e10))
    if whole.any():
        text = pc.if_else(pa.array(whole), pc.binary_join_element_wise(text, ".0", ""), text)
    if other.any():
        python = [repr(float(x)) for x in numbers[other]]
        text = pc.replace_with_mask(text, pa.array(other), pa.array(python, type=pa.string()))
    return text


def _temporal(kind: pa.DataType) -> bool:
    """Times, dates, times of day and durations: pandas writes them in forms of its own."""
    types = pa.types
    return types.is_timestamp(kind) or types.is_date(kind) or types.is_time(kind) or types.is_duration(kind)


def _pandas_text(values: pa.Array) -> pa.Array:
    """Cells of times, dates and durations as ``to_csv`` writes them, by ``to_csv`` itself: a column of dates
    '2024-01-01' (times only where some value has one, to the finest fraction of a second used), times with a time
    zone '2024-01-01 00:00:00+01:00', durations '0 days 01:00:00' ('1 days' in a column of whole days), missing
    cells empty. Such columns are few, and none holds a separator or a quote."""
    frame = pd.DataFrame({"cell": values.to_pandas(), "end": np.zeros(len(values), dtype=np.int8)})
    text = frame.to_csv(index=False, header=False, sep="\x1f", lineterminator="\n")
    return pa.array([line[:-2] for line in text.split("\n")[:-1]], pa.string())


def _cell_text(values: pa.Array, escape: bool) -> pa.Array:
    """One column of a block as CSV cells: text, missing cells empty."""
    kind = values.type
    if pa.types.is_dictionary(kind):
        values, kind = values.cast(kind.value_type), kind.value_type
    if pa.types.is_floating(kind):
        text = _float_text(values)
    elif pa.types.is_boolean(kind):
        text = pc.if_else(values, "True", "False")
    elif pa.types.is_string(kind) or pa.types.is_large_string(kind):
        values = values.cast(pa.string())  # one text type for the joins (a block is far below 2 GB)
        text = _quoted(escape_text(values) if escape else values)
    elif pa.types.is_null(kind):
        text = pa.nulls(len(values), pa.string())
    elif _temporal(kind):
        text = _pandas_text(values)
    else:
        try:
            text = pc.cast(values, pa.string())
        except (pa.ArrowInvalid, pa.ArrowNotImplementedError):
            text = pa.array([None if cell is None else str(cell) for cell in values.to_pylist()], pa.string())
        text = _quoted(text)
    return pc.fill_null(text.cast(pa.string()), "")


def _header_line(names: list[str], escape: bool) -> bytes:
    cells = []
    for name in names:
        name = escape_cell(name) if escape else name
        cells.append(f'"{name.replace(chr(34), chr(34) * 2)}"' if re.search(_NEEDS_QUOTES, name) else name)
    return (",".join(cells) + "\n").encode("utf-8")


def _block_bytes(columns: list[pa.Array], escape: bool) -> pa.Buffer:
    """The lines of one block of rows: the cells joined by ',' and each line ended by a line break."""
    cells = [_cell_text(values, escape) for values in columns]
    if len(cells) == 1:  # a lone empty cell is written "" (a blank line would be skipped when read)
        cells[0] = pc.if_else(pc.equal(cells[0], ""), '""', cells[0])
    cells[-1] = pc.binary_join_element_wise(cells[-1], "\n", "")
    lines = pc.binary_join_element_wise(*cells, ",") if len(cells) > 1 else cells[0]
    width = np.int64 if pa.types.is_large_string(lines.type) else np.int32
    offsets = np.frombuffer(lines.buffers()[1], dtype=width)[lines.offset:lines.offset + len(lines) + 1]
    return lines.buffers()[2].slice(int(offsets[0]), int(offsets[-1] - offsets[0]))


def write_csv_text(table: pd.DataFrame | pa.Table, stream: BinaryIO, *, escape: bool = True) -> None:
    """Write ``table`` (pandas without its index, or Arrow) as CSV text to a binary stream, a block of
    :data:`ROWS_PER_BLOCK` rows at a time; ``escape`` applies :func:`escape_cell` to text cells and headers."""
    if isinstance(table, pd.DataFrame):
        table = arrow_table(table)
    stream.write(_header_line([str(n) for n in table.column_names], escape))
    if table.num_columns == 0:
        return
    for start in range(0, table.num_rows, ROWS_PER_BLOCK):
        block = table.slice(start, ROWS_PER_BLOCK)
        stream.write(_block_bytes([column.combine_chunks() for column in block.columns], escape))
