"""The DP11A lab rig of the DP11A manual: processing readings (tasks 1-3, tables 4 and 5), the shipped example."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingheat.analysis.lab import EXAMPLE_TRUTH, generate_example, process_lab
from bearingheat.errors import LabError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lab_dp11a_example.csv"


def test_p0_uses_table_1():
    r = process_lab(pd.DataFrame({"bearing": ["101"] * 2, "Q [kg]": [2.0, 2.0], "beta [deg]": [0.0, 60.0],
                                  "n [1/min]": [3000.0, 3000.0], "T [N*mm]": [0.1, 0.1]})).readings
    # beta = 0: P0 = max(0.6*0 + 0.5*19.62, 0) = 9.81; beta = 60: max(0.6*16.99 + 0.5*9.81, 16.99) = 16.99
    np.testing.assert_allclose(r["P0"], [9.81, 19.62 * np.sin(np.radians(60))], rtol=1e-12)


def _rel(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b)) / np.max(np.abs(np.asarray(b))))


def test_closed_forms_agree_with_general_least_squares_on_the_example():
    result = process_lab(pd.read_csv(EXAMPLE))
    assert _rel(result.task1["mu"], result.task1["mu_lstsq"]) < 1e-12
    assert _rel(result.task2["f0"], result.task2["f0_lstsq"]) < 1e-12
    assert _rel(result.task2["T_F"], result.task2["T_F_lstsq"]) < 1e-12
    assert _rel(result.task3["f"], result.task3["f_lstsq"]) < 1e-12
    assert _rel(result.task3["T0"], result.task3["T0_lstsq"]) < 1e-12


def test_shipped_example_is_the_generator_output():
    shipped = pd.read_csv(EXAMPLE, dtype={"bearing": str})
    pd.testing.assert_frame_equal(shipped, generate_example(), check_dtype=False)


def test_example_recovers_the_generating_coefficients():
    result = process_lab(pd.read_csv(EXAMPLE))
    # f of task 3, averaged over beta and n, within 5 % of the f the example was generated with
    assert result.task3.groupby("bearing")["f"].mean().to_numpy() == pytest.approx(
        [EXAMPLE_TRUTH["f"]] * 3, rel=0.05)
    assert len(result.table4) == 9 and len(result.table5) == 9
    assert result.table4[("101", 30.0)].shape == (3, 4)        # rows Q, columns n
    assert result.table5[("101", 2.0)].shape == (4, 3)         # rows n, columns beta


def test_catalogue_comparison():
    result = process_lab(pd.read_csv(EXAMPLE))
    assert list(result.comparison.columns) == ["bearing", "readings", "T_mean [N*mm]", "DP11A mu model / measured",
                                               "catalogue MR / measured", "catalogue M0 share"]
    assert result.notes == []
    no_nu = process_lab(pd.read_csv(EXAMPLE).drop(columns="nu [mm^2/s]"))
    assert no_nu.notes == ["no viscosity given (column 'nu [mm^2/s]' or --nu): the Schaeffler catalogue comparison is skipped"]


def _readings(T=None):
    """Bearing 101 (d = 12 mm) radial at 3000 1/min under 0.5, 1 and 2 kg: P0 = 4.905, 9.81, 19.62 N."""
    table = pd.DataFrame({"bearing": ["101"] * 3, "Q [kg]": [0.5, 1.0, 2.0], "beta [deg]": [90.0] * 3,
                          "n [1/min]": [3000.0] * 3, "T [N*mm]": [0.1, 0.1, 0.1] if T is None else T})
    return table


def test_task1_keeps_the_manuals_mu_through_the_origin_and_fits_the_line_with_an_intercept():
    P0 = np.array([4.905, 9.81, 19.62])
    d = process_lab(_readings()).readings["d"].iat[0]
    T = 0.04 + 0.0003 * P0 * d / 2.0                    # a load-independent 0.04 N*mm and mu = 0.0003
    row = process_lab(_readings(T)).task1.iloc[0]
    assert d == 12.0
    # the manual's mu = 2*sum(T*P0)/(d*sum(P0^2)) misses the intercept: 0.0003 + 0.04*2*sum(P0)/(d*sum(P0^2))
    assert row["mu"] == pytest.approx(0.0003 + 0.04 * 2 * P0.sum() / (d * (P0 ** 2).sum()), rel=1e-12)
    assert row["mu"] == pytest.approx(0.00075305, rel=1e-4)
    assert row["mu_slope"] == pytest.approx(0.0003, rel=1e-9)
    assert row["T_intercept"] == pytest.approx(0.04, rel=1e-9)
    one_load = process_lab(_readings().iloc[:1]).task1.iloc[0]
    assert one_load["mu"] == pytest.approx(2 * 0.1 / (12.0 * 4.905), rel=1e-12)
    assert np.isnan(one_load["mu_slope"]) and np.isnan(one_load["T_intercept"])


def test_unknown_bearing():
    with pytest.raises(LabError, match=re.escape("bearing '6205' is not in the DP11A manual table 3; expected one of "
                                                 "1000095, 18, 101")):
        process_lab(pd.DataFrame({"bearing": ["6205"], "Q [kg]": [1.0], "beta [deg]": [0.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


def test_missing_column_and_bad_angle():
    with pytest.raises(LabError, match=re.escape("missing column: 'beta [deg]'")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [kg]": [1.0], "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))
    with pytest.raises(LabError, match=re.escape("row 1: beta [deg] = 120 must be in 0..90 deg")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [kg]": [1.0], "beta [deg]": [120.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


def test_a_reading_in_two_columns_is_refused():
    """T in N·mm and T in N·m: the last was taken, silently."""
    table = pd.DataFrame({"bearing": ["101"], "Q [kg]": [1.0], "beta [deg]": [0.0], "n [1/min]": [3000.0],
                          "T [N*mm]": [0.1], "T [N*m]": [0.0001]})
    with pytest.raises(LabError, match=re.escape("column 'T [N*m]': T appears twice")):
        process_lab(table)


def test_weight_as_force_is_refused():
    with pytest.raises(LabError, match=re.escape("column 'Q [N]': unit N cannot be converted to kg")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [N]": [1.0], "beta [deg]": [0.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


@pytest.mark.parametrize("changes, message", [
    ({"T [N*mm]": [np.inf]}, "row 1: inf is not a number for T [N*mm]"),
    ({"T [N*mm]": [np.nan]}, "row 1: blank is not a number for T [N*mm]"),
    ({"nu [mm^2/s]": [-5.0]}, "row 1: nu [mm^2/s] = -5 must be > 0"),
    ({"nu [mm^2/s]": [0.0]}, "row 1: nu [mm^2/s] = 0 must be > 0"),
])
def test_readings_that_are_no_finite_numbers_or_no_viscosity_are_refused(changes, message):
    """An infinite torque gave mu = inf, a viscosity <= 0 left the row's catalogue torque out of the median."""
    row = {"bearing": ["101"], "Q [kg]": [1.0], "beta [deg]": [0.0], "n [1/min]": [3000.0], "T [N*mm]": [0.1],
           "nu [mm^2/s]": [20.0]}
    row.update(changes)
    with pytest.raises(LabError) as exc:
        process_lab(pd.DataFrame(row))
    assert str(exc.value) == message
