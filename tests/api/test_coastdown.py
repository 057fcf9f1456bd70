"""Coast-down analysis with pint Quantities (the unit boundary), and real data: Liu et al. (2024) fig. 6."""
from __future__ import annotations

import math
import pathlib
import re

import numpy as np
import pandas as pd
import pytest
from coastdown_helpers import integrate_rundown

from bearingheat.api.coastdown import analyse_coastdown
from bearingheat.errors import UnitError
from bearingheat.kernels.coastdown import plain_torque
from bearingheat.units import ureg

DATA = pathlib.Path(__file__).resolve().parents[2] / ".." / "shared" / "data"
LIU = DATA / "coastdown_centrifuge_spindown_liu2024_fig6.csv"


def test_result_invariant_to_speed_unit():
    u = ureg()
    t, n, _ = integrate_rundown(plain_torque(0.55), 2.6, 930.0, 4.0, 2.0, 1)
    in_rpm = analyse_coastdown(t * u.s, n * u.rpm)
    in_rad = analyse_coastdown((t / 60) * u.min, (n * math.pi / 30) * u("rad/s"), I=2.6 * u("kg*m^2"),
                               G=1.1 * u.kN, r=0.025 * u.m)
    assert in_rad.model == in_rpm.model
    assert in_rad.f_constant == pytest.approx(in_rpm.f_constant, rel=1e-6)


def test_inertia_with_wrong_unit_message():
    u = ureg()
    with pytest.raises(UnitError, match=re.escape(
            "I: 2.6 kilogram cannot be converted to kg*m^2 "
            "(dimension [mass], expected [mass] * [length] ** 2)")):
        analyse_coastdown(np.arange(12.0) * u.s, (100 - np.arange(12.0)) * u.rpm, I=2.6 * u.kg)


# ----------------------------------------------------------------- real data: Liu et al. (2024) fig. 6
@pytest.mark.skipif(not LIU.exists(), reason="../shared/data (Liu 2024 centrifuge run-down) not available")
def test_liu2024_centrifuge_constant_torque_matches_published_11_Nm():
    data = pd.read_csv(LIU)
    u = ureg()
    for pressure, group in data.groupby("chamber_pressure_kPa"):
        result = analyse_coastdown(group["time_s"].to_numpy() * u.s,
                                   group["angular_speed_rad_s"].to_numpy() * u("rad/s"),
                                   I=845.69 * u("kg*m^2"), G=None, r=None)
        # the seed's constant-f view: published M_f = I*beta = 10.99 N*m (Liu et al. 2024)
        assert result.fits["coulomb"].value("M_c") == pytest.approx(10.99, abs=0.1)
        # the curves are concave: a speed-dependent model fits n(t) better than constant torque ...
        assert result.model != "coulomb"
        assert result.rmse_after < 0.75 * result.rmse_before
        # ... with the torque falling with speed (negative c_v), not a viscous drag
        assert result.fits["coulomb_viscous"].value("c_v") < 0
        assert math.isnan(result.f_constant)
