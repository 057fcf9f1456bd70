"""diagnose's statistics: bounds the training fold sets, parameters on their bounds, the influence of single
readings, the error measure the choice uses."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from synthetic_torque import measured_set

from bearingheat.analysis.diagnose import diagnose_table, model_data, read_measurements
from bearingheat.analysis.effects import CANDIDATES
from bearingheat.analysis.influence import influence, leverage
from bearingheat.cli import main
from bearingheat.io.reports.diagnose import summary_lines, write_outputs

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "measured_torque_example.csv"


def _data(effect, seed, designations):
    table, _, _ = measured_set(effect, seed, designations=list(designations))
    return model_data(read_measurements(table))[0]


def test_run_in_takes_its_tau_bounds_from_the_rows_it_fits_not_the_held_out_ones():
    """A training fold's τ was bounded by the time span of the whole data set, held-out rows included, so what a
    fold could fit depended on the rows it was tested on. Fitted on the rows up to 6 h (τ of the data 10-25 h),
    τ now ends at the 6 h those rows span, exactly as when the other rows are not there at all."""
    data = _data("run_in", 101, ("6205", "6310"))
    train = np.flatnonzero(data.t <= 6.0)
    assert 0 < len(train) < len(data) and float(np.ptp(data.t)) > 100.0
    run_in = CANDIDATES["run_in"]
    in_fold = run_in.fit(data, train)
    alone = run_in.fit(data.take(train), np.arange(len(train)))
    assert in_fold["tau"] == pytest.approx(alone["tau"], rel=1e-12)
    assert in_fold["a"] == pytest.approx(alone["a"], rel=1e-12)
    assert in_fold["tau"] <= float(np.ptp(data.t[train])) * (1 + 1e-12)


def _churning_set():
    """A control set (6205, 6310, NU208-E, 3 % noise) with a churning loss growing as n^4 (dM^7): faster than the
    drag_losses candidate's p may reach (at most 3)."""
    table, _, _ = measured_set("none", 7, designations=["6205", "6310", "NU208-E"], noise=0.03)
    n = table["n [1/min]"].to_numpy()
    dM = (table["d [mm]"] + table["D [mm]"]).to_numpy() / 2
    raw = 1e-7 * dM ** 3 * (n * dM / 1000) ** 4.0
    table["M [N*mm]"] = table["M [N*mm]"] + 0.6 * raw / raw.max() * table["M [N*mm]"].max()
    return table


def test_a_parameter_that_ends_on_its_bound_is_marked_in_the_summary_report_and_console(tmp_path):
    """drag_losses fitted p = 3, the top of its range, and nothing said the value was a bound rather than an
    estimate. The summary, each candidate, report.md and the console now mark it."""
    diagnosis = diagnose_table(_churning_set())
    summary = write_outputs(diagnosis, tmp_path)
    assert summary["effect"] == "drag_losses"
    assert summary["parameters"]["p"] == 3.0
    assert summary["at_bound"] == {"c": None, "p": "upper"}
    candidates = summary["candidates"]
    assert candidates["viscosity_heating"]["parameters"]["R_th [K/W]"] == 0.0
    assert candidates["viscosity_heating"]["at_bound"] == {"R_th [K/W]": "lower"}   # (b is no fitted parameter)
    assert candidates["preload"]["parameters"]["F_pre [N]"]["6205"] == 0.0
    assert candidates["preload"]["at_bound"]["F_pre [N]"] == {"6205": "lower", "6310": None, "NU208-E": None}
    assert candidates["f0_scale"]["at_bound"] == {"k": None} and candidates["none"]["at_bound"] == {}
    report = (tmp_path / "report.md").read_text()
    assert ("On a bound of its fit: p (upper): the data would push it past the bound its fit keeps it within, so "
            "its value is that bound, not an estimate (at a lower bound of 0, or k = 1, the term is absent).") in report
    assert "| viscosity_heating | R_th [K/W]: 0, b [1/K]: 0.03; on a bound: R_th [K/W] (lower) |" in report
    assert summary_lines(summary, tmp_path)[1] == \
        "on a bound of its fit (the value is the bound, not an estimate): p (upper)"
    # the example's seal torques lie inside their bounds: nothing is marked
    example = diagnose_table(pd.read_csv(EXAMPLE)).summary()
    assert example["at_bound"] == {"M_seal [N*mm]": {b: None for b in ("6205", "6208", "6210", "6305")}}
    assert not any(line.startswith("on a bound") for line in summary_lines(example, tmp_path))


def test_the_report_shows_the_relative_error_the_choice_is_made_on_beside_the_rmse(tmp_path):
    """The choice is made on the relative error, the headline was the RMSE in N·mm only. On the example, f0_scale
    makes the RMSE worse (23.37 -> 24.75 N·mm) while it cuts the relative RMSE from 40.9 % to 26.8 %: the summary,
    report.md and the console now give both, before and after, fitted and held out, and say which the choice uses."""
    diagnosis = diagnose_table(pd.read_csv(EXAMPLE))
    summary = write_outputs(diagnosis, tmp_path)
    data = diagnosis.data
    assert summary["rel_rmse_before"] == pytest.approx(float(np.sqrt(np.mean(((data.M - data.MR) / data.M) ** 2))),
                                                       rel=1e-12)
    assert summary["rel_rmse_before"] == pytest.approx(0.409, abs=5e-4)
    assert summary["rel_rmse_after"] == pytest.approx(0.0419, abs=5e-5)
    seal = summary["candidates"]["seal_drag"]
    assert (summary["rel_rmse_after"], summary["cv_rel_rmse_after"]) == (seal["rel_rmse"], seal["cv_rel_rmse"])
    assert summary["choice_metric"] == "rel_rmse" and summary["units"]["rel_rmse"] == "1"
    f0_scale, none = summary["candidates"]["f0_scale"], summary["candidates"]["none"]
    assert f0_scale["rmse"] > none["rmse"] and f0_scale["rel_rmse"] < none["rel_rmse"]
    report = (tmp_path / "report.md").read_text()
    assert "| with the effect, held-out folds | 3.823 | 4.267 | 3.44 |  |" in report
    assert "| catalogue model, fitting data | 23.37 | 40.9 | 37.84 | 21.96 |" in report
    assert ("The choice uses the relative error (M measured − M model)/M measured: every candidate is fitted by least "
            "squares on it") in report
    assert summary_lines(summary, tmp_path)[2] == (
        "relative RMSE 40.9 -> 4.19 % (held-out 40.9 -> 4.27 %): the error the choice is made on")


# ---- the influence of single readings ----------------------------------------------------------------------

def test_leverage_of_a_seal_torque_and_of_an_f0_scale_is_their_hand_formula():
    """Both are linear in their parameter: e = (M − MR − M_seal[b])/M has the Jacobian −1/M on the rows of bearing
    b, so h = (1/M²)/Σ_b(1/M²) within each bearing; f0_scale's −M0/M gives h = (M0/M)²/Σ(M0/M)²."""
    data = _data("seal_drag", 101, ("6205", "6310"))
    rows = np.arange(len(data))
    seal, f0_scale = CANDIDATES["seal_drag"], CANDIDATES["f0_scale"]
    params = seal.fit(data, rows)
    h, p = leverage(seal, data, params, seal.predict(data, params, rows))
    w = 1.0 / data.M ** 2
    expected = w / np.bincount(data.bearing, weights=w)[data.bearing]
    assert p == 2
    np.testing.assert_allclose(h, expected, rtol=1e-5)
    assert h.sum() == pytest.approx(2.0, rel=1e-5)                # trace of the hat matrix: the parameters
    params = f0_scale.fit(data, rows)
    h, p = leverage(f0_scale, data, params, f0_scale.predict(data, params, rows))
    share = (data.M0 / data.M) ** 2
    assert p == 1
    np.testing.assert_allclose(h, share / share.sum(), rtol=1e-5)


def test_cooks_distance_is_the_shift_of_the_fit_without_the_reading():
    """For a fit linear in its parameter (f0_scale: M = MR + θ·M0), Cook's distance is exactly
    (θ − θ without the reading)²·Σ(M0/M)²/s² (Cook and Weisberg 1982, eq. 3.5.2): checked on the reading of the
    largest studentised residual against a refit without it."""
    data = _data("f0_scale", 202, ("6004", "6208"))
    rows = np.arange(len(data))
    f0_scale = CANDIDATES["f0_scale"]
    params = f0_scale.fit(data, rows)
    predicted = f0_scale.predict(data, params, rows)
    found = influence(f0_scale, data, params, predicted, [f"row {i + 1}" for i in rows], lambda i: "unused",
                      "f0_scale")
    top = found.readings[0]
    i = int(top["row"].split()[1]) - 1
    without = f0_scale.fit(data, rows[rows != i])
    residual = (data.M - predicted) / data.M
    s2 = float(residual @ residual) / (len(data) - 1)
    shift = (params["k"] - without["k"]) ** 2 * float(np.sum((data.M0 / data.M) ** 2)) / s2
    assert top["cooks_distance"] == pytest.approx(shift, rel=1e-4)
    assert found.flagged == 0 and found.dropped is None and found.warning is None


def _corrupted_seal_set():
    """The seal-drag set of seed 101 (6205, 6310, 30206-A, NU208-E; 504 readings) with the reading at position 17
    written at a tenth of its value (2.909 N·mm for 29.09): a slipped decimal."""
    table, _, _ = measured_set("seal_drag", 101, designations=["6205", "6310", "30206-A", "NU208-E"])
    clean = table.copy()
    table.loc[17, "M [N*mm]"] *= 0.1
    return clean, table


def test_one_corrupted_reading_that_flips_the_choice_is_flagged_and_warned_about(tmp_path, capsys):
    """Relative least squares let one reading at a tenth of its value turn a seal-drag set into 'drag_losses'
    without a word. The reading is now flagged (studentised residual −14.6, Bonferroni p 1e-37), the choice made
    without it is 'seal_drag', and the warning says so: in the summary, report.md, on stderr and by exit 1."""
    clean, corrupted = _corrupted_seal_set()
    assert diagnose_table(clean).effect == "seal_drag"
    diagnosis = diagnose_table(corrupted)
    assert diagnosis.effect == "drag_losses"
    summary = diagnosis.summary()
    found = summary["influence"]
    assert found["flagged"] == 1
    top = found["readings"][0]
    assert top["row"] == "row 18" and top["flagged"] and not found["readings"][1]["flagged"]
    assert top["M"] == pytest.approx(2.909, abs=5e-4)
    assert top["studentised"] == pytest.approx(-14.6, abs=0.05) and top["p_value"] < 1e-30
    assert (found["dropped"], found["effect_without"]) == ("row 18", "seal_drag")
    warning = ("one reading decides the choice: without row 18 (its studentised residual -14.6) the effect chosen is "
               "'seal_drag', not 'drag_losses'; check that reading")
    assert summary["warnings"] == [warning]
    # from a file: the reading is named by its line, as calc names rows
    path = tmp_path / "corrupted.csv"
    corrupted.to_csv(path, index=False)
    out = tmp_path / "out"
    out.mkdir()
    assert main(["diagnose", str(path), "--out-dir", str(out)]) == 1
    printed = capsys.readouterr()
    assert printed.err.strip() == f"bearingheat diagnose: warning: {warning.replace('row 18', 'row 19')}"
    assert ("1 reading(s) flagged as outliers, the largest row 19 (studentised residual -14.6); without it the "
            "effect chosen is 'seal_drag'") in printed.out.splitlines()
    report = (out / "report.md").read_text()
    assert f"**Warning: {warning.replace('row 18', 'row 19')}.**" in report
    assert "| row 19 | 2.909 | 16.77 | -4.76 |" in report


def test_clean_data_flag_no_reading_and_the_choice_is_made_once():
    diagnosis = diagnose_table(pd.read_csv(EXAMPLE))
    found = diagnosis.summary()["influence"]
    assert found["flagged"] == 0 and found["dropped"] is None and found["effect_without"] is None
    assert diagnosis.summary()["warnings"] == []
    assert found["n_params"] == 4 and len(found["readings"]) == 5
    assert max(abs(r["studentised"]) for r in found["readings"]) < 4.0
