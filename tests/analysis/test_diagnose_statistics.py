"""diagnose's statistics: bounds the training fold sets, parameters on their bounds, the influence of single
readings, the error measure the choice uses."""
from __future__ import annotations

import numpy as np
import pytest
from synthetic_torque import measured_set

from bearingheat.analysis.diagnose import model_data, read_measurements
from bearingheat.analysis.effects import CANDIDATES


def _data(effect, seed, designations):
    table, _, _ = measured_set(effect, seed, designations=list(designations))
    return model_data(read_measurements(table))[0]


def test_run_in_takes_its_tau_bounds_from_the_rows_it_fits_not_the_held_out_ones():
    """A training fold's τ was bounded by the time span of the whole data set, held-out rows included, so what a
    fold could fit depended on the rows it was tested on. Fitted on the rows up to 6 h (τ of the data 10-25 h),
    τ now ends at the 6 h those rows span, exactly as when the other rows are not there at all."""
    data = _data("run_in", 101, ("6205", "6310"))
    train = np.flatnonzero(data.t <= 6.0)
    assert 0 < len(train) < len(data) and float(np.ptp(data.t)) > 100.0
    run_in = CANDIDATES["run_in"]
    in_fold = run_in.fit(data, train)
    alone = run_in.fit(data.take(train), np.arange(len(train)))
    assert in_fold["tau"] == pytest.approx(alone["tau"], rel=1e-12)
    assert in_fold["a"] == pytest.approx(alone["a"], rel=1e-12)
    assert in_fold["tau"] <= float(np.ptp(data.t[train])) * (1 + 1e-12)
