"""Coefficient audit: measured torque against the tables, and the tables against the catalogue's own speeds.

Two audits, both on tables with unit headers:

* :func:`audit_coefficients` fits f0 and f1 (and f2 where a cylindrical
  roller bearing with ribs carries Fa) for each bearing of a measured data
  set (the columns of ``calc`` plus ``M [N*mm]``) by least squares with
  ``scipy.optimize.least_squares``, gives 95 % confidence intervals from the
  Jacobian and flags the seed 002 table values that lie outside them.

  The model is linear in the coefficients (seed 002, pp. 64-70)::

      M = f0·X0 + a1·X1 + f2·X2,  X0 = M0/f0 = g(ν·n)·dM³·1e-7,
      X1 = M1/a1 = load·dM·(P0/C0 or Fa/C0)^x,  X2 = Fa·dM

  where a1 is the f1 constant of the table (f1 itself for constant-f1 types;
  for f1 = a1·(P0/C0)^x it is a1). The residuals are relative,
  (M − model)/M, so bearings and speeds of any size weigh alike.

* :func:`audit_reference_speeds` computes the thermal reference speed n_θr
  of every bearing of a catalogue list from the tables
  (:func:`bearingheat.calc.thermal.thermal_reference_speed_rows`) and compares
  it with the published value, series by series. A series deviates
  systematically under :data:`SYSTEMATIC_RULE`.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
from scipy import optimize, stats

from bearingheat.analysis.diagnose import model_data, read_measurements
from bearingheat.analysis.effects import catalogue_arrays
from bearingheat.calc.contract import parse_header
from bearingheat.calc.thermal import thermal_reference_speed_rows
from bearingheat.catalogue.friction import resolve
from bearingheat.errors import AuditError, DesignationError, DiagnoseError, UnitError
from bearingheat.units import convert_column

__all__ = [
    "AuditError",
    "CONFIDENCE",
    "SYSTEMATIC_RULE",
    "REFERENCE_SPEED_COLUMNS",
    "fit_linear_coefficients",
    "audit_coefficients",
    "audit_reference_speeds",
    "series_deviation_summary",
]

#: two-sided confidence level of the coefficient intervals
CONFIDENCE = 0.95
#: systematic deviation of a series of catalogue speeds (median, agreement of signs, count)
SYSTEMATIC_MEDIAN = 0.05
SYSTEMATIC_SAME_SIGN = 0.8
SYSTEMATIC_MIN_ROWS = 5
SYSTEMATIC_RULE = (
    f"a series deviates systematically when it has at least {SYSTEMATIC_MIN_ROWS} computed bearings, the median "
    f"of n_thr(tables)/n_thr(published) - 1 is beyond ±{SYSTEMATIC_MEDIAN:.0%}, and at least "
    f"{SYSTEMATIC_SAME_SIGN:.0%} of its bearings deviate in the same direction"
)
#: accepted names of the published thermal reference speed column (first match wins)
REFERENCE_SPEED_COLUMNS = ("n_thr", "n_B", "n_theta_r", "n_θr", "n_ref", "nthr")


# ---------------------------------------------------------------------------------------------
# Coefficient fit
# ---------------------------------------------------------------------------------------------

def fit_linear_coefficients(X: np.ndarray, M: np.ndarray, *, confidence: float = CONFIDENCE) -> dict:
    """Least squares fit of M = X·θ on relative residuals (M − X·θ)/M, with confidence intervals.

    Uses ``scipy.optimize.least_squares`` (trust region reflective) on the
    exact Jacobian −X/M; the covariance is s²·(JᵀJ)⁻¹ with
    s² = Σr²/(N − p), and the interval is θ ± t(1 − α/2, N − p)·se.

    >>> X = np.array([[1.0, 1.0], [1.0, 2.0], [1.0, 3.0], [1.0, 4.0]])
    >>> fit = fit_linear_coefficients(X, X @ np.array([2.0, 0.5]))
    >>> np.round(fit["theta"], 10).tolist(), fit["dof"]
    ([2.0, 0.5], 2)
    """
    X = np.asarray(X, dtype=float)
    M = np.asarray(M, dtype=float)
    N, p = X.shape
    J = -X / M[:, None]
    theta0, *_ = np.linalg.lstsq(-J, np.ones(N), rcond=None)
    result = optimize.least_squares(lambda th: (M - X @ th) / M, theta0, jac=lambda th: J, method="trf",
                                    xtol=1e-14, ftol=1e-14, gtol=1e-14)
    theta = result.x
    residual = result.fun
    dof = N - p
    sse = float(residual @ residual)
    if dof > 0:
        cov = sse / dof * np.linalg.inv(J.T @ J)
        se = np.sqrt(np.diag(cov))
        half = stats.t.ppf(0.5 + confidence / 2.0, dof) * se
    else:
        se = np.full(p, np.nan)
        half = np.full(p, np.nan)
    return {"theta": theta, "se": se, "low": theta - half, "high": theta + half, "dof": dof,
            "rel_rmse": math.sqrt(sse / N)}


def audit_coefficients(table: pd.DataFrame, *, confidence: float = CONFIDENCE) -> pd.DataFrame:
    """Fit f0, f1 (and f2) for each bearing of a measured table and compare them with the tables.

    Returns one row per bearing and coefficient: ``bearing``, ``coefficient``
    (f0, f1 or f1_a, f2), ``table`` (the seed 002 value, NaN for f2 read off
    a chart), ``fitted``, ``se``, ``ci_low``, ``ci_high``, ``rows``,
    ``rel_rmse`` [1], ``flag`` ('' or 'table value outside the 95 % interval')
    and ``status`` ('ok' or the reason the bearing could not be fitted).
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
    out = []
    for code, name in enumerate(data.bearing_names):
        mine = data.bearing == code
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
        status = _identifiable(X, names, data, mine)
        base = {"bearing": name, "rows": n_rows}
        if status:
            for coef, ref in zip(names, table_values):
                out.append({**base, "coefficient": coef, "table": ref, "fitted": math.nan, "se": math.nan,
                            "ci_low": math.nan, "ci_high": math.nan, "rel_rmse": math.nan, "flag": "",
                            "status": status})
            continue
        fit = fit_linear_coefficients(X, data.M[mine], confidence=confidence)
        for j, (coef, ref) in enumerate(zip(names, table_values)):
            outside = not math.isnan(ref) and not (fit["low"][j] <= ref <= fit["high"][j])
            out.append({**base, "coefficient": coef, "table": ref, "fitted": float(fit["theta"][j]),
                        "se": float(fit["se"][j]), "ci_low": float(fit["low"][j]), "ci_high": float(fit["high"][j]),
                        "rel_rmse": fit["rel_rmse"],
                        "flag": f"table value outside the {confidence:.0%} interval" if outside else "",
                        "status": "ok"})
    result = pd.DataFrame(out)
    result.attrs["excluded"] = excluded
    return result


def _identifiable(X: np.ndarray, names: list[str], data, mine: np.ndarray) -> str:
    """'' if the coefficients can be separated, otherwise why not."""
    n_rows, p = X.shape
    if n_rows <= p:
        return f"{n_rows} rows for {p} coefficients: need more than {p}"
    if not np.all(np.isfinite(X)):
        return "a regressor is not finite (missing C0 or load)"
    scaled = X / np.linalg.norm(X, axis=0)
    if np.linalg.matrix_rank(scaled, tol=1e-8) < p:
        return ("the coefficients cannot be separated: " + ", ".join(names) +
                " need rows where n·ν and the load vary independently")
    return ""


# ---------------------------------------------------------------------------------------------
# Catalogue thermal reference speeds
# ---------------------------------------------------------------------------------------------

_GEOMETRY_UNITS = {"d": "mm", "D": "mm", "B": "mm", "T": "mm", "C0": "N", "Y": "1", "e": "1", "Y0": "1"}


def _convert(values: pd.Series, header: str, unit_text: str | None, target: str) -> np.ndarray:
    """A catalogue-list column in the catalogue unit (units.convert_column); AuditError naming the column."""
    numbers = pd.to_numeric(values, errors="coerce").to_numpy(dtype=float)
    try:
        return convert_column(numbers, unit_text, target, name=header, header=header)[0]
    except UnitError as exc:
        raise AuditError(f"column {header!r}: {exc}") from exc


def _group_keys(table: pd.DataFrame, columns: dict[str, str], frame: pd.DataFrame) -> list[str]:
    """Series label of each row: 'family series [shield]' from the list, else the resolved type and series."""
    def col(name):
        return table[columns[name]].astype(str).str.strip().to_numpy() if name in columns else None

    family, series, shield = col("family"), col("series"), col("shield")
    keys = []
    for i in range(len(table)):
        if family is not None and series is not None:
            key = f"{family[i]} {series[i]}"
        else:
            try:
                entry = resolve(frame["designation"].iat[i] if "designation" in frame else None,
                                frame["type"].iat[i] if "type" in frame else None,
                                frame["series"].iat[i] if "series" in frame else None).entry
                key = f"{entry.bearing_type} {entry.series}"
            except DesignationError:
                key = "unresolved"
        if shield is not None and shield[i] not in ("open", "", "nan"):
            key += f" -{shield[i]}"
        keys.append(key)
    return keys


def audit_reference_speeds(table: pd.DataFrame, *, speed_column: str | None = None) -> pd.DataFrame:
    """n_θr from the tables against the published n_θr, for each bearing of a catalogue list.

    ``table`` has unit headers: ``designation`` (or ``type`` and ``series``
    of the seed 002 tables), ``d``, ``D``, ``B``, ``T`` (tapered), ``C0``
    and the published speed (``n_thr``, ``n_B``, ... see
    :data:`REFERENCE_SPEED_COLUMNS`, or ``speed_column``). Optional
    ``family``, ``series`` and ``shield`` columns name the series. Returns
    one row per bearing with ``series_key``, ``n_thr_published``,
    ``n_thr_tables`` [1/min], ``deviation`` [1] (tables/published − 1) and
    ``reason`` (why n_thr could not be computed).
    """
    columns: dict[str, str] = {}
    units: dict[str, str | None] = {}
    for header in table.columns:
        name, unit = parse_header(header)
        columns.setdefault(name, header)
        units.setdefault(name, unit)
    wanted = [speed_column] if speed_column else list(REFERENCE_SPEED_COLUMNS)
    published_name = next((c for c in wanted if c in columns), None)
    if published_name is None:
        raise AuditError("missing column: the published thermal reference speed, e.g. 'n_thr [1/min]' "
                         f"(accepted names: {', '.join(wanted)})")
    if "designation" not in columns and not {"type", "series"} <= set(columns):
        raise AuditError("missing column: 'designation' (or 'type' and 'series')")
    frame = pd.DataFrame(index=table.index)
    if "designation" in columns:
        frame["designation"] = table[columns["designation"]].astype(str).str.strip()
    else:
        frame["type"] = table[columns["type"]].astype(str).str.strip()
        frame["series"] = table[columns["series"]].astype(str).str.strip()
    for name, target in _GEOMETRY_UNITS.items():
        if name in columns:
            frame[name] = _convert(table[columns[name]], columns[name], units[name], target)
        elif name in ("d", "D", "C0"):
            raise AuditError(f"missing column: '{name} [{target}]'")
        else:
            frame[name] = np.nan
    published = _convert(table[columns[published_name]], columns[published_name], units[published_name], "1/min")
    computed = thermal_reference_speed_rows(frame)
    reason = computed.attrs.get("reason", pd.Series("", index=frame.index))
    with np.errstate(divide="ignore", invalid="ignore"):
        deviation = computed.to_numpy(dtype=float) / published - 1.0
    out = pd.DataFrame({
        "designation": frame["designation"] if "designation" in frame else frame["type"] + " " + frame["series"],
        "series_key": _group_keys(table, columns, frame),
        "n_thr_published": published,
        "n_thr_tables": computed.to_numpy(dtype=float),
        "deviation": deviation,
        "reason": np.where(np.isnan(published), f"{columns[published_name]}: blank", reason.to_numpy(dtype=object)),
    }, index=table.index)
    return out


def series_deviation_summary(rows: pd.DataFrame) -> pd.DataFrame:
    """Per series: counts, median/mean/min/max deviation [1], share above 0, and the systematic flag.

    >>> rows = pd.DataFrame({"series_key": ["a"] * 6, "deviation": [0.2, 0.21, 0.19, 0.2, 0.22, 0.18]})
    >>> s = series_deviation_summary(rows)
    >>> bool(s.loc[0, "systematic"]), round(float(s.loc[0, "median"]), 3)
    (True, 0.2)
    """
    out = []
    for key, group in rows.groupby("series_key", sort=True):
        dev = group["deviation"].to_numpy(dtype=float)
        ok = dev[~np.isnan(dev)]
        entry = {"series_key": key, "bearings": len(group), "computed": len(ok)}
        if len(ok):
            share_up = float(np.mean(ok > 0))
            median = float(np.median(ok))
            same_side = share_up if median > 0 else 1.0 - share_up
            systematic = (len(ok) >= SYSTEMATIC_MIN_ROWS and abs(median) > SYSTEMATIC_MEDIAN
                          and same_side >= SYSTEMATIC_SAME_SIGN)
            entry.update(median=median, mean=float(np.mean(ok)), min=float(np.min(ok)), max=float(np.max(ok)),
                         share_above=share_up, systematic=bool(systematic))
        else:
            entry.update(median=math.nan, mean=math.nan, min=math.nan, max=math.nan, share_above=math.nan,
                         systematic=False)
        out.append(entry)
    return pd.DataFrame(out)
