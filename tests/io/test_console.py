"""The summary table of calc results (plain, or a rich table in colour on a terminal) and the progress bar."""
from __future__ import annotations

import io
import re

import pandas as pd
import pytest
from rich.console import Console

from bearingheat.io.console import PROGRESS_MIN_ROWS, Progress, print_record, print_summary, print_table


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


_RESULT = pd.DataFrame({"id": ["a", "b", "c"], "designation": ["6208", "6208", "XYZ"],
                        "MR [N*mm]": [102.2345, 1117.0, float("nan")], "NR [W]": [16.05, 11580.0, float("nan")],
                        "message": ["", "row 4 (id \"b\"): n [1/min]: 99000 is above the limiting speed",
                                    "no such [kN]"],
                        "status": ["ok", "warning", "error"]})

#: the plain text of _RESULT: the output of every stream that is no terminal, byte for byte
_PLAIN = """\
id designation  MR [N*mm]    NR [W]  status
 a        6208      102.2     16.05      ok
 b        6208       1117 1.158e+04 warning
 c         XYZ          -         -   error
warning: row 4 (id "b"): n [1/min]: 99000 is above the limiting speed
error: c: no such [kN]
3 supports: 1 ok, 1 warning, 1 error; results written to out.csv
"""

GREEN, YELLOW, BOLD_RED = "\x1b[32m", "\x1b[33m", "\x1b[1;31m"


@pytest.fixture
def colour_terminal(monkeypatch):
    """An environment in which a terminal takes colours (whatever the test runner's is)."""
    monkeypatch.delenv("NO_COLOR", raising=False)
    monkeypatch.setenv("TERM", "xterm-256color")


def _terminal(**options) -> Console:
    return Console(file=io.StringIO(), force_terminal=True, width=100, **options)


def test_plain_text_where_the_stream_is_no_terminal(colour_terminal, monkeypatch):
    monkeypatch.setenv("FORCE_COLOR", "1")  # a pipe stays plain whatever the environment says about colours
    stream = io.StringIO()
    print_summary(_RESULT, "out.csv", stream=stream)
    assert stream.getvalue() == _PLAIN


def test_a_colour_terminal_gets_a_rich_table_with_coloured_statuses(colour_terminal):
    console = _terminal()
    print_summary(_RESULT, "out.csv", console=console)
    text = console.file.getvalue()
    assert f"{GREEN}ok" in text and f"{YELLOW}warning" in text and f"{BOLD_RED}error" in text
    plain = re.sub(r"\x1b\[[0-9;]*m", "", text).splitlines()
    assert plain[0].split() == ["id", "designation", "MR", "[N*mm]", "NR", "[W]", "status"]
    assert set(plain[1]) == {"─"}                      # the rule under the header
    assert plain[2].split() == ["a", "6208", "102.2", "16.05", "ok"]
    assert plain[4].split() == ["c", "XYZ", "-", "-", "error"]
    assert plain[5:] == _PLAIN.splitlines()[4:]        # the messages and counts read as in plain text
    # the terminal of a real stream: one whose isatty() is true
    stream = Terminal()
    print_summary(_RESULT, "out.csv", stream=stream)
    assert f"{BOLD_RED}error" in stream.getvalue()


@pytest.mark.parametrize("variable, value", [("NO_COLOR", "1"), ("NO_COLOR", "yes"), ("TERM", "dumb")])
def test_no_color_and_a_dumb_terminal_give_the_plain_text(colour_terminal, monkeypatch, variable, value):
    monkeypatch.setenv(variable, value)
    console = _terminal()
    print_summary(_RESULT, "out.csv", console=console)
    assert console.file.getvalue() == _PLAIN
    stream = Terminal()
    print_summary(_RESULT, "out.csv", stream=stream)
    assert stream.getvalue() == _PLAIN


def test_an_empty_no_color_keeps_the_colours(colour_terminal, monkeypatch):
    monkeypatch.setenv("NO_COLOR", "")  # https://no-color.org: set and not empty
    console = _terminal()
    print_summary(_RESULT, "out.csv", console=console)
    assert GREEN in console.file.getvalue()


def test_tables_and_records_plain_and_on_a_terminal(colour_terminal, monkeypatch):
    frame = pd.DataFrame({"support": ["input shaft A"], "MR_mean [N*mm]": [125.130323], "status": ["ok"]})
    stream = io.StringIO()
    print_table(frame, stream, title="duty cycle:")
    assert stream.getvalue() == "duty cycle:\n" + frame.to_string(index=False) + "\n"
    stream = io.StringIO()
    print_table(frame, stream, float_format=".4g")
    assert stream.getvalue() == frame.to_string(index=False, float_format=lambda x: f"{x:.4g}") + "\n"
    console = _terminal()
    print_table(frame, title="duty cycle:", float_format=".4g", console=console)
    assert f"{GREEN}ok" in console.file.getvalue() and "125.1" in console.file.getvalue()
    stream = io.StringIO()
    print_record({"alpha [deg]": 14.46578, "z": 7, "warning": "Fa below Fa_min"}, stream)
    assert stream.getvalue() == "alpha [deg]: 14.4658\nz: 7\nwarning: Fa below Fa_min\n"
    console = _terminal()
    print_record({"alpha [deg]": 14.46578, "warning": "Fa below Fa_min"}, console=console)
    assert f"{YELLOW}Fa below Fa_min" in console.file.getvalue()
    monkeypatch.setenv("NO_COLOR", "1")
    console = _terminal()
    print_record({"alpha [deg]": 14.46578}, console=console)
    assert console.file.getvalue() == "alpha [deg]: 14.4658\n"


def test_a_table_wider_than_the_terminal_keeps_its_columns(colour_terminal):
    wide = pd.DataFrame({f"column number {k} [N*mm]": [1.0 + k] for k in range(12)} | {"status": ["ok"]})
    console = _terminal()
    print_table(wide, console=console)
    plain = re.sub(r"\x1b\[[0-9;]*m", "", console.file.getvalue()).splitlines()
    assert "…" not in "".join(plain) and plain[0].split("  ")[0] == "column number 0 [N*mm]"
    assert plain[2].split() == [f"{1.0 + k:g}" for k in range(12)] + ["ok"]


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
