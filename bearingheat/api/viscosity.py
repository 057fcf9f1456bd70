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
from bearingheat.units import celsius, magnitude, quantity

__all__ = ["oil_viscosity"]


def oil_viscosity(temperature, *, nu40=None, nu100=None, points=None, iso_vg=None,
                  viscosity_index=DEFAULT_VISCOSITY_INDEX, pour_point=None):
    """Kinematic viscosity of an oil at ``temperature`` (pint Quantities in and out).

    Give exactly one of: ``nu40`` and ``nu100``; ``points`` = ((ν1, θ1),
    (ν2, θ2)) at any two temperatures; ``iso_vg`` (a grade number) with
    ``viscosity_index`` (default 95). Temperatures are absolute (degC, K,
    degF); the result is in mm²/s. Values outside ASTM D341 (ν < 2 mm²/s,
    or below ``pour_point``) raise a :class:`~bearingheat.errors.ViscosityRangeWarning`;
    data that fix no line raise :class:`~bearingheat.errors.ViscosityError`.

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
        grade = np.asarray(iso_vg.magnitude if hasattr(iso_vg, "magnitude") else iso_vg, dtype=float)
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
    elif given["points"] and not (given["nu40"] or given["nu100"] or given["iso_vg"]):
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
