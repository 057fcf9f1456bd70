"""Admissible pV and pressure of self-lubricating DU/DP bushings and thrust washers (the DU/DP bushing handbook).

The DU/DP bushing handbook works in kgf/cm² and m/s; its tables are stored as typed, in
``tables/bushing_pv_limits.csv`` (table 25, K = pV in kgf/cm²·m/s) and
``tables/bushing_pressure_limits.csv`` (the admissible specific load [p] in
kgf/cm², p. 167). The lookups return catalogue units: N/mm²·m/s and N/mm²,
with 1 kgf/cm² = 9.80665 N / 100 mm² = 0.0980665 N/mm² (:data:`KGF_PER_CM2`).

>>> round(KGF_PER_CM2, 7)
0.0980665
"""
from __future__ import annotations

import math

from bearingheat.catalogue.tables import load_table
from bearingheat.errors import BushingInputError

__all__ = ["KGF_PER_CM2", "pv_limit_du_dp_table25", "pressure_limit_du_dp"]

#: 1 kgf/cm² in N/mm² (9.80665 N per 100 mm²).
KGF_PER_CM2 = 9.80665 / 100.0


def pv_limit_du_dp_table25(application: str, shaft: str, life: float) -> float:
    """Admissible K = pV [N/mm²·m/s] from the DU/DP bushing handbook table 25 (stored in kgf/cm²·m/s).

    application: thrust_washer, guide, bushing_constant_load,
    bushing_rotating_load, bushing_oscillating; shaft: soft (mild steel, also
    cast iron, austenitic stainless, anodised aluminium, chromium-plated mild
    steel) or hardened (HB 540); life: 1000 or 10000 h.

    >>> round(pv_limit_du_dp_table25("bushing_constant_load", "soft", 1000), 4)
    0.5541
    """
    table = load_table("bushing_pv_limits")
    for column, value in (("application", application), ("shaft", shaft)):
        choices = sorted(set(table[column]))
        if value not in choices:
            raise BushingInputError(f"the DU/DP bushing handbook table 25: {column} {value!r} unknown; "
                                    f"expected one of {', '.join(choices)}")
    lives = sorted(set(table["life"].astype(int)))
    if life not in lives:
        raise BushingInputError(f"the DU/DP bushing handbook table 25: life {life:g} h not tabulated; expected one of "
                                f"{', '.join(f'{x:g}' for x in lives)} h (or give K directly)")
    row = table[(table["application"] == application) & (table["shaft"] == shaft) & (table["life"] == life)]
    K = float(row["K"].iloc[0])
    if not math.isfinite(K):
        raise BushingInputError(f"the DU/DP bushing handbook table 25: K for {application}, {shaft} shaft, {life:g} h was lost in "
                                "the OCR of the DU/DP bushing handbook; give K directly")
    return K * KGF_PER_CM2


def pressure_limit_du_dp(load_type: str) -> float:
    """Admissible specific load [p] [N/mm²] for a load type, the DU/DP bushing handbook p. 167 (stored in kgf/cm²).

    >>> round(pressure_limit_du_dp("rotating_fixed_load_point"), 3)
    55.408
    """
    table = load_table("bushing_pressure_limits")
    if load_type not in set(table["load_type"]):
        raise BushingInputError(f"the DU/DP bushing handbook [p]: load type {load_type!r} unknown; expected one of "
                                f"{', '.join(table['load_type'])}")
    return float(table.loc[table["load_type"] == load_type, "p_adm"].iloc[0]) * KGF_PER_CM2
