"""Blank dimensions, ratings and factors come from the bearing table (Schaeffler HR 1, 2006) by designation."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingheat.calc.table import calc

DEMO = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"
RESULTS = ["f0", "f1", "P0 [N]", "P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]",
           "n_thr [1/min]", "n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "Q_S [W]", "Q_L [W]"]


def test_designations_alone_give_the_demo_numbers():
    typed = pd.read_csv(DEMO)
    # what a designer types: no dimensions, ratings, speeds or static load factors (the demo's Y0 = 0.26 of the
    # 40-degree 7210-B is HR 1's, p. 237)
    short = typed[["id", "designation", "arrangement", "lubrication", "n [rpm]", "Fr [kN]", "Fa [kN]",
                   "nu [mm^2/s]", "T_amb [degC]", "T_bearing [degC]"]]
    full, filled = calc(typed), calc(short)
    for column in RESULTS:
        np.testing.assert_array_equal(filled[column].to_numpy(), full[column].to_numpy(), err_msg=column)
    assert filled["status"].tolist() == full["status"].tolist()
    assert filled["message"].tolist() == full["message"].tolist()


def _row(**cells):
    base = {"designation": "6208", "lubrication": "oil_bath", "n [rpm]": 3000, "Fr [kN]": 2, "nu [mm^2/s]": 12}
    return pd.DataFrame([{**base, **cells}])


def test_suffixes_match_and_the_values_are_the_catalogue_rows():
    out = calc(pd.concat([_row(designation="6208-2Z"), _row(designation="NU208-E-TVP2"), _row(designation="6208")],
                         ignore_index=True))
    assert out["status"].tolist() == ["ok", "ok", "ok"]
    # 6208: 40 x 80 mm (HR 1 p. 196); M0 = f0 (nu n)^(2/3) dM^3 1e-7 by hand, f0 = 2 (series 62, oil bath)
    assert out.loc[2, "M0 [N*mm]"] == pytest.approx(2.0 * (12 * 3000) ** (2 / 3) * 60.0 ** 3 * 1e-7, rel=1e-12)
    assert out["M0 [N*mm]"].nunique() == 1


def test_a_40_degree_angular_contact_bearing_under_axial_load_takes_Y0_of_HR1():
    """7205-B (HR 1 p. 240/241: 25 x 52 mm, C0 9300 N; contact angle 40 deg from the B suffix): Y0 = 0.26 and
    X0 = 0.5 of HR 1 p. 237 ('P0 = 0,5 · F0r + 0,26 · F0a' for a single bearing); it was an error ('give Y0
    from the catalogue')."""
    out = calc(_row(designation="7205-B", **{"Fr [kN]": 1, "Fa [kN]": 3}))
    assert out["status"].iat[0] == "ok"
    P0 = 0.5 * 1000 + 0.26 * 3000                      # 1280 N > Fr
    f1 = 0.001 * (P0 / 9300) ** 0.33                   # series 72: f1 = 0.001 (P0/C0)^0.33 (p. 68)
    P1 = 3000 - 0.1 * 1000                             # single angular contact: P1 = Fa - 0.1 Fr (p. 68)
    assert out["P0 [N]"].iat[0] == pytest.approx(P0, rel=1e-12)
    assert out["M1 [N*mm]"].iat[0] == pytest.approx(f1 * P1 * (25 + 52) / 2, rel=1e-12)


def test_a_sealed_bearing_fills_its_values_keeps_the_seal_warning_and_gets_no_heat_balance():
    """6208-2RSR (HR 1 p. 206/207, row 1: 40 x 80 x 18, C0 18 000 N, n_G 5600, n_B '–'): M1 takes the table's
    C0, the speed check its own n_G (not the 20 000 1/min of 6208), and n_thr, n_per, T_op are not computed."""
    out = calc(_row(designation="6208-2RSR", **{"n [rpm]": 6000, "T_amb [degC]": 20, "T_bearing [degC]": 70}))
    # P0 = P1 = 2000 N; f1 = 0.0009 (2000/18000)^0.5 = 3e-4; M1 = f1 P1 dM = 3e-4 * 2000 * 60 = 36 N*mm
    assert out["M1 [N*mm]"].iat[0] == pytest.approx(36.0, rel=1e-12)
    assert out.loc[0, ["n_thr [1/min]", "n_per [1/min]", "T_op [degC]"]].isna().all()
    assert out["status"].iat[0] == "warning"
    assert out["message"].iat[0] == (
        "contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, lists "
        "seal friction among the components; its formulas have no term for it); n [rpm]: 6000 is above the "
        "limiting speed n_G = 5600 1/min of 6208-2RSR (Schaeffler HR 1, 2006); check the speed and its unit; "
        "n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its "
        "reference conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, "
        "whose heat balance would leave the seal friction out, are not computed either")


def test_the_more_series_fill_by_designation_alone():
    """One bearing of each series added from HR 1 beside the data set (scripts/hr1_2006_more_series_rows.csv; text
    copy lines of the dimension / ratings row): 61908 (23921 / 24278: 40 x 62, C0 10 000), NU1010-M1 (62599 /
    63088: 50 x 80, C0 41 500), 32919 (95078 / 95648: 95 x 130), T7FC045 (91864 / 92364: 45 x 95), 7004-B-TVP
    (32215 / 32698: 20 x 42, C0 7500), 71810-B-TVH (33814 / 34246: 50 x 65, C0 7350), typed as a designer types
    them; M0 = f0 (nu n)^(2/3) dM^3 1e-7 and M1 = f1 P1 dM by hand, f0 and f1 of the Schaeffler catalogue's oil
    bath rows 619 (1.7; f1 = 0.0007 (P0/C0)^0.5), 10 (2; 0.0002), 329 and T7FC (3; 0.0004), 70 and 718 (2;
    0.001 (P0/C0)^0.33). HR 1 prints no n_B for 7004-B-TVP and 71810-B-TVH: n_thr is computed all the same."""
    names = ["61908", "NU1010", "32919", "T7FC045", "7004-B", "71810"]
    out = calc(pd.concat([_row(designation=name) for name in names], ignore_index=True))
    assert out["status"].tolist() == ["ok"] * 6 and out["message"].tolist() == [""] * 6
    assert out["n_thr [1/min]"].notna().all()
    speed_term = (12 * 3000) ** (2 / 3) * 1e-7
    for i, (f0, dM) in enumerate([(1.7, 51.0), (2.0, 65.0), (3.0, 112.5), (3.0, 70.0), (2.0, 31.0), (2.0, 57.5)]):
        assert out.loc[i, "M0 [N*mm]"] == pytest.approx(f0 * speed_term * dM ** 3, rel=1e-12), names[i]
    f1_61908 = 0.0007 * (2000 / 10000) ** 0.5
    assert out.loc[0, "M1 [N*mm]"] == pytest.approx(f1_61908 * 2000 * 51.0, rel=1e-12)
    assert out.loc[1:, "M1 [N*mm]"].tolist() == pytest.approx([
        0.0002 * 2000 * 65.0, 0.0004 * 2000 * 112.5, 0.0004 * 2000 * 70.0,
        0.001 * (2000 / 7500) ** 0.33 * 2000 * 31.0, 0.001 * (2000 / 7350) ** 0.33 * 2000 * 57.5], rel=1e-12)


def test_a_622_bearing_with_grease_fills_its_values_and_keeps_the_seal_warning():
    """62205-2RSR (HR 1 p. 202/203, row 22, text copy lines 23135 / 23499: 25 x 52 x 18, C0 7800 N, n_B '–'),
    with grease: the Schaeffler catalogue prints no oil-bath f0 for 622. f0 = 1.1, f1 = 0.0009 (P0/C0)^0.5."""
    out = calc(_row(designation="62205-2RSR", lubrication="grease"))
    dM = (25 + 52) / 2
    assert out["M0 [N*mm]"].iat[0] == pytest.approx(1.1 * (12 * 3000) ** (2 / 3) * dM ** 3 * 1e-7, rel=1e-12)
    assert out["M1 [N*mm]"].iat[0] == pytest.approx(0.0009 * (2000 / 7800) ** 0.5 * 2000 * dM, rel=1e-12)
    assert out["status"].iat[0] == "warning" and out["message"].iat[0].startswith(
        "contact seals: their friction comes on top of the catalogue model")
    assert np.isnan(out["n_thr [1/min]"].iat[0])


def test_a_typed_value_wins_and_a_disagreement_is_a_warning():
    # C0 is printed to 3 significant digits (18 kN: +-50 N); 18.04 kN agrees, 19 kN does not
    out = calc(pd.concat([_row(**{"C0 [kN]": 19.0, "D [mm]": 80.0}), _row(**{"C0 [kN]": 18.04})],
                         ignore_index=True))
    assert out["status"].tolist() == ["warning", "ok"]
    # (the table's value in the column's unit, and in the catalogue unit after it)
    assert out["message"].iat[0] == ("C0 [kN]: 19 differs from 18 (18000 N) of 6208 in the bearing table "
                                     "(Schaeffler HR 1, 2006); the value given is used")
    assert out["P0 [N]"].iat[0] == 2000.0


def test_an_unknown_designation_without_dimensions_lists_close_matches():
    out = calc(pd.concat([_row(designation="6208-2ZZ"), _row()], ignore_index=True))
    assert out["status"].tolist() == ["error", "ok"]
    assert out["message"].iat[0].startswith(
        "designation: '6208-2ZZ' is not in the bearing table (Schaeffler HR 1, 2006); close matches: 6208-2Z, "
        "6208-2RSR, 6208, 608-2Z, 6320-2Z; or type the dimensions d, D (and C0)")


def test_an_unknown_designation_with_dimensions_is_computed_as_before():
    out = calc(_row(designation="22208-E1", **{"d [mm]": 40, "D [mm]": 80, "C0 [kN]": 90, "e": 0.28, "Y": 2.4,
                                               "Y0": 2.5}))
    assert out["status"].tolist() == ["ok"] and out["message"].tolist() == [""]
