"""Benchmark: ``diagnose`` on 10^5 measurements, all candidates, grouped 5-fold cross-validation.

Target (issue 5): under 60 s on the 2-core build machine. Run as a script:

    .venv/bin/python benchmarks/bench_diagnose.py [ROWS] [EFFECT]

It prints the time of each stage. The data are synthetic (catalogue model +
one effect + 4 % noise) from ``tests/synthetic_torque.py``; the time to make
them is not counted.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


def main(rows: int = 100_000, effect: str = "preload") -> float:
    from synthetic_torque import grid, measured_set  # noqa: F401  (tests/ on the path)

    from bearingheat.analysis.diagnose import diagnose, model_data, read_measurements

    designations = ["6205", "6208", "7206-B", "30206-A", "NU208-E"]
    per_repeat = len(grid(designations, __import__("numpy").random.default_rng(0)))
    repeats = max(1, -(-rows // per_repeat))
    table, noise, _ = measured_set(effect, seed=11, designations=designations, noise=0.04, repeats=repeats)
    table = table.iloc[:rows]
    start = time.perf_counter()
    measured = read_measurements(table)
    data, kept, excluded = model_data(measured)
    prepared = time.perf_counter()
    result = diagnose(data, k=5)
    done = time.perf_counter()
    summary = result.summary()
    print(f"rows: {len(data)}  candidates: {len(result.scores)}  folds: 5  effect in data: {effect}  "
          f"found: {result.effect}")
    print(f"read + catalogue model: {prepared - start:.2f} s")
    print(f"fit + cross-validate all candidates: {done - prepared:.2f} s")
    print(f"total: {done - start:.2f} s (target < 60 s)")
    print(f"rmse before {summary['rmse_before']:.4g} N*mm, after {summary['rmse_after']:.4g} N*mm, "
          f"noise {noise:.4g} N*mm")
    return done - start


if __name__ == "__main__":
    args = sys.argv[1:]
    main(int(args[0]) if args else 100_000, args[1] if len(args) > 1 else "preload")
