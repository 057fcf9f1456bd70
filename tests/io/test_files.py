"""Output files (bearingheat.io.files): checked targets, atomic writes, workbook locks, stale temporary files."""
from __future__ import annotations

import errno
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from bearingheat.errors import OutputFileError, WorkbookChangedError, WorkbookLockedError
from bearingheat.io import files
from bearingheat.io.files import (atomic_write, atomic_write_text, check_outputs, remove_stale_temps, safe_output,
                                  temp_name, workbook_lock, write_outputs)


def _chmod_enforced(path: Path, mode: int) -> bool:
    """chmod ``path``; False when the permission is not enforced (running as root)."""
    os.chmod(path, mode)
    return not os.access(path, os.W_OK)


def _temps(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if ".bearingheat-" in p.name)


# ---- safe_output -------------------------------------------------------------------------------------------

def test_new_file_is_accepted_and_resolved(tmp_path):
    assert safe_output(tmp_path / "out.csv", force=False) == (tmp_path / "out.csv").resolve()


def test_existing_file_needs_force(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    with pytest.raises(OutputFileError) as exc:
        safe_output(target, force=False)
    assert str(exc.value) == f"{target} exists; give --force to replace it"
    assert safe_output(target, force=True) == target.resolve()


def test_output_equal_to_the_input_is_refused_also_through_links(tmp_path):
    source = tmp_path / "in.csv"
    source.write_text("a\n1\n")
    link = tmp_path / "link.csv"
    link.symlink_to(source)
    hard = tmp_path / "hard.csv"
    os.link(source, hard)
    with pytest.raises(OutputFileError) as exc:
        safe_output(source, force=True, inputs=(source,))
    assert str(exc.value) == f"{source} is the input file; write the results to another file"
    for alias in (link, hard):
        with pytest.raises(OutputFileError) as exc:
            safe_output(alias, force=True, inputs=(source,))
        assert str(exc.value) == f"{alias} is the input file {source}; write the results to another file"


def test_symlink_target_is_the_real_file(tmp_path):
    real = tmp_path / "real.csv"
    real.write_text("old")
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    assert safe_output(link, force=True) == real.resolve()
    atomic_write_text(safe_output(link, force=True), "new")
    assert link.is_symlink() and real.read_text() == "new"


def test_read_only_target_is_refused_even_for_root(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    os.chmod(target, 0o444)
    with pytest.raises(OutputFileError) as exc:
        safe_output(target, force=True)
    assert str(exc.value) == f"{target} is read-only; make it writable or write to another file"


def test_hard_linked_target_is_refused(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    os.link(target, tmp_path / "other.csv")
    with pytest.raises(OutputFileError) as exc:
        safe_output(target, force=True)
    assert str(exc.value) == (f"{target} has 1 other hard link(s); replacing it would leave them with the old "
                              "content; write to another file")


def test_missing_folder_and_folder_target(tmp_path):
    with pytest.raises(OutputFileError) as exc:
        safe_output(tmp_path / "nope" / "out.csv", force=False)
    assert str(exc.value) == f"{tmp_path / 'nope' / 'out.csv'}: no such folder {tmp_path / 'nope'}"
    with pytest.raises(OutputFileError) as exc:
        safe_output(tmp_path, force=True)
    assert str(exc.value) == f"{tmp_path} is a folder, not a file"
    with pytest.raises(OutputFileError) as exc:
        safe_output("/dev/null", force=True)
    assert str(exc.value) == "/dev/null is not a regular file; write to a file"


def test_folder_not_writable(tmp_path):
    folder = tmp_path / "ro"
    folder.mkdir()
    try:
        if not _chmod_enforced(folder, 0o555):
            pytest.skip("permissions are not enforced (running as root)")
        with pytest.raises(OutputFileError) as exc:
            safe_output(folder / "out.csv", force=False)
        assert str(exc.value) == f"{folder / 'out.csv'}: folder {folder} is not writable (permission denied)"
    finally:
        os.chmod(folder, 0o755)


# ---- atomic_write ------------------------------------------------------------------------------------------

def test_atomic_write_replaces_and_keeps_the_permission_bits(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    os.chmod(target, 0o640)
    assert atomic_write_text(target, "new") == target
    assert target.read_text() == "new"
    assert target.stat().st_mode & 0o777 == 0o640
    assert _temps(tmp_path) == []


def test_temp_name_pattern(tmp_path):
    name = temp_name(tmp_path / "book.xlsx").name
    assert name.startswith(f".book.xlsx.bearingheat-{os.getpid()}-") and name.endswith(".tmp")


def test_failed_write_leaves_the_old_file_and_no_temp(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")

    def broken(temp):
        Path(temp).write_text("half")
        raise ValueError("boom")

    with pytest.raises(ValueError, match="boom"):
        atomic_write(target, broken)
    assert target.read_text() == "old" and _temps(tmp_path) == []


def test_disk_full_is_an_output_file_error_naming_the_file(tmp_path, monkeypatch):
    target = tmp_path / "out.csv"
    target.write_text("old")

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(files.os, "replace", full)
    with pytest.raises(OutputFileError) as exc:
        atomic_write_text(target, "new")
    assert str(exc.value) == f"cannot write {target}: No space left on device"
    assert target.read_text() == "old" and _temps(tmp_path) == []


def test_disk_full_while_writing(tmp_path):
    def full(temp):
        Path(temp).write_bytes(b"x" * 10)
        raise OSError(errno.ENOSPC, "No space left on device", str(temp))

    with pytest.raises(OutputFileError) as exc:
        atomic_write(tmp_path / "out.csv", full)
    assert str(exc.value) == f"cannot write {tmp_path / 'out.csv'}: No space left on device"
    assert list(tmp_path.iterdir()) == []


# ---- stale temporary files ---------------------------------------------------------------------------------

def _dead_pid() -> int:
    done = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    return int(done.stdout)


def test_stale_temps_of_dead_runs_are_removed(tmp_path):
    dead = _dead_pid()
    old = tmp_path / f".out.csv.bearingheat-{dead}-0a1b2c3d.tmp"
    young = tmp_path / f".out.csv.bearingheat-{dead}-0a1b2c3e.tmp"
    alive = tmp_path / f".out.csv.bearingheat-{os.getpid()}-0a1b2c3f.tmp"
    other = tmp_path / f".other.csv.bearingheat-{dead}-0a1b2c40.tmp"
    for path in (old, young, alive, other):
        path.write_text("x")
    long_ago = time.time() - 3600
    for path in (old, alive, other):
        os.utime(path, (long_ago, long_ago))
    assert remove_stale_temps(tmp_path, "out.csv") == [old]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in (young, alive, other))
    atomic_write_text(tmp_path / "other.csv", "new")  # every write cleans its own name first
    assert not other.exists()


# ---- workbook_lock -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("lock, program", [("~$book.xlsx", "Excel"), (".~lock.book.xlsx#", "LibreOffice")])
def test_office_lock_files_refuse(tmp_path, lock, program):
    book = tmp_path / "book.xlsx"
    book.write_bytes(b"PK")
    (tmp_path / lock).write_text("someone")
    with pytest.raises(WorkbookLockedError) as exc:
        with workbook_lock(book):
            pass
    assert str(exc.value) == f"{book} is open in {program} (lock file {lock}); close it and run again"


@pytest.mark.parametrize("lock, program", [("~$out.xlsx", "Excel"), (".~lock.out.xlsx#", "LibreOffice")])
def test_an_output_open_in_another_program_is_refused_also_with_force(tmp_path, lock, program):
    out = tmp_path / "out.xlsx"
    out.write_bytes(b"PK designer")
    link = tmp_path / "link.xlsx"
    link.symlink_to(out)
    (tmp_path / lock).write_text("someone")
    for target in (out, link):  # through a link: the lock file beside the real file
        for force in (False, True):
            with pytest.raises(WorkbookLockedError) as exc:
                safe_output(target, force=force)
            assert str(exc.value) == f"{out} is open in {program} (lock file {lock}); close it and run again"
    assert safe_output(tmp_path / "new.xlsx", force=False) == tmp_path / "new.xlsx"  # nothing there to replace


def test_atomic_write_does_not_replace_a_file_opened_meanwhile(tmp_path):
    """The lock file appears while the new file is written (LibreOffice opened the target): the target stays."""
    out = tmp_path / "out.xlsx"
    out.write_bytes(b"PK old")

    def write(temp):
        Path(temp).write_bytes(b"PK new")
        (tmp_path / ".~lock.out.xlsx#").write_text("someone")

    with pytest.raises(WorkbookLockedError) as exc:
        atomic_write(out, write)
    assert str(exc.value) == f"{out} is open in LibreOffice (lock file .~lock.out.xlsx#); close it and run again"
    assert out.read_bytes() == b"PK old"
    assert sorted(p.name for p in tmp_path.iterdir()) == [".~lock.out.xlsx#", "out.xlsx"]


_HOLD = """
import sys, time
from bearingheat.io.files import workbook_lock
with workbook_lock(sys.argv[1]):
    print("held", flush=True)
    time.sleep(float(sys.argv[2]))
"""


def test_a_second_process_is_refused_and_the_lock_is_released(tmp_path):
    book = tmp_path / "book.xlsx"
    book.write_bytes(b"PK")
    holder = subprocess.Popen([sys.executable, "-c", _HOLD, str(book), "30"], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        with pytest.raises(WorkbookLockedError) as exc:
            with workbook_lock(book):
                pass
        assert str(exc.value) == (f"{book} is being written by another bearingheat run (lock file "
                                  ".book.xlsx.bearingheat.lock); wait for it to finish and run again")
    finally:
        holder.kill()
        holder.wait()
    with workbook_lock(book) as held:  # the kernel released the lock of the killed process
        assert held.path == book.resolve()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["book.xlsx"]


def test_lock_is_reentrant_in_one_process_and_follows_links(tmp_path):
    book = tmp_path / "book.xlsx"
    book.write_bytes(b"PK")
    link = tmp_path / "link.xlsx"
    link.symlink_to(book)
    with workbook_lock(link) as outer:
        with workbook_lock(book) as inner:
            assert inner.path == outer.path == book.resolve()
        assert (tmp_path / ".book.xlsx.bearingheat.lock").exists()
    assert not (tmp_path / ".book.xlsx.bearingheat.lock").exists()


def test_check_unchanged_sees_a_save_by_another_program(tmp_path):
    book = tmp_path / "book.xlsx"
    book.write_bytes(b"PK one")
    with workbook_lock(book) as held:
        held.check_unchanged()
        book.write_bytes(b"PK two")
        with pytest.raises(WorkbookChangedError) as exc:
            held.check_unchanged()
    assert str(exc.value) == f"{book} changed while bearingheat was working; nothing was written; run again"


def test_check_unchanged_sees_excel_opening_the_file(tmp_path):
    book = tmp_path / "book.xlsx"
    book.write_bytes(b"PK")
    with workbook_lock(book) as held:
        (tmp_path / "~$book.xlsx").write_text("x")
        with pytest.raises(WorkbookLockedError):
            held.check_unchanged()


# ---- report folders ----------------------------------------------------------------------------------------

def test_report_files_are_refused_all_at_once_and_nothing_is_written(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "report.md").write_text("mine")
    (out / "summary.json").write_text("{}")
    writers = {name: (lambda p: Path(p).write_text("new")) for name in ("a.png", "report.md", "summary.json")}
    with pytest.raises(OutputFileError) as exc:
        write_outputs(out, writers, force=False)
    assert str(exc.value) == f"{out}: report.md, summary.json exist; give --force to replace them"
    assert sorted(p.name for p in out.iterdir()) == ["report.md", "summary.json"]
    assert write_outputs(out, writers, force=True) == [out / "a.png", out / "report.md", out / "summary.json"]
    assert (out / "report.md").read_text() == "new"


def test_report_folder_that_is_a_file_or_holds_the_input(tmp_path):
    (tmp_path / "x.csv").write_text("")
    with pytest.raises(OutputFileError) as exc:
        check_outputs(tmp_path / "x.csv", ["a"], force=False)
    assert str(exc.value) == f"{tmp_path / 'x.csv'} is a file, not a folder"
    source = tmp_path / "report.md"
    source.write_text("input")
    with pytest.raises(OutputFileError) as exc:
        check_outputs(tmp_path, ["report.md"], force=False, inputs=(source,))
    assert str(exc.value) == f"{source} is the input file; write the results to another file"
    assert check_outputs(tmp_path / "new", ["a"], force=False, create=False) == {}
    assert not (tmp_path / "new").exists()
