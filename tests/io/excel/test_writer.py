"""Writing results sheets: header and units rows, extra columns, the pint-pandas round trip, other sheets kept."""
from __future__ import annotations

import re

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import add_zip_part, csv_result, make_workbook

from bearingheat.errors import ExcelError, WorkbookContentError
from bearingheat.io.excel.reader import read_supports, with_units
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.excel.writer import write_results, write_results_workbook


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


def test_write_results_refuses_a_workbook_openpyxl_would_not_keep_as_it_is(tmp_path):
    """write_results rewrites an existing workbook with openpyxl: pivot parts (dropped) refuse it, named."""
    path = make_workbook(tmp_path / "pivot.xlsx")
    add_zip_part(path, "xl/pivotTables/pivotTable1.xml")
    before = path.read_bytes()
    message = (f"{path}: write_results refused, rewriting the workbook would lose or alter its pivot tables (openpyxl "
               "cannot keep them as they are); the file is unchanged. Write the results to a new workbook with -o "
               "OUTPUT.xlsx instead")
    with pytest.raises(WorkbookContentError, match=f"^{re.escape(message)}$"):
        write_results(pd.DataFrame({"x [mm]": [1.0]}), path, sheet="Notes")
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
    assert sorted(workbook.defined_names) == ["_bearingheat_input_1", "_bearingheat_results_1",
                                              "_bearingheat_table_1"]
