"""The friction model over many supports: coefficients, checks, kernels, status.

This is the orchestrator of the catalogue friction model. It works in
catalogue units on a table of supports (one row each) and holds no formula
of its own: coefficients come from :mod:`bearingheat.coefficients`, the
torques from :mod:`bearingheat.friction`.

:func:`compute_supports` takes a DataFrame whose columns are the names of
the calc contract without units (``d``, ``D``, ``Fr``, ``n``, ``nu`` ...,
in mm, N, 1/min, mm²/s) and returns the results with a ``status`` (ok,
warning, error) and a ``message`` per row. A bad row never stops the others.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import pandas as pd

from bearingheat import friction
from bearingheat.coefficients import LUBRICATION_F0_COLUMN, ResolvedBearing, resolve
from bearingheat.designation import DesignationError
from bearingheat.f2chart import F2Chart

__all__ = [
    "INPUT_UNITS",
    "RESULT_UNITS",
    "Problem",
    "compute_supports",
    "bearing_constants",
    "check_and_evaluate",
]

#: calc input column -> catalogue unit ('' for text, '1' for a dimensionless number)
INPUT_UNITS = {
    "id": "", "designation": "", "type": "", "series": "",
    "d": "mm", "D": "mm", "B": "mm", "C0": "N",
    "Y": "1", "e": "1", "X0": "1", "Y0": "1", "alpha": "deg",
    "arrangement": "", "f0": "1", "f1": "1", "f2": "1",
    "lubrication": "", "n": "1/min", "Fr": "N", "Fa": "N", "nu": "mm^2/s",
    "f_plain": "1",
}
#: support types that are not rolling bearings -> how their rows are computed
PLAIN_TYPES = ("plain_bushing",)
#: result column -> unit
RESULT_UNITS = {
    "f0": "1", "f1": "1", "P0": "N", "P1": "N",
    "M0": "N*mm", "M1": "N*mm", "M2": "N*mm", "MR": "N*mm", "NR": "W",
}
#: extra result columns written when a row carries M2
M2_REPORT_UNITS = {"Fa_over_A": "1", "nu_n_dM": "mm^3/(s*min)"}
#: extra result columns written when a row is a plain bushing (seed 004)
PLAIN_REPORT_UNITS = {"p_plain": "N/mm^2", "V_plain": "m/s"}

_F1_BASIS_CODE = {"constant": 0, "P0/C0": 1, "Fa/C0": 2}


@dataclass
class Problem:
    """Rows that fail one check, and how to word it for row i."""

    mask: np.ndarray
    level: str  # 'error' or 'warning'
    message: Callable[[int], str]


@dataclass
class Labels:
    """How messages name a column and show its value: the user's header and unit."""

    headers: dict[str, tuple[str, float]] = field(default_factory=dict)

    #: optional (column, row position) -> cell reference such as 'Supports!F7'
    cell: Callable[[str, int], str] | None = None

    def name(self, column: str, row: int | None = None) -> str:
        if column in self.headers:
            header = self.headers[column][0]
        else:
            unit = INPUT_UNITS.get(column, "")
            header = f"{column} [{unit}]" if unit not in ("", "1") else column
        if self.cell is not None and row is not None:
            return f"{self.cell(column, row)} {header}"
        return header

    def value(self, column: str, value: float) -> str:
        factor = self.headers.get(column, (None, 1.0))[1]
        return f"{value / factor:g}"


def bearing_constants(resolved: ResolvedBearing, lubrication: str | None, arrangement: str) -> dict:
    """Row-constant coefficients of one bearing, or an 'error' entry saying why there are none.

    ``lubrication`` None means f0 comes from the user (no table column).
    """
    entry = resolved.entry
    out = {
        "bearing_type": entry.bearing_type, "series": entry.series,
        "f0_table": math.nan, "f0_basis": entry.f0_basis,
        "f1_a": entry.f1_a, "f1_x": entry.f1_x, "f1_basis": _F1_BASIS_CODE[entry.f1_basis],
        "m1_load": entry.m1_load, "p1_rule": None,
        "X0_table": entry.X0, "Y0_table": entry.Y0, "kB": resolved.kB,
        "m2": resolved.takes_axial_m2, "no_axial": resolved.cannot_take_axial,
        "seal": resolved.seal, "contact_angle": resolved.contact_angle,
        "label": entry.label, "prefix": resolved.prefix,
        "notes": resolved.designation.notes if resolved.designation else (), "error": "",
    }
    if lubrication is not None:
        if lubrication not in LUBRICATION_F0_COLUMN:
            out["error"] = (f"lubrication: {lubrication!r} is not one of "
                            f"{', '.join(LUBRICATION_F0_COLUMN)}")
            return out
        f0 = entry.f0_for(lubrication)
        if math.isnan(f0):
            out["error"] = (f"lubrication: {lubrication!r} has no f0 for {entry.label} (seed 002 prints a dash); "
                            "use grease or oil_mist, or give f0")
            return out
        out["f0_table"] = f0
    if arrangement not in ("single", "paired"):
        out["error"] = f"arrangement: {arrangement!r} is not one of single, paired"
        return out
    if entry.m1_load == "P1":
        rule = entry.p1_single if arrangement == "single" else entry.p1_paired
        if rule is None:
            out["error"] = (f"arrangement: {arrangement!r} has no P1 rule for {entry.label} "
                            "(seed 002, p. 68 prints a dash)")
            return out
        out["p1_rule"] = rule
    return out


def _nan_array(n: int) -> np.ndarray:
    return np.full(n, np.nan)


def _column(frame: pd.DataFrame, name: str, default=np.nan) -> np.ndarray:
    if name in frame.columns:
        return pd.to_numeric(frame[name], errors="coerce").to_numpy(dtype=float)
    return np.full(len(frame), default, dtype=float)


def _text(frame: pd.DataFrame, name: str) -> list:
    if name not in frame.columns:
        return [None] * len(frame)
    return [None if (v is None or (isinstance(v, float) and math.isnan(v)) or str(v).strip() == "")
            else str(v).strip() for v in frame[name]]


def _at(value, i):
    """Element i of a per-row array, or the value itself when it is one constant for all rows."""
    return value if np.ndim(value) == 0 else value[i]


def check_and_evaluate(a: dict, labels: Labels, f2_chart: F2Chart | None = None):
    """Checks and kernels over arrays of one length (catalogue units).

    ``a`` holds the inputs (d, D, B, C0, Y, e, X0, Y0, alpha, n, nu, Fr, Fa,
    f0, f1, f2 as float arrays with NaN for 'not given') and the row
    constants of :func:`bearing_constants`, either as per-row arrays (many
    bearings) or as scalars (one bearing, many operating points).
    Returns (results, problems); every result is an array of the rows' length.
    """
    n_rows = len(a["n"])  # the operating speed spans the rows; other inputs are arrays of that length or scalars
    shape = (n_rows,)
    problems: list[Problem] = []

    def add(mask, level, message):
        mask = np.broadcast_to(np.asarray(mask, dtype=bool), shape)
        if mask.any():
            problems.append(Problem(mask, level, message))

    def value_of(col, i):
        return labels.value(col, _at(a[col], i))

    def bad_value(col, condition_text, mask):
        add(mask, "error", lambda i, c=col: f"{labels.name(c, i)}: {value_of(c, i)} {condition_text}")

    def missing(col, why, mask):
        add(mask, "error", lambda i, c=col: f"{labels.name(c, i)}: missing; {why(i)}")

    def label(i):
        return _at(a["label"], i)

    d, D, n, nu, Fr, Fa = a["d"], a["D"], a["n"], a["nu"], a["Fr"], a["Fa"]
    # --- geometry and operating point (seed 002, p. 64: units and ranges of the formulas)
    missing("d", lambda i: "the bore d gives dM = (d + D)/2", np.isnan(d))
    bad_value("d", "must be > 0", d <= 0)
    missing("D", lambda i: "the outside diameter D gives dM = (d + D)/2", np.isnan(D))
    add(~np.isnan(D) & ~np.isnan(d) & (D <= d) & (d > 0), "error",
        lambda i: f"{labels.name('D', i)}: {value_of('D', i)} must be larger than "
                  f"{labels.name('d', i)} = {value_of('d', i)}")
    missing("n", lambda i: "the operating speed is needed", np.isnan(n))
    bad_value("n", "must be >= 0 (speed magnitude)", n < 0)
    missing("nu", lambda i: "the operating viscosity (base oil viscosity for grease) is needed", np.isnan(nu))
    bad_value("nu", "must be > 0", nu <= 0)
    bad_value("Fr", "must be >= 0", Fr < 0)
    bad_value("Fa", "must be >= 0", Fa < 0)
    for col in ("f0", "f1", "f2"):
        bad_value(col, "must be >= 0", a[col] < 0)

    # --- f0: user value, or the table column of the lubrication (needle formulas need B)
    f0_given = ~np.isnan(a["f0"])
    needle_formula = np.equal(a["f0_basis"], "B/(33+d)") & ~f0_given
    missing("B", lambda i: f"f0 of {label(i)} is value*B/(33+d) (seed 002, p. 66)", needle_formula & np.isnan(a["B"]))
    bad_value("B", "must be > 0", a["B"] <= 0)
    f0 = np.where(f0_given, a["f0"], a["f0_table"])
    if np.any(needle_formula):
        f0 = np.where(needle_formula, friction.f0_needle(a["f0_table"], a["B"], d), f0)

    # --- P0 (only where f1 depends on P0/C0 and there is axial load)
    f1_given = ~np.isnan(a["f1"])
    f1_basis = a["f1_basis"]
    needs_c0 = (f1_basis > 0) & ~f1_given
    missing("C0", lambda i: f"f1 of {label(i)} depends on "
                            f"{'P0/C0' if _at(f1_basis, i) == 1 else 'Fa/C0'} (seed 002, pp. 66-68)",
            needs_c0 & np.isnan(a["C0"]))
    bad_value("C0", "must be > 0", a["C0"] <= 0)
    X0 = np.broadcast_to(np.where(np.isnan(a["X0"]), a["X0_table"], a["X0"]), shape)
    Y0 = np.broadcast_to(np.where(np.isnan(a["Y0"]), a["Y0_table"], a["Y0"]), shape)
    Y0, angle_reported = _angular_contact_y0(a, Y0, add, shape)
    needs_p0 = (f1_basis == 1) & ~f1_given & (Fa > 0)
    angular = np.equal(a["bearing_type"], "angular_contact_ball")
    for col, values in (("X0", X0), ("Y0", Y0)):
        missing(col, lambda i, c=col: f"P0 of {label(i)} under axial load needs the catalogue value {c}"
                                      + (" or the contact angle alpha (seed 000, table 1: 18 to 36 deg)"
                                         if _at(angular, i) else " (seed 000, table 1 has none for this type)"),
                needs_p0 & np.isnan(values) & ~angle_reported)
    P0 = friction.static_equivalent_load(Fr, Fa, X0, Y0)

    # --- P1 rules (seed 002, p. 68): tapered needs Y, spherical needs e
    rules = a["p1_rule"]
    is_p1 = np.equal(a["m1_load"], "P1") & np.not_equal(rules, "")
    for col, rule_names in (("Y", ("tapered_single", "tapered_paired")), ("e", ("spherical",))):
        wanted = np.isin(np.asarray(rules, dtype=str), rule_names) & (Fa > 0)
        missing(col, lambda i, c=col: f"P1 of {label(i)} under axial load needs the catalogue value {c} "
                                      "(seed 002, p. 68)", wanted & np.isnan(a[col]))
        bad_value(col, "must be > 0", a[col] <= 0)
    if np.ndim(rules) == 0:
        P1 = (friction.effective_load(rules, Fr, Fa, a["Y"], a["e"]) if is_p1 else np.full(shape, np.nan))
    else:
        P1 = np.full(shape, np.nan)
        if is_p1.any():
            Y, e = (np.broadcast_to(a[c], shape) for c in ("Y", "e"))
            P1[is_p1] = friction.effective_load(rules[is_p1].astype(str), Fr[is_p1], Fa[is_p1], Y[is_p1], e[is_p1])
    load = np.where(np.equal(a["m1_load"], "Fa"), Fa, np.where(is_p1, P1, Fr))

    # --- f1
    ratio = np.where(f1_basis == 1, P0 / a["C0"], np.where(f1_basis == 2, Fa / a["C0"], 1.0))
    f1 = np.where(f1_given, a["f1"], friction.f1_from_load_ratio(a["f1_a"], a["f1_x"], ratio))

    # --- axial load on cylindrical roller bearings (seed 002, p. 69)
    add(a["no_axial"] & (Fa > 0), "error",
        lambda i: f"{labels.name('Fa', i)}: {value_of('Fa', i)} on {_at(a['prefix'], i)} {label(i)}: "
                  "one ring has no ribs, the bearing takes no axial load")
    m2_rows = np.broadcast_to(a["m2"] & (Fa > 0), shape)
    add(m2_rows & (Fr <= 0), "error",
        lambda i: f"{labels.name('Fa', i)}: {value_of('Fa', i)} without radial load on {label(i)}: "
                  "axially loaded cylindrical roller bearings need Fr > 0 (seed 002, p. 69)")
    fa_fr = Fa / Fr
    add(m2_rows & (Fr > 0) & (fa_fr > 0.4), "warning",
        lambda i: f"Fa/Fr = {_at(fa_fr, i):.3g} is above 0.4, the limit for axially loaded cylindrical roller "
                  "bearings; M2 is uncertain there")
    dM = friction.mean_diameter(d, D)
    f2 = np.zeros(shape)
    Fa_over_A = np.full(shape, np.nan)
    nu_n_dM = np.full(shape, np.nan)
    if m2_rows.any():
        A = friction.axial_load_parameter(a["kB"], dM)
        Fa_over_A = np.where(m2_rows, Fa / A, np.nan)
        nu_n_dM = np.where(m2_rows, nu * n * dM, np.nan)
        f2 = np.where(m2_rows, a["f2"], 0.0)
        need_f2 = m2_rows & np.isnan(f2)
        if f2_chart is not None and need_f2.any():
            no_kb = need_f2 & np.isnan(a["kB"])
            missing("kB", lambda i: f"{label(i)} has no kB in seed 002 p. 70, so Fa/A for the f2 chart is "
                                    "unknown; give f2", no_kb)
            rows = np.flatnonzero(need_f2 & ~no_kb)
            chart_f2, reasons = f2_chart.lookup(Fa_over_A[rows], nu_n_dM[rows])
            f2[rows] = chart_f2
            refused = np.zeros(shape, dtype=bool)
            refused[rows] = reasons != ""
            reason_of = dict(zip(rows.tolist(), reasons.tolist()))
            add(refused, "error", lambda i: f"f2: {reason_of[i]}")
        elif need_f2.any():
            add(need_f2, "error",
                lambda i: f"f2: missing; {label(i)} carries Fa, so M2 = f2*Fa*dM needs f2: give f2, or a "
                          f"digitised chart (--f2-chart); read it at Fa/A = {Fa_over_A[i]:.4g}, "
                          f"nu*n*dM = {nu_n_dM[i]:.4g} mm^3/(s*min) (seed 002, p. 70, figs. 3 and 4)")
    add(np.equal(a["seal"], "contact"), "warning",
        lambda i: "contact seals: their friction comes on top of the catalogue model (seed 002, p. 64)")

    M0 = friction.speed_dependent_torque(f0, nu, n, dM)
    M1 = friction.load_dependent_torque(f1, load, dM)
    M2 = friction.axial_load_torque(f2, Fa, dM)
    MR = friction.total_torque(M0, M1, M2)
    results = {
        "f0": f0, "f1": f1, "P0": P0, "P1": P1, "M0": M0, "M1": M1, "M2": M2, "MR": MR,
        "NR": friction.power_loss(MR, n), "Fa_over_A": Fa_over_A, "nu_n_dM": nu_n_dM,
    }
    return {k: np.broadcast_to(np.asarray(v, dtype=float), shape) for k, v in results.items()}, problems


def _angular_contact_y0(a, Y0, add, shape):
    """Y0 of single row angular contact ball bearings from the contact angle (seed 000, table 1)."""
    rows = np.broadcast_to(np.equal(a["bearing_type"], "angular_contact_ball") & np.isnan(a["Y0"])
                           & (a["Fa"] > 0), shape)
    reported = np.zeros(shape, dtype=bool)
    if not rows.any():
        return Y0, reported
    from bearingheat.contact import y0_for_contact_angle

    angle = np.broadcast_to(np.where(np.isnan(a["alpha"]), np.asarray(a["contact_angle"], dtype=float),
                                     a["alpha"]), shape)
    Y0 = np.array(Y0, dtype=float)
    wanted = rows & ~np.isnan(angle)
    unique_angles, inverse = np.unique(angle[wanted], return_inverse=True)
    rows_at = np.flatnonzero(wanted)
    for k, alpha in enumerate(unique_angles):
        these = rows_at[inverse == k]
        try:
            Y0[these] = y0_for_contact_angle(alpha)
        except ValueError as exc:
            mask = np.zeros(shape, dtype=bool)
            mask[these] = True
            reported |= mask
            add(mask, "error", lambda j, text=str(exc): f"Y0: missing; {text}; give Y0 from the catalogue")
    return Y0, reported


def compute_supports(frame: pd.DataFrame, *, f2_chart: F2Chart | None = None,
                     labels: Labels | None = None) -> pd.DataFrame:
    """Friction results for every row of ``frame`` (catalogue units, contract column names).

    Returns a DataFrame with the index of ``frame`` and the columns of
    :data:`RESULT_UNITS`, ``status`` and ``message`` (plus ``Fa_over_A``
    and ``nu_n_dM`` when a row carries M2, and ``bearing_type``/``series``).
    """
    labels = labels or Labels()
    n_rows = len(frame)
    designations = _text(frame, "designation")
    types = _text(frame, "type")
    series = _text(frame, "series")
    lubrication = _text(frame, "lubrication")
    arrangement = [v or "single" for v in _text(frame, "arrangement")]
    f0_user = _column(frame, "f0")
    row_errors: list[list[str]] = [[] for _ in range(n_rows)]
    plain = np.array([(t or "").lower() in PLAIN_TYPES for t in types], dtype=bool)
    constants = []
    for i in range(n_rows):
        if plain[i]:
            constants.append(None)
            continue
        try:
            resolved = resolve(designations[i], types[i], series[i])
        except DesignationError as exc:
            row_errors[i].append(str(exc))
            constants.append(None)
            continue
        lub = lubrication[i]
        if lub is None and np.isnan(f0_user[i]):
            row_errors[i].append("lubrication: missing; expected one of " + ", ".join(LUBRICATION_F0_COLUMN))
            constants.append(None)
            continue
        const = bearing_constants(resolved, lub, arrangement[i])
        if const["error"]:
            row_errors[i].append(const["error"])
        const["bore"] = resolved.designation.bore if resolved.designation else None
        const["width"] = resolved.designation.width if resolved.designation else None
        constants.append(const)
    blank = {"bearing_type": "", "series": "", "f0_table": np.nan, "f0_basis": "", "f1_a": np.nan,
             "f1_x": np.nan, "f1_basis": 0, "m1_load": "Fr", "p1_rule": None, "X0_table": np.nan,
             "Y0_table": np.nan, "kB": np.nan, "m2": False, "no_axial": False, "seal": "open",
             "contact_angle": None, "label": "", "prefix": "", "notes": (), "bore": None, "width": None}
    const_frame = pd.DataFrame([c if c is not None else blank for c in constants], index=range(n_rows))
    arrays = {col: _column(frame, col) for col in
              ("d", "D", "B", "C0", "Y", "e", "X0", "Y0", "alpha", "f0", "f1", "f2", "n", "nu")}
    arrays["Fr"] = np.nan_to_num(_column(frame, "Fr"), nan=0.0)
    arrays["Fa"] = np.nan_to_num(_column(frame, "Fa"), nan=0.0)
    # bore and width printed in the designation fill empty cells (HK2016: d = 20, B = 16)
    bore = pd.to_numeric(const_frame["bore"], errors="coerce").to_numpy(dtype=float)
    width = pd.to_numeric(const_frame["width"], errors="coerce").to_numpy(dtype=float)
    arrays["d"] = np.where(np.isnan(arrays["d"]), bore, arrays["d"])
    arrays["B"] = np.where(np.isnan(arrays["B"]), width, arrays["B"])
    for col in ("bearing_type", "f0_basis", "m1_load", "label", "seal", "prefix"):
        arrays[col] = const_frame[col].astype(str).to_numpy(dtype=object)
    for col in ("f0_table", "f1_a", "f1_x", "X0_table", "Y0_table", "kB"):
        arrays[col] = const_frame[col].to_numpy(dtype=float)
    arrays["f1_basis"] = const_frame["f1_basis"].to_numpy(dtype=int)
    arrays["p1_rule"] = np.array([r if isinstance(r, str) else "" for r in const_frame["p1_rule"]], dtype=object)
    arrays["m2"] = const_frame["m2"].to_numpy(dtype=bool)
    arrays["no_axial"] = const_frame["no_axial"].to_numpy(dtype=bool)
    arrays["contact_angle"] = pd.to_numeric(const_frame["contact_angle"], errors="coerce").to_numpy(dtype=float)
    arrays["notes"] = list(const_frame["notes"])

    with np.errstate(all="ignore"):
        results, problems = check_and_evaluate(arrays, labels, f2_chart)
    for i, notes in enumerate(arrays["notes"]):
        if notes:
            mask = np.zeros(n_rows, dtype=bool)
            mask[i] = True
            problems.append(Problem(mask, "warning", lambda j, text="; ".join(notes): text))

    warnings_by_row: list[list[str]] = [[] for _ in range(n_rows)]
    results = {k: np.array(v, dtype=float) for k, v in results.items()}
    if plain.any():
        _plain_rows(frame, plain, results, row_errors, warnings_by_row)
    for problem in problems:
        for i in np.flatnonzero(problem.mask & ~plain):
            target = row_errors if problem.level == "error" else warnings_by_row
            if constants[i] is None and problem.level == "error":
                continue  # the row already failed to resolve
            target[i].append(problem.message(i))
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
    if np.any(~np.isnan(results["nu_n_dM"]) & ~failed):
        for col in M2_REPORT_UNITS:
            out[col] = np.where(failed, np.nan, results[col])
    if plain.any():
        for col in PLAIN_REPORT_UNITS:
            out[col] = np.where(failed, np.nan, results[col])
    out["status"] = status
    out["message"] = message
    out["bearing_type"] = np.where(plain, "plain_bushing", const_frame["bearing_type"].to_numpy())
    out["series"] = const_frame["series"].to_numpy()
    return out


def _plain_rows(frame, plain, results, row_errors, warnings_by_row) -> None:
    """Plain (DU/DP) bushings by seed 004: M_R = f·F·d/2 and N = f·F·V from the bushing kernel."""
    from bearingheat.bushing import plain_bushing_power_loss

    rows = np.flatnonzero(plain)
    d, B, F, n, f = (_column(frame, c)[rows] for c in ("d", "B", "Fr", "n", "f_plain"))
    loss = plain_bushing_power_loss(d, B, np.nan_to_num(F, nan=0.0), n, f)
    for col in RESULT_UNITS:
        results[col][rows] = np.nan
    results["MR"][rows] = loss.f_used * np.nan_to_num(F, nan=0.0) * d / 2.0
    results["NR"][rows] = loss.power
    results["p_plain"] = np.full(len(plain), np.nan)
    results["V_plain"] = np.full(len(plain), np.nan)
    results["p_plain"][rows] = loss.p
    results["V_plain"][rows] = loss.V
    for k, i in enumerate(rows):
        if loss.status[k] == "error":
            row_errors[i].append(loss.message[k])
        elif loss.message[k]:
            warnings_by_row[i].append(loss.message[k])
