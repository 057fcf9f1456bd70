"""Digitised f2 charts: log-log interpolation, never extrapolation (the Schaeffler catalogue p. 69)."""
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import F2ChartError
from bearingheat.calc.models import compute_supports

EXAMPLE = Path(__file__).resolve().parents[2] / "docs" / "f2_chart_example.csv"


def synthetic(level_exponent=0.5, x_exponent=-0.6):
    """Made-up power-law curves f2 = 0.01 * (Fa/A)^a * (x/1e4)^b: log-log linear, so interpolation is exact."""
    points = {}
    for label, level in (("low", 0.1), ("mid", 1.0), ("high", 10.0)):
        xs = [1e3, 1e4, 1e5, 1e6]
        points[label] = (level, xs, [0.01 * level ** level_exponent * (x / 1e4) ** x_exponent for x in xs])
    return F2Chart(points, name="synthetic")


def exact(level, x, a=0.5, b=-0.6):
    return 0.01 * level ** a * (x / 1e4) ** b


def test_loglog_interpolation_is_exact_for_power_laws():
    chart = synthetic()
    levels = np.array([0.1, 0.3, 1.0, 2.5, 10.0])
    xs = np.array([1e3, 3.3e3, 5e4, 2e5, 1e6])
    f2, reasons = chart.lookup(levels, xs)
    assert list(reasons) == [""] * 5
    np.testing.assert_allclose(f2, exact(levels, xs), rtol=1e-12)


def test_extrapolation_is_refused():
    chart = synthetic()
    f2, reasons = chart.lookup([20.0, 1.0, 0.5], [1e4, 2e6, 500.0])
    assert np.isnan(f2).all()
    assert reasons[0] == ("Fa/A = 20 is outside the f2 chart's curves (0.1 to 10); "
                          "the Schaeffler catalogue forbids extrapolating the chart")
    assert reasons[1] == ("nu*n*dM = 2e+06 mm^3/(s*min) is outside curve 'mid' (Fa/A = 1: 1000 to 1e+06); "
                          "the Schaeffler catalogue forbids extrapolating the chart")
    assert reasons[2] == ("nu*n*dM = 500 mm^3/(s*min) is outside curve 'low' (Fa/A = 0.1: 1000 to 1e+06); "
                          "the Schaeffler catalogue forbids extrapolating the chart")


def test_values_are_those_of_lookup_for_many_points_at_once():
    """The heat balance reads f2 at every trial speed and temperature of its roots: values() gives lookup's f2,
    NaN where lookup refuses, and x_range() the nu*n*dM the two bracketing curves share."""
    chart = F2Chart({"a": (0.5, [1e3, 1e5], [0.02, 0.005]), "b": (2.0, [2e3, 1e6], [0.03, 0.005])}, name="test")
    levels = np.array([0.5, 1.0, 2.0, 1.0, 1.0, 3.0, 1.0])
    xs = np.array([1e3, 5e4, 5e5, 1.5e3, 2e5, 5e4, np.nan])
    f2, reasons = chart.lookup(levels, xs)
    np.testing.assert_array_equal(chart.values(levels, xs), f2)
    assert [bool(r) for r in reasons] == [False, False, False, True, True, True, True]
    # between the curves: log f2 of each curve at x, then linear in log Fa/A (by hand)
    on_a = math.log(0.02) + math.log(5e4 / 1e3) / math.log(1e5 / 1e3) * math.log(0.005 / 0.02)
    on_b = math.log(0.03) + math.log(5e4 / 2e3) / math.log(1e6 / 2e3) * math.log(0.005 / 0.03)
    assert f2[1] == pytest.approx(math.exp(on_a + math.log(1.0 / 0.5) / math.log(2.0 / 0.5) * (on_b - on_a)),
                                  rel=1e-12)
    low, high = chart.x_range([0.5, 1.0, 2.0, 3.0])
    np.testing.assert_array_equal(low, [1e3, 2e3, 2e3, np.nan])
    np.testing.assert_array_equal(high, [1e5, 1e5, 1e6, np.nan])


def test_example_file_reads(tmp_path):
    chart = F2Chart.from_csv(EXAMPLE)
    assert chart.Fa_over_A_range[0] > 0
    csv = tmp_path / "chart.csv"
    csv.write_text("curve,Fa_over_A,nu_n_dM,f2\n-,1,m^3/(s*min),1\nA,1,1e-6,0.01\nA,1,1e-4,0.002\n")
    chart = F2Chart.from_csv(csv)  # m^3 -> mm^3: 1e-6 m^3 = 1e3 mm^3
    f2, reasons = chart.lookup(1.0, 1e4)
    assert reasons[0] == "" and f2[0] == pytest.approx(math.sqrt(0.01 * 0.002), rel=1e-12)


@pytest.mark.parametrize("text,message", [
    ("curve,Fa_over_A,nu_n_dM\n-,1,mm^3/(s*min)\n",
     "{p}: an f2 chart needs the columns curve, Fa_over_A, nu_n_dM, f2 and a units row"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm,1\nA,1,1,1\nA,1,2,1\n",
     "{p}: units row: nu_n_dM unit 'mm' is not convertible to mm^3/(s*min)"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,x,1\n",
     "{p}, line 3: not a number in ['A', '1', 'x', '1']"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,10,1\nA,2,20,1\n",
     "{p}, line 4: curve 'A' has Fa_over_A 2, earlier points have 1"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,10,1\n",
     "{p}, curve 'A': needs at least two points, has 1"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,20,1\nA,1,10,1\n",
     "{p}, curve 'A': nu_n_dM must increase strictly from point to point"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,10,0\nA,1,20,1\n",
     "{p}, curve 'A': Fa_over_A, nu_n_dM and f2 must all be > 0"),
    ("curve,Fa_over_A,nu_n_dM,f2\n-,1,mm^3/(s*min),1\nA,1,10,1\nA,1,20,1\nB,1,10,1\nB,1,20,1\n",
     "{p}: two curves share one Fa_over_A value"),
])
def test_bad_chart_files(tmp_path, text, message):
    path = tmp_path / "chart.csv"
    path.write_text(text)
    with pytest.raises(F2ChartError) as exc:
        F2Chart.from_csv(path)
    assert str(exc.value) == message.format(p=path)


def test_missing_chart_file(tmp_path):
    with pytest.raises(F2ChartError) as exc:
        F2Chart.from_csv(tmp_path / "none.csv")
    assert str(exc.value) == f"{tmp_path / 'none.csv'}: cannot read the f2 chart (No such file or directory)"


def test_chart_feeds_m2_and_refuses_outside():
    chart = synthetic()
    dM = 46.0
    A = 15e-3 * dM ** 2.1
    rows = pd.DataFrame([
        dict(designation="NJ206-E", d=30, D=62, lubrication="circulating_oil", n=300, nu=20, Fr=5000, Fa=200.0),
        dict(designation="NJ206-E", d=30, D=62, lubrication="circulating_oil", n=300, nu=20, Fr=5000, Fa=1000.0,
             f2=0.003),
        dict(designation="NJ206-E", d=30, D=62, lubrication="circulating_oil", n=300, nu=20, Fr=2000, Fa=800.0),
    ])
    rows.loc[2, "Fa"] = 0.05 * A  # below the lowest curve
    out = compute_supports(rows, f2_chart=chart)
    f2 = exact(200 / A, 20 * 300 * dM)
    assert out.loc[0, "M2"] == pytest.approx(f2 * 200 * dM, rel=1e-12)
    assert out.loc[1, "M2"] == pytest.approx(0.003 * 1000 * dM, rel=1e-12)  # a user f2 wins over the chart
    assert out.loc[2, "status"] == "error"
    assert out.loc[2, "message"] == ("f2: Fa/A = 0.05 is outside the f2 chart's curves (0.1 to 10); "
                                     "the Schaeffler catalogue forbids extrapolating the chart")


def test_chart_needs_kb():
    rows = pd.DataFrame([dict(designation=None, type="cylindrical_roller_full_complement", series="SL0248", d=30,
                              D=62, lubrication="circulating_oil", n=3000, nu=20, Fr=5000, Fa=1000)])
    out = compute_supports(rows, f2_chart=synthetic())
    assert out.loc[0, "message"] == ("kB: missing; cylindrical roller bearing without cage series SL0248 has no kB in "
                                     "the Schaeffler catalogue p. 70, so Fa/A for the f2 chart is unknown; give f2")
