"""Results in colour on a terminal, plain text to a pipe and with NO_COLOR (https://no-color.org), per command."""
from __future__ import annotations

import io
import sys
from pathlib import Path

import pytest
from synthetic_torque import measured_set

from bearingheat.analysis.audit import audit_coefficients
from bearingheat.cli import main
from bearingheat.io.reports.audit import coefficient_lines
from bearingheat.io.tables import read_table

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BOLD, GREEN = "\x1b[1m", "\x1b[32m"
CONTACT = ["contact", "--z", "7", "--dw", "2mm", "--dm", "8.7355mm", "--ri", "1.05mm", "--ro", "1.16mm",
           "--alpha0", "12deg", "--Fa", "2kgf", "--n", "3000rpm"]


class Terminal(io.StringIO):
    def isatty(self):
        return True


def _run(monkeypatch, argv: list[str], *, terminal: bool) -> str:
    stream = Terminal() if terminal else io.StringIO()
    monkeypatch.setattr(sys, "stdout", stream)
    assert main(argv) == 0
    return stream.getvalue()


@pytest.fixture
def colour_terminal(monkeypatch):
    monkeypatch.delenv("NO_COLOR", raising=False)
    monkeypatch.setenv("TERM", "xterm-256color")


@pytest.mark.parametrize("command", ["calc", "calc-duty", "lab", "contact"])
def test_colour_on_a_terminal_and_plain_text_with_no_color(colour_terminal, monkeypatch, tmp_path, command):
    argv = {"calc": ["calc", str(EXAMPLES / "gearbox_shaft.csv")],
            "calc-duty": ["calc", str(EXAMPLES / "gearbox_duty_cycle.csv")],
            "lab": ["lab", str(EXAMPLES / "lab_dp11a_example.csv"), "--out-dir", str(tmp_path), "--force"],
            "contact": CONTACT}[command]
    plain = _run(monkeypatch, argv, terminal=False)
    assert "\x1b[" not in plain
    coloured = _run(monkeypatch, argv, terminal=True)
    assert BOLD in coloured and (GREEN in coloured or command in ("lab", "contact"))
    monkeypatch.setenv("NO_COLOR", "1")
    assert _run(monkeypatch, argv, terminal=True) == plain


def test_the_plain_summary_of_calc_is_unchanged(monkeypatch):
    text = _run(monkeypatch, ["calc", str(EXAMPLES / "gearbox_duty_cycle.csv")], terminal=False).splitlines()
    assert text[0].split()[:6] == ["id", "designation", "f0", "f1", "P1", "[N]"]
    assert text[1] == ("input shaft A - full load        6208   2 0.0003795    3200      88.83      72.86          "
                       "0      161.7   25.06           9325           5009        41.54      ok")
    # the NU208-E idles below its minimum load (Schaeffler HR 1, p. 364)
    assert text[7].startswith('warning: row 7 (id "input shaft B - idle"): Fr [kN]: 0.4 is below the minimum load')
    assert text[8:11] == ["6 supports: 5 ok, 1 warning, 0 error", "", "duty cycle (time-weighted per support):"]
    assert text[11].split()[:3] == ["support", "designation", "cases"]


def test_lookup_is_a_record_in_colour_and_the_same_lines_without(colour_terminal, monkeypatch):
    plain = _run(monkeypatch, ["lookup", "6208"], terminal=False)
    assert plain.splitlines()[:3] == ["designation: 6208", "match: exact", "family: deep groove ball"]
    coloured = _run(monkeypatch, ["lookup", "6208"], terminal=True)
    assert BOLD in coloured and "n_thr [1/min]" in coloured and "9300" in coloured
    monkeypatch.setenv("NO_COLOR", "1")
    assert _run(monkeypatch, ["lookup", "6208"], terminal=True) == plain


def test_audit_coefficients_in_colour_and_the_text_of_the_report_without(colour_terminal, monkeypatch, tmp_path):
    table, _, _ = measured_set("none", 3, designations=["6004", "6310"])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    plain = _run(monkeypatch, ["audit", str(source)], terminal=False)
    assert plain == "\n".join(coefficient_lines(audit_coefficients(read_table(str(source), None)))) + "\n"
    assert plain.startswith("Coefficients fitted to the measured torque (95 % confidence intervals):\n")
    coloured = _run(monkeypatch, ["audit", str(source)], terminal=True)
    assert BOLD in coloured and GREEN in coloured
    monkeypatch.setenv("NO_COLOR", "1")
    assert _run(monkeypatch, ["audit", str(source)], terminal=True) == plain
