"""Static load factors X0, Y0 of angular contact ball bearings against the contact angle (the DP11A manual, table 1)."""
import math
import re

import numpy as np
import pandas as pd
import pytest

from bearingheat.catalogue import contact as ct
from bearingheat.catalogue.tables import load_table
from bearingheat.errors import ContactInputError


# ----------------------------------------------------------------------------- static load factors
def test_static_load_factor_table_rows_read_back():
    table = load_table("static_load_factors")
    rows = table[table["bearing_type"] == "angular_contact_ball"]
    # The DP11A manual, table 1: alpha, X0, Y0; Schaeffler HR 1 (2006) p. 237: 40 deg, P0 = 0,5 · F0r + 0,26 · F0a
    assert rows[["contact_angle", "X0", "Y0"]].values.tolist() == [
        [18, 0.5, 0.43], [20, 0.5, 0.42], [26, 0.5, 0.37], [30, 0.5, 0.33], [36, 0.5, 0.28], [40, 0.5, 0.26]]


def test_y0_interpolation():
    assert ct.y0_for_contact_angle([18, 20, 26, 30, 36, 40]) == pytest.approx([0.43, 0.42, 0.37, 0.33, 0.28, 0.26])
    assert ct.y0_for_contact_angle(38.0) == pytest.approx(0.27)  # halfway between 36 and 40 deg
    assert ct.y0_for_contact_angle([19, 23, 28, 33]) == pytest.approx([0.425, 0.395, 0.35, 0.305])
    assert ct.x0_for_contact_angle(np.array([18.0, 27.3, 36.0])) == pytest.approx([0.5, 0.5, 0.5])
    series = ct.y0_for_contact_angle(pd.Series([20.0, np.nan, 28.0], index=[4, 5, 6]))
    assert list(series.index) == [4, 5, 6] and math.isnan(series[5]) and series[6] == pytest.approx(0.35)


def test_y0_refused_outside_the_table():
    with pytest.raises(ContactInputError, match=re.escape(
            "alpha = 14.4658 deg is outside the contact angles of the static load factors (18 to 40 deg: the DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, 40 deg); "
            "Y0 is not extrapolated")):
        ct.y0_for_contact_angle(14.4658)
    with pytest.raises(ContactInputError, match=re.escape(
            "alpha = 45 deg is outside the contact angles of the static load factors (18 to 40 deg: the DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, 40 deg); "
            "Y0 is not extrapolated (row b)")) as info:
        ct.y0_for_contact_angle(pd.Series([20.0, 45.0], index=["a", "b"]))
    assert info.value.row == "b"
    with pytest.raises(ContactInputError, match=re.escape(
            "alpha = 17.9 deg is outside the contact angles of the static load factors (18 to 40 deg: the DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, 40 deg); "
            "X0 is not extrapolated (element 1)")):
        ct.x0_for_contact_angle(np.array([20.0, 17.9]))
