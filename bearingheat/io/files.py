"""Output files that never lose a designer's data: checked targets, atomic writes, workbook locks.

Every file bearingheat writes goes through this module:

- :func:`safe_output` checks a target before any work is done: it resolves
  symbolic links (the write goes through the link to the real file), and
  refuses (:class:`~bearingheat.errors.OutputFileError`) an output that is an
  input (also through a link or a hard link), an existing file that Excel or
  LibreOffice has open (their lock files; also with ``force``), an existing
  file without ``force``, a read-only file, a file with other hard links, and
  a folder that is missing or not writable.
- :func:`atomic_write` writes to a temporary file beside the target
  (``.<name>.bearingheat-<pid>-<random>.tmp``), flushes it to disk, gives it
  the target's permission bits and renames it over the target, so the target
  is always either the old file or the new complete one; a failure (a full
  disk included) removes the temporary file and names the file and the cause.
- :func:`workbook_lock` guards the read-modify-write of a workbook: it refuses
  a workbook that Excel or LibreOffice has open (their lock files), takes an
  advisory lock so that a second bearingheat run on the same workbook is
  refused, and :meth:`WorkbookLock.check_unchanged` refuses to write when
  another program saved the workbook meanwhile.
- :func:`remove_stale_temps` removes the temporary files of runs that were
  killed (``kill -9``, a power cut); :func:`atomic_write` calls it first.
- :func:`check_outputs` and :func:`write_outputs` do the same for the files a
  report command writes into an ``--out`` folder.

>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> target = safe_output(folder / "results.csv", force=False)
>>> _ = atomic_write(target, lambda temp: temp.write_text("a,b\\n1,2\\n"))
>>> safe_output(folder / "results.csv", force=False)
Traceback (most recent call last):
...
bearingheat.errors.OutputFileError: ...results.csv exists; give --force to replace it
"""
from __future__ import annotations

import contextlib
import errno
import fcntl
import hashlib
import os
import re
import secrets
import stat as stat_module
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path

from bearingheat.errors import OutputFileError, WorkbookChangedError, WorkbookLockedError

__all__ = ["safe_output", "atomic_write", "atomic_write_text", "workbook_lock", "WorkbookLock",
           "remove_stale_temps", "temp_name", "check_outputs", "write_outputs", "file_fingerprint", "run_folder",
           "stale_run_folders",
           "STALE_SECONDS", "EXCEL_SUFFIXES"]

#: the workbook suffixes the Excel bridge reads and writes (here, so that code that only tells a workbook from a
#: table does not import the bridge and openpyxl)
EXCEL_SUFFIXES = (".xlsx", ".xlsm")

#: temporary files of dead processes older than this are removed by :func:`remove_stale_temps`
STALE_SECONDS = 60.0

#: workbooks this process holds (workbook_lock re-enters instead of refusing itself): real path -> depth
_HELD: dict[Path, int] = {}

_TEMP = re.compile(r"^\.(?P<name>.+)\.bearingheat-(?P<pid>\d+)-(?P<token>[0-9a-f]+)\.tmp$")
_RUN_FOLDER = re.compile(r"^\.(?P<name>.+)\.bearingheat-(?P<pid>\d+)-(?P<token>[0-9a-f]+)\.(?P<kind>tmp|old)$")


def _cause(exc: BaseException) -> str:
    """The cause of an OSError in words ('No space left on device'), else the exception's text."""
    if isinstance(exc, OSError):
        if exc.strerror:
            return exc.strerror
        if exc.errno:
            return os.strerror(exc.errno)
    return str(exc) or type(exc).__name__


def _real(path: Path) -> Path:
    """``path`` with every symbolic link resolved (the file a write through it lands in)."""
    try:
        return Path(os.path.realpath(path, strict=False))
    except (OSError, RuntimeError) as exc:  # a link loop
        raise OutputFileError(f"{path}: cannot follow its links ({_cause(exc)})") from exc


def _same_file(a: os.stat_result, b: os.stat_result) -> bool:
    return (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino)


def safe_output(path, *, force: bool, inputs: Iterable = ()) -> Path:
    """The real file to write for the output ``path``, or :class:`OutputFileError` saying why not.

    Symbolic links are resolved: the returned path is the link's target, so
    a write replaces the real file and keeps the link. Refused, with a
    message naming the file and the cause: an output that is one of
    ``inputs`` (compared by device and inode, so links and hard links count),
    an existing file that Excel or LibreOffice has open, also with ``force``
    (:class:`WorkbookLockedError` naming their lock file beside it), an
    existing file without ``force`` (``... exists; give --force to replace
    it``), a read-only file, a file with other hard links (an atomic rename
    would leave them with the old content), a folder, and a folder that is
    missing or not writable.
    """
    given = Path(path)
    real = _real(given)
    try:
        stat = os.stat(real)
    except FileNotFoundError:
        stat = None
    except OSError as exc:
        raise OutputFileError(f"{given}: cannot check it ({_cause(exc)})") from exc
    if stat is not None:
        for source in inputs:
            if source is None:
                continue
            try:
                source_stat = os.stat(source)
            except OSError:
                continue
            if _same_file(stat, source_stat):
                how = "" if Path(source) == given else f" {source}"
                raise OutputFileError(f"{given} is the input file{how}; write the results to another file")
        if stat_module.S_ISDIR(stat.st_mode):
            raise OutputFileError(f"{given} is a folder, not a file")
        if not stat_module.S_ISREG(stat.st_mode):  # /dev/null, a pipe: a rename would replace the device itself
            raise OutputFileError(f"{given} is not a regular file; write to a file")
        _office_locks(given, real)  # (--force too: the program would save its copy over the new file)
        if not force:
            raise OutputFileError(f"{given} exists; give --force to replace it")
        if not stat.st_mode & 0o222 or not os.access(real, os.W_OK):
            raise OutputFileError(f"{given} is read-only; make it writable or write to another file")
        if stat.st_nlink > 1:
            raise OutputFileError(f"{given} has {stat.st_nlink - 1} other hard link(s); replacing it would leave "
                                  "them with the old content; write to another file")
    folder = real.parent
    if not folder.is_dir():
        raise OutputFileError(f"{given}: no such folder {folder}")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise OutputFileError(f"{given}: folder {folder} is not writable (permission denied)")
    return real


def temp_name(target) -> Path:
    """A fresh temporary file name beside ``target``: ``.<name>.bearingheat-<pid>-<random>.tmp``."""
    target = Path(target)
    return target.with_name(f".{target.name}.bearingheat-{os.getpid()}-{secrets.token_hex(4)}.tmp")


def _fsync_file(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_folder(folder: Path) -> None:
    with contextlib.suppress(OSError):  # not every file system can sync a folder
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def atomic_write(target, write: Callable[[Path], object]) -> Path:
    """Write ``target`` atomically: ``write(temp_path)`` fills a temporary file beside it, which is renamed over it.

    Temporary files of earlier killed runs are removed first
    (:func:`remove_stale_temps`). The temporary file is flushed to disk and
    given the target's permission bits before :func:`os.replace`, so the
    target is always the old file or the new complete one; an existing target
    that Excel or LibreOffice has open by then is not replaced
    (:class:`WorkbookLockedError`, the temporary file removed). Symbolic links are
    followed (the real file is replaced, the link kept). On any failure the
    temporary file is removed and the exception re-raised; an :class:`OSError`
    (a full disk, a folder that is not writable) becomes
    :class:`OutputFileError` ``cannot write TARGET: CAUSE``. Returns the file
    written.
    """
    given = Path(target)
    target = _real(given)
    remove_stale_temps(target.parent, target.name)
    temp = temp_name(target)
    try:
        write(temp)
        _fsync_file(temp)
        with contextlib.suppress(FileNotFoundError):
            os.chmod(temp, os.stat(target).st_mode & 0o7777)
        if os.path.lexists(target):  # Excel or LibreOffice opened it during the work: its save would undo ours
            _office_locks(given, target)
        os.replace(temp, target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        if isinstance(exc, OSError):
            raise OutputFileError(f"cannot write {target}: {_cause(exc)}") from exc
        raise
    _fsync_folder(target.parent)
    return target


def atomic_write_text(target, text: str, encoding: str = "utf-8") -> Path:
    """:func:`atomic_write` of a text file."""
    return atomic_write(target, lambda temp: Path(temp).write_text(text, encoding=encoding))


def _alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # a process of another user
        return True
    except (OverflowError, OSError):
        return False
    return True


def remove_stale_temps(folder, name: str, *, older_than: float = STALE_SECONDS) -> list[Path]:
    """Remove the temporary files ``.<name>.bearingheat-<pid>-...tmp`` of killed runs; returns those removed.

    A temporary file is removed when its process is no longer alive and it
    is older than ``older_than`` seconds; a file that cannot be removed is
    left (it is never the target).
    """
    folder = Path(folder)
    removed: list[Path] = []
    try:
        entries = os.listdir(folder)
    except OSError:
        return removed
    now = time.time()
    for entry in entries:
        match = _TEMP.match(entry)
        if not match or match.group("name") != name or _alive(int(match.group("pid"))):
            continue
        path = folder / entry
        try:
            if now - os.lstat(path).st_mtime < older_than:
                continue
            os.unlink(path)
        except OSError:
            continue
        removed.append(path)
    return removed


def run_folder(target, kind: str) -> Path:
    """A new empty folder beside ``target`` that names this run: ``.<name>.bearingheat-<pid>-<random>.<kind>``
    (``tmp``: the new contents of a folder being written; ``old``: its earlier contents set aside while the new
    ones are moved in); its mode is the one a folder made here gets."""
    target = Path(target)
    path = target.with_name(f".{target.name}.bearingheat-{os.getpid()}-{secrets.token_hex(4)}.{kind}")
    path.mkdir()
    return path


def stale_run_folders(target, *, older_than: float = STALE_SECONDS) -> list[tuple[Path, str]]:
    """The folders :func:`run_folder` made beside ``target`` for runs that are no longer alive, older than
    ``older_than`` seconds: (folder, kind), the newest first (then by name). Only bearingheat's own names are
    looked at."""
    target = Path(target)
    found: list[tuple[float, Path, str]] = []
    try:
        entries = os.listdir(target.parent)
    except OSError:
        return []
    now = time.time()
    for entry in entries:
        match = _RUN_FOLDER.match(entry)
        if not match or match.group("name") != target.name or _alive(int(match.group("pid"))):
            continue
        path = target.parent / entry
        try:
            stat = os.lstat(path)
        except OSError:
            continue
        if stat_module.S_ISDIR(stat.st_mode) and now - stat.st_mtime >= older_than:
            found.append((stat.st_mtime, path, match.group("kind")))
    return [(path, kind) for _, path, kind in sorted(found, key=lambda item: (-item[0], item[1].name))]


def file_fingerprint(path) -> tuple[int, int, str]:
    """(size, mtime_ns, sha256 of the bytes) of a file: it changes when any program saves the file."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        stat = os.fstat(handle.fileno())
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return stat.st_size, stat.st_mtime_ns, digest.hexdigest()


def _office_lock(path: Path) -> None:
    """WorkbookLockedError when Excel's or LibreOffice's lock file sits beside ``path``."""
    for lock, program in ((path.with_name("~$" + path.name), "Excel"),
                          (path.with_name(f".~lock.{path.name}#"), "LibreOffice")):
        if os.path.lexists(lock):
            raise WorkbookLockedError(f"{path} is open in {program} (lock file {lock.name}); close it and run again")


def _office_locks(given: Path, real: Path) -> None:
    """:func:`_office_lock` beside the path given and beside the real file a link of it leads to."""
    _office_lock(given)
    if real != given:
        _office_lock(real)


class WorkbookLock:
    """What :func:`workbook_lock` yields: the workbook, its fingerprint on entry, and :meth:`check_unchanged`."""

    def __init__(self, path: Path, given: Path):
        self.path = path
        self.given = given
        self.fingerprint = self._fingerprint()

    def _fingerprint(self) -> tuple[int, int, str]:
        try:
            return file_fingerprint(self.path)
        except FileNotFoundError as exc:
            raise WorkbookChangedError(f"{self.given} changed while bearingheat was working (it is gone); "
                                       "nothing was written; run again") from exc

    def check_unchanged(self) -> None:
        """Raise :class:`WorkbookChangedError` when another program saved the workbook since the lock was taken,
        :class:`WorkbookLockedError` when Excel or LibreOffice opened it meanwhile. Call it just before the rename."""
        _office_lock(self.given)
        if self._fingerprint() != self.fingerprint:
            raise WorkbookChangedError(f"{self.given} changed while bearingheat was working; nothing was written; "
                                       "run again")


@contextlib.contextmanager
def workbook_lock(path) -> Iterator[WorkbookLock]:
    """Hold a workbook for a whole read-modify-write.

    Refused with :class:`WorkbookLockedError` when Excel (``~$<name>``) or
    LibreOffice (``.~lock.<name>#``) has the workbook open, or when another
    bearingheat run holds it (an exclusive, non-blocking ``fcntl.flock`` on
    the sidecar ``.<name>.bearingheat.lock``, removed on exit). Yields a
    :class:`WorkbookLock`; call its ``check_unchanged()`` before replacing
    the file. Symbolic links are followed: the lock is taken on the real file.
    The lock is re-entrant within one process (the command line may hold it
    around :func:`bearingheat.io.excel.workbook.calc_workbook`, which takes it
    again); it excludes other processes, not other threads.
    """
    given = Path(path)
    real = _real(given)
    _office_locks(given, real)
    if real in _HELD:  # this process holds it already (the command line around the Excel bridge): re-enter
        _HELD[real] += 1
        try:
            yield WorkbookLock(real, given)
        finally:
            _HELD[real] -= 1
        return
    sidecar = real.with_name(f".{real.name}.bearingheat.lock")
    while True:
        try:
            fd = os.open(sidecar, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as exc:
            raise OutputFileError(f"cannot lock {given}: cannot create {sidecar.name} ({_cause(exc)})") from exc
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            os.close(fd)
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                raise WorkbookLockedError(f"{given} is being written by another bearingheat run (lock file "
                                          f"{sidecar.name}); wait for it to finish and run again") from exc
            raise OutputFileError(f"cannot lock {given}: {_cause(exc)}") from exc
        try:  # the sidecar may have been removed by the run that held it: lock the file that is there now
            same = _same_file(os.fstat(fd), os.stat(sidecar))
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)
    _HELD[real] = 1
    try:
        yield WorkbookLock(real, given)
    finally:
        del _HELD[real]
        with contextlib.suppress(OSError):
            os.unlink(sidecar)
        os.close(fd)


def check_outputs(folder, names: Iterable[str], *, force: bool, inputs: Iterable = (),
                  create: bool = True) -> dict[str, Path]:
    """Create the folder ``folder`` if needed and check every file ``names`` it will receive.

    Returns {name: real path}. With ``create=False`` (a check before the
    work starts) a missing folder is not created and nothing in it is checked. Existing files without ``force`` are refused
    all at once (``DIR: report.md, summary.json exist; give --force to replace
    them``); every other refusal of :func:`safe_output` applies per file.
    """
    folder = Path(folder)
    if os.path.lexists(folder) and not folder.is_dir():
        raise OutputFileError(f"{folder} is a file, not a folder")
    if not create and not folder.is_dir():
        return {}
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputFileError(f"cannot create the folder {folder}: {_cause(exc)}") from exc
    names = list(dict.fromkeys(names))
    inputs = [i for i in inputs if i is not None]
    if not force:
        existing = [n for n in names if os.path.lexists(folder / n)]
        for name in existing:  # an input in the folder is refused as the input, not as an existing file
            safe_output(folder / name, force=True, inputs=inputs)
        if existing:
            verb = "exists; give --force to replace it" if len(existing) == 1 else \
                "exist; give --force to replace them"
            raise OutputFileError(f"{folder}: {', '.join(existing)} {verb}")
    return {name: safe_output(folder / name, force=True, inputs=inputs) for name in names}


def write_outputs(folder, writers: Mapping[str, Callable[[Path], object]], *, force: bool,
                  inputs: Iterable = ()) -> list[Path]:
    """Write the files of a report into ``folder``: {file name: write(temp_path)}, each atomically.

    Every file is checked (:func:`check_outputs`) before the first is
    written, so a refusal writes nothing. Returns the files written
    (``folder/name``), in the order of ``writers``.
    """
    targets = check_outputs(folder, writers, force=force, inputs=inputs)
    for name, write in writers.items():
        atomic_write(targets[name], write)
    return [Path(folder) / name for name in writers]
