"""calc rows beyond the rolling friction model: plain bushings (seed 004) and the minimum axial load (seed 001)."""
import math

import numpy as np
import pandas as pd
import pytest

from bearingheat.contact import minimum_axial_load
from bearingheat.frame import calc


def test_plain_bushings_mix_with_rolling_bearings():
    table = pd.DataFrame({
        "id": ["roller", "bush", "bush with f", "bush too slow"],
        "designation": ["6205", None, None, None],
        "type": [None, "plain_bushing", "plain_bushing", "plain_bushing"],
        "d [mm]": [25, 20, 20, 20], "D [mm]": [52, None, None, None], "B [mm]": [15, 20, 20, 20],
        "C0 [N]": [7800, None, None, None], "lubrication": ["grease", None, None, None],
        "n [rpm]": [3000, 1000, 1000, 10], "Fr [N]": [1000] * 4, "nu [mm^2/s]": [20, None, None, None],
        "f_plain": [None, None, 0.08, None]})
    out = calc(table)
    assert list(out["status"]) == ["ok", "warning", "ok", "error"]
    V = math.pi * 20 * 1000 / 60000                      # m/s, seed 004
    assert out.loc[1, "V [m/s]"] == pytest.approx(V, rel=1e-12)
    assert out.loc[1, "p [N/mm^2]"] == pytest.approx(1000 / (20 * 20), rel=1e-12)
    assert out.loc[1, "NR [W]"] == pytest.approx(0.2 * 1000 * V, rel=1e-12)   # high end of 0.1-0.2
    assert out.loc[1, "MR [N*mm]"] == pytest.approx(0.2 * 1000 * 10, rel=1e-12)
    assert out.loc[1, "message"] == ("f not given: N uses f = 0.2, the high end of seed 004's range 0.1-0.2 at "
                                     "V = 1.05 m/s (conservative)")
    assert out.loc[2, "NR [W]"] == pytest.approx(0.08 * 1000 * V, rel=1e-12)
    assert out.loc[3, "message"] == "V = 0.01047 m/s is below 0.05 m/s: outside seed 004's method"
    assert math.isnan(out.loc[3, "NR [W]"])
    assert np.isnan(out.loc[1, ["f0", "f1", "M0 [N*mm]"]].astype(float)).all()
    assert out.loc[0, "MR [N*mm]"] > 0


def test_only_plain_bushings_need_no_rolling_columns():
    table = pd.DataFrame({"type": ["plain_bushing"], "d [mm]": [30], "B [mm]": [30], "n [1/min]": [500],
                          "Fr [kN]": [2], "f_plain": [0.1]})
    out = calc(table)
    V = math.pi * 30 * 500 / 60000
    assert out.loc[0, "status"] == "ok"
    assert out.loc[0, "NR [W]"] == pytest.approx(0.1 * 2000 * V, rel=1e-12)


def test_minimum_axial_load_warning():
    base = {"designation": "7205", "d [mm]": 25, "D [mm]": 52, "C0 [N]": 9300, "alpha [deg]": 30, "z": 12,
            "Dw [mm]": 7.9, "dm_pitch [mm]": 38.5, "lubrication": "grease", "n [rpm]": 12000, "Fr [N]": 100,
            "nu [mm^2/s]": 20}
    table = pd.DataFrame([{**base, "Fa [N]": 10}, {**base, "Fa [N]": 500}, {**base, "alpha [deg]": None, "Fa [N]": 0,
                                                                           "designation": "6205"}])
    out = calc(table)
    fa_min = minimum_axial_load(12, 7.9, 38.5, 12000, 30.0)
    assert out.loc[0, "Fa_min [N]"] == pytest.approx(fa_min, rel=1e-12)
    assert out.loc[0, "status"] == "warning"
    assert out.loc[0, "message"] == (f"Fa = 10 N is below the minimum axial load {fa_min:.4g} N at 12000 1/min: "
                                     "the balls may skid (seed 001)")
    assert out.loc[1, "status"] == "ok"
    assert out.loc[2, "message"] == ("Fa_min: give alpha [deg] (the contact angle) to check the minimum axial load "
                                     "against ball skidding (seed 001)")


def test_no_geometry_no_column():
    table = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [N]": [7800],
                          "lubrication": ["grease"], "n [rpm]": [3000], "Fr [N]": [100], "nu [mm^2/s]": [20]})
    assert "Fa_min [N]" not in calc(table).columns
