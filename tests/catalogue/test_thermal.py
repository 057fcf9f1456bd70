"""Reference conditions of the thermal reference speed (issue 3): the table and its lookup."""
from __future__ import annotations

import re

import pytest

from bearingheat.catalogue.tables import load_table, table_units
from bearingheat.catalogue.thermal import THERMAL_KIND, method_refusal, reference_conditions
from bearingheat.errors import HeatBalanceError


def test_reference_conditions_table_reads_back():
    table = load_table("thermal_reference_conditions")
    rows = table.drop(columns="source").to_dict("records")
    assert rows == [
        {"kind": "radial", "load_ratio": 0.05, "nu_ref": 12.0, "q_r": 0.016, "A_r_limit": 50000.0,
         "q_r_exponent": -0.34, "T_ambient": 20.0, "T_bearing": 70.0},
        {"kind": "thrust", "load_ratio": 0.02, "nu_ref": 24.0, "q_r": 0.020, "A_r_limit": 50000.0,
         "q_r_exponent": -0.16, "T_ambient": 20.0, "T_bearing": 70.0},
    ]
    assert table_units("thermal_reference_conditions")["q_r"] == "W/mm^2"
    assert all("issue 3" in s for s in table["source"])


def test_reference_conditions_tapered_uses_radial_and_bad_kind():
    assert reference_conditions("tapered") == reference_conditions("radial")
    with pytest.raises(ValueError, match=re.escape("kind: 'axial' is not one of radial, tapered, thrust")):
        reference_conditions("axial")


def test_method_refusals_name_the_reason():
    assert method_refusal("thrust_ball") == ("the thermal method (ISO 15312, DIN 732) does not apply to thrust ball "
                                             "bearings")
    assert method_refusal("deep_groove_ball", "contact") == (
        "the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its reference "
        "conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, whose heat "
        "balance would leave the seal friction out, are not computed either")
    assert method_refusal("deep_groove_ball", "shield") == ""
    assert THERMAL_KIND["tapered_roller"] == "tapered" and THERMAL_KIND["combined"] is None
    with pytest.raises(HeatBalanceError):
        reference_conditions("axial")
