"""The live check of calc --formulas: a changed input marks its row's results, LibreOffice recalculates, calc clears.

The scenario of issue 15: on the gearbox example, Fr and n of the first support are doubled in the sheet.
Before the check, LibreOffice showed MR 19 % low (f1 was a stale value) and n_per 4790 1/min instead of
3267 1/min. Now MR (with f1) follows the inputs, n_per is struck through with 'recalculate with
bearingheat' in the status, and a second calc run gives 3267 1/min and clears the mark.
"""
from __future__ import annotations

import re
import shutil

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import EXAMPLE_XLSX, ROOT, require_soffice

from bearingheat.io.excel import style as st
from bearingheat.io.excel.freshness import NOTE, NOTE_EVERY, conditional_rules
from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.template import build_example, save_deterministic
from bearingheat.io.excel.workbook import calc_workbook

ROOT_BASED = ["n_thr", "n_per", "T_op", "nu_op", "Q_S", "Q_L"]


def results(path, sheet="Results") -> pd.DataFrame:
    """The rows of supports of a results sheet (down to the blank row above the check of a --formulas sheet)."""
    ws = openpyxl.load_workbook(path, data_only=True)[sheet]
    rows = list(ws.iter_rows(values_only=True))
    supports = rows[2:]
    if None in [row[0] for row in supports]:
        supports = supports[:[row[0] for row in supports].index(None)]
    return pd.DataFrame(supports, columns=rows[0])


def example_table() -> pd.DataFrame:
    """The example's supports as calc reads them from the workbook."""
    return calc_workbook(EXAMPLE_XLSX).result


def probe_rules(path, sheet="Results") -> pd.DataFrame:
    """The workbook with a sheet 'Probe' that evaluates every conditional format of the results sheet on every
    row (what the spreadsheet program decides when it draws the cell): one column per rule, TRUE = applied."""
    workbook = openpyxl.load_workbook(path)
    ws = workbook[sheet]
    probe = workbook.create_sheet("Probe")
    rules = [(str(cf.sqref), rule.formula[0], rule.dxf.font.strike) for cf in ws.conditional_formatting
             for rule in cf.rules if re.match(r"[A-Z]+3:", str(cf.sqref))]  # (not the check below the table)
    for col, (_sqref, formula, _strike) in enumerate(rules, start=1):
        for row in range(3, ws.max_row + 1):
            text = re.sub(r"\$([A-Z]+)3\b", lambda m: f"{sheet}!${m.group(1)}{row}", formula)
            probe.cell(row, col, f"={text}")
    workbook.save(path)
    return rules


@pytest.fixture(scope="module", params=["copy", "in_place"])
def doubled(request, tmp_path_factory):
    """The example written with --formulas, Fr and n of row 3 doubled, the designation of row 4 changed, T_amb
    of row 5 changed, all recalculated by LibreOffice; and the same workbook after calc ran on it again."""
    require_soffice()
    folder = tmp_path_factory.mktemp(f"freshness_{request.param}")
    live = folder / "live.xlsx"
    if request.param == "copy":
        calc_workbook(EXAMPLE_XLSX, live, formulas=True)
    else:
        shutil.copyfile(EXAMPLE_XLSX, live)
        calc_workbook(live, in_place=True, formulas=True)
    edited = folder / "edited.xlsx"
    workbook = openpyxl.load_workbook(live)
    ws = workbook["Supports"]
    header = {c.value: c.column_letter for c in ws[1]}
    ws[f"{header['Fr']}3"] = ws[f"{header['Fr']}3"].value * 2
    ws[f"{header['n']}3"] = ws[f"{header['n']}3"].value * 2
    ws[f"{header['designation']}4"] = "NU2208-E"
    ws[f"{header['T_amb']}5"] = 35
    workbook.save(edited)
    rules = probe_rules(edited)
    expected = calc_workbook(edited).result  # what calc gives for the edited inputs
    recalculated = convert([edited], "xlsx", folder / "recalculated")[0]
    again = folder / "again.xlsx"
    if request.param == "copy":
        calc_workbook(recalculated, again, formulas=True)
    else:
        shutil.copyfile(recalculated, again)
        calc_workbook(again, in_place=True, formulas=True)
    cleared = convert([again], "xlsx", folder / "cleared")[0]
    return rules, expected, recalculated, cleared


@pytest.mark.integration
def test_a_changed_input_marks_the_row(doubled):
    rules, _, recalculated, _ = doubled
    sheet = results(recalculated)
    assert sheet["status"].tolist() == [NOTE, NOTE_EVERY, NOTE, "ok", "warning", "ok"]
    # the probe evaluates each conditional format: values struck on any change, formulas on NOTE_EVERY only
    probe = openpyxl.load_workbook(recalculated, data_only=True)["Probe"]
    applied = [[probe.cell(row, col).value for row in range(3, 9)] for col in range(1, len(rules) + 1)]
    kinds = {(strike, "every result" in formula): flags for (_, formula, strike), flags in zip(rules, applied)}
    assert kinds[(True, False)] == [True, True, True, False, False, False]      # n_thr ... Q_L struck
    assert kinds[(True, True)] == [False, True, False, False, False, False]     # f0 ... NR struck
    assert kinds[(None, False)] == [True, True, True, False, False, False]      # the status in orange


@pytest.mark.integration
def test_the_marked_values_are_the_stale_ones_and_the_formulas_follow(doubled):
    _, expected, recalculated, _ = doubled
    sheet = results(recalculated)
    original = example_table()
    # row 3: MR, NR (and f1, P0, P1) follow the doubled Fr and n; n_per is the stale 4790 1/min, marked
    for column, header in (("f1", "f1"), ("P0", "P0 [N]"), ("MR", "MR [N*mm]"), ("NR", "NR [W]")):
        assert sheet[column][0] == pytest.approx(expected[header][0], rel=1e-9), column
    assert expected["MR [N*mm]"][0] == pytest.approx(310.24016, rel=1e-6)
    assert sheet["n_per"][0] == pytest.approx(original["n_per [1/min]"][0], rel=1e-12)
    assert sheet["n_per"][0] == pytest.approx(4790.252, rel=1e-6)
    assert expected["n_per [1/min]"][0] == pytest.approx(3267.267, rel=1e-6)  # what the mark hides
    assert expected["T_op [degC]"][0] == pytest.approx(64.286, rel=1e-4)
    # row 4: another designation; the formulas still hold the 6208's table values, so every result is marked
    assert sheet["MR"][1] == pytest.approx(original["MR [N*mm]"][1], rel=1e-9)
    assert expected["MR [N*mm]"][1] != pytest.approx(original["MR [N*mm]"][1], rel=1e-3)


@pytest.mark.integration
def test_calc_again_clears_the_marks(doubled):
    _, expected, _, cleared = doubled
    sheet = results(cleared)
    assert sheet["status"].tolist() == expected["status"].tolist()
    assert not sheet["status"].str.startswith(NOTE).any()
    np.testing.assert_allclose(sheet["n_per"].astype(float), expected["n_per [1/min]"], rtol=1e-12)
    np.testing.assert_allclose(sheet["MR"].astype(float), expected["MR [N*mm]"], rtol=1e-9)
    assert sheet["n_per"][0] == pytest.approx(3267.267, rel=1e-6)


@pytest.mark.integration
def test_a_formula_input_and_an_unchanged_workbook_stay_ok(tmp_path):
    """Opened and recalculated without a change (a formula among the inputs included), nothing is marked."""
    require_soffice()
    source = tmp_path / "book.xlsx"
    shutil.copyfile(EXAMPLE_XLSX, source)
    workbook = openpyxl.load_workbook(source)
    ws = workbook["Supports"]
    ws["AZ3"] = 1.6
    ws["F3"] = "=AZ3*2"  # Fr = 3.2 kN as a formula
    workbook.save(source)
    saved = convert([source], "xlsx", tmp_path / "saved")[0]  # a spreadsheet program saves its value
    out = tmp_path / "live.xlsx"
    run = calc_workbook(saved, out, formulas=True)
    assert run.result["Fr"][0] == 3.2
    sheet = results(convert([out], "xlsx", tmp_path / "recalculated")[0])
    assert sheet["status"].tolist() == run.result["status"].tolist()


def test_status_formula_and_conditional_formats(tmp_path):
    out = tmp_path / "live.xlsx"
    run = calc_workbook(EXAMPLE_XLSX, out, formulas=True)
    assert run.companions == {"snapshot": "Calc inputs"}
    workbook = openpyxl.load_workbook(out)
    ws = workbook["Results"]
    header = [c.value for c in ws[1]]
    status = ws.cell(3, header.index("status") + 1).value
    # a header or unit, the designation, arrangement, alpha, type, series, f2 (not read for a 6208) make every
    # result stale
    assert status.startswith("=IF(OR(SUMPRODUCT(--(Supports!$A$1:$BA$2<>'Calc inputs'!$A$1:$BA$2))>0,"
                             "Supports!B3<>'Calc inputs'!B3,Supports!J3<>'Calc inputs'!J3,")
    assert '"recalculate with bearingheat (every result)",IF(OR(Supports!C3<>\'Calc inputs\'!C3,' in status
    assert status.endswith('),"recalculate with bearingheat","ok"))')
    assert "Supports!A3" not in status  # the id is a label
    assert ws.cell(3, header.index("status") + 1).style == "bearingheat status ok"
    rules = {str(cf.sqref): (rule.formula[0], rule.dxf.font.strike) for cf in ws.conditional_formatting
             for rule in cf.rules}
    status_letter = openpyxl.utils.get_column_letter(header.index("status") + 1)
    letters = {h: openpyxl.utils.get_column_letter(i) for i, h in enumerate(header, start=1)}
    assert rules[f"C3:C8 {letters['n_thr']}3:{letters['Q_L']}8"] == (f'LEFT(${status_letter}3,28)="{NOTE}"', True)
    assert rules[f"D3:{letters['NR']}8"] == (f'${status_letter}3="{NOTE_EVERY}"', True)
    # the copy holds the cells calc read, at the same addresses, and is hidden
    copy = workbook["Calc inputs"]
    assert copy.sheet_state == "hidden"
    supports = workbook["Supports"]
    for address in ("B3", "E3", "F7", "I8", "Y5", "B1", "F2"):
        assert copy[address].value == supports[address].value, address
    assert copy["A3"].value is None  # not the id


def test_rules_cover_values_and_formulas():
    columns = ["row", "id", "designation", "f0", "f1", "f2", "M1 load", "MR [N*mm]", "n_per [1/min]",
               "n_per_method_used", "status", "message"]
    rules = conditional_rules(columns, ["f0", "f1", "f2", "MR [N*mm]"], 4)
    assert [(r.sqref, r.dxf) for r in rules] == [("C3:C6 I3:J6", st.STALE), ("D3:H6", st.STALE),
                                                  ("K3:K6", st.RECALCULATE)]
    assert conditional_rules(columns, [], 0) == []


def test_without_formulas_no_copy_and_no_check(tmp_path):
    out = tmp_path / "values.xlsx"
    run = calc_workbook(EXAMPLE_XLSX, out)
    assert run.companions == {}
    workbook = openpyxl.load_workbook(out)
    assert workbook.sheetnames == ["Supports", "Results", "Instructions", "Lists"]
    ws = workbook["Results"]
    status = [c.value for c in ws[1]].index("status") + 1
    assert [ws.cell(r, status).value for r in range(3, 9)] == run.result["status"].tolist()
    assert not list(ws.conditional_formatting)


def test_a_sheet_of_the_designer_named_like_the_copy_is_kept(tmp_path):
    source = tmp_path / "book.xlsx"
    shutil.copyfile(EXAMPLE_XLSX, source)
    workbook = openpyxl.load_workbook(source)
    workbook.create_sheet("Calc inputs")["A1"] = "my notes"
    workbook.save(source)
    for run in (calc_workbook(source, tmp_path / "copy.xlsx", formulas=True),
                calc_workbook(source, in_place=True, formulas=True),
                calc_workbook(source, in_place=True, formulas=True)):
        assert run.companions == {"snapshot": "Calc inputs (2)"}
        book = openpyxl.load_workbook(run.output)
        assert book["Calc inputs"]["A1"].value == "my notes" and book["Calc inputs"].sheet_state == "visible"
        assert book["Calc inputs (2)"].sheet_state == "hidden"
        status = [c.value for c in book["Results"][1]].index("status") + 1
        assert "'Calc inputs (2)'!" in book["Results"].cell(3, status).value


@pytest.mark.integration
def test_a_viscosity_from_the_oils_curve_is_a_value_and_any_change_marks_every_result(tmp_path):
    """The duty cycle example gives the oil as ISO VG 68: calc takes ν from its curve, a value of the operating
    point; the formulas use that value, so a change of any input marks every result."""
    require_soffice()
    source = save_deterministic(build_example(ROOT / "examples" / "gearbox_duty_cycle.csv"), tmp_path / "duty.xlsx")
    live = tmp_path / "live.xlsx"
    run = calc_workbook(source, live, formulas=True)
    workbook = openpyxl.load_workbook(live)
    results_ws = workbook["Results"]
    header = [c.value for c in results_ws[1]]
    assert results_ws.cell(3, header.index("nu") + 1).data_type == "n"  # a value
    assert results_ws.cell(3, header.index("M0") + 1).value.startswith("=")  # a formula that uses it
    ws = workbook["Supports"]
    letter = {c.value: c.column_letter for c in ws[1]}
    ws[f"{letter['Fr']}4"] = ws[f"{letter['Fr']}4"].value * 2
    workbook.save(tmp_path / "edited.xlsx")
    recalculated = convert([live, tmp_path / "edited.xlsx"], "xlsx", tmp_path / "recalculated")
    before, after = results(recalculated[0]), results(recalculated[1])
    np.testing.assert_allclose(before["MR"].astype(float), run.result["MR [N*mm]"], rtol=1e-9)
    # (the NU208-E idles below its minimum load: a warning of calc's that the recalculation keeps)
    assert before["status"].tolist() == ["ok"] * 5 + ["warning"]
    assert after["status"].tolist() == ["ok", NOTE_EVERY, "ok", "ok", "ok", "warning"]


@pytest.mark.integration
def test_a_changed_unit_marks_every_result_of_every_row(tmp_path):
    """Fr typed in N instead of kN (the units cell only, and with the loads retyped in N): the live MR has the
    factor 1000 of kN built in, so every row says NOTE_EVERY; the same workbook unchanged stays as calc gave."""
    require_soffice()
    live = tmp_path / "live.xlsx"
    run = calc_workbook(EXAMPLE_XLSX, live, formulas=True)
    edited = {}
    for tag in ("unit", "unit_and_loads", "unchanged"):
        workbook = openpyxl.load_workbook(live)
        ws = workbook["Supports"]
        fr = {c.value: c.column_letter for c in ws[1]}["Fr"]
        if tag != "unchanged":
            ws[f"{fr}2"] = "N"
        if tag == "unit_and_loads":
            for row in range(3, ws.max_row + 1):
                if isinstance(ws[f"{fr}{row}"].value, (int, float)):
                    ws[f"{fr}{row}"] = ws[f"{fr}{row}"].value * 1000
        edited[tag] = tmp_path / f"{tag}.xlsx"
        workbook.save(edited[tag])
    recalculated = convert(list(edited.values()), "xlsx", tmp_path / "recalculated")
    by_tag = {path.stem: results(path)["status"].tolist() for path in recalculated}
    n_rows = len(run.result)
    assert by_tag["unit"] == [NOTE_EVERY] * n_rows
    assert by_tag["unit_and_loads"] == [NOTE_EVERY] * n_rows
    assert by_tag["unchanged"] == run.result["status"].tolist()


UNREAD = "sheet 'Supports' has {count} without results: recalculate with bearingheat"


def test_the_check_for_supports_without_results_sits_below_the_table(tmp_path):
    """With --formulas the results sheet ends with a blank row and a cell that counts the rows of the input sheet
    calc read against those it had; bold orange when it has something to say."""
    out = tmp_path / "live.xlsx"
    run = calc_workbook(EXAMPLE_XLSX, out, formulas=True)
    ws = openpyxl.load_workbook(out)["Results"]
    assert len(run.result) == 6 and run.info.filled_rows == 7  # the units row and six supports
    assert [c.value for c in ws[9]] == [None] * ws.max_column and ws.max_row == 10
    check = ws["A10"].value
    assert check.startswith("=IF(ROWS(Supports!A2:A1048576)-COUNTIFS(Supports!A2:A1048576,\"\",Supports!B2:B1048576")
    count = check[4:check.index(">7,")]  # the rows counted now, written twice
    assert check == (f'=IF({count}>7,"sheet \'Supports\' has "&TEXT({count}-7,"[=1]""1 support"";0"" supports""")'
                     '&" without results: recalculate with bearingheat","")')
    assert check.count("COUNTIFS(") == 2 and check.count('1048576,""') == 2 * 53  # every column calc read
    rules = {str(cf.sqref): (rule.formula[0], rule.dxf.font.b, rule.dxf.font.color.rgb)
             for cf in ws.conditional_formatting for rule in cf.rules}
    assert rules["A10"] == ("LEN($A$10)>0", True, "FFC65911")  # bold orange, as the status asking for a run


@pytest.mark.integration
@pytest.mark.parametrize("where", ["copy", "in_place"])
def test_supports_typed_below_the_others_are_counted_on_the_results_sheet(tmp_path, where):
    """A support added under the others on the input sheet after a --formulas run got no results and nothing said
    so; now the cell under the results says how many supports have none, and is empty while there are none (an
    input changed in a row of its own is the status's business)."""
    require_soffice()
    live = tmp_path / "live.xlsx"
    if where == "copy":
        run = calc_workbook(EXAMPLE_XLSX, live, formulas=True)
    else:
        shutil.copyfile(EXAMPLE_XLSX, live)
        run = calc_workbook(live, in_place=True, formulas=True)
    edits = {"unchanged": [], "one": [9], "two": [9, 14], "changed": []}
    for tag, rows in edits.items():
        workbook = openpyxl.load_workbook(live)
        ws = workbook["Supports"]
        header = {c.value: c.column_letter for c in ws[1]}
        for row in rows:  # a support like the last, typed below it (with a gap: row 14)
            for column in ("id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication"):
                ws[f"{header[column]}{row}"] = ws[f"{header[column]}8"].value
            ws[f"{header['id']}{row}"] = f"added in row {row}"
        if tag == "changed":
            ws[f"{header['Fr']}3"] = 2 * ws[f"{header['Fr']}3"].value
        workbook.save(tmp_path / f"{tag}.xlsx")
    recalculated = convert([tmp_path / f"{tag}.xlsx" for tag in edits], "xlsx", tmp_path / "recalculated")
    checks = {path.stem: openpyxl.load_workbook(path, data_only=True)["Results"]["A10"].value for path in recalculated}
    assert checks == {"unchanged": None, "one": UNREAD.format(count="1 support"),
                      "two": UNREAD.format(count="2 supports"), "changed": None}
    statuses = {path.stem: results(path)["status"].tolist() for path in recalculated}
    assert statuses["one"] == statuses["unchanged"] == run.result["status"].tolist()
    assert statuses["changed"][0] == NOTE
    # calc again reads the added supports: their results, and the check is empty
    again = tmp_path / "again.xlsx"
    rerun = calc_workbook(tmp_path / "two.xlsx", again, formulas=True)
    assert rerun.info.rows == [3, 4, 5, 6, 7, 8, 9, 14] and rerun.info.filled_rows == 9
    (cleared,) = convert([again], "xlsx", tmp_path / "cleared")
    assert openpyxl.load_workbook(cleared, data_only=True)["Results"]["A12"].value is None
    assert results(cleared)["id"].tolist()[-2:] == ["added in row 9", "added in row 14"]
