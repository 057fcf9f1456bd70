"""The summary table of calc results and the progress bar on a terminal."""
from __future__ import annotations

import io
import re

import pandas as pd

from bearingheat.io.console import PROGRESS_MIN_ROWS, Progress, print_summary


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_summary_lists_rows_problems_and_counts():
    result = pd.DataFrame({"id": ["a", "b"], "designation": ["6208", "6209"], "MR [N*mm]": [138.4812, float("nan")],
                           "message": ["", "Supports!F4: 'abc' is not a number for Fr [kN]"],
                           "status": ["ok", "error"]})
    stream = io.StringIO()
    print_summary(result, "out.xlsx, sheet 'Results'", stream=stream)
    lines = stream.getvalue().splitlines()
    assert lines[0].split() == ["id", "designation", "MR", "[N*mm]", "status"]
    assert lines[1].split() == ["a", "6208", "138.5", "ok"] and lines[2].split() == ["b", "6209", "-", "error"]
    assert lines[3] == "error: b: Supports!F4: 'abc' is not a number for Fr [kN]"
    assert lines[4] == "2 supports: 1 ok, 0 warning, 1 error; results written to out.xlsx, sheet 'Results'"


def _screens(text: str) -> list[str]:
    """What a terminal shows after each redraw of rich's bar: the line after each 'erase line' code, without the
    colour codes."""
    plain = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", text.replace("\x1b[2K", "\x00"))
    return [screen.strip() for screen in plain.split("\x00")[1:]]


def test_progress_draws_only_on_a_terminal_for_long_tables():
    stream = Terminal()
    bar = Progress(stream=stream, width=10)
    bar.start(PROGRESS_MIN_ROWS, "reading Supports")
    bar.update(PROGRESS_MIN_ROWS // 2)
    bar.finish()
    screens = _screens(stream.getvalue())
    # label, a bar of 10 cells, rows done of the total, time elapsed
    half = f"{PROGRESS_MIN_ROWS // 2}/{PROGRESS_MIN_ROWS}"
    assert any(re.fullmatch(rf"reading Supports +[━╺╸]{{10}} +{half} 0:00:0\d", screen) for screen in screens), screens
    assert re.fullmatch(rf"reading Supports +━{{10}} {PROGRESS_MIN_ROWS}/{PROGRESS_MIN_ROWS} 0:00:0\d",
                        screens[-1]), screens
    assert stream.getvalue().replace("\x1b[?25h", "").endswith("\n")
    short = Terminal()
    bar = Progress(stream=short)
    bar.start(PROGRESS_MIN_ROWS - 1, "reading Supports")
    bar.finish()
    assert short.getvalue() == ""
    pipe = io.StringIO()
    bar = Progress(stream=pipe)
    bar.start(PROGRESS_MIN_ROWS, "reading Supports")
    bar.finish()
    assert pipe.getvalue() == ""
