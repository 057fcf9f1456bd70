"""The DP11A lab rig of the DP11A manual: processing a table of readings (tasks 1-3, tables 4 and 5, the comparison).

Readings: bearing (the DP11A manual table 3: 1000095, 18, 101), Q [kg], β [deg]
(inclination of the spindle axis), n [1/min], T [N·mm]. The DP11A manual pp. 11-13:
loads Fa = 9.81·Q·cos β, Fr = 9.81·Q·sin β [N]; P0 = max(X0·Fr + Y0·Fa, Fr)
with X0 = 0.6, Y0 = 0.5 (table 1, radial ball bearing); task 1 μ for each
speed, task 2 f0 and T_F for each β, task 3 f and T0 for each speed, by the
closed forms of :mod:`bearingheat.kernels.lab`, each checked against a
general least-squares solver. The comparison runs the catalogue model of
the Schaeffler catalogue (:func:`bearingheat.calc.table.calc`) on the same bearings.

Task 1's μ is, as the manual defines it, the slope of a line through the
origin. The torque of the same manual's tasks 2 and 3 has a load-independent
part (T_F, T0), so task 1 also fits the line with an intercept,
T = μ_slope·P0·d/2 + T_intercept, which is the line the report draws.

The report, its tables and figures are written by :mod:`bearingheat.io.reports.lab`.
"""
from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from bearingheat.analysis.passthrough import unread_columns
from bearingheat.calc.contract import parse_header
from bearingheat.calc.conversion import not_a_number, numbers_of, row_name, row_numbers
from bearingheat.calc.table import calc
from bearingheat.catalogue.lab import (
    LOAD_COEFFICIENT_RADIAL,
    LOAD_EXPONENT_RADIAL,
    REDUCED_FRICTION_RADIAL,
    lab_bearing,
    radial_static_load_factors,
)
from bearingheat.errors import LabError, UnitError
from bearingheat.kernels import friction
from bearingheat.kernels.lab import (
    catalogue_f0_equivalent,
    lab_loads,
    least_squares_line,
    load_fit,
    reduced_friction_coefficient,
    speed_fit,
)
from bearingheat.units import convert_column

__all__ = [
    "LAB_UNITS",
    "EXAMPLE_TRUTH",
    "LabResult",
    "process_lab",
    "read_lab_table",
    "generate_example",
]

#: lab columns -> catalogue unit
LAB_UNITS = {"bearing": "", "Q": "kg", "beta": "deg", "n": "1/min", "T": "N*mm", "nu": "mm^2/s"}


def read_lab_table(table: pd.DataFrame) -> pd.DataFrame:
    """Readings with unit headers -> columns bearing, Q [kg], beta [deg], n [1/min], T [N*mm], nu [mm²/s].

    Any unit of the right dimension is converted (``T [N*m]``, ``n [Hz]``,
    ``nu [cSt]``); a missing column, a cell that is not a number, a unit that
    does not fit and a value out of range raise :class:`~bearingheat.errors.LabError`. A table read from a CSV
    by :func:`bearingheat.io.tables.read_table` is read with its decimal mark (``attrs['decimal']``) and its
    messages cite the file's lines (``attrs['lines']``), as calc's do.
    """
    rows = row_numbers(table)
    decimal = str(table.attrs.get("decimal", "."))
    out = pd.DataFrame(index=range(len(table)))
    seen = _lab_headers(table)
    for name in ("bearing", "Q", "beta", "n", "T"):
        if name not in seen:
            unit = LAB_UNITS[name]
            raise LabError(f"missing column: '{name} [{unit}]'" if unit else f"missing column: '{name}'")
    values = table.reset_index(drop=True)
    typed: dict[str, np.ndarray] = {}  # the numbers as typed, in the user's unit
    for name, (header, unit_text) in seen.items():
        target = LAB_UNITS[name]
        if target == "":
            out[name] = values[header].astype(str).str.strip()
            continue
        numbers = numbers_of(values[header], decimal)
        typed[name] = numbers
        bad = np.flatnonzero(~np.isfinite(numbers))  # (text, a blank cell, inf)
        if len(bad):
            i = int(bad[0])
            cell = values[header].iat[i]
            if pd.isna(cell):
                raise LabError(f"{row_name(rows, i)}: blank is not a number for {header}")
            value = cell.item() if isinstance(cell, np.generic) else cell
            raise LabError(f"{row_name(rows, i)}: {not_a_number(value, header, decimal)}")
        if unit_text is None or unit_text.strip() in ("", "-"):
            raise LabError(f"column {header!r}: needs a unit, e.g. '{name} [{target}]'")
        try:
            out[name] = convert_column(numbers, unit_text, target, name=name, header=header)[0]
        except UnitError as exc:
            raise LabError(f"column {header!r}: {exc}") from exc
    checks = [("Q", 0.0, None, "must be > 0"), ("n", 0.0, None, "must be > 0"), ("T", 0.0, None, "must be > 0"),
              ("beta", -1e-12, 90.0, "must be in 0..90 deg")]
    checks += [("nu", 0.0, None, "must be > 0")] if "nu" in out else []
    for name, low, high, text in checks:
        col = out[name].to_numpy(dtype=float)
        bad = (col <= low) | ((col > high) if high is not None else False)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise LabError(f"{row_name(rows, i)}: {seen[name][0]} = {typed[name][i]:g} {text}")
    return out


def _lab_headers(table: pd.DataFrame) -> dict[str, tuple[str, str | None]]:
    """Lab column name -> (its header, the unit typed there) of the columns a table of readings has; a header that
    is no 'name [unit]' names no reading (it is passed through, as calc passes it)."""
    seen: dict[str, tuple[str, str | None]] = {}
    for header in table.columns:
        name, unit = parse_header(header, strict=False)
        if name in LAB_UNITS:
            if name in seen:  # ('T [degC]' and 'T [K]': which one is the reading? as calc and diagnose refuse it)
                raise LabError(f"column {header!r}: {name} appears twice")
            seen[name] = (header, unit)
    return seen


def _first(group: pd.DataFrame, column: str) -> float:
    """The value of a column that is the same on every reading of a group (a bearing's d, dm, C0)."""
    return float(group[column].to_numpy(dtype=float)[0])


@dataclass
class LabResult:
    """Everything the lab report shows."""

    readings: pd.DataFrame                      # with Fa, Fr, P0 [N], d, dm, C0, catalogue columns, unread columns
    # (bearing, beta) -> mean T, rows Q, columns n; (bearing, Q) -> mean T, rows n, columns beta
    table4: dict[tuple[Hashable, Hashable], pd.DataFrame] = field(default_factory=dict)
    table5: dict[tuple[Hashable, Hashable], pd.DataFrame] = field(default_factory=dict)
    # bearing, beta, n, points, mu, mu_lstsq (through the origin), mu_slope, T_intercept (line with an intercept)
    task1: pd.DataFrame = field(default_factory=pd.DataFrame)
    # bearing, Q, beta, points, f0, T_F, (lstsq), f0_catalogue_equivalent
    task2: pd.DataFrame = field(default_factory=pd.DataFrame)
    # bearing, beta, n, points, f, T0, (lstsq)
    task3: pd.DataFrame = field(default_factory=pd.DataFrame)
    # per bearing: measured against the DP11A manual's μ model and the Schaeffler catalogue model
    comparison: pd.DataFrame = field(default_factory=pd.DataFrame)
    notes: list[str] = field(default_factory=list)


def process_lab(table: pd.DataFrame, *, nu: float | None = None, lubrication: str = "grease") -> LabResult:
    """Run the three tasks of the DP11A manual on a table of readings (unit headers).

    ``nu`` [mm²/s] is the viscosity for the Schaeffler catalogue comparison when the
    table has no ``nu`` column; without either the comparison is skipped.
    """
    r = read_lab_table(table)
    X0, Y0 = radial_static_load_factors()
    geometry = pd.DataFrame([lab_bearing(b) for b in r["bearing"]])
    for col in ("d", "dm", "D", "C0"):
        r[col] = geometry[col].to_numpy()
    r["Fa"], r["Fr"] = lab_loads(r["Q"].to_numpy(), r["beta"].to_numpy())
    r["P0"] = friction.static_equivalent_load(r["Fr"].to_numpy(), r["Fa"].to_numpy(), X0, Y0)
    result = LabResult(r)
    rows1: list[dict[str, object]] = []
    rows2: list[dict[str, object]] = []
    rows3: list[dict[str, object]] = []
    for (bearing, beta, n), g in r.groupby(["bearing", "beta", "n"], sort=True):
        d = _first(g, "d")
        mu = reduced_friction_coefficient(g["T"], g["P0"], d)
        mu_ls, _ = least_squares_line(g["P0"] * d / 2.0, g["T"], through_origin=True)
        mu_slope, T_intercept = (least_squares_line(g["P0"] * d / 2.0, g["T"]) if g["P0"].nunique() >= 2
                                 else (np.nan, np.nan))
        rows1.append({"bearing": bearing, "beta": beta, "n": n, "points": len(g), "mu": mu, "mu_lstsq": mu_ls,
                      "mu_slope": mu_slope, "T_intercept": T_intercept})
        if g["P0"].nunique() >= 2:
            dm, C0 = _first(g, "dm"), _first(g, "C0")
            f, T0 = load_fit(g["T"], g["P0"], C0, dm)
            slope, intercept = least_squares_line(g["P0"] ** (1 + LOAD_EXPONENT_RADIAL), g["T"])
            rows3.append({"bearing": bearing, "beta": beta, "n": n, "points": len(g), "f": f, "T0": T0,
                          "f_lstsq": slope * C0 ** LOAD_EXPONENT_RADIAL / dm, "T0_lstsq": intercept})
    for (bearing, Q, beta), g in r.groupby(["bearing", "Q", "beta"], sort=True):
        if g["n"].nunique() < 2:
            continue
        dm = _first(g, "dm")
        f0, TF = speed_fit(g["T"], g["n"], dm)
        slope, intercept = least_squares_line(g["n"] ** (2.0 / 3.0), g["T"])
        row = {"bearing": bearing, "Q": Q, "beta": beta, "points": len(g), "f0": f0, "T_F": TF,
               "f0_lstsq": slope / dm ** 3, "T_F_lstsq": intercept}
        rows2.append(row)
    result.task1, result.task2, result.task3 = pd.DataFrame(rows1), pd.DataFrame(rows2), pd.DataFrame(rows3)
    for (bearing, beta), g in r.groupby(["bearing", "beta"], sort=True):
        result.table4[(bearing, beta)] = g.pivot_table(index="Q", columns="n", values="T", aggfunc="mean")
    for (bearing, Q), g in r.groupby(["bearing", "Q"], sort=True):
        result.table5[(bearing, Q)] = g.pivot_table(index="n", columns="beta", values="T", aggfunc="mean")
    # --- comparison with the DP11A manual's μ model and the Schaeffler catalogue model
    r["T_mu_model"] = REDUCED_FRICTION_RADIAL * r["P0"] * r["d"] / 2.0
    viscosity = r["nu"] if "nu" in r.columns else (pd.Series(nu, index=r.index) if nu is not None else None)
    if viscosity is not None:
        rows = pd.DataFrame({"designation": r["bearing"], "d [mm]": r["d"], "D [mm]": r["D"],
                             "C0 [N]": r["C0"], "lubrication": lubrication, "n [1/min]": r["n"],
                             "Fr [N]": r["Fr"], "Fa [N]": r["Fa"], "nu [mm^2/s]": viscosity})
        catalogue = calc(rows)
        r["MR_catalogue"] = catalogue["MR [N*mm]"].to_numpy()
        r["M0_catalogue"] = catalogue["M0 [N*mm]"].to_numpy()
        r["M1_catalogue"] = catalogue["M1 [N*mm]"].to_numpy()
        r["nu"] = viscosity.to_numpy(dtype=float)
        if not result.task2.empty:
            nu_of = r.groupby(["bearing", "Q", "beta"])["nu"].mean()
            keys = list(zip(result.task2["bearing"], result.task2["Q"], result.task2["beta"]))
            result.task2["f0_catalogue_equivalent"] = catalogue_f0_equivalent(
                result.task2["f0"].to_numpy(), nu_of.loc[keys].to_numpy())
    else:
        result.notes.append("no viscosity given (column 'nu [mm^2/s]' or --nu): the Schaeffler catalogue comparison is skipped")
    comp = []
    for bearing, g in r.groupby("bearing", sort=True):
        entry = {"bearing": bearing, "readings": len(g), "T_mean [N*mm]": g["T"].mean(),
                 "DP11A mu model / measured": float((g["T_mu_model"] / g["T"]).median())}
        if "MR_catalogue" in g:
            entry["catalogue MR / measured"] = float((g["MR_catalogue"] / g["T"]).median())
            entry["catalogue M0 share"] = float((g["M0_catalogue"] / g["MR_catalogue"]).median())
        comp.append(entry)
    result.comparison = pd.DataFrame(comp)
    # the columns no reading is taken from (a remark, 'remark [see note]]'), kept in readings.csv as calc keeps them
    kept = unread_columns(table, [header for header, _ in _lab_headers(table).values()], set(r.columns),
                          "lab writes into readings.csv", LabError)
    result.readings = pd.concat([r, kept], axis=1) if len(kept.columns) else r
    return result


# ---------------------------------------------------------------------------------------------
# The worked example (generated)
# ---------------------------------------------------------------------------------------------

#: parameters the example was generated with: the DP11A manual two-term model, f0 (the DP11A manual sense), f, c
EXAMPLE_TRUTH = {"f0": 3e-8, "f": LOAD_COEFFICIENT_RADIAL, "c": LOAD_EXPONENT_RADIAL, "noise": 0.02,
                 "nu": 20.0, "seed": 2016}


def generate_example(seed: int = int(EXAMPLE_TRUTH["seed"])) -> pd.DataFrame:
    """The shipped example examples/lab_dp11a_example.csv: GENERATED readings, not measurements.

    Follows the procedure of the DP11A manual: the three bearings of table 3, the
    weights 0.5, 1 and 2 kg, β = 30°, 60°, 90°, four speeds in the rig's
    range (motor 3600-4600 1/min over a 1.5 belt ratio), T from the manual's
    two-term formula with :data:`EXAMPLE_TRUTH` and 2 % noise, rounded to 4
    significant digits like a read-off.
    """
    rng = np.random.default_rng(seed)
    rows = []
    for bearing in ("1000095", "18", "101"):
        geo = lab_bearing(bearing)
        for beta in (30.0, 60.0, 90.0):
            for n in (2400.0, 2600.0, 2800.0, 3000.0):
                for Q in (0.5, 1.0, 2.0):
                    Fa, Fr = lab_loads(Q, beta)
                    P0 = float(friction.static_equivalent_load(Fr, Fa, 0.6, 0.5))
                    T = (EXAMPLE_TRUTH["f0"] * geo["dm"] ** 3 * n ** (2.0 / 3.0)
                         + EXAMPLE_TRUTH["f"] * P0 * (P0 / geo["C0"]) ** EXAMPLE_TRUTH["c"] * geo["dm"])
                    T *= 1.0 + EXAMPLE_TRUTH["noise"] * rng.standard_normal()
                    rows.append({"bearing": bearing, "Q [kg]": Q, "beta [deg]": beta, "n [1/min]": n,
                                 "T [N*mm]": float(f"{T:.4g}"), "nu [mm^2/s]": EXAMPLE_TRUTH["nu"]})
    return pd.DataFrame(rows)
