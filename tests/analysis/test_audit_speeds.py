"""The reference-speed audit on lists it could not fully use: few series, cells that are no published speed."""
from __future__ import annotations

import numpy as np

from bearingheat.analysis.audit import audit_reference_speeds, classify_reference_speeds
from bearingheat.analysis.deviations import consistent_scale
from bearingheat.catalogue.bearings import bearing_table
from bearingheat.io.reports.audit import reference_speed_lines

HR1_COLUMNS = {"d": "d [mm]", "D": "D [mm]", "B": "B [mm]", "T": "T [mm]", "C0": "C0 [N]", "n_thr": "n_thr [1/min]"}


def test_too_few_series_keep_none_and_sigma_is_the_floor():
    sigma, kept = consistent_scale([-0.175, -0.154], z=5.0, floor=0.002, min_groups=5)
    assert sigma == 0.002 and kept.tolist() == [False, False]
    # three of five agree: too few to estimate from after clipping, none kept
    sigma, kept = consistent_scale([0.001, -0.002, 0.0015, 0.2, -0.15], z=5.0, floor=0.002, min_groups=5)
    assert sigma == 0.002 and not kept.any()


def test_two_series_say_sigma_is_the_floor_not_the_scale_of_series_that_agree():
    """618 and 313 of HR 1 alone: the text called 0.20 % the robust scale of '2 series that agree with the
    tables' and then flagged both."""
    hr1 = bearing_table().rename(columns=HR1_COLUMNS)
    keys = audit_reference_speeds(hr1)["series_key"]
    two = hr1[keys.isin(["deep groove ball 618", "tapered roller 313"]).to_numpy()]
    audit = classify_reference_speeds(audit_reference_speeds(two))
    assert (audit.scale, audit.consistent, audit.series) == (0.002, 0, 2)
    assert reference_speed_lines(audit)[1] == (
        "sigma = 0.20% (the floor, not estimated from the data: of the 2 series, fewer than 5 agree with the "
        "tables, too few for a robust scale); threshold = +/-1.00%.")
    # the whole list: 14 series give sigma, as before
    whole = classify_reference_speeds(audit_reference_speeds(hr1))
    assert whole.consistent == 14 and np.isclose(whole.scale, 0.0029, atol=5e-5)
    assert reference_speed_lines(whole)[1].startswith(
        "sigma = 0.29% (robust scale of the median deviations of the 14 series that agree with the tables)")
