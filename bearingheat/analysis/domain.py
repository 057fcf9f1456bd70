"""Where an effect of ``bearingheat diagnose`` was fitted, and the rows of ``calc --effects`` outside it.

A fitted effect is a least-squares fit on the measured rows: its parameters
say nothing of speeds, sizes, viscosities or loads the data did not reach
(a churning term fitted at n <= 5000 1/min grows as n^p beyond it). The
summary records the range of each quantity the effect's term depends on
(:attr:`bearingheat.analysis.effects.Candidate.domain`) and the base model
it extends; :func:`outside` gives calc a warning for each row and quantity
outside that range.

>>> domain = fitted_domain({"n": np.array([300.0, 5000.0])}, ("n",), ["6205"])
>>> domain
{'n [1/min]': [300.0, 5000.0], 'bearings': ['6205']}
>>> outside(domain, {"n": np.array([3000.0, 15000.0])}, np.array([0, 1]), "drag_losses")
[(1, 'warning', 'diagnose effect drag_losses: n = 15000 1/min is outside the range it was fitted on (300 to 5000 1/min): the effect is extrapolated there')]
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingheat.errors import DiagnoseError

__all__ = ["DOMAIN_UNITS", "domain_values", "fitted_domain", "read_domain", "outside"]

#: quantity an effect may depend on -> its catalogue unit (the keys of summary.json are 'name [unit]')
DOMAIN_UNITS = {"n": "1/min", "nu*n": "mm^2/s*1/min", "dM": "mm", "load": "N"}

#: a row within this relative margin of an end of the range counts as inside (the summary's numbers are rounded
#: by JSON only in the last digit)
_MARGIN = 1e-9


def domain_values(n: np.ndarray, nu: np.ndarray, dM: np.ndarray, load: np.ndarray) -> dict[str, np.ndarray]:
    """The quantities of :data:`DOMAIN_UNITS` of some rows, from their n, nu, dM and M1's load (catalogue units)."""
    return {"n": n, "nu*n": nu * n, "dM": dM, "load": load}


def _key(quantity: str) -> str:
    return f"{quantity} [{DOMAIN_UNITS[quantity]}]"


def fitted_domain(values: dict[str, np.ndarray], quantities: Sequence[str], bearings: Sequence[str]
                  ) -> dict[str, Any]:
    """The domain of summary.json: [min, max] of each quantity over the fitted rows (NaN ignored) and the
    bearings (designations, else 'type series dxD') the effect was fitted on."""
    domain: dict[str, Any] = {}
    for quantity in quantities:
        finite = np.asarray(values[quantity], dtype=float)
        finite = finite[np.isfinite(finite)]
        if len(finite):
            domain[_key(quantity)] = [float(np.min(finite)), float(np.max(finite))]
    domain["bearings"] = [str(b) for b in bearings]
    return domain


def read_domain(domain: Any) -> dict[str, Any]:
    """The domain of a summary.json, checked: ranges of known quantities as two finite numbers, low <= high."""
    if not isinstance(domain, dict):
        raise DiagnoseError(f"'domain' of the summary is {type(domain).__name__}, not a table of ranges")
    checked: dict[str, Any] = {}
    known = {_key(q): q for q in DOMAIN_UNITS}
    for key, value in domain.items():
        if key == "bearings":
            if not isinstance(value, list):
                raise DiagnoseError("'domain' of the summary: 'bearings' is no list of designations")
            checked[key] = [str(v) for v in value]
            continue
        if key not in known:
            raise DiagnoseError(f"'domain' of the summary: {key!r} is not one of {', '.join(known)}, bearings")
        ok = (isinstance(value, list) and len(value) == 2
              and all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in value))
        if not ok or value[0] > value[1]:
            raise DiagnoseError(f"'domain' of the summary: {key} is {value!r}; expected [low, high], two finite "
                                "numbers with low <= high")
        checked[key] = [float(value[0]), float(value[1])]
    return checked


def outside(domain: dict[str, Any], values: dict[str, np.ndarray], positions: np.ndarray, effect: str
            ) -> list[tuple[int, str, str]]:
    """(row position, 'warning', message) for each row of ``positions`` and quantity of ``domain`` whose value in
    ``values`` lies outside the fitted range (a NaN value is not judged)."""
    problems: list[tuple[int, str, str]] = []
    for quantity, unit in DOMAIN_UNITS.items():
        if _key(quantity) not in domain or quantity not in values:
            continue
        low, high = domain[_key(quantity)]
        column = np.asarray(values[quantity], dtype=float)[positions]
        slack = _MARGIN * max(abs(low), abs(high))
        beyond = (column < low - slack) | (column > high + slack)  # (NaN compares False: not judged)
        for i, value in zip(positions[beyond].tolist(), column[beyond].tolist()):  # texts for those rows only
            problems.append((int(i), "warning",
                             f"diagnose effect {effect}: {quantity} = {value:g} {unit} is outside the range it "
                             f"was fitted on ({low:g} to {high:g} {unit}): the effect is extrapolated there"))
    problems.sort(key=lambda problem: problem[0])  # row by row, each row's quantities in the order above
    return problems
