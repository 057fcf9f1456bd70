"""Benchmark: permissible speed n_per of 10^5 bearings (issue 3).

Two ways to the same numbers, timed in one run:

1. one vectorised call: :func:`bearingheat.kernels.thermal.balance_speed` for n_θr at the
   reference conditions and :func:`bearingheat.kernels.thermal.permissible_speed_factor`
   for f_n at the operating conditions (exact roots, both ν·n regimes);
2. a per-row loop of ``scipy.optimize.brentq`` on the same two heat balances.

Target: (1) at least 50x faster than (2). The bearings mix sizes, loads,
viscosities and heat flows. Run as a script (prints the ratio) or import
:func:`main` (returns the figures):

    .venv/bin/python benchmarks/bench_thermal.py [ROWS]
"""
from __future__ import annotations

import math
import time

import numpy as np

from common import size_argument, verdict

TARGET_RATIO = 50.0


def make_bearings(rows: int, seed: int = 3) -> dict[str, np.ndarray]:
    """Synthetic radial bearings in catalogue units (mm, N, mm²/s, W)."""
    rng = np.random.default_rng(seed)
    d = rng.uniform(10.0, 200.0, rows)
    D = d * rng.uniform(1.6, 2.2, rows)
    B = (D - d) * rng.uniform(0.25, 0.6, rows)
    C0 = 20.0 * d * B * rng.uniform(0.5, 2.0, rows)
    return {
        "dM": (d + D) / 2.0, "A_r": math.pi * B * (D + d), "C0": C0,
        "f0_ref": rng.uniform(1.7, 4.0, rows), "f1_ref": rng.uniform(1e-4, 4e-4, rows),
        "f0": rng.uniform(1.0, 6.0, rows), "M_load": rng.uniform(1e-4, 5e-4, rows) * C0 * rng.uniform(0.02, 0.3, rows)
        * (d + D) / 2.0, "nu": rng.uniform(3.0, 200.0, rows), "Q": rng.uniform(10.0, 2000.0, rows),
    }


def vectorised(b: dict[str, np.ndarray]) -> np.ndarray:
    from bearingheat.kernels.thermal import balance_speed, permissible_speed_factor, reference_heat_flux_density

    q_r = reference_heat_flux_density("radial", b["A_r"])
    M1_ref = b["f1_ref"] * 0.05 * b["C0"] * b["dM"]
    n_thr = balance_speed(b["f0_ref"], 12.0, b["dM"], M1_ref, q_r * b["A_r"])
    return n_thr * permissible_speed_factor(n_thr, b["f0"], b["nu"], b["dM"], b["M_load"], b["Q"])


def per_row_brentq(b: dict[str, np.ndarray]) -> np.ndarray:
    """The same two balances, one row at a time with scipy.optimize.brentq (scalar Python arithmetic)."""
    from scipy.optimize import brentq

    K = math.pi / 30.0 * 1e-3

    def power(n, f0, nu, dM, M_load):
        factor = (nu * n) ** (2.0 / 3.0) if nu * n >= 2000.0 else 160.0
        return K * n * (f0 * factor * dM ** 3 * 1e-7 + M_load)

    def first_root(f0, nu, dM, M_load, Q):
        # lowest speed at which the friction power reaches Q (the low-regime root where it exists)
        n_switch = 2000.0 / nu
        below = n_switch * (1.0 - 1e-12)
        if power(below, f0, nu, dM, M_load) >= Q:
            return brentq(lambda n: power(n, f0, nu, dM, M_load) - Q, 0.0, below, xtol=1e-9, rtol=1e-13)
        upper = 2.0 * n_switch
        while power(upper, f0, nu, dM, M_load) < Q:
            upper *= 2.0
        return brentq(lambda n: power(n, f0, nu, dM, M_load) - Q, n_switch, upper, xtol=1e-9, rtol=1e-13)

    out = np.empty(len(b["dM"]))
    for i in range(len(out)):
        dM = float(b["dM"][i])
        A_r = float(b["A_r"][i])
        q_r = 0.016 if A_r <= 50000.0 else 0.016 * (A_r / 50000.0) ** -0.34
        M1_ref = float(b["f1_ref"][i]) * 0.05 * float(b["C0"][i]) * dM
        first_root(float(b["f0_ref"][i]), 12.0, dM, M1_ref, q_r * A_r)  # n_thr (f_n * n_thr = n_per)
        out[i] = first_root(float(b["f0"][i]), float(b["nu"][i]), dM, float(b["M_load"][i]), float(b["Q"][i]))
    return out


def main(rows: int = 100_000) -> dict[str, float]:
    bearings = make_bearings(rows)
    vectorised(make_bearings(100))  # warm up imports and tables
    start = time.perf_counter()
    fast = vectorised(bearings)
    t_vector = time.perf_counter() - start
    start = time.perf_counter()
    slow = per_row_brentq(bearings)
    t_loop = time.perf_counter() - start
    deviation = float(np.max(np.abs(fast / slow - 1.0)))
    ratio = t_loop / t_vector
    print(f"bearings: {rows}")
    print(f"vectorised exact roots: {t_vector:.4f} s")
    print(f"per-row scipy brentq:   {t_loop:.3f} s")
    print(f"largest relative difference of n_per: {deviation:.2e}")
    print(f"n_per of {rows:,} bearings, one vectorised call vs a per-row brentq loop: {ratio:.0f}x faster "
          f"({verdict(ratio, TARGET_RATIO, at_most=False)})")
    return {"rows": rows, "vectorised_s": t_vector, "brentq_s": t_loop, "ratio": ratio, "max_rel_diff": deviation}


if __name__ == "__main__":
    main(size_argument(100_000, 100_000))
