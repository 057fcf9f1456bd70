"""User-digitised VM charts of the SKF drag loss factor: reading, interpolation without extrapolation, and calc.

The chart points here are made up (the SKF diagrams are not public); the roller curve of edition 6000 passes
through VM = 0.3e-4 at H/dm = 2.5/60, the value the SKF 6000 worked example (22208 E, pp. 104-105) reads.
"""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from bearingheat.calc.table import calc
from bearingheat.catalogue.vm_chart import VMChart
from bearingheat.errors import VMChartError

CSV = """edition,curve,H_over_dm,VM,source
-,-,1,percent,-
6000,roller,0,0,made up for the test
6000,roller,0.083333333333,0.006,made up for the test
6000,roller,1.0,0.02,made up for the test
10000,ball,0.0,0.0,made up for the test
10000,ball,0.5,0.01,made up for the test
"""

# SKF General Catalogue 6000, pp. 104-105 (the worked example): VM 0.3e-4 typed, H = 2.5 mm, dm = 60 mm
EXAMPLE = {"id": "22208 E", "designation": "22208 E", "d [mm]": 40, "D [mm]": 80, "B [mm]": 23, "C0 [kN]": 90,
           "lubrication": "oil_bath", "n [1/min]": 3500, "Fr [N]": 2990, "Fa [N]": 100, "nu [mm^2/s]": 68,
           "oil_level [mm]": 2.5, "VM": 0.3e-4, "skf_edition": "6000", "mu_sl": 0.05, "model": "skf"}


@pytest.fixture()
def chart_file(tmp_path):
    path = tmp_path / "vm.csv"
    path.write_text(CSV, encoding="utf-8")
    return path


def test_read_and_interpolate_linearly_in_H_over_dm(chart_file):
    chart = VMChart.from_csv(chart_file)
    assert chart.curves == [("10000", "ball"), ("6000", "roller")]
    VM, reasons = chart.lookup("6000", "roller", [2.5 / 60.0, 0.5, 1.0])
    # percent in the units row: 0.006 % = 6e-5; halfway to H/dm = 1/12 gives 3e-5
    np.testing.assert_allclose(VM, [3.0e-5, 6e-5 + (0.5 - 1 / 12) / (1 - 1 / 12) * (2e-4 - 6e-5), 2e-4], rtol=1e-9)
    assert list(reasons) == ["", "", ""]


def test_never_extrapolated_and_a_missing_curve_is_named(chart_file):
    chart = VMChart.from_csv(chart_file)
    VM, reasons = chart.lookup(["10000", "10000"], ["ball", "roller"], [0.6, 0.2])
    assert np.isnan(VM).all()
    assert reasons[0] == ("H/dm = 0.6 is outside the VM chart's ball bearing curve of SKF 10000/3 (0 to 0.5); "
                          "the chart is not extrapolated")
    assert reasons[1] == f"{chart_file} has no roller bearing curve for SKF edition 10000"


def test_calc_reads_a_blank_VM_off_the_chart_and_gives_the_worked_example(chart_file):
    typed = calc(pd.DataFrame([EXAMPLE]))
    read = calc(pd.DataFrame([{**EXAMPLE, "VM": None}]), vm_chart=str(chart_file))
    assert read["status"].tolist() == ["ok"]
    assert read["VM_chart"].iat[0] == pytest.approx(0.3e-4, rel=1e-9)
    assert read["MR [N*mm]"].iat[0] == pytest.approx(typed["MR [N*mm]"].iat[0], rel=1e-9)
    assert read["M_drag [N*mm]"].iat[0] == pytest.approx(14.5, abs=0.05)   # printed: Mdrag = 14.5 N·mm
    assert "VM_chart" not in typed.columns
    # a VM typed in the table wins over the chart
    both = calc(pd.DataFrame([{**EXAMPLE, "VM": 0.6e-4}]), vm_chart=str(chart_file))
    assert "VM_chart" not in both.columns
    assert both["M_drag [N*mm]"].iat[0] == pytest.approx(2 * 14.46, rel=0.01)


def test_a_level_outside_the_chart_is_a_row_error(chart_file):
    high = {**EXAMPLE, "VM": None, "oil_level [mm]": 70.0}   # H/dm = 1.17, beyond the curve's 1.0
    out = calc(pd.DataFrame([high]), vm_chart=str(chart_file))
    assert out["status"].tolist() == ["error"]
    assert out["message"].iat[0].startswith(
        f"VM: not read off {chart_file}: H/dm = 1.167 is outside the VM chart's roller bearing curve of SKF 6000 "
        "(0 to 1); the chart is not extrapolated; give VM")


def test_rows_of_the_catalogue_model_are_left_alone(chart_file):
    row = {**EXAMPLE, "designation": "22208-E1", "e": 0.28, "X0": 1, "Y0": 2.4, "model": "schaeffler", "VM": None}
    out = calc(pd.DataFrame([row]), vm_chart=str(chart_file))
    assert out["status"].iat[0] in ("ok", "warning") and "VM_chart" not in out.columns


@pytest.mark.parametrize("text, message", [
    ("edition,curve,H_over_dm\n-,-,1\n", "{path}: a VM chart needs the columns edition, curve, H_over_dm, VM and a "
                                         "units row"),
    ("edition,curve,H_over_dm,VM\n-,-,1,mm\n6000,ball,0,0\n6000,ball,1,1\n",
     "{path}: units row: VM unit 'mm' is not dimensionless"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n7000,ball,0,0\n7000,ball,1,1\n",
     "{path}, edition '7000' curve 'ball': the edition must be one of 6000, 10000"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,needle,0,0\n6000,needle,1,1\n",
     "{path}, edition '6000' curve 'needle': the curve must be one of ball, roller"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,ball,0,0\n",
     "{path}, edition '6000' curve 'ball': needs at least two points, has 1"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,ball,0.5,0\n6000,ball,0.2,1\n",
     "{path}, edition '6000' curve 'ball': H_over_dm must increase strictly from point to point"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,ball,0,-1\n6000,ball,1,1\n",
     "{path}, edition '6000' curve 'ball': H_over_dm and VM must all be numbers >= 0"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,ball,low,0\n",
     "{path}, line 3: not a number in ['6000', 'ball', 'low', '0']"),
    ("edition,curve,H_over_dm,VM\n-,-,1,1\n", "{path}: no curves"),
])
def test_bad_charts_are_refused_with_the_reason(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(VMChartError, match=f"^{re.escape(message.format(path=path))}$"):
        VMChart.from_csv(path)


def test_a_missing_file_is_refused(tmp_path):
    path = tmp_path / "absent.csv"
    with pytest.raises(VMChartError, match=f"^{re.escape(f'{path}: cannot read the VM chart (No such file or directory)')}$"):
        VMChart.from_csv(path)
