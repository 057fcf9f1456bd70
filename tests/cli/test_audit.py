"""bearingheat audit on the command line: tables, files and exit codes."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
from synthetic_torque import measured_set

from bearingheat.cli import main

HR1 = Path(__file__).resolve().parents[3] / "shared" / "data" / "hr1_2006_reference_speeds.csv"


def test_cli_reference_speeds(capsys, tmp_path):
    if not HR1.is_file():
        pytest.skip(f"{HR1} is not present")
    assert main(["audit", "--reference-speeds", str(HR1), "--out", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert "systematic: tapered roller 330" in out
    assert (tmp_path / "reference_speed_series.csv").is_file()


def test_cli_coefficients(tmp_path, capsys):
    table, _, _ = measured_set("none", 3, designations=["30206-A", "6004", "6310", "NU208-E"])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    assert main(["audit", str(source), "--out", str(tmp_path)]) == 0
    assert pd.read_csv(tmp_path / "coefficients.csv")["fitted"].notna().all()


def test_cli_neither_kind(tmp_path, capsys):
    source = tmp_path / "x.csv"
    pd.DataFrame({"a": [1]}).to_csv(source, index=False)
    assert main(["audit", str(source)]) == 2
    assert capsys.readouterr().err.strip() == (
        f"bearingheat audit: error: {source}: neither a measured torque column 'M [N*mm]' nor a published "
        "thermal reference speed column (n_thr, n_B, n_theta_r, n_θr, n_ref, nthr)")


def test_cli_no_input(capsys):
    assert main(["audit"]) == 2
    assert capsys.readouterr().err.strip() == "bearingheat audit: error: give DATA, --reference-speeds CSV, or both"


def test_subprocess_audit(tmp_path):
    table = pd.DataFrame({"designation": ["6205", "6206"], "d [mm]": [25, 30], "D [mm]": [52, 62],
                          "B [mm]": [15, 16], "C0 [N]": [7800, 11200], "n_B [1/min]": [14400, 12000]})
    source = tmp_path / "list.csv"
    table.to_csv(source, index=False)
    done = subprocess.run([sys.executable, "-m", "bearingheat", "audit", str(source)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "deep_groove_ball 62" in done.stdout


def test_top_level_help_lists_the_measured_data_commands():
    done = subprocess.run([sys.executable, "-m", "bearingheat", "--help"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    for name in ("lab", "audit", "diagnose"):
        assert f"    {name} " in done.stdout
