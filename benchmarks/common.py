"""What the benchmarks share: one timing helper, peak memory in a fresh process, the verdict against a target,
the size argument, and the test data (random operating points, the demo's supports tiled).

Not a benchmark itself (``python -m benchmarks`` runs the ``bench_*.py`` scripts only).
"""
from __future__ import annotations

import argparse
import functools
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
DEMO = ROOT / "examples" / "gearbox_shaft.csv"


def best_of(run, repeats: int = 3):
    """(the shortest of ``repeats`` wall-clock times of ``run()`` [s], the value of its last call)."""
    return best_in_turns({"run": run}, repeats)["run"]


def best_in_turns(runs: dict, repeats: int = 5) -> dict:
    """{name: (the shortest wall-clock time [s], the value of its last call)} of each ``runs[name]()``, the runs
    called in turns ``repeats`` times: a shared machine's load comes and goes, and every side of a ratio gets the
    same chances."""
    best: dict = {}
    for _ in range(max(1, repeats)):
        for name, run in runs.items():
            start = time.perf_counter()
            value = run()
            elapsed = time.perf_counter() - start
            best[name] = (min(best[name][0], elapsed) if name in best else elapsed, value)
    return best


def peak_run(code: str) -> tuple[float, float]:
    """(wall time [s], peak resident memory [MB]) of ``python -c code`` in a fresh process: it reports its own
    high-water mark VmHWM from /proc (ru_maxrss of the children would count the parent's memory at the fork).
    The time includes starting Python and importing the package."""
    report = ("\nprint('PEAK', next(line.split()[1] for line in open('/proc/self/status') "
              "if line.startswith('VmHWM')))")
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", code + report], check=True, capture_output=True, text=True,
                          cwd=str(Path(__file__).parent))
    elapsed = time.perf_counter() - start
    peak = next(int(line.split()[1]) for line in done.stdout.splitlines() if line.startswith("PEAK "))
    return elapsed, peak / 1024.0


def verdict(ratio: float, target: float, at_most: bool = True) -> str:
    """'target <= 10x: met' (or '>= 1.7x', 'not met')."""
    met = ratio <= target if at_most else ratio >= target
    return f"target {'<=' if at_most else '>='} {target:g}x: {'met' if met else 'NOT met'}"


def _row_count(text: str) -> int:
    """A size typed on the command line: a whole number of rows, as 200000 or 1e6."""
    try:
        count = float(text)
    except ValueError:
        count = math.nan
    if not (count >= 1 and count.is_integer()):
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of rows (a whole number >= 1, e.g. 200000 or 1e6)")
    return int(count)


def size_argument(default: int, full: int) -> int:
    """The size from the command line: a number, ``--full`` (the issue's size) or nothing (the default, quick on
    2 cores). ``-h`` prints the calling script's docstring and the options."""
    caller = sys._getframe(1).f_globals
    parser = argparse.ArgumentParser(prog=Path(caller.get("__file__") or "benchmark").name,
                                     description=(caller.get("__doc__") or "").strip(),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rows", nargs="?", type=_row_count, help=f"the size to run (default {default:,})")
    parser.add_argument("--full", action="store_true", help=f"the size the targets are set for ({full:,})")
    args = parser.parse_args(sys.argv[1:])
    if args.rows is not None:
        return args.rows
    return full if args.full else default


def operating_points(count: int, seed: int = 1):
    """n in 10..10 000 1/min, ν in 2..300 mm²/s (both ν·n regimes), loads up to 20 kN, Fa up to half of Fr."""
    rng = np.random.default_rng(seed)
    n = rng.uniform(10, 10_000, count)
    nu = np.exp(rng.uniform(math.log(2), math.log(300), count))
    Fr = rng.uniform(100, 20_000, count)
    Fa = Fr * rng.uniform(0, 0.5, count)
    return n, nu, Fr, Fa


@functools.lru_cache(maxsize=1)
def _demo_supports() -> pd.DataFrame:
    """The demo's single-bearing rows, read once per process."""
    demo = pd.read_csv(DEMO)
    return demo[demo["arrangement"] == "single"]


def demo_rows(rows: int, heat_balance: bool, seed: int = 3, oil: bool = False) -> pd.DataFrame:
    """The demo's single-bearing supports (examples/gearbox_shaft.csv) tiled to ``rows`` rows, loads and speeds
    varied by ±50 %; without the heat balance's columns (T_amb, T_bearing, B, T) when ``heat_balance`` is
    false. ``oil``: ν not given but taken from an ISO VG 68 oil's nu40 and nu100 (68 and 8.6 mm²/s) at each
    row's operating temperature."""
    demo = _demo_supports()
    table = demo.iloc[np.resize(np.arange(len(demo)), rows)].reset_index(drop=True)
    rng = np.random.default_rng(seed)
    for column in ("Fr [kN]", "Fa [kN]", "n [rpm]"):
        table[column] = table[column] * rng.uniform(0.5, 1.5, rows)
    if not heat_balance:
        table = table.drop(columns=["T_amb [degC]", "T_bearing [degC]", "B [mm]", "T [mm]"])
    if oil:
        table = table.drop(columns=["nu [mm^2/s]"]).assign(**{"nu40 [mm^2/s]": 68.0, "nu100 [mm^2/s]": 8.6})
    return table
