"""bearingheat audit on the command line: tables, files and exit codes."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from PIL import Image
from synthetic_catalogue import synthetic_catalogue
from synthetic_torque import measured_set, model_set

from bearingheat.analysis.audit import audit_coefficients
from bearingheat.cli import main
from bearingheat.io.tables import read_table

HR1 = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "hr1_2006_reference_speeds.csv"


def test_cli_reference_speeds(capsys, tmp_path):
    if not HR1.is_file():
        pytest.skip(f"{HR1} is not present: the HR 1 (2006) list is read from ../shared/data next to the repository")
    assert main(["audit", "--reference-speeds", str(HR1), "--out-dir", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert "systematic: tapered roller 330" in out
    # the flagged groups and their implied f0 come first, before the outliers and the table of all groups
    flagged = out.index("Flagged groups (7)")
    assert flagged < out.index("Outliers") < out.index("All series and size classes:")
    head = out[flagged:out.index("Outliers")]
    for group, implied in (("deep groove ball 618 d 45-140 mm", "1.212 ["), ("tapered roller 313", "2.991 ["),
                           ("tapered roller 320", "4.502 ["), ("tapered roller 330", "6.072 [")):
        line = next(line for line in head.splitlines() if group in line)
        assert implied in line, line
    series = pd.read_csv(tmp_path / "reference_speed_series.csv", keep_default_na=False)
    flagged_rows = series[series["systematic"].astype(str) == "True"]
    assert sorted(zip(flagged_rows["series"].astype(str), flagged_rows["subgroup"])) == [
        ("313", ""), ("320", ""), ("330", ""), ("331", ""), ("332", ""), ("60", "d 7-140 mm"),
        ("618", "d 45-140 mm")]
    assert (tmp_path / "reference_speeds.png").is_file()


#: the columns reference_speed_series.csv has at least (issue 13)
SERIES_COLUMNS = ["family", "series", "subgroup", "bearings", "median_deviation", "systematic", "f0_table",
                  "f0_implied", "f0_implied_low", "f0_implied_high"]


def test_cli_reference_speed_files(tmp_path, capsys):
    source = tmp_path / "catalogue.csv"
    synthetic_catalogue(f0_factor={("tapered roller 302", 0): 4.0 / 3.0}, misprints={"6208": 1.4}).to_csv(
        source, index=False)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    assert main(["audit", "--reference-speeds", str(source), "--out-dir", str(out_dir)]) == 1
    out = capsys.readouterr().out
    assert out.index("Flagged groups (1)") < out.index("tapered roller 302") < out.index("Outliers (1)")
    series = pd.read_csv(out_dir / "reference_speed_series.csv", keep_default_na=False)
    assert list(series.columns[:4]) == ["group", "family", "series", "subgroup"]
    assert set(SERIES_COLUMNS) <= set(series.columns)
    row = series[series["group"] == "tapered roller 302"].iloc[0]
    assert row["systematic"] and row["subgroup"] == "" and row["bearings"] == 31
    assert float(row["f0_implied_low"]) <= 4.0 <= float(row["f0_implied_high"])
    bearings = pd.read_csv(out_dir / "reference_speeds.csv", keep_default_na=False)
    assert {"designation", "group", "subgroup", "variant", "deviation", "local_deviation", "outlier",
            "f0_implied", "rounding_step"} <= set(bearings.columns)
    assert list(bearings.loc[bearings["outlier"].astype(str) == "True", "designation"]) == ["6208"]
    with Image.open(out_dir / "reference_speeds.png") as image:
        assert image.size[0] == 1650                     # 11 in at 150 dpi
        assert round(image.info["dpi"][0]) == 150
    # the files are there: a second run refuses to replace them without --force, and replaces them with it
    assert main(["audit", "--reference-speeds", str(source), "--out-dir", str(out_dir)]) == 2
    assert main(["audit", "--reference-speeds", str(source), "--out-dir", str(out_dir), "--force", "-q"]) == 1


def test_cli_coefficients(tmp_path, capsys):
    table, _, _ = measured_set("none", 3, designations=["30206-A", "6004", "6310", "NU208-E"])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    assert main(["audit", str(source), "--out-dir", str(tmp_path)]) == 0
    assert pd.read_csv(tmp_path / "coefficients.csv")["fitted"].notna().all()


def test_cli_neither_kind(tmp_path, capsys):
    source = tmp_path / "x.csv"
    pd.DataFrame({"a": [1]}).to_csv(source, index=False)
    assert main(["audit", str(source)]) == 2
    assert capsys.readouterr().err.strip() == (
        f"bearingheat audit: error: {source}: neither a measured torque column 'M [N*mm]' nor a published "
        "thermal reference speed column (n_thr, n_B, n_theta_r, n_θr, n_ref, nthr)")


def test_cli_no_input(capsys):
    assert main(["audit"]) == 2
    assert capsys.readouterr().err.strip() == "bearingheat audit: error: give DATA, --reference-speeds CSV, or both"


def test_subprocess_audit(tmp_path):
    table = pd.DataFrame({"designation": ["6205", "6206"], "d [mm]": [25, 30], "D [mm]": [52, 62],
                          "B [mm]": [15, 16], "C0 [N]": [7800, 11200], "n_B [1/min]": [14400, 12000]})
    source = tmp_path / "list.csv"
    table.to_csv(source, index=False)
    done = subprocess.run([sys.executable, "-m", "bearingheat", "audit", str(source)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "deep_groove_ball 62" in done.stdout


def test_top_level_help_lists_the_measured_data_commands():
    done = subprocess.run([sys.executable, "-m", "bearingheat", "--help"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    for name in ("lab", "audit", "diagnose"):
        assert f"    {name} " in done.stdout


def test_audit_model_all_prints_the_comparison_after_the_coefficients(tmp_path, capsys):

    source = tmp_path / "made.csv"
    model_set("schaeffler", seed=23).to_csv(source, index=False)
    assert main(["audit", str(source), "--model", "all", "--out-dir", str(tmp_path / "a")]) == 0
    printed = capsys.readouterr().out
    assert "schaeffler fits these data better than skf" in printed
    assert {p.name for p in (tmp_path / "a").iterdir()} == {"coefficients.csv", "models.md", "models.json",
                                                           "models.png"}


def test_audit_writes_no_file_when_one_of_its_jobs_fails(tmp_path, capsys):
    """--model all on data the SKF model cannot use (no oil level): refused with exit 2, and the coefficients,
    computed before the comparison failed, are not left in the folder (a rerun would need --force)."""
    out = tmp_path / "a"
    out.mkdir()
    example = Path(__file__).resolve().parents[2] / "examples" / "measured_torque_example.csv"
    assert main(["audit", str(example), "--model", "all", "--out-dir", str(out), "-q"]) == 2
    assert "the model comparison needs" in capsys.readouterr().err
    assert list(out.iterdir()) == []


def _with_blank_torque(tmp_path):
    """A 6205/6310 set of 60 rows with M blanked in 48 of them (every row whose position is no multiple of 5)."""
    table, _, _ = measured_set("none", 3, designations=["6205", "6310"])
    table = table.iloc[:60].reset_index(drop=True)
    blank = np.arange(len(table)) % 5 != 0
    table.loc[blank, "M [N*mm]"] = np.nan
    source = tmp_path / "blank.csv"
    table.to_csv(source, index=False)
    return source, int(blank.sum())


def test_excluded_rows_are_counted_listed_written_and_exit_1(tmp_path, capsys):
    """48 rows without torque: exit 0 before, 20 'excluded:' lines and no '... 28 more', no file."""
    source, blank = _with_blank_torque(tmp_path)
    assert blank == 48
    out = tmp_path / "out"
    out.mkdir()
    assert main(["audit", str(source), "--out-dir", str(out)]) == 1
    printed = capsys.readouterr().out.splitlines()
    excluded = audit_coefficients(read_table(str(source), None)).attrs["excluded"]
    assert len(excluded) == 48
    start = printed.index(f"48 rows excluded from the fit, all listed with their reasons in {out / 'excluded.csv'}:")
    assert printed[start + 1:start + 21] == [f"excluded: {message}" for message in excluded[:20]]
    assert printed[start + 21] == "... 28 more"
    written = pd.read_csv(out / "excluded.csv", keep_default_na=False)
    assert list(written.columns) == ["reason"] and list(written["reason"]) == excluded
    # -q: nothing printed, the exit code and the file still tell; a second run needs --force for excluded.csv
    assert main(["audit", str(source), "--out-dir", str(out), "-q"]) == 2
    capsys.readouterr()
    assert main(["audit", str(source), "--out-dir", str(out), "-q", "--force"]) == 1
    assert capsys.readouterr() == ("", "")


def test_an_earlier_runs_excluded_rows_are_not_left_behind(tmp_path, capsys):
    source, _ = _with_blank_torque(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    assert main(["audit", str(source), "--out-dir", str(out), "-q"]) == 1
    clean = tmp_path / "clean.csv"
    measured_set("none", 3, designations=["6205", "6310"])[0].to_csv(clean, index=False)
    assert main(["audit", str(clean), "--out-dir", str(out), "-q"]) == 2     # excluded.csv is there: --force
    assert main(["audit", str(clean), "--out-dir", str(out), "-q", "--force"]) == 0
    assert pd.read_csv(out / "excluded.csv").empty


def test_reference_speed_rows_not_computed_are_listed_and_exit_1(tmp_path, capsys):
    """n_B = 0 in 25 rows of series 62: no reason, deviation inf and exit 0 before; now each row is named, the
    first 20 are listed with '... 5 more', and the exit code is 1 (as for a row in error elsewhere)."""
    table = synthetic_catalogue()
    table = table[table["series"] == "62"].reset_index(drop=True)
    table.loc[:24, "n_B [1/min]"] = 0
    source = tmp_path / "list.csv"
    table.to_csv(source, index=False)
    assert main(["audit", "--reference-speeds", str(source)]) == 1
    printed = capsys.readouterr().out.splitlines()
    start = printed.index("Rows not computed (25), left out of every group:")
    assert printed[start + 1:start + 22] == [
        f"  row {i + 2} ({table['designation'].iat[i]}): n_B [1/min] = 0 is outside the expected range (a published "
        "speed must be a finite number > 0)" for i in range(20)] + ["  ... 5 more"]
    assert main(["audit", "--reference-speeds", str(source), "-q"]) == 1
    assert capsys.readouterr() == ("", "")


def test_sealed_bearings_without_a_published_speed_are_skipped_and_exit_0(tmp_path, capsys):
    """6205-2RSR has no n_B in HR 1: the row is named as skipped, and it is no row error (exit 0)."""
    path = tmp_path / "list.csv"
    pd.DataFrame({"designation": ["6205", "6206", "6205-2RSR"], "d [mm]": [25, 30, 25], "D [mm]": [52, 62, 52],
                  "B [mm]": [15, 16, 15], "C0 [N]": [7800, 11200, 7800],
                  "n_B [1/min]": ["14400", "12000", ""]}).to_csv(path, index=False)
    assert main(["audit", "--reference-speeds", str(path), "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert printed["reference_speed_rows_skipped"] == ["row 4 (6205-2RSR)"]
    assert printed["reference_speed_rows_not_computed"] == []
    assert main(["audit", "--reference-speeds", str(path)]) == 0
    assert ("Rows skipped (1), bearings with no published n_thr where catalogues print none (Schaeffler HR 1: '–'): "
            "those with contact seals, to which the thermal method (ISO 15312, DIN 732) does not apply, and those the "
            "bearing table holds without one (HR 1's 70..-B, 718..-B, NU19..); not audited: "
            "row 4 (6205-2RSR)") in capsys.readouterr().out.splitlines()
