"""CLI of ``bearingheat coastdown``: run-down report, PNG and summary; usage errors (exit 2)."""
from __future__ import annotations

import json
import math
import pathlib

import numpy as np
import pytest

from bearingheat.cli import main

REPO = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "coastdown_example.csv"


def test_coastdown_example_writes_report_png_and_summary(tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["coastdown", str(EXAMPLE), "--out-dir", str(out), "--dn", "100rpm"]) == 0
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
        "bearingheat coastdown: error: --G: '1100' has no unit; write it with one, e.g. 1100N\n")


@pytest.mark.parametrize("cell", ["1e300", "inf"])
def test_coastdown_absurd_reading_is_named(tmp_path, capsys, cell):
    """One absurd speed made the rest of the run-down look flat ('fewer than 4 samples above 2 %')."""
    lines = EXAMPLE.read_text().splitlines()
    lines.insert(3, f"5,{cell}")
    path = tmp_path / "absurd.csv"
    path.write_text("\n".join(lines) + "\n")
    assert main(["coastdown", str(path)]) == 2
    assert capsys.readouterr().err == (f"bearingheat coastdown: error: {path} line 4, column 'n [1/min]': {cell!r} is "
                                       "not a plausible reading (not finite, or beyond 1e+09)\n")


def _straight_csv(tmp_path):
    """600 1/min falling 10 1/min per second to 0 at 60 s: M = I*(pi/30)*10 by hand (2.6 kg*m^2: 2.72271 N*m)."""
    data = tmp_path / "line.csv"
    t = np.arange(0.0, 61.0, 2.0)
    data.write_text("t [s],n [1/min]\n" + "".join(f"{a:g},{600.0 - 10.0 * a:g}\n" for a in t))
    return data


def test_coastdown_torque_only_computes_no_f(tmp_path, capsys):
    """--torque-only: G and r are not the TMM-7M rig's, f is not computed (null in the JSON, said in the report)."""
    data = _straight_csv(tmp_path)
    assert main(["coastdown", str(data), "--torque-only", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["M_c [N*m]"] == pytest.approx(2.6 * math.pi / 30.0 * 10.0, rel=1e-6)
    assert (summary["f_constant"], summary["f_computed"], summary["G [N]"], summary["r [mm]"]) == (None, False, None,
                                                                                                 None)
    assert summary["rig_defaults"] == ["I"]
    assert main(["coastdown", str(data), "--torque-only"]) == 0
    report = capsys.readouterr().out
    assert ("Rig: I = 2.6 kg·m² (G and r not given: torques only, f is not computed); I: the TMM-7M rig's default."
            in report)
    assert ("- Constant f (the TMM-7M lab sheet's single coefficient, from the Coulomb-only fit): "
            "not computed (no G and r: torques only)") in report
    assert "| 600 | 542 | 5.8 | 2.723 | not computed |" in report


def test_coastdown_torque_only_takes_no_journal_load(capsys):
    assert main(["coastdown", str(EXAMPLE), "--torque-only", "--G", "1000N"]) == 2
    assert capsys.readouterr().err == "bearingheat coastdown: error: --torque-only computes no f and takes no --G or --r\n"


def test_coastdown_another_rotor_with_the_rig_journal_is_flagged(tmp_path, capsys):
    """--I of another rotor without --G/--r: f = M_c/(G*r) with the rig's 1100 N and 25 mm (27.5 N*m by hand),
    and the report says G and r are the TMM-7M rig's defaults, not the rotor's."""
    data = _straight_csv(tmp_path)
    assert main(["coastdown", str(data), "--I", "5kg*m^2", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["M_c [N*m]"] == pytest.approx(5.0 * math.pi / 30.0 * 10.0, rel=1e-6)
    assert summary["f_constant"] == pytest.approx(5.0 * math.pi / 3.0 / 27.5, rel=1e-6)
    assert summary["rig_defaults"] == ["G", "r"]
    assert main(["coastdown", str(data), "--I", "5kg*m^2"]) == 0
    report = capsys.readouterr().out
    assert "Rig: I = 5 kg·m², G = 1100 N, r = 25 mm; G, r: the TMM-7M rig's defaults." in report
    assert ("**Note:** f is computed with the TMM-7M rig's journal load G and radius r (not given) for a rotor of "
            "another inertia: it is not the f of that rotor. Give its G and r, or analyse torques only.") in report
    assert main(["coastdown", str(data), "--I", "5kg*m^2", "--G", "900N", "--r", "20mm"]) == 0
    report = capsys.readouterr().out
    assert "Rig: I = 5 kg·m², G = 900 N, r = 20 mm. Samples" in report and "**Note:**" not in report


@pytest.mark.parametrize("f0", ["0", "nan", "-2"])
def test_coastdown_catalogue_f0_must_be_positive(f0, capsys):
    """--f0 0 crashed (ZeroDivisionError, exit 1), nan became null, -2 printed a negative ratio: now exit 2."""
    shown = {"0": "0", "nan": "nan", "-2": "-2"}[f0]
    assert main(["coastdown", str(EXAMPLE), "--spindle", "--nu", "20mm^2/s", "--dM", "50mm", f"--f0={f0}"]) == 2
    assert capsys.readouterr().err == (f"bearingheat coastdown: error: spindle coast-down: catalogue f0 = {shown}; "
                                       "expected a finite value > 0 to compare the fitted f0 with\n")
