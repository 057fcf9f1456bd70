"""One operating state: calc reports MR and NR at T_op, and agrees with heat_balance + friction_torque."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.units import ureg

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
    chart = "docs/f2_chart_example.csv"
    out = bh.calc(_axially_loaded(), f2_chart=chart)
    assert out["status"].tolist() == ["ok"] and out["nu_at"].tolist() == ["T_op"]
    assert out["M2 [N*mm]"].iat[0] > 0
    assert out["nu_used [mm^2/s]"].iat[0] == pytest.approx(out["nu_op [mm^2/s]"].iat[0], rel=1e-10)
    given = bh.calc(_axially_loaded(**{"nu [mm^2/s]": out["nu_used [mm^2/s]"].iat[0]})
                    .drop(columns=["nu40 [mm^2/s]", "nu100 [mm^2/s]"]), f2_chart=chart)
    for column in ("M2 [N*mm]", "MR [N*mm]", "T_op [degC]"):
        assert given[column].iat[0] == pytest.approx(out[column].iat[0], rel=1e-9), column


def test_a_row_computed_again_names_its_own_cell():
    rows = pd.concat([table(), table(**{"n [rpm]": 60000, "T_bearing [degC]": np.nan})], ignore_index=True)

    def cell(name, row):
        return f"Supports!{name}{row + 7}"

    out = bh.calc(rows, viscosity_at="operating", cell=cell)
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].iat[1] == (
        "Supports!nu8 nu [mm^2/s]: missing; the operating viscosity (base oil viscosity for grease) is needed; "
        "Supports!nu8 nu [mm^2/s]: cannot be taken at T_op; no equilibrium below 150 degC: the friction heat exceeds "
        "the heat carried away (the temperature runs away); give T_bearing; Supports!n8 n [rpm]: 60000 is above the "
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


def test_a_row_off_the_f2_chart_at_T_op_is_told_where_nu_came_from():
    out = bh.calc(_axially_loaded(**{"n [rpm]": 300}), f2_chart="docs/f2_chart_example.csv")
    assert out["status"].tolist() == ["error"] and out["nu_at"].tolist() == ["T_op"]
    assert out["message"].iat[0] == (
        "f2: nu*n*dM = 2.567e+06 mm^3/(s*min) is outside curve 'A' (Fa/A = 0.5: 1000 to 1e+06); the Schaeffler "
        "catalogue forbids extrapolating the chart; nu [mm^2/s]: 186, taken at the operating temperature T_op = "
        "22.32 degC; give T_bearing and viscosity_at 'bearing', or nu, for another viscosity")
    # at T_bearing (70 degC) the oil is thin enough for the chart
    assert bh.calc(_axially_loaded(**{"n [rpm]": 300}), f2_chart="docs/f2_chart_example.csv",
                   viscosity_at="bearing")["status"].tolist() == ["ok"]


def test_an_ambient_at_or_above_the_search_limit_is_said_so_not_called_a_runaway():
    """The search for T_op ends at 150 degC; an ambient of 160 degC leaves nothing to search, which is no proof
    that the heat runs away (n_per says the bearing may run at n)."""
    rows = pd.concat([table(**{"T_amb [degC]": 20.0}), table(**{"T_amb [degC]": 170.0, "T_bearing [degC]": 199.0})],
                     ignore_index=True)
    out = bh.calc(rows)
    assert out["T_op [degC]"].iat[0] > 20.0 and np.isnan(out["T_op [degC]"].iat[1])
    assert out["status"].iat[1] == "warning"
    assert out["message"].iat[1].split("T_op: ")[-1] == (
        "the ambient temperature T_amb = 170 degC is not below 150 degC, the upper end of the search for the operating "
        "temperature; T_op is not computed")
