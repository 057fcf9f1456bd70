"""calc on a workbook: results equal the CSV's, messages that cite cells, the results sheet, the progress bar."""
from __future__ import annotations

import io

import numpy as np
import openpyxl
import pytest
from excel_helpers import EXAMPLE_XLSX, HEADER, UNITS, csv_result, gearbox_rows, make_workbook

from bearingheat.errors import ExcelError
from bearingheat.io.console import Progress
from bearingheat.io.excel.workbook import calc_workbook

RESULTS = ["P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]"]


def test_workbook_calc_equals_csv_calc():
    run = calc_workbook(EXAMPLE_XLSX)
    expected = csv_result()
    for column in RESULTS:
        np.testing.assert_allclose(run.result[column].to_numpy(dtype=float),
                                   expected[column].to_numpy(dtype=float), rtol=1e-12, equal_nan=True)
    assert run.output is None


def test_not_a_number_cites_the_cell(tmp_path):
    rows = gearbox_rows()
    rows[4][5] = "abc"  # Fr of the fifth support: sheet row 7, column F
    path = make_workbook(tmp_path / "bad.xlsx", rows=rows)
    result = calc_workbook(path).result
    assert result.loc[4, "status"] == "error"
    assert result.loc[4, "message"] == "Supports!F7: 'abc' is not a number for Fr [kN]"
    assert np.isnan(result.loc[4, "MR [N*mm]"])
    assert (result.drop(index=4)["status"] != "error").all()


def test_cell_of_a_column_the_sheet_lacks(tmp_path):
    header = ["type", "series", "D", "n", "Fr", "nu", "lubrication"]
    units = ["-", "-", "mm", "1/min", "N", "mm^2/s", "-"]
    path = make_workbook(tmp_path / "nod.xlsx", header, units, [["deep_groove_ball", "62", 52, 3000, 2000, 12,
                                                                 "oil_bath"]])
    result = calc_workbook(path).result
    assert result.loc[0, "status"] == "error"
    assert result.loc[0, "message"] == ("Supports row 3 d [mm]: missing; the bore d gives dM = (d + D)/2; "
                                        "Supports row 3 C0 [N]: missing; f1 of deep groove ball bearing series 62 "
                                        "depends on P0/C0 (the Schaeffler catalogue, pp. 66-68)")


def test_formula_without_saved_value_gets_a_message(tmp_path):
    rows = gearbox_rows()
    rows[1][4] = "=E3"  # n of the second support refers to the first
    path = make_workbook(tmp_path / "formula.xlsx", rows=rows)
    result = calc_workbook(path).result
    assert result.loc[1, "status"] == "error"
    assert result.loc[1, "message"].startswith(
        "Supports!E4: formula =E3 has no saved value (the file was never opened and saved in a spreadsheet "
        "program); open it in Excel or LibreOffice, save it, and run again")
    assert np.isnan(result.loc[1, "MR [N*mm]"])


def test_unit_of_wrong_dimension_cites_the_units_cell(tmp_path):
    units = list(UNITS)
    units[HEADER.index("Fr")] = "kg"
    path = make_workbook(tmp_path / "kg.xlsx", units=units)
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path)
    assert str(exc.value) == ("Supports!F2: column 'Fr [kg]': kilogram is a mass, not a force; "
                              "for kilogram-force write kgf")


def test_missing_required_column_names_the_sheet(tmp_path):
    header = [h for h in HEADER if h != "nu"]
    units = [u for h, u in zip(HEADER, UNITS) if h != "nu"]
    rows = [[v for h, v in zip(HEADER, row) if h != "nu"] for row in gearbox_rows()]
    path = make_workbook(tmp_path / "nonu.xlsx", header, units, rows)
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path)
    assert str(exc.value) == ("sheet 'Supports' (header row 1): missing column: 'nu [mm^2/s]' "
                              "(any nu unit of the right dimension)")


# ---- the results sheet --------------------------------------------------------------------------

def test_results_sheet_layout(tmp_path):
    out = tmp_path / "out.xlsx"
    run = calc_workbook(EXAMPLE_XLSX, out)
    workbook = openpyxl.load_workbook(out)
    assert workbook.sheetnames[:2] == ["Supports", "Results"]
    ws = workbook["Results"]
    header = [c.value for c in ws[1]]
    units = [c.value for c in ws[2]]
    assert header[:3] == ["row", "id", "designation"] and header[-2:] == ["status", "message"]
    assert dict(zip(header, units))["MR"] == "N*mm" and dict(zip(header, units))["NR"] == "W"
    assert ws.max_row == 2 + 6
    assert [ws.cell(r, 1).value for r in range(3, 9)] == [3, 4, 5, 6, 7, 8]
    mr = [ws.cell(r, header.index("MR") + 1).value for r in range(3, 9)]
    np.testing.assert_allclose(mr, run.result["MR [N*mm]"], rtol=1e-15)
    assert ws.freeze_panes == "A3"
    assert ws.cell(3, header.index("status") + 1).style == "bearingheat status " + ws.cell(
        3, header.index("status") + 1).value


# ---- progress -----------------------------------------------------------------------------------

class Terminal(io.StringIO):
    def isatty(self):
        return True


def big_workbook(path, n_rows):
    rows = gearbox_rows()
    return make_workbook(path, rows=[rows[i % len(rows)] for i in range(n_rows)])


def test_progress_bar_on_a_terminal_for_large_sheets(tmp_path):
    path = big_workbook(tmp_path / "big.xlsx", 2500)
    stream = Terminal()
    calc_workbook(path, tmp_path / "out.xlsx", progress=Progress(stream=stream))
    text = stream.getvalue()
    assert "\x1b[2Kreading Supports" in text and "2500/2500" in text and "\x1b[2Kwriting Results" in text
    assert text.replace("\x1b[?25h", "").endswith("\n")  # each stage ends its line (rich shows the cursor again)


def test_no_progress_bar_when_not_a_terminal_or_small(tmp_path):
    path = big_workbook(tmp_path / "big.xlsx", 2500)
    pipe = io.StringIO()
    calc_workbook(path, tmp_path / "out.xlsx", progress=Progress(stream=pipe))
    assert pipe.getvalue() == ""
    small = Terminal()
    calc_workbook(EXAMPLE_XLSX, tmp_path / "small.xlsx", progress=Progress(stream=small))
    assert small.getvalue() == ""
    quiet = Terminal()
    calc_workbook(path, tmp_path / "out2.xlsx", progress=Progress(stream=quiet, enabled=False))
    assert quiet.getvalue() == ""


def test_a_typo_in_the_units_row_names_its_cell(tmp_path):
    """One unit that is no unit ('KN') in a units row of units: the cell and the cause, not 'column d needs a
    unit' (the whole row taken for a row of supports)."""
    units = list(UNITS)
    units[HEADER.index("Fr")] = "KN"
    with pytest.raises(ExcelError) as exc:
        calc_workbook(make_workbook(tmp_path / "typo.xlsx", units=units))
    assert str(exc.value) == ("Supports!F2: Fr: unknown unit 'KN' in the units row; write a unit such as kN, N, rpm, "
                              "mm^2/s (docs/excel.md lists them)")


def test_a_column_named_twice_cites_its_header_cell(tmp_path):
    header = list(HEADER) + ["Fr [N]"]
    rows = [list(row) + [3200] for row in gearbox_rows()]
    with pytest.raises(ExcelError) as exc:
        calc_workbook(make_workbook(tmp_path / "twice.xlsx", header=header, units=list(UNITS) + [None], rows=rows))
    assert str(exc.value) == "Supports!N1: column 'Fr [N]': Fr appears twice"


@pytest.mark.parametrize("mode", ["values", "formulas", "in_place", "in_place_formulas"])
def test_a_header_calc_cannot_read_passes_through_a_workbook(tmp_path, mode):
    """A column whose brackets are no unit ('remark [see note]]') passed through a CSV, Parquet or Arrow table but
    stopped a workbook ("Supports!...: column 'remark [see note]]': cannot read the header"); it is now left as
    it is on the input sheet, and the results are those of the sheet without it."""
    rows = [list(row) + [f"r{i}"] for i, row in enumerate(gearbox_rows())]
    path = make_workbook(tmp_path / "in.xlsx", header=[*HEADER, "remark [see note]]"], units=[*UNITS, "-"], rows=rows)
    plain = make_workbook(tmp_path / "plain.xlsx")
    formulas = mode.endswith("formulas")
    if mode.startswith("in_place"):
        run = calc_workbook(path, in_place=True, formulas=formulas)
        written = path
    else:
        written = tmp_path / "out.xlsx"
        run = calc_workbook(path, written, formulas=formulas)
    expected = calc_workbook(plain).result
    for column in RESULTS:
        np.testing.assert_allclose(run.result[column].to_numpy(dtype=float), expected[column].to_numpy(dtype=float),
                                   rtol=1e-12, equal_nan=True)
    assert run.result["status"].tolist() == expected["status"].tolist()
    assert run.result["remark [see note]]"].tolist() == [f"r{i}" for i in range(len(rows))]
    sheet = openpyxl.load_workbook(written)["Supports"]
    column = len(HEADER) + 1
    assert [sheet.cell(r, column).value for r in range(1, len(rows) + 3)] == \
        ["remark [see note]]", "-", *[f"r{i}" for i in range(len(rows))]]
