"""Oil viscosity against temperature for Python callers: pint Quantities in, a Quantity in mm²/s out.

The formulas are :mod:`bearingheat.kernels.viscosity` (ASTM D341 Walther,
ISO 3448 grades, ASTM D2270 viscosity index).
"""
from __future__ import annotations

import warnings
from collections.abc import Callable

import numpy as np

from bearingheat.catalogue.viscosity import iso_vg_grades
from bearingheat.errors import ViscosityError, ViscosityRangeWarning
from bearingheat.kernels.viscosity import (DEFAULT_VISCOSITY_INDEX, KELVIN_OFFSET, MIN_VISCOSITY, iso_vg_nu40,
                                           iso_vg_viscosity, viscosity_from_two_points, viscosity_range_messages)
from bearingheat.units import Quantity, celsius, magnitude, quantity

__all__ = ["oil_viscosity"]


def oil_viscosity(temperature: Quantity, *, nu40: Quantity | None = None, nu100: Quantity | None = None,
                  points: tuple[tuple[Quantity, Quantity], tuple[Quantity, Quantity]] | None = None,
                  iso_vg: float | None = None, viscosity_index: float = DEFAULT_VISCOSITY_INDEX,
                  pour_point: Quantity | None = None) -> Quantity:
    """Kinematic viscosity of an oil at ``temperature`` (pint Quantities in and out).

    The viscosity-temperature line of ASTM D341 (Walther),
    log10 log10(ν + 0.7) = A − B·log10 T, through two points; an ISO VG grade
    gives ν40 (the ISO 3448 mid-point) and ν100 from the viscosity index by
    ASTM D2270 (table 1, its formulas above ν100 = 70 mm²/s).

    Give exactly one of: ``nu40`` and ``nu100``; ``points`` = ((ν1, θ1),
    (ν2, θ2)) at any two temperatures; ``iso_vg`` (a grade number) with
    ``viscosity_index`` (default 95). Temperatures are absolute (degC, K,
    degF); the result is in mm²/s. Values outside ASTM D341 (ν < 2 mm²/s,
    or below ``pour_point``) emit a :class:`~bearingheat.errors.ViscosityRangeWarning`;
    data that fix no line raise :class:`~bearingheat.errors.ViscosityError`.

    Parameters
    ----------
    temperature : pint.Quantity [temperature]
        Absolute temperature(s) at which ν is wanted (a float or an array).
    nu40 : pint.Quantity [mm²/s], optional
        Kinematic viscosity at 40 °C, with ``nu100``.
    nu100 : pint.Quantity [mm²/s], optional
        Kinematic viscosity at 100 °C, with ``nu40``.
    points : tuple of two (pint.Quantity [mm²/s], pint.Quantity [temperature]), optional
        Two (viscosity, absolute temperature) pairs at any temperatures.
    iso_vg : float, optional
        ISO 3448 viscosity grade, one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68,
        100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200.
    viscosity_index : float, optional
        Viscosity index of the ``iso_vg`` oil (ASTM D2270); default 95, the
        mineral oil of the bearing catalogues' viscosity-temperature diagrams.
        It must be reachable by an oil of the grade with ν100 >= 2 mm²/s.
    pour_point : pint.Quantity [temperature], optional
        Pour point of the oil; below it the value is an extrapolation (a
        warning).

    Returns
    -------
    pint.Quantity [mm²/s]
        ν at ``temperature``, of its shape.

    Raises
    ------
    bearingheat.errors.ViscosityError
        When the data fix no line: not exactly one of nu40 with nu100,
        points, iso_vg; an ``iso_vg`` that is not an ISO 3448 grade; a
        ``viscosity_index`` no oil of the grade reaches; a viscosity below
        2 mm²/s (or not a number); two points at one temperature; a
        viscosity that rises with the temperature. Also for a temperature
        at or below absolute zero, or so far below the data that ν
        overflows.
    bearingheat.errors.UnitError
        For a plain number or a temperature difference where an absolute
        temperature is needed, or a unit of the wrong dimension.

    Warns
    -----
    bearingheat.errors.ViscosityRangeWarning
        Where ν < 2 mm²/s or the temperature is below ``pour_point``: the
        value is an extrapolation of ASTM D341.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> round(oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"), nu100=28 * u.cSt).magnitude, 2)
    132.13
    >>> points = ((68 * u("mm^2/s"), u.Quantity(40, "degC")), (14.85 * u("mm^2/s"), u.Quantity(80, "degC")))
    >>> round(oil_viscosity(u.Quantity(373.15, "K"), points=points).magnitude, 2)
    8.79
    >>> oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"))
    Traceback (most recent call last):
    ...
    bearingheat.errors.ViscosityError: oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got nu40 only)
    """
    given = {"nu40": nu40 is not None, "nu100": nu100 is not None, "points": points is not None,
             "iso_vg": iso_vg is not None}
    theta = celsius(temperature, "temperature")
    _first(np.asarray(theta, dtype=float) <= -KELVIN_OFFSET,
           lambda i, at: f"temperature: {np.ravel(theta)[i]:g} degC{at} is at or below absolute zero")
    if given["iso_vg"] and not (given["nu40"] or given["nu100"] or given["points"]):
        grade = np.asarray(getattr(iso_vg, "magnitude", iso_vg), dtype=float)
        unknown = np.ravel(grade)[np.isnan(np.ravel(iso_vg_nu40(grade)))]
        if unknown.size:
            raise ViscosityError(f"iso_vg: {unknown[0]:g} is not an ISO VG grade; expected one of "
                             f"{', '.join(str(g) for g in iso_vg_grades())}")
        VI = np.asarray(getattr(viscosity_index, "magnitude", viscosity_index), dtype=float)
        nu = iso_vg_viscosity(grade, theta, VI)
        if np.any(np.isnan(nu)):
            raise ViscosityError(f"viscosity_index: {float(np.ravel(VI)[0]):g} cannot be reached by an oil of "
                             "that grade with nu100 >= 2 mm^2/s (ASTM D2270)")
    elif given["nu40"] and given["nu100"] and not (given["points"] or given["iso_vg"]):
        line = _line("nu40 and nu100", ("nu40", magnitude(nu40, "mm^2/s", "nu40"), 40.0),
                     ("nu100", magnitude(nu100, "mm^2/s", "nu100"), 100.0))
        nu = viscosity_from_two_points(*line, theta)
    elif points is not None and not (given["nu40"] or given["nu100"] or given["iso_vg"]):
        (nu1, t1), (nu2, t2) = points
        line = _line("points", ("points[0] viscosity", magnitude(nu1, "mm^2/s", "points[0] viscosity"),
                      celsius(t1, "points[0] temperature")),
                     ("points[1] viscosity", magnitude(nu2, "mm^2/s", "points[1] viscosity"),
                      celsius(t2, "points[1] temperature")))
        nu = viscosity_from_two_points(*line, theta)
    else:
        got = ", ".join(k for k, v in given.items() if v) or "nothing"
        if got in ("nu40", "nu100"):
            got += " only"
        raise ViscosityError(f"oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got {got})")
    _check_result(nu, theta)
    pour = celsius(pour_point, "pour_point") if pour_point is not None else np.nan
    for message in np.ravel(viscosity_range_messages(nu, theta, pour)):
        if message:
            warnings.warn(message, ViscosityRangeWarning, stacklevel=2)
    return quantity(nu, "mm^2/s")


def _first(bad: np.ndarray, message: Callable[[int, str], str]) -> None:
    """Raise :class:`ViscosityError` with ``message(i, where)`` of the first point where ``bad`` holds."""
    flat = np.ravel(bad)
    if flat.any():
        i = int(np.flatnonzero(flat)[0])
        raise ViscosityError(message(i, f" (at index {i})" if np.ndim(bad) else ""))


def _line(pair: str, first: tuple[str, object, object], second: tuple[str, object, object]) -> tuple:
    """(ν1, θ1, ν2, θ2) of two points (``pair`` names them in messages) that fix a Walther line, or
    :class:`ViscosityError`: each ν finite and >= 2 mm²/s (ASTM D341 without its correction terms), two
    temperatures, and ν falling as θ rises."""
    (name1, nu1, t1), (name2, nu2, t2) = first, second
    nu1, t1, nu2, t2 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (nu1, t1, nu2, t2)))
    for name, nu in ((name1, nu1), (name2, nu2)):
        _first(~(nu >= MIN_VISCOSITY),
               lambda i, at: f"{name}: {np.ravel(nu)[i]:g} mm^2/s{at} must be >= 2 (ASTM D341)")
    _first(t1 == t2, lambda i, at: f"{pair}: both at {np.ravel(t1)[i]:g} degC{at}; two temperatures fix the line")
    _first((nu1 - nu2) * (t1 - t2) >= 0,
           lambda i, at: f"{pair}: the viscosity must fall as the temperature rises ({np.ravel(nu1)[i]:g} "
                         f"mm^2/s at {np.ravel(t1)[i]:g} degC, {np.ravel(nu2)[i]:g} mm^2/s at "
                         f"{np.ravel(t2)[i]:g} degC){at}")
    return nu1, t1, nu2, t2


def _check_result(nu: np.ndarray | float, theta: np.ndarray | float) -> None:
    """A viscosity the line gives as infinite or NaN (a temperature far below the oil's data) is refused."""
    _first(~np.isfinite(np.broadcast_to(nu, np.shape(theta)) if np.ndim(theta) else nu),
           lambda i, at: f"temperature: {np.ravel(theta)[i]:g} degC{at} is so far below the oil's data that its "
                         "viscosity line overflows (ASTM D341 holds down to about the pour point)")
