"""The heat balance of a table of supports (issue 3): n_thr rows and the ``bearingheat calc`` extension."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq
from thermal_helpers import THERMAL_COLUMNS, supports

from bearingheat.calc.table import EXTENSIONS, calc
from bearingheat.calc.contract import input_units, output_units
from bearingheat.calc.thermal import (extend, prepare, thermal_reference_speed_details,
                                      thermal_reference_speed_rows)
from bearingheat.errors import InputError
from bearingheat.kernels.thermal import (default_heat_transfer_coefficient, friction_heat, permissible_speed_factor,
                                         seat_heat_flow, speed_factor_coefficients)
from bearingheat.kernels.viscosity import iso_vg_viscosity, viscosity_from_two_points

HR1 = Path(__file__).resolve().parents[2] / ".." / "shared" / "data" / "hr1_2006_reference_speeds.csv"

# issue 3: catalogue values (Schaeffler HR 1, 2006) the method must reproduce within 2 %
CATALOGUE = [
    # designation, d, D, B, T, C0 [N], n_thr [1/min]
    ("6205", 25, 52, 15, np.nan, 7800, 14400),
    ("6206", 30, 62, 16, np.nan, 11200, 12000),
    ("6305", 25, 62, 17, np.nan, 11400, 12300),
    ("NU206-E", 30, 62, 16, np.nan, 36000, 9800),
    ("7205-B", 25, 52, 15, np.nan, 9300, 13600),
    ("30205-A", 25, 52, np.nan, 16.25, 34500, 9100),
    ("6230", 150, 270, 45, np.nan, 170000, 3350),
    ("NU2232-E", 160, 290, 80, np.nan, 1170000, 1670),
]


def catalogue_frame():
    return pd.DataFrame(CATALOGUE, columns=["designation", "d", "D", "B", "T", "C0", "n_catalogue"],
                        index=[f"row{i}" for i in range(len(CATALOGUE))])


# ---- thermal reference speed ---------------------------------------------------------------------

def test_catalogue_reference_speeds_within_two_percent():
    frame = catalogue_frame()
    n_thr = thermal_reference_speed_rows(frame)
    assert n_thr.index.equals(frame.index)
    assert (n_thr.attrs["reason"] == "").all()
    np.testing.assert_allclose(n_thr.to_numpy(), frame["n_catalogue"].to_numpy(), rtol=0.02)


def test_large_bearings_use_the_reduced_heat_flux():
    details = thermal_reference_speed_details(catalogue_frame())
    large = details.loc[["row6", "row7"]]
    assert (large["A_r"] > 50000).all()
    assert (large["q_r"] < 0.016).all()
    assert (details.drop(index=["row6", "row7"])["q_r"] == 0.016).all()


def test_reference_speed_solves_the_heat_balance_like_brentq():
    details = thermal_reference_speed_details(catalogue_frame())
    frame = catalogue_frame()
    for label, row in details.iterrows():
        dM = (frame.loc[label, "d"] + frame.loc[label, "D"]) / 2.0
        target = row["q_r"] * row["A_r"]

        def residual(n):
            return friction_heat(row["f0"], 12.0, n, dM, row["M1"]) - target

        n_brent = brentq(residual, 200.0, 1e6, xtol=1e-10, rtol=1e-14)
        assert row["n_thr"] == pytest.approx(n_brent, rel=1e-12)
        assert abs(residual(row["n_thr"])) < 1e-9 * target


def test_reference_speed_rows_never_raise_and_give_reasons():
    frame = pd.DataFrame({
        "designation": ["6205-2RSR", "51105", "bogus", "6205", "30205-A", "6205", "6205"],
        "d": [25, 25, 10, 25, 25, 25, 25], "D": [52, 42, 20, 52, 52, 20, 52],
        "B": [15, 11, 5, np.nan, 15, 15, 15], "T": [np.nan] * 7,
        "C0": [7800, 28500, 1000, 7800, 34500, 7800, np.nan],
    }, index=list("abcdefg"))
    n_thr = thermal_reference_speed_rows(frame)
    assert n_thr.isna().all()
    assert n_thr.attrs["reason"].to_dict() == {
        "a": "n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its "
             "reference conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and "
             "T_op, whose heat balance would leave the seal friction out, are not computed either",
        "b": "n_thr: the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings",
        "c": "designation: 'bogus' matches no row of the Schaeffler catalogue tables; give type and series explicitly instead",
        "d": "B [mm]: missing; the heat flow area A_r = pi*B*(D+d) needs the width",
        "e": "T [mm]: missing; the heat flow area A_r = pi*T*(D+d) needs the total width",
        "f": "D [mm]: 20 must be larger than d = 25 mm",
        "g": "C0 [N]: missing; the reference load is a fraction of C0",
    }


def test_reference_speed_of_thrust_roller_bearing_uses_thrust_conditions():
    frame = pd.DataFrame({"designation": ["81105"], "d": [25.0], "D": [42.0], "C0": [50000.0]})
    details = thermal_reference_speed_details(frame)
    row = details.iloc[0]
    assert row["kind"] == "thrust"
    assert row["P1"] == pytest.approx(0.02 * 50000)
    assert row["q_r"] == 0.020
    dM = 33.5
    power = friction_heat(row["f0"], 24.0, row["n_thr"], dM, row["M1"])
    assert power == pytest.approx(0.020 * row["A_r"], rel=1e-12)


@pytest.mark.skipif(not HR1.is_file(), reason="../shared/data/hr1_2006_reference_speeds.csv is not present")
def test_hr1_catalogue_reference_speeds_report():
    """Finding, not a hard check: how well the method reproduces HR 1 per series (see /work/notes/issue3.md)."""
    data = pd.read_csv(HR1)
    frame = pd.DataFrame({"designation": data["designation"], "d": data["d [mm]"], "D": data["D [mm]"],
                          "B": data["B [mm]"], "T": data["T [mm]"], "C0": data["C0 [N]"]})
    n_thr = thermal_reference_speed_rows(frame)
    assert n_thr.notna().all(), n_thr.attrs["reason"][n_thr.isna()].head().tolist()
    deviation = (n_thr / data["n_B [1/min]"] - 1.0) * 100.0
    summary = deviation.groupby([data["family"], data["series"]]).median().round(1)
    print("\nmedian deviation of n_thr from HR 1 per series [%]:\n" + summary.to_string())
    for key in [("deep groove ball", 62), ("deep groove ball", 63), ("cylindrical roller", 2),
                ("cylindrical roller", 22), ("tapered roller", 302)]:
        assert abs(summary[key]) < 1.0


def test_f_n_is_one_at_the_reference_conditions():
    details = thermal_reference_speed_details(catalogue_frame())
    frame = catalogue_frame()
    dM = (frame["d"] + frame["D"]) / 2.0
    k_q = default_heat_transfer_coefficient("radial", details["A_r"])
    Q = seat_heat_flow(k_q, details["A_r"], 50.0)      # k_q * dT_A = q_r
    f_n = permissible_speed_factor(details["n_thr"], details["f0"], 12.0, dM, details["M1"], Q)
    np.testing.assert_allclose(f_n.to_numpy(), 1.0, rtol=1e-12)
    k_L, k_P = speed_factor_coefficients(details["n_thr"], details["f0"], 12.0, dM, details["M1"], Q)
    np.testing.assert_allclose((k_L + k_P).to_numpy(), 1.0, rtol=1e-12)


# ---- the calc extension ----------------------------------------------------------------------------

def test_extension_is_registered():
    assert EXTENSIONS["thermal"].prepare is prepare and EXTENSIONS["thermal"].extend is extend
    assert set(output_units(owner="thermal")) == {"n_thr", "n_per", "n_per_method_used", "T_op", "nu_op", "Q_S", "Q_L",
                                                "nu_used", "nu_at"}
    assert input_units()["dT_oil"] == "delta_degC" and input_units()["T_amb"] == "degC"


def test_no_thermal_columns_without_their_inputs():
    table = supports(**{"nu [mm^2/s]": [12, 20]}).drop(columns="B [mm]")
    # n_thr only with a width B: typed, or from the bearing table for a designation it knows
    table["designation"] = ["22205-E1", "22206-E1"]
    assert not set(THERMAL_COLUMNS) & set(calc(table).columns)


def test_the_bearing_table_gives_the_width_for_the_reference_speed_only():
    out = calc(supports(**{"nu [mm^2/s]": [12, 20]}).drop(columns="B [mm]"))
    assert set(THERMAL_COLUMNS) & set(out.columns) == {"n_thr [1/min]"}
    np.testing.assert_allclose(out["n_thr [1/min]"], [14416.18, 9850.52], rtol=1e-6)


def test_reference_speed_only_with_geometry():
    out = calc(supports(**{"nu [mm^2/s]": [12, 20]}))
    assert "n_thr [1/min]" in out.columns and "T_op [degC]" not in out.columns
    np.testing.assert_allclose(out["n_thr [1/min]"], [14416.18, 9850.52], rtol=1e-6)
    assert out["status"].tolist() == ["ok", "ok"]


def test_all_columns_with_nu40_nu100_at_the_bearing_temperature():
    out = calc(supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                           "T_bearing [degC]": [70, 70]}))
    for column in THERMAL_COLUMNS:
        assert column in out.columns
    assert out["status"].tolist() == ["ok", "ok"]
    np.testing.assert_allclose(out["n_per [1/min]"], [8053.40, 6058.83], rtol=1e-5)
    # Q_S at T_bearing: default k_q = q_r / 50 K -> q_r * A_r
    np.testing.assert_allclose(out["Q_S [W]"], [0.016 * math.pi * 15 * 77, 0.016 * math.pi * 16 * 92], rtol=1e-12)
    assert (out["Q_L [W]"] == 0).all()
    np.testing.assert_allclose(out["nu_op [mm^2/s]"],
                               viscosity_from_two_points(68, 40, 8.6, 100, out["T_op [degC]"].to_numpy()),
                               rtol=1e-12)


def test_iso_vg_fills_nu_at_the_operating_temperature_without_T_bearing():
    out = calc(supports(**{"iso_vg": [68, 68], "T_amb [degC]": [20, 20]}))
    assert "n_per [1/min]" not in out.columns
    assert out["status"].tolist() == ["ok", "ok"]
    T_op = out["T_op [degC]"].to_numpy()
    np.testing.assert_allclose(out["nu_op [mm^2/s]"], iso_vg_viscosity(68, T_op), rtol=1e-12)
    # the friction pass ran at nu(T_op): N_R equals the heat carried away at T_op
    carried = out["Q_S [W]"].to_numpy()
    assert out["NR [W]"].to_numpy() == pytest.approx(carried, rel=1e-3)  # engine N_R uses n/9550


def test_temperature_header_units_and_fahrenheit():
    a = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}))
    b = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [K]": [293.15, 293.15], "T_bearing [degF]": [158, 158]}))
    np.testing.assert_allclose(a["n_per [1/min]"], b["n_per [1/min]"], rtol=1e-9)
    np.testing.assert_allclose(a["T_op [degC]"], b["T_op [degC]"], rtol=1e-9)


def test_oil_temperature_rise_in_degC_is_refused():
    table = supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "V_oil [l/min]": [0.5, 0.5],
                        "dT_oil [degC]": [5, 5]})
    with pytest.raises(InputError) as exc:
        calc(table)
    assert str(exc.value) == ("column 'dT_oil [degC]': unit degC cannot be converted to delta_degC")


def test_circulating_oil_and_external_heat():
    base = {"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}
    plain = calc(supports(**base))
    oil = calc(supports(**base, **{"V_oil [l/min]": [0.5, 0.5], "dT_oil [K]": [4, 4]}))
    hot = calc(supports(**base, **{"Q_E [W]": [10, 10]}))
    np.testing.assert_allclose(oil["Q_L [W]"], 28.6 * 0.5 * 4, rtol=1e-12)
    assert (oil["n_per [1/min]"] > plain["n_per [1/min]"]).all()
    assert (hot["n_per [1/min]"] < plain["n_per [1/min]"]).all()
    assert (hot["T_op [degC]"] > plain["T_op [degC]"]).all()


def test_catalogue_reference_speed_and_limiting_speed():
    out = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70],
                           "n_thr_catalogue [1/min]": [14400, 9800], "n_G [1/min]": [5000, np.nan]}))
    assert out["n_thr_catalogue [1/min]"].tolist() == [14400, 9800]
    np.testing.assert_allclose(out["n_thr [1/min]"], [14416.18, 9850.52], rtol=1e-6)
    assert out.loc[0, "n_per [1/min]"] == 5000.0
    assert out.loc[0, "status"] == "warning"
    assert out.loc[0, "message"] == ("n_G [1/min]: 5000 differs from 17000 1/min of 6205 in the bearing table "
                                     "(Schaeffler HR 1, 2006); the value given is used; n_per: the thermal value "
                                     "8050 1/min is above the limiting speed n_G = 5000 1/min; n_per = n_G")
    assert out.loc[1, "status"] == "ok"


def test_row_problems_are_messages_not_exceptions():
    table = pd.DataFrame({
        "designation": ["6205-2RSR", "6205", "6205", "6205"], "d [mm]": [25] * 4, "D [mm]": [52] * 4,
        "B [mm]": [15, 15, 15, 15], "C0 [kN]": [7.8] * 4, "lubrication": ["oil_bath"] * 4,
        "n [rpm]": [3000, 3000, np.nan, 3000], "Fr [kN]": [2] * 4,
        "nu40 [mm^2/s]": [68, 68, 68, 68], "nu100 [mm^2/s]": [8.6, np.nan, 8.6, 8.6],
        "T_amb [degC]": [20, 20, 20, 80], "T_bearing [degC]": [70, 70, np.nan, 70],
    })
    out = calc(table)
    assert out["status"].tolist() == ["warning", "error", "error", "error"]
    assert out.loc[0, "message"] == (
        "contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, lists seal friction among the components; its formulas have no term for it); n_thr: the thermal "
        "method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its reference conditions have no "
        "seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, whose heat balance would leave "
        "the seal friction out, are not computed either")
    assert "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line (ASTM D341)" \
        in out.loc[1, "message"]
    assert ("n [1/min]: missing; nu from nu40/nu100 or iso_vg is taken at the operating temperature T_op, which "
            "needs n and T_amb (or give T_bearing)") in out.loc[2, "message"]
    assert "T_bearing [degC]: 70 must be above T_amb = 80 degC for heat to leave through the seat" \
        in out.loc[3, "message"]
    assert out.loc[1:, THERMAL_COLUMNS].isna().all().all()


def test_friction_only_tables_get_n_thr_quietly():
    table = supports(**{"nu [mm^2/s]": [12, 20]})
    table.loc[1, "designation"] = "NU206-E"
    table["C0 [kN]"] = [7.8, np.nan]
    table["lubrication"] = ["oil_bath", "oil_bath"]
    out = calc(table)
    assert out["status"].tolist() == ["ok", "ok"]
    assert out["message"].tolist() == ["", ""]
    assert out.loc[0, "n_thr [1/min]"] == pytest.approx(14416.18, rel=1e-6)
    # the blank C0 of the NU206-E comes from the bearing table (36 kN, as typed in the other tests)
    assert out.loc[1, "n_thr [1/min]"] == pytest.approx(9850.52, rel=1e-6)


def test_reference_speed_details_of_a_table_are_those_of_each_row_alone():
    # the checks run in arrays over all rows (each distinct bearing resolved once); every row's reason and numbers
    # are what the row gets on its own, whatever its neighbours, for rows that pass and rows that fail each check
    rng = np.random.default_rng(7)
    n = 60
    frame = pd.DataFrame({
        "designation": rng.choice(np.array(["6205", "NU206-E", "51105", "30208-A", "K81104-TV", "6205-2RSR", "HK2016",
                                            "29412-E1", "XYZ", None], dtype=object), n),
        "arrangement": rng.choice(np.array(["single", "paired"], dtype=object), n, p=[0.8, 0.2]),
        "d": rng.choice([25.0, 30.0, 40.0, 0.0, np.nan], n),
        "D": rng.choice([52.0, 62.0, 80.0, 20.0, np.nan], n),
        "B": rng.choice([15.0, 16.0, 0.0, np.nan], n),
        "T": rng.choice([19.75, np.nan], n),
        "d1": rng.choice([60.0, np.nan], n),
        "D1": rng.choice([45.0, np.nan], n),
        "C0": rng.choice([7800.0, 36000.0, -3.0, np.nan], n),
    })
    together = thermal_reference_speed_details(frame)
    for i in range(n):
        alone = thermal_reference_speed_details(frame.iloc[[i]])
        assert together["reason"].iat[i] == alone["reason"].iat[0]
        for column in ("n_thr", "A_r", "q_r", "f0", "f1", "P1", "M1"):
            np.testing.assert_array_equal(together[column].iat[i], alone[column].iat[0])
    reasons = together["reason"].astype(str)
    assert reasons.eq("").any() and reasons.str.contains("must be > 0").any() and reasons.str.contains("pair").any()
    # the columns asked for, alone: the same values
    chosen = thermal_reference_speed_details(frame, names=("n_thr", "reason"))
    assert list(chosen.columns) == ["n_thr", "reason"]
    np.testing.assert_array_equal(chosen["n_thr"].to_numpy(), together["n_thr"].to_numpy())
    assert chosen["reason"].tolist() == together["reason"].tolist()
    assert list(thermal_reference_speed_details(frame.iloc[:1], names=("A_r",)).columns) == ["A_r"]


def test_a_thrust_bearing_gets_n_thr_without_width_columns():
    """A_r = (pi/2)(D^2 - d^2) of a thrust bearing needs d and D only: a table without B, T, d1 and D1 got n_per
    but no n_thr column, although the heat balance computed it."""
    table = pd.DataFrame([{"designation": "81212", "d [mm]": 60, "D [mm]": 95, "C0 [N]": 200000, "n [1/min]": 1000,
                           "Fa [N]": 5000, "lubrication": "oil_bath", "nu [mm^2/s]": 24, "T_amb [degC]": 20,
                           "T_bearing [degC]": 70}])
    out = calc(table)
    # by hand, the ISO 15312 reference of a thrust bearing: 24 mm^2/s, Fa = 0.02 C0, q_r = 0.020 W/mm^2; the
    # 812 series in an oil bath f0 = 3, f1 = 0.0015, M1 = f1 Fa dM (the Schaeffler catalogue, pp. 66-67)
    dM, A_r = 77.5, math.pi / 2 * (95 ** 2 - 60 ** 2)

    def reference(n):
        return math.pi * n / 30e3 * (3 * (24 * n) ** (2 / 3) * dM ** 3 * 1e-7 + 0.0015 * 0.02 * 200000 * dM) \
            - 0.020 * A_r

    assert out["status"].tolist() == ["ok"]
    assert out["n_thr [1/min]"].iat[0] == pytest.approx(brentq(reference, 1, 1e6, xtol=1e-10), rel=1e-9)
    assert round(out["n_thr [1/min]"].iat[0]) == 2414 and round(out["n_per [1/min]"].iat[0]) == 2108


def test_nu_op_is_blank_where_T_op_is_not_computed():
    """nu_op is the viscosity at T_op: a row without T_op (a bearing with contact seals: no heat balance) has no
    nu_op either, also where nu is a constant column (it was shown as that constant beside a blank T_op)."""
    rows = pd.DataFrame({"designation": ["6205-2RSR", "6205"], "lubrication": ["grease", "grease"],
                         "n [rpm]": [6000, 6000], "Fr [kN]": [1, 1], "nu [mm^2/s]": [20, 20], "T_amb [degC]": [25, 25]})
    out = calc(rows)
    assert np.isnan(out["T_op [degC]"].iat[0]) and np.isnan(out["nu_op [mm^2/s]"].iat[0])
    assert out["T_op [degC]"].iat[1] > 25 and out["nu_op [mm^2/s]"].iat[1] == 20.0
