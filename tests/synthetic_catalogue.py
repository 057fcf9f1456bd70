"""Synthetic catalogue lists for the reference speed audit: the HR 1 bearings of tables/ with known changes.

The published speeds are computed from the tables (the reference heat
balance of :mod:`bearingheat.kernels.thermal`), with f0 scaled in the
series and size classes a test names, rounded the way HR 1 (2006) rounds
(:data:`bearingheat.analysis.audit.ROUNDING_STEPS`), and single rows
misprinted by a factor. The audit should recover each change and nothing
else.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.analysis.audit import ROUNDING_STEPS
from bearingheat.calc.thermal import thermal_reference_speed_details
from bearingheat.catalogue.bearings import bearing_table
from bearingheat.catalogue.thermal import reference_conditions
from bearingheat.kernels.friction import mean_diameter
from bearingheat.kernels.thermal import balance_speed


def _round_like_hr1(n: np.ndarray) -> np.ndarray:
    limits = np.array([limit for limit, _ in ROUNDING_STEPS])
    steps = np.array([step for _, step in ROUNDING_STEPS])
    step = steps[np.searchsorted(limits, n, side="right")]
    return np.round(n / step) * step


def synthetic_catalogue(f0_factor=None, misprints=None) -> pd.DataFrame:
    """The HR 1 bearings of tables/ that have an n_thr, with speeds computed from the tables, f0 scaled where told,
    rounded like HR 1.

    ``f0_factor``: {(series_key, smallest bore): factor}; ``misprints``: {designation: factor on the speed}.
    """
    table = bearing_table()
    # the bearings HR 1 prints a speed for (not those with contact seals)
    table = table[table["n_thr"].notna()].reset_index(drop=True)
    frame = table[["designation", "d", "D", "B", "T", "C0"]]
    details = thermal_reference_speed_details(frame)
    f0 = details["f0"].to_numpy(dtype=float).copy()
    key = (table["family"] + " " + table["series"]).to_numpy()
    for (series, d_min), factor in (f0_factor or {}).items():
        f0[(key == series) & (table["d"].to_numpy() >= d_min)] *= factor
    nu = np.array([reference_conditions(k).nu for k in details["kind"]])
    n = balance_speed(f0, nu, mean_diameter(table["d"], table["D"]).to_numpy(), details["M1"].to_numpy(),
                      (details["q_r"] * details["A_r"]).to_numpy())
    n = _round_like_hr1(np.asarray(n, dtype=float))
    for designation, factor in (misprints or {}).items():
        n[(table["designation"] == designation).to_numpy()] *= factor
    return pd.DataFrame({"designation": table["designation"], "family": table["family"], "series": table["series"],
                         "shield": table["shield"], "d [mm]": table["d"], "D [mm]": table["D"], "B [mm]": table["B"],
                         "T [mm]": table["T"], "C0 [N]": table["C0"], "n_B [1/min]": n})
