"""Benchmark: bh.calc on a Dask DataFrame with one and with two worker processes (issue 16).

The demo's supports tiled to ROWS rows (varied loads and speeds, with the heat-balance columns) in
PARTITIONS partitions, each made on the worker that computes it (``dd.from_map``: no table travels from
the client), computed by ``bh.calc`` on a dask.distributed LocalCluster of one worker process and then of
two (one thread each, set up as ``bearingheat calc --dask`` sets one up: :func:`bearingheat.io.dataset.local_cluster`); the results are reduced on the workers (the sum of NR and the count of rows in
error), as a cluster job that writes its results where it computes them. Prints the rows per second of
each, the scaling ratio (target >= 1.7x on two cores) and the cost of a row against pandas calc in one
process.

    .venv/bin/python benchmarks/bench_dask.py [ROWS | --full]   (default 400 000; --full: the issue's 10^7)
"""
from __future__ import annotations

import time

import pandas as pd

import bearingheat as bh
from common import best_of, demo_rows, size_argument, verdict

SCALING_TARGET = 1.7


def partition(number: int, rows: int) -> pd.DataFrame:
    """Partition ``number`` of the table: ``rows`` demo rows, loads and speeds varied by its own seed."""
    return demo_rows(rows, heat_balance=True, seed=1000 + number)


def main(rows: int = 400_000, partitions: int = 16) -> dict[str, float]:
    import dask.dataframe as dd
    from distributed import Client

    from bearingheat.io.dataset import local_cluster

    sizes = [rows // partitions + (1 if i < rows % partitions else 0) for i in range(partitions)]
    sample = partition(0, sizes[0])
    bh.calc(sample.head(12))  # imports and caches, as the workers' warm-up below
    pandas_time, _ = best_of(lambda: bh.calc(sample), 1)
    rates = {}
    for workers in (1, 2):
        with local_cluster(workers) as cluster, Client(cluster) as client:  # as `calc --dask` sets one up
            client.run(lambda: bh.calc(demo_rows(12, heat_balance=True)))  # every worker imports and warms up
            warm = bh.calc(dd.from_map(partition, range(workers), [12] * workers, meta=sample.iloc[:0]))
            warm["NR [W]"].sum().compute()  # and runs a task graph once
            table = dd.from_map(partition, range(partitions), sizes, meta=sample.iloc[:0])
            results = bh.calc(table)
            start = time.perf_counter()
            power, errors, counted = dd.compute(results["NR [W]"].sum(), (results["status"] == "error").sum(),
                                                results["status"].count())
            elapsed = time.perf_counter() - start
        assert counted == rows and errors == 0 and power > 0
        rates[workers] = rows / elapsed
        print(f"  {workers} worker process{'es' if workers > 1 else ''}: {elapsed:.2f} s, {rates[workers]:,.0f} rows/s "
              f"({1e6 / rates[workers]:.1f} us a row of the cluster's time)")
    ratio = rates[2] / rates[1]
    print(f"bh.calc on a Dask DataFrame, {rows:,} rows in {partitions} partitions: two workers vs one "
          f"{ratio:.2f}x the rows/s ({verdict(ratio, SCALING_TARGET, at_most=False)})")
    print(f"  pandas bh.calc in this process on one partition ({sizes[0]:,} rows): "
          f"{sizes[0] / pandas_time:,.0f} rows/s; one worker reaches {rates[1] / (sizes[0] / pandas_time):.2f}x that")
    return {"rows": rows, "rows_per_s_1": rates[1], "rows_per_s_2": rates[2], "scaling": ratio,
            "pandas_rows_per_s": sizes[0] / pandas_time}


if __name__ == "__main__":
    rows = size_argument(400_000, 10_000_000)
    main(rows, partitions=max(16, rows // 250_000))
