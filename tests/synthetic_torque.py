"""Synthetic measured friction torque: the catalogue model + one effect + noise (tests and benchmarks).

The effects are written here independently of :mod:`bearingheat.kernels.effects`:
the viscosity of the heated bearing follows a Vogel law (not the
exponential of the candidate), the seal torque creeps up 5 % over the speed
range, the churning loss uses its own exponents.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.table import calc
from bearingheat.kernels import friction

#: designation -> (d, D, C0 [N], extra catalogue columns); rough catalogue sizes
BEARINGS = {
    "6205": (25, 52, 7800, {}),
    "6208": (40, 80, 19000, {}),
    "6310": (50, 110, 38000, {}),
    "6004": (20, 42, 5000, {}),
    "7206-B": (30, 62, 15300, {"Y0": 0.26}),
    "30206-A": (30, 62, 44000, {"Y": 1.6}),
    "NU208-E": (40, 80, 53000, {}),
    "NU206-E": (30, 62, 36000, {}),
}
AXIAL = {"6205", "6208", "6310", "6004", "7206-B", "30206-A"}
EFFECTS = ("none", "seal_drag", "f0_scale", "viscosity_heating", "drag_losses", "run_in", "preload")

SPEEDS = (300.0, 600.0, 1000.0, 1500.0, 2200.0, 3000.0, 4000.0, 5000.0)
OILS = ((8.0, 70.0), (20.0, 50.0), (50.0, 30.0))   # (nu [mm^2/s], T_oil [degC]) of one oil at three temperatures


def grid(designations, rng, repeats=1) -> pd.DataFrame:
    rows = []
    for des in designations:
        d, D, C0, extra = BEARINGS[des]
        for n in SPEEDS:
            for nu, T_oil in OILS:
                for fr in (0.02, 0.05, 0.1):
                    for fa in ((0.0, 0.02) if des in AXIAL else (0.0,)):
                        for _ in range(repeats):
                            row = {"designation": des, "d [mm]": d, "D [mm]": D, "C0 [N]": C0,
                                   "lubrication": "oil_bath", "n [1/min]": n, "Fr [N]": fr * C0,
                                   "Fa [N]": fa * C0, "nu [mm^2/s]": nu, "T_oil [degC]": T_oil}
                            row.update(extra)
                            rows.append(row)
    table = pd.DataFrame(rows)
    table["t [h]"] = rng.uniform(0.0, 120.0, len(table))
    return table


def _catalogue(table: pd.DataFrame) -> pd.DataFrame:
    cols = [c for c in table.columns if not c.startswith(("T_oil", "t ["))]
    out = calc(table[cols])
    assert (out["status"] != "error").all(), out.loc[out["status"] == "error", "message"].tolist()
    return out


def true_torque(table: pd.DataFrame, effect: str, rng) -> np.ndarray:
    """The noise-free torque [N*mm] of every row with ``effect`` added."""
    base = _catalogue(table)
    M0 = base["M0 [N*mm]"].to_numpy(float)
    M1 = base["M1 [N*mm]"].to_numpy(float) + base["M2 [N*mm]"].to_numpy(float)
    MR = M0 + M1
    des = table["designation"].to_numpy()
    n = table["n [1/min]"].to_numpy(float)
    nu = table["nu [mm^2/s]"].to_numpy(float)
    dM = (table["d [mm]"].to_numpy(float) + table["D [mm]"].to_numpy(float)) / 2
    f0 = base["f0"].to_numpy(float)
    if effect == "none":
        return MR
    if effect == "seal_drag":
        out = MR.copy()
        for b in np.unique(des):
            mine = des == b
            level = rng.uniform(0.4, 0.9) * np.median(MR[mine])
            out[mine] += level * (1.0 + 0.05 * n[mine] / n.max())
        return out
    if effect == "f0_scale":
        return MR + (rng.uniform(2.0, 3.0) - 1.0) * M0
    if effect == "viscosity_heating":
        # Vogel: nu(T) ~ exp(B/(T + C)), B = 900 K, C = 95 K (ISO VG 46-like)
        T_oil = table["T_oil [degC]"].to_numpy(float)
        R = 25.0 / friction.power_loss(MR, n).max()
        M = MR.copy()
        for _ in range(200):
            T = T_oil + R * friction.power_loss(M, n)
            nu_hot = nu * np.exp(900.0 / (T + 95.0) - 900.0 / (T_oil + 95.0))
            M = 0.5 * M + 0.5 * (friction.speed_dependent_torque(f0, nu_hot, n, dM) + M1)
        return M
    if effect == "drag_losses":
        raw = dM ** 4.7 * n ** 1.8
        top = np.argmax(raw)
        return MR + rng.uniform(0.6, 1.2) * MR[top] * raw / raw[top]
    if effect == "run_in":
        t = table["t [h]"].to_numpy(float)
        return MR + rng.uniform(2.0, 4.0) * M0 * np.exp(-t / rng.uniform(10.0, 25.0))
    if effect == "preload":
        loaded = table.copy()
        C0 = loaded["C0 [N]"].to_numpy(float)
        extra = np.zeros(len(loaded))
        for b in np.unique(des):
            if b in AXIAL:
                extra[des == b] = rng.uniform(0.04, 0.08) * C0[des == b]
        loaded["Fa [N]"] = loaded["Fa [N]"] + extra
        pre = _catalogue(loaded)
        return pre["MR [N*mm]"].to_numpy(float)
    raise ValueError(effect)


def measured_set(effect: str, seed: int, designations=None, noise=None, repeats=1):
    """(table with 'M [N*mm]', noise RMS [N*mm], relative noise) for one effect and seed."""
    rng = np.random.default_rng(seed)
    if designations is None:
        pool = sorted(BEARINGS)
        designations = list(rng.choice(pool, size=4, replace=False))
    table = grid(designations, rng, repeats)
    truth = true_torque(table, effect, rng)
    sigma = rng.uniform(0.03, 0.05) if noise is None else noise
    measured = truth * (1.0 + sigma * rng.standard_normal(len(truth)))
    table["M [N*mm]"] = measured
    noise_rms = float(np.sqrt(np.mean((measured - truth) ** 2)))
    return table, noise_rms, sigma


#: widths B [mm] (T of the tapered bearing) for the SKF model, which needs them
WIDTHS = {"6205": 15, "6208": 18, "6310": 27, "6004": 12, "7206-B": 16, "30206-A": 16, "NU208-E": 18,
          "NU206-E": 16}


def model_set(model: str, seed: int, *, designations=("6205", "6208", "NU208-E", "30206-A"), sigma=0.05,
              f0_scale=1.0):
    """Measured torque made with one friction model ('schaeffler' or 'skf') on circulating oil, with
    multiplicative log-normal noise of ``sigma``; ``f0_scale`` scales the catalogue model's M0 (a fitted f0)."""
    rng = np.random.default_rng(seed)
    table = grid(list(designations), rng).drop(columns=["T_oil [degC]", "t [h]"])
    table["lubrication"] = "circulating_oil"
    table["B [mm]"] = table["designation"].map(WIDTHS)
    table["T [mm]"] = np.where(table["designation"].str.startswith("3"), 17.25, np.nan)
    out = calc(table, model=model)
    assert (out["status"] != "error").all(), out.loc[out["status"] == "error", "message"].tolist()
    torque = out["MR [N*mm]"].to_numpy() + (f0_scale - 1.0) * out["M0 [N*mm]"].to_numpy() \
        if model == "schaeffler" else out["MR [N*mm]"].to_numpy()
    table["M [N*mm]"] = torque * np.exp(rng.normal(0.0, sigma, len(table)))
    return table
