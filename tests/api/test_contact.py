"""Ball bearing contact with units (Zaitsev & Voronkin): unit invariance, the clearance route, unit errors."""
import math

import numpy as np
import pytest

from bearingheat.api import contact as ct
from bearingheat.errors import ContactInputError, UnitError
from bearingheat.kernels.contact import KGF
from bearingheat.units import ureg

# Zaitsev & Voronkin, example: bearing 4-1006095 (5 x 13 x 4 mm; the seed's table swaps D and d).
Z, DW, DM, ALPHA0, RI, RO = 7, 2.0, 8.7355, 12.0, 1.05, 1.16
FA_SEED = 2.0 * KGF


def test_ball_bearing_contact_unit_invariance():
    u = ureg()
    mm = ct.ball_bearing_contact(z=Z, d_w=DW * u.mm, d_m=DM * u.mm, r_i=RI * u.mm, r_o=RO * u.mm,
                                 alpha0=ALPHA0 * u.deg, Fa=2 * u.kgf, n=3000 * u.rpm)
    si = ct.ball_bearing_contact(z=Z, d_w=(DW / 25.4) * u.inch, d_m=(DM * 1e-3) * u.m, r_i=(RI * 1e3) * u.um,
                                 r_o=(RO / 10) * u.cm, alpha0=math.radians(ALPHA0) * u.rad,
                                 Fa=(FA_SEED / 1000) * u.kN, n=50 * u.Hz)
    a, b = mm.to_dict(), si.to_dict()
    assert a.keys() == b.keys()
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=1e-9), key
    assert mm.C_star.to("kgf").magnitude == pytest.approx(7.79e3, rel=0.003)


def test_ball_bearing_contact_from_clearance():
    u = ureg()
    e = 2 * (RI + RO - DW) * (1 - math.cos(math.radians(ALPHA0)))
    r = ct.ball_bearing_contact(z=Z, d_w=DW * u.mm, d_m=DM * u.mm, r_i=RI * u.mm, r_o=RO * u.mm,
                                clearance=e * 1000 * u.um, Fa=2 * u.kgf)
    assert r.alpha0.to("deg").magnitude == pytest.approx(ALPHA0, abs=1e-9)
    assert r.delta_a.to("mm").magnitude == pytest.approx(r.xi_a.magnitude * 0.21, rel=1e-12)
    assert r.Fa_min is None and "Fa_min [N]" not in r.to_dict()
    assert ct.contact_angle_from_clearance(e * u.mm, RI * u.mm, RO * u.mm, DW * u.mm).to("deg").magnitude == (
        pytest.approx(ALPHA0))


def test_unit_errors_exact_messages():
    u = ureg()
    geometry = dict(z=Z, d_w=DW * u.mm, d_m=DM * u.mm, r_i=RI * u.mm, r_o=RO * u.mm)
    with pytest.raises(UnitError) as info:
        ct.ball_bearing_contact(**geometry, alpha0=u.Quantity(12.0))
    assert str(info.value) == "alpha0: 12.0 has no unit; write it as an angle, e.g. 12.0 deg"
    with pytest.raises(UnitError) as info:
        ct.ball_bearing_contact(**{**geometry, "d_w": 2.0}, alpha0=12 * u.deg)
    assert str(info.value) == ("d_w: expected a pint Quantity in mm (for example 2.5 * ureg('mm')); "
                               "got a plain float 2.0")
    with pytest.raises(UnitError) as info:
        ct.ball_bearing_contact(**geometry, alpha0=12 * u.deg, Fa=2 * u.kg)
    assert str(info.value) == "Fa: 2 kilogram is a mass, not a force; for kilogram-force write 2 kgf"
    with pytest.raises(ContactInputError) as info:
        ct.ball_bearing_contact(**geometry, alpha0=12 * u.deg, clearance=0.01 * u.mm)
    assert str(info.value) == "give exactly one of alpha0 (an angle) or clearance (the mean radial clearance)"


def test_ball_contact_is_a_result_with_a_warning_below_the_minimum_axial_load():
    """Per point status: Fa below Fa_min (gyroscopic sliding, at α0) is a warning; to_frame as calc's headers."""
    u = ureg()
    r = ct.ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
                             alpha0=12 * u.deg, Fa=np.array([0.1, 20.0]) * u.gram_force, n=3000 * u.rpm)
    minimum = r.Fa_min.to("N").magnitude
    assert minimum == pytest.approx(0.01019, abs=5e-6)  # the value of the docstring example, 10.19 mN
    assert r.status == ["warning", "ok"]  # 0.1 gf = 0.98 mN < 10.19 mN < 20 gf = 196 mN
    assert r.messages[0] == ("Fa = 0.0009807 N is below the minimum axial load Fa_min = 0.01019 N at n = 3000 1/min "
                             "(gyroscopic sliding of the balls, Zaitsev & Voronkin)")
    assert r.messages[1] == ""
    frame = r.to_frame()
    assert list(frame["status"]) == ["warning", "ok"] and "alpha [deg]" in frame.columns
    assert repr(r).splitlines()[0] == "BallContact: 2 points (1 ok, 1 warning)"
    without_speed = ct.ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
                                         alpha0=12 * u.deg, Fa=0.1 * u.gram_force)
    assert without_speed.status == ["ok"]  # no speed: no minimum load to compare with


def _minimum_axial_load_by_hand(alpha_deg, n=30000.0, z=7, dw=2.0, d0=8.7355):
    """Zaitsev & Voronkin, p. 1: 5.75e-12·z·d_w³·D0·n²·sin²α·[1 − (d_w/D0)²·cos²α] kgf, in N."""
    a = math.radians(alpha_deg)
    return 5.75e-12 * z * dw**3 * d0 * n**2 * math.sin(a) ** 2 * (1 - (dw / d0) ** 2 * math.cos(a) ** 2) * KGF


def test_a_load_between_the_minimum_at_alpha0_and_at_the_working_angle_is_a_warning():
    """30 000 1/min, Fa = 1.05 N: Fa_min = 1.019 N at α0 = 12° (the paper's rule) is met, but Fa turns the angle to
    12.42° (by bisection of Fa = C*·(cos α0/cos α − 1)^1.5·sin α with the result's C*), where the minimum is 1.091 N:
    a warning (it used to be 'ok'). 1.0 N is below both (the old warning), 1.1 N above both."""
    u = ureg()
    r = ct.ball_bearing_contact(z=Z, d_w=DW * u.mm, d_m=DM * u.mm, r_i=RI * u.mm, r_o=RO * u.mm, alpha0=ALPHA0 * u.deg,
                                Fa=np.array([1.0, 1.05, 1.1]) * u.N, n=30000 * u.rpm)
    c_star = r.C_star.to("N").magnitude
    a0, low, high = math.radians(ALPHA0), math.radians(ALPHA0), math.radians(30.0)
    for _ in range(100):
        mid = 0.5 * (low + high)
        load = c_star * (math.cos(a0) / math.cos(mid) - 1) ** 1.5 * math.sin(mid)
        low, high = (mid, high) if load < 1.05 else (low, mid)
    working = math.degrees(low)
    assert working == pytest.approx(12.4223, abs=1e-4)
    assert r.Fa_min.to("N").magnitude == pytest.approx(_minimum_axial_load_by_hand(ALPHA0), rel=1e-9)
    assert r.Fa_min.to("N").magnitude == pytest.approx(1.019, abs=5e-4)
    assert r.Fa_min_at_alpha.to("N").magnitude[1] == pytest.approx(_minimum_axial_load_by_hand(working), rel=1e-9)
    assert r.Fa_min_at_alpha.to("N").magnitude[1] == pytest.approx(1.091, abs=5e-4)
    assert r.status == ["warning", "warning", "ok"]
    assert r.messages[0] == ("Fa = 1 N is below the minimum axial load Fa_min = 1.019 N at n = 30000 1/min "
                             "(gyroscopic sliding of the balls, Zaitsev & Voronkin)")
    assert r.messages[1] == ("Fa = 1.05 N meets the minimum axial load at the initial angle alpha0 = 12 deg, "
                             "Fa_min = 1.019 N (Zaitsev & Voronkin's rule), but not the stricter one at the working "
                             "angle alpha = 12.42 deg under this load, Fa_min at alpha = 1.091 N, at n = 30000 1/min: "
                             "the balls may slide under their gyroscopic moment")
    assert r.messages[2] == ""


def test_a_load_above_the_stands_20_percent_is_no_warning():
    """Zaitsev & Voronkin, p. 3: the stand load may exceed the computed nominal one by at most 20 %; that chooses the
    load of a vibration test, it does not bound the contact formulas: 1.5 N at 30 000 1/min (1.47 times Fa_min =
    1.019 N at α0, 1.35 times the 1.110 N at its working angle) and the paper's 2 kgf at 3000 1/min are 'ok'."""
    u = ureg()
    r = ct.ball_bearing_contact(z=Z, d_w=DW * u.mm, d_m=DM * u.mm, r_i=RI * u.mm, r_o=RO * u.mm, alpha0=ALPHA0 * u.deg,
                                Fa=np.array([1.5, FA_SEED]) * u.N, n=np.array([30000, 3000]) * u.rpm)
    assert r.Fa.to("N").magnitude[0] > 1.2 * r.Fa_min_at_alpha.to("N").magnitude[0]
    assert r.status == ["ok", "ok"] and r.messages == ["", ""]


def test_plausibility_warnings_of_fa_and_n_are_per_point():
    """Fa above 1e8 N or n above 2e5 1/min are kept with a warning (the contract's plausible ranges), on the points
    that have them, before the minimum-load warning of the same point."""
    u = ureg()
    geometry = dict(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm, alpha0=12 * u.deg)
    r = ct.ball_bearing_contact(**geometry, Fa=np.array([2.0, 2e8]) * u.N, n=3000 * u.rpm)
    assert r.status == ["ok", "warning"]
    assert r.messages == ["", "Fa: 2e+08 is outside the plausible range up to 1e+08 N; check the number and its unit"]
    fast = ct.ball_bearing_contact(**geometry, Fa=2 * u.kgf, n=3e5 * u.rpm)
    assert fast.status == ["warning"]
    assert fast.messages == [
        "n: 300000 is outside the plausible range up to 200000 1/min; check the number and its unit; Fa = 19.61 N is "
        "below the minimum axial load Fa_min = 101.9 N at n = 300000 1/min (gyroscopic sliding of the balls, "
        "Zaitsev & Voronkin)"]
    # speeds as an array with one load (or none): a status per speed
    speeds = ct.ball_bearing_contact(**geometry, Fa=2 * u.kgf, n=np.array([3000.0, 4000.0, 3e5]) * u.rpm)
    assert speeds.status == ["ok", "ok", "warning"]
    assert ct.ball_bearing_contact(**geometry, n=np.array([3000.0, 3e5]) * u.rpm).messages == [
        "", "n: 300000 is outside the plausible range up to 200000 1/min; check the number and its unit"]


@pytest.mark.parametrize("changes, message", [
    (dict(Fa=float("nan")), "Fa: nan is not a number; leave the argument out where it is not known"),
    (dict(Fa=1e300), "Fa: 1e+300 is outside the valid range up to 1e+10 N"),
    (dict(z=float("inf")), "z: inf is not a finite number"),
    (dict(alpha0=float("nan")), "alpha0: nan is not a finite number"),
    (dict(d_w=float("nan")), "d_w: nan is not a finite number"),
    (dict(n=float("nan")), "n: nan is not a number; leave the argument out where it is not known"),
])
def test_numbers_that_are_not_finite_are_refused_by_name(changes, message):
    """A kernel carries NaN and inf through to every result; the API says which argument holds one (a load so
    large that no angle can be bracketed is outside the valid range)."""
    u = ureg()
    args = dict(z=7, d_w=2.0, d_m=8.7355, r_i=1.05, r_o=1.16, alpha0=12.0, Fa=1.0, n=3000.0)
    args.update(changes)
    units = dict(d_w=u.mm, d_m=u.mm, r_i=u.mm, r_o=u.mm, alpha0=u.deg, Fa=u.N, n=u.rpm)
    quantities = {k: (v * units[k] if k in units else v) for k, v in args.items()}
    with pytest.raises(ContactInputError) as exc:
        ct.ball_bearing_contact(**quantities)
    assert str(exc.value) == message


def test_series_in_series_out_with_their_index():
    pd = pytest.importorskip("pandas")
    pytest.importorskip("pint_pandas")
    u = ureg()
    geometry = dict(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm)
    Fa = pd.Series([0.5, 1.0, 2.0], index=[10, 20, 30], dtype="pint[kgf]")
    result = ct.ball_bearing_contact(**geometry, alpha0=12 * u.deg, Fa=Fa, n=3000 * u.rpm)
    assert result.to_frame().index.tolist() == [10, 20, 30]
    one = ct.ball_bearing_contact(**geometry, alpha0=12 * u.deg, Fa=1.0 * u.kgf, n=3000 * u.rpm)
    assert result.to_dict()["alpha [deg]"][1] == pytest.approx(one.to_dict()["alpha [deg]"], rel=1e-12)
    with pytest.raises(ContactInputError) as exc:
        ct.ball_bearing_contact(**geometry, alpha0=pd.Series([12.0] * 3, index=[30, 20, 10], dtype="pint[deg]"), Fa=Fa)
    assert str(exc.value).startswith("alpha0 and Fa are Series with different indexes")
