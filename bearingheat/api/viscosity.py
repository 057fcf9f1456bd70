"""Oil viscosity against temperature for Python callers: pint Quantities in, a Quantity in mm²/s out.

The formulas are :mod:`bearingheat.kernels.viscosity` (ASTM D341 Walther,
ISO 3448 grades, ASTM D2270 viscosity index).
"""
from __future__ import annotations

import warnings

import numpy as np

from bearingheat.catalogue.viscosity import iso_vg_grades
from bearingheat.errors import ViscosityError, ViscosityRangeWarning
from bearingheat.kernels.viscosity import (DEFAULT_VISCOSITY_INDEX, iso_vg_nu40, iso_vg_viscosity,
                                           viscosity_from_two_points, viscosity_range_messages)
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
        ``viscosity_index`` no oil of the grade reaches.
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
        nu = viscosity_from_two_points(magnitude(nu40, "mm^2/s", "nu40"), 40.0,
                                       magnitude(nu100, "mm^2/s", "nu100"), 100.0, theta)
    elif points is not None and not (given["nu40"] or given["nu100"] or given["iso_vg"]):
        (nu1, t1), (nu2, t2) = points
        nu = viscosity_from_two_points(magnitude(nu1, "mm^2/s", "points[0] viscosity"), celsius(t1, "points[0] temperature"),
                                       magnitude(nu2, "mm^2/s", "points[1] viscosity"), celsius(t2, "points[1] temperature"),
                                       theta)
    else:
        got = ", ".join(k for k, v in given.items() if v) or "nothing"
        if got in ("nu40", "nu100"):
            got += " only"
        raise ViscosityError(f"oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got {got})")
    pour = celsius(pour_point, "pour_point") if pour_point is not None else np.nan
    for message in np.ravel(viscosity_range_messages(nu, theta, pour)):
        if message:
            warnings.warn(message, ViscosityRangeWarning, stacklevel=2)
    return quantity(nu, "mm^2/s")
