"""The heat-balance figure (io/reports/thermal.py): its curves cross at n_per and T_op; the docs image."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from thermal_helpers import plot_table, supports

from bearingheat.calc.table import calc
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
