"""Benchmark: bh.calc on a Dask DataFrame with one and with two worker processes (issue 16).

The demo's supports tiled to ROWS rows (varied loads and speeds, with the heat balance) in 16 partitions,
computed on a dask.distributed LocalCluster of one worker process and then of two (one thread each):
rows per second and the scaling ratio (target >= 1.7x on two cores).

    .venv/bin/python benchmarks/bench_dask.py [ROWS]     (default 400 000; the issue's size is 10 000 000)
"""
from __future__ import annotations

import sys
import time

import bearingheat as bh
from bench_pipeline import demo_rows


def main(rows: int = 400_000, partitions: int = 16) -> dict[str, float]:
    import dask.dataframe as dd
    from distributed import Client, LocalCluster

    table = dd.from_pandas(demo_rows(rows, heat_balance=True), npartitions=partitions)
    rates = {}
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster):
            bh.calc(table.partitions[0]).compute()  # the workers import bearingheat once
            start = time.perf_counter()
            done = bh.calc(table).compute()
            elapsed = time.perf_counter() - start
        assert len(done) == rows
        rates[workers] = rows / elapsed
        print(f"{workers} worker{'s' if workers > 1 else ''}: {elapsed:.2f} s, {rates[workers]:,.0f} rows/s")
    print(f"scaling 2 workers / 1 worker: {rates[2] / rates[1]:.2f}x (target >= 1.7x)")
    return {"rows_per_s_1": rates[1], "rows_per_s_2": rates[2]}


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 400_000)
