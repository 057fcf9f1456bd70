"""calc rows beyond the rolling friction model: plain bushings (the DU/DP bushing handbook)."""
import math

import numpy as np
import pandas as pd
import pytest

from bearingheat.calc.table import calc


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
    V = math.pi * 20 * 1000 / 60000                      # m/s, the DU/DP bushing handbook
    assert out.loc[1, "V [m/s]"] == pytest.approx(V, rel=1e-12)
    assert out.loc[1, "p [N/mm^2]"] == pytest.approx(1000 / (20 * 20), rel=1e-12)
    assert out.loc[1, "NR [W]"] == pytest.approx(0.2 * 1000 * V, rel=1e-12)   # high end of 0.1-0.2
    assert out.loc[1, "MR [N*mm]"] == pytest.approx(0.2 * 1000 * 10, rel=1e-12)
    assert out.loc[1, "message"] == ("f not given: N uses f = 0.2, the high end of the DU/DP bushing handbook's range 0.1-0.2 at "
                                     "V = 1.05 m/s (conservative)")
    assert out.loc[2, "NR [W]"] == pytest.approx(0.08 * 1000 * V, rel=1e-12)
    assert out.loc[3, "message"] == ("V = 0.01047 m/s is below 0.05 m/s: the DU/DP bushing handbook gives no friction "
                                     "coefficient there; give f_plain")
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
