"""The heat flows of a table of supports as functions of the bearing temperature, and ν(T) of its rows.

What the heat balance (:mod:`bearingheat.calc.thermal`) and the curves of
``bearingheat plot`` (:mod:`bearingheat.calc.heat_flow_curves`) both solve
with: the heat carried away through the seat Q_S(θ) and by circulating oil
Q_L(θ) (Schaeffler HR 1, after ISO 15312 and DIN 732; the formulas are
:mod:`bearingheat.kernels.thermal`), the viscosity of each row at θ
(Walther's law where oil data are given), and the speed at which a model's
friction power meets a heat flow where the model has no closed speed law.
Catalogue units: mm, N, 1/min, mm²/s, °C, W.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.models import FrictionPower
from bearingheat.calc.reference_speed import thermal_reference_speed_details
from bearingheat.calc.supports import number_column, zero_where_blank
from bearingheat.calc.viscosity import OIL_LINE_INPUTS, viscosity_model_rows
from bearingheat.kernels.roots import bracketed_root
from bearingheat.kernels.thermal import oil_heat_flow, seat_heat_flow
from bearingheat.kernels.viscosity import walther_temperature, walther_viscosity

__all__ = ["OIL_DATA", "HEAT_BALANCE_DETAILS", "RowViscosity", "viscosity_of_rows", "walther_columns",
           "heat_flow_setup", "generic_speed"]

#: the columns a viscosity-temperature law comes from (:func:`~bearingheat.calc.viscosity.viscosity_model_rows`;
#: a VI only serves an ISO VG grade)
OIL_DATA = frozenset(OIL_LINE_INPUTS) - {"VI"}
#: the reference-speed details the heat balance reads: n_thr and why a row has none, the heat flow area A_r and
#: the default heat transfer coefficient k_q of the reference conditions
HEAT_BALANCE_DETAILS = ("n_thr", "reason", "A_r", "k_q_ref")


class RowViscosity:
    """ν(θ) of every row: Walther's law where its constants A, B are known, the constant ``nu`` column
    otherwise (:func:`viscosity_of_rows`)."""

    def __init__(self, A: np.ndarray, B: np.ndarray, nu_fixed: np.ndarray):
        self.A, self.B, self.nu_fixed = A, B, nu_fixed
        self.has_model = ~np.isnan(A)
        self.varies = bool(self.has_model.any())

    def __call__(self, theta, rows: slice = slice(None)) -> np.ndarray:
        """ν at θ of every row, or of the block ``rows`` (a slice)."""
        if not self.varies:  # no row has oil data: ν does not depend on the temperature
            return np.broadcast_arrays(np.asarray(theta, dtype=float), self.nu_fixed[rows])[1].copy()
        with np.errstate(invalid="ignore", over="ignore"):
            return np.where(self.has_model[rows], walther_viscosity(self.A[rows], self.B[rows], theta),
                            self.nu_fixed[rows])

    def temperature_at(self, nu) -> np.ndarray:
        """θ [°C] at which each row's ν(θ) is ``nu`` (one per row): the inverse of Walther's law; NaN for rows
        without one."""
        return np.where(self.has_model, walther_temperature(self.A, self.B, nu), np.nan)


def viscosity_of_rows(frame: pd.DataFrame, A, B) -> RowViscosity:
    """ν(θ) for every row: Walther where A, B are known, the constant ``nu`` column otherwise."""
    return RowViscosity(np.asarray(A, dtype=float), np.asarray(B, dtype=float), number_column(frame, "nu"))


def walther_columns(frame: pd.DataFrame):
    """The Walther constants A, B of every row (NaN without oil data) and the problems of the oil data."""
    if "_walther_A" in frame.columns:
        return number_column(frame, "_walther_A"), number_column(frame, "_walther_B"), []
    if not set(OIL_LINE_INPUTS) & set(frame.columns):  # (a VI alone is an error of viscosity_model_rows)
        none = np.broadcast_to(np.nan, len(frame))  # (a read-only view: no memory per row)
        return none, none, []
    return viscosity_model_rows(frame)


def heat_flow_setup(frame: pd.DataFrame, details: pd.DataFrame | None = None):
    """A_r, k_q, reference-speed details and the heat flows as functions of the bearing temperature
    (``details``: at least the :data:`HEAT_BALANCE_DETAILS` of
    :func:`~bearingheat.calc.reference_speed.thermal_reference_speed_details` where the caller has them)."""
    if details is None:
        details = thermal_reference_speed_details(frame, names=HEAT_BALANCE_DETAILS)
    A_r = details["A_r"].to_numpy(dtype=float)
    k_q_default = details["k_q_ref"].to_numpy(dtype=float)  # worked out once a bearing
    if "k_q" in frame.columns:
        k_q_user = number_column(frame, "k_q")
        k_q = np.where(np.isnan(k_q_user), k_q_default, k_q_user)
    else:
        k_q = k_q_default
    T_amb = number_column(frame, "T_amb")
    V_oil = zero_where_blank(frame, "V_oil")
    dT_oil = number_column(frame, "dT_oil")
    Q_E = zero_where_blank(frame, "Q_E")

    def Q_S(theta, rows=slice(None)):
        """Heat flow through the seat at θ of every row, or of the block ``rows`` (a slice)."""
        return seat_heat_flow(k_q[rows], A_r[rows], np.asarray(theta, dtype=float) - T_amb[rows])

    if (V_oil > 0).any():
        def Q_L(theta, rows=slice(None)):
            # oil temperature rise: given dT_oil, otherwise oil fed at ambient and leaving at the bearing temperature
            rise = np.where(np.isnan(dT_oil[rows]), np.asarray(theta, dtype=float) - T_amb[rows], dT_oil[rows])
            return np.where(V_oil[rows] > 0, oil_heat_flow(V_oil[rows], rise), 0.0)
    else:
        def Q_L(theta, rows=slice(None)):  # no row has an oil flow: no heat leaves with oil
            return np.zeros(np.broadcast_shapes(np.shape(theta), T_amb[rows].shape))

    return details, k_q, T_amb, Q_E, Q_S, Q_L


def generic_speed(power: FrictionPower, nu: np.ndarray, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The speed [1/min] at which each row's friction power equals Q [W], by bracketing, and a status per row.

    N_R grows with the speed from 0 at standstill, so the bracket [0, n_high]
    is widened fourfold until N_R(n_high) > Q (from 1000 1/min, at most 20
    times). A row whose N_R is known only between two speeds
    (:meth:`~bearingheat.calc.models.FrictionPower.speed_range`: f2 read off
    a chart) is bracketed by them. Status as
    :func:`~bearingheat.kernels.roots.bracketed_root`: 0 for a root, +1
    where N_R exceeds Q already at the lower end (the root lies below it),
    -1 where N_R stays below Q at the upper end, 2 where N_R is unknown at
    an end; the speed is NaN where the status is not 0.
    """
    low, limit = power.speed_range(nu)
    bounded = np.isfinite(limit)
    n_high = np.where(bounded, limit, np.fmax(1000.0, low))
    for _ in range(20):
        short = ~bounded & (power(n_high, nu) < Q)
        if not short.any():
            break
        n_high = np.where(short, n_high * 4.0, n_high)
    return bracketed_root(lambda n: power(n, nu) - Q, low, n_high)
