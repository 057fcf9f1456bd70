"""Kernels of the ball bearing contact after Zaitsev & Voronkin (Zaitsev, Voronkin): seed example, first principles, errors."""
import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.special import ellipe, ellipk

from bearingheat.errors import ContactInputError
from bearingheat.kernels import contact as ct
from bearingheat.kernels.contact import KGF

# Zaitsev & Voronkin, example: bearing 4-1006095 (5 x 13 x 4 mm; the seed's table swaps D and d).
Z, DW, DM, ALPHA0, RI, RO = 7, 2.0, 8.7355, 12.0, 1.05, 1.16
D1, d1 = 10.74, 6.731
SEED_TABLE_DEFLECTION = (0.63, 0.852)  # 2K/(mu*pi) read from a table in the seed
FA_SEED = 2.0 * KGF


def dms(degrees, minutes, seconds=0.0):
    return degrees + minutes / 60 + seconds / 3600


# ----------------------------------------------------------------------------- seed example
def test_seed_intermediate_parameters():
    # xi_i = 0.525, xi_o = 0.58, xi = 0.105; T/(d_w cos alpha0) = 4.514, 4.304; T = 8.831, 8.42
    assert RI / DW == pytest.approx(0.525) and RO / DW == pytest.approx(0.58)
    assert (RI + RO) / DW - 1 == pytest.approx(0.105)
    cos0 = math.cos(math.radians(ALPHA0))
    assert round((d1 + 2 * RI) / (DW * cos0), 3) == 4.514
    assert round((D1 - 2 * RO) / (DW * cos0), 3) == 4.304
    # the groove-centre diameters follow from the pitch diameter to 0.003 mm
    assert DM + (2 * RI - DW) * cos0 == pytest.approx(d1 + 2 * RI, abs=0.003)
    assert DM - (2 * RO - DW) * cos0 == pytest.approx(D1 - 2 * RO, abs=0.003)


def test_seed_curvature_sums_and_auxiliaries():
    rc = ct.race_curvatures(DW, DM, ALPHA0, RI, RO)
    assert rc.sum_rho_i == pytest.approx(1.3361919, abs=2e-7)
    assert rc.sum_rho_o == pytest.approx(0.9549594, abs=2e-7)
    assert rc.cos_tau_i == pytest.approx(0.9287242, abs=2e-7)
    assert rc.cos_tau_o == pytest.approx(0.7111268, abs=2e-7)


def test_seed_form_with_groove_centre_diameters_gives_the_same_curvatures():
    """The seed's T-form, with its '± 2ξ − 1' read as '± (2ξ − 1)' (upper sign: outer ring)."""
    cos0 = math.cos(math.radians(ALPHA0))
    rc = ct.race_curvatures(DW, DM, ALPHA0, RI, RO)
    for T, xi, sign, sum_rho, cos_tau in (
        (DM + (2 * RI - DW) * cos0, RI / DW, -1, rc.sum_rho_i, rc.cos_tau_i),
        (DM - (2 * RO - DW) * cos0, RO / DW, +1, rc.sum_rho_o, rc.cos_tau_o),
    ):
        A = T / (DW * cos0)
        core = 4 * xi * (A + sign * (2 * xi - 1)) - A
        assert 2 / DW * core / (2 * xi * (A + sign * 2 * xi)) == pytest.approx(sum_rho, rel=1e-12)
        assert A / core == pytest.approx(cos_tau, rel=1e-12)


def test_seed_hertz_coefficients_exact_versus_table():
    rc = ct.race_curvatures(DW, DM, ALPHA0, RI, RO)
    inner, outer = ct.hertz_coefficients(rc.cos_tau_i), ct.hertz_coefficients(rc.cos_tau_o)
    # seed's table: mu*nu = 1.52, 2K/(mu pi) = 0.63 (inner); 1.17, 0.852 (outer)
    assert inner.mu * inner.nu == pytest.approx(1.52, abs=0.005)
    assert outer.mu * outer.nu == pytest.approx(1.17, abs=0.005)
    assert inner.deflection == pytest.approx(0.63, abs=0.002)
    assert outer.deflection == pytest.approx(0.852, abs=0.001)
    assert inner.deflection == pytest.approx(0.628344, abs=1e-6)
    assert outer.deflection == pytest.approx(0.852454, abs=1e-6)


def test_seed_compliances_and_stiffness_with_table_coefficients():
    rc = ct.race_curvatures(DW, DM, ALPHA0, RI, RO)
    to_cm_kgf = (100 / KGF) ** (2 / 3)
    c_i = ct.race_compliance(DW, rc.sum_rho_i, SEED_TABLE_DEFLECTION[0]) / to_cm_kgf
    c_o = ct.race_compliance(DW, rc.sum_rho_o, SEED_TABLE_DEFLECTION[1]) / to_cm_kgf
    assert c_i == pytest.approx(0.5176e-4, abs=0.00005e-4)
    assert c_o == pytest.approx(0.6258e-4, abs=0.00005e-4)
    c_star = ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO, deflection_coefficients=SEED_TABLE_DEFLECTION)
    assert c_star / KGF == pytest.approx(7792, abs=0.5)


def test_seed_example_reproduced():
    c_star = ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO)
    assert c_star / KGF == pytest.approx(7.79e3, rel=0.003)
    alpha = ct.working_contact_angle(FA_SEED, c_star, ALPHA0)
    assert abs(alpha - dms(14, 28)) * 3600 <= 10.0
    assert ct.axial_displacement_ratio(alpha, ALPHA0) == pytest.approx(0.04447, abs=2e-4)


def test_seed_iteration_table():
    """Seed table: x_0 = 0.0433985 (Fa_1 = 2.029, 1.45 %), x_1 = 0.0430573 (Fa_2 = 2.001, 0.05 %), C* = 7792 kgf."""
    rows = ct.series_iterates(2.0, 7792.0, ALPHA0, newton_steps=1)
    assert rows[0].x == pytest.approx(0.0433985, abs=5e-6)  # C* printed to 4 digits
    assert rows[0].load == pytest.approx(2.029, abs=0.002)
    assert rows[0].deviation_percent == pytest.approx(1.45, abs=0.1)
    assert rows[1].x == pytest.approx(0.0430573, abs=2e-5)  # the seed's step lands 2" short of the root
    assert rows[1].load == pytest.approx(2.001, abs=0.003)
    assert abs(rows[1].deviation_percent) < 0.1
    assert rows[0].xi_a == pytest.approx(0.0448324, abs=5e-5)
    assert rows[1].xi_a == pytest.approx(0.0444763, abs=5e-5)


def test_seed_angles_were_converted_with_pi_equal_3_14():
    """The seed's 14°29′16″ and 14°28′5″ are 12° + x·180/3.14; with π they are 14°29′12″ and 14°28′01″."""
    for x, seed_angle in ((0.0433985, dms(14, 29, 16)), (0.0430573, dms(14, 28, 5))):
        assert abs(ALPHA0 + x * 180 / 3.14 - seed_angle) * 3600 < 1.0
        assert (seed_angle - (ALPHA0 + math.degrees(x))) * 3600 == pytest.approx(4.5, abs=1.0)


def test_series_start_is_the_root_of_the_quadratic_truncation():
    a = ct.series_coefficients(2.0, 7792.0, ALPHA0)
    x0 = ct.series_start(2.0, 7792.0, ALPHA0)
    assert a[0] + a[1] * x0 + a[2] * x0**2 == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("alpha0", [5.0, 12.0, 25.0, 40.0])
def test_series_coefficients_match_a_taylor_fit(alpha0):
    """a_1..a_4 of the seed against a Chebyshev fit of f(x) around x = 0."""
    a0r = math.radians(alpha0)
    h = min(0.05, a0r / 4)  # inside the radius of convergence (sin^(2/3) branch point at x = -alpha0)
    nodes = np.cos(np.pi * (np.arange(40) + 0.5) / 40) * h
    values = (np.cos(a0r) / np.cos(a0r + nodes) - 1) * np.sin(a0r + nodes) ** (2 / 3)
    cheb = np.polynomial.chebyshev.chebfit(nodes / h, values, 16)
    poly = np.polynomial.chebyshev.cheb2poly(cheb)
    fitted = [poly[k] / h**k for k in range(1, 5)]
    seed = ct.series_coefficients(0.0, 1.0, alpha0)[1:]
    assert seed == pytest.approx(fitted, rel=1e-6)


@settings(max_examples=60, deadline=None)
@given(alpha0=st.floats(0.5, 89.99), load_ratio=st.floats(0.0, 1e-2))
def test_series_with_newton_converges_to_the_bracketed_root(alpha0, load_ratio):
    exact = ct.working_contact_angle(load_ratio, 1.0, alpha0)
    series = ct.working_contact_angle_series(load_ratio, 1.0, alpha0)
    assert series == pytest.approx(exact, abs=1e-9)


def _exact_angle_by_bisection(load_ratio, alpha0):
    """α of Fa/C* = (cos α0/cos α − 1)^(3/2)·sin α by 200 bisections of [α0, 90°), independent of the kernels."""
    a0 = math.radians(alpha0)
    low, high = a0, math.pi / 2
    for _ in range(200):
        mid = 0.5 * (low + high)
        load = (math.cos(a0) / math.cos(mid) - 1.0) ** 1.5 * math.sin(mid)
        low, high = (mid, high) if load < load_ratio else (low, mid)
    return math.degrees(low)


def test_series_method_is_right_where_two_newton_steps_are_not():
    """α0 = 2°, Fa/C* = 0.01: the exact root is 23.1099°; the paper's two Newton steps stop 0.60° above it (they
    used to be the result); iterated to 1e-12 rad the series method gives the root."""
    exact = _exact_angle_by_bisection(0.01, 2.0)
    assert exact == pytest.approx(23.109882, abs=1e-6)
    two_steps = ct.series_iterates(0.01, 1.0, 2.0, newton_steps=2)[-1].alpha
    assert two_steps - exact == pytest.approx(0.6018, abs=1e-4)
    assert ct.working_contact_angle_series(0.01, 1.0, 2.0) == pytest.approx(exact, abs=1e-10)
    assert ct.working_contact_angle_series(2.0, 7792.0, 12.0) == pytest.approx(
        _exact_angle_by_bisection(2.0 / 7792.0, 12.0), abs=1e-10)


def test_series_method_over_its_whole_range():
    """α0 from 0.5° to 89.99°, Fa/C* from 0 (and 1e-300) to 0.01: every angle within 1e-9° of the bracketed root,
    none NaN (the quadratic start and the Newton denominator used to cancel to 0 at small loads)."""
    alpha0, load_ratio = np.meshgrid(np.linspace(0.5, 89.99, 60),
                                     np.concatenate([[0.0, 1e-300, 1e-30], np.logspace(-20, -2, 40)]))
    series = ct.working_contact_angle_series(load_ratio, 1.0, alpha0)
    exact = ct.working_contact_angle(load_ratio, 1.0, alpha0)
    assert np.isfinite(series).all()
    assert np.abs(series - exact).max() < 1e-9


def test_series_at_tiny_loads_keeps_the_start_and_the_iterate_loads():
    """Fa/C* = 1e-26 at α0 = 89.99°: the quadratic start is the linear root (Fa/C*)^(2/3)/a_1 = 8.10e-19 rad (it was
    0, √(1 + u) − 1 rounding to 0); Fa/C* = 1e-30 at α0 = 12°: the iterates' load is Fa (Δ = 0 %), though α0 + x
    rounds to α0 in degrees (it was 0, Δ = −100 %)."""
    a1 = math.sin(math.radians(89.99)) ** (2 / 3) * math.tan(math.radians(89.99))
    assert ct.series_start(1e-26, 1.0, 89.99) == pytest.approx(1e-26 ** (2 / 3) / a1, rel=1e-9)
    last = ct.series_iterates(1e-30, 1.0, 12.0, newton_steps=2)[-1]
    assert last.alpha == 12.0 and last.deviation_percent == pytest.approx(0.0, abs=1e-9)


def test_series_newton_steps_shrink_the_error():
    exact = ct.working_contact_angle(2.0, 7792.0, ALPHA0)
    errors = [abs(r.alpha - exact) for r in ct.series_iterates(2.0, 7792.0, ALPHA0, newton_steps=3)]
    assert errors[1] < errors[0] / 5 and errors[2] < errors[1] / 5 and errors[3] < 1e-9


# ----------------------------------------------------------------------------- constants from first principles
def test_hertz_constant_from_steel_elasticity():
    """0.592e-4 (cm²/kgf)^(2/3) = (3(1-ν²)/E)^(2/3)/2 for E = 2.08e5 N/mm², ν = 0.3."""
    E, nu = 2.08e5, 0.3
    k_mm_n = (3 * (1 - nu**2) / E) ** (2 / 3) / 2
    k_cm_kgf = k_mm_n * (KGF / 100) ** (2 / 3)  # 1 mm²/N = 0.0980665 cm²/kgf
    assert round(k_cm_kgf, 7) == ct.HERTZ_COMPLIANCE_CM_KGF
    assert ct.HERTZ_COMPLIANCE_MM_N == pytest.approx(k_mm_n, rel=0.002)
    assert ct.HERTZ_COMPLIANCE_MM_N == pytest.approx(2.784e-4, abs=5e-7)  # Harris: 2.79e-4 for E = 2.075e5


def test_compliance_reproduces_the_hertz_approach():
    """δ = c·d_w·(Q/d_w²)^(2/3) equals Hertz's δ = δ*·(3Q/(E'Σρ))^(2/3)·Σρ/2 (E' = E/(1-ν²))."""
    rc = ct.race_curvatures(DW, DM, ALPHA0, RI, RO)
    h = ct.hertz_coefficients(rc.cos_tau_i)
    e_prime = 2.08e5 / (1 - 0.3**2)
    q = 10.0  # N on one ball
    hertz = h.deflection * (3 * q / (e_prime * rc.sum_rho_i)) ** (2 / 3) * rc.sum_rho_i / 2
    seed = ct.race_compliance(DW, rc.sum_rho_i, h.deflection) * DW * (q / DW**2) ** (2 / 3)
    assert seed == pytest.approx(hertz, rel=0.002)


def test_gyroscopic_constant_from_ball_dynamics():
    """5.75e-12 = ρπ/(240μ)·(2π/60)²/g: J = m d_w²/10, ball spin (D0/2d_w)ω(1-γ²), cage ω/2, ρ = 7.85 g/cm³, μ = 0.02."""
    rho, mu = 7.85e-6, 0.02  # kg/mm³; friction coefficient
    constant_kgf = rho * math.pi / (240 * mu) * (2 * math.pi / 60) ** 2 * 1e-3 / KGF  # kg·mm/s² = 1e-3 N
    assert constant_kgf == pytest.approx(ct.GYROSCOPIC_CONSTANT_KGF, rel=0.002)


def test_minimum_axial_load_from_the_gyroscopic_moment():
    z, dw, d0, n, alpha = 7, 2.0, 8.7355, 30000.0, 15.0
    a, omega = math.radians(alpha), 2 * math.pi * n / 60
    gamma = dw * math.cos(a) / d0
    mass = 7.85e-6 * math.pi * dw**3 / 6
    moment = mass * dw**2 / 10 * (d0 / (2 * dw)) * (1 - gamma**2) * omega * (omega / 2) * math.sin(a) * 1e-3  # N·mm
    ball_load = moment / (0.02 * dw)
    expected = z * ball_load * math.sin(a)
    assert ct.minimum_axial_load(z, dw, d0, n, alpha) == pytest.approx(expected, rel=0.002)


def test_minimum_axial_load_seed_formula():
    expected_kgf = 5.75e-12 * 7 * 8 * 8.7355 * 3000**2 * math.sin(math.radians(12)) ** 2 * (
        1 - (2 / 8.7355) ** 2 * math.cos(math.radians(12)) ** 2)
    assert ct.minimum_axial_load(7, 2.0, 8.7355, 3000, 12.0) == pytest.approx(expected_kgf * KGF, rel=1e-12)
    assert ct.minimum_axial_load(7, 2.0, 8.7355, 3000, 0.0) == 0.0
    assert ct.minimum_axial_load(7, 2.0, 8.7355, 6000, 12.0) == pytest.approx(
        4 * ct.minimum_axial_load(7, 2.0, 8.7355, 3000, 12.0), rel=1e-12)


def test_hertz_coefficients_circle_and_round_trip():
    circle = ct.hertz_coefficients(0.0)
    assert (circle.kappa, circle.mu, circle.nu, circle.deflection) == pytest.approx((1.0, 1.0, 1.0, 1.0))
    for f in (0.1, 0.5, 0.9, 0.99, 0.9999):
        kappa = ct.hertz_coefficients(f).kappa
        m = 1 - 1 / kappa**2
        again = ((kappa**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((kappa**2 - 1) * ellipe(m))
        assert again == pytest.approx(f, abs=1e-12)


# ----------------------------------------------------------------------------- initial contact angle
def test_initial_contact_angle_inverts_the_clearance():
    e = 2 * (RI + RO - DW) * (1 - math.cos(math.radians(ALPHA0)))
    assert e == pytest.approx(0.009178, abs=1e-6)
    assert ct.initial_contact_angle(e, RI, RO, DW) == pytest.approx(ALPHA0, abs=1e-12)
    assert ct.initial_contact_angle(0.0, RI, RO, DW) == 0.0


def test_shortcut_052_equals_the_general_formula():
    e = np.array([0.0, 0.002, 0.01, 0.05])
    assert ct.initial_contact_angle_052(e, 2.0) == pytest.approx(ct.initial_contact_angle(e, 1.04, 1.04, 2.0))


def test_initial_contact_angle_symmetric_in_the_groove_radii():
    assert ct.initial_contact_angle(0.01, 1.16, 1.05, 2.0) == ct.initial_contact_angle(0.01, 1.05, 1.16, 2.0)


# ----------------------------------------------------------------------------- monotonicity, limits, similarity
@settings(max_examples=60, deadline=None)
@given(alpha0=st.floats(0.0, 45.0), f1=st.floats(1e-9, 1e-2), f2=st.floats(1e-9, 1e-2))
def test_working_angle_grows_with_axial_load(alpha0, f1, f2):
    lo, hi = sorted((f1, f2))
    a_lo, a_hi = ct.working_contact_angle(lo, 1.0, alpha0), ct.working_contact_angle(hi, 1.0, alpha0)
    assert alpha0 < a_lo <= a_hi < 90.0


def test_working_angle_tends_to_alpha0_as_load_vanishes():
    c_star = ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO)
    assert ct.working_contact_angle(0.0, c_star, ALPHA0) == ALPHA0
    gaps = [ct.working_contact_angle(fa, c_star, ALPHA0) - ALPHA0 for fa in (1e-3, 1e-6, 1e-9)]
    assert gaps[0] > gaps[1] > gaps[2] > 0 and gaps[2] < 1e-5


def test_working_angle_is_the_inverse_of_the_load_equation():
    alphas = np.array([12.5, 14.0, 20.0, 35.0])
    loads = ct.axial_load_at_angle(alphas, ALPHA0, 7792.0)
    assert ct.working_contact_angle(loads, 7792.0, ALPHA0) == pytest.approx(alphas, abs=1e-10)


def test_axial_displacement_ratio_over_its_range():
    """ξ_a = (tan α − tan α0)·cos α0 by hand: 0 at α = α0, (0.257997 − 0.212557)·0.978148 = 0.044447 at the paper's
    14°28′, (57.28996 − 0.212557)·0.978148 = 55.8301 at 89°; NaN (a row without geometry) stays NaN."""
    assert ct.axial_displacement_ratio(12.0, 12.0) == 0.0
    assert ct.axial_displacement_ratio(dms(14, 28), 12.0) == pytest.approx(0.044447, abs=1e-6)
    assert ct.axial_displacement_ratio(89.0, 12.0) == pytest.approx(55.8301, abs=1e-4)
    assert math.isnan(ct.axial_displacement_ratio(np.nan, 12.0))


def test_working_angle_is_never_below_alpha0():
    """α = α0 + x: a load so small that x is below the spacing of floats at α0 gives α0 itself, which ξ_a accepts
    (7.5° does not survive a round trip through radians, 7.499999999999999: α from the radians was below α0)."""
    assert np.degrees(7.5 * math.pi / 180) < 7.5
    for load in (0.0, 1e-40, 1e-20):
        alpha = ct.working_contact_angle(load, 7792.0, 7.5)
        assert alpha >= 7.5 and ct.axial_displacement_ratio(alpha, 7.5) >= 0.0


def test_working_angle_from_zero_initial_angle():
    """alpha0 = 0 (no clearance): the bracketing solver works where the series does not."""
    alpha = ct.working_contact_angle(1e-3, 1.0, 0.0)
    assert ct.axial_load_at_angle(alpha, 0.0, 1.0) == pytest.approx(1e-3, rel=1e-10)


def test_geometric_similarity():
    """Scaling every length by s scales C* by s²; the angle under Fa·s² is unchanged."""
    s = 3.0
    c1 = ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO)
    c3 = ct.stiffness_characteristic(Z, s * DW, s * DM, ALPHA0, s * RI, s * RO)
    assert c3 == pytest.approx(s**2 * c1, rel=1e-12)
    assert ct.working_contact_angle(FA_SEED * s**2, c3, ALPHA0) == pytest.approx(
        ct.working_contact_angle(FA_SEED, c1, ALPHA0), abs=1e-10)


def test_stiffness_proportional_to_number_of_balls():
    assert ct.stiffness_characteristic(14, DW, DM, ALPHA0, RI, RO) == pytest.approx(
        2 * ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO), rel=1e-12)


# ----------------------------------------------------------------------------- vectorisation
def test_scalar_array_and_series_agree():
    loads = [0.0, 5.0, FA_SEED, 50.0]
    index = pd.Index(["a", "b", "c", "d"])
    c_star = ct.stiffness_characteristic(Z, DW, DM, ALPHA0, RI, RO)
    scalars = [ct.working_contact_angle(f, c_star, ALPHA0) for f in loads]
    array = ct.working_contact_angle(np.array(loads), c_star, ALPHA0)
    series = ct.working_contact_angle(pd.Series(loads, index=index), c_star, ALPHA0)
    assert isinstance(series, pd.Series) and list(series.index) == list(index)
    assert array == pytest.approx(scalars, abs=1e-12)
    assert series.to_numpy() == pytest.approx(scalars, abs=1e-12)
    speeds = pd.Series([1000.0, 3000.0, np.nan], index=[10, 11, 12])
    fa_min = ct.minimum_axial_load(Z, DW, DM, speeds, 14.0)
    assert list(fa_min.index) == [10, 11, 12] and math.isnan(fa_min[12])
    assert fa_min[11] == pytest.approx(ct.minimum_axial_load(Z, DW, DM, 3000.0, 14.0))


# ----------------------------------------------------------------------------- errors
@pytest.mark.parametrize("call, message", [
    (lambda: ct.initial_contact_angle(0.01, 0.95, 1.0, 2.0),
     "impossible geometry: r_i + r_o = 1.95 mm must exceed d_w = 2 mm"),
    (lambda: ct.initial_contact_angle(0.01, 1.0, 1.0, 2.0),
     "impossible geometry: r_i + r_o = 2 mm must exceed d_w = 2 mm"),
    (lambda: ct.initial_contact_angle(-0.01, 1.05, 1.16, 2.0),
     "e = -0.01 mm: the radial clearance must not be negative"),
    (lambda: ct.initial_contact_angle(0.5, 1.05, 1.16, 2.0),
     "e = 0.5 mm exceeds 2*(r_i + r_o - d_w) = 0.42 mm: the contact angle would pass 90 deg"),
    (lambda: ct.initial_contact_angle_052(-0.001, 2.0),
     "e = -0.001 mm: the radial clearance must not be negative"),
    (lambda: ct.initial_contact_angle(0.01, 1.05, 1.16, 0.0),
     "d_w = 0 mm: the ball diameter must be positive"),
    (lambda: ct.race_curvatures(2.0, 8.7355, 12.0, 0.95, 1.16),
     "impossible geometry: r_i = 0.95 mm must exceed d_w/2 = 1 mm (groove narrower than the ball)"),
    (lambda: ct.race_curvatures(2.0, 1.5, 12.0, 1.05, 1.16),
     "impossible geometry: pitch diameter d_m = 1.5 mm must exceed d_w = 2 mm"),
    (lambda: ct.race_curvatures(2.0, 8.7355, 90.0, 1.05, 1.16),
     "alpha0 = 90 deg must lie in [0, 90) deg"),
    (lambda: ct.stiffness_characteristic(6.5, 2.0, 8.7355, 12.0, 1.05, 1.16),
     "z = 6.5: the number of balls must be a whole number of at least 1"),
    (lambda: ct.working_contact_angle(-1.0, 7792.0, 12.0),
     "Fa = -1 N: the axial load must not be negative"),
    (lambda: ct.working_contact_angle(1.0, 0.0, 12.0),
     "C_star = 0 N: the stiffness characteristic must be positive"),
    (lambda: ct.series_start(2.0, 7792.0, 0.0),
     "alpha0 = 0 deg: the series method of Zaitsev & Voronkin needs alpha0 > 0 "
     "(no expansion in powers of x at alpha0 = 0); use working_contact_angle"),
    (lambda: ct.working_contact_angle_series(2.0, 7792.0, 0.0),
     "alpha0 = 0 deg: the series method of Zaitsev & Voronkin needs alpha0 > 0 "
     "(no expansion in powers of x at alpha0 = 0); use working_contact_angle"),
    (lambda: ct.hertz_coefficients(1.0), "cos_tau = 1 must lie in [0, 1)"),
    (lambda: ct.minimum_axial_load(7, 2.0, 8.7355, -3000.0, 12.0),
     "n = -3000 1/min: the speed must not be negative"),
    (lambda: ct.minimum_axial_load(7, 2.0, 2.0, 3000.0, 12.0),
     "impossible geometry: pitch diameter D0 = 2 mm must exceed d_w = 2 mm"),
    (lambda: ct.axial_load_at_angle(11.0, 12.0, 7792.0),
     "alpha = 11 deg must lie in [alpha0, 90) deg = [12, 90) deg"),
    # tan(90 deg) in floating point is 1.6e16: the ratio used to come back as 1.6e16, and as a negative
    # displacement below alpha0
    (lambda: ct.axial_displacement_ratio(90.0, 12.0), "alpha = 90 deg must lie in [alpha0, 90) deg = [12, 90) deg"),
    (lambda: ct.axial_displacement_ratio(11.0, 12.0), "alpha = 11 deg must lie in [alpha0, 90) deg = [12, 90) deg"),
    (lambda: ct.axial_displacement_ratio(np.array([14.0, 95.0]), 12.0),
     "alpha = 95 deg must lie in [alpha0, 90) deg = [12, 90) deg (element 1)"),
    (lambda: ct.axial_displacement_ratio(14.0, -1.0), "alpha0 = -1 deg must lie in [0, 90) deg"),
    # non-finite and far-out inputs: refused by the package, not by scipy's bracket or as inf/nan out
    (lambda: ct.working_contact_angle(np.inf, 7792.0, 12.0), "Fa = inf N: the axial load must be finite"),
    (lambda: ct.working_contact_angle(2.0, np.inf, 12.0), "C_star = inf N: the stiffness characteristic must be finite"),
    (lambda: ct.working_contact_angle(1e30, 1.0, 12.0),
     "Fa = 1e+30 N with C_star = 1 N: Fa/C_star = 1e+30 must lie in [0, 1e+06] "
     "(the working angle is then within 0.01 deg of 90 deg)"),
    (lambda: ct.working_contact_angle_series(2e7, 2.0, 12.0),
     "Fa = 2e+07 N with C_star = 2 N: Fa/C_star = 1e+07 must lie in [0, 1e+06] "
     "(the working angle is then within 0.01 deg of 90 deg)"),
    (lambda: ct.working_contact_angle_series(0.02, 1.0, 12.0),
     "Fa = 0.02 N with C_star = 1 N: Fa/C_star = 0.02; the series method of Zaitsev & Voronkin (a small "
     "x = alpha - alpha0) is used up to Fa/C_star = 0.01 (beyond it its Newton steps can leave [alpha0, 90) deg); "
     "use working_contact_angle"),
    (lambda: ct.series_iterates(2.0, 7792.0, 0.3),
     "alpha0 = 0.3 deg: the series method of Zaitsev & Voronkin is used from alpha0 = 0.5 deg on (below it its "
     "Newton steps can leave [alpha0, 90) deg); use working_contact_angle"),
    (lambda: ct.minimum_axial_load(7, 2, 8.7, np.inf, 12), "n = inf 1/min: the speed must be finite"),
    (lambda: ct.stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16, deflection_coefficients=(-0.63, -0.852)),
     "deflection_coefficients: inner 2K/(mu*pi) = -0.63 must lie in (0, 1] "
     "(1 for a circular contact, falling towards 0 as the contact ellipse lengthens)"),
    (lambda: ct.stiffness_characteristic(7, 2.0, 8.7355, 12.0, 1.05, 1.16, deflection_coefficients=(0.63, 1.5)),
     "deflection_coefficients: outer 2K/(mu*pi) = 1.5 must lie in (0, 1] "
     "(1 for a circular contact, falling towards 0 as the contact ellipse lengthens)"),
    # r_o above the outer race's radius along the rolling direction: (2.2 + 2*cos 0)/(2*cos 0) = 2.1 mm by hand
    (lambda: ct.race_curvatures(2.0, 2.2, 0.0, 1.05, 2.5),
     "impossible geometry: r_o = 2.5 mm must not exceed (d_m + d_w*cos(alpha0))/(2*cos(alpha0)) = 2.1 mm "
     "with d_w = 2 mm, d_m = 2.2 mm, alpha0 = 0 deg (the outer groove would be flatter across than the race is "
     "along it)"),
])
def test_errors_exact_messages(call, message):
    with pytest.raises(ContactInputError) as info:
        call()
    assert str(info.value) == message


def test_series_method_refuses_what_its_cap_of_newton_steps_does_not_reach(monkeypatch):
    """α0 = 2°, Fa/C* = 0.01 takes six steps to 1e-12 rad; with the cap lowered to two it is refused, not returned."""
    monkeypatch.setattr(ct, "SERIES_MAX_NEWTON_STEPS", 2)
    with pytest.raises(ContactInputError) as info:
        ct.working_contact_angle_series(pd.Series([0.0, 0.01], index=["a", "b"]), 1.0, 2.0)
    assert str(info.value) == ("Fa = 0.01 N with C_star = 1 N, alpha0 = 2 deg: the Newton steps of the series method "
                               "did not come below 1e-12 rad in 2 steps; use working_contact_angle (row b)")


@pytest.mark.parametrize("angle, message", [
    (math.nan, "alpha = nan deg: only a finite angle can be written in degrees, minutes and seconds"),
    (np.float64(np.inf), "alpha = inf deg: only a finite angle can be written in degrees, minutes and seconds"),
    (-math.inf, "alpha = -inf deg: only a finite angle can be written in degrees, minutes and seconds"),
])
def test_degrees_to_dms_refuses_what_is_not_a_finite_angle(angle, message):
    """Python's own 'cannot convert float NaN to integer' (and OverflowError for inf) used to come out."""
    with pytest.raises(ContactInputError) as info:
        ct.degrees_to_dms(angle)
    assert str(info.value) == message


def test_degrees_to_dms_by_hand():
    """14.4670° = 14° 28′ 1.2″; −0.5° = −0°30′00″; 59.99999° rounds up to 60°00′00″ (not 59°59′60″)."""
    assert ct.degrees_to_dms(14.4670) == "14°28′01″"
    assert ct.degrees_to_dms(-0.5) == "-0°30′00″"
    assert ct.degrees_to_dms(59.99999) == "60°00′00″"


def test_error_names_the_row_of_a_series():
    clearance = pd.Series([0.01, -0.002], index=["bearing A", "bearing B"])
    with pytest.raises(ContactInputError) as info:
        ct.initial_contact_angle(clearance, 1.05, 1.16, 2.0)
    assert str(info.value) == "e = -0.002 mm: the radial clearance must not be negative (row bearing B)"
    assert info.value.row == "bearing B"


def test_error_of_an_inner_kernel_names_the_row_of_the_outer_series():
    """A kernel calling another with the arrays of its Series: the inner refusal is renamed to the Series row by
    the outer kernel (the inner wrapper, which sees no labels, used to drop what the renaming needs)."""
    with pytest.raises(ContactInputError) as info:
        ct.stiffness_characteristic(pd.Series([7, 7], index=["a", "b"]), 2.0, 8.7355, 12.0,
                                    pd.Series([1.05, 0.95], index=["a", "b"]), 1.16)
    assert str(info.value) == ("impossible geometry: r_i = 0.95 mm must exceed d_w/2 = 1 mm "
                               "(groove narrower than the ball) (row b)")
    assert info.value.row == "b"
    index = ["6205", "6206"]
    d_w, d_m = pd.Series([2.0, 2.0], index=index), pd.Series([8.7, 1.0], index=index)
    expected = "impossible geometry: pitch diameter d_m = 1 mm must exceed d_w = 2 mm (row 6206)"
    for call in (lambda: ct.stiffness_characteristic(7, d_w, d_m, 12.0, 1.05, 1.16),
                 lambda: ct.race_curvatures(d_w, d_m, 12.0, 1.05, 1.16)):
        with pytest.raises(ContactInputError) as info:
            call()
        assert str(info.value) == expected and info.value.row == "6206"
    with pytest.raises(ContactInputError) as info:  # an array still names the element
        ct.stiffness_characteristic(7, d_w.to_numpy(), d_m.to_numpy(), 12.0, 1.05, 1.16)
    assert str(info.value) == "impossible geometry: pitch diameter d_m = 1 mm must exceed d_w = 2 mm (element 1)"
    assert info.value.row == 1
    with pytest.raises(ContactInputError) as info:
        ct.stiffness_characteristic(pd.Series([7, 6.5], index=["a", "b"]), 2.0, 8.7355, 12.0, 1.05, 1.16)
    assert str(info.value) == "z = 6.5: the number of balls must be a whole number of at least 1 (row b)"
    assert info.value.row == "b"


def test_a_clearance_at_its_limit_is_90_degrees_whichever_way_its_float_rounds():
    """e = 2(r_i + r_o - d_w) is valid (the docstring's range is closed): 0.42 mm, or 420 um converted to mm
    (0.42000000000000004), gives 90 deg, not a refusal by rounding; 0.43 mm is still refused."""
    from bearingheat.kernels.contact import initial_contact_angle
    for e in (0.42, 420e-3, 0.42000000000000004):
        assert initial_contact_angle(e, 1.05, 1.16, 2.0) == 90.0
    with pytest.raises(Exception, match=r"^e = 0.43 mm exceeds 2\*\(r_i \+ r_o - d_w\) = 0.42 mm"):
        initial_contact_angle(0.43, 1.05, 1.16, 2.0)


def test_the_outer_groove_limit_is_where_cos_tau_o_reaches_zero():
    """By hand: cos τ_o = [d_w/r_o − 2γ/(1 + γ)]/(d_w·Σρ_o) is 0 at r_o = d_w(1 + γ)/(2γ), γ = d_w·cos α0/d_m
    (d_w = 2, d_m = 8.7355, α0 = 12°: γ = 0.223949, 5.4653 mm); just below it is accepted with cos τ_o ≈ 0."""
    gamma = 2.0 * math.cos(math.radians(12.0)) / 8.7355
    limit = 2.0 * (1.0 + gamma) / (2.0 * gamma)
    assert limit == pytest.approx(5.4653, abs=1e-4)
    assert ct.race_curvatures(2.0, 8.7355, 12.0, 1.05, limit * (1 - 1e-9)).cos_tau_o == pytest.approx(0.0, abs=1e-8)
    with pytest.raises(ContactInputError, match=r"^impossible geometry: r_o = 5\.5 mm must not exceed"):
        ct.race_curvatures(2.0, 8.7355, 12.0, 1.05, 5.5)


def test_series_at_zero_load_gives_alpha0_for_a_scalar_as_for_an_array():
    """Fa = 0: x_0 = 0, the Newton step is 0, α = α0 = 12° and Fa_k = 0 = Fa, so Δ = 0 %; the scalar form used to
    divide by zero, the array form gave a NaN deviation."""
    scalar = ct.series_iterates(0.0, 7792.0, 12.0, newton_steps=2)
    array = ct.series_iterates(np.array([0.0, 2.0]), 7792.0, 12.0, newton_steps=2)
    for row, row_of_array in zip(scalar, array):
        assert (row.x, row.alpha, row.xi_a, row.load, row.deviation_percent) == (0.0, 12.0, 0.0, 0.0, 0.0)
        assert (row_of_array.alpha[0], row_of_array.deviation_percent[0]) == (12.0, 0.0)
    assert ct.working_contact_angle_series(0.0, 7792.0, 12.0) == 12.0
    assert ct.working_contact_angle_series(np.array([0.0]), 7792.0, 12.0).tolist() == [12.0]
    series = ct.series_iterates(pd.Series([0.0, 2.0], index=["x", "y"]), 7792.0, 12.0)[-1].deviation_percent
    assert isinstance(series, pd.Series) and series["x"] == 0.0


def test_the_docstrings_show_the_digits_the_code_prints():
    """The doctest NUMBER flag accepts 14.467 for 14.4677: the docstrings must carry the printed digits. The exact
    root x = α − α0 at Fa = 2, C* = 7792, α0 = 12° by an independent bisection of Fa = C*(cos α0/cos α − 1)^1.5 sin α."""
    assert round(ct.working_contact_angle(2.0, 7792.0, 12.0), 4) == 14.4677
    assert "    14.4677\n" in ct.working_contact_angle.__doc__
    a0 = math.radians(12.0)
    low, high = 0.0, 0.1
    for _ in range(200):
        mid = 0.5 * (low + high)
        load = 7792.0 * (math.cos(a0) / math.cos(a0 + mid) - 1.0) ** 1.5 * math.sin(a0 + mid)
        low, high = (mid, high) if load < 2.0 else (low, mid)
    assert round(low, 7) == 0.0430689
    assert "exact root 0.0430689" in ct.newton_increment.__doc__


def test_initial_contact_angle_refuses_a_groove_narrower_than_the_ball():
    # r_i = 0.9 mm < d_w/2 = 1 mm: the ball does not fit the groove (race_curvatures refused it; the contact angle
    # from the clearance gave 12.84 deg)
    with pytest.raises(ContactInputError) as exc:
        ct.initial_contact_angle(0.01, 0.9, 1.5, 2.0)
    assert str(exc.value) == ("impossible geometry: r_i = 0.9 mm must exceed d_w/2 = 1 mm (groove narrower than "
                              "the ball)")
