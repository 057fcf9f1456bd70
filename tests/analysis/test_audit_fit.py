"""The coefficient audit on awkward measured sets: no load, repeated readings, two lubrications of one bearing.

Every expected number is computed here by hand (numpy/scipy) from the
catalogue formulas, not by the code under test.
"""
from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
from scipy import stats

from bearingheat.analysis.audit import audit_coefficients

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
