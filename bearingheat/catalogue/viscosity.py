"""Lubricant tables: ISO 3448 viscosity grades and ASTM D2270 table 1 (L and H of the viscosity index).

>>> iso_vg_grades()[68]
68.0
>>> grid, L, H = d2270_table()
>>> float(grid[0]), float(L[0]), float(H[0])
(2.0, 7.994, 6.394)
"""
from __future__ import annotations

import functools

import numpy as np

from bearingheat.catalogue.tables import load_table

__all__ = ["iso_vg_grades", "d2270_table"]


@functools.lru_cache(maxsize=None)
def iso_vg_grades() -> dict[int, float]:
    """ISO 3448 grade -> mid-point ν40 [mm²/s] (tables/iso_vg_grades.csv).

    >>> iso_vg_grades()[68], iso_vg_grades()[5]
    (68.0, 4.6)
    """
    table = load_table("iso_vg_grades")
    return {int(g): float(v) for g, v in zip(table["grade"], table["nu40"])}


@functools.lru_cache(maxsize=None)
def d2270_table() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ν100, L, H) [mm²/s] of ASTM D2270 table 1, ν100 from 2 to 70 mm²/s.

    From tables/astm_d2270_viscosity_index.csv; the arrays are cached, do not change them.
    """
    table = load_table("astm_d2270_viscosity_index")
    return (table["nu100"].to_numpy(dtype=float), table["L"].to_numpy(dtype=float),
            table["H"].to_numpy(dtype=float))
