"""Heat balance (issue 3): n_θr, n_per, operating temperature, sign convention, refusals."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pint
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from bearingheat import thermal
from bearingheat.tables_io import load_table, table_units
from bearingheat.thermal import (
    HeatBalanceError,
    balance_speed,
    default_heat_transfer_coefficient,
    heat_balance,
    heat_flow_area,
    oil_heat_flow,
    permissible_speed_factor,
    reference_conditions,
    reference_heat_flux_density,
    seat_heat_flow,
    speed_factor_catalogue_approximation,
    speed_factor_coefficients,
    speed_factor_exact,
    thermal_reference_speed,
    thermal_reference_speed_details,
    thermal_reference_speed_rows,
)

u = pint.get_application_registry()
HR1 = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "hr1_2006_reference_speeds.csv"

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


# ---- reference conditions table -------------------------------------------------------------------

def test_reference_conditions_table_reads_back():
    table = load_table("thermal_reference_conditions")
    rows = table.drop(columns="source").to_dict("records")
    assert rows == [
        {"kind": "radial", "load_ratio": 0.05, "nu_ref": 12.0, "q_r": 0.016, "A_r_limit": 50000.0,
         "q_r_exponent": -0.34, "T_ambient": 20.0, "T_bearing": 70.0},
        {"kind": "thrust", "load_ratio": 0.02, "nu_ref": 24.0, "q_r": 0.020, "A_r_limit": 50000.0,
         "q_r_exponent": -0.16, "T_ambient": 20.0, "T_bearing": 70.0},
    ]
    assert table_units("thermal_reference_conditions")["q_r"] == "W/mm^2"
    assert all("issue 3" in s for s in table["source"])


def test_reference_conditions_tapered_uses_radial_and_bad_kind():
    assert reference_conditions("tapered") == reference_conditions("radial")
    with pytest.raises(ValueError, match=re.escape("kind: 'axial' is not one of radial, tapered, thrust")):
        reference_conditions("axial")


# ---- heat flow area and heat carried away ------------------------------------------------------

def test_heat_flow_area_formulas():
    assert heat_flow_area("radial", 25, 52, B=15) == pytest.approx(math.pi * 15 * 77)
    assert heat_flow_area("tapered", 25, 52, T=16.25) == pytest.approx(math.pi * 16.25 * 77)
    assert heat_flow_area("thrust", 25, 42) == pytest.approx(math.pi / 2 * (42 ** 2 - 25 ** 2))


def test_heat_flux_density_branches_meet_at_the_limit():
    for kind, q in (("radial", 0.016), ("thrust", 0.020)):
        assert reference_heat_flux_density(kind, 50000.0) == q
        assert reference_heat_flux_density(kind, 50000.0 * (1 + 1e-12)) == pytest.approx(q, rel=1e-9)
    assert reference_heat_flux_density("radial", 100000.0) == pytest.approx(0.016 * 2 ** -0.34, rel=1e-12)
    assert reference_heat_flux_density("thrust", 100000.0) == pytest.approx(0.020 * 2 ** -0.16, rel=1e-12)


def test_default_k_q_inside_catalogue_range():
    k_q = default_heat_transfer_coefficient("radial", 20000.0)  # W/(mm^2 K)
    assert k_q == pytest.approx(0.016 / 50)
    assert 0.2e-3 <= k_q <= 1.0e-3  # catalogue 0.2..1.0e-6 kW/(mm^2 K) for seats up to 25 000 mm^2


def test_seat_and_oil_heat_flows():
    assert seat_heat_flow(3.2e-4, 3628.5, 50.0) == pytest.approx(58.056)
    assert oil_heat_flow(2.0, 5.0) == pytest.approx(0.0286e3 * 2.0 * 5.0)


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
            return thermal.friction_heat(row["f0"], 12.0, n, dM, row["M1"]) - target

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
        "a": "n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals",
        "b": "n_thr: the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings",
        "c": "designation: 'bogus' matches no row of the seed 002 tables; give type and series explicitly instead",
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
    power = thermal.friction_heat(row["f0"], 24.0, row["n_thr"], dM, row["M1"])
    assert power == pytest.approx(0.020 * row["A_r"], rel=1e-12)


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


# ---- speed factor f_n ------------------------------------------------------------------------------

def test_speed_factor_exact_matches_brentq():
    rng = np.random.default_rng(5)
    k_L = 10 ** rng.uniform(-3, 2, 200)
    k_P = 10 ** rng.uniform(-3, 2, 200)
    f_n = speed_factor_exact(k_L, k_P)
    for kl, kp, f in zip(k_L, k_P, f_n):
        root = brentq(lambda x: kl * x ** (5 / 3) + kp * x - 1.0, 1e-9, 1e9, xtol=1e-15, rtol=1e-14)
        assert f == pytest.approx(root, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-4, 1e3), st.floats(1e-4, 1e3))
def test_speed_factor_exact_satisfies_the_equation(k_L, k_P):
    f = speed_factor_exact(k_L, k_P)
    assert k_L * f ** (5 / 3) + k_P * f == pytest.approx(1.0, rel=1e-13)


def test_speed_factor_exact_edge_cases():
    assert speed_factor_exact(0.0, 0.5) == pytest.approx(2.0, rel=1e-15)
    assert speed_factor_exact(1.0, 0.0) == pytest.approx(1.0, rel=1e-15)
    assert speed_factor_exact(0.0, 0.0) == math.inf
    assert math.isnan(speed_factor_exact(-1.0, 0.5))


def test_speed_factor_scalar_array_series_agree():
    k_L = pd.Series([0.2, 0.9, 3.0], index=["x", "y", "z"])
    k_P = pd.Series([0.1, 0.05, 2.0], index=["x", "y", "z"])
    series = speed_factor_exact(k_L, k_P)
    array = speed_factor_exact(k_L.to_numpy(), k_P.to_numpy())
    scalars = [speed_factor_exact(a, b) for a, b in zip(k_L, k_P)]
    assert series.index.equals(k_L.index)
    np.testing.assert_array_equal(series.to_numpy(), array)
    np.testing.assert_array_equal(array, scalars)


def test_catalogue_approximation_against_exact_root():
    grid = np.logspace(-2, 1, 61)
    k_L, k_P = np.meshgrid(grid, grid)
    exact = speed_factor_exact(k_L, k_P)
    approximate = speed_factor_catalogue_approximation(k_L, k_P)
    deviation = np.abs(approximate / exact - 1.0)
    assert deviation.max() < 0.06          # worst corner k_L = 0.01, k_P = 10: 5.7 %
    assert np.percentile(deviation, 95) < 0.021
    assert speed_factor_catalogue_approximation(0.5, 0.5) == pytest.approx(1.0, abs=0.01)


def test_catalogue_approximation_refuses_outside_its_range():
    with pytest.raises(ValueError, match=re.escape(
            "k_P: 12 is outside 0.01 <= k_P <= 10, the range of the catalogue approximation of f_n; "
            "use speed_factor_exact")):
        speed_factor_catalogue_approximation(np.array([0.5, 0.5]), np.array([1.0, 12.0]))


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


def test_n_per_does_not_depend_on_which_n_thr_scales_f_n():
    # n_per = n_thr * f_n(k_L(n_thr), k_P(n_thr)) is the speed where friction heat = Q, whatever n_thr is
    args = dict(f0=2.0, nu=20.0, dM=38.5, load_torque=35.0, Q=58.0)
    n_a = 14416.0 * permissible_speed_factor(14416.0, **args)
    n_b = 14400.0 * permissible_speed_factor(14400.0, **args)
    assert n_a == pytest.approx(n_b, rel=1e-13)
    assert n_a == pytest.approx(balance_speed(**args), rel=1e-13)


def test_low_regime_uses_the_constant_M0():
    # nu*n < 2000: M0 = f0*160*dM^3*1e-7, so (pi n/30) 1e-3 (M0 + M1) = Q is linear in n
    f0, nu, dM, M1, Q = 2.0, 0.2, 100.0, 50.0, 50.0
    M0 = f0 * 160 * dM ** 3 * 1e-7
    n_expected = Q / (math.pi / 30 * 1e-3 * (M0 + M1))
    assert nu * n_expected < 2000
    assert balance_speed(f0, nu, dM, M1, Q) == pytest.approx(n_expected, rel=1e-14)
    n_thr = 5000.0
    assert n_thr * permissible_speed_factor(n_thr, f0, nu, dM, M1, Q) == pytest.approx(n_expected, rel=1e-14)


def test_balance_speed_is_continuous_and_rising_in_the_heat():
    Q = np.linspace(1.0, 500.0, 400)
    n = balance_speed(2.0, 12.0, 38.5, 3.0, Q)
    assert np.all(np.diff(n) > 0)


# ---- operating temperature and sign convention (Python API) ----------------------------------------

def base_case(**overrides):
    args = dict(d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm, Fr=2 * u.kN,
                nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"), T_ambient=u.Quantity(20, "degC"),
                T_bearing=u.Quantity(70, "degC"))
    args.update(overrides)
    return heat_balance("6205", **args)


def test_heat_balance_holds_at_the_operating_temperature():
    r = base_case()
    assert r.status == ["ok"]
    T_op = r.T_op.to("degC").magnitude
    A_r = math.pi * 15 * 77
    Q_S = 0.016 / 50 * A_r * (T_op - 20.0)
    from bearingheat.viscosity import viscosity_from_two_points
    nu = viscosity_from_two_points(68, 40, 8.6, 100, T_op)
    assert r.nu_op.to("mm^2/s").magnitude == pytest.approx(nu, rel=1e-10)
    from bearingheat.model import compute_supports
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
    from bearingheat.viscosity import viscosity_from_two_points
    nu70 = viscosity_from_two_points(68, 40, 8.6, 100, 70.0)
    carried = 0.016 / 50 * math.pi * 15 * 77 * 50.0 + 28.6 * 0.2 * 5.0 - 10.0
    frame = pd.DataFrame({"designation": ["6205"], "d": [25.0], "D": [52.0], "C0": [7800.0], "n": [n_per],
                          "Fr": [2000.0], "nu": [nu70], "lubrication": ["oil_bath"]})
    from bearingheat.model import compute_supports
    MR = compute_supports(frame)["MR"].iloc[0]
    assert math.pi * n_per / 30 * 1e-3 * MR == pytest.approx(carried, rel=1e-10)
    assert r.Q_L.to("W").magnitude == pytest.approx(28.6 * 0.2 * 5.0)


def test_external_heat_above_what_is_carried_away():
    r = base_case(Q_E=100 * u.W)
    assert math.isnan(r.n_per.magnitude)
    assert r.status == ["warning"]
    assert ("n_per: the external heat Q_E = 100 W is not less than the heat carried away 58.06 W at T_bearing; "
            "no speed is permissible") in r.messages[0]


def test_runaway_is_reported():
    r = base_case(n=20000 * u.rpm, k_q=2e-5 * u("W/(mm^2*K)"))
    assert math.isnan(r.T_op.magnitude)
    assert r.messages[0].endswith("T_op: no equilibrium below 150 degC: the friction heat exceeds the heat carried "
                                  "away (the temperature runs away)")


def test_temperature_units_are_invariant():
    a = base_case()
    b = base_case(T_ambient=u.Quantity(293.15, "K"), T_bearing=u.Quantity(158, "degF"), n=50 * u.Hz)
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
    at_bearing = base_case()
    at_operating = base_case(viscosity_at="operating")
    # the bearing settles at about 40 degC < 70 degC: thicker oil, more friction, lower n_per
    assert at_operating.n_per.magnitude < at_bearing.n_per.magnitude
    with pytest.raises(ValueError, match=re.escape("viscosity_at: 'oil' is not one of auto, bearing, operating")):
        base_case(viscosity_at="oil")


def test_limiting_speed_caps_n_per_with_a_warning():
    r = base_case(n_G=5000 * u("1/min"))
    assert r.n_per.to("1/min").magnitude == 5000.0
    assert r.status == ["warning"]
    assert "n_per: the thermal value 8053.4 1/min is above the limiting speed n_G = 5000 1/min; n_per = n_G" \
        in r.messages[0]


def test_method_does_not_apply_to_contact_seals_and_thrust_ball_bearings():
    sealed = heat_balance("6205-2RSR", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
                          Fr=2 * u.kN, nu=20 * u("mm^2/s"), T_ambient=u.Quantity(20, "degC"),
                          T_bearing=u.Quantity(70, "degC"))
    assert math.isnan(sealed.n_per.magnitude) and math.isnan(sealed.T_op.magnitude)
    assert ("n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals"
            in sealed.messages[0])
    thrust = heat_balance("51105", d=25 * u.mm, D=42 * u.mm, B=11 * u.mm, C0=28.5 * u.kN, n=1000 * u.rpm,
                          Fa=1 * u.kN, nu=20 * u("mm^2/s"), T_ambient=u.Quantity(20, "degC"),
                          T_bearing=u.Quantity(70, "degC"))
    assert math.isnan(thrust.n_per.magnitude)
    assert "does not apply to thrust ball bearings" in thrust.messages[0]


def test_approximation_method_close_to_exact():
    exact = base_case()
    approx = base_case(method="approximation")
    assert approx.n_per.magnitude == pytest.approx(exact.n_per.magnitude, rel=0.03)
    with pytest.raises(ValueError, match=re.escape("method: 'closed' is not one of exact, approximation")):
        base_case(method="closed")


def test_regime_step_with_two_roots_takes_the_lower_speed():
    # the catalogue M0 steps down by 0.79 % at nu*n = 2000; a heat flow between the two sides has two roots
    f0, nu, dM, M1 = 2.0, 1.0, 100.0, 0.0
    n_switch = 2000.0 / nu
    K = math.pi / 30 * 1e-3
    c = f0 * dM ** 3 * 1e-7
    Q = 0.5 * (K * n_switch * c * 160.0 + K * n_switch * c * 2000.0 ** (2 / 3))
    n = balance_speed(f0, nu, dM, M1, Q)
    assert n < n_switch
    assert n == pytest.approx(Q / (K * c * 160.0), rel=1e-14)
