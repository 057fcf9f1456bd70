"""Output files of every command: --force, never the input, links, read-only targets, atomic writes,
kill -9 during a write, concurrent runs and lock files."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import openpyxl
import pandas as pd
import pytest
from excel_helpers import EXAMPLE_CSV, digest, gearbox_rows, make_workbook
from synthetic_torque import measured_set
from thermal_helpers import plot_table

from bearingheat.cli import main
from bearingheat.io.excel.writer import results_sheet_name
from bearingheat.io.files import STALE_SECONDS, atomic_write_text

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
LAB = EXAMPLES / "lab_dp11a_example.csv"
COASTDOWN = EXAMPLES / "coastdown_example.csv"


def _err(capsys) -> str:
    err = capsys.readouterr().err
    assert "Traceback" not in err and err.count("\n") == 1, err
    return err.strip()


def _has_results(book: Path, sheet: str) -> bool:
    """The workbook holds the results sheet of ``sheet``."""
    return results_sheet_name(sheet) in openpyxl.load_workbook(book).sheetnames


def _temps(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.rglob("*") if ".bearingheat-" in p.name)


# ---- -o needs --force; the output is never the input ---------------------------------------------------------

@pytest.mark.parametrize("suffix", [".csv", ".xlsx"])
def test_calc_output_exists_needs_force(tmp_path, capsys, suffix):
    target = tmp_path / f"out{suffix}"
    target.write_bytes(b"designer's file")
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(target), "-q"]) == 2
    assert _err(capsys) == f"bearingheat calc: error: {target} exists; give --force to replace it"
    assert target.read_bytes() == b"designer's file"
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(target), "-q", "--force"]) == 0
    assert target.read_bytes() != b"designer's file" and _temps(tmp_path) == []


def test_calc_workbook_output_exists_needs_force(tmp_path, capsys):
    source = make_workbook(tmp_path / "in.xlsx")
    for suffix in (".xlsx", ".csv"):
        target = tmp_path / f"out{suffix}"
        target.write_bytes(b"old")
        assert main(["calc", str(source), "-o", str(target), "-q"]) == 2
        assert _err(capsys) == f"bearingheat calc: error: {target} exists; give --force to replace it"
        assert main(["calc", str(source), "-o", str(target), "-q", "--force"]) == 0
        assert target.read_bytes() != b"old"


def test_output_is_never_the_input(tmp_path, capsys):
    source = tmp_path / "in.csv"
    source.write_bytes(EXAMPLE_CSV.read_bytes())
    link = tmp_path / "link.csv"
    link.symlink_to(source)
    hard = tmp_path / "hard.csv"
    os.link(source, hard)
    before = digest(source)
    assert main(["calc", str(source), "-o", str(source), "--force", "-q"]) == 2
    assert _err(capsys) == f"bearingheat calc: error: {source} is the input file; write the results to another file"
    for alias in (link, hard):
        assert main(["calc", str(source), "-o", str(alias), "--force", "-q"]) == 2
        assert _err(capsys) == (f"bearingheat calc: error: {alias} is the input file {source}; write the results to "
                                "another file")
    assert digest(source) == before


def test_output_is_never_a_file_the_run_reads(tmp_path, capsys):
    """The f2 chart, VM chart and coefficients files are inputs as well: -o --force does not write over them."""
    chart = tmp_path / "f2.csv"
    chart.write_bytes((EXAMPLES.parent / "docs" / "f2_chart_example.csv").read_bytes())
    before = digest(chart)
    assert main(["calc", str(EXAMPLE_CSV), "--f2-chart", str(chart), "-o", str(chart), "--force", "-q"]) == 2
    assert _err(capsys) == f"bearingheat calc: error: {chart} is the input file; write the results to another file"
    assert digest(chart) == before


def test_an_input_file_with_glob_characters_in_its_name_is_read(tmp_path, capsys):
    source = tmp_path / "supports [v2].csv"
    source.write_bytes(EXAMPLE_CSV.read_bytes())
    assert main(["calc", str(source), "-q"]) == 0


@pytest.mark.parametrize("workers", ["-1", "0", "two"])
def test_workers_must_be_a_whole_number_of_at_least_one(tmp_path, capsys, workers):
    with pytest.raises(SystemExit) as exc:
        main(["calc", str(tmp_path), "--dask", "--workers", workers, "-o", str(tmp_path / "out")])
    assert exc.value.code == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        f"bearingheat calc: error: argument --workers: {workers!r} is not a number of worker processes (a whole "
        "number >= 1)")


def test_output_through_a_symlink_writes_the_real_file(tmp_path, capsys):
    real = tmp_path / "real.csv"
    real.write_text("old")
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(link), "--force", "-q"]) == 0
    assert link.is_symlink() and len(pd.read_csv(real)) == len(pd.read_csv(EXAMPLE_CSV))


def test_read_only_target_is_refused(tmp_path, capsys):
    target = tmp_path / "out.csv"
    target.write_text("old")
    os.chmod(target, 0o444)
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(target), "--force", "-q"]) == 2
    assert _err(capsys) == f"bearingheat calc: error: {target} is read-only; make it writable or write to another file"
    assert target.read_text() == "old"


def test_plot_output_needs_force(tmp_path, capsys):
    table = plot_table(tmp_path)
    png = tmp_path / "heat.png"
    png.write_bytes(b"old")
    assert main(["plot", str(table), "-o", str(png)]) == 2
    assert _err(capsys) == f"bearingheat plot: error: {png} exists; give --force to replace it"
    assert main(["plot", str(table), "-o", str(png), "--force"]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    svg = tmp_path / "heat.svg"
    assert main(["plot", str(table), "-o", str(svg)]) == 0
    assert b"<svg" in svg.read_bytes()[:500]
    assert main(["plot", str(table), "-o", str(tmp_path / "heat.txt")]) == 2
    assert _err(capsys) == (f"bearingheat plot: error: {tmp_path / 'heat.txt'}: a figure is written as .png, .svg, "
                            ".svgz, .pdf, .eps, .ps, .jpg, .jpeg, .tif, .tiff, .webp; name it e.g. heat_balance.png")
    odd = tmp_path / "table.png"  # a CSV named like a figure: still never overwritten by its own plot
    odd.write_bytes(table.read_bytes())
    assert main(["plot", str(odd), "-o", str(odd), "--force"]) == 2
    assert _err(capsys) == f"bearingheat plot: error: {odd} is the input file; write the results to another file"


def test_template_output(tmp_path, capsys):
    target = tmp_path / "t.xlsx"
    target.write_bytes(b"old")
    assert main(["template", "-o", str(target)]) == 2
    assert _err(capsys) == f"bearingheat template: error: {target} exists; give --force to replace it"
    os.chmod(target, 0o444)
    assert main(["template", "-o", str(target), "--force"]) == 2
    assert _err(capsys) == f"bearingheat template: error: {target} is read-only; make it writable or write to another file"
    os.chmod(target, 0o644)
    assert main(["template", "-o", str(target), "--force", "-q"]) == 0
    assert openpyxl.load_workbook(target).sheetnames[0] == "Supports"


# ---- --out DIR of the report commands ------------------------------------------------------------------------

def test_lab_report_files_need_force(tmp_path, capsys):
    out = tmp_path / "lab"
    assert main(["lab", str(LAB), "--out-dir", str(out), "-q"]) == 0
    report = (out / "report.md").read_bytes()
    assert main(["lab", str(LAB), "--out-dir", str(out), "-q"]) == 2
    assert _err(capsys) == (f"bearingheat lab: error: {out}: readings.csv, task1_mu.csv, task2_f0_TF.csv, "
                            "task3_f_T0.csv, comparison.csv, report.md exist; give --force to replace them")
    assert main(["lab", str(LAB), "--out-dir", str(out), "-q", "--force"]) == 0
    assert (out / "report.md").read_bytes() == report and _temps(out) == []


def test_lab_report_refuses_a_figure_that_exists(tmp_path, capsys):
    out = tmp_path / "lab"
    out.mkdir()
    (out / "task1_101.png").write_bytes(b"mine")
    assert main(["lab", str(LAB), "--out-dir", str(out), "-q"]) == 2
    assert _err(capsys) == f"bearingheat lab: error: {out}: task1_101.png exists; give --force to replace it"
    assert sorted(p.name for p in out.iterdir()) == ["task1_101.png"]


def test_coastdown_report_files_need_force(tmp_path, capsys):
    out = tmp_path / "c"
    assert main(["coastdown", str(COASTDOWN), "--out-dir", str(out)]) == 0
    capsys.readouterr()
    assert main(["coastdown", str(COASTDOWN), "--out-dir", str(out)]) == 2
    assert _err(capsys) == (f"bearingheat coastdown: error: {out}: coastdown.png, report.md, summary.json exist; "
                            "give --force to replace them")
    assert main(["coastdown", str(COASTDOWN), "--out-dir", str(out), "--force"]) == 0


def test_coastdown_input_in_the_out_folder(tmp_path, capsys):
    data = tmp_path / "summary.json"
    data.write_bytes(COASTDOWN.read_bytes())
    assert main(["coastdown", str(data), "--out-dir", str(tmp_path), "--force"]) == 2
    assert _err(capsys) == f"bearingheat coastdown: error: {data} is the input file; write the results to another file"


def test_audit_and_diagnose_report_files_need_force(tmp_path, capsys):
    table, _, _ = measured_set("none", 3, designations=["30206-A", "6004", "6310", "NU208-E"])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    out = tmp_path / "a"
    assert main(["audit", str(source), "--out-dir", str(out), "-q"]) == 0
    assert main(["audit", str(source), "--out-dir", str(out), "-q"]) == 2
    assert _err(capsys) == f"bearingheat audit: error: {out}: coefficients.csv exists; give --force to replace it"
    assert main(["audit", str(source), "--out-dir", str(out), "-q", "--force"]) == 0
    d = tmp_path / "d"
    d.mkdir()
    (d / "report.md").write_text("mine")
    assert main(["diagnose", str(source), "--out-dir", str(d), "-q"]) == 2
    assert _err(capsys) == f"bearingheat diagnose: error: {d}: report.md exists; give --force to replace it"
    assert (d / "report.md").read_text() == "mine"


# ---- in-place: links, read-only, lock files, concurrent runs -----------------------------------------------------

def test_in_place_through_a_symlink_keeps_the_link(tmp_path, capsys):
    real = make_workbook(tmp_path / "real.xlsx")
    link = tmp_path / "link.xlsx"
    link.symlink_to(real)
    assert main(["calc", str(link), "--in-place", "-q"]) == 0
    assert link.is_symlink()
    assert _has_results(real, "Supports")


def test_in_place_refuses_read_only_and_hard_linked_workbooks(tmp_path, capsys):
    book = make_workbook(tmp_path / "book.xlsx")
    before = digest(book)
    os.chmod(book, 0o444)
    assert main(["calc", str(book), "--in-place", "-q"]) == 2
    assert _err(capsys) == f"bearingheat calc: error: {book} is read-only; make it writable or write to another file"
    os.chmod(book, 0o644)
    os.link(book, tmp_path / "twin.xlsx")
    assert main(["calc", str(book), "--in-place", "-q"]) == 2
    assert _err(capsys) == (f"bearingheat calc: error: {book} has 1 other hard link(s); replacing it would leave them "
                            "with the old content; write to another file")
    assert digest(book) == before


@pytest.mark.parametrize("lock, program", [("~$book.xlsx", "Excel"), (".~lock.book.xlsx#", "LibreOffice")])
def test_in_place_honours_office_lock_files(tmp_path, capsys, lock, program):
    book = make_workbook(tmp_path / "book.xlsx")
    before = digest(book)
    (tmp_path / lock).write_text("designer")
    assert main(["calc", str(book), "--in-place", "-q"]) == 2
    assert _err(capsys) == (f"bearingheat calc: error: {book} is open in {program} (lock file {lock}); close it and "
                            "run again")
    assert digest(book) == before


@pytest.mark.parametrize("lock, program", [("~$out.xlsx", "Excel"), (".~lock.out.xlsx#", "LibreOffice")])
def test_output_open_in_another_program_is_not_replaced_even_with_force(tmp_path, capsys, lock, program):
    """-o OUT.xlsx --force over a workbook Excel or LibreOffice has open: their later save would throw the results
    away (and ours their edits), so it is refused, before any work, whether the input is a workbook or a CSV."""
    book = make_workbook(tmp_path / "book.xlsx")
    out = tmp_path / "out.xlsx"
    out.write_bytes(b"the designer's open workbook")
    (tmp_path / lock).write_text("designer")
    for source in (book, EXAMPLE_CSV):
        for force in ([], ["--force"]):
            assert main(["calc", str(source), "-o", str(out), "-q", *force]) == 2
            assert _err(capsys) == (f"bearingheat calc: error: {out} is open in {program} (lock file {lock}); "
                                    "close it and run again")
    assert out.read_bytes() == b"the designer's open workbook" and _temps(tmp_path) == []
    (tmp_path / lock).unlink()
    assert main(["calc", str(book), "-o", str(out), "-q", "--force"]) == 0
    assert _has_results(out, "Supports")


_HOLD = """
import sys, time
from bearingheat.io.files import workbook_lock
with workbook_lock(sys.argv[1]):
    print("held", flush=True)
    time.sleep(60)
"""


def test_in_place_is_refused_while_another_run_holds_the_workbook(tmp_path, capsys):
    book = make_workbook(tmp_path / "book.xlsx")
    before = digest(book)
    holder = subprocess.Popen([sys.executable, "-c", _HOLD, str(book)], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        assert main(["calc", str(book), "--in-place", "-q"]) == 2
        assert _err(capsys) == (f"bearingheat calc: error: {book} is being written by another bearingheat run (lock "
                                "file .book.xlsx.bearingheat.lock); wait for it to finish and run again")
        assert digest(book) == before
    finally:
        holder.kill()
        holder.wait()
        holder.stdout.close()
    assert main(["calc", str(book), "--in-place", "-q"]) == 0


def test_concurrent_in_place_runs_lose_no_results_sheet(tmp_path):
    """Two runs on two sheets of one workbook at once: each run that reports success has its results sheet."""
    book = make_workbook(tmp_path / "book.xlsx", rows=gearbox_rows() * 50)
    workbook = openpyxl.load_workbook(book)
    workbook.copy_worksheet(workbook["Supports"]).title = "Other"
    workbook.save(book)
    for _ in range(2):
        runs = {sheet: subprocess.Popen([sys.executable, "-m", "bearingheat", "calc", str(book), "--in-place",
                                         "--sheet", sheet, "-q"], stderr=subprocess.PIPE, text=True)
                for sheet in ("Supports", "Other")}
        codes = {}
        for sheet, run in runs.items():  # (communicate reads stderr while waiting and closes the pipe)
            err = run.communicate(timeout=120)[1]
            codes[sheet] = (run.returncode, err)
        assert any(code == 0 for code, _ in codes.values())
        for sheet, (code, err) in codes.items():
            if code == 0:
                assert _has_results(book, sheet), (sheet, openpyxl.load_workbook(book).sheetnames)
            else:
                assert code == 2 and "is being written by another bearingheat run" in err, err
        assert _temps(tmp_path) == [] and not (tmp_path / ".book.xlsx.bearingheat.lock").exists()


# ---- kill -9 during a write --------------------------------------------------------------------------------------

_SLOW_WRITE = """
import sys, time
from pathlib import Path
from bearingheat.io.files import atomic_write

def write(temp):
    Path(temp).write_text("half of the new")
    print("writing", flush=True)
    time.sleep(60)

atomic_write(sys.argv[1], write)
"""


def test_kill_during_a_write_leaves_the_old_file_and_the_next_run_removes_the_temp(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old results")
    writer = subprocess.Popen([sys.executable, "-c", _SLOW_WRITE, str(target)], stdout=subprocess.PIPE, text=True)
    assert writer.stdout.readline().strip() == "writing"
    os.kill(writer.pid, signal.SIGKILL)
    writer.wait()
    writer.stdout.close()
    assert target.read_text() == "old results"
    (temp,) = [p for p in tmp_path.iterdir() if ".bearingheat-" in p.name]
    long_ago = time.time() - STALE_SECONDS - 5
    os.utime(temp, (long_ago, long_ago))
    atomic_write_text(target, "new results")
    assert target.read_text() == "new results" and _temps(tmp_path) == []


def test_kill_during_calc_of_a_big_csv(tmp_path):
    """SIGKILL at some moment of 'calc big.csv -o out.csv --force': out.csv is the old file or the new complete one."""
    big = tmp_path / "big.csv"
    table = pd.read_csv(EXAMPLE_CSV)
    pd.concat([table] * 2000, ignore_index=True).to_csv(big, index=False)
    target = tmp_path / "out.csv"
    reference = tmp_path / "reference.csv"
    assert main(["calc", str(big), "-o", str(reference), "-q"]) == 0
    complete = reference.read_bytes()
    caught = []
    for delay in (0.3, 60.0):  # early (before the write), and as soon as the temporary file appears
        target.write_text("old results")
        run = subprocess.Popen([sys.executable, "-m", "bearingheat", "calc", str(big), "-o", str(target), "--force",
                                "-q"])
        deadline = time.time() + delay
        while time.time() < deadline and run.poll() is None:
            if any(".bearingheat-" in p.name for p in tmp_path.iterdir()):  # caught while writing
                caught.append(delay)
                break
            time.sleep(0.005)
        run.send_signal(signal.SIGKILL)
        run.wait()
        assert target.read_bytes() in (b"old results", complete)
    assert caught == [60.0]
    for temp in tmp_path.iterdir():
        if ".bearingheat-" in temp.name:
            os.utime(temp, (time.time() - STALE_SECONDS - 5,) * 2)
    assert main(["calc", str(big), "-o", str(target), "--force", "-q"]) == 0
    assert target.read_bytes() == complete and _temps(tmp_path) == []


# ---- contact --csv: European CSV in, escaped CSV out ---------------------------------------------------------------

def test_contact_csv_semicolons_decimal_commas_and_escaped_text(tmp_path, capsys):
    comma = tmp_path / "comma.csv"
    comma.write_text("designation,z,Dw [um],dm_pitch [cm],ri [mm],ro [mm],clearance [um],Fa [N]\n"
                     "=cmd,7,2000,0.87355,1.05,1.16,9.178008,19.6133\n")
    euro = tmp_path / "euro.csv"
    euro.write_text("designation;z;Dw [um];dm_pitch [cm];ri [mm];ro [mm];clearance [um];Fa [N]\n"
                    "=cmd;7;2000;0,87355;1,05;1,16;9,178008;19,6133\n")
    assert main(["contact", str(comma)]) == 0
    first = capsys.readouterr().out
    assert main(["contact", str(euro)]) == 0
    assert capsys.readouterr().out == first
    assert first.splitlines()[1].startswith("1,'=cmd,")


def test_sep_and_decimal_are_refused_for_a_binary_table(tmp_path, capsys):
    source = tmp_path / "in.parquet"
    pd.read_csv(EXAMPLE_CSV).to_parquet(source, index=False)
    for output in ([], ["-o", str(tmp_path / "out.xlsx")]):
        assert main(["calc", str(source), "--decimal", ",", *output]) == 2
        assert _err(capsys) == ("bearingheat calc: error: --sep and --decimal apply to CSV input only (a Parquet or "
                                "Arrow file holds numbers)")
