"""Which friction model fits measured torque better: each model's error before and after fitting its scales.

Every model of :data:`bearingheat.calc.models.MODELS` names the terms of
its torque that a fit may scale (:attr:`FrictionModel.fit_terms`): M0 and
M1 of the catalogue model (a fitted f0 and f1), φish·φrs·M_rr and M_sl of
the SKF model (a fitted rolling and sliding moment); the model's other
terms (M2, seals, drag) stay as computed. For each model:

- *before*: the model as published, on every usable row;
- *after*: the scales fitted by non-negative least squares on relative
  residuals, ``min Σ ((M − fixed − Σ kᵢ·termᵢ)/M)²``, both on the fitting
  data and on held-out folds of a grouped k-fold cross-validation (the
  groups and folds of :mod:`bearingheat.analysis.diagnose`, so repeated
  readings of one operating point never sit on both sides of a split).

Every model is scored on the same rows: those that are usable in every
model. The better model is the one with the lower held-out relative RMSE
after fitting; how much better is the ratio of the two, with a one-sided
paired t-test over the groups of the held-out squared relative errors.
Residuals are measured − model throughout.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
from scipy import optimize, stats

from bearingheat.analysis.diagnose import (MIN_ROWS, MeasuredData, assign_folds, error_metrics, operating_point_groups,
                                           read_measurements)
from bearingheat.analysis.effects import bearing_keys
from bearingheat.calc.models import DEFAULT_MODEL, MODELS, compute_supports, failed_rows, get_model
from bearingheat.calc.supports import number_column
from bearingheat.calc.table import calc
from bearingheat.errors import DiagnoseError

__all__ = ["ALL_MODELS", "ModelFit", "ModelComparison", "model_names", "compare_models", "compare_models_table",
           "side_by_side"]

#: the ``--model`` value that compares every model of the registry
ALL_MODELS = "all"


@dataclass(frozen=True)
class ModelFit:
    """One model on the compared rows: its error as published and with its terms' scales fitted."""

    model: str
    scales: dict[str, float]          # fitted factor of each fit term (1 = as published)
    before: dict[str, float]          # error_metrics of the model as published
    after: dict[str, float]           # error_metrics with the fitted scales, on the fitting data
    cv_after: dict[str, float]        # error_metrics of the held-out predictions of the fitted scales
    bic_after: float
    predicted: np.ndarray             # N·mm, as published
    fitted: np.ndarray                # N·mm, with the fitted scales
    cv_fitted: np.ndarray             # N·mm, held-out predictions

    def as_json(self) -> dict[str, Any]:
        return {"model": self.model, "scales": self.scales, "before": self.before, "after": self.after,
                "cv_after": self.cv_after, "bic_after": self.bic_after}


@dataclass(frozen=True)
class ModelComparison:
    """The outcome of :func:`compare_models`."""

    fits: dict[str, ModelFit]
    best: str
    runner_up: str | None
    ratio: float                      # runner-up's held-out rel. RMSE / the best's (NaN with one model)
    p_value: float                    # one-sided paired t-test over groups (NaN with one model)
    n_rows: int
    k: int
    excluded: list[str]
    measured: np.ndarray              # N·mm, the compared rows

    def verdict(self) -> str:
        """One sentence: which model fits better and by how much."""
        best = self.fits[self.best]
        if self.runner_up is None:
            return (f"{self.best}: held-out relative RMSE {best.cv_after['rel_rmse']:.1%} after fitting its scales "
                    f"({best.before['rel_rmse']:.1%} as published), {self.n_rows} rows.")
        other = self.fits[self.runner_up]
        return (f"{self.best} fits these data better than {self.runner_up}: held-out relative RMSE after fitting "
                f"{best.cv_after['rel_rmse']:.1%} against {other.cv_after['rel_rmse']:.1%} ({self.ratio:.2f} times "
                f"lower, paired t-test over operating points p = {self.p_value:.2g}); as published "
                f"{best.before['rel_rmse']:.1%} against {other.before['rel_rmse']:.1%}; {self.n_rows} rows.")

    def table(self) -> pd.DataFrame:
        """One row per model: the errors before and after fitting, and the fitted scales."""
        rows = []
        for fit in self.fits.values():
            rows.append({"model": fit.model, "rmse_before [N*mm]": fit.before["rmse"],
                         "rel_rmse_before": fit.before["rel_rmse"], "bias_before [N*mm]": fit.before["bias"],
                         "rmse_after [N*mm]": fit.after["rmse"], "cv_rmse_after [N*mm]": fit.cv_after["rmse"],
                         "cv_rel_rmse_after": fit.cv_after["rel_rmse"],
                         "scales": ", ".join(f"{name} × {value:.3g}" for name, value in fit.scales.items())})
        return pd.DataFrame(rows)

    def summary(self) -> dict[str, Any]:
        return {"best": self.best, "runner_up": self.runner_up, "ratio": _clean(self.ratio),
                "p_value": _clean(self.p_value), "n_rows": self.n_rows, "folds": self.k,
                "verdict": self.verdict(), "residual": "measured - model",
                "models": {name: fit.as_json() for name, fit in self.fits.items()}}


def _clean(value: float) -> float | None:
    return None if not math.isfinite(value) else float(value)


def model_names(model: str) -> tuple[str, ...]:
    """The models a ``--model`` value selects: one name of the registry, or ``all``.

    >>> model_names("all")
    ('schaeffler', 'skf')
    """
    if model == ALL_MODELS:
        return tuple(MODELS)
    return (get_model(model).name,)


def _evaluate(measured: MeasuredData, name: str) -> tuple[np.ndarray, dict[str, np.ndarray], np.ndarray, list[str]]:
    """(MR, fit terms, usable mask, exclusion messages) of one model on every measured row."""
    results = compute_supports(measured.frame, labels=measured.labels, model=name)
    failed = failed_rows(results)
    messages = [f"{measured.row(i)} ({name}): {results['message'].iat[i]}" for i in map(int, np.flatnonzero(failed))]
    MR = results["MR"].to_numpy(dtype=float)
    model = get_model(name)
    if model.fit_terms is None:
        raise DiagnoseError(f"model {name!r} names no terms a fit may scale; it cannot be compared")
    terms = model.fit_terms(results)
    usable = ~failed & np.isfinite(MR)
    for values in terms.values():
        usable &= np.isfinite(values)
    return MR, terms, usable, messages


def _fit_scales(M: np.ndarray, fixed: np.ndarray, terms: np.ndarray) -> np.ndarray:
    """Non-negative least squares of (M − fixed)/M on terms/M (one column per fit term)."""
    scales, _ = optimize.nnls(terms / M[:, None], (M - fixed) / M)
    return scales


def compare_models(measured: MeasuredData, models: tuple[str, ...] = (DEFAULT_MODEL,), *, k: int = 5, seed: int = 0
                   ) -> ModelComparison:
    """Score each model on the rows usable in all of them, as published and with its term scales fitted.

    Parameters
    ----------
    measured : MeasuredData
        A measured table read by :func:`bearingheat.analysis.diagnose.read_measurements`.
    models : tuple of str
        Names of :data:`bearingheat.calc.models.MODELS`.
    k : int
        Folds of the grouped cross-validation.
    seed : int
        Seed of the fold assignment.

    Returns
    -------
    ModelComparison

    Raises
    ------
    bearingheat.errors.DiagnoseError
        With fewer than the minimum usable rows or operating points.
    """
    evaluated = {name: _evaluate(measured, name) for name in models}
    usable = np.array([not errors for errors in measured.row_errors], dtype=bool)
    excluded = ["; ".join(errors) for errors in measured.row_errors if errors]
    for MR, terms, model_usable, messages in evaluated.values():
        usable &= model_usable
        excluded.extend(messages)
    rows = np.flatnonzero(usable)
    if len(rows) < MIN_ROWS:
        first = f"; the first left out: {excluded[0]}" if excluded else ""
        raise DiagnoseError(f"the model comparison needs at least {MIN_ROWS} rows usable in every model "
                            f"({', '.join(models)}); got {len(rows)}{first}")
    M = measured.M[rows]
    frame = measured.frame.iloc[rows]
    keys = [pd.factorize(pd.Series(bearing_keys(frame), dtype=object))[0]]
    keys += [number_column(frame, name) for name in ("n", "nu", "Fr", "Fa")] + [measured.T_oil[rows]]
    groups = operating_point_groups(keys, None if measured.group is None else measured.group[rows])
    if len(np.unique(groups)) < k:
        raise DiagnoseError(f"{k}-fold cross-validation needs at least {k} operating points (groups); "
                            f"got {len(np.unique(groups))}")
    folds = assign_folds(groups, k, seed)
    fits = {name: _fit_model(name, M, MR[rows], {t: v[rows] for t, v in terms.items()}, folds, k)
            for name, (MR, terms, _, _) in evaluated.items()}
    ranked = sorted(fits.values(), key=lambda fit: fit.cv_after["rel_rmse"])
    best = ranked[0]
    if len(ranked) == 1:
        return ModelComparison(fits, best.model, None, math.nan, math.nan, len(rows), k, excluded, M)
    other = ranked[1]
    squared = {fit.model: ((M - fit.cv_fitted) / M) ** 2 for fit in (best, other)}
    per_group = pd.Series(squared[other.model] - squared[best.model]).groupby(groups).mean().to_numpy()
    p_value = 1.0 if np.allclose(per_group, 0.0) else \
        float(stats.ttest_1samp(per_group, 0.0, alternative="greater").pvalue)
    ratio = other.cv_after["rel_rmse"] / best.cv_after["rel_rmse"]
    return ModelComparison(fits, best.model, other.model, ratio, p_value, len(rows), k, excluded, M)


def _fit_model(name: str, M: np.ndarray, MR: np.ndarray, terms: dict[str, np.ndarray], folds: np.ndarray,
               k: int) -> ModelFit:
    matrix = np.column_stack(list(terms.values()))
    fixed = MR - matrix.sum(axis=1)
    scales = _fit_scales(M, fixed, matrix)
    fitted = fixed + matrix @ scales
    cv_fitted = np.empty_like(M)
    for fold in range(k):
        test, train = folds == fold, folds != fold
        cv_fitted[test] = fixed[test] + matrix[test] @ _fit_scales(M[train], fixed[train], matrix[train])
    relative = (M - fitted) / M
    N = len(M)
    bic = N * math.log(max(float(relative @ relative), 1e-300) / N) + len(scales) * math.log(N)
    return ModelFit(name, {t: float(s) for t, s in zip(terms, scales)}, error_metrics(M, MR),
                    error_metrics(M, fitted), error_metrics(M, cv_fitted), bic, MR, fitted, cv_fitted)


def compare_models_table(table: pd.DataFrame, model: str = ALL_MODELS, *, k: int = 5, seed: int = 0
                         ) -> ModelComparison:
    """Read a measured table (unit headers, ``M [N*mm]``) and :func:`compare_models` the models ``model`` selects."""
    return compare_models(read_measurements(table), model_names(model), k=k, seed=seed)


def side_by_side(table: pd.DataFrame, models: tuple[str, ...] | None = None) -> pd.DataFrame:
    """MR and NR of every support under each model, and each model's MR over the default model's.

    Parameters
    ----------
    table : pandas.DataFrame
        A calc table (``name [unit]`` headers) with the inputs every model needs.
    models : tuple of str, optional
        Names of :data:`bearingheat.calc.models.MODELS` (default: all).

    Returns
    -------
    pandas.DataFrame
        ``id`` (or ``designation``), then ``MR [N*mm] (model)`` and ``NR [W] (model)`` per model and
        ``MR model/default`` for the other models; a row in error under a model has NaN there and its
        message in ``message (model)``.
    """
    models = tuple(models or MODELS)
    label = "id" if "id" in table.columns else "designation"
    out = pd.DataFrame({label: table[label].to_numpy()}, index=table.index)
    out["designation"] = table["designation"].to_numpy()
    for name in models:
        result = calc(table, model=name)
        out[f"MR [N*mm] ({name})"] = result["MR [N*mm]"].to_numpy()
        out[f"NR [W] ({name})"] = result["NR [W]"].to_numpy()
        out[f"message ({name})"] = np.where(result["status"] == "error", result["message"], "")
    for name in models:
        if name != DEFAULT_MODEL and DEFAULT_MODEL in models:
            out[f"MR {name}/{DEFAULT_MODEL}"] = out[f"MR [N*mm] ({name})"] / out[f"MR [N*mm] ({DEFAULT_MODEL})"]
    return out.loc[:, [c for c in out.columns if not (c.startswith("message") and not out[c].astype(bool).any())]]
