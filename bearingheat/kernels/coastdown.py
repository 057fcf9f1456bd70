"""Kernels of the coast-down (run-down) test: the TMM-7M lab sheet formulas, the Schaeffler catalogue rolling form, smoothing, integration.

The TMM-7M lab sheet (lab work on the TMM-7M rig) finds the *reduced friction coefficient*
f of a plain bearing from the run-down diagram n(t) after the motor is
disconnected. Its formulas were lost in the OCR; they are rebuilt here from
the equation of motion of the rotor.

Equation of motion (the TMM-7M lab sheet, driving torque M_d = 0 during the run-down)::

    I·dω/dt = −M_c,   M_c = f·G·r,   ω = π·n/30

so that (formula 1, instantaneous, from the slope of n(t))::

    f = −(π·I / (30·G·r)) · dn/dt

and, over an interval where f is taken as constant (formula 2)::

    f = π·I·Δn / (30·G·r·Δt)

with Δn the speed drop [1/min] over Δt [s].

A rolling-bearing spindle follows the catalogue form of the Schaeffler catalogue instead:
M = z·(M0(n) + M1), with M0 and M1 from the engine kernels
(:mod:`bearingheat.kernels.friction`).

Units: t [s], n [1/min], I [kg·m²], G [N], r [mm], torques [N·m] (the Schaeffler catalogue
M0 and M1 in [N·mm]). No units are checked here: :mod:`bearingheat.api.coastdown`
is the unit boundary; the fits are in :mod:`bearingheat.analysis.coastdown`.

>>> round(reduced_friction_coefficient_tmm7m_formula2(100.0, 10.0, I=2.6, G=1100.0, r=25.0), 5)
0.09901
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from bearingheat.errors import CoastdownError
from bearingheat.kernels import friction

__all__ = [
    "RPM_TO_RAD_S",
    "TMM_7M",
    "reduced_friction_coefficient_tmm7m_formula1",
    "reduced_friction_coefficient_tmm7m_formula2",
    "rolling_bearing_M0_schaeffler",
    "rolling_bearing_M1_schaeffler",
    "savitzky_golay_irregular",
    "rundown_speed",
    "plain_torque",
]

RPM_TO_RAD_S = math.pi / 30.0  # ω = π·n/30 (the TMM-7M lab sheet)

#: Rig data of the TMM-7M (the TMM-7M lab sheet, 'technical characteristics'): moment of
#: inertia of the rotor [kg·m²], rotor weight [N], journal radius [mm] (Ø 50 mm).
TMM_7M = {"I": 2.6, "G": 1100.0, "r": 25.0}


# --------------------------------------------------------------------------- the TMM-7M lab sheet formulas
def reduced_friction_coefficient_tmm7m_formula1(dn_dt, I, G, r):
    """Instantaneous reduced friction coefficient, the TMM-7M lab sheet formula (1).

    f = −π·I·(dn/dt) / (30·G·r)

    dn_dt [1/min per s] slope of the run-down diagram (negative while slowing
    down), I [kg·m²] moment of inertia about the shaft, G [N] rotor weight
    (the journal load), r [mm] journal radius. Derived from I·dω/dt = −f·G·r
    with ω = π·n/30 (the TMM-7M lab sheet, p. 'Установка ТММ-7М', equation of motion).
    Valid while the rotor runs down with no driving torque (M_d = 0) and I,
    G, r > 0.

    >>> round(reduced_friction_coefficient_tmm7m_formula1(-10.0, I=2.6, G=1100.0, r=25.0), 5)
    0.09901
    """
    return -I * RPM_TO_RAD_S * dn_dt / (G * r / 1000.0)


def reduced_friction_coefficient_tmm7m_formula2(delta_n, delta_t, I, G, r):
    """Interval-average reduced friction coefficient, the TMM-7M lab sheet formula (2).

    f = π·I·Δn / (30·G·r·Δt)

    delta_n [1/min] speed drop over the interval (positive), delta_t [s] its
    duration, I [kg·m²], G [N], r [mm]. Formula (1) with dn/dt replaced by the
    finite slope −Δn/Δt, i.e. f taken as constant over the interval (valid
    for Δt > 0 during a run-down with no driving torque).

    TMM-7M (I = 2.6 kg·m², G = 1100 N, r = 25 mm), Δn = 100 1/min in 10 s:
    f = π·2.6·100 / (30·1100·0.025·10) = 816.8 / 8250

    >>> round(reduced_friction_coefficient_tmm7m_formula2(100.0, 10.0, I=2.6, G=1100.0, r=25.0), 5)
    0.09901
    """
    return I * RPM_TO_RAD_S * delta_n / (G * r / 1000.0 * delta_t)


# --------------------------------------------------------------------------- the Schaeffler catalogue rolling form
def rolling_bearing_M0_schaeffler(n, nu, dM, f0):
    """Speed-dependent friction torque M0 [N·mm] of one rolling bearing (the Schaeffler catalogue, p. 64).

    M0 = f0·(ν·n)^(2/3)·dM³·1e-7   for ν·n ≥ 2000
    M0 = f0·160·dM³·1e-7           for ν·n < 2000

    n [1/min], nu [mm²/s] oil (or grease base oil) viscosity at operating
    temperature, dM [mm] mean diameter (d + D)/2, f0 [1]. The engine kernel
    :func:`bearingheat.kernels.friction.speed_dependent_torque`, in the
    argument order of the coast-down fit.

    >>> round(float(rolling_bearing_M0_schaeffler(3000.0, 20.0, 50.0, 2.0)), 3)
    38.315
    >>> round(float(rolling_bearing_M0_schaeffler(50.0, 20.0, 50.0, 2.0)), 3)
    4.0
    """
    return friction.speed_dependent_torque(f0, nu, n, dM)


def rolling_bearing_M1_schaeffler(P, dM, f1):
    """Load-dependent friction torque M1 = f1·P·dM [N·mm] of one rolling bearing (the Schaeffler catalogue, p. 64).

    P [N] load that determines the friction torque (P1, or F for roller
    bearings), dM [mm] mean diameter, f1 [1]. The engine kernel
    :func:`bearingheat.kernels.friction.load_dependent_torque`.

    >>> rolling_bearing_M1_schaeffler(1000.0, 50.0, 0.0005)
    25.0
    """
    return friction.load_dependent_torque(f1, P, dM)


# --------------------------------------------------------------------------- smoothing
def savitzky_golay_irregular(t, y, window, order=2):
    """Savitzky–Golay smoothing and first derivative for samples that need not be equally spaced.

    At every sample a polynomial of degree ``order`` is fitted by least squares
    to the ``window`` nearest samples (the window is centred, and shifted
    inwards at the ends); its value and slope at the sample are returned. On
    equally spaced samples this is exactly ``scipy.signal.savgol_filter`` with
    ``mode='interp'`` (Savitzky and Golay, Anal. Chem. 36 (1964) 1627).
    t [s] strictly increasing; y in any unit; window: an odd number of
    samples from order + 2 to the number of samples, else
    :class:`~bearingheat.errors.CoastdownError`.

    Returns (smoothed y, dy/dt) as arrays.

    >>> t = np.arange(7.0); y = 3.0 - 0.5 * t
    >>> savitzky_golay_irregular(t, y, 5)[1]
    array([-0.5, -0.5, -0.5, -0.5, -0.5, -0.5, -0.5])
    """
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    count = t.size
    if window % 2 != 1 or window < order + 2 or window > count:
        raise CoastdownError(
            f"Savitzky-Golay window = {window}: expected an odd number of samples between "
            f"{order + 2 if (order + 2) % 2 else order + 3} and {count}"
        )
    half = window // 2
    starts = np.clip(np.arange(count) - half, 0, count - window)
    idx = starts[:, None] + np.arange(window)[None, :]
    offsets = t[idx] - t[:, None]
    scale = np.max(np.abs(offsets), axis=1, keepdims=True)
    design = np.stack([(offsets / scale) ** k for k in range(order + 1)], axis=-1)
    normal = np.einsum("nwi,nwj->nij", design, design)
    rhs = np.einsum("nwi,nw->ni", design, y[idx])
    beta = np.linalg.solve(normal, rhs[..., None])[..., 0]
    return beta[:, 0], beta[:, 1] / scale[:, 0]


# --------------------------------------------------------------------------- run-down integration
def rundown_speed(t, t0, n0, torque: Callable[[np.ndarray], np.ndarray], I, grid_points=4001):
    """Speed n(t) [1/min] of a rotor running down from n0 [1/min] at t0 [s] under torque(ω) [N·m].

    Solves I·dω/dt = −M(ω) (the equation of motion of the TMM-7M lab sheet) through the
    time taken to slow down to ω,
    t(ω) = t0 + I·∫_ω^ω0 dw / M(w) (trapezoid rule on ``grid_points`` speeds),
    inverted by interpolation. The rotor stops at ω = 0 and stays there
    (static friction holds it); if M falls to zero at ω* > 0 the speed tends
    to ω*. I [kg·m²]. Returns NaN everywhere when M(ω0) ≤ 0 (no run-down).

    Constant torque gives the straight line of the TMM-7M lab sheet:

    >>> rundown_speed(np.array([0.0, 5.0, 50.0]), 0.0, 300.0, lambda w: 0.0 * w + 2.6 * np.pi / 30, 2.6)
    array([300., 295., 250.])
    """
    t = np.asarray(t, dtype=float)
    if n0 <= 0.0:
        return np.zeros_like(t)
    omega0 = n0 * RPM_TO_RAD_S
    omega = np.linspace(omega0, 0.0, grid_points)
    moment = np.asarray(torque(omega), dtype=float)
    if not np.isfinite(moment[0]) or moment[0] <= 0.0:
        return np.full_like(t, np.nan)
    bad = np.flatnonzero(~(moment > 0.0))
    end = bad[0] if bad.size else grid_points
    inverse = I / moment[:end]
    steps = 0.5 * (inverse[1:] + inverse[:-1]) * (omega[: end - 1] - omega[1:end])
    times = t0 + np.concatenate(([0.0], np.cumsum(steps)))
    speed = np.interp(t, times, omega[:end], left=omega0, right=omega[end - 1])
    return speed / RPM_TO_RAD_S


def plain_torque(M_c=0.0, c_v=0.0, c_a=0.0):
    """Resisting torque M(ω) = M_c + c_v·ω + c_a·ω² [N·m] as a function of ω [rad/s].

    M_c [N·m] Coulomb (constant) part, the TMM-7M lab sheet M_c = f·G·r; c_v [N·m·s]
    viscous and c_a [N·m·s²] aerodynamic parts, the nested models the
    coast-down fit chooses from. Any ω ≥ 0.

    >>> plain_torque(0.3, 0.004, 5e-5)(10.0)
    0.345
    """
    return lambda omega: M_c + c_v * omega + c_a * omega * omega
