"""No data loss: in_place keeps everything else and writes atomically; -o copies note what openpyxl drops."""
from __future__ import annotations

import os
import re
import zipfile

import openpyxl
import pytest
from excel_helpers import digest, make_workbook, rich_workbook, vba_workbook

from bearingheat.errors import OutputFileError, SheetContentError, WorkbookContentError, WorkbookLockedError
from bearingheat.io.excel.safety import unsupported_content, workbook_fingerprint
from bearingheat.io.excel.workbook import calc_workbook


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
    assert copy == original  # the marks of the skipped results sheet are left out too
    marks = [n for n in workbook_fingerprint(tmp_path / "copy.xlsx")["defined_names"] if n[0].startswith("_bearing")]
    assert marks[:1] + marks[2:] == [("_bearingheat_input_1", "Supports!$1:$1048576", None),
                                     ("_bearingheat_results_1", "Results!$1:$1048576", None)]
    assert re.fullmatch(r'"A1:[A-Z]+8 [0-9a-f]{16}"', marks[1][1]) and marks[1][0] == "_bearingheat_record_1"
    assert run.dropped == []


@pytest.mark.parametrize("in_place", [False, True])
def test_failed_write_leaves_the_workbook_and_no_temp_file(tmp_path, monkeypatch, in_place):
    """A full disk while the package is written (-o: the copy, --in-place: the workbook) leaves the workbook as
    it was and no file behind."""
    path = rich_workbook(tmp_path / "rich.xlsx")
    before = digest(path)
    written = []
    real_writestr = zipfile.ZipFile.writestr

    def broken_writestr(self, info, data, *args, **kwargs):
        written.append(info)
        if len(written) == 2:
            raise OSError(28, "No space left on device")
        return real_writestr(self, info, data, *args, **kwargs)

    monkeypatch.setattr(zipfile.ZipFile, "writestr", broken_writestr)
    target = path if in_place else tmp_path / "copy.xlsx"
    with pytest.raises(OutputFileError, match=f"cannot write {target}: No space left on device"):
        calc_workbook(path, in_place=True) if in_place else calc_workbook(path, target)
    assert digest(path) == before
    assert sorted(os.listdir(tmp_path)) == ["rich.xlsx"]


def test_failed_save_of_an_openpyxl_copy_leaves_no_temp_file(tmp_path, monkeypatch):
    """An .xlsm saved as .xlsx (its macros left out) is a copy openpyxl writes: a failed save leaves nothing."""
    path = vba_workbook(tmp_path / "macros.xlsm")
    before = digest(path)

    def broken_save(self, filename):
        with open(filename, "wb") as handle:
            handle.write(b"PK half a workbook")
        raise OSError("disk full")

    monkeypatch.setattr(openpyxl.Workbook, "save", broken_save)
    copy = tmp_path / "copy.xlsx"
    with pytest.raises(OutputFileError, match=f"^{re.escape(f'cannot write {copy}: disk full')}$"):
        calc_workbook(path, copy)
    assert digest(path) == before
    assert sorted(os.listdir(tmp_path)) == ["macros.xlsm"]


def test_in_place_keeps_file_permissions(tmp_path):
    path = make_workbook(tmp_path / "perm.xlsx")
    os.chmod(path, 0o640)
    calc_workbook(path, in_place=True)
    assert os.stat(path).st_mode & 0o777 == 0o640


def test_in_place_keeps_vba_of_xlsm(tmp_path):
    path = vba_workbook(tmp_path / "macro.xlsm")
    calc_workbook(path, in_place=True)
    with zipfile.ZipFile(path) as archive:
        assert archive.read("xl/vbaProject.bin") == b"\xd0\xcf\x11\xe0 macro bytes"
    assert "Results" in openpyxl.load_workbook(path, keep_vba=True).sheetnames


def test_in_place_without_keep_vba_refuses(tmp_path):
    path = vba_workbook(tmp_path / "macro.xlsm")
    with pytest.raises(WorkbookContentError) as exc:
        calc_workbook(path, in_place=True, keep_vba=False)
    assert str(exc.value) == (f"{path}: --in-place keeps every part of the workbook, its VBA macros too; "
                              "keep_vba=False would drop them; the file is unchanged. Write the results to a new "
                              "workbook with -o OUTPUT.xlsx instead")


def test_an_xlsm_copied_to_xlsx_names_its_form_button(tmp_path):
    """A legacy form button (a VML drawing's ObjectType="Button") goes with the macros when an .xlsm is written as
    .xlsx by openpyxl: the copy's note names it and its cell, not only 'VBA macros'; a note is no such object."""
    import xlsxwriter

    source = tmp_path / "macro.xlsm"
    (tmp_path / "vbaProject.bin").write_bytes(b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + b"VBA project" * 40)
    book = xlsxwriter.Workbook(str(source))
    ws = book.add_worksheet("Supports")
    ws.write_row(0, 0, ["id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication"])
    ws.write_row(1, 0, ["-", "-", "mm", "mm", "rpm", "kN", "kN", "mm^2/s", "-"])
    ws.write_row(2, 0, ["A", "6208", 40, 80, 1480, 3.2, 0.9, 40, "oil_bath"])
    book.add_vba_project(str(tmp_path / "vbaProject.bin"))
    ws.insert_button("P2", {"macro": "recalc", "caption": "Run"})
    ws.write_comment("A3", "support A: checked")
    book.close()
    run = calc_workbook(source, tmp_path / "out.xlsx", keep_vba=False)
    assert run.dropped == ["VBA macros", "form button at Supports!P2"]
    assert unsupported_content(source, keep_vba=True) == []


def test_in_place_refuses_a_workbook_open_in_excel(tmp_path):
    path = make_workbook(tmp_path / "open.xlsx")
    (tmp_path / "~$open.xlsx").write_bytes(b"owner")
    with pytest.raises(WorkbookLockedError) as exc:
        calc_workbook(path, in_place=True)
    assert str(exc.value) == f"{path} is open in Excel (lock file ~$open.xlsx); close it and run again"
    (tmp_path / "~$open.xlsx").unlink()
    (tmp_path / ".~lock.open.xlsx#").write_bytes(b"owner")
    with pytest.raises(WorkbookLockedError) as exc:
        calc_workbook(path, in_place=True)
    assert str(exc.value) == (f"{path} is open in LibreOffice (lock file .~lock.open.xlsx#); close it and run "
                              "again")


def test_unsupported_content_of_a_plain_workbook_is_empty(tmp_path):
    assert unsupported_content(rich_workbook(tmp_path / "rich.xlsx")) == []


def test_a_copy_is_refused_where_the_results_sheet_holds_content_of_the_designer(tmp_path):
    """Replacing a results sheet that the designer has given a chart would lose it in a copy too (openpyxl
    replaces the sheet as well): -o is refused like --in-place, nothing written, the workbook unchanged."""
    from workbook_corpus import CASES

    case = CASES["refused_results_sheet_with_a_chart"](tmp_path)
    before = digest(case.path)
    copy = tmp_path / "copy.xlsx"
    why = ("sheet 'Results' (bearingheat's results of 'Supports') now holds charts, images or shapes that replacing "
           "it would lose; move them to another sheet or delete the sheet, then run again")
    refused_copy = f"{case.path}: -o {copy} refused, {why}; nothing was written"
    with pytest.raises(SheetContentError, match=f"^{re.escape(refused_copy)}$"):
        calc_workbook(case.path, copy)
    refused_in_place = f"{case.path}: --in-place refused, {why}; the file is unchanged"
    with pytest.raises(SheetContentError, match=f"^{re.escape(refused_in_place)}"):
        calc_workbook(case.path, in_place=True)
    assert digest(case.path) == before and not copy.exists()


def test_an_openpyxl_copy_says_it_lacks_the_signature_and_the_change_history(tmp_path):
    """A signed workbook, or a shared one with a change history, is copied by openpyxl (the package edit refuses
    them): the copy is unsigned and has no history, and the note says so."""
    from workbook_corpus import CASES

    for name, lost in (("refused_digitally_signed", ["digital signatures"]),
                       ("refused_shared_workbook_with_history", ["change history (shared workbook)"])):
        (tmp_path / name).mkdir()
        case = CASES[name](tmp_path / name)
        run = calc_workbook(case.path, tmp_path / name / "copy.xlsx")
        assert run.dropped == lost, name
