"""Run every benchmark script in this folder: `python -m benchmarks` (or `make bench`).

Each script runs in turn; a script that ends with SystemExit(0) or returns goes on to the next. The runner exits
non-zero only when a script raised an error (a failed benchmark prints its traceback and the others still run).
"""
import runpy
import sys
import traceback
from pathlib import Path

here = Path(__file__).parent
sys.path.insert(0, str(here))
failed = []
for script in sorted(here.glob("bench_*.py")):
    print(f"== {script.name}", flush=True)
    try:
        runpy.run_path(str(script), run_name="__main__")
    except SystemExit as exc:  # a script's own exit code: only a failure counts
        if exc.code not in (None, 0):
            failed.append(script.name)
    except Exception:  # noqa: BLE001 (report it and run the others)
        traceback.print_exc()
        failed.append(script.name)
if failed:
    print(f"failed: {', '.join(failed)}", file=sys.stderr)
    sys.exit(1)
