"""Every error and warning path of the friction model, with its exact message.

Bad rows get status 'error' and NaN results; the other rows are still computed.
"""
import math

import numpy as np
import pandas as pd
import pytest

from bearingheat.calc.models import compute_supports

BASE = dict(designation="6205", d=25, D=52, C0=7800, lubrication="oil_bath", n=3000, Fr=2000, Fa=0, nu=12)
TYPES = ("needle_roller, cylindrical_roller_full_complement, cylindrical_roller, thrust_roller, combined, "
         "tapered_roller, spherical_roller, axial_spherical_roller, deep_groove_ball, angular_contact_ball, "
         "angular_contact_ball_double_row, self_aligning_ball, four_point_contact_ball, thrust_ball")

CASES = {
    "unknown designation": (dict(designation="6Z05"), "error",
        "designation: '6Z05' matches no row of the Schaeffler catalogue tables (close matches: 6405, 6305, 6205, 6015, 6005); "
        "give type and series explicitly instead"),
    "no designation": (dict(designation=None), "error",
        "designation: missing; give a designation, or type and series"),
    "type without series": (dict(designation=None, type="deep_groove_ball"), "error",
        "series: missing; give type and series together"),
    "unknown type": (dict(designation=None, type="ball", series="62"), "error",
        f"type: 'ball' is not a bearing type; expected one of {TYPES}"),
    "unknown series": (dict(designation=None, type="deep_groove_ball", series="99"), "error",
        "series: '99' is not in the Schaeffler catalogue table of deep groove ball bearings; "
        "expected one of 618, 160, 60, 619, 622, 623, 62, 63, 64, 42, 43"),
    "unknown lubrication": (dict(lubrication="oil"), "error",
        "lubrication: 'oil' is not one of grease, oil_mist, oil_bath, circulating_oil"),
    "no lubrication": (dict(lubrication=None), "error",
        "lubrication: missing; expected one of grease, oil_mist, oil_bath, circulating_oil"),
    "oil on a grease-only row": (dict(designation="62205", lubrication="circulating_oil"), "error",
        "lubrication: 'circulating_oil' has no f0 for deep groove ball bearing series 622 (the Schaeffler catalogue prints a dash); "
        "use grease or oil_mist, or give f0"),
    "paired deep groove": (dict(arrangement="paired"), "error",
        "arrangement: 'paired' has no P1 rule for deep groove ball bearing series 62 (the Schaeffler catalogue, p. 68, prints no rule for a pair)"),
    "unknown arrangement": (dict(arrangement="triple"), "error",
        "arrangement: 'triple' is not one of single, paired"),
    "no bore": (dict(designation="62..", d=None), "error", "d [mm]: missing; the bore d gives dM = (d + D)/2"),
    "negative bore": (dict(d=-1), "error", "d [mm]: -1 must be > 0"),
    "D not above d": (dict(D=20), "error", "D [mm]: 20 must be larger than d [mm] = 25"),
    "no D": (dict(D=None), "error", "D [mm]: missing; the outside diameter D gives dM = (d + D)/2"),
    "no speed": (dict(n=None), "error", "n [1/min]: missing; the operating speed is needed"),
    "negative speed": (dict(n=-5), "error", "n [1/min]: -5 must be >= 0 (speed magnitude)"),
    "no viscosity": (dict(nu=None), "error",
        "nu [mm^2/s]: missing; the operating viscosity (base oil viscosity for grease) is needed"),
    "zero viscosity": (dict(nu=0), "error", "nu [mm^2/s]: 0 must be > 0"),
    "negative Fr": (dict(Fr=-1), "error", "Fr [N]: -1 must be >= 0"),
    "negative Fa": (dict(Fa=-1), "error", "Fa [N]: -1 must be >= 0"),
    "negative f0": (dict(f0=-1), "error", "f0: -1 must be >= 0"),
    "negative f1": (dict(f1=-0.1), "error", "f1: -0.1 must be >= 0"),
    "no C0": (dict(C0=None), "error",
        "C0 [N]: missing; f1 of deep groove ball bearing series 62 depends on P0/C0 (the Schaeffler catalogue, pp. 66-68)"),
    "no C0 thrust ball": (dict(designation="51105", D=42, C0=None, Fr=0, Fa=1000), "error",
        "C0 [N]: missing; f1 of thrust ball bearing series 511 depends on Fa/C0 (the Schaeffler catalogue, pp. 66-68)"),
    "zero C0": (dict(C0=0), "error", "C0 [N]: 0 must be > 0"),
    "needle without width": (dict(designation=None, type="needle_roller", series="NK", D=33, B=None), "error",
        "B [mm]: missing; f0 of needle roller bearing series NK is value*B/(33+d) (the Schaeffler catalogue, p. 66)"),
    "negative width": (dict(designation="HK2016", d=None, D=26, B=-2), "error", "B [mm]: -2 must be > 0"),
    "tapered without Y": (dict(designation="30205-A", Fa=500), "error",
        "Y: missing; P1 of tapered roller bearing series 302 under axial load needs the catalogue value Y "
        "(the Schaeffler catalogue, p. 68)"),
    "negative Y": (dict(designation="30205-A", Fa=500, Y=-1), "error", "Y: -1 must be > 0"),
    "spherical without e": (dict(designation="22205-E1", Fa=500, X0=1, Y0=2.8, C0=40000), "error",
        "e: missing; P1 of spherical roller bearing series 222 under axial load needs the catalogue value e "
        "(the Schaeffler catalogue, p. 68)"),
    "spherical without X0, Y0": (dict(designation="22205-E1", Fa=500, e=0.3, C0=40000), "error",
        "X0: missing; P0 of spherical roller bearing series 222 under axial load needs the catalogue value X0 "
        "(the DP11A manual, table 1 has none for this type); Y0: missing; P0 of spherical roller bearing series 222 under "
        "axial load needs the catalogue value Y0 (the DP11A manual, table 1 has none for this type)"),
    "angular contact at 45 deg": (dict(designation="7205", alpha=45, Fa=500), "error",
        "Y0: missing; alpha = 45 deg is outside the contact angles of the static load factors (18 to 40 deg: the "
        "DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, 40 deg); Y0 is not extrapolated; give Y0 "
        "from the catalogue"),
    "angular contact without angle": (dict(designation="7205", Fa=500), "error",
        "Y0: missing; P0 of single row angular contact ball bearing series 72 under axial load needs the catalogue "
        "value Y0 or the contact angle alpha (the DP11A manual, table 1, 18 to 36 deg; Schaeffler HR 1, p. 237, "
        "40 deg)"),
    "radial load on a thrust ball bearing": (dict(designation="51105", D=42, Fa=1000), "error",
        "Fr [N]: 2000 on thrust ball bearing series 511: thrust ball and thrust roller bearings take no radial load "
        "(their M1 is f1*Fa*dM)"),
    "radial load on a thrust roller bearing": (dict(designation=None, type="thrust_roller", series="811", d=40, D=60,
                                                    Fa=5000), "error",
        "Fr [N]: 2000 on thrust roller bearing series 811: thrust ball and thrust roller bearings take no radial load "
        "(their M1 is f1*Fa*dM)"),
    "axial load on NU": (dict(designation="NU206-E", Fa=500), "error",
        "Fa [N]: 500 on NU cylindrical roller bearing with cage series 2: one ring has no ribs, "
        "the bearing takes no axial load"),
    "axial without radial on NJ": (dict(designation="NJ206-E", Fr=0, Fa=500, f2=0.01), "error",
        "Fa [N]: 500 without radial load on cylindrical roller bearing with cage series 2: axially loaded "
        "cylindrical roller bearings need Fr > 0 (the Schaeffler catalogue, p. 69)"),
    "NJ without f2": (dict(designation="NJ206-E", Fa=500), "error",
        "f2: missing; cylindrical roller bearing with cage series 2 carries Fa, so M2 = f2*Fa*dM needs f2: give f2, "
        "or a digitised f2 chart (f2_chart; --f2-chart on the command line); read it at Fa/A = 15.61, "
        "nu*n*dM = 1.386e+06 mm^3/(s*min) "
        "(the Schaeffler catalogue, p. 70, figs. 3 and 4)"),
    "Fa/Fr above 0.4": (dict(designation="NJ206-E", Fr=1000, Fa=500, f2=0.01), "warning",
        "Fa/Fr = 0.5 is above 0.4: M2 is uncertain there (bearingheat's caution for cylindrical roller bearings; "
        "the Schaeffler catalogue, p. 69, prints no limit)"),
    "contact seal": (dict(designation="6205-2RSR", lubrication="grease"), "warning",
        "contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, lists seal friction among the components; its formulas have no term for it)"),
    "not the E design": (dict(designation="NU206"), "warning",
        "the Schaeffler catalogue row for series 2 is for the E design (2..-E)"),
}


@pytest.fixture(scope="module")
def results():
    rows = []
    for update, _, _ in CASES.values():
        row = dict(BASE)
        row.update(update)
        rows.append(row)
    rows.append(dict(BASE))  # a good row among the bad ones
    return compute_supports(pd.DataFrame(rows, index=[*CASES, "good"]))


@pytest.mark.parametrize("case", list(CASES))
def test_message(results, case):
    _, status, message = CASES[case]
    assert results.loc[case, "status"] == status
    assert results.loc[case, "message"] == message
    if status == "error":
        assert np.isnan(results.loc[case, ["f0", "f1", "P0", "P1", "M0", "M1", "M2", "MR", "NR"]].astype(float)).all()
    else:
        assert results.loc[case, "MR"] > 0


def test_good_row_still_computed(results):
    assert results.loc["good", "status"] == "ok"
    assert results.loc["good", "message"] == ""
    hand = 2 * 36000 ** (2 / 3) * 38.5 ** 3 * 1e-7 + 0.0009 * (2000 / 7800) ** 0.5 * 2000 * 38.5  # the Schaeffler catalogue
    assert results.loc["good", "MR"] == pytest.approx(hand, rel=1e-12)


def test_index_is_kept(results):
    assert list(results.index) == [*CASES, "good"]


# ---- the friction-model registry -----------------------------------------------------------------

def _rows(**extra):
    base = {"designation": ["6205", "6205"], "d [mm]": [25, 25], "D [mm]": [52, 52], "C0 [kN]": [7.8, 7.8],
            "lubrication": ["oil_bath", "oil_bath"], "n [rpm]": [3000, 3000], "Fr [kN]": [2, 2],
            "nu [mm^2/s]": [12, 12]}
    base.update(extra)
    return pd.DataFrame(base)


def test_registry_keys_come_from_the_models():
    from bearingheat.calc.models import MODELS

    assert all(name == model.name for name, model in MODELS.items())


def test_model_column_selects_the_model_per_row():
    from bearingheat.calc.table import calc

    out = calc(_rows(model=["schaeffler", None]))
    assert out["MR [N*mm]"].round(3).tolist() == [47.535, 47.535]
    assert out["status"].tolist() == ["ok", "ok"]


def test_unknown_model_in_a_row_is_that_row_error():
    from bearingheat.calc.table import calc

    out = calc(_rows(model=["schaeffler", "palmgren"]))
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].iat[1] == "model: 'palmgren' is not one of schaeffler, skf"
    assert math.isnan(out["MR [N*mm]"].iat[1])


def test_unknown_model_argument_is_refused():
    from bearingheat.calc.table import calc
    from bearingheat.errors import ModelError

    with pytest.raises(ModelError) as exc:
        calc(_rows(), model="palmgren")
    assert str(exc.value) == "model: 'palmgren' is not one of schaeffler, skf"


def test_friction_torque_model_argument():
    import pint

    from bearingheat.api.friction import friction_torque
    from bearingheat.errors import ModelError

    u = pint.get_application_registry()
    args = dict(d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath", n=3000 * u.rpm,
                Fr=2 * u.kN, nu=12 * u("mm^2/s"))
    assert friction_torque("6205", model="schaeffler", **args).MR.to("N*mm").magnitude == pytest.approx(47.535,
                                                                                                        abs=5e-4)
    with pytest.raises(ModelError) as exc:
        friction_torque("6205", model="palmgren", **args)
    assert str(exc.value) == "model: 'palmgren' is not one of schaeffler, skf"
