"""The unit-aware heat balance (issue 3): n_thr, n_per, operating temperature, sign convention, refusals."""
from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pint
import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
import pytest
from scipy.optimize import brentq

from bearingheat.api.thermal import heat_balance, thermal_reference_speed
from bearingheat.calc.models import compute_supports
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import F2ChartError, HeatBalanceError, UnitError
from bearingheat.kernels.viscosity import viscosity_from_two_points
from thermal_helpers import nj208_chart, nj208_roots

u = pint.get_application_registry()


def test_thermal_reference_speed_quantity_api_and_unit_invariance():
    a = thermal_reference_speed("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN)
    b = thermal_reference_speed("6205", d=2.5 * u.cm, D=0.052 * u.m, B=15 * u.mm, C0=7800 * u.N)
    assert a.units == u("1/min").units
    assert a.magnitude == pytest.approx(b.magnitude, rel=1e-12)
    arr = thermal_reference_speed("6205", d=25 * u.mm, D=52 * u.mm, B=np.array([15.0, 16.0]) * u.mm,
                                  C0=7.8 * u.kN)
    assert arr.magnitude[0] == pytest.approx(a.magnitude, rel=1e-12)
    assert arr.magnitude[1] > arr.magnitude[0]  # wider seat carries away more heat


def test_thermal_reference_speed_error_message():
    with pytest.raises(HeatBalanceError) as exc:
        thermal_reference_speed("51105", d=25 * u.mm, D=42 * u.mm, C0=28.5 * u.kN)
    assert str(exc.value) == ("51105: n_thr: the thermal method (ISO 15312, DIN 732) does not apply to thrust "
                              "ball bearings")


def base_case(**overrides):
    args = dict(d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm, Fr=2 * u.kN,
                nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"),
                T_bearing=u.Quantity(70, "degC"))
    args.update(overrides)
    return heat_balance("6205", **args)


def test_heat_balance_holds_at_the_operating_temperature():
    r = base_case()
    assert r.status == ["ok"]
    T_op = r.T_op.to("degC").magnitude
    A_r = math.pi * 15 * 77
    Q_S = 0.016 / 50 * A_r * (T_op - 20.0)
    nu = viscosity_from_two_points(68, 40, 8.6, 100, T_op)
    assert r.nu_op.to("mm^2/s").magnitude == pytest.approx(nu, rel=1e-10)
    frame = pd.DataFrame({"designation": ["6205"], "d": [25.0], "D": [52.0], "C0": [7800.0], "n": [3000.0],
                          "Fr": [2000.0], "nu": [nu], "lubrication": ["oil_bath"]})
    MR = compute_supports(frame)["MR"].iloc[0]
    assert math.pi * 3000 / 30 * 1e-3 * MR == pytest.approx(Q_S, rel=1e-9)


def test_sign_convention_external_heat_flows_into_the_bearing():
    cold = base_case()
    hot = base_case(Q_E=10 * u.W)      # Q_E > 0: heat INTO the bearing
    cooled = base_case(Q_E=-10 * u.W)  # Q_E < 0: extra cooling
    assert hot.T_op.magnitude > cold.T_op.magnitude > cooled.T_op.magnitude
    assert hot.n_per.magnitude < cold.n_per.magnitude < cooled.n_per.magnitude


def test_sign_convention_at_the_permissible_speed():
    # n_per is the speed at which N_R = Q_S + Q_L - Q_E at T_bearing
    r = base_case(Q_E=10 * u.W, V_oil=0.2 * u("l/min"), dT_oil=5 * u.K)
    n_per = r.n_per.to("1/min").magnitude
    nu70 = viscosity_from_two_points(68, 40, 8.6, 100, 70.0)
    carried = 0.016 / 50 * math.pi * 15 * 77 * 50.0 + 28.6 * 0.2 * 5.0 - 10.0
    frame = pd.DataFrame({"designation": ["6205"], "d": [25.0], "D": [52.0], "C0": [7800.0], "n": [n_per],
                          "Fr": [2000.0], "nu": [nu70], "lubrication": ["oil_bath"]})
    MR = compute_supports(frame)["MR"].iloc[0]
    assert math.pi * n_per / 30 * 1e-3 * MR == pytest.approx(carried, rel=1e-10)
    assert r.Q_L.to("W").magnitude == pytest.approx(28.6 * 0.2 * 5.0)


def test_external_heat_above_what_is_carried_away():
    r = base_case(Q_E=100 * u.W)
    assert math.isnan(r.n_per.magnitude)
    assert r.status == ["warning"]
    assert ("n_per: the external heat Q_E = 100 W is not less than the heat carried away 58.06 W at T_bearing; "
            "no speed is permissible") in r.messages[0]


ABOVE = ("T_op: no equilibrium up to 150 degC, the upper end of the search: the friction heat still exceeds the "
         "heat carried away there; with the catalogue model the friction heat stays bounded as the temperature rises "
         "while the heat carried away grows with it, so an equilibrium lies above; T_op is not computed")


def test_no_equilibrium_below_the_search_limit_is_not_called_a_runaway():
    """The catalogue model's friction heat falls as the oil thins while the heat carried away grows: a 6205 at
    15000 1/min in 140 degC air settles at 201.5 degC, above the search (it was reported as 'the temperature runs
    away')."""
    r = base_case(n=15000 * u.rpm, T_amb=u.Quantity(140, "degC"), T_bearing=u.Quantity(160, "degC"))
    assert math.isnan(r.T_op.magnitude)
    assert r.messages[0] == ABOVE
    # by hand: M0 = f0 (nu n)^(2/3) dM^3 1e-7 with f0 = 2, M1 = 0.0009 (Fr/C0)^0.5 Fr dM (the Schaeffler catalogue),
    # Q_S = q_r/50 K A_r (T - T_amb)
    dM, M1 = 38.5, 0.0009 * (2 / 7.8) ** 0.5 * 2000 * 38.5

    def balance(T):
        nu = viscosity_from_two_points(68, 40, 8.6, 100, T)
        return math.pi * 15000 / 30e3 * (2 * (nu * 15000) ** (2 / 3) * dM ** 3 * 1e-7 + M1) \
            - 0.016 / 50 * math.pi * 15 * (52 + 25) * (T - 140)

    assert balance(150) > 0 and round(brentq(balance, 150, 400), 1) == 201.5


def test_temperature_units_are_invariant():
    a = base_case()
    b = base_case(T_amb=u.Quantity(293.15, "K"), T_bearing=u.Quantity(158, "degF"), n=50 * u.Hz)
    assert a.T_op.to("degC").magnitude == pytest.approx(b.T_op.to("degC").magnitude, rel=1e-9)
    assert a.n_per.magnitude == pytest.approx(b.n_per.magnitude, rel=1e-9)


def test_array_of_speeds_matches_scalar_calls():
    speeds = np.array([1000.0, 3000.0, 6000.0])
    arr = base_case(n=speeds * u.rpm)
    for i, n in enumerate(speeds):
        one = base_case(n=n * u.rpm)
        assert arr.T_op.magnitude[i] == pytest.approx(one.T_op.magnitude, rel=1e-12)
    assert np.all(np.diff(arr.T_op.magnitude) > 0)  # faster runs hotter


def test_viscosity_at_operating_temperature_option():
    at_bearing = base_case(viscosity_at="bearing")
    at_operating = base_case(viscosity_at="operating")
    # the bearing settles at about 40 degC < 70 degC: thicker oil, more friction at the operating state;
    # n_per is the speed at which the bearing reaches T_bearing, so its oil has the viscosity of T_bearing either way
    assert at_operating.NR.magnitude > at_bearing.NR.magnitude
    assert at_operating.n_per.magnitude == at_bearing.n_per.magnitude
    with pytest.raises(ValueError, match=re.escape("viscosity_at: 'oil' is not one of auto, bearing, operating")):
        base_case(viscosity_at="oil")


def test_limiting_speed_caps_n_per_with_a_warning():
    r = base_case(n_G=5000 * u("1/min"))
    assert r.n_per.to("1/min").magnitude == 5000.0
    assert r.status == ["warning"]
    assert "n_per: the thermal value 8053.4 1/min is above the limiting speed n_G = 5000 1/min; n_per = n_G" \
        in r.messages[0]


def test_a_sealed_bearing_of_the_table_gets_its_values_but_no_thermal_speeds():
    """6205-2RSR from the bearing table (HR 1: 25 x 52 x 15, C0 7800 N, n_B '–'): the friction is computed with
    them; n_thr, n_per and T_op are not, and the message says why. By hand: dM = 38.5 mm, nu*n = 60000,
    M0 = 2*60000^(2/3)*38.5^3*1e-7 = 17.492, f1 = 0.0009*sqrt(2000/7800) = 4.5573e-4,
    M1 = f1*2000*38.5 = 35.091, MR = 52.584 N*mm, NR = MR*pi*3000/30*1e-3 = 16.520 W."""
    sealed = heat_balance("6205-2RSR", n=3000 * u.rpm, Fr=2 * u.kN, nu=20 * u("mm^2/s"), lubrication="oil_bath",
                          T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    assert sealed.NR.to("W").magnitude == pytest.approx(16.520, abs=5e-4)
    assert all(math.isnan(q.magnitude) for q in (sealed.n_thr, sealed.n_per, sealed.T_op))
    assert sealed.status == ["warning"]
    assert sealed.messages == [
        "contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, lists "
        "seal friction among the components; its formulas have no term for it); n_thr: the thermal method (ISO "
        "15312, DIN 732) does not apply to bearings with contact seals: its reference conditions have no seal "
        "friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, whose heat balance would leave "
        "the seal friction out, are not computed either"]


def test_method_does_not_apply_to_contact_seals_and_thrust_ball_bearings():
    sealed = heat_balance("6205-2RSR", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
                          Fr=2 * u.kN, nu=20 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"),
                          T_bearing=u.Quantity(70, "degC"))
    assert math.isnan(sealed.n_per.magnitude) and math.isnan(sealed.T_op.magnitude)
    assert ("n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals"
            in sealed.messages[0])
    thrust = heat_balance("51105", d=25 * u.mm, D=42 * u.mm, B=11 * u.mm, C0=28.5 * u.kN, n=1000 * u.rpm,
                          Fa=1 * u.kN, nu=20 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"),
                          T_bearing=u.Quantity(70, "degC"))
    assert math.isnan(thrust.n_per.magnitude)
    assert "does not apply to thrust ball bearings" in thrust.messages[0]


def test_approximation_method_close_to_exact():
    exact = base_case()
    approx = base_case(method="approximation")
    assert approx.n_per.magnitude == pytest.approx(exact.n_per.magnitude, rel=0.03)
    with pytest.raises(ValueError, match=re.escape("method: 'closed' is not one of exact, approximation")):
        base_case(method="closed")


def test_heat_balance_and_reference_speed_refuse_series_of_different_indexes():
    args = dict(nu=40 * u("mm^2/s"), lubrication="oil_bath", T_amb=u.Quantity(20, "degC"),
                T_bearing=u.Quantity(70, "degC"))
    n = pd.Series([1000.0, 3000.0], index=["a", "b"], dtype="pint[rpm]")
    Fr = pd.Series([8.0, 1.0], index=["b", "a"], dtype="pint[kN]")
    message = ("n and Fr are Series with different indexes (2 rows: 'a', 'b' against 2 rows: 'b', 'a'); give them "
               "one index, e.g. Fr.reindex(n.index), or pass arrays")
    with pytest.raises(HeatBalanceError, match=f"^{re.escape(message)}$"):
        heat_balance("6208", n=n, Fr=Fr, **args)
    aligned = heat_balance("6208", n=n, Fr=Fr.reindex(n.index), **args)
    by_label = [heat_balance("6208", n=s * u.rpm, Fr=f * u.kN, **args).T_op.to("degC").magnitude
                for s, f in ((1000, 1.0), (3000, 8.0))]
    np.testing.assert_allclose(aligned.T_op.pint.to("degC").pint.magnitude.to_numpy(dtype=float), by_label,
                               rtol=1e-12)
    d = pd.Series([40.0, 50.0], index=[0, 1], dtype="pint[mm]")
    D = pd.Series([80.0, 90.0], index=[1, 0], dtype="pint[mm]")
    with pytest.raises(HeatBalanceError, match="^d and D are Series with different indexes"):
        thermal_reference_speed("6208", d=d, D=D, B=18 * u.mm, C0=18 * u.kN)
    speeds = thermal_reference_speed("6208", d=d, D=D.reindex(d.index), B=18 * u.mm, C0=18 * u.kN)
    assert isinstance(speeds, pd.Series) and list(speeds.index) == [0, 1]
    single = thermal_reference_speed("6208", d=40 * u.mm, D=90 * u.mm, B=18 * u.mm, C0=18 * u.kN)
    assert speeds.pint.to("1/min").pint.magnitude[0] == pytest.approx(single.to("1/min").magnitude, rel=1e-15)


def test_a_point_with_oil_data_but_no_temperature_to_take_it_at_is_an_error_not_a_raise():
    """Good oil data and viscosity_at 'bearing' without T_bearing: the point is in error with the reason, as calc's
    row is; only oil data that fix no line at all raise (they leave the call nothing to compute)."""
    r = base_case(T_bearing=None, viscosity_at="bearing")
    assert r.status == ["error"]
    assert r.messages == ["T_bearing [degC]: missing; the viscosity is to be taken at the bearing temperature"]


@pytest.mark.parametrize("oil, message", [
    (dict(iso_vg=47), "iso_vg: 47 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, "
                      "150, 220, 320, 460, 680, 1000, 1500, 2200, 3200"),
    (dict(iso_vg=5), "VI: 95 cannot be reached by ISO VG 5 with nu100 >= 2 mm^2/s (ASTM D2270)"),
    (dict(nu40=5 * u("mm^2/s"), nu100=8 * u("mm^2/s")), "nu40 [mm^2/s]: 5 must be larger than nu100 = 8"),
    (dict(nu40=68 * u("mm^2/s")), "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line "
                                  "(ASTM D341)"),
    (dict(VI=120), "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"),
    (dict(iso_vg=np.array([47.0, 47.0])), "iso_vg: 47 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, "
                                          "22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200 "
                                          "(at index 0)"),
])
def test_unusable_oil_data_is_named_not_called_missing(oil, message):
    """The reason calc gives for the row (beside a row whose oil is usable), not 'nu: missing; give nu, or nu40 and
    nu100, or iso_vg'."""
    with pytest.raises(HeatBalanceError) as exc:
        base_case(**{"nu40": None, "nu100": None, **oil})
    assert str(exc.value) == message
    if np.ndim(oil.get("iso_vg", 0)) == 0:
        from bearingheat.calc.table import calc
        cells = {"iso_vg": oil.get("iso_vg"), "VI": oil.get("VI"), "nu40 [mm^2/s]": oil.get("nu40"),
                 "nu100 [mm^2/s]": oil.get("nu100")}
        bad = {"designation": "6205", "C0 [kN]": 7.8, "n [rpm]": 3000, "Fr [kN]": 2, "T_amb [degC]": 20,
               "lubrication": "oil_bath", **{k: getattr(v, "magnitude", v) for k, v in cells.items() if v is not None}}
        good = {**{k: v for k, v in bad.items() if k not in cells}, "iso_vg": 68}
        out = calc(pd.DataFrame([bad, good]))
        assert out["status"].tolist() == ["error", "ok"] and out["message"].iat[0] == message


def test_a_row_in_error_gets_no_heat_balance_messages():
    """k_q <= 0 is an error; the balance's messages would only follow from it (they said 'the temperature runs
    away' and 'Q_E = 0 W is not less than the heat carried away -181.4 W')."""
    r = base_case(k_q=-1e-3 * u("W/(mm^2*K)"))
    assert r.status == ["error"]
    assert r.messages[0] == ("k_q: -0.001 is outside the plausible range 2e-05 to 0.01 W/(mm^2*K) (a tenth to ten "
                             "times the 0.2e-3 to 1.0e-3 W/(mm^2*K) of the Schaeffler HR 1 catalogue for seats up "
                             "to 25 000 mm^2; its default q_r/50 K is 3.2e-4); check the number and its unit; "
                             "k_q [W/(mm^2*K)]: -0.001 must be > 0")
    assert np.isnan([r.T_op.magnitude, r.n_per.magnitude, r.Q_S.magnitude]).all()


def test_the_heat_carried_away_is_printed_as_it_is_not_as_a_difference():
    """Q_S + Q_L at T_bearing is 3.2e-4 * pi * 15 * 77 * 50 K = 58.06 W whatever Q_E is (with Q_E = 1e300 it
    came out of (Q_S + Q_L - Q_E) + Q_E as 0 W)."""
    assert round(3.2e-4 * math.pi * 15 * (52 + 25) * 50, 2) == 58.06
    r = base_case(Q_E=1e300 * u.W)
    assert ("n_per: the external heat Q_E = 1e+300 W is not less than the heat carried away 58.06 W at T_bearing; "
            "no speed is permissible") in r.messages[0]


def test_a_warning_of_one_operating_point_is_that_point_s():
    """T_bearing = 250 degC is implausible at index 2 only: the other points stay 'ok' (all three were
    'warning', each with the message of index 2)."""
    r = base_case(n=np.array([3000.0, 3000.0, 3000.0]) * u.rpm, T_bearing=u.Quantity(np.array([70.0, 70.0, 250.0]),
                                                                                        "degC"))
    assert r.status == ["ok", "ok", "warning"]
    assert r.messages[:2] == ["", ""]
    assert r.messages[2].startswith("T_bearing: 250 is outside the plausible range -60 to 200 degC; check the number "
                                    "and its unit; n_per: ")
    # a single implausible value concerns every point
    every = base_case(n=np.array([1000.0, 3000.0]) * u.rpm, k_q=1 * u("W/(mm^2*K)"))
    assert every.status == ["warning", "warning"]
    assert all(m.startswith("k_q: 1 is outside the plausible range 2e-05 to 0.01 W/(mm^2*K)") for m in every.messages)


def test_arrays_that_do_not_pair_point_by_point_are_named():
    """numpy's bare 'shape mismatch: objects cannot be broadcast to a single shape' named no argument."""
    with pytest.raises(HeatBalanceError) as exc:
        base_case(n=np.array([1000.0, 2000.0]) * u.rpm, Fr=np.array([1.0, 2.0, 3.0]) * u.kN)
    assert str(exc.value) == ("n has shape (2,) and Fr has shape (3,): arrays are paired value by value, so they "
                              "need one shape (or give single values)")
    with pytest.raises(HeatBalanceError) as exc:
        thermal_reference_speed("6205", d=25 * u.mm, D=np.array([52.0, 62.0]) * u.mm, C0=np.ones(3) * u.kN,
                                B=15 * u.mm)
    assert str(exc.value) == ("D has shape (2,) and C0 has shape (3,): arrays are paired value by value, so they "
                              "need one shape (or give single values)")


def test_a_thrust_bearing_gets_its_n_thr_without_an_ambient_temperature():
    """n_thr is a field of every result: a thrust bearing's needs d and D only (by hand in tests/calc)."""
    r = heat_balance("81212", d=60 * u.mm, D=95 * u.mm, C0=200 * u.kN, n=1000 * u.rpm, Fa=5 * u.kN,
                     nu=24 * u("mm^2/s"))
    assert r.status == ["ok"]
    assert r.n_thr.magnitude == pytest.approx(
        thermal_reference_speed("81212", d=60 * u.mm, D=95 * u.mm, C0=200 * u.kN).magnitude, rel=1e-12)
    assert round(r.n_thr.magnitude) == 2414


def test_no_equilibrium_is_a_warning_unless_nu_was_to_come_from_it():
    """As the docstring says: T_op NaN and 'warning' with a given nu or a T_bearing to take nu at; 'error' only
    where nu was to be taken at T_op (the 6205 at 15000 1/min in 140 degC air settles above the search)."""
    hot = dict(n=15000 * u.rpm, T_amb=u.Quantity(140, "degC"))
    given = base_case(**hot, nu=12 * u("mm^2/s"), nu40=None, nu100=None, T_bearing=None)
    fallback = base_case(**hot, T_bearing=u.Quantity(160, "degC"))
    nothing = base_case(**hot, T_bearing=None)
    assert (given.status, fallback.status, nothing.status) == (["warning"], ["warning"], ["error"])
    assert np.isnan([given.T_op.magnitude, fallback.T_op.magnitude, nothing.T_op.magnitude]).all()
    assert nothing.messages[0].startswith("nu [mm^2/s]: cannot be taken at T_op; no equilibrium up to 150 degC")


# --- axially loaded cylindrical roller bearings: M2 = f2*Fa*dM (the Schaeffler catalogue, pp. 69-70) ---------------

def _nj208(**overrides):
    """NJ208-E in an oil bath at 1000 1/min, Fr = 6 kN, Fa = 2 kN (dM = 60 mm, f0 = 2, f1 = 0.0003, kB = 15)."""
    arguments = dict(d=40 * u.mm, D=80 * u.mm, B=18 * u.mm, C0=53 * u.kN, n=1000 * u.rpm, Fr=6 * u.kN, Fa=2 * u.kN,
                     nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"),
                     T_bearing=u.Quantity(70, "degC"))
    return heat_balance("NJ208-E", **{**arguments, **overrides})


def test_a_given_f2_holds_m2_at_every_speed_and_temperature():
    r = _nj208(f2=0.005)
    n_per, T_op = nj208_roots(lambda nu_n: 0.005 * 2000 * 60.0)  # M2 = f2*Fa*dM = 600 N*mm
    assert r.status == ["ok"]
    assert r.n_per.to("1/min").magnitude == pytest.approx(n_per, rel=1e-9)
    assert r.T_op.to("degC").magnitude == pytest.approx(T_op, rel=1e-9)
    # a dimensionless Quantity is converted: 0.5 % is 0.005
    assert _nj208(f2=0.5 * u.percent).n_per.magnitude == pytest.approx(n_per, rel=1e-9)


def test_f2_off_a_chart_follows_each_root_as_calc_does(tmp_path):
    chart = nj208_chart(tmp_path)
    n_per, T_op = nj208_roots()  # M2 with f2 off the chart at each trial speed and temperature
    assert (round(n_per), round(T_op, 2)) == (1471, 52.59)
    for given in (str(chart), F2Chart.from_csv(chart)):
        r = _nj208(f2_chart=given)
        assert r.status == ["ok"]
        assert r.n_per.to("1/min").magnitude == pytest.approx(n_per, rel=1e-9)
        assert r.T_op.to("degC").magnitude == pytest.approx(T_op, rel=1e-9)


def test_without_f2_the_axially_loaded_point_says_what_to_give():
    r = _nj208()
    assert r.status == ["error"] and math.isnan(r.n_per.magnitude) and math.isnan(r.T_op.magnitude)
    assert r.messages == [
        "f2: missing; cylindrical roller bearing with cage series 2 carries Fa, so M2 = f2*Fa*dM needs f2: give f2, "
        "or a digitised f2 chart (f2_chart; --f2-chart on the command line); read it at Fa/A = 24.59, "
        "nu*n*dM = 1.198e+06 mm^3/(s*min) (the Schaeffler catalogue, p. 70, figs. 3 and 4)"]


@pytest.mark.parametrize("overrides, error, message", [
    (dict(f2="low"), HeatBalanceError, "f2: 'low' is not a number"),
    (dict(f2=[0.005, "x"]), HeatBalanceError, "f2: 'x' is not a number (at index 1)"),
    (dict(f2=2 * u.mm), UnitError, "f2: 2 millimeter cannot be converted to dimensionless (dimension [length], "
                                   "expected dimensionless)"),
    (dict(f2_chart="/no/such/chart.csv"), F2ChartError,
     "/no/such/chart.csv: cannot read the f2 chart (No such file or directory)"),
    (dict(iso_vg="VG68", nu40=None, nu100=None), HeatBalanceError, "iso_vg: 'VG68' is not a number"),
    (dict(iso_vg=50 * u.percent, nu40=None, nu100=None), HeatBalanceError,
     "iso_vg: 0.5 is outside the valid range 1 to 10000"),
])
def test_bad_dimensionless_arguments_are_named(overrides, error, message):
    with pytest.raises(error) as exc:
        _nj208(**overrides)
    assert str(exc.value) == message


def test_a_negative_f2_is_the_point_s_error():
    r = _nj208(f2=np.array([0.005, -0.1]))
    assert r.status == ["ok", "error"] and r.messages[1] == "f2: -0.1 must be >= 0"
