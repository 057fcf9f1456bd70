"""The DP11A lab rig of seed 000: loads, the three processing tasks, tables 4 and 5, plots.

Readings: bearing (seed 000 table 3: 1000095, 18, 101), Q [kg], β [deg]
(inclination of the spindle axis), n [1/min], T [N·mm]. Seed 000 pp. 11-13:

* loads: Fa = 9.81·Q·cos β, Fr = 9.81·Q·sin β [N];
  P0 = max(X0·Fr + Y0·Fa, Fr) with X0 = 0.6, Y0 = 0.5 (table 1, radial ball bearing);
* task 1, reduced friction coefficient for each speed:
  μ = 2·ΣT·P0/(d·ΣP0²), the least-squares slope of T = μ·P0·d/2 through the origin;
* task 2, for each β: T = f0·dm³·n^(2/3) + T_F, least squares on N = n^(2/3);
* task 3, for each speed: T = T0 + f·P0·(P0/C0)^c·dm, least squares on
  N = P0^(1+c), c = 0.55 for radial ball bearings.

The closed forms of the seed are implemented as printed and checked against
a general least-squares solver (:func:`least_squares_line`). Note that the
seed 000 f0 has no 10^-7 and no viscosity: T0 = f0·dm³·n^(2/3); the seed 002
catalogue f0 of the same bearing is f0·1e7/ν^(2/3) (:func:`catalogue_f0_equivalent`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat import friction
from bearingheat.errors import LabError

__all__ = [
    "LabError",
    "GRAVITY",
    "LOAD_EXPONENT_RADIAL",
    "REDUCED_FRICTION_RADIAL",
    "lab_bearing",
    "lab_loads",
    "reduced_friction_coefficient",
    "speed_fit",
    "load_fit",
    "least_squares_line",
    "catalogue_f0_equivalent",
    "LabResult",
    "process_lab",
    "read_lab_table",
    "write_lab_outputs",
    "generate_example",
]

#: g used by seed 000 p. 12 [m/s²]
GRAVITY = 9.81
#: c of T_F = f·P0·(P0/C0)^c·dm for radial ball bearings (seed 000, table 2 and p. 13)
LOAD_EXPONENT_RADIAL = 0.55
#: μ of single row radial ball bearings in T = μ·P0·d/2 (seed 000, p. 5)
REDUCED_FRICTION_RADIAL = 0.0015
#: f of radial ball bearings (seed 000, table 2)
LOAD_COEFFICIENT_RADIAL = 0.0009
#: lab columns -> catalogue unit
LAB_UNITS = {"bearing": "", "Q": "kg", "beta": "deg", "n": "1/min", "T": "N*mm", "nu": "mm^2/s"}




def lab_bearing(designation: str) -> dict:
    """Row of seed 000 table 3 (tables/lab_bearings.csv): d, dm, D [mm], C0 [N].

    >>> lab_bearing("101")["C0"]
    2227.0
    """
    from bearingheat.tables_io import load_table

    table = load_table("lab_bearings")
    hit = table[table["designation"] == str(designation).strip()]
    if hit.empty:
        raise LabError(f"bearing {designation!r} is not in seed 000 table 3; expected one of "
                       f"{', '.join(table['designation'])}")
    row = hit.iloc[0]
    return {"designation": row["designation"], "d": float(row["d"]), "dm": float(row["dm"]),
            "D": float(row["D"]), "C0": float(row["C0"])}


def lab_loads(Q, beta):
    """(Fa, Fr) [N] of a weight Q [kg] on the spindle inclined at β [deg] (seed 000, p. 12).

    >>> [round(v, 4) for v in lab_loads(2.0, 30.0)]
    [16.9914, 9.81]
    """
    Q = np.asarray(Q, dtype=float)
    b = np.radians(np.asarray(beta, dtype=float))
    Fa, Fr = GRAVITY * Q * np.cos(b), GRAVITY * Q * np.sin(b)
    if np.ndim(Fa) == 0:
        return float(Fa), float(Fr)
    return Fa, Fr


def reduced_friction_coefficient(T, P0, d):
    """μ = 2·ΣT·P0/(d·ΣP0²) [-] (seed 000, task 1, item 5); T [N·mm], P0 [N], d [mm].

    >>> round(reduced_friction_coefficient([0.1, 0.2], [10.0, 20.0], 12.0), 8)
    0.00166667
    """
    T = np.asarray(T, dtype=float)
    P0 = np.asarray(P0, dtype=float)
    return float(2.0 * np.sum(T * P0) / (d * np.sum(P0 * P0)))


def _closed_form_line(T, N):
    """Slope and intercept of T = slope·N + intercept by the sums printed in seed 000."""
    T = np.asarray(T, dtype=float)
    N = np.asarray(N, dtype=float)
    m = len(T)
    den = m * np.sum(N * N) - np.sum(N) ** 2
    slope = (m * np.sum(T * N) - np.sum(T) * np.sum(N)) / den
    intercept = (np.sum(T) * np.sum(N * N) - np.sum(T * N) * np.sum(N)) / den
    return float(slope), float(intercept)


def speed_fit(T, n, dm):
    """(f0, T_F) of T = f0·dm³·n^(2/3) + T_F by the closed forms of seed 000 task 2, N = n^(2/3).

    f0 in N·mm/(mm³·min^(-2/3)) as the seed defines it (no 1e-7, no ν); T_F [N·mm].

    >>> n = np.array([2400.0, 2600.0, 2800.0, 3000.0])
    >>> f0, TF = speed_fit(2e-8 * 20**3 * n**(2/3) + 0.03, n, 20.0)
    >>> round(f0 * 1e8, 10), round(TF, 12)
    (2.0, 0.03)
    """
    slope, intercept = _closed_form_line(T, np.power(np.asarray(n, dtype=float), 2.0 / 3.0))
    return slope / dm ** 3, intercept


def load_fit(T, P0, C0, dm, c=LOAD_EXPONENT_RADIAL):
    """(f, T0) of T = T0 + f·P0·(P0/C0)^c·dm by the closed forms of seed 000 task 3, N = P0^(1+c).

    >>> P0 = np.array([4.9, 9.81, 19.62])
    >>> f, T0 = load_fit(0.05 + 0.0009 * P0 * (P0 / 2227)**0.55 * 20, P0, 2227.0, 20.0)
    >>> round(f, 12), round(T0, 12)
    (0.0009, 0.05)
    """
    slope, intercept = _closed_form_line(T, np.power(np.asarray(P0, dtype=float), 1.0 + c))
    return slope * C0 ** c / dm, intercept


def least_squares_line(x, y, *, through_origin: bool = False) -> tuple[float, float]:
    """(slope, intercept) of y = slope·x + intercept by a general solver (numpy lstsq, SVD).

    The reference the seed's closed forms are checked against.

    >>> [round(v, 12) for v in least_squares_line([1.0, 2.0, 3.0], [3.0, 5.0, 7.0])]
    [2.0, 1.0]
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    A = x[:, None] if through_origin else np.column_stack([x, np.ones_like(x)])
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    slope = float(coef[0])
    intercept = 0.0 if through_origin else float(coef[1])
    return slope, intercept


def catalogue_f0_equivalent(f0_seed000, nu):
    """Seed 002 f0 equal to a seed 000 f0 at viscosity ν [mm²/s] (ν·n >= 2000): f0·1e7/ν^(2/3).

    >>> round(float(catalogue_f0_equivalent(1e-7, 8.0)), 6)
    0.25
    """
    return np.asarray(f0_seed000, dtype=float) * 1e7 / np.power(np.asarray(nu, dtype=float), 2.0 / 3.0)


# ---------------------------------------------------------------------------------------------
# Processing a table of readings
# ---------------------------------------------------------------------------------------------

def read_lab_table(table: pd.DataFrame) -> pd.DataFrame:
    """Readings with unit headers -> columns bearing, Q [kg], beta [deg], n [1/min], T [N*mm], nu [mm²/s]."""
    from bearingheat.frame import parse_header
    from bearingheat.units import UnitError, parse_unit, speed_rpm, ureg
    import pint

    out = pd.DataFrame(index=range(len(table)))
    seen = {}
    for header in table.columns:
        name, unit = parse_header(header)
        if name in LAB_UNITS:
            seen[name] = (header, unit)
    for name in ("bearing", "Q", "beta", "n", "T"):
        if name not in seen:
            unit = LAB_UNITS[name]
            raise LabError(f"missing column: '{name} [{unit}]'" if unit else f"missing column: '{name}'")
    values = table.reset_index(drop=True)
    for name, (header, unit_text) in seen.items():
        target = LAB_UNITS[name]
        if target == "":
            out[name] = values[header].astype(str).str.strip()
            continue
        numbers = pd.to_numeric(values[header], errors="coerce").to_numpy(dtype=float)
        bad = np.flatnonzero(np.isnan(numbers))
        if len(bad):
            i = int(bad[0])
            raise LabError(f"row {i + 1}: {values[header].iat[i]!r} is not a number for {header}")
        if unit_text is None or unit_text.strip() in ("", "-"):
            raise LabError(f"column {header!r}: needs a unit, e.g. '{name} [{target}]'")
        try:
            unit = parse_unit(unit_text, name=header)
            if target == "1/min":
                out[name] = numbers * speed_rpm(ureg().Quantity(1.0, unit), header)
            else:
                out[name] = ureg().Quantity(numbers, unit).to(target).magnitude
        except UnitError as exc:
            raise LabError(f"column {header!r}: {exc}") from exc
        except pint.errors.DimensionalityError as exc:
            raise LabError(f"column {header!r}: unit {unit_text} cannot be converted to {target}") from exc
    for name, low, high, text in (("Q", 0.0, None, "must be > 0"), ("n", 0.0, None, "must be > 0"),
                                  ("T", 0.0, None, "must be > 0"), ("beta", -1e-12, 90.0, "must be in 0..90 deg")):
        col = out[name].to_numpy(dtype=float)
        bad = (col <= low) | ((col > high) if high is not None else False)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise LabError(f"row {i + 1}: {seen[name][0]} = {float(values[seen[name][0]].iat[i]):g} {text}")
    return out


@dataclass
class LabResult:
    """Everything the lab report shows."""

    readings: pd.DataFrame                      # with Fa, Fr, P0 [N], d, dm, C0, and catalogue columns
    table4: dict = field(default_factory=dict)  # (bearing, beta) -> DataFrame rows Q, columns n
    table5: dict = field(default_factory=dict)  # (bearing, Q) -> DataFrame rows n, columns beta
    task1: pd.DataFrame | None = None           # bearing, beta, n, mu, mu_lstsq, points
    task2: pd.DataFrame | None = None           # bearing, Q, beta, f0, T_F, (lstsq), f0_catalogue_equivalent
    task3: pd.DataFrame | None = None           # bearing, beta, n, f, T0, (lstsq)
    comparison: pd.DataFrame | None = None      # per bearing: measured vs seed 002 / seed 000 models
    notes: list[str] = field(default_factory=list)


def process_lab(table: pd.DataFrame, *, nu: float | None = None, lubrication: str = "grease") -> LabResult:
    """Run the three tasks of seed 000 on a table of readings (unit headers).

    ``nu`` [mm²/s] is the viscosity for the seed 002 comparison when the
    table has no ``nu`` column; without either the comparison is skipped.
    """
    from bearingheat.frame import calc
    from bearingheat.tables_io import load_table

    r = read_lab_table(table)
    factors = load_table("static_load_factors")
    radial = factors[factors["bearing_type"] == "deep_groove_ball"].iloc[0]
    geometry = pd.DataFrame([lab_bearing(b) for b in r["bearing"]])
    for col in ("d", "dm", "D", "C0"):
        r[col] = geometry[col].to_numpy()
    r["Fa"], r["Fr"] = lab_loads(r["Q"].to_numpy(), r["beta"].to_numpy())
    r["P0"] = friction.static_equivalent_load(r["Fr"].to_numpy(), r["Fa"].to_numpy(),
                                              float(radial["X0"]), float(radial["Y0"]))
    result = LabResult(r)
    rows1, rows2, rows3 = [], [], []
    for (bearing, beta, n), g in r.groupby(["bearing", "beta", "n"], sort=True):
        d = float(g["d"].iat[0])
        mu = reduced_friction_coefficient(g["T"], g["P0"], d)
        mu_ls, _ = least_squares_line(g["P0"] * d / 2.0, g["T"], through_origin=True)
        rows1.append({"bearing": bearing, "beta": beta, "n": n, "points": len(g), "mu": mu, "mu_lstsq": mu_ls})
        if g["P0"].nunique() >= 2:
            dm, C0 = float(g["dm"].iat[0]), float(g["C0"].iat[0])
            f, T0 = load_fit(g["T"], g["P0"], C0, dm)
            slope, intercept = least_squares_line(g["P0"] ** (1 + LOAD_EXPONENT_RADIAL), g["T"])
            rows3.append({"bearing": bearing, "beta": beta, "n": n, "points": len(g), "f": f, "T0": T0,
                          "f_lstsq": slope * C0 ** LOAD_EXPONENT_RADIAL / dm, "T0_lstsq": intercept})
    for (bearing, Q, beta), g in r.groupby(["bearing", "Q", "beta"], sort=True):
        if g["n"].nunique() < 2:
            continue
        dm = float(g["dm"].iat[0])
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
    # --- comparison with the models of the seeds
    r["T_seed000_mu"] = REDUCED_FRICTION_RADIAL * r["P0"] * r["d"] / 2.0
    viscosity = r["nu"] if "nu" in r.columns else (pd.Series(nu, index=r.index) if nu is not None else None)
    if viscosity is not None:
        rows = pd.DataFrame({"designation": r["bearing"], "d [mm]": r["d"], "D [mm]": r["D"],
                             "C0 [N]": r["C0"], "lubrication": lubrication, "n [1/min]": r["n"],
                             "Fr [N]": r["Fr"], "Fa [N]": r["Fa"], "nu [mm^2/s]": viscosity})
        catalogue = calc(rows)
        r["MR_seed002"] = catalogue["MR [N*mm]"].to_numpy()
        r["M0_seed002"] = catalogue["M0 [N*mm]"].to_numpy()
        r["M1_seed002"] = catalogue["M1 [N*mm]"].to_numpy()
        r["nu"] = viscosity.to_numpy(dtype=float)
        if not result.task2.empty:
            nu_of = r.groupby(["bearing", "Q", "beta"])["nu"].mean()
            keys = list(zip(result.task2["bearing"], result.task2["Q"], result.task2["beta"]))
            result.task2["f0_seed002_equivalent"] = catalogue_f0_equivalent(
                result.task2["f0"].to_numpy(), nu_of.loc[keys].to_numpy())
    else:
        result.notes.append("no viscosity given (column 'nu [mm^2/s]' or --nu): the seed 002 comparison is skipped")
    comp = []
    for bearing, g in r.groupby("bearing", sort=True):
        entry = {"bearing": bearing, "readings": len(g), "T_mean [N*mm]": g["T"].mean(),
                 "seed000_mu_model / measured": float((g["T_seed000_mu"] / g["T"]).median())}
        if "MR_seed002" in g:
            entry["seed002_MR / measured"] = float((g["MR_seed002"] / g["T"]).median())
            entry["seed002 M0 share"] = float((g["M0_seed002"] / g["MR_seed002"]).median())
        comp.append(entry)
    result.comparison = pd.DataFrame(comp)
    return result


# ---------------------------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------------------------


def _figure(out, files: list, bearing: str, task: int, title: str, xlabel: str, groups) -> list[str]:
    """Plot one task of one bearing into OUT/task<k>_<bearing>.png; the report lines that show it."""
    path = out / f"task{task}_{bearing}.png"
    _plot_task(path, title, xlabel, groups)
    files.append(path)
    return ["", f"![task {task}]({path.name})", ""]


def _plot_task(path: Path, title: str, xlabel: str, groups) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.0, 3.6))
    for label, x, y, x_line, y_line in groups:
        points = ax.plot(x, y, "o", ms=4, label=label)[0]
        ax.plot(x_line, y_line, "-", color=points.get_color(), lw=1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("T [N·mm]")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _table_markdown(frame: pd.DataFrame, index_name: str, column_name: str) -> list[str]:
    cols = [f"{column_name} = {c:g}" for c in frame.columns]
    lines = [f"| {index_name} | " + " | ".join(cols) + " |", "|---" * (len(cols) + 1) + "|"]
    for idx, row in frame.iterrows():
        lines.append(f"| {idx:g} | " + " | ".join("–" if pd.isna(v) else f"{v:.4g}" for v in row) + " |")
    return lines


def write_lab_outputs(result: LabResult, out_dir) -> list[Path]:
    """report.md, task CSVs and one PNG per task and bearing into ``out_dir``; returns the files."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    r = result.readings
    for name, frame in (("readings", r), ("task1_mu", result.task1), ("task2_f0_TF", result.task2),
                        ("task3_f_T0", result.task3), ("comparison", result.comparison)):
        path = out / f"{name}.csv"
        frame.to_csv(path, index=False)
        files.append(path)
    lines = ["# DP11A lab rig: processing after seed 000", ""]
    lines += [f"- {note}" for note in result.notes] + ([""] if result.notes else [])
    for bearing in sorted(r["bearing"].unique()):
        g = r[r["bearing"] == bearing]
        d, dm, C0 = g["d"].iat[0], g["dm"].iat[0], g["C0"].iat[0]
        lines += [f"## Bearing {bearing} (d = {d:g} mm, dm = {dm:g} mm, C0 = {C0:g} N)", ""]
        for (b, beta), t4 in result.table4.items():
            if b != bearing:
                continue
            lines += [f"### Table 4, β = {beta:g}°: friction torque T [N·mm]", ""]
            lines += _table_markdown(t4, "Q [kg]", "n [1/min]") + [""]
        for (b, Q), t5 in result.table5.items():
            if b != bearing or t5.shape[0] < 2:
                continue
            lines += [f"### Table 5, Q = {Q:g} kg: friction torque T [N·mm]", ""]
            lines += _table_markdown(t5, "n [1/min]", "β [deg]") + [""]
        t1 = result.task1[result.task1["bearing"] == bearing]
        groups1 = []
        for _, row in t1.iterrows():
            pts = g[(g["beta"] == row["beta"]) & (g["n"] == row["n"])]
            x = np.linspace(0.0, pts["P0"].max() * 1.05, 20)
            groups1.append((f"β={row['beta']:g}°, n={row['n']:g}, μ={row['mu']:.3g}", pts["P0"], pts["T"],
                            x, row["mu"] * x * d / 2.0))
        lines += ["### Task 1: reduced friction coefficient μ", "",
                  "| β [deg] | n [1/min] | μ | μ (general least squares) |", "|---|---|---|---|"]
        lines += [f"| {row['beta']:g} | {row['n']:g} | {row['mu']:.5g} | {row['mu_lstsq']:.5g} |"
                  for _, row in t1.iterrows()]
        lines += _figure(out, files, bearing, 1, f"{bearing}: T = μ·P0·d/2", "P0 [N]", groups1)
        t2 = result.task2[result.task2["bearing"] == bearing] if not result.task2.empty else result.task2
        if len(t2):
            lines += ["### Task 2: f0 and T_F (T = f0·dm³·n^(2/3) + T_F)", "",
                      "| Q [kg] | β [deg] | f0 (seed 000) | T_F [N·mm] | f0 as seed 002 f0 |", "|---|---|---|---|---|"]
            groups2 = []
            for _, row in t2.iterrows():
                pts = g[(g["Q"] == row["Q"]) & (g["beta"] == row["beta"])]
                N = pts["n"] ** (2.0 / 3.0)
                x = np.linspace(N.min(), N.max(), 20)
                groups2.append((f"Q={row['Q']:g}, β={row['beta']:g}°", N, pts["T"], x, row["f0"] * dm ** 3 * x
                                + row["T_F"]))
                equivalent = row.get("f0_seed002_equivalent", math.nan)
                lines.append(f"| {row['Q']:g} | {row['beta']:g} | {row['f0']:.4g} | {row['T_F']:.4g} | "
                             f"{'–' if pd.isna(equivalent) else f'{equivalent:.3g}'} |")
            lines += _figure(out, files, bearing, 2, f"{bearing}: T = f0·dm³·N + T_F", "N = n^(2/3)", groups2)
        t3 = result.task3[result.task3["bearing"] == bearing] if not result.task3.empty else result.task3
        if len(t3):
            lines += ["### Task 3: f and T0 (T = T0 + f·P0·(P0/C0)^c·dm, c = 0.55)", "",
                      "| β [deg] | n [1/min] | f | T0 [N·mm] |", "|---|---|---|---|"]
            groups3 = []
            for _, row in t3.iterrows():
                pts = g[(g["beta"] == row["beta"]) & (g["n"] == row["n"])]
                N = pts["P0"] ** (1 + LOAD_EXPONENT_RADIAL)
                x = np.linspace(0.0, N.max(), 20)
                groups3.append((f"β={row['beta']:g}°, n={row['n']:g}", N, pts["T"], x,
                                row["T0"] + row["f"] * dm / C0 ** LOAD_EXPONENT_RADIAL * x))
                lines.append(f"| {row['beta']:g} | {row['n']:g} | {row['f']:.4g} | {row['T0']:.4g} |")
            lines += _figure(out, files, bearing, 3, f"{bearing}: T = T0 + f·(dm/C0^c)·N", "N = P0^(1+c) [N^1.55]",
                             groups3)
    lines += ["## Comparison with the models of the seeds", "",
              f"Medians over the readings. seed 000: T = μ·P0·d/2 with μ = {REDUCED_FRICTION_RADIAL}; "
              "seed 002: the catalogue model M_R = M0 + M1 of the same bearing (its ISO series row).", ""]
    lines += ["| " + " | ".join(result.comparison.columns) + " |", "|---" * len(result.comparison.columns) + "|"]
    for _, row in result.comparison.iterrows():
        lines.append("| " + " | ".join(f"{v:.4g}" if isinstance(v, float) else str(v) for v in row) + " |")
    path = out / "report.md"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    files.append(path)
    return files


# ---------------------------------------------------------------------------------------------
# The worked example (generated)
# ---------------------------------------------------------------------------------------------

#: parameters the example was generated with: seed 000 two-term model, f0 (seed 000 sense), f, c
EXAMPLE_TRUTH = {"f0": 3e-8, "f": LOAD_COEFFICIENT_RADIAL, "c": LOAD_EXPONENT_RADIAL, "noise": 0.02,
                 "nu": 20.0, "seed": 2016}


def generate_example(seed: int = EXAMPLE_TRUTH["seed"]) -> pd.DataFrame:
    """The shipped example examples/lab_dp11a_example.csv: GENERATED readings, not measurements.

    Follows the procedure of seed 000: the three bearings of table 3, the
    weights 0.5, 1 and 2 kg, β = 30°, 60°, 90°, four speeds in the rig's
    range (motor 3600-4600 1/min over a 1.5 belt ratio), T from the seed's
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
