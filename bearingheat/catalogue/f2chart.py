"""User-digitised f2 charts for axially loaded cylindrical roller bearings.

The Schaeffler catalogue (p. 70, figures 3 and 4) gives f2 as curves against the
viscosity-speed figure ν·n·dM, one curve per value of Fa/A. The chart images
are missing from the Schaeffler catalogue text and no public digitisation is known, so bearingheat
never ships chart values: the user digitises the chart of their catalogue and
passes the points as a CSV.

CSV format (one row per digitised point, a units row under the header)::

    curve,Fa_over_A,nu_n_dM,f2,source
    -,1,mm^3/(s*min),1,-
    A,0.5,2000,0.012,my catalogue p. 70 fig. 3
    A,0.5,50000,0.004,my catalogue p. 70 fig. 3
    B,2.0,2000,0.020,my catalogue p. 70 fig. 3
    ...

- ``curve``: a label, one per curve; every point of a curve has the same ``Fa_over_A``.
- ``nu_n_dM`` in the unit of the units row (any pint unit of volume per
  time², e.g. ``mm^3/(s*min)``, the catalogue's mm²/s · 1/min · mm).
- at least two points per curve, ``nu_n_dM`` strictly increasing, all
  values > 0; ``source`` is optional.

Interpolation is linear in log-log: log f2 against log(ν·n·dM) along each
curve, then log f2 against log(Fa/A) between the two curves that bracket
the query. A query outside the Fa/A range of the curves, or outside the
ν·n·dM range of either bracketing curve, is refused: the catalogue says the
charts must not be extrapolated.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bearingheat.catalogue.digitised import read_chart_csv
from bearingheat.errors import F2ChartError, UnitError
from bearingheat.units import convert_column

__all__ = ["F2Chart", "F2ChartError"]

_X_UNIT = "mm^3/(s*min)"




@dataclass(frozen=True)
class _Curve:
    label: str
    Fa_over_A: float
    x_range: tuple[float, float]
    log_x: np.ndarray
    log_f2: np.ndarray


class F2Chart:
    """Curves f2(ν·n·dM) at fixed Fa/A, interpolated in log-log and never extrapolated.

    The f2 charts of axially loaded cylindrical roller bearings (Schaeffler
    rolling bearing catalogue, Russian edition, chapter «Трение и нагрев»,
    Friction and increases in temperature, p. 70, figures 3 and 4), as the
    user digitised them from their catalogue: bearingheat ships no chart
    values. Read one with :meth:`from_csv` (format in the module docstring)
    and pass it to :func:`~bearingheat.api.friction.friction_torque` or
    :func:`~bearingheat.calc.table.calc`; :meth:`lookup` reads f2.

    Parameters
    ----------
    points : dict of str to (float, list of float, list of float)
        Curve label -> (Fa/A [1], [ν·n·dM in mm³/(s·min)], [f2 [1]]): at
        least two points per curve, ν·n·dM strictly increasing, every value
        > 0, and no two curves at the same Fa/A.
    name : str, optional
        Name of the chart in messages (the CSV path for :meth:`from_csv`);
        default 'f2 chart'.

    Raises
    ------
    bearingheat.errors.F2ChartError
        For no curves, a curve with fewer than two points, a value that is
        not > 0, ν·n·dM not strictly increasing along a curve, or two curves
        sharing one Fa/A.

    Examples
    --------
    >>> chart = F2Chart({"A": (0.5, [2000.0, 50000.0], [0.012, 0.004]),
    ...                  "B": (2.0, [2000.0, 50000.0], [0.020, 0.006])})   # made-up points
    >>> f2, refused = chart.lookup([1.0, 3.0], 10000.0)
    >>> f2.round(5), chart.Fa_over_A_range
    (array([0.00871,     nan]), (0.5, 2.0))
    >>> refused[1]
    "Fa/A = 3 is outside the f2 chart's curves (0.5 to 2); the Schaeffler catalogue forbids extrapolating the chart"
    """

    def __init__(self, points: dict[str, tuple[float, list[float], list[float]]], name: str = "f2 chart"):
        """``points``: curve label -> (Fa/A, [ν·n·dM in mm³/(s·min)], [f2])."""
        self.name = name
        curves = []
        for label, (Fa_over_A, given_xs, given_f2s) in points.items():
            xs = np.asarray(given_xs, dtype=float)
            f2s = np.asarray(given_f2s, dtype=float)
            where = f"{name}, curve {label!r}"
            if len(xs) < 2:
                raise F2ChartError(f"{where}: needs at least two points, has {len(xs)}")
            if not (np.all(xs > 0) and np.all(f2s > 0) and Fa_over_A > 0):
                raise F2ChartError(f"{where}: Fa_over_A, nu_n_dM and f2 must all be > 0")
            if np.any(np.diff(xs) <= 0):
                raise F2ChartError(f"{where}: nu_n_dM must increase strictly from point to point")
            curves.append(_Curve(label, float(Fa_over_A), (float(xs[0]), float(xs[-1])), np.log(xs), np.log(f2s)))
        if not curves:
            raise F2ChartError(f"{name}: no curves")
        curves.sort(key=lambda c: c.Fa_over_A)
        levels = [c.Fa_over_A for c in curves]
        if len(set(levels)) != len(levels):
            raise F2ChartError(f"{name}: two curves share one Fa_over_A value")
        self._curves = curves
        self._levels = np.array(levels)

    @classmethod
    def from_csv(cls, path: str | Path) -> "F2Chart":
        """Read a digitised chart in the format of the module docstring."""
        path = Path(path)
        col, units, rows = read_chart_csv(path, ["curve", "Fa_over_A", "nu_n_dM", "f2"], "an f2 chart", F2ChartError)
        try:
            scale = convert_column(np.ones(1), units[col["nu_n_dM"]], _X_UNIT, name="nu_n_dM")[1]
        except UnitError as exc:  # an unknown unit, or one of another dimension
            raise F2ChartError(f"{path}: units row: nu_n_dM unit {units[col['nu_n_dM']]!r} "
                               f"is not convertible to {_X_UNIT}") from exc
        points: dict[str, tuple[float, list[float], list[float]]] = {}
        for line_no, row in rows:
            try:
                label = row[col["curve"]].strip()
                level, x, f2 = (float(row[col[c]]) for c in ("Fa_over_A", "nu_n_dM", "f2"))
            except (ValueError, IndexError) as exc:
                raise F2ChartError(f"{path}, line {line_no}: not a number in {row!r}") from exc
            known = points.setdefault(label, (level, [], []))
            if known[0] != level:
                raise F2ChartError(f"{path}, line {line_no}: curve {label!r} has Fa_over_A {level:g}, "
                                   f"earlier points have {known[0]:g}")
            known[1].append(x * scale)
            known[2].append(f2)
        return cls(points, name=str(path))

    @property
    def Fa_over_A_range(self) -> tuple[float, float]:
        return float(self._levels[0]), float(self._levels[-1])

    def _brackets(self, Fa_over_A: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Per query the indexes of the curves below and above its Fa/A (the same curve where it lies on one), and
        whether it lies within the curves' Fa/A at all (the indexes of one outside are not to be read)."""
        inside = (Fa_over_A >= self._levels[0]) & (Fa_over_A <= self._levels[-1])
        upper = np.searchsorted(self._levels, np.where(inside, Fa_over_A, self._levels[0]), side="left")
        lower = np.where(self._levels[upper] == Fa_over_A, upper, np.maximum(upper - 1, 0))
        return lower, upper, inside

    def x_range(self, Fa_over_A) -> tuple[np.ndarray, np.ndarray]:
        """The ν·n·dM [mm³/(s·min)] range on which f2 is read at each Fa/A: the overlap of the two bracketing
        curves (NaN for an Fa/A outside the curves)."""
        level = np.atleast_1d(np.asarray(Fa_over_A, dtype=float))
        lower, upper, inside = self._brackets(level)
        lows = np.array([c.x_range[0] for c in self._curves])
        highs = np.array([c.x_range[1] for c in self._curves])
        return (np.where(inside, np.fmax(lows[lower], lows[upper]), np.nan),
                np.where(inside, np.fmin(highs[lower], highs[upper]), np.nan))

    def values(self, Fa_over_A, nu_n_dM) -> np.ndarray:
        """f2 at each query point, NaN where the chart does not reach (:meth:`lookup` says why); vectorised over
        the points, for the roots of the heat balance that read f2 at every trial speed or temperature."""
        level, x = np.broadcast_arrays(np.atleast_1d(np.asarray(Fa_over_A, dtype=float)),
                                       np.atleast_1d(np.asarray(nu_n_dM, dtype=float)))
        level, x = level.ravel(), x.ravel()
        lower, upper, inside = self._brackets(level)
        x_lo, x_hi = self.x_range(level)
        with np.errstate(invalid="ignore", divide="ignore"):
            usable = inside & (x >= x_lo) & (x <= x_hi)
            log_x = np.log(np.where(usable, x, 1.0))
            log_f2 = np.full((2, len(x)), np.nan)
            for side, index in enumerate((lower, upper)):  # log f2 along each bracketing curve, curve by curve
                for k in np.unique(index[usable]).tolist():
                    at = usable & (index == k)
                    log_f2[side, at] = np.interp(log_x[at], self._curves[k].log_x, self._curves[k].log_f2)
            low_level, high_level = np.log(self._levels[lower]), np.log(self._levels[upper])
            w = (np.log(np.where(usable, level, 1.0)) - low_level) / (high_level - low_level)
            f2 = np.where(lower == upper, np.exp(log_f2[0]), np.exp(log_f2[0] + w * (log_f2[1] - log_f2[0])))
        return np.where(usable, f2, np.nan).reshape(np.shape(level))

    def lookup(self, Fa_over_A, nu_n_dM):
        """f2 at each query point, and a refusal message per point ('' where f2 is valid).

        ``nu_n_dM`` in mm³/(s·min). Refused points get f2 = NaN.
        """
        q_level = np.atleast_1d(np.asarray(Fa_over_A, dtype=float))
        q_x = np.atleast_1d(np.asarray(nu_n_dM, dtype=float))
        q_level, q_x = np.broadcast_arrays(q_level, q_x)
        f2 = self.values(q_level, q_x).reshape(q_level.shape)
        reasons = np.full(q_level.shape, "", dtype=object)
        lo, hi = self.Fa_over_A_range
        lower, upper, inside = self._brackets(q_level.ravel())
        for i in np.flatnonzero(np.isnan(f2.ravel())).tolist():  # the refused points only: why each one is
            level, x = float(q_level.flat[i]), float(q_x.flat[i])
            if not inside[i]:
                reasons.flat[i] = (f"Fa/A = {level:.4g} is outside the f2 chart's curves ({lo:g} to {hi:g}); "
                                   "the Schaeffler catalogue forbids extrapolating the chart")
                continue
            for curve in [self._curves[k] for k in dict.fromkeys((int(lower[i]), int(upper[i])))]:
                x_lo, x_hi = curve.x_range
                if not (x_lo <= x <= x_hi):
                    reasons.flat[i] = (f"nu*n*dM = {x:.4g} mm^3/(s*min) is outside curve {curve.label!r} "
                                       f"(Fa/A = {curve.Fa_over_A:g}: {x_lo:.4g} to {x_hi:.4g}); "
                                       "the Schaeffler catalogue forbids extrapolating the chart")
                    break
        return f2, reasons
