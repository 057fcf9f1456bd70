"""Viscosity-temperature lines of the rows of a table (catalogue units): the Walther constants per row.

The formulas are :mod:`bearingheat.kernels.viscosity` (ASTM D341, ISO VG
grades, ASTM D2270); the heat balance (:mod:`bearingheat.calc.thermal`)
takes ν at its temperatures from the constants found here.

>>> import pandas as pd
>>> A, B, problems = viscosity_model_rows(pd.DataFrame({"nu40": [68.0], "nu100": [8.79]}))
>>> round(float(A[0]), 4), round(float(B[0]), 4), problems
(9.2493, 3.6002, [])
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.supports import group_rows, number_column, object_column
from bearingheat.catalogue.viscosity import iso_vg_grades
from bearingheat.kernels.viscosity import (DEFAULT_VISCOSITY_INDEX, MIN_VISCOSITY, iso_vg_nu40,
                                           nu100_from_viscosity_index, walther_constants)

__all__ = ["OIL_LINE_INPUTS", "viscosity_model_rows"]


#: the columns a row's viscosity-temperature line is found from
OIL_LINE_INPUTS = ("nu40", "nu100", "iso_vg", "VI")


def viscosity_model_rows(frame: pd.DataFrame):
    """Walther constants (A, B) per row from ``nu40``/``nu100`` or ``iso_vg`` (+ ``VI``) columns [mm²/s].

    Returns (A, B, problems): NaN where a row has no viscosity-temperature
    data; problems are (row position, 'error', message) for unusable data.
    Rows with the same oil data are worked out once (a table of many
    operating points names few oils).
    """
    names = [name for name in OIL_LINE_INPUTS if name in frame.columns]
    if not names or len(frame) < 2:
        return _viscosity_model(frame)
    codes, first = group_rows(frame, names)
    if len(first) == len(frame):
        return _viscosity_model(frame)
    A, B, distinct_problems = _viscosity_model(frame.iloc[first])
    said: dict[int, list[tuple[str, str]]] = {}
    for j, level, message in distinct_problems:
        said.setdefault(j, []).append((level, message))
    flagged = np.flatnonzero(np.isin(codes, list(said))) if said else np.zeros(0, dtype=np.intp)
    problems = [(int(i), level, message) for i in flagged.tolist() for level, message in said[int(codes[i])]]
    return A[codes], B[codes], problems


def _viscosity_model(frame: pd.DataFrame):
    """:func:`viscosity_model_rows` of every row of ``frame`` (no grouping)."""
    n_rows = len(frame)
    nu40, nu100, grade, VI = (number_column(frame, name) for name in OIL_LINE_INPUTS)
    VI_used = np.where(np.isnan(VI), DEFAULT_VISCOSITY_INDEX, VI)
    grade_nu40 = iso_vg_nu40(grade)
    grade_nu100 = np.full(n_rows, np.nan)
    graded = np.flatnonzero(~np.isnan(grade_nu40))
    if len(graded):  # ASTM D2270 once per distinct (grade, VI) pair
        pairs, where = np.unique(np.column_stack([grade_nu40[graded], VI_used[graded]]), axis=0, return_inverse=True)
        with np.errstate(invalid="ignore"):
            grade_nu100[graded] = nu100_from_viscosity_index(pairs[:, 0], pairs[:, 1])[where.ravel()]
    has40, has100, has_grade = ~np.isnan(nu40), ~np.isnan(nu100), ~np.isnan(grade)
    A = np.full(n_rows, np.nan)
    B = np.full(n_rows, np.nan)
    messages = object_column(n_rows, "")

    def tell(rows: np.ndarray, text) -> None:
        """The message of each flagged row (``text(i)``), built only for those rows."""
        for i in np.flatnonzero(rows):
            messages[i] = text(i)

    tell(has_grade & (has40 | has100), lambda i: "iso_vg: give either iso_vg or nu40 and nu100, not both")
    by_grade = has_grade & ~(has40 | has100)
    no_grade = by_grade & np.isnan(grade_nu40)
    tell(no_grade, lambda i: f"iso_vg: {grade[i]:g} is not an ISO VG grade; expected one of "
                             f"{', '.join(str(g) for g in iso_vg_grades())}")
    no_nu100 = by_grade & ~no_grade & np.isnan(grade_nu100)
    tell(no_nu100, lambda i: f"VI: {VI_used[i]:g} cannot be reached by ISO VG {grade[i]:g} with nu100 >= 2 mm^2/s "
                             "(ASTM D2270)")
    good = by_grade & ~no_grade & ~no_nu100
    A[good], B[good] = walther_constants(grade_nu40[good], 40.0, grade_nu100[good], 100.0)
    tell(~has_grade & (has40 != has100),
         lambda i: ("nu100 [mm^2/s]: missing; nu40 alone" if has40[i] else "nu40 [mm^2/s]: missing; nu100 alone")
         + " does not fix the viscosity-temperature line (ASTM D341)")
    by_points = ~has_grade & has40 & has100
    with np.errstate(invalid="ignore"):
        low100 = by_points & ~(nu100 >= MIN_VISCOSITY)
        inverted = by_points & ~low100 & ~(nu40 > nu100)
    tell(low100, lambda i: f"nu100 [mm^2/s]: {nu100[i]:g} must be >= 2 (ASTM D341)")
    tell(inverted, lambda i: f"nu40 [mm^2/s]: {nu40[i]:g} must be larger than nu100 = {nu100[i]:g}")
    good = by_points & ~low100 & ~inverted
    A[good], B[good] = walther_constants(nu40[good], 40.0, nu100[good], 100.0)
    tell(~has_grade & ~np.isnan(VI) & (messages == ""),
         lambda i: "VI: given without iso_vg; the viscosity index only serves an ISO VG grade")
    problems = [(int(i), "error", messages[i]) for i in np.flatnonzero(messages != "")]
    return A, B, problems
