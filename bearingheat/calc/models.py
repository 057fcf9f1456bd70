"""The friction-model registry, and the friction results of a table of supports.

:data:`MODELS` maps a model's name to its :class:`FrictionModel`: the
columns it reads and writes, its evaluation over
:class:`~bearingheat.calc.supports.SupportArrays`, and how the heat balance
finds its roots. ``friction_torque(..., model=)``, ``calc(..., model=)``,
a ``model`` column of the table, the command line and the Excel template
all look models up here. Adding a model is: a kernel module, a catalogue
module with its tables, an evaluation, and one entry below.

>>> sorted(MODELS)
['schaeffler', 'skf']
>>> get_model("palmgren")
Traceback (most recent call last):
...
bearingheat.errors.ModelError: model: 'palmgren' is not one of schaeffler, skf
"""
from __future__ import annotations

import functools
import math
from collections import defaultdict

from dataclasses import dataclass
from typing import Any, Callable

import numpy as np
import pandas as pd

from bearingheat.calc import contract
from bearingheat.calc.bushing import plain_rows
from bearingheat.calc.friction import EXCEL_FORMULAS, RESULTS, catalogue_model_at_viscosity, evaluate_catalogue_model
from bearingheat.calc.skf import RESULTS as SKF_RESULTS
from bearingheat.calc.skf import evaluate_skf_model, skf_bearing_keys
from bearingheat.calc.messages import ERROR, Labels, Problem, row_status, status_codes, with_texts
from bearingheat.calc.supports import BEARING_GROUP, KEY_INPUTS, NUMBER_INPUTS, SupportArrays, \
    build_support_arrays, coded_categorical, column_codes, nonblank, number_column, text_codes
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import ModelError
from bearingheat.kernels.friction import axial_load_torque, mean_diameter
from bearingheat.kernels.thermal import friction_heat, friction_power

__all__ = ["FrictionModel", "FrictionPower", "MODELS", "DEFAULT_MODEL", "get_model", "compute_supports",
           "RESULT_UNITS", "M2_REPORT_UNITS", "PLAIN_REPORT_UNITS", "MODEL_REPORT_UNITS", "EXTRA_INPUTS",
           "model_inputs", "support_arrays_of", "row_model_names", "rows_of_models", "SKF", "failed_rows",
           "plain_bushing_rows", "results_at_viscosity", "set_rows"]

Evaluation = Callable[[SupportArrays, Labels, "F2Chart | None"], "tuple[dict[str, np.ndarray], list[Problem]]"]


@dataclass(frozen=True)
class FrictionModel:
    """One friction model of the registry.

    ``evaluate(supports, labels, f2_chart)`` returns (results, problems):
    arrays of the model's ``outputs`` (catalogue units) and the rows that
    fail a check. ``speed_exponent`` is the power of the speed in the
    model's speed-dependent torque above its low-speed regime (M0 ∝ n^(2/3)
    for the catalogue model, whose other terms do not depend on the speed),
    which gives the heat balance its exact 5/3 root (:class:`FrictionPower`);
    None means the heat balance uses the generic bracketed root of
    :mod:`bearingheat.kernels.roots`. ``excel_formulas`` maps result
    columns to live Excel formula templates (``calc --formulas``), or is
    None where the model has none (``no_formulas`` then says why).
    ``catalogue_keys`` says whether the model
    uses the catalogue model's resolution of designations (its errors are
    then the row's); a model with its own tables reports its own.
    ``fit_terms(results) -> {name: torque [N*mm]}`` gives the terms of MR
    that a fit to measured torque scales (the catalogue model's M0 and M1:
    a fitted f0 and f1); MR minus their sum stays as computed
    (:mod:`bearingheat.analysis.comparison`). ``at_viscosity(supports,
    results) -> {name: array}`` gives the results that change when only the
    viscosity does (supports at the new ν, results of an evaluation at the
    old one; rows without M2), so that a viscosity taken at the solved
    operating temperature costs no second evaluation
    (:func:`results_at_viscosity`); None means the rows are evaluated again.
    ``bearing_keys(supports) -> (type, series)`` names the bearing type and
    the series row of the model's own tables that a row was computed with.
    ``own_minimum_load`` says whether the model checks a bearing's minimum
    load itself (the SKF model: its source's rule, under which the model
    does not hold); the rows of the other models get the bearing table's
    (:func:`bearingheat.calc.fill.below_minimum_load`).
    """

    name: str
    title: str
    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    evaluate: Evaluation
    speed_exponent: float | None = None
    excel_formulas: dict[str, str] | None = None
    catalogue_keys: bool = True
    fit_terms: Callable[[pd.DataFrame], dict[str, np.ndarray]] | None = None
    no_formulas: str = ""
    at_viscosity: Callable[[SupportArrays, dict[str, np.ndarray]], dict[str, np.ndarray]] | None = None
    bearing_keys: Callable[[SupportArrays], tuple[Any, Any]] = lambda s: (s.bearing_type, s.series)
    own_minimum_load: bool = False


SCHAEFFLER = FrictionModel(
    name="schaeffler",
    title=("catalogue friction model: M_R = M0 + M1 (+ M2), Schaeffler rolling bearing catalogue, "
           "chapter 'Friction and increases in temperature', pp. 64-70 (after ISO 15312)"),
    inputs=contract.columns(owner="friction"),
    outputs=RESULTS,
    evaluate=evaluate_catalogue_model,
    speed_exponent=2.0 / 3.0,
    excel_formulas=EXCEL_FORMULAS,
    fit_terms=lambda results: {"M0": results["M0"].to_numpy(dtype=float), "M1": results["M1"].to_numpy(dtype=float)},
    at_viscosity=catalogue_model_at_viscosity,
)

def _evaluate_skf(supports: SupportArrays, labels: Labels, f2_chart: F2Chart | None):
    return evaluate_skf_model(supports, labels, f2_chart, extra=supports.extra)


SKF = FrictionModel(
    name="skf",
    title=("SKF four-component model: M = phi_ish*phi_rs*M_rr + M_sl + M_seal + M_drag, SKF General Catalogue "
           "6000 (Russian edition), chapter 'Friction', pp. 87-105, and SKF Rolling bearings 10000/3 (2017), "
           "pp. 97-114"),
    inputs=contract.columns(owner="skf") + ("designation", "type", "series", "lubrication", "arrangement", "d",
                                             "D", "B", "C0", "C", "Y", "Fr", "Fa", "n", "nu", "Dw", "T"),
    outputs=SKF_RESULTS,
    evaluate=_evaluate_skf,
    catalogue_keys=False,
    no_formulas=("its per-type geometry constants (R1-R4, S1-S5), the seal and drag tables, the inlet shear "
                 "and replenishment factors and the edition's drag formula would take some forty helper cells "
                 "a row, too many to check by eye; bearingheat writes its results as numbers"),
    fit_terms=lambda results: {
        "phi_ish*phi_rs*M_rr": (results["phi_ish"] * results["phi_rs"] * results["M_rr"]).to_numpy(dtype=float),
        "M_sl": results["M_sl"].to_numpy(dtype=float)},
    bearing_keys=skf_bearing_keys,
    own_minimum_load=True,
)

#: name -> model; the keys come from the models themselves
MODELS: dict[str, FrictionModel] = {m.name: m for m in (SCHAEFFLER, SKF)}
#: the inputs a model reads beyond the support arrays, carried in SupportArrays.extra
EXTRA_INPUTS = tuple(dict.fromkeys(name for m in MODELS.values() if not m.catalogue_keys for name in m.inputs
                                   if name not in NUMBER_INPUTS))
DEFAULT_MODEL = SCHAEFFLER.name
contract.register_choices("model", lambda: tuple(MODELS))

#: result column -> unit, in the order calc writes them
RESULT_UNITS = {name: contract.output_units()[name] for name in RESULTS}
#: extra result columns written when a row carries M2
M2_REPORT_UNITS = {name: contract.output_units()[name] for name in ("Fa_over_A", "nu_n_dM")}
#: extra result columns written when a row is a plain bushing
PLAIN_REPORT_UNITS = contract.output_units(owner="plain")
#: result columns of the other models, written when a row uses one
MODEL_REPORT_UNITS = {name: contract.output_units()[name] for name in SKF_RESULTS if name not in RESULTS}


#: inputs that are per-row arrays in the support arrays of a table even where their column is absent: the size
#: (dM) and the operating point, which the analyses index by row
PER_ROW_INPUTS = ("d", "D", "n", "nu", "Fr", "Fa")


def model_inputs(frame: pd.DataFrame) -> dict:
    """The model-specific inputs a frame has (catalogue units; text cells as they are, the model cleans them:
    a numeric column may hold 6000.0 for the edition '6000'). calc's text columns stay categoricals: no Python
    object per row for a model that may run on none of them."""
    out = {}
    for name in EXTRA_INPUTS:
        if name in frame.columns:
            column = frame[name]
            if contract.column(name).unit != "":
                out[name] = number_column(frame, name)
            elif isinstance(column.dtype, pd.CategoricalDtype):
                out[name] = column.array
            else:
                out[name] = column.to_numpy(dtype=object)
    return out


def support_arrays_of(frame: pd.DataFrame) -> SupportArrays:
    """The support arrays of a frame in catalogue units (contract names), with the models' extra inputs."""
    keys = frame[[c for c in (*KEY_INPUTS, BEARING_GROUP) if c in frame.columns]]
    # another absent input is one NaN for all rows (the support arrays take scalars), not 8 MB of NaN per 10^6 rows
    supports = build_support_arrays(keys if len(keys.columns) else pd.DataFrame(index=frame.index),
                                    {c: number_column(frame, c) if c in frame.columns or c in PER_ROW_INPUTS
                                     else math.nan for c in NUMBER_INPUTS})
    supports.extra = model_inputs(frame)
    return supports


def get_model(name: str) -> FrictionModel:
    """The registered model of that name; an unknown name is a :class:`ModelError` listing the known ones."""
    try:
        return MODELS[name]
    except KeyError:
        raise ModelError(f"model: {name!r} is not one of {', '.join(MODELS)}") from None


def _row_models(frame: pd.DataFrame, default: str) -> tuple[np.ndarray, list[str]]:
    """Per row the code of its model name (its ``model`` cell, else ``default``), and the names the codes
    stand for (a name may appear under two codes: cells that differ only in blanks)."""
    codes, texts = text_codes(frame, "model")
    return codes, [text or default for text in texts]


def row_model_names(frame: pd.DataFrame, default: str) -> np.ndarray:
    """The model name of every row: its ``model`` cell, else ``default`` (an object array)."""
    codes, names = _row_models(frame, default)
    return np.array(names, dtype=object)[codes]


def rows_of_models(frame: pd.DataFrame, default: str, wanted: Callable[[FrictionModel], bool]) -> np.ndarray:
    """Per row whether its model (its ``model`` cell, else ``default``) is a registered one for which ``wanted``
    holds; each distinct model asked once."""
    codes, names = _row_models(frame, default)
    return np.array([name in MODELS and wanted(MODELS[name]) for name in names], dtype=bool)[codes]


def failed_rows(results: pd.DataFrame) -> np.ndarray:
    """The rows of friction results (:func:`compute_supports`) in error."""
    return status_codes(results["status"]) == ERROR


def plain_bushing_rows(results: pd.DataFrame) -> np.ndarray:
    """The rows of friction results (:func:`compute_supports`) that are plain bushings, not rolling bearings."""
    if "bearing_type" not in results.columns:
        return np.zeros(len(results), dtype=bool)
    return (results["bearing_type"] == contract.PLAIN_TYPES[0]).to_numpy(dtype=bool)


def set_rows(results: pd.DataFrame, name: str, rows: np.ndarray, values) -> None:
    """Write ``values`` into the rows ``rows`` of the number column ``name`` of ``results`` (a new column of NaN
    where it is absent)."""
    column = (results[name].to_numpy(dtype=float).copy() if name in results.columns
              else np.full(len(results), np.nan))
    column[rows] = values
    results[name] = pd.Series(column, index=results.index, copy=False)


def _model_error(name: str) -> str:
    return f"model: {name!r} is not one of {', '.join(MODELS)}"


def _message_at(problem: Problem, position: np.ndarray, row: int) -> str:
    """The message of ``problem`` (found on a subset of rows) for ``row`` of the whole table (``position``: each
    row's place in the subset)."""
    return problem.message(int(position[row]))


def _scatter(results: dict, part: dict, rows: np.ndarray, size: int) -> None:
    for name, values in part.items():
        if name not in results:
            results[name] = np.full(size, np.nan)
        results[name][rows] = values


def _own_row_array(values, size: int) -> np.ndarray:
    """``values`` (an array of ``size`` rows or one value) as a writeable float array of ``size`` rows: the model's
    own array as it is, a copy of a view or of a broadcast value."""
    if isinstance(values, np.ndarray) and values.shape == (size,) and values.dtype == np.float64 \
            and values.flags.writeable and values.flags.owndata:
        return values
    return np.array(np.broadcast_to(values, (size,)), dtype=float)


def evaluate_models(supports: SupportArrays, model_codes: np.ndarray, model_names: list[str], labels: Labels,
                    f2_chart: F2Chart | None):
    """Each row by its own model (``model_names[model_codes]``); returns (results, problems) over all rows."""
    size = supports.size
    used = np.flatnonzero(np.bincount(model_codes, minlength=len(model_names))).tolist()  # codes are 0, 1, ...
    present = [name for name in MODELS if any(model_names[k] == name for k in used)]
    if len(present) == 1 and all(model_names[k] == present[0] for k in used):
        with np.errstate(all="ignore"):
            one_model, one_model_problems = MODELS[present[0]].evaluate(supports, labels, f2_chart)
        filled = {k: _own_row_array(v, size) for k, v in one_model.items()}
        for name in RESULTS:
            filled.setdefault(name, np.full(size, np.nan))
        return filled, one_model_problems
    results: dict[str, np.ndarray] = {}
    problems: list[Problem] = []
    for name in present:
        rows = np.flatnonzero(np.array([n == name for n in model_names], dtype=bool)[model_codes])
        with np.errstate(all="ignore"):
            part, part_problems = MODELS[name].evaluate(supports.take(rows), labels.subset(rows), f2_chart)
        _scatter(results, part, rows, size)
        position = np.empty(size, dtype=np.intp)  # a row's place among this model's rows (no dict per row)
        position[rows] = np.arange(len(rows))
        for problem in part_problems:
            mask = np.zeros(size, dtype=bool)
            mask[rows] = problem.mask
            problems.append(Problem(mask, problem.level, functools.partial(_message_at, problem, position),
                                    problem.column))
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
    supports = support_arrays_of(frame)
    model_codes, model_names = _row_models(frame, model)
    plain = supports.plain
    # rows of a model with its own tables skip the catalogue's resolution errors
    catalogue_rows = np.array([name not in MODELS or MODELS[name].catalogue_keys for name in model_names],
                              dtype=bool)[model_codes]
    model_ok = np.array([name in MODELS for name in model_names], dtype=bool)[model_codes]
    # rows with messages only: error and warning lists keyed by row position
    row_errors: defaultdict[int, list[str]] = defaultdict(list)
    for i in np.flatnonzero(~model_ok & ~plain).tolist():
        row_errors[i].append(labels.cite(_model_error(model_names[model_codes[i]]), i))
    own_error = model_ok & catalogue_rows & ~plain
    for i in np.flatnonzero(own_error & nonblank(supports.error, n_rows)).tolist():
        row_errors[i].append(labels.cite(supports.error if np.ndim(supports.error) == 0 else supports.error[i], i))
    # a row whose bearing did not resolve has its error already; rows of a model with its own tables report theirs
    resolved = (np.broadcast_to(supports.resolved, (n_rows,)) | ~catalogue_rows) & model_ok

    results, problems = evaluate_models(supports, model_codes, model_names, labels, f2_chart)
    warnings_by_row: defaultdict[int, list[str]] = defaultdict(list)
    if plain.any():
        plain_rows(frame, plain, results, row_errors, warnings_by_row)
    # a row whose nu could not be found from its oil data says why itself (the heat balance's message): the model's
    # 'nu: missing' would only follow from it
    explained = (frame["_nu_explained"].to_numpy(dtype=bool) if "_nu_explained" in frame.columns
                 else np.zeros(n_rows, dtype=bool))
    silent = []
    for problem in problems:
        quiet = problem.level == "error" and problem.column == "nu"
        for i in np.flatnonzero(problem.mask & ~plain).tolist():
            if problem.level == "error":
                if quiet and explained[i]:
                    silent.append(i)
                elif resolved[i]:  # a row that failed to resolve has its error already
                    row_errors[i].append(problem.message(i))
            else:
                warnings_by_row[i].append(problem.message(i))
    notes_of = np.broadcast_to(supports.notes, (n_rows,))
    # the designation's notes concern the catalogue model's tables: rows of a model with its own tables skip them
    noted = np.broadcast_to(supports.noted, (n_rows,)) & ~plain & catalogue_rows
    for i in np.flatnonzero(noted).tolist():  # after the warnings
        warnings_by_row[i].append("; ".join(notes_of[i]))  # a designation's notes
    status, message = row_status(n_rows, warnings_by_row, row_errors, silent)
    failed = status.codes == ERROR
    reported = list(RESULT_UNITS)
    if "nu_n_dM" in results and np.any(~np.isnan(results["nu_n_dM"]) & ~failed):
        reported += list(M2_REPORT_UNITS)
    if plain.any():
        reported += list(PLAIN_REPORT_UNITS)
    reported += [col for col in MODEL_REPORT_UNITS if col in results]  # other models' results, where a row uses one
    any_failed = failed.any()  # (the arrays of evaluate_models are its own: no copy where no row failed)
    columns: dict[str, Any] = {col: np.where(failed, np.nan, results[col]) if any_failed else results[col]
                               for col in reported}
    # status and message are categoricals (messages.row_status); the bearing type and series stay categoricals
    # where the support arrays hold them so
    columns.update({name: pd.Series(values, index=frame.index, copy=False)
                    for name, values in (("status", status), ("message", message))})
    for name, values in (("bearing_type", supports.bearing_type), ("series", supports.series)):
        if isinstance(values, pd.Categorical) and not (name == "bearing_type" and plain.any()):
            columns[name] = pd.Series(values, index=frame.index, copy=False)
            continue
        cells = np.array(np.broadcast_to(np.asarray(values, dtype=object), (n_rows,)))  # its own, writeable
        if name == "bearing_type":
            cells[plain] = contract.PLAIN_TYPES[0]
        columns[name] = pd.Series(cells, index=frame.index, dtype=object, copy=False)
    columns["model"] = pd.Series(coded_categorical(model_codes, model_names), index=frame.index)
    return pd.DataFrame(columns, index=frame.index, copy=False)  # calc's own arrays: no copy into one block


def results_at_viscosity(frame: pd.DataFrame, results: pd.DataFrame, changed: np.ndarray, *,
                         f2_chart: F2Chart | None = None, labels: Labels | None = None,
                         model: str = DEFAULT_MODEL) -> pd.DataFrame:
    """The friction results of ``frame`` whose rows ``changed`` have a new ``nu``, from ``results``
    (:func:`compute_supports` of the frame at the old ν; the arguments of that call again).

    A changed row whose model has an ``at_viscosity`` update and which carries no M2 gets it: the model is not
    evaluated again. The other changed rows (another model, M2 with f2 read off the chart at ν·n·dM, a row in
    error or whose ν is now missing: its messages may change) are computed again, messages and all; their
    messages name the cells of the whole table. Returns ``results`` with those rows replaced (the same frame).
    """
    changed = np.asarray(changed, dtype=bool)
    if not changed.any():
        return results
    codes, names = column_codes(results["model"])
    updates = [MODELS[name].at_viscosity if name in MODELS else None for name in names] + [None]
    with_m2 = (~np.isnan(results["nu_n_dM"].to_numpy(dtype=float)) if "nu_n_dM" in results.columns
               else np.zeros(len(results), dtype=bool))
    again = changed & (failed_rows(results) | np.isnan(number_column(frame, "nu")) | with_m2
                       | plain_bushing_rows(results) | np.array([u is None for u in updates], dtype=bool)[codes])
    for code in np.unique(codes[changed & ~again]).tolist():
        rows = np.flatnonzero(changed & ~again & (codes == code))
        supports = support_arrays_of(frame.iloc[rows])
        with np.errstate(all="ignore"):
            part = updates[code](supports, {name: results[name].to_numpy(dtype=float)[rows] for name in RESULTS})
        for name, values in part.items():
            set_rows(results, name, rows, values)
    rows = np.flatnonzero(again)
    if len(rows):
        part = compute_supports(frame.iloc[rows].reset_index(drop=True), f2_chart=f2_chart,
                                labels=(labels or Labels()).subset(rows), model=model)
        for name in part.columns.drop(["model", "bearing_type", "series"]):
            if part[name].dtype.kind in "fiub":
                set_rows(results, name, rows, part[name].to_numpy(dtype=float))
            else:  # status, message: categoricals
                results[name] = pd.Series(with_texts(results[name], rows.tolist(), part[name].tolist()),
                                          index=results.index, copy=False)
        for name in results.columns.difference(part.columns):  # a result none of these rows has any more
            if results[name].dtype == np.float64:
                set_rows(results, name, rows, np.nan)
    return results


class FrictionPower:
    """Friction power N_R [W] of every row as a function of its speed and viscosity, by the row's model.

    The heat balance solves N_R(n, ν) + Q_E = Q_S + Q_L for the speed or the
    temperature. Rows of a model with the catalogue speed law (M0 ∝ (ν·n)^(2/3),
    M1 and M2 independent of the speed: ``speed_exponent`` 2/3) use the
    closed forms of :mod:`bearingheat.kernels.thermal` and keep the exact
    5/3 root; rows of any other model are evaluated by the model itself, so
    the heat balance finds their roots by bracketing. Rows of the catalogue
    model whose f2 is read off ``f2_chart`` at ν·n·dM (the Schaeffler
    catalogue, p. 70; ``chart_rows``) take M2 at each trial speed and
    viscosity, so they have no closed law either: their N_R is NaN where
    ν·n·dM is off the chart, and :meth:`speed_range` gives the speeds the
    chart reaches.
    """

    def __init__(self, frame: pd.DataFrame, results: pd.DataFrame, f2_chart: F2Chart | None = None):
        self.size = len(frame)
        if "model" in results.columns:  # a categorical (compute_supports): its codes, no hashing of names
            codes, distinct = column_codes(results["model"])
        else:
            codes, distinct = np.zeros(self.size, dtype=np.intp), np.array([DEFAULT_MODEL], dtype=object)
        self.f0 = results["f0"].to_numpy(dtype=float)
        self.load_torque = results["M1"].to_numpy(dtype=float) + np.nan_to_num(results["M2"].to_numpy(dtype=float))
        self.dM = mean_diameter(number_column(frame, "d"), number_column(frame, "D"))
        closed_of_name = self.closed_of(distinct)
        self.closed = np.array(closed_of_name + [True], dtype=bool)[codes]  # last: rows without a name
        self.generic: dict[str, tuple[np.ndarray, SupportArrays]] = {}
        if not self.closed.all():
            supports = support_arrays_of(frame)
            for name in sorted({str(m) for m, closed in zip(distinct, closed_of_name) if not closed}):
                rows = np.flatnonzero(np.array([m == name for m in distinct] + [False], dtype=bool)[codes])
                self.generic[name] = (rows, supports.take(rows))
        # M2 = f2·Fa·dM with f2 read off the chart (no f2 given): M2 follows ν·n·dM; M1 stays (pp. 64, 69-70)
        self.chart_rows = np.zeros(self.size, dtype=bool)
        if f2_chart is not None and "Fa_over_A" in results.columns:
            self.Fa_over_A = results["Fa_over_A"].to_numpy(dtype=float)
            self.chart_rows = (self.closed & ~np.isnan(self.Fa_over_A) & np.isnan(number_column(frame, "f2"))
                               & ~failed_rows(results))
            if self.chart_rows.any():
                self.chart, self.Fa = f2_chart, number_column(frame, "Fa")
                self.M1 = results["M1"].to_numpy(dtype=float)
                self.closed = self.closed & ~self.chart_rows
                lowest, highest = f2_chart.x_range(np.where(self.chart_rows, self.Fa_over_A, np.nan))
                self.chart_x = (lowest, highest)  # the ν·n·dM the chart reaches at each row's Fa/A [mm³/(s·min)]

    @staticmethod
    def closed_of(names) -> list[bool]:
        """Whether each model name has the catalogue speed law (an unknown name counts as closed: its rows
        are in error)."""
        return [MODELS[m].speed_exponent is not None if m in MODELS else True for m in names]

    def __call__(self, n, nu, rows: slice = slice(None)) -> np.ndarray:
        """N_R [W] of every row, or of the block ``rows`` (a slice), at speeds ``n`` [1/min] and viscosities
        ``nu`` [mm²/s] (one per row of the block)."""
        start, stop, _ = rows.indices(self.size)
        size = max(stop - start, 0)
        n = np.broadcast_to(np.asarray(n, dtype=float), (size,))
        nu = np.broadcast_to(np.asarray(nu, dtype=float), (size,))
        with np.errstate(invalid="ignore", over="ignore"):
            out = friction_heat(self.f0[rows], nu, n, self.dM[rows], self.load_torque[rows])
        for name, (model_rows, supports) in self.generic.items():
            inside = np.flatnonzero((model_rows >= start) & (model_rows < stop))
            if len(inside):
                local = model_rows[inside] - start
                block = supports if len(inside) == len(model_rows) else supports.take(inside)
                out[local] = self._evaluate(name, block, n[local], nu[local])
        local = np.flatnonzero(self.chart_rows[rows])
        if len(local):
            out[local] = self._chart_power(local + start, n[local], nu[local])
        return out

    def _chart_power(self, i: np.ndarray, n: np.ndarray, nu: np.ndarray) -> np.ndarray:
        """N_R [W] of the chart rows ``i`` at speeds ``n`` and viscosities ``nu``, with f2 read at their ν·n·dM."""
        dM = self.dM[i]
        with np.errstate(invalid="ignore", over="ignore"):
            f2 = self.chart.values(self.Fa_over_A[i], nu * n * dM)
            return friction_heat(self.f0[i], nu, n, dM, self.M1[i] + axial_load_torque(f2, self.Fa[i], dM))

    def speed_range(self, nu) -> tuple[np.ndarray, np.ndarray]:
        """The speeds [1/min] between which each row's N_R is known at the viscosity ``nu`` (one per row): 0 and
        inf, except on the chart rows, whose ν·n·dM must lie on the f2 chart (a hair inside its ends, so that
        rounding does not carry an end off the chart)."""
        low, high = np.zeros(self.size), np.full(self.size, np.inf)
        if self.chart_rows.any():
            with np.errstate(invalid="ignore", divide="ignore"):
                per_speed = np.asarray(nu, dtype=float) * self.dM
                low = np.where(self.chart_rows, self.chart_x[0] / per_speed * (1.0 + 1e-12), low)
                high = np.where(self.chart_rows, self.chart_x[1] / per_speed * (1.0 - 1e-12), high)
        return low, high

    def at_row(self, i: int, n, nu) -> np.ndarray:
        """N_R [W] of row ``i`` at many speeds and viscosities (the curves of a heat-balance figure)."""
        n, nu = np.broadcast_arrays(np.asarray(n, dtype=float), np.asarray(nu, dtype=float))
        if self.chart_rows[i]:
            return self._chart_power(np.full(n.size, i), n.ravel(), nu.ravel()).reshape(n.shape)
        if self.closed[i]:
            return friction_heat(self.f0[i], nu, n, self.dM[i], self.load_torque[i])
        for name, (rows, supports) in self.generic.items():
            if i in rows:
                position = int(np.flatnonzero(rows == i)[0])
                return self._evaluate(name, supports.take(np.full(n.size, position)), n.ravel(), nu.ravel())
        raise KeyError(i)

    def is_closed(self, i: int) -> bool:
        """Whether row ``i`` has the catalogue speed law with a constant M1 + M2 (exact 5/3 root)."""
        return bool(self.closed[i])

    @staticmethod
    def _evaluate(name: str, supports: SupportArrays, n: np.ndarray, nu: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            results, _ = MODELS[name].evaluate(supports.replace(n=n, nu=nu), Labels(), None)
        return friction_power(results["MR"], n)
