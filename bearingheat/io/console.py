"""Terminal output of the table commands: the summary table of calc results and a progress bar (rich).

:func:`print_summary` writes the readable table that ``bearingheat calc``
prints for a CSV and for a workbook alike; :class:`Progress` draws the bar
that :func:`bearingheat.io.excel.workbook.calc_workbook` advances while it
reads and writes large sheets and :func:`bearingheat.io.pipeline.calc_file`
block by block (any object with ``start``, ``update`` and ``finish`` will
do).
"""
from __future__ import annotations

import re
import sys

import pandas as pd
import pyarrow as pa
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, TextColumn, TimeElapsedColumn
from rich.progress import Progress as RichProgress

__all__ = ["print_summary", "summary_columns", "Progress", "PROGRESS_MIN_ROWS", "SHOWN_ROWS", "SHOWN_MESSAGES"]

_CITED = re.compile(r"^row \d+[ :]")

#: sheets at least this long get a progress bar (when stderr is a terminal)
PROGRESS_MIN_ROWS = 2000
#: at most this many rows of the table and lines of row messages are printed (a big table goes to -o FILE)
SHOWN_ROWS = 50
SHOWN_MESSAGES = 20


#: the results the summary table shows (by name, before the unit)
SHOWN_RESULTS = ("f0", "f1", "P1", "M0", "M1", "M2", "MR", "NR", "n_thr", "n_per", "T_op")


def _shown(columns) -> tuple[str | None, list[str]]:
    """(the column naming a row, the columns of the summary table)."""
    label = "id" if "id" in columns else ("designation" if "designation" in columns else None)
    shown = [c for c in (label, "designation" if label == "id" else None) if c]
    shown += [c for c in columns if c.split(" [")[0] in SHOWN_RESULTS]
    return label, shown + ["status"]


def summary_columns(columns) -> list[str]:
    """The columns of a results table :func:`print_summary` reads (to read only those from a big file)."""
    return _shown(list(columns))[1] + (["message"] if "message" in columns else [])


def print_summary(result: pd.DataFrame | pa.Table, output: str | None, stream=None) -> None:
    """A readable table of the main results, then one line per warning or error, then the counts.

    A table longer than :data:`SHOWN_ROWS` rows shows its first rows, and at most :data:`SHOWN_MESSAGES`
    messages (errors first), each followed by how many were left out. An Arrow table (the results of a big
    table) is read only in the columns shown.
    """
    stream = stream or sys.stdout
    if isinstance(result, pa.Table):
        result = result.select(summary_columns(result.column_names)).to_pandas()
    label, shown = _shown(list(result.columns))
    table = result[shown].head(SHOWN_ROWS)
    stream.write(table.to_string(index=False, na_rep="-", float_format=lambda x: f"{x:.4g}") + "\n")
    if len(result) > SHOWN_ROWS:
        stream.write(f"... {len(result) - SHOWN_ROWS} more rows; -o FILE writes them all\n")
    status = result["status"].to_numpy(dtype=object)
    errors, warnings = (status == "error").nonzero()[0], (status == "warning").nonzero()[0]
    flagged = sorted(list(errors[:SHOWN_MESSAGES]) + list(warnings[:max(0, SHOWN_MESSAGES - len(errors))]))
    for i in flagged:
        row = result.iloc[i]
        message = row["message"]
        if isinstance(message, str) and _CITED.match(message):  # 'row 7 (id "x"): ...' names the row already
            stream.write(f"{row['status']}: {message}\n")
            continue
        who = row[label] if label else ""
        stream.write(f"{row['status']}: {who}: {message}\n")
    if len(errors) + len(warnings) > len(flagged):
        stream.write(f"... {len(errors) + len(warnings) - len(flagged)} more rows with messages; -o FILE writes "
                     "them all\n")
    counts = result["status"].value_counts()
    summary = ", ".join(f"{counts.get(s, 0)} {s}" for s in ("ok", "warning", "error"))
    where = f"; results written to {output}" if output else ""
    stream.write(f"{len(result)} supports: {summary}{where}\n")


class Progress:
    """A progress bar on stderr (rich), one line per stage (reading, calc, writing); silent when disabled.

    Drawn when ``enabled`` is true and the stream is a terminal (not when
    stderr goes to a file or a pipe, whatever the environment says about
    colours), for stages of at least :data:`PROGRESS_MIN_ROWS` rows. Each
    stage shows its label, the bar, rows done of the total and the time
    elapsed, and ends with a newline.
    """

    def __init__(self, stream=None, enabled: bool = True, width: int = 30):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.width = width
        self.total = 0
        self.label = ""
        self.active = False
        self._bar = None
        self._task = None

    def start(self, total: int, label: str) -> None:
        self.finish()
        self.total, self.label = total, label
        self.active = self.enabled and total >= PROGRESS_MIN_ROWS
        if not self.active:
            return
        console = Console(file=self.stream, force_terminal=True)
        self._bar = RichProgress(TextColumn(f"{{task.description:<{max(24, len(label))}}}"),
                                 BarColumn(bar_width=self.width), MofNCompleteColumn(), TimeElapsedColumn(),
                                 console=console, auto_refresh=False, transient=False)
        self._bar.start()
        self._task = self._bar.add_task(label, total=total)
        self.update(0)

    def update(self, done: int) -> None:
        if not self.active:
            return
        self._bar.update(self._task, completed=min(done, self.total), refresh=True)

    def finish(self) -> None:
        if not self.active:
            return
        self.update(self.total)
        self._bar.stop()
        self.active = False
        self._bar = self._task = None
