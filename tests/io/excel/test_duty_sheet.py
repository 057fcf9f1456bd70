"""The 'Duty cycle' sheet: the summary per support of a table with a duty cycle, in every Excel output."""
from __future__ import annotations

import zipfile

import numpy as np
import openpyxl
import pandas as pd
import pytest
from excel_helpers import ROOT, TEMPLATE_XLSX

from bearingheat.calc.duty import duty_cycle
from bearingheat.calc.table import calc
from bearingheat.cli import main
from bearingheat.io.excel.template import build_example, save_deterministic
from bearingheat.io.excel.workbook import calc_workbook

DUTY_CSV = ROOT / "examples" / "gearbox_duty_cycle.csv"


@pytest.fixture()
def duty_workbook(tmp_path):
    """The gearbox duty cycle (two supports, three cases each) in the template."""
    return save_deterministic(build_example(DUTY_CSV), tmp_path / "duty.xlsx")


def sheet_frame(path, sheet) -> pd.DataFrame:
    rows = list(openpyxl.load_workbook(path)[sheet].iter_rows(values_only=True))
    units = rows[1]
    names = [f"{h} [{u}]" if u not in ("-", "1") else h for h, u in zip(rows[0], units)]
    return pd.DataFrame(rows[2:], columns=names)


def assert_summary(frame: pd.DataFrame, expected: pd.DataFrame) -> None:
    assert list(frame.columns) == list(expected.columns)
    for column in expected.columns:
        if expected[column].dtype.kind == "f":
            np.testing.assert_allclose(frame[column].astype(float), expected[column], rtol=1e-12)
        else:
            # a blank cell reads as None, or as NaN where pandas makes the column text
            assert ["" if v is None or (isinstance(v, float) and np.isnan(v)) else v for v in frame[column]] \
                == list(expected[column]), column


def test_duty_cycle_sheet_of_a_copy(duty_workbook, tmp_path):
    expected = duty_cycle(calc(pd.read_csv(DUTY_CSV)))  # the Python API on the same supports
    assert expected["support"].tolist() == ["input shaft A", "input shaft B"]
    run = calc_workbook(duty_workbook, tmp_path / "out.xlsx")
    assert run.companions == {"duty": "Duty cycle"}
    assert_summary(run.duty, expected)
    workbook = openpyxl.load_workbook(run.output)
    # the template's Results sheet filled where it is, the summary added after the last sheet (as --in-place)
    assert workbook.sheetnames == ["Supports", "Results", "Instructions", "Lists", "Duty cycle"]
    assert_summary(sheet_frame(run.output, "Duty cycle"), expected)
    ws = workbook["Duty cycle"]
    assert ws["D3"].number_format == "[>=100]0;[>=10]0.0;0.00" and ws["G3"].number_format == "0.0"
    results = workbook["Results"]
    assert [c.value for c in results[1]][:5] == ["row", "id", "designation", "support", "case"]


def test_duty_cycle_sheet_in_place(duty_workbook):
    expected = duty_cycle(calc(pd.read_csv(DUTY_CSV)))
    first = calc_workbook(duty_workbook, in_place=True, formulas=True)
    assert first.companions == {"snapshot": "Calc inputs", "duty": "Duty cycle"}
    assert_summary(sheet_frame(duty_workbook, "Duty cycle"), expected)
    with zipfile.ZipFile(duty_workbook) as archive:
        parts = archive.namelist()
        workbook_xml = archive.read("xl/workbook.xml").decode()
    assert '<definedName name="_bearingheat_duty_1" hidden="1">\'Duty cycle\'!$1:$1048576</definedName>' \
        in workbook_xml
    second = calc_workbook(duty_workbook, in_place=True, formulas=True)
    assert second.companions == first.companions
    with zipfile.ZipFile(duty_workbook) as archive:
        assert archive.namelist() == parts  # replaced, nothing added
    assert openpyxl.load_workbook(duty_workbook).sheetnames == ["Supports", "Results", "Instructions", "Lists",
                                                                "Calc inputs", "Duty cycle"]


def test_a_sheet_of_the_designer_named_duty_cycle_is_kept(duty_workbook, tmp_path):
    workbook = openpyxl.load_workbook(duty_workbook)
    workbook.create_sheet("Duty cycle")["A1"] = "my own summary"
    workbook.save(duty_workbook)
    for run in (calc_workbook(duty_workbook, tmp_path / "copy.xlsx"), calc_workbook(duty_workbook, in_place=True)):
        assert run.companions == {"duty": "Duty cycle (2)"}
        book = openpyxl.load_workbook(run.output)
        assert book["Duty cycle"]["A1"].value == "my own summary"
        assert book["Duty cycle (2)"]["A3"].value == "input shaft A"


def test_the_template_without_a_duty_cycle_gets_no_sheet(tmp_path):
    """The template has the duty cycle's columns; left empty, they are no duty cycle."""
    run = calc_workbook(TEMPLATE_XLSX, tmp_path / "out.xlsx")
    assert run.duty is None and run.companions == {}
    assert "Duty cycle" not in openpyxl.load_workbook(run.output).sheetnames


def test_cli_duty_cycle_outputs(duty_workbook, tmp_path, capsys):
    expected = duty_cycle(calc(pd.read_csv(DUTY_CSV)))
    out = tmp_path / "from_csv.xlsx"
    assert main(["calc", str(DUTY_CSV), "-o", str(out), "-q"]) == 0
    assert openpyxl.load_workbook(out).sheetnames == ["Results", "Duty cycle"]
    assert_summary(sheet_frame(out, "Duty cycle"), expected)
    csv_out = tmp_path / "from_xlsx.csv"
    assert main(["calc", str(duty_workbook), "-o", str(csv_out), "-q"]) == 0
    np.testing.assert_allclose(pd.read_csv(tmp_path / "from_xlsx.duty.csv")["NR_mean [W]"],
                               expected["NR_mean [W]"], rtol=1e-12)
    assert main(["calc", str(duty_workbook), "-o", str(tmp_path / "out.xlsx")]) == 0
    printed = capsys.readouterr().out
    assert "duty cycle (time-weighted per support):" in printed and "input shaft B" in printed


def test_shares_not_summing_to_1_are_refused(duty_workbook, tmp_path, capsys):
    workbook = openpyxl.load_workbook(duty_workbook)
    ws = workbook["Supports"]
    share = [c.value for c in ws[1]].index("time_share") + 1
    ws.cell(3, share).value = 0.3
    workbook.save(duty_workbook)
    assert main(["calc", str(duty_workbook), "-o", str(tmp_path / "out.xlsx")]) == 2
    assert capsys.readouterr().err == (
        "bearingheat calc: error: support 'input shaft A': the time_share values of its cases (full load 0.3, "
        "part load 0.5, idle 0.3) sum to 1.1, not 1 (within 0.1%)\n")
    assert not (tmp_path / "out.xlsx").exists()


def test_a_blank_support_or_case_names_its_cell(duty_workbook, tmp_path, capsys):
    workbook = openpyxl.load_workbook(duty_workbook)
    ws = workbook["Supports"]
    header = [c.value for c in ws[1]]
    support, case = header.index("support") + 1, header.index("case") + 1
    ws.cell(4, support).value = None
    workbook.save(duty_workbook)
    letter = openpyxl.utils.get_column_letter(support)
    assert main(["calc", str(duty_workbook), "-o", str(tmp_path / "out.xlsx")]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: Supports!{letter}4: support is blank; every row of a "
                                       "duty cycle names its support\n")
    ws.cell(4, support).value = ws.cell(3, support).value
    ws.cell(4, case).value = None
    ws.cell(4, header.index("time_share") + 1).value = 7  # shares not summing to 1 name the blank case by its cell
    workbook.save(duty_workbook)
    assert main(["calc", str(duty_workbook), "-o", str(tmp_path / "out.xlsx")]) == 2
    assert f", Supports!{openpyxl.utils.get_column_letter(case)}4 7, " in capsys.readouterr().err


@pytest.mark.parametrize("in_place", [True, False])
def test_companions_a_run_no_longer_writes_are_emptied(duty_workbook, tmp_path, in_place):
    """The designer removes the duty cycle (and runs without --formulas): the earlier 'Duty cycle' summary and
    the hidden copy of the inputs are not left with numbers that no longer match the results; each keeps its
    place, mark and visibility and holds a note instead."""
    calc_workbook(duty_workbook, in_place=True, formulas=True)
    workbook = openpyxl.load_workbook(duty_workbook)
    ws = workbook["Supports"]
    for name in ("support", "case", "time_share"):
        ws.delete_cols([c.value for c in ws[1]].index(name) + 1)
    workbook.save(duty_workbook)
    out = duty_workbook if in_place else tmp_path / "copy.xlsx"
    run = calc_workbook(duty_workbook, None if in_place else out, in_place=in_place)
    assert run.duty is None
    assert run.companions == {"duty": "Duty cycle", "snapshot": "Calc inputs"}
    after = openpyxl.load_workbook(out)
    assert after.sheetnames == ["Supports", "Results", "Instructions", "Lists", "Calc inputs", "Duty cycle"]
    assert list(after["Duty cycle"].iter_rows(values_only=True)) == [(
        "No duty cycle: the last run of calc on 'Supports' found none (no support, case and time_share columns), so "
        "this summary is empty; its earlier numbers would not match the results.",)]
    assert after["Duty cycle"].sheet_state == "visible" and after["Calc inputs"].sheet_state == "hidden"
    assert list(after["Calc inputs"].iter_rows(values_only=True)) == [(
        "No live formulas: the last run of calc on 'Supports' wrote numbers (without --formulas), so this copy of "
        "the inputs is empty.",)]
