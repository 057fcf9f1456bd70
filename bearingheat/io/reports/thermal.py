"""The heat-balance figure of one support (``bearingheat plot``): friction heat and heat carried away.

Two panels of the heat balance N_R + Q_E = Q_S + Q_L (after
Schaeffler HR 1): against speed at the bearing temperature (crossing: the
permissible speed n_per) and against temperature at the operating speed
(crossing: the operating temperature T_op). :func:`heat_balance_curves`
runs the calc rows of one support of a table (``name [unit]`` headers);
:func:`draw_heat_balance` writes the PNG with matplotlib's Figure API (no
pyplot, no global backend). The curves themselves are
:func:`bearingheat.calc.heat_flow_curves.heat_flow_curves`.
"""
from __future__ import annotations

import math
from pathlib import Path

import pandas as pd

from bearingheat.calc.table import compute_table
from bearingheat.calc.heat_flow_curves import heat_flow_curves
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import InputError
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["heat_balance_curves", "draw_heat_balance", "figure_format", "FIGURE_FORMATS"]

#: file name endings matplotlib writes a figure as
FIGURE_FORMATS = ("png", "svg", "svgz", "pdf", "eps", "ps", "jpg", "jpeg", "tif", "tiff", "webp")


def figure_format(path, example: str = "heat_balance.png") -> str:
    """The figure format of a file name (``plot.svg`` -> ``svg``); :class:`InputError` for an ending matplotlib
    does not write (naming ``example`` as a name to give)."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in FIGURE_FORMATS:
        raise InputError(f"{path}: a figure is written as {', '.join('.' + f for f in FIGURE_FORMATS)}; "
                         f"name it e.g. {example}")
    return suffix


def heat_balance_curves(table: pd.DataFrame, points: int = 200, f2_chart: F2Chart | None = None) -> dict:
    """Curves of the heat balance of the first row of ``table`` (calc columns with units) in catalogue units.

    ``f2_chart``: a digitised f2 chart for M2 of an axially loaded cylindrical roller bearing without ``f2``
    (read at each speed and temperature of the curves, as calc's heat balance reads it).

    Returns a dict with ``status`` ('ok' | 'warning' | 'error'), ``message``
    and ``label`` (the row's id or designation), and where the row can be
    drawn the curves of :func:`bearingheat.calc.heat_flow_curves.heat_flow_curves`.
    The row is computed as ``calc`` computes it (:func:`~bearingheat.calc.table.compute_table`: designations fill
    the dimensions, oil data the viscosity), with calc's status and message. A table that cannot be used at all
    raises :class:`~bearingheat.errors.InputError`.
    """
    computed = compute_table(table.iloc[:1].reset_index(drop=True), f2_chart=f2_chart)
    frame, results = computed.frame, computed.results
    message, status = str(results["message"].iloc[0]), str(results["status"].iloc[0])
    out = {"status": status, "message": message, "label": _label(table)}
    if status == "error":
        return out
    if "T_amb" not in frame.columns:
        out.update(status="error", message="; ".join([m for m in (message,) if m] + [
            "T_amb [degC]: missing; the plot needs the ambient temperature"]))
        return out
    columns = computed.extension_columns["thermal"][0]
    curves = heat_flow_curves(frame, results, columns, points=points, f2_chart=f2_chart)
    if curves is None:
        out.update(status="error", message=out["message"] or "the heat flow area A_r cannot be computed")
        return out
    out.update(curves)
    return out


def _label(table: pd.DataFrame) -> str:
    """'id (designation)', or whichever of the two the row has, else 'the support'."""
    found = []
    for name in ("id", "designation"):
        hits = [c for c in table.columns if str(c).split("[")[0].strip() == name]
        if hits and str(table[hits[0]].iloc[0]).strip() not in ("", "nan", "None"):
            found.append(str(table[hits[0]].iloc[0]).strip())
    if len(found) == 2 and found[0] != found[1]:
        return f"{found[0]} ({found[1]})"
    return found[0] if found else "the support"


def draw_heat_balance(curves: dict, path, format: str | None = None) -> None:  # noqa: A002 (matplotlib's name)
    """Write the two panels of :func:`heat_balance_curves` to a figure file (``format``, else the file's
    ending, :func:`figure_format`)."""
    Figure = matplotlib_figure()

    fig = Figure(figsize=(9.0, 3.6), dpi=90)
    left, right = fig.subplots(1, 2)
    left.plot(curves["speeds"], curves["friction_vs_speed"], label="friction heat N_R")
    left.plot(curves["speeds"], curves["carried_vs_speed"], "--", label="carried away Q_S + Q_L − Q_E")
    if not math.isnan(curves["n_cross"]):
        left.plot([curves["n_cross"]], [curves["carried_vs_speed"][0]], "o", color="black")
        left.annotate(f"{curves['n_cross']:.0f} 1/min", (curves["n_cross"], curves["carried_vs_speed"][0]),
                      textcoords="offset points", xytext=(6, -14))
    top = curves["speeds"][-1]
    ends = [speed for speed in curves["chart_speeds"] if 0 < speed <= top]
    for k, speed in enumerate(ends):  # N_R is not drawn beyond the digitised f2 chart (never extrapolated)
        left.axvline(speed, color="grey", lw=1.0, ls="-.", label="end of the f2 chart" if k == 0 else None)
    if not math.isnan(curves["n"]):
        margin = (f"; n_per/n = {curves['n_cross'] / curves['n']:.2f}"
                  if not math.isnan(curves["n_cross"]) and curves["n"] > 0 else "")
        left.axvline(curves["n"], color="tab:red", lw=1.0, ls=":", label=f"operating n = {curves['n']:.0f} 1/min{margin}")
    left.set_xlabel("speed n [1/min]")
    left.set_ylabel("heat flow [W]")
    left.set_title(f"at {curves['theta']:.1f} °C", fontsize=10)
    left.legend(fontsize=8, loc="best" if ends else "upper left")  # (more lines: where it hides the fewest points)
    right.plot(curves["temperatures"], curves["friction_vs_temperature"], label="N_R(ν(T)) + Q_E")
    right.plot(curves["temperatures"], curves["carried_vs_temperature"], "--", label="Q_S(T) + Q_L(T)")
    if not math.isnan(curves["T_op"]):
        right.plot([curves["T_op"]], [curves["heat_at_T_op"]], "o", color="black")
        right.annotate(f"T_op = {curves['T_op']:.1f} °C", (curves["T_op"], curves["heat_at_T_op"]),
                       textcoords="offset points", xytext=(6, -14))
    right.set_xlabel("bearing temperature [°C]")
    right.set_title(f"at n = {curves['n']:.0f} 1/min", fontsize=10)
    right.legend(fontsize=8, loc="upper left")
    fig.suptitle(f"Heat balance: {curves['label']}", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, format=format or figure_format(path), dpi=FIGURE_DPI)
