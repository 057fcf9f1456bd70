"""bearingheat calc: column contract, exit codes 0/1/2, help."""
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

from bearingheat.cli import main

ROOT = Path(__file__).parents[2]
EXAMPLE = ROOT / "examples" / "gearbox_shaft.csv"
RESULT_COLUMNS = ["f0", "f1", "P0 [N]", "P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]",
                  "status", "message"]


def test_example_runs_and_keeps_input_columns(tmp_path, capsys):
    out = tmp_path / "out.csv"
    assert main(["calc", str(EXAMPLE), "-o", str(out)]) == 0
    table = pd.read_csv(EXAMPLE)
    result = pd.read_csv(out)
    assert list(result.columns[: len(table.columns)]) == list(table.columns)
    added = list(result.columns[len(table.columns):])
    assert [c for c in added if c in RESULT_COLUMNS] == RESULT_COLUMNS
    assert added[:9] == RESULT_COLUMNS[:9] and added[-2:] == ["status", "message"]
    # every support is ok but the spindle's front pair, whose heat balance the sources do not define
    assert result["status"].tolist() == ["ok"] * 4 + ["warning", "ok"]
    assert result.loc[4, "message"].startswith('row 6 (id "spindle front (pair)"): n_thr: the heat balance of a '
                                               "bearing pair is not in the sources")
    # row 1: 6208 in an oil bath, hand calculation after the Schaeffler catalogue
    dM, n, nu = 60.0, 1480.0, 40.0
    P0 = max(0.6 * 3200 + 0.5 * 900, 3200)
    M = 2 * (nu * n) ** (2 / 3) * dM ** 3 * 1e-7 + 0.0009 * (P0 / 18000) ** 0.5 * max(3.3 * 900 - 320, 3200) * dM
    assert result.loc[0, "MR [N*mm]"] == pytest.approx(M, rel=1e-12)
    printed = capsys.readouterr().out
    assert "6 supports: 5 ok, 1 warning, 0 error; results written to" in printed


def test_bad_row_exit_1_other_rows_computed(tmp_path, capsys):
    src = tmp_path / "in.csv"
    src.write_text("id,designation,d [mm],D [mm],C0 [kN],lubrication,n [rpm],Fr [kN],nu [mm^2/s]\n"
                   "a,6205,25,52,7.8,oil_bath,3000,2,12\n"
                   "b,6205,25,52,7.8,oil_bath,3000,abc,12\n"
                   "c,6205,25,52,7.8,oil_bath,-10,2,12\n")
    out = tmp_path / "out.csv"
    assert main(["calc", str(src), "-o", str(out)]) == 1
    result = pd.read_csv(out, keep_default_na=False)
    assert list(result["status"]) == ["ok", "error", "error"]
    assert result.loc[1, "message"] == 'row 3 (id "b"): \'abc\' is not a number for Fr [kN]'
    assert result.loc[2, "message"] == 'row 4 (id "c"): n [rpm]: -10 must be >= 0 (speed magnitude)'
    assert float(result.loc[0, "MR [N*mm]"]) > 0
    assert 'error: row 3 (id "b"): \'abc\' is not a number for Fr [kN]' in capsys.readouterr().out


def test_units_in_headers_are_honoured(tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("designation,d [mm],D [cm],C0 [N],lubrication,n [Hz],Fr [lbf],nu [cSt]\n"
                   "6205,25,5.2,7800,oil_bath,50,449.6178861,12\n")
    out = tmp_path / "out.csv"
    assert main(["calc", str(src), "-o", str(out), "-q"]) == 0
    mr = pd.read_csv(out).loc[0, "MR [N*mm]"]
    hand = 2 * 36000 ** (2 / 3) * 38.5 ** 3 * 1e-7 + 0.0009 * (2000 / 7800) ** 0.5 * 2000 * 38.5
    assert mr == pytest.approx(hand, rel=1e-9)


@pytest.mark.parametrize("content,message", [
    ("designation,d [mm],lubrication,n [rpm],nu [mm^2/s]\n22205-E1,25,grease,100,10\n",
     "bearingheat calc: error: missing column: 'D [mm]' (any D unit of the right dimension)\n"),
    ("d [mm],D [mm],lubrication,n [rpm],nu [mm^2/s]\n25,52,grease,100,10\n",
     "bearingheat calc: error: missing column: 'designation' (or 'type' and 'series')\n"),
    ("designation,d [mm],D [mm],lubrication,n [rpm],Fr [kg],nu [mm^2/s]\n6205,25,52,grease,100,1,10\n",
     "bearingheat calc: error: column 'Fr [kg]': kilogram is a mass, not a force; for kilogram-force write kgf\n"),
    ("designation,d,D [mm],lubrication,n [rpm],nu [mm^2/s]\n6205,25,52,grease,100,10\n",
     "bearingheat calc: error: column 'd': needs a unit, e.g. 'd [mm]'\n"),
    ("designation,d [mm],D [mm],lubrication,n [m/s],nu [mm^2/s]\n6205,25,52,grease,100,10\n",
     "bearingheat calc: error: column 'n [m/s]': m/s is not a shaft speed; "
     "expected revolutions per time (1/min, rpm, Hz) or an angular speed (rad/s)\n"),
])
def test_unusable_input_exit_2(tmp_path, capsys, content, message):
    src = tmp_path / "in.csv"
    src.write_text(content)
    assert main(["calc", str(src)]) == 2
    assert capsys.readouterr().err == message


def test_missing_file_exit_2(tmp_path, capsys):
    assert main(["calc", str(tmp_path / "none.csv")]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {tmp_path / 'none.csv'}: no such file\n"


def test_excel_only_flags_refused_for_csv(capsys):
    assert main(["calc", str(EXAMPLE), "--formulas"]) == 2
    assert capsys.readouterr().err == ("bearingheat calc: error: --in-place, --formulas and --sheet apply to Excel "
                                       "workbooks only\n")


def test_f2_chart_option(tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("designation,d [mm],D [mm],lubrication,n [rpm],Fr [N],Fa [N],nu [mm^2/s]\n"
                   "NJ206-E,30,62,circulating_oil,300,5000,50,20\n")
    out = tmp_path / "out.csv"
    assert main(["calc", str(src), "-o", str(out), "-q", "--f2-chart", str(ROOT / "docs" / "f2_chart_example.csv")]) == 0
    result = pd.read_csv(out)
    assert result.loc[0, "M2 [N*mm]"] > 0
    assert result.loc[0, "Fa/A"] == pytest.approx(50 / (15e-3 * 46 ** 2.1), rel=1e-9)
    assert result.loc[0, "nu*n*dM [mm^3/(s*min)]"] == pytest.approx(20 * 300 * 46, rel=1e-12)


def test_help_lists_columns(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["calc", "--help"])
    assert exc.value.code == 0
    text = capsys.readouterr().out
    for piece in ("designation", "C0 [N]", "lubrication", "grease | oil_mist | oil_bath | circulating_oil",
                  "MR [N*mm]", "NR [W]", "Exit codes"):
        assert piece in text


def test_module_entry_point_subprocess(tmp_path):
    out = tmp_path / "o.csv"
    proc = subprocess.run([sys.executable, "-m", "bearingheat", "calc", str(EXAMPLE), "-o", str(out)],
                          capture_output=True, text=True, check=False)
    assert proc.returncode == 0, proc.stderr
    assert out.exists()
    top = subprocess.run([sys.executable, "-m", "bearingheat", "--help"], capture_output=True, text=True, check=False)
    assert top.returncode == 0 and "calc" in top.stdout


def test_n_per_method_option(tmp_path):
    exact, approx = tmp_path / "exact.csv", tmp_path / "approx.csv"
    assert main(["calc", str(EXAMPLE), "-o", str(exact), "-q"]) == 0
    assert main(["calc", str(EXAMPLE), "-o", str(approx), "-q", "--n-per-method", "approximation"]) == 0
    a, b = pd.read_csv(exact), pd.read_csv(approx)
    assert a["n_per_method_used"].tolist()[:4] == ["exact root"] * 4
    assert b["n_per_method_used"].tolist()[:4] == ["catalogue approximation"] * 4
    assert b["n_per [1/min]"].iat[0] == pytest.approx(a["n_per [1/min]"].iat[0], rel=0.01)
    assert b["MR [N*mm]"].tolist() == a["MR [N*mm]"].tolist()


def test_a_duty_cycle_gets_its_summary_beside_the_results(tmp_path, capsys):
    from pathlib import Path
    example = Path(__file__).resolve().parents[2] / "examples" / "gearbox_duty_cycle.csv"
    out = tmp_path / "results.csv"
    assert main(["calc", str(example), "-o", str(out)]) == 0
    summary = pd.read_csv(tmp_path / "results.duty.csv")
    assert summary["support"].tolist() == ["input shaft A", "input shaft B"]
    assert "duty cycle (time-weighted per support):" in capsys.readouterr().out
    # the summary is an output like the results: not replaced without --force
    (tmp_path / "results.csv").unlink()
    assert main(["calc", str(example), "-o", str(out)]) == 2
    assert "results.duty.csv" in capsys.readouterr().err


def test_json_prints_the_results_and_the_counts(capsys):
    import json
    from pathlib import Path
    example = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"
    assert main(["calc", str(example), "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert printed["counts"] == {"ok": 5, "warning": 1, "error": 0}
    assert printed["results"][0]["id"] == "input shaft A (locating)"
    assert printed["results"][0]["MR [N*mm]"] == pytest.approx(138.478171, rel=1e-8)
    assert printed["results"][4]["n_thr [1/min]"] is None  # NaN is null


def test_a_long_table_prints_its_first_rows_and_the_counts(tmp_path, capsys):
    from pathlib import Path
    example = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"
    big = pd.concat([pd.read_csv(example)] * 20, ignore_index=True)
    source = tmp_path / "big.csv"
    big.to_csv(source, index=False)
    assert main(["calc", str(source)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert "... 70 more rows; -o FILE writes them all" in out
    assert "... 20 more rows with messages; -o FILE writes them all" not in out  # 20 warnings: all shown
    assert out[-1] == "120 supports: 100 ok, 20 warning, 0 error"


def _big_table(tmp_path, copies: int) -> Path:
    big = pd.concat([pd.read_csv(EXAMPLE)] * copies, ignore_index=True)
    big["n [rpm]"] = big["n [rpm]"].astype(object)
    big.loc[7, "n [rpm]"] = "abc"
    source = tmp_path / "big.csv"
    big.to_csv(source, index=False)
    return source


def test_a_big_table_to_parquet_and_csv_gives_the_same_results(tmp_path, capsys):
    """The table path (blocks of rows, results in Arrow, pyarrow's writers) writes what calc computes: the same
    numbers in Parquet and CSV, the units as Parquet field metadata, the rows' own file lines in the messages."""
    import numpy as np
    import pyarrow.parquet as parquet

    from bearingheat.io.tables import calc_csv
    source = _big_table(tmp_path, 500)  # 3000 rows
    assert main(["calc", str(source), "-o", str(tmp_path / "out.parquet"), "-q"]) == 1
    assert main(["calc", str(source), "-o", str(tmp_path / "out.csv"), "-q"]) == 1
    assert capsys.readouterr().out == ""
    expected = calc_csv(source)
    parquet_result = pd.read_parquet(tmp_path / "out.parquet")
    csv_result = pd.read_csv(tmp_path / "out.csv")
    assert list(parquet_result.columns) == list(expected.columns) == list(csv_result.columns)
    for column in ("MR [N*mm]", "NR [W]", "n_thr [1/min]", "T_op [degC]"):
        np.testing.assert_array_equal(parquet_result[column].to_numpy(), expected[column].to_numpy())
        np.testing.assert_array_equal(csv_result[column].to_numpy(), expected[column].to_numpy())
    assert parquet_result["message"].iloc[7] == csv_result["message"].iloc[7] == \
        "row 9 (id \"input shaft B (floating)\"): 'abc' is not a number for n [rpm]; n [rpm]: missing; the " \
        "operating speed is needed"
    assert parquet.read_schema(tmp_path / "out.parquet").field("NR [W]").metadata == {b"unit": b"W"}


def test_the_progress_bar_is_drawn_on_a_terminal_only(tmp_path, monkeypatch, capsys):
    import io
    import sys

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    source = _big_table(tmp_path, 500)
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    assert main(["calc", str(source), "-o", str(tmp_path / "out.parquet")]) == 1
    assert "calc" in terminal.getvalue() and "3000/3000" in terminal.getvalue()
    quiet = Terminal()
    monkeypatch.setattr(sys, "stderr", quiet)
    assert main(["calc", str(source), "-o", str(tmp_path / "out.parquet"), "--force", "-q"]) == 1
    assert quiet.getvalue() == (f"error: 1 of 3000 supports are in error; see the message column of "
                                f"{tmp_path / 'out.parquet'}\n")  # no bar: the one line -q prints for rows in error
    monkeypatch.undo()
    assert main(["calc", str(source), "-o", str(tmp_path / "out.parquet"), "--force"]) == 1
    assert capsys.readouterr().err == ""  # stderr is no terminal here


def test_json_carries_dates_and_decimals_of_passed_through_columns(tmp_path, capsys):
    """A column calc does not know passes through, also into --json: dates as ISO 8601 text, decimals as numbers
    (not a TypeError traceback)."""
    import datetime
    import decimal
    import json

    import pyarrow as pa
    import pyarrow.parquet as parquet

    table = pa.Table.from_pandas(pd.read_csv(EXAMPLE), preserve_index=False)
    rows = table.num_rows
    table = table.append_column("inspected", pa.array([datetime.date(2024, 5, 1)] * rows, pa.date32()))
    table = table.append_column("logged", pa.array([datetime.datetime(2024, 5, 1, 8, 30)] * rows, pa.timestamp("s")))
    table = table.append_column("price", pa.array([decimal.Decimal("12.50")] * rows, pa.decimal128(6, 2)))
    parquet.write_table(table, tmp_path / "dated.parquet")
    assert main(["calc", str(tmp_path / "dated.parquet"), "--json"]) == 0
    first = json.loads(capsys.readouterr().out)["results"][0]
    assert (first["inspected"], first["logged"], first["price"]) == ("2024-05-01", "2024-05-01T08:30:00", 12.5)
