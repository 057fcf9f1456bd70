"""The heat balance of a table of supports (catalogue units) and the ``bearingheat calc`` extension ``thermal``.

Row functions: :func:`thermal_reference_speed_rows` and
:func:`thermal_reference_speed_details` (n_θr of catalogue bearings),
:func:`fill_viscosity` (ν from nu40/nu100 or iso_vg before the friction
pass) and :func:`heat_balance_rows` (n_thr, n_per, T_op, nu_op, Q_S, Q_L
after it). The formulas are :mod:`bearingheat.kernels.thermal`, the
reference conditions :mod:`bearingheat.catalogue.thermal`; the unit-aware
functions are :mod:`bearingheat.api.thermal` (after Schaeffler
HR 1, ISO 15312 and DIN 732).

As a calc extension (:func:`prepare`, :func:`extend`) it reads the
optional input columns of the column contract whose owner is ``thermal``
(:mod:`bearingheat.calc.contract`: T, k_q, T_amb, T_bearing, V_oil,
dT_oil, Q_E, nu40, nu100, iso_vg, VI, n_G, n_thr_catalogue) and B, C0 of
the friction model.

Output columns, each where its inputs are present: ``n_thr [1/min]`` (B or
T, or T_amb; C0), ``n_per [1/min]`` (T_bearing, T_amb), ``T_op [degC]`` and
``nu_op [mm^2/s]`` (T_amb; the operating temperature at the speed n),
``Q_S [W]`` and ``Q_L [W]`` (heat carried away at T_bearing, or at T_op
where T_bearing is not given).

When ``nu`` is left out and ``nu40``/``nu100`` or ``iso_vg`` are given,
:func:`prepare` fills it before the friction pass, at the row's
``viscosity_at``: by default (auto) at the operating temperature T_op
solved at the operating speed where the row gives ``n`` and ``T_amb``, and
at ``T_bearing`` where it does not or where T_op has no solution. A ``nu``
the user gives is kept as it is.

>>> n_thr = thermal_reference_speed_rows(pd.DataFrame(
...     {"designation": ["6205", "NU206-E", "51105"], "d": [25, 30, 25], "D": [52, 62, 42],
...      "B": [15, 16, 11], "C0": [7800, 36000, 28500]}))
>>> n_thr.round(0).tolist()[:2]
[14416.0, 9851.0]
>>> n_thr.attrs["reason"].iloc[2]
'n_thr: the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings'
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.contract import columns, register_choices
from bearingheat.calc.models import (DEFAULT_MODEL, FrictionPower, failed_rows, plain_bushing_rows, results_at_viscosity,
                                    set_rows)
from bearingheat.calc.operating_temperature import (BELOW_AMBIENT_SEARCH, OPERATING_TEMPERATURE_LIMIT,
                                                    lowest_operating_temperature, operating_point)
from bearingheat.calc.permissible_speed import (DEFAULT_SPEED_FACTOR_METHOD, SPEED_FACTOR_METHODS, SpeedFactorMethod,
                                                permissible_speed_rows)
from bearingheat.calc.reference_speed import (SEAL_FRICTION, seal_friction_rows, thermal_reference_speed_details,
                                              thermal_reference_speed_rows)
from bearingheat.calc.messages import with_texts
from bearingheat.calc.supports import coded_categorical, nonblank, number_column, text_codes, with_columns
from bearingheat.calc.heat_flows import (HEAT_BALANCE_DETAILS, OIL_DATA, heat_flow_setup, viscosity_of_rows,
                                         walther_columns)
from bearingheat.errors import HeatBalanceError
from bearingheat.kernels.thermal import OIL_HEAT_CAPACITY_FLOW
from bearingheat.kernels.viscosity import MIN_VISCOSITY, viscosity_range_messages, walther_viscosity

__all__ = [
    "OPERATING_TEMPERATURE_LIMIT",
    "BELOW_AMBIENT_SEARCH",
    "SPEED_FACTOR_METHODS",
    "DEFAULT_SPEED_FACTOR_METHOD",
    "SpeedFactorMethod",
    "VISCOSITY_AT",
    "DEFAULT_VISCOSITY_AT",
    "THERMAL_INPUTS",
    "lowest_operating_temperature",
    "thermal_reference_speed_details",
    "thermal_reference_speed_rows",
    "fill_viscosity",
    "settle_viscosity",
    "heat_balance_rows",
    "prepare",
    "extend",
]

#: the temperature [°C] of the provisional viscosity of the friction pass for rows whose ν is taken at T_op (only
#: M0 depends on it, and M0 is computed again at ν(T_op))
PROVISIONAL_TEMPERATURE = 70.0
#: where a row's ν comes from (the hidden column ``_nu_at``; '' for a row without oil data and without ν)
NU_SOURCES = ("given", "T_bearing", "T_op", "")
#: where the operating viscosity is taken when it comes from nu40/nu100 or iso_vg
VISCOSITY_AT = {
    "auto": ("the solved operating temperature T_op where T_amb and n are given (one operating state: the "
             "friction results, T_op and nu_op agree), otherwise, or where T_op has no solution, T_bearing"),
    "bearing": "the bearing temperature T_bearing (the friction results at the temperature n_per is found for)",
    "operating": "the solved operating temperature T_op at the operating speed n",
}
#: the viscosity_at of rows whose cell is blank
DEFAULT_VISCOSITY_AT = "auto"


#: input columns that only the heat balance reads (B and C0 belong to the friction model as well)
THERMAL_INPUTS = frozenset(columns(owner="thermal", kind="input"))


# ---- rows: heat balance of supports (calc and the Python API) --------------------------------


def fill_viscosity(frame: pd.DataFrame, *, viscosity_at: str = "auto"):
    """Fill an empty ``nu`` from ``nu40``/``nu100`` or ``iso_vg`` (catalogue units); returns (frame, problems).

    ``viscosity_at`` (a key of :data:`VISCOSITY_AT`) is the temperature of
    rows whose ``viscosity_at`` cell is blank. 'auto' takes the viscosity at
    the operating temperature T_op solved at the operating speed where the
    row gives ``T_amb`` and ``n`` (falling back to ``T_bearing`` where T_op
    has no solution: the heat balance's message says why), otherwise at
    ``T_bearing``;
    'bearing' at ``T_bearing``; 'operating' at T_op. A ``nu`` the user gives
    is never replaced. The Walther constants stay in the hidden columns
    ``_walther_A`` and ``_walther_B`` for the heat balance; ``_nu_at`` says
    where each row's ``nu`` comes from ('given', 'T_bearing', 'T_op').

    T_op needs the friction results, so a row to be taken at T_op gets a
    provisional ν (at :data:`PROVISIONAL_TEMPERATURE`) for the one friction
    pass and is marked in the hidden column ``_nu_pending``;
    :func:`settle_viscosity` then solves its T_op from that pass and puts in
    ν(T_op) (``_nu_fallback`` marks the rows that fall back to T_bearing).
    """
    if viscosity_at not in VISCOSITY_AT:
        raise HeatBalanceError(f"viscosity_at: {viscosity_at!r} is not one of {', '.join(VISCOSITY_AT)}")
    if not OIL_DATA & set(frame.columns):  # nothing to fill from: the frame as it is (the heat balance sees no A, B)
        return frame, []
    A, B, problems = walther_columns(frame)
    # the new and replaced columns go into a new frame at the end (calc's frame itself is not changed)
    frame = with_columns(frame, {"_walther_A": A, "_walther_B": B})
    if np.isnan(A).all():
        # no row's oil data gives a line: each row's own error says why (the table is not refused for lack of nu)
        no_line = {"_nu_explained": _rows_in_error(problems, len(frame))}
        if "nu" not in frame.columns:
            no_line["nu"] = np.full(len(frame), np.nan)
        return with_columns(frame, no_line), problems
    modes = _row_choices(frame, "viscosity_at", viscosity_at, VISCOSITY_AT, problems)
    nu = number_column(frame, "nu")
    given = ~np.isnan(nu)
    need = ~given & ~np.isnan(A)
    T_bearing = number_column(frame, "T_bearing")
    T_amb, n = number_column(frame, "T_amb"), number_column(frame, "n")
    solvable = ~np.isnan(T_amb) & ~np.isnan(n)
    # auto: T_op where it can be solved; without T_bearing, T_op is the only way (its refusals name what is missing)
    at_operating = need & ((modes == "operating") | ((modes == "auto") & (solvable | np.isnan(T_bearing))))
    at_bearing = need & ~at_operating & modes.isin(("auto", "bearing")) & ~np.isnan(T_bearing)
    for i in np.flatnonzero(need & (modes == "bearing") & np.isnan(T_bearing)):
        problems.append((int(i), "error", "T_bearing [degC]: missing; the viscosity is to be taken at the "
                                          "bearing temperature"))
    for i in np.flatnonzero(at_operating & ~solvable):
        missing = "T_amb [degC]" if np.isnan(T_amb[i]) else "n [1/min]"
        problems.append((int(i), "error", f"{missing}: missing; nu from nu40/nu100 or iso_vg is taken at the "
                                          "operating temperature T_op, which needs n and T_amb (or give T_bearing)"))
    # without D no row has friction results to solve T_op from (and calc refuses the table)
    pending = at_operating & solvable & ("D" in frame.columns)
    with np.errstate(invalid="ignore", over="ignore"):
        nu = np.where(at_operating, np.where(pending, walther_viscosity(A, B, PROVISIONAL_TEMPERATURE), np.nan), nu)
        nu = np.where(at_bearing, walther_viscosity(A, B, T_bearing), nu)
    filled = {"_nu_at": _nu_sources(np.where(at_bearing, NU_SOURCES.index("T_bearing"),
                                             np.where(given, NU_SOURCES.index("given"), NU_SOURCES.index("")))),
              "nu": nu}
    if pending.any():
        filled["_nu_pending"] = pending
        # auto rows with T_bearing fall back to it where T_op has no solution: their refusals become warnings
        filled["_nu_fallback"] = pending & (modes == "auto") & ~np.isnan(T_bearing)
    filled["_nu_explained"] = _rows_in_error(problems, len(frame))
    return with_columns(frame, filled), problems


def _rows_in_error(problems, size: int) -> np.ndarray:
    """The rows with an error among ``problems``: after :func:`fill_viscosity`, those whose errors say why they
    have no viscosity (:func:`~bearingheat.calc.models.compute_supports` leaves out the model's 'nu: missing',
    which would only follow from them)."""
    rows = np.zeros(size, dtype=bool)
    rows[[i for i, level, _ in problems if level == "error"]] = True
    return rows


def _nu_sources(codes: np.ndarray) -> pd.Categorical:
    """The column ``_nu_at`` from codes into :data:`NU_SOURCES` (a byte a row, no text per row)."""
    return pd.Categorical.from_codes(codes.astype(np.int8), categories=pd.Index(NU_SOURCES, dtype=object),
                                     validate=False)


def with_seal_friction(frame: pd.DataFrame, results: pd.DataFrame) -> pd.DataFrame:
    """``frame`` with the hidden column :data:`~bearingheat.calc.reference_speed.SEAL_FRICTION` where the friction
    results of some row hold a seal friction (``M_seal`` > 0, the SKF model with a contact seal): the heat balance
    then applies to its bearing with contact seals (:data:`~bearingheat.catalogue.thermal.SEAL_FRICTION_REASON`)."""
    if "M_seal" not in results.columns:
        return frame
    with np.errstate(invalid="ignore"):
        sealed = results["M_seal"].to_numpy(dtype=float) > 0
    return with_columns(frame, {SEAL_FRICTION: sealed}) if sealed.any() else frame


def settle_viscosity(frame: pd.DataFrame, results: pd.DataFrame, *, t_limit: float = OPERATING_TEMPERATURE_LIMIT,
                     f2_chart=None, labels=None, model: str = DEFAULT_MODEL):
    """The viscosity at T_op of the rows :func:`fill_viscosity` left pending, from the one friction pass.

    ``results`` are the friction results of ``frame``
    (:func:`~bearingheat.calc.models.compute_supports`, whose ``f2_chart``,
    ``labels`` and ``model`` are passed again). Each pending row's T_op is
    solved from its results, ``nu`` becomes ν(T_op) and the results follow
    it (:func:`~bearingheat.calc.models.results_at_viscosity`: M0, MR, NR
    of the catalogue model without a second evaluation). Where f2 is read
    off the chart at ν·n·dM, the heat balance takes M2 at each trial
    temperature's ν, so one solve gives the operating state. Returns
    (frame, results, problems); a row whose T_op has no solution is an
    error, or falls back to T_bearing in 'auto' mode.
    """
    if "_nu_pending" not in frame.columns:
        return frame, results, []
    pending = frame["_nu_pending"].to_numpy(dtype=bool)
    fallback = frame["_nu_fallback"].to_numpy(dtype=bool)
    A, B = number_column(frame, "_walther_A"), number_column(frame, "_walther_B")
    frame = with_seal_friction(frame.drop(columns=["_nu_pending", "_nu_fallback"]), results)
    if f2_chart is not None:
        results = _stand_in_f2(frame, results, pending, labels, model, f2_chart)
    failed_at_provisional = failed_rows(results)
    details, _, T_amb, Q_E, Q_S, Q_L = heat_flow_setup(frame)
    point = operating_point(frame, results, viscosity_of_rows(frame, A, B), ~np.isnan(A), Q_S, Q_L, Q_E, T_amb,
                            t_limit, FrictionPower(frame, results, f2_chart))
    # a row in error is left to its own message; a bearing without a heat balance says why (a sealed bearing with
    # its seal friction has a heat balance without n_thr)
    reasons = details["reason"].array  # (a categorical where spread from the distinct bearings: no text per row)
    asked = pending & ~(failed_at_provisional | plain_bushing_rows(results))
    balanced_without_n_thr = seal_friction_rows(frame) & ~np.isnan(details["A_r"].to_numpy(dtype=float))
    refused = asked & nonblank(reasons, len(asked)) & ~balanced_without_n_thr
    T_op = np.where(asked & ~refused & (point.status == 0), point.T, np.nan)
    why_unsolved = {int(i): reasons[i] for i in np.flatnonzero(refused)}
    why_unsolved.update({int(i): point.why(int(i)) for i in np.flatnonzero(asked & ~refused & (point.status != 0))})
    nu = number_column(frame, "nu").copy()
    with np.errstate(invalid="ignore", over="ignore"):
        nu[pending] = np.where(fallback & np.isnan(T_op), walther_viscosity(A, B, number_column(frame, "T_bearing")),
                               walther_viscosity(A, B, T_op))[pending]
    frame["nu"] = nu
    refused_nu = [i for i in why_unsolved if not fallback[i]]
    if refused_nu:  # their message says why nu is missing (the model's 'nu: missing' would only follow from it)
        explained = frame["_nu_explained"].to_numpy(dtype=bool).copy()
        explained[refused_nu] = True
        frame["_nu_explained"] = explained
    # a row refused at the provisional viscosity keeps that refusal and its messages (evaluated again without a
    # viscosity it would only say 'nu: missing', and the chart would not be read to say why f2 has none)
    results = results_at_viscosity(frame, results, pending & ~failed_at_provisional, f2_chart=f2_chart,
                                   labels=labels, model=model)
    problems = [(i, "error", f"nu [mm^2/s]: cannot be taken at T_op; {why}; give T_bearing")
                for i, why in sorted(why_unsolved.items()) if not fallback[i]]
    # a row the model refuses only at ν(T_op) is told where ν came from
    problems += [(int(i), "error", f"nu [mm^2/s]: {nu[i]:.4g}, taken at the operating temperature T_op = "
                                   f"{T_op[i]:.4g} degC; give T_bearing and viscosity_at 'bearing', or nu, for "
                                   "another viscosity")
                 for i in np.flatnonzero(pending & ~np.isnan(T_op) & failed_rows(results) & ~failed_at_provisional)]
    source = frame["_nu_at"].array.codes.copy()
    source[pending & ~np.isnan(T_op)] = NU_SOURCES.index("T_op")
    source[pending & fallback & np.isnan(T_op)] = NU_SOURCES.index("T_bearing")
    frame["_nu_at"] = _nu_sources(source)
    # the heat balance takes this T_op of every row (solved from f0, M1 and M2 as they are now), and why a row
    # that the heat balance reports on has none, rather than solving again
    said = np.flatnonzero(~failed_rows(results) & ~plain_bushing_rows(results) & ~np.isnan(T_amb)
                          & ~np.isnan(details["A_r"].to_numpy(dtype=float)) & (point.status != 0))
    frame["_T_op"] = point.T
    frame["_T_op_why"] = with_texts(pd.Categorical.from_codes(np.zeros(len(frame), dtype=np.int8), pd.Index([""])),
                                    said.tolist(), [point.why(int(i)) for i in said])
    return frame, results, problems


def _stand_in_f2(frame, results, pending, labels, model, f2_chart):
    """The results of the pending rows that the friction pass refused (f2 read off the chart at ν·n·dM of the
    provisional viscosity is off it, and perhaps more) evaluated again with a stand-in f2: the heat balance reads
    M2 off the chart at ν(T)·n·dM itself and needs only f0, M1 and Fa/A. A row refused for another reason stays
    refused: one that the stand-in lets through but whose Fa/A is not on the chart's curves (no kB, or an Fa/A
    beyond them) keeps its refusal: its results are put back as they were, so that each row is evaluated once
    here. Every pending row is evaluated again at ν(T_op) with the chart (:func:`settle_viscosity`)."""
    f2 = number_column(frame, "f2")
    retry = pending & failed_rows(results) & np.isnan(f2) & (number_column(frame, "Fa") > 0)
    if not retry.any():
        return results
    # (results_at_viscosity replaces rows in the frame it is given: the trial works on a copy)
    trial = results_at_viscosity(frame.assign(f2=np.where(retry, 1.0, f2)), results.copy(), retry, labels=labels,
                                 model=model)
    off_curves = retry & np.isnan(f2_chart.x_range(trial["Fa_over_A"].to_numpy(dtype=float))[0])
    if not off_curves.any():
        return trial
    if not (retry & ~off_curves).any():
        return results
    return _rows_put_back(trial, results, off_curves)


def _rows_put_back(trial: pd.DataFrame, results: pd.DataFrame, rows: np.ndarray) -> pd.DataFrame:
    """``trial`` (:func:`~bearingheat.calc.models.results_at_viscosity` of a copy of ``results``) with the rows
    ``rows`` as they are in ``results``, written into it: its numbers (NaN in a column only the trial has: a row
    with one of those is on the chart's curves, so it is never put back, and the column stays), status and
    message; the model, bearing type and series are the trial's own (it leaves them as they were)."""
    positions = np.flatnonzero(rows)
    for name in trial.columns:
        if name in ("status", "message"):
            trial[name] = pd.Series(with_texts(trial[name], positions.tolist(), results[name].iloc[positions]),
                                    index=trial.index, copy=False)
        elif trial[name].dtype == np.float64:
            set_rows(trial, name, positions,
                     results[name].to_numpy(dtype=float)[positions] if name in results.columns else np.nan)
    return trial


def heat_balance_rows(frame: pd.DataFrame, results: pd.DataFrame, *, method: str = "exact",
                      t_limit: float = OPERATING_TEMPERATURE_LIMIT, f2_chart=None, reference_speed: bool = False):
    """n_thr, n_per, T_op, nu_op, Q_S, Q_L of every row (catalogue units); returns (columns, problems).

    ``frame`` holds the calc inputs (after :func:`fill_viscosity`),
    ``results`` the friction results of :func:`bearingheat.calc.models.compute_supports`
    (f0, M1, M2, status). Rows whose friction failed are skipped. Columns
    come out only where their inputs are present: n_thr with B, T, d1, D1,
    n_thr_catalogue or T_amb (thrust bearings need none of the widths), or
    wherever ``reference_speed`` is true (the API's result always has it); n_per
    with T_bearing and T_amb; T_op and nu_op with T_amb; Q_S and Q_L with
    T_amb. ``f2_chart`` is the chart the friction pass read f2 off (M2 of its
    rows follows the speed and viscosity of the roots). problems are (row
    position, 'warning' | 'error', message).
    """
    frame = with_seal_friction(frame, results)
    columns, problems = _heat_balance_columns(frame, results, method=method, t_limit=t_limit, f2_chart=f2_chart,
                                              reference_speed=reference_speed)
    _viscosity_at_bearing(frame, results, columns, problems)
    return columns, problems


def _viscosity_at_bearing(frame: pd.DataFrame, results: pd.DataFrame, columns: pd.DataFrame, problems: list) -> None:
    """Warn where ν(T_bearing) of the oil data is below 2 mm²/s, outside ASTM D341 (the check nu_op gets), on
    the rows that use it: friction results taken at T_bearing (``nu_used``), and n_per."""
    if "T_bearing" not in frame.columns:
        return
    A, B = walther_columns(frame)[:2]
    T_bearing = number_column(frame, "T_bearing")
    no_rows = np.zeros(len(frame), dtype=bool)
    friction_at = (frame["_nu_at"].array.codes == NU_SOURCES.index("T_bearing")) if "_nu_at" in frame.columns \
        else no_rows
    n_per_at = ~np.isnan(columns["n_per"].to_numpy(dtype=float)) if "n_per" in columns.columns else no_rows
    rows = np.flatnonzero(~failed_rows(results) & ~np.isnan(A) & ~np.isnan(T_bearing) & (friction_at | n_per_at))
    with np.errstate(invalid="ignore", over="ignore"):
        nu = walther_viscosity(A[rows], B[rows], T_bearing[rows])
    low = nu < MIN_VISCOSITY  # (no pour point here: the one range check; messages only for the rows it finds)
    rows, nu = rows[low], nu[low]
    for i, message in zip(rows.tolist(), viscosity_range_messages(nu, T_bearing[rows]).tolist()):
        if message:
            users = {(True, True): "the friction results (nu_used) and n_per are", (True, False): "the friction "
                     "results (nu_used) are", (False, True): "n_per is"}[bool(friction_at[i]), bool(n_per_at[i])]
            problems.append((i, "warning", f"T_bearing [degC]: {message}; {users} taken at it"))


def _heat_balance_columns(frame: pd.DataFrame, results: pd.DataFrame, *, method: str, t_limit: float, f2_chart,
                          reference_speed: bool):
    """:func:`heat_balance_rows` but the warnings on ν(T_bearing)."""
    if method not in SPEED_FACTOR_METHODS:
        raise HeatBalanceError(f"method: {method!r} is not one of {', '.join(SPEED_FACTOR_METHODS)}")
    n_rows = len(frame)
    problems: list[tuple[int, str, str]] = []
    methods = _row_methods(frame, method, problems)
    has = set(frame.columns)
    # rows whose friction failed, and plain bushings (no rolling bearing heat balance), are skipped
    failed = failed_rows(results) | plain_bushing_rows(results)
    columns: dict[str, np.ndarray | pd.Categorical] = {}
    wants_balance = "T_amb" in has
    # n_thr where its area columns are given, and wherever the heat balance computes it (the A_r of thrust bearings
    # needs d and D only)
    wants_thr = bool({"B", "T", "d1", "D1"} & has) or "n_thr_catalogue" in has or wants_balance or reference_speed
    for name, unit in (("T", "mm"), ("n_G", "1/min")):  # a width and a limiting speed are > 0 (B: the friction model)
        if name not in has:
            continue
        values = number_column(frame, name)
        with np.errstate(invalid="ignore"):
            for i in np.flatnonzero(~failed & (values <= 0)):
                problems.append((int(i), "error", f"{name} [{unit}]: {values[i]:g} must be > 0"))
    if not (wants_thr or wants_balance):
        return pd.DataFrame(index=frame.index), problems
    # (the details the heat balance reads are spread to the rows; without it n_thr and why a row has none)
    details = thermal_reference_speed_details(frame, names=HEAT_BALANCE_DETAILS if wants_balance
                                              else ("n_thr", "reason"))
    reasons = details["reason"].array  # read at the rows that have one
    has_reason = nonblank(reasons, n_rows)
    n_thr = details["n_thr"].to_numpy(dtype=float)
    n_thr_catalogue = number_column(frame, "n_thr_catalogue")
    reported_reason = np.zeros(n_rows, dtype=bool)

    # with only friction columns (B, C0) n_thr is added quietly; the reasons are told once the user asks
    # for thermal results with a thermal input column
    explicit = bool(has & THERMAL_INPUTS)

    def reason_once(i):
        if explicit and not reported_reason[i] and has_reason[i]:
            reported_reason[i] = True
            problems.append((int(i), "warning", reasons[i] if reasons[i].startswith("n_thr") else
                             f"n_thr: {reasons[i]}"))

    if wants_thr:
        columns["n_thr"] = n_thr
        for i in np.flatnonzero(~failed & np.isnan(n_thr)) if explicit else ():
            reason_once(i)
        for i in np.flatnonzero(~failed & (n_thr_catalogue <= 0)):
            problems.append((int(i), "error", f"n_thr_catalogue [1/min]: {n_thr_catalogue[i]:g} must be > 0"))
    if not wants_balance:
        return pd.DataFrame(columns, index=frame.index), problems

    _, k_q, T_amb, Q_E, Q_S, Q_L = heat_flow_setup(frame, details)
    A, B, model_problems = walther_columns(frame)
    if "_walther_A" not in has:
        problems.extend(model_problems)
    nu_at = viscosity_of_rows(frame, A, B)
    for i in np.flatnonzero(~failed & np.isnan(T_amb)):
        problems.append((int(i), "warning", "T_amb [degC]: missing; the heat balance (T_op, n_per) needs the "
                                            "ambient temperature"))
    k_q_user = number_column(frame, "k_q")
    for i in np.flatnonzero(~failed & (k_q_user <= 0)):
        problems.append((int(i), "error", f"k_q [W/(mm^2*K)]: {k_q_user[i]:g} must be > 0"))
    for name in ("V_oil",):
        values = number_column(frame, name)
        for i in np.flatnonzero(~failed & (values < 0)):
            problems.append((int(i), "error", f"V_oil [l/min]: {values[i]:g} must be >= 0"))
    # a row in error so far (an input the heat balance cannot use) gets no balance: its messages would only follow
    failed = failed | _rows_in_error(problems, n_rows)

    # --- operating temperature at the operating speed (solved already where the viscosity was taken at it)
    # N_R of each row by its model, for T_op and n_per
    power = FrictionPower(frame, results, f2_chart) if "_T_op" not in has or "T_bearing" in has else None
    if "_T_op" in has:
        T_op, why = number_column(frame, "_T_op"), frame["_T_op_why"].array
        unsolved, why_text = nonblank(why, n_rows), why.__getitem__
    else:
        point = operating_point(frame, results, nu_at, ~np.isnan(A), Q_S, Q_L, Q_E, T_amb, t_limit, power)
        T_op, unsolved, why_text = point.T, point.status != 0, point.why
    usable = ~failed & ~np.isnan(T_amb) & ~np.isnan(details["A_r"].to_numpy(dtype=float))
    for i in np.flatnonzero(usable & unsolved):
        problems.append((int(i), "warning", f"T_op: {why_text(int(i))}"))
    for i in np.flatnonzero(~failed & ~np.isnan(T_amb) & np.isnan(details["A_r"].to_numpy(dtype=float))):
        reason_once(i)
    T_op = np.where(usable, T_op, np.nan)
    with np.errstate(invalid="ignore", over="ignore"):
        nu_op = np.where(np.isnan(T_op), np.nan, nu_at(T_op))  # (a constant nu has no T_op to be taken at)
    for i in np.flatnonzero(~np.isnan(nu_op) & (nu_op < MIN_VISCOSITY)):  # ASTM D341's range; no pour point here
        message = viscosity_range_messages(nu_op[i], T_op[i])[0]
        if message:
            problems.append((int(i), "warning", f"nu_op: {message}"))
    columns["T_op"] = T_op
    columns["nu_op"] = nu_op

    # --- heat carried away: at T_bearing where given, otherwise at T_op
    T_bearing = number_column(frame, "T_bearing")
    theta = np.where(np.isnan(T_bearing), T_op, T_bearing)
    with np.errstate(invalid="ignore"):
        seat, oil = Q_S(theta), Q_L(theta)
        columns["Q_S"] = np.where(usable, seat, np.nan)
        columns["Q_L"] = np.where(usable, oil, np.nan)

    # --- permissible speed at the bearing temperature T_bearing (where it is given, theta is T_bearing)
    if "T_bearing" in has:
        carried = np.where(np.isnan(T_bearing), np.nan, seat + oil)
        columns["n_per"] = permissible_speed_rows(frame, results, details, n_thr, n_thr_catalogue, T_bearing,
                                                   T_amb, carried, Q_E, power, usable, methods, problems)
        titles = [SPEED_FACTOR_METHODS[m].title for m in methods.categories] + [""]  # the last: no n_per
        used = np.where(np.isnan(columns["n_per"]), len(titles) - 1, methods.codes)
        columns["n_per_method_used"] = coded_categorical(used, titles)
    _assumed_oil_outlet(frame, usable, problems)
    ordered = [c for c in ("n_thr", "n_per", "n_per_method_used", "T_op", "nu_op", "Q_S", "Q_L") if c in columns]
    return pd.DataFrame({c: columns[c] for c in ordered}, index=frame.index), problems


def _row_choices(frame: pd.DataFrame, column: str, default: str, choices, problems: list) -> pd.Categorical:
    """Every row's ``column`` cell, else ``default``, as a categorical (compared by its codes); a name not in
    ``choices`` is a row error (and the default). Each distinct cell is looked at once."""
    codes, texts = text_codes(frame, column)
    names = [text or default for text in texts]
    unknown = np.array([name not in choices for name in names], dtype=bool)
    for i in np.flatnonzero(unknown[codes]):
        problems.append((int(i), "error", f"{column}: {names[codes[i]]!r} is not one of {', '.join(choices)}"))
    return coded_categorical(codes, [default if bad else name for name, bad in zip(names, unknown)])


def _row_methods(frame: pd.DataFrame, default: str, problems: list) -> pd.Categorical:
    """The n_per method of every row: its ``n_per_method`` cell, else ``default``; unknown names are row errors."""
    return _row_choices(frame, "n_per_method", default, SPEED_FACTOR_METHODS, problems)


def _assumed_oil_outlet(frame: pd.DataFrame, usable: np.ndarray, problems: list) -> None:
    """Warn on every oil-cooled row without dT_oil: the optimistic assumption is said, not hidden."""
    V_oil = number_column(frame, "V_oil")
    dT_oil = number_column(frame, "dT_oil")
    for i in np.flatnonzero(usable & (V_oil > 0) & np.isnan(dT_oil)):
        problems.append((int(i), "warning", "dT_oil [K]: not given; the oil is taken to enter at T_amb and to leave "
                                            "at the bearing temperature, the most heat it can carry away "
                                            f"({OIL_HEAT_CAPACITY_FLOW:g} W/(l/min*K) * V_oil * (T - T_amb)); give "
                                            "dT_oil for a cautious value"))


register_choices("viscosity_at", lambda: tuple(VISCOSITY_AT))


# ---- the calc extension ``thermal`` ----------------------------------------------------------------

def prepare(frame: pd.DataFrame):
    """Fill ``nu`` from nu40/nu100 or iso_vg (at the row's ``viscosity_at``: T_op by default where it can be
    solved, else T_bearing; rows at T_op provisionally, see :func:`settle`); returns (frame, problems)."""
    return fill_viscosity(frame, viscosity_at=DEFAULT_VISCOSITY_AT)


def settle(frame: pd.DataFrame, results: pd.DataFrame, **compute):
    """After the friction pass: ν at T_op of the rows :func:`prepare` left pending, and the results at it
    (:func:`settle_viscosity`; ``compute`` are the friction pass's f2_chart, labels and model); returns
    (frame, results, problems)."""
    return settle_viscosity(frame, results, t_limit=OPERATING_TEMPERATURE_LIMIT, **compute)


def extend(frame: pd.DataFrame, results: pd.DataFrame, *, f2_chart=None, **compute):
    """The heat balance columns of every row whose friction succeeded, and where the viscosity of the friction
    results comes from (``nu_used``, ``nu_at``) when it was filled from oil data (``f2_chart``: that of the
    friction pass; the other ``compute`` options are not needed); returns (columns, problems)."""
    columns, problems = heat_balance_rows(frame, results, method=DEFAULT_SPEED_FACTOR_METHOD,
                                          t_limit=OPERATING_TEMPERATURE_LIMIT, f2_chart=f2_chart)
    columns.index = frame.index
    if "_nu_at" in frame.columns:  # first, in one new frame: no inserts into the heat balance's
        source = frame["_nu_at"].array.rename_categories({"": "-"})  # '-': a row without ν
        columns = pd.DataFrame({"nu_used": number_column(frame, "nu"), "nu_at": source,
                                **{name: columns[name] for name in columns.columns}},
                               index=frame.index, copy=False)
    return columns, problems
