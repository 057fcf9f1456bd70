"""The heat-balance figure (io/reports/thermal.py): its curves cross at n_per and T_op; the docs image."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from thermal_helpers import NJ208_ROW, nj208_chart, nj208_chart_m2, nj208_roots, plot_table, supports, walther_by_hand

from bearingheat.calc.table import calc
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.io.reports.thermal import draw_heat_balance, heat_balance_curves


def test_plot_curves_cross_at_n_per_and_T_op(tmp_path):
    table = pd.read_csv(plot_table(tmp_path)).iloc[[0]]
    curves = heat_balance_curves(table)
    out = calc(table)
    assert curves["n_cross"] == pytest.approx(out.loc[0, "n_per [1/min]"], rel=1e-12)
    assert curves["T_op"] == pytest.approx(out.loc[0, "T_op [degC]"], rel=1e-12)
    # the friction curve rises with speed and falls with temperature (thinner oil)
    assert np.all(np.diff(curves["friction_vs_speed"]) > 0)
    assert np.all(np.diff(curves["friction_vs_temperature"]) < 0)


def test_the_heat_balance_figure_is_written(tmp_path):
    """The figure of docs/thermal.md and the README (committed there from `bearingheat plot examples/gearbox_shaft.csv
    --row 0`); drawn here into a temporary folder, never over the committed one."""
    table = supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                        "T_bearing [degC]": [70, 70]}).iloc[[0]]
    target = tmp_path / "thermal_heat_balance.png"
    draw_heat_balance(heat_balance_curves(table), target)
    assert target.stat().st_size < 100_000


def test_the_curves_are_those_of_the_first_row_of_a_longer_table():
    # oil data on several rows: the curves are the first row's alone (ν(T) of every row broke the figure once)
    table = supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                        "T_bearing [degC]": [70, 70]})
    both, first = heat_balance_curves(table), heat_balance_curves(table.iloc[[0]])
    assert both["status"] == "ok"
    np.testing.assert_array_equal(both["friction_vs_temperature"], first["friction_vs_temperature"])
    assert both["T_op"] == first["T_op"] == pytest.approx(calc(table)["T_op [degC]"].iat[0], rel=1e-12)


def test_an_axially_loaded_cylindrical_roller_bearing_takes_f2_off_the_chart_along_its_curves(tmp_path):
    """NJ208-E with f2 off a digitised chart: the curves cross at the hand solution's n_per and T_op (M2 read at
    each speed and temperature, thermal_helpers.nj208_roots), and the friction heat at each point is that of M2
    read at its own nu*n*dM."""
    chart = F2Chart.from_csv(nj208_chart(tmp_path))
    curves = heat_balance_curves(pd.DataFrame([NJ208_ROW]), f2_chart=chart)
    n_per, T_op = nj208_roots()
    assert curves["status"] == "ok"
    assert curves["n_cross"] == pytest.approx(n_per, rel=1e-9)
    assert curves["T_op"] == pytest.approx(T_op, rel=1e-9)
    # one point by hand: N_R = pi*n/30e3*(M0 + M1 + M2) at 70 degC (dM = 60 mm, f0 = 2, M1 = 0.0003*6000*dM)
    nu_70, n = walther_by_hand(68, 8.6)(70), curves["speeds"][100]
    by_hand = np.pi * n / 30e3 * (2.0 * (nu_70 * n) ** (2 / 3) * 60.0 ** 3 * 1e-7 + 0.0003 * 6000 * 60.0
                                  + nj208_chart_m2(nu_70 * n))
    assert curves["friction_vs_speed"][100] == pytest.approx(by_hand, rel=1e-9)
    # the chart reaches from nu*n*dM = 1e3 to 1e8 mm^3/(s*min): at 70 degC from 1e3/(nu*dM) to 1e8/(nu*dM)
    low, high = curves["chart_speeds"]
    assert (low, high) == pytest.approx((1e3 / (nu_70 * 60.0), 1e8 / (nu_70 * 60.0)), rel=1e-9)
    below = curves["speeds"] < low
    assert np.isnan(curves["friction_vs_speed"][below]).all() and below.any()  # off the chart: not drawn
    assert not np.isnan(curves["friction_vs_speed"][~below]).any()
    draw_heat_balance(curves, tmp_path / "nj.png")
    assert (tmp_path / "nj.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_where_the_chart_ends_before_the_crossing_the_speed_axis_reaches_its_end():
    # the made-up docs chart ends at nu*n*dM = 1e6: the NJ206-E's N_R at 70 degC stays below the heat carried away
    # up to the chart's end (1088.8 1/min), so no n_per, and the axis runs to 1.5 times that end
    row = {"designation": "NJ206-E", "d [mm]": 30, "D [mm]": 62, "B [mm]": 16, "C0 [kN]": 36,
           "lubrication": "oil_bath", "n [rpm]": 100, "Fr [kN]": 5.0, "Fa [kN]": 0.05, "nu40 [mm^2/s]": 68,
           "nu100 [mm^2/s]": 8.6, "T_amb [degC]": 20, "T_bearing [degC]": 70}
    curves = heat_balance_curves(pd.DataFrame([row]), f2_chart=F2Chart.from_csv("docs/f2_chart_example.csv"))
    assert curves["status"] == "warning" and np.isnan(curves["n_cross"]) and np.isnan(curves["n_per"])
    assert curves["message"].startswith("n_per: the friction heat stays below the heat carried away at T_bearing "
                                        "up to 1088.8 1/min, where nu*n*dM = 1e+06 mm^3/(s*min) is the upper end")
    high = curves["chart_speeds"][1]
    assert high == pytest.approx(1e6 / (walther_by_hand(68, 8.6)(70) * 46.0), rel=1e-9)  # dM = 46 mm
    assert curves["speeds"][-1] == pytest.approx(1.5 * high, rel=1e-12)
    assert np.isnan(curves["friction_vs_speed"][curves["speeds"] > high]).all()


def test_without_a_chart_the_axially_loaded_row_is_an_error():
    curves = heat_balance_curves(pd.DataFrame([NJ208_ROW]))
    assert curves["status"] == "error" and curves["message"].startswith("f2: missing; ")
