"""``calc --in-place`` as a surgical edit of the package: the parts it writes, the marks, text, the calc chain."""
from __future__ import annotations

import io
import os
import re
import shutil
import zipfile

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import EXAMPLE_XLSX, gearbox_rows, make_workbook
from excel_helpers import HEADER as HEADER_PLAIN, UNITS as UNITS_PLAIN
from workbook_corpus import CASES, edit_package, results_part

from bearingheat.cli import main
from bearingheat.errors import ExcelError
from bearingheat.io.console import Progress
from bearingheat.io.excel.libreoffice import convert, soffice
from bearingheat.io.excel.ownership import choose_results_sheet, read_marks, sheet_of_mark
from bearingheat.io.excel import record, sheetxml
from bearingheat.io.excel.sheetxml import xstring
from bearingheat.io.excel.workbook import calc_workbook


pytestmark = pytest.mark.filterwarnings("ignore:.*extension is not supported:UserWarning")


def part(path, name) -> bytes:
    with zipfile.ZipFile(path) as archive:
        return archive.read(name)


def names(path) -> list[str]:
    with zipfile.ZipFile(path) as archive:
        return archive.namelist()


def test_results_are_inline_strings_and_the_shared_strings_stay(tmp_path):
    path = CASES["rich_text"](tmp_path).path  # XlsxWriter: shared strings with rich text runs
    strings = part(path, "xl/sharedStrings.xml")
    run = calc_workbook(path, in_place=True)
    assert part(path, "xl/sharedStrings.xml") == strings
    sheet = part(path, results_part(path, run.results_sheet)).decode()
    assert 't="s"' not in sheet and 't="inlineStr"' in sheet
    assert '<pane ySplit="2" topLeftCell="A3" activePane="bottomLeft" state="frozen"/>' in sheet
    assert '<tabColor rgb="FF44546A"/>' in sheet


def test_the_results_sheet_is_marked_by_hidden_names(tmp_path):
    path = make_workbook(tmp_path / "book.xlsx", sheet="Shaft 2")
    calc_workbook(path, in_place=True)
    workbook = part(path, "xl/workbook.xml").decode()
    assert ('<definedName name="_bearingheat_results_1" hidden="1">\'Shaft 2 results\'!$1:$1048576</definedName>'
            in workbook)
    assert '<definedName name="_bearingheat_input_1" hidden="1">\'Shaft 2\'!$1:$1048576</definedName>' in workbook
    assert re.search(r'<calcPr[^>]*fullCalcOnLoad="1"', workbook)
    book = openpyxl.load_workbook(path)
    marks = read_marks((n, d.attr_text) for n, d in book.defined_names.items())
    assert marks == {1: ("Shaft 2 results", "Shaft 2")}
    assert book.defined_names["_bearingheat_results_1"].hidden


def test_marks_and_names():
    assert sheet_of_mark("=Supports!$1:$1048576") == "Supports"
    assert sheet_of_mark("'Loss 2024'!$1:$1048576") == "Loss 2024"
    assert sheet_of_mark("#REF!") is None and sheet_of_mark("") is None and sheet_of_mark("42") is None
    marks = {1: ("Results", "Supports"), 2: ("Other results", "Other")}
    assert choose_results_sheet(["Supports", "Results", "Other"], marks, "Supports") == ("Results", True, None)
    assert choose_results_sheet(["Supports", "Results (3)"], {1: ("Results (3)", "Supports")}, "Supports") == (
        "Results (3)", True, None)
    name, replace, note = choose_results_sheet(["Supports", "RESULTS"], {}, "Supports")
    assert (name, replace) == ("Results (2)", False) and note.startswith("sheet 'RESULTS' is not a results sheet")
    # a mark that names the input sheet as its results sheet is never followed
    assert choose_results_sheet(["Supports"], {1: ("Supports", "Supports")}, "Supports")[:2] == ("Results", False)


def test_text_is_never_a_formula_on_the_results_sheet(tmp_path):
    rows = gearbox_rows()
    rows[0][0] = "=1+1"
    rows[1][0] = "=HYPERLINK(\"http://evil.example\",\"x\")"
    source = make_workbook(tmp_path / "book.xlsx", rows=rows)
    workbook = openpyxl.load_workbook(source)
    for cell in (workbook["Supports"]["A3"], workbook["Supports"]["A4"]):
        cell.data_type = "s"  # apostrophe-quoted text, as a designer types '=1+1
        cell.quotePrefix = True
    workbook.save(source)
    copy = tmp_path / "copy.xlsx"
    calc_workbook(source, copy)
    calc_workbook(source, in_place=True)
    for path in (copy, source):
        ws = openpyxl.load_workbook(path)["Results"]
        cells = [ws.cell(3, 2), ws.cell(4, 2)]
        assert [c.value for c in cells] == ["=1+1", "=HYPERLINK(\"http://evil.example\",\"x\")"]
        assert [c.data_type for c in cells] == ["s", "s"]
        assert all(c.quotePrefix for c in cells)


def test_a_copy_keeps_a_sheet_named_results_too(tmp_path):
    case = CASES["user_sheet_named_results"](tmp_path)
    run = calc_workbook(case.path, tmp_path / "copy.xlsx")
    assert run.results_sheet == "Results (2)" and run.notes[0].startswith("sheet 'Results' is not a results sheet")
    copy = openpyxl.load_workbook(tmp_path / "copy.xlsx")
    assert copy["Results"]["A1"].value == "my own results, typed by hand"
    assert calc_workbook(tmp_path / "copy.xlsx", in_place=True).results_sheet == "Results (2)"  # marked in the copy


def test_xstring_escapes():
    assert xstring("a\rb\x00c") == "a_x000D_b_x0000_c"
    assert xstring("_x0041_ and _x41_") == "_x005F_x0041_ and _x41_"
    assert xstring("tab\tand\nnewline & <b>") == "tab\tand\nnewline &amp; &lt;b&gt;"


def test_a_second_run_adds_no_style_and_keeps_the_workbook_part(tmp_path):
    path = make_workbook(tmp_path / "book.xlsx")
    calc_workbook(path, in_place=True)
    styles, workbook = part(path, "xl/styles.xml"), part(path, "xl/workbook.xml")
    calc_workbook(path, in_place=True)
    assert part(path, "xl/styles.xml") == styles and part(path, "xl/workbook.xml") == workbook
    # --formulas adds the hidden copy of the inputs and the formats of the live check, once
    calc_workbook(path, in_place=True, formulas=True)
    styles, workbook, parts = part(path, "xl/styles.xml"), part(path, "xl/workbook.xml"), names(path)
    assert b'name="Calc inputs" sheetId="3" state="hidden" r:id="rId5"/>' in workbook
    assert b'<definedName name="_xlnm.Print_Titles" localSheetId="1">Results!$A:$C,Results!$1:$2</definedName>' \
        in workbook
    assert b'<definedName name="_bearingheat_snapshot_1" hidden="1">\'Calc inputs\'!$1:$1048576</definedName>' \
        in workbook
    assert b'<dxfs count="2"><dxf><font><strike/><color rgb="FF808080"/></font></dxf>' in styles
    calc_workbook(path, in_place=True, formulas=True)
    calc_workbook(path, in_place=True)
    # (the record of the cells written follows the sheet: values only have fewer columns than --formulas)
    record = re.compile(rb'<definedName name="_bearingheat_record_1" hidden="1">[^<]*</definedName>')
    assert part(path, "xl/styles.xml") == styles
    assert record.sub(b"", part(path, "xl/workbook.xml")) == record.sub(b"", workbook)
    assert names(path) == parts
    names_ = openpyxl.load_workbook(path).named_styles
    assert "bearingheat result" in names_ and "bearingheat status ok" in names_


def test_a_new_results_sheet_goes_last_and_no_sheet_moves(tmp_path):
    path = make_workbook(tmp_path / "book.xlsx")
    workbook = openpyxl.load_workbook(path)
    workbook.create_sheet("Notes")["A1"] = "keep me"
    workbook.save(path)
    run = calc_workbook(path, in_place=True)
    book = openpyxl.load_workbook(path)
    assert book.sheetnames == ["Supports", "Notes", "Results"] and run.results_sheet == "Results"
    assert book["Results"].cell(3, 1).style == "bearingheat result"
    status = [c.value for c in book["Results"][1]].index("status") + 1
    assert book["Results"].cell(3, status).style == "bearingheat status ok"


def test_the_template_placeholder_is_filled(tmp_path):
    path = tmp_path / "example.xlsx"
    shutil.copy(EXAMPLE_XLSX, path)
    run = calc_workbook(path, in_place=True)
    assert run.results_sheet == "Results" and run.notes == []
    assert openpyxl.load_workbook(path).sheetnames == ["Supports", "Results", "Instructions", "Lists"]
    # once the designer typed into it, an unmarked sheet is theirs
    other = make_workbook(tmp_path / "typed.xlsx")
    workbook = openpyxl.load_workbook(other)
    typed = workbook.create_sheet("Results")
    typed.append(["row", "id"])
    typed.append(["-", "-"])
    typed["A3"] = "bearingheat calc fills this sheet"
    typed["B4"] = "my note"
    workbook.save(other)
    assert calc_workbook(other, in_place=True).results_sheet == "Results (2)"


def test_calc_chain_entries_of_the_replaced_sheet_are_dropped(tmp_path):
    case = CASES["results_sheet_with_formulas_in_the_calc_chain"](tmp_path)
    calc_workbook(case.path, in_place=True)
    chain = part(case.path, "xl/calcChain.xml").decode()
    assert re.findall(r"<c [^>]*/>", chain) == ['<c r="A1" i="2"/>']
    # only cells of the results sheet: the part goes, with its relationship and content type
    calc_workbook(case.path, in_place=True, formulas=True)
    edit_package(case.path, {"xl/calcChain.xml": lambda d: re.sub(rb'<c r="A1" i="2"/>', b'<c r="M3" i="3"/>', d)})
    calc_workbook(case.path, in_place=True)
    assert "xl/calcChain.xml" not in names(case.path)
    assert b"calcChain" not in part(case.path, "xl/_rels/workbook.xml.rels")
    assert b"calcChain" not in part(case.path, "[Content_Types].xml")


def test_in_place_through_a_symbolic_link_writes_the_real_file(tmp_path):
    real = make_workbook(tmp_path / "real.xlsx")
    link = tmp_path / "link.xlsx"
    link.symlink_to(real)
    calc_workbook(link, in_place=True)
    assert link.is_symlink() and "Results" in openpyxl.load_workbook(real).sheetnames


def test_progress_while_writing_in_place(tmp_path):
    rows = gearbox_rows()
    path = make_workbook(tmp_path / "big.xlsx", rows=[rows[i % len(rows)] for i in range(2100)])

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    stream = Terminal()
    calc_workbook(path, in_place=True, progress=Progress(stream=stream))
    assert "\x1b[2Kreading Supports" in stream.getvalue() and "\x1b[2Kwriting Results" in stream.getvalue()


def test_command_line_in_place_keeps_a_sheet_named_results(tmp_path, capsys):
    case = CASES["user_sheet_named_results"](tmp_path)
    mine = part(case.path, "xl/worksheets/sheet2.xml")
    assert main(["calc", str(case.path), "--in-place"]) == 0
    assert part(case.path, "xl/worksheets/sheet2.xml") == mine
    assert openpyxl.load_workbook(case.path).sheetnames == ["Supports", "Results", "Results (2)"]
    assert "Results (2)" in capsys.readouterr().out


def test_command_line_refusal_leaves_the_file(tmp_path, capsys):
    case = CASES["refused_digitally_signed"](tmp_path)
    before = case.path.read_bytes()
    assert main(["calc", str(case.path), "--in-place"]) == 2
    assert "the workbook is digitally signed" in capsys.readouterr().err
    assert case.path.read_bytes() == before


def test_a_damaged_workbook_is_an_excel_error(tmp_path):
    case = CASES["refused_damaged_part"](tmp_path)
    with pytest.raises(ExcelError, match="damaged workbook, the part xl/workbook.xml cannot be read"):
        calc_workbook(case.path, in_place=True)


@pytest.mark.integration
def test_libreoffice_reads_the_results_written_in_place(tmp_path):
    if soffice() is None:
        if os.environ.get("CI") == "true":
            pytest.fail("CI=true but LibreOffice (soffice) is not installed")
        pytest.skip("LibreOffice (soffice) is not installed")
    case = CASES["validation_and_conditional_formats"](tmp_path)
    run = calc_workbook(case.path, in_place=True)
    (converted,) = convert([case.path], "xlsx", tmp_path / "lo")
    ws = openpyxl.load_workbook(converted, data_only=True)["Results"]
    header = [c.value for c in ws[1]]
    mr = [ws.cell(r, header.index("MR") + 1).value for r in range(3, 3 + len(run.result))]
    assert mr == pytest.approx(list(run.result["MR [N*mm]"]), rel=1e-12)
    assert [ws.cell(r, 2).value for r in range(3, 3 + len(run.result))] == list(run.result["id"])


def test_type_and_series_filled_in_later_do_not_move_the_results(tmp_path):
    """type and series go after the results: filled in on a re-run, MR stays in the column the designer's
    =SUM(Results!K3:K5) reads."""
    header, units = [*HEADER_PLAIN, "type", "series"], [*UNITS_PLAIN, "-", "-"]
    path = make_workbook(tmp_path / "ts.xlsx", header, units, [[*row, None, None] for row in gearbox_rows()])
    calc_workbook(path, in_place=True)
    before = [c.value for c in openpyxl.load_workbook(path)["Results"][1]]
    workbook = openpyxl.load_workbook(path)
    for row in range(3, workbook["Supports"].max_row + 1):
        workbook["Supports"].cell(row, len(header) - 1).value = "deep_groove_ball"
        workbook["Supports"].cell(row, len(header)).value = "62"
    workbook.save(path)
    run = calc_workbook(path, in_place=True)
    after = [c.value for c in openpyxl.load_workbook(path)["Results"][1]]
    assert after == before + ["type", "series"] and run.notes == []


def test_columns_that_moved_and_their_readers_are_named(tmp_path):
    """A viscosity from the oil's grade adds nu_used and nu_at before n_thr: the note names the columns that
    moved and the formula and defined name that read the results sheet by letter."""
    path = make_workbook(tmp_path / "moved.xlsx")
    calc_workbook(path, in_place=True)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    ws["H1"], ws["H2"], ws["N1"], ws["N2"] = "iso_vg", "1", "T_bearing", "degC"
    for row in range(3, ws.max_row + 1):
        ws.cell(row, 8).value, ws.cell(row, 14).value = 46, 70
    workbook.create_sheet("Summary")["B1"] = "=SUM(Results!M3:M8)"
    workbook.defined_names["n_thr_all"] = openpyxl.workbook.defined_name.DefinedName(
        "n_thr_all", attr_text="Results!$M$3:$M$8")
    workbook.save(path)
    run = calc_workbook(path, in_place=True)
    assert run.notes == ["the columns of sheet 'Results' changed since the last run: n_thr (M -> O), status "
                         "(N -> P), message (O -> Q); the name n_thr_all, Summary!B1 refer to sheet 'Results' "
                         "and may now read other quantities: check them"]


def _hand_edit(path, edit):
    workbook = openpyxl.load_workbook(path)
    edit(workbook["Results"])
    workbook.save(path)


def _refusal(path) -> str:
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path, in_place=True)
    return str(exc.value)


def test_what_the_designer_typed_on_the_results_sheet_is_refused_not_lost(tmp_path):
    """A note beside the results, a sign-off below them, a changed result, a tab colour or a conditional format of
    the designer's: a re-run refuses, naming the first foreign cell, and leaves the file as it was; a sheet only
    opened and saved (here by openpyxl, which rewrites every number and string) is replaced."""
    path = make_workbook(tmp_path / "book.xlsx")
    calc_workbook(path, in_place=True)
    _hand_edit(path, lambda ws: None)
    assert calc_workbook(path, in_place=True).notes == []
    _hand_edit(path, lambda ws: (ws.cell(3, 16, "checked JS"), ws.cell(10, 1, "Reviewer sign-off: ____")))
    before = path.read_bytes()
    assert _refusal(path) == (f"{path}: Results!P3 holds 'checked JS' that bearingheat did not write; move it to "
                              "another sheet or run with -o to write a copy; the file is unchanged")
    assert path.read_bytes() == before
    _hand_edit(path, lambda ws: setattr(ws["P3"], "value", None))
    assert "Results!A10 holds 'Reviewer sign-off: ____' that bearingheat did not write" in _refusal(path)
    # into a copy the results go, with a note: the workbook keeps the sign-off
    run = calc_workbook(path, tmp_path / "copy.xlsx")
    assert run.notes == [f"Results!A10 holds 'Reviewer sign-off: ____' that bearingheat did not write; the copy "
                         f"{tmp_path / 'copy.xlsx'} has the results sheet without it (the workbook keeps it)"]
    _hand_edit(path, lambda ws: setattr(ws["A10"], "value", None))
    calc_workbook(path, in_place=True)
    edited = ("C4 changed", lambda ws: ws.cell(4, 3, 1.0)), \
        ("tab colour", lambda ws: setattr(ws.sheet_properties, "tabColor", "FF0000")), \
        ("conditional format", lambda ws: ws.conditional_formatting.add(
            "K3:K8", openpyxl.formatting.rule.CellIsRule(operator="greaterThan", formula=["100"])))
    for what, edit in edited:
        shutil.copyfile(path, tmp_path / "edited.xlsx")
        _hand_edit(tmp_path / "edited.xlsx", edit)
        assert _refusal(tmp_path / "edited.xlsx") == (
            f"{tmp_path / 'edited.xlsx'}: sheet 'Results' was edited since bearingheat wrote it: what "
            "Results!A1:O8 holds (a value, a formula, a conditional format, a validation, merged cells or the tab "
            "colour) differs from what bearingheat wrote; move your edits to another sheet or run with -o to write "
            "a copy; the file is unchanged"), what


def test_a_results_sheet_without_a_record_is_checked_beyond_its_table(tmp_path):
    """A results sheet of an earlier version has no record of its cells: a cell beyond its table (right of the
    header row, below the last row of column A) is refused; without one it is replaced, once, with a note."""
    path = make_workbook(tmp_path / "old.xlsx")
    calc_workbook(path, in_place=True)
    workbook = openpyxl.load_workbook(path)
    del workbook.defined_names["_bearingheat_record_1"]
    workbook["Results"]["P3"] = "checked JS"
    workbook.save(path)
    assert "Results!P3 holds 'checked JS' that bearingheat did not write" in _refusal(path)
    _hand_edit(path, lambda ws: setattr(ws["P3"], "value", None))
    assert calc_workbook(path, in_place=True).notes == [
        "sheet 'Results' has no record of the cells bearingheat wrote (an earlier version wrote it): nothing was "
        "found beyond its table, and it was replaced; edits inside the table cannot be told from bearingheat's own "
        "cells. From now on any edit of it is found"]
    assert calc_workbook(path, in_place=True).notes == []


def _as_others_write(part: bytes) -> bytes:
    """A worksheet part as other programs write it: the main namespace with a prefix (x:c), the attributes of a
    cell in another order (t and s before r), an empty cell with an end tag instead of self-closing."""
    text = part.decode()
    text = text.replace('<worksheet xmlns="', '<x:worksheet xmlns:x="').replace("</worksheet>", "</x:worksheet>")
    text = re.sub(r"<(/?)(?!x:)([A-Za-z]+)(?=[\s>/])", r"<\1x:\2", text)
    text = re.sub(r'<x:c r="([A-Z]+\d+)" s="(\d+)"( t="\w+")?', r'<x:c\3 s="\2" r="\1"', text)
    return re.sub(r'<x:c ([^>]*?)/>', r"<x:c \1></x:c>", text).encode()


def test_the_record_made_while_writing_equals_the_sheet_read_back(tmp_path):
    """The record's range and digest are made as the cells are written (WrittenCells); read back from the part
    written, on the sheet of values and on the --formulas sheet (live and status formulas, a conditional format), and
    on the same part as other programs write it, the cells give the same range and digest."""
    path = make_workbook(tmp_path / "book.xlsx")
    for formulas in (False, True):
        out = tmp_path / f"out_{formulas}.xlsx"
        calc_workbook(path, out, formulas=formulas)
        recorded = record.parse_record(openpyxl.load_workbook(out).defined_names["_bearingheat_record_1"].attr_text)
        written = part(out, results_part(out, "Results"))
        for data in (written, _as_others_write(written)):
            cells = record.read_cells(data)
            assert (cells.extent, cells.digest(cells.extent)) == recorded
        assert recorded[0] == ("A1:V10" if formulas else "A1:O8")  # (--formulas: the check in A10)
        assert (b"<f>" in written) == formulas and (b"cfRule" in written) == formulas
    # every kind of cell: text to escape, look-alikes of _xHHHH_, spaces, a formula-like text, booleans, dates,
    # integers, NaN and infinity (no value), a number with 17 digits, empty text
    table = pd.DataFrame({"id": ["a<b & c", "_x0041_ \x01", "  padded  ", "two\nlines", "=HYPERLINK(1)", ""],
                          "flag": [True, False, None, True, False, True],
                          "when": pd.to_datetime(["2024-05-01 00:00", "2024-05-02 13:30", None, "1900-03-01 00:00",
                                                  "2024-01-01 00:00", "2024-01-01 00:00"]),
                          "n [1/min]": [1480, 0, -3, 7, 2**60, 12],
                          "MR [N*mm]": [0.1 + 0.2, np.nan, np.inf, 1e-300, 138.47817095928783, -0.0]})
    written_cells = record.WrittenCells()
    data = sheetxml.results_sheet_xml(table, lambda *args, **kwargs: 0, formulas={("MR [N*mm]", 5): "=1+1"},
                                      written=written_cells, tab_color=None)
    for form in (data, _as_others_write(data)):
        cells = record.read_cells(form)
        assert (cells.extent, cells.digest(cells.extent)) == (written_cells.extent, written_cells.digest())
    assert written_cells.extent == "A1:E8"
    assert written_cells.record() == record.record_value("A1:E8", written_cells.digest())
