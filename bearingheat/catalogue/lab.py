"""The DP11A lab rig of the DP11A manual: its bearings (table 3) and the coefficients of radial ball bearings.

``tables/lab_bearings.csv`` holds the DP11A manual table 3 (d, dm, D [mm], C0 [N]
of the bearings 1000095, 18 and 101); the static load factors X0, Y0 of a
radial ball bearing are the row 'radial' of the DP11A manual table 1
(``tables/static_load_factors.csv``).
"""
from __future__ import annotations

from bearingheat.catalogue.tables import load_table
from bearingheat.errors import LabError

__all__ = [
    "LOAD_EXPONENT_RADIAL",
    "REDUCED_FRICTION_RADIAL",
    "LOAD_COEFFICIENT_RADIAL",
    "lab_bearing",
    "radial_static_load_factors",
]

#: c of T_F = f·P0·(P0/C0)^c·dm for radial ball bearings (the DP11A manual, table 2 and p. 13)
LOAD_EXPONENT_RADIAL = 0.55
#: μ of single row radial ball bearings in T = μ·P0·d/2 (the DP11A manual, p. 5)
REDUCED_FRICTION_RADIAL = 0.0015
#: f of radial ball bearings (the DP11A manual, table 2)
LOAD_COEFFICIENT_RADIAL = 0.0009


def lab_bearing(designation: str) -> dict:
    """Row of the DP11A manual table 3 (tables/lab_bearings.csv): d, dm, D [mm], C0 [N].

    >>> lab_bearing("101")["C0"]
    2227.0
    """
    table = load_table("lab_bearings")
    hit = table[table["designation"] == str(designation).strip()]
    if hit.empty:
        raise LabError(f"bearing {designation!r} is not in the DP11A manual table 3; expected one of "
                       f"{', '.join(table['designation'])}")
    row = hit.iloc[0]
    return {"designation": row["designation"], "d": float(row["d"]), "dm": float(row["dm"]),
            "D": float(row["D"]), "C0": float(row["C0"])}


def radial_static_load_factors() -> tuple[float, float]:
    """(X0, Y0) of a radial (deep groove) ball bearing, the DP11A manual table 1, row 'radial'.

    >>> radial_static_load_factors()
    (0.6, 0.5)
    """
    factors = load_table("static_load_factors")
    radial = factors[factors["bearing_type"] == "deep_groove_ball"].iloc[0]
    return float(radial["X0"]), float(radial["Y0"])
