"""The DP11A lab rig of seed 000: loads, the three tasks, tables 4 and 5, the shipped example."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingheat.cli import main
from bearingheat.lab import (EXAMPLE_TRUTH, LabError, generate_example, lab_bearing, lab_loads, least_squares_line,
                             load_fit, process_lab, reduced_friction_coefficient, speed_fit)

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "lab_dp11a_example.csv"


def test_lab_bearings_of_table_3():
    assert [lab_bearing(b)["C0"] for b in ("1000095", "18", "101")] == [392.0, 1354.0, 2227.0]
    assert [lab_bearing(b)["dm"] for b in ("1000095", "18", "101")] == [9.0, 13.5, 20.0]


def test_loads_of_seed_000():
    # Fa = 9.81 Q cos(beta), Fr = 9.81 Q sin(beta): axial at 0 deg, radial at 90 deg
    assert lab_loads(1.0, 0.0) == (9.81, 0.0)
    Fa, Fr = lab_loads(2.0, 90.0)
    assert Fa == pytest.approx(0.0, abs=1e-14) and Fr == 19.62
    Fa, Fr = lab_loads(np.array([0.5, 2.0]), np.array([45.0, 45.0]))
    np.testing.assert_allclose(Fa, Fr, rtol=1e-15)


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


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.01, 10.0), min_size=3, max_size=8), st.floats(2000.0, 3000.0), st.floats(5, 30))
def test_closed_forms_agree_with_lstsq_property(torques, n0, dm):
    T = np.array(torques)
    n = n0 + 100.0 * np.arange(len(T))
    f0, TF = speed_fit(T, n, dm)
    slope, intercept = least_squares_line(n ** (2 / 3), T)
    assert f0 * dm ** 3 == pytest.approx(slope, rel=1e-9, abs=1e-12)
    assert TF == pytest.approx(intercept, rel=1e-9, abs=1e-9)
    P0 = 5.0 + 5.0 * np.arange(len(T))
    mu = reduced_friction_coefficient(T, P0, dm)
    mu_ls, _ = least_squares_line(P0 * dm / 2, T, through_origin=True)
    assert mu == pytest.approx(mu_ls, rel=1e-12)
    f, T0 = load_fit(T, P0, 2227.0, dm)
    slope, intercept = least_squares_line(P0 ** 1.55, T)
    assert f == pytest.approx(slope * 2227.0 ** 0.55 / dm, rel=1e-9, abs=1e-15)


def test_exact_data_give_the_parameters_back():
    n = np.array([2400.0, 2600.0, 2800.0, 3000.0])
    f0, TF = speed_fit(3e-8 * 20 ** 3 * n ** (2 / 3) + 0.02, n, 20.0)
    assert f0 == pytest.approx(3e-8, rel=1e-10) and TF == pytest.approx(0.02, rel=1e-9)
    P0 = np.array([4.905, 9.81, 19.62])
    assert reduced_friction_coefficient(0.0015 * P0 * 12 / 2, P0, 12.0) == pytest.approx(0.0015, rel=1e-14)


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
    assert "seed002_MR / measured" in result.comparison.columns
    assert result.notes == []
    no_nu = process_lab(pd.read_csv(EXAMPLE).drop(columns="nu [mm^2/s]"))
    assert no_nu.notes == ["no viscosity given (column 'nu [mm^2/s]' or --nu): the seed 002 comparison is skipped"]


def test_unknown_bearing():
    with pytest.raises(LabError, match=re.escape("bearing '6205' is not in seed 000 table 3; expected one of "
                                                 "1000095, 18, 101")):
        process_lab(pd.DataFrame({"bearing": ["6205"], "Q [kg]": [1.0], "beta [deg]": [0.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


def test_missing_column_and_bad_angle():
    with pytest.raises(LabError, match=re.escape("missing column: 'beta [deg]'")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [kg]": [1.0], "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))
    with pytest.raises(LabError, match=re.escape("row 1: beta [deg] = 120 must be in 0..90 deg")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [kg]": [1.0], "beta [deg]": [120.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


def test_weight_as_force_is_refused():
    with pytest.raises(LabError, match=re.escape("column 'Q [N]': unit N cannot be converted to kg")):
        process_lab(pd.DataFrame({"bearing": ["101"], "Q [N]": [1.0], "beta [deg]": [0.0],
                                  "n [1/min]": [3000.0], "T [N*mm]": [0.1]}))


def test_cli_lab(tmp_path, capsys):
    assert main(["lab", str(EXAMPLE), "--out", str(tmp_path), "-q"]) == 0
    report = (tmp_path / "report.md").read_text()
    assert "Table 4, β = 30°" in report and "Table 5, Q = 2 kg" in report
    assert (tmp_path / "task2_101.png").read_bytes()[:4] == b"\x89PNG"


def test_cli_lab_bad_nu(tmp_path, capsys):
    assert main(["lab", str(EXAMPLE), "--out", str(tmp_path), "--nu", "20"]) == 2
    assert capsys.readouterr().err.strip() == (
        "bearingheat lab: error: --nu: '20' has no unit; write it with one, e.g. 20mm")


def test_subprocess_lab(tmp_path):
    done = subprocess.run([sys.executable, "-m", "bearingheat", "lab", str(EXAMPLE), "--out", str(tmp_path),
                           "--nu", "30cSt"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "files written to" in done.stdout
