"""bearingheat diagnose on the command line: the files it writes, exit codes, calc --effects."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from diagnose_cases import CASES, CONTROLS, run_case, small_table
from synthetic_torque import EFFECTS, model_set

from bearingheat.analysis.diagnose import error_metrics
from bearingheat.cli import main


def test_summary_and_report_files(tmp_path):
    table, noise, _ = run_case(*CASES[0])
    source = tmp_path / "measured.csv"
    table.to_csv(source, index=False)
    out = tmp_path / "diag"
    assert main(["diagnose", str(source), "--out-dir", str(out), "-q"]) == 0
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


def test_calc_cli_takes_the_effects(tmp_path, capsys):
    table, noise, diagnosis = run_case(*CASES[0])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out-dir", str(tmp_path / "d"), "-q"]) == 0
    result = tmp_path / "r.csv"
    assert main(["calc", str(source), "--effects", str(tmp_path / "d" / "summary.json"), "-o", str(result), "-q"]) == 0
    rmse = error_metrics(table["M [N*mm]"], pd.read_csv(result)["MR [N*mm]"])["rmse"]
    assert rmse == pytest.approx(diagnosis.summary()["rmse_after"], rel=1e-9)


def test_summary_missing_parameter(tmp_path, capsys):
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"effect": "drag_losses", "parameters": {"c": 1.0}}))
    source = tmp_path / "in.csv"
    small_table().to_csv(source, index=False)
    assert main(["calc", str(source), "--effects", str(path)]) == 2
    assert capsys.readouterr().err.strip() == (
        f"bearingheat calc: error: --effects {path}: effect 'drag_losses' needs the parameter 'p'")


def test_cli_too_few_rows_exit_2(tmp_path, capsys):
    source = tmp_path / "in.csv"
    small_table().to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out-dir", str(tmp_path / "o")]) == 2
    assert capsys.readouterr().err.strip() == (
        "bearingheat diagnose: error: diagnose needs at least 20 usable rows of measured torque; got 3")


def test_cli_excluded_rows_exit_1(tmp_path, capsys):
    table, noise, _ = run_case(*CONTROLS[0])
    table = table.copy()
    table["M [N*mm]"] = table["M [N*mm]"].astype(object)
    table.loc[0, "M [N*mm]"] = "broken"
    source = tmp_path / "in.csv"
    table.to_csv(source, index=False)
    assert main(["diagnose", str(source), "--out-dir", str(tmp_path / "o")]) == 1
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["excluded"] == ["row 2: 'broken' is not a number for M [N*mm]"]
    assert summary["effect"] == "none"


def test_subprocess_diagnose(tmp_path):
    table, noise, _ = run_case(*CASES[2])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    done = subprocess.run([sys.executable, "-m", "bearingheat", "diagnose", str(source), "--out-dir", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("effect: f0_scale")


def test_diagnose_model_all_compares_the_models_and_still_searches_the_effects(tmp_path, capsys):

    source = tmp_path / "skf_made.csv"
    model_set("skf", seed=21).to_csv(source, index=False)
    out = tmp_path / "d"
    assert main(["diagnose", str(source), "--out-dir", str(out), "--model", "all"]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert printed[0].startswith("skf fits these data better than schaeffler: held-out relative RMSE after fitting")
    assert {p.name for p in out.iterdir()} == {"models.md", "models.json", "models.png", "summary.json",
                                               "report.md", "residuals.png", "measured_vs_predicted.png"}
    summary = json.loads((out / "models.json").read_text())
    assert summary["best"] == "skf" and summary["residual"] == "measured - model"


def test_diagnose_model_skf_writes_only_the_comparison(tmp_path):

    source = tmp_path / "skf_made.csv"
    model_set("skf", seed=22).to_csv(source, index=False)
    out = tmp_path / "d"
    assert main(["diagnose", str(source), "--out-dir", str(out), "--model", "skf", "-q"]) == 0
    assert {p.name for p in out.iterdir()} == {"models.md", "models.json", "models.png"}


def test_the_residual_plot_draws_every_bearing():
    """The plot drew the first 10 bearings only; every row is drawn now, the legend names the 10 with the most
    rows and puts the rest under one entry."""
    from bearingheat.analysis.diagnose import CandidateScore, Diagnosis
    from bearingheat.analysis.effects import ModelData
    from bearingheat.io.reports.diagnose import residuals_figure

    rng = np.random.default_rng(3)
    bearing = np.repeat(np.arange(13), [5] * 10 + [2, 3, 4])   # 13 bearings, 62 rows
    N = len(bearing)
    n = rng.uniform(300.0, 5000.0, N)
    M = rng.uniform(10.0, 50.0, N)
    data = ModelData(M=M, M0=0.5 * M, M1=0.4 * M, M2=np.zeros(N), f0=np.full(N, 2.0), n=n, nu=np.full(N, 20.0),
                     dM=np.full(N, 40.0), Fr=np.full(N, 500.0), Fa=np.zeros(N), load=np.full(N, 500.0),
                     t=np.full(N, np.nan), T_oil=np.full(N, np.nan), bearing=bearing,
                     bearing_names=[f"b{i:02d}" for i in range(13)])
    none = CandidateScore("none", True, predicted=0.9 * M, cv_predicted=0.9 * M)
    diagnosis = Diagnosis(data, "none", {"none": none}, np.zeros(N, dtype=int), bearing, 5, [])
    fig, key = residuals_figure(diagnosis)
    assert key == "n"
    for ax in fig.axes:
        drawn = np.concatenate([c.get_offsets() for c in ax.collections])
        assert sorted(drawn[:, 0]) == sorted(n)
        np.testing.assert_allclose(sorted(drawn[:, 1]), sorted(np.full(N, 10.0)), rtol=1e-12)
    labels = [t.get_text() for t in fig.axes[1].get_legend().get_texts()]
    assert labels == [f"b{i:02d}" for i in range(10)] + ["3 other bearings"]
