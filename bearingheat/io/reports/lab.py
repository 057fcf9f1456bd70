"""Report of the DP11A lab rig (the DP11A manual): report.md with tables 4 and 5, the task CSVs and one figure per task.

The figures are drawn with matplotlib's Figure API (no pyplot, no global
backend); matplotlib is imported when a figure is drawn. Each series of a
figure has its own pair of colour and marker, the legend stands beside the
axes, every axis names its unit, and the PNG is written at 150 dpi.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import pandas as pd

from bearingheat.analysis.lab import LabResult
from bearingheat.catalogue.lab import LOAD_EXPONENT_RADIAL, REDUCED_FRICTION_RADIAL
from bearingheat.io.files import write_outputs
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure
from bearingheat.io.tables import escape_formulas

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["write_lab_outputs", "lab_task_figure", "series_styles", "LabSeries"]

#: seven markers against matplotlib's ten default colours: 70 series before a (colour, marker) pair repeats
MARKERS = ("o", "s", "^", "D", "v", "P", "X")
COLOURS = 10


class LabSeries(NamedTuple):
    """One series of a task figure: its readings and the fitted line (empty arrays draw no line)."""

    label: str
    x: np.ndarray
    y: np.ndarray
    x_line: np.ndarray
    y_line: np.ndarray


def series_styles(count: int) -> list[tuple[str, str]]:
    """(colour, marker) of ``count`` series: colour k mod 10 of the default cycle, marker k mod 7."""
    return [(f"C{k % COLOURS}", MARKERS[k % len(MARKERS)]) for k in range(count)]


def lab_task_figure(series: Sequence[LabSeries], *, title: str, xlabel: str, lines: str) -> Figure:
    """The readings of one task of one bearing and their fitted lines, T [N·mm] against ``xlabel``.

    ``lines`` says what the lines are (the legend's title). The legend stands to the right of the axes.
    """
    figure_class = matplotlib_figure()
    fig = figure_class(figsize=(7.6, 4.0), layout="constrained")
    ax = fig.subplots()
    for (colour, marker), s in zip(series_styles(len(series)), series):
        ax.plot(s.x, s.y, linestyle="none", marker=marker, ms=5, color=colour, label=s.label)
        if len(s.x_line):
            ax.plot(s.x_line, s.y_line, "-", color=colour, lw=1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("T [N·mm]")
    ax.set_title(title, fontsize=9)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize=7, title=lines,
              title_fontsize=7, alignment="left")
    return fig


def _save_figure(path: Path, series: Sequence[LabSeries], title: str, xlabel: str, lines: str) -> None:
    lab_task_figure(series, title=title, xlabel=xlabel, lines=lines).savefig(path, dpi=FIGURE_DPI, format="png")


def _figure(writers: dict[str, Callable[[Path], object]], bearing: str, task: int, series: list[LabSeries], *,
            title: str, xlabel: str, lines: str) -> list[str]:
    """Plan the plot of one task of one bearing as OUT/task<k>_<bearing>.png; the report lines that show it."""
    name = f"task{task}_{bearing}.png"
    writers[name] = partial(_save_figure, series=series, title=title, xlabel=xlabel, lines=lines)
    return ["", f"![task {task}]({name})", ""]


def _write_csv(frame: pd.DataFrame, path: Path) -> None:
    escape_formulas(frame).to_csv(path, index=False)


def _markdown(frame: pd.DataFrame, formats: Iterable[str]) -> list[str]:
    """``frame`` as a markdown table (DataFrame.to_markdown): floats by ``formats`` (one per column), a missing
    value as '–', text columns as they are."""
    cells = frame.astype(object).where(frame.notna(), None)
    text_columns = [k for k, column in enumerate(frame.columns) if not pd.api.types.is_numeric_dtype(frame[column])]
    text = cells.to_markdown(index=False, floatfmt=tuple(formats), missingval="–", disable_numparse=text_columns)
    return text.splitlines()


def _table_markdown(frame: pd.DataFrame, index_name: str, column_name: str) -> list[str]:
    """A table 4 or 5 (mean T of each cell) with its index as the first column."""
    table = pd.DataFrame({f"{column_name} = {c:g}": frame[c].to_numpy(dtype=float) for c in frame.columns})
    table.insert(0, index_name, frame.index.to_numpy(dtype=float))
    return _markdown(table, ["g"] + [".4g"] * len(frame.columns))


def _line(x_max: float, slope: float, intercept: float) -> tuple[np.ndarray, np.ndarray]:
    """A fitted line from 0 to a little beyond the last reading (no line where the fit is undetermined)."""
    if not np.isfinite(slope):
        return np.empty(0), np.empty(0)
    x = np.linspace(0.0, x_max * 1.05, 20)
    return x, slope * x + intercept


def write_lab_outputs(result: LabResult, out_dir: str | Path, *, force: bool = False,
                      inputs: Iterable[str | Path] = ()) -> list[Path]:
    """report.md, task CSVs and one PNG per task and bearing into ``out_dir``; returns the files.

    Existing files are not replaced unless ``force``; none of them may be one of ``inputs``. Every file is
    checked before the first is written, and each is written atomically
    (:func:`bearingheat.io.files.write_outputs`).
    """
    writers: dict[str, Callable[[Path], object]] = {}
    r = result.readings
    for name, frame in (("readings", r), ("task1_mu", result.task1), ("task2_f0_TF", result.task2),
                        ("task3_f_T0", result.task3), ("comparison", result.comparison)):
        writers[f"{name}.csv"] = partial(_write_csv, frame)
    lines = ["# DP11A lab rig: processing after the DP11A manual", ""]
    lines += [f"- {note}" for note in result.notes] + ([""] if result.notes else [])
    for bearing in sorted(r["bearing"].unique()):
        g = r[r["bearing"] == bearing]
        d, dm, C0 = (float(g[c].to_numpy(dtype=float)[0]) for c in ("d", "dm", "C0"))
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
        lines += _task1(result, g, bearing, d, writers)
        lines += _task2(result, g, bearing, dm, writers)
        lines += _task3(result, g, bearing, dm, C0, writers)
    lines += ["## Comparison with the DP11A manual's μ model and the Schaeffler catalogue model", "",
              f"Medians over the readings. The DP11A manual: T = μ·P0·d/2 with μ = {REDUCED_FRICTION_RADIAL}; "
              "the Schaeffler catalogue: the catalogue model M_R = M0 + M1 of the same bearing (its ISO series row).",
              ""]
    lines += _markdown(result.comparison, [".4g"] * len(result.comparison.columns))
    text = "\n".join(lines) + "\n"
    writers["report.md"] = lambda path: Path(path).write_text(text, encoding="utf-8")
    return write_outputs(out_dir, writers, force=force, inputs=inputs)


def _task1(result: LabResult, g: pd.DataFrame, bearing: str, d: float,
           writers: dict[str, Callable[[Path], object]]) -> list[str]:
    t1 = result.task1[result.task1["bearing"] == bearing]
    series = []
    for _, row in t1.iterrows():
        pts = g[(g["beta"] == row["beta"]) & (g["n"] == row["n"])]
        x, y = _line(float(pts["P0"].max()), row["mu_slope"] * d / 2.0, row["T_intercept"])
        label = f"β = {row['beta']:g}°, n = {row['n']:g} 1/min" + ("" if len(x) else " (one load: no line)")
        series.append(LabSeries(label, pts["P0"].to_numpy(), pts["T"].to_numpy(), x, y))
    table = pd.DataFrame({"β [deg]": t1["beta"], "n [1/min]": t1["n"], "μ": t1["mu"],
                          "μ (general least squares)": t1["mu_lstsq"], "μ_slope": t1["mu_slope"],
                          "T_intercept [N·mm]": t1["T_intercept"]})
    return (["### Task 1: reduced friction coefficient μ", "",
             "μ as the DP11A manual defines it: the slope of T = μ·P0·d/2 through the origin, by the manual's sums "
             "and by a general least-squares solver. The torque has a part that does not depend on the load (T_F "
             "of task 2, T0 of task 3), so the lines of the figure fit an intercept: T = μ_slope·P0·d/2 + "
             "T_intercept.", ""]
            + _markdown(table, ["g", "g", ".5g", ".5g", ".4g", ".4g"])
            + _figure(writers, bearing, 1, series, title=f"bearing {bearing}, task 1: T against P0",
                      xlabel="P0 [N]", lines="lines: T = μ_slope·P0·d/2 + T_intercept\n(intercept fitted)"))


def _rows_of(task: pd.DataFrame, bearing: str) -> pd.DataFrame:
    """The rows of one bearing in a task's results (an empty table, which may lack the column, as it is)."""
    return task[task["bearing"] == bearing] if not task.empty else task


def _task2(result: LabResult, g: pd.DataFrame, bearing: str, dm: float,
           writers: dict[str, Callable[[Path], object]]) -> list[str]:
    t2 = _rows_of(result.task2, bearing)
    if not len(t2):
        return []
    series = []
    for _, row in t2.iterrows():
        pts = g[(g["Q"] == row["Q"]) & (g["beta"] == row["beta"])]
        N = pts["n"].to_numpy(dtype=float) ** (2.0 / 3.0)
        x = np.linspace(N.min(), N.max(), 20)
        series.append(LabSeries(f"Q = {row['Q']:g} kg, β = {row['beta']:g}°", N, pts["T"].to_numpy(), x,
                                row["f0"] * dm ** 3 * x + row["T_F"]))
    equivalent = t2["f0_catalogue_equivalent"] if "f0_catalogue_equivalent" in t2 else np.nan
    table = pd.DataFrame({"Q [kg]": t2["Q"], "β [deg]": t2["beta"], "f0 (the DP11A manual)": t2["f0"],
                          "T_F [N·mm]": t2["T_F"], "f0 as the Schaeffler catalogue f0": equivalent})
    return (["### Task 2: f0 and T_F (T = f0·dm³·n^(2/3) + T_F)", ""]
            + _markdown(table, ["g", "g", ".4g", ".4g", ".3g"])
            + _figure(writers, bearing, 2, series, title=f"bearing {bearing}, task 2: T against N = n^(2/3)",
                      xlabel="N = n^(2/3) [min^(-2/3)]", lines="lines: T = f0·dm³·N + T_F\n(intercept T_F fitted)"))


def _task3(result: LabResult, g: pd.DataFrame, bearing: str, dm: float, C0: float,
           writers: dict[str, Callable[[Path], object]]) -> list[str]:
    t3 = _rows_of(result.task3, bearing)
    if not len(t3):
        return []
    series = []
    for _, row in t3.iterrows():
        pts = g[(g["beta"] == row["beta"]) & (g["n"] == row["n"])]
        N = pts["P0"].to_numpy(dtype=float) ** (1 + LOAD_EXPONENT_RADIAL)
        x, y = _line(float(N.max()), row["f"] * dm / C0 ** LOAD_EXPONENT_RADIAL, row["T0"])
        series.append(LabSeries(f"β = {row['beta']:g}°, n = {row['n']:g} 1/min", N, pts["T"].to_numpy(), x, y))
    table = pd.DataFrame({"β [deg]": t3["beta"], "n [1/min]": t3["n"], "f": t3["f"], "T0 [N·mm]": t3["T0"]})
    c = LOAD_EXPONENT_RADIAL
    return ([f"### Task 3: f and T0 (T = T0 + f·P0·(P0/C0)^c·dm, c = {c:g})", ""]
            + _markdown(table, ["g", "g", ".4g", ".4g"])
            + _figure(writers, bearing, 3, series, title=f"bearing {bearing}, task 3: T against N = P0^(1+c)",
                      xlabel=f"N = P0^(1+c) [N^{1 + c:g}]",
                      lines="lines: T = T0 + f·(dm/C0^c)·N\n(intercept T0 fitted)"))
