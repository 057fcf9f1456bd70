"""Coast-down analysis (seed 003) and the rolling-bearing spindle form (seed 002)."""
from __future__ import annotations

import math
import pathlib
import re

import numpy as np
import pandas as pd
import pytest
from scipy.integrate import solve_ivp
from scipy.signal import savgol_filter

from bearingheat import coastdown as cd
from bearingheat.units import UnitError, ureg

DATA = pathlib.Path(__file__).resolve().parents[1] / ".." / "shared" / "data"
LIU = DATA / "coastdown_centrifuge_spindown_liu2024_fig6.csv"


def integrate_rundown(torque, I, n0, dt, sigma, seed, fraction=0.95):
    """Reference run-down from solve_ivp (independent of the package's integrator), with noise."""
    def rhs(_, w):
        return [-torque(w[0]) / I]
    stop = lambda _, w: w[0]  # noqa: E731
    stop.terminal = True
    sol = solve_ivp(rhs, (0.0, 1e5), [n0 * math.pi / 30], events=stop, rtol=1e-11, atol=1e-12, dense_output=True)
    t_stop = float(sol.t_events[0][0])
    t = np.arange(0.0, fraction * t_stop, dt)
    n = sol.sol(t)[0] * 30 / math.pi + np.random.default_rng(seed).normal(0.0, sigma, t.size)
    return t, n, t_stop


# ----------------------------------------------------------------- seed 003 formulas by hand
def test_formula2_worked_example_by_hand():
    # TMM-7M: I = 2.6 kg*m^2, G = 1100 N, journal 50 mm; the diagram drops by 100 1/min in 10 s.
    # f = pi*I*dn / (30*G*r*dt) = pi*2.6*100 / (30*1100*0.025*10) = 816.81/8250
    by_hand = math.pi * 2.6 * 100 / (30 * 1100 * 0.025 * 10)
    assert by_hand == pytest.approx(0.099008, abs=5e-7)
    assert cd.reduced_friction_coefficient_seed003_formula2(100.0, 10.0, 2.6, 1100.0, 25.0) == pytest.approx(by_hand)


def test_formula1_is_formula2_for_a_straight_line():
    assert cd.reduced_friction_coefficient_seed003_formula1(-7.5, 2.6, 1100.0, 25.0) == pytest.approx(
        cd.reduced_friction_coefficient_seed003_formula2(75.0, 10.0, 2.6, 1100.0, 25.0))


def test_formula2_scalar_array_series_agree():
    dn = [100.0, 50.0]
    dt = [10.0, 20.0]
    scalar = [cd.reduced_friction_coefficient_seed003_formula2(a, b, 2.6, 1100.0, 25.0) for a, b in zip(dn, dt)]
    array = cd.reduced_friction_coefficient_seed003_formula2(np.array(dn), np.array(dt), 2.6, 1100.0, 25.0)
    series = cd.reduced_friction_coefficient_seed003_formula2(pd.Series(dn, index=["a", "b"]), np.array(dt),
                                                              2.6, 1100.0, 25.0)
    np.testing.assert_allclose(array, scalar)
    assert list(series.index) == ["a", "b"]
    np.testing.assert_allclose(series.to_numpy(), scalar)


def test_interval_table_reproduces_formula2_on_a_straight_line():
    t = np.linspace(0.0, 90.0, 91)
    n = 900.0 - 10.0 * t
    table = cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dn=100.0)
    assert len(table) == 9
    np.testing.assert_allclose(table["dt [s]"], 10.0)
    np.testing.assert_allclose(table["f"], 0.0990078, rtol=1e-6)
    table_dt = cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dt=30.0)
    np.testing.assert_allclose(table_dt["n_from [1/min]"] - table_dt["n_to [1/min]"], 300.0)


# ----------------------------------------------------------------- smoothing and integration
def test_savitzky_golay_matches_scipy_on_uniform_samples():
    t = np.arange(0.0, 60.0, 0.5)
    y = 800.0 - 9.0 * t + 0.05 * t ** 2 + np.random.default_rng(3).normal(0, 2.0, t.size)
    smooth, slope = cd.savitzky_golay_irregular(t, y, 11)
    np.testing.assert_allclose(smooth, savgol_filter(y, 11, 2, mode="interp"), atol=1e-9)
    np.testing.assert_allclose(slope, savgol_filter(y, 11, 2, deriv=1, delta=0.5, mode="interp"), atol=1e-9)


def test_savitzky_golay_exact_on_quadratic_irregular_samples():
    t = np.sort(np.random.default_rng(5).uniform(0, 50, 40))
    smooth, slope = cd.savitzky_golay_irregular(t, 3.0 - 2.0 * t + 0.1 * t ** 2, 7)
    np.testing.assert_allclose(slope, -2.0 + 0.2 * t, atol=1e-8)


def test_savitzky_golay_bad_window_message():
    with pytest.raises(ValueError, match=re.escape(
            "Savitzky-Golay window = 6: expected an odd number of samples between 5 and 20")):
        cd.savitzky_golay_irregular(np.arange(20.0), np.arange(20.0), 6)


@pytest.mark.parametrize("torque", [cd.plain_torque(0.3, 0.008), cd.plain_torque(0.3, 0.004, 5e-5),
                                    cd.plain_torque(0.02, 0.01)])
def test_rundown_speed_matches_solve_ivp(torque):
    t, n, _ = integrate_rundown(torque, 2.6, 930.0, 5.0, 0.0, 0)
    np.testing.assert_allclose(cd.rundown_speed(t, 0.0, 930.0, torque, 2.6), n, atol=0.05)


def test_rundown_speed_coulomb_closed_form_and_stop():
    # constant torque: n = n0 - 30*M*t/(pi*I); stops at t = pi*I*n0/(30*M) and stays stopped
    t = np.array([0.0, 10.0, 40.0, 100.0])
    n = cd.rundown_speed(t, 0.0, 600.0, cd.plain_torque(0.55), 2.6)
    slope = 30 * 0.55 / (math.pi * 2.6)
    np.testing.assert_allclose(n, np.maximum(600.0 - slope * t, 0.0), atol=1e-9)


# ----------------------------------------------------------------- nested models
def test_constant_f_data_come_back_as_coulomb_only():
    M_c = 0.02 * 1100 * 0.025  # f = 0.02 on the TMM-7M
    for seed in range(3):
        t, n, t_stop = integrate_rundown(cd.plain_torque(M_c), 2.6, 930.0, 2.0, 2.0, seed)
        result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
        assert result.model == "coulomb"
        assert result.f_constant == pytest.approx(0.02, rel=0.01)
        low, high = result.chosen.interval("M_c")
        assert low < M_c < high
        assert result.rmse_after == result.rmse_before
        assert result.rundown_time == pytest.approx(t_stop, rel=0.01)


def test_viscous_components_recovered():
    t, n, _ = integrate_rundown(cd.plain_torque(0.3, 0.008), 2.6, 930.0, 2.0, 2.0, 11)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    assert result.model == "coulomb_viscous"
    assert result.chosen.value("M_c") == pytest.approx(0.3, rel=0.03)
    assert result.chosen.value("c_v") == pytest.approx(0.008, rel=0.03)
    for name, true in (("M_c", 0.3), ("c_v", 0.008)):
        low, high = result.chosen.interval(name)
        assert low < true < high
    assert result.rmse_after < 0.1 * result.rmse_before


def test_aero_components_recovered_and_energy_balances():
    t, n, _ = integrate_rundown(cd.plain_torque(0.3, 0.004, 5e-5), 2.6, 930.0, 2.0, 2.0, 12)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    assert result.model == "coulomb_viscous_aero"
    for name, true in (("M_c", 0.3), ("c_v", 0.004), ("c_a", 5e-5)):
        assert result.chosen.value(name) == pytest.approx(true, rel=0.1)
        low, high = result.chosen.interval(name)
        assert low < true < high
    e = result.energy
    # first principles: the work of the three torques equals the kinetic energy lost
    assert e["coulomb"] + e["viscous"] + e["aero"] == pytest.approx(e["total"], rel=1e-4)
    assert e["to_standstill"] == pytest.approx(0.5 * 2.6 * (930 * math.pi / 30) ** 2, rel=0.005)


def test_formula1_follows_the_model_torque():
    t, n, _ = integrate_rundown(cd.plain_torque(0.3, 0.008), 2.6, 930.0, 2.0, 0.5, 4)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    s = result.samples.dropna(subset=["f_formula1"])
    true_f = cd.plain_torque(0.3, 0.008)(s["n_smooth [1/min]"] * math.pi / 30) / (1100 * 0.025)
    np.testing.assert_allclose(s["f_formula1"], true_f, rtol=0.05)


def test_result_invariant_to_speed_unit():
    u = ureg()
    t, n, _ = integrate_rundown(cd.plain_torque(0.55), 2.6, 930.0, 4.0, 2.0, 1)
    in_rpm = cd.analyse_coastdown(t * u.s, n * u.rpm)
    in_rad = cd.analyse_coastdown((t / 60) * u.min, (n * math.pi / 30) * u("rad/s"), I=2.6 * u("kg*m^2"),
                                  G=1.1 * u.kN, r=0.025 * u.m)
    assert in_rad.model == in_rpm.model
    assert in_rad.f_constant == pytest.approx(in_rpm.f_constant, rel=1e-6)


def test_summary_keys():
    t, n, _ = integrate_rundown(cd.plain_torque(0.55), 2.6, 930.0, 4.0, 2.0, 1)
    summary = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0).summary()
    for key in ("model", "M_c [N*m]", "c_v [N*m*s]", "c_a [N*m*s^2]", "f_constant", "rmse_before [1/min]",
                "rmse_after [1/min]"):
        assert key in summary
    assert summary["c_v [N*m*s]"] == 0.0


# ----------------------------------------------------------------- bad input
def test_too_few_samples_message():
    with pytest.raises(ValueError, match=re.escape(
            "coast-down: 5 samples; at least 10 are needed to fit and cross-validate the nested models")):
        cd.coastdown_analysis(np.arange(5.0), 100 - np.arange(5.0), 2.6, 1100.0, 25.0)


def test_time_not_increasing_message():
    t = np.arange(12.0)
    t[4] = 3.0
    with pytest.raises(ValueError, match=re.escape(
            "coast-down: sample 5: t = 3 s does not follow t = 3 s; times must increase strictly")):
        cd.coastdown_analysis(t, 100 - t, 2.6, 1100.0, 25.0)


def test_negative_speed_message():
    n = 100 - np.arange(12.0)
    n[2] = -4.0
    with pytest.raises(ValueError, match=re.escape(
            "coast-down: sample 3: n = -4 1/min; expected a finite speed >= 0 1/min")):
        cd.coastdown_analysis(np.arange(12.0), n, 2.6, 1100.0, 25.0)


def test_speed_not_falling_message():
    with pytest.raises(ValueError, match=re.escape(
            "coast-down: the speed does not fall (n = 100 1/min at the start, 111 1/min at the end); "
            "a run-down diagram is needed")):
        cd.coastdown_analysis(np.arange(12.0), 100 + np.arange(12.0), 2.6, 1100.0, 25.0)


def test_bad_rig_value_message():
    with pytest.raises(ValueError, match=re.escape("coast-down: G = -1100 N; expected a value > 0")):
        cd.coastdown_analysis(np.arange(12.0), 100 - np.arange(12.0), 2.6, -1100.0, 25.0)


def test_inertia_with_wrong_unit_message():
    u = ureg()
    with pytest.raises(UnitError, match=re.escape(
            "I: 2.6 kilogram cannot be converted to kg*m^2 "
            "(dimension [mass], expected [mass] * [length] ** 2)")):
        cd.analyse_coastdown(np.arange(12.0) * u.s, (100 - np.arange(12.0)) * u.rpm, I=2.6 * u.kg)


# ----------------------------------------------------------------- rolling-bearing spindle (seed 002)
def spindle_torque(f0, M1, nu, dM, z):
    return lambda w: z * (cd.rolling_bearing_M0_seed002(w * 30 / math.pi, nu, dM, f0) + M1) / 1000.0


def test_M0_branches_meet_near_nu_n_2000():
    # 2000^(2/3) = 158.74: the seed's constant 160 below 2000 is within 0.8 % of the upper branch
    above = cd.rolling_bearing_M0_seed002(100.0, 20.0, 60.0, 1.7)
    below = cd.rolling_bearing_M0_seed002(99.999, 20.0, 60.0, 1.7)
    assert below / above == pytest.approx(160 / 2000 ** (2 / 3), rel=1e-5)


def test_spindle_f0_and_f1_recovered():
    torque = spindle_torque(2.0, 25.0, 20.0, 50.0, 2)
    t, n, _ = integrate_rundown(torque, 0.05, 6000.0, 2.0, 3.0, 1, fraction=0.98)
    fit = cd.spindle_coastdown_fit(t, n, 0.05, 20.0, 50.0, bearings=2, P=1000.0, f0_catalogue=2.0)
    assert fit.f0 == pytest.approx(2.0, rel=0.02)
    assert fit.f1 == pytest.approx(0.0005, rel=0.02)
    low, high = fit.fit.interval("f0")
    assert low < 2.0 < high
    assert fit.summary()["f0_ratio_fitted_to_catalogue"] == pytest.approx(1.0, abs=0.02)


def test_spindle_below_nu_n_2000_is_refused():
    with pytest.raises(ValueError, match=re.escape(
            "spindle coast-down: ν·n reaches only 1000 mm²/s·1/min (< 2000): M0 of seed 002 is constant over "
            "the whole run-down and cannot be told apart from M1")):
        cd.spindle_coastdown_fit(np.arange(12.0), 100 - np.arange(12.0), 0.05, 10.0, 50.0)


# ----------------------------------------------------------------- real data: Liu et al. (2024) fig. 6
@pytest.mark.skipif(not LIU.exists(), reason="../shared/data (Liu 2024 centrifuge run-down) not available")
def test_liu2024_centrifuge_constant_torque_matches_published_11_Nm():
    data = pd.read_csv(LIU)
    u = ureg()
    for pressure, group in data.groupby("chamber_pressure_kPa"):
        result = cd.analyse_coastdown(group["time_s"].to_numpy() * u.s,
                                      group["angular_speed_rad_s"].to_numpy() * u("rad/s"),
                                      I=845.69 * u("kg*m^2"), G=None, r=None)
        # the seed's constant-f view: published M_f = I*beta = 10.99 N*m (Liu et al. 2024)
        assert result.fits["coulomb"].value("M_c") == pytest.approx(10.99, abs=0.1)
        # the curves are concave: a speed-dependent model fits n(t) better than constant torque ...
        assert result.model != "coulomb"
        assert result.rmse_after < 0.75 * result.rmse_before
        # ... with the torque falling with speed (negative c_v), not a viscous drag
        assert result.fits["coulomb_viscous"].value("c_v") < 0
        assert math.isnan(result.f_constant)
