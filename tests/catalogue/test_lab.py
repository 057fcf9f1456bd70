"""The bearings of the DP11A lab rig: the DP11A manual table 3 (tables/lab_bearings.csv)."""
from __future__ import annotations

import re

import pytest

from bearingheat.catalogue.lab import lab_bearing, radial_static_load_factors
from bearingheat.errors import LabError


def test_lab_bearings_of_table_3():
    assert [lab_bearing(b)["C0"] for b in ("1000095", "18", "101")] == [392.0, 1354.0, 2227.0]
    assert [lab_bearing(b)["dm"] for b in ("1000095", "18", "101")] == [9.0, 13.5, 20.0]


def test_unknown_lab_bearing():
    with pytest.raises(LabError, match=re.escape("bearing '6205' is not in the DP11A manual table 3; expected one of "
                                                 "1000095, 18, 101")):
        lab_bearing("6205")


def test_radial_static_load_factors_of_table_1():
    assert radial_static_load_factors() == (0.6, 0.5)
