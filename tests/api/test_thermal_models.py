"""heat_balance with a friction model of choice: model=, model_inputs= and arrangement= as friction_torque takes them,
the same operating state as calc on the same row, and the refusals with their messages."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pint
import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
import pytest

import bearingheat as bh
from bearingheat.api.thermal import heat_balance
from bearingheat.errors import FrictionInputError, HeatBalanceError, ModelError, UnitError

u = pint.get_application_registry()
NU = u("mm^2/s")

#: a 6205 in an oil bath (the row of tests/calc/test_operating_state.py), and the SKF model's inputs of the bath:
#: the oil level and VM of the worked example of the SKF General Catalogue 6000, chapter Friction (22208 E)
BEARING = dict(d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm, Fr=2 * u.kN, nu40=68 * NU,
               nu100=8.6 * NU, T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(80, "degC"))
BATH = {"oil_level": 2.5 * u.mm, "VM": 3e-5}
ROW = {"designation": "6205", "d [mm]": 25, "D [mm]": 52, "B [mm]": 15, "C0 [kN]": 7.8, "lubrication": "oil_bath",
       "n [rpm]": 3000, "Fr [kN]": 2.0, "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6, "T_amb [degC]": 20,
       "T_bearing [degC]": 80, "oil_level [mm]": 2.5, "VM": 3e-5}
#: heat_balance's N_R is the exact power M*2*pi*n/60, calc's NR the catalogue's M*n/9550 (docs/thermal.md)
EXACT_OVER_CATALOGUE = 9550 / (30000 / np.pi)


def balance(**overrides):
    return heat_balance("6205", **{**BEARING, **overrides})


def test_the_skf_heat_balance_is_calc_s_on_the_same_row():
    r = balance(model="skf", model_inputs=BATH)
    out = bh.calc(pd.DataFrame([{**ROW, "model": "skf"}]))
    assert r.status == ["ok"] and out["status"].tolist() == ["ok"] and out["nu_at"].tolist() == ["T_op"]
    assert r.n_per.to("1/min").magnitude == pytest.approx(out["n_per [1/min]"].iat[0], rel=1e-9)
    assert r.T_op.to("degC").magnitude == pytest.approx(out["T_op [degC]"].iat[0], rel=1e-9)
    assert r.NR.to("W").magnitude == pytest.approx(out["NR [W]"].iat[0] * EXACT_OVER_CATALOGUE, rel=1e-9)
    # the model chosen is the one computed: the catalogue model's state differs (n_per 9979 against 12258 1/min)
    catalogue = balance()
    assert round(catalogue.n_per.to("1/min").magnitude) == 9979 and round(r.n_per.to("1/min").magnitude) == 12258
    # n_thr is the catalogue model's whatever the model (ISO 15312)
    assert r.n_thr.magnitude == catalogue.n_thr.magnitude


def test_a_pair_is_calc_s_pair():
    # each bearing at Fr/2 (the SKF model); the sources give no heat balance of a pair, so both routes leave n_per
    # and T_op out with the same warning, and nu is taken at T_bearing
    r = balance(model="skf", model_inputs=BATH, arrangement="paired")
    out = bh.calc(pd.DataFrame([{**ROW, "model": "skf", "arrangement": "paired"}]))
    assert r.status == out["status"].tolist() == ["warning"] and out["nu_at"].tolist() == ["T_bearing"]
    assert r.messages == out["message"].tolist()
    assert r.messages[0].startswith("n_thr: the heat balance of a bearing pair is not in the sources")
    assert np.isnan(r.n_per.magnitude) and np.isnan(out["n_per [1/min]"].iat[0])
    assert np.isnan(r.T_op.magnitude) and np.isnan(out["T_op [degC]"].iat[0])
    assert r.NR.to("W").magnitude == pytest.approx(out["NR [W]"].iat[0] * EXACT_OVER_CATALOGUE, rel=1e-9)
    # the pair's NR: twice that of one bearing at half the load, at the same viscosity (nu at T_bearing)
    one = balance(model="skf", model_inputs=BATH, Fr=1 * u.kN, viscosity_at="bearing")
    assert r.NR.to("W").magnitude == pytest.approx(2 * one.NR.to("W").magnitude, rel=1e-12)


def test_a_catalogue_factor_goes_in_as_calc_s_column():
    # f0 is no argument of heat_balance: the catalogue model reads it from model_inputs, as from calc's f0 column
    r = balance(model_inputs={"f0": 3.0})
    out = bh.calc(pd.DataFrame([{**ROW, "f0": 3.0}]).drop(columns=["oil_level [mm]", "VM"]))
    assert r.T_op.to("degC").magnitude == pytest.approx(out["T_op [degC]"].iat[0], rel=1e-9)
    assert r.n_per.to("1/min").magnitude == pytest.approx(out["n_per [1/min]"].iat[0], rel=1e-9)
    assert r.T_op.magnitude > balance().T_op.magnitude  # more friction than the tabulated f0 = 2


FIELDS = ("n_thr", "n_per", "T_op", "nu_op", "Q_S", "Q_L", "NR")


def assert_point_by_point(whole, points):
    for i, point in enumerate(points):
        for name in FIELDS:
            assert getattr(whole, name).magnitude[i] == pytest.approx(getattr(point, name).magnitude, rel=1e-12,
                                                                     nan_ok=True), (name, i)
        assert (whole.status[i], whole.messages[i]) == (point.status[0], point.messages[0])


def test_an_array_of_speeds_gives_the_scalar_calls_point_by_point():
    speeds = [1500.0, 3000.0, 4500.0]
    whole = balance(model="skf", model_inputs=BATH, n=speeds * u.rpm)
    assert whole.T_op.magnitude.shape == (3,) and whole.status == ["ok"] * 3
    assert_point_by_point(whole, [balance(model="skf", model_inputs=BATH, n=n * u.rpm) for n in speeds])


def test_array_model_inputs_numbers_and_text_give_the_scalar_calls_point_by_point():
    levels, editions = [2.5, 5.0, 2.5], ["10000", "10000", "6000"]
    whole = balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": levels * u.mm, "skf_edition": editions})
    assert_point_by_point(whole, [balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": level * u.mm,
                                                                    "skf_edition": edition})
                                  for level, edition in zip(levels, editions)])
    assert len(set(whole.T_op.magnitude.tolist())) == 3  # each point its own level and drag formula


def test_model_inputs_series_are_paired_by_their_index():
    n = pd.Series([3000.0, 1500.0], index=["a", "b"], dtype="pint[rpm]")
    H = pd.Series([2.5, 5.0], index=["a", "b"], dtype="pint[mm]")
    r = balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": H}, n=n)
    assert r.T_op.index.tolist() == ["a", "b"]
    assert r.T_op.pint.magnitude.tolist() == pytest.approx(
        [balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": 2.5 * u.mm}).T_op.magnitude,
         balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": 5 * u.mm}, n=1500 * u.rpm).T_op.magnitude],
        rel=1e-12)
    with pytest.raises(HeatBalanceError) as info:
        balance(model="skf", model_inputs={"VM": 3e-5, "oil_level": H[["b", "a"]]}, n=n)
    assert str(info.value) == ("n and oil_level are Series with different indexes (2 rows: 'a', 'b' against 2 rows: "
                               "'b', 'a'); give them one index, e.g. oil_level.reindex(n.index), or pass arrays")


@pytest.mark.parametrize("overrides, error, message", [
    (dict(model="palmgren"), ModelError, "model: 'palmgren' is not one of schaeffler, skf"),
    (dict(model="skf", model_inputs=dict(BATH, oil_lvl=3 * u.mm)), HeatBalanceError,
     "model_inputs: 'oil_lvl' is not an input of this model; it reads oil, mu_sl, mu_bl, oil_level, VM, skf_edition, "
     "seal, seals, d_s, C, Y, Dw"),
    (dict(model_inputs=BATH), HeatBalanceError,  # the catalogue model reads no oil level
     "model_inputs: 'oil_level' is not an input of this model; it reads Y, e, X0, Y0, alpha, f0, f1, C"),
    (dict(model="skf", model_inputs=dict(BATH, T=16.25 * u.mm)), HeatBalanceError,
     "model_inputs: 'T' is an argument of heat_balance; give it as T="),
    (dict(model="skf", model_inputs=dict(BATH, designation="6206")), HeatBalanceError,
     "model_inputs: 'designation' is an argument of heat_balance; give it as designation="),
    (dict(model="skf", model_inputs=dict(BATH, type="deep_groove_ball")), HeatBalanceError,
     "model_inputs: 'type' is an argument of heat_balance; give it as bearing_type="),
    (dict(model="skf", model_inputs=dict(BATH, arrangement="paired")), HeatBalanceError,
     "model_inputs: 'arrangement' is an argument of heat_balance; give it as arrangement="),
    (dict(model="skf", model_inputs=dict(BATH, Fr=1 * u.kN)), HeatBalanceError,
     "model_inputs: 'Fr' is an argument of heat_balance; give it as Fr="),
    (dict(model="skf", model_inputs=dict(BATH, oil_level=2.5 * u.s)), UnitError,
     "oil_level: 2.5 second cannot be converted to mm (dimension [time], expected [length])"),
    (dict(model="skf", model_inputs=dict(BATH, oil_level=2.5)), UnitError,
     "oil_level: expected a pint Quantity in mm (for example 2.5 * ureg('mm')); got a plain float 2.5"),
    (dict(model="skf", model_inputs=dict(BATH, mu_sl="abc")), HeatBalanceError, "mu_sl: 'abc' is not a number"),
    (dict(model="skf", model_inputs=dict(BATH, VM=[3e-5, "x"])), HeatBalanceError,
     "VM: 'x' is not a number (at index 1)"),
    (dict(model="skf", model_inputs=dict(BATH, oil_level=[2.5, 5.0] * u.mm), n=[1500.0, 3000.0, 4500.0] * u.rpm),
     HeatBalanceError, "n has shape (3,) and oil_level has shape (2,): arrays are paired value by value, so they "
                       "need one shape (or give single values)"),
    (dict(arrangement="tandem"), HeatBalanceError, "arrangement: 'tandem' is not one of single, paired"),
])
def test_bad_model_arguments_are_refused_naming_them(overrides, error, message):
    with pytest.raises(error) as info:
        balance(**overrides)
    assert str(info.value) == message


def test_a_model_input_the_model_refuses_is_that_point_s_error():
    # as every point heat_balance cannot compute: NaN and status 'error', not a raise (friction_torque raises)
    r = balance(model="skf", model_inputs=dict(BATH, VM=[3e-5, -1e-5]))
    assert r.status == ["ok", "error"] and r.messages == ["", "VM: -1e-05 must be >= 0"]
    assert not np.isnan(r.T_op.magnitude[0]) and np.isnan(r.T_op.magnitude[1]) and np.isnan(r.NR.magnitude[1])


def test_friction_torque_refuses_the_same_names_naming_itself():
    args = dict(d=25 * u.mm, D=52 * u.mm, n=3000 * u.rpm, nu=20 * NU, Fr=2 * u.kN, lubrication="oil_bath",
                model="skf")
    with pytest.raises(FrictionInputError) as info:
        bh.friction_torque("6205", **args, model_inputs=dict(BATH, Fr=1 * u.kN))
    # (before, a number argument given in model_inputs was left out without a word)
    assert str(info.value) == "model_inputs: 'Fr' is an argument of friction_torque; give it as Fr="
    with pytest.raises(FrictionInputError) as info:
        bh.friction_torque("6205", **args, model_inputs=dict(BATH, oil_lvl=3 * u.mm))
    assert str(info.value) == ("model_inputs: 'oil_lvl' is not an input of this model; it reads oil, mu_sl, mu_bl, "
                               "oil_level, VM, skf_edition, seal, seals, d_s, C, Dw, T")
    with pytest.raises(FrictionInputError) as info:
        bh.friction_torque("6205", **{**args, "model": "schaeffler"}, model_inputs={"oil_level": 2.5 * u.mm})
    # (C, the basic dynamic load rating of the minimum load: every other input of the model is an argument)
    assert str(info.value) == "model_inputs: 'oil_level' is not an input of this model; it reads C"
    with pytest.raises(ModelError) as info:
        bh.friction_torque("6205", **{**args, "model": "palmgren"})
    assert str(info.value) == "model: 'palmgren' is not one of schaeffler, skf"
