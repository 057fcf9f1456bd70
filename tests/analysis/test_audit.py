"""bearingheat audit: coefficients against measured torque; n_thr of the tables against the catalogue."""
from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from synthetic_catalogue import synthetic_catalogue
from synthetic_torque import measured_set

from bearingheat.analysis.audit import (ROUNDING_STEPS, AuditError, audit_coefficients, audit_reference_speeds,
                                        classify_reference_speeds, fit_linear_coefficients, implied_coefficients,
                                        rounding_step, series_deviation_summary)
from bearingheat.analysis.deviations import change_point, local_residuals, median_interval
from bearingheat.calc.thermal import thermal_reference_speed_details

#: the HR 1 (2006) list lives next to the repository, in ../shared/data (hr1_2006_reference_speeds.md)
HR1 = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "hr1_2006_reference_speeds.csv"


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
    summary = series_deviation_summary(rows).set_index("group")
    assert summary["systematic"].to_dict() == {"a": True, "b": False, "c": False}
    assert summary.loc["c", "note"] == "3 bearings: too few to judge"


# ---- robust statistics ------------------------------------------------------------------------

def test_change_point_finds_a_step_under_noise_and_a_misprint():
    rng = np.random.default_rng(7)
    d = np.arange(40.0)
    x = np.where(d < 23, -0.18, 0.0) + 0.004 * rng.standard_normal(40)
    x[5] = 0.4                                     # a misprint does not move the split
    assert change_point(x, d, min_size=5) == 23


def test_change_point_never_cuts_between_variants_of_one_size():
    d = np.array([1, 2, 3, 3, 4, 5, 6, 7, 8, 9], dtype=float)
    x = np.array([0, 0, 0, 1, 1, 1, 1, 1, 1, 1], dtype=float)
    assert change_point(x, d, min_size=2) in (2, 4)


def test_local_residuals_follow_a_trend_and_expose_a_misprint():
    d = np.arange(1.0, 31.0)
    x = 0.2 - 0.004 * d                            # a drift along the series is no outlier
    x[14] *= 1.4
    r = local_residuals(x, d)
    assert abs(r[14]) > 0.04
    assert np.all(np.abs(np.delete(r, 14)) < 0.02)


def test_median_interval_covers_about_95_percent():
    rng = np.random.default_rng(11)
    covered = [lo <= 0.0 <= hi for lo, hi in
               (median_interval(rng.standard_normal(25))[1:3] for _ in range(400))]
    assert 0.93 <= np.mean(covered) <= 0.995


def test_median_interval_widens_for_rounded_values():
    values = np.arange(1.0, 12.0)
    plain = median_interval(values)
    rounded = median_interval(values, values - 0.5, values + 0.5)
    assert rounded[0] == plain[0]
    assert (rounded[1], rounded[2]) == (plain[1] - 0.5, plain[2] + 0.5)
    assert median_interval([1.0, 2.0, 3.0])[1:] == (1.0, 3.0, 0.75)   # too few for 95 %: the range, 75 %


# ---- rounding and implied coefficients ---------------------------------------------------------

def test_rounding_step_by_magnitude_and_digits():
    assert ROUNDING_STEPS[-1][1] == 500.0
    steps = rounding_step([57000, 46500, 23400, 9300, 4750, 4350, 2410, 980, 455, 1234.5, np.nan])
    assert steps[:-1].tolist() == [500.0, 500.0, 100.0, 100.0, 50.0, 50.0, 10.0, 10.0, 5.0, 0.0]
    assert np.isnan(steps[-1])


def test_implied_f0_and_f1_give_back_the_tables_at_the_computed_speed():
    table = pd.DataFrame({"designation": ["6205", "NU206-E", "30205-A", "7205-B"], "d [mm]": [25, 30, 25, 25],
                          "D [mm]": [52, 62, 52, 52], "B [mm]": [15, 16, 15, 15], "T [mm]": [np.nan, np.nan, 16.25,
                                                                                              np.nan],
                          "C0 [N]": [7800, 36000, 34500, 9300], "n_thr [1/min]": [14400, 9800, 9100, 13600]})
    rows = audit_reference_speeds(table)
    details = thermal_reference_speed_details(pd.DataFrame(
        {"designation": table["designation"], "d": table["d [mm]"], "D": table["D [mm]"], "B": table["B [mm]"],
         "T": table["T [mm]"], "C0": table["C0 [N]"]}))
    back = implied_coefficients(details, table["d [mm]"], table["D [mm]"], rows["n_thr_tables"])
    np.testing.assert_allclose(back["f0"], rows["f0_table"], rtol=1e-9)
    np.testing.assert_allclose(back["f1"], rows["f1_table"], rtol=1e-9)
    # a published speed below the computed one implies more friction; the interval brackets the value
    assert (rows["f0_implied_low"] <= rows["f0_implied"]).all()
    assert (rows["f0_implied"] <= rows["f0_implied_high"]).all()
    slower = rows["n_thr_published"] < rows["n_thr_tables"]
    assert ((rows["f0_implied"] > rows["f0_table"]) == slower).all()


# ---- synthetic catalogues made from the tables -------------------------------------------------

def test_synthetic_catalogue_without_changes_flags_nothing():
    audit = classify_reference_speeds(audit_reference_speeds(synthetic_catalogue()))
    assert audit.flagged.empty
    assert audit.outliers.empty
    assert (audit.groups["subgroup"] == "").all()
    consistent = audit.groups
    inside = (consistent["f0_implied_low"] <= consistent["f0_table"]) & (consistent["f0_table"]
                                                                          <= consistent["f0_implied_high"])
    assert inside.all()


def test_synthetic_catalogue_recovers_each_change_and_nothing_else():
    catalogue = synthetic_catalogue(f0_factor={("tapered roller 302", 0): 4.0 / 3.0,
                                               ("cylindrical roller 22", 100): 0.8},
                                    misprints={"6208": 1.4})
    audit = classify_reference_speeds(audit_reference_speeds(catalogue))
    flagged = audit.flagged.set_index("group")
    assert list(flagged.index) == ["cylindrical roller 22 d 100-380 mm", "tapered roller 302"]
    # the whole series: the f0 of the change, inside its interval
    assert flagged.loc["tapered roller 302", "f0_implied"] == pytest.approx(4.0, rel=0.01)
    assert flagged.loc["tapered roller 302", "f0_implied_low"] <= 4.0 <= flagged.loc["tapered roller 302",
                                                                                     "f0_implied_high"]
    # one size class: split at the changed bore, the class flagged and the rest of the series not
    f22 = flagged.loc["cylindrical roller 22 d 100-380 mm"]
    assert f22["f0_implied"] == pytest.approx(2.4, rel=0.01)
    assert f22["f0_implied_low"] <= 2.4 <= f22["f0_implied_high"]
    groups = audit.groups.set_index("group")
    assert not groups.loc["cylindrical roller 22", "systematic"]
    assert not groups.loc["cylindrical roller 22 d 17-95 mm", "systematic"]
    assert set(audit.groups.loc[audit.groups["subgroup"] != "", "series"]) == {"22"}
    # the misprint: listed, series 62 not flagged
    assert list(audit.outliers["designation"]) == ["6208"]
    assert audit.outliers["deviation"].iloc[0] == pytest.approx(1 / 1.4 - 1, abs=0.01)
    assert not groups.loc["deep groove ball 62", "systematic"]


def test_a_misprint_in_a_deviating_series_is_an_outlier_and_the_series_still_flagged():
    catalogue = synthetic_catalogue(f0_factor={("tapered roller 313", 0): 0.66}, misprints={"31310-A": 0.6})
    audit = classify_reference_speeds(audit_reference_speeds(catalogue))
    assert list(audit.flagged["group"]) == ["tapered roller 313"]
    assert list(audit.outliers["designation"]) == ["31310-A"]
    assert audit.flagged["f0_implied"].iloc[0] == pytest.approx(4.5 * 0.66, rel=0.01)


# ---- the HR 1 (2006) list ----------------------------------------------------------------------

@pytest.fixture(scope="module")
def hr1_audit():
    if not HR1.is_file():
        pytest.skip(f"{HR1} is not present: the HR 1 (2006) list is read from ../shared/data next to the repository")
    rows = audit_reference_speeds(pd.read_csv(HR1))
    return rows, classify_reference_speeds(rows)


def test_hr1_every_bearing_is_computed(hr1_audit):
    rows, audit = hr1_audit
    assert len(rows) == 1034
    assert rows["n_thr_tables"].notna().all()


def test_hr1_series_pool_their_variants(hr1_audit):
    rows, audit = hr1_audit
    groups = audit.groups.set_index("group")
    assert groups.loc["deep groove ball 62", "variants"] == "open, 2Z"
    assert groups.loc["deep groove ball 618", "bearings"] == 50
    assert not any("2Z" in key for key in rows["series_key"])


def test_hr1_series_that_agree(hr1_audit):
    rows, audit = hr1_audit
    groups = audit.groups.set_index("group")
    # The Schaeffler catalogue rows of these series reproduce the catalogue's own n_thr within 1.5 % (median)
    for key in ("deep groove ball 62", "deep groove ball 63", "deep groove ball 160", "deep groove ball 64",
                "cylindrical roller 2", "cylindrical roller 3", "cylindrical roller 22", "cylindrical roller 23",
                "tapered roller 302", "tapered roller 303", "tapered roller 322", "tapered roller 323",
                "angular contact ball 72", "angular contact ball 73", "deep groove ball 60 d 150-360 mm",
                "deep groove ball 618 d 320-850 mm"):
        assert abs(groups.loc[key, "median_deviation"]) < 0.015, key
        assert not groups.loc[key, "systematic"], key
        assert groups.loc[key, "f0_implied_low"] <= groups.loc[key, "f0_table"] * 1.03, key


#: the issue's implied f0 (backed out by hand) of every group HR 1 (2006) publishes off the tables
HR1_IMPLIED_F0 = {"deep groove ball 60 d 7-140 mm": 1.59, "deep groove ball 618 d 45-140 mm": 1.21,
                  "tapered roller 313": 2.99, "tapered roller 320": 4.50, "tapered roller 330": 6.07,
                  "tapered roller 331": 6.03, "tapered roller 332": 6.02}


def test_hr1_flags_exactly_the_deviating_groups(hr1_audit):
    rows, audit = hr1_audit
    assert set(audit.flagged["group"]) == set(HR1_IMPLIED_F0)
    groups = audit.groups.set_index("group")
    # 60 and 618 deviate in their small sizes only: the classes are flagged, the series and large sizes not
    for series, small, large in (("60", "d 7-140 mm", "d 150-360 mm"), ("618", "d 45-140 mm", "d 320-850 mm")):
        assert not groups.loc[f"deep groove ball {series}", "systematic"]
        assert groups.loc[f"deep groove ball {series}", "note"] == "the deviation lies in one size class"
        assert groups.loc[f"deep groove ball {series} {small}", "variants"] == "open, 2Z"
    assert groups.loc["deep groove ball 618 d 45-140 mm", "bearings"] == 31
    assert groups.loc["tapered roller 330", "median_deviation"] == pytest.approx(0.289, abs=0.01)
    assert groups.loc["tapered roller 313", "median_deviation"] == pytest.approx(-0.154, abs=0.01)


@pytest.mark.parametrize("group", sorted(HR1_IMPLIED_F0))
def test_hr1_implied_f0(hr1_audit, group):
    rows, audit = hr1_audit
    found = audit.groups.set_index("group").loc[group]
    expected = HR1_IMPLIED_F0[group]
    assert found["f0_implied"] == pytest.approx(expected, rel=0.03)
    assert found["f0_implied_low"] <= expected <= found["f0_implied_high"]
    assert found["f0_implied_low"] <= found["f0_implied"] <= found["f0_implied_high"]


def test_hr1_spread_is_noted_for_60_only(hr1_audit):
    rows, audit = hr1_audit
    flagged = audit.flagged.set_index("group")
    assert list(flagged.index[~flagged["single_f0"]]) == ["deep groove ball 60 d 7-140 mm"]
    assert "no single f0 reproduces the group" in flagged.loc["deep groove ball 60 d 7-140 mm", "note"]
    # the large 618 bearings imply the table value
    large = audit.groups.set_index("group").loc["deep groove ball 618 d 320-850 mm"]
    assert large["f0_implied"] == pytest.approx(1.70, rel=0.01)


def test_hr1_outliers_are_single_rows_the_catalogue_itself_contradicts(hr1_audit):
    rows, audit = hr1_audit
    outliers = set(audit.outliers["designation"])
    # NJ311 prints n_B 6000 where N/NU/NUP311 print 5600; NJ309 prints a lower C0 than N/NU/NUP309;
    # 32015-X prints 3350 between 3250 (32014-X) and 2950 (32016-X) (hr1_2006_reference_speeds.md)
    assert {"NJ311-E-TVP2", "NJ309-E-TVP2", "32015-X"} <= outliers
    assert len(outliers) <= 12
    assert not rows.loc[rows["designation"].isin(["NU311-E-TVP2", "NUP311-E-TVP2"])].empty
    marked = audit.bearings.set_index("designation")
    assert not marked.loc["NU311-E-TVP2", "outlier"]


def test_linear_fit_without_residual_dof_has_no_intervals_and_no_warning():
    X = np.array([[1.0, 1.0], [1.0, 2.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fit = fit_linear_coefficients(X, X @ np.array([2.0, 0.5]))
    np.testing.assert_allclose(fit["theta"], [2.0, 0.5], rtol=1e-12)
    assert fit["dof"] == 0
    assert np.isnan(fit["se"]).all() and np.isnan(fit["low"]).all() and np.isnan(fit["high"]).all()
