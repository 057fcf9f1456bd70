"""CLI of ``bearingheat lab``: the report of the shipped example, usage errors (exit 2)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from bearingheat.cli import main

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lab_dp11a_example.csv"


def test_cli_lab(tmp_path, capsys):
    assert main(["lab", str(EXAMPLE), "--out-dir", str(tmp_path), "-q"]) == 0
    report = (tmp_path / "report.md").read_text()
    assert "Table 4, β = 30°" in report and "Table 5, Q = 2 kg" in report
    assert (tmp_path / "task2_101.png").read_bytes()[:4] == b"\x89PNG"


def test_cli_lab_bad_nu(tmp_path, capsys):
    assert main(["lab", str(EXAMPLE), "--out-dir", str(tmp_path), "--nu", "20"]) == 2
    assert capsys.readouterr().err.strip() == (
        "bearingheat lab: error: --nu: '20' has no unit; write it with one, e.g. 20mm^2/s")


def test_subprocess_lab(tmp_path):
    done = subprocess.run([sys.executable, "-m", "bearingheat", "lab", str(EXAMPLE), "--out-dir", str(tmp_path),
                           "--nu", "30cSt"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "files written to" in done.stdout
