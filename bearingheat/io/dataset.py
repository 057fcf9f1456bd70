"""A fleet of supports in Parquet files, computed on a Dask cluster: ``bearingheat calc FOLDER --dask -o OUT``.

The input is a folder of Parquet files (every ``*.parquet`` in it) or a glob
pattern (``'fleet/*.parquet'``), each file with the ``name [unit]`` headers
calc reads (:mod:`bearingheat.io.fleet` checks them). Each file is one piece of
work (a big one a run of its row groups per piece), read and computed on a
worker as the single-file path computes a file (:func:`bearingheat.io.pipeline.calc_block`,
a block of rows at a time), and written as one part of a Parquet dataset: a
folder with one part file per piece. Every part has the same columns, those of
the Dask path (:func:`bearingheat.calc.distributed.result_layout`: every
result column of the contract), in the same types: the input columns as the
files hold them, the results as the single-file path writes them, each
column's unit as field metadata. A fleet with a duty cycle (a ``support``
column) also gets its summary per support, ``<folder>.duty.parquet`` beside
the folder, as the single-file path writes ``OUT.duty.parquet``. The cluster is a
:class:`distributed.LocalCluster` of worker processes (one thread each) unless
a scheduler address names an existing ``dask.distributed`` cluster. Dask is an
optional extra (``pip install 'bearingheat[dask]'``) and is imported only
inside the functions here.
"""
from __future__ import annotations

import contextlib
import logging
import os
import re
import shutil
import warnings
from dataclasses import dataclass
from pathlib import Path

import pandas as pd
import pyarrow as pa
import pyarrow.parquet as parquet

from bearingheat.calc.contract import parse_header
from bearingheat.calc.distributed import result_layout
from bearingheat.calc.duty import duty_cycle, has_duty_cycle, support_headers
from bearingheat.errors import BearingheatError, InputError, OutputFileError
from bearingheat.io.arrow import parquet_writer, write_arrow
from bearingheat.io.files import run_folder, safe_output, stale_run_folders
from bearingheat.io.fleet import dataset_files, fleet_pieces, fleet_schema, is_dataset, read_piece
from bearingheat.io.pipeline import ROWS_PER_BLOCK, calc_block, load_options

__all__ = ["check_dataset_target", "check_scheduler", "recover_target", "calc_dataset", "plan_dataset",
           "compute_dataset", "DatasetPlan", "DatasetRun", "dask_client", "local_cluster", "dataset_columns",
           "read_dataset_columns", "part_name", "WORKER_MMAP_THRESHOLD", "quiet_worker_shutdown",
           "dataset_files", "is_dataset"]  # (the last two from io.fleet, where they moved, for callers of this module)


@contextlib.contextmanager
def dask_client(scheduler: str | None = None, workers: int | None = None):
    """A :class:`distributed.Client` of the cluster at ``scheduler``, or of a new local cluster of ``workers``
    worker processes with one thread each (default: one per CPU core), closed on exit. An address that is none
    is refused by :func:`check_scheduler` (which a caller may run before any other work, as the command does)."""
    try:
        from distributed import Client
    except ImportError as exc:
        raise InputError("--dask needs Dask: pip install 'bearingheat[dask]'") from exc
    if scheduler is not None:
        try:
            client = Client(scheduler, timeout="10s")
        except ValueError:  # no address ('missing port number ...'): named as check_scheduler names it
            check_scheduler(scheduler)
            raise
        except (OSError, TimeoutError) as exc:
            raise InputError(f"--scheduler {scheduler}: no Dask scheduler answers there ({exc})") from exc
        with client:
            yield client
        return
    with local_cluster(workers) as cluster, Client(cluster) as client:
        try:
            yield client
        finally:
            with contextlib.suppress(Exception):  # (a worker already gone has nothing to say)
                client.run(quiet_worker_shutdown)


def quiet_worker_shutdown() -> None:
    """Run on each worker of a local cluster before it closes: its own log records below CRITICAL are dropped
    from then on. When the cluster closes, a worker's heartbeat can still meet the scheduler that has closed (a
    race of Dask's own, https://github.com/dask/distributed/issues/7891), and the worker logs that as an ERROR
    with a traceback on the terminal's stderr, after the command's own last line; the results are written by
    then, nothing was lost."""
    logging.getLogger("distributed.worker").setLevel(logging.CRITICAL)


def check_scheduler(address: str) -> None:
    """:class:`InputError` naming ``address`` when it is no address of a Dask scheduler (``tcp://HOST:PORT``)."""
    try:
        from distributed.comm import get_address_host_port
    except ImportError as exc:
        raise InputError("--dask needs Dask: pip install 'bearingheat[dask]'") from exc
    try:
        get_address_host_port(address)
    except ValueError as exc:
        raise InputError(f"--scheduler {address}: not the address of a Dask scheduler ({exc}); give it as "
                         "tcp://HOST:PORT, such as tcp://scheduler:8786") from exc


#: glibc's mmap threshold of the workers. dask.distributed starts its workers with MALLOC_TRIM_THRESHOLD_=65536,
#: which also switches off glibc's growing mmap threshold: every array above 128 kB is then mapped and unmapped
#: again, and calc ran half as fast in a worker (measured: 0.47 s against 0.24 s for 25 000 rows). Arrays up to
#: 16 MiB come from the heap again with this (0.25 s); dask's trimming of freed memory stays.
WORKER_MMAP_THRESHOLD = 16 * 2**20


@contextlib.contextmanager
def local_cluster(workers: int | None = None):
    """A :class:`distributed.LocalCluster` of ``workers`` worker processes (default one per CPU core), one thread
    each, with the workers' allocator set for calc (:data:`WORKER_MMAP_THRESHOLD`); closed on exit."""
    import dask
    from distributed import LocalCluster

    environ = {"distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": WORKER_MMAP_THRESHOLD}
    with dask.config.set(environ):
        with warnings.catch_warnings():  # the scheduler's HTTP port taken by another cluster: it takes a free one
            warnings.filterwarnings("ignore", message="Port .* is already in use", category=UserWarning)
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
        with cluster:
            yield cluster


#: the files of a Parquet dataset (its parts, and the metadata files Dask writes): a folder holding only these is
#: an earlier dataset, which --force replaces
_DATASET_FILE = re.compile(r"^(part\.\d+\.parquet|_metadata|_common_metadata)$")


def part_name(position: int, count: int) -> str:
    """The file name of the part at ``position`` of ``count``: ``part.<position>.parquet``, the number padded with
    zeros to the width of the last one (part.07 before part.10), so that the parts' order by name, in which
    readers take them, is the order of the rows."""
    return f"part.{position:0{len(str(max(count - 1, 0)))}d}.parquet"


def check_dataset_target(target, files: list[str], *, force: bool) -> Path:
    """The folder a dataset of results goes to, checked before any work: not a file name with a table suffix,
    not holding (or above) the input files, in a folder that exists, empty or (with ``force``) holding only a
    dataset's own files."""
    target = Path(target)
    if target.suffix.lower() in (".csv", ".parquet", ".arrow", ".feather", ".xlsx", ".xlsm"):
        raise InputError(f"-o {target}: --dask writes a folder of Parquet parts; give a folder name")
    real = target.resolve()
    if any(real == Path(f).resolve().parent or real in Path(f).resolve().parents for f in files):
        raise InputError(f"-o {target} holds the input files; give another folder")
    if target.exists() and not target.is_dir():
        raise InputError(f"-o {target} is a file; give a folder for the Parquet dataset")
    if not target.parent.is_dir():
        raise InputError(f"-o {target}: the folder {target.parent} does not exist; create it or give another folder")
    if target.exists() and any(target.iterdir()):
        if not force:
            raise InputError(f"-o {target} exists; give --force to replace it")
        others = sorted(p.name for p in target.iterdir() if not _DATASET_FILE.match(p.name))
        if others:
            raise InputError(f"-o {target} holds {others[0]!r}, which is no part of a Parquet dataset; --force "
                             "replaces only a dataset's own parts: give another folder")
    return target


def recover_target(target) -> list[str]:
    """Put right what a bearingheat run on the dataset folder ``target`` left when it was stopped (killed, a power
    cut) and returns a note for each: a hidden folder of new parts is removed; an earlier dataset it had set aside
    while moving the new one in is moved back where the target is missing, else (the new one was in place)
    removed. Only folders bearingheat names for this target (:func:`bearingheat.io.files.run_folder`) of runs
    that are no longer alive are touched."""
    real = Path(os.path.realpath(target))
    notes = []
    for folder, kind in stale_run_folders(real):
        if kind == "old" and not os.path.lexists(real):
            os.rename(folder, real)
            notes.append(f"moved {folder.name} back to {target}: the earlier dataset, set aside by a bearingheat "
                         "run that was stopped before its new one was in place")
            continue
        shutil.rmtree(folder, ignore_errors=True)
        what = "the new parts of" if kind == "tmp" else "the earlier dataset of"
        notes.append(f"removed {folder.name}, {what} {target} left by a bearingheat run that was stopped")
    return notes


def _publish(staging: Path, target: Path) -> None:
    """Put the folder ``staging`` in the place of the folder ``target`` (its real path) by renames, so that the
    target is at every moment the earlier dataset or the new one: the earlier folder is renamed aside, the new
    one into its place (on failure the earlier one back), then the earlier one is removed. The new folder gets
    the earlier one's permission bits. :class:`OutputFileError` when a rename fails, saying where the earlier
    dataset is."""
    def failed(exc: OSError, where: str) -> OutputFileError:
        return OutputFileError(f"cannot write {target}: {exc.strerror or exc}; {where}")

    if not os.path.lexists(target):
        try:
            os.rename(staging, target)
        except OSError as exc:
            raise failed(exc, "nothing was written") from exc
        return
    aside = None
    try:
        os.chmod(staging, os.stat(target).st_mode & 0o7777)
        aside = run_folder(target, "old")
        os.rename(target, aside)  # (a folder renamed onto the empty folder just made)
    except OSError as exc:
        if aside is not None:
            with contextlib.suppress(OSError):
                os.rmdir(aside)
        raise failed(exc, "the earlier dataset is as it was") from exc
    try:
        os.rename(staging, target)
    except OSError as exc:
        try:
            os.rename(aside, target)
        except OSError:
            raise failed(exc, f"the earlier dataset is in {aside}") from exc
        raise failed(exc, "the earlier dataset is as it was") from exc
    shutil.rmtree(aside, ignore_errors=True)


def _results_schema(source: pa.Table, options: dict, layout: dict) -> pa.Schema:
    """The Arrow schema of every part: what :func:`calc_block` makes of a piece without rows (the input's own
    types, the layout's for the results), each field's unit as metadata."""
    return calc_block(source.to_pandas(), source, options, layout=layout).schema


def _calc_piece(path: str, groups: list[int], columns: pa.Schema, part: str, schema: pa.Schema, layout: dict,
                options: dict) -> int:
    """calc of one piece of a Parquet file, a block of :data:`ROWS_PER_BLOCK` rows at a time as the single-file
    path computes (:func:`bearingheat.io.pipeline.calc_block`), its input ``columns`` those of the fleet
    (:func:`bearingheat.io.fleet.fleet_schema`), written to the part file ``part`` in ``schema``; returns the
    rows written."""
    table = read_piece(path, groups, columns)
    with parquet_writer(part, schema) as writer:
        for start in range(0, max(table.num_rows, 1), ROWS_PER_BLOCK):
            source = table.slice(start, ROWS_PER_BLOCK)
            writer.write_table(calc_block(source.to_pandas(), source, options, layout=layout).cast(schema))
    return table.num_rows


def _calc_piece_task(*arguments) -> int | BearingheatError:
    """:func:`_calc_piece` as a task: the error of unusable input (a :class:`BearingheatError`: a unit of the
    wrong kind, a missing column ...) is its result, to be raised on the client, rather than an exception the
    worker would log at length ('Compute Failed', the task, its traceback) before the one-line message."""
    try:
        return _calc_piece(*arguments)
    except BearingheatError as exc:
        return exc


def _run(tasks: list) -> None:
    """Compute ``tasks`` on the current Dask scheduler, then raise the error the first of them returned (in the
    order of the pieces, so the same fleet gives the same message). Every task runs to its end rather than being
    cancelled at the first error: an input error stops a piece as its calc starts (calc checks the columns and
    units first), and a cluster closed under running tasks logs its own tracebacks."""
    import dask

    for result in dask.compute(*tasks):
        if isinstance(result, BearingheatError):
            raise result


@dataclass(frozen=True)
class DatasetPlan:
    """A fleet's computation as :func:`plan_dataset` checked it: the files and their pieces, the target folder,
    the fleet's input columns (:func:`bearingheat.io.fleet.fleet_schema`), calc's options with their files read,
    the layout of the results, the schema of every part, and the file of the duty-cycle summary (a fleet with a
    ``support`` column: ``<folder>.duty.parquet`` beside the folder) or None."""

    files: list[str]
    target: Path
    overwrite: bool
    columns: pa.Schema
    options: dict
    layout: dict
    schema: pa.Schema
    pieces: list[tuple[str, list[int]]]
    duty: Path | None = None


@dataclass(frozen=True)
class DatasetRun:
    """What :func:`compute_dataset` wrote: the dataset folder and the duty-cycle summary (None without one)."""

    target: Path
    duty: pd.DataFrame | None = None


def plan_dataset(files: list[str], target, *, overwrite: bool = False, **options) -> DatasetPlan:
    """Everything a fleet's computation checks before any work, on the client and without a cluster: the target
    folder (:func:`check_dataset_target`; run :func:`recover_target` on it first), the files' columns and types
    (:func:`bearingheat.io.fleet.fleet_schema`), calc's options with the charts they name read once
    (:func:`bearingheat.io.pipeline.load_options`), and the schema of the parts; where the files hold a duty
    cycle (a ``support`` column), the summary's file beside the folder, checked as any output file
    (:func:`bearingheat.io.files.safe_output`). :class:`InputError` (or the chart's own error) says what is
    wrong."""
    target = check_dataset_target(target, files, force=overwrite)
    columns = fleet_schema(files)
    options = load_options(options)  # the charts read here, once: a worker need not see the client's files
    layout = result_layout(columns.names)
    schema = _results_schema(columns.empty_table(), options, layout)
    pieces = [piece for path in files for piece in fleet_pieces(path)]
    duty = None
    if support_headers(columns.names):  # (a support column blank in every part: no summary, see _duty_summary)
        duty = safe_output(target.with_name(f"{target.name}.duty.parquet"), force=overwrite, inputs=files)
    return DatasetPlan(files, target, overwrite, columns, options, layout, schema, pieces, duty)


#: the results a duty-cycle summary reads (:func:`bearingheat.calc.duty.duty_cycle`)
_DUTY_NAMES = frozenset({"support", "case", "time_share", "duration", "designation", "n", "MR", "NR", "T_op", "n_per",
                         "status", "message"})


def _duty_summary(plan: DatasetPlan, parts: Path) -> pd.DataFrame | None:
    """The duty-cycle summary of the parts in the folder ``parts`` (None for a fleet without rows, or whose support
    column is blank in every row): the columns it reads, without the results the layout adds where pandas calc
    writes none (a column missing in every row), so that it is the summary of the same rows in one file."""
    wanted = [name for name in plan.schema.names if parse_header(name, strict=False)[0] in _DUTY_NAMES]
    table = parquet.read_table(parts, columns=wanted)
    if table.num_rows == 0:
        return None
    kept = [name for name in wanted if name in plan.columns.names or name not in plan.layout
            or table.column(name).null_count < table.num_rows]
    results = table.select(kept).to_pandas()
    return duty_cycle(results) if has_duty_cycle(results) else None  # (a support column all blank: no duty cycle)


def compute_dataset(plan: DatasetPlan) -> DatasetRun:
    """The computation :func:`plan_dataset` planned, on the current Dask scheduler: each piece becomes one part
    file, written into a hidden folder beside the target first; the duty-cycle summary (where the plan has one)
    is computed from those parts; an earlier dataset in the target is replaced once every part is written and
    the summary is made, and the summary is written after it (a fleet without rows has none: an earlier one is
    removed). A summary that cannot be made (shares that do not sum to 1 ...) or a swap that fails leaves the
    earlier dataset and its summary as they were."""
    import dask

    target = plan.target
    real = Path(os.path.realpath(target))  # a link to the folder stays a link, to the new folder
    staging = run_folder(real, "tmp")
    try:
        shared = dask.delayed(plan.options, traverse=False)  # one key: sent to each worker once, not in every task
        tasks = [dask.delayed(_calc_piece_task, pure=False)(path, groups, plan.columns,
                                                           str(staging / part_name(i, len(plan.pieces))),
                                                           plan.schema, plan.layout, shared)
                 for i, (path, groups) in enumerate(plan.pieces)]
        _run(tasks)
        duty = _duty_summary(plan, staging) if plan.duty is not None else None
        _publish(staging, real)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    # the summary follows the dataset it sums up, once that is in place (a failed swap leaves both as they were);
    # a fleet without rows has none, and an earlier one beside the new dataset would sum up rows it no longer has
    if plan.duty is not None:
        if duty is not None:
            write_arrow(duty, plan.duty)
        else:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(plan.duty)
    return DatasetRun(target, duty)


def calc_dataset(files: list[str], target, *, overwrite: bool = False, **options) -> Path:
    """calc of every row of the Parquet ``files`` on the current Dask scheduler, written as the Parquet dataset
    folder ``target``; ``options`` go to calc. Returns the folder (:func:`recover_target`, :func:`plan_dataset`,
    then :func:`compute_dataset`).

    Each file is computed in pieces of its row groups (one piece per file up to
    :data:`bearingheat.io.fleet.PIECE_BYTES`), a block of rows at a time as the single-file path computes it, and
    each piece becomes one part file: every column of the Dask path's layout
    (:func:`bearingheat.calc.distributed.result_layout`), the input columns in the types the files hold them, the
    results in the types the single-file path writes. A fleet with a duty cycle (a ``support`` column) also gets
    its summary per support beside the folder, ``<folder>.duty.parquet``, as ``calc FILE -o OUT.parquet`` writes
    ``OUT.duty.parquet``.
    """
    recover_target(target)
    return compute_dataset(plan_dataset(files, target, overwrite=overwrite, **options)).target


def dataset_columns(target) -> list[str]:
    """The column names of a Parquet dataset folder (from its first part)."""
    return parquet.read_schema(min(Path(target).glob("*.parquet"))).names


def read_dataset_columns(target, columns: list[str]) -> pa.Table:
    """The named columns of a Parquet dataset folder, as one Arrow table (the parts in their order)."""
    return parquet.read_table(str(target), columns=columns)
