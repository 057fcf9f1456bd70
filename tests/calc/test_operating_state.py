"""One operating state: calc reports MR and NR at T_op, and agrees with heat_balance + friction_torque."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

import bearingheat as bh
from bearingheat.units import ureg
from thermal_helpers import NJ208_ROW, nj208_chart, nj208_chart_m2, nj208_roots, walther_by_hand

u = ureg()


def table(**cells):
    row = {"designation": "6205", "d [mm]": 25, "D [mm]": 52, "B [mm]": 15, "C0 [kN]": 7.8,
           "lubrication": "oil_bath", "n [rpm]": 3000, "Fr [kN]": 2.0, "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6,
           "T_amb [degC]": 20, "T_bearing [degC]": 80}
    return pd.DataFrame([{**row, **cells}])


def test_calc_reports_the_friction_at_the_operating_temperature():
    out = bh.calc(table())
    assert out["nu_at"].tolist() == ["T_op"]
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(out["nu_op [mm^2/s]"].iat[0], rel=1e-9)
    # the catalogue model by hand at nu_op: M0 = f0 (nu n)^(2/3) dM^3 1e-7 with f0 = 2 (series 62, oil bath)
    nu = out["nu_op [mm^2/s]"].iat[0]
    assert out["M0 [N*mm]"].iat[0] == pytest.approx(2.0 * (nu * 3000) ** (2 / 3) * 38.5 ** 3 * 1e-7, rel=1e-9)


def test_the_two_python_routes_give_the_same_numbers():
    out = bh.calc(table())
    balance = bh.heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
                              Fr=2 * u.kN, nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"),
                              T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(80, "degC"))
    assert balance.T_op.to("degC").magnitude == pytest.approx(out["T_op [degC]"].iat[0], rel=1e-9)
    friction = bh.friction_torque("6205", n=3000 * u.rpm, nu=balance.nu_op, lubrication="oil_bath", d=25 * u.mm,
                                  D=52 * u.mm, C0=7.8 * u.kN, Fr=2 * u.kN)
    assert friction.MR.to("N*mm").magnitude == pytest.approx(out["MR [N*mm]"].iat[0], rel=1e-9)
    assert friction.NR.to("W").magnitude == pytest.approx(out["NR [W]"].iat[0], rel=1e-9)
    # the heat balance's own N_R is at the operating state too; it is the exact power M*2*pi*n/60, calc's NR the
    # catalogue's M*n/9550 (30000/pi = 9549.3): 0.007 % apart
    assert balance.NR.to("W").magnitude == pytest.approx(out["NR [W]"].iat[0] * 9550 / (30000 / np.pi), rel=1e-9)
    # n_per is the speed at which the bearing reaches T_bearing: the same on both routes
    assert balance.n_per.to("1/min").magnitude == pytest.approx(out["n_per [1/min]"].iat[0], rel=1e-9)


def test_viscosity_at_bearing_keeps_the_former_state():
    out = bh.calc(table(), viscosity_at="bearing")
    assert out["nu_at"].tolist() == ["T_bearing"]
    nu_80 = bh.oil_viscosity(u.Quantity(80, "degC"), nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"))
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(np.asarray(nu_80.magnitude).item(), rel=1e-9)
    at_op = bh.calc(table())
    # cooler oil at T_op (the bearing runs below 80 degC): thicker, more friction; n_per is unchanged
    assert at_op["MR [N*mm]"].iat[0] > out["MR [N*mm]"].iat[0]
    assert at_op["n_per [1/min]"].iat[0] == out["n_per [1/min]"].iat[0]
    per_row = bh.calc(table(viscosity_at="bearing"))
    assert per_row["nu_at"].tolist() == ["T_bearing"]


def test_a_bad_viscosity_at_is_named():
    with pytest.raises(bh.InputError) as info:
        bh.calc(table(), viscosity_at="oil")
    assert str(info.value) == "viscosity_at: 'oil' is not one of auto, bearing, operating"
    out = bh.calc(table(viscosity_at="oil"))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0].startswith("viscosity_at: 'oil' is not one of auto, bearing, operating")


def _counting(monkeypatch, name):
    """Count the rows each evaluation of model ``name`` gets (the registry entry wrapped, nothing else changed)."""
    import dataclasses

    from bearingheat.calc import models
    sizes = []
    model = models.MODELS[name]

    def evaluate(supports, labels, f2_chart):
        sizes.append(supports.size)
        return model.evaluate(supports, labels, f2_chart)

    monkeypatch.setitem(models.MODELS, name, dataclasses.replace(model, evaluate=evaluate))
    return sizes


def test_the_catalogue_model_runs_once_per_row_when_nu_is_taken_at_T_op(monkeypatch):
    sizes = _counting(monkeypatch, "schaeffler")
    rows = pd.concat([table(), table(**{"n [rpm]": 1500}), table(**{"Fr [kN]": 4.0})], ignore_index=True)
    out = bh.calc(rows)
    assert sizes == [3]  # one evaluation of the three rows; M0, MR, NR follow nu(T_op) by the kernels
    assert out["nu_at"].tolist() == ["T_op"] * 3
    # the same numbers as the model evaluated at that viscosity
    given = bh.calc(rows.drop(columns=["nu40 [mm^2/s]", "nu100 [mm^2/s]"])
                    .assign(**{"nu [mm^2/s]": out["nu_used [mm^2/s]"]}))
    for column in ("M0 [N*mm]", "M1 [N*mm]", "MR [N*mm]", "NR [W]", "T_op [degC]"):
        np.testing.assert_allclose(out[column], given[column], rtol=1e-12)
    np.testing.assert_allclose(out["nu_used [mm^2/s]"], out["nu_op [mm^2/s]"], rtol=1e-12)


def test_the_skf_model_gives_its_own_operating_state():
    # the viscosity at T_op is that of the SKF model's heat balance (it was the catalogue model's until 2026-11)
    out = bh.calc(table(**{"oil_level [mm]": 2.5, "VM": 3e-5}), model="skf")
    assert out["nu_at"].tolist() == ["T_op"]
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(out["nu_op [mm^2/s]"].iat[0], rel=1e-12)
    given = bh.calc(table(**{"nu [mm^2/s]": out["nu_used [mm^2/s]"].iat[0], "oil_level [mm]": 2.5, "VM": 3e-5})
                    .drop(columns=["nu40 [mm^2/s]", "nu100 [mm^2/s]"]), model="skf")
    assert given["MR [N*mm]"].iat[0] == pytest.approx(out["MR [N*mm]"].iat[0], rel=1e-12)
    assert given["T_op [degC]"].iat[0] == pytest.approx(out["T_op [degC]"].iat[0], rel=1e-12)


def _axially_loaded(**cells):
    row = {"designation": "NJ206-E-XL", "d [mm]": 30, "D [mm]": 62, "B [mm]": 16, "C0 [kN]": 36,
           "lubrication": "oil_bath", "n [rpm]": 100, "Fr [kN]": 5.0, "Fa [kN]": 0.05, "nu40 [mm^2/s]": 68,
           "nu100 [mm^2/s]": 8.6, "T_amb [degC]": 20, "T_bearing [degC]": 70}
    return pd.DataFrame([{**row, **cells}])


def test_f2_read_off_the_chart_settles_with_the_operating_temperature():
    # M2 = f2*Fa*dM with f2 read at nu*n*dM (the Schaeffler catalogue, p. 70): nu, T_op and M2 are solved together
    # (no T_bearing: this made-up chart does not reach the speed n_per would be at)
    chart = "docs/f2_chart_example.csv"
    out = bh.calc(_axially_loaded().drop(columns=["T_bearing [degC]"]), f2_chart=chart)
    assert out["status"].tolist() == ["ok"] and out["nu_at"].tolist() == ["T_op"]
    assert out["M2 [N*mm]"].iat[0] > 0
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(out["nu_op [mm^2/s]"].iat[0], rel=1e-10)
    given = bh.calc(_axially_loaded(**{"nu [mm^2/s]": out["nu_used [mm^2/s]"].iat[0]})
                    .drop(columns=["nu40 [mm^2/s]", "nu100 [mm^2/s]", "T_bearing [degC]"]), f2_chart=chart)
    for column in ("M2 [N*mm]", "MR [N*mm]", "T_op [degC]"):
        assert given[column].iat[0] == pytest.approx(out[column].iat[0], rel=1e-9), column


def test_m2_read_off_the_chart_follows_the_speed_and_temperature_of_each_root(tmp_path):
    """n_per and T_op of an axially loaded NJ208-E whose f2 comes from a chart are the same whatever viscosity the
    friction results are reported at: M2 = f2(nu*n*dM)*Fa*dM is taken at the speed and viscosity of each root
    (before, M2 of the operating point was held fixed: n_per 1361 or 1549 1/min, T_op 56.95 or 52.59 degC)."""
    both = bh.calc(pd.DataFrame([{**NJ208_ROW, "viscosity_at": "bearing"}, {**NJ208_ROW, "viscosity_at": ""}]),
                   f2_chart=str(nj208_chart(tmp_path)))
    n_per, T_op = nj208_roots()
    assert (round(n_per), round(T_op, 2)) == (1471, 52.59)
    assert both["status"].tolist() == ["ok", "ok"] and both["nu_at"].tolist() == ["T_bearing", "T_op"]
    np.testing.assert_allclose(both["n_per [1/min]"], [n_per, n_per], rtol=1e-9)
    np.testing.assert_allclose(both["T_op [degC]"], [T_op, T_op], rtol=1e-9)
    # the friction results themselves are those of each row's viscosity
    nu = walther_by_hand(68, 8.6)
    np.testing.assert_allclose(both["M2 [N*mm]"], [nj208_chart_m2(nu(70) * 1000), nj208_chart_m2(nu(T_op) * 1000)],
                               rtol=1e-9)


def test_a_row_computed_again_names_its_own_cell():
    rows = pd.concat([table(), table(**{"n [rpm]": 60000, "T_bearing [degC]": np.nan})], ignore_index=True)

    def cell(name, row):
        return f"Supports!{name}{row + 7}"

    out = bh.calc(rows, viscosity_at="operating", cell=cell)
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].iat[1] == (  # (not 'nu: missing ... is needed' before it: that only follows from it)
        "Supports!nu8 nu [mm^2/s]: cannot be taken at T_op; no equilibrium up to 150 degC, the upper end of the search: "
        "the friction heat still exceeds the heat carried away there; with the catalogue model the friction heat stays "
        "bounded as the temperature rises while the heat carried away grows with it, so an equilibrium lies above; "
        "T_op is not computed; give T_bearing; Supports!n8 n [rpm]: 60000 is above the "
        "limiting speed n_G = 17000 1/min of 6205 (Schaeffler HR 1, 2006); check the speed and its unit")


def test_blocks_of_rows_give_the_same_numbers(monkeypatch):
    # the root searches take rows in blocks that stay in the cache (10^6-row tables); a block's rows are solved
    # on their own, so blocks of 2 rows give what one block of all rows gives, to the last bit
    import importlib

    thermal = importlib.import_module("bearingheat.calc.operating_temperature")
    kernels = importlib.import_module("bearingheat.kernels.thermal")
    skf = pd.read_csv("examples/gearbox_shaft_skf.csv")
    rows = skf.drop(columns=["nu [mm^2/s]"]).assign(**{"nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6})
    rows["model"] = ["skf", "schaeffler"] * (len(rows) // 2) + ["skf"] * (len(rows) % 2)
    whole = bh.calc(rows)
    monkeypatch.setattr(thermal, "ROOT_BLOCK", 2)
    monkeypatch.setattr(kernels, "_NEWTON_BLOCK", 3)
    blocked = bh.calc(rows)
    pd.testing.assert_frame_equal(blocked, whole, check_exact=True)
    assert whole["nu_at"].eq("T_op").sum() >= 4 and whole["n_per [1/min]"].notna().sum() >= 4


def test_an_equilibrium_off_the_f2_chart_is_not_computed():
    """At 300 1/min the heat balance of this NJ206-E would settle below 38.74 degC, where nu*n*dM is above the
    made-up chart's 1e6 mm^3/(s*min): T_op is not computed there (the Schaeffler catalogue, p. 70: the charts are
    not extrapolated); before, M2 of another temperature stood in and gave 22.32 degC. n_per, at 70 degC, would
    lie above 1088.8 1/min, where the chart ends too."""
    chart = "docs/f2_chart_example.csv"
    nu = walther_by_hand(68, 8.6)
    T_chart = brentq(lambda T: nu(T) * 300 * 46 - 1e6, 20, 150)  # dM = 46 mm
    assert round(T_chart, 2) == 38.74 and round(1e6 / (nu(70) * 46), 1) == 1088.8
    Fa_over_A = 50 / (15e-3 * 46 ** 2.1)  # kB = 15 (the Schaeffler catalogue, p. 70)
    assert round(Fa_over_A, 3) == 1.074
    t_op = ("no equilibrium down to 38.74 degC, where nu*n*dM rises to 1e+06 mm^3/(s*min), the upper end of the f2 "
            "chart at Fa/A = 1.074: the heat carried away already exceeds the friction heat there; the Schaeffler "
            "catalogue forbids extrapolating the chart, so T_op is not computed")
    n_per = ("n_per: the friction heat stays below the heat carried away at T_bearing up to 1088.8 1/min, where "
             "nu*n*dM = 1e+06 mm^3/(s*min) is the upper end of the f2 chart at Fa/A = 1.074; the Schaeffler catalogue "
             "forbids extrapolating it; n_per lies above")
    rows = pd.concat([_axially_loaded(**{"n [rpm]": 300, "viscosity_at": mode})
                      for mode in ("operating", "auto", "bearing")], ignore_index=True)
    out = bh.calc(rows, f2_chart=chart)
    assert out["status"].tolist() == ["error", "warning", "warning"]
    assert out["nu_at"].tolist() == ["-", "T_bearing", "T_bearing"]
    assert out["message"].iat[0] == f"nu [mm^2/s]: cannot be taken at T_op; {t_op}; give T_bearing"
    assert out["message"].iat[1] == out["message"].iat[2] == f"T_op: {t_op}; {n_per}"
    assert out[["T_op [degC]", "n_per [1/min]"]].iloc[1:].isna().all().all()


def test_an_ambient_at_or_above_the_search_limit_is_said_so_not_called_a_runaway():
    """The search for T_op ends at 150 degC; an ambient of 160 degC leaves nothing to search, which is no proof
    that the heat runs away (n_per says the bearing may run at n)."""
    rows = pd.concat([table(**{"T_amb [degC]": 20.0}), table(**{"T_amb [degC]": 170.0, "T_bearing [degC]": 199.0})],
                     ignore_index=True)
    out = bh.calc(rows)
    assert out["T_op [degC]"].iat[0] > 20.0 and np.isnan(out["T_op [degC]"].iat[1])
    assert out["status"].iat[1] == "warning"
    nu_199 = walther_by_hand(68, 8.6)(199)  # (thinner than ASTM D341 reaches: said too)
    assert out["message"].iat[1].split("T_op: ")[-1] == (
        "the ambient temperature T_amb = 170 degC is not below 150 degC, the upper end of the search for the operating "
        f"temperature; T_op is not computed; T_bearing [degC]: nu = {nu_199:.4g} mm^2/s at 199 degC is below 2 mm^2/s, "
        "outside ASTM D341 (an extrapolation); the friction results (nu_used) and n_per are taken at it")


def test_the_f2_chart_ends_that_bound_the_operating_temperature_are_named():
    """The search for T_op of a row whose f2 comes from the chart covers only the temperatures at which
    nu(T)*n*dM lies on it; where it ends there, the message says at which temperature and nu*n*dM."""
    nu = walther_by_hand(68, 8.6)
    rows = pd.concat([_axially_loaded(**{"n [rpm]": 4, "Q_E [W]": 200, "viscosity_at": "operating"}),
                      _axially_loaded(**{"n [rpm]": 8000, "viscosity_at": "bearing", "T_bearing [degC]": 200})],
                     ignore_index=True)
    out = bh.calc(rows, f2_chart="docs/f2_chart_example.csv")
    # 4 1/min: the chart's lowest nu*n*dM, 1000, is met where nu = 1000/(4*46); still heating there with 200 W in
    assert round(brentq(lambda T: nu(T) * 4 * 46 - 1000, 20, 150), 1) == 121.7
    assert out["status"].iat[0] == "error"
    assert out["message"].iat[0].endswith(
        "nu [mm^2/s]: cannot be taken at T_op; no equilibrium up to 121.7 degC, where nu*n*dM falls to 1000 "
        "mm^3/(s*min), the lower end of the f2 chart at Fa/A = 1.074: the friction heat still exceeds the heat "
        "carried away there; the Schaeffler catalogue forbids extrapolating the chart, so T_op is not computed; "
        "give T_bearing")
    # 8000 1/min: even at 150 degC nu*n*dM is above the chart's 1e6 (the friction results at 200 degC are on it)
    assert nu(150) * 8000 * 46 > 1e6 > nu(200) * 8000 * 46
    assert out["message"].iat[1].startswith(
        "T_op: nu*n*dM lies above the f2 chart at Fa/A = 1.074 (1000 to 1e+06 mm^3/(s*min)) at every temperature "
        "from -30 to 150 degC; the Schaeffler catalogue forbids extrapolating the chart, so T_op is not computed; "
        f"n_per: the friction heat stays below the heat carried away at T_bearing up to {1e6 / (nu(200) * 46):.5g} "
        "1/min")


def test_a_row_whose_chart_is_off_at_the_provisional_viscosity_is_solved():
    """calc evaluates the friction of a row whose nu is taken at T_op at a provisional nu (70 degC) first. At
    2000 1/min this NJ206-E's nu*n*dM there, 1.84e6 mm^3/(s*min), is off the made-up chart, but with 100 W flowing
    in it settles at 100.5 degC, where it is on it: the row is solved, not refused for a viscosity it never has."""
    nu = walther_by_hand(68, 8.6)
    assert nu(70) * 2000 * 46 > 1e6
    out = bh.calc(_axially_loaded(**{"n [rpm]": 2000, "Q_E [W]": 100}).drop(columns=["T_bearing [degC]"]),
                  f2_chart="docs/f2_chart_example.csv")
    # by hand: dM = 46 mm, f0 = 2, M1 = 0.0003*5000*46, kB = 15 (the Schaeffler catalogue, pp. 66-70); the chart's
    # curves at Fa/A = 0.5 and 2, log-log between their points at 1e5 and 1e6, then in log Fa/A
    Fa_over_A = 50 / (15e-3 * 46 ** 2.1)

    def f2(x):
        t = math.log(x / 1e5) / math.log(10)
        on_a = math.log(0.005) + t * math.log(0.003 / 0.005)
        on_b = math.log(0.008) + t * math.log(0.005 / 0.008)
        return math.exp(on_a + math.log(Fa_over_A / 0.5) / math.log(4) * (on_b - on_a))

    def balance(T):
        x = nu(T) * 2000 * 46
        M = 2.0 * (nu(T) * 2000) ** (2 / 3) * 46 ** 3 * 1e-7 + 0.0003 * 5000 * 46 + f2(x) * 50 * 46
        return math.pi * 2000 / 30e3 * M + 100 - 0.016 / 50 * math.pi * 16 * (62 + 30) * (T - 20)

    T_op = brentq(balance, 95, 110, xtol=1e-12)
    assert 1e5 < nu(T_op) * 2000 * 46 < 1e6 and round(T_op, 2) == 100.53
    assert out["status"].tolist() == ["ok"] and out["nu_at"].tolist() == ["T_op"]
    assert out["T_op [degC]"].iat[0] == pytest.approx(T_op, rel=1e-9)
    assert out["M2 [N*mm]"].iat[0] == pytest.approx(f2(nu(T_op) * 2000 * 46) * 50 * 46, rel=1e-9)


def test_a_row_refused_for_its_own_chart_reading_keeps_that_refusal():
    """A row whose nu is taken at T_op and whose f2 cannot be read at any viscosity (no kB, or an Fa/A beyond the
    chart's curves) is not solved with the stand-in f2 and keeps the model's own reason, alone: not a heat
    balance built on the stand-in, nor 'nu: missing'."""
    row = {"d [mm]": 50, "D [mm]": 80, "B [mm]": 16, "C0 [kN]": 50, "lubrication": "oil_bath", "n [rpm]": 1000,
           "Fr [kN]": 5.0, "Fa [kN]": 0.2, "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6, "T_amb [degC]": 20}
    rows = pd.DataFrame([{**row, "designation": "NJ1010"},
                         {**row, "designation": "NJ206-E-XL", "d [mm]": 30, "D [mm]": 62, "C0 [kN]": 36,
                          "n [rpm]": 100}])
    out = bh.calc(rows, f2_chart="docs/f2_chart_example.csv")
    assert out["status"].tolist() == ["error", "error"]
    assert out["message"].tolist() == [
        "kB: missing; cylindrical roller bearing with cage series 10 has no kB in the Schaeffler catalogue p. 70, "
        "so Fa/A for the f2 chart is unknown; give f2",
        "f2: Fa/A = 4.297 is outside the f2 chart's curves (0.5 to 2); the Schaeffler catalogue forbids "
        "extrapolating the chart"]


def test_rows_off_the_chart_beside_one_on_it_are_evaluated_once_with_the_stand_in(monkeypatch):
    """The NJ206-E at 2000 1/min whose chart is off at the provisional viscosity (solved at T_op = 100.53 degC, see
    above) between the NJ1010 (no kB) and the NJ206-E at an Fa/A of 4.297 (beyond the curves): the stand-in f2 was
    tried on the three rows, then the solved one was evaluated again alone. The refused rows' results are now put
    back from before the trial: three rows evaluated once, then the solved row at its T_op; every row as alone."""
    import importlib
    thermal = importlib.import_module("bearingheat.calc.thermal")
    row = {"d [mm]": 50, "D [mm]": 80, "B [mm]": 16, "C0 [kN]": 50, "lubrication": "oil_bath", "n [rpm]": 1000,
           "Fr [kN]": 5.0, "Fa [kN]": 0.2, "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6, "T_amb [degC]": 20}
    solved = _axially_loaded(**{"n [rpm]": 2000, "Q_E [W]": 100}).drop(columns=["T_bearing [degC]"])
    rows = pd.concat([pd.DataFrame([{**row, "designation": "NJ1010"}]), solved,
                      pd.DataFrame([{**row, "designation": "NJ206-E-XL", "d [mm]": 30, "D [mm]": 62, "C0 [kN]": 36,
                                     "n [rpm]": 100}])], ignore_index=True)
    evaluated = []
    real = thermal.results_at_viscosity

    def counted(frame, results, changed, **options):
        evaluated.append(np.flatnonzero(changed).tolist())
        return real(frame, results, changed, **options)

    monkeypatch.setattr(thermal, "results_at_viscosity", counted)
    out = bh.calc(rows, f2_chart="docs/f2_chart_example.csv")
    assert evaluated == [[0, 1, 2], [1]]
    assert out["status"].tolist() == ["error", "ok", "error"]
    assert out["message"].tolist() == [
        "kB: missing; cylindrical roller bearing with cage series 10 has no kB in the Schaeffler catalogue p. 70, "
        "so Fa/A for the f2 chart is unknown; give f2",
        "",
        "f2: Fa/A = 4.297 is outside the f2 chart's curves (0.5 to 2); the Schaeffler catalogue forbids "
        "extrapolating the chart"]
    assert round(out["T_op [degC]"].iat[1], 2) == 100.53
    alone = bh.calc(solved, f2_chart="docs/f2_chart_example.csv")
    pd.testing.assert_frame_equal(out.iloc[[1]].reset_index(drop=True)[alone.columns], alone, check_dtype=False)


def test_a_viscosity_below_astm_d341_at_T_bearing_is_told():
    """nu(T_bearing) is the viscosity of n_per, and of the friction results with viscosity_at 'bearing': below
    2 mm^2/s it is an extrapolation of ASTM D341 and is said so, as nu_op is (it was used silently)."""
    nu = walther_by_hand(10, 2.6)
    assert nu(150) < 2 < nu(100)
    oil = {"nu40 [mm^2/s]": 10, "nu100 [mm^2/s]": 2.6, "T_bearing [degC]": 150}
    out = bh.calc(pd.concat([table(**oil, viscosity_at=mode) for mode in ("bearing", "auto")], ignore_index=True))
    assert out["nu_at"].tolist() == ["T_bearing", "T_op"]
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(nu(150), rel=1e-12)
    said = (f"T_bearing [degC]: nu = {nu(150):.4g} mm^2/s at 150 degC is below 2 mm^2/s, outside ASTM D341 (an "
            "extrapolation); ")
    assert said + "the friction results (nu_used) and n_per are taken at it" in out["message"].iat[0]
    assert said + "n_per is taken at it" in out["message"].iat[1]
    # without T_amb there is no heat balance, but the friction results are at T_bearing all the same
    alone = bh.calc(table(**oil, viscosity_at="bearing").drop(columns=["T_amb [degC]"]))
    assert alone["message"].iat[0] == said + "the friction results (nu_used) are taken at it"
    # at 100 degC the oil is inside the standard's range: nothing to say
    assert bh.calc(table(**{"nu40 [mm^2/s]": 10, "nu100 [mm^2/s]": 2.6, "T_bearing [degC]": 100}))[
        "message"].tolist() == ["n_per: the thermal value 17809 1/min is above the limiting speed n_G = 17000 1/min; "
                                "n_per = n_G"]


def test_no_equilibrium_in_the_search_says_what_is_known_beyond_it():
    """Below the search (-30 degC here) the catalogue model with oil data has an equilibrium: as the oil cools,
    nu and the friction heat grow without bound while the heat carried away falls. With 1500 W of cooling the
    6205 settles at -34.08 degC by hand. With a given nu nothing is claimed beyond the search."""
    nu = walther_by_hand(68, 8.6)
    M1 = 0.0009 * (2 / 7.8) ** 0.5 * 2000 * 38.5  # f1 of the 62 series (the Schaeffler catalogue, p. 67)

    def balance(T, viscosity):
        M0 = 2.0 * (viscosity * 3000) ** (2 / 3) * 38.5 ** 3 * 1e-7
        return math.pi * 3000 / 30e3 * (M0 + M1) - 1500 - 0.016 / 50 * math.pi * 15 * (52 + 25) * (T - 20)

    assert balance(-30, nu(-30)) < 0 and round(brentq(lambda T: balance(T, nu(T)), -80, -30), 2) == -34.08
    given = table(**{"Q_E [W]": -1500, "nu [mm^2/s]": 30}).drop(columns=["nu40 [mm^2/s]", "nu100 [mm^2/s]"])
    out = bh.calc(pd.concat([table(**{"Q_E [W]": -1500, "viscosity_at": "bearing"}), given], ignore_index=True))
    search = ("T_op: no equilibrium down to -30 degC, the lower end of the search: the heat carried away already "
              "exceeds the friction heat there")
    assert out["message"].iat[0].startswith(
        search + "; as the oil cools its viscosity, and with it the friction heat of the catalogue model, grows "
        "without bound while the heat carried away falls, so an equilibrium lies below; T_op is not computed")
    assert out["message"].iat[1].startswith(search + "; T_op is not computed")
