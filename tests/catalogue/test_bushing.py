"""The admissible pV and pressure tables of DU/DP bushings (the DU/DP bushing handbook): typed from the seed, units, refusals."""
from __future__ import annotations

import math
import re

import pytest

from bearingheat.catalogue import bushing as bu
from bearingheat.catalogue.tables import load_table, table_units
from bearingheat.errors import BushingInputError
from bearingheat.units import ureg


# ----------------------------------------------------------------- tables typed from the seed
def test_table25_reads_back_as_typed_from_seed():
    table = load_table("bushing_pv_limits")
    typed = [  # (application, shaft, life h, K kgf/cm^2*m/s or None where the OCR lost it)
        ("thrust_washer", "soft", 1000, 4.25), ("thrust_washer", "soft", 10000, None),
        ("thrust_washer", "hardened", 1000, 10.6), ("thrust_washer", "hardened", 10000, None),
        ("guide", "soft", 1000, 4.25), ("guide", "soft", 10000, None),
        ("guide", "hardened", 1000, None), ("guide", "hardened", 10000, None),
        ("bushing_constant_load", "soft", 1000, 5.65), ("bushing_constant_load", "soft", 10000, 4.25),
        ("bushing_constant_load", "hardened", 1000, 8.8), ("bushing_constant_load", "hardened", 10000, None),
        ("bushing_rotating_load", "soft", 1000, 10.6), ("bushing_rotating_load", "soft", 10000, None),
        ("bushing_rotating_load", "hardened", 1000, None), ("bushing_rotating_load", "hardened", 10000, None),
        ("bushing_oscillating", "soft", 1000, 10.6), ("bushing_oscillating", "soft", 10000, 8.15),
        ("bushing_oscillating", "hardened", 1000, 11.7), ("bushing_oscillating", "hardened", 10000, None),
    ]
    assert len(table) == len(typed)
    for (_, row), (application, shaft, life, K) in zip(table.iterrows(), typed):
        assert (row["application"], row["shaft"], row["life"]) == (application, shaft, life)
        assert (math.isnan(row["K"]) if K is None else row["K"] == K)
        assert row["source"].startswith("the DU/DP bushing handbook, table 25")
    assert table_units("bushing_pv_limits")["K"] == "kgf/cm^2*m/s"


def test_pressure_table_reads_back_as_typed_from_seed():
    table = load_table("bushing_pressure_limits")
    assert list(zip(table["load_type"], table["p_adm"])) == [
        ("static", 1410), ("rotating_fixed_load_point", 565), ("moving_load_moderate", 282),
        ("moving_load_severe", 141)]
    assert table_units("bushing_pressure_limits")["p_adm"] == "kgf/cm^2"


def test_table_units_convert_with_pint_to_the_kernel_constant():
    u = ureg()
    assert u("kgf/cm^2").to("N/mm^2").magnitude == pytest.approx(bu.KGF_PER_CM2, rel=1e-12)
    assert bu.pv_limit_du_dp_table25("bushing_constant_load", "soft", 1000) == pytest.approx(
        u.Quantity(5.65, "kgf/cm^2*m/s").to("N/mm^2*m/s").magnitude, rel=1e-12)


def test_lost_table_cell_message():
    with pytest.raises(BushingInputError, match=re.escape(
            "the DU/DP bushing handbook table 25: K for guide, hardened shaft, 1000 h was lost in the OCR of the DU/DP bushing handbook; give K directly")):
        bu.pv_limit_du_dp_table25("guide", "hardened", 1000)


def test_unknown_application_message():
    with pytest.raises(BushingInputError, match=re.escape(
            "the DU/DP bushing handbook table 25: application 'sleeve' unknown; expected one of bushing_constant_load, "
            "bushing_oscillating, bushing_rotating_load, guide, thrust_washer")):
        bu.pv_limit_du_dp_table25("sleeve", "soft", 1000)


def test_unknown_load_type_message():
    with pytest.raises(BushingInputError, match=re.escape(
            "the DU/DP bushing handbook [p]: load type 'heavy' unknown; expected one of static, rotating_fixed_load_point, "
            "moving_load_moderate, moving_load_severe")):
        bu.pressure_limit_du_dp("heavy")
