"""Measured files as diagnose and lab read them: the decimal mark, the rows messages cite, headers that look like
a measured column, blank group labels, why too few rows were left, the arguments of diagnose, the columns they
pass through."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from diagnose_cases import small_table
from synthetic_catalogue import synthetic_catalogue

from bearingheat.analysis.audit import audit_reference_speeds
from bearingheat.analysis.diagnose import (DiagnoseError, diagnose, diagnose_measurements, diagnose_table,
                                           model_data, read_measurements)
from bearingheat.analysis.lab import process_lab
from bearingheat.calc.contract import LABEL_COLUMNS, input_units
from bearingheat.calc.conversion import lookalike_column
from bearingheat.cli import main
from bearingheat.errors import AuditError, LabError
from bearingheat.io.tables import calc_csv, read_table

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MEASURED = EXAMPLES / "measured_torque_example.csv"
READINGS = EXAMPLES / "lab_dp11a_example.csv"


def _exactly(message: str) -> str:
    return f"^{re.escape(message)}$"


def _euro(source: Path, target: Path) -> Path:
    """The same table as a spreadsheet of a comma-decimal locale writes it: ';' between cells, ',' in numbers."""
    pd.read_csv(source).to_csv(target, sep=";", decimal=",", index=False)
    return target


# ---- the file's decimal mark -------------------------------------------------------------------

def test_a_comma_decimal_csv_diagnoses_as_the_point_csv(tmp_path):
    euro = _euro(MEASURED, tmp_path / "euro.csv")
    assert "0,0;8,0;70,0;" in euro.read_text().splitlines()[1]  # the measured columns are text with commas
    point = diagnose_measurements(read_measurements(read_table(MEASURED)))
    for table in (read_table(euro), read_table(euro, sep=";", decimal=",")):
        comma = diagnose_measurements(read_measurements(table))
        assert comma.effect == point.effect == "seal_drag"
        np.testing.assert_allclose(comma.data.M, point.data.M, rtol=1e-12)
        np.testing.assert_allclose(comma.data.T_oil, point.data.T_oil, rtol=1e-12)
        got, expected = comma.summary(), point.summary()
        for key in ("rmse_before", "rmse_after", "cv_rmse_after", "mape_before", "bias_before", "n_rows"):
            assert got[key] == pytest.approx(expected[key], rel=1e-12)
        for name, value in expected["parameters"]["M_seal [N*mm]"].items():
            assert got["parameters"]["M_seal [N*mm]"][name] == pytest.approx(value, rel=1e-12)


def test_a_point_in_a_comma_decimal_file_is_no_number(tmp_path):
    euro = _euro(MEASURED, tmp_path / "euro.csv")
    lines = euro.read_text().splitlines()
    lines[3] = ";".join(lines[3].split(";")[:-1] + ["19.68"])
    euro.write_text("\n".join(lines) + "\n")
    measured = read_measurements(read_table(euro, decimal=","))
    assert measured.row_errors[2] == ["row 4: '19.68' is not a number for M [N*mm] (the decimal mark is ',')"]


def test_a_comma_decimal_csv_of_lab_readings(tmp_path):
    euro = _euro(READINGS, tmp_path / "lab_euro.csv")
    point = process_lab(read_table(READINGS))
    comma = process_lab(read_table(euro, sep=";", decimal=","))
    for task in ("task1", "task2", "task3", "comparison"):
        pd.testing.assert_frame_equal(getattr(comma, task), getattr(point, task), rtol=1e-12, check_exact=False)


# ---- the row a message cites -------------------------------------------------------------------

def test_messages_cite_the_line_of_the_file_as_calc_does(tmp_path):
    table = small_table(5)
    for column in ("Fr [N]", "M [N*mm]"):
        table[column] = table[column].astype(object)
    table.loc[3, "Fr [N]"] = "x"          # file line 5
    table.loc[1, "M [N*mm]"] = "abc"      # file line 3
    path = tmp_path / "m.csv"
    table.to_csv(path, index=False)
    assert calc_csv(path)["message"].iat[3] == "row 5: 'x' is not a number for Fr [N]"
    measured = read_measurements(read_table(path))
    assert measured.row_errors[3] == ["row 5: 'x' is not a number for Fr [N]"]
    assert measured.row_errors[1] == ["row 3: 'abc' is not a number for M [N*mm]"]
    # a blank line of the file is no row: the rows after it keep their line numbers
    text = path.read_text().splitlines()
    path.write_text("\n".join(text[:2] + [""] + text[2:]) + "\n")
    measured = read_measurements(read_table(path))
    assert measured.row_errors[1] == ["row 4: 'abc' is not a number for M [N*mm]"]
    assert calc_csv(path)["message"].iat[3] == "row 6: 'x' is not a number for Fr [N]"
    # a sheet: the sheet's row, as calc names the cell (Sheet1!B4)
    book = tmp_path / "m.xlsx"
    table.to_excel(book, index=False)
    assert read_measurements(read_table(book)).row_errors[1] == ["row 3: 'abc' is not a number for M [N*mm]"]
    # a table without lines (the API, Parquet): the row's position + 1
    assert read_measurements(table).row_errors[1] == ["row 2: 'abc' is not a number for M [N*mm]"]


def test_model_errors_cite_the_line_of_the_file(tmp_path):
    table = small_table(4)
    table["designation"] = ["6205", "6205", "6205", "9999X"]
    table["d [mm]"], table["D [mm]"] = table["d [mm]"].astype(object), table["D [mm]"].astype(object)
    table.loc[3, ["d [mm]", "D [mm]"]] = None
    path = tmp_path / "m.csv"
    table.to_csv(path, index=False)
    calc_message = calc_csv(path)["message"].iat[3]
    _, _, excluded = model_data(read_measurements(read_table(path)))
    assert calc_message.startswith("row 5: ")
    assert [e.split(": ")[0] for e in excluded] == ["row 5"]


def test_lab_messages_cite_the_line_of_the_file(tmp_path):
    table = pd.read_csv(READINGS).astype({"Q [kg]": object})
    table.loc[1, "Q [kg]"] = "heavy"
    path = tmp_path / "r.csv"
    table.to_csv(path, index=False)
    with pytest.raises(LabError, match=_exactly("row 3: 'heavy' is not a number for Q [kg]")):
        process_lab(read_table(path))
    table.loc[1, "Q [kg]"] = -1.0
    table.to_csv(path, index=False)
    with pytest.raises(LabError, match=_exactly("row 3: Q [kg] = -1 must be > 0")):
        process_lab(read_table(path))


# ---- headers that look like a measured column ------------------------------------------------------------

@pytest.mark.parametrize("header,message", [
    ("T_oil (degC)", "column 'T_oil (degC)' looks like 'T_oil', which is not read from it: name it 'T_oil [degC]' "
                     "(headers are 'name [unit]', the name in its own letters); as it is, the oil temperature would "
                     "be taken as not measured"),
    ("t(h)", "column 't(h)' looks like 't', which is not read from it: name it 't [h]' (headers are 'name [unit]', "
             "the name in its own letters); as it is, the running time would be taken as not measured (and run_in "
             "as not applicable)"),
    ("Group", "column 'Group' looks like 'group', which is not read from it: name it 'group' (headers are "
              "'name [unit]', the name in its own letters); as it is, the rows would be grouped by operating point "
              "instead of by these labels"),
    ("T_OIL [degC]", "column 'T_OIL [degC]' looks like 'T_oil', which is not read from it: name it 'T_oil [degC]' "
                     "(headers are 'name [unit]', the name in its own letters); as it is, the oil temperature would "
                     "be taken as not measured"),
])
def test_a_header_that_looks_like_a_measured_column_is_refused(header, message):
    table = small_table(4)
    table[header] = [1.0, 2.0, 3.0, 4.0]
    with pytest.raises(DiagnoseError, match=_exactly(message)):
        read_measurements(table)


def test_a_torque_header_with_its_unit_in_parentheses_is_refused():
    table = small_table(4).rename(columns={"M [N*mm]": "M (N*m)"})
    with pytest.raises(DiagnoseError, match=_exactly(
            "column 'M (N*m)' looks like 'M', which is not read from it: name it 'M [N*m]' (headers are "
            "'name [unit]', the name in its own letters); as it is, the table would have no measured torque")):
        read_measurements(table)


def test_one_matcher_finds_calcs_and_diagnoses_lookalikes_and_only_diagnose_refuses_a_text_column_in_unit_form():
    """calc.conversion and diagnose had two copies of the lookalike matcher; one serves both now. A text column
    written in the other-unit form is a note to calc ('lubrication (old)') but diagnose's group ('group (run)')."""
    table = small_table(4)
    table["group (run)"] = ["a", "a", "b", "b"]
    with pytest.raises(DiagnoseError, match=_exactly(
            "column 'group (run)' looks like 'group', which is not read from it: name it 'group' (headers are "
            "'name [unit]', the name in its own letters); as it is, the rows would be grouped by operating point "
            "instead of by these labels")):
        read_measurements(table)
    noted = small_table(4).drop(columns=["lubrication"])
    noted["lubrication (old)"] = "grease"
    noted["f0"] = 2.0
    assert lookalike_column(noted.columns, input_units(), never_missed=LABEL_COLUMNS) is None
    assert read_measurements(noted).frame["f0"].tolist() == [2.0] * 4


def test_the_measured_column_itself_beside_a_lookalike_is_read():
    table = small_table(4)
    table["T_oil [degC]"] = 60.0
    table["T_oil (max) [degC]"] = 80.0   # another column, not a unit written another way
    assert np.all(read_measurements(table).T_oil == 60.0)


# ---- blank group labels --------------------------------------------------------------------------------

def test_a_blank_group_label_is_a_row_error(tmp_path):
    table = small_table(4)
    table["group"] = ["run 1", None, "run 2", " "]
    path = tmp_path / "g.csv"
    table.to_csv(path, index=False)
    measured = read_measurements(read_table(path))
    assert measured.row_errors == [
        [], ["row 3: group is blank; with a group column every row needs its label (the run it belongs to)"],
        [], ["row 5: group is blank; with a group column every row needs its label (the run it belongs to)"]]


# ---- why too few rows are left; the arguments of diagnose --------------------------------------------

def test_too_few_rows_says_why_rows_were_left_out():
    table = small_table(25)
    table["T_oil [degC]"] = 400.0
    with pytest.raises(DiagnoseError, match=_exactly(
            'diagnose needs at least 20 usable rows of measured torque; got 0; 25 rows left out, the first: '
            'row 1: T_oil = 400 degC is outside -60 to 300 degC')):
        diagnose_table(table)


def test_folds_and_candidates_are_checked():
    data, _, _ = model_data(read_measurements(small_table(25)))
    with pytest.raises(DiagnoseError, match=_exactly(
            'k = 1: the grouped cross-validation needs an integer number of folds >= 2')):
        diagnose(data, k=1)
    with pytest.raises(DiagnoseError, match=_exactly(
            "candidate 'seal' is not one of none, seal_drag, f0_scale, viscosity_heating, drag_losses, run_in, "
            "preload")):
        diagnose(data, candidates=["seal"])
    with pytest.raises(DiagnoseError, match=_exactly(
            '5-fold cross-validation needs at least 5 operating points (groups); got 1')):
        diagnose(data, k=5)


# ---- a header that is no 'name [unit]' ---------------------------------------------------------

def test_a_header_that_is_no_name_and_unit_is_left_alone_as_calc_leaves_it(tmp_path):
    """'remark [see note]]' passes through calc; diagnose, audit and lab refused the whole file ('cannot read the
    header'). It names no measured quantity, so they now leave it out and read the rest as before."""
    noted = tmp_path / "noted.csv"
    table = pd.read_csv(MEASURED)
    table.insert(2, "remark [see note]]", "r")
    table.to_csv(noted, index=False)
    plain, with_note = (diagnose_measurements(read_measurements(read_table(path))) for path in (MEASURED, noted))
    assert with_note.effect == plain.effect == "seal_drag"
    assert with_note.summary()["rmse_after"] == pytest.approx(plain.summary()["rmse_after"], rel=1e-12)
    readings = pd.read_csv(READINGS)
    readings["remark [see note]]"] = "r"
    lab_noted = tmp_path / "lab_noted.csv"
    readings.to_csv(lab_noted, index=False)
    pd.testing.assert_frame_equal(process_lab(read_table(lab_noted)).task1, process_lab(read_table(READINGS)).task1)


def test_a_remark_left_out_of_the_reading_keeps_the_files_decimal_mark_and_lines(tmp_path):
    """The columns diagnose reads are selected from the table without the remark; the selection keeps the file's
    decimal mark and line numbers (DataFrame.attrs, which pandas carries to a column selection)."""
    euro = _euro(MEASURED, tmp_path / "euro.csv")
    lines = euro.read_text().splitlines()
    lines[3] = ";".join(lines[3].split(";")[:-1] + ["19.68"])
    euro.write_text("\n".join([f"{lines[0]};remark [see note]]"] + [f"{line};r" for line in lines[1:]]) + "\n")
    measured = read_measurements(read_table(euro, decimal=","))
    assert measured.row_errors[2] == ["row 4: '19.68' is not a number for M [N*mm] (the decimal mark is ',')"]
    assert sum(map(bool, measured.row_errors)) == 1


def test_audit_lab_and_diagnose_pass_a_remark_through_and_keep_it_where_they_write_the_rows_back(tmp_path):
    """audit (measured torque and a catalogue list) still refused 'remark [see note]]' ('cannot read the header');
    lab and the reference speed audit dropped a remark from the rows they write back. Now every command reads the
    rest as before, and readings.csv and reference_speeds.csv keep the columns they do not read, as calc does."""
    measured = pd.read_csv(MEASURED)
    noted = measured.copy()
    noted.insert(2, "remark [see note]]", [f"r{i}" for i in range(len(noted))])
    noted["comment"] = "bench 2"
    noted_path = tmp_path / "noted.csv"
    noted.to_csv(noted_path, index=False)
    plain_dir, noted_dir = tmp_path / "plain", tmp_path / "noted"
    for out in (plain_dir, noted_dir):
        out.mkdir()
    # (exit 1: the example's seal drag puts the table f0 and f1 outside their intervals)
    assert main(["audit", str(MEASURED), "--out-dir", str(plain_dir), "-q"]) == \
        main(["audit", str(noted_path), "--out-dir", str(noted_dir), "-q"]) == 1
    pd.testing.assert_frame_equal(pd.read_csv(noted_dir / "coefficients.csv"),
                                  pd.read_csv(plain_dir / "coefficients.csv"))
    assert main(["diagnose", str(noted_path), "--out-dir", str(noted_dir), "-q"]) == 0
    assert json.loads((noted_dir / "summary.json").read_text())["effect"] == "seal_drag"
    # lab: the readings written back end with the columns no reading is taken from, as typed
    readings = pd.read_csv(READINGS)
    readings.insert(1, "remark [see note]]", [f"r{i}" for i in range(len(readings))])
    readings["comment"] = "rig 2"
    lab_noted = tmp_path / "lab_noted.csv"
    readings.to_csv(lab_noted, index=False)
    lab = process_lab(read_table(lab_noted), nu=20.0)
    assert list(lab.readings.columns[-2:]) == ["remark [see note]]", "comment"]
    assert lab.readings["remark [see note]]"].tolist() == [f"r{i}" for i in range(len(readings))]
    assert set(lab.readings["comment"]) == {"rig 2"}
    pd.testing.assert_frame_equal(lab.readings.iloc[:, :-2], process_lab(read_table(READINGS), nu=20.0).readings)
    # the reference speed audit: each bearing's row keeps its page and remark
    catalogue = synthetic_catalogue()
    catalogue.insert(1, "remark [see note]]", [f"r{i}" for i in range(len(catalogue))])
    catalogue["page"] = np.arange(len(catalogue)) + 100
    listed = tmp_path / "catalogue.csv"
    catalogue.to_csv(listed, index=False)
    speeds = audit_reference_speeds(read_table(listed))
    assert list(speeds.columns[-2:]) == ["remark [see note]]", "page"]
    assert speeds["remark [see note]]"].tolist() == [f"r{i}" for i in range(len(catalogue))]
    pd.testing.assert_frame_equal(speeds.iloc[:, :-2], audit_reference_speeds(
        catalogue.drop(columns=["remark [see note]]", "page"])))
    speeds_dir = tmp_path / "speeds"
    speeds_dir.mkdir()
    main(["audit", "--reference-speeds", str(listed), "--out-dir", str(speeds_dir), "-q"])
    written = pd.read_csv(speeds_dir / "reference_speeds.csv")
    assert written["page"].tolist() == list(range(100, 100 + len(catalogue)))
    assert written["remark [see note]]"].tolist() == [f"r{i}" for i in range(len(catalogue))]


def test_a_column_kept_under_a_header_the_command_writes_is_refused():
    """Kept, a user's 'Fa' beside lab's own Fa (or a 'group' beside the audit's) would give the file two columns of
    one header: refused, as calc refuses an input column named like one of its results."""
    readings = pd.read_csv(READINGS)
    readings["Fa"] = 1.0
    with pytest.raises(LabError, match=_exactly(
            "column 'Fa' is a column lab writes into readings.csv; rename it (e.g. 'Fa (own)')")):
        process_lab(readings)
    catalogue = synthetic_catalogue()
    catalogue["group"] = "A"
    with pytest.raises(AuditError, match=_exactly(
            "column 'group' is a column the reference speed audit writes into reference_speeds.csv; rename it "
            "(e.g. 'group (own)')")):
        audit_reference_speeds(catalogue)
