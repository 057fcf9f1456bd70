"""Excel bridge at scale: 10 000 supports read, computed and written (target: under 10 s).

Run as a script: ``.venv/bin/python benchmarks/bench_excel.py [N_ROWS]``. It
builds a workbook of N_ROWS supports (the gearbox example cycled), then times
``calc_workbook`` (read the sheet, run calc, write the results sheet) with
values and with live formulas, and prints one line per stage.
"""
from __future__ import annotations

import tempfile
import time
from pathlib import Path

import openpyxl
import pandas as pd

from bearingheat.calc.table import calc
from bearingheat.io.excel import calc_workbook, read_supports
from common import size_argument

ROOT = Path(__file__).resolve().parents[1]
TARGET_SECONDS = 10.0


def build(path: Path, n_rows: int) -> Path:
    table = pd.read_csv(ROOT / "examples" / "gearbox_shaft.csv")
    names, units = [], []
    for header in table.columns:
        name, _, unit = header.partition(" [")
        names.append(name)
        units.append(unit.rstrip("]") or "-")
    records = [[None if pd.isna(v) else (v.item() if hasattr(v, "item") else v) for v in row]
               for row in table.itertuples(index=False)]
    workbook = openpyxl.Workbook(write_only=True)
    ws = workbook.create_sheet("Supports")
    ws.append(names)
    ws.append(units)
    for i in range(n_rows):
        row = list(records[i % len(records)])
        row[0] = f"support {i + 1}"
        ws.append(row)
    workbook.save(path)
    return path


def main(n_rows: int = 10_000) -> dict[str, float]:

    with tempfile.TemporaryDirectory() as folder:
        source = build(Path(folder) / "supports.xlsx", n_rows)
        start = time.perf_counter()
        table, info = read_supports(source)
        read = time.perf_counter() - start
        start = time.perf_counter()
        calc(table, units=info.units, cell=info.cell)
        compute = time.perf_counter() - start
        timings = {}
        for formulas in (False, True):
            start = time.perf_counter()
            run = calc_workbook(source, Path(folder) / f"out_{formulas}.xlsx", formulas=formulas)
            timings[formulas] = time.perf_counter() - start
        assert len(run.result) == n_rows
    print(f"{n_rows} supports: read {read:.2f} s, calc {compute:.2f} s")
    print(f"{n_rows} supports: read + calc + write results (values)   {timings[False]:.2f} s "
          f"(target < {TARGET_SECONDS:.0f} s)")
    print(f"{n_rows} supports: read + calc + write results (--formulas) {timings[True]:.2f} s "
          f"({'within' if max(timings.values()) < TARGET_SECONDS else 'above'} the target)")
    return {"read": read, "calc": compute, "values": timings[False], "formulas": timings[True]}


if __name__ == "__main__":
    main(size_argument(10_000, 10_000))
