"""Bearing data by designation for Python callers (Schaeffler HR 1, 2006).

:func:`bearing` returns the catalogue's :class:`~bearingheat.catalogue.bearings.BearingData`:
floats in catalogue units (mm, N, 1/min; NaN where the catalogue gives none), the ``source``
(catalogue, edition, page, row) and how the designation was matched. Its
:meth:`~bearingheat.catalogue.bearings.BearingData.quantities` gives the values as pint
Quantities. An unknown designation raises :class:`~bearingheat.errors.DesignationError`
naming close designations of the table.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from bearingheat.catalogue import bearings as catalogue_bearings
from bearingheat.catalogue.bearings import BearingData, bearing_table, designations
from bearingheat.errors import InputError
from bearingheat.units import QuantityLike, magnitude

__all__ = ["bearing", "BearingData", "bearing_table", "designations", "bearings_with_bore"]


def bearing(designation: str) -> BearingData:
    """The bearing ``designation`` (with or without cage and design suffixes) of the bearing table.

    The table holds 1277 bearings of the Schaeffler catalogue HR 1 "Rolling
    bearings" (edition June 2006): deep groove ball bearings 618, 619, 160,
    60, 62, 63, 64 (open, -2Z and, with contact seals, -2RSR) and 622, 623
    (-2RSR), angular contact ball bearings 70..-B, 72..-B and 73..-B (open
    and -2RS) and 718..-B, cylindrical roller bearings N, NU, NJ, NUP of
    series 2, 3, 22, 23 (E design), NU10..-M1 and NU19..-M1, and metric
    tapered roller bearings, 329 and the ISO 355 codes T7FC, T4CB, T2EE,
    T5ED among them. HR 1 gives no thermal reference speed n_thr for the
    sealed bearings nor for the 70..-B, 718..-B and NU19 bearings (NaN).
    The designation is
    matched in three steps, the first that finds it wins: ``exact`` (case,
    spaces and a suffix glued to the number do not matter), ``cage``
    (without cage, material, clearance and tolerance suffixes), ``design``
    (where no design suffix is given, also without the table's); see
    :mod:`bearingheat.catalogue.bearings`. Seal and shield suffixes are
    never dropped (``6208-2RS`` finds neither ``6208-2RSR`` nor ``6208``).

    Parameters
    ----------
    designation : str
        Designation as printed in the catalogue, with or without cage and
        design suffixes, e.g. ``"6208"``, ``"NU206-E"``, ``"30205-A"``,
        ``"nu 206 e tvp2"``.

    Returns
    -------
    BearingData
        The row in catalogue units (d, D, B, T [mm]; C, C0 [N]; e, Y, Y0 [1];
        n_G, n_thr [1/min]; NaN where the catalogue gives none), its
        ``source`` (catalogue, edition, page, row), the ``match`` step and a
        ``note`` on how it was matched. :meth:`BearingData.quantities` gives
        the values as pint Quantities.

    Raises
    ------
    bearingheat.errors.DesignationError
        For an empty designation; one that is not in the table (naming close
        designations of the table, and the bearing type or series the table
        does not hold); one that matches several bearings whose values
        differ (``7220-B``, ``32307``), listing them.

    Examples
    --------
    >>> b = bearing("NU206-E")
    >>> b.designation, b.match, b.d, b.D, b.B, b.C0, b.n_thr
    ('NU206-E-TVP2', 'cage', 30.0, 62.0, 16.0, 36000.0, 9800.0)
    >>> q = bearing("30205-A").quantities()
    >>> q["T"], q["Y"]
    (<Quantity(16.25, 'millimeter')>, <Quantity(1.6, 'dimensionless')>)
    >>> sealed = bearing("6205-2RSR")
    >>> sealed.C0, sealed.n_G, sealed.n_thr
    (7800.0, 9000.0, nan)
    >>> bearing("6205-2ZZ")
    Traceback (most recent call last):
    ...
    bearingheat.errors.DesignationError: designation: '6205-2ZZ' is not in the bearing table (Schaeffler HR 1, 2006); close matches: 6205-2Z, 6205-2RSR, 6205, 625-2Z, 6320-2Z
    """
    return catalogue_bearings.bearing(designation)


def bearings_with_bore(d: QuantityLike, *, D_max: QuantityLike | None = None, B_max: QuantityLike | None = None,
                       family: str | list[str] | None = None, shield: str | list[str] | None = None) -> pd.DataFrame:
    """The bearings of the bearing table that fit a shaft of diameter ``d``: the candidates for a support.

    Parameters
    ----------
    d : pint.Quantity
        Bore (the shaft seat), any length unit; matched to half the
        catalogue's printing step (0.005 mm: ``1.5748 * u.inch`` finds 40 mm).
    D_max, B_max : pint.Quantity, optional
        The largest outside diameter and width the housing takes (for a
        tapered roller bearing the width is its total width T).
    family : str or list of str, optional
        ``"deep groove ball"``, ``"angular contact ball"``,
        ``"cylindrical roller"``, ``"tapered roller"``; all when None.
    shield : str or list of str, optional
        ``"open"``, ``"2Z"``, ``"2RSR"``, ``"2RS"``; all when None.

    Returns
    -------
    pandas.DataFrame
        The rows of :func:`bearing_table` (catalogue units: mm, N, 1/min),
        in catalogue order. ``bh.calc`` computes them at an operating point
        from their designations (see the example).

    Raises
    ------
    bearingheat.errors.UnitError
        For a plain number or a unit that is no length.
    bearingheat.errors.DesignationError
        For an unknown family or shield, and when no bearing is left: the
        message names the nearest bores of the table, or the diameters,
        widths, families and shields the bore offers.

    Examples
    --------
    >>> import pint, bearingheat as bh
    >>> u = pint.get_application_registry()
    >>> found = bh.bearings_with_bore(40 * u.mm, D_max=80 * u.mm, family="deep groove ball", shield="open")
    >>> found["designation"].tolist()
    ['61908', '16008', '6008', '6208']
    >>> point = found[["designation"]].assign(lubrication="oil_bath", **{"n [rpm]": 6000, "Fr [kN]": 2.0,
    ...                                                                  "nu [mm^2/s]": 20.0})
    >>> print(bh.calc(point)[["designation", "MR [N*mm]", "n_thr [1/min]"]].round(1).to_string(index=False))
    designation  MR [N*mm]  n_thr [1/min]
          61908       86.8         9989.3
          16008       98.6         7825.9
           6008       96.5        10667.5
           6208      141.1         9325.1
    """
    limit = {name: math.inf if value is None else _one_length(value, name)
             for name, value in (("D_max", D_max), ("B_max", B_max))}
    return catalogue_bearings.bearings_with_bore(_one_length(d, "d"), families=family, shields=shield, **limit)


def _one_length(value: QuantityLike, name: str) -> float:
    """A scalar length Quantity in mm; :class:`InputError` for several values."""
    millimetres = np.asarray(magnitude(value, "mm", name), dtype=float)
    if millimetres.ndim != 0:
        raise InputError(f"{name}: give one length, e.g. 40 * u.mm; got {millimetres.size} values")
    return float(millimetres)
