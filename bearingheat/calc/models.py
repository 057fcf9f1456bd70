"""The friction-model registry, and the friction results of a table of supports.

:data:`MODELS` maps a model's name to its :class:`FrictionModel`: the
columns it reads and writes, its evaluation over
:class:`~bearingheat.calc.supports.SupportArrays`, and how the heat balance
finds its roots. ``friction_torque(..., model=)``, ``calc(..., model=)``,
a ``model`` column of the table, the command line and the Excel template
all look models up here. Adding a model is: a kernel module, a catalogue
module with its tables, an evaluation, and one entry below.

>>> sorted(MODELS)
['schaeffler']
>>> get_model("skf")
Traceback (most recent call last):
...
bearingheat.errors.ModelError: model: 'skf' is not one of schaeffler
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd

from bearingheat.calc import contract
from bearingheat.calc.bushing import plain_rows
from bearingheat.calc.friction import RESULTS, evaluate_catalogue_model
from bearingheat.calc.messages import Labels, Problem
from bearingheat.calc.supports import KEY_INPUTS, NUMBER_INPUTS, SupportArrays, build_support_arrays, number_column, \
    text_column
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import ModelError

__all__ = ["FrictionModel", "MODELS", "DEFAULT_MODEL", "get_model", "compute_supports", "RESULT_UNITS",
           "M2_REPORT_UNITS", "PLAIN_REPORT_UNITS"]

Evaluation = Callable[[SupportArrays, Labels, "F2Chart | None"], "tuple[dict[str, np.ndarray], list[Problem]]"]


@dataclass(frozen=True)
class FrictionModel:
    """One friction model of the registry.

    ``evaluate(supports, labels, f2_chart)`` returns (results, problems):
    arrays of the model's ``outputs`` (catalogue units) and the rows that
    fail a check. ``speed_exponent`` is the power of the speed in the
    model's speed-dependent torque above its low-speed regime (M0 ∝ n^(2/3)
    for the catalogue model), which gives the heat balance a closed root;
    None means the heat balance uses the generic bracketed root.
    """

    name: str
    title: str
    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    evaluate: Evaluation
    speed_exponent: float | None = None


SCHAEFFLER = FrictionModel(
    name="schaeffler",
    title=("catalogue friction model: M_R = M0 + M1 (+ M2), Schaeffler rolling bearing catalogue, "
           "chapter 'Friction and increases in temperature', pp. 64-70 (after ISO 15312)"),
    inputs=contract.columns(owner="friction"),
    outputs=RESULTS,
    evaluate=evaluate_catalogue_model,
    speed_exponent=2.0 / 3.0,
)

#: name -> model; the keys come from the models themselves
MODELS: dict[str, FrictionModel] = {m.name: m for m in (SCHAEFFLER,)}
DEFAULT_MODEL = SCHAEFFLER.name
contract.register_choices("model", lambda: tuple(MODELS))

#: result column -> unit, in the order calc writes them
RESULT_UNITS = {name: contract.output_units()[name] for name in RESULTS}
#: extra result columns written when a row carries M2
M2_REPORT_UNITS = {name: contract.output_units()[name] for name in ("Fa_over_A", "nu_n_dM")}
#: extra result columns written when a row is a plain bushing
PLAIN_REPORT_UNITS = contract.output_units(owner="plain")


def get_model(name: str) -> FrictionModel:
    """The registered model of that name; an unknown name is a :class:`ModelError` listing the known ones."""
    try:
        return MODELS[name]
    except KeyError:
        raise ModelError(f"model: {name!r} is not one of {', '.join(MODELS)}") from None


def _row_models(frame: pd.DataFrame, default: str) -> tuple[np.ndarray, list[str]]:
    """The model name of every row (the ``model`` column, else ``default``) and the rows' errors."""
    names = np.array([v or default for v in text_column(frame, "model")], dtype=object)
    errors = ["" if name in MODELS else f"model: {name!r} is not one of {', '.join(MODELS)}" for name in names]
    return names, errors


def _scatter(results: dict, part: dict, rows: np.ndarray, size: int) -> None:
    for name, values in part.items():
        if name not in results:
            results[name] = np.full(size, np.nan)
        results[name][rows] = values


def evaluate_models(supports: SupportArrays, names: np.ndarray, labels: Labels, f2_chart: F2Chart | None):
    """Each row by its own model; returns (results, problems) over all rows."""
    size = supports.size
    present = [name for name in MODELS if np.any(names == name)]
    if len(present) == 1 and np.all(names == present[0]):
        with np.errstate(all="ignore"):
            results, problems = MODELS[present[0]].evaluate(supports, labels, f2_chart)
        return {k: np.array(v, dtype=float) for k, v in results.items()}, problems
    results: dict[str, np.ndarray] = {}
    problems: list[Problem] = []
    for name in present:
        rows = np.flatnonzero(names == name)
        with np.errstate(all="ignore"):
            part, part_problems = MODELS[name].evaluate(supports.take(rows), labels, f2_chart)
        _scatter(results, part, rows, size)
        for problem in part_problems:
            mask = np.zeros(size, dtype=bool)
            mask[rows] = problem.mask
            problems.append(Problem(mask, problem.level,
                                    lambda i, p=problem, pos={int(r): k for k, r in enumerate(rows)}: p.message(pos[i])))
    for name in RESULTS:
        results.setdefault(name, np.full(size, np.nan))
    return results, problems


def compute_supports(frame: pd.DataFrame, *, f2_chart: F2Chart | None = None, labels: Labels | None = None,
                     model: str = DEFAULT_MODEL) -> pd.DataFrame:
    """Friction results for every row of ``frame`` (catalogue units, contract column names).

    Returns a DataFrame with the index of ``frame`` and the columns of
    :data:`RESULT_UNITS`, ``status`` and ``message`` (plus ``Fa_over_A``
    and ``nu_n_dM`` when a row carries M2, ``p_plain`` and ``V_plain`` for
    plain bushings, and ``bearing_type``/``series``). ``model`` is the
    model of rows whose ``model`` cell is blank.
    """
    get_model(model)
    labels = labels or Labels()
    n_rows = len(frame)
    keys = frame[[c for c in KEY_INPUTS if c in frame.columns]]
    numbers = {c: number_column(frame, c) for c in NUMBER_INPUTS}
    supports = build_support_arrays(keys if len(keys.columns) else pd.DataFrame(index=frame.index), numbers)
    names, model_errors = _row_models(frame, model)
    plain = supports.plain
    row_errors: list[list[str]] = [[] for _ in range(n_rows)]
    for i in range(n_rows):
        text = model_errors[i] or (supports.error[i] if np.ndim(supports.error) else supports.error)
        if text and not plain[i]:
            row_errors[i].append(text)
    resolved = np.broadcast_to(supports.resolved, (n_rows,)) & np.array([not e for e in model_errors])

    results, problems = evaluate_models(supports, names, labels, f2_chart)
    for i, notes in enumerate(supports.notes if len(supports.notes) == n_rows else supports.notes * n_rows):
        if notes:
            mask = np.zeros(n_rows, dtype=bool)
            mask[i] = True
            problems.append(Problem(mask, "warning", lambda j, text="; ".join(notes): text))

    warnings_by_row: list[list[str]] = [[] for _ in range(n_rows)]
    if plain.any():
        plain_rows(frame, plain, results, row_errors, warnings_by_row)
    for problem in problems:
        for i in np.flatnonzero(problem.mask & ~plain):
            if problem.level == "error":
                if resolved[i]:  # a row that failed to resolve has its error already
                    row_errors[i].append(problem.message(i))
            else:
                warnings_by_row[i].append(problem.message(i))
    out = pd.DataFrame({col: results[col] for col in RESULT_UNITS}, index=frame.index)
    status, message = [], []
    for i in range(n_rows):
        if row_errors[i]:
            status.append("error")
            message.append("; ".join(row_errors[i]))
        elif warnings_by_row[i]:
            status.append("warning")
            message.append("; ".join(warnings_by_row[i]))
        else:
            status.append("ok")
            message.append("")
    failed = np.array([s == "error" for s in status], dtype=bool)
    out.loc[failed, list(RESULT_UNITS)] = np.nan
    if "nu_n_dM" in results and np.any(~np.isnan(results["nu_n_dM"]) & ~failed):
        for col in M2_REPORT_UNITS:
            out[col] = np.where(failed, np.nan, results[col])
    if plain.any():
        for col in PLAIN_REPORT_UNITS:
            out[col] = np.where(failed, np.nan, results[col])
    out["status"] = status
    out["message"] = message
    out["bearing_type"] = np.where(plain, "plain_bushing", np.broadcast_to(supports.bearing_type, (n_rows,)))
    out["series"] = np.broadcast_to(supports.series, (n_rows,))
    return out
