"""Numbers a designer could not have meant: non-finite, logical, outside the valid or plausible range.

No result leaves calc or the API as NaN or inf with status ok: such a row is
an error, and a number that is only implausible (a unit mix-up, usually) is
a warning naming the column, the value and the range.
"""
import datetime
import math
import re

import numpy as np
import pandas as pd
import pint
import pytest

import bearingheat as bh
from bearingheat.calc.table import calc
from bearingheat.errors import InputError

u = pint.get_application_registry()


def row(**changes):
    """The demo's 6208 in an oil bath, with columns replaced (a header with another unit replaces its column)."""
    base = {"id": "A", "designation": "6208", "D [mm]": 80.0, "C0 [kN]": 18.0, "lubrication": "oil_bath",
            "n [1/min]": 1480.0, "Fr [kN]": 3.2, "Fa [kN]": 0.5, "nu [mm^2/s]": 40.0}
    for header in changes:
        for old in [h for h in base if h.split(" [")[0] == header.split(" [")[0]]:
            del base[old]
    base.update(changes)
    return base


def results_of(out):
    """The result columns of calc (the inputs come back as they were given)."""
    first = list(out.columns).index("f0")
    return out.iloc[:, first:].select_dtypes(float).to_numpy()


def run(*rows):
    return calc(pd.DataFrame(list(rows)))


def test_a_good_row_stays_ok():
    out = run(row())
    assert out["status"].tolist() == ["ok"] and out["message"].tolist() == [""]


@pytest.mark.parametrize("column, value, message", [
    ("n [1/min]", math.inf, "n [1/min]: inf is not a finite number"),
    ("Fr [kN]", -math.inf, "Fr [kN]: -inf is not a finite number"),
    ("nu [mm^2/s]", math.inf, "nu [mm^2/s]: inf is not a finite number"),
    ("D [mm]", 1e300, "D [mm]: 1e+300 is outside the valid range up to 100000 mm"),
    ("Fr [kN]", 1e300, "Fr [kN]: 1e+300 (1e+303 N) is outside the valid range up to 1e+10 N"),
])
def test_non_finite_and_absurd_numbers_are_row_errors(column, value, message):
    out = run(row(), row(**{column: value}))
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].iat[1].split("; ")[0] == message
    assert math.isnan(out["MR [N*mm]"].iat[1]) and not np.isinf(results_of(out)).any()


def test_a_logical_value_is_not_a_load():
    out = run(row(**{"Fr [kN]": True}))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0] == "True is a logical value, not a number for Fr [kN]"


def test_logical_values_among_equal_numbers_are_told_apart():
    """True == 1 and False == 0 in Python (and hash alike): an Excel TRUE among loads of 1 kN is still an error,
    and loads of 0 among FALSE cells are still numbers, whichever comes first."""
    out = run(row(**{"Fr [kN]": 1}), row(**{"Fr [kN]": True}), row(**{"Fa [kN]": False}), row(**{"Fa [kN]": 0}),
              row(**{"Fa [kN]": 0.0}), row(**{"Fr [kN]": 1.0}))
    assert out["status"].tolist() == ["ok", "error", "error", "ok", "ok", "ok"]
    assert out["message"].tolist()[1:3] == ["True is a logical value, not a number for Fr [kN]",
                                            "False is a logical value, not a number for Fa [kN]"]
    assert out["MR [N*mm]"].iat[0] == out["MR [N*mm]"].iat[5]


def test_ambient_temperature_in_kelvin_holding_celsius_is_refused():
    out = run(row(**{"T_amb [K]": 20.0, "B [mm]": 18.0}))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0] == "T_amb [K]: 20 (-253.15 degC) is outside the valid range -60 to 200 degC"
    assert math.isnan(out["T_op [degC]"].iat[0])


def test_rpm_typed_under_hz_warns_against_the_limiting_speed():
    out = run(row(**{"n [Hz]": 1480.0}))
    assert out["status"].tolist() == ["warning"]
    assert out["message"].iat[0] == ("n [Hz]: 1480 (88800 1/min) is above the limiting speed n_G = 20000 1/min of "
                                     "6208 (Schaeffler HR 1, 2006); check the speed and its unit")


def test_a_given_limiting_speed_wins_over_the_table():
    out = run(row(**{"n [1/min]": 3000.0, "n_G [1/min]": 2500.0, "B [mm]": 18.0}))
    assert "n [1/min]: 3000 is above the limiting speed n_G = 2500 1/min; check the speed and its unit" in \
        out["message"].iat[0]


def test_a_load_above_the_static_rating_warns():
    out = run(row(**{"Fr [kN]": 30.0}))
    assert out["status"].tolist() == ["warning"]
    assert out["message"].iat[0] == ("Fr [kN]: 30 (30000 N) is above the static load rating C0 = 18000 N; check "
                                     "the load and its unit")


def test_an_implausible_but_valid_diameter_warns():
    out = run(row(**{"D [mm]": 8000.0, "d [mm]": 7000.0}))
    assert out["status"].tolist() == ["warning"]
    assert out["message"].iat[0] == ("D [mm]: 8000 is outside the plausible range 1 to 6000 mm; check the number "
                                     "and its unit; d [mm]: 7000 is outside the plausible range 0.5 to 5000 mm; "
                                     "check the number and its unit; d [mm]: 7000 differs from 40 mm of 6208 in "
                                     "the bearing table (Schaeffler HR 1, 2006); the value given is used; D [mm]: "
                                     "8000 differs from 80 mm of 6208 in the bearing table (Schaeffler HR 1, 2006); "
                                     "the value given is used")


def test_a_subnormal_static_rating_cannot_give_an_ok_infinite_torque():
    out = run(row(**{"C0 [N]": 5e-324}))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0].endswith("f1: the result is not a finite number for these inputs; check their "
                                          "magnitudes and units")
    assert not np.isinf(results_of(out)).any()


#: (Fr 1 kN: above the minimum load C/100 = 140 N of the 6205, whose warning is not the point here)
API = dict(d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath", n=3000 * u.rpm, nu=12 * u("mm^2/s"),
           Fr=1 * u.kN)


@pytest.mark.parametrize("changes, message", [
    (dict(Fr=np.array([1.0, np.nan]) * u.kN),
     "Fr: nan is not a number; leave the argument out where it is not known (at index 1)"),
    (dict(Fa=np.inf * u.kN), "Fa: inf is not a finite number"),
    (dict(D=1e300 * u.mm), "D: 1e+300 is outside the valid range up to 100000 mm"),
    (dict(C0=5e-324 * u.N, Fa=1 * u.kN),
     "MR: the result is not a finite number for these inputs; check their magnitudes and units"),
])
def test_the_api_raises_for_numbers_it_cannot_use(changes, message):
    with pytest.raises(bh.FrictionInputError) as exc:
        bh.friction_torque("6205", **{**API, **changes})
    assert str(exc.value) == message


def test_the_api_warns_for_an_implausible_number():
    r = bh.friction_torque("6205", **{**API, "nu": 0.5 * u("mm^2/s")})
    assert r.status == ["warning"]
    assert r.messages[0] == "nu: 0.5 is outside the plausible range 1 to 100000 mm^2/s; check the number and its unit"


def test_the_api_warns_of_a_load_above_c0_and_a_speed_above_n_g_as_calc_does():
    """calc's warnings of a unit mix-up, point by point, in the API's words: 20 kN on a 6205 (C0 7.8 kN), and
    30000 1/min above its n_G of 17000 1/min (HR 1, 2006)."""
    r = bh.friction_torque("6205", lubrication="oil_bath", n=[3000, 30000] * u.rpm, Fr=20 * u.kN, nu=12 * u("mm^2/s"))
    load = "Fr: 20000 is above the static load rating C0 = 7800 N; check the load and its unit"
    speed = ("n: 30000 is above the limiting speed n_G = 17000 1/min of 6205 (Schaeffler HR 1, 2006); check the speed "
             "and its unit")
    assert r.status == ["warning", "warning"] and r.messages == [load, f"{load}; {speed}"]
    balance = bh.heat_balance("6205", n=30000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"),
                              T_bearing=u.Quantity(70, "degC"))
    assert balance.status == ["warning"] and balance.messages[0].startswith(f"{speed}; T_op: ")
    # a limiting speed given is the user's own, named without the catalogue
    given = bh.heat_balance("6205", n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"), n_G=2500 * u.rpm)
    assert given.messages == ["n_G: 2500 differs from 17000 1/min of 6205 in the bearing table (Schaeffler HR 1, "
                              "2006); the value given is used; n: 3000 is above the limiting speed n_G = 2500 1/min; "
                              "check the speed and its unit"]
    assert bh.friction_torque("6205", lubrication="oil_bath", n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s")
                              ).status == ["ok"]


def test_the_heat_balance_api_raises_for_an_ambient_temperature_out_of_range():
    with pytest.raises(bh.HeatBalanceError) as exc:
        bh.heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
                        nu=12 * u("mm^2/s"), T_amb=u.Quantity(20, "K"))
    assert str(exc.value) == "T_amb: -253.15 is outside the valid range -60 to 200 degC"


@pytest.mark.parametrize("changes, message", [
    ({"Y0": -1.0}, "Y0: -1 must be >= 0"),
    ({"X0": -0.5}, "X0: -0.5 must be >= 0"),
    ({"n_G [1/min]": -1.0}, "n_G [1/min]: -1 must be > 0"),
    ({"n_G [1/min]": 0.0}, "n_G [1/min]: 0 must be > 0"),
    ({"T [mm]": 0.0}, "T [mm]: 0 must be > 0"),
])
def test_factors_widths_and_limiting_speeds_out_of_their_range_are_errors(changes, message):
    """A negative X0 or Y0 would hide behind P0 = max(X0*Fr + Y0*Fa, Fr); a limiting speed or a width <= 0 would
    give n_per = n_G <= 0 or no n_thr under a mere warning."""
    out = run(row(**changes))
    assert out["status"].tolist() == ["error"]
    assert message in out["message"].iat[0].split("; ")
    assert math.isnan(out["MR [N*mm]"].iat[0])


@pytest.mark.parametrize("header, written", [
    ("fr [kN]", "Fr [kN]"), ("FR [kN]", "Fr [kN]"), ("Fr (kN)", "Fr [kN]"), ("Fr, kN", "Fr [kN]"),
    ("Fr/kN", "Fr [kN]"), ("Fr in kN", "Fr [kN]"), ("FR", "Fr [N]"), ("Nu [cSt]", "nu [cSt]"),
])
def test_a_header_that_looks_like_a_missing_number_column_is_refused(header, written):
    """Passed through as an unknown column, its loads would count as 0 with status ok."""
    table = pd.DataFrame([{k: v for k, v in row().items() if not k.startswith(written.split(" ")[0] + " ")}])
    table[header] = 3.2
    meant = written.split(" ")[0]
    message = (f"column {header!r} looks like {meant!r}, which calc would not read from it: name it {written!r} "
               f"(headers are 'name [unit]', the name in its own letters); as it is, the table would be computed as if "
               f"{meant} were not given")
    with pytest.raises(InputError, match=f"^{re.escape(message)}$"):
        calc(table)


@pytest.mark.parametrize("header, meant", [("Arrangement", "arrangement"), ("Model", "model"), ("TYPE", "type"),
                                           ("Series", "series"), ("Lubrication", "lubrication")])
def test_a_header_that_looks_like_a_missing_text_column_is_refused(header, meant):
    """'Arrangement' = paired was passed through and the pair computed as a single bearing, status ok."""
    table = pd.DataFrame([{k: v for k, v in row().items() if k != meant}])
    table[header] = "paired" if meant == "arrangement" else "x"
    message = (f"column {header!r} looks like {meant!r}, which calc would not read from it: name it {meant!r} "
               f"(headers are 'name [unit]', the name in its own letters); as it is, the table would be computed as "
               f"if {meant} were not given")
    with pytest.raises(InputError, match=f"^{re.escape(message)}$"):
        calc(table)


def test_columns_of_the_users_own_are_still_passed_through():
    # 'Fa [kN]' is there: Fa (kN) is his; 'Model (old)' is a note on a model, no unit
    out = run(row(**{"ID": "x", "E": 2.1e5, "Fa (kN)": 9.0, "note": "spare", "Model (old)": "x"}))
    assert out["status"].tolist() == ["ok"] and out["E"].iat[0] == 2.1e5


def test_a_date_in_a_number_cell_is_shown_as_the_sheet_shows_it():
    out = run(row(**{"Fr [kN]": datetime.datetime(2024, 3, 2)}), row(**{"Fr [kN]": datetime.datetime(2024, 3, 2, 8, 30)}))
    assert out["message"].tolist() == ["'2024-03-02' is not a number for Fr [kN]",
                                       "'2024-03-02T08:30:00' is not a number for Fr [kN]"]


K_Q_SOURCE = ("(a tenth to ten times the 0.2e-3 to 1.0e-3 W/(mm^2*K) of the Schaeffler HR 1 catalogue for seats up to "
              "25 000 mm^2; its default q_r/50 K is 3.2e-4); check the number and its unit")
Q_E_SOURCE = ("(the heat q_r*A_r the seat of a bearing of plausible size (D up to 6000 mm, B up to 2000 mm) carries "
              "away at the ISO 15312 reference conditions is below 1e5 W); check the number and its unit")


@pytest.mark.parametrize("header, value, message", [
    ("k_q [W/(mm^2*K)]", 1.0, "k_q [W/(mm^2*K)]: 1 is outside the plausible range 2e-05 to 0.01 W/(mm^2*K) "),
    ("k_q [W/(mm^2*K)]", 1e-300, "k_q [W/(mm^2*K)]: 1e-300 is outside the plausible range 2e-05 to 0.01 W/(mm^2*K) "),
    ("Q_E [W]", 1e300, "Q_E [W]: 1e+300 is outside the plausible range -100000 to 100000 W "),
    ("Q_E [kW]", -200.0, "Q_E [kW]: -200 (-200000 W) is outside the plausible range -100000 to 100000 W "),
])
def test_an_implausible_heat_transfer_or_external_heat_warns_with_its_source(header, value, message):
    """k_q = 1 W/(mm^2*K), 3000 times the default, held the bearing at 20.004 degC without a word."""
    out = run(row(**{header: value, "T_amb [degC]": 20.0, "B [mm]": 18.0}))
    assert out["status"].tolist() == ["warning"]
    assert out["message"].iat[0].startswith(message + (K_Q_SOURCE if header.startswith("k_q") else Q_E_SOURCE))


def test_the_default_heat_transfer_of_every_catalogue_bearing_is_plausible():
    from bearingheat.calc.contract import column
    from bearingheat.calc.reference_speed import thermal_reference_speed_details
    table = pd.read_csv("tables/bearings_hr1_2006.csv", skiprows=[1])
    k_q = thermal_reference_speed_details(table[["designation", "d", "D", "B", "T", "C0"]])["k_q_ref"].dropna()
    low, high = column("k_q").plausible
    assert len(k_q) > 900 and low <= k_q.min() and k_q.max() <= high
    # q_r*A_r at the reference (50 K) is below 1e5 W up to D = 6000 mm, B = 2000 mm: 0.016 (A_r/5e4)^-0.34 A_r
    A_r = math.pi * 2000 * (6000 + 5000)
    assert 0.016 * (A_r / 5e4) ** -0.34 * A_r < column("Q_E").plausible[1]


def test_the_heat_balance_api_warns_for_an_implausible_heat_transfer():
    r = bh.heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm, Fr=1 * u.kN,
                        nu=12 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"), k_q=1 * u("W/(mm^2*K)"))
    assert r.status == ["warning"]
    assert r.messages[0] == ("k_q: 1 is outside the plausible range 2e-05 to 0.01 W/(mm^2*K) " + K_Q_SOURCE)
