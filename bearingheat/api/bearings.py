"""Bearing data by designation for Python callers (Schaeffler HR 1, 2006).

:func:`bearing` returns the catalogue's :class:`~bearingheat.catalogue.bearings.BearingData`:
floats in catalogue units (mm, N, 1/min; NaN where the catalogue gives none), the ``source``
(catalogue, edition, page, row) and how the designation was matched. Its
:meth:`~bearingheat.catalogue.bearings.BearingData.quantities` gives the values as pint
Quantities. An unknown designation raises :class:`~bearingheat.errors.DesignationError`
naming close designations of the table.
"""
from __future__ import annotations

from bearingheat.catalogue import bearings as catalogue_bearings
from bearingheat.catalogue.bearings import BearingData, bearing_table, designations

__all__ = ["bearing", "BearingData", "bearing_table", "designations"]


def bearing(designation: str) -> BearingData:
    """The bearing ``designation`` (with or without cage and design suffixes) of the bearing table.

    >>> b = bearing("NU206-E")
    >>> b.designation, b.match, b.d, b.D, b.B, b.C0, b.n_thr
    ('NU206-E-TVP2', 'cage', 30.0, 62.0, 16.0, 36000.0, 9800.0)
    >>> q = bearing("30205-A").quantities()
    >>> q["T"], q["Y"]
    (<Quantity(16.25, 'millimeter')>, <Quantity(1.6, 'dimensionless')>)
    >>> bearing("6205-2ZZ")
    Traceback (most recent call last):
    ...
    bearingheat.errors.DesignationError: designation: '6205-2ZZ' is not in the bearing table (Schaeffler HR 1, 2006); close matches: 6205-2Z, 6205, 625-2Z, 6320-2Z, 6305-2Z
    """
    return catalogue_bearings.bearing(designation)
