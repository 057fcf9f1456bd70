"""Live formulas (calc --formulas): their text, and their values recalculated by LibreOffice.

The LibreOffice test runs wherever ``soffice`` is installed; under CI=true it
must run (.ci/run installs libreoffice-calc-nogui), elsewhere it skips with
the reason.
"""
from __future__ import annotations

import math
import re

import numpy as np
import openpyxl
import pytest
from excel_helpers import EXAMPLE_XLSX, make_workbook, require_soffice

from bearingheat.errors import ExcelError
from bearingheat.io.excel.formulas import excel_number, unit_factor
from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.workbook import calc_workbook

LIVE = ["f0", "f1", "P0 [N]", "P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]"]
INCH = 25.4
LBF = 4.4482216152605

# a sheet in mixed units: D in inches, n in Hz, Fr in lbf, nu in cSt; every M1 load rule of the Schaeffler catalogue
HEADER = ["id", "designation", "d", "D", "B", "n", "Fr", "Fa", "nu", "lubrication", "arrangement", "C0", "Y", "e",
          "X0", "Y0", "f2"]
UNITS = ["-", "-", "mm", "in", "mm", "Hz", "lbf", "kN", "cSt", "-", "-", "kN", "1", "1", "1", "1", "1"]


def row(id_, designation, d, D_mm, n_rpm, Fr_N, Fa_kN, nu, lubrication, arrangement="single", C0=None, Y=None,
        e=None, X0=None, Y0=None, f2=None, B=None):
    return [id_, designation, d, D_mm / INCH, B, n_rpm / 60.0, Fr_N / LBF, Fa_kN, nu, lubrication, arrangement,
            C0, Y, e, X0, Y0, f2]


ROWS = [
    row("radial ball", "6208", 40, 80, 1480, 3200, 0.9, 40, "oil_bath", C0=18),
    row("cylindrical, Fr", "NU208-E", 40, 80, 1480, 4100, 0, 40, "oil_bath", C0=53),
    row("tapered", "30208-A", 40, 80, 310, 6000, 2.4, 40, "oil_bath", C0=66, Y=1.6),
    row("angular pair", "7210-B", 50, 90, 6000, 1500, 2.0, 22, "grease", "paired", C0=28.5, Y0=0.26),
    row("spherical, high Fa", "22210-E", 50, 90, 1000, 5000, 3.0, 60, "oil_bath", C0=98, e=0.24, X0=1, Y0=2.8),
    row("spherical, low Fa", "22210-E", 50, 90, 1000, 9000, 0.5, 60, "oil_bath", C0=98, e=0.24, X0=1, Y0=2.8),
    row("four point", "QJ210", 50, 90, 3000, 2000, 3.0, 30, "oil_mist", C0=44, X0=1, Y0=0.66),
    row("NJ with f2", "NJ210-E", 50, 90, 2000, 8000, 1.5, 30, "circulating_oil", f2=0.006),
    row("thrust ball", "51210", 50, 78, 1200, 0, 4.0, 50, "oil_bath", C0=110),
    row("low regime", "6210", 50, 90, 100, 1000, 0, 5, "grease", C0=24),
    row("bore from designation", "6208", None, 80, 1480, 3200, 0, 40, "oil_bath", C0=18),
    row("needle", "HK2016", 20, 26, 3000, 1500, 0, 20, "grease", B=16),
    row("bad load", "6208", 40, 80, 1480, 1, 0, 40, "oil_bath", C0=18),
]
ROWS[-1][6] = "abc"


def results_by_header(path) -> tuple[list, list[list]]:
    ws = openpyxl.load_workbook(path, data_only=True)["Results"]
    header = [c.value for c in ws[1]]
    units = [c.value for c in ws[2]]
    names = [f"{h} [{u}]" if u not in ("-", "1") else h for h, u in zip(header, units)]
    rows = [list(r) for r in ws.iter_rows(min_row=3, values_only=True)]
    return names, rows[:[r[0] for r in rows].index(None)]  # (below a blank row: the check for unread supports)


def assert_formulas_equal_python(recalculated, result):
    names, rows = results_by_header(recalculated)
    assert len(rows) == len(result)
    checked = 0
    for i, values in enumerate(rows):
        got = dict(zip(names, values))
        for column in LIVE:
            expected = result[column].iloc[i]
            if result["status"].iloc[i] == "error" or (isinstance(expected, float) and math.isnan(expected)):
                assert got[column] is None, (i, column, got[column])
                continue
            assert isinstance(got[column], (int, float)), (i, column, got[column])
            assert got[column] == pytest.approx(expected, rel=1e-9, abs=1e-12), (i, column)
            checked += 1
    return checked


@pytest.fixture(scope="module", params=["copy", "in_place"])
def recalculated(request, tmp_path_factory):
    """The formula workbook (written with -o, or into the input with --in-place), a copy with new n, ν and loads
    typed into 'Supports', both recalculated."""
    require_soffice()
    folder = tmp_path_factory.mktemp(f"formulas_{request.param}")
    source = make_workbook(folder / "mixed.xlsx", HEADER, UNITS, ROWS)
    live = folder / "live.xlsx"
    if request.param == "copy":
        run = calc_workbook(source, live, formulas=True)
    else:
        source.rename(live)
        run = calc_workbook(live, in_place=True, formulas=True)
        assert run.results_sheet == "Results"
    edited = folder / "edited.xlsx"
    workbook = openpyxl.load_workbook(live)
    ws = workbook["Supports"]
    letters = {name: openpyxl.utils.get_column_letter(i) for i, name in enumerate(HEADER, start=1)}
    for excel_row in range(3, 3 + len(ROWS)):
        label = ws[f"A{excel_row}"].value
        ws[f"{letters['n']}{excel_row}"] = ws[f"{letters['n']}{excel_row}"].value * 1.7
        # M0 changes formula at ν·n = 2000: the radial ball row drops below it, the low regime row rises above
        nu = {"radial ball": 0.5, "low regime": 20}.get(label, 2 * ws[f"{letters['nu']}{excel_row}"].value)
        ws[f"{letters['nu']}{excel_row}"] = nu
        if label != "bad load":  # f1 follows the load too (P0/C0, Fa/C0)
            ws[f"{letters['Fr']}{excel_row}"] = ws[f"{letters['Fr']}{excel_row}"].value * 1.3
            ws[f"{letters['Fa']}{excel_row}"] = ws[f"{letters['Fa']}{excel_row}"].value * 0.6
    workbook.save(edited)
    edited_result = calc_workbook(edited).result
    out = convert([live, edited], "xlsx", folder / "recalculated")
    return run.result, out[0], edited_result, out[1]


@pytest.mark.integration
def test_libreoffice_recalculation_equals_python(recalculated):
    result, path, _, _ = recalculated
    assert (result["status"] == "error").sum() == 1
    assert assert_formulas_equal_python(path, result) >= 8 * 12


@pytest.mark.integration
def test_changed_inputs_update_the_formulas(recalculated):
    original, _, edited_result, path = recalculated
    assert assert_formulas_equal_python(path, edited_result) >= 8 * 12
    # f1 follows the load where it depends on P0/C0 or Fa/C0 (the radial ball, the spherical rows ...)
    assert (np.abs(edited_result["f1"] / original["f1"] - 1) > 1e-3).sum() >= 4
    assert not np.allclose(edited_result["MR [N*mm]"].dropna(), original["MR [N*mm]"].dropna())
    nu_n = edited_result["nu"] * edited_result["n"] * 60
    regime_before = original["nu"] * original["n"] * 60 >= 2000
    assert list((nu_n >= 2000) != regime_before).count(True) == 2  # both regimes of M0 were crossed


def test_formula_text_of_a_radial_ball_bearing(tmp_path):
    out = tmp_path / "live.xlsx"
    calc_workbook(EXAMPLE_XLSX, out, formulas=True)
    ws = openpyxl.load_workbook(out)["Results"]
    header = [c.value for c in ws[1]]
    cell = {name: ws.cell(3, header.index(name) + 1).value for name in header}
    assert header[:12] == ["row", "id", "designation", "f0", "f1", "f2", "M1 load", "dM", "n", "nu", "Fr", "Fa"]
    assert cell["M1 load"] == "P1: 3.3·Fa − 0.1·Fr (P1 >= Fr)"
    # the operating point in catalogue units: each input cell read once, with what a blank cell means to calc
    # (the loads 0, the bore of the designation, n and nu missing) and the unit factor of the units row
    assert cell["dM"] == "=(IF(TRIM(Supports!C3&\"\")=\"\",40,Supports!C3)+IF(TRIM(Supports!D3&\"\")=\"\",80,Supports!D3))/2"
    assert cell["n"] == "=IF(TRIM(Supports!E3&\"\")=\"\",NA(),Supports!E3)"
    assert cell["nu"] == "=IF(TRIM(Supports!H3&\"\")=\"\",NA(),Supports!H3)"
    assert cell["Fr"] == "=IF(TRIM(Supports!F3&\"\")=\"\",0,(Supports!F3*1000))"
    assert cell["Fa"] == "=IF(TRIM(Supports!G3&\"\")=\"\",0,(Supports!G3*1000))"
    # f0 of the 6208 (the Schaeffler catalogue table: 1.3 for grease and oil mist, 2 in an oil bath or circulating oil)
    assert cell["f0"] == ('=IF(TRIM(Supports!T3&\"\")=\"\",IF(OR(EXACT(TRIM(Supports!I3),"grease"),EXACT(TRIM(Supports!I3),'
                          '"oil_mist")),1.3,IF(OR(EXACT(TRIM(Supports!I3),"oil_bath"),EXACT(TRIM(Supports!I3),'
                          '"circulating_oil")),2,NA())),Supports!T3)')
    # f1 = 0.0009*(P0/C0)^0.5 of the 62 series; C0 of the table where the cell is blank (18 kN)
    assert cell["f1"] == ("=IF(TRIM(Supports!U3&\"\")=\"\",0.0009*(M3/IF(TRIM(Supports!L3&\"\")=\"\",18000,(Supports!L3*1000)))"
                          "^0.5,Supports!U3)")
    # P0 = max(X0*Fr + Y0*Fa, Fr) with X0 = 0.6, Y0 = 0.5 of the DP11A manual table 1 for a blank cell
    assert cell["P0"] == ("=IF(L3>0,MAX(IFERROR(IF(TRIM(Supports!O3&\"\")=\"\",0.6,Supports!O3)*K3+IF(TRIM(Supports!P3&\"\")=\"\","
                          "0.5,Supports!P3)*L3,K3),K3),K3)")
    assert cell["P1"] == "=MAX(3.3*L3-0.1*K3,K3)"
    assert cell["M0"] == "=D3*IF(J3*I3>=2000,(J3*I3)^(2/3),160)*H3^3*1E-07"
    assert cell["M1"] == "=E3*N3*H3"
    assert cell["M2"] == "=F3*L3*H3"
    assert cell["MR"] == "=O3+P3+Q3"
    assert cell["NR"] == "=R3*I3/9550"
    second = {name: ws.cell(4, header.index(name) + 1).value for name in header}  # NU208-E: M1 = f1*Fr*dM
    assert second["M1 load"] == "Fr" and second["P1"] is None
    assert second["f1"] == "=IF(TRIM(Supports!U4&\"\")=\"\",0.0003,Supports!U4)"
    assert second["f2"] == "=IF(L4>0,NA(),0)"  # NU: no ribs on one ring, an axial load is an error of calc
    assert second["M1"] == "=E4*K4*H4"
    assert ws.cell(3, header.index("M0") + 1).style == "bearingheat formula"
    assert ws.cell(3, header.index("f1") + 1).number_format == "General"
    assert ws.cell(3, header.index("MR") + 1).number_format == "[>=100]0;[>=10]0.0;0.00"
    # the operating point is grouped and collapsed; the outline's + button opens it
    assert [ws.column_dimensions[letter].hidden for letter in "HIJKLM"] == [True] * 5 + [False]


def test_formulas_cannot_express_effects(tmp_path):
    with pytest.raises(ExcelError, match="--formulas cannot express the fitted effect of --effects; "
                                         "use one of them"):
        calc_workbook(EXAMPLE_XLSX, str(tmp_path / "OUT.xlsx"), formulas=True, effects=object())
    assert not (tmp_path / "OUT.xlsx").exists()


def test_unit_factors_from_pint():
    assert unit_factor("lbf", "N", "Fr") == pytest.approx(LBF, rel=1e-15)
    assert unit_factor("Hz", "1/min", "n") == 60.0
    assert unit_factor("rad/s", "1/min", "n") == pytest.approx(60 / (2 * math.pi), rel=1e-15)
    assert unit_factor("cSt", "mm^2/s", "nu") == pytest.approx(1.0, rel=1e-15)
    assert unit_factor("in", "mm", "D") == pytest.approx(INCH, rel=1e-15)
    assert unit_factor("%", "1", "Y") == pytest.approx(0.01, rel=1e-15)


@pytest.mark.parametrize("value", [1000.0, 4.4482216152605, 1e-07, 2.0 / 3.0, 25.4, 123456789.0, 1e22])
def test_excel_number_reads_back_exactly(value):
    assert float(excel_number(value).replace("E", "e")) == value


@pytest.mark.integration
def test_a_cell_of_spaces_is_blank_to_the_formulas_as_to_calc(tmp_path):
    """calc reads a cell of only spaces as blank (Fa given as nothing: 0); the live formulas test blanks the same
    way, so they compute what calc computed instead of #VALUE!."""
    require_soffice()
    rows = [list(r) for r in ROWS[:3]]
    rows[0][7] = "   "  # Fa of the radial ball bearing
    rows[2][12] = " "  # Y of the tapered roller bearing: its table value
    source = make_workbook(tmp_path / "spaces.xlsx", HEADER, UNITS, rows)
    run = calc_workbook(source, tmp_path / "live.xlsx", formulas=True)
    assert run.result["status"].tolist() == ["ok", "ok", "ok"]
    (recalculated,) = convert([tmp_path / "live.xlsx"], "xlsx", tmp_path / "lo")
    assert assert_formulas_equal_python(recalculated, run.result) == run.result[LIVE].notna().sum().sum()


#: sheet names Excel reads as a cell reference unquoted (A1 and R1C1 forms), or that need quotes anyway
NAMES_TO_QUOTE = ["C", "R", "RC", "R1C1", "A1", "XFD1", "2024", "Shaft 1", "Q1's loads"]


@pytest.mark.parametrize("sheet", NAMES_TO_QUOTE)
def test_every_formula_quotes_the_sheet_name_alike(tmp_path, sheet):
    """The live formulas, the status formulas and the marks name the input sheet the same way: 'C'!I3, not C!I3
    (Excel would read C as the column C of R1C1 notation)."""
    source = make_workbook(tmp_path / "book.xlsx", sheet=sheet)
    out = tmp_path / "live.xlsx"
    run = calc_workbook(source, out, formulas=True)
    workbook = openpyxl.load_workbook(out)
    quoted = "'" + sheet.replace("'", "''") + "'"
    formulas = [cell.value for row in workbook[run.results_sheet].iter_rows() for cell in row
                if isinstance(cell.value, str) and cell.value.startswith("=")]
    references = [ref for formula in formulas for ref in re.findall(r"((?:'(?:[^']|'')+'|[A-Za-z0-9_.]+)!)\$?[A-Z]",
                                                                     formula)]
    copy = "'" + run.companions["snapshot"].replace("'", "''") + "'!"
    assert {quoted + "!", copy} == set(references), set(references)  # the input sheet and the copy of its inputs
    header = [c.value for c in workbook[run.results_sheet][1]]
    dm = workbook[run.results_sheet].cell(3, header.index("dM") + 1).value
    assert dm == f'=(IF(TRIM({quoted}!C3&"")="",40,{quoted}!C3)+IF(TRIM({quoted}!D3&"")="",80,{quoted}!D3))/2'
    assert workbook.defined_names["_bearingheat_input_1"].attr_text == f"{quoted}!$1:$1048576"


@pytest.mark.integration
def test_sheets_named_like_references_recalculate_in_libreoffice(tmp_path):
    """Input sheets named C and R1C1 (in one workbook, each with its results written in place): LibreOffice
    recalculates the live formulas to calc's numbers and the status formulas to calc's statuses."""
    require_soffice()
    book = make_workbook(tmp_path / "named.xlsx", sheet="C")
    workbook = openpyxl.load_workbook(book)
    workbook.copy_worksheet(workbook["C"]).title = "R1C1"
    workbook["R1C1"]["E4"] = 2 * workbook["R1C1"]["E4"].value  # another speed: the sheets' results differ
    workbook.save(book)
    runs = {sheet: calc_workbook(book, in_place=True, sheet=sheet, formulas=True) for sheet in ("C", "R1C1")}
    (recalculated,) = convert([book], "xlsx", tmp_path / "lo")
    values = openpyxl.load_workbook(recalculated, data_only=True)
    for sheet, run in runs.items():
        assert run.results_sheet == f"{sheet} results"
        ws = values[run.results_sheet]
        rows = list(ws.iter_rows(min_row=3, max_row=2 + len(run.result), values_only=True))
        header = [c.value for c in ws[1]]
        statuses = [r[header.index("status")] for r in rows]
        assert statuses == run.result["status"].tolist() == ["ok"] * 4 + ["warning", "ok"]
        np.testing.assert_allclose([r[header.index("MR")] for r in rows], run.result["MR [N*mm]"], rtol=1e-9)
    assert runs["R1C1"].result["MR [N*mm]"][1] != pytest.approx(runs["C"].result["MR [N*mm]"][1], rel=1e-3)
