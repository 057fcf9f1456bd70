"""No data loss: --in-place keeps everything else, writes atomically, and refuses what openpyxl would drop."""
from __future__ import annotations

import hashlib
import os
import zipfile

import openpyxl
import pytest
from excel_helpers import add_zip_part, make_workbook
from openpyxl.chart import BarChart, Reference
from openpyxl.comments import Comment
from openpyxl.formatting.rule import CellIsRule
from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
from openpyxl.workbook.defined_name import DefinedName
from openpyxl.worksheet.datavalidation import DataValidation

from bearingheat.cli import main
from bearingheat.excel import ExcelError, calc_workbook
from bearingheat.excel_safety import unsupported_content, workbook_fingerprint


def digest(path) -> str:
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def rich_workbook(path):
    """Supports plus everything a designer keeps in a workbook: sheets, formulas, styles, names, lists, notes."""
    make_workbook(path)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    ws["A3"].font = Font(bold=True, color="C00000")
    ws["F3"].fill = PatternFill("solid", fgColor="FFFF00")
    ws["F3"].number_format = "0.000"
    ws["B4"].comment = Comment("checked by J. Smith", "J. Smith")
    ws.column_dimensions["A"].width = 31.5
    ws.row_dimensions[5].height = 22
    lists = DataValidation(type="list", formula1='"grease,oil_mist,oil_bath,circulating_oil"', allow_blank=True)
    lists.add("I3:I100")
    ws.add_data_validation(lists)
    ws.conditional_formatting.add("F3:F8", CellIsRule(operator="greaterThan", formula=["5"],
                                                      fill=PatternFill("solid", fgColor="F4B084")))
    ws["O1"] = "drawing"
    ws["O1"].hyperlink = "https://example.org/drawing-G17.pdf"
    ws.freeze_panes = "C3"
    notes = workbook.create_sheet("Notes")
    notes["A1"] = "Gearbox G-17"
    notes["A1"].font = Font(size=16, bold=True)
    notes.merge_cells("A1:D1")
    notes["A3"] = "total radial load"
    notes["B3"] = "=SUM(Supports!F3:F8)"
    notes["B3"].border = Border(bottom=Side(style="double"))
    notes["B3"].alignment = Alignment(horizontal="right")
    notes["A4"] = "approved"
    notes["B4"] = True
    notes["A5"] = 0.1 + 0.2
    notes["A5"].comment = Comment("a float that has no short decimal", "QA")
    notes.column_dimensions["A"].width = 20
    hidden = workbook.create_sheet("Calc (hidden)")
    hidden["A1"] = "=Notes!B3*2"
    hidden.sheet_state = "hidden"
    workbook.defined_names["total_Fr"] = DefinedName("total_Fr", attr_text="Supports!$F$3:$F$8")
    notes.defined_names["approval"] = DefinedName("approval", attr_text="Notes!$B$4")
    workbook.save(path)
    return path


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
    assert workbook.sheetnames == ["Supports", "Results", "Notes", "Calc (hidden)"]
    assert workbook["Results"].max_row == 8
    assert not [p for p in os.listdir(tmp_path) if p.startswith(".rich")]


def test_in_place_replaces_the_results_sheet_where_it_was(tmp_path):
    path = make_workbook(tmp_path / "again.xlsx")
    workbook = openpyxl.load_workbook(path)
    workbook.create_sheet("Notes")["A1"] = "keep me"
    workbook.move_sheet("Notes", offset=-1)
    workbook.save(path)
    calc_workbook(path, in_place=True)
    calc_workbook(path, in_place=True)
    workbook = openpyxl.load_workbook(path)
    assert workbook.sheetnames == ["Notes", "Supports", "Results"]
    assert workbook["Notes"]["A1"].value == "keep me"
    assert workbook["Results"].max_row == 8


def test_output_leaves_the_input_untouched(tmp_path):
    path = rich_workbook(tmp_path / "rich.xlsx")
    before, stamp = digest(path), os.stat(path).st_mtime_ns
    run = calc_workbook(path, tmp_path / "copy.xlsx")
    assert (digest(path), os.stat(path).st_mtime_ns) == (before, stamp)
    copy = workbook_fingerprint(tmp_path / "copy.xlsx", skip_sheets=("Results",))
    original = workbook_fingerprint(path)
    copy.pop("named_styles"), original.pop("named_styles")
    assert copy == original
    assert run.dropped == []


def test_failed_save_leaves_the_workbook_and_no_temp_file(tmp_path, monkeypatch):
    path = rich_workbook(tmp_path / "rich.xlsx")
    before = digest(path)

    def broken_save(self, filename):
        with open(filename, "wb") as handle:
            handle.write(b"PK half a workbook")
        raise OSError("disk full")

    monkeypatch.setattr(openpyxl.Workbook, "save", broken_save)
    with pytest.raises(OSError, match="disk full"):
        calc_workbook(path, in_place=True)
    assert digest(path) == before
    assert sorted(os.listdir(tmp_path)) == ["rich.xlsx"]


def test_in_place_keeps_file_permissions(tmp_path):
    path = make_workbook(tmp_path / "perm.xlsx")
    os.chmod(path, 0o640)
    calc_workbook(path, in_place=True)
    assert os.stat(path).st_mode & 0o777 == 0o640


def chart_workbook(path):
    make_workbook(path)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    chart = BarChart()
    chart.add_data(Reference(ws, min_col=6, min_row=3, max_row=8))
    ws.add_chart(chart, "P2")
    workbook.save(path)
    return path


def image_workbook(path):
    from openpyxl.drawing.image import Image
    from PIL import Image as PILImage

    make_workbook(path)
    png = path.with_suffix(".png")
    PILImage.new("RGB", (4, 4), "red").save(png)
    workbook = openpyxl.load_workbook(path)
    workbook["Supports"].add_image(Image(str(png)), "P2")
    workbook.save(path)
    return path


def pivot_workbook(path):
    make_workbook(path)
    add_zip_part(path, "xl/pivotTables/pivotTable1.xml")
    add_zip_part(path, "xl/pivotCache/pivotCacheDefinition1.xml")
    return path


def control_workbook(path):
    make_workbook(path)
    add_zip_part(path, "xl/ctrlProps/ctrlProp1.xml")
    return path


@pytest.mark.parametrize("build, lost", [
    (chart_workbook, "charts"),
    (image_workbook, "images"),
    (pivot_workbook, "pivot tables, pivot caches"),
    (control_workbook, "form controls"),
])
def test_in_place_refuses_what_openpyxl_would_drop(tmp_path, capsys, build, lost):
    path = build(tmp_path / "lossy.xlsx")
    before = digest(path)
    assert main(["calc", str(path), "--in-place"]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat calc: error: {path}: --in-place refused, rewriting the workbook would lose its {lost} "
        "(openpyxl cannot keep them); the file is unchanged. Write the results to a new workbook with "
        "-o OUTPUT.xlsx instead\n")
    assert digest(path) == before


def test_output_of_a_lossy_workbook_says_what_the_copy_lacks(tmp_path, capsys):
    path = chart_workbook(tmp_path / "chart.xlsx")
    before = digest(path)
    out = tmp_path / "out.xlsx"
    assert main(["calc", str(path), "-o", str(out)]) == 0
    assert capsys.readouterr().err == (f"note: {out} lacks the charts of {path} (openpyxl cannot copy them); "
                                       f"{path} is unchanged\n")
    assert digest(path) == before


def vba_workbook(path):
    make_workbook(path.with_suffix(".xlsx"))
    os.replace(path.with_suffix(".xlsx"), path)
    add_zip_part(path, "xl/vbaProject.bin", b"\xd0\xcf\x11\xe0 macro bytes")
    return path


def test_in_place_keeps_vba_of_xlsm(tmp_path):
    path = vba_workbook(tmp_path / "macro.xlsm")
    calc_workbook(path, in_place=True)
    with zipfile.ZipFile(path) as archive:
        assert archive.read("xl/vbaProject.bin") == b"\xd0\xcf\x11\xe0 macro bytes"
    assert "Results" in openpyxl.load_workbook(path, keep_vba=True).sheetnames


def test_in_place_without_keep_vba_refuses(tmp_path):
    path = vba_workbook(tmp_path / "macro.xlsm")
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path, in_place=True, keep_vba=False)
    assert str(exc.value) == (f"{path}: --in-place refused, rewriting the workbook would lose its VBA macros "
                              "(openpyxl cannot keep them); the file is unchanged. Write the results to a new "
                              "workbook with -o OUTPUT.xlsx instead")


def test_in_place_refuses_a_workbook_open_in_excel(tmp_path):
    path = make_workbook(tmp_path / "open.xlsx")
    (tmp_path / "~$open.xlsx").write_bytes(b"owner")
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path, in_place=True)
    assert str(exc.value) == f"{path} is open in Excel (lock file ~$open.xlsx); close it and run again"


def test_unsupported_content_of_a_plain_workbook_is_empty(tmp_path):
    assert unsupported_content(rich_workbook(tmp_path / "rich.xlsx")) == []
