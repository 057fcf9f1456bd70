"""Faults at the command line: one line naming the file and the cause, exit 2, never a traceback.

Exit 1 stays "some row has an error"; everything that stops a command (a file
that cannot be read or written, a full disk, a damaged workbook, a header-only
CSV) is exit 2 with one line on stderr.
"""
from __future__ import annotations

import errno
import os
import shutil
import subprocess
import sys
import zipfile
import zlib
from pathlib import Path

import pytest
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX, make_workbook

from bearingheat.io.excel import workbook as excel_workbook
from bearingheat.cli import main
from bearingheat.io import files

LAB = Path(__file__).resolve().parents[2] / "examples" / "lab_dp11a_example.csv"


def _error(capsys, command: str = "calc") -> str:
    """The one error line of a run (asserting there is exactly one and no traceback)."""
    captured = capsys.readouterr()
    assert "Traceback" not in captured.err
    assert captured.err.count("\n") == 1, captured.err
    prefix = f"bearingheat {command}: error: "
    assert captured.err.startswith(prefix), captured.err
    return captured.err[len(prefix):-1]


def _enforced(path: Path, mode: int) -> bool:
    os.chmod(path, mode)
    return not os.access(path, os.W_OK if mode & 0o444 else os.R_OK)


def _truncated(tmp_path) -> Path:
    raw = EXAMPLE_XLSX.read_bytes()
    path = tmp_path / "truncated.xlsx"
    path.write_bytes(raw[: len(raw) // 2])
    return path


def _garbage_sheet(tmp_path) -> Path:
    path = tmp_path / "garbage.xlsx"
    with zipfile.ZipFile(make_workbook(tmp_path / "good.xlsx")) as zin, zipfile.ZipFile(path, "w") as zout:
        for item in zin.infolist():
            data = zin.read(item.filename)
            if item.filename == "xl/worksheets/sheet1.xml":
                data = data[:100] + b"<<<garbage&&&" + data[100:]
            zout.writestr(item, data)
    return path


# ---- files that cannot be read -----------------------------------------------------------------------------

def test_missing_input(tmp_path, capsys):
    missing = tmp_path / "missing.csv"
    assert main(["calc", str(missing)]) == 2
    assert _error(capsys) == f"{missing}: no such file"
    assert main(["lab", str(missing), "--out", str(tmp_path / "o")]) == 2
    assert _error(capsys, "lab") == f"{missing}: no such file"
    assert main(["coastdown", str(missing)]) == 2
    assert _error(capsys, "coastdown") == f"cannot read {missing}: No such file or directory"


def test_unreadable_input(tmp_path, capsys):
    source = tmp_path / "in.csv"
    shutil.copy(EXAMPLE_CSV, source)
    try:
        if not _enforced(source, 0o000):
            pytest.skip("permissions are not enforced (running as root)")
        assert main(["calc", str(source)]) == 2
        assert _error(capsys) == f"{source}: Permission denied"
    finally:
        os.chmod(source, 0o644)


def test_header_only_csv(tmp_path, capsys):
    source = tmp_path / "in.csv"
    source.write_text(EXAMPLE_CSV.read_text().splitlines()[0] + "\n")
    assert main(["calc", str(source)]) == 2
    assert _error(capsys) == f"{source}: no supports (only a header row)"
    assert main(["lab", str(source), "--out", str(tmp_path / "o")]) == 2
    assert _error(capsys, "lab") == f"{source}: no rows (only a header row)"


def test_truncated_workbook(tmp_path, capsys):
    path = _truncated(tmp_path)
    assert main(["lab", str(path), "--out", str(tmp_path / "o")]) == 2
    assert _error(capsys, "lab") == f"{path}: damaged workbook, its zip package cannot be read (File is not a zip file)"
    assert main(["calc", str(path)]) == 2
    assert _error(capsys).startswith(f"{path}: ")


def test_damaged_sheet_xml(tmp_path, capsys):
    path = _garbage_sheet(tmp_path)
    assert main(["calc", str(path)]) == 2
    line = _error(capsys)
    assert line.startswith(f"{path}: ") and "xml" in line.lower()
    assert main(["diagnose", str(path), "--out", str(tmp_path / "o")]) == 2
    assert _error(capsys, "diagnose").startswith(f"{path}: damaged workbook, an XML part cannot be read (")


def test_workbook_rewritten_during_the_read(tmp_path, capsys, monkeypatch):
    """Another program rewriting the file in place while it is read shows up as a broken compressed stream."""
    path = make_workbook(tmp_path / "in.xlsx")

    def rewritten(*args, **kwargs):
        raise zlib.error("Error -3 while decompressing data: invalid stored block lengths")

    monkeypatch.setattr(excel_workbook, "calc_workbook", rewritten)
    assert main(["calc", str(path)]) == 2
    assert _error(capsys) == (f"{path}: damaged workbook, its zip package cannot be read (Error -3 while "
                              "decompressing data: invalid stored block lengths)")


def test_file_ending_too_early(tmp_path, capsys, monkeypatch):
    path = make_workbook(tmp_path / "in.xlsx")

    def truncated(*args, **kwargs):
        raise EOFError("Compressed file ended before the end-of-stream marker was reached")

    monkeypatch.setattr(excel_workbook, "calc_workbook", truncated)
    assert main(["calc", str(path)]) == 2
    assert _error(capsys) == f"{path}: the file ends too early (truncated, or still being written)"


# ---- files that cannot be written ----------------------------------------------------------------------------

def test_missing_output_folder(tmp_path, capsys):
    target = tmp_path / "nope" / "out.csv"
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(target)]) == 2
    assert _error(capsys) == f"{target}: no such folder {tmp_path.resolve() / 'nope'}"


def test_read_only_output_folder(tmp_path, capsys):
    folder = tmp_path / "ro"
    folder.mkdir()
    try:
        if not _enforced(folder, 0o555):
            pytest.skip("permissions are not enforced (running as root)")
        assert main(["calc", str(EXAMPLE_CSV), "-o", str(folder / "out.csv")]) == 2
        assert _error(capsys) == f"{folder / 'out.csv'}: folder {folder.resolve()} is not writable (permission denied)"
        assert main(["lab", str(LAB), "--out", str(folder / "lab")]) == 2
        assert _error(capsys, "lab") == f"cannot create the folder {folder / 'lab'}: Permission denied"
    finally:
        os.chmod(folder, 0o755)


def test_disk_full(tmp_path, capsys, monkeypatch):
    target = tmp_path / "out.csv"
    target.write_text("old results")

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(files.os, "replace", full)
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(target), "--force", "-q"]) == 2
    assert _error(capsys) == f"cannot write {target.resolve()}: No space left on device"
    assert target.read_text() == "old results"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
    assert main(["coastdown", str(LAB.with_name("coastdown_example.csv")), "--out", str(tmp_path / "c")]) == 2
    assert _error(capsys, "coastdown") == f"cannot write {(tmp_path / 'c' / 'coastdown.png').resolve()}: No space left on device"
    assert list((tmp_path / "c").iterdir()) == []


def test_oserror_without_a_file_name_names_the_input(tmp_path, capsys, monkeypatch):
    path = make_workbook(tmp_path / "in.xlsx")

    def broken(*args, **kwargs):
        raise OSError(errno.EIO, os.strerror(errno.EIO))

    monkeypatch.setattr(excel_workbook, "calc_workbook", broken)
    assert main(["calc", str(path)]) == 2
    assert _error(capsys) == f"{path}: Input/output error"


def test_no_traceback_in_a_subprocess(tmp_path):
    path = _garbage_sheet(tmp_path)
    done = subprocess.run([sys.executable, "-m", "bearingheat", "calc", str(path)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 2
    assert "Traceback" not in done.stderr and done.stderr.count("\n") == 1
