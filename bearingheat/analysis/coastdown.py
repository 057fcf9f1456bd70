"""Coast-down (run-down) analysis of a rotor on plain or rolling bearings: the fits (the TMM-7M lab sheet, the Schaeffler catalogue).

A constant reduced friction coefficient f (the TMM-7M lab sheet) gives a straight
run-down line. To test that assumption the resisting torque is fitted as
nested models (Coulomb; + viscous; + aerodynamic)::

    M(ω) = M_c + c_v·ω + c_a·ω²

by least squares on n(t) itself (the model is integrated, not differentiated,
:func:`bearingheat.kernels.coastdown.rundown_speed`), and the model is chosen
by cross-validation and by the Bayesian information criterion. A
rolling-bearing spindle is fitted with the catalogue form of the Schaeffler catalogue
instead: M = z·(M0(n) + M1).

The formulas are the kernels of :mod:`bearingheat.kernels.coastdown`.
Units: t [s], n [1/min], I [kg·m²], G [N], r [mm], torques [N·m] (the Schaeffler catalogue
M0 and M1 in [N·mm]), energy [J]. The unit-aware functions
:func:`~bearingheat.api.coastdown.analyse_coastdown` and
:func:`~bearingheat.api.coastdown.analyse_spindle_coastdown` take pint
Quantities.

>>> t = np.arange(0.0, 61.0, 2.0)
>>> result = coastdown_analysis(t, 600.0 - 10.0 * t, 2.6, 1100.0, 25.0)   # 10 1/min per second
>>> result.model, round(result.f_constant, 4)
('coulomb', 0.099)
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd
from scipy import stats
from scipy.optimize import least_squares

from bearingheat.errors import CoastdownError
from bearingheat.kernels.coastdown import (
    RPM_TO_RAD_S,
    plain_torque,
    reduced_friction_coefficient_tmm7m_formula2,
    rolling_bearing_M0_schaeffler,
    rundown_speed,
    savitzky_golay_irregular,
)

__all__ = [
    "PLAIN_MODELS",
    "PARAMETER_UNITS",
    "MIN_SAMPLES",
    "CV_FOLDS",
    "CONFIDENCE",
    "EXTRAPOLATION_WARNING_FACTOR",
    "interval_friction_table",
    "ModelFit",
    "SpindleFit",
    "CoastdownResult",
    "coastdown_analysis",
    "spindle_coastdown_fit",
]

#: A run-down time extrapolated past the record by more than this many record durations is flagged: the fitted
#: torque near standstill, which sets it, was not measured.
EXTRAPOLATION_WARNING_FACTOR = 10.0

#: Nested models of the resisting torque, simplest first: name -> fitted components.
PLAIN_MODELS: dict[str, tuple[str, ...]] = {
    "coulomb": ("M_c",),
    "coulomb_viscous": ("M_c", "c_v"),
    "coulomb_viscous_aero": ("M_c", "c_v", "c_a"),
}

#: Unit of each fitted parameter (summary keys are 'name [unit]').
PARAMETER_UNITS = {
    "n0": "1/min",
    "M_c": "N*m",
    "c_v": "N*m*s",
    "c_a": "N*m*s^2",
    "f0": "1",
    "M1": "N*mm",
}

#: torque parameters -> resisting torque M(ω) [N·m] as a function of ω [rad/s]
TorqueBuilder = Callable[[np.ndarray], Callable[[np.ndarray], np.ndarray]]

MIN_SAMPLES = 10
CV_FOLDS = 5
CONFIDENCE = 0.95


def _default_window(count: int) -> int:
    window = max(7, int(round(count / 10.0)))
    window = min(window, 51, count if count % 2 else count - 1)
    return window if window % 2 else window - 1


# --------------------------------------------------------------------------- fitting
@dataclass
class ModelFit:
    """One least-squares fit of n(t): parameter values, 95 % intervals, goodness of fit."""

    name: str
    parameters: tuple[str, ...]
    values: np.ndarray
    std_errors: np.ndarray
    ci_low: np.ndarray
    ci_high: np.ndarray
    rmse: float  # [1/min]
    bic: float
    cv_rmse: float  # [1/min], interleaved k-fold
    fitted: np.ndarray  # model n at the samples [1/min]
    cut_at_bound: np.ndarray  # True where the interval's low end is the parameter's bound (M_c >= 0), not t·SE below

    def value(self, name: str) -> float:
        return float(self.values[self.parameters.index(name)]) if name in self.parameters else 0.0

    def interval(self, name: str) -> tuple[float, float]:
        """The 95 % interval of a parameter of the fit ((0, 0) for a component the model does not have)."""
        if name not in self.parameters:
            return (0.0, 0.0)
        k = self.parameters.index(name)
        return (float(self.ci_low[k]), float(self.ci_high[k]))

    def interval_cut(self, name: str) -> bool:
        """Whether the interval of ``name`` ends at the parameter's lower bound (e.g. M_c >= 0) rather than t·SE
        below the value."""
        return name in self.parameters and bool(self.cut_at_bound[self.parameters.index(name)])


def _least_squares_fit(t: np.ndarray, n: np.ndarray, build_torque: TorqueBuilder, start: np.ndarray,
                       lower: np.ndarray, upper: np.ndarray, scale: np.ndarray, I: float,
                       t0: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fit (n0 at t0, torque parameters) to n(t); returns (values, jacobian, residuals)."""
    penalty = 10.0 * float(np.max(n))

    def residuals(params: np.ndarray) -> np.ndarray:
        model = rundown_speed(t, t0, params[0], build_torque(params[1:]), I)
        res = model - n
        return np.where(np.isfinite(res), res, penalty)

    start = np.clip(np.asarray(start, dtype=float), lower, upper)
    solution = least_squares(residuals, start, bounds=(lower, upper), x_scale=scale, method="trf",
                             xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=2000)
    return solution.x, solution.jac, solution.fun


def _fit_model(name: str, t: np.ndarray, n: np.ndarray, build_torque: TorqueBuilder, start: np.ndarray,
               lower: np.ndarray, upper: np.ndarray, scale: np.ndarray, I: float,
               parameters: tuple[str, ...]) -> ModelFit:
    t0 = float(t[0])
    values, jac, res = _least_squares_fit(t, n, build_torque, start, lower, upper, scale, I, t0)
    count, k = n.size, values.size
    rss = float(res @ res)
    dof = max(count - k, 1)
    # s²·(JᵀJ)⁻¹ as J⁺·J⁺ᵀ: the pseudo-inverse of J, not of JᵀJ (which squares its condition number)
    jac_pinv = np.linalg.pinv(jac)
    covariance = jac_pinv @ jac_pinv.T * rss / dof
    std_errors = np.sqrt(np.clip(np.diag(covariance), 0.0, None))
    half_width = stats.t.ppf(0.5 + CONFIDENCE / 2.0, dof) * std_errors
    bic = count * math.log(max(rss, 1e-300) / count) + k * math.log(count)
    # interleaved k-fold cross-validation: every CV_FOLDS-th sample held out in turn
    held_out_sq = 0.0
    folds = np.arange(count) % CV_FOLDS
    for fold in range(CV_FOLDS):
        train = folds != fold
        fold_values, _, _ = _least_squares_fit(t[train], n[train], build_torque, values, lower, upper, scale, I, t0)
        predicted = rundown_speed(t[~train], t0, fold_values[0], build_torque(fold_values[1:]), I)
        err = predicted - n[~train]
        held_out_sq += float(err @ err)
    cv_rmse = math.sqrt(held_out_sq / count)
    fitted = rundown_speed(t, float(t[0]), values[0], build_torque(values[1:]), I)
    # a parameter bounded below (n0, M_c, f0, M1 >= 0) cannot lie below its bound, so the interval stops there: the
    # same coverage, without negative torques
    cut_at_bound = values - half_width < lower
    return ModelFit(name, ("n0",) + tuple(parameters), values, std_errors, np.maximum(values - half_width, lower),
                    values + half_width, math.sqrt(rss / count), bic, cv_rmse, fitted, cut_at_bound)


def _plain_builder(components: tuple[str, ...]) -> TorqueBuilder:
    def build(params: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
        named = dict(zip(components, params))
        return plain_torque(**named)
    return build


def _select_model(fits: dict[str, ModelFit]) -> str:
    """The simpler of the BIC choice and the cross-validation choice."""
    names = list(fits)
    by_bic = min(names, key=lambda m: fits[m].bic)
    by_cv = min(names, key=lambda m: fits[m].cv_rmse)
    return names[min(names.index(by_bic), names.index(by_cv))]


# --------------------------------------------------------------------------- interval table (formula 2)
def interval_friction_table(t: npt.ArrayLike, n_smooth: npt.ArrayLike, I: float, G: float | None = None,
                            r: float | None = None, dn: float | None = None, dt: float | None = None,
                            count: int = 10) -> pd.DataFrame:
    """Interval-average torque and the TMM-7M lab sheet formula (2) over chosen intervals of the smoothed run-down.

    Intervals are speed steps ``dn`` [1/min] down from the first smoothed speed
    (the TMM-7M lab sheet's way: read Δt for a chosen Δn off the diagram), or time steps
    ``dt`` [s]; with neither, ``count`` equal speed steps over the recorded
    range. Crossing times are interpolated linearly on the smoothed curve.
    Returns a DataFrame; the ``f`` column is NaN when G or r is not given.
    """
    _check_interval_count(count)
    t = np.asarray(t, dtype=float)
    speed = np.asarray(n_smooth, dtype=float)
    if dn is not None and dt is not None:
        raise CoastdownError("intervals: give either a speed step Δn or a time step Δt, not both")
    if dt is not None:
        if not dt > 0:
            raise CoastdownError(f"intervals: Δt = {dt:g} s; expected a time step > 0 s")
        if dt > t[-1] - t[0]:  # not one interval would fit: an empty table would say nothing
            raise CoastdownError(f"intervals: Δt = {dt:g} s is longer than the recorded run-down "
                                 f"({t[-1] - t[0]:g} s); give a shorter time step")
        edges_t = np.arange(t[0], t[-1] + 1e-9 * dt, dt)
        edges_n = np.interp(edges_t, t, speed)
    else:
        top = float(speed[0])
        bottom = max(float(np.min(speed)), 0.0)
        if dn is None:
            dn = (top - bottom) / count
        if not dn > 0:
            raise CoastdownError(f"intervals: Δn = {dn:g} 1/min; expected a speed step > 0 1/min")
        if dn > top - bottom:
            raise CoastdownError(f"intervals: Δn = {dn:g} 1/min is larger than the recorded speed range "
                                 f"({top:g} to {bottom:g} 1/min); give a smaller speed step")
        edges_n = top - dn * np.arange(int(math.floor((top - bottom) / dn + 1e-9)) + 1)
        edges_t = np.array([_first_crossing(t, speed, level) for level in edges_n])
    rows = []
    for k in range(len(edges_t) - 1):
        n_from, n_to = float(edges_n[k]), float(edges_n[k + 1])
        t_from, t_to = float(edges_t[k]), float(edges_t[k + 1])
        duration = t_to - t_from
        torque = I * RPM_TO_RAD_S * (n_from - n_to) / duration
        f = (reduced_friction_coefficient_tmm7m_formula2(n_from - n_to, duration, I, G, r)
             if G is not None and r is not None else float("nan"))
        rows.append({"n_from [1/min]": n_from, "n_to [1/min]": n_to, "n_mean [1/min]": 0.5 * (n_from + n_to),
                     "t_from [s]": t_from, "t_to [s]": t_to, "dt [s]": duration, "M [N*m]": torque, "f": f})
    columns = ["n_from [1/min]", "n_to [1/min]", "n_mean [1/min]", "t_from [s]", "t_to [s]", "dt [s]", "M [N*m]", "f"]
    return pd.DataFrame(rows, columns=columns)


def _check_interval_count(count: Any) -> None:
    """``count`` equal speed steps: a whole number >= 1 (0 divided the range by zero, -3 made a negative Δn)."""
    if isinstance(count, bool) or not isinstance(count, (int, float, np.integer, np.floating)) or \
            not (math.isfinite(count) and count == int(count) and count >= 1):
        raise CoastdownError(f"intervals: interval_count = {count!r}; expected a whole number >= 1")


def _first_crossing(t: np.ndarray, speed: np.ndarray, level: float) -> float:
    below = np.flatnonzero(speed <= level + 1e-9 * abs(float(speed[0])))
    k = int(below[0])
    if k == 0:
        return float(t[0])
    span = speed[k - 1] - speed[k]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (speed[k - 1] - level) / span)


# --------------------------------------------------------------------------- results
@dataclass
class SpindleFit:
    """The Schaeffler catalogue catalogue form fitted to a run-down of a shaft on ``bearings`` rolling bearings."""

    fit: ModelFit
    nu: float  # [mm²/s]
    dM: float  # [mm]
    bearings: int
    P: float | None  # [N]
    f0_catalogue: float | None

    @property
    def f0(self) -> float:
        return self.fit.value("f0")

    @property
    def M1(self) -> float:
        """Load-dependent torque of one bearing [N·mm]."""
        return self.fit.value("M1")

    @property
    def f1(self) -> float:
        return self.M1 / (self.P * self.dM) if self.P else float("nan")

    def summary(self) -> dict[str, Any]:
        out = {
            "model": "rolling_M0_M1_schaeffler",
            "bearings": self.bearings,
            "nu [mm^2/s]": self.nu,
            "dM [mm]": self.dM,
            "f0": self.f0,
            "f0_ci95": list(self.fit.interval("f0")),
            "M1 [N*mm]": self.M1,
            "M1_ci95 [N*mm]": list(self.fit.interval("M1")),
            "rmse [1/min]": self.fit.rmse,
        }
        if self.P:
            low, high = self.fit.interval("M1")
            out.update({"P [N]": self.P, "f1": self.f1, "f1_ci95": [low / (self.P * self.dM), high / (self.P * self.dM)]})
        if self.f0_catalogue is not None:
            out.update({"f0_catalogue": self.f0_catalogue, "f0_ratio_fitted_to_catalogue": self.f0 / self.f0_catalogue})
        return out


@dataclass
class CoastdownResult:
    """Everything :func:`coastdown_analysis` finds.

    ``summary()`` holds the values of the ``summary.json`` the CLI writes; non-finite values (f without G and
    r, a run-down that never stops) stay NaN or inf here and become null in the file
    (:func:`bearingheat.io.json.json_safe`, applied by :mod:`bearingheat.io.reports.coastdown`).
    """

    I: float
    G: float | None
    r: float | None
    model: str
    fits: dict[str, ModelFit]
    samples: pd.DataFrame
    intervals: pd.DataFrame
    window: int
    rundown_time: float  # [s] from the first sample to standstill (inf: never stops)
    rundown_extrapolated: bool
    energy: dict[str, float]  # [J]
    spindle: SpindleFit | None = field(default=None)
    #: the rig values (of "I", "G", "r") taken from the TMM-7M rig's defaults, not given (set by the unit-aware API)
    rig_defaults: tuple[str, ...] = ()

    @property
    def chosen(self) -> ModelFit:
        return self.fits[self.model]

    @property
    def f_constant(self) -> float:
        """The TMM-7M lab sheet's single coefficient: M_c of the constant-torque (Coulomb) fit over G·r."""
        if self.G is None or self.r is None:
            return float("nan")
        return self.fits["coulomb"].value("M_c") / (self.G * self.r / 1000.0)

    @property
    def f_computed(self) -> bool:
        """Whether f is computed: it needs the journal load G and radius r (without them: torques only)."""
        return self.G is not None and self.r is not None

    @property
    def record_duration(self) -> float:
        """Duration of the record [s], first to last sample."""
        t = self.samples["t [s]"]
        return float(t.iloc[-1] - t.iloc[0])

    @property
    def rundown_warning(self) -> str | None:
        """Why the run-down time is doubtful: extrapolated past the record by more than
        :data:`EXTRAPOLATION_WARNING_FACTOR` times its duration (None otherwise)."""
        beyond = self.rundown_time - self.record_duration
        if not (math.isfinite(beyond) and beyond > EXTRAPOLATION_WARNING_FACTOR * self.record_duration):
            return None
        return (f"the run-down time is extrapolated {beyond:.4g} s past a record of {self.record_duration:.4g} s "
                f"(more than {EXTRAPOLATION_WARNING_FACTOR:g} times its duration): it rests on the fitted torque "
                "near standstill, which was not measured")

    @property
    def rmse_before(self) -> float:
        return self.fits["coulomb"].rmse

    @property
    def rmse_after(self) -> float:
        return self.chosen.rmse

    def torque(self, omega: npt.ArrayLike) -> np.ndarray:
        """Fitted resisting torque [N·m] of the chosen model at ω [rad/s]."""
        fit = self.chosen
        return plain_torque(fit.value("M_c"), fit.value("c_v"), fit.value("c_a"))(np.asarray(omega, dtype=float))

    def summary(self) -> dict[str, Any]:
        fit = self.chosen
        out: dict[str, Any] = {"model": self.model}
        for name in ("M_c", "c_v", "c_a"):
            unit = PARAMETER_UNITS[name]
            out[f"{name} [{unit}]"] = fit.value(name)
            # a component the chosen model does not have is 0 there, but was not measured: no interval (null)
            out[f"{name}_ci95 [{unit}]"] = list(fit.interval(name)) if name in fit.parameters else None
        out.update({
            "f_computed": self.f_computed,
            "f_constant": self.f_constant,
            "rmse_before [1/min]": self.rmse_before,
            "rmse_after [1/min]": self.rmse_after,
            "rundown_time [s]": self.rundown_time,
            "rundown_time_extrapolated": self.rundown_extrapolated,
            "rundown_time_warning": self.rundown_warning,
            "energy [J]": dict(self.energy),
            "I [kg*m^2]": self.I,
            "G [N]": self.G,
            "r [mm]": self.r,
            "rig_defaults": list(self.rig_defaults),
            "savgol_window": self.window,
            "models": {
                name: {"parameters": dict(zip(f.parameters, map(float, f.values))),
                       "rmse [1/min]": f.rmse, "cv_rmse [1/min]": f.cv_rmse, "bic": f.bic}
                for name, f in self.fits.items()
            },
        })
        if self.spindle is not None:
            out["spindle"] = self.spindle.summary()
        return out


# --------------------------------------------------------------------------- analysis
def _validate(t: npt.ArrayLike, n: npt.ArrayLike, I: float, G: float | None,
              r: float | None) -> tuple[np.ndarray, np.ndarray]:
    t = np.asarray(t, dtype=float)
    n = np.asarray(n, dtype=float)
    if t.shape != n.shape or t.ndim != 1:
        raise CoastdownError(f"coast-down: t and n must be 1-D and of equal length; got {t.shape} and {n.shape}")
    if t.size < MIN_SAMPLES:
        raise CoastdownError(f"coast-down: {t.size} samples; at least {MIN_SAMPLES} are needed "
                         "to fit and cross-validate the nested models")
    for k in range(t.size):
        if not math.isfinite(t[k]):
            raise CoastdownError(f"coast-down: sample {k + 1}: t = {t[k]}; expected a finite time in s")
        if not (math.isfinite(n[k]) and n[k] >= 0.0):
            raise CoastdownError(f"coast-down: sample {k + 1}: n = {n[k]:g} 1/min; expected a finite speed >= 0 1/min")
        if k and not t[k] > t[k - 1]:
            raise CoastdownError(f"coast-down: sample {k + 1}: t = {t[k]:g} s does not follow t = {t[k - 1]:g} s; "
                             "times must increase strictly")
    if not n[-1] < n[0]:
        raise CoastdownError(f"coast-down: the speed does not fall (n = {n[0]:g} 1/min at the start, "
                         f"{n[-1]:g} 1/min at the end); a run-down diagram is needed")
    for name, value, unit in (("I", I, "kg*m^2"), ("G", G, "N"), ("r", r, "mm")):
        if value is not None and not (math.isfinite(value) and value > 0.0):
            raise CoastdownError(f"coast-down: {name} = {value:g} {unit}; expected a value > 0")
    return t, n


def _trapezoid(y: np.ndarray, x: np.ndarray) -> float:
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))


def _usable_derivative_mask(n_smooth: np.ndarray, n_max: float) -> np.ndarray:
    """Samples before the rotor stops (smoothed speed above 2 % of the top speed)."""
    running = n_smooth > 0.02 * n_max
    stop = np.flatnonzero(~running)
    if stop.size:
        running[stop[0]:] = False
    return running


def coastdown_analysis(t: npt.ArrayLike, n: npt.ArrayLike, I: float, G: float | None = None, r: float | None = None,
                       *, window: int | None = None, interval_dn: float | None = None,
                       interval_dt: float | None = None, interval_count: int = 10) -> CoastdownResult:
    """Analyse a run-down n(t): the TMM-7M lab sheet formulas (1) and (2) and the nested torque models.

    t [s], n [1/min] samples; I [kg·m²]; G [N] and r [mm] (None: no friction
    coefficient, torques only); window: Savitzky–Golay window in samples
    (default about a tenth of the samples, odd, 7 to 51); interval_count: the
    number of equal speed steps of formula (2) where neither interval_dn nor
    interval_dt is given, a whole number >= 1.
    """
    t, n = _validate(t, n, I, G, r)
    _check_interval_count(interval_count)
    window = _default_window(t.size) if window is None else int(window)
    n_smooth, dn_dt = savitzky_golay_irregular(t, n, window)
    n_max = float(np.max(n))
    omega = n_smooth * RPM_TO_RAD_S
    torque_formula1 = -I * RPM_TO_RAD_S * dn_dt
    usable = _usable_derivative_mask(n_smooth, n_max)
    if usable.sum() < 4:
        raise CoastdownError("coast-down: fewer than 4 samples above 2 % of the top speed; the run-down is too short")

    # start values from the smoothed derivative: regress I·|dω/dt| on 1, ω, ω²
    omega_top = n_max * RPM_TO_RAD_S
    mean_torque = I * omega_top / (t[-1] - t[0])
    fits: dict[str, ModelFit] = {}
    for name, components in PLAIN_MODELS.items():
        k = len(components)
        design = np.stack([omega[usable] ** j for j in range(k)], axis=1)
        guess, *_ = np.linalg.lstsq(design, torque_formula1[usable], rcond=None)
        guess[0] = max(guess[0], 0.01 * mean_torque)
        start = np.concatenate(([n[0]], guess))
        lower = np.array([0.0, 0.0] + [-np.inf] * (k - 1))
        upper = np.full(k + 1, np.inf)
        scale = np.array([n_max] + [mean_torque / omega_top ** j for j in range(k)])
        fits[name] = _fit_model(name, t, n, _plain_builder(components), start, lower, upper, scale, I, components)
    model = _select_model(fits)
    chosen = fits[model]
    torque = plain_torque(chosen.value("M_c"), chosen.value("c_v"), chosen.value("c_a"))

    # run-down time and energy from the chosen model
    omega_first = chosen.value("n0") * RPM_TO_RAD_S
    grid = np.linspace(omega_first, 0.0, 20001)
    moment = torque(grid)
    if np.all(moment > 0.0):
        inverse = I / moment
        rundown_time = float(np.sum(0.5 * (inverse[1:] + inverse[:-1]) * (grid[:-1] - grid[1:])))
    else:
        rundown_time = float("inf")
    dense_t = np.linspace(t[0], t[-1], 4001)
    dense_omega = rundown_speed(dense_t, t[0], chosen.value("n0"), torque, I) * RPM_TO_RAD_S
    energy = {
        "coulomb": chosen.value("M_c") * _trapezoid(dense_omega, dense_t),
        "viscous": chosen.value("c_v") * _trapezoid(dense_omega ** 2, dense_t),
        "aero": chosen.value("c_a") * _trapezoid(dense_omega ** 3, dense_t),
    }
    energy["total"] = 0.5 * I * (dense_omega[0] ** 2 - dense_omega[-1] ** 2)
    energy["to_standstill"] = 0.5 * I * dense_omega[0] ** 2

    f_scale = (G * r / 1000.0) if G is not None and r is not None else float("nan")
    samples = pd.DataFrame({
        "t [s]": t,
        "n [1/min]": n,
        "n_smooth [1/min]": n_smooth,
        "dn/dt [1/min/s]": dn_dt,
        "M_formula1 [N*m]": np.where(usable, torque_formula1, np.nan),
        "f_formula1": np.where(usable, torque_formula1 / f_scale, np.nan),
        "n_constant_f [1/min]": fits["coulomb"].fitted,
        "n_model [1/min]": chosen.fitted,
        "M_model [N*m]": torque(n_smooth * RPM_TO_RAD_S),
        "f_model": torque(n_smooth * RPM_TO_RAD_S) / f_scale,
    })
    stopped = ~usable
    samples.loc[stopped, ["M_model [N*m]", "f_model"]] = np.nan
    intervals = interval_friction_table(t[usable], n_smooth[usable], I, G, r, dn=interval_dn, dt=interval_dt,
                                        count=interval_count)
    return CoastdownResult(I=float(I), G=None if G is None else float(G), r=None if r is None else float(r),
                           model=model, fits=fits, samples=samples, intervals=intervals, window=window,
                           rundown_time=rundown_time, rundown_extrapolated=bool(t[0] + rundown_time > t[-1]),
                           energy=energy)


def spindle_coastdown_fit(t: npt.ArrayLike, n: npt.ArrayLike, I: float, nu: float, dM: float, bearings: int = 2,
                          P: float | None = None, f0_catalogue: float | None = None) -> SpindleFit:
    """Fit f0 and M1 of the Schaeffler catalogue form to a run-down of a shaft on rolling bearings.

    M(n) = bearings·(M0(n; ν, dM, f0) + M1) [N·mm], M0 from
    :func:`rolling_bearing_M0_schaeffler`, M1 = f1·P·dM constant during the
    run-down (the load does not change). ν [mm²/s] is taken as constant
    (steady temperature). f1 = M1/(P·dM) is reported when P [N] is given;
    the fitted f0 is compared with ``f0_catalogue`` when given (finite, > 0).
    """
    t, n = _validate(t, n, I, None, None)
    if f0_catalogue is not None and not (math.isfinite(f0_catalogue) and f0_catalogue > 0.0):
        # the fitted-to-catalogue ratio divides by it: 0 crashed, nan became null, -2 gave a negative ratio
        raise CoastdownError(f"spindle coast-down: catalogue f0 = {f0_catalogue:g}; expected a finite value > 0 "
                             "to compare the fitted f0 with")
    for name, value, unit in (("nu", nu, "mm^2/s"), ("dM", dM, "mm")):
        if not (math.isfinite(value) and value > 0.0):
            raise CoastdownError(f"spindle coast-down: {name} = {value:g} {unit}; expected a value > 0")
    if int(bearings) != bearings or bearings < 1:
        raise CoastdownError(f"spindle coast-down: bearings = {bearings}; expected a whole number >= 1")
    if P is not None and not (math.isfinite(P) and P > 0.0):
        raise CoastdownError(f"spindle coast-down: P = {P:g} N; expected a load > 0 N")
    n_max = float(np.max(n))
    if nu * n_max < 2000.0:
        raise CoastdownError(
            f"spindle coast-down: ν·n reaches only {nu * n_max:.0f} mm²/s·1/min (< 2000): M0 of the Schaeffler catalogue is constant "
            "over the whole run-down and cannot be told apart from M1"
        )
    n_smooth, dn_dt = savitzky_golay_irregular(t, n, _default_window(t.size))
    usable = _usable_derivative_mask(n_smooth, n_max)
    torque_nmm = -I * RPM_TO_RAD_S * dn_dt[usable] * 1000.0 / bearings
    shape = rolling_bearing_M0_schaeffler(n_smooth[usable], nu, dM, 1.0)
    design = np.stack([shape, np.ones_like(shape)], axis=1)
    guess, *_ = np.linalg.lstsq(design, torque_nmm, rcond=None)
    mean_torque_nmm = I * n_max * RPM_TO_RAD_S / (t[-1] - t[0]) * 1000.0 / bearings
    guess = np.maximum(guess, [0.01 * mean_torque_nmm / float(np.max(shape)), 0.01 * mean_torque_nmm])

    def build(params: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
        f0, m1 = params
        return lambda omega: bearings * (rolling_bearing_M0_schaeffler(omega / RPM_TO_RAD_S, nu, dM, f0) + m1) / 1000.0

    start = np.concatenate(([n[0]], guess))
    scale = np.array([n_max, mean_torque_nmm / float(np.max(shape)), mean_torque_nmm])
    fit = _fit_model("rolling_M0_M1_schaeffler", t, n, build, start, np.zeros(3), np.full(3, np.inf), scale, I,
                     ("f0", "M1"))
    return SpindleFit(fit=fit, nu=float(nu), dM=float(dM), bearings=int(bearings), P=P, f0_catalogue=f0_catalogue)
