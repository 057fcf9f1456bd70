"""The operating temperature of a table of supports: the lowest temperature where the bearing stops heating up.

At the operating speed n the bearing settles where N_R(ν(T)) + Q_E = Q_S(T) + Q_L(T) (Schaeffler HR 1, after
ISO 15312 and DIN 732; the heat flows are :mod:`bearingheat.calc.heat_flows`, N_R each row's friction model,
:class:`~bearingheat.calc.models.FrictionPower`). All rows are solved at once: scanned for the first step from
heating to cooling, then refined by :func:`~bearingheat.kernels.roots.bracketed_root`. The heat balance of
:mod:`bearingheat.calc.thermal` builds on it.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable

import numpy as np

from bearingheat.calc.models import FrictionPower
from bearingheat.calc.supports import number_column
from bearingheat.kernels import friction
from bearingheat.kernels.roots import bracketed_root
from bearingheat.kernels.viscosity import KELVIN_OFFSET

__all__ = ["OPERATING_TEMPERATURE_LIMIT", "BELOW_AMBIENT_SEARCH", "OPERATING_TEMPERATURE_CELLS", "ROOT_BLOCK",
           "OFF_CHART", "OperatingPoint", "operating_point", "lowest_operating_temperature", "no_equilibrium_text"]

#: upper end of the search for the operating temperature [°C]
OPERATING_TEMPERATURE_LIMIT = 150.0
#: the search for the operating temperature starts this far below the ambient temperature [K]
BELOW_AMBIENT_SEARCH = 50.0
#: the search range is scanned in this many steps (about 8 K each) for the lowest equilibrium
OPERATING_TEMPERATURE_CELLS = 24
#: rows refined together by the root search when the balance can be evaluated block by block (the arrays of a
#: block stay in a core's cache for all its steps; every row's steps are its own, so the roots are the same)
ROOT_BLOCK = 1 << 14


@dataclass
class OperatingPoint:
    """The operating temperature of every row (:func:`operating_point`) and how it was searched.

    ``T`` [°C] is NaN where ``status`` is not 0 (as :func:`lowest_operating_temperature`, and
    :data:`OFF_CHART` where ν·n·dM lies off the f2 chart at every temperature of the search); ``balance(T)``
    is N_R + Q_E − Q_S − Q_L [W]; ``T_low`` and ``T_high`` are the ends searched, narrowed on rows whose f2 is
    read off the chart to the temperatures the chart reaches (``chart_low``, ``chart_high``: where it did);
    ``falling`` marks the rows whose balance is known to fall with T (an equilibrium lies above the search if not
    in it), ``cooling_grows`` those of them whose ν follows T (one lies below it too, as N_R grows as the oil cools).
    """

    T: np.ndarray
    status: np.ndarray
    balance: Callable
    T_low: np.ndarray
    T_high: np.ndarray
    T_amb: np.ndarray
    t_limit: float
    power: FrictionPower
    chart_low: np.ndarray
    chart_high: np.ndarray
    falling: np.ndarray
    cooling_grows: np.ndarray

    def why(self, i: int) -> str:
        """Why row ``i`` has no T_op."""
        status, T_amb, t_limit, power = self.status[i], self.T_amb[i], self.t_limit, self.power
        if status == 1 and T_amb >= t_limit:  # the search lies below the ambient: nothing is known about running away
            return (f"the ambient temperature T_amb = {T_amb:g} degC is not below {t_limit:g} degC, the upper end of "
                    "the search for the operating temperature; T_op is not computed")
        if status == OFF_CHART or (status == 1 and self.chart_high[i]) or (status == -1 and self.chart_low[i]):
            x_lo, x_hi = power.chart_x[0][i], power.chart_x[1][i]
            chart = f"the f2 chart at Fa/A = {power.Fa_over_A[i]:.4g}"
            tail = "the Schaeffler catalogue forbids extrapolating the chart, so T_op is not computed"
            if status == 1:
                return (f"no equilibrium up to {self.T_high[i]:.4g} degC, where nu*n*dM falls to {x_lo:.4g} "
                        f"mm^3/(s*min), the lower end of {chart}: the friction heat still exceeds the heat carried "
                        f"away there; {tail}")
            if status == -1:
                return (f"no equilibrium down to {self.T_low[i]:.4g} degC, where nu*n*dM rises to {x_hi:.4g} "
                        f"mm^3/(s*min), the upper end of {chart}: the heat carried away already exceeds the friction "
                        f"heat there; {tail}")
            return (f"nu*n*dM lies {'above' if self.chart_low[i] else 'below'} {chart} ({x_lo:.4g} to {x_hi:.4g} "
                    f"mm^3/(s*min)) at every temperature from {T_amb - BELOW_AMBIENT_SEARCH:g} to {t_limit:g} "
                    f"degC; {tail}")
        return no_equilibrium_text(status, T_amb, t_limit, bool(self.falling[i]), bool(self.cooling_grows[i]))


#: the status of a row whose ν·n·dM lies off its f2 chart at every temperature searched
OFF_CHART = 3


def operating_point(frame, results, nu_at, nu_varies, Q_S, Q_L, Q_E, T_amb, t_limit, power=None) -> OperatingPoint:
    """The operating temperature at the operating speed: N_R(ν(T)) + Q_E = Q_S(T) + Q_L(T), N_R by each row's
    model (``power``: the :class:`~bearingheat.calc.models.FrictionPower` of ``results`` where the caller has
    it; rows whose f2 is read off a chart take M2 at ν(T)·n·dM); ``nu_varies`` marks the rows whose ν follows
    T (Walther), ``nu_at`` gives ν(T) of every row."""
    n = number_column(frame, "n")
    power = power if power is not None else FrictionPower(frame, results)
    T_low = T_amb - BELOW_AMBIENT_SEARCH
    T_high = np.full(len(frame), float(t_limit))
    if nu_varies.any():
        def balance(theta, rows=slice(None)):
            """N_R + Q_E − Q_S − Q_L [W] at θ of every row, or of the block ``rows`` (a slice)."""
            with np.errstate(invalid="ignore", over="ignore"):
                return power(n[rows], nu_at(theta, rows), rows) + Q_E[rows] - Q_S(theta, rows) - Q_L(theta, rows)
    else:  # ν, and so N_R, the same at every T: N_R + Q_E once (the same sum, the same bits)
        with np.errstate(invalid="ignore", over="ignore"):
            generated = power(n, nu_at(T_low)) + Q_E

        def balance(theta, rows=slice(None)):
            with np.errstate(invalid="ignore", over="ignore"):
                return generated[rows] - Q_S(theta, rows) - Q_L(theta, rows)
    T_low, T_high, chart_low, chart_high, off_chart = _chart_window(power, nu_at, n, nu_varies, T_low, T_high)
    # With the catalogue speed law N_R grows with ν, ν(T) is monotone (Walther or constant), Q_S = k_q·A_r·(T − T_amb)
    # and Q_L grow with T: where ν does not rise with T and k_q·A_r > 0 the balance falls strictly and has one root
    # (rows with a missing input compare as NaN: their balance is NaN at the ends, status 2 whatever the scan)
    with np.errstate(invalid="ignore", over="ignore"):
        rising_nu = (nu_at(T_high) > nu_at(T_low)) if nu_varies.any() else np.False_  # (~False is -1, not True)
        falling = power.closed & ~(Q_S(T_amb + 1.0) <= Q_S(T_amb)) & ~rising_nu
    walther_falling = falling & nu_varies
    if np.any(walther_falling):
        T_low, T_high = _side_of_the_regime_step(balance, nu_at, n, walther_falling, T_low, T_high)
    # where ν does not depend on T (no oil data) N_R does not either: the balance is a straight line in T
    affine = power.closed & ~nu_varies
    T_op, status = lowest_operating_temperature(balance, T_low, T_high, single_root=falling, affine=affine,
                                                blocks=True)
    status = np.where(off_chart, OFF_CHART, status)
    return OperatingPoint(T_op, status, balance, T_low, T_high, T_amb, float(t_limit), power, chart_low, chart_high,
                          np.broadcast_to(falling, T_op.shape), np.broadcast_to(walther_falling, T_op.shape))


def _chart_window(power, nu_at, n, nu_varies, T_low, T_high):
    """[T_low, T_high] narrowed, on the rows whose f2 is read off the chart and whose ν follows T, to the
    temperatures at which ν(T)·n·dM lies on the chart (ν falls as T rises: the chart's largest ν·n·dM is met at
    the cold end); a hair inside, so that rounding does not carry an end off the chart. Returns the ends, where
    the chart narrowed the low and the high end, and the rows the chart reaches at no temperature searched (their
    range is left empty at T_low)."""
    chart = power.chart_rows & nu_varies
    no_rows = np.zeros(len(T_low), dtype=bool)
    if not chart.any():
        return T_low, T_high, no_rows, no_rows, no_rows
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        per_nu = n * power.dM
        T_cold = nu_at.temperature_at(power.chart_x[1] / per_nu)
        T_hot = nu_at.temperature_at(power.chart_x[0] / per_nu)
        T_cold = T_cold + 1e-9 * (T_cold + KELVIN_OFFSET)
        T_hot = T_hot - 1e-9 * (T_hot + KELVIN_OFFSET)
        chart_low = chart & (T_cold > T_low)
        chart_high = chart & (T_hot < T_high)
        off = chart & ((T_cold >= T_high) | (T_hot <= T_low))
    low, high = np.where(chart_low, T_cold, T_low), np.where(chart_high, T_hot, T_high)
    return np.where(off, T_low, low), np.where(off, T_low, high), chart_low, chart_high, off


def _side_of_the_regime_step(balance, nu_at, n, rows, T_low, T_high):
    """The range [T_low, T_high] of each of ``rows`` (a falling balance with ν(T) from Walther's law) narrowed to
    the side of M0's regime step that holds the lowest root.

    M0 = f0·(ν·n)^(2/3)·dM³·10⁻⁷ for ν·n >= 2000 and f0·160·dM³·10⁻⁷ below (the Schaeffler catalogue, p. 64):
    where ν·n falls through 2000 as T rises, M0 steps up by 0.79 % (2000^(2/3) = 158.74 to 160). The balance
    falls on both sides of that temperature but jumps up there, so it can cross zero just below it and again
    above it, and a root search over the whole range may find the upper crossing. Just below the step (in
    the high regime) the balance tells the side: not heating any more there, the lowest root is below;
    still heating, there is none below and one above.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        T_step = nu_at.temperature_at(friction.REGIME_LIMIT / n)
        inside = rows & (T_step > T_low) & (T_step < T_high)
        if not inside.any():
            return T_low, T_high
        # a hair below the step (10⁻⁹ of T in K): ν·n above 2000 by far more than ν(T)'s rounding
        below_step = np.where(inside, T_step - 1e-9 * (T_step + KELVIN_OFFSET), T_low)
        f_below = balance(below_step)
    return (np.where(inside & (f_below > 0), below_step, T_low),
            np.where(inside & (f_below <= 0), below_step, T_high))


def lowest_operating_temperature(balance, T_low, T_high, *, cells: int = OPERATING_TEMPERATURE_CELLS,
                                 single_root=False, affine=False, blocks: bool = False):
    """The lowest temperature in [T_low, T_high] where the bearing stops heating up, for all rows at once.

    ``balance(T)`` is N_R + Q_E − Q_S − Q_L [W] per row (positive while the
    bearing heats up). The range is scanned at ``cells + 1`` evenly spaced
    temperatures (one array call each, every row together) for the first
    step from heating (> 0) to not heating (<= 0); that step is refined by
    :func:`~bearingheat.kernels.roots.bracketed_root`. Returns (T, status),
    status 0 for an equilibrium, 1 where the bearing still heats up at T_high (no equilibrium up to it), -1
    where it no longer heats up at T_low, 2 where the balance is NaN at an
    end. Two roots closer together than one cell may both be missed; one
    root is never missed. Rows marked ``single_root`` (a balance known to
    fall strictly) are refined between the ends of the range whatever the
    other rows are, so a row's T does not depend on the rows computed with
    it; where every row is, the scan is skipped. Rows marked ``affine`` (a
    balance that is a straight line in T, and falls) take the secant of the
    range's ends, which is their root; where every row is, nothing is
    refined. With ``blocks`` the balance is ``balance(T, rows)`` for a slice
    of the rows too, and rows are refined :data:`ROOT_BLOCK` at a time.

    >>> T, status = lowest_operating_temperature(
    ...     lambda T: -(T - 40.0) * (T - 90.0) * (T - 120.0), np.array([0.0, 0.0]), np.array([150.0, 30.0]))
    >>> np.round(T, 9).tolist(), status.tolist()
    ([40.0, nan], [0, 1])
    """
    T_low = np.asarray(T_low, dtype=float)
    T_high = np.asarray(T_high, dtype=float)
    shape = np.broadcast_shapes(T_low.shape, T_high.shape)
    affine = np.broadcast_to(np.asarray(affine, dtype=bool), shape)
    single = np.broadcast_to(np.asarray(single_root, dtype=bool), shape) | affine
    if single.all():
        cells = 1
    grid = T_low + np.linspace(0.0, 1.0, cells + 1)[:, None] * (T_high - T_low)
    with np.errstate(invalid="ignore", over="ignore"):
        values = np.array([np.asarray(balance(T), dtype=float) for T in grid])  # a loop over the grid, not rows
    heating = values > 0
    crossing = heating[:-1] & ~heating[1:] & ~np.isnan(values[1:])
    found = crossing.any(axis=0)
    f_low, f_high = values[0], values[-1]
    at_low = ~found & (f_low == 0) & ~(f_high > 0)  # in balance already at T_low
    status = np.where(found | at_low, 0, np.where(f_high > 0, 1, np.where(f_low < 0, -1, 2)))  # 2: NaN inside
    status = np.where(np.isnan(f_low) | np.isnan(f_high), 2, status)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        if affine.all():  # every row takes the secant below: nothing to refine
            T = np.full(shape, np.nan)
        else:
            first, rows = np.argmax(crossing, axis=0), np.arange(grid.shape[1])  # each row's first crossing cell
            low = np.where(found, np.where(single, T_low, grid[first, rows]), T_low)
            high = np.where(found, np.where(single, T_high, grid[first + 1, rows]), T_low)
            f_at_low = np.where(found, np.where(single, f_low, values[first, rows]), f_low)
            f_at_high = np.where(found, np.where(single, f_high, values[first + 1, rows]), f_low)
            if blocks and len(shape) == 1:
                T = np.full(shape, np.nan)
                refined = found & ~affine
                for part in (slice(start, start + ROOT_BLOCK) for start in range(0, shape[0], ROOT_BLOCK)):
                    if refined[part].any():
                        T[part], _ = bracketed_root(functools.partial(balance, rows=part), low[part], high[part],
                                                    rtol=1e-14, f_low=f_at_low[part], f_high=f_at_high[part])
            else:
                T, _ = bracketed_root(balance, low, high, rtol=1e-14, f_low=f_at_low, f_high=f_at_high)
        secant = np.where(f_high == 0, T_high, T_low + f_low * ((T_high - T_low) / (f_low - f_high)))
    T = np.where(at_low, T_low, np.where(affine & found, secant, T))
    return np.where(status == 0, T, np.nan), status


def no_equilibrium_text(status, T_amb, t_limit, above=False, below=False):
    """Why a row has no T_op, by its status (:func:`lowest_operating_temperature`). ``above``: an equilibrium is
    known to lie above the search (the catalogue model: its friction heat stays bounded as T rises, while Q_S grows
    in proportion to T − T_amb); ``below``: one is known to lie below it (the catalogue model with ν(T) from
    Walther's law: ν, and so N_R, grows without bound as the oil cools, while Q_S falls)."""
    if status == 1 and T_amb >= t_limit:  # the search lies below the ambient: nothing is known about running away
        return (f"the ambient temperature T_amb = {T_amb:g} degC is not below {t_limit:g} degC, the upper end of the "
                "search for the operating temperature; T_op is not computed")
    if status == 1:  # (nothing is said beyond the search where the model's friction heat may grow with T)
        beyond = ("; with the catalogue model the friction heat stays bounded as the temperature rises while the heat "
                  "carried away grows with it, so an equilibrium lies above" if above else "")
        return (f"no equilibrium up to {t_limit:g} degC, the upper end of the search: the friction heat still "
                f"exceeds the heat carried away there{beyond}; T_op is not computed")
    if status == -1:
        beyond = ("; as the oil cools its viscosity, and with it the friction heat of the catalogue model, grows "
                  "without bound while the heat carried away falls, so an equilibrium lies below" if below else "")
        return (f"no equilibrium down to {T_amb - BELOW_AMBIENT_SEARCH:g} degC, the lower end of the search: the heat "
                f"carried away already exceeds the friction heat there{beyond}; T_op is not computed")
    return "the heat balance is undefined (missing inputs)"
