"""Heat balance of a rolling bearing: thermal reference speed, permissible speed, operating temperature.

Seed 002 (p. 63, "Теплоотвод") says the thermally permissible speed comes
from the balance between the friction power and the heat carried away; its
page 72 with the formulas is missing, so the method is the published one of
the Schaeffler HR 1 catalogue (2006, after ISO 15312 and the draft of
DIN 732), as restated in issue 3.

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
(:func:`bearingheat.friction.speed_dependent_torque` and
:func:`bearingheat.friction.load_dependent_torque`); the friction power of
the heat balance is (π·n/30)·1e-3·M [W], as issue 3 writes it (the engine's
N_R = M·n/9550 rounds π/30000 to 1/9550, 0.005 % apart).

>>> n_thr = thermal_reference_speed_rows(pd.DataFrame(
...     {"designation": ["6205", "NU206-E", "51105"], "d": [25, 30, 25], "D": [52, 62, 42],
...      "B": [15, 16, 11], "C0": [7800, 36000, 28500]}))
>>> n_thr.round(0).tolist()[:2]
[14416.0, 9851.0]
>>> n_thr.attrs["reason"].iloc[2]
'n_thr: the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings'
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from bearingheat import friction
from bearingheat._series import series_aware
from bearingheat.coefficients import resolve
from bearingheat.designation import DesignationError
from bearingheat.tables_io import load_table
from bearingheat.errors import HeatBalanceError

__all__ = [
    "POWER_PER_TORQUE_SPEED",
    "OIL_HEAT_CAPACITY_FLOW",
    "THERMAL_KIND",
    "HEAT_FLOW_AREA",
    "ReferenceConditions",
    "reference_conditions",
    "heat_flow_area",
    "reference_heat_flux_density",
    "default_heat_transfer_coefficient",
    "seat_heat_flow",
    "oil_heat_flow",
    "friction_heat",
    "balance_speed",
    "speed_factor_coefficients",
    "speed_factor_exact",
    "speed_factor_catalogue_approximation",
    "permissible_speed_factor",
    "operating_temperature",
    "thermal_reference_speed_rows",
    "thermal_reference_speed_details",
    "thermal_reference_speed",
    "method_refusal",
    "fill_viscosity",
    "heat_balance_rows",
    "heat_balance",
    "HeatBalanceResult",
    "HeatBalanceError",
    "OPERATING_TEMPERATURE_LIMIT",
]

#: (π/30)·1e-3: friction power [W] per torque [N·mm] and speed [1/min] (issue 3, the n_θr equation).
POWER_PER_TORQUE_SPEED = math.pi / 30.0 * 1e-3
#: Heat carried away by circulating oil: 0.0286 kW/(l/min·K) = 28.6 W/(l/min·K) (issue 3, after HR 1).
OIL_HEAT_CAPACITY_FLOW = 28.6

#: bearing type -> geometry of the heat flow area and reference conditions; None: the method does not apply
THERMAL_KIND: dict[str, str | None] = {
    "needle_roller": "radial",
    "cylindrical_roller_full_complement": "radial",
    "cylindrical_roller": "radial",
    "tapered_roller": "tapered",
    "spherical_roller": "radial",
    "deep_groove_ball": "radial",
    "angular_contact_ball": "radial",
    "angular_contact_ball_double_row": "radial",
    "self_aligning_ball": "radial",
    "four_point_contact_ball": "radial",
    "thrust_roller": "thrust",
    "axial_spherical_roller": "thrust",
    "thrust_ball": None,
    "combined": None,
}
#: why THERMAL_KIND is None for a type
_REFUSED_TYPES = {
    "thrust_ball": "the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings",
    "combined": ("combined radial/thrust bearings have no single heat flow area A_r in the method "
                 "(radial: pi*B*(D+d), thrust: (pi/2)*(D^2-d^2))"),
}
_CONTACT_SEAL_REASON = "the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals"


# ---- reference conditions (tables/thermal_reference_conditions.csv) ---------------------------

@dataclass(frozen=True)
class ReferenceConditions:
    """Reference conditions of the thermal reference speed for radial or thrust bearings."""

    kind: str               # 'radial' (also tapered) or 'thrust'
    load_ratio: float       # P1/C0 (radial) or Fa/C0 (thrust) [-]
    nu: float               # oil-bath viscosity [mm²/s]
    q_r: float              # heat flux density up to A_r_limit [W/mm²]
    A_r_limit: float        # [mm²]
    q_r_exponent: float     # q_r·(A_r/A_r_limit)^exponent above the limit [-]
    T_ambient: float        # [°C]
    T_bearing: float        # outer ring [°C]

    @property
    def temperature_rise(self) -> float:
        """Δθ_A of the reference conditions [K] (70 °C − 20 °C = 50 K)."""
        return self.T_bearing - self.T_ambient


@functools.lru_cache(maxsize=None)
def reference_conditions(kind: str) -> ReferenceConditions:
    """Reference conditions for 'radial', 'tapered' (radial conditions) or 'thrust' bearings.

    >>> r = reference_conditions("radial")
    >>> r.load_ratio, r.nu, r.q_r, r.temperature_rise
    (0.05, 12.0, 0.016, 50.0)
    >>> reference_conditions("thrust").q_r_exponent
    -0.16
    """
    key = "radial" if kind == "tapered" else kind
    table = load_table("thermal_reference_conditions")
    hit = table[table["kind"] == key]
    if hit.empty:
        raise ValueError(f"kind: {kind!r} is not one of radial, tapered, thrust")
    row = hit.iloc[0]
    return ReferenceConditions(kind=key, load_ratio=float(row["load_ratio"]), nu=float(row["nu_ref"]),
                               q_r=float(row["q_r"]), A_r_limit=float(row["A_r_limit"]),
                               q_r_exponent=float(row["q_r_exponent"]), T_ambient=float(row["T_ambient"]),
                               T_bearing=float(row["T_bearing"]))


# ---- heat flow area and heat carried away ----------------------------------------------------

def _area_radial(d, D, B, T):
    return math.pi * np.asarray(B, dtype=float) * (np.asarray(D, dtype=float) + d)


def _area_tapered(d, D, B, T):
    return math.pi * np.asarray(T, dtype=float) * (np.asarray(D, dtype=float) + d)


def _area_thrust(d, D, B, T):
    return math.pi / 2.0 * (np.square(np.asarray(D, dtype=float)) - np.square(np.asarray(d, dtype=float)))


#: kind -> (A_r function(d, D, B, T) [mm²], formula, width column it needs)
HEAT_FLOW_AREA = {
    "radial": (_area_radial, "pi*B*(D+d)", "B"),
    "tapered": (_area_tapered, "pi*T*(D+d)", "T"),
    "thrust": (_area_thrust, "(pi/2)*(D^2-d^2)", None),
}


@series_aware
def heat_flow_area(kind, d, D, B=np.nan, T=np.nan):
    """Reference heat flow area A_r [mm²] (issue 3, after HR 1 and ISO 15312).

    radial bearings π·B·(D+d); tapered roller bearings π·T·(D+d) with the
    total width T; thrust bearings (π/2)·(D²−d²). d, D, B, T [mm].

    >>> round(heat_flow_area("radial", 25, 52, B=15), 1)     # 6205
    3628.5
    >>> round(heat_flow_area("tapered", 25, 52, T=16.25), 1) # 30205-A
    3930.9
    >>> round(heat_flow_area("thrust", 25, 42), 1)           # 51105 size
    1789.1
    """
    return HEAT_FLOW_AREA[str(kind)][0](d, D, B, T)


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
def friction_heat(f0, nu, n, dM, load_torque):
    """Friction power (π·n/30)·1e-3·(M0 + M_load) [W] of the heat balance.

    M0 = :func:`bearingheat.friction.speed_dependent_torque` (both regimes);
    load_torque = M1 (+ M2) [N·mm] from the engine.

    >>> round(friction_heat(2.0, 12.0, 14416.4, 38.5, 3.0218), 2)  # 6205 at n_thr
    58.06
    """
    M0 = friction.speed_dependent_torque(f0, nu, n, dM)
    return POWER_PER_TORQUE_SPEED * np.asarray(n, dtype=float) * (M0 + np.asarray(load_torque, dtype=float))


# ---- exact roots of the heat balance ---------------------------------------------------------

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
        for _ in range(200):
            y2 = y * y
            y3 = y2 * y
            step = ((av * y2 + bv) * y3 - 1.0) / ((5.0 * av * y2 + 3.0 * bv) * y2)
            y = y - step
            if not np.any(np.abs(step) > 1e-15 * y):
                break
    if valid.all():
        x = y * y * y
    else:
        x[valid] = y * y * y
    return x.reshape(shape) if shape else float(x[0])


def _torque_coefficients(f0, dM):
    """(f0·dM³·1e-7, f0·160·dM³·1e-7) [N·mm] taken from the engine's M0 kernel.

    M0 = c_high·(ν·n)^(2/3) for ν·n >= 2000 and c_low for ν·n < 2000.
    """
    limit = friction.REGIME_LIMIT
    c_high = np.asarray(friction.speed_dependent_torque(f0, 1.0, limit, dM), dtype=float) / limit ** (2.0 / 3.0)
    return c_high, c_high * friction.LOW_REGIME_FACTOR


def _balance_root(c_high, c_low, load_torque, nu, Q, scale):
    """x = n/scale where (π·n/30)·1e-3·(M0(ν·n) + M_load) = Q, both M0 regimes.

    Below ν·n = 2000 M0 is constant, and the friction power steps down by
    0.79 % where the regimes meet; where both regimes give a root the lower
    speed is taken (the bearing reaches the heat limit there first).
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
    c_high, c_low = _torque_coefficients(f0, dM)
    x, _, _, _ = _balance_root(c_high, c_low, load_torque, nu, np.asarray(Q, dtype=float), 1.0)
    return x


@series_aware
def speed_factor_coefficients(n_thr, f0, nu, dM, load_torque, Q):
    """(k_L, k_P) of the speed factor f_n (issue 3, after HR 1).

    k_L = 1e-6·(π/30)·n_θr·1e-7·f0·(ν·n_θr)^(2/3)·dM³/Q,
    k_P = 1e-6·(π/30)·n_θr·f1·P1·dM/Q with Q in kW; here Q [W] and
    M_load = f1·P1·dM (+ M2) [N·mm], so the 1e-6 becomes 1e-3.

    >>> kL, kP = speed_factor_coefficients(14416.4, 2.0, 12.0, 38.5, 3.0218, 58.056)
    >>> round(kL, 4), round(kP, 4), round(kL + kP, 6)
    (0.9214, 0.0786, 1.0)
    """
    c_high, _ = _torque_coefficients(f0, dM)
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


#: validity of the catalogue approximation of f_n (issue 3, after HR 1)
APPROXIMATION_RANGE = (0.01, 10.0)


@series_aware
def speed_factor_catalogue_approximation(k_L, k_P):
    """Catalogue approximation of the speed factor (issue 3, after HR 1)::

        f_n = 490.77 / (1 + 498.78·k_L^0.599 + 852.88·k_P^0.963 − 504.5·k_L^0.055·k_P^0.832)

    Valid for 0.01 <= k_L, k_P <= 10; outside that range it raises
    ValueError naming the value (no extrapolation).

    >>> round(speed_factor_catalogue_approximation(0.5, 0.5), 3)
    0.991
    >>> speed_factor_catalogue_approximation(0.005, 0.5)
    Traceback (most recent call last):
    ...
    ValueError: k_L: 0.005 is outside 0.01 <= k_L <= 10, the range of the catalogue approximation of f_n; use speed_factor_exact
    """
    k_L = np.asarray(k_L, dtype=float)
    k_P = np.asarray(k_P, dtype=float)
    low, high = APPROXIMATION_RANGE
    for name, values in (("k_L", k_L), ("k_P", k_P)):
        bad = ~((values >= low) & (values <= high))
        if np.any(bad):
            first = np.ravel(values)[np.flatnonzero(np.ravel(np.broadcast_to(bad, np.shape(values))))[0]]
            raise ValueError(f"{name}: {first:g} is outside {low:g} <= {name} <= {high:g}, the range of the "
                             "catalogue approximation of f_n; use speed_factor_exact")
    return 490.77 / (1.0 + 498.78 * k_L ** 0.599 + 852.88 * k_P ** 0.963
                     - 504.5 * k_L ** 0.055 * k_P ** 0.832)


@series_aware
def permissible_speed_factor(n_thr, f0, nu, dM, load_torque, Q):
    """Speed factor f_n = n_per/n_θr for the operating f0, ν, M_load [N·mm] and heat Q [W] carried away.

    The exact root of k_L·f_n^(5/3) + k_P·f_n = 1; where the operating
    point n_θr·f_n falls in the ν·n < 2000 regime the balance is solved with
    that regime's constant M0 instead.

    >>> round(permissible_speed_factor(14416.4, 2.0, 12.0, 38.5, 3.0218, 58.056), 6)
    1.0
    """
    c_high, c_low = _torque_coefficients(f0, dM)
    x, _, _, _ = _balance_root(c_high, c_low, load_torque, nu, np.asarray(Q, dtype=float), n_thr)
    return x


# ---- operating temperature -------------------------------------------------------------------

def operating_temperature(heat_balance, T_low, T_high, *, iterations: int = 64):
    """Temperature T [°C] in [T_low, T_high] where ``heat_balance(T)`` changes sign, vectorised bisection.

    ``heat_balance(T)`` returns N_R(T) + Q_E − Q_S(T) − Q_L(T) [W] for an
    array of temperatures (one per row): positive while the bearing still
    heats up. Returns (T, status) where status is 0 for an equilibrium,
    1 where the balance is still positive at T_high (no equilibrium below
    T_high: the heat runs away), −1 where it is already negative at T_low.

    >>> import numpy as np
    >>> T, status = operating_temperature(lambda T: 100.0 - 2.0 * (T - 20.0), np.array([0.0]), np.array([150.0]))
    >>> T.round(9).tolist(), status.tolist()
    ([70.0], [0])
    """
    lo = np.asarray(T_low, dtype=float).copy()
    hi = np.asarray(T_high, dtype=float).copy()
    f_lo = np.asarray(heat_balance(lo), dtype=float)
    f_hi = np.asarray(heat_balance(hi), dtype=float)
    status = np.where(f_hi > 0, 1, np.where(f_lo < 0, -1, 0))
    status = np.where(np.isnan(f_lo) | np.isnan(f_hi), 2, status)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        f_mid = np.asarray(heat_balance(mid), dtype=float)
        heating = f_mid > 0
        lo = np.where(heating, mid, lo)
        hi = np.where(heating, hi, mid)
    T = np.where(status == 0, 0.5 * (lo + hi), np.nan)
    return T, status


# ---- rows: thermal reference speed of catalogue bearings -------------------------------------

def method_refusal(bearing_type: str, seal: str = "open") -> str:
    """Why the thermal method does not apply to a bearing ('' when it does).

    >>> method_refusal("thrust_ball")
    'the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings'
    >>> method_refusal("deep_groove_ball", "contact")
    'the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals'
    >>> method_refusal("deep_groove_ball", "shield")
    ''
    """
    if THERMAL_KIND.get(bearing_type, None) is None:
        return _REFUSED_TYPES.get(bearing_type, f"no thermal reference conditions for {bearing_type!r}")
    if seal == "contact":
        return _CONTACT_SEAL_REASON
    return ""


def _text_column(frame: pd.DataFrame, name: str) -> list:
    if name not in frame.columns:
        return [None] * len(frame)
    out = []
    for v in frame[name]:
        if v is None or (isinstance(v, float) and math.isnan(v)) or str(v).strip() == "":
            out.append(None)
        else:
            out.append(str(v).strip())
    return out


def _number_column(frame: pd.DataFrame, name: str) -> np.ndarray:
    if name not in frame.columns:
        return np.full(len(frame), np.nan)
    return pd.to_numeric(frame[name], errors="coerce").to_numpy(dtype=float, copy=True)


def _resolve_rows(frame: pd.DataFrame):
    """Per row: (ResolvedBearing or None, reason)."""
    designations = _text_column(frame, "designation")
    types = _text_column(frame, "type")
    series = _text_column(frame, "series")
    out = []
    for des, typ, ser in zip(designations, types, series):
        try:
            out.append((resolve(des, typ, ser), ""))
        except DesignationError as exc:
            out.append((None, str(exc)))
    return out


def thermal_reference_speed_details(frame: pd.DataFrame) -> pd.DataFrame:
    """Thermal reference speed of every row with the quantities behind it.

    ``frame`` is in catalogue units with columns ``designation`` (or
    ``type`` and ``series``), ``d``, ``D``, ``B``, ``T`` (total width of
    tapered roller bearings), ``C0`` [mm, N]. Returns a DataFrame with the
    same index: ``n_thr`` [1/min], ``kind``, ``A_r`` [mm²] and ``q_r``
    [W/mm²] (wherever the geometry allows, even without C0), ``f0``, ``f1``, ``P1`` [N], ``M1`` [N·mm], ``regime``
    ('nu*n >= 2000' or 'nu*n < 2000') and ``reason`` ('' where n_thr was
    computed, otherwise why not). Never raises for a bad row.

    Reference conditions: 20 °C ambient, 70 °C outer ring, oil bath with
    ν = 12 mm²/s (radial) or 24 mm²/s (thrust), load P1 = 0.05·C0 (radial)
    or Fa = 0.02·C0 (thrust), f0 = oil-bath value, f1 at load/C0 of the
    reference load.
    """
    n_rows = len(frame)
    resolved = _resolve_rows(frame)
    d = _number_column(frame, "d")
    D = _number_column(frame, "D")
    B = _number_column(frame, "B")
    T = _number_column(frame, "T")
    C0 = _number_column(frame, "C0")
    reason = [r for _, r in resolved]
    kind = np.array([""] * n_rows, dtype=object)
    f0 = np.full(n_rows, np.nan)
    f1_a = np.full(n_rows, np.nan)
    f1_x = np.full(n_rows, np.nan)
    geometry_ok = np.zeros(n_rows, dtype=bool)
    for i, (res, _) in enumerate(resolved):
        if res is None:
            continue
        entry = res.entry
        if np.isnan(d[i]) and res.designation is not None and res.designation.bore is not None:
            d[i] = res.designation.bore
        if np.isnan(B[i]) and res.designation is not None and res.designation.width is not None:
            B[i] = res.designation.width
        refusal = method_refusal(entry.bearing_type, res.seal)
        if refusal:
            reason[i] = f"n_thr: {refusal}"
            continue
        kind[i] = THERMAL_KIND[entry.bearing_type]
        checks = (
            ("d", d[i], "the bore d gives dM = (d + D)/2", lambda v: v > 0, "must be > 0"),
            ("D", D[i], "the outside diameter D gives dM = (d + D)/2 and A_r", lambda v: v > d[i],
             f"must be larger than d = {d[i]:g} mm"),
        )
        width = HEAT_FLOW_AREA[kind[i]][2]
        if width is not None:
            formula = HEAT_FLOW_AREA[kind[i]][1]
            value = B[i] if width == "B" else T[i]
            what = "width" if width == "B" else "total width"
            checks += ((width, value, f"the heat flow area A_r = {formula} needs the {what}",
                        lambda v: v > 0, "must be > 0"),)
        for column, value, why, ok, condition in checks:
            if np.isnan(value):
                reason[i] = f"{column} [mm]: missing; {why}"
                break
            if not ok(value):
                reason[i] = f"{column} [mm]: {value:g} {condition}"
                break
        if reason[i]:
            continue
        geometry_ok[i] = True
        f0_oil = entry.f0_oil
        if math.isnan(f0_oil):
            reason[i] = f"n_thr: {entry.label} has no oil-bath f0 in seed 002 (the table prints a dash)"
            continue
        f0[i] = friction.f0_needle(f0_oil, B[i], d[i]) if entry.f0_basis == "B/(33+d)" else f0_oil
        f1_a[i], f1_x[i] = entry.f1_a, entry.f1_x
        if np.isnan(C0[i]):
            reason[i] = "C0 [N]: missing; the reference load is a fraction of C0"
        elif not C0[i] > 0:
            reason[i] = f"C0 [N]: {C0[i]:g} must be > 0"
    usable = np.array([r == "" for r in reason], dtype=bool)
    A_r = np.full(n_rows, np.nan)
    q_r = np.full(n_rows, np.nan)
    load_ratio = np.full(n_rows, np.nan)
    nu_ref = np.full(n_rows, np.nan)
    for k in ("radial", "tapered", "thrust"):
        rows = geometry_ok & (kind == k)
        if not rows.any():
            continue
        ref = reference_conditions(k)
        A_r[rows] = heat_flow_area(k, d[rows], D[rows], B[rows], T[rows])
        q_r[rows] = reference_heat_flux_density(k, A_r[rows])
        load_ratio[rows] = ref.load_ratio
        nu_ref[rows] = ref.nu
    dM = friction.mean_diameter(d, D)
    P1 = load_ratio * C0
    with np.errstate(invalid="ignore"):
        f1 = friction.f1_from_load_ratio(f1_a, f1_x, load_ratio)
        M1 = friction.load_dependent_torque(f1, P1, dM)
        c_high, c_low = _torque_coefficients(f0, dM)
        x, _, _, low = _balance_root(c_high, c_low, M1, nu_ref, q_r * A_r, 1.0)
    n_thr = np.where(usable, x, np.nan)
    return pd.DataFrame({
        "n_thr": n_thr, "kind": kind, "A_r": A_r, "q_r": q_r,
        "f0": np.where(usable, f0, np.nan), "f1": np.where(usable, f1, np.nan),
        "P1": np.where(usable, P1, np.nan), "M1": np.where(usable, M1, np.nan),
        "regime": np.where(usable, np.where(low, "nu*n < 2000", "nu*n >= 2000"), ""),
        "reason": reason,
    }, index=frame.index)


def thermal_reference_speed_rows(frame: pd.DataFrame) -> pd.Series:
    """Thermal reference speed n_θr [1/min] of every row of ``frame`` (catalogue units).

    Columns: ``designation`` (or ``type`` + ``series``), ``d``, ``D``,
    ``B``, ``T`` (total width, tapered roller bearings; NaN otherwise),
    ``C0`` [mm, N]. Returns a float Series named ``n_thr`` with the index of
    ``frame``; rows that cannot be computed are NaN (no exception), and
    ``result.attrs['reason']`` is a Series of messages with the same index
    ('' where n_thr was computed). :func:`thermal_reference_speed_details`
    gives A_r, q_r, f0, f1, P1 and M1 as well.
    """
    details = thermal_reference_speed_details(frame)
    out = details["n_thr"].astype(float).rename("n_thr")
    out.attrs["reason"] = details["reason"].rename("reason")
    return out



# ---- rows: heat balance of supports (calc and the Python API) ------------------------------------

#: upper end of the search for the operating temperature [°C]; above it the heat is said to run away
OPERATING_TEMPERATURE_LIMIT = 150.0
#: the search for the operating temperature starts this far below the ambient temperature [K]
BELOW_AMBIENT_SEARCH = 50.0
#: how the permissible speed factor is found: exact root, or the catalogue approximation
SPEED_FACTOR_METHODS = {"exact": "exact root", "approximation": "catalogue approximation"}
#: where the operating viscosity is taken when it comes from nu40/nu100 or iso_vg
VISCOSITY_AT = {
    "auto": "T_bearing where given, otherwise the solved operating temperature T_op",
    "bearing": "the bearing temperature T_bearing",
    "operating": "the solved operating temperature T_op at the operating speed n",
}


#: input columns that only the heat balance reads (B and C0 belong to the friction model as well)
THERMAL_INPUTS = frozenset({"T", "k_q", "T_amb", "T_bearing", "V_oil", "dT_oil", "Q_E", "nu40", "nu100", "iso_vg",
                            "VI", "n_G", "n_thr_catalogue"})


def _viscosity_of_rows(frame: pd.DataFrame, A, B):
    """ν(θ) for every row: Walther where A, B are known, the constant ``nu`` column otherwise."""
    nu_fixed = _number_column(frame, "nu")
    has_model = ~np.isnan(A)

    def nu_at(theta):
        with np.errstate(invalid="ignore", over="ignore"):
            from bearingheat.viscosity import walther_viscosity

            return np.where(has_model, walther_viscosity(A, B, theta), nu_fixed)

    return nu_at


def _walther_columns(frame: pd.DataFrame):
    if "_walther_A" in frame.columns:
        return _number_column(frame, "_walther_A"), _number_column(frame, "_walther_B"), []
    from bearingheat.viscosity import viscosity_model_rows

    return viscosity_model_rows(frame)


def _heat_flow_setup(frame: pd.DataFrame):
    """A_r, k_q, reference-speed details and the heat flows as functions of the bearing temperature."""
    details = thermal_reference_speed_details(frame)
    kinds = details["kind"].to_numpy(dtype=object)
    A_r = details["A_r"].to_numpy(dtype=float)
    k_q_default = np.full(len(frame), np.nan)
    for k in ("radial", "tapered", "thrust"):
        rows = kinds == k
        if rows.any():
            k_q_default[rows] = default_heat_transfer_coefficient(k, A_r[rows])
    k_q_user = _number_column(frame, "k_q")
    k_q = np.where(np.isnan(k_q_user), k_q_default, k_q_user)
    T_amb = _number_column(frame, "T_amb")
    V_oil = np.nan_to_num(_number_column(frame, "V_oil"), nan=0.0)
    dT_oil = _number_column(frame, "dT_oil")
    Q_E = np.nan_to_num(_number_column(frame, "Q_E"), nan=0.0)

    def Q_S(theta):
        return seat_heat_flow(k_q, A_r, np.asarray(theta, dtype=float) - T_amb)

    def Q_L(theta):
        # oil temperature rise: given dT_oil, otherwise oil fed at ambient and leaving at the bearing temperature
        rise = np.where(np.isnan(dT_oil), np.asarray(theta, dtype=float) - T_amb, dT_oil)
        return np.where(V_oil > 0, oil_heat_flow(V_oil, rise), 0.0)

    return details, k_q, T_amb, Q_E, Q_S, Q_L


def _operating_point(frame, results, nu_at, Q_S, Q_L, Q_E, T_amb, t_limit):
    """(T_op, status) at the operating speed: N_R(ν(T)) + Q_E = Q_S(T) + Q_L(T)."""
    n = _number_column(frame, "n")
    dM = friction.mean_diameter(_number_column(frame, "d"), _number_column(frame, "D"))
    f0 = results["f0"].to_numpy(dtype=float)
    load_torque = results["M1"].to_numpy(dtype=float) + np.nan_to_num(results["M2"].to_numpy(dtype=float))

    def balance(theta):
        with np.errstate(invalid="ignore", over="ignore"):
            return friction_heat(f0, nu_at(theta), n, dM, load_torque) + Q_E - Q_S(theta) - Q_L(theta)

    T_low = T_amb - BELOW_AMBIENT_SEARCH
    T_high = np.full(len(frame), float(t_limit))
    T_op, status = operating_temperature(balance, T_low, T_high)
    return T_op, status, balance


def fill_viscosity(frame: pd.DataFrame, *, viscosity_at: str = "auto",
                   t_limit: float = OPERATING_TEMPERATURE_LIMIT):
    """Fill an empty ``nu`` from ``nu40``/``nu100`` or ``iso_vg`` (catalogue units); returns (frame, problems).

    Where ``viscosity_at`` is 'auto' the viscosity is taken at ``T_bearing``
    when the row gives it, otherwise at the operating temperature T_op
    solved at the operating speed (``n``, ``T_amb``). A ``nu`` the user
    gives is never replaced. The Walther constants stay in the hidden
    columns ``_walther_A`` and ``_walther_B`` for the heat balance.
    """
    if viscosity_at not in VISCOSITY_AT:
        raise ValueError(f"viscosity_at: {viscosity_at!r} is not one of {', '.join(VISCOSITY_AT)}")
    frame = frame.copy()
    A, B, problems = _walther_columns(frame)
    frame["_walther_A"] = A
    frame["_walther_B"] = B
    if np.isnan(A).all():
        return frame, problems
    from bearingheat.viscosity import walther_viscosity

    nu = _number_column(frame, "nu")
    need = np.isnan(nu) & ~np.isnan(A)
    T_bearing = _number_column(frame, "T_bearing")
    at_bearing = need & ~np.isnan(T_bearing) & (viscosity_at in ("auto", "bearing"))
    at_operating = need & ~at_bearing & (viscosity_at in ("auto", "operating"))
    with np.errstate(invalid="ignore", over="ignore"):
        nu = np.where(at_bearing, walther_viscosity(A, B, T_bearing), nu)
    source = np.where(at_bearing, "T_bearing", np.where(~np.isnan(_number_column(frame, "nu")), "given", ""))
    if viscosity_at == "bearing":
        for i in np.flatnonzero(need & np.isnan(T_bearing)):
            problems.append((int(i), "error", "T_bearing [degC]: missing; the viscosity is to be taken at the "
                                              "bearing temperature"))
    if at_operating.any():
        T_op = _solve_operating_temperature(frame, A, B, at_operating, t_limit, problems)
        with np.errstate(invalid="ignore", over="ignore"):
            nu = np.where(at_operating, walther_viscosity(A, B, T_op), nu)
        source = np.where(at_operating & ~np.isnan(T_op), "T_op", source)
    frame["nu"] = nu
    frame["_nu_source"] = source
    return frame, problems


def _solve_operating_temperature(frame, A, B, rows, t_limit, problems):
    """T_op of the selected rows before the friction pass (f0, M1, M2 do not depend on ν)."""
    from bearingheat.model import compute_supports
    from bearingheat.viscosity import walther_viscosity

    T_op = np.full(len(frame), np.nan)
    T_amb = _number_column(frame, "T_amb")
    n = _number_column(frame, "n")
    for i in np.flatnonzero(rows & (np.isnan(T_amb) | np.isnan(n))):
        missing = "T_amb [degC]" if np.isnan(T_amb[i]) else "n [1/min]"
        problems.append((int(i), "error", f"{missing}: missing; nu from nu40/nu100 or iso_vg is taken at the "
                                          "operating temperature T_op, which needs n and T_amb (or give T_bearing)"))
    rows = rows & ~np.isnan(T_amb) & ~np.isnan(n)
    if not rows.any() or not {"D"} <= set(frame.columns):
        return T_op
    provisional = frame.reset_index(drop=True).copy()
    with np.errstate(invalid="ignore", over="ignore"):
        provisional["nu"] = np.where(np.isnan(_number_column(frame, "nu")),
                                     walther_viscosity(A, B, np.full(len(frame), 70.0)), _number_column(frame, "nu"))
    results = compute_supports(provisional)
    details, k_q, T_amb, Q_E, Q_S, Q_L = _heat_flow_setup(provisional)
    nu_at = _viscosity_of_rows(provisional, A, B)
    T, status, _ = _operating_point(provisional, results, nu_at, Q_S, Q_L, Q_E, T_amb, t_limit)
    failed = (results["status"].to_numpy() == "error") | _plain_rows(results)
    reasons = details["reason"].to_numpy(dtype=object)
    for i in np.flatnonzero(rows):
        if failed[i]:
            continue  # the friction pass reports the row's own error
        if reasons[i]:
            problems.append((int(i), "error", f"nu [mm^2/s]: cannot be taken at T_op; {reasons[i]}; give T_bearing"))
        elif status[i] != 0:
            problems.append((int(i), "error", f"nu [mm^2/s]: cannot be taken at T_op; "
                                              f"{_no_equilibrium_text(status[i], T_amb[i], t_limit)}"))
        else:
            T_op[i] = T[i]
    return T_op


def _plain_rows(results: pd.DataFrame) -> np.ndarray:
    if "bearing_type" not in results.columns:
        return np.zeros(len(results), dtype=bool)
    return (results["bearing_type"].astype(str) == "plain_bushing").to_numpy()


def _no_equilibrium_text(status, T_amb, t_limit):
    if status == 1:
        return (f"no equilibrium below {t_limit:g} degC: the friction heat exceeds the heat carried away "
                "(the temperature runs away)")
    if status == -1:
        return (f"no equilibrium above {T_amb - BELOW_AMBIENT_SEARCH:g} degC: the heat carried away exceeds "
                "the friction heat")
    return "the heat balance is undefined (missing inputs)"


def heat_balance_rows(frame: pd.DataFrame, results: pd.DataFrame, *, method: str = "exact",
                      t_limit: float = OPERATING_TEMPERATURE_LIMIT):
    """n_thr, n_per, T_op, nu_op, Q_S, Q_L of every row (catalogue units); returns (columns, problems).

    ``frame`` holds the calc inputs (after :func:`fill_viscosity`),
    ``results`` the friction results of :func:`bearingheat.model.compute_supports`
    (f0, M1, M2, status). Rows whose friction failed are skipped. Columns
    come out only where their inputs are present: n_thr with B or T; n_per
    with T_bearing and T_amb; T_op and nu_op with T_amb; Q_S and Q_L with
    T_amb. problems are (row position, 'warning' | 'error', message).
    """
    if method not in SPEED_FACTOR_METHODS:
        raise ValueError(f"method: {method!r} is not one of {', '.join(SPEED_FACTOR_METHODS)}")
    n_rows = len(frame)
    problems: list[tuple[int, str, str]] = []
    has = set(frame.columns)
    # rows whose friction failed, and plain bushings (no rolling bearing heat balance), are skipped
    failed = (results["status"].to_numpy() == "error") | _plain_rows(results)
    columns: dict[str, np.ndarray] = {}
    wants_thr = bool({"B", "T"} & has) or "n_thr_catalogue" in has
    wants_balance = "T_amb" in has
    if not (wants_thr or wants_balance):
        return pd.DataFrame(index=frame.index), problems
    details, k_q, T_amb, Q_E, Q_S, Q_L = _heat_flow_setup(frame)
    reasons = details["reason"].to_numpy(dtype=object)
    n_thr = details["n_thr"].to_numpy(dtype=float)
    n_thr_catalogue = _number_column(frame, "n_thr_catalogue")
    reported_reason = np.zeros(n_rows, dtype=bool)

    # with only friction columns (B, C0) n_thr is added quietly; the reasons are told once the user asks
    # for thermal results with a thermal input column
    explicit = bool(has & THERMAL_INPUTS)

    def reason_once(i):
        if explicit and not reported_reason[i] and reasons[i]:
            reported_reason[i] = True
            problems.append((int(i), "warning", reasons[i] if reasons[i].startswith("n_thr") else
                             f"n_thr: {reasons[i]}"))

    if wants_thr:
        columns["n_thr"] = n_thr
        for i in np.flatnonzero(~failed & np.isnan(n_thr)):
            reason_once(i)
        for i in np.flatnonzero(~failed & (n_thr_catalogue <= 0)):
            problems.append((int(i), "error", f"n_thr_catalogue [1/min]: {n_thr_catalogue[i]:g} must be > 0"))
    if not wants_balance:
        return pd.DataFrame(columns, index=frame.index), problems

    A, B, model_problems = _walther_columns(frame)
    if "_walther_A" not in has:
        problems.extend(model_problems)
    nu_at = _viscosity_of_rows(frame, A, B)
    for i in np.flatnonzero(~failed & np.isnan(T_amb)):
        problems.append((int(i), "warning", "T_amb [degC]: missing; the heat balance (T_op, n_per) needs the "
                                            "ambient temperature"))
    k_q_user = _number_column(frame, "k_q")
    for i in np.flatnonzero(~failed & (k_q_user <= 0)):
        problems.append((int(i), "error", f"k_q [W/(mm^2*K)]: {k_q_user[i]:g} must be > 0"))
    for name in ("V_oil",):
        values = _number_column(frame, name)
        for i in np.flatnonzero(~failed & (values < 0)):
            problems.append((int(i), "error", f"V_oil [l/min]: {values[i]:g} must be >= 0"))

    # --- operating temperature at the operating speed
    T_op, status, _ = _operating_point(frame, results, nu_at, Q_S, Q_L, Q_E, T_amb, t_limit)
    usable = ~failed & ~np.isnan(T_amb) & ~np.isnan(details["A_r"].to_numpy(dtype=float))
    for i in np.flatnonzero(usable & (status != 0)):
        problems.append((int(i), "warning", f"T_op: {_no_equilibrium_text(status[i], T_amb[i], t_limit)}"))
    for i in np.flatnonzero(~failed & ~np.isnan(T_amb) & np.isnan(details["A_r"].to_numpy(dtype=float))):
        reason_once(i)
    T_op = np.where(usable, T_op, np.nan)
    with np.errstate(invalid="ignore", over="ignore"):
        nu_op = nu_at(T_op)
    from bearingheat.viscosity import viscosity_range_messages

    for i in np.flatnonzero(~np.isnan(nu_op)):
        message = viscosity_range_messages(nu_op[i], T_op[i])[0]
        if message:
            problems.append((int(i), "warning", f"nu_op: {message}"))
    columns["T_op"] = T_op
    columns["nu_op"] = nu_op

    # --- heat carried away: at T_bearing where given, otherwise at T_op
    T_bearing = _number_column(frame, "T_bearing")
    theta = np.where(np.isnan(T_bearing), T_op, T_bearing)
    with np.errstate(invalid="ignore"):
        columns["Q_S"] = np.where(usable, Q_S(theta), np.nan)
        columns["Q_L"] = np.where(usable, Q_L(theta), np.nan)

    # --- permissible speed at the bearing temperature T_bearing
    if "T_bearing" in has:
        columns["n_per"] = _permissible_speed_rows(frame, results, details, n_thr, n_thr_catalogue,
                                                   T_bearing, T_amb, Q_S, Q_L, Q_E, usable, method, problems)
    ordered = [c for c in ("n_thr", "n_per", "T_op", "nu_op", "Q_S", "Q_L") if c in columns]
    return pd.DataFrame({c: columns[c] for c in ordered}, index=frame.index), problems


def _permissible_speed_rows(frame, results, details, n_thr, n_thr_catalogue, T_bearing, T_amb, Q_S, Q_L, Q_E,
                            usable, method, problems):
    n_rows = len(frame)
    rows = usable & ~np.isnan(T_bearing)
    for i in np.flatnonzero(usable & np.isnan(T_bearing)):
        problems.append((int(i), "warning", "T_bearing [degC]: missing; n_per is the speed at which the bearing "
                                            "reaches T_bearing"))
    for i in np.flatnonzero(rows & (T_bearing <= T_amb)):
        problems.append((int(i), "error", f"T_bearing [degC]: {T_bearing[i]:g} must be above T_amb = {T_amb[i]:g} "
                                          "degC for heat to leave through the seat"))
    rows &= T_bearing > T_amb
    n_used = np.where(np.isnan(n_thr_catalogue), n_thr, n_thr_catalogue)
    rows &= n_used > 0
    Q = Q_S(T_bearing) + Q_L(T_bearing) - Q_E
    for i in np.flatnonzero(rows & ~(Q > 0)):
        problems.append((int(i), "warning", f"n_per: the external heat Q_E = {Q_E[i]:g} W is not less than the heat "
                                            f"carried away {Q[i] + Q_E[i]:.4g} W at T_bearing; no speed is "
                                            "permissible"))
    rows &= Q > 0
    out = np.full(n_rows, np.nan)
    if not rows.any():
        return out
    dM = friction.mean_diameter(_number_column(frame, "d"), _number_column(frame, "D"))
    nu = _number_column(frame, "nu")
    f0 = results["f0"].to_numpy(dtype=float)
    load_torque = results["M1"].to_numpy(dtype=float) + np.nan_to_num(results["M2"].to_numpy(dtype=float))
    sel = np.flatnonzero(rows)
    if method == "exact":
        f_n = permissible_speed_factor(n_used[sel], f0[sel], nu[sel], dM[sel], load_torque[sel], Q[sel])
    else:
        k_L, k_P = speed_factor_coefficients(n_used[sel], f0[sel], nu[sel], dM[sel], load_torque[sel], Q[sel])
        f_n = np.full(len(sel), np.nan)
        inside = ((k_L >= APPROXIMATION_RANGE[0]) & (k_L <= APPROXIMATION_RANGE[1])
                  & (k_P >= APPROXIMATION_RANGE[0]) & (k_P <= APPROXIMATION_RANGE[1]))
        if inside.any():
            f_n[inside] = speed_factor_catalogue_approximation(k_L[inside], k_P[inside])
        for j in np.flatnonzero(~inside):
            problems.append((int(sel[j]), "warning", f"n_per: k_L = {k_L[j]:.4g}, k_P = {k_P[j]:.4g} outside "
                                                     "0.01..10, the range of the catalogue approximation"))
    out[sel] = f_n * n_used[sel]
    n_G = _number_column(frame, "n_G")
    capped = rows & (out > n_G)
    for i in np.flatnonzero(capped):
        problems.append((int(i), "warning", f"n_per: the thermal value {out[i]:.5g} 1/min is above the limiting "
                                            f"speed n_G = {n_G[i]:g} 1/min; n_per = n_G"))
    return np.where(capped, n_G, out)


# ---- unit-aware API ------------------------------------------------------------------------------



@dataclass
class HeatBalanceResult:
    """Heat balance of one bearing or of many operating points, as Quantities.

    n_thr, n_per [1/min]; T_op [degC]; nu_op [mm²/s]; Q_S, Q_L [W] carried
    away (at T_bearing where given, else at T_op); N_R [W] friction power at
    the operating point. NaN where a value could not be computed:
    ``status`` ('ok' | 'warning' | 'error') and ``messages`` say why, per row.
    """

    n_thr: object
    n_per: object
    T_op: object
    nu_op: object
    Q_S: object
    Q_L: object
    N_R: object
    status: list
    messages: list


def _frame_column(value, unit, name):
    if value is None:
        return None
    if unit == "degC":
        from bearingheat.viscosity import _celsius

        return _celsius(value, name)
    if unit == "1":
        return np.asarray(getattr(value, "magnitude", value), dtype=float)
    from bearingheat.units import magnitude

    return magnitude(value, unit, name)


_API_COLUMNS = {
    # argument -> (frame column, catalogue unit)
    "d": ("d", "mm"), "D": ("D", "mm"), "B": ("B", "mm"), "T": ("T", "mm"), "C0": ("C0", "N"),
    "n": ("n", "1/min"), "Fr": ("Fr", "N"), "Fa": ("Fa", "N"), "nu": ("nu", "mm^2/s"),
    "T_ambient": ("T_amb", "degC"), "T_bearing": ("T_bearing", "degC"), "k_q": ("k_q", "W/(mm^2*K)"),
    "V_oil": ("V_oil", "l/min"), "dT_oil": ("dT_oil", "delta_degC"), "Q_E": ("Q_E", "W"),
    "nu40": ("nu40", "mm^2/s"), "nu100": ("nu100", "mm^2/s"), "iso_vg": ("iso_vg", "1"),
    "viscosity_index": ("VI", "1"), "n_G": ("n_G", "1/min"), "n_thr_catalogue": ("n_thr_catalogue", "1/min"),
}


def heat_balance(designation: str | None = None, *, d, D, n=None, C0=None, B=None, T=None, Fr=None, Fa=None,
                 lubrication: str = "oil_bath", nu=None, nu40=None, nu100=None, iso_vg=None, viscosity_index=None,
                 T_ambient=None, T_bearing=None, k_q=None, V_oil=None, dT_oil=None, Q_E=None, n_G=None,
                 n_thr_catalogue=None, viscosity_at: str = "auto", method: str = "exact",
                 t_limit=None, bearing_type: str | None = None, series: str | None = None) -> HeatBalanceResult:
    """Thermal reference speed, permissible speed and operating temperature of a bearing (Quantities).

    Every dimensional argument is a pint Quantity (arrays and pint-pandas
    Series broadcast: one bearing, many operating points). Temperatures are
    absolute (degC, K); ``dT_oil`` is a difference (K, delta_degC);
    ``iso_vg`` and ``viscosity_index`` are plain numbers. ``viscosity_at``:
    'auto' (ν at T_bearing where given, else at T_op), 'bearing' or
    'operating' — where ν comes from nu40/nu100 or iso_vg; a given ``nu``
    is always used as it is. ``method``: 'exact' root of the f_n equation
    or the catalogue 'approximation'. ``t_limit``: the highest temperature
    searched for T_op (default 150 °C).

    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
    ...                  Fr=2 * u.kN, nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"),
    ...                  T_ambient=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    >>> round(r.n_thr.to("1/min").magnitude), round(r.n_per.to("1/min").magnitude), r.status
    (14416, 8053, ['ok'])
    >>> round(r.T_op.to("degC").magnitude, 1), round(r.nu_op.to("mm^2/s").magnitude, 1)
    (40.1, 67.5)
    """
    from bearingheat.model import compute_supports
    from bearingheat.units import quantity

    if method not in SPEED_FACTOR_METHODS:
        raise ValueError(f"method: {method!r} is not one of {', '.join(SPEED_FACTOR_METHODS)}")
    if viscosity_at not in VISCOSITY_AT:
        raise ValueError(f"viscosity_at: {viscosity_at!r} is not one of {', '.join(VISCOSITY_AT)}")
    args = {"d": d, "D": D, "B": B, "T": T, "C0": C0, "n": n, "Fr": Fr, "Fa": Fa, "nu": nu,
            "T_ambient": T_ambient, "T_bearing": T_bearing, "k_q": k_q, "V_oil": V_oil, "dT_oil": dT_oil,
            "Q_E": Q_E, "nu40": nu40, "nu100": nu100, "iso_vg": iso_vg, "viscosity_index": viscosity_index,
            "n_G": n_G, "n_thr_catalogue": n_thr_catalogue}
    columns = {}
    index = None
    for name, value in args.items():
        column, unit = _API_COLUMNS[name]
        mag = _frame_column(value, unit, name)
        if mag is None:
            continue
        if isinstance(mag, pd.Series):
            index = mag.index if index is None else index
            mag = mag.to_numpy(dtype=float)
        columns[column] = mag
    if "n" not in columns:
        columns["n"] = np.nan
    shape = np.broadcast_shapes(*(np.shape(v) for v in columns.values()))
    size = int(np.prod(shape)) if shape else 1
    frame = pd.DataFrame({k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for k, v in columns.items()},
                         index=range(size))
    frame["designation"] = designation
    if bearing_type or series:
        frame["type"] = bearing_type
        frame["series"] = series
    frame["lubrication"] = lubrication
    limit = OPERATING_TEMPERATURE_LIMIT
    if t_limit is not None:
        from bearingheat.viscosity import _celsius

        limit = float(_celsius(t_limit, "t_limit"))
    frame, problems = fill_viscosity(frame, viscosity_at=viscosity_at, t_limit=limit)
    if "nu" not in frame.columns:
        raise HeatBalanceError("nu: missing; give nu, or nu40 and nu100, or iso_vg")
    results = compute_supports(frame)
    extra, more = heat_balance_rows(frame, results, method=method, t_limit=limit)
    problems = problems + more
    status = results["status"].tolist()
    messages = [[m] if m else [] for m in results["message"]]
    for position, level, message in problems:
        messages[position].append(message)
        if level == "error":
            status[position] = "error"
        elif status[position] == "ok":
            status[position] = "warning"
    failed = np.array([s == "error" for s in status])

    def out(name, unit):
        values = extra[name].to_numpy(dtype=float) if name in extra.columns else np.full(size, np.nan)
        values = np.where(failed, np.nan, values)
        if index is not None:
            return quantity(pd.Series(values, index=index), unit)
        return quantity(values.reshape(shape) if shape else float(values[0]), unit)

    N_R = np.where(failed, np.nan, POWER_PER_TORQUE_SPEED * frame["n"].to_numpy(dtype=float)
                   * results["MR"].to_numpy(dtype=float))
    N_R_q = (quantity(pd.Series(N_R, index=index), "W") if index is not None
             else quantity(N_R.reshape(shape) if shape else float(N_R[0]), "W"))
    return HeatBalanceResult(n_thr=out("n_thr", "1/min"), n_per=out("n_per", "1/min"), T_op=out("T_op", "degC"),
                             nu_op=out("nu_op", "mm^2/s"), Q_S=out("Q_S", "W"), Q_L=out("Q_L", "W"), N_R=N_R_q,
                             status=status, messages=["; ".join(m) for m in messages])


def thermal_reference_speed(designation: str | None = None, *, d, D, C0, B=None, T=None,
                            bearing_type: str | None = None, series: str | None = None):
    """Thermal reference speed n_θr of catalogue bearings as a Quantity [1/min].

    Arguments are pint Quantities (arrays broadcast). Raises
    :class:`HeatBalanceError` with the reason where n_θr cannot be computed;
    :func:`thermal_reference_speed_rows` returns NaN and the reasons instead.

    >>> import pint
    >>> u = pint.get_application_registry()
    >>> round(thermal_reference_speed("30205-A", d=25 * u.mm, D=52 * u.mm, T=16.25 * u.mm, C0=34.5 * u.kN).magnitude)
    9132
    >>> thermal_reference_speed("6205-2RSR", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: 6205-2RSR: n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals
    """
    from bearingheat.units import magnitude, quantity

    columns = {"d": magnitude(d, "mm", "d"), "D": magnitude(D, "mm", "D"), "C0": magnitude(C0, "N", "C0")}
    if B is not None:
        columns["B"] = magnitude(B, "mm", "B")
    if T is not None:
        columns["T"] = magnitude(T, "mm", "T")
    shape = np.broadcast_shapes(*(np.shape(v) for v in columns.values()))
    size = int(np.prod(shape)) if shape else 1
    frame = pd.DataFrame({k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for k, v in columns.items()})
    frame["designation"] = designation
    if bearing_type or series:
        frame["type"], frame["series"] = bearing_type, series
    result = thermal_reference_speed_rows(frame)
    reasons = result.attrs["reason"]
    bad = reasons[reasons != ""]
    if len(bad):
        label = designation or f"{bearing_type} {series}"
        where = f" (row {bad.index[0]})" if size > 1 else ""
        raise HeatBalanceError(f"{label}{where}: {bad.iloc[0]}")
    values = result.to_numpy(dtype=float)
    return quantity(values.reshape(shape) if shape else float(values[0]), "1/min")
