"""The unit-aware friction API with the SKF model: pairs, the model's own inputs, its notes and its series."""
import pandas as pd
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


#: the worked example of SKF 6000 pp. 104-105 (22208 E in an oil bath), its model inputs besides the oil level
EXAMPLE = dict(designation="22208 E", d=40 * u.mm, D=80 * u.mm, B=23 * u.mm, nu=68 * NU, Fr=2990 * u.N,
               Fa=100 * u.N, lubrication="oil_bath", model="skf")
BATH = dict(VM=0.3e-4, skf_edition="6000", mu_sl=0.05)


def example_mr(oil_level, n=3500 * u.rpm):
    r = friction_torque(**EXAMPLE, n=n, model_inputs=dict(BATH, oil_level=oil_level))
    return r.MR.to("N*mm").magnitude


def test_model_inputs_series_are_paired_by_their_index():
    n = pd.Series([3000.0, 3500.0], index=["a", "b"], dtype="pint[rpm]")
    H = pd.Series([40.0, 2.5], index=["a", "b"], dtype="pint[mm]")
    r = friction_torque(**EXAMPLE, n=n, model_inputs=dict(BATH, oil_level=H))
    assert r.MR.index.tolist() == ["a", "b"]
    assert r.MR.pint.to("N*mm").pint.magnitude.tolist() == pytest.approx(
        [example_mr(40 * u.mm, 3000 * u.rpm), example_mr(2.5 * u.mm)], rel=1e-15)
    assert example_mr(2.5 * u.mm) == pytest.approx(331.075, abs=1e-3)     # the example (printed 334)
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**EXAMPLE, n=n, model_inputs=dict(BATH, oil_level=H[["b", "a"]]))
    assert str(info.value) == ("n and oil_level are Series with different indexes (2 rows: 'a', 'b' against 2 rows: "
                               "'b', 'a'); give them one index, e.g. oil_level.reindex(n.index), or pass arrays")


def test_model_inputs_broadcast_with_the_other_arguments():
    r = friction_torque(**EXAMPLE, n=3500 * u.rpm, model_inputs=dict(BATH, oil_level=[2.5, 40.0] * u.mm))
    assert r.MR.to("N*mm").magnitude.tolist() == pytest.approx([example_mr(2.5 * u.mm), example_mr(40 * u.mm)],
                                                               rel=1e-15)
    assert r.status == ["ok", "ok"]


@pytest.mark.parametrize("n, model_inputs, message", [
    ([3500.0] * 3 * u.rpm, dict(BATH, oil_level=[2.5, 50.0] * u.mm),
     "n has shape (3,) and oil_level has shape (2,): arrays are paired value by value, so they need one shape (or "
     "give single values)"),
    (3500 * u.rpm, dict(BATH, oil_level=2.5 * u.mm, mu_sl="abc"), "mu_sl: 'abc' is not a number"),
    (3500 * u.rpm, dict(BATH, oil_level=2.5 * u.mm, VM=[0.3e-4, "x"]), "VM: 'x' is not a number (at index 1)"),
    (3500 * u.rpm, dict(BATH, oil_level=2.5 * u.mm, seal="CS", seals="two", d_s=60 * u.mm),
     "seals: 'two' is not a number"),
])
def test_model_inputs_the_model_cannot_use_are_refused_naming_the_argument(n, model_inputs, message):
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**EXAMPLE, n=n, model_inputs=model_inputs)
    assert str(info.value) == message


def test_arguments_of_different_lengths_are_refused_naming_both():
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**{**EXAMPLE, "Fr": [1.0, 2.0, 3.0] * u.kN}, n=[3000.0, 3500.0] * u.rpm,
                        model_inputs=dict(BATH, oil_level=2.5 * u.mm))
    assert str(info.value) == ("n has shape (2,) and Fr has shape (3,): arrays are paired value by value, so they "
                               "need one shape (or give single values)")


def test_model_inputs_name_no_argument_of_friction_torque():
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**EXAMPLE, n=3500 * u.rpm, model_inputs=dict(BATH, oil_level=2.5 * u.mm, arrangement="paired"))
    assert str(info.value) == "model_inputs: 'arrangement' is an argument of friction_torque; give it as arrangement="
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**EXAMPLE, n=3500 * u.rpm, model_inputs=dict(BATH, oil_level=2.5 * u.mm, oil_lvl=3 * u.mm))
    assert str(info.value) == ("model_inputs: 'oil_lvl' is not an input of this model; it reads oil, mu_sl, mu_bl, "
                               "oil_level, VM, skf_edition, seal, seals, d_s, C, Dw, T")


def test_an_implausible_model_input_is_a_warning_of_the_points_it_concerns():
    r = friction_torque(**EXAMPLE, n=3500 * u.rpm, model_inputs=dict(BATH, oil_level=2.5 * u.mm, VM=[0.3e-4, 0.3]))
    assert r.status == ["ok", "warning"]
    assert r.messages[1] == ("VM: 0.3 is outside the plausible range up to 0.01 (over 300 times the 0.3·10⁻⁴ the "
                             "worked example of SKF 6000 pp. 104-105 reads off diagram 2; the diagram's data are not "
                             "in bearingheat, so the bound is wide); check the number and its unit")
    with pytest.raises(FrictionInputError) as info:
        friction_torque(**EXAMPLE, n=3500 * u.rpm, model_inputs=dict(BATH, oil_level=2.5 * u.mm, d_s=100 * u.mm))
    assert str(info.value) == ("d_s [mm]: 100 must lie between d [mm] = 40 and D [mm] = 80: the seal counterface "
                               "diameter is d1, d2 or E of the bearing tables (SKF 6000 table 4, p. 96)")


def test_only_the_notes_and_the_series_of_the_model_that_computed_the_point():
    # (Fr above the minimum load 0.02 C = 1.26 kN of the NU 208, below which the SKF model warns)
    args = dict(n=3000 * u.rpm, nu=20 * NU, Fr=2 * u.kN, lubrication="grease", d=40 * u.mm, D=80 * u.mm)
    skf = friction_torque("NU 208", model="skf", **args)
    assert (skf.status, skf.messages, skf.bearing_type, skf.series) == (["ok"], [""], "cylindrical_roller", "2")
    catalogue = friction_torque("NU 208", **args)
    assert catalogue.messages == ["the Schaeffler catalogue row for series 2 is for the E design (2..-E)"]
    spherical = friction_torque("22208 E", model="skf", **args)
    assert (spherical.bearing_type, spherical.series) == ("spherical_roller", "222 E")     # SKF table 3e
    carb = friction_torque("C 2208", model="skf", **args)        # no row of the Schaeffler tables
    assert (carb.bearing_type, carb.series) == ("carb_toroidal_roller", "C 22")            # SKF table 3f
