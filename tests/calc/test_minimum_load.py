"""The bearing table's minimum load: a bearing loaded below what its type needs for slippage-free running gets a
warning, under the catalogue model (the SKF model has its own rule, tests/calc/test_skf_minimum_load.py).

Schaeffler HR 1 (2006) prints, in continuous operation, P/Cr >= 0.01 for deep groove ball (p. 192), angular
contact ball (p. 237) and tapered roller bearings (p. 470), and C0r/P <= 60 for cylindrical roller bearings
(p. 364). The ratings are typed from the same catalogue: 6205 C = 14 000 N, 7205-B C = 14 600 N, 30205-A
C = 32 000 N, NU205-E-TVP2 C0 = 27 500 N.
"""
import pandas as pd
import pint
import pytest

import bearingheat as bh

u = pint.get_application_registry()
NU = u("mm^2/s")

ROW = {"designation": "6205", "n [rpm]": 3000, "nu [mm^2/s]": 20, "lubrication": "grease"}
SLIP = "for slippage-free running (Schaeffler HR 1, 2006, p. {page}): the bearing may slip, the more so at high " \
       "speeds and accelerations"


def calc(*rows):
    return bh.calc(pd.DataFrame([{**ROW, **row} for row in rows]))


def test_a_deep_groove_ball_bearing_below_a_hundredth_of_c_and_at_it():
    out = calc({"Fr [N]": 100}, {"Fr [N]": 140}, {"Fr [N]": 200})
    assert out["status"].tolist() == ["warning", "ok", "ok"]
    assert out["message"].iat[0] == ("Fr [N]: 100 is below the minimum load 140 = C/100 of a deep groove ball bearing "
                                     + SLIP.format(page=192))
    # a warning only: the friction is computed as before
    assert out["MR [N*mm]"].notna().all()


@pytest.mark.parametrize("designation, load, minimum, kind, page", [
    ("30205-A", 0.3, "0.32 = C/100", "tapered roller bearing", 470),
    ("NU205-E-TVP2", 0.45, "0.458333 = C0/60", "cylindrical roller bearing with cage", 364),
])
def test_the_rule_of_each_type(designation, load, minimum, kind, page):
    out = calc({"designation": designation, "Fr [kN]": load})
    assert out["message"].iat[0] == (f"Fr [kN]: {load:g} is below the minimum load {minimum} of a {kind} "
                                     + SLIP.format(page=page))


def test_a_pair_and_an_axial_load():
    out = calc({"designation": "7205-B", "arrangement": "paired", "Fr [kN]": 0.28},
               {"designation": "7205-B", "arrangement": "paired", "Fr [kN]": 0.3},
               {"Fr [kN]": 0.05, "Fa [kN]": 0.2}, {"Fr [kN]": 0.05, "Fa [kN]": 0.1})
    # each bearing of the pair at Fr/2: 140 N < 146 N, 150 N is not
    assert out["message"].iat[0].startswith("Fr [kN]: 0.28 (0.14 on each bearing of the pair) is below the minimum "
                                            "load 0.146 = C/100 of a single row angular contact ball bearing")
    assert "minimum load" not in out["message"].iat[1]
    assert out["status"].iat[2] == "ok"
    assert out["message"].iat[3] == ("Fa [kN]: 0.1 is below the minimum load 0.14 = C/100 of a deep groove ball "
                                     "bearing " + SLIP.format(page=192))


def test_a_blank_radial_load_is_0_and_the_axial_load_is_the_one_named():
    # (the row's Fr cell is blank: 0; its Fa of 100 N is the load compared with C/100 = 140 N, so the message names it)
    out = calc({"Fr [kN]": 1.0}, {"Fa [kN]": 0.1})
    assert out["message"].iat[1] == ("Fa [kN]: 0.1 is below the minimum load 0.14 = C/100 of a deep groove ball "
                                     "bearing " + SLIP.format(page=192))


def test_the_skf_model_has_its_own_rule_and_a_row_in_error_none():
    out = calc({"Fr [N]": 100, "model": "skf"}, {"Fr [N]": 100, "n [rpm]": -5})
    assert out["message"].iat[0].startswith("Fr [N]: 100 is below the recommended minimum load 140 = 0.01 C of a ball "
                                            "bearing (C = 14000 N, SKF 6000 p. 75)")
    assert "slippage-free" not in out["message"].iat[0]
    assert out["status"].iat[1] == "error" and "minimum load" not in out["message"].iat[1]


def test_a_given_rating_is_used_and_without_one_nothing_is_checked():
    out = calc({"Fr [N]": 120, "C [kN]": 10})  # C/100 = 100 N: no warning; the table's C differs
    assert out["message"].iat[0] == ("C [kN]: 10 differs from 14 (14000 N) of 6205 in the bearing table (Schaeffler "
                                     "HR 1, 2006); the value given is used")
    out = calc({"designation": "", "type": "deep_groove_ball", "series": "62", "d [mm]": 25, "D [mm]": 52,
                "C0 [N]": 7800, "Fr [N]": 10})
    assert out["status"].iat[0] == "ok"


def test_the_unit_of_the_load_changes_nothing():
    statuses = [calc({f"Fr [{unit}]": 100 / factor})["status"].iat[0]
                for unit, factor in (("N", 1.0), ("kN", 1000.0), ("lbf", 4.4482216152605))]
    assert statuses == ["warning"] * 3


def test_the_python_api_warns_as_calc_does():
    r = bh.friction_torque("6205", n=3000 * u.rpm, nu=20 * NU, Fr=[0.1, 0.2] * u.kN, lubrication="grease")
    assert r.status == ["warning", "ok"]
    assert r.messages[0] == ("Fr: 100 is below the minimum load 140 = C/100 of a deep groove ball bearing "
                             + SLIP.format(page=192))
    balance = bh.heat_balance("6205", n=3000 * u.rpm, nu=20 * NU, Fr=0.1 * u.kN, lubrication="grease",
                              T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    assert balance.messages == r.messages[:1]
