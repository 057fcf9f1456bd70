"""The checks every unit-aware function applies to its numbers after the unit conversion.

Error policy of the API: a given number that is NaN, infinite or outside
the valid range of its contract column raises (naming the argument and,
for arrays, the index); a number outside the plausible range is returned
as a warning message.
"""
from __future__ import annotations

import numpy as np

from bearingheat.calc.contract import range_problems
from bearingheat.errors import BearingheatError

__all__ = ["check_ranges", "point_warnings", "where"]


def where(i: int, shape: tuple) -> str:
    """' (at index i)' for an array argument, '' for scalars."""
    return f" (at index {np.unravel_index(i, shape) if len(shape) > 1 else i})" if shape else ""


def check_ranges(arrays: dict[str, np.ndarray], shape: tuple, error: type[BearingheatError]) -> list[str]:
    """Raise for a given number that is NaN, infinite or outside its valid range; return the plausibility warnings."""
    warnings = []
    for name, values in arrays.items():
        flat = np.broadcast_to(values, shape).ravel() if shape else np.asarray(values, dtype=float).reshape(1)
        if np.isnan(flat).any():
            i = int(np.flatnonzero(np.isnan(flat))[0])
            raise error(f"{name}: nan is not a number; leave the argument out where it is not known"
                        f"{where(i, shape)}")
        errors, found = range_problems(name, flat, lambda i, v=flat, n=name: f"{n}: {v[i]:g}")
        if errors:
            i, message = errors[0]
            raise error(message + where(i, shape))
        warnings += [message + where(i, shape) for i, message in found[:1]]
    return warnings


def point_warnings(arrays: dict[str, np.ndarray], shape: tuple, error: type[BearingheatError]) -> list[list[str]]:
    """:func:`check_ranges` per operating point: raise for unusable numbers, and return each point's plausibility
    warnings (a list per point of the flattened broadcast shape)."""
    size = int(np.prod(shape)) if shape else 1
    out: list[list[str]] = [[] for _ in range(size)]
    check_ranges(arrays, shape, error)  # the refusals
    for name, values in arrays.items():
        flat = np.broadcast_to(values, shape).ravel() if shape else np.asarray(values, dtype=float).reshape(1)
        _, found = range_problems(name, flat, lambda i, v=flat, n=name: f"{n}: {v[i]:g}")
        for i, message in found:
            if np.ndim(values) == 0:  # one value for every point
                for point in out:
                    point.append(message)
                break
            out[i].append(message)
    return out
