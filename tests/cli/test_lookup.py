"""``bearingheat lookup``: text and JSON output, matching notes, exit codes and exact messages."""
import json

from bearingheat.cli import main

SOURCE_6208 = ("Schaeffler HR 1 (June 2006), p. 204 (dimensions) and p. 205 (ratings), "
               "table 'deep groove ball bearings, single row', row 37; text copy ArtemFilin1990/Mar@68b9707")


def test_text_output_of_a_deep_groove_ball_bearing(capsys):
    assert main(["lookup", "6208"]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    assert captured.out.splitlines() == [
        "designation: 6208",
        "match: exact",
        "family: deep groove ball",
        "bearing_type: deep_groove_ball",
        "series: 62",
        "shield: open",
        "d [mm]: 40",
        "D [mm]: 80",
        "B [mm]: 18",
        "C [N]: 29000",
        "C0 [N]: 18000",
        "n_G [1/min]: 20000",
        "n_thr [1/min]: 9300",
        f"source: {SOURCE_6208}",
    ]


def test_a_sealed_bearing_prints_its_values_and_says_hr1_gives_no_n_thr(capsys):
    """6205-2RSR, HR 1 p. 202/203 row 18 (text copy lines 23099 and 23467): 25 x 52 x 15, C 14 000, C0 7 800,
    n_G 9 000, n_B '–'."""
    assert main(["lookup", "6205-2RSR"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[lines.index("shield: 2RSR"):-1] == [
        "shield: 2RSR",
        "d [mm]: 25",
        "D [mm]: 52",
        "B [mm]: 15",
        "C [N]: 14000",
        "C0 [N]: 7800",
        "n_G [1/min]: 9000",
        "n_thr [1/min]: not given: HR 1 prints no thermal reference speed for bearings with contact seals (the "
        "reference conditions of ISO 15312 have no seal friction)",
    ]
    assert lines[-1] == ("source: Schaeffler HR 1 (June 2006), p. 202 (dimensions) and p. 203 (ratings), table "
                         "'deep groove ball bearings, single row', row 18; text copy ArtemFilin1990/Mar@68b9707")
    # --json: null, as for every value the catalogue does not give
    assert main(["lookup", "7205-B-2RS", "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert (record["designation"], record["match"], record["shield"]) == ("7205-B-2RS-TVP", "cage", "2RS")
    assert (record["C [N]"], record["C0 [N]"], record["n_G [1/min]"], record["n_thr [1/min]"]) == (
        14600.0, 9300.0, 8000.0, None)


def test_an_open_bearing_hr1_prints_without_n_thr_says_so(capsys):
    """71810-B-TVH, HR 1 p. 244/245 row 1 (text copy lines 33814 and 34246): 50 x 65 x 7, C 6 950, C0 7 350,
    n_G 9 500, n_B '–' although it has no seals."""
    assert main(["lookup", "71810"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[:2] == ["designation: 71810-B-TVH", "match: design"]
    assert lines[lines.index("shield: open"):-1] == [
        "shield: open",
        "d [mm]: 50",
        "D [mm]: 65",
        "B [mm]: 7",
        "C [N]: 6950",
        "C0 [N]: 7350",
        "n_G [1/min]: 9500",
        "n_thr [1/min]: not given: HR 1 prints none for this bearing ('–')",
    ]


def test_text_output_of_a_tapered_bearing_matched_without_its_design_suffix(capsys):
    assert main(["lookup", "30208"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[:3] == [
        "designation: 30208-A",
        "match: design",
        "note: '30208' is 30208-A of the bearing table (Schaeffler HR 1, 2006) without cage and design suffixes",
    ]
    for line in ("T [mm]: 19.75", "C [N]: 61000", "C0 [N]: 66000", "e: 0.37", "Y: 1.6", "Y0: 0.88",
                 "n_G [1/min]: 9000", "n_thr [1/min]: 5900"):
        assert line in lines


def test_large_ratings_print_every_digit(capsys):
    assert main(["lookup", "NU2328-E-M1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "C [N]: 1210000" in lines and "C0 [N]: 1390000" in lines and "prefix: NU" in lines


def test_json_output(capsys):
    assert main(["lookup", "NU208-E", "--json"]) == 0
    captured = capsys.readouterr()
    record = json.loads(captured.out)
    assert captured.err == ""
    assert list(record) == ["designation", "match", "note", "family", "bearing_type", "series", "prefix", "shield",
                            "d [mm]", "D [mm]", "B [mm]", "T [mm]", "C [N]", "C0 [N]", "e", "Y", "Y0",
                            "n_G [1/min]", "n_thr [1/min]", "source"]
    assert record["designation"] == "NU208-E-TVP2" and record["match"] == "cage"
    assert (record["d [mm]"], record["D [mm]"], record["B [mm]"], record["C [N]"], record["C0 [N]"],
            record["n_G [1/min]"], record["n_thr [1/min]"]) == (40.0, 80.0, 18.0, 63000.0, 53000.0, 9000.0, 7600.0)
    assert record["T [mm]"] is None and record["e"] is None and record["Y"] is None and record["Y0"] is None
    assert record["prefix"] == "NU" and record["series"] == "2"


def test_unknown_designation_exits_2_with_close_matches(capsys):
    assert main(["lookup", "6208-2ZZ"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == ("bearingheat lookup: error: designation: '6208-2ZZ' is not in the bearing table "
                            "(Schaeffler HR 1, 2006); close matches: 6208-2Z, 6208-2RSR, 6208, 608-2Z, 6320-2Z\n")


def test_unknown_designation_exits_2_with_json_too(capsys):
    assert main(["lookup", "22208-E1", "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == ("bearingheat lookup: error: designation: '22208-E1' is not in the bearing table "
                            "(Schaeffler HR 1, 2006), which holds no spherical roller bearing; close matches: "
                            "NU2228-E-M1, NJ2228-E-M1, N228-E-M1, NUP2228-E-M1, NU228-E-M1\n")


def test_ambiguous_designation_exits_2(capsys):
    assert main(["lookup", "7220-B"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat lookup: error: designation: '7220-B' matches 2 bearings of the bearing table "
        "(Schaeffler HR 1, 2006) that differ in C, C0: 7220-B-JP, 7220-B-TVP; give the full designation\n")
