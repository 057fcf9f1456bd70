"""bearingheat calc on Excel workbooks: outputs, exit codes 0/1/2, messages, --in-place, --formulas."""
from __future__ import annotations

import os
import subprocess
import sys
import zipfile

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX, add_zip_part, chart_workbook, control_workbook, csv_result, \
    digest, gearbox_rows, image_workbook, make_workbook, pivot_workbook, rich_workbook
from openpyxl.workbook.protection import WorkbookProtection

from bearingheat.cli import main
from bearingheat.io.excel.safety import workbook_fingerprint


def test_cli_writes_output_and_leaves_input(tmp_path, capsys):
    path = make_workbook(tmp_path / "in.xlsx")
    before = digest(path)
    out = tmp_path / "out.xlsx"
    assert main(["calc", str(path), "-o", str(out)]) == 0
    assert digest(path) == before
    printed = capsys.readouterr().out
    assert printed.splitlines()[-1] == f"6 supports: 6 ok, 0 warning, 0 error; results written to {out}, " \
                                       "sheet 'Results'" or "results written to" in printed
    assert openpyxl.load_workbook(out)["Results"].max_row == 8


def test_cli_exit_1_on_row_errors(tmp_path, capsys):
    rows = gearbox_rows()
    rows[0][5] = "abc"
    path = make_workbook(tmp_path / "in.xlsx", rows=rows)
    assert main(["calc", str(path), "-o", str(tmp_path / "out.xlsx")]) == 1
    assert "error: input shaft A (locating): Supports!F3: 'abc' is not a number for Fr [kN]" in capsys.readouterr().out


@pytest.mark.parametrize("extra, message", [
    (["--in-place", "-o", "OUT"], "give either --in-place or -o OUTPUT, not both"),
    (["--formulas"], "--formulas writes a workbook: give -o OUTPUT.xlsx or --in-place"),
    (["--sheet", "Nope"], "in.xlsx has no sheet 'Nope'; its sheets are Supports"),
])
def test_cli_usage_errors(tmp_path, capsys, extra, message):
    path = make_workbook(tmp_path / "in.xlsx")
    extra = [str(tmp_path / "out.xlsx") if e == "OUT" else e for e in extra]
    assert main(["calc", str(path), *extra]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {message}\n"


def test_cli_output_is_the_input(tmp_path, capsys):
    path = make_workbook(tmp_path / "in.xlsx")
    assert main(["calc", str(path), "-o", str(path)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: -o {path} is the input workbook; "
                                       "use --in-place to write into it\n")


def test_cli_csv_to_xlsx(tmp_path, capsys):
    out = tmp_path / "from_csv.xlsx"
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(out), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    ws = openpyxl.load_workbook(out)["Results"]
    header = [c.value for c in ws[1]]
    assert header[:3] == ["id", "designation", "d"] and [c.value for c in ws[2]][2] == "mm"
    assert ws.max_row == 8
    np.testing.assert_allclose([ws.cell(r, header.index("MR") + 1).value for r in range(3, 9)],
                               csv_result()["MR [N*mm]"], rtol=1e-15)


def test_cli_workbook_to_csv(tmp_path):
    out = tmp_path / "r.csv"
    assert main(["calc", str(EXAMPLE_XLSX), "-o", str(out), "-q"]) == 0
    np.testing.assert_allclose(pd.read_csv(out)["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_cli_workbook_to_csv_writes_the_units_of_the_units_row(tmp_path):
    """The CSV had 'd,D,n,Fr' over kN and rpm; read back it gave "column 'd': needs a unit"."""
    out, again = tmp_path / "r.csv", tmp_path / "again.csv"
    assert main(["calc", str(make_workbook(tmp_path / "in.xlsx")), "-o", str(out), "-q"]) == 0
    written = pd.read_csv(out)
    assert list(written.columns[:13]) == ["id", "designation", "d [mm]", "D [mm]", "n [rpm]", "Fr [kN]", "Fa [kN]",
                                          "nu [mm^2/s]", "lubrication", "arrangement", "C0 [kN]", "Y", "Y0"]
    assert main(["calc", str(out), "-o", str(again), "-q"]) == 0
    np.testing.assert_allclose(pd.read_csv(again)["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_cli_in_place_formulas_refuses_an_input_column_named_status(tmp_path, capsys):
    """--in-place --formulas crashed with a traceback on a designer's own 'status' column."""
    rows = [row + ["released"] for row in gearbox_rows()]
    header = ["id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication", "arrangement", "C0", "Y", "Y0"]
    units = ["-", "-", "mm", "mm", "rpm", "kN", "kN", "mm^2/s", "-", "-", "kN", "1", "1"]
    path = make_workbook(tmp_path / "in.xlsx", header=header + ["status"], units=units + ["-"], rows=rows)
    before = digest(path)
    assert main(["calc", str(path), "--in-place", "--formulas"]) == 2
    err = capsys.readouterr().err
    assert "Supports!N1: 'status' is a column calc writes; rename it (e.g. 'status (design)')" in err
    assert "Traceback" not in err and digest(path) == before


def test_cli_quiet_prints_nothing(tmp_path, capsys):
    assert main(["calc", str(EXAMPLE_XLSX), "-o", str(tmp_path / "o.xlsx"), "--quiet"]) == 0
    assert capsys.readouterr() == ("", "")


def test_subprocess_calc(tmp_path):
    out = tmp_path / "sub.xlsx"
    done = subprocess.run([sys.executable, "-m", "bearingheat", "calc", str(EXAMPLE_XLSX), "-o", str(out)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert f"results written to {out}, sheet 'Results'" in done.stdout
    assert "Results" in openpyxl.load_workbook(out).sheetnames


def test_in_place_keeps_everything_else(tmp_path, capsys):
    path = rich_workbook(tmp_path / "rich.xlsx")
    before = workbook_fingerprint(path)
    assert main(["calc", str(path), "--in-place"]) == 0
    assert f"results written to {path}, sheet 'Results'" in capsys.readouterr().out
    after = workbook_fingerprint(path, skip_sheets=("Results",))
    styles_before, styles_after = before.pop("named_styles"), after.pop("named_styles")
    assert set(styles_before) <= set(styles_after)
    assert after == before
    workbook = openpyxl.load_workbook(path)
    assert workbook.sheetnames == ["Supports", "Notes", "Calc (hidden)", "Results"]  # a new sheet goes last
    assert workbook["Results"].max_row == 8
    assert not [p for p in os.listdir(tmp_path) if p.startswith(".rich")]


@pytest.mark.parametrize("in_place", [True, False])
@pytest.mark.parametrize("build", [chart_workbook, image_workbook, pivot_workbook, control_workbook])
def test_the_written_workbook_keeps_what_openpyxl_would_drop(tmp_path, capsys, build, in_place):
    """Charts, images, pivot tables and form controls survive --in-place, and -o (the same edit written to a new
    file): only the results sheet is added, and nothing is noted as missing."""
    path = build(tmp_path / "rich.xlsx")
    original = digest(path)
    with zipfile.ZipFile(path) as archive:
        before = {name: archive.read(name) for name in archive.namelist()}
    written = path if in_place else tmp_path / "out.xlsx"
    assert main(["calc", str(path), "-q", *(["--in-place"] if in_place else ["-o", str(written)])]) == 0
    assert capsys.readouterr().err == ""
    with zipfile.ZipFile(written) as archive:
        after = {name: archive.read(name) for name in archive.namelist()}
    registration = {"xl/workbook.xml", "xl/_rels/workbook.xml.rels", "[Content_Types].xml", "xl/styles.xml"}
    assert set(before) <= set(after)
    assert {name for name in before if before[name] != after[name]} <= registration
    added = set(after) - set(before)
    assert len(added) == 1 and added.pop().startswith("xl/worksheets/sheet")
    if not in_place:
        assert digest(path) == original  # the input untouched


def test_output_of_a_lossy_workbook_says_what_the_copy_lacks(tmp_path, capsys):
    """A workbook whose structure is protected cannot take a sheet by the surgical edit: openpyxl writes the copy,
    which lacks the pivot table, and the note says so."""
    path = make_workbook(tmp_path / "pivot.xlsx")
    workbook = openpyxl.load_workbook(path)
    workbook.security = WorkbookProtection(lockStructure=True)
    workbook.save(path)
    add_zip_part(path, "xl/pivotTables/pivotTable1.xml")
    add_zip_part(path, "xl/pivotCache/pivotCacheDefinition1.xml")
    before = digest(path)
    out = tmp_path / "out.xlsx"
    assert main(["calc", str(path), "-o", str(out)]) == 0
    assert capsys.readouterr().err == (f"note: {out} lacks or has altered the pivot tables, pivot caches of {path} "
                                       f"(openpyxl cannot copy them as they are); {path} is unchanged\n")
    assert digest(path) == before
    with zipfile.ZipFile(out) as archive:
        assert not [name for name in archive.namelist() if "pivot" in name]


@pytest.mark.parametrize("extra, message", [
    (["-o", "OUT.csv", "--formulas"], "--formulas needs an Excel output (.xlsx), not a CSV"),
])
def test_formulas_usage_errors(tmp_path, capsys, extra, message):
    extra = [str(tmp_path / e) if e.startswith("OUT") else e for e in extra]
    assert main(["calc", str(EXAMPLE_XLSX), *extra]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {message}\n"


def test_the_csv_of_the_example_workbook_is_computed_again_as_the_workbook_was(tmp_path, capsys):
    """calc spreadsheets/gearbox_shaft_example.xlsx -o x.csv, then calc x.csv: the CSV holds the workbook's unused
    duty-cycle columns (support, case, time_share, duration [h]) blank in every row, which a workbook skips and a
    CSV took for a duty cycle ('row 1: support is blank', exit 2). Now both read them alike: the CSV run gives the
    workbook run's columns and values, its one message cited with the CSV's row as a CSV cites its rows."""
    first, again = tmp_path / "x.csv", tmp_path / "again.csv"
    assert main(["calc", str(EXAMPLE_XLSX), "-o", str(first), "-q"]) == 0
    assert main(["calc", str(first), "-o", str(again), "-q"]) == 0
    assert not (tmp_path / "again.duty.csv").exists()
    capsys.readouterr()
    workbook, csv = pd.read_csv(first), pd.read_csv(again)
    for name in ("support", "case", "time_share", "duration [h]"):
        assert workbook[name].isna().all()
    assert list(csv.columns) == list(workbook.columns)
    pd.testing.assert_frame_equal(csv.drop(columns="message"), workbook.drop(columns="message"))
    said = workbook["message"].fillna("").tolist()
    assert [i for i, text in enumerate(said) if text] == [4]
    assert csv["message"].fillna("").tolist() == [
        f'row 6 (id "spindle front (pair)"): {text}' if text else "" for text in said]

