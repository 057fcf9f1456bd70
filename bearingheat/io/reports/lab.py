"""Report of the DP11A lab rig (the DP11A manual): report.md with tables 4 and 5, the task CSVs and one figure per task.

The figures are drawn with matplotlib's Figure API (no pyplot, no global
backend); matplotlib is imported when a figure is drawn.
"""
from __future__ import annotations

import math
from functools import partial
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.analysis.lab import LabResult
from bearingheat.catalogue.lab import LOAD_EXPONENT_RADIAL, REDUCED_FRICTION_RADIAL
from bearingheat.io.files import write_outputs
from bearingheat.io.tables import escape_formulas
from bearingheat.io.reports import matplotlib_figure

__all__ = ["write_lab_outputs"]


def _figure(writers: dict, bearing: str, task: int, title: str, xlabel: str, groups) -> list[str]:
    """Plan the plot of one task of one bearing as OUT/task<k>_<bearing>.png; the report lines that show it."""
    name = f"task{task}_{bearing}.png"
    writers[name] = partial(_plot_task, title=title, xlabel=xlabel, groups=groups)
    return ["", f"![task {task}]({name})", ""]


def _write_csv(frame: pd.DataFrame, path: Path) -> None:
    escape_formulas(frame).to_csv(path, index=False)


def _plot_task(path: Path, title: str, xlabel: str, groups) -> None:
    Figure = matplotlib_figure()

    fig = Figure(figsize=(5.0, 3.6))
    ax = fig.subplots()
    for label, x, y, x_line, y_line in groups:
        points = ax.plot(x, y, "o", ms=4, label=label)[0]
        ax.plot(x_line, y_line, "-", color=points.get_color(), lw=1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("T [N·mm]")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90, format="png")


def _table_markdown(frame: pd.DataFrame, index_name: str, column_name: str) -> list[str]:
    cols = [f"{column_name} = {c:g}" for c in frame.columns]
    lines = [f"| {index_name} | " + " | ".join(cols) + " |", "|---" * (len(cols) + 1) + "|"]
    for idx, row in frame.iterrows():
        lines.append(f"| {idx:g} | " + " | ".join("–" if pd.isna(v) else f"{v:.4g}" for v in row) + " |")
    return lines


def write_lab_outputs(result: LabResult, out_dir, *, force: bool = False, inputs=()) -> list[Path]:
    """report.md, task CSVs and one PNG per task and bearing into ``out_dir``; returns the files.

    Existing files are not replaced unless ``force``; none of them may be one of ``inputs``. Every file is
    checked before the first is written, and each is written atomically
    (:func:`bearingheat.io.files.write_outputs`).
    """
    writers: dict = {}
    r = result.readings
    for name, frame in (("readings", r), ("task1_mu", result.task1), ("task2_f0_TF", result.task2),
                        ("task3_f_T0", result.task3), ("comparison", result.comparison)):
        writers[f"{name}.csv"] = partial(_write_csv, frame)
    lines = ["# DP11A lab rig: processing after the DP11A manual", ""]
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
        lines += _figure(writers, bearing, 1, f"{bearing}: T = μ·P0·d/2", "P0 [N]", groups1)
        t2 = result.task2[result.task2["bearing"] == bearing] if not result.task2.empty else result.task2
        if len(t2):
            lines += ["### Task 2: f0 and T_F (T = f0·dm³·n^(2/3) + T_F)", "",
                      "| Q [kg] | β [deg] | f0 (the DP11A manual) | T_F [N·mm] | f0 as the Schaeffler catalogue f0 |", "|---|---|---|---|---|"]
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
            lines += _figure(writers, bearing, 2, f"{bearing}: T = f0·dm³·N + T_F", "N = n^(2/3)", groups2)
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
            lines += _figure(writers, bearing, 3, f"{bearing}: T = T0 + f·(dm/C0^c)·N", "N = P0^(1+c) [N^1.55]",
                             groups3)
    lines += ["## Comparison with the models of the seeds", "",
              f"Medians over the readings. The DP11A manual: T = μ·P0·d/2 with μ = {REDUCED_FRICTION_RADIAL}; "
              "the Schaeffler catalogue: the catalogue model M_R = M0 + M1 of the same bearing (its ISO series row).", ""]
    lines += ["| " + " | ".join(result.comparison.columns) + " |", "|---" * len(result.comparison.columns) + "|"]
    for _, row in result.comparison.iterrows():
        lines.append("| " + " | ".join(f"{v:.4g}" if isinstance(v, float) else str(v) for v in row) + " |")
    text = "\n".join(lines) + "\n"
    writers["report.md"] = lambda path: Path(path).write_text(text, encoding="utf-8")
    return write_outputs(out_dir, writers, force=force, inputs=inputs)
