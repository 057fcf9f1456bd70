"""The curves of one row's heat balance, the figure of ``bearingheat plot`` (catalogue units).

The friction heat and the heat carried away against speed (they cross at
n_per) and against temperature (they cross at T_op), from the heat balance
of :mod:`bearingheat.calc.thermal` and the heat flows of :mod:`bearingheat.calc.heat_flows`.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from bearingheat.calc.models import FrictionPower
from bearingheat.calc.heat_flows import generic_speed, heat_flow_setup, viscosity_of_rows, walther_columns
from bearingheat.calc.thermal import OPERATING_TEMPERATURE_LIMIT, with_seal_friction
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.kernels.thermal import balance_speed

__all__ = ["heat_flow_curves"]


def heat_flow_curves(frame: pd.DataFrame, results: pd.DataFrame, columns: pd.DataFrame, *,
                     points: int = 200, f2_chart: F2Chart | None = None) -> dict | None:
    """Friction heat and heat carried away of the first row against speed and temperature (catalogue units).

    ``frame`` holds the calc inputs after :func:`~bearingheat.calc.thermal.settle_viscosity` (with
    ``T_amb``), ``results`` the friction results of
    :func:`bearingheat.calc.models.compute_supports` and ``columns`` those of
    :func:`~bearingheat.calc.thermal.heat_balance_rows`; ``f2_chart`` the chart
    their f2 was read off (M2 then follows ν·n·dM along the curves, NaN where
    that lies off the chart). Returns None where the row has no heat flow
    area A_r or no ambient temperature, otherwise a dict: ``n``, ``n_per``,
    ``T_op``, ``T_amb``; ``theta`` (T_bearing, else T_op) and ``n_cross``,
    the speed at which the friction heat equals Q_S + Q_L − Q_E at theta;
    ``chart_speeds`` (lowest, highest) [1/min], the speeds at theta between
    which ν·n·dM lies on the f2 chart (0 and inf without one);
    ``speeds`` [1/min] with ``friction_vs_speed`` and ``carried_vs_speed``
    [W] at theta; ``temperatures`` [°C] with ``friction_vs_temperature``
    (N_R(ν(T)) + Q_E) and ``carried_vs_temperature`` (Q_S + Q_L) [W] at the
    speed n; ``heat_at_T_op`` [W].
    """
    frame = with_seal_friction(frame, results)  # (a sealed bearing whose model has its seal friction: A_r)
    details, k_q, T_amb, Q_E, Q_S, Q_L = heat_flow_setup(frame)
    if np.isnan(details["A_r"].iloc[0]) or np.isnan(T_amb[0]):
        return None
    A, B, _ = walther_columns(frame)
    nu_at = viscosity_of_rows(frame, A, B)
    power = FrictionPower(frame, results, f2_chart)
    n = float(frame["n"].iloc[0])
    T_op = float(columns["T_op"].iloc[0])
    n_per = float(columns["n_per"].iloc[0]) if "n_per" in columns.columns else math.nan
    T_bearing = float(frame["T_bearing"].iloc[0]) if "T_bearing" in frame.columns else math.nan
    theta = T_bearing if not np.isnan(T_bearing) else T_op
    nu_theta = float(nu_at(np.array([theta]))[0]) if not np.isnan(theta) else math.nan
    carried_theta = float(Q_S(np.array([theta]))[0] + Q_L(np.array([theta]))[0] - Q_E[0])
    n_cross = math.nan
    if carried_theta > 0 and power.is_closed(0):
        n_cross = float(balance_speed(power.f0[0], nu_theta, power.dM[0], power.load_torque[0], carried_theta))
    elif carried_theta > 0:
        speed, _ = generic_speed(power, np.full(power.size, nu_theta), np.full(power.size, carried_theta))
        n_cross = float(speed[0])
    # f2 read off a chart: N_R is known only between the speeds at which nu*n*dM lies on it (0 and inf otherwise)
    chart_low, chart_high = (float(end[0]) for end in power.speed_range(np.full(power.size, nu_theta)))
    # where the chart's end is why no crossing was found, the axis reaches it, so that the reader sees the end
    chart_end = chart_high if np.isnan(n_cross) and np.isfinite(chart_high) else math.nan
    n_top = 1.5 * np.nanmax([n, n_cross, n_per, chart_end, 1.0])
    speeds = np.linspace(0.0, n_top, points)
    temperatures = np.linspace(T_amb[0], OPERATING_TEMPERATURE_LIMIT, points)
    ones = np.ones(points)
    return dict(
        n=n, n_per=n_per, n_cross=n_cross, theta=theta, T_op=T_op, T_amb=float(T_amb[0]),
        chart_speeds=(chart_low, chart_high),
        speeds=speeds,
        friction_vs_speed=power.at_row(0, speeds, nu_theta),
        carried_vs_speed=carried_theta * ones,
        temperatures=temperatures,
        friction_vs_temperature=power.at_row(0, n * ones, nu_at(temperatures)) + Q_E[0],
        carried_vs_temperature=Q_S(temperatures) + Q_L(temperatures),
        heat_at_T_op=float(Q_S(np.array([T_op]))[0] + Q_L(np.array([T_op]))[0]) if not np.isnan(T_op) else np.nan,
    )
