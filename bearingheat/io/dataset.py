"""A fleet of supports in Parquet files, computed on a Dask cluster: ``bearingheat calc FOLDER --dask -o OUT``.

The input is a folder of Parquet files (every ``*.parquet`` in it) or a glob
pattern (``'fleet/*.parquet'``), each file with the ``name [unit]`` headers
calc reads. Dask reads them on the workers (one partition per file or row
group), :func:`bearingheat.calc.distributed.calc_dask` computes each
partition, and the results are written as a Parquet dataset: a folder with
one part file per input partition, each column's unit as field metadata.
The cluster is a :class:`distributed.LocalCluster` of worker processes (one
thread each) unless a scheduler address names an existing
``dask.distributed`` cluster. Dask is an optional extra
(``pip install 'bearingheat[dask]'``) and is imported only inside the
functions here.
"""
from __future__ import annotations

import contextlib
import glob
import os
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as parquet

from bearingheat.calc.table import calc
from bearingheat.errors import InputError
from bearingheat.io.arrow import unit_of

__all__ = ["dataset_files", "is_dataset", "check_dataset_target", "calc_dataset", "dask_client", "local_cluster",
           "dataset_columns", "read_dataset_columns", "WORKER_MMAP_THRESHOLD"]


def is_dataset(text: str) -> bool:
    """True when an INPUT names a folder or a glob pattern (``*``, ``?``, ``[``) rather than one file (a file
    that exists is a file, whatever its name holds: ``supports [v2].csv``)."""
    path = Path(text)
    return path.is_dir() or (not path.is_file() and any(mark in text for mark in "*?["))


def dataset_files(text: str) -> list[str]:
    """The Parquet files of a folder (every ``*.parquet`` in it) or of a glob pattern, sorted; :class:`InputError`
    when there are none or some matched file is no Parquet file."""
    folder = Path(text)
    found = sorted(str(p) for p in folder.glob("*.parquet")) if folder.is_dir() else sorted(glob.glob(text))
    if not found:
        where = "no *.parquet in the folder" if folder.is_dir() else "the pattern matches nothing"
        raise InputError(f"{text}: no Parquet files ({where})")
    others = [f for f in found if not f.lower().endswith(".parquet") or not os.path.isfile(f)]
    if others:
        raise InputError(f"{others[0]}: --dask reads Parquet files (.parquet) only")
    return found


@contextlib.contextmanager
def dask_client(scheduler: str | None = None, workers: int | None = None):
    """A :class:`distributed.Client` of the cluster at ``scheduler``, or of a new local cluster of ``workers``
    worker processes with one thread each (default: one per CPU core), closed on exit."""
    try:
        from distributed import Client
    except ImportError as exc:
        raise InputError("--dask needs Dask: pip install 'bearingheat[dask]'") from exc
    if scheduler is not None:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise InputError(f"--scheduler {scheduler}: no Dask scheduler answers there ({exc})") from exc
        with client:
            yield client
        return
    with local_cluster(workers) as cluster, Client(cluster) as client:
        yield client


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
    with dask.config.set(environ), LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                                processes=True, dashboard_address=None) as cluster:
        yield cluster


def _schema(meta) -> pa.Schema:
    """The Parquet schema of the results: pandas' types, text for text columns, each field's unit as metadata."""
    fields = []
    for name, dtype in meta.dtypes.items():
        numeric = isinstance(dtype, np.dtype) and dtype.kind in "biufM"
        kind = pa.from_numpy_dtype(dtype) if numeric else pa.string()
        fields.append(pa.field(str(name), kind, metadata={"unit": unit_of(str(name))}))
    return pa.schema(fields)


#: the files of a Parquet dataset Dask writes (its parts and metadata), the only ones --force removes
_DATASET_FILE = re.compile(r"^(part\.\d+\.parquet|_metadata|_common_metadata)$")


def check_dataset_target(target, files: list[str], *, force: bool) -> Path:
    """The folder a dataset of results goes to, checked before any work: not a file name with a table suffix,
    not holding (or above) the input files, empty or (with ``force``) holding only a dataset's own files."""
    target = Path(target)
    if target.suffix.lower() in (".csv", ".parquet", ".arrow", ".feather", ".xlsx", ".xlsm"):
        raise InputError(f"-o {target}: --dask writes a folder of Parquet parts; give a folder name")
    real = target.resolve()
    if any(real == Path(f).resolve().parent or real in Path(f).resolve().parents for f in files):
        raise InputError(f"-o {target} holds the input files; give another folder")
    if target.exists() and not target.is_dir():
        raise InputError(f"-o {target} is a file; give a folder for the Parquet dataset")
    if target.exists() and any(target.iterdir()):
        if not force:
            raise InputError(f"-o {target} exists; give --force to replace it")
        others = sorted(p.name for p in target.iterdir() if not _DATASET_FILE.match(p.name))
        if others:
            raise InputError(f"-o {target} holds {others[0]!r}, which is no part of a Parquet dataset; --force "
                             "replaces only a dataset's own parts: give another folder")
    return target


def clear_dataset(target: Path) -> None:
    """Remove the parts and metadata of an earlier dataset in ``target`` (and nothing else)."""
    for path in target.iterdir():
        if _DATASET_FILE.match(path.name):
            path.unlink()


def calc_dataset(files: list[str], target, *, overwrite: bool = False, **options) -> Path:
    """calc of every row of the Parquet ``files`` on the current Dask client, written as the Parquet dataset
    folder ``target`` (one part per input partition); ``options`` go to calc. Returns the folder."""
    import dask.dataframe as dd

    _check_same_columns(files)
    supports = dd.read_parquet(files)
    results = calc(supports, **options)
    target = check_dataset_target(target, files, force=overwrite)
    # written beside the target first: an earlier dataset is replaced only once every part is written
    staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.bearingheat-", suffix=".tmp", dir=target.parent))
    try:
        results.to_parquet(str(staging), write_index=False, schema=_schema(results._meta))  # noqa: SLF001
        target.mkdir(exist_ok=True)
        clear_dataset(target)
        for part in sorted(staging.iterdir()):
            os.replace(part, target / part.name)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return target


def _check_same_columns(files: list[str]) -> None:
    """Every file of a fleet has the columns of the first (Dask computes each with the first's layout):
    :class:`InputError` naming the first file that differs and how."""
    first = parquet.read_schema(files[0]).names
    for path in files[1:]:
        names = parquet.read_schema(path).names
        if set(names) != set(first):
            lacks = [n for n in first if n not in names]
            extra = [n for n in names if n not in first]
            how = "; ".join(part for part in (f"lacks {', '.join(map(repr, lacks))}" if lacks else "",
                                              f"has {', '.join(map(repr, extra))} besides" if extra else "") if part)
            raise InputError(f"{path}: its columns differ from those of {files[0]} ({how}); every file of a "
                             "fleet needs the same columns")


def dataset_columns(target) -> list[str]:
    """The column names of a Parquet dataset folder (from its first part)."""
    return parquet.read_schema(min(Path(target).glob("*.parquet"))).names


def read_dataset_columns(target, columns: list[str]) -> pa.Table:
    """The named columns of a Parquet dataset folder, as one Arrow table (the parts in their order)."""
    return parquet.read_table(str(target), columns=columns)
