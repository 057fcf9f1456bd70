"""A CSV with a units row under a header of bare names, as a spreadsheet saves the Excel template's sheet 'Supports'."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX

from bearingheat.cli import main
from bearingheat.errors import InputError
from bearingheat.io.excel.libreoffice import convert, soffice
from bearingheat.io.tables import calc_csv, read_csv, read_table

HEADER = "id,designation,d,D,C0,lubrication,n,Fr,Fa,nu"
UNITS = "-,-,mm,mm,kN,-,rpm,kN,kN,mm^2/s"
ROWS = ["spindle rear,6205,25,52,7.8,oil_bath,3000,2.5,0.4,12.5",
        "spindle front,6205,25,52,7.8,oil_bath,3000,2.5,0,12.5"]
#: the same supports with the units in the headers
WITH_UNITS_IN_HEADERS = "id,designation,d [mm],D [mm],C0 [kN],lubrication,n [rpm],Fr [kN],Fa [kN],nu [mm^2/s]"
RESULTS = ["P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "MR [N*mm]", "NR [W]", "n_thr [1/min]"]


def _write(path: Path, *lines: str, newline: str = "\n") -> Path:
    path.write_bytes(newline.join(lines).encode() + newline.encode())
    return path


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_units_row_gives_the_units_of_the_headers(tmp_path, newline):
    with_row = calc_csv(_write(tmp_path / "units_row.csv", HEADER, UNITS, *ROWS, newline=newline))
    in_headers = calc_csv(_write(tmp_path / "headers.csv", WITH_UNITS_IN_HEADERS, *ROWS))
    assert list(with_row.columns) == list(in_headers.columns)
    pd.testing.assert_frame_equal(with_row, in_headers)
    # 6205, Fa = 0.4 kN: P1 = max(3.3*400 - 0.1*2500, 2500) = 2500 N (the Schaeffler catalogue, p. 68)
    assert with_row["P1 [N]"].tolist() == [2500.0, 2500.0]


def test_read_csv_takes_the_units_row_out_of_the_rows(tmp_path):
    table = read_csv(_write(tmp_path / "in.csv", HEADER, UNITS, *ROWS))
    assert list(table.columns) == WITH_UNITS_IN_HEADERS.split(",")
    assert len(table) == 2 and table["d [mm]"].tolist() == [25, 25] and table["Fr [kN]"].tolist() == [2.5, 2.5]
    assert list(table.attrs["lines"]) == [3, 4]  # the file's lines: header 1, units 2


def test_semicolons_decimal_commas_and_spaces_after_separators(tmp_path):
    # a European spreadsheet's CSV, with spaces after the separators (pandas' parser reads it)
    lines = [line.replace(",", ";") for line in (HEADER, UNITS)] + [
        "; ".join(cell.replace(".", ",") for cell in row.split(",")) for row in ROWS]
    with_row = calc_csv(_write(tmp_path / "eu.csv", *lines))
    in_headers = calc_csv(_write(tmp_path / "headers.csv", WITH_UNITS_IN_HEADERS, *ROWS))
    pd.testing.assert_frame_equal(with_row, in_headers)


def test_row_messages_cite_the_file_line_below_the_units_row(tmp_path, capsys):
    path = _write(tmp_path / "in.csv", HEADER, UNITS, ROWS[0], "", "bad,6205,25,52,7.8,oil_bath,-10,2,0,12")
    out = tmp_path / "out.csv"
    assert main(["calc", str(path), "-o", str(out), "-q"]) == 1
    messages = pd.read_csv(out, keep_default_na=False)["message"].tolist()
    assert messages == ["", 'row 5 (id "bad"): n [rpm]: -10 must be >= 0 (speed magnitude)']


def test_a_header_with_its_unit_keeps_it_and_an_equal_unit_below_is_accepted(tmp_path):
    header = HEADER.replace(",n,", ",n [1/min],")
    table = read_csv(_write(tmp_path / "in.csv", header, UNITS, *ROWS))  # rpm under 'n [1/min]': one unit
    assert "n [1/min]" in table.columns and table["n [1/min]"].tolist() == [3000, 3000]


def test_a_unit_that_contradicts_the_header_is_refused(tmp_path, capsys):
    path = _write(tmp_path / "in.csv", HEADER.replace(",Fr,", ",Fr [N],"), UNITS, *ROWS)
    message = (f"{path}: line 2, column 'Fr [N]': unit 'kN' in the units row contradicts the header 'Fr [N]'; "
               "keep one of them")
    with pytest.raises(InputError, match=f"^{re.escape(message)}$"):
        read_csv(path)
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {message}\n"


def test_a_cell_of_the_units_row_that_is_no_unit_is_named(tmp_path):
    path = _write(tmp_path / "in.csv", HEADER, UNITS.replace(",kN,kN,", ",KNN,kN,"), *ROWS)
    with pytest.raises(InputError) as exc:
        read_csv(path)
    assert str(exc.value) == (f"{path}: line 2: Fr: unknown unit 'KNN' (column 8) in the units row under the header; "
                              "write a unit such as kN, N, rpm, mm^2/s (docs/columns.md lists the columns)")


def test_a_units_row_without_rows(tmp_path):
    path = _write(tmp_path / "in.csv", HEADER, UNITS)
    with pytest.raises(InputError) as exc:
        read_csv(path)
    assert str(exc.value) == f"{path}: no supports (only a header row and a units row)"


@pytest.mark.parametrize("first_row", [
    "spindle rear,6205,25,52,7.8,oil_bath,3000,2.5,0.4,12.5",  # numbers: a row of data
    ",,,,,,,,,",                                                 # blank cells: no unit
    "x,6205,,,,oil_bath,,,,",                                    # texts, no number and no unit in a number column
])
def test_a_first_row_without_units_is_a_row_of_data(tmp_path, first_row):
    table = read_csv(_write(tmp_path / "in.csv", HEADER, first_row, ROWS[1]))
    assert list(table.columns) == HEADER.split(",")


def test_a_quoted_cell_over_two_lines_is_no_units_row(tmp_path):
    # the first record spans lines 2-3: a row of data, whose quoted id holds a line break
    table = read_csv(_write(tmp_path / "in.csv", WITH_UNITS_IN_HEADERS, '"two', 'lines",6205,25,52,7.8,oil_bath,'
                                                                               '3000,2.5,0,12.5'))
    assert table["id"].tolist() == ["two\nlines"]


def test_the_audit_reads_the_bearing_table_of_the_package(tmp_path, capsys):
    """bearingheat audit --reference-speeds on the package's own table (a units row under its header), as the
    Python API audits it (docs/measured.md)."""
    table = Path(__file__).resolve().parents[2] / "tables" / "bearings_hr1_2006.csv"
    assert main(["audit", "--reference-speeds", str(table), "--json", "-q"]) == 1  # (groups are flagged)
    report = json.loads(capsys.readouterr().out)
    audited = read_table(table)
    assert "n_thr [1/min]" in audited.columns and "C0 [N]" in audited.columns
    skipped = report["reference_speed_rows_skipped"]
    assert len(skipped) == 158 and len(audited) - len(skipped) == 1119


def _lines_of(path: Path) -> list[str]:
    return path.read_text(encoding="utf-8").splitlines()


@pytest.mark.integration
@pytest.mark.skipif(soffice() is None, reason="LibreOffice is not installed")
def test_the_example_workbook_saved_as_csv_by_libreoffice_is_computed_as_the_example_csv(tmp_path):
    """LibreOffice saves the example workbook's first sheet ('Supports', a header and a units row) as CSV: calc
    reads it and gives the example CSV's results."""
    saved, = convert([EXAMPLE_XLSX], "csv", tmp_path)
    assert _lines_of(saved)[1].startswith("-,-,mm,mm,rpm,kN,kN,mm^2/s,")
    from_workbook = calc_csv(saved)
    from_example = calc_csv(EXAMPLE_CSV)
    assert from_workbook["id"].tolist() == from_example["id"].tolist()
    assert from_workbook["status"].tolist() == from_example["status"].tolist()
    for column in RESULTS + ["T_op [degC]"]:
        np.testing.assert_allclose(from_workbook[column].to_numpy(float), from_example[column].to_numpy(float),
                                   rtol=1e-12, err_msg=column)


# ---- property: a units row reads as the same units written in the headers -----------------------------------------

#: dimensional columns and spellings of their units that engineers type
UNIT_CHOICES = {"d": ["mm", "in", "cm"], "Fr": ["kN", "N", "lbf"], "n": ["rpm", "1/min", "Hz", "U/min"],
                "nu": ["mm^2/s", "cSt"], "T_amb": ["degC", "°C"]}
_SEPARATORS = {",": ".", ";": ",", "\t": "."}  # separator -> a decimal mark it is used with


@st.composite
def _tables(draw):
    names = draw(st.lists(st.sampled_from(sorted(UNIT_CHOICES)), min_size=1, max_size=5, unique=True))
    units = [draw(st.sampled_from(UNIT_CHOICES[name])) for name in names]
    cell = st.one_of(st.just(""), st.floats(0.001, 1e5, allow_nan=False).map(lambda v: f"{v:.6g}"))
    rows = draw(st.lists(st.tuples(st.text("abcxyz 0123", min_size=1, max_size=6).map(str.strip).filter(bool),
                                   st.lists(cell, min_size=len(names), max_size=len(names))), min_size=1, max_size=6))
    sep = draw(st.sampled_from(sorted(_SEPARATORS)))
    return names, units, rows, sep


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(_tables())
def test_a_units_row_reads_as_units_in_the_headers(tmp_path_factory, table):
    names, units, rows, sep = table
    decimal = _SEPARATORS[sep]
    lines = [sep.join(cell.replace(".", decimal) for cell in [identifier, *cells]) for identifier, cells in rows]
    folder = tmp_path_factory.mktemp("units")
    with_row = _write(folder / "row.csv", sep.join(["id", *names]), sep.join(["-", *units]), *lines)
    in_headers = _write(folder / "headers.csv", sep.join(["id", *(f"{n} [{u}]" for n, u in zip(names, units))]),
                        *lines)
    expected = read_csv(in_headers)
    read = read_csv(with_row)
    pd.testing.assert_frame_equal(read, expected)
    assert list(read.attrs["lines"]) == [line + 1 for line in expected.attrs["lines"]]
