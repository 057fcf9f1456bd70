"""The unit-aware friction API with the SKF model: pairs, the model's own inputs, its notes and its series."""
import pint
import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
import pytest

from bearingheat import FrictionInputError, friction_torque

u = pint.get_application_registry()
NU = u("mm^2/s")
#: a 7210-B spindle bearing in grease (SKF table 3: angular contact ball bearings)
SPINDLE = dict(designation="7210-B", d=50 * u.mm, D=90 * u.mm, n=3000 * u.rpm, nu=22 * NU, lubrication="grease",
               model="skf")


def test_a_pair_is_two_bearings_each_at_half_the_radial_load():
    pair = friction_torque(**SPINDLE, Fr=2 * u.kN, arrangement="paired")
    one = friction_torque(**SPINDLE, Fr=1 * u.kN)
    assert pair.status == ["ok"]
    assert pair.MR.to("N*mm").magnitude == pytest.approx(2 * one.MR.to("N*mm").magnitude, rel=1e-15)
    assert pair.NR.to("W").magnitude == pytest.approx(2 * one.NR.to("W").magnitude, rel=1e-15)
    assert pair.model_results["M_start"].to("N*mm").magnitude == pytest.approx(
        2 * one.model_results["M_start"].to("N*mm").magnitude, rel=1e-15)
    assert pair.model_results["phi_rs"] == one.model_results["phi_rs"]


def test_a_pair_under_axial_load_is_refused():
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**SPINDLE, Fr=2 * u.kN, Fa=0.5 * u.kN, arrangement="paired")
    assert str(info.value) == (
        "Fa [N]: 500 on a pair: how a pair shares an axial load depends on its arrangement and preload, which the SKF "
        "model does not cover; give the two bearings as two rows, each with the loads it carries, or use the "
        "catalogue model (model = schaeffler)")
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**SPINDLE, Fr=2 * u.kN, arrangement="tandem")
    assert str(info.value) == "arrangement: 'tandem' is not one of single, paired"
