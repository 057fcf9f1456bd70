"""Sizing of DU/DP bushings and thrust washers with units (the DU/DP bushing handbook)."""
from __future__ import annotations

import math

import pytest

from bearingheat.api import bushing as bu
from bearingheat.api.bushing import size_bushing
from bearingheat.errors import BushingInputError
from bearingheat.catalogue.bushing import KGF_PER_CM2
from bearingheat.units import ureg


def test_size_bushing_with_quantities_and_temperature():
    u = ureg()
    cold = bu.size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
                           load_type="rotating_fixed_load_point")
    hot = bu.size_bushing(2000 * u.N, 500 * u.rpm, 2.5 * u.cm, shaft="soft", life=1000 * u.h,
                          load_type="rotating_fixed_load_point", T=u.Quantity(200, "degC"))
    assert hot.temperature_factor == 0.75
    assert hot.l_pV.to("mm").magnitude == pytest.approx(cold.l_pV.to("mm").magnitude / 0.75)


def test_size_thrust_washer_governed_by_pressure():
    # slow (V = 0.054 m/s at the mean diameter), heavy axial load: D from [p] = sqrt(d^2 + 4F/(pi [p]))
    u = ureg()
    out = bu.size_thrust_washer(20 * u.kN, 25 * u.rpm, 30 * u.mm, shaft="hardened", life=1000 * u.h,
                                load_type="moving_load_severe")
    expected = math.sqrt(30 ** 2 + 4 * 20000 / (math.pi * 141 * KGF_PER_CM2))
    assert out.governing == "pressure"
    assert out.D_required.to("mm").magnitude == pytest.approx(expected)


def test_bushing_result_is_a_result_with_status_and_frame():
    """The sizing is the API's common result type: status per point, to_frame with 'name [unit]', to_dict as JSON."""
    u = ureg()
    out = bu.size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
                          load_type="rotating_fixed_load_point", standard_lengths=[20, 30, 50, 100] * u.mm)
    assert (out.status, out.messages) == (["ok"], [""])
    frame = out.to_frame()
    assert frame.loc[0, "l_standard [mm]"] == 100.0 and frame.loc[0, "status"] == "ok"
    assert frame.loc[0, "pV [N/mm^2*m/s]"] == pytest.approx(0.8 * 0.654498, rel=1e-6)  # p·V = F/(d·l)·π·d·n/60000
    assert out.to_dict()["l_standard [mm]"] == 100.0 and out.to_dict()["kind"] == "bushing"
    assert repr(out).splitlines()[0] == "BushingSize: 1 point (1 ok)"


def test_bushing_outside_the_life_line_is_a_warning():
    # pV = 2 N/mm²·m/s lies above the fig. 86 line (0.353 to 1.765): the size is computed, the life is unknown
    u = ureg()
    out = bu.size_bushing(2 * u.kN, 50 * u.rpm, 25 * u.mm, K=2 * u("N/mm^2*m/s"), load_type="static")
    assert out.status == ["warning"]
    assert out.messages == ["life_fig86: pV = 2 N/mm²*m/s is outside the two-point fit of the DU/DP bushing handbook "
                            "fig. 86 (0.353 to 1.765 N/mm²*m/s, i.e. 3.6 to 18 kgf/cm²*m/s)"]
    assert math.isnan(out.life_fig86.to("h").magnitude)
    washer = bu.size_thrust_washer(20 * u.kN, 25 * u.rpm, 30 * u.mm, shaft="hardened", life=1000 * u.h,
                                   load_type="moving_load_severe")
    assert type(washer).__name__ == "ThrustWasherSize" and washer.to_dict()["kind"] == "thrust_washer"


@pytest.mark.parametrize("f, message", [(-0.1, "f = -0.1: expected a friction coefficient > 0 and <= 1"),
                                        (float("nan"), "f = nan: expected a friction coefficient > 0 and <= 1"),
                                        (5.0, "f = 5: expected a friction coefficient > 0 and <= 1")])
def test_a_friction_coefficient_out_of_its_range_is_refused(f, message):
    u = ureg()
    with pytest.raises(BushingInputError) as exc:
        size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h, load_type="static", f=f)
    assert str(exc.value) == message


def test_no_power_loss_above_5_m_s_without_f_is_a_warning():
    """The handbook's friction coefficients end at V = 5 m/s: N is NaN there, so the status says why."""
    u = ureg()
    out = size_bushing(2 * u.kN, 4600 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h, load_type="static")
    assert out.status == ["warning"]
    assert out.messages == ["N: the DU/DP bushing handbook gives no friction coefficient above V = 5 m/s; give f for "
                            "the power loss"]
    with_f = size_bushing(2 * u.kN, 4600 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h, load_type="static",
                          f=0.1 * u.dimensionless)
    assert with_f.N_low.to("W").magnitude == pytest.approx(0.1 * 2000 * with_f.V.to("m/s").magnitude, rel=1e-12)


def test_a_sizing_is_of_one_bushing():
    import numpy as np
    u = ureg()
    with pytest.raises(BushingInputError) as exc:
        size_bushing(np.array([1.0, 2.0]) * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
                     load_type="static")
    assert str(exc.value) == "F: 2 values; a sizing is of one bushing, so give one F (and loop over the cases)"
