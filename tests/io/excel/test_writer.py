"""Writing results sheets: header and units rows, extra columns, the pint-pandas round trip, other sheets kept."""
from __future__ import annotations

import datetime
import re
import zipfile

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import (chart_workbook, csv_result, make_workbook, pivot_workbook, require_soffice,
                           vba_workbook)
from openpyxl.chart import BarChart, Reference

from bearingheat.errors import ExcelError, SheetContentError, WorkbookLockedError
from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.reader import read_supports, with_units
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.excel.writer import write_results, write_results_workbook


def zip_parts(path) -> dict[str, bytes]:
    with zipfile.ZipFile(path) as archive:
        return {info.filename: archive.read(info.filename) for info in archive.infolist()}


def test_extra_result_columns_are_written_generically(tmp_path):
    frame = pd.DataFrame({"id": ["a", "b"], "MR [N*mm]": [1.5, 2.5], "T_op [degC]": [61.0, np.nan],
                          "Q_oil [W]": [3.0, 4.0], "regime": ["dry", "wet"], "status": ["ok", "error"],
                          "message": ["", "x"]})
    path = write_results(frame, tmp_path / "extra.xlsx")
    ws = openpyxl.load_workbook(path)["Results"]
    assert [c.value for c in ws[1]] == ["id", "MR", "T_op", "Q_oil", "regime", "status", "message"]
    assert [c.value for c in ws[2]] == ["-", "N*mm", "degC", "W", "-", "-", "-"]
    assert [c.value for c in ws[4]] == ["b", 2.5, None, 4.0, "wet", "error", "x"]


def test_pint_dataframe_round_trip(tmp_path):
    pytest.importorskip("pint_pandas")
    frame = pd.DataFrame({
        "id": ["input A", "input B"],
        "designation": ["6208", "NU208-E"],
        "d": pd.Series([40.0, 40.0], dtype="pint[mm]"),
        "Fr": pd.Series([3.2, 4.1], dtype="pint[kN]"),
        "n": pd.Series([1480.0, 1480.0], dtype="pint[rpm]"),
        "nu": pd.Series([40.0, 22.5], dtype="pint[mm^2/s]"),
        "Y": [np.nan, 1.6],
        "count": [1, 2],
    })
    path = write_results(frame, tmp_path / "pint.xlsx", sheet="Supports")
    table, info = read_supports(path, sheet="Supports")
    assert info.units == {"id": "-", "designation": "-", "d": "mm", "Fr": "kN", "n": "rpm", "nu": "mm^2/s",
                          "Y": "1", "count": "1"}
    back = with_units(table, info.units)
    pd.testing.assert_frame_equal(back, frame)


def test_write_results_keeps_other_sheets(tmp_path):
    path = make_workbook(tmp_path / "keep.xlsx")
    write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Notes")
    workbook = openpyxl.load_workbook(path)
    assert workbook.sheetnames == ["Supports", "Notes"]
    assert workbook["Supports"]["B3"].value == "6208"


def test_results_of_a_csv_go_to_a_new_xlsx_only(tmp_path):
    with pytest.raises(ExcelError, match=re.escape(f"{tmp_path / 'r.xlsm'}: results of a CSV are written to a "
                                                   "new .xlsx workbook")):
        write_results_workbook(csv_result(), tmp_path / "r.xlsm")
    assert not (tmp_path / "r.xlsm").exists()


def test_write_results_keeps_every_other_part_byte_for_byte(tmp_path):
    """An existing workbook is edited part by part (as calc --in-place edits it): pivot tables, charts and macros
    that openpyxl would drop or redraw are kept as they are (the corpus test runs this on 56 workbooks)."""
    for build, name in ((pivot_workbook, "pivot.xlsx"), (chart_workbook, "chart.xlsx"), (vba_workbook, "vba.xlsm")):
        path = build(tmp_path / name)
        before = zip_parts(path)
        write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Loads")
        after = zip_parts(path)
        changed = {part for part in before if after[part] != before[part]}
        assert changed <= {"xl/workbook.xml", "xl/_rels/workbook.xml.rels", "[Content_Types].xml", "xl/styles.xml"}
        assert set(after) - set(before) == {"xl/worksheets/sheet2.xml"}
        assert openpyxl.load_workbook(path).sheetnames == ["Supports", "Loads"]


def test_a_table_sheet_looks_the_same_in_a_new_and_in_an_existing_workbook(tmp_path):
    """openpyxl's writer (a new workbook) and the part edit (an existing one) render one layout: headers, units,
    values, formulas, named styles, number formats, widths, frozen panes."""
    frame = pd.DataFrame({"designation": ["6208", "=6209"], "Fr [kN]": [3.2, 4.1], "MR [N*mm]": [138.48, 1.5],
                          "NR [W]": [np.nan, 2.25], "status": ["ok", "error"], "message": ["", "x" * 140],
                          "inspected": [pd.Timestamp("2024-05-01"), pd.NaT],
                          "logged": [datetime.datetime(2024, 5, 1, 8, 30), datetime.datetime(2024, 5, 2)]})
    options = dict(sheet="Loads", input_columns=["designation", "Fr [kN]"],
                   formulas={("NR [W]", 0): "=C3*1480/9550"})
    fresh = write_results(frame, tmp_path / "new.xlsx", **options)
    existing = write_results(frame, make_workbook(tmp_path / "existing.xlsx"), **options)

    def shown(path):
        ws = openpyxl.load_workbook(path)["Loads"]
        cells = [[(c.value, c.data_type if c.value is not None else None, c.style, c.number_format,
                   bool(c.quotePrefix)) for c in row] for row in ws.iter_rows()]
        widths = {k: d.width for k, d in ws.column_dimensions.items()}
        return cells, widths, ws.freeze_panes, ws.row_dimensions[4].height

    assert shown(existing) == shown(fresh)
    cells = shown(existing)[0]
    assert [c[2] for c in cells[0]] == ["bearingheat header"] * 2 + ["bearingheat result header"] * 6
    assert cells[2][6][0] == datetime.datetime(2024, 5, 1) and cells[2][6][3] == "yyyy-mm-dd"  # Excel dates
    assert cells[2][7][0] == datetime.datetime(2024, 5, 1, 8, 30) and cells[2][7][3] == "yyyy-mm-dd hh:mm:ss"
    assert cells[2][3][:2] == ("=C3*1480/9550", "f")
    assert cells[3][0][:2] == ("=6209", "s") and cells[3][0][4]
    assert b'fullCalcOnLoad="1"' in zip_parts(existing)["xl/workbook.xml"]


def test_dates_follow_the_date_system_of_the_workbook(tmp_path):
    """A workbook saved with the 1904 date system counts its date cells from 1904: a date written into it shows
    the same day as in a 1900 workbook."""
    path = make_workbook(tmp_path / "mac.xlsx")
    workbook = openpyxl.load_workbook(path)
    workbook.epoch = openpyxl.utils.datetime.CALENDAR_MAC_1904
    workbook.save(path)
    write_results(pd.DataFrame({"inspected": [datetime.date(2024, 5, 1)]}), path, sheet="Dates")
    assert openpyxl.load_workbook(path)["Dates"]["A3"].value == datetime.datetime(2024, 5, 1)
    assert b'date1904="1"' in zip_parts(path)["xl/workbook.xml"]


def test_write_results_refuses_a_sheet_it_wrote_that_now_holds_a_chart(tmp_path):
    path = make_workbook(tmp_path / "book.xlsx")
    write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Loads")
    workbook = openpyxl.load_workbook(path)
    chart = BarChart()
    chart.add_data(Reference(workbook["Loads"], min_col=1, min_row=3, max_row=3))
    workbook["Loads"].add_chart(chart, "C2")
    workbook.save(path)
    before = path.read_bytes()
    message = (f"{path}: write_results refused, sheet 'Loads' (a sheet bearingheat wrote) now holds charts, images "
               "or shapes that replacing it would lose; move them to another sheet or delete the sheet, then run "
               "again; the file is unchanged. Write the table to a new workbook instead")
    with pytest.raises(SheetContentError, match=f"^{re.escape(message)}$"):
        write_results(pd.DataFrame({"x [mm]": [2.0]}), path, sheet="Loads")
    assert path.read_bytes() == before


@pytest.mark.parametrize("sheet, problem", [
    ("Loads/2", "has the character '/', which Excel does not allow in a sheet name (none of \\ / ? * : [ ])"),
    ("x" * 32, "has 32 characters; Excel allows at most 31"),
    ("'Loads'", "begins or ends with an apostrophe, which Excel does not allow"),
    ("history", "is reserved by Excel (for a shared workbook's change history)"),
    (" ", "is blank; a sheet needs a name"),
])
def test_write_results_refuses_a_sheet_name_excel_would_not_take(tmp_path, sheet, problem):
    path = make_workbook(tmp_path / "book.xlsx")
    before = path.read_bytes()
    for target in (path, tmp_path / "new.xlsx"):
        message = f"{target}: sheet name {sheet!r} {problem}; nothing was written"
        with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
            write_results(pd.DataFrame({"x [mm]": [1.0]}), target, sheet=sheet)
    assert path.read_bytes() == before and not (tmp_path / "new.xlsx").exists()


def test_write_results_waits_for_excel_to_close_the_workbook(tmp_path):
    path = make_workbook(tmp_path / "book.xlsx")
    (tmp_path / "~$book.xlsx").write_bytes(b"")
    before = path.read_bytes()
    message = f"{path} is open in Excel (lock file ~$book.xlsx); close it and run again"
    with pytest.raises(WorkbookLockedError, match=f"^{re.escape(message)}$"):
        write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Loads")
    assert path.read_bytes() == before


def test_write_results_never_replaces_a_sheet_of_the_designer(tmp_path):
    """A sheet the designer made is kept whatever the case of the name asked for; the file is unchanged."""
    path = make_workbook(tmp_path / "mine.xlsx")
    before = path.read_bytes()
    for asked in ("Supports", "SUPPORTS"):
        message = (f"{path}: sheet 'Supports' is not a sheet bearingheat wrote (it has no bearingheat mark), so it "
                   "is kept; the file is unchanged. Write the table to a sheet of another name")
        with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
            write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet=asked)
        assert path.read_bytes() == before


def test_write_results_replaces_the_sheet_it_wrote(tmp_path):
    """A second write to the same sheet replaces it in place (its mark says bearingheat wrote it); so does a
    write to calc's results sheet; the designer's sheets stay."""
    path = make_workbook(tmp_path / "book.xlsx")
    write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Loads")
    write_results(pd.DataFrame({"x [mm]": [2.0, 3.0]}), path, sheet="loads")
    workbook = openpyxl.load_workbook(path)
    assert workbook.sheetnames == ["Supports", "Loads"]
    assert [c.value for c in workbook["Loads"]["A"]] == ["x", "mm", 2.0, 3.0]
    assert {name: d.attr_text for name, d in workbook.defined_names.items()} == \
        {"_bearingheat_table_1": "Loads!$1:$1048576"}
    calc_workbook(path, in_place=True)  # the results sheet 'Results', marked by calc
    write_results(pd.DataFrame({"x [mm]": [4.0]}), path, sheet="Results")
    workbook = openpyxl.load_workbook(path)
    assert workbook.sheetnames == ["Supports", "Loads", "Results"]
    assert workbook["Results"]["A3"].value == 4.0
    assert sorted(workbook.defined_names) == ["_bearingheat_input_1", "_bearingheat_record_1",
                                              "_bearingheat_results_1", "_bearingheat_table_1"]


@pytest.mark.integration
def test_libreoffice_recalculates_a_table_written_into_an_existing_workbook(tmp_path):
    """The designer's formula that reads the table and the table's own formula are computed when the workbook is
    opened (fullCalcOnLoad): LibreOffice, headless, recalculates them."""
    require_soffice()
    path = make_workbook(tmp_path / "book.xlsx")
    workbook = openpyxl.load_workbook(path)
    workbook["Supports"]["P1"] = "=SUM(Loads!B3:B4)"  # the designer's formula over the table to come
    workbook.save(path)
    frame = pd.DataFrame({"id": ["a", "b"], "Fr [kN]": [3.5, 1.25], "P [kW]": [np.nan, np.nan]})
    write_results(frame, path, sheet="Loads", formulas={("P [kW]", 0): "=B3*2", ("P [kW]", 1): "=B4*2"})
    (converted,) = convert([path], "xlsx", tmp_path / "lo")
    values = openpyxl.load_workbook(converted, data_only=True)
    assert values["Supports"]["P1"].value == pytest.approx(4.75, rel=1e-15)
    assert [values["Loads"][f"C{r}"].value for r in (3, 4)] == pytest.approx([7.0, 2.5], rel=1e-15)
