"""The unit boundary: pint Quantities in, catalogue-unit magnitudes out.

Kernels work in catalogue units (mm, N, 1/min, mm²/s, °C, N·mm, W). Public
functions call :func:`magnitude` once per argument and :func:`quantity` once
per result. The registry is looked up at call time with
``pint.get_application_registry()`` and is never modified, so a caller who
sets their own application registry gets Quantities of that registry back.

Shaft speed is revolutions per time: 50 Hz is 3000 1/min, 1 rpm is 1 1/min,
and an angular speed in rad/s is divided by 2π (see :func:`speed_rpm`).
"""
from __future__ import annotations

import functools
import math
import pickle
import re
import threading
from typing import Any, TypeAlias, Union, overload

import numpy as np
import pandas as pd
import pint
import platformdirs  # where pint keeps its ':auto:' disk cache (pint's own choice)
from bearingheat.errors import UnitError

__all__ = [
    "Quantity",
    "QuantityLike",
    "Magnitude",
    "ureg",
    "UnitError",
    "magnitude",
    "quantity",
    "speed_rpm",
    "parse_unit",
    "normalise_unit_text",
    "parse_quantity",
    "convert_column",
    "celsius",
    "quantity_parts",
    "use_definition_cache",
]

TWO_PI = 2.0 * math.pi

#: A pint Quantity, scalar or array magnitude (the type of the unit-aware API's arguments and results).
Quantity: TypeAlias = pint.Quantity
#: A Quantity or a pint-pandas Series (dtype ``pint[unit]``): what :func:`magnitude` converts.
QuantityLike: TypeAlias = Union[pint.Quantity, pd.Series]
#: Numbers in catalogue units: a float for a scalar, a float array, a float Series for a pint-pandas Series.
Magnitude: TypeAlias = Union[float, np.ndarray, pd.Series]

_LOADING = threading.Lock()
_LOADED: set[int] = set()


def ureg() -> pint.UnitRegistry:
    """The application registry, looked up at call time (never cached).

    pint loads its definitions at the registry's first use; threads that
    first use it at the same moment (a Dask worker's threads) can see it half
    loaded ("'mm' is not defined"), so the first call of each registry loads
    it under a lock.
    """
    registry = pint.get_application_registry()
    if id(registry) not in _LOADED:
        with _LOADING:
            registry.parse_units("mm")  # loads the definitions once
            _LOADED.add(id(registry))
    return registry


def use_definition_cache() -> bool:
    """Let the application registry keep pint's parsed unit definitions in the user's cache folder.

    For a process bearingheat owns (the ``bearingheat`` program), never for a
    library call: pint parses its definitions file at each start (0.3-0.4 s
    here); with ``cache_folder=":auto:"`` (pint's own disk cache, in the
    user's cache folder) it reads them back in about 0.05 s. Changes nothing
    where the application registry was set by someone else or is already in
    use. Returns whether the cached registry is now the application registry.

    pint writes a cache file in place, so a run killed while it wrote leaves
    a file cut short, on which pint fails at every later start. Such files
    (those that no longer unpickle) are removed and the cache is built once
    more; if that fails too, the default registry stays (a slower start).
    """
    if not isinstance(pint.get_application_registry().get(), pint.registry.LazyRegistry):
        return False  # set by the caller, or already loaded: Quantities of it may exist
    for attempt in range(2):
        try:
            registry: pint.UnitRegistry = pint.UnitRegistry(cache_folder=":auto:")
        except Exception:  # a damaged or unreadable cache: only the start is slower, so the default registry stays
            if attempt or not _remove_unreadable_cache_files():
                return False
        else:
            pint.set_application_registry(registry)
            return True
    return False


def _remove_unreadable_cache_files() -> bool:
    """Remove the files of pint's disk cache (its ``:auto:`` folder, ``<user cache>/pint``) that do not unpickle;
    whether any was removed. Readable files, those of other definitions among them, stay."""
    removed = False
    for path in platformdirs.user_cache_path(appname="pint", appauthor=False).glob("*.pickle"):
        try:
            with path.open("rb") as file:
                pickle.load(file)
        except OSError:
            continue  # unreadable to this user: not a file cut short, and maybe not this user's to remove
        except Exception:  # cut short or garbled: pint would fail on it at every start
            try:
                path.unlink()
                removed = True
            except OSError:
                continue
    return removed


# Spellings found in engineers' sheets that pint does not read, or reads as
# something else ('U' is the unified atomic mass unit to pint).
_UNIT_ALIASES = {
    "u/min": "1/min",
    "1/min": "1/min",
    "min^-1": "1/min",
    "min-1": "1/min",
    "min⁻¹": "1/min",
    "rev/min": "rpm",
    "r/min": "rpm",
    "mm²/s": "mm^2/s",
    "mm2/s": "mm^2/s",
    "°c": "degC",
    "c": "degC",
    "deg c": "degC",
    "nmm": "N*mm",
    "n.mm": "N*mm",
    "n·mm": "N*mm",
    "nm": "N*m",
    "n·m": "N*m",
    "-": "dimensionless",
    "": "dimensionless",
    "1": "dimensionless",
}


def normalise_unit_text(text: str) -> str:
    """Map the unit spellings of engineers' sheets onto pint syntax.

    >>> normalise_unit_text(' U/min ')
    '1/min'
    >>> normalise_unit_text('kN')
    'kN'
    """
    cleaned = str(text).strip()
    alias = _UNIT_ALIASES.get(cleaned.lower())
    if alias is not None:
        return alias
    return cleaned.replace("·", "*").replace("²", "^2").replace("³", "^3").replace("°C", "degC")


def parse_unit(text: str, *, name: str = "value") -> pint.Unit:
    """Parse a unit string as typed in a header or a units row.

    Raises :class:`UnitError` naming the column when pint cannot read it.
    """
    spelled = normalise_unit_text(text)
    try:
        return ureg().parse_units(spelled)
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError, AttributeError,
            TypeError, ValueError, AssertionError) as exc:
        raise UnitError(f"{name}: unknown unit {text!r}") from exc


def _is_pint_series(value: Any) -> bool:
    return isinstance(value, pd.Series) and str(value.dtype).startswith("pint[")


def _as_quantity(value: Any, name: str, expected: str) -> tuple[Quantity, pd.Index | None]:
    """Return (Quantity, index) for a Quantity or a pint-pandas Series."""
    if _is_pint_series(value):
        return value.pint.quantity, value.index
    if isinstance(value, pint.Quantity):
        return value, None
    kind = type(value).__name__
    raise UnitError(
        f"{name}: expected a pint Quantity in {expected} (for example 2.5 * ureg('{expected}')); "
        f"got a plain {kind} {_short(value)}"
    )


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _describe(q: Quantity) -> str:
    """'3 meter / second' for a scalar, 'values in meter / second' for an array."""
    if np.ndim(q.magnitude) == 0:
        return f"{float(q.magnitude):g} {q.units}"
    return f"values in {q.units}"


def _restore_index(mag: float | np.ndarray, index: pd.Index | None) -> Magnitude:
    if index is None:
        return mag
    return pd.Series(np.asarray(mag, dtype=float), index=index)


@overload
def magnitude(value: pd.Series, unit: str, name: str) -> pd.Series: ...


@overload
def magnitude(value: Quantity, unit: str, name: str) -> float | np.ndarray: ...


@overload
def magnitude(value: object, unit: str, name: str) -> Magnitude: ...


def magnitude(value: Any, unit: str, name: str) -> Magnitude:
    """Convert a Quantity to ``unit`` and return its magnitude.

    ``value`` is a pint Quantity (scalar or ndarray) or a pint-pandas Series;
    a pint-pandas Series comes back as a float Series with its index.

    >>> u = ureg()
    >>> magnitude(2.5 * u.kN, "N", "Fr")
    2500.0
    >>> magnitude(u.Quantity(553.15, "K"), "degC", "T")
    280.0
    >>> magnitude(2 * u.kg, "N", "Fr")
    Traceback (most recent call last):
    ...
    bearingheat.errors.UnitError: Fr: 2 kilogram is a mass, not a force; for kilogram-force write 2 kgf
    """
    if unit == "1/min":
        return speed_rpm(value, name)
    q, index = _as_quantity(value, name, unit)
    target = _units(unit)
    try:
        # one scalar factor, one pass over an array; an offset unit on either side (K to degC) is no factor
        if q._is_multiplicative and _multiplicative(q._REGISTRY, unit):
            return _restore_index(_scaled(q.magnitude, _factor(q._REGISTRY, q.units._units, unit)), index)
        converted = q.to(target)
    except pint.errors.DimensionalityError as exc:
        if q.dimensionality == ureg().kg.dimensionality and target.dimensionality == ureg().N.dimensionality:
            if np.ndim(q.magnitude) == 0:
                raise UnitError(f"{name}: {_describe(q)} is a mass, not a force; "
                                f"for kilogram-force write {float(q.magnitude):g} kgf") from exc
            raise UnitError(f"{name}: {_describe(q)} are masses, not forces; for kilogram-force use kgf") from exc
        raise UnitError(
            f"{name}: {_describe(q)} cannot be converted to {unit} "
            f"(dimension {q.dimensionality}, expected {target.dimensionality})"
        ) from exc
    return _restore_index(_plain(converted.magnitude), index)


def _scaled(mag: Any, factor: float) -> float | np.ndarray:
    """mag·factor as float, without a copy when the factor is exactly 1."""
    if factor == 1.0:
        return _plain(mag)
    return _plain(np.multiply(mag, factor))


def _plain(mag: Any) -> float | np.ndarray:
    if isinstance(mag, np.ndarray):
        return np.asarray(mag, dtype=float) if mag.ndim else float(mag)  # no copy of a float array
    return float(mag)


@overload
def speed_rpm(value: pd.Series, name: str = ...) -> pd.Series: ...


@overload
def speed_rpm(value: Quantity, name: str = ...) -> float | np.ndarray: ...


@overload
def speed_rpm(value: object, name: str = ...) -> Magnitude: ...


def speed_rpm(value: Any, name: str = "n") -> Magnitude:
    """Shaft speed in revolutions per minute.

    Revolutions per time convert directly (50 Hz = 3000 1/min, rpm = 1/min);
    an angular speed (rad/s, deg/s) is divided by 2π per revolution.

    >>> u = ureg()
    >>> speed_rpm(50 * u.Hz)
    3000.0
    >>> round(speed_rpm(100 * u('rad/s')), 6)
    954.929659
    >>> speed_rpm(3000 * u.rpm)
    3000.0
    """
    q, index = _as_quantity(value, name, "1/min")
    factor = _rpm_factor(q._REGISTRY, q.units._units)
    if factor is None:
        raise UnitError(
            f"{name}: {_describe(q)} is not a shaft speed; expected revolutions per time "
            "(1/min, rpm, Hz) or an angular speed (rad/s)"
        )
    return _restore_index(_scaled(q.magnitude, factor), index)


@functools.lru_cache(maxsize=256)
def _rpm_factor(registry: Any, units: Any) -> float | None:
    """Revolutions per minute per one of ``units`` (a unit container of ``registry``; None where they are no
    shaft speed), once per unit: pint's conversion takes tens of microseconds a call. The registry is part of
    the key: pint refuses to compare units of two registries."""
    root = registry.Quantity(1.0, units).to_root_units()
    dims = dict(root._units)
    radians = dims.pop("radian", 0)
    if dims != {"second": -1} or radians not in (0, 1):
        return None
    per_second = float(root.magnitude)
    if radians == 1:
        per_second /= TWO_PI  # rad/s -> rev/s
    factor = per_second * 60.0
    return 1.0 if abs(factor - 1.0) < 1e-15 else factor  # 1/min and rpm: exactly one revolution per minute


@functools.lru_cache(maxsize=256)
def _multiplicative(registry: Any, unit: str) -> bool:
    """Whether ``unit`` converts by a factor alone (not degC or degF, which have an offset), once per unit."""
    return bool(registry.Quantity(1.0, unit)._is_multiplicative)


@functools.lru_cache(maxsize=256)
def _factor(registry: Any, units: Any, unit: str) -> float:
    """``unit`` per one of the multiplicative ``units`` (a unit container of ``registry``), once per pair (pint
    raises DimensionalityError for units of another dimension; errors are not cached)."""
    return float(registry.Quantity(1.0, units).to(unit).magnitude)


def _units(unit: str) -> Any:
    """The parsed ``unit`` of the application registry, parsed once per registry behind it (parsing a unit
    string takes pint tens of microseconds)."""
    return _parsed_units(pint.get_application_registry().get(), unit)


@functools.lru_cache(maxsize=256)
def _parsed_units(registry: Any, unit: str) -> Any:
    ureg()  # the definitions loaded under the lock
    return registry.parse_units(unit)


@overload
def quantity(mag: pd.Series, unit: str) -> pd.Series: ...


@overload
def quantity(mag: float | np.ndarray, unit: str) -> Quantity: ...


def quantity(mag: float | np.ndarray | pd.Series, unit: str) -> Quantity | pd.Series:
    """Wrap a kernel result in a Quantity of the application registry.

    A Series result becomes a pint-pandas Series when pint-pandas is
    installed, otherwise it stays a float Series and the unit is put in its
    ``attrs['unit']``.
    """
    u = ureg()
    if isinstance(mag, pd.Series):
        try:
            import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
        except ImportError:
            out = mag.astype(float)
            out.attrs["unit"] = unit
            return out
        return mag.astype(f"pint[{unit}]")  # type: ignore[call-overload]  # pint-pandas dtype by name
    if unit == "degC":
        return u.Quantity(mag, u.degC)
    return u.Quantity(mag, _units(unit))


def parse_quantity(text: str, *, name: str = "value", example: str | None = None) -> Quantity:
    """Parse a command-line value with its unit, e.g. ``'2mm'``, ``'2.6kg*m^2'``, ``'3000rpm'``; ``example`` is a
    unit of the option's kind, shown where the unit is missing.

    >>> parse_quantity('2.6kg*m^2', name='--I').to('kg*m^2').magnitude
    2.6
    >>> parse_quantity('3000', name='--n', example='rpm')
    Traceback (most recent call last):
    ...
    bearingheat.errors.UnitError: --n: '3000' has no unit; write it with one, e.g. 3000rpm
    """
    raw = str(text).strip()
    match = re.match(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)$", raw)
    if not match:
        raise UnitError(f"{name}: {text!r} is not a number with a unit")
    number, unit_text = match.groups()
    if not unit_text:
        hint = f"e.g. {number}{example}" if example else "e.g. 12mm, 2kN, 3000rpm, 150degC"
        raise UnitError(f"{name}: {text!r} has no unit; write it with one, {hint}")
    unit = parse_unit(unit_text, name=name)
    return ureg().Quantity(float(number), unit)


def convert_column(numbers: np.ndarray, unit_text: str | None, target: str, *, name: str,
                   header: str | None = None, copy: bool = True) -> tuple[np.ndarray, float]:
    """Numbers of a column headed ``name [unit_text]`` in the catalogue unit ``target``.

    The one converter of header units (calc tables, workbooks, measured
    data, lab readings, catalogue lists). Returns ``(values, factor)``:
    ``factor`` is catalogue units per header unit (one multiplication over
    the column), NaN for an absolute temperature (an offset conversion of
    the whole column). ``target`` ``'1'`` is a dimensionless number and
    ``'1/min'`` a shaft speed (revolutions per time; rad/s divided by 2π).
    The values are ``numbers`` themselves for a dimensionless column, and
    for the catalogue unit where ``copy`` is false; else a new array.
    Raises :class:`UnitError` saying what is wrong with the unit; callers
    prefix the column.

    >>> import numpy as np
    >>> convert_column(np.array([2.0, 3.5]), "kN", "N", name="Fr")
    (array([2000., 3500.]), 1000.0)
    >>> convert_column(np.array([50.0]), "Hz", "1/min", name="n")
    (array([3000.]), 60.0)
    >>> convert_column(np.array([20.0]), "degC", "delta_degC", name="dT_oil")
    Traceback (most recent call last):
    ...
    bearingheat.errors.UnitError: unit degC cannot be converted to delta_degC
    >>> convert_column(np.array([5.0]), "kg", "N", name="Fr")
    Traceback (most recent call last):
    ...
    bearingheat.errors.UnitError: kilogram is a mass, not a force; for kilogram-force write kgf
    """
    header = header or (f"{name} [{unit_text}]" if unit_text else name)
    numbers = np.asarray(numbers, dtype=float)
    if target == "1" and (unit_text is None or unit_text.strip() in ("", "-", "1")):
        return numbers, 1.0
    factor = _column_factor(unit_text, target, name, header)
    if math.isnan(factor):  # an absolute temperature (K, degC, degF): offset conversion of the whole column
        unit = parse_unit(str(unit_text), name=header)
        return np.asarray(ureg().Quantity(numbers, unit).to(target).magnitude, dtype=float), math.nan
    if factor == 1.0 and not copy:  # the catalogue unit itself: no pass over the column
        return numbers, factor
    return numbers * factor, factor


@functools.lru_cache(maxsize=1024)
def _column_factor(unit_text: str | None, target: str, name: str, header: str) -> float:
    """Catalogue units per header unit of :func:`convert_column` (NaN: an offset conversion), once per header:
    calc reads a big table in blocks, and pint's parse takes milliseconds. Errors are not cached."""
    if target == "1":
        one = ureg().Quantity(1.0, parse_unit(str(unit_text), name=header))
        if not one.dimensionless:
            raise UnitError(f"{name} is dimensionless, {unit_text!r} is not")
        return float(one.to("dimensionless").magnitude)
    if unit_text is None or unit_text.strip() in ("", "-"):
        raise UnitError(f"needs a unit, e.g. '{name} [{target}]'")
    unit = parse_unit(unit_text, name=header)
    if target == "1/min":
        try:
            return float(speed_rpm(ureg().Quantity(1.0, unit), header))
        except UnitError as exc:
            raise UnitError(f"{unit_text} is not a shaft speed; expected revolutions per time "
                            "(1/min, rpm, Hz) or an angular speed (rad/s)") from exc
    one = ureg().Quantity(1.0, unit)
    try:
        if one._is_multiplicative and ureg().Quantity(1.0, target)._is_multiplicative:
            return float(one.to(target).magnitude)
        ureg().Quantity(np.zeros(1), unit).to(target)  # an absolute temperature: the offset conversion must work
        return math.nan
    except (pint.errors.DimensionalityError, pint.errors.OffsetUnitCalculusError) as exc:
        if one.dimensionality == ureg().kg.dimensionality and target == "N":
            raise UnitError(f"{one.units} is a mass, not a force; for kilogram-force write kgf") from exc
        raise UnitError(f"unit {unit_text} cannot be converted to {target}") from exc


@overload
def celsius(value: Quantity, name: str) -> float | np.ndarray: ...


@overload
def celsius(value: object, name: str) -> Magnitude: ...


def celsius(value: Any, name: str) -> Magnitude:
    """An absolute temperature Quantity as a magnitude in °C (degC, K, degF); a temperature difference is refused.

    Scalars come back as float, arrays as float arrays.

    >>> u = ureg()
    >>> celsius(u.Quantity(293.15, "K"), "T_ambient")
    20.0
    >>> celsius(u.Quantity(10, "delta_degC"), "T_ambient")
    Traceback (most recent call last):
    ...
    bearingheat.errors.UnitError: T_ambient: 10 delta_degree_Celsius is a temperature difference; give an absolute temperature (degC, K)
    """
    if not hasattr(value, "to") or not hasattr(value, "units"):
        raise UnitError(f"{name}: expected a temperature Quantity, e.g. Quantity(60, 'degC'); got {value!r}")
    u = ureg()
    if value.units in (u.delta_degC, u.delta_degF):
        raise UnitError(f"{name}: {value} is a temperature difference; give an absolute temperature (degC, K)")
    try:
        mag = value.to(u.degC).magnitude
    except Exception as exc:  # pint raises DimensionalityError / OffsetUnitCalculusError
        raise UnitError(f"{name}: {value} is not a temperature (degC, K, degF)") from exc
    if isinstance(mag, pd.Series):
        return mag.astype(float)
    return np.asarray(mag, dtype=float) if np.ndim(mag) else float(mag)


def quantity_parts(value: Any) -> tuple[np.ndarray, str]:
    """(magnitudes as a flat float array, unit text) of a Quantity, pint-pandas Series or plain number ('' unit).

    >>> quantity_parts(ureg().Quantity([1.0, 2.0], "W"))
    (array([1., 2.]), 'W')
    >>> quantity_parts(3.5)
    (array([3.5]), '')
    """
    if _is_pint_series(value):
        value = value.pint.quantity
    if isinstance(value, pint.Quantity):
        return np.ravel(np.asarray(value.magnitude, dtype=float)), f"{value.units:~C}".replace("·", "*")
    if isinstance(value, pd.Series):
        return value.to_numpy(dtype=float).ravel(), ""
    return np.ravel(np.asarray(value, dtype=float)), ""
