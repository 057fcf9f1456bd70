"""Tables of supports shared by the heat-balance tests (calc, cli, io): two bearings with calc headers."""
from __future__ import annotations

import pandas as pd

THERMAL_COLUMNS = ["n_thr [1/min]", "n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "Q_S [W]", "Q_L [W]"]


def supports(**extra):
    table = pd.DataFrame({
        "id": ["a", "b"], "designation": ["6205", "NU206-E"], "d [mm]": [25, 30], "D [mm]": [52, 62],
        "B [mm]": [15, 16], "C0 [kN]": [7.8, 36], "lubrication": ["oil_bath", "oil_bath"],
        "n [rpm]": [3000, 1500], "Fr [kN]": [2, 5],
    })
    for key, value in extra.items():
        table[key] = value
    return table


def plot_table(tmp_path, **extra):
    path = tmp_path / "supports.csv"
    supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                "T_bearing [degC]": [70, 70]}, **extra).to_csv(path, index=False)
    return path
