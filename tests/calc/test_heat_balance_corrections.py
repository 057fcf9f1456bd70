"""Corrections of the heat balance: the heat flow area of axial spherical roller bearings, the oil outlet
assumption said out loud, and the n_per method chosen per table or per row and reported."""
import math

import pandas as pd
import pytest

from bearingheat.calc.table import calc
from bearingheat.errors import InputError
from bearingheat.kernels.thermal import heat_flow_area

# 29412-E: 60 x 130 mm, d1 = 112.2 mm, D1 = 85.5 mm, C0 = 915 kN (Schaeffler HR 1, 2006)
AXIAL = {"designation": "29412-E", "d [mm]": 60, "D [mm]": 130, "C0 [kN]": 915, "lubrication": "oil_bath",
         "n [1/min]": 1000, "Fa [kN]": 10, "nu [mm^2/s]": 40}


def test_axial_spherical_heat_flow_area_by_hand():
    by_hand = math.pi / 4 * (130 ** 2 + 112.2 ** 2 - 85.5 ** 2 - 60 ** 2)
    assert heat_flow_area("axial_spherical", 60, 130, d1=112.2, D1=85.5) == pytest.approx(by_hand, rel=1e-15)
    generic = math.pi / 2 * (130 ** 2 - 60 ** 2)
    assert generic / by_hand - 1 == pytest.approx(0.43, abs=0.01)     # the thrust formula is 43 % too large


def test_axial_spherical_reference_speed():
    out = calc(pd.DataFrame([{**AXIAL, "d1 [mm]": 112.2, "D1 [mm]": 85.5}]))
    assert out["status"].tolist() == ["ok"]
    # 2704 1/min with the area of HR 1 p. 64 (the generic thrust area gave 3556; SKF lists 2800)
    assert out["n_thr [1/min]"].iat[0] == pytest.approx(2704, abs=0.5)


def test_axial_spherical_without_washer_diameters_keeps_its_friction():
    out = calc(pd.DataFrame([{**AXIAL, "d1 [mm]": None, "D1 [mm]": None}]))
    assert out["status"].tolist() == ["warning"]
    assert out["message"].iat[0] == (
        "n_thr: d1 [mm] and D1 [mm]: missing; the heat flow area A_r = (pi/4)*(D^2+d1^2-D1^2-d^2) of axial "
        "spherical roller bearings needs them (HR 1, p. 64); the friction torque is computed without them")
    assert math.isnan(out["n_thr [1/min]"].iat[0]) and out["MR [N*mm]"].iat[0] > 0


ROW = {"designation": "6208", "d [mm]": 40, "D [mm]": 80, "B [mm]": 18, "C0 [kN]": 18, "lubrication": "circulating_oil",
       "n [1/min]": 3000, "Fr [kN]": 3.2, "nu [mm^2/s]": 40, "T_amb [degC]": 20, "T_bearing [degC]": 70}


def test_oil_cooling_without_dT_oil_says_what_it_assumed():
    out = calc(pd.DataFrame([{**ROW, "V_oil [l/min]": 1.0}, {**ROW, "V_oil [l/min]": 1.0, "dT_oil [K]": 10}]))
    assert out["message"].iat[0].endswith(
        "dT_oil [K]: not given; the oil is taken to enter at T_amb and to leave at the bearing temperature, the "
        "most heat it can carry away (28.6 W/(l/min*K) * V_oil * (T - T_amb)); give dT_oil for a cautious value")
    assert "dT_oil" not in out["message"].iat[1]
    # at T_bearing = 70 degC: 28.6 * 1 * 50 = 1430 W against 28.6 * 1 * 10 = 286 W
    assert out["Q_L [W]"].tolist() == pytest.approx([1430.0, 286.0], rel=1e-12)


def test_n_per_method_per_table_and_per_row():
    rows = pd.DataFrame([ROW, {**ROW, "n_per_method": "exact"}])
    exact = calc(rows)
    approx = calc(rows, n_per_method="approximation")
    assert exact["n_per_method_used"].tolist() == ["exact root", "exact root"]
    assert approx["n_per_method_used"].tolist() == ["catalogue approximation", "exact root"]
    assert approx["n_per [1/min]"].iat[1] == exact["n_per [1/min]"].iat[1]
    # the catalogue's approximation of f_n is within a few per cent of the exact root here
    assert approx["n_per [1/min]"].iat[0] == pytest.approx(exact["n_per [1/min]"].iat[0], rel=0.05)
    assert approx["n_per [1/min]"].iat[0] != exact["n_per [1/min]"].iat[0]


def test_unknown_n_per_method():
    out = calc(pd.DataFrame([{**ROW, "n_per_method": "guess"}]))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0] == "n_per_method: 'guess' is not one of exact, approximation"
    with pytest.raises(InputError) as exc:
        calc(pd.DataFrame([ROW]), n_per_method="guess")
    assert str(exc.value) == "n_per_method: 'guess' is not one of exact, approximation"


PAIR = {"designation": "7210-B", "d [mm]": 50, "D [mm]": 90, "B [mm]": 20, "C0 [kN]": 28.5, "Y0": 0.26,
        "lubrication": "grease", "n [1/min]": 6000, "Fr [kN]": 1.5, "Fa [kN]": 2.0, "nu [mm^2/s]": 22,
        "T_amb [degC]": 20, "T_bearing [degC]": 70}


def test_a_paired_row_is_the_pair():
    out = calc(pd.DataFrame([PAIR, {**PAIR, "arrangement": "paired"}]))
    single, pair = out.iloc[0], out.iloc[1]
    dM = (50 + 90) / 2
    # M0 of both bearings: 2 * f0 * (nu*n)^(2/3) * dM^3 * 1e-7 with f0 = 1.3 (grease, 72..-B)
    assert pair["M0 [N*mm]"] == pytest.approx(2 * 1.3 * (22 * 6000) ** (2 / 3) * dM ** 3 * 1e-7, rel=1e-12)
    assert pair["M0 [N*mm]"] == pytest.approx(2 * single["M0 [N*mm]"], rel=1e-15)
    # the pair's P1 = 1.4*Fa - 0.1*Fr (p. 68) against the single bearing's Fa - 0.1*Fr, both at least Fr
    assert pair["P1 [N]"] == pytest.approx(1.4 * 2000 - 0.1 * 1500, rel=1e-15)
    assert single["P1 [N]"] == pytest.approx(max(2000 - 0.1 * 1500, 1500), rel=1e-15)
    assert pair["MR [N*mm]"] == pytest.approx(pair["M0 [N*mm]"] + pair["M1 [N*mm]"], rel=1e-15)


def test_a_paired_row_has_no_heat_balance():
    out = calc(pd.DataFrame([PAIR, {**PAIR, "arrangement": "paired"}]))
    assert out["status"].tolist() == ["ok", "warning"]
    assert out["message"].iat[1] == (
        "n_thr: the heat balance of a bearing pair is not in the sources (ISO 15312 and the Schaeffler catalogue "
        "define A_r, the reference conditions and n_thr for single bearings); MR and NR are the pair's; give the "
        "two bearings as single rows for their heat balance")
    for column in ("n_thr [1/min]", "n_per [1/min]", "T_op [degC]"):
        assert not math.isnan(out[column].iat[0]) and math.isnan(out[column].iat[1]), column
