"""The reference-speed audit on lists it could not fully use: few series, cells that are no published speed."""
from __future__ import annotations

import numpy as np
import pandas as pd
from synthetic_catalogue import synthetic_catalogue

from bearingheat.analysis.audit import audit_reference_speeds, classify_reference_speeds
from bearingheat.analysis.deviations import consistent_scale
from bearingheat.catalogue.bearings import bearing_table
from bearingheat.io.reports.audit import reference_speed_lines
from bearingheat.io.tables import read_table

HR1_COLUMNS = {"d": "d [mm]", "D": "D [mm]", "B": "B [mm]", "T": "T [mm]", "C0": "C0 [N]", "n_thr": "n_thr [1/min]"}


def test_too_few_series_keep_none_and_sigma_is_the_floor():
    sigma, kept = consistent_scale([-0.175, -0.154], z=5.0, floor=0.002, min_groups=5)
    assert sigma == 0.002 and kept.tolist() == [False, False]
    # three of five agree: too few to estimate from after clipping, none kept
    sigma, kept = consistent_scale([0.001, -0.002, 0.0015, 0.2, -0.15], z=5.0, floor=0.002, min_groups=5)
    assert sigma == 0.002 and not kept.any()


def test_two_series_say_sigma_is_the_floor_not_the_scale_of_series_that_agree():
    """618 and 313 of HR 1 alone: the text called 0.20 % the robust scale of '2 series that agree with the
    tables' and then flagged both."""
    hr1 = bearing_table().rename(columns=HR1_COLUMNS)
    keys = audit_reference_speeds(hr1)["series_key"]
    two = hr1.loc[keys.index[keys.isin(["deep groove ball 618", "tapered roller 313"])]]  # (the audit's index)
    audit = classify_reference_speeds(audit_reference_speeds(two))
    assert (audit.scale, audit.consistent, audit.series) == (0.002, 0, 2)
    assert reference_speed_lines(audit)[1] == (
        "sigma = 0.20% (the floor, not estimated from the data: of the 2 series, fewer than 5 agree with the "
        "tables, too few for a robust scale); threshold = +/-1.00%.")
    # the whole list: 16 series give sigma (the 14 of the HR 1 data set, and deep groove ball 619 and
    # cylindrical roller 10 of the more series)
    whole = classify_reference_speeds(audit_reference_speeds(hr1))
    assert whole.consistent == 16 and np.isclose(whole.scale, 0.0029, atol=5e-5)
    assert reference_speed_lines(whole)[1].startswith(
        "sigma = 0.29% (robust scale of the median deviations of the 16 series that agree with the tables)")


# ---- cells that are no published speed or no dimension ------------------------------------------

#: position in series 62 of the synthetic list -> (column, typed cell, the reason of its row)
BAD_CELLS = {
    3: ("C0 [N]", "abc", "row 5 (624-2Z): 'abc' is not a number for C0 [N] (the static load rating C0 must be a "
                         "finite number > 0)"),
    4: ("n_B [1/min]", "5 600", "row 6 (625): '5 600' is not a number for n_B [1/min] (a published speed must be a "
                                "finite number > 0)"),
    5: ("d [mm]", "5,5", "row 7 (625-2Z): '5,5' is not a number for d [mm] (the bore d must be a finite number > 0)"),
    6: ("n_B [1/min]", "0", "row 8 (626): n_B [1/min] = 0 is outside the expected range (a published speed must be "
                            "a finite number > 0)"),
    7: ("n_B [1/min]", "-5", "row 9 (626-2Z): n_B [1/min] = -5 is outside the expected range (a published speed "
                             "must be a finite number > 0)"),
    8: ("n_B [1/min]", "", "row 10 (627): n_B [1/min] is blank (a published speed must be a finite number > 0)"),
    9: ("C0 [N]", "-220", "row 11 (627-2Z): C0 [N] = -220 is outside the expected range (the static load rating C0 "
                          "must be a finite number > 0)"),
}


def series_62(tmp_path, cells=None):
    """Series 62 of the synthetic list (the tables' own speeds) as a CSV with ``cells`` typed in, read as the
    command reads it (file lines: the header is line 1, the row at position i is line i + 2)."""
    table = synthetic_catalogue()
    table = table[table["series"] == "62"].reset_index(drop=True).astype(object)
    for position, (column, text, _) in (cells or {}).items():
        table.loc[position, column] = text
    path = tmp_path / "list.csv"
    table.to_csv(path, index=False)
    return read_table(path), path


def test_cells_that_are_no_number_or_out_of_range_name_row_column_value_and_range(tmp_path):
    """'abc' in C0 was 'C0 [N]: missing', '5 600' in n_B 'blank', '5,5' in d silently the catalogue bore,
    n_B = 0 a deviation of inf without reason, n_B = -5 an outlier of -932066.9 %."""
    clean = audit_reference_speeds(series_62(tmp_path)[0])
    rows = audit_reference_speeds(series_62(tmp_path, BAD_CELLS)[0])
    bad = sorted(BAD_CELLS)
    assert list(rows["reason"].iloc[bad]) == [BAD_CELLS[i][2] for i in bad]
    assert (rows["reason"].drop(index=bad) == "").all() and (clean["reason"] == "").all()
    for column in ("n_thr_tables", "deviation", "f0_implied", "f0_implied_low", "f1_implied_high"):
        assert rows[column].iloc[bad].isna().all(), column
        np.testing.assert_array_equal(rows[column].drop(index=bad), clean[column].drop(index=bad))
    audit = classify_reference_speeds(rows)
    assert audit.outliers.empty and audit.groups["computed"].iat[0] == len(rows) - len(bad)
    assert reference_speed_lines(audit)[-2 - len(bad):-1] == [
        f"Rows not computed ({len(bad)}), left out of every group:"] + [f"  {BAD_CELLS[i][2]}" for i in bad]


def test_a_list_with_decimal_commas_reads_a_point_as_no_number(tmp_path):
    """With decimal commas '3,2' is 3.2 and '1.480' no number, as calc reads them: '1.480' in d was read as 1.48 mm
    and '6.300' in n_B as 6.3 1/min without a reason where pandas reads text columns as its str dtype."""
    table = synthetic_catalogue()
    table = table[table["series"] == "62"].reset_index(drop=True).astype(object)
    for column in ("d [mm]", "D [mm]", "B [mm]", "C0 [N]", "n_B [1/min]"):
        table[column] = [f"{value:g}".replace(".", ",") for value in table[column]]
    table.loc[2, "d [mm]"], table.loc[3, "n_B [1/min]"] = "1.480", "6.300"
    path = tmp_path / "list.csv"
    table.to_csv(path, index=False, sep=";")
    rows = audit_reference_speeds(read_table(path, sep=";", decimal=","))
    clean = audit_reference_speeds(series_62(tmp_path)[0])
    assert list(rows["reason"].iloc[2:4]) == [
        "row 4 (624): '1.480' is not a number for d [mm] (the bore d must be a finite number > 0)",
        "row 5 (624-2Z): '6.300' is not a number for n_B [1/min] (a published speed must be a finite number > 0)"]
    assert (rows["reason"].drop(index=[2, 3]) == "").all()
    np.testing.assert_array_equal(rows["n_thr_tables"].drop(index=[2, 3]), clean["n_thr_tables"].drop(index=[2, 3]))


def test_rows_of_a_frame_are_numbered_from_1():
    table = pd.DataFrame({"designation": ["6205", "6206"], "d [mm]": [25, 30], "D [mm]": [52, 62],
                          "B [mm]": [15, 16], "C0 [N]": [7800, 11200], "n_B [1/min]": [14400, float("inf")]})
    assert list(audit_reference_speeds(table)["reason"]) == [
        "", "row 2 (6206): n_B [1/min] = inf is outside the expected range (a published speed must be a finite "
            "number > 0)"]


# ---- bearings with contact seals: no published speed --------------------------------------------

def test_sealed_bearings_without_a_published_speed_are_skipped_not_row_errors(tmp_path):
    """HR 1 prints n_B '–' for 6205-2RSR and 7205-B-2RS-TVP: a blank speed there is what the catalogue says, so
    the row is skipped and named; a blank speed of an open bearing stays a row error, and a sealed bearing with
    a speed is not computed (the method does not apply)."""
    path = tmp_path / "list.csv"
    pd.DataFrame({
        "designation": ["6205", "6205-2RSR", "6205-2Z", "7205-B-2RS-TVP", "6206-2RSR", "6207"],
        "d [mm]": [25, 25, 25, 25, 30, 35], "D [mm]": [52, 52, 52, 52, 62, 72], "B [mm]": [15, 15, 15, 15, 16, 17],
        "C0 [N]": [7800, 7800, 7800, 9300, 11200, 15300],
        "n_B [1/min]": ["14400", "", "14400", "", "12000", ""]}).to_csv(path, index=False)
    rows = audit_reference_speeds(read_table(path))
    assert list(rows["designation"]) == ["6205", "6205-2Z", "6206-2RSR", "6207"]
    assert rows.attrs["skipped"] == ["row 3 (6205-2RSR)", "row 5 (7205-B-2RS-TVP)"]
    assert list(rows["reason"]) == [
        "", "",
        "row 6 (6206-2RSR): n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with "
        "contact seals: its reference conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for "
        "them; n_per and T_op, whose heat balance would leave the seal friction out, are not computed either",
        "row 7 (6207): n_B [1/min] is blank (a published speed must be a finite number > 0)"]
    audit = classify_reference_speeds(rows)
    assert audit.skipped == ("row 3 (6205-2RSR)", "row 5 (7205-B-2RS-TVP)")
    assert audit.groups["bearings"].sum() == 4
    assert reference_speed_lines(audit)[2] == (
        "Rows skipped (2), bearings with no published n_thr where catalogues print none (Schaeffler HR 1: '–'): "
        "those with contact seals, to which the thermal method (ISO 15312, DIN 732) does not apply, and those the "
        "bearing table holds without one (HR 1's 70..-B, 718..-B, NU19..); not audited: "
        "row 3 (6205-2RSR), row 5 (7205-B-2RS-TVP)")


def test_open_bearings_hr1_prints_without_a_speed_are_skipped_too(tmp_path):
    """HR 1 prints n_B '–' for the open 7004-B-TVP (text copy line 32698) and 71810-B-TVH (34246) too: blank there,
    the row is skipped as the sealed ones are; 7004-B, not a designation of the bearing table as printed, and
    7205-B-TVP, which HR 1 prints with a speed, stay row errors."""
    path = tmp_path / "list.csv"
    pd.DataFrame({
        "designation": ["7004-B-TVP", "71810-B-TVH", "7004-B", "7205-B-TVP"],
        "d [mm]": [20, 50, 20, 25], "D [mm]": [42, 65, 42, 52], "B [mm]": [12, 7, 12, 15],
        "C0 [N]": [7500, 7350, 7500, 9300], "n_B [1/min]": ["", "", "", ""]}).to_csv(path, index=False)
    rows = audit_reference_speeds(read_table(path))
    assert rows.attrs["skipped"] == ["row 2 (7004-B-TVP)", "row 3 (71810-B-TVH)"]
    assert list(rows["reason"]) == [
        "row 4 (7004-B): n_B [1/min] is blank (a published speed must be a finite number > 0)",
        "row 5 (7205-B-TVP): n_B [1/min] is blank (a published speed must be a finite number > 0)"]


def test_the_shipped_table_skips_its_sealed_bearings_and_computes_every_other():
    rows = audit_reference_speeds(bearing_table().rename(columns=HR1_COLUMNS))
    assert len(rows) == 1119 and (rows["reason"] == "").all() and rows["n_thr_tables"].notna().all()
    skipped = rows.attrs["skipped"]
    # 136 with contact seals, 22 open ones HR 1 prints without a speed (70..-B-TVP, 718..-B-TVH, NU19..-M1)
    assert len(skipped) == 158 and skipped[:2] == ["row 2 (623-2RSR)", "row 5 (624-2RSR)"]
    assert {"row 97 (6205-2RSR)", "row 99 (62205-2RSR)", "row 454 (7004-B-TVP)"} <= set(skipped)
    assert not rows["variant"].isin(["2RSR", "2RS"]).any()
