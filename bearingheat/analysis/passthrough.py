"""The columns a measured-data command does not read, kept where it writes the rows back, as calc keeps them.

calc passes every column it does not read through to its output, a header that is no ``name [unit]``
('remark [see note]]') included (:func:`bearingheat.calc.contract.readable_header`). ``lab`` writes its readings
back (readings.csv) and the reference speed audit its bearings (reference_speeds.csv): each keeps the user's other
columns after its own, as typed.
"""
from __future__ import annotations

from collections.abc import Collection, Iterable

import pandas as pd

__all__ = ["unread_columns"]


def unread_columns(table: pd.DataFrame, read: Iterable[str], written: Collection[str], writes: str,
                   error: type[Exception]) -> pd.DataFrame:
    """The columns of ``table`` whose header is not one of ``read`` (the headers the command reads), in their order
    and positionally indexed, to be written back after the command's own columns.

    ``error`` (the command's error class) for a header that is one of ``written``, the columns the command writes
    there (``writes``: 'lab writes into readings.csv'): the two would share a header, as calc refuses an input
    column named like one of its results.

    >>> table = pd.DataFrame({"T [N*mm]": [1.0], "remark [see note]]": ["r"]})
    >>> unread_columns(table, ["T [N*mm]"], ["T"], "lab writes into readings.csv", ValueError).columns.tolist()
    ['remark [see note]]']
    """
    reading = set(read)
    kept = [position for position, header in enumerate(table.columns) if header not in reading]
    for position in kept:
        header = table.columns[position]
        if str(header).strip() in written:
            raise error(f"column {header!r} is a column {writes}; rename it (e.g. '{str(header).strip()} (own)')")
    return table.iloc[:, kept].reset_index(drop=True)
