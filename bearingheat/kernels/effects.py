"""Kernels of the effects the catalogue friction model lacks (the candidates of ``bearingheat diagnose``).

Plain floats and numpy arrays in catalogue units: M [N·mm], dM [mm],
n [1/min], ν [mm²/s], t [h], R_th [K/W], b [1/K]. Each kernel is one term
added to (or one factor on) the Schaeffler catalogue model M_R = M0 + M1 (+ M2); the
candidates that fit their parameters to measured torque are in
:mod:`bearingheat.analysis.effects`.

References
----------
The Schaeffler catalogue: Schaeffler, "Трение и нагрев" (friction and heating), catalogue
pp. 63-70, after ISO 15312: M0 and its low-speed constant 160 (p. 64); seal
friction is among the components of p. 63 but has no term in the formulas (so it
comes on top of M_R: bearingheat's reading); freshly greased bearings show an f0
2 to 5 times the table and an oil level above the lowest rolling element raises
f0 up to threefold (p. 65, fig. 2). ISO 3448: viscosity grades of mineral oils (the
temperature coefficient b).
"""
from __future__ import annotations

import numpy as np
from scipy import special

from bearingheat.kernels import friction

__all__ = [
    "VISCOSITY_TEMPERATURE_COEFFICIENT",
    "seal_drag_torque",
    "drag_loss_torque",
    "run_in_factor",
    "heated_total_torque",
]

#: b in ν(T_oil + ΔT) = ν(T_oil)·exp(−b·ΔT) [1/K]: mineral oils lose about half their viscosity per
#: 23 K near 40-80 °C (ISO 3448 VG grades, viscosity index about 95-100). Only b·R_th is identified by
#: torque data, so R_th is reported for this b.
VISCOSITY_TEMPERATURE_COEFFICIENT = 0.03


def seal_drag_torque(M_seal, bearing_code):
    """Seal torque of each row [N·mm]: the fitted M_seal of its bearing (constant in n).

    .. math::
        M_{seal,i} = M_{seal}[b_i]

    M_seal [N·mm] >= 0, one per bearing; bearing_code [-] integer index of
    each row's bearing into M_seal. Valid for contact seals whose torque
    does not change with speed (the seal torque is added to M_R; the Schaeffler catalogue,
    p. 63, lists seal friction among the components, and its formulas have no term for it).

    >>> seal_drag_torque(np.array([5.0, 8.0]), np.array([0, 1, 1]))
    array([5., 8., 8.])
    """
    return np.asarray(M_seal, dtype=float)[np.asarray(bearing_code, dtype=int)]


def drag_loss_torque(c, p, dM, n):
    """Churning torque c·1e-7·dM³·(n·dM/1000)^p [N·mm]; dM [mm], n [1/min].

    .. math::
        M_{drag} = c \\cdot 10^{-7} d_M^3 (n d_M / 1000)^p

    c [-] >= 0, p [-] in [0.9, 3] (the range ``diagnose`` fits), dM [mm] > 0,
    n [1/min] >= 0. p > 2/3 makes it grow faster with speed than M0 of the Schaeffler
    catalogue; p = 2 gives the dM^5·n^2 law of splash losses.

    Source: no catalogue formula; a power law in the peripheral speed n·dM
    that extends the Schaeffler catalogue M0 (p. 64, M0 ∝ (ν·n)^(2/3)·dM³), its
    exponent fitted to the data.

    >>> round(float(drag_loss_torque(1.0, 2.0, 40.0, 3000.0)), 4)
    92.16
    """
    dM = np.asarray(dM, dtype=float)
    return c * 1e-7 * dM ** 3 * np.power(np.asarray(n, dtype=float) * dM / 1000.0, p)


def run_in_factor(a, tau, t):
    """Factor on M0 of a bearing that is not yet run in: 1 + a·exp(−t/τ) [-]; t, τ [h].

    .. math::
        k(t) = 1 + a \\, e^{-t/\\tau}

    a [-] >= 0, τ [h] > 0, t [h] >= 0 (running time since greasing or
    assembly). The Schaeffler catalogue p. 65: freshly greased bearings show an f0 2 to 5
    times the table, so a of 1 to 4 at t = 0, decaying to the table f0.

    >>> round(float(run_in_factor(2.0, 10.0, 10.0)), 6)
    1.735759
    """
    return 1.0 + a * np.exp(-np.asarray(t, dtype=float) / tau)


def heated_total_torque(R_th, f0, nu, n, dM, M_load, b=VISCOSITY_TEMPERATURE_COEFFICIENT):
    """Total torque [N·mm] of a bearing running R_th·N_R above the given oil temperature.

    Solves M = M_load + M0(ν') with ν' = ν·exp(−b·R_th·N_R), N_R = M·n/9550,
    exactly: in the regime ν'·n >= 2000 it is M = B + W(κA·e^(−κB))/κ with
    A = f0·(ν n)^(2/3)·dM³·1e-7, κ = (2/3)·b·R_th·n/9550, B = M_load (W the
    Lambert function); where the heated ν'·n falls below 2000 the constant
    160 of the Schaeffler catalogue p. 64 applies and M0 no longer depends on ν.

    .. math::
        M = M_{load} + f_0 (\\nu' n)^{2/3} d_M^3 10^{-7}, \\quad
        \\nu' = \\nu \\, e^{-b R_{th} M n / 9550}

    R_th [K/W] >= 0 (0 gives the catalogue model), f0 [-], ν [mm²/s] at the
    oil temperature given, n [1/min] >= 0, dM [mm], M_load = M1 + M2 [N·mm],
    b [1/K] (0.03 for mineral oils near 40-80 °C, ISO 3448 VG grades).
    Source: M0 and its low-speed constant of the Schaeffler catalogue, p. 64; the
    exponential viscosity law with :data:`VISCOSITY_TEMPERATURE_COEFFICIENT`.

    >>> round(float(heated_total_torque(0.0, 2.0, 12.0, 3000.0, 38.5, 10.0)), 4)
    22.4436
    >>> round(float(heated_total_torque(1.0, 2.0, 12.0, 3000.0, 38.5, 10.0)), 4)
    20.9116
    """
    f0, nu, n, dM, M_load = (np.asarray(v, dtype=float) for v in (f0, nu, n, dM, M_load))
    M0_cold = friction.speed_dependent_torque(f0, nu, n, dM)
    if np.all(np.asarray(R_th) == 0.0):
        return M0_cold + M_load
    A = f0 * np.power(np.maximum(nu * n, 0.0), 2.0 / 3.0) * dM ** 3 * 1e-7
    kappa = (2.0 / 3.0) * b * R_th * n / 9550.0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        z = kappa * A * np.exp(-kappa * M_load)
        hot = M_load + np.real(special.lambertw(z)) / kappa
    hot = np.where(kappa > 0.0, hot, M_load + A)
    M0_low = f0 * friction.LOW_REGIME_FACTOR * dM ** 3 * 1e-7
    nu_hot = nu * np.exp(-b * R_th * hot * n / 9550.0)
    low_regime = (nu * n < friction.REGIME_LIMIT) | (nu_hot * n < friction.REGIME_LIMIT)
    return np.where(low_regime, M_load + M0_low, hot)
