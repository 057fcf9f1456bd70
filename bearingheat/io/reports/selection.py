"""The figure of ``bearingheat select --plot``: operating temperature against speed of the leading candidates.

Each candidate's T_op (the heat balance of calc) over a common range of
speeds, up to its limiting speed n_G; the admissible bearing temperature
T_bearing as a line, so a curve crosses it at the candidate's permissible
speed n_per (calc's own value, marked); the operating speed as a line, so
each curve meets it at the candidate's T_op there. Written with matplotlib's
Figure API (no pyplot, no global backend).
"""
from __future__ import annotations

import math
import textwrap

import numpy as np

from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure
from bearingheat.io.reports.thermal import figure_format

__all__ = ["draw_candidates"]

#: characters of a legend line (a candidate's label names all the bearings of its curve)
_LEGEND_WIDTH = 48


def draw_candidates(curves: dict, path, format: str | None = None) -> None:  # noqa: A002 (matplotlib's name)
    """Write the T_op curves of the candidates to a figure file (``format``, else the file's ending).

    ``curves``: ``speeds`` [1/min] (the common range), ``T_op`` (designation -> T_op [°C] at each speed, NaN
    where it is not computed or the speed is above the bearing's n_G), ``n_per`` (designation -> calc's n_per
    [1/min]), ``T_op_at_n`` (designation -> T_op at the operating speed), ``n``, ``T_bearing``, ``T_amb`` and
    ``title`` (the operating point in words)."""
    Figure = matplotlib_figure()
    fig = Figure(figsize=(12.0, 5.4), dpi=90, layout="constrained")
    ax = fig.subplots()
    speeds = np.asarray(curves["speeds"], dtype=float)
    for designation, temperatures in curves["T_op"].items():
        n_per, at_n = curves["n_per"][designation], curves["T_op_at_n"][designation]
        label = f"{designation}: T_op {at_n:.1f} °C" + (f", n_per {n_per:.0f} 1/min" if math.isfinite(n_per) else "")
        line, = ax.plot(speeds, temperatures, lw=1.6, label=textwrap.fill(label, _LEGEND_WIDTH, subsequent_indent="  "))
        if math.isfinite(n_per) and speeds[0] <= n_per <= speeds[-1]:
            ax.plot([n_per], [curves["T_bearing"]], "o", color=line.get_color(), ms=5)
        ax.plot([curves["n"]], [at_n], "s", color=line.get_color(), ms=4)
    ax.axhline(curves["T_bearing"], color="tab:red", lw=1.0, ls="--",
               label=f"T_bearing = {curves['T_bearing']:g} °C\n  (a curve crosses it at n_per, ●)")
    ax.axvline(curves["n"], color="0.3", lw=1.0, ls=":",
               label=f"operating n = {curves['n']:.0f} 1/min\n  (T_op there, ■)")
    ax.set_xlabel("speed n [1/min]")
    ax.set_ylabel("operating temperature T_op [°C]")
    ax.set_xlim(speeds[0], speeds[-1])
    ax.set_ylim(bottom=curves["T_amb"])
    ax.grid(True, color="0.85", lw=0.5)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # (beside: no curve hidden)
    ax.set_title(curves["title"], fontsize=10)
    fig.suptitle("Candidates: operating temperature against speed (a curve ends at the bearing's n_G)", fontsize=11)
    fig.savefig(path, format=format or figure_format(path), dpi=FIGURE_DPI)
