"""The unit-aware API and the table compute the same state of a bearing: heat_balance and friction_torque against
calc's row, over bearings drawn across the whole bearing table.

heat_balance runs its own orchestration of calc's parts (fill, viscosity, friction model, heat balance), and
friction_torque its own fill and checks: a step one of them takes and the other does not (as the plot's own copy
of calc's steps once skipped the fill) shows here as a bearing whose status or numbers differ.
"""
import numpy as np
import pandas as pd
import pint
import pytest

import bearingheat as bh
from bearingheat.catalogue.bearings import bearing, designations
from bearingheat.errors import FrictionInputError

u = pint.get_application_registry()
NU = u("mm^2/s")
#: heat_balance's N_R is the exact power M*2*pi*n/60, calc's NR the catalogue's M*n/9550 (docs/thermal.md)
EXACT_OVER_CATALOGUE = 9550 / (30000 / np.pi)
LUBRICATIONS = ("oil_bath", "grease", "circulating_oil", "oil_mist")


def operating_points(count: int = 48, seed: int = 11) -> list[dict]:
    """Bearings of every kind in the table (every k-th designation), each at its own speed, loads, lubrication,
    model and oil (a fixed nu, or nu40/nu100 taken at T_op). Cylindrical roller bearings carry no axial load (M2
    would need an f2 chart); the SKF model's oil baths have the worked example's level and VM."""
    rng = np.random.default_rng(seed)
    table = list(designations())
    points = []
    for k, designation in enumerate(table[::len(table) // count][:count]):
        axial = float(rng.choice([0.0, rng.uniform(0, 2)]))
        model = ("schaeffler", "skf")[k % 3 == 0]
        points.append({"designation": designation, "n": float(rng.uniform(100, 8000)),
                       "Fr": float(rng.uniform(0.1, 5)),
                       "Fa": 0.0 if bearing(designation).family == "cylindrical roller" else axial,
                       "lubrication": LUBRICATIONS[k % 4], "model": model, "oil": bool(k % 2),
                       "bath": model == "skf" and LUBRICATIONS[k % 4] == "oil_bath"})
    return points


POINTS = operating_points()


def table_row(p: dict) -> dict:
    row = {"designation": p["designation"], "n [rpm]": p["n"], "Fr [kN]": p["Fr"], "Fa [kN]": p["Fa"],
           "lubrication": p["lubrication"], "model": p["model"], "T_amb [degC]": 20.0, "T_bearing [degC]": 70.0}
    row.update({"nu40 [mm^2/s]": 68.0, "nu100 [mm^2/s]": 8.6} if p["oil"] else {"nu [mm^2/s]": 20.0})
    return {**row, **({"oil_level [mm]": 2.5, "VM": 3e-5} if p["bath"] else {})}


def bath(p: dict) -> dict:
    return {"model_inputs": {"oil_level": 2.5 * u.mm, "VM": 3e-5}} if p["bath"] else {}


def arguments(p: dict) -> dict:
    oil = dict(nu40=68 * NU, nu100=8.6 * NU) if p["oil"] else dict(nu=20 * NU)
    return dict(n=p["n"] * u.rpm, Fr=p["Fr"] * u.kN, Fa=p["Fa"] * u.kN, lubrication=p["lubrication"],
                model=p["model"], T_amb=u.Quantity(20.0, "degC"), T_bearing=u.Quantity(70.0, "degC"), **oil,
                **bath(p))


@pytest.fixture(scope="module")
def table():
    return bh.calc(pd.DataFrame([table_row(p) for p in POINTS]))


def test_the_points_cover_the_kinds_of_bearings_both_models_and_every_status(table):
    assert {bearing(d).family for d in table["designation"]} == {"deep groove ball", "angular contact ball",
                                                                 "cylindrical roller", "tapered roller"}
    assert {p["model"] for p in POINTS} == {"schaeffler", "skf"} and set(table["status"]) == {"ok", "warning", "error"}


@pytest.mark.parametrize("k", range(len(POINTS)))
def test_heat_balance_is_calc_s_row(table, k):
    p, row = POINTS[k], table.iloc[k]
    r = bh.heat_balance(p["designation"], **arguments(p))
    assert r.status == [row["status"]]
    pairs = {"n_thr": (r.n_thr.to("1/min").magnitude, row["n_thr [1/min]"]),
             "n_per": (r.n_per.to("1/min").magnitude, row["n_per [1/min]"]),
             "T_op": (r.T_op.to("degC").magnitude, row["T_op [degC]"]),
             "NR": (r.NR.to("W").magnitude, row["NR [W]"] * EXACT_OVER_CATALOGUE)}
    for name, (api, calc) in pairs.items():
        assert api == pytest.approx(calc, rel=1e-9, nan_ok=True), name


@pytest.mark.parametrize("k", range(len(POINTS)))
def test_friction_torque_is_calc_s_row_at_calc_s_viscosity(table, k):
    """At the viscosity calc used (the given nu, or that of the oil at T_op), friction_torque gives calc's MR;
    where calc's row is an error, friction_torque raises with calc's error (here: sealed bearings whose seal is no
    type of the SKF model's table)."""
    p, row = POINTS[k], table.iloc[k]
    given = "nu [mm^2/s]" in table.columns and not np.isnan(row["nu [mm^2/s]"])
    nu = 20.0 if row["status"] == "error" else row["nu [mm^2/s]"] if given else row["nu_used [mm^2/s]"]
    point = dict(n=p["n"] * u.rpm, Fr=p["Fr"] * u.kN, Fa=p["Fa"] * u.kN, nu=nu * NU, lubrication=p["lubrication"],
                 model=p["model"], **bath(p))
    if row["status"] == "error":
        with pytest.raises(FrictionInputError) as info:
            bh.friction_torque(p["designation"], **point)
        assert row["message"].startswith(str(info.value))  # (calc's row goes on with its warnings)
        return
    r = bh.friction_torque(p["designation"], **point)
    assert r.MR.to("N*mm").magnitude == pytest.approx(row["MR [N*mm]"], rel=1e-9)
