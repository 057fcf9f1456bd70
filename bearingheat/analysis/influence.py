"""How much single readings weigh in diagnose's choice: outlier test, leverage and Cook's distance of the chosen fit.

The candidates are fitted, and the choice is made, on relative residuals e = (M − model)/M, so a reading whose
torque is off by a decimal weighs like hundreds of good ones: one reading read at a tenth of its value turned a
seal-drag data set of 504 readings into 'drag_losses'. :func:`influence` measures, for the fit of the chosen
effect, each reading's leverage h (the diagonal of J(JᵀJ)⁺Jᵀ, J the Jacobian of e with respect to the parameters
not on a bound, by forward differences), its internally and externally studentised residual and Cook's distance
(Cook and Weisberg, *Residuals and Influence in Regression*, 1982, ch. 2 and 3). A reading is flagged by the
Bonferroni outlier test of its externally studentised residual (:data:`INFLUENCE_RULE`); the most outlying flagged
reading is then left out, the choice made again on the other rows with the same folds, and a changed choice is
reported as a warning. Nothing is dropped from the result.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np
from scipy import stats

from bearingheat.analysis.effects import Candidate, ModelData, Params, bound_sides

__all__ = ["OUTLIER_LEVEL", "SHOWN_READINGS", "INFLUENCE_RULE", "ReadingNames", "Influence", "leverage", "influence"]

#: family-wise level of the Bonferroni outlier test of the studentised residuals
OUTLIER_LEVEL = 0.05
#: the readings the report lists (the largest studentised residuals)
SHOWN_READINGS = 5
#: relative step of the forward differences of the Jacobian
_STEP = 1e-6
INFLUENCE_RULE = (
    f"A reading is flagged when its externally studentised relative residual under the chosen effect fails the "
    f"Bonferroni outlier test: N times its two-sided p (Student's t, N − p − 1 degrees of freedom, p the effect's "
    f"parameters not on a bound) is below {OUTLIER_LEVEL:g}. The most outlying flagged reading is left out and the "
    f"choice made again on the other rows, with the same folds; a changed choice is a warning. The choice runs on "
    f"sums of squared relative residuals, which the most outlying reading dominates; Cook's distance, shown too, "
    f"measures its pull on the chosen effect's parameters. No reading is dropped from the result.")


class ReadingNames(Protocol):
    """The names of the readings by position, ``names[position]``: a list, or names made when asked (diagnose's)."""

    def __getitem__(self, position: int, /) -> str: ...


@dataclass
class Influence:
    """The influence of single readings on the chosen effect (:func:`influence`).

    ``readings``: the :data:`SHOWN_READINGS` readings of the largest externally studentised residual, each with
    its ``row``, measured ``M`` and ``predicted`` torque [N·mm], ``relative_residual``, ``leverage``,
    ``studentised`` (external), ``cooks_distance`` and Bonferroni ``p_value``, and ``flagged``. ``flagged`` counts
    the flagged readings; ``dropped`` is the row left out for the second choice (None where none is flagged) and
    ``effect_without`` the effect chosen without it.
    """

    effect: str
    n_params: int
    readings: list[dict[str, Any]] = field(default_factory=list)
    flagged: int = 0
    dropped: str | None = None
    effect_without: str | None = None

    @property
    def warning(self) -> str | None:
        """The warning where leaving out the most outlying reading changes the choice, else None."""
        if self.dropped is None or self.effect_without == self.effect:
            return None
        return (f"one reading decides the choice: without {self.dropped} (its studentised residual "
                f"{self.readings[0]['studentised']:.3g}) the effect chosen is '{self.effect_without}', not "
                f"'{self.effect}'; check that reading")

    def as_json(self) -> dict[str, Any]:
        return {"rule": INFLUENCE_RULE, "n_params": self.n_params, "flagged": self.flagged,
                "readings": self.readings, "dropped": self.dropped, "effect_without": self.effect_without,
                "warning": self.warning}


def _jacobian_columns(candidate: Candidate, data: ModelData, params: Params, predicted: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, int]:
    """The Jacobian of the relative residuals with respect to the parameters not on a bound, as each row's
    non-zero entries: values V and column indices C (rows × entries; index p where the entry is 0), and p.

    A float parameter is one column; an array per bearing one column per bearing, non-zero on its bearing's
    rows only, so every row has at most one entry per parameter name.
    """
    rows = np.arange(len(data))
    values, columns = [], []
    p = 0
    for name, (low, high) in candidate.limits(data, rows).items():
        value = params[name]
        per_bearing = np.ndim(value) > 0
        current = np.asarray(value, dtype=float)
        # inside its bounds (no side: None), and fitted (a NaN bound: a bearing whose parameter is not fitted)
        free = ~bound_sides(current, low, high).astype(bool) & np.isfinite(np.broadcast_to(low, current.shape))
        if not free.any():
            continue
        step = np.where(free, _STEP * np.maximum(np.abs(current), 1e-12), 0.0)
        moved = candidate.predict(data, {**params, name: current + step if per_bearing else float(current + step)},
                                  rows)
        if per_bearing:
            codes = np.cumsum(free) - 1 + p          # column of each fitted bearing's parameter
            row_free = free[data.bearing]
            derivative = np.where(row_free, (moved - predicted) / np.where(row_free, step[data.bearing], 1.0), 0.0)
            column = np.where(row_free, codes[data.bearing], -1)
            p += int(free.sum())
        else:
            derivative = (moved - predicted) / float(step)
            column = np.full(len(data), p)
            p += 1
        values.append(-derivative / data.M)
        columns.append(column)
    if not values:
        return np.zeros((len(data), 0)), np.zeros((len(data), 0), dtype=np.intp), 0
    C = np.column_stack(columns)
    return np.column_stack(values), np.where(C < 0, p, C), p


def leverage(candidate: Candidate, data: ModelData, params: Params, predicted: np.ndarray) -> tuple[np.ndarray, int]:
    """The leverage h of every reading in the fit of ``candidate`` (``params``, its ``predicted`` torque) and the
    rank of its Jacobian (the parameters that move the fit): h = diag(J (JᵀJ)⁺ Jᵀ), J the Jacobian of the relative
    residuals with respect to the parameters not on a bound. 0 for every reading of 'none'."""
    V, C, p = _jacobian_columns(candidate, data, params, predicted)
    if p == 0:
        return np.zeros(len(data)), 0
    size = p + 1                                      # index p: a zero entry
    normal = np.zeros(size * size)
    for j in range(V.shape[1]):
        for k in range(V.shape[1]):
            normal += np.bincount(C[:, j] * size + C[:, k], weights=V[:, j] * V[:, k], minlength=size * size)
    A = normal.reshape(size, size)[:p, :p]
    inverse = np.zeros((size, size))
    inverse[:p, :p] = np.linalg.pinv(A)
    h = np.zeros(len(data))
    for j in range(V.shape[1]):
        for k in range(V.shape[1]):
            h += V[:, j] * V[:, k] * inverse[C[:, j], C[:, k]]
    return np.clip(h, 0.0, 1.0), int(np.linalg.matrix_rank(A))


def influence(candidate: Candidate, data: ModelData, params: Params, predicted: np.ndarray, row_names: ReadingNames,
              choose_without: Callable[[int], str], effect: str) -> Influence:
    """The outlier test, leverage and Cook's distance of every reading in the fit of the chosen ``effect``
    (``candidate`` with ``params`` and its ``predicted`` torque), and the choice without the most outlying flagged
    reading (``choose_without(position)`` makes the choice again without it). ``row_names`` name the readings."""
    N = len(data)
    residual = (data.M - predicted) / data.M
    h, p = leverage(candidate, data, params, predicted)
    dof = N - p
    s2 = float(residual @ residual) / dof if dof > 0 else math.nan
    with np.errstate(divide="ignore", invalid="ignore"):
        # a reading fitted exactly by a parameter of its own (h = 1) has no studentised residual: taken as 0
        internal = np.where(1.0 - h > 1e-9, residual / np.sqrt(s2 * (1.0 - h)), 0.0)
        external = internal * np.sqrt(np.clip((dof - 1) / (dof - internal ** 2), 0.0, None)) if dof > 1 \
            else np.zeros(N)
        cooks = internal ** 2 * h / (p * (1.0 - h)) if p else np.zeros(N)
    cooks = np.where(np.isfinite(cooks), cooks, 0.0)
    p_values = np.minimum(1.0, N * 2.0 * stats.t.sf(np.abs(external), max(dof - 1, 1)))
    flagged = p_values < OUTLIER_LEVEL
    order = np.argsort(-np.abs(external), kind="stable")
    shown = [{"row": row_names[i], "M": float(data.M[i]), "predicted": float(predicted[i]),
              "relative_residual": float(residual[i]), "leverage": float(h[i]),
              "studentised": float(external[i]), "cooks_distance": float(cooks[i]), "p_value": float(p_values[i]),
              "flagged": bool(flagged[i])} for i in order[:SHOWN_READINGS]]
    result = Influence(effect, p, shown, int(flagged.sum()))
    if flagged.any():
        worst = int(order[0])
        result.dropped = row_names[worst]
        result.effect_without = choose_without(worst)
    return result
