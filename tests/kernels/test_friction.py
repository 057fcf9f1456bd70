"""The catalogue friction model against hand calculations from the Schaeffler catalogue formulas.

Each case types the seed's coefficients as literals and works the formulas
out in plain arithmetic, independently of the kernels.
"""
import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingheat.kernels import friction
from bearingheat.calc.models import compute_supports


def m0_hand(f0, nu, n, dM):
    """The Schaeffler catalogue p. 64"""
    return f0 * ((nu * n) ** (2 / 3) if nu * n >= 2000 else 160) * dM ** 3 * 1e-7


HIGH = dict(n=3000.0, nu=12.0)   # ν·n = 36000
LOW = dict(n=100.0, nu=10.0)     # ν·n = 1000

# designation, inputs, f0 (the seed's value), f1 (hand), M1 load (hand)
CASES = [
    ("NA4905", dict(d=25, D=42, lubrication="oil_bath", Fr=3000), 5.5, 0.0005, 3000),
    ("HK2016", dict(D=26, lubrication="grease", Fr=1000), 24 * 16 / (33 + 20), 0.0005, 1000),
    ("SL182205", dict(d=25, D=47, lubrication="grease", Fr=4000), 5, 0.00055, 4000),
    ("NU206-E", dict(d=30, D=62, lubrication="grease", Fr=5000), 1.3, 0.0003, 5000),
    ("81105", dict(d=25, D=42, lubrication="oil_bath", Fa=6000), 3, 0.0015, 6000),
    ("NKX20", dict(d=20, D=30, C0=10000, lubrication="grease", Fr=500, Fa=1000), 2,
     0.001 * (1000 / 10000) ** 0.33, 1000),
    ("30205-A", dict(d=25, D=52, C0=34500, Y=1.6, lubrication="oil_bath", Fr=4000, Fa=1500), 3, 0.0004,
     max(2 * 1.6 * 1500, 4000)),
    ("22210-E1", dict(d=50, D=90, C0=134000, e=0.24, X0=1.0, Y0=2.8, lubrication="oil_bath", Fr=10000, Fa=1000), 4,
     0.0005 * (max(10000 + 2.8 * 1000, 10000) / 134000) ** 0.33, 10000 * (1 + 0.6 * (1000 / (0.24 * 10000)) ** 3)),
    ("29412-E", dict(d=60, D=130, lubrication="circulating_oil", Fa=20000), 3.3, 0.00033, 20000),
    ("6205", dict(d=25, D=52, C0=7800, lubrication="oil_bath", Fr=1000, Fa=800), 2,
     0.0009 * (max(0.6 * 1000 + 0.5 * 800, 1000) / 7800) ** 0.5, max(3.3 * 800 - 0.1 * 1000, 1000)),
    ("7205-B", dict(d=25, D=52, C0=9300, Y0=0.26, lubrication="grease", Fr=1000, Fa=2000), 1.3,
     0.001 * (max(0.5 * 1000 + 0.26 * 2000, 1000) / 9300) ** 0.33, max(2000 - 0.1 * 1000, 1000)),
    ("7205", dict(d=25, D=52, C0=9300, alpha=30, lubrication="grease", Fr=1000, Fa=2000), 1.3,
     0.001 * (max(0.5 * 1000 + 0.33 * 2000, 1000) / 9300) ** 0.33, max(2000 - 0.1 * 1000, 1000)),
    ("3205-B", dict(d=25, D=52, C0=15000, X0=1, Y0=0.66, lubrication="oil_bath", Fr=2000, Fa=1500), 3.5,
     0.001 * (max(2000 + 0.66 * 1500, 2000) / 15000) ** 0.33, max(1.4 * 1500 - 0.1 * 2000, 2000)),
    ("1205", dict(d=25, D=52, C0=4400, lubrication="grease", Fr=1500), 1, 0.0003 * (1500 / 4400) ** 0.4, 1500),
    ("QJ210", dict(d=50, D=90, C0=40000, X0=1, Y0=0.58, lubrication="oil_bath", Fr=500, Fa=4000), 4,
     0.001 * (max(500 + 0.58 * 4000, 500) / 40000) ** 0.33, 1.5 * 4000 + 3.6 * 500),
    ("51105", dict(d=25, D=42, C0=30000, lubrication="grease", Fa=3000), 1, 0.0012 * (3000 / 30000) ** 0.33, 3000),
]


@pytest.mark.parametrize("regime", [HIGH, LOW], ids=["nu_n>=2000", "nu_n<2000"])
@pytest.mark.parametrize("designation,inputs,f0,f1,load", CASES, ids=[c[0] for c in CASES])
def test_hand_calculation_every_type(designation, inputs, f0, f1, load, regime):
    row = {"designation": designation, **inputs, **regime}
    out = compute_supports(pd.DataFrame([row])).iloc[0]
    assert out["status"] in ("ok", "warning"), out["message"]
    d = inputs.get("d", 20)  # HK2016: bore from the designation
    dM = (d + inputs["D"]) / 2
    M0 = m0_hand(f0, regime["nu"], regime["n"], dM)
    M1 = f1 * load * dM
    assert out["f0"] == pytest.approx(f0, rel=1e-12)
    assert out["f1"] == pytest.approx(f1, rel=1e-12)
    assert out["M0"] == pytest.approx(M0, rel=1e-12)
    assert out["M1"] == pytest.approx(M1, rel=1e-12)
    assert out["MR"] == pytest.approx(M0 + M1, rel=1e-12)
    assert out["NR"] == pytest.approx((M0 + M1) * regime["n"] / 9550, rel=1e-12)


def test_all_bearing_types_covered():
    types = set(compute_supports(pd.DataFrame([{"designation": c[0], **c[1], **HIGH} for c in CASES]))["bearing_type"])
    from bearingheat.catalogue.designation import BEARING_TYPES
    assert types == set(BEARING_TYPES)


def test_m2_hand_calculation_nj_bearing():
    """The Schaeffler catalogue p. 69: M_R = M0 + M1 + M2, M2 = f2*Fa*dM, A = kB*1e-3*dM^2.1 (kB = 15 for NJ2..-E)."""
    row = dict(designation="NJ206-E", d=30, D=62, lubrication="circulating_oil", n=3000, nu=20, Fr=5000, Fa=1000,
               f2=0.004)
    out = compute_supports(pd.DataFrame([row])).iloc[0]
    dM = 46.0
    assert out["M2"] == pytest.approx(0.004 * 1000 * dM, rel=1e-12)
    assert out["MR"] == pytest.approx(m0_hand(2, 20, 3000, dM) + 0.0003 * 5000 * dM + 0.004 * 1000 * dM, rel=1e-12)
    assert out["Fa_over_A"] == pytest.approx(1000 / (15 * 1e-3 * dM ** 2.1), rel=1e-12)
    assert out["nu_n_dM"] == pytest.approx(20 * 3000 * dM, rel=1e-12)


def test_regime_step_at_2000_is_the_printed_one():
    """At ν·n = 2000 the formula steps from 160 to 2000^(2/3) = 158.74: a drop of 0.79 %."""
    below = friction.speed_dependent_torque(1.0, 2000 * (1 - 1e-12), 1.0, 10.0)
    at = friction.speed_dependent_torque(1.0, 2000.0, 1.0, 10.0)
    assert below == 160 * 1000 * 1e-7
    assert at == pytest.approx(2000 ** (2 / 3) * 1000 * 1e-7, rel=1e-15)
    assert 2000 ** (2 / 3) == pytest.approx(158.7401052, abs=5e-8)
    assert 1 - at / below == pytest.approx(1 - 2000 ** (2 / 3) / 160, rel=1e-12)
    assert 1 - at / below == pytest.approx(0.0079, abs=1e-4)


def test_p1_never_below_fr_and_each_rule():
    Fr, Fa = 2000.0, 500.0
    assert friction.effective_load("radial_ball", Fr, Fa) == 2000.0            # 3.3*500-200 = 1450 < Fr
    assert friction.effective_load("radial_ball", Fr, 1000.0) == 3100.0
    assert friction.effective_load("angular_single", Fr, 3000.0) == 2800.0
    assert friction.effective_load("angular_paired", Fr, 3000.0) == pytest.approx(4000.0)
    assert friction.effective_load("angular_double_row", Fr, 3000.0) == pytest.approx(4000.0)
    assert friction.effective_load("four_point", Fr, Fa) == 1.5 * 500 + 3.6 * 2000
    assert friction.effective_load("tapered_single", Fr, 1000.0, Y=1.6) == 3200.0
    assert friction.effective_load("tapered_paired", Fr, 1000.0, Y=1.6) == 2000.0
    # spherical: both branches and their meeting point Fa/Fr = e
    assert friction.effective_load("spherical", 1000.0, 500.0, e=0.25) == pytest.approx(1.6 * 500 / 0.25)
    assert friction.effective_load("spherical", 1000.0, 250.0, e=0.25) == pytest.approx(1600.0)
    assert friction.effective_load("spherical", 1000.0, 0.0, e=np.nan) == 1000.0
    assert friction.effective_load("spherical", 0.0, 100.0, e=0.3) == pytest.approx(1.6 * 100 / 0.3)


def test_per_row_rule_arrays_match_scalar_rules():
    rules = np.array(["radial_ball", "four_point", "tapered_single", "spherical"], dtype=object)
    Fr = np.array([1000.0, 1000.0, 1000.0, 1000.0])
    Fa = np.array([800.0, 800.0, 800.0, 800.0])
    Y = np.array([np.nan, np.nan, 1.6, np.nan])
    e = np.array([np.nan, np.nan, np.nan, 0.3])
    vector = friction.effective_load(rules, Fr, Fa, Y, e)
    scalar = [friction.effective_load(r, 1000.0, 800.0, y, ee) for r, y, ee in zip(rules, Y, e)]
    np.testing.assert_allclose(vector, scalar, rtol=0)


def test_scalar_array_and_series_agree():
    n = np.array([50.0, 500.0, 3000.0, 12000.0])
    scalar = [friction.catalogue_friction_torque(2.0, 0.0003, 4000.0, 46.0, 15.0, x) for x in n]
    array = friction.catalogue_friction_torque(2.0, 0.0003, 4000.0, 46.0, 15.0, n)
    series = friction.catalogue_friction_torque(2.0, 0.0003, 4000.0, 46.0, 15.0, pd.Series(n, index=list("abcd")))
    np.testing.assert_allclose(array, scalar, rtol=0)
    assert isinstance(series, pd.Series) and list(series.index) == list("abcd")
    np.testing.assert_allclose(series.to_numpy(), scalar, rtol=0)
    assert isinstance(scalar[0], float)


def test_series_with_different_indexes_are_refused():
    with pytest.raises(ValueError, match="^speed_dependent_torque: Series arguments must share one index$"):
        friction.speed_dependent_torque(1.0, pd.Series([10.0], index=["a"]), pd.Series([10.0], index=["b"]), 40.0)


def test_power_loss_unit_check():
    """N_R [W] = M_R [N·mm] · n [1/min] / 9550: 1000 N·mm at 9550 1/min is 1000 W within 0.01 % (9550 rounds 30000/π = 9549.3)."""
    assert friction.power_loss(1000.0, 9550.0) == 1000.0
    exact = 1.0 * 9550 * 2 * math.pi / 60  # N·m · rad/s
    assert exact == pytest.approx(1000.0, rel=1e-4)


regime_nu = st.floats(0.5, 500.0)


@settings(max_examples=200, deadline=None)
@given(f0=st.floats(0.5, 10), nu=st.floats(0.5, 500), n1=st.floats(1, 20000), n2=st.floats(1, 20000),
       dM=st.floats(5, 500))
def test_m0_never_falls_as_speed_rises_within_a_regime(f0, nu, n1, n2, dM):
    lo, hi = sorted((n1, n2))
    same_regime = (nu * lo >= 2000) == (nu * hi >= 2000)
    if same_regime:
        assert friction.speed_dependent_torque(f0, nu, hi, dM) >= friction.speed_dependent_torque(f0, nu, lo, dM)


@settings(max_examples=200, deadline=None)
@given(f0=st.floats(0.5, 10), n=st.floats(1, 20000), nu1=st.floats(0.5, 500), nu2=st.floats(0.5, 500),
       dM=st.floats(5, 500))
def test_m0_never_falls_as_viscosity_rises_within_a_regime(f0, n, nu1, nu2, dM):
    lo, hi = sorted((nu1, nu2))
    if (lo * n >= 2000) == (hi * n >= 2000):
        assert friction.speed_dependent_torque(f0, hi, n, dM) >= friction.speed_dependent_torque(f0, lo, n, dM)


@settings(max_examples=200, deadline=None)
@given(Fr1=st.floats(0, 1e5), Fr2=st.floats(0, 1e5), Fa=st.floats(0, 5e4),
       rule=st.sampled_from(["radial_ball", "angular_single", "angular_paired", "four_point", "tapered_single",
                             "spherical"]))
def test_m1_never_falls_as_the_radial_load_rises(Fr1, Fr2, Fa, rule):
    lo, hi = sorted((Fr1, Fr2))
    kw = dict(Y=1.6, e=0.3)
    # f1 of a ball bearing grows with P0/C0 too: M1 = a*(P0/C0)^x*P1*dM
    def m1(Fr):
        P1 = friction.effective_load(rule, Fr, Fa, **kw)
        P0 = friction.static_equivalent_load(Fr, Fa, 0.6, 0.5)
        return friction.load_dependent_torque(friction.f1_from_load_ratio(0.0009, 0.5, P0 / 20000), P1, 40.0)
    assert m1(hi) >= m1(lo) * (1 - 1e-12)


@settings(max_examples=200, deadline=None)
@given(Fa1=st.floats(0, 5e4), Fa2=st.floats(0, 5e4), Fr=st.floats(0, 1e5),
       rule=st.sampled_from(["radial_ball", "angular_single", "angular_paired", "four_point", "tapered_single",
                             "spherical"]))
def test_m1_never_falls_as_the_axial_load_rises(Fa1, Fa2, Fr, rule):
    lo, hi = sorted((Fa1, Fa2))
    P_lo = friction.effective_load(rule, Fr, lo, Y=1.6, e=0.3)
    P_hi = friction.effective_load(rule, Fr, hi, Y=1.6, e=0.3)
    assert P_hi >= P_lo * (1 - 1e-12)


@settings(max_examples=300, deadline=None)
@given(ratio=st.floats(0.0, 50.0), x=st.sampled_from([0.0, 0.5, 0.33, 0.4, 1.0]), a=st.floats(1e-5, 1e-2))
def test_f1_is_a_times_the_ratio_to_the_power_x(ratio, x, a):
    """The table's f1 = a·ratio^x, to the last digits, in scalars and in arrays of mixed exponents."""
    hand = a * ratio ** x if x else a
    assert friction.f1_from_load_ratio(a, x, ratio) == pytest.approx(hand, rel=1e-15, abs=0.0)
    rows = friction.f1_from_load_ratio(np.array([a, a, a]), np.array([x, 0.5, 0.0]), np.array([ratio] * 3))
    assert rows.tolist() == pytest.approx([hand, a * math.sqrt(ratio), a], rel=1e-15, abs=0.0)


def test_f1_of_a_constant_coefficient_ignores_the_ratio_and_keeps_powers_sign():
    assert friction.f1_from_load_ratio(0.0004, 0.0, math.nan) == 0.0004  # x = 0: a constant f1, no ratio needed
    assert math.copysign(1.0, friction.f1_from_load_ratio(0.0009, 0.5, -0.0)) == 1.0  # as (-0.0)**0.5 = +0.0
    assert math.isnan(friction.f1_from_load_ratio(0.0009, 0.5, math.nan))


@settings(max_examples=300, deadline=None)
@given(f0=st.floats(0.5, 10), nu=st.floats(0.5, 500), n=st.floats(0, 20000), dM=st.floats(5, 2000))
def test_m0_is_the_printed_formula_to_the_last_digits(f0, nu, n, dM):
    # a few units in the last place: (ν·n)^(2/3) as a cube root squared, dM³ as two products
    assert friction.speed_dependent_torque(f0, nu, n, dM) == pytest.approx(m0_hand(f0, nu, n, dM), rel=1e-14)
