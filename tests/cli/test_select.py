"""``bearingheat select`` and ``bh.bearings_with_bore``: the bearings of the table for a shaft, ranked at an
operating point; hand calculations of the catalogue model, exact messages, files and exit codes."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import openpyxl
import pandas as pd
import pint
import pytest
from PIL import Image

import bearingheat as bh
from bearingheat.catalogue.bearings import FAMILIES, SHIELDS
from bearingheat.cli import main
from bearingheat.cli.select import PLOTTED
from bearingheat.errors import DesignationError, InputError, SelectionError, UnitError

u = pint.get_application_registry()
#: deep groove ball bearings of bore 40 mm, open, D <= 80 mm (HR 1, 2006, pp. 198-205)
OPEN_BALL_40 = ["61908", "16008", "6008", "6208"]
POINT = ["--n", "6000rpm", "--Fr", "2kN", "--nu", "20mm^2/s", "--lubrication", "oil_bath"]


def _torque(f0: float, f1_a: float, C0: float, d: float, D: float, Fr: float, nu: float, n: float) -> float:
    """M_R = M0 + M1 of a radial ball bearing without axial load, by hand (the Schaeffler catalogue, pp. 64-68):
    M0 = f0 (nu n)^(2/3) dM^3 1e-7 for nu n >= 2000; P0 = P1 = Fr; f1 = f1_a (P0/C0)^0.5; M1 = f1 P1 dM."""
    dM = (d + D) / 2
    return f0 * math.pow(nu * n, 2 / 3) * dM ** 3 * 1e-7 + f1_a * math.sqrt(Fr / C0) * Fr * dM


def test_the_candidates_of_a_bore_in_catalogue_order(capsys):
    assert main(["select", "--d", "40mm", "--D-max", "62mm"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "4 candidates (catalogue order)",
        "designation  D [mm]  B [mm]  C0 [N]  n_G [1/min]  n_thr_catalogue [1/min]",
        "      61908      62      12   10000        28000                    10000",
        " 61908-2RSR      62      12   10000         7000                        -",
        "   61908-2Z      62      12   10000        11000                    10000",
        "71808-B-TVH      52       7    5850        13000                        -",
    ]


def test_a_bore_in_inches_and_the_filters():
    found = bh.bearings_with_bore(1.5748 * u.inch, D_max=80 * u.mm, family="deep groove ball", shield="open")
    assert found["designation"].tolist() == OPEN_BALL_40
    tapered = bh.bearings_with_bore(40 * u.mm, B_max=20 * u.mm, family=["tapered roller"])
    assert tapered["designation"].tolist() == ["32008-XA", "30208-A"]  # by T: 19 and 19.75 mm; 32208-A has 24.75
    assert set(FAMILIES) == set(bh.bearing_table()["family"]) and set(SHIELDS) == set(bh.bearing_table()["shield"])


def test_ranked_by_power_loss_with_hand_calculations(capsys):
    assert main(["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *POINT, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    # f0 (oil) and f1_a of the Schaeffler catalogue p. 66: 619 1.7/0.0007, 160 and 60 1.7/0.0007, 62 2/0.0009
    by_hand = {"61908": _torque(1.7, 0.0007, 10000, 40, 62, 2000, 20, 6000),
               "16008": _torque(1.7, 0.0007, 10200, 40, 68, 2000, 20, 6000),
               "6008": _torque(1.7, 0.0007, 11600, 40, 68, 2000, 20, 6000),
               "6208": _torque(2.0, 0.0009, 18000, 40, 80, 2000, 20, 6000)}
    assert [r["designation"] for r in rows] == sorted(by_hand, key=by_hand.get)  # the least power loss first
    for row in rows:
        assert row["MR [N*mm]"] == pytest.approx(by_hand[row["designation"]], rel=1e-12)
        assert row["NR [W]"] == pytest.approx(by_hand[row["designation"]] * 6000 / 9550, rel=1e-12)
        assert row["status"] == "ok" and row["d [mm]"] == 40
    assert rows[0]["designation"] == "61908" and round(rows[0]["MR [N*mm]"], 2) == 86.79


def test_the_same_results_as_calc_of_each_designation_and_the_margin_of_the_heat_balance(tmp_path):
    out = tmp_path / "candidates.csv"
    assert main(["select", "--d", "40mm", "--D-max", "90mm", *POINT, "--Fa", "0.5kN", "--T-amb", "20degC",
                 "--T-bearing", "70degC", "-o", str(out), "-q"]) == 0
    ranked = pd.read_csv(out, keep_default_na=False, na_values=[""])
    supports = pd.DataFrame({"designation": ranked["designation"], "lubrication": "oil_bath", "n [1/min]": 6000.0,
                             "Fr [N]": 2000.0, "Fa [N]": 500.0, "nu [mm^2/s]": 20.0, "T_amb [degC]": 20.0,
                             "T_bearing [degC]": 70.0})
    alone = bh.calc(supports)
    for name in ("MR [N*mm]", "NR [W]", "n_thr [1/min]", "n_per [1/min]", "T_op [degC]"):
        np.testing.assert_allclose(ranked[name].to_numpy(float), alone[name].to_numpy(float), rtol=1e-12,
                                   equal_nan=True, err_msg=name)
    assert ranked["status"].tolist() == alone["status"].tolist()
    np.testing.assert_allclose(ranked["n_per/n"], ranked["n_per [1/min]"] / 6000.0, rtol=1e-15)
    computed = ranked[ranked["status"] != "error"]
    assert (np.diff(computed["NR [W]"].to_numpy()) >= 0).all() and len(computed) == 31
    # the bearings that cannot run here come last: NU and N without ribs under Fa, NJ and NUP without f2, 622 and
    # 623 without an f0 for oil
    failed = ranked[ranked["status"] == "error"]
    assert failed.index.min() == len(computed) and len(failed) == 17
    assert failed.loc[failed["designation"] == "NU208-E-TVP2", "message"].item() == (
        "Fa [N]: 500 on NU cylindrical roller bearing with cage series 2: one ring has no ribs, the bearing takes "
        "no axial load")
    assert main(["select", "--d", "40mm", *POINT, "-o", str(out)]) == 2  # the file exists: not replaced


def test_no_candidate_computed_is_exit_code_1(capsys):
    assert main(["select", "--d", "40mm", "--family", "cylindrical roller", *POINT, "--Fa", "1kN"]) == 1
    assert capsys.readouterr().out.splitlines()[-1] == "15 candidates: 0 ok, 0 warning, 15 error"


@pytest.mark.parametrize(("arguments", "message"), [
    (["--d", "40"], "--d: '40' has no unit; write it with one, e.g. 40mm"),
    (["--d", "41mm"], "d = 41 mm: no bearing of the bearing table (Schaeffler HR 1, 2006) has this bore; the nearest "
                      "bores: 40, 45 mm"),
    (["--d", "40mm", "--D-max", "50mm"],
     "d = 40 mm: none of the 48 bearings of this bore in the bearing table (Schaeffler HR 1, 2006) has D <= 50 mm "
     "(they have D 52-90 mm, width 7-35.25 mm; families: deep groove ball, angular contact ball, cylindrical roller, "
     "tapered roller; shields: open, 2RSR, 2Z, 2RS)"),
    (["--d", "40mm", "--n", "6000rpm"], "the operating point (--n) needs --nu (or the oil: --iso-vg, or --nu40 and "
                                        "--nu100) and --lubrication too"),
    (["--d", "40mm", *POINT[:2], "--Fr=-2kN", *POINT[4:]], "Fr: -2 kN must be >= 0"),
    (["--d", "40mm", *POINT[:4], "--nu", "0cSt", *POINT[6:]], "nu: 0 cSt must be > 0"),
    (["--d", "40mm", *POINT, "--T-amb", "250degC", "--T-bearing", "70degC"],
     "T_amb: 250 °C is outside the valid range -60 to 200 degC"),
    (["--d", "40mm", "--n", "6000kN", *POINT[2:]], "n: 6000 kilonewton is not a shaft speed; expected revolutions "
                                                    "per time (1/min, rpm, Hz) or an angular speed (rad/s)"),
])
def test_unusable_input_is_named(capsys, arguments, message):
    assert main(["select", *arguments]) == 2
    assert capsys.readouterr().err == f"bearingheat select: error: {message}\n"


def test_the_api_refuses_a_plain_number_and_an_unknown_family():
    with pytest.raises(UnitError) as exc:
        bh.bearings_with_bore(40)
    assert str(exc.value).startswith("d: ")
    with pytest.raises(DesignationError) as exc:
        bh.bearings_with_bore(40 * u.mm, family="ball")
    assert str(exc.value) == ("family: 'ball' is none of the bearing table's: deep groove ball, angular contact ball, "
                              "cylindrical roller, tapered roller")


def test_the_api_takes_one_bore():
    with pytest.raises(InputError) as exc:
        bh.bearings_with_bore([40, 45] * u.mm)
    assert str(exc.value) == "d: give one length, e.g. 40 * u.mm; got 2 values"


HEAT = ["--T-amb", "20degC", "--T-bearing", "70degC"]


@pytest.mark.parametrize(("rank_by", "column", "largest_first"), [("T_op", "T_op [degC]", False),
                                                                   ("n_per", "n_per [1/min]", True)])
def test_ranked_by_the_heat_balance(capsys, rank_by, column, largest_first):
    """The least power loss is not the coolest bearing: 61908 makes the least heat at 6000 1/min, 6008 gives off
    more and runs coolest (57.2 degC against 64.3 degC)."""
    assert main(["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *POINT, *HEAT, "--rank-by", rank_by, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    values = [row[column] for row in rows]
    assert values == sorted(values, reverse=largest_first)
    assert [row["designation"] for row in rows] == ["6008", "6208", "61908", "16008"]
    assert round(rows[0]["T_op [degC]"], 2) == 57.24 and round(rows[2]["T_op [degC]"], 2) == 64.32


def test_a_sealed_bearing_without_heat_balance_comes_last_when_ranked_by_it(capsys):
    assert main(["select", "--d", "40mm", "--D-max", "62mm", "--family", "deep groove ball", *POINT, *HEAT,
                 "--rank-by", "T_op", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [(row["designation"], row["status"]) for row in rows] == [
        ("61908", "ok"), ("61908-2Z", "ok"), ("61908-2RSR", "warning")]
    assert rows[-1]["T_op [degC]"] is None


def test_ranking_by_the_heat_balance_needs_its_temperatures(capsys):
    assert main(["select", "--d", "40mm", *POINT, "--rank-by", "n_per"]) == 2
    assert capsys.readouterr().err == ("bearingheat select: error: --rank-by n_per needs the heat balance: give "
                                       "--T-amb and --T-bearing\n")


def test_the_candidates_into_a_new_workbook(tmp_path, capsys):
    out = tmp_path / "candidates.xlsx"
    arguments = ["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *POINT, *HEAT, "--rank-by", "T_op"]
    assert main([*arguments, "-o", str(out), "-q"]) == 0
    assert capsys.readouterr().out == ""
    sheet = openpyxl.load_workbook(out)["Results"]
    header, units = ([cell.value for cell in row] for row in sheet.iter_rows(min_row=1, max_row=2))
    assert (units[header.index("NR")], units[header.index("T_op")], units[header.index("n_per/n")]) == (
        "W", "degC", "1")
    designations = [row[0].value for row in sheet.iter_rows(min_row=3)]
    assert designations == ["6008", "6208", "61908", "16008"]


def test_the_skf_model_in_an_oil_bath_with_the_oil_level_and_the_vm_chart(capsys):
    chart = str(Path(__file__).resolve().parents[2] / "docs" / "vm_chart_example.csv")
    assert main(["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *POINT, "--model", "skf", "--oil-level", "10mm", "--vm-chart", chart, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    supports = pd.DataFrame({"designation": [row["designation"] for row in rows], "lubrication": "oil_bath",
                             "model": "skf", "n [rpm]": 6000.0, "Fr [kN]": 2.0, "nu [cSt]": 20.0,
                             "oil_level [mm]": 10.0})
    alone = bh.calc(supports, vm_chart=chart)
    np.testing.assert_allclose([row["MR [N*mm]"] for row in rows], alone["MR [N*mm]"], rtol=1e-12)
    assert [row["model"] for row in rows] == ["skf"] * 4 and all(row["status"] == "ok" for row in rows)


def test_the_temperature_curves_of_the_leading_candidates(tmp_path):
    figure = tmp_path / "candidates.png"
    arguments = ["select", "--d", "40mm", "--D-max", "90mm", *POINT, *HEAT, "--rank-by", "T_op"]
    assert main([*arguments, "--plot", str(figure), "-q"]) == 0
    with Image.open(figure) as image:
        assert image.size == (1800, 810)
    found = bh.bearings_with_bore(40 * u.mm, D_max=90 * u.mm)
    ranked = bh.rank_bearings(found, lubrication="oil_bath", n=6000 * u.rpm, nu=20 * u.cSt, Fr=2 * u.kN,
                              T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"), rank_by="T_op")
    curves = bh.temperature_curves(ranked, count=PLOTTED)
    names = list(curves["T_op"])
    # alike bearings share one curve, named by all of them, in the order of the ranking
    assert names[:2] == ["6008, 6008-2Z", "N308-E-TVP2, NU308-E-TVP2, NJ308-E-TVP2, NUP308-E-TVP2"]
    assert len(names) == PLOTTED
    speeds = curves["speeds"]
    for name, temperatures in curves["T_op"].items():
        running = temperatures[np.isfinite(temperatures)]
        assert (np.diff(running) > 0).all(), name  # hotter the faster it runs
        n_per = curves["n_per"][name]  # calc's n_per: where the curve crosses T_bearing
        below, above = temperatures[speeds < n_per][-1], temperatures[speeds > n_per][0]
        assert below < 70.0 < above, name
    # N308-E-TVP2 stops at its n_G of 7500 1/min
    assert np.isnan(curves["T_op"][names[1]][speeds > 7500]).all()
    assert np.isfinite(curves["T_op"][names[1]][speeds <= 7500]).all()


@pytest.mark.parametrize(("extra", "message"), [
    (["--plot", "c.png"], "--plot draws T_op against speed: give the operating point (--n, the viscosity, "
                          "--lubrication) and --T-amb and --T-bearing"),
    (["--plot", "c.txt", *HEAT], "c.txt: a figure is written as .png, .svg, .svgz, .pdf, .eps, .ps, .jpg, .jpeg, .tif, "
                                 ".tiff, .webp; name it e.g. candidates.png"),
])
def test_the_plot_needs_the_heat_balance_and_a_figure_format(tmp_path, monkeypatch, capsys, extra, message):
    monkeypatch.chdir(tmp_path)
    assert main(["select", "--d", "40mm", *POINT, *extra]) == 2
    assert capsys.readouterr().err == f"bearingheat select: error: {message}\n"
    assert list(tmp_path.iterdir()) == []


def test_no_range_of_speeds_to_draw_at_standstill_without_n_per():
    ranked = pd.DataFrame({"designation": ["6208"], "lubrication": ["oil_bath"], "model": ["schaeffler"],
                           "n [1/min]": [0.0], "Fr [N]": [2000.0], "Fa [N]": [0.0], "nu [mm^2/s]": [20.0],
                           "T_amb [degC]": [20.0], "T_bearing [degC]": [70.0], "T_op [degC]": [20.0],
                           "n_per [1/min]": [np.nan], "n_G [1/min]": [20000.0]})
    with pytest.raises(SelectionError) as exc:
        bh.temperature_curves(ranked)
    assert str(exc.value) == ("at n = 0 without a permissible speed n_per of any candidate there is no range of "
                              "speeds to draw; give the operating speed")


@pytest.mark.parametrize(("options", "message"), [
    ({"rank_by": "MR"}, "rank_by: 'MR' is none of NR, T_op, n_per"),
    ({"rank_by": "T_op"}, "rank_by T_op needs the heat balance: give T_amb and T_bearing"),
    ({"n": [3000, 6000] * u.rpm}, "n: give one value (one operating point); got 2 values"),
    ({"Fa": -1 * u.N}, "Fa: -1 N must be >= 0"),
])
def test_rank_bearings_refuses_what_it_cannot_use(options, message):
    found = bh.bearings_with_bore(40 * u.mm, D_max=62 * u.mm)
    arguments = {"lubrication": "grease", "n": 6000 * u.rpm, "nu": 20 * u.cSt, **options}
    with pytest.raises(SelectionError) as exc:
        bh.rank_bearings(found, **arguments)
    assert str(exc.value) == message


def _walther(nu40: float, nu100: float, theta: float) -> float:
    """ν at ``theta`` [°C] on the ASTM D341 line through ν40 and ν100, by hand:
    log10 log10(ν + 0.7) = A - B log10(T [K])."""
    def z(nu):
        return math.log10(math.log10(nu + 0.7))
    B = (z(nu40) - z(nu100)) / (math.log10(373.15) - math.log10(313.15))
    A = z(nu40) + B * math.log10(313.15)
    return 10 ** 10 ** (A - B * math.log10(theta + 273.15)) - 0.7


OIL_POINT = ["--n", "6000rpm", "--Fr", "2kN", "--lubrication", "oil_bath"]


def test_an_oil_by_nu40_and_nu100_is_taken_at_t_bearing_without_t_amb(capsys):
    assert main(["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *OIL_POINT, "--nu40", "68cSt", "--nu100", "8.6mm^2/s", "--T-bearing", "70degC", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    nu = _walther(68.0, 8.6, 70.0)
    assert round(nu, 2) == 19.97  # an ISO VG 68 oil at 70 degC
    by_hand = {"61908": _torque(1.7, 0.0007, 10000, 40, 62, 2000, nu, 6000),
               "16008": _torque(1.7, 0.0007, 10200, 40, 68, 2000, nu, 6000),
               "6008": _torque(1.7, 0.0007, 11600, 40, 68, 2000, nu, 6000),
               "6208": _torque(2.0, 0.0009, 18000, 40, 80, 2000, nu, 6000)}
    assert [r["designation"] for r in rows] == sorted(by_hand, key=by_hand.get)
    for row in rows:
        assert row["nu_used [mm^2/s]"] == pytest.approx(nu, rel=1e-12) and row["nu_at"] == "T_bearing"
        assert row["MR [N*mm]"] == pytest.approx(by_hand[row["designation"]], rel=1e-12)
        assert (row["nu40 [mm^2/s]"], row["nu100 [mm^2/s]"]) == pytest.approx((68.0, 8.6), rel=1e-15)
        assert "nu [mm^2/s]" not in row


def test_an_iso_vg_oil_is_taken_at_each_bearings_own_operating_temperature(capsys):
    """With T_amb the oil thins where the bearing runs hot: each candidate's viscosity is the oil's at its own
    T_op (ASTM D341), and the results are those of calc with the same oil, designation by designation."""
    assert main(["select", "--d", "40mm", "--D-max", "80mm", "--family", "deep groove ball", "--shield", "open",
                 *OIL_POINT, "--iso-vg", "68", "--VI", "95", *HEAT, "--rank-by", "T_op", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [row["designation"] for row in rows] == ["6008", "6208", "61908", "16008"]
    for row in rows:
        assert row["nu_at"] == "T_op" and (row["iso_vg"], row["VI"]) == (68.0, 95.0)
        at_t_op = bh.oil_viscosity(u.Quantity(row["T_op [degC]"], "degC"), iso_vg=68).to("mm^2/s").magnitude
        assert row["nu_used [mm^2/s]"] == pytest.approx(at_t_op, rel=1e-9)
    # the hottest runs in the thinnest oil
    assert [round(row["nu_used [mm^2/s]"], 2) for row in rows] == [26.16, 23.89, 22.38, 15.75]
    supports = pd.DataFrame({"designation": [row["designation"] for row in rows], "lubrication": "oil_bath",
                             "n [rpm]": 6000.0, "Fr [kN]": 2.0, "iso_vg": 68.0, "T_amb [degC]": 20.0,
                             "T_bearing [degC]": 70.0})
    alone = bh.calc(supports)
    for name in ("MR [N*mm]", "NR [W]", "T_op [degC]", "n_per [1/min]"):
        np.testing.assert_allclose([row[name] for row in rows], alone[name], rtol=1e-12)


def test_the_temperature_curves_in_an_oil_follow_its_viscosity():
    found = bh.bearings_with_bore(40 * u.mm, D_max=68 * u.mm, family="deep groove ball", shield="open")
    ranked = bh.rank_bearings(found, lubrication="oil_bath", n=6000 * u.rpm, Fr=2 * u.kN, iso_vg=68,
                              T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"), rank_by="T_op")
    curves = bh.temperature_curves(ranked, count=2, points=12)
    assert curves["title"] == "oil_bath, Fr 2 kN, Fa 0 kN, ISO VG 68 (VI 95) at T_op, T_amb 20 °C; schaeffler model"
    grid = pd.DataFrame({"designation": "6008", "lubrication": "oil_bath", "n [1/min]": curves["speeds"],
                         "Fr [N]": 2000.0, "Fa [N]": 0.0, "iso_vg": 68.0, "VI": 95.0, "T_amb [degC]": 20.0,
                         "T_bearing [degC]": 70.0})
    np.testing.assert_allclose(curves["T_op"]["6008"], bh.calc(grid)["T_op [degC]"], rtol=1e-12)
    assert curves["n_per"]["6008"] == pytest.approx(ranked["n_per [1/min]"].iloc[0], rel=1e-12)


@pytest.mark.parametrize(("options", "message"), [
    ({}, "the viscosity: give one of nu (the operating viscosity), iso_vg (the oil's grade, with VI) or nu40 and "
         "nu100; got none"),
    ({"nu": 20 * u.cSt, "nu40": 68 * u.cSt, "nu100": 8.6 * u.cSt},
     "the viscosity: give one of nu (the operating viscosity), iso_vg (the oil's grade, with VI) or nu40 and "
     "nu100; got nu and nu40 and nu100"),
    ({"nu": 20 * u.cSt, "VI": 95}, "VI: given without iso_vg; the viscosity index only serves an ISO VG grade"),
    ({"iso_vg": 68}, "the oil's viscosity (iso_vg) is taken at each bearing's temperature: give T_bearing, and "
                     "T_amb to take it at the operating temperature T_op"),
    ({"nu100": 8.6 * u.cSt, "T_bearing": u.Quantity(70, "degC")},
     "nu40 [mm^2/s]: missing; nu100 alone does not fix the viscosity-temperature line (ASTM D341)"),
    ({"iso_vg": 67, "T_bearing": u.Quantity(70, "degC")},
     "iso_vg: 67 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, "
     "460, 680, 1000, 1500, 2200, 3200"),
    ({"iso_vg": "VG68", "T_bearing": u.Quantity(70, "degC")}, "iso_vg: 'VG68' is not a number"),
    ({"iso_vg": 68, "VI": 500, "T_bearing": u.Quantity(70, "degC")}, "VI: 500 is outside the valid range -100 to 400"),
    ({"iso_vg": 2, "VI": -100, "T_bearing": u.Quantity(70, "degC")},
     "VI: -100 cannot be reached by ISO VG 2 with nu100 >= 2 mm^2/s (ASTM D2270)"),
    ({"nu40": 8 * u.cSt, "nu100": 68 * u.cSt, "T_bearing": u.Quantity(70, "degC")},
     "nu40 [mm^2/s]: 8 must be larger than nu100 = 68"),
    ({"nu40": 3 * u.cSt, "nu100": 1.5 * u.cSt, "T_bearing": u.Quantity(70, "degC")},
     "nu100 [mm^2/s]: 1.5 must be >= 2 (ASTM D341)"),
    ({"nu40": 0 * u.cSt, "nu100": 8.6 * u.cSt, "T_bearing": u.Quantity(70, "degC")}, "nu40: 0 cSt must be > 0"),
])
def test_rank_bearings_refuses_a_viscosity_it_cannot_use(options, message):
    found = bh.bearings_with_bore(40 * u.mm, D_max=62 * u.mm)
    with pytest.raises(SelectionError) as exc:
        bh.rank_bearings(found, lubrication="oil_bath", n=6000 * u.rpm, **options)
    assert str(exc.value) == message


@pytest.mark.parametrize(("arguments", "message"), [
    (["--n", "6000rpm", "--lubrication", "oil_bath", "--T-bearing", "70degC"],
     "the operating point (--n, --T-bearing, --lubrication) needs --nu (or the oil: --iso-vg, or --nu40 and "
     "--nu100) too"),
    (["--iso-vg", "68"], "the operating point (--iso-vg) needs --n and --lubrication too"),
    ([*OIL_POINT, "--nu40", "68", "--nu100", "8.6cSt", "--T-bearing", "70degC"],
     "--nu40: '68' has no unit; write it with one, e.g. 68mm^2/s"),
])
def test_the_oil_options_are_checked(capsys, arguments, message):
    assert main(["select", "--d", "40mm", *arguments]) == 2
    assert capsys.readouterr().err == f"bearingheat select: error: {message}\n"
