"""The SKF model's minimum load: a bearing loaded below 0.01 C (ball) or 0.02 C (roller bearings) gets a warning.

SKF General Catalogue 6000 RU p. 75 recommends at least 0.02 C on roller and 0.01 C on ball bearings, and p. 89
says the model holds at loads equal to or above that minimum. Below it the model's rolling and sliding moments
fall with the load towards 0 (a 6205 without load: M = 0 in grease), which nothing flagged before. The basic
dynamic load ratings here are typed from the Schaeffler HR 1 catalogue (2006), as the bearing table holds them:
6205 C = 14 000 N, NU205-E-TVP2 C = 34 500 N.
"""
import numpy as np
import pandas as pd
import pint
import pytest

import bearingheat as bh
from bearingheat.errors import FrictionInputError

u = pint.get_application_registry()
NU = u("mm^2/s")

ROW = {"designation": "6205", "n [rpm]": 3000, "nu [mm^2/s]": 20, "lubrication": "grease", "model": "skf"}
SOURCE = ("the SKF model holds at loads at or above it (p. 89), and below it the rolling elements may skid")


def calc(*rows):
    return bh.calc(pd.DataFrame([{**ROW, **row} for row in rows]))


def test_a_ball_bearing_below_a_hundredth_of_c_is_warned_of_and_at_it_is_not():
    out = calc({"Fr [N]": 100}, {"Fr [N]": 140}, {"Fr [N]": 200})  # (in N: 140 N is 0.01 C to the last digit)
    assert out["status"].tolist() == ["warning", "ok", "ok"]
    assert out["message"].iat[0] == ("Fr [N]: 100 is below the recommended minimum load 140 = 0.01 C of a ball "
                                     f"bearing (C = 14000 N, SKF 6000 p. 75); {SOURCE}")
    # a warning only: the moments are computed as before, and they grow with the load
    assert np.all(np.diff(out["MR [N*mm]"].to_numpy()) > 0)


def test_without_any_load_the_moment_is_only_drag_and_seals_and_that_is_said():
    out = calc({"Fr [kN]": 0.0})
    assert out["MR [N*mm]"].iat[0] == 0.0  # grease, no seals: no drag, and M_rr = M_sl = 0 without load
    assert out["message"].iat[0] == ("Fr [kN]: 0 is below the recommended minimum load 0.14 = 0.01 C of a ball "
                                     f"bearing (C = 14000 N, SKF 6000 p. 75); {SOURCE}")


def test_a_roller_bearing_needs_two_hundredths_of_c():
    out = calc({"designation": "NU205-E-TVP2", "Fr [kN]": 0.5}, {"designation": "NU205-E-TVP2", "Fr [kN]": 0.69})
    assert out["status"].tolist() == ["warning", "ok"]
    assert out["message"].iat[0] == ("Fr [kN]: 0.5 is below the recommended minimum load 0.69 = 0.02 C of a roller "
                                     f"bearing (C = 34500 N, SKF 6000 p. 75); {SOURCE}")


def test_each_bearing_of_a_pair_carries_half_the_radial_load():
    out = calc({"arrangement": "paired", "Fr [kN]": 0.25}, {"arrangement": "paired", "Fr [kN]": 0.3})
    assert out["message"].iat[0].startswith("Fr [kN]: 0.25 (0.125 on each bearing of the pair) is below the "
                                            "recommended minimum load 0.14 = 0.01 C of a ball bearing")
    assert "minimum load" not in out["message"].iat[1]


def test_an_axial_load_above_the_minimum_loads_the_bearing_and_one_below_is_named():
    out = calc({"Fr [kN]": 0.05, "Fa [kN]": 0.2}, {"Fr [kN]": 0.05, "Fa [kN]": 0.1})
    assert out["status"].tolist() == ["ok", "warning"]
    assert out["message"].iat[1] == ("Fa [kN]: 0.1 is below the recommended minimum load 0.14 = 0.01 C of a ball "
                                     f"bearing (C = 14000 N, SKF 6000 p. 75); {SOURCE}")


def test_a_given_c_is_used_and_one_that_differs_from_the_table_is_named():
    out = calc({"Fr [kN]": 0.1, "C [kN]": 5})
    # 0.01 C = 50 N < 100 N: no minimum-load warning, but the table's C differs
    assert out["message"].iat[0] == ("C [kN]: 5 differs from 14 (14000 N) of 6205 in the bearing table (Schaeffler "
                                     "HR 1, 2006); the value given is used")
    out = calc({"designation": "", "type": "deep_groove_ball", "series": "62", "d [mm]": 25, "D [mm]": 52,
                "Fr [N]": 80, "C [N]": 10000})
    assert out["message"].iat[0].startswith("Fr [N]: 80 is below the recommended minimum load 100 = 0.01 C of a ball "
                                            "bearing (C = 10000 N, SKF 6000 p. 75)")


def test_without_c_only_a_bearing_without_any_load_is_warned_of():
    bare = {"designation": "", "type": "deep_groove_ball", "series": "62", "d [mm]": 25, "D [mm]": 52}
    out = calc({**bare, "Fr [kN]": 0.0}, {**bare, "Fr [kN]": 0.05})
    # (the table has no Fa column: the message names it in the catalogue unit)
    assert out["message"].iat[0] == ("Fr [kN]: 0 and Fa [N]: 0: without load the SKF model's rolling and sliding "
                                     "moments are 0, but it holds only at loads at or above the recommended minimum "
                                     "load, 0.01 C of ball and 0.02 C of roller bearings (SKF 6000 pp. 75 and 89); "
                                     "give C to check a light load too")
    assert out["status"].iat[1] == "ok"


def test_the_catalogue_model_keeps_its_friction_and_gets_the_bearing_table_s_rule():
    # M0 does not depend on the load: an unloaded bearing keeps its speed-dependent friction; the warning is the
    # bearing table's minimum load for slippage-free running (tests/calc/test_minimum_load.py), not the SKF model's
    out = calc({"model": "schaeffler", "Fr [kN]": 0.0}, {"model": "schaeffler", "Fr [kN]": 0.1})
    assert (out["MR [N*mm]"] > 0).all()
    assert [m.split(" for ")[0] for m in out["message"]] == [
        "Fr [kN]: 0 is below the minimum load 0.14 = C/100 of a deep groove ball bearing",
        "Fr [kN]: 0.1 is below the minimum load 0.14 = C/100 of a deep groove ball bearing"]


@pytest.mark.parametrize("value, message", [
    (0, "C [kN]: 0 must be > 0"),
    (-3, "C [kN]: -3 must be > 0"),
])
def test_a_rating_that_is_no_rating_is_the_row_s_error(value, message):
    out = calc({"Fr [kN]": 1.0, "C [kN]": value})
    assert out["status"].iat[0] == "error" and message in out["message"].iat[0]


def test_the_unit_of_the_load_changes_nothing():
    in_kn = calc({"Fr [kN]": 0.1})
    in_n = calc({"Fr [N]": 100})
    in_lbf = calc({"Fr [lbf]": 100 / 4.4482216152605})
    assert in_kn["status"].tolist() == in_n["status"].tolist() == in_lbf["status"].tolist() == ["warning"]
    assert in_n["message"].iat[0].startswith("Fr [N]: 100 is below the recommended minimum load 140 = 0.01 C")


def test_the_python_api_warns_point_by_point_as_calc_does():
    r = bh.friction_torque("6205", n=3000 * u.rpm, nu=20 * NU, Fr=[0.1, 0.2] * u.kN, lubrication="grease",
                           model="skf")
    assert r.status == ["warning", "ok"]
    assert r.messages[0] == ("Fr [N]: 100 is below the recommended minimum load 140 = 0.01 C of a ball bearing "
                             f"(C = 14000 N, SKF 6000 p. 75); {SOURCE}")
    given = bh.friction_torque("6205", n=3000 * u.rpm, nu=20 * NU, Fr=0.1 * u.kN, lubrication="grease", model="skf",
                               model_inputs={"C": 5 * u.kN})
    assert given.messages == ["C: 5000 N differs from 14000 N of 6205 in the bearing table (Schaeffler HR 1, 2006); "
                              "the value given is used"]
    with pytest.raises(FrictionInputError) as info:
        bh.friction_torque("6205", n=3000 * u.rpm, nu=20 * NU, Fr=0.1 * u.kN, lubrication="grease", model="skf",
                           model_inputs={"C": 0 * u.kN})
    assert str(info.value) == "C [N]: 0 must be > 0"
    balance = bh.heat_balance("6205", n=3000 * u.rpm, nu=20 * NU, Fr=0.1 * u.kN, lubrication="grease", model="skf",
                              T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    assert balance.messages[0].startswith("Fr [N]: 100 is below the recommended minimum load 140 = 0.01 C")
