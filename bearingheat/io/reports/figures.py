"""The figures of the documentation: friction torque against speed and load, the bushing pV chart, a coast-down.

Each function draws one PNG (150 dpi) from the package's own calculations on
the examples of the docs pages; ``docs/conf.py`` calls :func:`write_doc_figures`
at build time, so the pictures follow the code.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.analysis.coastdown import coastdown_analysis
from bearingheat.calc.table import calc
from bearingheat.catalogue.bushing import pressure_limit_du_dp, pv_limit_du_dp_table25
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure
from bearingheat.io.reports.coastdown import plot_coastdown

__all__ = ["plot_friction_torque", "plot_bushing_pv", "write_doc_figures"]

#: the bearing of the friction figure: the demo's locating bearing in an oil bath
_BEARING = {"designation": "6208", "lubrication": "oil_bath", "Fa [kN]": 0.0}


def plot_friction_torque(path) -> Path:
    """MR of a 6208 in an oil bath against speed (three viscosities) and against radial load, by calc."""
    Figure = matplotlib_figure()
    speeds = np.geomspace(50.0, 8000.0, 120)
    fig = Figure(figsize=(9.0, 3.6))
    by_speed, by_load = fig.subplots(1, 2)
    for nu in (12.0, 40.0, 100.0):
        rows = pd.DataFrame({**_BEARING, "n [1/min]": speeds, "Fr [kN]": 3.2, "nu [mm^2/s]": nu})
        by_speed.plot(speeds, calc(rows)["MR [N*mm]"], label=f"ν = {nu:g} mm²/s")
    by_speed.set_xscale("log")
    by_speed.set_xlabel("n [1/min]")
    by_speed.set_ylabel("M_R [N·mm]")
    by_speed.set_title("6208, oil bath, Fr = 3.2 kN", fontsize=10)
    by_speed.legend(fontsize=8)
    loads = np.linspace(0.0, 18.0, 91)
    for n in (300.0, 1480.0, 6000.0):
        rows = pd.DataFrame({**_BEARING, "n [1/min]": n, "Fr [kN]": loads, "nu [mm^2/s]": 40.0})
        by_load.plot(loads, calc(rows)["MR [N*mm]"], label=f"n = {n:g} 1/min")
    by_load.set_xlabel("Fr [kN] (C0 = 18 kN)")
    by_load.set_ylabel("M_R [N·mm]")
    by_load.set_title("6208, oil bath, ν = 40 mm²/s", fontsize=10)
    by_load.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=FIGURE_DPI, format="png")
    return Path(path)


def plot_bushing_pv(path, *, F_N: float = 2000.0, n_rpm: float = 500.0, d_mm: float = 25.0, l_mm: float = 100.0,
                    application: str = "bushing_constant_load", shaft: str = "soft", life_h: float = 1000.0,
                    load_type: str = "rotating_fixed_load_point") -> Path:
    """The admissible region p <= [p], p·v <= K of a DU bushing and the operating point of the docs' example."""
    Figure = matplotlib_figure()
    K = pv_limit_du_dp_table25(application, shaft, life_h)
    p_adm = pressure_limit_du_dp(load_type)
    p = F_N / (d_mm * l_mm)                              # N/mm², projected area
    v = np.pi * d_mm * n_rpm / 60000.0                    # m/s
    speeds = np.geomspace(0.002, 10.0, 200)
    limit = np.minimum(p_adm, K / speeds)
    fig = Figure(figsize=(5.2, 4.0))
    ax = fig.subplots()
    ax.fill_between(speeds, 1e-3, limit, color="tab:green", alpha=0.15, label="admissible")
    ax.plot(speeds, limit, color="tab:green", label=f"p·v = K = {K:.3g} N/mm²·m/s, p ≤ [p] = {p_adm:.3g} N/mm²")
    ax.plot([v], [p], "o", color="tab:red", label=f"operating point: p = {p:.2f} N/mm², v = {v:.2f} m/s")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(1e-2, 2 * p_adm)
    ax.set_xlabel("sliding speed v [m/s]")
    ax.set_ylabel("specific load p [N/mm²]")
    ax.set_title(f"DU bushing d = {d_mm:g} mm, l = {l_mm:g} mm, F = {F_N / 1000:g} kN, n = {n_rpm:g} 1/min",
                 fontsize=9)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=FIGURE_DPI, format="png")
    return Path(path)


def write_doc_figures(folder, examples) -> list[Path]:
    """Write friction_torque.png, bushing_pv.png and coastdown_fit.png into ``folder``; ``examples`` is the
    project's examples folder (coastdown_example.csv)."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    data = pd.read_csv(Path(examples) / "coastdown_example.csv")
    result = coastdown_analysis(data["t [s]"].to_numpy(dtype=float), data["n [1/min]"].to_numpy(dtype=float),
                                2.6, 1100.0, 25.0)
    plot_coastdown(result, folder / "coastdown_fit.png")
    return [plot_friction_torque(folder / "friction_torque.png"), plot_bushing_pv(folder / "bushing_pv.png"),
            folder / "coastdown_fit.png"]
