"""Benchmark: the whole pipeline against honest baselines (issue 16), each ratio measured in one run.

On the demo's supports (examples/gearbox_shaft.csv) tiled to ROWS rows with varied loads and speeds:

1. the friction kernel :func:`bearingheat.kernels.friction.catalogue_friction_torque` (coefficients
   resolved) against a minimal numpy version of the same formulas written here, and against the
   memory-bandwidth floor (copying its input arrays once);
2. ``bh.calc(df)`` against the kernel on the same rows: the overhead of the table API (designations,
   units, checks, messages), without and with the heat-balance columns (targets 10x and 30x);
3. ``bearingheat calc big.csv -o out.parquet -q`` against a bare ``pd.read_csv(engine='pyarrow')`` +
   ``to_parquet`` of the same file, each in its own process, with its peak memory (targets 5x, < 1 GB).

    .venv/bin/python benchmarks/bench_pipeline.py [ROWS]     (default 200 000; the issue's size is 1 000 000)
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

import bearingheat as bh
from bearingheat.kernels import friction

ROOT = Path(__file__).resolve().parents[1]
DEMO = ROOT / "examples" / "gearbox_shaft.csv"


def best_of(run, repeats: int = 3) -> float:
    """The shortest of ``repeats`` wall-clock times of ``run()`` [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def demo_rows(rows: int, heat_balance: bool, seed: int = 3) -> pd.DataFrame:
    """The demo's single-bearing supports tiled to ``rows`` rows, loads and speeds varied by ±50 %."""
    demo = pd.read_csv(DEMO)
    demo = demo[demo["arrangement"] == "single"]
    table = pd.concat([demo] * (rows // len(demo) + 1), ignore_index=True).iloc[:rows].copy()
    rng = np.random.default_rng(seed)
    for column in ("Fr [kN]", "Fa [kN]", "n [rpm]"):
        table[column] = table[column] * rng.uniform(0.5, 1.5, rows)
    if not heat_balance:
        table = table.drop(columns=["T_amb [degC]", "T_bearing [degC]", "B [mm]", "T [mm]"])
    return table


def numpy_torque(f0, f1, load, dM, nu, n):
    """The catalogue model's M0 + M1 in plain numpy, written here as the baseline."""
    nun = nu * n
    M0 = f0 * np.where(nun >= 2000.0, np.cbrt(nun * nun), 160.0) * dM ** 3 * 1e-7
    return M0 + f1 * load * dM


def _peak_run(code: str) -> tuple[float, float]:
    """(wall time [s], peak resident memory [MB]) of ``python -c code`` in a fresh process: it reports its own
    high-water mark VmHWM [kB] from /proc (ru_maxrss would count the parent's memory at the fork)."""
    report = ("\nprint('PEAK', next(line.split()[1] for line in open('/proc/self/status') "
              "if line.startswith('VmHWM')))")
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", code + report], check=True, capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    peak = next(int(line.split()[1]) for line in done.stdout.splitlines() if line.startswith("PEAK "))
    return elapsed, peak / 1024.0


def main(rows: int = 200_000, repeats: int = 3, cli: bool = True) -> dict[str, float]:
    figures: dict[str, float] = {"rows": rows}
    table = demo_rows(rows, heat_balance=False)
    result = bh.calc(table)
    f0, f1 = result["f0"].to_numpy(), result["f1"].to_numpy()
    load = np.where(result["P1 [N]"].isna(), table["Fr [kN]"].to_numpy() * 1e3, result["P1 [N]"].to_numpy())
    dM = (table["d [mm]"].to_numpy() + table["D [mm]"].to_numpy()) / 2
    nu, n = table["nu [mm^2/s]"].to_numpy(dtype=float), table["n [rpm]"].to_numpy(dtype=float)
    kernel = best_of(lambda: friction.catalogue_friction_torque(f0, f1, load, dM, nu, n), repeats)
    baseline = best_of(lambda: numpy_torque(f0, f1, load, dM, nu, n), repeats)
    floor = best_of(lambda: [a.copy() for a in (f0, f1, load, dM, nu, n)], repeats)
    np.testing.assert_allclose(friction.catalogue_friction_torque(f0, f1, load, dM, nu, n),
                               numpy_torque(f0, f1, load, dM, nu, n), rtol=1e-12)
    figures.update(kernel=kernel, numpy_baseline=baseline, memory_floor=floor)
    print(f"friction kernel on {rows:,} rows: {kernel * 1e3:.1f} ms; minimal numpy {baseline * 1e3:.1f} ms "
          f"({kernel / baseline:.2f}x); memory floor {floor * 1e3:.1f} ms ({kernel / floor:.1f}x)")
    for heat_balance, target in ((False, 10.0), (True, 30.0)):
        rows_table = demo_rows(rows, heat_balance=heat_balance)
        elapsed = best_of(lambda: bh.calc(rows_table), 1)
        ratio = elapsed / kernel
        figures[f"calc_{'heat' if heat_balance else 'friction'}"] = elapsed
        print(f"bh.calc {'with' if heat_balance else 'without'} heat-balance columns: {elapsed:.2f} s = "
              f"{elapsed / rows * 1e6:.1f} us/row, {ratio:.0f}x the kernel (target {target:g}x)")
    if cli:
        with tempfile.TemporaryDirectory() as folder:
            source = Path(folder) / "big.csv"
            demo_rows(rows, heat_balance=True).to_csv(source, index=False)
            bare, bare_peak = _peak_run(f"import pandas as pd; pd.read_csv({str(source)!r}, engine='pyarrow')"
                                        f".to_parquet({str(Path(folder) / 'bare.parquet')!r})")
            full, full_peak = _peak_run(f"from bearingheat.cli import main; main(['calc', {str(source)!r}, '-o', "
                                        f"{str(Path(folder) / 'out.parquet')!r}, '-q'])")
        figures.update(cli=full, cli_bare=bare, cli_peak_mb=full_peak)
        print(f"bearingheat calc big.csv -o out.parquet -q: {full:.2f} s; bare read_csv + to_parquet {bare:.2f} s "
              f"({full / bare:.1f}x, target 5x); peak memory {full_peak:.0f} MB (bare {bare_peak:.0f} MB, "
              "target < 1024 MB at 10^6 rows)")
    return figures


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200_000)
