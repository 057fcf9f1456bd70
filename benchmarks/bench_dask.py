"""Benchmark: bh.calc on a Dask DataFrame with one and with two worker processes (issue 16).

The demo's supports tiled to ROWS rows (varied loads and speeds, with the heat-balance columns) in
PARTITIONS partitions, each made on the worker that computes it (``dd.from_map``: no table travels from
the client), computed by ``bh.calc`` on a dask.distributed LocalCluster of one worker process and on one of
two (one thread each, set up as ``bearingheat calc --dask`` sets one up:
:func:`bearingheat.io.dataset.local_cluster`). Each run has a new cluster; the two run in turns three times
and the shortest run of each counts, as in the other benchmarks. The results are reduced on the
workers (the sum of NR and the count of rows in error), as a cluster job that writes its results where it
computes them. Prints the rows per second of each, the scaling ratio (target >= 1.7x on two cores) and the
cost of a row against pandas calc in one process; and, before and after the clusters, the machine's own
ceiling for that ratio: two plain processes computing bh.calc at once against one alone
(:func:`machine_scaling`).

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


def _calc_repeatedly(rows: int, times: int, start, elapsed) -> None:
    """In a process of its own: ``bh.calc`` of one partition ``times`` times once ``start`` (a barrier) lets all
    such processes go, the time taken put on the queue ``elapsed`` (the table is made and calc warmed up before)."""
    table = partition(0, rows)
    bh.calc(table.head(12))
    start.wait()
    begun = time.perf_counter()
    for _ in range(times):
        bh.calc(table)
    elapsed.put(time.perf_counter() - begun)


def machine_scaling(rows: int, times: int = 6) -> float:
    """The machine's own ceiling for the scaling ratio: the rows/s of two plain processes that each compute
    ``bh.calc`` of one partition ``times`` times at once, against one such process alone (no Dask, no
    scheduler, nothing shared). On a machine whose two cores do not each run a process at full speed at once
    (two hyperthreads of one core, a neighbour on the host) it is below 2, and no cluster can do better."""
    import multiprocessing

    context = multiprocessing.get_context("spawn")
    rates = {}
    for processes in (1, 2):
        start, elapsed = context.Barrier(processes + 1), context.Queue()
        workers = [context.Process(target=_calc_repeatedly, args=(rows, times, start, elapsed))
                   for _ in range(processes)]
        for worker in workers:
            worker.start()
        start.wait()  # every process has made its table and imported the package
        longest = max(elapsed.get() for _ in workers)
        for worker in workers:
            worker.join()
        rates[processes] = processes * times * rows / longest
    return rates[2] / rates[1]


def cluster_run(workers: int, table_sizes: list[int], sample: pd.DataFrame) -> float:
    """The wall time [s] of ``bh.calc`` over the partitions of ``table_sizes`` rows on a new local cluster of
    ``workers`` worker processes (set up as ``bearingheat calc --dask`` sets one up), warmed up first, with the
    results reduced on the workers."""
    import dask.dataframe as dd
    from distributed import Client

    from bearingheat.io.dataset import local_cluster

    rows = sum(table_sizes)
    with local_cluster(workers) as cluster, Client(cluster) as client:
        client.run(lambda: bh.calc(demo_rows(12, heat_balance=True)))  # every worker imports and warms up
        warm = bh.calc(dd.from_map(partition, range(workers), [12] * workers, meta=sample.iloc[:0]))
        warm["NR [W]"].sum().compute()  # and runs a task graph once
        table = dd.from_map(partition, range(len(table_sizes)), table_sizes, meta=sample.iloc[:0])
        results = bh.calc(table)
        start = time.perf_counter()
        power, errors, counted = dd.compute(results["NR [W]"].sum(), (results["status"] == "error").sum(),
                                            results["status"].count())
        elapsed = time.perf_counter() - start
    assert counted == rows and errors == 0 and power > 0
    return elapsed


def main(rows: int = 400_000, partitions: int = 16, repeats: int = 1) -> dict[str, float]:
    sizes = [rows // partitions + (1 if i < rows % partitions else 0) for i in range(partitions)]
    sample = partition(0, sizes[0])
    bh.calc(sample.head(12))  # imports and caches, as the workers' warm-up
    pandas_time, _ = best_of(lambda: bh.calc(sample), 1)
    ceilings = [machine_scaling(sizes[0])]  # before the clusters and after them: the machine's load comes and goes
    # one worker and two in turns, the shortest of each counts (as every other benchmark: the machine's speed
    # comes and goes, and both sides of the ratio get the same chances)
    times: dict[int, list[float]] = {1: [], 2: []}
    for _ in range(max(1, repeats)):
        for workers in times:
            times[workers].append(cluster_run(workers, sizes, sample))
    rates = {workers: rows / min(elapsed) for workers, elapsed in times.items()}
    for workers, elapsed in times.items():
        print(f"  {workers} worker process{'es' if workers > 1 else ''}: {min(elapsed):.2f} s "
              f"({', '.join(f'{value:.2f}' for value in elapsed)} s in turns), {rates[workers]:,.0f} rows/s "
              f"({1e6 / rates[workers]:.1f} us a row of the cluster's time)")
    ceilings.append(machine_scaling(sizes[0]))
    ratio = rates[2] / rates[1]
    print(f"bh.calc on a Dask DataFrame, {rows:,} rows in {partitions} partitions: two workers vs one "
          f"{ratio:.2f}x the rows/s, the shortest of {len(times[1])} runs of each "
          f"({verdict(ratio, SCALING_TARGET, at_most=False)})")
    print(f"  the machine's own ceiling, two plain processes computing bh.calc of a partition at once vs one alone "
          f"(no Dask; before and after the clusters): {ceilings[0]:.2f}x and {ceilings[1]:.2f}x; Dask reaches "
          f"{ratio / max(ceilings):.2f}-{ratio / min(ceilings):.2f} of it")
    print(f"  pandas bh.calc in this process on one partition ({sizes[0]:,} rows): "
          f"{sizes[0] / pandas_time:,.0f} rows/s; one worker reaches {rates[1] / (sizes[0] / pandas_time):.2f}x that")
    return {"rows": rows, "rows_per_s_1": rates[1], "rows_per_s_2": rates[2], "scaling": ratio,
            "machine_scaling_before": ceilings[0], "machine_scaling_after": ceilings[1],
            "pandas_rows_per_s": sizes[0] / pandas_time}


if __name__ == "__main__":
    rows = size_argument(400_000, 10_000_000)
    main(rows, partitions=max(16, rows // 250_000), repeats=3)
