"""The unit-aware API fills dimensions and ratings from the bearing table like calc."""
from __future__ import annotations

import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.units import ureg

u = ureg()


def test_friction_torque_by_designation_alone_equals_the_typed_dimensions():
    typed = bh.friction_torque("6208", d=40 * u.mm, D=80 * u.mm, C0=18 * u.kN, n=1480 * u.rpm,
                               nu=40 * u("mm^2/s"), lubrication="oil_bath", Fr=3.2 * u.kN, Fa=0.9 * u.kN)
    alone = bh.friction_torque("6208", n=1480 * u.rpm, nu=40 * u("mm^2/s"), lubrication="oil_bath",
                               Fr=3.2 * u.kN, Fa=0.9 * u.kN)
    assert alone.MR.magnitude == typed.MR.magnitude and alone.status == ["ok"]
    same = bh.calc(pd.DataFrame({"designation": ["6208"], "lubrication": ["oil_bath"], "n [rpm]": [1480],
                                 "Fr [kN]": [3.2], "Fa [kN]": [0.9], "nu [mm^2/s]": [40]}))
    assert same["MR [N*mm]"].iat[0] == pytest.approx(alone.MR.to("N*mm").magnitude, rel=1e-12)


def test_a_given_value_wins_with_a_warning():
    r = bh.friction_torque("6208", n=1480 * u.rpm, nu=40 * u("mm^2/s"), lubrication="oil_bath", Fr=3.2 * u.kN,
                           C0=19 * u.kN)
    assert r.status == ["warning"]
    assert r.messages == ["C0: 19000 N differs from 18000 N of 6208 in the bearing table (Schaeffler HR 1, 2006); "
                          "the value given is used"]


def test_an_unknown_designation_without_dimensions_is_refused():
    with pytest.raises(bh.FrictionInputError) as info:
        bh.friction_torque("6208-2ZZ", n=1480 * u.rpm, nu=40 * u("mm^2/s"), lubrication="oil_bath")
    assert str(info.value) == ("designation: '6208-2ZZ' is not in the bearing table (Schaeffler HR 1, 2006); close "
                               "matches: 6208-2Z, 6208-2RSR, 6208, 608-2Z, 6320-2Z; or give d, D (and C0)")


def test_heat_balance_by_designation_alone():
    args = dict(n=1480 * u.rpm, iso_vg=68, lubrication="oil_bath", Fr=3.2 * u.kN, Fa=0.9 * u.kN,
                T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    alone = bh.heat_balance("6208", **args)
    typed = bh.heat_balance("6208", d=40 * u.mm, D=80 * u.mm, B=18 * u.mm, C0=18 * u.kN, n_G=20000 * u.rpm, **args)
    assert alone.status == typed.status == ["ok"]
    assert alone.n_per.magnitude == typed.n_per.magnitude and alone.n_thr.magnitude == typed.n_thr.magnitude
