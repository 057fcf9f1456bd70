"""bearingheat diagnose: the right effect for data built from the catalogue model + one effect + noise."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from diagnose_cases import CASES, CONTROLS, run_case, small_table

from bearingheat.analysis.diagnose import DiagnoseError, FittedEffect, diagnose_table, read_measurements
from bearingheat.analysis.effects import CANDIDATES
from bearingheat.calc.table import calc

DATA = Path(__file__).resolve().parents[3] / "shared" / "data"

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


def test_run_in_in_calc_without_running_time_is_taken_as_run_in():
    frame = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [N]": [7800],
                          "lubrication": ["oil_bath"], "n [1/min]": [3000], "Fr [N]": [1000], "nu [mm^2/s]": [12]})
    plain = calc(frame)
    out = calc(frame, effects=FittedEffect("run_in", {"a": 3.0, "tau [h]": 10.0}))
    assert out["MR [N*mm]"].iat[0] == plain["MR [N*mm]"].iat[0]
    assert out["message"].iat[0] == "diagnose effect run_in: no running time t given; taken as run in (t >> tau)"


# ---- bad input: exact messages ------------------------------------------------------------------

def test_missing_torque_column():
    with pytest.raises(DiagnoseError, match=re.escape(
            "missing column: 'M [N*mm]' (the measured friction torque, any torque unit)")):
        diagnose_table(small_table().drop(columns="M [N*mm]"))


def test_torque_in_a_force_unit():
    table = small_table().rename(columns={"M [N*mm]": "M [N]"})
    with pytest.raises(DiagnoseError, match=re.escape("column 'M [N]': unit N cannot be converted to N*mm")):
        diagnose_table(table)


def test_bad_torque_cells_are_row_errors():
    table = small_table(4)
    table["M [N*mm]"] = table["M [N*mm]"].astype(object)
    table.loc[1, "M [N*mm]"] = "abc"
    table.loc[2, "M [N*mm]"] = -3.0
    measured = read_measurements(table)
    assert measured.row_errors[1] == ["row 2: 'abc' is not a number for M [N*mm]"]
    assert measured.row_errors[2] == ["row 3: M = -3 N*mm must be > 0"]
    assert measured.row_errors[0] == []


def test_infinite_torques_and_impossible_oil_temperatures_are_row_errors():
    """One infinite torque made every error measure infinite (and diagnose name no effect, audit stop with a
    traceback); an oil temperature below absolute zero passed silently."""
    table = small_table(4)
    table["M [N*mm]"] = table["M [N*mm]"].astype(float)
    table.loc[1, "M [N*mm]"] = np.inf
    table["T_oil [degC]"] = 50.0
    table.loc[2, "T_oil [degC]"] = -400.0
    measured = read_measurements(table)
    assert measured.row_errors[1] == ["row 2: M = inf N*mm is not a finite number"]
    assert measured.row_errors[2] == ["row 3: T_oil = -400 degC is outside -60 to 300 degC"]
    assert measured.row_errors[0] == measured.row_errors[3] == []


def test_too_few_rows():
    with pytest.raises(DiagnoseError, match=re.escape(
            "diagnose needs at least 20 usable rows of measured torque; got 3")):
        diagnose_table(small_table())


def test_unknown_effect_in_summary(tmp_path):
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"effect": "magic", "parameters": {}}))
    with pytest.raises(DiagnoseError, match=re.escape(
            "effect 'magic' is not one of none, seal_drag, f0_scale, viscosity_heating, drag_losses, run_in, preload")):
        FittedEffect.from_summary(path)


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


def test_the_selection_text_says_what_was_chosen():
    from diagnose_cases import CASES, CONTROLS, run_case
    effect, seed, bearings = next(c for c in CASES if c[0] == "seal_drag")
    chosen = run_case(effect, seed, bearings)[2]
    assert chosen.summary()["selection"].startswith("Chosen: 'seal_drag' (ΔBIC ")
    assert "the answer is 'none'." not in chosen.summary()["selection"]
    control = run_case(*CONTROLS[0])[2]
    assert control.summary()["selection"] == "No candidate is significant: the answer is 'none'."
