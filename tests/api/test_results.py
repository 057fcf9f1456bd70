"""One result protocol: per-point status, to_frame with calc's headers, a short repr and an HTML view."""
from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.units import ureg

u = ureg()


@pytest.fixture(scope="module")
def friction():
    return bh.friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                              n=[1000, 3000] * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"))


def test_to_frame_has_the_headers_and_numbers_of_calc(friction):
    frame = friction.to_frame()
    table = pd.DataFrame({"designation": "6205", "d [mm]": 25, "D [mm]": 52, "C0 [kN]": 7.8,
                          "lubrication": "oil_bath", "n [rpm]": [1000, 3000], "Fr [kN]": 2, "nu [mm^2/s]": 12})
    out = bh.calc(table)
    for header in ("f0", "f1", "P0 [N]", "P1 [N]", "M0 [N*mm]", "M1 [N*mm]", "M2 [N*mm]", "MR [N*mm]", "NR [W]"):
        np.testing.assert_allclose(frame[header].to_numpy(), out[header].to_numpy(), rtol=1e-12, err_msg=header)
    assert frame["status"].tolist() == ["ok", "ok"] and frame["message"].tolist() == ["", ""]


def test_warnings_belong_to_their_points():
    r = bh.friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                           n=[1000, 3000] * u.rpm, Fr=2 * u.kN, nu=[12, 0.5] * u("mm^2/s"))
    assert r.status == ["ok", "warning"]
    assert r.messages == ["", "nu: 0.5 is outside the plausible range 1 to 100000 mm^2/s; check the number and its "
                              "unit"]


def test_results_are_frozen_with_a_short_repr_and_an_html_view(friction):
    with pytest.raises(dataclasses.FrozenInstanceError):
        friction.MR = None
    text = repr(friction)
    assert text.splitlines()[0] == "FrictionResult: 2 points (2 ok)"
    assert "  MR = 41.07 to 47.54 N*mm" in text.splitlines() and len(text.splitlines()) <= 14
    assert friction._repr_html_().startswith("<table") and "MR [N*mm]" in friction._repr_html_()


def test_heat_balance_uses_the_contract_names():
    r = bh.heat_balance("6208", n=1480 * u.rpm, iso_vg=68, lubrication="oil_bath", Fr=3.2 * u.kN,
                        T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    frame = r.to_frame()
    assert list(frame.columns) == ["n_thr [1/min]", "n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "Q_S [W]",
                                   "Q_L [W]", "NR [W]", "status", "message"]
    assert r.status == ["ok"] and len(r) == 1
