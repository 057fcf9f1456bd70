"""Terminal output of the table commands: the summary table of calc results and a progress bar.

:func:`print_summary` writes the readable table that ``bearingheat calc``
prints for a CSV and for a workbook alike; :class:`Progress` draws the bar
that :func:`bearingheat.io.excel.workbook.calc_workbook` advances while it
reads and writes large sheets (any object with ``start``, ``update`` and
``finish`` will do).
"""
from __future__ import annotations

import re
import sys

import pandas as pd

__all__ = ["print_summary", "Progress", "PROGRESS_MIN_ROWS", "SHOWN_ROWS", "SHOWN_MESSAGES"]

_CITED = re.compile(r"^row \d+[ :]")

#: sheets at least this long get a progress bar (when stderr is a terminal)
PROGRESS_MIN_ROWS = 2000
#: at most this many rows of the table and lines of row messages are printed (a big table goes to -o FILE)
SHOWN_ROWS = 50
SHOWN_MESSAGES = 20


def print_summary(result: pd.DataFrame, output: str | None, stream=None) -> None:
    """A readable table of the main results, then one line per warning or error, then the counts.

    A table longer than :data:`SHOWN_ROWS` rows shows its first rows, and at most :data:`SHOWN_MESSAGES`
    messages (errors first), each followed by how many were left out.
    """
    stream = stream or sys.stdout
    label = "id" if "id" in result.columns else ("designation" if "designation" in result.columns else None)
    shown = [c for c in (label, "designation" if label == "id" else None) if c]
    shown += [c for c in result.columns if c.split(" [")[0] in ("f0", "f1", "P1", "M0", "M1", "M2", "MR", "NR",
                                                              "n_thr", "n_per", "T_op")]
    shown.append("status")
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
    """A one-line progress bar on a terminal stream; silent when disabled.

    Enabled when ``enabled`` is true and the stream is a terminal; each
    stage (reading, writing) draws its own bar and ends it with a newline,
    for sheets of at least :data:`PROGRESS_MIN_ROWS` rows.
    """

    def __init__(self, stream=None, enabled: bool = True, width: int = 30):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.width = width
        self.total = 0
        self.label = ""
        self.active = False

    def start(self, total: int, label: str) -> None:
        self.total, self.label = total, label
        self.active = self.enabled and total >= PROGRESS_MIN_ROWS
        self.update(0)

    def update(self, done: int) -> None:
        if not self.active:
            return
        done = min(done, self.total)
        filled = int(self.width * done / self.total) if self.total else self.width
        bar = "#" * filled + "-" * (self.width - filled)
        self.stream.write(f"\r{self.label:<24} [{bar}] {done}/{self.total}")
        self.stream.flush()

    def finish(self) -> None:
        if not self.active:
            return
        self.update(self.total)
        self.stream.write("\n")
        self.stream.flush()
        self.active = False
