"""Terminal output of the commands: result tables and summaries, and a progress bar (rich).

:func:`print_summary` writes the readable table that ``bearingheat calc``
prints for a CSV and for a workbook alike; :func:`print_table` and
:func:`print_record` print the other tables and key-value results of the
commands. On a terminal that takes colours they draw a rich table with the
status of each row in colour (ok green, warning yellow, error red); to a file
or a pipe, with ``NO_COLOR`` set (https://no-color.org) or with ``TERM=dumb``
they write plain text, the same bytes as before there were colours.

:class:`Progress` draws the bar that
:func:`bearingheat.io.excel.workbook.calc_workbook` advances while it reads
and writes large sheets and :func:`bearingheat.io.pipeline.calc_file` block
by block (any object with ``start``, ``update`` and ``finish`` will do).
"""
from __future__ import annotations

import re
import sys
from collections.abc import Callable, Iterable, Mapping
from typing import IO, Any

import numpy as np
import pandas as pd
import pyarrow as pa
from rich import box
from rich.console import Console
from rich.measure import Measurement
from rich.segment import Segments
from rich.progress import BarColumn, MofNCompleteColumn, TaskID, TextColumn, TimeElapsedColumn
from rich.progress import Progress as RichProgress
from rich.table import Table
from rich.text import Text

__all__ = ["print_summary", "print_table", "print_record", "rich_console", "summary_columns", "Progress",
           "PROGRESS_MIN_ROWS", "SHOWN_ROWS", "SHOWN_MESSAGES", "STATUS_STYLES"]

_CITED = re.compile(r"^row \d+[ :]")

#: sheets at least this long get a progress bar (when stderr is a terminal)
PROGRESS_MIN_ROWS = 2000
#: at most this many rows of the table and lines of row messages are printed (a big table goes to -o FILE)
SHOWN_ROWS = 50
SHOWN_MESSAGES = 20

#: the results the summary table shows (by name, before the unit)
SHOWN_RESULTS = ("f0", "f1", "P1", "M0", "M1", "M2", "MR", "NR", "n_thr", "n_per", "T_op")

#: the colour of each row status on a terminal
STATUS_STYLES = {"ok": "green", "warning": "yellow", "error": "bold red"}


def rich_console(stream: IO[str] | None = None, console: Console | None = None) -> Console | None:
    """The rich console to draw on, or None where plain text is written.

    ``console`` (e.g. ``Console(force_terminal=True)`` in a test) is used as it is; otherwise one is made for
    ``stream`` (stdout by default) when it is a terminal. Plain text where the stream is no terminal (a file, a
    pipe: whatever the environment says about colours, so output that is read back never changes), a dumb
    terminal (``TERM=dumb``), or one without colours (``NO_COLOR`` set to anything but empty).
    """
    if console is None:
        out = stream if stream is not None else sys.stdout
        try:
            terminal = out.isatty()
        except (AttributeError, ValueError):  # no isatty, or a closed file
            terminal = False
        if not terminal:
            return None
        console = Console(file=out)
    if not console.is_terminal or console.is_dumb_terminal or console.no_color or console.color_system is None:
        return None
    return console


def _stream(stream: IO[str] | None, console: Console | None) -> IO[str]:
    """Where plain text goes: ``stream``, else the file of ``console``, else stdout."""
    if stream is not None:
        return stream
    return console.file if console is not None else sys.stdout


def _shown(columns: list[str]) -> tuple[str | None, list[str]]:
    """(the column naming a row, the columns of the summary table)."""
    label = "id" if "id" in columns else ("designation" if "designation" in columns else None)
    shown = [c for c in (label, "designation" if label == "id" else None) if c]
    shown += [c for c in columns if c.split(" [")[0] in SHOWN_RESULTS]
    return label, shown + ["status"]


def summary_columns(columns: Iterable[str]) -> list[str]:
    """The columns of a results table :func:`print_summary` reads (to read only those from a big file)."""
    names = [str(c) for c in columns]
    return _shown(names)[1] + (["message"] if "message" in names else [])


def _cell(value: Any, float_format: Callable[[float], str] | None) -> str:
    """A table cell as the plain table writes it: '-' for a missing value, floats by ``float_format``."""
    if value is None or (isinstance(value, float) and np.isnan(value)) or value is pd.NA:
        return "-"
    if isinstance(value, (float, np.floating)):
        return float_format(float(value)) if float_format is not None else f"{float(value):.6g}"
    return str(value)


def _rich_table(frame: pd.DataFrame, float_format: Callable[[float], str] | None,
                title: str | None = None) -> Table:
    """A rich table of ``frame`` (numbers right-aligned, the status column in its colour)."""
    table = Table(title=Text(title) if title is not None else None, title_justify="left", header_style="bold",
                  box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, collapse_padding=True)
    for name in frame.columns:
        numeric = pd.api.types.is_numeric_dtype(frame[name].dtype)
        table.add_column(Text(str(name)), justify="right" if numeric else "left", no_wrap=numeric)
    for row in frame.itertuples(index=False):
        cells = [_cell(value, float_format) for value in row]
        table.add_row(*(_status(text) if name == "status" else Text(text) for name, text in zip(frame.columns, cells)))
    return table


def _draw(console: Console, table: Table) -> None:
    """Print a table at its natural width: a table wider than the terminal runs over like the plain one does
    rather than squeezing its columns to ellipses."""
    unlimited = console.options.update(width=10_000, max_width=10_000)
    width = max(console.width, Measurement.get(console, unlimited, table).maximum)
    lines = console.render(table, console.options.update(width=width, max_width=width))
    console.print(Segments(lines), crop=False)


def _status(status: str) -> Text:
    return Text(status, style=STATUS_STYLES.get(status, ""))


def print_summary(result: pd.DataFrame | pa.Table, output: str | None, stream: IO[str] | None = None, *,
                  console: Console | None = None, columns: list[str] | None = None, rows: str = "supports") -> None:
    """A readable table of the main results, then one line per warning or error, then the counts.

    A table longer than :data:`SHOWN_ROWS` rows shows its first rows, and at most :data:`SHOWN_MESSAGES`
    messages (errors first), each followed by how many were left out. An Arrow table (the results of a big
    table) is read only in the columns shown. On a terminal (:func:`rich_console`) the table is a rich table
    and the statuses are coloured; otherwise plain text. ``columns``: the table's columns (its first names the
    rows in the messages; calc's main results by default); ``rows``: what the counts count.
    """
    out = _stream(stream, console)
    rich = rich_console(out, console)
    if isinstance(result, pa.Table):
        result = result.select(summary_columns(result.column_names)).to_pandas()
    label, shown = _shown([str(c) for c in result.columns]) if columns is None else (columns[0], columns)
    table = result[shown].head(SHOWN_ROWS)

    def number(x: float) -> str:
        return f"{x:.4g}"

    if rich is None:
        out.write(table.to_string(index=False, na_rep="-", float_format=number) + "\n")
    else:
        _draw(rich, _rich_table(table, number))
    notes: list[Text] = []
    if len(result) > SHOWN_ROWS:
        notes.append(Text(f"... {len(result) - SHOWN_ROWS} more rows; -o FILE writes them all"))
    status = result["status"].to_numpy(dtype=object)
    errors, warnings = (status == "error").nonzero()[0], (status == "warning").nonzero()[0]
    flagged = sorted(list(errors[:SHOWN_MESSAGES]) + list(warnings[:max(0, SHOWN_MESSAGES - len(errors))]))
    for i in flagged:
        row = result.iloc[i]
        message = row["message"]
        if isinstance(message, str) and _CITED.match(message):  # 'row 7 (id "x"): ...' names the row already
            notes.append(Text.assemble(_status(str(row["status"])), f": {message}"))
            continue
        who = row[label] if label else ""
        notes.append(Text.assemble(_status(str(row["status"])), f": {who}: {message}"))
    if len(errors) + len(warnings) > len(flagged):
        notes.append(Text(f"... {len(errors) + len(warnings) - len(flagged)} more rows with messages; -o FILE "
                          "writes them all"))
    counts = result["status"].value_counts()
    summary: list[Text | str] = [f"{len(result)} {rows}: "]
    for k, name in enumerate(("ok", "warning", "error")):
        count = counts.get(name, 0)
        summary += [", " if k else "", Text(f"{count} {name}", style=STATUS_STYLES[name] if count else "")]
    summary.append(f"; results written to {output}" if output else "")
    notes.append(Text.assemble(*summary))
    for note in notes:
        if rich is None:
            out.write(str(note) + "\n")
        else:
            rich.print(note, soft_wrap=True)


def print_table(frame: pd.DataFrame, stream: IO[str] | None = None, *, float_format: str | None = None,
                title: str | None = None, console: Console | None = None, na_rep: str = "NaN") -> None:
    """A table of results: ``frame.to_string(index=False)`` in plain text, a rich table on a terminal.

    ``float_format`` is a format spec for floats ('.4g'; pandas' own without it); ``title`` a line before the
    table (printed as it is in plain text); ``na_rep`` the plain text of a missing value (the rich table's is '-').
    """
    out = _stream(stream, console)
    rich = rich_console(out, console)
    formatter = None if float_format is None else (lambda x: format(x, float_format))
    if rich is None:
        if title is not None:
            out.write(title + "\n")
        out.write(frame.to_string(index=False, float_format=formatter, na_rep=na_rep) + "\n")
    else:
        _draw(rich, _rich_table(frame, formatter, title))


def print_record(record: Mapping[str, Any], stream: IO[str] | None = None, *, float_format: str = ".6g",
                 console: Console | None = None) -> None:
    """One result as 'key: value' lines in plain text, a two-column rich table on a terminal."""
    out = _stream(stream, console)
    rich = rich_console(out, console)
    text = {key: format(value, float_format) if isinstance(value, float) else str(value)
            for key, value in record.items()}
    if rich is None:
        out.writelines(f"{key}: {value}\n" for key, value in text.items())
        return
    table = Table(show_header=False, show_edge=False, pad_edge=False, box=None)
    table.add_column(style="bold")
    table.add_column()
    for key, value in text.items():
        table.add_row(Text(key), Text(value, style="yellow" if key == "warning" else ""))
    rich.print(table)


class Progress:
    """A progress bar on stderr (rich), one line per stage (reading, calc, writing); silent when disabled.

    Drawn when ``enabled`` is true and the stream is a terminal (not when
    stderr goes to a file or a pipe, whatever the environment says about
    colours), for stages of at least :data:`PROGRESS_MIN_ROWS` rows. Each
    stage shows its label, the bar, rows done of the total and the time
    elapsed, and ends with a newline.
    """

    def __init__(self, stream: IO[str] | None = None, enabled: bool = True, width: int = 30):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.width = width
        self.total = 0
        self.label = ""
        self.active = False
        self._bar: RichProgress | None = None
        self._task: TaskID | None = None

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
        if not self.active or self._bar is None or self._task is None:
            return
        self._bar.update(self._task, completed=min(done, self.total), refresh=True)

    def finish(self) -> None:
        if not self.active or self._bar is None:
            return
        self.update(self.total)
        self._bar.stop()
        self.active = False
        self._bar = None
        self._task = None
