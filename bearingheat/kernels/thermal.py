"""Heat balance kernels of a rolling bearing: heat flow area, heat carried away, friction power, the exact roots.

The Schaeffler catalogue (p. 63, "Теплоотвод") says the thermally permissible speed comes
from the balance between the friction power and the heat carried away; its
page 72 with the formulas is missing, so the method is the published one of
the Schaeffler HR 1 catalogue (2006, after ISO 15312 and the draft of
DIN 732).

Kernels work on floats, arrays or Series in catalogue units: lengths [mm],
areas [mm²], loads [N], torques [N·mm], speeds [1/min], viscosity [mm²/s],
temperatures [°C], temperature differences [K], heat flows [W], heat
transfer coefficient k_q [W/(mm²·K)], oil flow [l/min].

Sign convention of the heat balance (one for the whole package)::

    N_R + Q_E = Q_S + Q_L

N_R is the friction power, Q_S the heat carried away through the bearing
seat, Q_L the heat carried away by circulating oil, and Q_E the external
heat flowing INTO the bearing (a hot housing, a heated shaft): Q_E > 0 adds
heat, Q_E < 0 is extra cooling. The heat the bearing may generate itself
is Q = Q_S + Q_L − Q_E.

The friction torque comes from the engine kernels
(:func:`bearingheat.kernels.friction.speed_dependent_torque` and
:func:`bearingheat.kernels.friction.load_dependent_torque`); the friction
power of the heat balance is :func:`friction_power`, (π·n/30)·1e-3·M [W], as
the standard writes it. The engine's :func:`bearingheat.kernels.friction.power_loss`
N_R = M·n/9550, as the catalogue prints it, rounds π/30000 to 1/9550
(about 0.007 % apart); the heat balance keeps the exact form, which the
published checks of its roots are written in. The rows of a table are
:mod:`bearingheat.calc.thermal`, the unit-aware functions
:mod:`bearingheat.api.thermal`.

>>> A_r = heat_flow_area("radial", 25, 52, B=15)                 # 6205
>>> Q = seat_heat_flow(default_heat_transfer_coefficient("radial", A_r), A_r, 50.0)
>>> round(balance_speed(2.0, 12.0, 38.5, 3.0218, Q))             # n_thr of the 6205
14416
"""
from __future__ import annotations

import math

import numpy as np

from bearingheat.catalogue.thermal import reference_conditions
from bearingheat.errors import HeatBalanceError
from bearingheat.kernels import friction
from bearingheat.kernels._series import series_aware

__all__ = [
    "POWER_PER_TORQUE_SPEED",
    "OIL_HEAT_CAPACITY_FLOW",
    "HEAT_FLOW_AREA",
    "APPROXIMATION_RANGE",
    "heat_flow_area",
    "reference_heat_flux_density",
    "default_heat_transfer_coefficient",
    "seat_heat_flow",
    "oil_heat_flow",
    "friction_power",
    "friction_heat",
    "torque_coefficients",
    "balance_root",
    "balance_speed",
    "speed_factor_coefficients",
    "speed_factor_exact",
    "speed_factor_catalogue_approximation",
    "permissible_speed_factor",
]

#: (π/30)·1e-3: friction power [W] per torque [N·mm] and speed [1/min] (ISO 15312, the n_θr equation).
POWER_PER_TORQUE_SPEED = math.pi / 30.0 * 1e-3
#: Heat carried away by circulating oil: 0.0286 kW/(l/min·K) = 28.6 W/(l/min·K) (Schaeffler HR 1).
OIL_HEAT_CAPACITY_FLOW = 28.6


# ---- heat flow area and heat carried away ----------------------------------------------------

def _area_radial(d, D, B, T, d1, D1):
    return math.pi * np.asarray(B, dtype=float) * (np.asarray(D, dtype=float) + d)


def _area_tapered(d, D, B, T, d1, D1):
    return math.pi * np.asarray(T, dtype=float) * (np.asarray(D, dtype=float) + d)


def _area_thrust(d, D, B, T, d1, D1):
    return math.pi / 2.0 * (np.square(np.asarray(D, dtype=float)) - np.square(np.asarray(d, dtype=float)))


def _area_axial_spherical(d, D, B, T, d1, D1):
    D, d, d1, D1 = (np.asarray(v, dtype=float) for v in (D, d, d1, D1))
    return math.pi / 4.0 * (np.square(D) + np.square(d1) - np.square(D1) - np.square(d))


#: kind -> (A_r function(d, D, B, T, d1, D1) [mm²], formula, the columns it needs besides d and D)
HEAT_FLOW_AREA = {
    "radial": (_area_radial, "pi*B*(D+d)", ("B",)),
    "tapered": (_area_tapered, "pi*T*(D+d)", ("T",)),
    "thrust": (_area_thrust, "(pi/2)*(D^2-d^2)", ()),
    "axial_spherical": (_area_axial_spherical, "(pi/4)*(D^2+d1^2-D1^2-d^2)", ("d1", "D1")),
}


@series_aware
def heat_flow_area(kind, d, D, B=np.nan, T=np.nan, d1=np.nan, D1=np.nan):
    """Reference heat flow area A_r [mm²] (Schaeffler HR 1 (2006), p. 64; ISO 15312).

    Radial bearings π·B·(D+d); tapered roller bearings π·T·(D+d) with the
    total width T; thrust bearings (π/2)·(D²−d²); axial spherical roller
    bearings (π/4)·(D² + d1² − D1² − d²) with the shaft washer's outside
    diameter d1 and the housing washer's bore D1. d, D, B, T, d1, D1 [mm].

    >>> round(heat_flow_area("radial", 25, 52, B=15), 1)     # 6205
    3628.5
    >>> round(heat_flow_area("tapered", 25, 52, T=16.25), 1) # 30205-A
    3930.9
    >>> round(heat_flow_area("thrust", 25, 42), 1)           # 51105 size
    1789.1
    >>> round(heat_flow_area("axial_spherical", 60, 130, d1=112.2, D1=85.5), 1)  # 29412-E
    14591.6
    """
    return HEAT_FLOW_AREA[str(kind)][0](d, D, B, T, d1, D1)


@series_aware
def reference_heat_flux_density(kind, A_r):
    """Heat flux density q_r [W/mm²] of the reference conditions for A_r [mm²].

    Radial (and tapered): 0.016 up to A_r = 50 000 mm², 0.016·(A_r/50 000)^−0.34
    above; thrust: 0.020, above the limit 0.020·(A_r/50 000)^−0.16.

    >>> reference_heat_flux_density("radial", 3628.5)
    0.016
    >>> round(reference_heat_flux_density("radial", 100000.0), 6)
    0.012641
    """
    ref = reference_conditions(str(kind))
    A_r = np.asarray(A_r, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        large = ref.q_r * np.power(A_r / ref.A_r_limit, ref.q_r_exponent)
    return np.where(A_r > ref.A_r_limit, large, ref.q_r)


@series_aware
def default_heat_transfer_coefficient(kind, A_r):
    """Default k_q = q_r/Δθ_A,ref [W/(mm²·K)]: the heat transfer of the reference conditions.

    With this default a bearing at 70 °C in 20 °C air carries away exactly
    q_r·A_r, so f_n = 1 at the reference conditions. For A_r <= 50 000 mm²
    it is 0.016/50 = 3.2e-4 W/(mm²·K) = 0.32e-6 kW/(mm²·K), inside the
    catalogue's 0.2–1.0e-6 kW/(mm²·K) for seats up to 25 000 mm².

    >>> default_heat_transfer_coefficient("radial", 3628.5)
    0.00032
    """
    return reference_heat_flux_density(kind, A_r) / reference_conditions(str(kind)).temperature_rise


@series_aware
def seat_heat_flow(k_q, A_r, dT_A):
    """Q_S = k_q·A_r·Δθ_A [W], heat carried away through the bearing seat.

    k_q [W/(mm²·K)], A_r [mm²], Δθ_A = bearing − ambient temperature [K].

    >>> round(seat_heat_flow(3.2e-4, 3628.5, 50.0), 3)
    58.056
    """
    return np.asarray(k_q, dtype=float) * A_r * dT_A


@series_aware
def oil_heat_flow(V_L, dT_L):
    """Q_L = 0.0286 kW/(l/min·K)·V_L·Δθ_L [W], heat carried away by circulating oil.

    V_L [l/min] oil flow, Δθ_L [K] oil temperature rise (outlet − inlet).

    >>> round(oil_heat_flow(0.5, 10.0), 6)
    143.0
    """
    return OIL_HEAT_CAPACITY_FLOW * np.asarray(V_L, dtype=float) * dT_L


@series_aware
def friction_power(M, n):
    """Friction power N_R = (π·n/30)·1e-3·M [W] of the heat balance (ISO 15312, the n_θr equation).

    M [N·mm] friction torque, n [1/min] >= 0. The one definition of the
    power in the heat balance: the roots below use its factor
    :data:`POWER_PER_TORQUE_SPEED`. It is about 0.007 % above the catalogue's
    rounded N_R = M·n/9550 (:func:`bearingheat.kernels.friction.power_loss`),
    which calc reports as ``NR``.

    >>> round(friction_power(100.0, 3000.0), 4)
    31.4159
    """
    return POWER_PER_TORQUE_SPEED * np.asarray(n, dtype=float) * M


@series_aware
def friction_heat(f0, nu, n, dM, load_torque):
    """Friction power (π·n/30)·1e-3·(M0 + M_load) [W] of the heat balance.

    M0 = :func:`bearingheat.kernels.friction.speed_dependent_torque` (both
    regimes); load_torque = M1 (+ M2) [N·mm] from the engine; f0 [-],
    ν [mm²/s], n [1/min], dM [mm].

    >>> round(friction_heat(2.0, 12.0, 14416.4, 38.5, 3.0218), 2)  # 6205 at n_thr
    58.06
    """
    M0 = friction.speed_dependent_torque(f0, nu, n, dM)
    return friction_power(M0 + np.asarray(load_torque, dtype=float), n)


# ---- exact roots of the heat balance ---------------------------------------------------------

#: rows the Newton iteration of :func:`_root_five_thirds` takes at a time (eight arrays of it fit a core's cache)
_NEWTON_BLOCK = 1 << 14


def _newton_five_thirds(a, b, y):
    """Newton's method on a·y^5 + b·y^3 = 1 from the upper bound ``y`` (updated in place), until no step is
    above 1e-15 of y. The step ((a·y² + b)·y³ − 1) / ((5a·y² + 3b)·y²) is written into arrays made once."""
    a5, b3 = 5.0 * a, 3.0 * b
    y2, y3, step, slope, small = (np.empty_like(y) for _ in range(5))
    for _ in range(200):
        np.multiply(y, y, out=y2)
        np.multiply(y2, y, out=y3)
        np.multiply(a, y2, out=step)
        step += b
        step *= y3
        step -= 1.0
        np.multiply(a5, y2, out=slope)
        slope += b3
        slope *= y2
        step /= slope
        y -= step
        np.abs(step, out=step)
        np.multiply(y, 1e-15, out=small)
        if not np.any(step > small):
            return


def _root_five_thirds(a, b):
    """x > 0 with a·x^(5/3) + b·x = 1 for a, b >= 0 (not both 0), to machine precision.

    With y = x^(1/3) the equation is the polynomial a·y^5 + b·y^3 − 1 = 0,
    convex and increasing for y > 0. Newton from the upper bound
    y0 = min(1/b, a^(-3/5))^(1/3) falls monotonically onto the root; the
    loop ends when no step is above 1e-15 of y (the next step would change
    the last digit only). a = b = 0 gives inf (no friction), negative or
    NaN inputs give NaN.
    """
    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    shape = a.shape
    a = a.ravel()
    b = b.ravel()
    x = np.full(a.shape, np.nan)
    x[(a == 0) & (b == 0)] = np.inf
    valid = (a >= 0) & (b >= 0) & ((a > 0) | (b > 0))
    if valid.all():
        av, bv = a, b
    else:
        av, bv = a[valid], b[valid]
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        x0 = np.fmin(np.where(bv > 0, 1.0 / bv, np.inf), np.where(av > 0, np.power(av, -0.6), np.inf))
        y = np.cbrt(x0)
        for block in range(0, len(y), _NEWTON_BLOCK):  # a block's arrays stay in the cache for all its steps
            part = slice(block, block + _NEWTON_BLOCK)
            _newton_five_thirds(av[part], bv[part], y[part])
    if valid.all():
        x = y * y * y
    else:
        x[valid] = y * y * y
    return x.reshape(shape) if shape else float(x[0])


def torque_coefficients(f0, dM):
    """(c_high, c_low) = (f0·dM³·1e-7, f0·160·dM³·1e-7) [N·mm] from the engine's M0 kernel (the Schaeffler catalogue, p. 64).

    M0 = c_high·(ν·n)^(2/3) for ν·n >= 2000 and c_low for ν·n < 2000;
    f0 [-], dM [mm].

    >>> c_high, c_low = torque_coefficients(2.0, 38.5)
    >>> round(float(c_high), 6), round(float(c_low), 4)
    (0.011413, 1.8261)
    """
    limit = friction.REGIME_LIMIT
    c_high = np.asarray(friction.speed_dependent_torque(f0, 1.0, limit, dM), dtype=float) / limit ** (2.0 / 3.0)
    return c_high, c_high * friction.LOW_REGIME_FACTOR


def balance_root(c_high, c_low, load_torque, nu, Q, scale):
    """x = n/scale where (π·n/30)·1e-3·(M0(ν·n) + M_load) = Q, both M0 regimes (Schaeffler HR 1).

    c_high, c_low [N·mm] of :func:`torque_coefficients`; M_load = M1 (+ M2)
    [N·mm]; ν [mm²/s]; Q [W]; scale [1/min] (1 for the speed itself, n_θr
    for the speed factor f_n). Returns (x, k_L, k_P, low_regime): k_L, k_P
    of k_L·x^(5/3) + k_P·x = 1 and where the root is in the ν·n < 2000 regime.

    Below ν·n = 2000 M0 is constant, and the friction power steps down by
    0.79 % where the regimes meet; where both regimes give a root the lower
    speed is taken (the bearing reaches the heat limit there first).

    >>> x, k_L, k_P, low = balance_root(*torque_coefficients(2.0, 38.5), 3.0218, 12.0, 58.056, 1.0)
    >>> round(float(x), 1), bool(low)
    (14416.1, False)
    """
    K = POWER_PER_TORQUE_SPEED
    nu = np.asarray(nu, dtype=float)
    scale = np.asarray(scale, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        k_L = K * scale * c_high * np.power(nu * scale, 2.0 / 3.0) / Q
        k_P = K * scale * np.asarray(load_torque, dtype=float) / Q
        x_high = _root_five_thirds(k_L, k_P)
        x_low = 1.0 / (K * scale * c_low / Q + k_P)
        low_regime = nu * scale * x_low < friction.REGIME_LIMIT
        x = np.where(low_regime, x_low, x_high)
    return x, k_L, k_P, low_regime


@series_aware
def balance_speed(f0, nu, dM, load_torque, Q):
    """Speed n [1/min] at which the friction power equals the heat Q [W] carried away.

    Solves (π·n/30)·1e-3·(M0(ν, n) + M_load) = Q exactly (Newton to machine
    precision, vectorised), with M0 of the engine in the regime the root
    falls in. f0 [-], ν [mm²/s], dM [mm], M_load = M1 (+ M2) [N·mm], Q [W].

    >>> round(balance_speed(2.0, 12.0, 38.5, 3.0218, 58.056), 1)   # 6205 at the reference
    14416.1
    """
    c_high, c_low = torque_coefficients(f0, dM)
    x, _, _, _ = balance_root(c_high, c_low, load_torque, nu, np.asarray(Q, dtype=float), 1.0)
    return x


@series_aware
def speed_factor_coefficients(n_thr, f0, nu, dM, load_torque, Q):
    """(k_L, k_P) of the speed factor f_n (Schaeffler HR 1).

    k_L = 1e-6·(π/30)·n_θr·1e-7·f0·(ν·n_θr)^(2/3)·dM³/Q,
    k_P = 1e-6·(π/30)·n_θr·f1·P1·dM/Q with Q in kW; here Q [W] and
    M_load = f1·P1·dM (+ M2) [N·mm], so the 1e-6 becomes 1e-3.

    >>> kL, kP = speed_factor_coefficients(14416.4, 2.0, 12.0, 38.5, 3.0218, 58.056)
    >>> round(kL, 4), round(kP, 4), round(kL + kP, 6)      # n_thr of the 6205 rounded: the sum is not quite 1
    (0.9215, 0.0786, 1.000037)
    """
    c_high, _ = torque_coefficients(f0, dM)
    K = POWER_PER_TORQUE_SPEED
    n_thr = np.asarray(n_thr, dtype=float)
    Q = np.asarray(Q, dtype=float)
    k_L = K * n_thr * c_high * np.power(np.asarray(nu, dtype=float) * n_thr, 2.0 / 3.0) / Q
    k_P = K * n_thr * np.asarray(load_torque, dtype=float) / Q
    return k_L, k_P


@series_aware
def speed_factor_exact(k_L, k_P):
    """The root f_n > 0 of k_L·f_n^(5/3) + k_P·f_n = 1, exact and vectorised.

    >>> speed_factor_exact(0.5, 0.5)
    1.0
    >>> round(speed_factor_exact(0.1, 0.2), 6)
    2.577419
    """
    return _root_five_thirds(k_L, k_P)


#: validity of the catalogue approximation of f_n (Schaeffler HR 1)
APPROXIMATION_RANGE = (0.01, 10.0)


@series_aware
def speed_factor_catalogue_approximation(k_L, k_P):
    """Catalogue approximation of the speed factor (Schaeffler HR 1)::

        f_n = 490.77 / (1 + 498.78·k_L^0.599 + 852.88·k_P^0.963 − 504.5·k_L^0.055·k_P^0.832)

    Valid for 0.01 <= k_L, k_P <= 10; outside that range it raises
    HeatBalanceError naming the value (no extrapolation).

    >>> round(speed_factor_catalogue_approximation(0.5, 0.5), 3)
    0.991
    >>> speed_factor_catalogue_approximation(0.005, 0.5)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: k_L: 0.005 is outside 0.01 <= k_L <= 10, the range of the catalogue approximation of f_n; use speed_factor_exact
    """
    k_L = np.asarray(k_L, dtype=float)
    k_P = np.asarray(k_P, dtype=float)
    low, high = APPROXIMATION_RANGE
    for name, values in (("k_L", k_L), ("k_P", k_P)):
        bad = ~((values >= low) & (values <= high))
        if np.any(bad):
            first = np.ravel(values)[np.flatnonzero(np.ravel(np.broadcast_to(bad, np.shape(values))))[0]]
            raise HeatBalanceError(f"{name}: {first:g} is outside {low:g} <= {name} <= {high:g}, the range of the "
                             "catalogue approximation of f_n; use speed_factor_exact")
    return 490.77 / (1.0 + 498.78 * k_L ** 0.599 + 852.88 * k_P ** 0.963
                     - 504.5 * k_L ** 0.055 * k_P ** 0.832)


@series_aware
def permissible_speed_factor(n_thr, f0, nu, dM, load_torque, Q):
    """Speed factor f_n = n_per/n_θr for the operating f0, ν, M_load [N·mm] and heat Q [W] carried away.

    The exact root of k_L·f_n^(5/3) + k_P·f_n = 1; where the operating
    point n_θr·f_n falls in the ν·n < 2000 regime the balance is solved with
    that regime's constant M0 instead.

    >>> round(permissible_speed_factor(14416.4, 2.0, 12.0, 38.5, 3.0218, 58.056), 6)   # (n_thr rounded up)
    0.999977
    """
    c_high, c_low = torque_coefficients(f0, dM)
    x, _, _, _ = balance_root(c_high, c_low, load_torque, nu, np.asarray(Q, dtype=float), n_thr)
    return x
