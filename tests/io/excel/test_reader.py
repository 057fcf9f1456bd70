"""Reading supports from a sheet: header and units rows, merged cells, cached formula values, messages citing cells."""
from __future__ import annotations

import re

import numpy as np
import openpyxl
import pandas as pd
import pytest
from workbook_corpus import edit_package
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX, HEADER, UNITS, csv_result, gearbox_rows, make_workbook, \
    set_cached_value

from bearingheat.errors import ExcelError
from bearingheat.io.excel.reader import read_supports
from bearingheat.io.excel.workbook import calc_workbook


def test_read_example_gives_rows_units_and_cells():
    table, info = read_supports(EXAMPLE_XLSX)
    assert info.sheet == "Supports" and info.header_row == 1 and info.units_row == 2
    assert info.rows == [3, 4, 5, 6, 7, 8]
    assert info.units["Fr"] == "kN" and info.units["n"] == "rpm" and info.units["nu"] == "mm^2/s"
    assert info.cell("Fr", 4) == "Supports!F7"
    assert info.cell("designation", 0) == "Supports!B3"
    csv = pd.read_csv(EXAMPLE_CSV)
    assert table["designation"].tolist() == csv["designation"].tolist()
    np.testing.assert_array_equal(table["Fr"].to_numpy(), csv["Fr [kN]"].to_numpy())


def test_empty_rows_are_skipped(tmp_path):
    rows = gearbox_rows()
    blank = [None] * len(HEADER)
    spaces = ["  "] + [None] * (len(HEADER) - 1)
    path = make_workbook(tmp_path / "gaps.xlsx", rows=[rows[0], blank, rows[1], spaces, blank, rows[2]])
    table, info = read_supports(path)
    assert info.rows == [3, 5, 8]
    assert table["designation"].tolist() == ["6208", "NU208-E", "30208-A"]
    assert (calc_workbook(path).result["status"] == "ok").all()


@pytest.mark.parametrize("spelling", ["1/min", "min^-1", "rpm", "U/min", " rpm ", "r/min"])
def test_speed_unit_spellings(tmp_path, spelling):
    units = list(UNITS)
    units[HEADER.index("n")] = spelling
    path = make_workbook(tmp_path / "n.xlsx", units=units)
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_hz_and_lbf_are_honoured(tmp_path):
    rows = gearbox_rows()
    units = list(UNITS)
    units[HEADER.index("n")] = "Hz"
    units[HEADER.index("Fr")] = "lbf"
    units[HEADER.index("Fa")] = "N"
    lbf = 4.4482216152605
    converted = []
    for row in rows:
        row = list(row)
        row[4] = row[4] / 60.0
        row[5] = row[5] * 1000.0 / lbf
        row[6] = row[6] * 1000.0
        converted.append(row)
    path = make_workbook(tmp_path / "lbf.xlsx", units=units, rows=converted)
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-9)


def test_units_in_headers_without_units_row_and_trailing_spaces(tmp_path):
    header = ["id ", "designation", "d [mm]", "D [mm] ", "n [U/min]", "Fr [kN]", "Fa [kN]", "nu [cSt]",
              " lubrication", "arrangement", "C0 [kN]", "Y", "Y0"]
    path = make_workbook(tmp_path / "headers.xlsx", header=header, units=None)
    table, info = read_supports(path)
    assert info.units_row is None and info.rows[0] == 2
    assert "D [mm]" in table.columns and "lubrication" in table.columns
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_merged_header_cells_and_title_rows(tmp_path):
    path = tmp_path / "merged.xlsx"
    workbook = openpyxl.Workbook()
    ws = workbook.active
    ws.title = "Shaft 1"
    ws["A1"] = "Gearbox G-17, intermediate shaft"
    ws.merge_cells("A1:F1")
    ws.append([])  # row 2 blank
    # row 3: the header; text columns merged down over the units row (row 4); 'Loads' above Fr, Fa
    header = ["id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication", "arrangement", "C0", "Y", "Y0"]
    for col, name in enumerate(header, start=1):
        ws.cell(3, col, name)
    for col, unit in enumerate(UNITS, start=1):
        if unit != "-":
            ws.cell(4, col, unit)
    for letter in "ABIJ":
        ws.merge_cells(f"{letter}3:{letter}4")
    for i, row in enumerate(gearbox_rows(), start=5):
        for col, value in enumerate(row, start=1):
            ws.cell(i, col, value)
    workbook.save(path)
    table, info = read_supports(path)
    assert (info.header_row, info.units_row, info.rows[0]) == (3, 4, 5)
    assert "designation" not in info.units and info.units["Fr"] == "kN"
    assert info.cell("Fr", 0) == "'Shaft 1'!F5"
    run = calc_workbook(path, tmp_path / "out.xlsx")
    assert run.results_sheet == "Shaft 1 results"
    np.testing.assert_allclose(run.result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_a_formula_saved_with_an_empty_text_is_a_blank_cell(tmp_path):
    """=IF(...,"",...) saved by Excel or LibreOffice holds an empty text (t="str", an empty <v>): a blank cell, as
    typed blank (Fa not given: 0); a formula never saved is still refused."""
    rows = gearbox_rows()
    rows[0][6] = '=""'
    path = make_workbook(tmp_path / "empty_text.xlsx", rows=rows)
    result = calc_workbook(path).result
    assert result["message"].iat[0].startswith("Supports!G3: formula =\"\" has no saved value")
    edit_package(path, {"xl/worksheets/sheet1.xml": lambda data: re.sub(
        rb'<c r="G3"([^>]*)><f>([^<]*)</f><v\s*/?>(</v>)?', rb'<c r="G3"\1 t="str"><f>\2</f><v></v>', data)})
    rows[0][6] = None
    blank = calc_workbook(make_workbook(tmp_path / "blank.xlsx", rows=rows)).result
    result = calc_workbook(path).result
    assert result["status"].iat[0] == blank["status"].iat[0] == "ok"
    assert result["MR [N*mm]"].iat[0] == blank["MR [N*mm]"].iat[0]


def test_formula_with_saved_value_is_read(tmp_path):
    rows = gearbox_rows()
    rows[1][4] = "=E3"
    path = make_workbook(tmp_path / "cached.xlsx", rows=rows)
    set_cached_value(path, 1, "E4", "1480")
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_header_unit_contradicting_units_row(tmp_path):
    header = list(HEADER)
    header[HEADER.index("Fr")] = "Fr [N]"
    path = make_workbook(tmp_path / "twice.xlsx", header=header)
    with pytest.raises(ExcelError, match=re.escape(
            "Supports!F2: unit 'kN' contradicts the header 'Fr [N]'; keep one of them")):
        read_supports(path)


@pytest.mark.parametrize("column, header, unit", [("n", "n [rpm]", "1/min"), ("nu", "nu [mm^2/s]", "cSt"),
                                                  ("Fr", "Fr [kN]", "kN")])
def test_one_unit_spelled_two_ways_does_not_contradict(tmp_path, column, header, unit):
    """rpm and 1/min, cSt and mm^2/s are the same unit: the header and the units row agree."""
    headers, units = list(HEADER), list(UNITS)
    headers[HEADER.index(column)], units[HEADER.index(column)] = header, unit
    result = calc_workbook(make_workbook(tmp_path / "same.xlsx", header=headers, units=units)).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_sheet_without_header_row(tmp_path):
    path = make_workbook(tmp_path / "none.xlsx", header=["a", "b"], units=None, rows=[[1, 2]])
    with pytest.raises(ExcelError, match=re.escape(
            "sheet 'Supports': no header row in rows 1-20; a header row names the columns, e.g. designation, "
            "d, D, n, Fr, nu (docs/excel.md lists them)")):
        read_supports(path)
    path = make_workbook(tmp_path / "none.xlsx", header=["a", "b"], units=None, rows=[[1, 2]], sheet="Sheet1")
    with pytest.raises(ExcelError, match=re.escape(
            "none.xlsx: no sheet has a header row of supports (designation, d, D, n, Fr, nu ...); "
            "name the sheet with --sheet")):
        read_supports(path)


def test_unknown_sheet(tmp_path):
    path = make_workbook(tmp_path / "s.xlsx")
    with pytest.raises(ExcelError, match=re.escape("s.xlsx has no sheet 'Loads'; its sheets are Supports")):
        read_supports(path, sheet="Loads")


def test_duplicate_header(tmp_path):
    header = HEADER + ["Fr"]
    path = make_workbook(tmp_path / "dup.xlsx", header=header, units=UNITS + ["kN"],
                         rows=[r + [1] for r in gearbox_rows()])
    with pytest.raises(ExcelError, match=re.escape("Supports!N1: column 'Fr' appears twice (also in column F)")):
        read_supports(path)


def test_not_a_workbook(tmp_path):
    path = tmp_path / "fake.xlsx"
    path.write_text("id,designation\n")
    with pytest.raises(ExcelError, match=re.escape(f"{path}: not a readable Excel workbook")):
        read_supports(path)


def test_a_workbook_part_that_is_not_xml_is_a_damaged_workbook(tmp_path):
    """openpyxl's parser error (lxml's XMLSyntaxError) becomes an ExcelError naming the file, for a copy too."""
    path = make_workbook(tmp_path / "damaged.xlsx")
    edit_package(path, {"xl/workbook.xml": b"<workbook><sheets"})
    message = (f"{path}: damaged workbook, a part is not well-formed XML (Couldn't find end of Start Tag sheets "
               "line 1, line 1, column 18 (<string>, line 1))")
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        read_supports(path)
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        calc_workbook(path, tmp_path / "copy.xlsx")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["damaged.xlsx"]


def test_messages_of_a_table_of_two_models_name_their_own_cells(tmp_path):
    """Rows of each friction model are computed as a table of their own; their messages still name the cell of
    their row on the sheet (row 4 is the skf row, row 5 the second schaeffler row)."""
    header = ["designation", "model", "d", "D", "n", "Fr", "Fa", "nu", "lubrication"]
    units = ["-", "-", "mm", "mm", "rpm", "kN", "kN", "mm^2/s", "-"]
    rows = [["6208", "schaeffler", 40, 80, 1000, 1.0, 0, 20, "oil_bath"],
            ["6208", "skf", 40, 80, 1000, 1.0, 0, 20, "oil_bath"],
            ["6208", "schaeffler", 40, 80, 1000, 1.0, 0, -1, "oil_bath"]]
    path = make_workbook(tmp_path / "models.xlsx", header, units, rows)
    result = calc_workbook(path).result
    assert list(result["status"]) == ["ok", "error", "error"]
    assert result["message"][1].startswith("Supports row 4 oil_level [mm]: missing; an oil bath needs the oil level")
    assert result["message"][2].startswith("Supports!H5 nu [mm^2/s]: -1 must be > 0; ")


def test_row_messages_name_the_cell_of_their_column(tmp_path):
    """Messages of the bearing keys, the model name and the heat balance begin with the cell to fix, as the
    friction model's own messages do (a blank cell of a column the sheet has, or the row where it has none)."""
    header = ["id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication", "arrangement", "T_amb", "model",
              "B", "T", "n_G"]
    units = ["-", "-", "mm", "mm", "1/min", "kN", "kN", "mm^2/s", "-", "-", "degC", "-", "mm", "mm", "1/min"]
    good = ["6208", 40, 80, 1480, 3.2, 0.9, 40]
    rows = [["x", *good, "Oil_Bath", None, 20, None, 18],
            ["y", *good, None, None, 20, None, 18],
            ["z", *good, "oil_bath", "triple", 20, None, 18],
            ["m", *good, "oil_bath", None, 20, "foo", 18],
            ["q", "XYZ123", *good[1:], "oil_bath", None, 20, None, 18],
            ["t", *good, "oil_bath", None, None, None, 18],
            ["w", *good, "oil_bath", None, 20, None, 18, None, -5]]
    result = calc_workbook(make_workbook(tmp_path / "cells.xlsx", header, units, rows)).result
    messages = result["message"].tolist()
    assert messages[0] == "Supports!I3 lubrication: 'Oil_Bath' is not one of grease, oil_mist, oil_bath, circulating_oil"
    assert messages[1] == "Supports!I4 lubrication: missing; expected one of grease, oil_mist, oil_bath, circulating_oil"
    assert messages[2] == "Supports!J5 arrangement: 'triple' is not one of single, paired"
    assert messages[3] == "Supports!L6 model: 'foo' is not one of schaeffler, skf"
    assert messages[4].startswith("Supports!B7 designation: 'XYZ123' matches no row of the Schaeffler catalogue")
    assert messages[5].startswith("Supports!K8 T_amb [degC]: missing; the heat balance (T_op, n_per) needs the ")
    assert "Supports!O9 n_G [1/min]: -5 must be > 0" in messages[6].split("; ")
    assert result["status"].tolist() == ["error"] * 5 + ["warning", "error"]


def test_merged_cells_over_rows_of_supports_are_refused(tmp_path):
    """A load merged over two rows shows 3.2 on both, but the second row holds no value (it would be 0 kN)."""
    path = make_workbook(tmp_path / "merged.xlsx")
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    ws["F4"] = None
    ws.merge_cells("F3:F4")
    ws.merge_cells("N3:P5")  # a note of the designer's beside the table: not read, not refused
    workbook.save(path)
    message = ("Supports!F3:F4: merged cells among the rows of supports; the sheet shows their value on every row, "
               "but only F3 holds it, so the other rows would read as blank. Unmerge them and give each row its own "
               "value")
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        read_supports(path)
    workbook["Supports"].unmerge_cells("F3:F4")
    workbook["Supports"]["F4"] = 3.2
    workbook.save(path)
    table, _ = read_supports(path)
    assert table["Fr"].tolist()[:2] == [3.2, 3.2]


def test_hidden_rows_are_computed_and_said(tmp_path, capsys):
    """A row hidden by hand or by a filter is a support like the others; the run says so instead of silently
    computing what the designer does not see."""
    path = make_workbook(tmp_path / "hidden.xlsx")
    workbook = openpyxl.load_workbook(path)
    for row in (4, 6):
        workbook["Supports"].row_dimensions[row].hidden = True
    workbook.save(path)
    run = calc_workbook(path)
    assert len(run.result) == len(gearbox_rows())
    assert run.notes == ["rows 4, 6 of sheet 'Supports' are hidden (by hand or by a filter) and computed like the "
                         "others; delete them to leave them out"]
    from bearingheat.cli import main
    assert main(["calc", str(path), "-o", str(tmp_path / "out.xlsx")]) == 0
    assert capsys.readouterr().err.splitlines()[0] == f"note: {run.notes[0]}"
