"""Excel bridge: reading sheets, calc on workbooks, messages that cite cells, the CLI, progress, pint round trip."""
from __future__ import annotations

import hashlib
import io
import re
import subprocess
import sys

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX, HEADER, UNITS, gearbox_rows, make_workbook, set_cached_value

from bearingheat.cli import main
from bearingheat.excel import (
    ExcelError,
    Progress,
    calc_workbook,
    read_supports,
    with_units,
    write_results,
)
from bearingheat.frame import calc

RESULTS = ["P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]"]


def csv_result() -> pd.DataFrame:
    return calc(pd.read_csv(EXAMPLE_CSV))


def digest(path) -> str:
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


# ---- reading ------------------------------------------------------------------------------------

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
                                        "depends on P0/C0 (seed 002, pp. 66-68)")


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


def test_formula_with_saved_value_is_read(tmp_path):
    rows = gearbox_rows()
    rows[1][4] = "=E3"
    path = make_workbook(tmp_path / "cached.xlsx", rows=rows)
    set_cached_value(path, 1, "E4", "1480")
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_result()["MR [N*mm]"], rtol=1e-12)


def test_unit_of_wrong_dimension_cites_the_units_cell(tmp_path):
    units = list(UNITS)
    units[HEADER.index("Fr")] = "kg"
    path = make_workbook(tmp_path / "kg.xlsx", units=units)
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path)
    assert str(exc.value) == ("Supports!F2: column 'Fr [kg]': kilogram is a mass, not a force; "
                              "for kilogram-force write kgf")


def test_header_unit_contradicting_units_row(tmp_path):
    header = list(HEADER)
    header[HEADER.index("Fr")] = "Fr [N]"
    path = make_workbook(tmp_path / "twice.xlsx", header=header)
    with pytest.raises(ExcelError, match=re.escape(
            "Supports!F2: unit 'kN' contradicts the header 'Fr [N]'; keep one of them")):
        read_supports(path)


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


def test_missing_required_column_names_the_sheet(tmp_path):
    header = [h for h in HEADER if h != "nu"]
    units = [u for h, u in zip(HEADER, UNITS) if h != "nu"]
    rows = [[v for h, v in zip(HEADER, row) if h != "nu"] for row in gearbox_rows()]
    path = make_workbook(tmp_path / "nonu.xlsx", header, units, rows)
    with pytest.raises(ExcelError) as exc:
        calc_workbook(path)
    assert str(exc.value) == ("sheet 'Supports' (header row 1): missing column: 'nu [mm^2/s]' "
                              "(any nu unit of the right dimension)")


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


# ---- writing ------------------------------------------------------------------------------------

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


# ---- CLI --------------------------------------------------------------------------------------

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


def test_template_cli(tmp_path, capsys):
    target = tmp_path / "supports.xlsx"
    assert main(["template", str(target)]) == 0
    assert capsys.readouterr().out == (f"template written to {target}; fill in the sheet 'Supports', then run: "
                                       f"bearingheat calc {target} -o results.xlsx\n")
    assert main(["template", str(target)]) == 2
    assert capsys.readouterr().err == (f"bearingheat template: error: {target} exists; it is not overwritten "
                                       "(give --force to replace it)\n")
    assert main(["template", str(target), "--force", "-q"]) == 0
    assert main(["template", str(tmp_path / "t.csv")]) == 2
    assert capsys.readouterr().err == (f"bearingheat template: error: {tmp_path / 't.csv'}: the template is an "
                                       ".xlsx workbook; name it e.g. supports.xlsx\n")


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
    assert "\rreading Supports" in text and "2500/2500" in text and "\rwriting Results" in text
    assert text.endswith("\n")


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
