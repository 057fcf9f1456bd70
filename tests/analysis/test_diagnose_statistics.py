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
