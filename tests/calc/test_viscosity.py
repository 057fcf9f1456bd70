"""Viscosity-temperature lines of the rows of a table: Walther constants and the row problems."""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.viscosity import viscosity_model_rows


OILS = pd.DataFrame({"nu40": [68.0, 68.0, np.nan, 8.0, np.nan, 68.0, np.nan, np.nan],
                     "nu100": [8.6, np.nan, np.nan, 9.0, np.nan, 8.6, np.nan, np.nan],
                     "iso_vg": [np.nan, np.nan, 47.0, np.nan, 68.0, 68.0, np.nan, 220.0],
                     "VI": [np.nan, np.nan, np.nan, np.nan, -5000.0, np.nan, 95.0, 95.0]})


def test_viscosity_model_rows_problems():
    frame = OILS.iloc[:7]
    A, B, problems = viscosity_model_rows(frame)
    assert not np.isnan(A[0])
    assert np.isnan(A[1:]).all()
    assert problems == [
        (1, "error", "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line (ASTM D341)"),
        (2, "error", "iso_vg: 47 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, "
                     "150, 220, 320, 460, 680, 1000, 1500, 2200, 3200"),
        (3, "error", "nu40 [mm^2/s]: 8 must be larger than nu100 = 9"),
        (4, "error", "VI: -5000 cannot be reached by ISO VG 68 with nu100 >= 2 mm^2/s (ASTM D2270)"),
        (5, "error", "iso_vg: give either iso_vg or nu40 and nu100, not both"),
        (6, "error", "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"),
    ]


def test_a_viscosity_index_without_oil_data_is_a_row_error_of_calc():
    """A table with a VI column but no nu40, nu100 or iso_vg still has its VI checked (calc skips the
    viscosity-temperature lines only where no oil column is given at all)."""
    import bearingheat as bh

    rows = pd.DataFrame({"designation": ["6205"], "D [mm]": [52.0], "lubrication": ["oil_bath"], "n [rpm]": [3000.0],
                         "Fr [kN]": [2.0], "nu [mm^2/s]": [12.0], "T_amb [degC]": [20.0], "VI": [95.0]})
    out = bh.calc(rows)
    assert out["status"].tolist() == ["error"]
    assert out["message"].iloc[0] == "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"


def test_a_table_whose_every_row_has_unusable_oil_data_gets_each_row_s_reason():
    """Where no row's oil data fixes a line (one support with ISO VG 47, say), calc refused the whole table with
    "missing column: 'nu [mm^2/s]'", although the oil data were given; each row now says what is wrong with its
    own, as it does beside a row whose oil data are good."""
    import bearingheat as bh

    rows = pd.DataFrame({"designation": ["6208", "6208"], "d [mm]": [40.0] * 2, "D [mm]": [80.0] * 2,
                         "lubrication": ["oil_bath"] * 2, "n [rpm]": [1480.0] * 2, "Fr [kN]": [3.2] * 2,
                         "iso_vg": [47.0, np.nan], "nu40 [mm^2/s]": [np.nan, 68.0], "T_amb [degC]": [20.0] * 2,
                         "T_bearing [degC]": [70.0] * 2})
    out = bh.calc(rows)
    assert out["status"].tolist() == ["error", "error"]
    assert out["message"].tolist() == [
        "iso_vg: 47 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, "
        "460, 680, 1000, 1500, 2200, 3200",
        "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line (ASTM D341)"]


def test_rows_with_the_same_oil_data_are_worked_out_once_and_alike():
    """A table of many rows naming few oils (here the eight above in a shuffled order, 40 times each): every row
    gets the constants and the problems it gets alone; the work is done once per distinct oil."""
    order = np.random.default_rng(5).permutation(np.resize(np.arange(len(OILS)), 320))
    frame = OILS.iloc[order].reset_index(drop=True)
    alone = [viscosity_model_rows(OILS.iloc[[k]].reset_index(drop=True)) for k in range(len(OILS))]
    A, B, problems = viscosity_model_rows(frame)
    np.testing.assert_array_equal(A, [alone[k][0][0] for k in order])
    np.testing.assert_array_equal(B, [alone[k][1][0] for k in order])
    assert problems == [(i, level, message) for i, k in enumerate(order) for _, level, message in alone[k][2]]
    assert not np.isnan(A[order == 7]).any()  # ISO VG 220 with VI 95
