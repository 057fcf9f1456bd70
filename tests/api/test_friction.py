"""The unit-aware friction API: the same answer in any unit, scalar = array = Series, clear unit errors."""
import math

import re

import numpy as np
import pandas as pd
import pint
import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
import pytest

from bearingheat import FrictionInputError, UnitError, friction_torque

u = pint.get_application_registry()
NU = u("mm^2/s")


def mr(**kw):
    args = dict(designation="6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                n=3000 * u.rpm, Fr=2 * u.kN, Fa=0.5 * u.kN, nu=12 * NU)
    args.update(kw)
    return friction_torque(**args).MR.to("N*mm").magnitude


def test_force_units_are_invariant():
    ref = mr()
    assert mr(Fr=2000 * u.N, Fa=500 * u.N) == pytest.approx(ref, rel=1e-14)
    assert mr(Fr=(2000 / 9.80665) * u.kgf, Fa=(500 / 9.80665) * u.kgf) == pytest.approx(ref, rel=1e-12)
    assert mr(Fr=(2000 / 4.4482216152605) * u.lbf, Fa=(500 / 4.4482216152605) * u.lbf) == pytest.approx(ref, rel=1e-12)
    assert mr(C0=7800 * u.N) == pytest.approx(ref, rel=1e-14)


def test_length_and_viscosity_units_are_invariant():
    ref = mr()
    assert mr(d=2.5 * u.cm, D=0.052 * u.m) == pytest.approx(ref, rel=1e-14)
    assert mr(nu=12 * u.cSt) == pytest.approx(ref, rel=1e-12)
    assert mr(nu=12e-6 * u("m^2/s")) == pytest.approx(ref, rel=1e-12)


def test_speed_is_revolutions_per_time():
    ref = mr()
    assert mr(n=3000 / u.min) == pytest.approx(ref, rel=1e-14)
    assert mr(n=50 * u.Hz) == pytest.approx(ref, rel=1e-14)          # 50 rev/s = 3000 1/min
    assert mr(n=50 / u.s) == pytest.approx(ref, rel=1e-14)
    assert mr(n=100 * math.pi * u("rad/s")) == pytest.approx(ref, rel=1e-14)   # 2π rad per revolution
    assert mr(n=18000 * u("deg/s")) == pytest.approx(ref, rel=1e-14)




def test_mass_as_force_suggests_kgf():
    with pytest.raises(UnitError) as exc:
        mr(Fr=200 * u.kg)
    assert str(exc.value) == "Fr: 200 kilogram is a mass, not a force; for kilogram-force write 200 kgf"


def test_plain_number_is_refused():
    with pytest.raises(UnitError) as exc:
        mr(Fr=2000)
    assert str(exc.value) == ("Fr: expected a pint Quantity in N (for example 2.5 * ureg('N')); "
                              "got a plain int 2000")


def test_wrong_dimension():
    with pytest.raises(UnitError) as exc:
        mr(nu=12 * u.mm)
    assert str(exc.value) == ("nu: 12 millimeter cannot be converted to mm^2/s "
                              "(dimension [length], expected [length] ** 2 / [time])")


def test_scalar_array_series_agree():
    speeds = np.array([100.0, 600.0, 3000.0, 9000.0])      # both ν·n regimes at ν = 12
    array = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                            n=speeds * u.rpm, Fr=2 * u.kN, nu=12 * NU)
    scalars = [mr(n=s * u.rpm, Fa=0 * u.N) for s in speeds]
    np.testing.assert_allclose(array.MR.to("N*mm").magnitude, scalars, rtol=1e-15)
    series = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                             n=pd.Series(speeds, index=list("wxyz"), dtype="pint[rpm]"), Fr=2 * u.kN, nu=12 * NU)
    assert isinstance(series.MR, pd.Series) and list(series.MR.index) == list("wxyz")
    np.testing.assert_allclose(series.MR.pint.to("N*mm").pint.magnitude.to_numpy(dtype=float), scalars, rtol=1e-15)
    assert isinstance(series.f1, pd.Series)


def test_broadcast_two_dimensional_grid():
    n = np.array([[500.0], [3000.0]]) * u.rpm
    Fr = np.array([1.0, 2.0, 3.0]) * u.kN
    r = friction_torque("NU206-E", d=30 * u.mm, D=62 * u.mm, lubrication="grease", n=n, Fr=Fr, nu=20 * NU)
    assert r.MR.shape == (2, 3)
    assert r.MR[1, 2].to("N*mm").magnitude == pytest.approx(
        1.3 * (20 * 3000) ** (2 / 3) * 46 ** 3 * 1e-7 + 0.0003 * 3000 * 46, rel=1e-14)


def test_result_carries_coefficients_and_loads():
    r = friction_torque("30205-A", d=25 * u.mm, D=52 * u.mm, C0=34.5 * u.kN, Y=1.6, lubrication="oil_bath",
                        n=2000 * u.rpm, Fr=4 * u.kN, Fa=1.5 * u.kN, nu=12 * NU)
    assert (r.f0, r.f1) == (3.0, 0.0004)
    assert r.P1.to("N").magnitude == pytest.approx(4800.0)
    assert r.bearing_type == "tapered_roller" and r.series == "302"
    assert r.status == ["ok"] and r.messages == [""]


def test_m2_reports_chart_coordinates():
    r = friction_torque("NJ206-E", d=30 * u.mm, D=62 * u.mm, lubrication="circulating_oil", n=3000 * u.rpm,
                        Fr=5 * u.kN, Fa=1 * u.kN, nu=20 * NU, f2=0.004)
    assert r.Fa_over_A == pytest.approx(1000 / (15e-3 * 46 ** 2.1), rel=1e-12)
    assert r.nu_n_dM.to("mm^3/(s*min)").magnitude == pytest.approx(20 * 3000 * 46, rel=1e-12)
    assert r.M2.to("N*mm").magnitude == pytest.approx(0.004 * 1000 * 46, rel=1e-12)


def test_warnings_are_returned():
    r = friction_torque("6205-2RSR", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="grease",
                        n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * NU)
    assert r.status == ["warning"]
    assert r.messages == ["contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, lists seal friction among the components; its formulas have no term for it)"]


def test_errors_name_argument_value_and_index():
    with pytest.raises(FrictionInputError) as exc:
        mr(n=np.array([100.0, -5.0]) * u.rpm)
    assert str(exc.value) == "n [1/min]: -5 must be >= 0 (speed magnitude) (at index 1)"
    with pytest.raises(FrictionInputError) as exc:
        mr(lubrication="oil")
    assert str(exc.value) == "lubrication: 'oil' is not one of grease, oil_mist, oil_bath, circulating_oil"
    with pytest.raises(FrictionInputError) as exc:
        mr(lubrication=None)
    assert str(exc.value) == "lubrication: missing; expected one of grease, oil_mist, oil_bath, circulating_oil"


def test_explicit_type_and_series():
    a = mr()
    b = mr(designation=None, bearing_type="deep_groove_ball", series="62")
    assert a == b


def test_application_registry_is_used_not_changed():
    before = pint.get_application_registry()
    r = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
                        n=3000 * u.rpm, nu=12 * NU)
    assert pint.get_application_registry() is before
    assert r.MR._REGISTRY is before.get() if hasattr(before, "get") else before



def test_series_of_different_indexes_are_refused_not_paired_by_position():
    """Series are paired row by row: the same labels in another order (or other labels, or another length)
    would pair rows of different labels, so they are refused, naming both arguments; one index works."""
    n = pd.Series([1000.0, 2000.0, 3000.0], index=[0, 1, 2], dtype="pint[rpm]")
    for Fr in (pd.Series([3.0, 1.0, 2.0], index=[2, 0, 1], dtype="pint[kN]"),
               pd.Series([3.0, 1.0, 2.0], index=["a", "b", "c"], dtype="pint[kN]"),
               pd.Series([3.0, 1.0], index=[0, 1], dtype="pint[kN]")):
        labels = ", ".join(map(repr, Fr.index.tolist()))
        message = (f"n and Fr are Series with different indexes (3 rows: 0, 1, 2 against {len(Fr)} rows: {labels}); "
                   "give them one index, e.g. Fr.reindex(n.index), or pass arrays")
        with pytest.raises(FrictionInputError, match=f"^{re.escape(message)}$"):
            mr(n=n, Fr=Fr)
    aligned = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath", nu=12 * NU,
                              n=n, Fr=pd.Series([3.0, 1.0, 2.0], index=[2, 0, 1], dtype="pint[kN]").reindex(n.index))
    by_label = [mr(n=s * u.rpm, Fr=f * u.kN, Fa=0 * u.N) for s, f in ((1000, 1.0), (2000, 2.0), (3000, 3.0))]
    np.testing.assert_allclose(aligned.MR.pint.to("N*mm").pint.magnitude.to_numpy(dtype=float), by_label, rtol=1e-15)
