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

from bearingheat.calc.supports import number_column
from bearingheat.catalogue.viscosity import iso_vg_grades
from bearingheat.kernels.viscosity import (DEFAULT_VISCOSITY_INDEX, MIN_VISCOSITY, iso_vg_nu40,
                                           nu100_from_viscosity_index, walther_constants)

__all__ = ["viscosity_model_rows"]


def viscosity_model_rows(frame: pd.DataFrame):
    """Walther constants (A, B) per row from ``nu40``/``nu100`` or ``iso_vg`` (+ ``VI``) columns [mm²/s].

    Returns (A, B, problems): NaN where a row has no viscosity-temperature
    data; problems are (row position, 'error', message) for unusable data.
    """
    n_rows = len(frame)
    nu40, nu100, grade, VI = (number_column(frame, name) for name in ("nu40", "nu100", "iso_vg", "VI"))
    VI_used = np.where(np.isnan(VI), DEFAULT_VISCOSITY_INDEX, VI)
    grade_nu40 = iso_vg_nu40(grade)
    with np.errstate(invalid="ignore"):
        grade_nu100 = nu100_from_viscosity_index(grade_nu40, VI_used)
    A = np.full(n_rows, np.nan)
    B = np.full(n_rows, np.nan)
    problems = []
    for i in range(n_rows):
        has40, has100, has_grade = not np.isnan(nu40[i]), not np.isnan(nu100[i]), not np.isnan(grade[i])
        message = ""
        if has_grade and (has40 or has100):
            message = "iso_vg: give either iso_vg or nu40 and nu100, not both"
        elif has_grade:
            if np.isnan(grade_nu40[i]):
                message = (f"iso_vg: {grade[i]:g} is not an ISO VG grade; expected one of "
                           f"{', '.join(str(g) for g in iso_vg_grades())}")
            elif np.isnan(grade_nu100[i]):
                message = (f"VI: {VI_used[i]:g} cannot be reached by ISO VG {grade[i]:g} with nu100 >= 2 mm^2/s "
                           "(ASTM D2270)")
            else:
                A[i], B[i] = walther_constants(grade_nu40[i], 40.0, grade_nu100[i], 100.0)
        elif has40 != has100:
            have, need = ("nu40", "nu100") if has40 else ("nu100", "nu40")
            message = f"{need} [mm^2/s]: missing; {have} alone does not fix the viscosity-temperature line (ASTM D341)"
        elif has40 and has100:
            if not nu100[i] >= MIN_VISCOSITY:
                message = f"nu100 [mm^2/s]: {nu100[i]:g} must be >= 2 (ASTM D341)"
            elif not nu40[i] > nu100[i]:
                message = f"nu40 [mm^2/s]: {nu40[i]:g} must be larger than nu100 = {nu100[i]:g}"
            else:
                A[i], B[i] = walther_constants(nu40[i], 40.0, nu100[i], 100.0)
        if not has_grade and not np.isnan(VI[i]):
            message = message or "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"
        if message:
            problems.append((i, "error", message))
    return A, B, problems
