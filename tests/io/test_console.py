"""The summary table of calc results and the progress bar on a terminal."""
from __future__ import annotations

import io

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


def test_progress_draws_only_on_a_terminal_for_long_tables():
    stream = Terminal()
    bar = Progress(stream=stream, width=10)
    bar.start(PROGRESS_MIN_ROWS, "reading Supports")
    bar.update(PROGRESS_MIN_ROWS // 2)
    bar.finish()
    assert stream.getvalue().endswith(f"[##########] {PROGRESS_MIN_ROWS}/{PROGRESS_MIN_ROWS}\n")
    assert f"[#####-----] {PROGRESS_MIN_ROWS // 2}/{PROGRESS_MIN_ROWS}" in stream.getvalue()
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
