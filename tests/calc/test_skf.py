"""The SKF model's evaluation over support arrays: the worked example, hand calculations, every bad input.

Hand calculations type the catalogue's constants (SKF General Catalogue 6000 RU,
tables 3-5, pp. 92-98; SKF 10000/3 pp. 110-111) and work the formulas out in
plain arithmetic, independently of the kernels.
"""
import math

import numpy as np
import pandas as pd
import pytest

from bearingheat.calc.messages import Labels
from bearingheat.calc.models import model_inputs
from bearingheat.calc.skf import EXTRA_INPUTS, RESULTS, evaluate_skf_model
from bearingheat.calc.supports import NUMBER_INPUTS, build_support_arrays

#: headers of the new columns, fixed here so that the messages do not depend on the column contract
LABELS = Labels(headers={
    "oil_level": ("oil_level [mm]", 1.0), "VM": ("VM", 1.0), "d_s": ("d_s [mm]", 1.0), "seal": ("seal", 1.0),
    "seals": ("seals", 1.0), "skf_edition": ("skf_edition", 1.0), "oil": ("oil", 1.0), "mu_sl": ("mu_sl", 1.0),
    "mu_bl": ("mu_bl", 1.0), "Dw": ("Dw [mm]", 1.0), "T": ("T [mm]", 1.0), "lubrication": ("lubrication", 1.0),
})

EXAMPLE = dict(designation="22208 E", d=40.0, D=80.0, B=23.0, Fr=2990.0, Fa=100.0, n=3500.0, nu=68.0,
               lubrication="oil_bath", oil_level=2.5, VM=0.3e-4, skf_edition="6000", mu_sl=0.05)


def run(*rows, labels=LABELS):
    """Evaluate table rows (dicts of input columns); returns (results, {row: [(level, message)]})."""
    frame = pd.DataFrame(list(rows))
    keys = frame[[c for c in ("designation", "type", "series", "lubrication") if c in frame.columns]]
    numbers = {c: pd.to_numeric(frame[c], errors="coerce").to_numpy(dtype=float)
               for c in NUMBER_INPUTS if c in frame.columns}
    supports = build_support_arrays(keys, numbers)
    extra = {c: frame[c].to_numpy(dtype=object) for c in EXTRA_INPUTS if c in frame.columns}
    with np.errstate(all="ignore"):
        results, problems = evaluate_skf_model(supports, labels, None, extra)
    messages = {}
    for p in problems:
        for i in np.flatnonzero(p.mask):
            messages.setdefault(int(i), []).append((p.level, p.message(int(i))))
    return results, messages


def test_worked_example_of_the_catalogue():
    results, messages = run(EXAMPLE)
    assert messages == {}
    r = {k: float(v[0]) for k, v in results.items()}
    assert r["MR"] == pytest.approx(334, rel=0.01)                  # printed 334 (6000 p. 105)
    assert round(r["G_rr"], 2) == 0.26 and round(r["G_sl"]) == 434
    assert round(r["M_sl"], 1) == 21.7 and round(r["M_drag"], 1) == 14.5
    assert round(r["phi_ish"], 2) == 0.85 and round(r["phi_rs"], 1) == 0.8
    assert r["mu_sl"] == 0.05 and r["M_seal"] == 0.0
    assert r["M_rr"] == pytest.approx(0.25846590 * (68 * 3500) ** 0.6, rel=1e-7)
    assert r["NR"] == pytest.approx(r["MR"] * 3500 / 9550)
    assert set(RESULTS) >= {"M_rr", "M_sl", "M_seal", "M_drag", "phi_ish", "phi_rs", "mu_sl", "M_start", "MR", "NR"}


def test_worked_example_with_mu_sl_from_the_film_is_the_same():
    """At ν·n = 238 000 φbl is 0, so μsl = μEHL = 0.05 for mineral oil, as the example assumes."""
    full, _ = run(EXAMPLE)
    free, _ = run({**EXAMPLE, "mu_sl": None})
    assert float(free["mu_sl"][0]) == 0.05 and float(free["MR"][0]) == pytest.approx(float(full["MR"][0]))


def hand(Grr, Gsl, d, D, n, nu, Kz, Krs, mu_ehl, M_seal=0.0, M_drag=0.0):
    dm = (d + D) / 2
    ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    rs = math.exp(-Krs * nu * n * (d + D) * math.sqrt(Kz / (2 * (D - d))))
    bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu = bl * 0.15 + (1 - bl) * mu_ehl
    return ish * rs * Grr * (nu * n) ** 0.6 + Gsl * mu + M_seal + M_drag


def test_sealed_deep_groove_ball_bearing_in_grease_by_hand():
    row = dict(designation="6205-2RSH", d=25.0, D=52.0, C0=7800.0, Fr=1000.0, Fa=0.0, n=2000.0, nu=40.0,
               lubrication="grease", d_s=31.0)
    results, messages = run(row)
    assert messages == {}
    dm = 38.5
    Grr = 3.9e-7 * dm ** 1.96 * 1000 ** 0.54                   # table 3a, series 62
    Gsl = 3.23e-3 * dm ** -0.26 * 1000 ** (5 / 3)
    M_seal = 0.028 * 31 ** 2.25 + 2                            # table 4, RSH, D <= 52: both seals
    assert float(results["M_seal"][0]) == pytest.approx(M_seal, rel=1e-12)
    assert float(results["MR"][0]) == pytest.approx(hand(Grr, Gsl, 25, 52, 2000, 40, 3.1, 6e-8, 0.05, M_seal),
                                                    rel=1e-12)
    assert float(results["M_start"][0]) == pytest.approx(Gsl * 0.15 + M_seal, rel=1e-12)   # μsl = μbl at start


def test_one_seal_and_the_rsl_exception():
    base = dict(designation="6205", d=25.0, D=52.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease", d_s=31.0)
    results, messages = run({**base, "seal": "RSH", "seals": 1}, {**base, "seal": "RSL", "seals": 1},
                            {**base, "designation": "6205-RSL"}, {**base, "designation": "6205-2RSL"},
                            {**base, "designation": "6205-2RZ"}, {**base, "designation": "6205-2Z"})
    assert messages == {}
    rsh = 0.028 * 31 ** 2.25 + 2
    rsl = 0.0018 * 31 ** 2.25 + 0
    assert results["M_seal"].tolist() == pytest.approx([0.5 * rsh, rsl, rsl, rsl, 0.0, 0.0], rel=1e-12)


def test_angular_contact_starting_torque_takes_gsl_at_standstill():
    row = dict(designation="7205 BE", d=25.0, D=52.0, Fr=1000.0, Fa=500.0, n=6000.0, nu=20.0, lubrication="oil_mist")
    results, messages = run(row)
    assert messages == {}
    dm = 38.5
    Gsl_0 = 1.30e-2 * dm ** 0.26 * (1000 ** (4 / 3) + 0.68 * 500 ** (4 / 3))        # Fg = 0 at n = 0
    assert float(results["M_start"][0]) == pytest.approx(0.15 * Gsl_0, rel=1e-12)
    Fg = 1.91e-12 * dm ** 4 * 6000 ** 2
    assert float(results["G_sl"][0]) == pytest.approx(
        1.30e-2 * dm ** 0.26 * ((1000 + Fg) ** (4 / 3) + 0.68 * 500 ** (4 / 3)), rel=1e-12)


def test_a_pair_is_two_bearings_each_at_half_the_radial_load():
    """The SKF model is of one bearing; a pair's moments are the sums of its two bearings' (Fa = 0)."""
    row = dict(designation="7210-B", d=50.0, D=90.0, Fr=2000.0, n=3000.0, nu=22.0, lubrication="grease")
    pair, messages = run({**row, "arrangement": "paired"})
    assert messages == {}
    one, _ = run({**row, "Fr": 1000.0})
    for name in ("M_rr", "M_sl", "M_seal", "M_drag", "M_start", "MR", "NR"):
        assert float(pair[name][0]) == pytest.approx(2 * float(one[name][0]), rel=1e-15), name
    for name in ("G_rr", "G_sl", "phi_ish", "phi_rs", "phi_bl", "mu_sl"):
        assert float(pair[name][0]) == float(one[name][0]), name
    # by hand: table 3 (6000 p. 92), angular contact ball bearings: R1 5.03e-7, R3 1.90e-12, S1 1.30e-2,
    # S3 1.91e-12; Kz = 4.4 (table 5); each bearing at Fr = 1000 N
    dm, n = 70.0, 3000.0
    Grr = 5.03e-7 * dm ** 1.97 * (1000 + 1.90e-12 * dm ** 4 * n ** 2) ** 0.54
    Gsl = 1.30e-2 * dm ** 0.26 * (1000 + 1.91e-12 * dm ** 4 * n ** 2) ** (4 / 3)
    assert float(pair["MR"][0]) == pytest.approx(2 * hand(Grr, Gsl, 50, 90, n, 22, 4.4, 6e-8, 0.05), rel=1e-12)


def test_a_pair_has_the_seals_and_the_drag_of_both_bearings():
    sealed = dict(designation="6205-2RSH", d=25.0, D=52.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease",
                  d_s=31.0, arrangement="paired")
    results, messages = run(sealed, {**EXAMPLE, "Fa": 0.0, "arrangement": "paired"})
    assert messages == {}
    rsh = 0.028 * 31 ** 2.25 + 2                     # table 4, RSH, D <= 52: both seals of one bearing
    assert results["M_seal"].tolist() == pytest.approx([2 * rsh, 0.0], rel=1e-12)
    one, _ = run({**EXAMPLE, "Fa": 0.0, "Fr": 1495.0})
    assert float(results["M_drag"][1]) == pytest.approx(2 * 14.4598608, rel=1e-7)     # the example's drag, twice
    assert float(results["MR"][1]) == pytest.approx(2 * float(one["MR"][0]), rel=1e-15)


def test_a_pair_under_axial_load_or_an_unknown_arrangement_is_refused():
    row = dict(designation="7210-B", d=50.0, D=90.0, Fr=2000.0, Fa=500.0, n=3000.0, nu=22.0, lubrication="grease")
    results, messages = run({**row, "arrangement": "paired"}, {**row, "arrangement": "tandem"},
                            {**row, "arrangement": None})
    assert messages == {
        0: [("error", "Fa [N]: 500 on a pair: how a pair shares an axial load depends on its arrangement and "
                      "preload, which the SKF model does not cover; give the two bearings as two rows, each with the "
                      "loads it carries, or use the catalogue model (model = schaeffler)")],
        1: [("error", "arrangement: 'tandem' is not one of single, paired")]}
    assert float(results["MR"][2]) > 0                   # blank: a single bearing


def test_oil_bath_drag_of_the_2017_edition_by_hand():
    results, messages = run({**EXAMPLE, "skf_edition": "10000", "VM": 1.5e-4})
    assert messages == {}
    d, D, B, dm, n, nu, H, Kz, KL = 40, 80, 23, 60, 3500, 68, 2.5, 5.5, 0.8
    K_roll = KL * Kz * (d + D) / (D - d) * 1e-12
    lD = 5 * KL * B / dm
    Cw = 2.789e-10 * lD ** 3 - 2.786e-4 * lD ** 2 + 0.0195 * lD + 0.6439
    t = 2 * math.acos((0.6 * dm - H) / (0.6 * dm))
    ft = math.sin(0.5 * t)
    Rs = 0.36 * dm ** 2 * (t - math.sin(t)) * 0.05 * Kz * (D + d) / (D - d)
    drag = 4 * 1.5e-4 * K_roll * Cw * B * dm ** 4 * n ** 2 + 1.093e-7 * n ** 2 * dm ** 3 * (
        n * dm ** 2 * ft / nu) ** -1.379 * Rs
    assert float(results["M_drag"][0]) == pytest.approx(drag, rel=1e-12)


def test_tapered_roller_bearing_drag_of_2017_uses_t():
    row = dict(designation="30205", d=25.0, D=52.0, B=15.0, T=16.25, Y=1.6, Fr=4000.0, Fa=1000.0, n=2000.0,
               nu=32.0, lubrication="oil_bath", oil_level=3.0, VM=2e-4)
    results, messages = run(row)
    assert messages == {}
    d, D, dm, n, nu, H, Kz, KL, T = 25, 52, 38.5, 2000, 32, 3.0, 6, 0.7, 16.25
    K_roll = KL * Kz * (d + D) / (D - d) * 1e-12
    lD = 5 * KL * T / dm
    Cw = 2.789e-10 * lD ** 3 - 2.786e-4 * lD ** 2 + 0.0195 * lD + 0.6439
    t = 2 * math.acos((0.6 * dm - H) / (0.6 * dm))
    Rs = 0.36 * dm ** 2 * (t - math.sin(t)) * 0.05 * Kz * (D + d) / (D - d)
    drag = 4 * 2e-4 * K_roll * Cw * T * dm ** 4 * n ** 2 + 1.093e-7 * n ** 2 * dm ** 3 * (
        n * dm ** 2 * math.sin(0.5 * t) / nu) ** -1.379 * Rs
    assert float(results["M_drag"][0]) == pytest.approx(drag, rel=1e-12)
    Grr = 1.76e-6 * dm ** 2.38 * (4000 + 10.9 * 1.6 * 1000) ** 0.31
    Gsl = 0.017 * dm ** 0.82 * (4000 + 2 * 1.6 * 1000)
    assert float(results["MR"][0]) == pytest.approx(hand(Grr, Gsl, d, D, n, nu, Kz, 3e-8, 0.002, 0, drag), rel=1e-12)


def test_a_double_row_series_given_as_type_and_series_has_the_drag_of_its_designation():
    """6000 p. 99: Mdrag = VM·Kball·dm⁵·n², Kball = irw·Kz·(d + D)/(D − d)·10⁻¹²; irw = 2 for series 42 and 522."""
    bath = dict(Fr=2000.0, n=3000.0, nu=20.0, lubrication="oil_bath", oil_level=3.0, VM=5e-5, skf_edition="6000")
    deep = dict(bath, d=40.0, D=90.0, B=23.0)
    thrust = dict(bath, d=40.0, D=90.0, Fr=0.0, Fa=2000.0)
    results, messages = run({**deep, "designation": "4208"}, {**deep, "type": "deep_groove_ball", "series": "42"},
                            {**thrust, "designation": "52208"}, {**thrust, "type": "thrust_ball", "series": "522"})
    assert messages == {}
    dm = 65.0
    deep_drag = 5e-5 * (2 * 3.1 * 130 / 50 * 1e-12) * dm ** 5 * 3000 ** 2      # Kz = 3.1, table 5
    thrust_drag = 5e-5 * (2 * 3.8 * 130 / 50 * 1e-12) * dm ** 5 * 3000 ** 2    # Kz = 3.8, table 5
    assert results["M_drag"].tolist() == pytest.approx([deep_drag] * 2 + [thrust_drag] * 2, rel=1e-12)


def test_oil_level_low_or_high():
    """Below the centre of the lowest rolling element: Krs = 3e-8; above it the text names no starvation."""
    results, _ = run(EXAMPLE, {**EXAMPLE, "oil_level": 10.0}, {**EXAMPLE, "oil_level": 6.0, "Dw": 14.0},
                     {**EXAMPLE, "oil_level": 6.0, "Dw": 11.0})
    phi_rs = results["phi_rs"].tolist()
    assert phi_rs[0] < 1 and phi_rs[1] == 1.0      # no Dw: H >= (D − d)/4 is above the centre
    # Dw given: H < Dw/2 is low, H >= Dw/2 is not (without Dw, 6 mm < (D − d)/4 = 10 mm would count as low)
    assert phi_rs[2] < 1 and phi_rs[3] == 1.0


def test_a_rolling_element_larger_than_the_ring_section_is_refused():
    # 22208 E: (D - d)/2 = 20 mm between bore and outside diameter; a 40 mm roller is a typing or unit slip
    results, messages = run({**EXAMPLE, "Dw": 40.0}, {**EXAMPLE, "Dw": 19.9})
    assert messages == {0: [("error", "Dw [mm]: 40 must be smaller than (D - d)/2 = 20, the section between bore "
                                      "and outside diameter")]}


def test_oil_jet_drag_is_twice_the_bath_drag_at_the_given_level():
    jet = {**EXAMPLE, "lubrication": "circulating_oil"}
    results, messages = run(EXAMPLE, jet, {**jet, "VM": None, "oil_level": None})
    assert messages == {}
    assert results["M_drag"].tolist() == pytest.approx([14.4598608, 2 * 14.4598608, 0.0], rel=1e-7)
    assert results["phi_rs"][0] == results["phi_rs"][1]      # Krs = 3e-8 for oil jet and a low bath


def test_grease_has_no_drag_and_warns_about_vm():
    _, messages = run({**EXAMPLE, "lubrication": "grease"})
    assert messages == {0: [("warning", "VM: ignored; there is drag only in an oil bath or with oil jet")]}


def test_one_bearing_at_many_points_equals_the_table_of_rows():
    n = np.array([500.0, 2000.0, 3500.0])
    frame_results, _ = run(*[{**EXAMPLE, "n": v} for v in n])
    keys = pd.DataFrame({"designation": ["22208 E"], "lubrication": ["oil_bath"]})
    supports = build_support_arrays(keys, dict(d=40.0, D=80.0, B=23.0, Fr=2990.0, Fa=100.0, n=n, nu=68.0))
    extra = dict(designation="22208 E", lubrication="oil_bath", oil_level=2.5, VM=0.3e-4, skf_edition=6000,
                 mu_sl=0.05)
    results, problems = evaluate_skf_model(supports, LABELS, None, extra)
    assert problems == []
    for name in RESULTS:
        np.testing.assert_allclose(results[name], frame_results[name], rtol=1e-14)


def test_mixed_table_of_every_type():
    rows = [
        dict(designation="6205", C0=7800.0, Fa=300.0),
        dict(designation="7205 BE", Fa=300.0),
        dict(designation="3205 A", Fa=300.0),
        dict(designation="QJ 205", Fa=300.0),
        dict(designation="1205"),
        dict(designation="NU 205 ECP"),
        dict(designation="NCF 3005", B=16.0),
        dict(designation="30205", Y=1.6, Fa=300.0),
        dict(designation="22205 E", Fa=300.0),
        dict(designation="C 2205"),
        dict(designation="51105", Fr=0.0, Fa=1000.0),
        dict(designation="81105", Fr=0.0, Fa=1000.0),
        dict(type="axial_spherical_roller", series="293 E", Fr=0.0, Fa=5000.0),
        dict(type="plain_bushing"),
    ]
    base = dict(d=25.0, D=52.0, Fr=1000.0, n=1500.0, nu=30.0, lubrication="grease")
    results, messages = run(*[{**base, **r} for r in rows])
    assert messages == {12: [("warning", "M_start of a spherical roller thrust bearing series 293 E may be up to 8 "
                                         "times Msl + Mseal (SKF 6000 p. 103; 10000/3 p. 114)")]}
    assert np.all(results["MR"][:-1] > 0) and np.isnan(results["MR"][-1])


ERRORS = [
    ({"seal": "RS2"},
     "seal: 'RS2' is not a seal type of SKF table 4; expected one of RSL, RZ, RSH, RS1, LS, CS, CS2, CS5"),
    ({"designation": "NA4905"},
     "type: needle roller bearings have no published constants in the SKF model (SKF 10000/3 p. 113 refers them "
     "to SKF's online calculation tools); use model 'schaeffler' for them"),
    ({"oil_level": None},
     "oil_level [mm]: missing; an oil bath needs the oil level H [mm] above the lowest contact point of the outer "
     "ring raceway (SKF 10000/3 p. 110, fig. 2)"),
    ({"VM": None},
     "VM: missing; an oil bath needs the drag loss factor VM: read it off SKF 6000 diagram 2 (p. 99; red curve ball "
     "bearings, blue roller bearings) for roller bearings at H/dm = 0.0417, or digitise the diagram (calc --vm-chart)"),
    ({"VM": None, "skf_edition": "10000"},
     "VM: missing; an oil bath needs the drag loss factor VM: read it off SKF 10000/3 diagram 4 (p. 112) for roller "
     "bearings at H/dm = 0.0417, or digitise the diagram (calc --vm-chart)"),
    ({"skf_edition": "10000", "nu": 600.0},
     "nu [mm^2/s]: 600 is above 500 mm²/s, the limit of the SKF 10000/3 drag formula for an oil level H <= D/2 "
     "(p. 110); use skf_edition 6000 or a thinner oil"),
    ({"skf_edition": "10000", "nu": 300.0, "oil_level": 45.0},
     "nu [mm^2/s]: 300 is above 250 mm²/s, the limit of the SKF 10000/3 drag formula for an oil level H > D/2 "
     "(p. 110); use skf_edition 6000 or a thinner oil"),
    ({"skf_edition": "2005"}, "skf_edition: '2005' is not one of 6000, 10000"),
    ({"lubrication": None}, "lubrication: missing; expected one of grease, oil_mist, oil_bath, circulating_oil"),
    ({"lubrication": "dry"}, "lubrication: 'dry' is not one of grease, oil_mist, oil_bath, circulating_oil"),
    ({"oil": "olive"}, "oil: 'olive' is not one of mineral, synthetic, transmission_fluid"),
    ({"B": None}, "B [mm]: missing; the drag 10·VM·Kroll·B·dm⁴·n² of a spherical roller bearing series 222 E needs "
                  "the inner ring width B (SKF 6000 p. 99)"),
    ({"B": None, "skf_edition": "10000"},
     "B [mm]: missing; the drag of a spherical roller bearing series 222 E needs the bearing width B (the height "
     "of a thrust bearing; SKF 10000/3 p. 111)"),
    ({"VM": -1e-4}, "VM: -0.0001 must be >= 0"),
    ({"oil_level": -1.0}, "oil_level [mm]: -1 must be >= 0"),
    ({"mu_sl": -0.1}, "mu_sl: -0.1 must be >= 0"),
    ({"seal": "RSH", "d_s": 50.0},
     "seal: RSH on a spherical roller bearing series 222 E: SKF table 4 (6000 p. 96) has RSH seals only for deep "
     "groove ball bearing"),
    ({"seal": "CS"},
     "d_s [mm]: missing; CS seals need the seal counterface diameter d_s (d2 in the bearing tables; SKF 6000 "
     "table 4, p. 96)"),
    ({"seals": 2},
     "seal: missing; seals = 2 needs the seal type, one of RSL, RZ, RSH, RS1, LS, CS, CS2, CS5 (SKF 6000 table 4, "
     "p. 96)"),
    ({"seal": "CS", "seals": 3, "d_s": 55.0}, "seals: 3 must be 0, 1 or 2"),
    ({"d": None, "designation": None, "type": "spherical_roller", "series": "222 E"},
     "d [mm]: missing; the bore d gives dm = 0.5 (d + D) (SKF 6000 p. 90)"),
]


@pytest.mark.parametrize("change, message", ERRORS, ids=[m[:40] for _, m in ERRORS])
def test_bad_input_is_an_error_naming_the_column_and_the_expected_value(change, message):
    _, messages = run({**EXAMPLE, **change})
    assert ("error", message) in messages[0], messages


def test_bad_input_of_other_bearings():
    ball = dict(designation="6205", d=25.0, D=52.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease")
    cases = [
        ({"Fa": 300.0}, "C0 [N]: missing; the axial load of a deep groove ball bearing needs C0 for "
                        "αF = 24.6·(Fa/C0)^0.24 (SKF 6000 p. 91, table 2a)"),
        ({"designation": "30205", "Fa": 300.0}, "Y: missing; the axial load of a tapered roller bearing needs its "
                                                "catalogue factor Y (SKF 6000 p. 91, table 2a)"),
        ({"designation": "6205-2RS"},
         "seal: missing; the designation's contact seal '2RS' is not a seal type of SKF table 4 (6000 p. 96); give "
         "seal as one of RSL, RZ, RSH, RS1, LS, CS, CS2, CS5, or seals = 0 to leave the seal friction out"),
        ({"designation": "6210-2RSH", "d": 50.0, "D": 90.0, "d_s": 60.0},
         "D [mm]: 90 is outside SKF table 4 (6000 p. 96) for RSH seals on a deep groove ball bearing series 62 "
         "(D <= 52 mm)"),
        ({"designation": "30205", "Y": 1.6, "lubrication": "oil_bath", "oil_level": 3.0, "VM": 1e-4, "B": 15.0},
         "T [mm]: missing; the drag of a tapered roller bearing needs the total width T (SKF 10000/3 p. 111)"),
        ({"designation": "C2208 V"},
         "type: CARB toroidal roller bearings without cage (suffix V) have no geometry constants in the SKF model "
         "(SKF 10000/3 p. 108, table 3f is for CARB bearings with cage)"),
        ({"D": 20.0}, "D [mm]: 20 must be larger than d [mm] = 25"),
        ({"n": None}, "n [1/min]: missing; the operating speed is needed"),
        ({"nu": 0.0}, "nu [mm^2/s]: 0 must be > 0"),
    ]
    for change, message in cases:
        _, messages = run({**ball, **change})
        assert ("error", message) in messages.get(0, []), (change, messages)
    _, messages = run({**ball, "designation": "6205-2RS", "seals": 0})
    assert messages == {}


def test_the_seal_range_message_quotes_the_range_of_its_own_seal_type():
    """Table 4 (6000 p. 96): RSH on deep groove ball bearings only for D <= 52 mm; RZ up to 175 mm. A row of RZ
    after a row of RSH must not lend the RSH message its range."""
    row = dict(designation="6208", d=40.0, D=80.0, Fr=1000.0, n=3000.0, nu=20.0, lubrication="grease")
    _, messages = run({**row, "seal": "RSH", "d_s": 50.0}, {**row, "seal": "RZ"})
    assert messages == {0: [("error", "D [mm]: 80 is outside SKF table 4 (6000 p. 96) for RSH seals on a deep groove "
                                      "ball bearing series 62 (D <= 52 mm)")]}


def test_a_missing_value_is_said_once_and_no_message_prints_nan():
    sealed = dict(designation="6205-2RSH", d=25.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease", d_s=31.0)
    _, messages = run(sealed)
    assert messages == {0: [("error", "D [mm]: missing; the outside diameter D gives dm = 0.5 (d + D) "
                                      "(SKF 6000 p. 90)")]}
    _, messages = run({**EXAMPLE, "oil_level": None, "VM": None})
    assert messages == {0: [
        ("error", "oil_level [mm]: missing; an oil bath needs the oil level H [mm] above the lowest contact point of "
                  "the outer ring raceway (SKF 10000/3 p. 110, fig. 2)"),
        ("error", "VM: missing; an oil bath needs the drag loss factor VM: read it off SKF 6000 diagram 2 (p. 99; red "
                  "curve ball bearings, blue roller bearings) for roller bearings, or digitise the diagram "
                  "(calc --vm-chart)")]}


def test_an_axial_load_on_a_bearing_with_a_ring_without_ribs_is_refused_as_the_catalogue_model_refuses_it():
    row = dict(d=40.0, D=80.0, Fr=4000.0, Fa=1500.0, n=1500.0, nu=40.0, lubrication="grease")
    designs = ("NU208-E", "N 208", "RNU 2210 ECJB", "NJ 208", "NUP 208", "NCF 2210 ECJB")
    results, messages = run(*[{**row, "designation": d} for d in designs])
    why = ("one ring has no ribs, the bearing takes no axial load (the term S1·dm^0.9·Fa of Gsl is the sliding at "
           "the ribs; SKF 6000 p. 91, table 2a)")
    assert messages == {
        0: [("error", f"Fa [N]: 1500 on NU cylindrical roller bearing with cage series 2: {why}")],
        1: [("error", f"Fa [N]: 1500 on N cylindrical roller bearing with cage series 2: {why}")],
        2: [("error", f"Fa [N]: 1500 on RNU cylindrical roller bearing with cage series 22 high capacity: {why}")]}
    assert np.all(results["MR"][3:] > 0)      # a rib on each ring (NJ, NUP) or ribs on one side (NCF) take Fa
    _, messages = run({**row, "designation": "NU208-E", "Fa": 0.0})
    assert messages == {}


def test_a_seal_counterface_diameter_outside_the_bearing_is_refused():
    row = dict(designation="6205-2RSH", d=25.0, D=52.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease")
    results, messages = run(*[{**row, "d_s": d_s} for d_s in (300.0, 25.0, 52.0, 31.0)])
    why = "the seal counterface diameter is d1, d2 or E of the bearing tables (SKF 6000 table 4, p. 96)"
    assert messages == {
        0: [("error", f"d_s [mm]: 300 must lie between d [mm] = 25 and D [mm] = 52: {why}")],
        1: [("error", f"d_s [mm]: 25 must lie between d [mm] = 25 and D [mm] = 52: {why}")],
        2: [("error", f"d_s [mm]: 52 must lie between d [mm] = 25 and D [mm] = 52: {why}")]}
    assert float(results["M_seal"][3]) == pytest.approx(0.028 * 31 ** 2.25 + 2, rel=1e-12)   # table 4, RSH


def test_warnings():
    ball = dict(designation="6205", d=25.0, D=52.0, Fr=1000.0, n=2000.0, nu=40.0, lubrication="grease")
    cases = [
        ({"designation": "31305", "Y": 0.7, "Fa": 100.0},
         "M_start of a tapered roller bearing series 313 may be up to 4 times Msl + Mseal (SKF 6000 p. 103; "
         "10000/3 p. 114)"),
        ({"designation": None, "type": "tapered_roller", "series": "T7FC"},
         "M_start of a tapered roller bearing series other may be up to 4 times Msl + Mseal (SKF 6000 p. 103; "
         "10000/3 p. 114)"),
        ({"designation": "T7FC 045", "d": 45.0, "D": 95.0},
         "M_start of a tapered roller bearing series other may be up to 4 times Msl + Mseal (SKF 6000 p. 103; "
         "10000/3 p. 114)"),
        ({"lubrication": "oil_mist", "nu": 1.5},
         "nu [mm^2/s]: 1.5 is outside 2 to 500 mm²/s, the range of the SKF model for oil lubrication "
         "(SKF 10000/3 p. 100)"),
        ({"designation": "51105", "d": 25.0, "D": 42.0, "Fa": 2000.0},
         "Fr [N]: 1000 on a thrust ball bearing: its formulas (SKF 6000 p. 92, table 2b) use Fa only"),
        ({"designation": "C 2205", "Fa": 200.0},
         "Fa [N]: 200 on a CARB toroidal roller bearing with cage series C 22: CARB bearings take no axial load; "
         "their formulas (SKF 6000 p. 91, table 2a) use Fr only"),
    ]
    for change, message in cases:
        _, messages = run({**ball, **change})
        assert messages == {0: [("warning", message)]}, (change, messages)


def test_results_are_float_arrays_of_the_rows_length():
    results, _ = run(EXAMPLE, {**EXAMPLE, "designation": "NA4905"})
    assert set(results) == set(RESULTS)
    for values in results.values():
        assert values.shape == (2,) and values.dtype == float
    assert np.isnan(results["MR"][1])


def test_extra_inputs_of_a_table():
    frame = pd.DataFrame([{**EXAMPLE, "skf_edition": 6000.0, "VM": "3e-05", "id": "A"}])
    extra = model_inputs(frame)
    assert "id" not in extra and "d" not in extra
    assert extra["VM"].tolist() == [3e-05]
    keys = frame[["designation", "lubrication"]]
    supports = build_support_arrays(keys, {c: frame[c].to_numpy(dtype=float) for c in ("d", "D", "B", "Fr", "Fa",
                                                                                         "n", "nu")})
    results, problems = evaluate_skf_model(supports, LABELS, None, extra)
    assert problems == [] and float(results["MR"][0]) == pytest.approx(331.075, abs=1e-3)
