"""CSV tables of supports: read for calc, results written back; an unreadable file is an InputError naming it."""
from __future__ import annotations

import re

import pandas as pd
import pytest
from excel_helpers import EXAMPLE_CSV, csv_result

from bearingheat.cli import main
from bearingheat.errors import InputError
from bearingheat.io.tables import read_csv, write_csv


def test_read_csv_ignores_spaces_after_commas(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("designation, d [mm], lubrication\n6208, 40, oil_bath\n")
    table = read_csv(path)
    assert list(table.columns) == ["designation", "d [mm]", "lubrication"]
    assert table.loc[0, "lubrication"] == "oil_bath" and table.loc[0, "d [mm]"] == 40


def test_unreadable_csv_is_an_input_error(tmp_path, capsys):
    path = tmp_path / "empty.csv"
    path.write_text("")
    with pytest.raises(InputError, match=re.escape(f"{path}: not a readable CSV (")):
        read_csv(path)
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err.startswith(f"bearingheat calc: error: {path}: not a readable CSV (")


def test_write_csv_round_trip(tmp_path):
    result = csv_result()
    written = write_csv(result, tmp_path / "out.csv")
    back = pd.read_csv(written)
    assert list(back.columns) == list(result.columns)
    pd.testing.assert_series_equal(back["MR [N*mm]"], result["MR [N*mm]"], rtol=1e-15)
    assert len(pd.read_csv(EXAMPLE_CSV)) == len(back)
