"""Plain (DU/DP) bushings as rows of a calc table (type ``plain_bushing``).

M_R = f·F·d/2 and N_R = f·F·V from the bushing kernel (the DU/DP bushing
sizing method of the plain-bearing handbook); the rolling-bearing models
skip these rows.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.kernels.bushing import plain_bushing_power_loss
from bearingheat.calc.friction import RESULTS
from bearingheat.calc.supports import number_column

__all__ = ["plain_rows"]


def plain_rows(frame: pd.DataFrame, plain: np.ndarray, results: dict, row_errors: dict[int, list[str]],
               warnings_by_row: dict[int, list[str]]) -> None:
    """Fill MR, NR, p_plain and V_plain of the plain rows into ``results``; their messages into the row lists."""
    rows = np.flatnonzero(plain)
    d, B, F, n, f = (number_column(frame, c)[rows] for c in ("d", "B", "Fr", "n", "f_plain"))
    F = np.nan_to_num(F, nan=0.0)
    loss = plain_bushing_power_loss(d, B, F, n, f)
    for col in RESULTS:
        results[col][rows] = np.nan
    results["MR"][rows] = loss.f_used * F * d / 2.0
    results["NR"][rows] = loss.power
    for col, values in (("p_plain", loss.p), ("V_plain", loss.V)):
        results[col] = np.full(len(plain), np.nan)
        results[col][rows] = values
    for k, i in enumerate(rows.tolist()):
        if loss.status[k] == "error":
            row_errors[i].append(loss.message[k])
        elif loss.message[k]:
            warnings_by_row[i].append(loss.message[k])


