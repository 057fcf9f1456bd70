"""bearingheat diagnose: the right effect for data built from the catalogue model + one effect + noise."""
from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from synthetic_torque import EFFECTS, measured_set  # noqa: E402

from bearingheat.cli import main  # noqa: E402
from bearingheat.diagnose import (DiagnoseError, FittedEffect, diagnose_table, error_metrics,  # noqa: E402
                                  read_measurements)
from bearingheat.effects import CANDIDATES, heated_total_torque  # noqa: E402
from bearingheat.frame import calc  # noqa: E402

DATA = Path(__file__).resolve().parents[2] / "shared" / "data"

# (effect, seed, bearings): two draws per effect with different bearings, three controls
CASES = [(e, s, b) for e in EFFECTS if e != "none" for s, b in (
    (101, ("6205", "6310", "30206-A", "NU208-E")), (202, ("6004", "6208", "7206-B", "NU206-E")))]
CONTROLS = [("none", 7, ("6205", "6208", "7206-B", "NU208-E")), ("none", 8, ("6004", "6310", "30206-A", "NU206-E")),
            ("none", 9, ("6205", "30206-A"))]

_cache: dict = {}


def run_case(effect, seed, bearings):
    key = (effect, seed, bearings)
    if key not in _cache:
        table, noise, sigma = measured_set(effect, seed, designations=list(bearings))
        _cache[key] = (table, noise, diagnose_table(table))
    return _cache[key]


def test_library_has_the_named_candidates():
    assert list(CANDIDATES) == ["none", "seal_drag", "f0_scale", "viscosity_heating", "drag_losses", "run_in",
                                "preload"]


@pytest.mark.parametrize("effect,seed,bearings", CASES, ids=[f"{c[0]}-{c[1]}" for c in CASES])
def test_names_the_effect_in_the_data(effect, seed, bearings):
    table, noise, diagnosis = run_case(effect, seed, bearings)
    summary = diagnosis.summary()
    assert summary["effect"] == effect
    assert summary["rmse_after"] <= 1.3 * noise
    assert summary["cv_rmse_after"] <= 1.3 * noise
    assert summary["rmse_before"] > 2.0 * noise      # the effect was there to find
    assert summary["mape_after"] < summary["mape_before"]


@pytest.mark.parametrize("effect,seed,bearings", CONTROLS, ids=[f"control-{c[1]}" for c in CONTROLS])
def test_control_set_gives_none(effect, seed, bearings):
    table, noise, diagnosis = run_case(effect, seed, bearings)
    summary = diagnosis.summary()
    assert summary["effect"] == "none"
    assert summary["parameters"] == {}
    assert summary["rmse_after"] == summary["rmse_before"]
    assert summary["rmse_before"] <= 1.3 * noise
    assert not any(c["significant"] for c in summary["candidates"].values())


def test_fitted_parameters_recover_the_truth_of_f0_scale():
    # f0_scale draws k uniformly in [2, 3]; the fit on 3-5 % noise recovers it within 3 %
    table, noise, diagnosis = run_case("f0_scale", 101, CASES[2][2])
    k = diagnosis.summary()["parameters"]["k"]
    assert 2.0 * 0.97 < k < 3.0 * 1.03


def test_summary_and_report_files(tmp_path):
    table, noise, _ = run_case(*CASES[0])
    source = tmp_path / "measured.csv"
    table.to_csv(source, index=False)
    out = tmp_path / "diag"
    assert main(["diagnose", str(source), "--out", str(out), "-q"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    for key in ("effect", "parameters", "rmse_before", "rmse_after", "cv_rmse_after", "mape_before", "mape_after",
                "candidates"):
        assert key in summary
    assert summary["effect"] == "seal_drag"
    assert set(summary["candidates"]) == set(EFFECTS)
    report = (out / "report.md").read_text()
    assert "residuals.png" in report and "measured_vs_predicted.png" in report
    for png in ("residuals.png", "measured_vs_predicted.png"):
        assert (out / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("effect,seed,bearings", [c for c in CASES if c[1] == 101 and c[0] != "run_in"],
                         ids=lambda c: str(c))
def test_calc_with_effects_reproduces_the_fitted_model(effect, seed, bearings, tmp_path):
    table, noise, diagnosis = run_case(effect, seed, bearings)
    summary_path = tmp_path / "summary.json"
    summary_path.write_text(json.dumps(diagnosis.summary()))
    out = calc(table, effects=FittedEffect.from_summary(summary_path))
    np.testing.assert_allclose(out["MR [N*mm]"].to_numpy(), diagnosis.chosen.predicted, rtol=1e-9)
    np.testing.assert_allclose(out["NR [W]"].to_numpy(), out["MR [N*mm]"] * table["n [1/min]"] / 9550, rtol=1e-12)
    assert out["message"].str.contains(f"diagnose effect {effect}").all()


def test_calc_cli_takes_the_effects(tmp_path, capsys):
    table, noise, diagnosis = run_case(*CASES[0])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out", str(tmp_path / "d"), "-q"]) == 0
    result = tmp_path / "r.csv"
    assert main(["calc", str(source), "--effects", str(tmp_path / "d" / "summary.json"), "-o", str(result), "-q"]) == 0
    rmse = error_metrics(table["M [N*mm]"], pd.read_csv(result)["MR [N*mm]"])["rmse"]
    assert rmse == pytest.approx(diagnosis.summary()["rmse_after"], rel=1e-9)


def test_run_in_in_calc_without_running_time_is_taken_as_run_in():
    frame = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [N]": [7800],
                          "lubrication": ["oil_bath"], "n [1/min]": [3000], "Fr [N]": [1000], "nu [mm^2/s]": [12]})
    plain = calc(frame)
    out = calc(frame, effects=FittedEffect("run_in", {"a": 3.0, "tau [h]": 10.0}))
    assert out["MR [N*mm]"].iat[0] == plain["MR [N*mm]"].iat[0]
    assert out["message"].iat[0] == "diagnose effect run_in: no running time t given; taken as run in (t >> tau)"


def test_heated_torque_solves_its_own_balance():
    R, f0, nu, n, dM, load = 0.7, 2.0, 30.0, np.array([1000.0, 4000.0]), 50.0, 40.0
    M = heated_total_torque(R, f0, nu, n, dM, load)
    nu_hot = nu * np.exp(-0.03 * R * M * n / 9550)
    np.testing.assert_allclose(M, load + f0 * (nu_hot * n) ** (2 / 3) * dM ** 3 * 1e-7, rtol=1e-10)


# ---- bad input: exact messages ------------------------------------------------------------------

def _small_table(rows=3):
    return pd.DataFrame({"designation": ["6205"] * rows, "d [mm]": 25, "D [mm]": 52, "C0 [N]": 7800,
                         "lubrication": "oil_bath", "n [1/min]": 3000.0, "Fr [N]": 1000.0, "nu [mm^2/s]": 12.0,
                         "M [N*mm]": 20.0})


def test_missing_torque_column():
    with pytest.raises(DiagnoseError, match=re.escape(
            "missing column: 'M [N*mm]' (the measured friction torque, any torque unit)")):
        diagnose_table(_small_table().drop(columns="M [N*mm]"))


def test_torque_in_a_force_unit():
    table = _small_table().rename(columns={"M [N*mm]": "M [N]"})
    with pytest.raises(DiagnoseError, match=re.escape("column 'M [N]': unit N cannot be converted to N*mm")):
        diagnose_table(table)


def test_bad_torque_cells_are_row_errors():
    table = _small_table(4)
    table["M [N*mm]"] = table["M [N*mm]"].astype(object)
    table.loc[1, "M [N*mm]"] = "abc"
    table.loc[2, "M [N*mm]"] = -3.0
    measured = read_measurements(table)
    assert measured.row_errors[1] == ["row 2: 'abc' is not a number for M [N*mm]"]
    assert measured.row_errors[2] == ["row 3: M = -3 N*mm must be > 0"]
    assert measured.row_errors[0] == []


def test_too_few_rows():
    with pytest.raises(DiagnoseError, match=re.escape(
            "diagnose needs at least 20 usable rows of measured torque; got 3")):
        diagnose_table(_small_table())


def test_unknown_effect_in_summary(tmp_path):
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"effect": "magic", "parameters": {}}))
    with pytest.raises(ValueError, match=re.escape(
            "effect 'magic' is not one of none, seal_drag, f0_scale, viscosity_heating, drag_losses, run_in, preload")):
        FittedEffect.from_summary(path)


def test_summary_missing_parameter(tmp_path, capsys):
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"effect": "drag_losses", "parameters": {"c": 1.0}}))
    source = tmp_path / "in.csv"
    _small_table().to_csv(source, index=False)
    assert main(["calc", str(source), "--effects", str(path)]) == 2
    assert capsys.readouterr().err.strip() == (
        f"bearingheat calc: error: --effects {path}: effect 'drag_losses' needs the parameter 'p'")


def test_cli_too_few_rows_exit_2(tmp_path, capsys):
    source = tmp_path / "in.csv"
    _small_table().to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out", str(tmp_path / "o")]) == 2
    assert capsys.readouterr().err.strip() == (
        "bearingheat diagnose: error: diagnose needs at least 20 usable rows of measured torque; got 3")


def test_cli_excluded_rows_exit_1(tmp_path, capsys):
    table, noise, _ = run_case(*CONTROLS[0])
    table = table.copy()
    table["M [N*mm]"] = table["M [N*mm]"].astype(object)
    table.loc[0, "M [N*mm]"] = "broken"
    source = tmp_path / "in.csv"
    table.to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out", str(tmp_path / "o")]) == 1
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["excluded"] == ["row 1: 'broken' is not a number for M [N*mm]"]
    assert summary["effect"] == "none"


def test_subprocess_diagnose(tmp_path):
    table, noise, _ = run_case(*CASES[2])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    done = subprocess.run([sys.executable, "-m", "bearingheat", "diagnose", str(source), "--out", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("effect: f0_scale")


def test_real_published_running_torque_is_too_little_to_diagnose():
    """Zhang 2025: two running torques of a 32208 X pair; the only running-torque data in ../shared/data."""
    path = DATA / "trb_32208_x_pair_zhang2025.csv"
    if not path.is_file():
        pytest.skip(f"{path} is not present")
    raw = pd.read_csv(path)
    table = pd.DataFrame({"designation": "32208", "d [mm]": 40, "D [mm]": 80, "Y": 1.6, "arrangement": "paired",
                          "lubrication": "circulating_oil", "n [1/min]": raw["inner_ring_speed_rpm"],
                          "Fa [kN]": raw["axial_load_Fa_kN"], "nu [mm^2/s]": 20.0,
                          "M [N*m]": raw["mean_friction_torque_Nm"]})
    with pytest.raises(DiagnoseError, match=re.escape(
            "diagnose needs at least 20 usable rows of measured torque; got 2")):
        diagnose_table(table)


def test_docs_image():
    """docs/measured.md shows the residual plot of a synthetic seal-drag set (written here)."""
    from bearingheat.diagnose import plot_residuals

    table, noise, diagnosis = run_case(*CASES[0])
    target = Path(__file__).resolve().parents[1] / "docs" / "_static" / "diagnose_seal_drag_residuals.png"
    assert plot_residuals(diagnosis, target) == "n"
    assert target.stat().st_size < 150_000
