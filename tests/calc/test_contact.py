"""The calc extension of ball bearings: the minimum axial load Fa_min against ball skidding (Zaitsev & Voronkin)."""
import pandas as pd
import pytest

from bearingheat.calc.table import calc
from bearingheat.kernels.contact import minimum_axial_load


def test_minimum_axial_load_warning():
    base = {"designation": "7205", "d [mm]": 25, "D [mm]": 52, "C0 [N]": 9300, "alpha [deg]": 30, "z": 12,
            "Dw [mm]": 7.9, "dm_pitch [mm]": 38.5, "lubrication": "grease", "n [rpm]": 12000, "Fr [N]": 200,
            "nu [mm^2/s]": 20}
    table = pd.DataFrame([{**base, "Fa [N]": 10}, {**base, "Fa [N]": 500}, {**base, "alpha [deg]": None, "Fa [N]": 0, "C0 [N]": 7800,
                                                                           "designation": "6205"}])
    out = calc(table)
    fa_min = minimum_axial_load(12, 7.9, 38.5, 12000, 30.0)
    assert out.loc[0, "Fa_min [N]"] == pytest.approx(fa_min, rel=1e-12)
    assert out.loc[0, "status"] == "warning"
    assert out.loc[0, "message"] == (f"Fa = 10 N is below the minimum axial load {fa_min:.4g} N at 12000 1/min: "
                                     "the balls may skid (Zaitsev & Voronkin)")
    assert out.loc[1, "status"] == "ok"
    assert out.loc[2, "message"] == ("Fa_min: give alpha [deg] (the contact angle) to check the minimum axial load "
                                     "against ball skidding (Zaitsev & Voronkin)")


def test_no_geometry_no_column():
    table = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [N]": [7800],
                          "lubrication": ["grease"], "n [rpm]": [3000], "Fr [N]": [100], "nu [mm^2/s]": [20]})
    assert "Fa_min [N]" not in calc(table).columns


def test_rows_the_formula_refuses_are_errors_of_their_own_and_the_others_are_computed():
    """Fa_min is computed for all rows in one call: a row with an impossible geometry gets the kernel's own
    refusal as its error, the rows beside it their values (as one row at a time would give them)."""
    base = {"designation": "7205", "d [mm]": 25, "D [mm]": 52, "C0 [N]": 9300, "alpha [deg]": 30, "z": 12,
            "Dw [mm]": 7.9, "dm_pitch [mm]": 38.5, "lubrication": "grease", "n [rpm]": 12000, "Fr [N]": 200,
            "nu [mm^2/s]": 20, "Fa [N]": 500}
    table = pd.DataFrame([base, {**base, "z": 11.5}, {**base, "dm_pitch [mm]": 7.0}, {**base, "n [rpm]": 6000}])
    out = calc(table)
    assert out["status"].tolist() == ["ok", "error", "error", "ok"]
    assert out.loc[1, "message"] == "Fa_min: z = 11.5: the number of balls must be a whole number of at least 1"
    # (a pitch circle inside the bore: the bearing's own dimensions say so before the formula's d_w < D0 would)
    assert out.loc[2, "message"] == ("Fa_min: impossible geometry: dm_pitch = 7 mm must lie between d = 25 mm and "
                                     "D = 52 mm")
    alone = [calc(table.iloc[[i]])["Fa_min [N]"].iloc[0] for i in (0, 3)]
    assert out.loc[[0, 3], "Fa_min [N]"].tolist() == pytest.approx(alone, rel=1e-15)
    assert alone == pytest.approx([minimum_axial_load(12, 7.9, 38.5, 12000, 30.0),
                                   minimum_axial_load(12, 7.9, 38.5, 6000, 30.0)], rel=1e-12)


def test_balls_that_cannot_sit_in_their_bearing_are_errors_naming_why():
    """z, Dw and dm_pitch are checked against the bearing's own d and D: the pitch circle between bore and outside
    diameter, a ball within the section (D - d)/2, and z balls side by side on the pitch circle (two neighbours
    touch at Dw = dm_pitch*sin(180°/z)); a row of the 7205 that passes all three gets its Fa_min."""
    base = {"designation": "7205", "d [mm]": 25, "D [mm]": 52, "C0 [N]": 9300, "alpha [deg]": 30, "z": 12,
            "Dw [mm]": 7.9, "dm_pitch [mm]": 38.5, "lubrication": "grease", "n [rpm]": 12000, "Fr [N]": 200,
            "nu [mm^2/s]": 20, "Fa [N]": 600}
    table = pd.DataFrame([base, {**base, "Dw [mm]": 13.5}, {**base, "dm_pitch [mm]": 52}, {**base, "z": 16},
                          {**base, "z": 15}])
    out = calc(table)
    assert out["status"].tolist() == ["ok", "error", "error", "error", "ok"]
    assert out.loc[1, "message"] == ("Fa_min: impossible geometry: Dw = 13.5 mm must be smaller than (D - d)/2 = "
                                     "13.5 mm, the section between bore and outside diameter")
    assert out.loc[2, "message"] == ("Fa_min: impossible geometry: dm_pitch = 52 mm must lie between d = 25 mm and "
                                     "D = 52 mm")
    # 38.5*sin(180°/16) = 7.511 mm < 7.9 mm; with 15 balls 38.5*sin(12°) = 8.005 mm, room enough
    assert out.loc[3, "message"] == ("Fa_min: impossible geometry: 16 balls of Dw = 7.9 mm do not fit side by side on "
                                     "the pitch circle of dm_pitch = 38.5 mm: at most Dw = dm_pitch*sin(180°/z) = "
                                     "7.511 mm")
    assert out.loc[4, "Fa_min [N]"] == pytest.approx(minimum_axial_load(15, 7.9, 38.5, 12000, 30.0), rel=1e-12)
