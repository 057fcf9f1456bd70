"""Plot of the working contact angle against the axial load for Zaitsev & Voronkin example bearing.

``python -m bearingheat.io.reports.contact [PATH]`` writes ``docs/_static/contact_alpha_vs_Fa.png``
(or PATH). The output is deterministic: fixed data, fixed size, no time stamp in the PNG.
The figure is drawn with matplotlib's Figure API (no pyplot, no global backend).
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from bearingheat.kernels.contact import KGF, series_start, stiffness_characteristic, working_contact_angle
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["EXAMPLE_BEARING", "plot_alpha_vs_axial_load", "DEFAULT_PATH"]

DEFAULT_PATH = Path(__file__).resolve().parents[3] / "docs" / "_static" / "contact_alpha_vs_Fa.png"

# Bearing 4-1006095 of Zaitsev & Voronkin (5 x 13 x 4 mm), catalogue units mm, deg.
EXAMPLE_BEARING = {"z": 7, "d_w": 2.0, "d_m": 8.7355, "alpha0": 12.0, "r_i": 1.05, "r_o": 1.16}


def plot_alpha_vs_axial_load(path: str | Path = DEFAULT_PATH, max_load_N: float = 60.0) -> Path:
    """Write the PNG of α(Fa) for the example bearing: exact root, the paper's quadratic start, and its example point."""
    Figure = matplotlib_figure()
    import matplotlib

    b = EXAMPLE_BEARING
    c_star = stiffness_characteristic(b["z"], b["d_w"], b["d_m"], b["alpha0"], b["r_i"], b["r_o"])
    loads = np.linspace(0.0, max_load_N, 121)
    alpha = working_contact_angle(loads, c_star, b["alpha0"])
    alpha_start = b["alpha0"] + np.degrees(series_start(loads, c_star, b["alpha0"]))
    seed_alpha = 14 + 28 / 60  # Zaitsev & Voronkin: 14°28′ at Fa = 2 kgf

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with matplotlib.rc_context({"font.size": 9}):
        fig = Figure(figsize=(5.0, 3.2), dpi=100)
        ax = fig.subplots()
        ax.plot(loads, alpha, color="tab:blue", label="exact root (Brent)")
        ax.plot(loads, alpha_start, color="tab:orange", linestyle="--", label="quadratic start $x_0$")
        ax.plot([2 * KGF], [seed_alpha], "o", color="black", label="Zaitsev & Voronkin: 14°28′ at 2 kgf")
        ax.axhline(b["alpha0"], color="grey", linewidth=0.8, linestyle=":")
        ax.set_xlabel("axial load $F_a$ [N]")
        ax.set_ylabel("working contact angle α [deg]")
        ax.set_title("Bearing 4-1006095: z = 7, $d_w$ = 2 mm, α0 = 12°", fontsize=9)
        ax.set_xlim(0.0, max_load_N)
        ax.grid(True, linewidth=0.4)
        ax.legend(loc="lower right", fontsize=8)
        fig.tight_layout()
        fig.savefig(path, format="png", dpi=FIGURE_DPI, metadata={"Software": None})
    return path


if __name__ == "__main__":  # pragma: no cover
    print(plot_alpha_vs_axial_load(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH))
