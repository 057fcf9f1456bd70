"""The thermally permissible speed n_per = n_θr·f_n of a table of supports at the bearing temperature T_bearing.

f_n is the exact root of k_L·f_n^(5/3) + k_P·f_n = 1, or the catalogue's approximation of it (Schaeffler HR 1,
after DIN 732; the formulas are :mod:`bearingheat.kernels.thermal`); rows of a friction model without the
catalogue's speed law take the bracketed root of :func:`~bearingheat.calc.heat_flows.generic_speed`. The heat
balance of :mod:`bearingheat.calc.thermal` builds on it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from bearingheat.calc.contract import register_choices
from bearingheat.calc.heat_flows import generic_speed, walther_columns
from bearingheat.calc.supports import number_column
from bearingheat.kernels import friction
from bearingheat.kernels.thermal import (APPROXIMATION_RANGE, permissible_speed_factor,
                                         speed_factor_catalogue_approximation, speed_factor_coefficients)
from bearingheat.kernels.viscosity import walther_viscosity

__all__ = ["SpeedFactorMethod", "SPEED_FACTOR_METHODS", "DEFAULT_SPEED_FACTOR_METHOD", "permissible_speed_rows"]


def _exact_speed_factor(sel, n_thr, f0, nu, dM, load_torque, Q, problems):
    return permissible_speed_factor(n_thr, f0, nu, dM, load_torque, Q)


def _approximate_speed_factor(sel, n_thr, f0, nu, dM, load_torque, Q, problems):
    k_L, k_P = speed_factor_coefficients(n_thr, f0, nu, dM, load_torque, Q)
    f_n = np.full(len(sel), np.nan)
    inside = ((k_L >= APPROXIMATION_RANGE[0]) & (k_L <= APPROXIMATION_RANGE[1])
              & (k_P >= APPROXIMATION_RANGE[0]) & (k_P <= APPROXIMATION_RANGE[1]))
    if inside.any():
        f_n[inside] = speed_factor_catalogue_approximation(k_L[inside], k_P[inside])
    for j in np.flatnonzero(~inside):
        problems.append((int(sel[j]), "warning", f"n_per: k_L = {k_L[j]:.4g}, k_P = {k_P[j]:.4g} outside "
                                                 "0.01..10, the range of the catalogue approximation"))
    return f_n


@dataclass(frozen=True)
class SpeedFactorMethod:
    """How n_per = n_θr·f_n finds f_n for the selected rows.

    ``solve(positions, n_thr, f0, nu, dM, load_torque, Q, problems)`` returns
    f_n for the rows at ``positions`` and appends (row position, level,
    message) problems.
    """

    name: str
    title: str
    solve: Callable


#: how the permissible speed factor is found: exact root, or the catalogue approximation
SPEED_FACTOR_METHODS: dict[str, SpeedFactorMethod] = {m.name: m for m in (
    SpeedFactorMethod("exact", "exact root", _exact_speed_factor),
    SpeedFactorMethod("approximation", "catalogue approximation", _approximate_speed_factor),
)}
#: the method of rows whose n_per_method cell is blank
DEFAULT_SPEED_FACTOR_METHOD = "exact"
register_choices("n_per_method", lambda: tuple(SPEED_FACTOR_METHODS))


def permissible_speed_rows(frame, results, details, n_thr, n_thr_catalogue, T_bearing, T_amb, carried, Q_E, power,
                           usable, methods, problems):
    """n_per of the rows ``usable`` with a T_bearing above T_amb (and an n_thr, but rows of a model evaluated at
    each speed, whose own root needs none); ``carried`` is the heat carried away at
    T_bearing, Q_S + Q_L [W], ``power`` the rows' :class:`~bearingheat.calc.models.FrictionPower`."""
    n_rows = len(frame)
    Q = carried - Q_E  # the heat the bearing may make itself
    rows = usable & ~np.isnan(T_bearing)
    for i in np.flatnonzero(usable & np.isnan(T_bearing)):
        problems.append((int(i), "warning", "T_bearing [degC]: missing; n_per is the speed at which the bearing "
                                            "reaches T_bearing"))
    for i in np.flatnonzero(rows & (T_bearing <= T_amb)):
        problems.append((int(i), "error", f"T_bearing [degC]: {T_bearing[i]:g} must be above T_amb = {T_amb[i]:g} "
                                          "degC for heat to leave through the seat"))
    rows &= T_bearing > T_amb
    n_used = np.where(np.isnan(n_thr_catalogue), n_thr, n_thr_catalogue)
    rows &= (n_used > 0) | ~power.closed  # (a model evaluated at each speed finds n_per without n_thr)
    for i in np.flatnonzero(rows & ~(Q > 0)):
        problems.append((int(i), "warning", f"n_per: the external heat Q_E = {Q_E[i]:g} W is not less than the heat "
                                            f"carried away {carried[i]:.4g} W at T_bearing; no speed is "
                                            "permissible"))
    rows &= Q > 0
    out = np.full(n_rows, np.nan)
    if not rows.any():
        return out
    dM = friction.mean_diameter(number_column(frame, "d"), number_column(frame, "D"))
    # n_per is the speed at which the bearing reaches T_bearing: its oil has the viscosity of T_bearing there,
    # whatever temperature the friction results are reported at (a viscosity the user gives is used as it is)
    A, B = walther_columns(frame)[:2]
    at_bearing = ~np.isnan(A) & ~np.isnan(T_bearing)
    nu = number_column(frame, "nu")
    if at_bearing.any():  # (no oil data: no Walther line to evaluate)
        with np.errstate(invalid="ignore", over="ignore"):
            nu = np.where(at_bearing, walther_viscosity(A, B, T_bearing), nu)
    f0 = results["f0"].to_numpy(dtype=float)
    load_torque = results["M1"].to_numpy(dtype=float) + np.nan_to_num(results["M2"].to_numpy(dtype=float))
    for name, method in SPEED_FACTOR_METHODS.items():
        sel = np.flatnonzero(rows & power.closed & (methods == name))
        if len(sel) == n_rows:  # every row: the columns themselves, no copies of their rows
            out = method.solve(sel, n_used, f0, nu, dM, load_torque, Q, problems) * n_used
        elif len(sel):
            f_n = method.solve(sel, n_used[sel], f0[sel], nu[sel], dM[sel], load_torque[sel], Q[sel], problems)
            out[sel] = f_n * n_used[sel]
    generic = rows & ~power.closed
    if generic.any():
        speed, status = generic_speed(power, nu, Q)
        out[generic] = speed[generic]
        _chart_refusals(power, nu, generic & (status != 0), status, problems)
        for i in np.flatnonzero(generic & (methods != "exact")):
            why = ("a load torque that does not change with the speed; M2 read off the f2 chart at nu*n*dM does"
                   if power.chart_rows[i] else "the catalogue model only")
            problems.append((int(i), "warning", f"n_per: the {SPEED_FACTOR_METHODS[methods[i]].title} holds for "
                                                f"{why}; the exact root is used"))
    n_G = number_column(frame, "n_G")
    capped = rows & (out > n_G)
    for i in np.flatnonzero(capped):
        problems.append((int(i), "warning", f"n_per: the thermal value {out[i]:.5g} 1/min is above the limiting "
                                            f"speed n_G = {n_G[i]:g} 1/min; n_per = n_G"))
    return np.where(capped, n_G, out)


def _chart_refusals(power, nu, unsolved, status, problems) -> None:
    """Why the rows ``unsolved`` whose f2 is read off the chart have no n_per: the speed at which the friction
    heat meets the heat carried away lies where ν(T_bearing)·n·dM is off the chart (the Schaeffler catalogue,
    p. 70: the charts are not to be extrapolated)."""
    low, high = power.speed_range(nu)
    for i in np.flatnonzero(unsolved & power.chart_rows).tolist():
        chart = f"of the f2 chart at Fa/A = {power.Fa_over_A[i]:.4g}; the Schaeffler catalogue forbids extrapolating it"
        if status[i] == 1:
            problems.append((i, "warning", f"n_per: the friction heat exceeds the heat carried away at T_bearing "
                                           f"already at {low[i]:.5g} 1/min, where nu*n*dM = {power.chart_x[0][i]:.4g} "
                                           f"mm^3/(s*min) is the lower end {chart}; n_per lies below"))
        elif status[i] == -1:
            problems.append((i, "warning", f"n_per: the friction heat stays below the heat carried away at T_bearing "
                                           f"up to {high[i]:.5g} 1/min, where nu*n*dM = {power.chart_x[1][i]:.4g} "
                                           f"mm^3/(s*min) is the upper end {chart}; n_per lies above"))
        else:
            problems.append((i, "warning", f"n_per: the friction heat is not a number at nu = {nu[i]:.4g} mm^2/s "
                                           f"between {low[i]:.5g} and {high[i]:.5g} 1/min, the speeds {chart}"))
