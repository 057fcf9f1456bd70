"""Sizing of DU/DP bushings and thrust washers with units (the DU/DP bushing handbook)."""
from __future__ import annotations

import math

import pytest

from bearingheat.api import bushing as bu
from bearingheat.catalogue.bushing import KGF_PER_CM2
from bearingheat.units import ureg


def test_size_bushing_with_quantities_and_temperature():
    u = ureg()
    cold = bu.size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
                           load_type="rotating_fixed_load_point")
    hot = bu.size_bushing(2000 * u.N, 500 * u.rpm, 2.5 * u.cm, shaft="soft", life=1000 * u.h,
                          load_type="rotating_fixed_load_point", T=u.Quantity(200, "degC"))
    assert hot["temperature_factor"] == 0.75
    assert hot["l_pV [mm]"].to("mm").magnitude == pytest.approx(cold["l_pV [mm]"].to("mm").magnitude / 0.75)


def test_size_thrust_washer_governed_by_pressure():
    # slow (V = 0.054 m/s at the mean diameter), heavy axial load: D from [p] = sqrt(d^2 + 4F/(pi [p]))
    u = ureg()
    out = bu.size_thrust_washer(20 * u.kN, 25 * u.rpm, 30 * u.mm, shaft="hardened", life=1000 * u.h,
                                load_type="moving_load_severe")
    expected = math.sqrt(30 ** 2 + 4 * 20000 / (math.pi * 141 * KGF_PER_CM2))
    assert out["governing"] == "pressure"
    assert out["D_required [mm]"].to("mm").magnitude == pytest.approx(expected)
