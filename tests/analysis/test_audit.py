"""bearingheat audit: coefficients against measured torque; n_thr of the tables against the catalogue."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from synthetic_torque import measured_set

from bearingheat.analysis.audit import (AuditError, audit_coefficients, audit_reference_speeds,
                                        fit_linear_coefficients, series_deviation_summary)

HR1 = Path(__file__).resolve().parents[3] / "shared" / "data" / "hr1_2006_reference_speeds.csv"


def test_linear_fit_matches_weighted_normal_equations():
    rng = np.random.default_rng(3)
    X = np.column_stack([rng.uniform(1, 10, 40), rng.uniform(1, 100, 40)])
    M = X @ np.array([2.0, 0.03]) * (1 + 0.03 * rng.standard_normal(40))
    fit = fit_linear_coefficients(X, M)
    W = 1.0 / M
    reference, *_ = np.linalg.lstsq(X * W[:, None], np.ones(40), rcond=None)
    np.testing.assert_allclose(fit["theta"], reference, rtol=1e-10)
    assert fit["dof"] == 38
    assert np.all(fit["low"] < fit["theta"]) and np.all(fit["theta"] < fit["high"])


def test_intervals_cover_the_truth_about_95_percent():
    rng = np.random.default_rng(4)
    truth = np.array([1.5, 0.002])
    covered = 0
    for _ in range(200):
        X = np.column_stack([rng.uniform(1, 10, 30), rng.uniform(100, 1000, 30)])
        M = X @ truth * (1 + 0.04 * rng.standard_normal(30))
        fit = fit_linear_coefficients(X, M)
        covered += bool(fit["low"][0] <= truth[0] <= fit["high"][0])
    assert 0.90 <= covered / 200 <= 0.99


def test_table_values_hold_on_catalogue_data():
    table, _, _ = measured_set("none", 3, designations=["30206-A", "6004", "6310", "NU208-E"])
    result = audit_coefficients(table)
    assert list(result["coefficient"]) == ["f0", "f1", "f0", "f1_a", "f0", "f1_a", "f0", "f1"]
    assert list(result["table"]) == [3.0, 0.0004, 1.7, 0.0007, 2.3, 0.0009, 2.0, 0.0003]
    assert (result["status"] == "ok").all()
    assert (result["flag"] == "").all()
    np.testing.assert_allclose(result["fitted"], result["table"], rtol=0.05)


def test_raised_f0_is_flagged_and_measured():
    table, _, _ = measured_set("f0_scale", 3, designations=["30206-A", "6004", "6310", "NU208-E"])
    result = audit_coefficients(table)
    f0 = result[result["coefficient"] == "f0"]
    assert (f0["flag"] == "table value outside the 95% interval").all()
    ratio = (f0["fitted"] / f0["table"]).to_numpy()
    np.testing.assert_allclose(ratio, ratio.mean(), rtol=0.03)   # one k for all bearings
    assert 2.0 < ratio.mean() < 3.0


def test_f2_is_fitted_for_axially_loaded_nj():
    rng = np.random.default_rng(5)
    rows = []
    for n in (500.0, 1500.0, 3000.0, 4500.0):
        for fr in (3000.0, 8000.0):
            for fa in (0.0, 600.0, 1200.0):
                rows.append({"designation": "NJ208-E", "d [mm]": 40, "D [mm]": 80, "lubrication": "oil_bath",
                             "n [1/min]": n, "Fr [N]": fr, "Fa [N]": fa, "nu [mm^2/s]": 20.0})
    table = pd.DataFrame(rows)
    dM = 60.0
    M0 = 2.0 * (20.0 * table["n [1/min]"]) ** (2 / 3) * dM ** 3 * 1e-7
    table["M [N*mm]"] = (M0 + 0.0003 * table["Fr [N]"] * dM + 0.006 * table["Fa [N]"] * dM) * (
        1 + 0.01 * rng.standard_normal(len(table)))
    result = audit_coefficients(table).set_index("coefficient")
    assert list(result.index) == ["f0", "f1", "f2"]
    assert np.isnan(result.loc["f2", "table"])           # read off a chart: no table value
    assert result.loc["f2", "ci_low"] < 0.006 < result.loc["f2", "ci_high"]


def test_inseparable_coefficients_are_reported():
    table = pd.DataFrame({"designation": ["6205"] * 4, "d [mm]": 25, "D [mm]": 52, "C0 [N]": 7800,
                          "lubrication": "oil_bath", "n [1/min]": 3000.0, "Fr [N]": 1000.0,
                          "nu [mm^2/s]": 12.0, "M [N*mm]": [20.0, 21.0, 19.0, 20.5]})
    result = audit_coefficients(table)
    assert list(result["status"].unique()) == [
        "the coefficients cannot be separated: f0, f1_a need rows where n·ν and the load vary independently"]


def test_missing_published_speed_column():
    with pytest.raises(AuditError, match=re.escape(
            "missing column: the published thermal reference speed, e.g. 'n_thr [1/min]' "
            "(accepted names: n_thr, n_B, n_theta_r, n_θr, n_ref, nthr)")):
        audit_reference_speeds(pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52]}))


def test_any_catalogue_list_works():
    """Another maker's list: type + series instead of designations, speed in rpm, C0 in kN."""
    table = pd.DataFrame({"type": ["deep_groove_ball"] * 2, "series": ["62", "62"], "d [mm]": [25, 30],
                          "D [mm]": [52, 62], "B [mm]": [15, 16], "C0 [kN]": [7.8, 11.2],
                          "n_thr [rpm]": [14400, 12000]})
    rows = audit_reference_speeds(table)
    assert list(rows["series_key"]) == ["deep_groove_ball 62", "deep_groove_ball 62"]
    assert np.all(np.abs(rows["deviation"]) < 0.02)


def test_systematic_rule():
    rows = pd.DataFrame({"series_key": ["a"] * 6 + ["b"] * 6 + ["c"] * 3,
                         "deviation": [0.2] * 6 + [0.2, -0.2, 0.2, -0.2, 0.2, -0.2] + [0.5] * 3})
    summary = series_deviation_summary(rows).set_index("series_key")
    assert summary["systematic"].to_dict() == {"a": True, "b": False, "c": False}


@pytest.fixture(scope="module")
def hr1_audit():
    if not HR1.is_file():
        pytest.skip(f"{HR1} is not present")
    rows = audit_reference_speeds(pd.read_csv(HR1))
    return rows, series_deviation_summary(rows).set_index("series_key")


def test_hr1_every_bearing_is_computed(hr1_audit):
    rows, summary = hr1_audit
    assert len(rows) == 1034
    assert rows["n_thr_tables"].notna().all()


def test_hr1_series_that_agree(hr1_audit):
    rows, summary = hr1_audit
    # the seed 002 rows of these series reproduce the catalogue's own n_thr within 1.5 % (median)
    for key in ("deep groove ball 62", "deep groove ball 63", "deep groove ball 160", "cylindrical roller 2",
                "cylindrical roller 3", "cylindrical roller 22", "cylindrical roller 23", "tapered roller 302",
                "tapered roller 322", "angular contact ball 72", "angular contact ball 73"):
        assert abs(summary.loc[key, "median"]) < 0.015, key
        assert not summary.loc[key, "systematic"]


def test_hr1_series_that_deviate_systematically(hr1_audit):
    rows, summary = hr1_audit
    flagged = set(summary.index[summary["systematic"]])
    assert flagged == {"deep groove ball 618 -2Z", "tapered roller 313", "tapered roller 320",
                       "tapered roller 330", "tapered roller 331", "tapered roller 332"}
    assert summary.loc["tapered roller 330", "median"] == pytest.approx(0.289, abs=0.01)
    assert summary.loc["tapered roller 313", "median"] == pytest.approx(-0.154, abs=0.01)
