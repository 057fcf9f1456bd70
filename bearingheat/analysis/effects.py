"""Candidate effects the catalogue friction model lacks: a library of parametrised extensions.

Each candidate is a physical extension of the Schaeffler catalogue model
M_R = M0 + M1 (+ M2), written on the kernel outputs of
:func:`bearingheat.calc.models.compute_supports` (catalogue units: N·mm, N,
1/min, mm²/s, mm, W, h, °C); the physics of each extension is a kernel of
:mod:`bearingheat.kernels.effects`. A candidate fits its parameters by least
squares on relative residuals (M_measured − M_model)/M_measured, predicts the
torque of any rows, and applies its fitted parameters to the results of
``calc`` (:meth:`Candidate.apply`). :data:`CANDIDATES` maps each name to its
candidate; the names are the public vocabulary of ``bearingheat diagnose``:

================== =================================================================  =====================
name               extension                                                          parameters
================== =================================================================  =====================
none               M = M0 + M1 + M2 (the catalogue model)                             (none)
seal_drag          M += M_seal[bearing], constant in n (contact seals: a component      M_seal [N*mm] per bearing
                   without a term in the formulas, the Schaeffler catalogue p. 63)
f0_scale           M0 -> k·M0 (oil level above the lowest rolling element: k <= 3,    k [1] >= 1
                   freshly greased: k = 2..5; the Schaeffler catalogue p. 65, fig. 2)
viscosity_heating  the bearing runs ΔT = R_th·N_R above the oil temperature given, so   R_th [K/W] >= 0
                   ν -> ν·exp(−b·ΔT) with b = 0.03 1/K (self-consistent in N_R)
drag_losses        M += c·1e-7·dM³·(n·dM/1000)^p, churning faster than n^(2/3)         c [1] >= 0, p in [0.9, 3]
run_in             M0 -> M0·(1 + a·exp(−t/τ)), extra friction that decays with t      a [1] >= 0, tau [h]
preload            Fa -> Fa + F_pre[bearing] before P0, P1 and f1 (the Schaeffler catalogue p. 68)    F_pre [N] per bearing
================== =================================================================  =====================

Every bound is physical (an effect adds friction, a preload pushes), so a
candidate fitted to data without its effect collapses onto the catalogue
model instead of bending it; the significance rule lives in
:mod:`bearingheat.analysis.diagnose`.
"""
from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from scipy import optimize

from bearingheat.analysis.candidate_rows import (CalcRows, ModelData, bearing_keys, catalogue_arrays,
                                                 evaluate_with_axial_load, m1_load)
from bearingheat.analysis.domain import domain_values, outside, read_domain
from bearingheat.calc.messages import with_texts
from bearingheat.calc.models import DEFAULT_MODEL, failed_rows, get_model, row_model_names
from bearingheat.calc.supports import SupportArrays
from bearingheat.errors import DiagnoseError, ModelError
from bearingheat.kernels import friction
from bearingheat.kernels.effects import (VISCOSITY_TEMPERATURE_COEFFICIENT, drag_loss_torque, heated_total_torque,
                                         seal_drag_torque)

__all__ = [
    "FittedEffect",
    "format_value",
    "EFFECT_NAMES",
    "CANDIDATES",
    "ModelData",
    "CalcRows",
    "Candidate",
    "catalogue_arrays",
    "evaluate_with_axial_load",
    "bearing_keys",
    "m1_load",
    "bound_side",
    "bound_sides",
    "AT_BOUND_TOLERANCE",
]


#: fitted parameters of a candidate, by name (a float, or an array per bearing)
Params = dict[str, Any]


def _weighted_sse(M: np.ndarray, pred: np.ndarray) -> float:
    r = (M - pred) / M
    return float(np.dot(r, r))


def _nonneg_scale(M: np.ndarray, base: np.ndarray, extra: np.ndarray) -> float:
    """θ >= 0 minimising Σ((M − base − θ·extra)/M)² (closed form)."""
    w2 = 1.0 / (M * M)
    den = float(np.sum(w2 * extra * extra))
    if den <= 0.0:
        return 0.0
    return max(0.0, float(np.sum(w2 * extra * (M - base))) / den)


def _grid_best(objective: Callable[[float], float], grid: np.ndarray) -> tuple[int, list[float]]:
    """Index of the best grid point of a 1-D objective, and the objective on the whole grid."""
    values = [objective(float(g)) for g in grid]
    return int(np.argmin(values)), values


def _refine(objective: Callable[[float], float], grid: np.ndarray, best: int, values: list[float],
            xatol: float) -> float:
    """A bounded search between the neighbours of grid point ``best``; the better of it and the grid point."""
    lo, hi = grid[max(best - 1, 0)], grid[min(best + 1, len(grid) - 1)]
    res = optimize.minimize_scalar(objective, bounds=(lo, hi), method="bounded", options={"xatol": xatol})
    return float(res.x) if res.fun < values[best] else float(grid[best])


class Candidate:
    """One parametrised extension of the catalogue model.

    Subclasses set ``name``, ``description``, ``key_regressor`` and
    ``required`` (the parameters of summary.json a fitted effect must hold)
    and implement :meth:`fit` and :meth:`predict` on row positions of a
    :class:`ModelData`, and :meth:`change`, which applies the fitted public
    parameters to the results of ``calc``. :meth:`applicable` gives '' or
    the reason it is not.
    """

    name = ""
    description = ""
    key_regressor = "n"
    required: tuple[str, ...] = ()
    #: the quantities the effect's term depends on: their fitted ranges are its domain (summary.json)
    domain: tuple[str, ...] = ()

    def applicable(self, data: ModelData) -> str:
        return ""

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        raise NotImplementedError

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def n_params(self, data: ModelData, params: Params) -> int:
        return len(params)

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        """Parameters as written to summary.json (names with units)."""
        return dict(params)

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        """The bounds (low, high) the fit of ``rows`` keeps each fitted parameter within: floats, or arrays per
        bearing (NaN for a bearing whose parameter is not fitted); inf where a side is open."""
        return {}

    def at_bound(self, data: ModelData, params: Params, rows: np.ndarray) -> dict[str, Any]:
        """Each fitted parameter as summary.json names it -> 'lower' or 'upper' where the fit of ``rows`` ended on
        that bound (:func:`bound_sides`), None inside them; a dict per bearing for a parameter per bearing."""
        marks: dict[str, Any] = {}
        for name, (low, high) in self.limits(data, rows).items():
            public = next(p for p in self.required if p == name or p.startswith(f"{name} ["))
            sides = bound_sides(params[name], low, high)
            marks[public] = dict(zip(data.bearing_names, sides.tolist())) if sides.ndim else sides.item()
        return marks

    def apply(self, frame: pd.DataFrame, results: pd.DataFrame, parameters: dict[str, Any], note: str, *,
              refused: np.ndarray | None = None, domain: dict[str, Any] | None = None
              ) -> list[tuple[int, str, str]]:
        """Add the fitted effect to MR and recompute NR for every row of calc ``results`` that is not in error.

        ``frame`` holds calc's inputs (contract names, catalogue units),
        ``results`` its results (``MR``, ``M0``, ``f0``, ``NR``, ``status``,
        ``message``; changed in place), ``parameters`` the public parameters
        of summary.json. Each changed row's message gets ``note``. Rows of
        ``refused`` are left as they are; a ``domain`` (summary.json) gives a
        warning for each changed row and quantity outside it, returned as
        (row position, 'warning', message) for calc to add.
        """
        ok = ~failed_rows(results) if refused is None else ~failed_rows(results) & ~refused
        if not ok.any():
            return []
        frame = frame.reset_index(drop=True)
        arrays, _ = catalogue_arrays(frame)
        rows = CalcRows(frame, results, ok, results["MR"].to_numpy(dtype=float).copy(),
                        results["M0"].to_numpy(dtype=float), arrays.n, arrays.nu,
                        friction.mean_diameter(arrays.d, arrays.D), bearing_keys(frame), arrays,
                        {int(i): note for i in np.flatnonzero(ok)})
        # the domain's values before the effect changes anything (P1 as the catalogue model has it)
        P1 = results["P1"].to_numpy(dtype=float) if "P1" in results.columns else np.full(len(frame), np.nan)
        values = domain_values(rows.n, rows.nu, rows.dM, m1_load(P1, arrays))
        self.change(rows, parameters)
        index = results.index
        results["MR"] = np.where(ok, rows.MR, results["MR"].to_numpy(dtype=float))
        results["NR"] = np.where(ok, friction.power_loss(rows.MR, rows.n), results["NR"].to_numpy(dtype=float))
        current = results["message"].iloc[list(rows.notes)].tolist()
        noted = [f"{now}; {text}" if now else text for now, text in zip(current, rows.notes.values())]
        results["message"] = pd.Series(with_texts(results["message"], rows.notes.keys(), noted), index=index,
                                       copy=False)
        return outside(domain, values, rows.positions, self.name) if domain else []

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        """Change ``rows.MR`` of the rows ``rows.ok`` by the fitted ``parameters`` (and ``rows.notes``)."""
        raise NotImplementedError


#: a fitted parameter within this share of its bound (0.5 %, of the bound's value) ends on it: a bounded 1-D
#: search stops within its tolerance of a bound, not on it (a zero bound is met exactly: the fits clip to it)
AT_BOUND_TOLERANCE = 5e-3


def bound_side(value: float, low: float, high: float) -> str | None:
    """'lower' or 'upper' where ``value`` ends on that bound (within :data:`AT_BOUND_TOLERANCE`), else None (also
    for NaN bounds: a parameter not fitted).

    >>> bound_side(1.0, 1.0, math.inf), bound_side(2.995, 0.9, 3.0), bound_side(2.0, 0.9, 3.0)
    ('lower', 'upper', None)
    """
    if not (np.isfinite(value) and np.isfinite(low)):
        return None
    if value <= low + AT_BOUND_TOLERANCE * abs(low):
        return "lower"
    if np.isfinite(high) and value >= high - AT_BOUND_TOLERANCE * abs(high):
        return "upper"
    return None


def bound_sides(value: Any, low: Any, high: Any) -> np.ndarray:
    """:func:`bound_side` of each entry of a fitted parameter ``value`` (a float, or an array per bearing) within
    ``low`` and ``high`` (floats, or arrays of its shape): an object array of ``value``'s shape.

    >>> bound_sides(np.array([0.0, 5.0, 2.0]), np.array([0.0, 0.0, np.nan]), np.array([9.0, 5.0, np.nan])).tolist()
    ['lower', 'upper', None]
    """
    current = np.asarray(value, dtype=float)
    lows, highs = np.broadcast_to(low, current.shape), np.broadcast_to(high, current.shape)
    sides = [bound_side(v, lo, hi) for v, lo, hi in zip(current.ravel(), lows.ravel(), highs.ravel())]
    return np.array(sides, dtype=object).reshape(current.shape)


class NoEffect(Candidate):
    name = "none"
    description = "the catalogue model M0 + M1 (+ M2) as it stands"
    key_regressor = "n"

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        return {}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return data.MR[rows]

    def apply(self, frame: pd.DataFrame, results: pd.DataFrame, parameters: dict[str, Any], note: str, *,
              refused: np.ndarray | None = None, domain: dict[str, Any] | None = None
              ) -> list[tuple[int, str, str]]:
        """The catalogue model as it stands: the results are left as they are."""
        return []


class SealDrag(Candidate):
    name = "seal_drag"
    description = "a contact-seal torque per bearing, constant in n (the Schaeffler catalogue p. 63: seal friction is a component without a term in the formulas)"
    key_regressor = "n"
    required = ("M_seal [N*mm]",)
    domain = ("n",)  # constant in n: shown so within the speeds measured only

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        M, base, code = data.M[rows], data.MR[rows], data.bearing[rows]
        w2 = 1.0 / (M * M)
        k = len(data.bearing_names)
        num = np.bincount(code, weights=w2 * (M - base), minlength=k)
        den = np.bincount(code, weights=w2, minlength=k)
        with np.errstate(invalid="ignore", divide="ignore"):
            M_seal = np.where(den > 0, np.maximum(num / den, 0.0), 0.0)
        return {"M_seal": M_seal}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return data.MR[rows] + seal_drag_torque(params["M_seal"], data.bearing[rows])

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        return {"M_seal": (0.0, math.inf)}

    def n_params(self, data: ModelData, params: Params) -> int:
        return int(np.count_nonzero(np.bincount(data.bearing, minlength=len(data.bearing_names))))

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"M_seal [N*mm]": {name: float(v) for name, v in zip(data.bearing_names, params["M_seal"])}}

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        table = parameters["M_seal [N*mm]"]
        for i in rows.positions:
            if rows.keys[i] in table:
                rows.MR[i] += float(table[rows.keys[i]])
            else:
                rows.notes[int(i)] = (f"diagnose effect {self.name}: no seal torque fitted for {rows.keys[i]}; "
                                      "catalogue MR kept")


class F0Scale(Candidate):
    name = "f0_scale"
    description = "speed-dependent friction k times the table f0 (oil level, fresh grease; the Schaeffler catalogue p. 65, fig. 2)"
    key_regressor = "nu*n"
    required = ("k",)
    domain = ("nu*n",)  # M0 grows as (nu*n)^(2/3) (the Schaeffler catalogue p. 64)

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        theta = _nonneg_scale(data.M[rows], data.MR[rows], data.M0[rows])
        return {"k": 1.0 + theta}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return data.MR[rows] + (params["k"] - 1.0) * data.M0[rows]

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        return {"k": (1.0, math.inf)}

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"k": float(params["k"])}

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        rows.MR[rows.ok] += (float(parameters["k"]) - 1.0) * rows.M0[rows.ok]


class ViscosityHeating(Candidate):
    name = "viscosity_heating"
    description = ("the bearing runs R_th*N_R hotter than the oil temperature given, so nu is lower "
                   f"(nu*exp(-{VISCOSITY_TEMPERATURE_COEFFICIENT}*dT))")
    key_regressor = "NR"
    required = ("R_th [K/W]",)
    domain = ("n", "nu*n", "dM", "load")  # through N_R = M_R*n, which all of them set

    def _predict(self, data: ModelData, R_th: float, rows: np.ndarray) -> np.ndarray:
        return heated_total_torque(R_th, data.f0[rows], data.nu[rows], data.n[rows], data.dM[rows],
                                   data.M1[rows] + data.M2[rows]) if R_th > 0 else data.MR[rows]

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        NR = data.NR[rows]
        top = float(np.nanmax(NR)) if len(NR) else 0.0
        # ν down to e^-4 at the highest loss of the rows (no heating where there is no loss)
        return {"R_th": (0.0, 4.0 / (VISCOSITY_TEMPERATURE_COEFFICIENT * top) if top > 0 else 0.0)}

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        R_max = self.limits(data, rows)["R_th"][1]
        if not R_max > 0:
            return {"R_th": 0.0}
        M = data.M[rows]

        def sse(log_r: float) -> float:
            return _weighted_sse(M, self._predict(data, math.exp(log_r), rows))

        grid = np.linspace(math.log(R_max) - 9.0, math.log(R_max), 19)
        best, values = _grid_best(sse, grid)
        if _weighted_sse(M, data.MR[rows]) <= values[best]:
            return {"R_th": 0.0}
        return {"R_th": math.exp(_refine(sse, grid, best, values, 1e-4))}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return self._predict(data, params["R_th"], rows)

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"R_th [K/W]": float(params["R_th"]), "b [1/K]": VISCOSITY_TEMPERATURE_COEFFICIENT}

    def n_params(self, data: ModelData, params: Params) -> int:
        return 1

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        ok = rows.ok
        load_part = rows.MR - rows.M0
        rows.MR[ok] = heated_total_torque(float(parameters["R_th [K/W]"]),
                                          rows.results["f0"].to_numpy(dtype=float)[ok], rows.nu[ok], rows.n[ok],
                                          rows.dM[ok], load_part[ok])


class DragLosses(Candidate):
    name = "drag_losses"
    description = "oil churning c*1e-7*dM^3*(n*dM/1000)^p, growing faster than n^(2/3)"
    key_regressor = "n"
    required = ("c", "p")
    domain = ("n", "dM")  # the churning term c*1e-7*dM^3*(n*dM/1000)^p
    P_BOUNDS = (0.9, 3.0)

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        M, base, dM, n = data.M[rows], data.MR[rows], data.dM[rows], data.n[rows]

        def best_c(p: float) -> tuple[float, float]:
            extra = drag_loss_torque(1.0, p, dM, n)
            c = _nonneg_scale(M, base, extra)
            return c, _weighted_sse(M, base + c * extra)

        def sse(p: float) -> float:
            return best_c(p)[1]

        grid = np.linspace(*self.P_BOUNDS, 22)
        p = _refine(sse, grid, *_grid_best(sse, grid), 1e-4)
        c, _ = best_c(p)
        return {"c": c, "p": p}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return data.MR[rows] + drag_loss_torque(params["c"], params["p"], data.dM[rows], data.n[rows])

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        return {"c": (0.0, math.inf), "p": self.P_BOUNDS}

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"c": float(params["c"]), "p": float(params["p"])}

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        ok = rows.ok
        rows.MR[ok] += drag_loss_torque(float(parameters["c"]), float(parameters["p"]), rows.dM[ok], rows.n[ok])


class RunIn(Candidate):
    name = "run_in"
    description = "extra speed-dependent friction a*M0*exp(-t/tau) that decays with running time t"
    key_regressor = "t"
    required = ("a", "tau [h]")
    domain = ("nu*n",)  # a share of M0

    def applicable(self, data: ModelData) -> str:
        t = data.t
        if np.all(np.isnan(t)):
            return "no running time column 't [h]'"
        if np.any(np.isnan(t)):
            return "the running time 't [h]' is blank in some rows"
        if not np.ptp(t) > 0:
            return "the running time t does not vary"
        return ""

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        M, base, M0, t = data.M[rows], data.MR[rows], data.M0[rows], data.t[rows]

        def best_a(log_tau: float) -> tuple[float, float]:
            extra = M0 * np.exp(-t / math.exp(log_tau))
            a = _nonneg_scale(M, base, extra)
            return a, _weighted_sse(M, base + a * extra)

        def sse(log_tau: float) -> float:
            return best_a(log_tau)[1]

        shortest, longest = self.limits(data, rows)["tau"]
        grid = np.linspace(math.log(shortest), math.log(longest), 21)
        log_tau = _refine(sse, grid, *_grid_best(sse, grid), 1e-4)
        a, _ = best_a(log_tau)
        return {"a": a, "tau": math.exp(log_tau)}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        return data.MR[rows] + params["a"] * data.M0[rows] * np.exp(-data.t[rows] / params["tau"])

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        # τ between 1 % and 100 % of the time span of the rows fitted (a training fold's own, not the held-out
        # rows'): a decay slower than that is indistinguishable from a constant f0 scale within them
        span = float(np.ptp(data.t[rows])) or 1.0
        return {"a": (0.0, math.inf), "tau": (0.01 * span, span)}

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"a": float(params["a"]), "tau [h]": float(params["tau"])}

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        frame, ok = rows.frame, rows.ok
        t = pd.to_numeric(frame["t"], errors="coerce").to_numpy(dtype=float) if "t" in frame.columns \
            else np.full(len(frame), np.nan)
        known = ok & ~np.isnan(t)
        rows.MR[known] += float(parameters["a"]) * rows.M0[known] * np.exp(-t[known] / float(parameters["tau [h]"]))
        for i in np.flatnonzero(ok & np.isnan(t)):
            rows.notes[int(i)] = f"diagnose effect {self.name}: no running time t given; taken as run in (t >> tau)"


class Preload(Candidate):
    name = "preload"
    description = "an undeclared axial preload F_pre per bearing added to Fa before P0, P1 and f1 (the Schaeffler catalogue p. 68)"
    key_regressor = "load"
    required = ("F_pre [N]",)
    domain = ("load",)  # P1 and f1 with the preload added to Fa

    @staticmethod
    def _arrays(data: ModelData) -> SupportArrays:
        """The support arrays of ``data`` (the candidate is applicable only where they are given)."""
        assert data.arrays is not None, "the preload candidate needs the support arrays of the rows"
        return data.arrays

    def _axial_bearings(self, data: ModelData) -> np.ndarray:
        """Bearing codes whose M1 depends on the axial load (ball, tapered, spherical, thrust)."""
        a = self._arrays(data)
        depends = (a.m1_load != "Fr") & ~a.no_axial
        return np.unique(data.bearing[depends])

    def applicable(self, data: ModelData) -> str:
        if data.arrays is None or data.arrays.size == 0:
            return "no catalogue arrays"
        if len(self._axial_bearings(data)) == 0:
            return "no bearing in the data has an M1 that depends on the axial load"
        return ""

    def _m1(self, data: ModelData, rows: np.ndarray, F_pre: np.ndarray | float) -> np.ndarray:
        return evaluate_with_axial_load(self._arrays(data), rows, data.Fa[rows] + F_pre)

    def _top(self, data: ModelData, mine: np.ndarray) -> float:
        """The largest preload [N] searched for a bearing's rows ``mine``: its C0, else 10 times its largest load."""
        arrays = self._arrays(data)
        C0_rows = np.broadcast_to(arrays.C0, (arrays.size,))[mine]  # (one NaN where C0 is no column)
        C0 = np.nanmax(C0_rows) if np.any(~np.isnan(C0_rows)) else np.nan
        return C0 if C0 > 0 else 10.0 * max(float(np.max(data.Fr[mine] + data.Fa[mine])), 1.0)

    def limits(self, data: ModelData, rows: np.ndarray) -> dict[str, tuple[Any, Any]]:
        low, high = np.full(len(data.bearing_names), np.nan), np.full(len(data.bearing_names), np.nan)
        for code in self._axial_bearings(data):
            mine = rows[data.bearing[rows] == code]
            if len(mine):
                low[code], high[code] = 0.0, self._top(data, mine)
        return {"F_pre": (low, high)}

    def fit(self, data: ModelData, rows: np.ndarray) -> Params:
        F_pre = np.zeros(len(data.bearing_names))
        for code in self._axial_bearings(data):
            mine = rows[data.bearing[rows] == code]
            if len(mine) == 0:
                continue
            M, M0 = data.M[mine], data.M0[mine]
            top = self._top(data, mine)

            def sse(force: float) -> float:
                pred = M0 + self._m1(data, mine, force)
                return _weighted_sse(M, pred) if np.all(np.isfinite(pred)) else math.inf

            grid = np.concatenate([[0.0], np.geomspace(top * 1e-3, top, 16)])
            best, values = _grid_best(sse, grid)
            if best == 0 or not math.isfinite(values[best]):
                continue
            F_pre[code] = _refine(sse, grid, best, values, 1e-3 * grid[best])
        return {"F_pre": F_pre}

    def predict(self, data: ModelData, params: Params, rows: np.ndarray) -> np.ndarray:
        F_pre = params["F_pre"][data.bearing[rows]]
        out = data.MR[rows].copy()
        active = F_pre > 0
        if active.any():
            sub = rows[active]
            out[active] = data.M0[sub] + self._m1(data, sub, F_pre[active])
        return out

    def n_params(self, data: ModelData, params: Params) -> int:
        return len(self._axial_bearings(data))

    def public_parameters(self, data: ModelData, params: Params) -> dict[str, Any]:
        return {"F_pre [N]": {name: float(v) for name, v in zip(data.bearing_names, params["F_pre"])}}

    def change(self, rows: CalcRows, parameters: dict[str, Any]) -> None:
        table, keys, a = parameters["F_pre [N]"], rows.keys, rows.arrays
        force = np.array([float(table.get(keys[i], 0.0)) for i in range(len(rows.frame))])
        active = np.flatnonzero(rows.ok & (force > 0))
        if len(active):
            rows.MR[active] = rows.M0[active] + evaluate_with_axial_load(a, active, a.Fa[active] + force[active])
        for i in rows.positions:
            if keys[i] not in table:
                rows.notes[int(i)] = f"diagnose effect {self.name}: no preload fitted for {keys[i]}; catalogue MR kept"


#: candidate name -> the candidate (the order is the order of the report)
CANDIDATES: dict[str, Candidate] = {c.name: c for c in (
    NoEffect(), SealDrag(), F0Scale(), ViscosityHeating(), DragLosses(), RunIn(), Preload())}

EFFECT_NAMES = tuple(CANDIDATES)


def format_value(value: Any, digits: int = 4) -> str:
    """A number, None or a dict of them as the report and the calc messages show it ('–' for none).

    >>> format_value({"k": 2.123456, "tau [h]": None})
    'k: 2.123, tau [h]: –'
    """
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    if isinstance(value, dict):
        return ", ".join(f"{k}: {format_value(v)}" for k, v in value.items())
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return str(value)


# ---- the fitted effect, applied by calc (calc --effects) ----------------------------------------------

@dataclass
class FittedEffect:
    """An effect fitted by ``diagnose``, applied to calc results (MR, NR in place).

    ``domain`` holds the ranges of the quantities the effect depends on over
    the fitted rows and the bearings (:func:`bearingheat.analysis.domain.fitted_domain`;
    None: not known, as in a summary.json of an older diagnose), ``base_model``
    the friction model it extends.

    >>> effect = FittedEffect("f0_scale", {"k": 2.0})
    >>> frame = pd.DataFrame({"designation": ["6205"], "d": [25.0], "D": [52.0], "n": [3000.0], "nu": [12.0]})
    >>> results = pd.DataFrame({"M0": [12.0], "M1": [8.0], "M2": [0.0], "MR": [20.0], "NR": [6.28],
    ...                         "f0": [2.0], "status": ["ok"], "message": [""]})
    >>> effect.apply(frame, results)
    []
    >>> float(results.at[0, "MR"]), round(float(results.at[0, "NR"]), 4)
    (32.0, 10.0524)
    """

    effect: str
    parameters: dict[str, Any]
    domain: dict[str, Any] | None = None
    base_model: str = DEFAULT_MODEL

    def __post_init__(self) -> None:
        if self.effect not in CANDIDATES:
            raise DiagnoseError(f"effect {self.effect!r} is not one of {', '.join(EFFECT_NAMES)}")
        for name in CANDIDATES[self.effect].required:
            if name not in self.parameters:
                raise DiagnoseError(f"effect {self.effect!r} needs the parameter {name!r}")
        if self.domain is not None:
            self.domain = read_domain(self.domain)
        try:
            self.base_model = get_model(str(self.base_model)).name
        except ModelError as exc:
            raise DiagnoseError(f"base_model of the summary: {exc}") from exc

    @classmethod
    def from_summary(cls, path: str | Path) -> FittedEffect:
        """Load the effect of a ``diagnose`` summary.json (one without 'domain' or 'base_model', written before
        they were recorded, loads with the domain unknown and the catalogue model, the only one diagnose fitted
        effects on)."""
        text = Path(path).read_text(encoding="utf-8")
        try:
            summary = json.loads(text)
        except json.JSONDecodeError as exc:
            raise DiagnoseError(f"not a JSON file ({exc})") from exc
        if not isinstance(summary, dict) or "effect" not in summary:
            raise DiagnoseError("no 'effect' in the summary; expected the summary.json of bearingheat diagnose")
        return cls(str(summary["effect"]), dict(summary.get("parameters") or {}), summary.get("domain"),
                   str(summary.get("base_model") or DEFAULT_MODEL))

    def describe(self) -> str:
        text = f"diagnose effect {self.effect} ({format_value(self.parameters)})" if self.parameters else \
            f"diagnose effect {self.effect}"
        if self.domain is None and self.effect != "none":
            text += " (its fitted domain is unknown: rows outside it are not flagged)"
        return text

    def apply(self, frame: pd.DataFrame, results: pd.DataFrame, model: str = DEFAULT_MODEL
              ) -> list[tuple[int, str, str]]:
        """Add the effect to MR and recompute NR for every row that is not in error (the candidate applies itself).

        Returns (row position, level, message) for calc to add: an error for each row whose friction model
        (its ``model`` cell, else ``model``) is not the one the effect was fitted on, a warning for each row and
        quantity outside the fitted domain.
        """
        refused = np.zeros(len(frame), dtype=bool)
        problems: list[tuple[int, str, str]] = []
        if self.effect != "none":
            names = row_model_names(frame.reset_index(drop=True), model)
            refused = (names != self.base_model) & ~failed_rows(results)
            problems = [(int(i), "error",
                         f"diagnose effect {self.effect} extends the {self.base_model} model it was fitted on, not "
                         f"the {names[i]} model of this row (compute the row with the {self.base_model} model, or "
                         "without the effect)") for i in np.flatnonzero(refused)]
        problems += CANDIDATES[self.effect].apply(frame, results, self.parameters, self.describe(), refused=refused,
                                                  domain=self.domain)
        return problems
