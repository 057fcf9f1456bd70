"""Close the loop: residuals of the catalogue model -> the missing effect -> the model before and after.

``bearingheat diagnose DATA.csv --out DIR`` reads measured friction torque
with the columns of ``calc`` plus ``M [N*mm]`` (any torque unit), optional
``T_oil [degC]`` and ``t [h]``, and:

1. computes the catalogue model of the Schaeffler catalogue for every row and its error
   (RMSE [N·mm], MAPE [%], bias [N·mm]);
2. measures the structure of the relative residual against n, ν·n, the
   load, Fa/Fr, t, T_oil (Spearman rank correlation) and the bearing
   (one-way ANOVA);
3. fits every candidate of :data:`bearingheat.analysis.effects.CANDIDATES` by least
   squares on relative residuals;
4. scores each by grouped k-fold cross-validation (a group is one operating
   point: bearing, n, ν, Fr, Fa and T_oil, or the ``group`` column when
   given, so repeated readings never sit on both sides of a split) and by
   the Bayesian information criterion, and applies the significance rule
   :data:`SIGNIFICANCE_RULE`; ``none`` wins when no candidate earns its
   parameters;
5. measures how much single readings weigh in the choice (studentised
   residuals, leverage, Cook's distance; the choice again without the most
   outlying flagged reading: :mod:`bearingheat.analysis.influence`);
6. reports the error before and after, on the fitting data and on the
   held-out folds (:meth:`Diagnosis.summary`); ``summary.json``, ``report.md``
   and the PNG plots are written by :mod:`bearingheat.io.reports.diagnose`.

The fitted effect is reusable: ``bearingheat calc --effects DIR/summary.json``
loads it with :meth:`FittedEffect.from_summary` and applies it after the
friction model (each candidate applies itself, :meth:`Candidate.apply`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np
import numpy.typing as npt
import pandas as pd
from scipy import stats

from bearingheat.analysis.domain import domain_values, fitted_domain
from bearingheat.analysis.effects import (CANDIDATES, EFFECT_NAMES, FittedEffect, ModelData, bearing_keys,
                                          catalogue_arrays, format_value, m1_load)
from bearingheat.analysis.influence import Influence, influence
from bearingheat.calc.contract import column, parse_header, readable_header
from bearingheat.calc.messages import Labels
from bearingheat.calc.fill import fill_from_catalogue
from bearingheat.calc.models import DEFAULT_MODEL, compute_supports
from bearingheat.calc.supports import SupportArrays, per_distinct
from bearingheat.calc.conversion import (blank_cell, lookalike_column, not_a_number, numbers_of, row_name,
                                         row_numbers, to_catalogue_units)
from bearingheat.errors import DiagnoseError, InputError, UnitError
from bearingheat.kernels import friction
from bearingheat.units import convert_column, parse_unit

__all__ = [
    "DiagnoseError",
    "SIGNIFICANCE_RULE",
    "CHOICE_METRIC",
    "MEASURED_UNITS",
    "REGRESSOR_UNITS",
    "MeasuredData",
    "CandidateScore",
    "Diagnosis",
    "read_measurements",
    "model_data",
    "diagnose",
    "diagnose_table",
    "diagnose_measurements",
    "error_metrics",
    "regressors",
    "residual_structure",
    "key_regressor",
    "format_value",
    "bearing_keys",
    "operating_point_groups",
    "assign_folds",
    "FittedEffect",
]


#: measured columns beyond the calc contract -> catalogue unit
MEASURED_UNITS = {"M": "N*mm", "T_oil": "degC", "t": "h"}

#: the stated rule that decides whether a candidate earns its parameters
MIN_DELTA_BIC = 10.0          # "very strong" evidence on the Kass & Raftery (1995) scale
MIN_CV_IMPROVEMENT = 0.05     # held-out relative RMSE at least 5 % below the catalogue model's
MAX_P_VALUE = 0.01            # one-sided paired t-test over the held-out groups
CV_TIE = 0.02                 # candidates within 2 % of the best held-out error count as tied
SIGNIFICANCE_RULE = (
    f"A candidate is significant when (a) its BIC is at least {MIN_DELTA_BIC:g} below that of 'none', "
    f"(b) its grouped {{k}}-fold cross-validated relative RMSE is at least {MIN_CV_IMPROVEMENT:.0%} below that "
    f"of 'none', and (c) a one-sided paired t-test of the held-out squared relative errors, averaged per "
    f"group, gives p < {MAX_P_VALUE:g}. Among significant candidates whose held-out error is within "
    f"{CV_TIE:.0%} of the best, the lowest BIC wins; with no significant candidate the answer is 'none'."
)
MIN_ROWS = 20
#: which error the choice is made on, as the report and the summary say it
CHOICE_METRIC = (
    "The choice uses the relative error (M measured − M model)/M measured: every candidate is fitted by least "
    "squares on it, BIC and the held-out comparison (relative RMSE, paired t-test) are computed from it. RMSE, MAPE "
    "and bias in N·mm are shown for scale; a relative error weighs a reading of small torque as much as one of large "
    "torque, so a choice may improve the relative RMSE much more than the RMSE.")


# ---------------------------------------------------------------------------------------------
# Input
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _RowNames:
    """How messages name the rows: ``names[position]`` is 'row 5' for the row of the file's line 5 (``rows``,
    :func:`~bearingheat.calc.conversion.row_numbers`, as calc cites it; None: the position + 1). Each name is made
    when asked: the influence check names at most six of its readings."""

    rows: np.ndarray | None

    def __getitem__(self, position: int) -> str:
        return row_name(self.rows, position)


@dataclass
class MeasuredData:
    """A measured table split into the calc frame (catalogue units) and the measured columns."""

    frame: pd.DataFrame           # contract names, catalogue units, positional index
    M: np.ndarray                 # N·mm
    T_oil: np.ndarray             # °C, NaN if not given
    t: np.ndarray                 # h, NaN if not given
    group: np.ndarray | None      # user's group labels, or None
    row_errors: list[list[str]]   # per row
    labels: Labels | None = None
    rows: np.ndarray | None = None  # the row number each message cites (the file's line), None: position + 1

    def row(self, position: int) -> str:
        """How a message names the row at ``position``: 'row 5' for the file's line 5 (as calc cites it)."""
        return _RowNames(self.rows)[position]


def _measured_column(table: pd.DataFrame, name: str, row_errors: list[list[str]], row: _RowNames,
                     decimal: str) -> np.ndarray:
    target = MEASURED_UNITS[name]
    headers = [h for h in table.columns if parse_header(h)[0] == name]
    if not headers:
        return np.full(len(table), np.nan)
    if len(headers) > 1:
        raise DiagnoseError(f"column {headers[1]!r}: {name} appears twice")
    header = headers[0]
    unit_text = parse_header(header)[1]
    if unit_text is None or unit_text.strip() in ("", "-"):
        raise DiagnoseError(f"column {header!r}: needs a unit, e.g. '{name} [{target}]'")
    try:
        parse_unit(unit_text, name=header)
    except UnitError as exc:
        raise DiagnoseError(f"column {header!r}: {exc}") from exc
    raw = table[header]
    numbers = numbers_of(raw, decimal)
    for i, (num, value) in enumerate(zip(numbers, raw.to_numpy(dtype=object))):
        if np.isnan(num) and not blank_cell(value):
            row_errors[i].append(f"{row[i]}: {not_a_number(value, header, decimal)}")
    try:  # the unit reads (above): a refusal here is its dimension
        converted, _ = convert_column(numbers, unit_text, target, name=name, header=header)
    except UnitError as exc:
        raise DiagnoseError(f"column {header!r}: unit {unit_text} cannot be converted to {target}") from exc
    return np.asarray(converted, dtype=float)


#: the oil temperatures a measurement may have [degC]: the valid range of the bearing temperature of the column
#: contract (T_bearing)
T_OIL_RANGE = cast(tuple[float, float], column("T_bearing").valid)


#: measured column -> what becomes of the table when its header is not read
_UNREAD = {"M": "the table would have no measured torque",
           "T_oil": "the oil temperature would be taken as not measured",
           "t": "the running time would be taken as not measured (and run_in as not applicable)",
           "group": "the rows would be grouped by operating point instead of by these labels"}


def _refuse_lookalikes(headers: Any) -> None:
    """:class:`DiagnoseError` for a header that is not read but looks like a measured column the table lacks
    (M, T_oil, t, group; :func:`~bearingheat.calc.conversion.lookalike_column`, calc's rule for its own columns):
    the unit written another way ('T_oil (degC)', 't(h)') or the name in other letter case ('Group',
    't_OIL [degC]'). Unlike calc's text columns, ``group`` written in the other-unit form ('group (run)') is refused
    too: its rows would be grouped by operating point instead of by its labels."""
    found = lookalike_column(headers, {**MEASURED_UNITS, "group": ""}, text_in_other_form=True)
    if found is not None:
        raise DiagnoseError(found.message("is not read", _UNREAD[found.meant]))


def read_measurements(table: pd.DataFrame) -> MeasuredData:
    """Split a measured table (unit headers) into the calc frame and M, T_oil, t.

    Raises :class:`DiagnoseError` for unusable input (no torque column,
    wrong units, missing calc columns); bad cells become row errors. A table
    read from a CSV by :func:`bearingheat.io.tables.read_table` keeps its
    decimal mark (``attrs['decimal']``: every number column is read with it)
    and its line numbers (``attrs['lines']``: messages cite the file's rows,
    as calc does).
    """
    if not all(readable_header(h) for h in table.columns):  # ('remark [see note]]': a note, as calc passes it)
        table = table[[h for h in table.columns if readable_header(h)]]  # (pandas keeps attrs on the selection)
    names = [parse_header(h)[0] for h in table.columns]
    _refuse_lookalikes(table.columns)
    if "M" not in names:
        raise DiagnoseError("missing column: 'M [N*mm]' (the measured friction torque, any torque unit)")
    rows = row_numbers(table)
    decimal = str(table.attrs.get("decimal", "."))
    table = table.reset_index(drop=True)
    row_errors: list[list[str]] = [[] for _ in range(len(table))]
    row = _RowNames(rows)
    M = _measured_column(table, "M", row_errors, row, decimal)
    T_oil = _measured_column(table, "T_oil", row_errors, row, decimal)
    t = _measured_column(table, "t", row_errors, row, decimal)
    for i, value in enumerate(M):
        if np.isnan(value) and not row_errors[i]:
            row_errors[i].append(f"{row[i]}: M is blank; every row needs a measured torque")
        elif value <= 0:
            row_errors[i].append(f"{row[i]}: M = {value:g} N*mm must be > 0")
        elif np.isinf(value):  # (one such row would make every error measure infinite)
            row_errors[i].append(f"{row[i]}: M = {value:g} N*mm is not a finite number")
    low, high = T_OIL_RANGE
    for i, value in enumerate(T_oil):
        if not np.isnan(value) and not low <= value <= high:
            row_errors[i].append(f"{row[i]}: T_oil = {value:g} degC is outside {low:g} to {high:g} degC")
    for i, value in enumerate(t):
        if value < 0 or np.isinf(value):
            row_errors[i].append(f"{row[i]}: t = {value:g} h must be >= 0 and finite")
    measured_headers = [h for h, n in zip(table.columns, names) if n in MEASURED_UNITS or n == "group"]
    try:
        converted = to_catalogue_units(table.drop(columns=measured_headers), decimal=decimal)
    except InputError as exc:
        raise DiagnoseError(str(exc)) from exc
    # blank dimensions and ratings from the bearing table, as calc fills them
    frame, fill_problems, _ = fill_from_catalogue(converted.frame, converted.labels)
    for position, level, message in fill_problems:
        if level == "error":
            row_errors[position].append(f"{row[position]}: {message}")
    have = set(frame.columns)
    if "designation" not in have and not {"type", "series"} <= have:
        raise DiagnoseError("missing column: 'designation' (or 'type' and 'series')")
    for name, unit in (("D", "mm"), ("n", "1/min"), ("nu", "mm^2/s")):
        if name not in have:
            raise DiagnoseError(f"missing column: '{name} [{unit}]' (any {name} unit of the right dimension)")
    if "lubrication" not in have and "f0" not in have:
        raise DiagnoseError("missing column: 'lubrication' (grease, oil_mist, oil_bath or circulating_oil)")
    for i, errors in enumerate(converted.row_errors):
        row_errors[i].extend(f"{row[i]}: {e}" for e in errors)
    group = None
    if "group" in names:  # a blank label would pool the unlabelled rows of every run into one group
        header = table.columns[names.index("group")]
        labels = table[header]
        for position in np.flatnonzero(per_distinct(labels, blank_cell).astype(bool)).tolist():
            row_errors[position].append(f"{row[position]}: {header} is blank; with a group column every row needs its "
                                 "label (the run it belongs to)")
        group = labels.astype(str).to_numpy()
    return MeasuredData(frame, M, T_oil, t, group, row_errors, converted.labels, rows)


def model_data(measured: MeasuredData) -> tuple[ModelData, np.ndarray, list[str]]:
    """The catalogue model on every row; returns (data of usable rows, their positions, excluded messages)."""
    frame = measured.frame
    results = compute_supports(frame, labels=measured.labels)
    status = results["status"].to_numpy()
    excluded: list[str] = []
    usable = np.ones(len(frame), dtype=bool)
    for i in range(len(frame)):
        if measured.row_errors[i]:
            usable[i] = False
            excluded.append("; ".join(measured.row_errors[i]))
        elif status[i] == "error":
            usable[i] = False
            excluded.append(f"{measured.row(i)}: {results['message'].iat[i]}")
    arrays, unresolved = catalogue_arrays(frame)
    usable &= ~unresolved
    rows = np.flatnonzero(usable)
    a = arrays.take(rows)
    names_all = bearing_keys(frame)
    codes, names = pd.factorize(pd.Series(names_all[rows], dtype=object), sort=True)
    load = _load_column(results, a, rows)
    data = ModelData(
        M=measured.M[rows], M0=results["M0"].to_numpy(dtype=float)[rows],
        M1=results["M1"].to_numpy(dtype=float)[rows], M2=results["M2"].to_numpy(dtype=float)[rows],
        f0=results["f0"].to_numpy(dtype=float)[rows], n=a.n, nu=a.nu,
        dM=friction.mean_diameter(a.d, a.D), Fr=a.Fr, Fa=a.Fa, load=load,
        t=measured.t[rows], T_oil=measured.T_oil[rows], bearing=codes.astype(int),
        bearing_names=[str(n) for n in names], arrays=a,
    )
    return data, rows, excluded


def _load_column(results: pd.DataFrame, a: SupportArrays, rows: np.ndarray) -> np.ndarray:
    """The load M1 works with: P1, or F (Fr of radial, Fa of thrust bearings)."""
    return m1_load(results["P1"].to_numpy(dtype=float)[rows], a)


# ---------------------------------------------------------------------------------------------
# Metrics and residual structure
# ---------------------------------------------------------------------------------------------

def error_metrics(measured: npt.ArrayLike, predicted: npt.ArrayLike) -> dict[str, float]:
    """RMSE [N·mm], MAPE [%], bias = mean(measured − predicted) [N·mm] and relative RMSE [1].

    The residual is measured − model everywhere (reports, plots, bias): a
    positive bias means the model predicts too little torque.

    >>> error_metrics([10.0, 20.0], [11.0, 18.0])
    {'rmse': 1.5811388300841898, 'mape': 10.0, 'bias': 0.5, 'rel_rmse': 0.1}
    """
    M = np.asarray(measured, dtype=float)
    P = np.asarray(predicted, dtype=float)
    err = M - P
    return {
        "rmse": float(np.sqrt(np.mean(err ** 2))),
        "mape": float(np.mean(np.abs(err) / np.abs(M)) * 100.0),
        "bias": float(np.mean(err)),
        "rel_rmse": float(np.sqrt(np.mean((err / M) ** 2))),
    }


def regressors(data: ModelData) -> dict[str, np.ndarray]:
    """The quantities the relative residual is examined against, one array per regressor (catalogue units)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        fa_fr = np.where(data.Fr > 0, data.Fa / data.Fr, np.nan)
    return {"n": data.n, "nu*n": data.nu * data.n, "load": data.load, "Fa/Fr": fa_fr,
            "NR": data.NR, "t": data.t, "T_oil": data.T_oil}


#: regressor -> unit shown in the report
REGRESSOR_UNITS = {"n": "1/min", "nu*n": "mm^2/s*1/min", "load": "N", "Fa/Fr": "1", "NR": "W", "t": "h",
                   "T_oil": "degC", "bearing": "-"}


def residual_structure(data: ModelData, predicted: np.ndarray) -> list[dict[str, Any]]:
    """Relative residual (M − model)/M against each regressor: Spearman ρ and p; the bearing by ANOVA."""
    residual = (data.M - predicted) / data.M
    out: list[dict[str, Any]] = []
    for name, values in regressors(data).items():
        ok = ~np.isnan(values)
        if ok.sum() < 3 or np.ptp(values[ok]) == 0:
            out.append({"regressor": name, "statistic": "spearman_rho", "value": None, "p_value": None,
                        "note": "not measured" if ok.sum() == 0 else "constant in the data"})
            continue
        rho, p = stats.spearmanr(values[ok], residual[ok])
        out.append({"regressor": name, "statistic": "spearman_rho", "value": float(rho), "p_value": float(p),
                    "note": ""})
    groups = [residual[data.bearing == c] for c in range(len(data.bearing_names))]
    groups = [g for g in groups if len(g)]
    if len(groups) >= 2 and all(len(g) >= 2 for g in groups):
        f, p = stats.f_oneway(*groups)
        out.append({"regressor": "bearing", "statistic": "anova_F", "value": float(f), "p_value": float(p),
                    "note": ""})
    else:
        out.append({"regressor": "bearing", "statistic": "anova_F", "value": None, "p_value": None,
                    "note": "one bearing only"})
    return out


# ---------------------------------------------------------------------------------------------
# Fitting, cross-validation and selection
# ---------------------------------------------------------------------------------------------

@dataclass
class CandidateScore:
    """One candidate fitted and scored."""

    name: str
    applicable: bool
    reason: str = ""
    params: dict[str, Any] = field(default_factory=dict)
    public: dict[str, Any] = field(default_factory=dict)
    n_params: int = 0
    fit: dict[str, float] = field(default_factory=dict)       # error_metrics on the fitting data
    cv: dict[str, float] = field(default_factory=dict)        # error_metrics of the held-out predictions
    bic: float = math.nan
    delta_bic: float = math.nan                   # BIC(none) − BIC(candidate)
    cv_improvement: float = math.nan              # 1 − cv rel_rmse / cv rel_rmse of none
    p_value: float = math.nan
    significant: bool = False
    predicted: np.ndarray | None = None
    cv_predicted: np.ndarray | None = None
    #: each fitted parameter -> 'lower' or 'upper' where its fit ended on that bound, else None (per bearing a dict)
    at_bound: dict[str, Any] = field(default_factory=dict)

    def as_json(self) -> dict[str, Any]:
        def clean(x: float) -> float | None:
            return None if isinstance(x, float) and not math.isfinite(x) else x
        return {
            "applicable": self.applicable, "reason": self.reason, "parameters": self.public,
            "at_bound": self.at_bound,
            "n_params": self.n_params, "rmse": clean(self.fit.get("rmse", math.nan)),
            "mape": clean(self.fit.get("mape", math.nan)), "rel_rmse": clean(self.fit.get("rel_rmse", math.nan)),
            "cv_rmse": clean(self.cv.get("rmse", math.nan)), "cv_mape": clean(self.cv.get("mape", math.nan)),
            "cv_rel_rmse": clean(self.cv.get("rel_rmse", math.nan)),
            "bic": clean(self.bic), "delta_bic": clean(self.delta_bic),
            "cv_improvement": clean(self.cv_improvement), "p_value": clean(self.p_value),
            "significant": self.significant,
        }


@dataclass
class Diagnosis:
    """The outcome of :func:`diagnose`."""

    data: ModelData
    effect: str
    scores: dict[str, CandidateScore]
    folds: np.ndarray
    groups: np.ndarray
    k: int
    structure: list[dict[str, Any]]
    excluded: list[str] = field(default_factory=list)
    influence: Influence | None = None

    @property
    def chosen(self) -> CandidateScore:
        return self.scores[self.effect]

    def selection(self) -> str:
        """What the rule chose, in one sentence."""
        significant = [name for name, s in self.scores.items() if s.significant]
        if self.effect == "none":
            return "No candidate is significant: the answer is 'none'."
        others = [name for name in significant if name != self.effect]
        tied = f"; also significant: {', '.join(others)}" if others else ""
        chosen = self.chosen
        return (f"Chosen: '{self.effect}' (ΔBIC {chosen.delta_bic:.1f}, held-out gain {chosen.cv_improvement:.1%}, "
                f"p = {chosen.p_value:.2g}){tied}.")

    def domain(self) -> dict[str, Any]:
        """The ranges, over the fitted rows, of the quantities the chosen effect depends on, and the bearings."""
        data = self.data
        values = domain_values(data.n, data.nu, data.dM, data.load)
        return fitted_domain(values, CANDIDATES[self.effect].domain, data.bearing_names)

    def summary(self) -> dict[str, Any]:
        none, chosen = self.scores["none"], self.chosen
        return {
            "effect": self.effect,
            "parameters": chosen.public,
            "at_bound": chosen.at_bound,
            "description": CANDIDATES[self.effect].description,
            "rmse_before": none.fit["rmse"], "rmse_after": chosen.fit["rmse"],
            "cv_rmse_before": none.cv["rmse"], "cv_rmse_after": chosen.cv["rmse"],
            "mape_before": none.fit["mape"], "mape_after": chosen.fit["mape"],
            "cv_mape_before": none.cv["mape"], "cv_mape_after": chosen.cv["mape"],
            "bias_before": none.fit["bias"], "bias_after": chosen.fit["bias"],
            # the error the choice is made on: the candidates are fitted, scored by BIC and compared held out on it
            "rel_rmse_before": none.fit["rel_rmse"], "rel_rmse_after": chosen.fit["rel_rmse"],
            "cv_rel_rmse_before": none.cv["rel_rmse"], "cv_rel_rmse_after": chosen.cv["rel_rmse"],
            "choice_metric": "rel_rmse", "choice_metric_text": CHOICE_METRIC,
            # what calc --effects checks a row against: the model the effect extends, the fitted ranges
            "base_model": DEFAULT_MODEL, "domain": self.domain(),
            "units": {"rmse": "N*mm", "bias": "N*mm", "mape": "%", "rel_rmse": "1"},
            "n_rows": len(self.data), "n_excluded": len(self.excluded), "excluded": self.excluded[:50],
            "bearings": list(self.data.bearing_names),
            "folds": self.k, "groups": int(len(np.unique(self.groups))),
            "selection_rule": SIGNIFICANCE_RULE.format(k=self.k),
            "selection": self.selection(),
            "residual_structure": self.structure,
            "influence": self.influence.as_json() if self.influence is not None else None,
            "warnings": [self.influence.warning] if self.influence is not None and self.influence.warning else [],
            "candidates": {name: score.as_json() for name, score in self.scores.items()},
        }


def operating_point_groups(columns: list[np.ndarray], user_group: np.ndarray | None) -> np.ndarray:
    """Group codes of rows: the user's ``group`` labels, or one group per distinct operating point (the rows'
    values of ``columns``: bearing code, n, ν, Fr, Fa, T_oil; NaN counts as one value)."""
    if user_group is not None:
        return pd.factorize(pd.Series(user_group, dtype=object))[0]
    stacked = np.column_stack([np.where(np.isnan(values), -1.0, np.round(values, 6))
                               for values in (np.asarray(c, dtype=float) for c in columns)])
    _, codes = np.unique(stacked, axis=0, return_inverse=True)
    return codes.ravel()


def assign_folds(groups: np.ndarray, k: int, seed: int) -> np.ndarray:
    """Fold of each row: whole groups, shuffled with ``seed``, dealt round the ``k`` folds."""
    unique = np.unique(groups)
    rng = np.random.default_rng(seed)
    order = rng.permutation(len(unique))
    fold_of_group = np.empty(len(unique), dtype=int)
    fold_of_group[order] = np.arange(len(unique)) % k
    return fold_of_group[np.searchsorted(unique, groups)]


def _bic(M: np.ndarray, predicted: np.ndarray, n_params: int) -> float:
    r = (M - predicted) / M
    sse = float(np.dot(r, r))
    N = len(M)
    return N * math.log(max(sse, 1e-300) / N) + n_params * math.log(N)


def diagnose(data: ModelData, *, k: int = 5, seed: int = 0, groups: np.ndarray | None = None,
             candidates: list[str] | None = None, excluded: list[str] | None = None,
             rows: np.ndarray | None = None) -> Diagnosis:
    """Fit, cross-validate and rank every candidate effect; choose one by :data:`SIGNIFICANCE_RULE`; measure how
    much single readings weigh in the choice (:func:`~bearingheat.analysis.influence.influence`).

    ``k`` (>= 2, at most the number of groups) is the number of folds, ``candidates`` names of
    :data:`~bearingheat.analysis.effects.CANDIDATES` (all when None; 'none' is always scored), ``rows`` the row
    number messages cite for each reading (None: its position + 1).
    """
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 2:
        raise DiagnoseError(f"k = {k!r}: the grouped cross-validation needs an integer number of folds >= 2")
    unknown = [name for name in candidates or [] if name not in CANDIDATES]
    if unknown:
        raise DiagnoseError(f"candidate {unknown[0]!r} is not one of {', '.join(EFFECT_NAMES)}")
    N = len(data)
    if N < MIN_ROWS:
        first = f"; {len(excluded)} rows left out, the first: {excluded[0]}" if excluded else ""
        raise DiagnoseError(f"diagnose needs at least {MIN_ROWS} usable rows of measured torque; got {N}{first}")
    groups = operating_point_groups([data.bearing, data.n, data.nu, data.Fr, data.Fa, data.T_oil], groups)
    n_groups = len(np.unique(groups))
    if n_groups < k:
        raise DiagnoseError(f"{k}-fold cross-validation needs at least {k} operating points (groups); got {n_groups}")
    folds = assign_folds(groups, k, seed)
    names = candidates or list(CANDIDATES)
    if "none" not in names:
        names = ["none"] + names
    effect, scores = _choose(data, folds, groups, k, names)
    none, chosen = scores["none"], scores[effect]
    assert none.predicted is not None and chosen.predicted is not None, "'none' and the chosen effect apply"
    row_names = _RowNames(rows)

    def choose_without(position: int) -> str:
        keep = np.flatnonzero(np.arange(N) != position)
        return _choose(data.take(keep), folds[keep], groups[keep], k, names)[0]

    influential = influence(CANDIDATES[effect], data, chosen.params, chosen.predicted, row_names, choose_without,
                            effect)
    structure = residual_structure(data, none.predicted)
    return Diagnosis(data, effect, scores, folds, groups, k, structure, list(excluded or []), influential)


def _choose(data: ModelData, folds: np.ndarray, groups: np.ndarray, k: int, names: list[str]
            ) -> tuple[str, dict[str, CandidateScore]]:
    """The effect :data:`SIGNIFICANCE_RULE` chooses among the candidates ``names`` and the score of each, their
    held-out errors from the ``k`` folds ``folds``, the paired test over ``groups``."""
    N = len(data)
    all_rows = np.arange(N)
    scores: dict[str, CandidateScore] = {}
    for name in names:
        candidate = CANDIDATES[name]
        reason = candidate.applicable(data)
        if reason:
            scores[name] = CandidateScore(name, False, reason)
            continue
        params = candidate.fit(data, all_rows)
        predicted = candidate.predict(data, params, all_rows)
        cv_predicted = np.empty(N)
        for fold in range(k):
            test = all_rows[folds == fold]
            train = all_rows[folds != fold]
            if len(test):  # (a fold left empty where a reading is left out to measure its influence)
                cv_predicted[test] = candidate.predict(data, candidate.fit(data, train), test)
        n_params = candidate.n_params(data, params)
        scores[name] = CandidateScore(
            name, True, "", params, candidate.public_parameters(data, params), n_params,
            error_metrics(data.M, predicted), error_metrics(data.M, cv_predicted),
            _bic(data.M, predicted, n_params), predicted=predicted, cv_predicted=cv_predicted,
            at_bound=candidate.at_bound(data, params, all_rows))
    none = scores["none"]
    assert none.predicted is not None and none.cv_predicted is not None, "'none' applies to any data"
    none.delta_bic, none.cv_improvement = 0.0, 0.0
    r_none = ((data.M - none.cv_predicted) / data.M) ** 2
    for score in scores.values():
        if not score.applicable or score.name == "none":
            continue
        score.delta_bic = none.bic - score.bic
        score.cv_improvement = 1.0 - score.cv["rel_rmse"] / none.cv["rel_rmse"]
        r_c = ((data.M - score.cv_predicted) / data.M) ** 2
        per_group = pd.Series(r_none - r_c).groupby(groups).mean().to_numpy()
        if np.allclose(per_group, 0.0):
            score.p_value = 1.0
        else:
            score.p_value = float(stats.ttest_1samp(per_group, 0.0, alternative="greater").pvalue)
        score.significant = bool(score.delta_bic >= MIN_DELTA_BIC and score.cv_improvement >= MIN_CV_IMPROVEMENT
                                 and score.p_value < MAX_P_VALUE)
    significant = [s for s in scores.values() if s.significant]
    effect = "none"
    if significant:
        best_cv = min(s.cv["rel_rmse"] for s in significant)
        tied = [s for s in significant if s.cv["rel_rmse"] <= best_cv * (1.0 + CV_TIE)]
        effect = min(tied, key=lambda s: s.bic).name
    return effect, scores


def diagnose_table(table: pd.DataFrame, *, k: int = 5, seed: int = 0,
                   candidates: list[str] | None = None) -> Diagnosis:
    """Read a measured table (unit headers), run the catalogue model and :func:`diagnose` it."""
    return diagnose_measurements(read_measurements(table), k=k, seed=seed, candidates=candidates)


def diagnose_measurements(measured: MeasuredData, *, k: int = 5, seed: int = 0,
                          candidates: list[str] | None = None) -> Diagnosis:
    """Run the catalogue model on a measured table read by :func:`read_measurements` and :func:`diagnose` it."""
    data, rows, excluded = model_data(measured)
    user_groups = measured.group[rows] if measured.group is not None else None
    numbers = measured.rows[rows] if measured.rows is not None else rows + 1  # (row_number of each, at once)
    return diagnose(data, k=k, seed=seed, groups=user_groups, candidates=candidates, excluded=excluded,
                    rows=numbers)


# ---------------------------------------------------------------------------------------------
# What the report shows
# ---------------------------------------------------------------------------------------------

def key_regressor(diagnosis: Diagnosis) -> str:
    """The regressor the residual plot is drawn against: the chosen effect's, else the strongest correlation."""
    if diagnosis.effect != "none":
        return CANDIDATES[diagnosis.effect].key_regressor
    best, best_rho = "n", -1.0
    for entry in diagnosis.structure:
        if entry["statistic"] == "spearman_rho" and entry["value"] is not None and abs(entry["value"]) > best_rho:
            best, best_rho = entry["regressor"], abs(entry["value"])
    return best
