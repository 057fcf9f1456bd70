"""Reading a chart the user digitised from a catalogue figure: a CSV with a header, a units row, one point a row.

bearingheat ships no chart values (the figures are missing from the catalogue
texts it was built from); :class:`~bearingheat.catalogue.f2chart.F2Chart` and
:class:`~bearingheat.catalogue.vm_chart.VMChart` read the user's points with
:func:`read_chart_csv`.
"""
from __future__ import annotations

import csv
import io
from pathlib import Path

from bearingheat.errors import BearingheatError

__all__ = ["read_chart_csv"]


def read_chart_csv(path: str | Path, required: list[str], what: str, error: type[BearingheatError]
                   ) -> tuple[dict[str, int], list[str], list[tuple[int, list[str]]]]:
    """(column positions of ``required``, the units row, [(file line, cells)] of the non-blank point rows).

    ``what`` names the chart in messages ('an f2 chart'); ``error`` is the
    chart's error class, raised for a file that cannot be read, or that lacks
    a required column or the units row.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise error(f"{path}: cannot read the {what.split(' ', 1)[1]} ({exc.strerror})") from exc
    rows = list(csv.reader(io.StringIO(text)))
    if len(rows) < 2 or any(col not in rows[0] for col in required):
        raise error(f"{path}: {what} needs the columns {', '.join(required)} and a units row")
    header = rows[0]
    points = [(line_no, row) for line_no, row in enumerate(rows[2:], start=3) if any(cell.strip() for cell in row)]
    return {name: header.index(name) for name in required}, rows[1], points
