"""The checks every unit-aware function applies to its numbers after the unit conversion.

Error policy of the API: a given number that is NaN, infinite or outside
the valid range of its contract column raises (naming the argument and,
for arrays, the index); a number outside the plausible range is returned
as a warning message.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping

import numpy as np
import numpy.typing as npt
import pandas as pd

from bearingheat.calc.contract import column, input_units, inside_ranges, range_problems
from bearingheat.calc.messages import Labels
from bearingheat.errors import BearingheatError
from bearingheat.units import Magnitude, QuantityLike, magnitude

__all__ = ["point_warnings", "point_status", "where", "shared_index", "broadcast_shape", "dimensionless_number",
           "converted_model_inputs", "ARGUMENT_LABELS"]

#: calc's row messages in the API's words: an input by its argument's name, its value in catalogue units
#: ('Fr: 20000 is above the static load rating C0 = 7800 N', as 'nu: 0.5 is outside the plausible range ...')
ARGUMENT_LABELS = Labels({name: (name, 1.0) for name in input_units()})


def where(i: int, shape: tuple[int, ...]) -> str:
    """' (at index i)' for an array argument, '' for scalars."""
    return f" (at index {np.unravel_index(i, shape) if len(shape) > 1 else i})" if shape else ""


def dimensionless_number(value: object, name: str, error: type[BearingheatError]) -> Magnitude:
    """A dimensionless argument (a factor, a grade, an index) as a float or float array, a plain Series as it is
    (its index pairs it with the others): a Quantity or a pint-pandas Series is converted to 1 (50 % is 0.5, a
    unit of a dimension is refused), a number is taken as it is, and a cell that is no number raises ``error``
    naming the argument, the cell and, for arrays, its index.

    >>> from bearingheat.errors import HeatBalanceError
    >>> dimensionless_number([0.01, 0.02], "f2", HeatBalanceError)
    array([0.01, 0.02])
    >>> dimensionless_number([0.01, "low"], "f2", HeatBalanceError)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: f2: 'low' is not a number (at index 1)
    """
    if hasattr(value, "units") or (isinstance(value, pd.Series) and str(value.dtype).startswith("pint[")):
        return magnitude(value, "dimensionless", name)
    cells = value.to_numpy(dtype=object) if isinstance(value, pd.Series) else np.asarray(value, dtype=object)
    try:
        numbers = cells.astype(float)
    except (TypeError, ValueError):
        i = next(k for k, cell in enumerate(cells.ravel()) if not _is_number(cell))
        raise error(f"{name}: {cells.ravel()[i]!r} is not a number{where(i, cells.shape)}") from None
    if isinstance(value, pd.Series):
        return pd.Series(numbers, index=value.index)
    return numbers if numbers.ndim else float(numbers)


def converted_model_inputs(values: Mapping[str, QuantityLike | npt.ArrayLike | None], accepted: tuple[str, ...],
                           arguments: Mapping[str, str], function: str, error: type[BearingheatError]
                           ) -> dict[str, Magnitude | npt.ArrayLike | None]:
    """The ``model_inputs`` of ``function`` in catalogue units: a Quantity converted to the unit of its contract
    column, a dimensionless number checked (:func:`dimensionless_number`), text and None kept as they are.

    ``accepted`` are the columns the model reads, ``arguments`` the columns that ``function`` takes as arguments
    (column -> argument name). A name the model reads that is an argument is refused, naming the argument (in
    ``model_inputs`` it would give one input two values); so is a name the model does not read, naming the ones
    it reads. ``error`` is the error of ``function``.

    >>> from bearingheat.errors import HeatBalanceError
    >>> converted_model_inputs({"mu_sl": 0.05, "oil": "mineral"}, ("mu_sl", "oil", "T"), {"T": "T"}, "heat_balance",
    ...                        HeatBalanceError)
    {'mu_sl': 0.05, 'oil': 'mineral'}
    >>> converted_model_inputs({"T": 16.25}, ("mu_sl", "oil", "T"), {"T": "T"}, "heat_balance", HeatBalanceError)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: model_inputs: 'T' is an argument of heat_balance; give it as T=
    """
    out: dict[str, Magnitude | npt.ArrayLike | None] = {}
    for name, value in values.items():
        if name in arguments and name in accepted:
            raise error(f"model_inputs: {name!r} is an argument of {function}; give it as {arguments[name]}=")
        if name not in accepted:
            own = ", ".join(n for n in accepted if n not in arguments) or f"none besides the arguments of {function}"
            raise error(f"model_inputs: {name!r} is not an input of this model; it reads {own}")
        unit = column(name).unit
        if unit == "" or value is None:
            out[name] = value  # text: the model cleans it
        elif unit == "1":
            out[name] = dimensionless_number(value, name, error)
        else:
            out[name] = magnitude(value, unit, name)
    return out


def _is_number(value: object) -> bool:
    """Whether ``float(value)`` gives a number (a logical value does not count: True is no factor)."""
    if isinstance(value, (bool, np.bool_)):
        return False
    try:
        float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return False
    return True


def _describe(name: str, values: np.ndarray) -> Callable[[int], str]:
    """'name: value' of the point at a flat index, for the range messages."""
    return lambda i: f"{name}: {values[i]:g}"


def _range_warnings(name: str, values: float | np.ndarray, shape: tuple[int, ...], error: type[BearingheatError]
                    ) -> list[tuple[int, str]]:
    """Raise for a number that is NaN, infinite or outside its valid range; return the plausibility warnings as
    (flat index, message). A scalar argument is checked once, not once per point it is broadcast to."""
    scalar = np.ndim(values) == 0
    flat = np.asarray(values, dtype=float).reshape(1) if scalar or not shape else \
        np.broadcast_to(values, shape).ravel()
    if not flat.size:
        return []
    low, high = flat.min(), flat.max()  # NaN where any number is NaN (numpy's min and max carry it)
    if np.isnan(low) or np.isnan(high):
        i = int(np.flatnonzero(np.isnan(flat))[0])
        raise error(f"{name}: nan is not a number; leave the argument out where it is not known{where(i, shape)}")
    if inside_ranges(name, low, high):  # every point finite and inside: nothing to say
        return []
    errors, found = range_problems(name, flat, _describe(name, flat))
    if errors:
        i, message = errors[0]
        raise error(message + where(i, shape))
    return found


def point_warnings(arrays: Mapping[str, float | np.ndarray], shape: tuple[int, ...], error: type[BearingheatError]
                   ) -> tuple[list[str], dict[int, list[str]]]:
    """Raise for a given number that is NaN, infinite or outside its valid range; return the plausibility warnings of
    scalar arguments (every point's) and, for array arguments, those of the points that have them."""
    every: list[str] = []
    some: dict[int, list[str]] = {}
    for name, values in arrays.items():
        found = _range_warnings(name, values, shape, error)
        for i, message in found:
            if np.ndim(values) == 0:
                every.append(message)
            else:
                some.setdefault(i, []).append(message)
    return every, some


def point_status(size: int, every: list[str], some: dict[int, list[str]]) -> tuple[list[str], list[str]]:
    """Per-point 'ok' | 'warning' and messages joined by '; ': the ``every`` messages on each point, then a point's
    own; strings are built once for the common text and only for the points with their own messages."""
    common = "; ".join(every)
    status = ["warning" if every else "ok"] * size  # one string object shared by the points (list repetition)
    messages = [common] * size
    for i, own in some.items():
        status[i] = "warning"
        messages[i] = "; ".join(([common] if common else []) + own)
    return status, messages


def broadcast_shape(values: Mapping[str, float | np.ndarray], error: type[BearingheatError]) -> tuple[int, ...]:
    """The shape the arguments ``values`` (by name) broadcast to; ``error`` naming two that do not, with their
    shapes, rather than numpy's 'shape mismatch'.

    >>> from bearingheat.errors import HeatBalanceError
    >>> broadcast_shape({"n": np.ones(3), "Fr": 2.0}, HeatBalanceError)
    (3,)
    >>> broadcast_shape({"n": np.ones(2), "Fr": 2.0, "T_bearing": np.ones(3)}, HeatBalanceError)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: n has shape (2,) and T_bearing has shape (3,): arrays are paired value by value, so they need one shape (or give single values)
    """
    shapes = {name: np.shape(value) for name, value in values.items()}
    shape: tuple[int, ...] = ()
    for name, own in shapes.items():
        try:
            shape = np.broadcast_shapes(shape, own)
        except ValueError:
            other = next(n for n, s in shapes.items() if not _broadcast(s, own))
            raise error(f"{other} has shape {shapes[other]} and {name} has shape {own}: arrays are paired value by "
                        "value, so they need one shape (or give single values)") from None
    return shape


def _broadcast(a: tuple[int, ...], b: tuple[int, ...]) -> bool:
    try:
        np.broadcast_shapes(a, b)
    except ValueError:
        return False
    return True


def _labels(index: pd.Index) -> str:
    shown = ", ".join(map(repr, index[:3].tolist())) + (", ..." if len(index) > 3 else "")
    return f"{len(index)} rows: {shown}"


def shared_index(values: Mapping[str, object], error: type[BearingheatError]) -> pd.Index | None:
    """The one index of the Series among ``values`` (by argument name), None without a Series.

    Series are paired row by row, so they must have the same index (the same
    labels in the same order); others raise ``error`` naming two arguments,
    rather than pairing rows of different labels by position.

    >>> from bearingheat.errors import FrictionInputError
    >>> shared_index({"n": pd.Series([1.0, 2.0]), "Fr": 3.0}, FrictionInputError)
    RangeIndex(start=0, stop=2, step=1)
    >>> shared_index({"n": pd.Series([1.0, 2.0]), "Fr": pd.Series([3.0, 4.0], index=[1, 0])}, FrictionInputError)
    Traceback (most recent call last):
    ...
    bearingheat.errors.FrictionInputError: n and Fr are Series with different indexes (2 rows: 0, 1 against 2 rows: 1, 0); give them one index, e.g. Fr.reindex(n.index), or pass arrays
    """
    first: tuple[str, pd.Index] | None = None
    for name, value in values.items():
        if not isinstance(value, pd.Series):
            continue
        if first is None:
            first = (name, value.index)
        elif not value.index.equals(first[1]):
            raise error(f"{first[0]} and {name} are Series with different indexes ({_labels(first[1])} against "
                        f"{_labels(value.index)}); give them one index, e.g. {name}.reindex({first[0]}.index), or "
                        "pass arrays")
    return None if first is None else first[1]
