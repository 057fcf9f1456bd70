"""The coefficient audit on awkward measured sets: no load, repeated readings, two lubrications of one bearing.

Every expected number is computed here by hand (numpy/scipy) from the
catalogue formulas, not by the code under test.
"""
from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
from scipy import stats

from bearingheat.analysis.audit import audit_coefficients, fit_linear_coefficients

#: 6208: d = 40, D = 80 mm, so dM = 60 mm
DM_6208 = 60.0


def _x0(n, nu, dM):
    """M0/f0 [N·mm] of the Schaeffler catalogue (ν·n >= 2000 in these sets): (ν·n)^(2/3)·dM³·1e-7."""
    nu_n = np.asarray(nu, dtype=float) * np.asarray(n, dtype=float)
    assert np.all(nu_n >= 2000)
    return nu_n ** (2.0 / 3.0) * dM ** 3 * 1e-7


def _wls(X, M, confidence=0.95):
    """Least squares on relative residuals by hand: rows scaled by 1/M, s^2 (A^T A)^-1, Student's t."""
    A = X / M[:, None]
    theta, *_ = np.linalg.lstsq(A, np.ones(len(M)), rcond=None)
    r = 1 - A @ theta
    dof = len(M) - X.shape[1]
    se = np.sqrt(np.diag(r @ r / dof * np.linalg.inv(A.T @ A)))
    half = stats.t.ppf(0.5 + confidence / 2, dof) * se
    return theta, se, theta - half, theta + half


def _catalogue_6208(n, nu, Fr, f0, C0=19000.0):
    """X0, X1 of a 6208 under radial load (P0 = P1 = Fr): M = f0*X0 + a1*X1, f1 = a1*(P0/C0)^0.5."""
    return np.column_stack([_x0(n, nu, DM_6208), (Fr / C0) ** 0.5 * Fr * DM_6208])


def test_two_lubrications_of_one_bearing_are_fitted_apart():
    """6208 in an oil bath (f0 = 2) and with grease (f0 = 1.3): pooled, f0 was compared with 1.65, the median
    of the two, and flagged; each lubrication is now its own fit against its own table value."""
    rng = np.random.default_rng(8)
    n, nu, Fr = (a.ravel() for a in np.meshgrid([500.0, 1000.0, 2000.0, 4000.0], [10.0, 30.0, 60.0],
                                                 [500.0, 2000.0]))
    parts = []
    for lubrication, f0 in (("oil_bath", 2.0), ("grease", 1.3)):
        X = _catalogue_6208(n, nu, Fr, f0)
        M = X @ np.array([f0, 0.0009]) * (1 + 0.03 * rng.standard_normal(len(n)))
        parts.append(pd.DataFrame({"designation": "6208", "d [mm]": 40, "D [mm]": 80, "C0 [N]": 19000.0,
                                   "lubrication": lubrication, "n [1/min]": n, "Fr [N]": Fr, "nu [mm^2/s]": nu,
                                   "M [N*mm]": M}))
    table = pd.concat(parts, ignore_index=True)
    result = audit_coefficients(table)
    assert list(zip(result["bearing"], result["lubrication"], result["coefficient"], result["table"])) == [
        ("6208", "grease", "f0", 1.3), ("6208", "grease", "f1_a", 0.0009),
        ("6208", "oil_bath", "f0", 2.0), ("6208", "oil_bath", "f1_a", 0.0009)]
    assert (result["rows"] == 24).all() and (result["status"] == "ok").all()
    for lubrication, f0 in (("grease", 1.3), ("oil_bath", 2.0)):
        rows = table[table["lubrication"] == lubrication]
        X = _catalogue_6208(rows["n [1/min]"].to_numpy(), rows["nu [mm^2/s]"].to_numpy(),
                            rows["Fr [N]"].to_numpy(), f0)
        theta, se, low, high = _wls(X, rows["M [N*mm]"].to_numpy())
        mine = result[result["lubrication"] == lubrication]
        np.testing.assert_allclose(mine["fitted"], theta, rtol=1e-7)
        np.testing.assert_allclose(mine["se"], se, rtol=1e-6)
        np.testing.assert_allclose(mine["ci_low"], low, rtol=1e-6)
        np.testing.assert_allclose(mine["ci_high"], high, rtol=1e-6)
        assert np.all((low <= [f0, 0.0009]) & ([f0, 0.0009] <= high)), lubrication
    assert (result["flag"] == "").all()


def test_no_load_spin_test_fits_f0_alone_and_says_why_f1_is_not_fitted():
    rng = np.random.default_rng(21)
    n, nu = (a.ravel() for a in np.meshgrid([500.0, 1000.0, 2000.0, 4000.0], [10.0, 30.0, 60.0]))
    M = 2.0 * _x0(n, nu, DM_6208) * (1 + 0.03 * rng.standard_normal(len(n)))
    table = pd.DataFrame({"designation": "6208", "lubrication": "oil_bath", "n [1/min]": n, "Fr [N]": 0.0,
                          "nu [mm^2/s]": nu, "M [N*mm]": M})
    with warnings.catch_warnings():
        warnings.simplefilter("error")                 # was a RuntimeWarning, then LinAlgError
        result = audit_coefficients(table).set_index("coefficient")
    assert result.loc["f1_a", "status"] == (
        "f1_a not fitted: the load is 0 in every row (12 rows), so M1 = 0 and the torque holds no information "
        "on f1_a; f0 fitted alone")
    assert np.isnan(result.loc["f1_a", "fitted"]) and result.loc["f1_a", "flag"] == ""
    # f0 alone: minimise sum(((M - f0*x)/M)^2), x = X0; closed form and s^2 (J^T J)^-1 with J = x/M
    u = _x0(n, nu, DM_6208) / M
    f0 = u.sum() / (u @ u)
    r = 1 - f0 * u
    se = np.sqrt(r @ r / (len(M) - 1) / (u @ u))
    half = stats.t.ppf(0.975, len(M) - 1) * se
    f0_row = result.loc["f0"]
    assert f0_row["status"] == "ok"
    np.testing.assert_allclose([f0_row["fitted"], f0_row["se"], f0_row["ci_low"], f0_row["ci_high"]],
                               [f0, se, f0 - half, f0 + half], rtol=1e-8)
    assert f0_row["ci_low"] <= 2.0 <= f0_row["ci_high"] and f0_row["flag"] == ""


# ---- repeated readings: the operating point is the unit ------------------------------------------

#: (designation, d, D, C0, table f0 in an oil bath) of the repeated-readings set
REPEATED = (("6205", 25.0, 52.0, 7800.0, 2.0), ("6310", 50.0, 110.0, 38000.0, 2.3))


def _one_reading_per_point(seed=1):
    """Two deep groove ball bearings, 30 operating points each, M from the catalogue formulas with 3 % noise."""
    rng = np.random.default_rng(seed)
    parts, designs = [], {}
    for des, d, D, C0, f0 in REPEATED:
        n, nu, load = (a.ravel() for a in np.meshgrid([500.0, 1000.0, 2000.0, 3000.0, 4000.0], [10.0, 30.0, 60.0],
                                                      [0.02, 0.06], indexing="ij"))
        Fr = load * C0
        dM = (d + D) / 2
        X = np.column_stack([_x0(n, nu, dM), (Fr / C0) ** 0.5 * Fr * dM])
        M = X @ np.array([f0, 0.0009]) * (1 + 0.03 * rng.standard_normal(len(n)))
        designs[des] = (X, M)
        parts.append(pd.DataFrame({"designation": des, "d [mm]": d, "D [mm]": D, "C0 [N]": C0,
                                   "lubrication": "oil_bath", "n [1/min]": n, "Fr [N]": Fr, "nu [mm^2/s]": nu,
                                   "M [N*mm]": M}))
    return pd.concat(parts, ignore_index=True), designs


def test_one_reading_per_point_gives_the_intervals_of_the_rows():
    table, designs = _one_reading_per_point()
    result = audit_coefficients(table)
    assert (result["points"] == 30).all() and (result["rows"] == 30).all()
    for des, (X, M) in designs.items():
        theta, se, low, high = _wls(X, M)
        mine = result[result["bearing"] == des]
        np.testing.assert_allclose(mine["fitted"], theta, rtol=1e-7)
        np.testing.assert_allclose(mine[["se", "ci_low", "ci_high"]].to_numpy().T, [se, low, high], rtol=1e-6)


def test_four_copies_of_every_row_leave_the_intervals_and_flags_as_they_were():
    """Counted as rows, 4 copies halved every se and put 6310's table f1_a = 0.0009 outside its interval."""
    table, _ = _one_reading_per_point()
    once = audit_coefficients(table)
    four = audit_coefficients(pd.concat([table] * 4, ignore_index=True))
    assert (four["rows"] == 120).all() and (four["points"] == 30).all()
    for column in ("fitted", "se", "ci_low", "ci_high", "rel_rmse"):
        np.testing.assert_allclose(four[column], once[column], rtol=1e-9, err_msg=column)
    assert list(four["flag"]) == list(once["flag"])


def test_a_group_column_makes_its_rows_one_point():
    """The user's 'group' (as in diagnose): here each pair of neighbouring speeds is one point; the fit is on
    the pairs' means, by hand."""
    table, designs = _one_reading_per_point()
    table["group"] = [f"{des}-{i // 2}" for des, i in zip(table["designation"], table.groupby("designation").cumcount())]
    result = audit_coefficients(table)
    assert (result["points"] == 15).all()
    X, M = designs["6205"]
    pairs = np.arange(30) // 2
    X_mean = np.column_stack([np.bincount(pairs, X[:, j]) / 2 for j in range(2)])
    theta, se, low, high = _wls(X_mean, np.bincount(pairs, M) / 2)
    mine = result[result["bearing"] == "6205"]
    np.testing.assert_allclose(mine[["fitted", "se", "ci_low", "ci_high"]].to_numpy().T, [theta, se, low, high],
                               rtol=1e-6)


def test_intervals_with_repeated_readings_cover_the_truth_about_95_percent():
    """15 points of 4 readings: a deviation per point (3 %) and per reading (2 %). Fitted on the point means
    the 95 % intervals cover the truth within the binomial tolerance of 300 runs (3 standard deviations);
    counted as 60 independent rows they covered about 75 %."""
    rng = np.random.default_rng(12)
    truth = np.array([1.5, 0.002])
    runs, covered, naive = 300, np.zeros(2), np.zeros(2)
    groups = np.repeat(np.arange(15), 4)
    for _ in range(runs):
        X = np.repeat(np.column_stack([rng.uniform(1, 10, 15), rng.uniform(100, 1000, 15)]), 4, axis=0)
        deviation = np.repeat(0.03 * rng.standard_normal(15), 4) + 0.02 * rng.standard_normal(60)
        M = X @ truth * (1 + deviation)
        fit = fit_linear_coefficients(X, M, groups=groups)
        covered += (fit["low"] <= truth) & (truth <= fit["high"])
        rows = fit_linear_coefficients(X, M)
        naive += (rows["low"] <= truth) & (truth <= rows["high"])
    tolerance = 3 * np.sqrt(0.95 * 0.05 / runs)
    assert np.all(np.abs(covered / runs - 0.95) <= tolerance), covered / runs
    assert np.all(naive / runs < 0.85), naive / runs


def test_one_group_for_all_rows_leaves_no_interval_and_says_so():
    table, _ = _one_reading_per_point()
    result = audit_coefficients(table.assign(group="A"))
    assert (result["points"] == 1).all() and result["fitted"].isna().all()
    assert set(result["status"]) == {
        "1 operating point (30 rows) for 2 coefficients: need more than 2 for an interval (the rows of one "
        "operating point, or of one group of the 'group' column, count once)"}
