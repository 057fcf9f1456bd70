"""Coast-down fits (the TMM-7M lab sheet nested models) and the rolling-bearing spindle form (the Schaeffler catalogue)."""
from __future__ import annotations

import math
import re

import numpy as np
from scipy import stats
import pytest
from coastdown_helpers import integrate_rundown, spindle_torque
from scipy.optimize import curve_fit

from bearingheat.analysis import coastdown as cd
from bearingheat.errors import CoastdownError
from bearingheat.kernels.coastdown import plain_torque, rundown_speed


def test_interval_table_reproduces_formula2_on_a_straight_line():
    t = np.linspace(0.0, 90.0, 91)
    n = 900.0 - 10.0 * t
    table = cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dn=100.0)
    assert len(table) == 9
    np.testing.assert_allclose(table["dt [s]"], 10.0)
    np.testing.assert_allclose(table["f"], 0.0990078, rtol=1e-6)
    table_dt = cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dt=30.0)
    np.testing.assert_allclose(table_dt["n_from [1/min]"] - table_dt["n_to [1/min]"], 300.0)


def test_a_step_larger_than_the_recording_is_refused():
    """Not one interval of Δn or Δt fits in the run-down: an empty table would say nothing."""
    t = np.linspace(0.0, 90.0, 91)
    n = 900.0 - 10.0 * t
    with pytest.raises(CoastdownError) as exc:
        cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dn=5000.0)
    assert str(exc.value) == ("intervals: Δn = 5000 1/min is larger than the recorded speed range (900 to 0 1/min); "
                              "give a smaller speed step")
    with pytest.raises(CoastdownError) as exc:
        cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, dt=1000.0)
    assert str(exc.value) == ("intervals: Δt = 1000 s is longer than the recorded run-down (90 s); give a shorter "
                              "time step")


# ----------------------------------------------------------------- nested models
def test_constant_f_data_come_back_as_coulomb_only():
    M_c = 0.02 * 1100 * 0.025  # f = 0.02 on the TMM-7M
    for seed in range(3):
        t, n, t_stop = integrate_rundown(plain_torque(M_c), 2.6, 930.0, 2.0, 2.0, seed)
        result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
        assert result.model == "coulomb"
        assert result.f_constant == pytest.approx(0.02, rel=0.01)
        low, high = result.chosen.interval("M_c")
        assert low < M_c < high
        assert result.rmse_after == result.rmse_before
        assert result.rundown_time == pytest.approx(t_stop, rel=0.01)


def test_viscous_components_recovered():
    t, n, _ = integrate_rundown(plain_torque(0.3, 0.008), 2.6, 930.0, 2.0, 2.0, 11)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    assert result.model == "coulomb_viscous"
    assert result.chosen.value("M_c") == pytest.approx(0.3, rel=0.03)
    assert result.chosen.value("c_v") == pytest.approx(0.008, rel=0.03)
    for name, true in (("M_c", 0.3), ("c_v", 0.008)):
        low, high = result.chosen.interval(name)
        assert low < true < high
    assert result.rmse_after < 0.1 * result.rmse_before


def test_aero_components_recovered_and_energy_balances():
    t, n, _ = integrate_rundown(plain_torque(0.3, 0.004, 5e-5), 2.6, 930.0, 2.0, 2.0, 12)
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
    t, n, _ = integrate_rundown(plain_torque(0.3, 0.008), 2.6, 930.0, 2.0, 0.5, 4)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    s = result.samples.dropna(subset=["f_formula1"])
    true_f = plain_torque(0.3, 0.008)(s["n_smooth [1/min]"] * math.pi / 30) / (1100 * 0.025)
    np.testing.assert_allclose(s["f_formula1"], true_f, rtol=0.05)


def test_summary_keys():
    t, n, _ = integrate_rundown(plain_torque(0.55), 2.6, 930.0, 4.0, 2.0, 1)
    summary = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0).summary()
    for key in ("model", "M_c [N*m]", "c_v [N*m*s]", "c_a [N*m*s^2]", "f_constant", "rmse_before [1/min]",
                "rmse_after [1/min]"):
        assert key in summary
    assert summary["c_v [N*m*s]"] == 0.0
    # a component the chosen (Coulomb) model does not have is 0 there but was not measured: no interval, not [0, 0]
    assert summary["model"] == "coulomb"
    assert summary["c_v_ci95 [N*m*s]"] is None and summary["c_a_ci95 [N*m*s^2]"] is None
    low, high = summary["M_c_ci95 [N*m]"]
    assert low < summary["M_c [N*m]"] < high


def test_the_interval_of_a_torque_that_cannot_be_negative_stops_at_zero():
    """A small Coulomb torque under much noise (M_c = 0.002 N·m, 49 samples, σ = 15 1/min): the Wald interval
    M_c ± t·SE reaches below 0, where no friction torque lies; it stops at 0 and the report says so."""
    from bearingheat.io.reports.coastdown import render_report
    t, n, _ = integrate_rundown(plain_torque(0.002, 0.008), 2.6, 930.0, 20.0, 15.0, 1, fraction=0.5)
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    fit = result.chosen
    assert result.model == "coulomb_viscous"
    k = fit.parameters.index("M_c")
    half_width = stats.t.ppf(0.975, t.size - 3) * fit.std_errors[k]  # n0, M_c, c_v
    assert fit.value("M_c") - half_width < 0
    assert fit.interval("M_c") == (0.0, pytest.approx(fit.value("M_c") + half_width, rel=1e-12))
    assert fit.interval_cut("M_c") and not fit.interval_cut("c_v") and not fit.interval_cut("c_a")
    low, high = fit.interval("c_v")  # free in sign: symmetric about its value
    assert fit.value("c_v") - low == pytest.approx(high - fit.value("c_v"), rel=1e-12)
    assert result.summary()["M_c_ci95 [N*m]"][0] == 0.0
    assert f"(95 % CI 0 to {fit.interval('M_c')[1]:.4g}, cut at 0: it is not negative)" in render_report(
        result, "rundown.csv", None)


# ----------------------------------------------------------------- bad input
def test_too_few_samples_message():
    with pytest.raises(CoastdownError, match=re.escape(
            "coast-down: 5 samples; at least 10 are needed to fit and cross-validate the nested models")):
        cd.coastdown_analysis(np.arange(5.0), 100 - np.arange(5.0), 2.6, 1100.0, 25.0)


def test_time_not_increasing_message():
    t = np.arange(12.0)
    t[4] = 3.0
    with pytest.raises(CoastdownError, match=re.escape(
            "coast-down: sample 5: t = 3 s does not follow t = 3 s; times must increase strictly")):
        cd.coastdown_analysis(t, 100 - t, 2.6, 1100.0, 25.0)


def test_negative_speed_message():
    n = 100 - np.arange(12.0)
    n[2] = -4.0
    with pytest.raises(CoastdownError, match=re.escape(
            "coast-down: sample 3: n = -4 1/min; expected a finite speed >= 0 1/min")):
        cd.coastdown_analysis(np.arange(12.0), n, 2.6, 1100.0, 25.0)


def test_speed_not_falling_message():
    with pytest.raises(CoastdownError, match=re.escape(
            "coast-down: the speed does not fall (n = 100 1/min at the start, 111 1/min at the end); "
            "a run-down diagram is needed")):
        cd.coastdown_analysis(np.arange(12.0), 100 + np.arange(12.0), 2.6, 1100.0, 25.0)


def test_bad_rig_value_message():
    with pytest.raises(CoastdownError, match=re.escape("coast-down: G = -1100 N; expected a value > 0")):
        cd.coastdown_analysis(np.arange(12.0), 100 - np.arange(12.0), 2.6, -1100.0, 25.0)


# ----------------------------------------------------------------- rolling-bearing spindle (the Schaeffler catalogue)
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
    with pytest.raises(CoastdownError, match=re.escape(
            "spindle coast-down: ν·n reaches only 1000 mm²/s·1/min (< 2000): M0 of the Schaeffler catalogue is constant over "
            "the whole run-down and cannot be told apart from M1")):
        cd.spindle_coastdown_fit(np.arange(12.0), 100 - np.arange(12.0), 0.05, 10.0, 50.0)


def test_standard_errors_are_those_of_curve_fit():
    """s²(JᵀJ)⁻¹ from the pseudo-inverse of J: the covariance scipy's curve_fit gives at the same optimum."""
    t, n, _ = integrate_rundown(plain_torque(0.3, 0.004, 5e-5), 2.6, 930.0, 2.0, 2.0, 12)
    fit = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0).fits["coulomb_viscous_aero"]

    def speed(times, n0, M_c, c_v, c_a):
        return rundown_speed(times, float(t[0]), n0, plain_torque(M_c, c_v, c_a), 2.6)

    values, covariance = curve_fit(speed, t, n, p0=fit.values, method="trf", x_scale=np.abs(fit.values))
    np.testing.assert_allclose(values, fit.values, rtol=1e-6)
    np.testing.assert_allclose(np.sqrt(np.diag(covariance)), fit.std_errors, rtol=1e-3)


def _line():
    t = np.arange(0.0, 61.0, 2.0)
    return t, 600.0 - 10.0 * t


@pytest.mark.parametrize("count", [0, -3, 2.5, float("nan"), "3"])
def test_interval_count_must_be_a_whole_number_of_at_least_one(count):
    """0 divided the speed range by zero, -3 gave a message about a Δn the user never gave, 2.5 was accepted."""
    t, n = _line()
    message = f"intervals: interval_count = {count!r}; expected a whole number >= 1"
    for call in (lambda: cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0, interval_count=count),
                 lambda: cd.interval_friction_table(t, n, 2.6, 1100.0, 25.0, count=count)):
        with pytest.raises(CoastdownError) as info:
            call()
        assert str(info.value) == message


def test_interval_count_through_the_unit_aware_api():
    from bearingheat.api.coastdown import analyse_coastdown
    from bearingheat.units import ureg
    u = ureg()
    t, n = _line()
    with pytest.raises(CoastdownError) as info:
        analyse_coastdown(t * u.s, n * u.rpm, interval_count=0)
    assert str(info.value) == "intervals: interval_count = 0; expected a whole number >= 1"
    # a whole count given as a float is a count: 4 equal steps of (600 - 20)/4 = 145 1/min by hand
    table = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0, interval_count=4.0).intervals
    np.testing.assert_allclose(table["n_from [1/min]"], [600.0, 455.0, 310.0, 165.0], rtol=1e-9)


@pytest.mark.parametrize(("f0", "shown"), [(0.0, "0"), (float("nan"), "nan"), (-2.0, "-2"), (float("inf"), "inf")])
def test_spindle_catalogue_f0_must_be_finite_and_positive(f0, shown):
    t = np.linspace(0.0, 20.0, 41)
    n = 6000.0 - 250.0 * t
    with pytest.raises(CoastdownError) as info:
        cd.spindle_coastdown_fit(t, n, 0.01, 20.0, 50.0, f0_catalogue=f0)
    assert str(info.value) == (f"spindle coast-down: catalogue f0 = {shown}; expected a finite value > 0 "
                               "to compare the fitted f0 with")


def test_a_run_down_time_extrapolated_far_past_the_record_is_warned():
    """The straight line stops at 60 s inside its 60 s record: no warning. Set by hand to 650 s (590 s past the
    record, under 10 x 60 s) still none; 700 s (640 s past it) is warned, in the summary as in the report."""
    import dataclasses

    from bearingheat.io.reports.coastdown import coastdown_summary, render_report
    t, n = _line()
    result = cd.coastdown_analysis(t, n, 2.6, 1100.0, 25.0)
    assert result.record_duration == 60.0 and result.rundown_time == pytest.approx(60.0, rel=1e-3)
    assert result.rundown_warning is None and coastdown_summary(result)["rundown_time_warning"] is None
    assert dataclasses.replace(result, rundown_time=650.0).rundown_warning is None
    far = dataclasses.replace(result, rundown_time=700.0, rundown_extrapolated=True)
    text = ("the run-down time is extrapolated 640 s past a record of 60 s (more than 10 times its duration): "
            "it rests on the fitted torque near standstill, which was not measured")
    assert far.rundown_warning == text
    assert coastdown_summary(far)["rundown_time_warning"] == text
    assert f"- **Warning:** {text}\n" in render_report(far, "line.csv", png=None)
