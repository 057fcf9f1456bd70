"""Static load factors X0, Y0 of single-row angular contact ball bearings against the contact angle.

``tables/static_load_factors.csv`` holds the DP11A manual (SSAU lab manual,
2016), table 1: α = 18°, 20°, 26°, 30°, 36° with X0 = 0.5 and Y0 = 0.43,
0.42, 0.37, 0.33, 0.28; and Schaeffler HR 1 (June 2006), p. 237, for the
40° of its 70..-B, 718..-B, 72..-B and 73..-B bearings: P0 = 0.5·F0r +
0.26·F0a for a single bearing (X0 = 0.5, Y0 = 0.26). Between the rows the
factors are interpolated linearly in α; outside 18°–40° they are refused,
never extrapolated.

Floats, lists, numpy arrays or pandas Series of α [deg] in; a Series in gives
a Series out with its index. NaN gives NaN. An angle outside the table raises
:class:`~bearingheat.errors.ContactInputError` naming the value and, for an
array or Series, its element or row.
"""
from __future__ import annotations

import functools

import numpy as np
import pandas as pd

from bearingheat.catalogue.tables import load_table
from bearingheat.errors import ContactInputError

__all__ = ["TABLE_SOURCES", "static_load_factor_angles", "y0_for_contact_angle", "x0_for_contact_angle"]

#: where the angular contact rows of the static load factors come from, as messages name them
TABLE_SOURCES = "the DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, 40 deg"

_TABLE = "static_load_factors"
_TYPE = "angular_contact_ball"


@functools.lru_cache(maxsize=None)
def _angular_contact_factors() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Contact angles [deg], X0 and Y0 of the angular contact rows of the table, by angle (read-only)."""
    table = load_table(_TABLE)
    rows = table[table["bearing_type"] == _TYPE].sort_values("contact_angle")
    columns = (rows["contact_angle"].to_numpy(float), rows["X0"].to_numpy(float), rows["Y0"].to_numpy(float))
    for column in columns:
        column.setflags(write=False)
    return columns


def static_load_factor_angles() -> tuple[float, float]:
    """The range (lowest, highest) of contact angles [deg] that the table covers (:data:`TABLE_SOURCES`).

    >>> static_load_factor_angles()
    (18.0, 40.0)
    """
    angles = _angular_contact_factors()[0]
    return float(angles[0]), float(angles[-1])


def _interpolate_factor(alpha, column: int, name: str):
    angles = _angular_contact_factors()[0]
    values = _angular_contact_factors()[column]
    index = alpha.index if isinstance(alpha, pd.Series) else None
    alpha = np.asarray(alpha, dtype=float)
    lo, hi = angles[0], angles[-1]
    bad = (alpha < lo) | (alpha > hi)  # NaN never counts as bad
    if bad.any():
        flat = int(np.flatnonzero(bad.ravel())[0])
        message = (f"alpha = {alpha.ravel()[flat]:g} deg is outside the contact angles of the static load factors "
                   f"({lo:g} to {hi:g} deg: {TABLE_SOURCES}); {name} is not extrapolated")
        if bad.ndim == 0:
            raise ContactInputError(message)
        if index is not None:
            row = index[flat]
            raise ContactInputError(f"{message} (row {row})", row)
        position = np.unravel_index(flat, bad.shape)
        row = position[0] if len(position) == 1 else tuple(int(p) for p in position)
        raise ContactInputError(f"{message} (element {row})", row)
    result = np.asarray(np.interp(alpha, angles, values), dtype=float)
    if index is not None:
        return pd.Series(result.reshape(len(index)), index=index)
    return float(result) if result.ndim == 0 else result


def y0_for_contact_angle(alpha):
    """Axial static load factor Y0 of a single-row angular contact ball bearing [1].

    Linear interpolation in α [deg] between the rows of the DP11A manual, table 1
    (α = 18°, 20°, 26°, 30°, 36°: Y0 = 0.43, 0.42, 0.37, 0.33, 0.28) and
    Schaeffler HR 1, p. 237 (α = 40°: Y0 = 0.26); refused outside 18°–40°.
    NaN gives NaN.

    >>> y0_for_contact_angle(28.0)
    0.35
    >>> y0_for_contact_angle(40.0)  # a 72..-B bearing
    0.26
    """
    return _interpolate_factor(alpha, 2, "Y0")


def x0_for_contact_angle(alpha):
    """Radial static load factor X0 of a single-row angular contact ball bearing [1] (0.5 in 18°–40°).

    Same interpolation and range as :func:`y0_for_contact_angle`.

    >>> x0_for_contact_angle(20.0)
    0.5
    """
    return _interpolate_factor(alpha, 1, "X0")
