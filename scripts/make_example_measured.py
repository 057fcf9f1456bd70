"""Write examples/measured_torque_example.csv: SYNTHETIC measured friction torque for audit and diagnose.

The numbers are made, not measured: the catalogue friction model of
bearingheat (the Schaeffler catalogue) for four bearings over a grid of
speeds, oil viscosities and loads, plus the drag of a shaft seal on the rig that the model lacks
(a constant torque per bearing, 5 % higher at the top speed), plus 4 %
log-normal noise, with a fixed seed so that the file is reproducible. It
lets `bearingheat diagnose` and `bearingheat audit` be tried on a file
whose answer is known: diagnose should find 'seal_drag'.

    .venv/bin/python scripts/make_example_measured.py [OUTPUT]
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pandas as pd

import bearingheat as bh

ROOT = Path(__file__).resolve().parents[1]
#: designation -> drag of the rig's shaft seal [N*mm] that the data carry beyond the bearing model
SEAL_DRAG = {"6205": 12.0, "6208": 25.0, "6305": 18.0, "6210": 30.0}
SPEEDS = (300.0, 600.0, 1000.0, 1500.0, 2200.0, 3000.0, 4000.0)
OILS = ((8.0, 70.0), (20.0, 50.0), (50.0, 30.0))          # (nu [mm^2/s], T_oil [degC])
LOADS = (0.02, 0.05, 0.1)                                  # Fr / C0
SEED = 20261123
NOISE = 0.04


def measured_example(seed: int = SEED) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    rows = []
    for designation in SEAL_DRAG:
        C0 = bh.bearing(designation).C0
        for n in SPEEDS:
            for nu, T_oil in OILS:
                for load in LOADS:
                    rows.append({"designation": designation, "lubrication": "oil_bath", "n [1/min]": n,
                                 "Fr [N]": round(load * C0), "Fa [N]": 0.0, "nu [mm^2/s]": nu, "T_oil [degC]": T_oil})
    table = pd.DataFrame(rows)
    model = bh.calc(table.drop(columns="T_oil [degC]"))
    assert (model["status"] != "error").all()
    seal = table["designation"].map(SEAL_DRAG).to_numpy() * (1.0 + 0.05 * table["n [1/min]"] / max(SPEEDS))
    torque = (model["MR [N*mm]"].to_numpy() + seal) * np.exp(rng.normal(0.0, NOISE, len(table)))
    table["M [N*mm]"] = np.round(torque, 3)
    return table


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "examples" / "measured_torque_example.csv"
    measured_example().to_csv(target, index=False)
    print(f"wrote {target}")
