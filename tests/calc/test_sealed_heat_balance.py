"""The heat balance of a bearing with contact seals whose friction model has the seal friction (the SKF model's
M_seal): n_per and T_op with the seal friction in N_R, no n_thr (ISO 15312 defines none for sealed bearings).
Hand calculations of A_r, k_q, M_seal and the balance; the catalogue model keeps its refusal."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pint
import pytest

import bearingheat as bh
from bearingheat.catalogue.thermal import CONTACT_SEAL_REASON

u = pint.get_application_registry()
#: 6208-2RSR in grease (HR 1, 2006: d 40, D 80, B 18 mm), the SKF model with RS1 seals on d_s = 49 mm
ROW = {"designation": "6208-2RSR", "lubrication": "grease", "model": "skf", "n [rpm]": 3000.0, "Fr [kN]": 2.0,
       "nu [mm^2/s]": 20.0, "seal": "RS1", "d_s [mm]": 49.0, "T_amb [degC]": 20.0, "T_bearing [degC]": 70.0}
#: the heat balance of a radial bearing by hand: A_r = pi*B*(D + d) (HR 1, p. 64) and the default k_q = q_r/50 K
#: of the reference conditions (q_r = 0.016 W/mm^2 up to A_r = 50000 mm^2, ISO 15312)
A_r = math.pi * 18 * (80 + 40)
K_Q = 0.016 / 50
#: M_seal = KS1*d_s^beta + KS2 of RS1 seals on a deep groove ball bearing, 62 < D <= 80 mm (SKF General Catalogue
#: 6000, p. 96, table 4: KS1 0.018, beta 2.25, KS2 20)
M_SEAL = 0.018 * 49 ** 2.25 + 20
def friction_power(MR: float, n: float) -> float:
    """N_R [W] = M_R [N*mm] * 2*pi*n/60 [1/s] / 1000: the exact power the heat balance takes (calc's NR column is
    the catalogue's M_R*n/9550)."""
    return MR * 2 * math.pi * n / 60 / 1000


SEAL_FRICTION_MESSAGE = (
    "n_thr: ISO 15312 defines no thermal reference speed for bearings with contact seals (its reference conditions "
    "have no seal friction; Schaeffler HR 1 prints none for them); n_per and T_op are the heat balance's with the "
    "seal friction M_seal of the friction model in N_R (bearingheat's extension of the method, whose sources leave "
    "sealed bearings out)")


def test_the_seal_friction_heats_the_bearing_by_hand():
    rows = pd.DataFrame([ROW, {**ROW, "designation": "6208", "seal": None, "d_s [mm]": np.nan}])
    out = bh.calc(rows)
    sealed, open_ = out.iloc[0], out.iloc[1]
    assert sealed["M_seal [N*mm]"] == pytest.approx(M_SEAL, rel=1e-12) and round(M_SEAL, 2) == 134.34
    # the seals add their torque to the open bearing's (grease: no drag)
    assert sealed["MR [N*mm]"] - open_["MR [N*mm]"] == pytest.approx(M_SEAL, rel=1e-12)
    # nu given: N_R does not change with the temperature, so T_op = T_amb + N_R/(k_q*A_r)
    heat = friction_power(sealed["MR [N*mm]"], 3000)
    assert sealed["T_op [degC]"] == pytest.approx(20 + heat / (K_Q * A_r), rel=1e-9)
    assert round(sealed["T_op [degC]"], 1) == 48.6 and round(open_["T_op [degC]"], 1) == 29.2
    assert sealed["Q_S [W]"] == pytest.approx(K_Q * A_r * 50, rel=1e-12)
    assert np.isnan(sealed["n_thr [1/min]"]) and open_["n_thr [1/min]"] > 0
    assert (sealed["status"], sealed["message"]) == ("warning", SEAL_FRICTION_MESSAGE)


def test_n_per_is_the_speed_at_which_the_sealed_bearing_makes_the_heat_carried_away():
    out = bh.calc(pd.DataFrame([ROW]))
    n_per = out["n_per [1/min]"].iat[0]
    assert round(n_per) == 4995 and out["n_per_method_used"].iat[0] == "exact root"
    at_n_per = bh.calc(pd.DataFrame([{**ROW, "n [rpm]": n_per}]))
    heat = friction_power(at_n_per["MR [N*mm]"].iat[0], n_per)
    assert heat == pytest.approx(K_Q * A_r * 50, rel=1e-9)  # the heat carried away at T_bearing
    # the seal friction lowers the permissible speed: the open 6208 may run far faster
    open_ = bh.calc(pd.DataFrame([{**ROW, "designation": "6208", "seal": None, "d_s [mm]": np.nan}]))
    assert open_["n_per [1/min]"].iat[0] > 2 * n_per


def test_with_oil_data_the_viscosity_is_the_oil_s_at_the_operating_temperature():
    row = {key: value for key, value in ROW.items() if key != "nu [mm^2/s]"} | {"iso_vg": 68.0}
    out = bh.calc(pd.DataFrame([row]))
    T_op = out["T_op [degC]"].iat[0]
    assert out["nu_at"].iat[0] == "T_op" and out["status"].iat[0] == "warning"
    nu = bh.oil_viscosity(u.Quantity(T_op, "degC"), iso_vg=68).to("mm^2/s").magnitude
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(nu, rel=1e-9)
    # one operating state: the friction heat at nu(T_op) is the heat carried away at T_op
    assert friction_power(out["MR [N*mm]"].iat[0], 3000) == pytest.approx(K_Q * A_r * (T_op - 20), rel=1e-9)


def test_the_api_heat_balance_is_calc_s():
    r = bh.heat_balance("6208-2RSR", n=3000 * u.rpm, Fr=2 * u.kN, nu=20 * u("mm^2/s"), lubrication="grease",
                        T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"), model="skf",
                        model_inputs={"seal": "RS1", "d_s": 49 * u.mm})
    out = bh.calc(pd.DataFrame([ROW]))
    assert r.status == ["warning"] and r.messages == [SEAL_FRICTION_MESSAGE]
    assert r.T_op.to("degC").magnitude == pytest.approx(out["T_op [degC]"].iat[0], rel=1e-9)
    assert r.n_per.to("1/min").magnitude == pytest.approx(out["n_per [1/min]"].iat[0], rel=1e-9)
    assert np.isnan(r.n_thr.magnitude)


@pytest.mark.parametrize("row", [
    {**ROW, "model": "schaeffler"},  # the catalogue model has no seal term
    {**ROW, "seals": 0},  # the seal friction left out
], ids=["catalogue model", "seals 0"])
def test_without_the_seal_friction_a_sealed_bearing_still_has_no_heat_balance(row):
    out = bh.calc(pd.DataFrame([row]))
    assert np.isnan(out["T_op [degC]"].iat[0]) and np.isnan(out["n_per [1/min]"].iat[0])
    assert f"n_thr: {CONTACT_SEAL_REASON}" in out["message"].iat[0]


def test_a_table_of_sealed_and_open_rows_of_one_bearing_is_row_by_row():
    """The reference-speed details are worked out once per bearing and seal friction: a sealed row and a row of
    the same bearing without seal friction in one table get what each gets alone."""
    rows = [ROW, {**ROW, "seals": 0}, ROW, {**ROW, "model": "schaeffler"}]
    together = bh.calc(pd.DataFrame(rows))
    alone = pd.concat([bh.calc(pd.DataFrame([row])) for row in rows], ignore_index=True)
    for name in ("MR [N*mm]", "T_op [degC]", "n_per [1/min]", "n_thr [1/min]"):
        np.testing.assert_allclose(together[name], alone[name], rtol=1e-12)
    assert together["message"].tolist() == alone["message"].tolist()


def test_a_model_evaluated_at_each_speed_finds_n_per_without_n_thr():
    """n_per of the SKF model is the root of its own N_R(n) = Q at T_bearing: an NU 2 bearing typed without C0
    (no reference load, so no n_thr) still gets it; the catalogue model's n_per = n_thr*f_n does not."""
    row = {"type": "cylindrical_roller", "series": "2", "prefix": "NU", "d [mm]": 40, "D [mm]": 80, "B [mm]": 18,
           "lubrication": "grease", "model": "skf", "n [rpm]": 3000.0, "Fr [kN]": 2.0, "nu [mm^2/s]": 20.0,
           "T_amb [degC]": 20.0, "T_bearing [degC]": 70.0}
    out = bh.calc(pd.DataFrame([row, {**row, "model": "schaeffler"}]))
    assert out["message"].tolist() == ["n_thr: C0 [N]: missing; the reference load is a fraction of C0"] * 2
    n_per = out["n_per [1/min]"].iat[0]
    at_n_per = bh.calc(pd.DataFrame([{**row, "n [rpm]": n_per}]))
    assert friction_power(at_n_per["MR [N*mm]"].iat[0], n_per) == pytest.approx(K_Q * A_r * 50, rel=1e-9)
    assert np.isnan(out["n_per [1/min]"].iat[1]) and not np.isnan(out["T_op [degC]"].iat[1])


def test_the_seal_friction_only_ever_warms_the_bearing():
    """First principles: the seals add a torque of their own to the open bearing's at every speed, so the sealed
    bearing runs warmer at each speed, the warmer the faster it runs, and reaches T_bearing at a lower speed."""
    speeds = [250.0, 1000.0, 2000.0, 4000.0]
    sealed = bh.calc(pd.DataFrame([{**ROW, "n [rpm]": n} for n in speeds]))
    open_ = bh.calc(pd.DataFrame([{**ROW, "designation": "6208", "seal": None, "d_s [mm]": np.nan, "n [rpm]": n}
                                  for n in speeds]))
    np.testing.assert_allclose(sealed["MR [N*mm]"] - open_["MR [N*mm]"], M_SEAL, rtol=1e-12)
    assert (sealed["T_op [degC]"] > open_["T_op [degC]"]).all()
    assert (np.diff(sealed["T_op [degC]"]) > 0).all()
    assert (sealed["n_per [1/min]"] < open_["n_per [1/min]"]).all()
