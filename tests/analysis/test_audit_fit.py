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
