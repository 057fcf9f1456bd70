"""CLI of the plain-support commands: ``bearingheat coastdown`` and ``bearingheat bushing``."""
from __future__ import annotations

import json
import pathlib
import subprocess
import sys

import pytest

from bearingheat.cli import main

REPO = pathlib.Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "coastdown_example.csv"


def test_coastdown_example_writes_report_png_and_summary(tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["coastdown", str(EXAMPLE), "--out", str(out), "--dn", "100rpm"]) == 0
    stdout = capsys.readouterr().out
    assert "Chosen model: **coulomb_viscous_aero**" in stdout
    summary = json.loads((out / "summary.json").read_text())
    # generated with M_c = 0.3 N*m, c_v = 0.004 N*m*s, c_a = 5e-5 N*m*s^2 (docs/coastdown.md)
    assert summary["model"] == "coulomb_viscous_aero"
    assert summary["M_c [N*m]"] == pytest.approx(0.3, rel=0.05)
    assert summary["c_v [N*m*s]"] == pytest.approx(0.004, rel=0.1)
    assert summary["c_a [N*m*s^2]"] == pytest.approx(5e-5, rel=0.1)
    assert summary["rmse_after [1/min]"] < summary["rmse_before [1/min]"] / 10
    assert 0.015 < summary["f_constant"] < 0.03
    assert (out / "coastdown.png").stat().st_size > 1000
    assert "![run-down data" in (out / "report.md").read_text()


def test_coastdown_rig_units_are_converted(capsys):
    assert main(["coastdown", str(EXAMPLE), "--I", "2600000kg*mm^2", "--G", "1.1kN", "--r", "2.5cm"]) == 0
    assert "G = 1100 N, r = 25 mm" in capsys.readouterr().out


def test_coastdown_spindle_needs_viscosity(capsys):
    assert main(["coastdown", str(EXAMPLE), "--spindle", "--dM", "50mm"]) == 2
    assert capsys.readouterr().err == "bearingheat coastdown: error: --spindle needs --nu\n"


def test_coastdown_missing_column(tmp_path, capsys):
    data = tmp_path / "d.csv"
    data.write_text("time,n [1/min]\n0,100\n")
    assert main(["coastdown", str(data)]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat coastdown: error: {data}: no column 't [s]' (a 't [unit]' column); "
        "columns are: 'time', 'n [1/min]'\n")


def test_coastdown_bad_cell(tmp_path, capsys):
    data = tmp_path / "d.csv"
    data.write_text("t [s],n [1/min]\n0,100\n1,abc\n")
    assert main(["coastdown", str(data)]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat coastdown: error: {data} line 3, column 'n [1/min]': 'abc' is not a number\n")


def test_coastdown_rig_value_without_unit(capsys):
    assert main(["coastdown", str(EXAMPLE), "--G", "1100"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat coastdown: error: --G: '1100' has no unit; write it with one, e.g. 1100mm\n")


def test_bushing_text_shows_the_kgf_conversion(capsys):
    code = main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "rotating_fixed_load_point", "--standard", "20,30,50,100mm"])
    assert code == 0
    out = capsys.readouterr().out
    assert "K = pV = 5.65 kgf/cm²·m/s × 0.0980665 = 0.5541 N/mm²·m/s" in out
    assert "4. standard length: 100 mm" in out


def test_bushing_json(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--K", "0.5N/mm^2*m/s",
                 "--load-type", "static", "--f", "0.12", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["l_required [mm]"] == pytest.approx(104.72, rel=1e-4)
    assert result["N_low [W]"] == result["N_high [W]"] == pytest.approx(0.12 * 2000 * 0.654498, rel=1e-5)


def test_bushing_outside_method_exit_1(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "20rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "static"]) == 1
    assert capsys.readouterr().err == (
        "bearingheat bushing: V = 0.02618 m/s is below 0.05 m/s: outside seed 004's sizing method "
        "(the seed allows smaller bearings than calculated there)\n")


def test_bushing_lost_table_value_exit_2(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "hardened", "--life", "10000h",
                 "--load-type", "static"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat bushing: error: seed 004 table 25: K for bushing_constant_load, hardened shaft, 10000 h "
        "was lost in the OCR of the seed; give K directly\n")


def test_bushing_oscillation_speed(capsys):
    # 600 cycles/min x 90 deg (0.25 rev) = 150 1/min
    assert main(["bushing", "--F", "1kN", "--cycles", "600/min", "--amplitude", "90deg", "--d", "25mm",
                 "--application", "bushing_oscillating", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "rotating_fixed_load_point", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["n [1/min]"] == pytest.approx(150.0)


def test_subprocess_python_m_bearingheat():
    proc = subprocess.run([sys.executable, "-m", "bearingheat", "bushing", "--F", "2kN", "--n", "500rpm",
                           "--d", "25mm", "--shaft", "soft", "--life", "1000h", "--load-type", "static"],
                          capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "governed by pV: l = 94.5 mm" in proc.stdout
