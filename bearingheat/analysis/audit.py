"""Coefficient audit: measured torque against the tables (the first audit of ``bearingheat audit``).

:func:`audit_coefficients` fits f0 and f1 (and f2 where a cylindrical
roller bearing with ribs carries Fa) for each bearing of a measured data
set (the columns of ``calc`` plus ``M [N*mm]``) by least squares with
``scipy.optimize.curve_fit``, gives 95 % confidence intervals from the
Jacobian and flags the Schaeffler catalogue table values that lie outside them.

The model is linear in the coefficients (the Schaeffler catalogue, pp. 64-70)::

    M = f0·X0 + a1·X1 + f2·X2,  X0 = M0/f0 = g(ν·n)·dM³·1e-7,
    X1 = M1/a1 = load·dM·(P0/C0 or Fa/C0)^x,  X2 = Fa·dM

where a1 is the f1 constant of the table (f1 itself for constant-f1 types;
for f1 = a1·(P0/C0)^x it is a1). The residuals are relative,
(M − model)/M, so bearings and speeds of any size weigh alike.

The second audit, the tables against a catalogue's own thermal reference
speeds, is :mod:`bearingheat.analysis.reference_speeds`; its names are
imported here too.
"""
from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd
from scipy import optimize, stats

from bearingheat.analysis.deviations import CONFIDENCE
from bearingheat.analysis.diagnose import model_data, operating_point_groups, read_measurements
from bearingheat.analysis.effects import catalogue_arrays
from bearingheat.analysis.reference_speeds import (GROUP_COLUMNS, REFERENCE_SPEED_COLUMNS, ROUNDING_STEPS,
                                                   SYSTEMATIC_RULE, ReferenceSpeedAudit, audit_reference_speeds,
                                                   classify_reference_speeds, implied_coefficients, rounding_step,
                                                   series_deviation_summary)
from bearingheat.errors import AuditError, DiagnoseError

__all__ = [
    "AuditError",
    "CONFIDENCE",
    "SYSTEMATIC_RULE",
    "ROUNDING_STEPS",
    "REFERENCE_SPEED_COLUMNS",
    "GROUP_COLUMNS",
    "ReferenceSpeedAudit",
    "fit_linear_coefficients",
    "point_means",
    "audit_coefficients",
    "audit_reference_speeds",
    "rounding_step",
    "implied_coefficients",
    "classify_reference_speeds",
    "series_deviation_summary",
]


# ---------------------------------------------------------------------------------------------
# Coefficient fit
# ---------------------------------------------------------------------------------------------

def fit_linear_coefficients(X: npt.ArrayLike, M: npt.ArrayLike, *, groups: npt.ArrayLike | None = None,
                            confidence: float = CONFIDENCE) -> dict[str, Any]:
    """Least squares fit of M = X·θ on relative residuals (M − X·θ)/M, with confidence intervals.

    Uses ``scipy.optimize.curve_fit`` (trust region reflective, σ = M) on the
    exact Jacobian X/M; its covariance is s²·(JᵀJ)⁻¹ with
    s² = Σr²/(N − p), and the interval is θ ± t(1 − α/2, N − p)·se.

    ``groups`` (a label per row: its operating point) makes the operating
    point the unit of the fit: the rows of a group are replaced by their
    mean (of M and of each column of X; the model is linear, so the means
    follow it exactly) and N is the number of groups. Repeated readings at
    one point share its deviation (the rig's setting, the oil's temperature)
    and are no independent evidence of the coefficients: counted as rows,
    four copies of a data set would halve every interval. A cluster-robust
    (sandwich) covariance over the groups was not chosen: with the few
    operating points of a bearing test it is biased low unless corrected
    (CR2 with Satterthwaite degrees of freedom), and with one reading per
    point it is White's HC0, not s²·(JᵀJ)⁻¹, so it would change the
    intervals of data without repeats. Fitting the means leaves those
    unchanged (every row its own group) and gives a set copied k times the
    same intervals. Points with more readings weigh alike; the means'
    noise is then slightly unequal, which the interval ignores.

    >>> X = np.array([[1.0, 1.0], [1.0, 2.0], [1.0, 3.0], [1.0, 4.0]])
    >>> fit = fit_linear_coefficients(X, X @ np.array([2.0, 0.5]))
    >>> np.round(fit["theta"], 10).tolist(), fit["dof"]
    ([2.0, 0.5], 2)
    """
    if groups is not None:
        X, M = point_means(X, M, groups)
    X = np.asarray(X, dtype=float)
    M = np.asarray(M, dtype=float)
    N, p = X.shape
    theta0, *_ = np.linalg.lstsq(X / M[:, None], np.ones(N), rcond=None)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", optimize.OptimizeWarning)  # no covariance without dof: NaN below
        theta, cov = optimize.curve_fit(lambda x, *th: x @ np.asarray(th), X, M, p0=theta0, sigma=M,
                                        jac=lambda x, *th: x, method="trf", xtol=1e-14, ftol=1e-14, gtol=1e-14)
    residual = (M - X @ theta) / M
    dof = N - p
    sse = float(residual @ residual)
    if dof > 0:
        se = np.sqrt(np.diag(cov))
        half = stats.t.ppf(0.5 + confidence / 2.0, dof) * se
    else:
        se = np.full(p, np.nan)
        half = np.full(p, np.nan)
    return {"theta": theta, "se": se, "low": theta - half, "high": theta + half, "dof": dof,
            "rel_rmse": math.sqrt(sse / N)}


def point_means(X: npt.ArrayLike, M: npt.ArrayLike, groups: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The mean of the rows of X and of M in each group (groups in order of first appearance).

    >>> point_means([[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]], [1.0, 3.0, 5.0], ["a", "a", "b"])[1].tolist()
    [2.0, 5.0]
    """
    X = np.asarray(X, dtype=float)
    M = np.asarray(M, dtype=float)
    codes, _ = pd.factorize(pd.Series(np.asarray(groups), dtype=object))
    counts = np.bincount(codes).astype(float)
    means = np.column_stack([np.bincount(codes, weights=X[:, j]) / counts for j in range(X.shape[1])])
    return means.reshape(len(counts), X.shape[1]), np.bincount(codes, weights=M) / counts


def audit_coefficients(table: pd.DataFrame, *, confidence: float = CONFIDENCE) -> pd.DataFrame:
    """Fit f0, f1 (and f2) for each bearing of a measured table and compare them with the tables.

    A bearing is fitted once per distinct set of table coefficients (its rows
    with the same table f0, f1 constant and given f2, :func:`_fit_sets`):
    one bearing run in an oil bath and with grease gives two fits, each
    compared with its own table values.

    Returns one row per fit and coefficient: ``bearing``, ``lubrication``
    (the lubrication of the fit's rows, '' where not given), ``coefficient``
    (f0, f1 or f1_a, f2), ``table`` (the Schaeffler catalogue value, NaN for f2 read off
    a chart), ``fitted``, ``se``, ``ci_low``, ``ci_high``, ``rows``, ``points``
    (operating points: the rows' distinct bearing, n, ν, Fr, Fa, T_oil, or
    the user's ``group`` labels),
    ``rel_rmse`` [1], ``flag`` ('' or 'table value outside the 95 % interval')
    and ``status`` ('ok' or the reason the coefficient could not be fitted). A coefficient whose term
    is 0 in every row of a bearing (f1 of a no-load spin test, Fr = 0 so M1 = 0) is not fitted and its
    status says why; the other coefficients are fitted without it.
    """
    try:
        measured = read_measurements(table)
    except DiagnoseError as exc:
        raise AuditError(str(exc)) from exc
    frame = measured.frame
    arrays, _ = catalogue_arrays(frame)
    m2_rows = arrays.m2 & (arrays.Fa > 0)
    f2_given = "f2" in frame.columns
    if m2_rows.any():
        f2 = pd.to_numeric(frame["f2"], errors="coerce") if f2_given else pd.Series(np.nan, index=frame.index)
        frame = frame.copy()
        # the fit supplies f2; the model only needs a number to evaluate M0 and M1
        frame["f2"] = np.where(m2_rows & np.isnan(f2.to_numpy(dtype=float)), 0.0, f2)
        measured.frame = frame
    data, rows, excluded = model_data(measured)
    if len(data) == 0:
        raise AuditError("no usable row: " + "; ".join(excluded[:3]))
    a = data.arrays
    assert a is not None, "model_data gives the support arrays of its rows"
    with np.errstate(divide="ignore", invalid="ignore"):
        X0 = data.M0 / data.f0
        user_f1 = pd.to_numeric(frame["f1"], errors="coerce").to_numpy(dtype=float)[rows] \
            if "f1" in frame.columns else np.full(len(data), np.nan)
        a1 = np.where(np.isnan(user_f1), a.f1_a, user_f1)
        X1 = data.M1 / a1
    table_f2 = pd.to_numeric(frame["f2"], errors="coerce").to_numpy(dtype=float)[rows] if f2_given \
        else np.full(len(data), np.nan)
    carries_m2 = a.m2 & (data.Fa > 0)
    X2 = np.where(carries_m2, data.Fa * data.dM, 0.0)
    basis_ratio = (a.f1_basis > 0) & np.isnan(user_f1)
    lubrication = _texts(frame, "lubrication")[rows]
    fit_set = _fit_sets(data.bearing, data.f0, a1, table_f2)
    # the operating point of each row, as diagnose groups its folds (or the user's 'group' column)
    point = operating_point_groups([fit_set, data.n, data.nu, data.Fr, data.Fa, data.T_oil],
                                   measured.group[rows] if measured.group is not None else None)
    out = []
    for code in range(int(fit_set.max()) + 1):
        mine = fit_set == code
        name = data.bearing_names[int(data.bearing[mine][0])]
        n_rows = int(mine.sum())
        names = ["f0", "f1_a" if basis_ratio[mine].any() else "f1"]
        table_values = [float(np.nanmedian(data.f0[mine])), float(np.nanmedian(a1[mine]))]
        columns = [X0[mine], X1[mine]]
        if carries_m2[mine].any():
            names.append("f2")
            given = table_f2[mine & carries_m2]
            table_values.append(float(np.nanmedian(given)) if np.any(~np.isnan(given)) else math.nan)
            columns.append(X2[mine])
        X = np.column_stack(columns)
        X_point, M_point = point_means(X, data.M[mine], point[mine])
        base = {"bearing": name, "lubrication": ", ".join(sorted(set(lubrication[mine]) - {""})), "rows": n_rows,
                "points": len(M_point)}
        unfitted = _without_trace(X, names, data.load[mine])
        kept = [j for j in range(len(names)) if j not in unfitted]
        status = _identifiable(X[:, kept], X_point[:, kept], [names[j] for j in kept])
        fit = fit_linear_coefficients(X_point[:, kept], M_point, confidence=confidence) if not status else None
        for j, (coef, ref) in enumerate(zip(names, table_values)):
            if fit is None or j in unfitted:
                out.append({**base, "coefficient": coef, "table": ref, "fitted": math.nan, "se": math.nan,
                            "ci_low": math.nan, "ci_high": math.nan, "rel_rmse": math.nan, "flag": "",
                            "status": unfitted.get(j, status)})
                continue
            k = kept.index(j)
            outside = not math.isnan(ref) and not (fit["low"][k] <= ref <= fit["high"][k])
            out.append({**base, "coefficient": coef, "table": ref, "fitted": float(fit["theta"][k]),
                        "se": float(fit["se"][k]), "ci_low": float(fit["low"][k]), "ci_high": float(fit["high"][k]),
                        "rel_rmse": fit["rel_rmse"],
                        "flag": f"table value outside the {confidence:.0%} interval" if outside else "",
                        "status": "ok"})
    result = pd.DataFrame(out)
    result.attrs["excluded"] = excluded
    return result


def _texts(frame: pd.DataFrame, column: str) -> np.ndarray:
    """The cleaned texts of a column ('' for blank cells, or every row where the column is absent)."""
    if column not in frame.columns:
        return np.full(len(frame), "", dtype=object)
    values = frame[column].astype(object).to_numpy()
    return np.array(["" if pd.isna(v) else str(v).strip() for v in values], dtype=object)


def _fit_sets(bearing: np.ndarray, f0: np.ndarray, a1: np.ndarray, f2: np.ndarray) -> np.ndarray:
    """Code of each row's fit: the rows of one bearing with the same table f0, a1 and given f2.

    One bearing run with two lubrications (oil bath f0 = 2, grease f0 = 1.3)
    has two table f0: pooled, the fit would compare the data with neither.
    Codes run in the order of the bearings' names, then of f0, a1, f2.
    """
    keys = pd.DataFrame({"bearing": bearing, "f0": np.round(f0, 9), "a1": np.round(a1, 12), "f2": np.round(f2, 9)})
    return keys.groupby(list(keys.columns), sort=True, dropna=False).ngroup().to_numpy()


#: the torque term each coefficient scales
_TERMS = {"f0": "M0", "f1": "M1", "f1_a": "M1", "f2": "M2"}


def _without_trace(X: np.ndarray, names: list[str], load: np.ndarray) -> dict[int, str]:
    """The coefficients whose term is 0 in every row (column index -> why it is not fitted).

    Such a term leaves no trace in the torque (a no-load spin test has
    M1 = 0): its coefficient cannot be fitted, and the others are fitted
    without it.
    """
    zero = [j for j in range(X.shape[1]) if np.all(np.isfinite(X[:, j])) and not np.any(X[:, j])]
    others = ", ".join(names[j] for j in range(len(names)) if j not in zero)
    reasons = {}
    for j in zero:
        term = _TERMS[names[j]]
        why = "the load is 0 in every row" if term == "M1" and not np.any(load) else f"{term} is 0 in every row"
        reasons[j] = (f"{names[j]} not fitted: {why} ({len(X)} rows), so {term} = 0 and the torque holds no "
                      f"information on {names[j]}" + (f"; {others} fitted alone" if others else ""))
    return reasons


def _separable(X: np.ndarray) -> bool:
    """The columns of X (none 0 in every row) are linearly independent (rank of the column-scaled X)."""
    return bool(np.linalg.matrix_rank(X / np.linalg.norm(X, axis=0), tol=1e-8) == X.shape[1])


def _identifiable(X: np.ndarray, X_point: np.ndarray, names: list[str]) -> str:
    """'' if the coefficients can be separated with residual degrees of freedom, otherwise why not.

    X holds the rows, X_point their operating points' means
    (:func:`point_means`); no column is 0 in every row.
    """
    n_rows, p = X.shape
    n_points = len(X_point)
    if p == 0:
        return "no coefficient has a term that is not 0 in every row"
    if not np.all(np.isfinite(X)):
        return "a regressor is not finite (missing C0 or load)"
    inseparable = ("the coefficients cannot be separated: " + ", ".join(names) +
                   " need rows where n·ν and the load vary independently")
    if not _separable(X):
        return inseparable
    if n_points <= p:
        return (f"{n_points} operating point{'s' if n_points > 1 else ''} ({n_rows} rows) for {p} coefficients: "
                f"need more than {p} for an interval (the rows of one operating point, or of one group of the "
                "'group' column, count once)")
    if not _separable(X_point):
        return inseparable + " between operating points"
    return ""
