"""The heat balance in ``bearingheat calc`` (extension bearingheat.thermal_calc) and ``bearingheat plot``."""
from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from bearingheat import frame as frame_module
from bearingheat.cli import main
from bearingheat.frame import InputError, calc
from bearingheat.thermal_calc import INPUT_UNITS, OUTPUT_UNITS
from bearingheat.viscosity import iso_vg_viscosity, viscosity_from_two_points

THERMAL_COLUMNS = ["n_thr [1/min]", "n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "Q_S [W]", "Q_L [W]"]


def supports(**extra):
    table = pd.DataFrame({
        "id": ["a", "b"], "designation": ["6205", "NU206-E"], "d [mm]": [25, 30], "D [mm]": [52, 62],
        "B [mm]": [15, 16], "C0 [kN]": [7.8, 36], "lubrication": ["oil_bath", "oil_bath"],
        "n [rpm]": [3000, 1500], "Fr [kN]": [2, 5],
    })
    for key, value in extra.items():
        table[key] = value
    return table


def test_extension_is_registered():
    assert "bearingheat.thermal_calc" in frame_module.EXTENSIONS
    assert set(OUTPUT_UNITS) == {"n_thr", "n_per", "T_op", "nu_op", "Q_S", "Q_L"}
    assert INPUT_UNITS["dT_oil"] == "delta_degC" and INPUT_UNITS["T_amb"] == "degC"


def test_no_thermal_columns_without_their_inputs():
    out = calc(supports(**{"nu [mm^2/s]": [12, 20]}).drop(columns="B [mm]"))
    assert not set(THERMAL_COLUMNS) & set(out.columns)


def test_reference_speed_only_with_geometry():
    out = calc(supports(**{"nu [mm^2/s]": [12, 20]}))
    assert "n_thr [1/min]" in out.columns and "T_op [degC]" not in out.columns
    np.testing.assert_allclose(out["n_thr [1/min]"], [14416.18, 9850.52], rtol=1e-6)
    assert out["status"].tolist() == ["ok", "ok"]


def test_all_columns_with_nu40_nu100_at_the_bearing_temperature():
    out = calc(supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                           "T_bearing [degC]": [70, 70]}))
    for column in THERMAL_COLUMNS:
        assert column in out.columns
    assert out["status"].tolist() == ["ok", "ok"]
    np.testing.assert_allclose(out["n_per [1/min]"], [8053.40, 6058.83], rtol=1e-5)
    # Q_S at T_bearing: default k_q = q_r / 50 K -> q_r * A_r
    np.testing.assert_allclose(out["Q_S [W]"], [0.016 * math.pi * 15 * 77, 0.016 * math.pi * 16 * 92], rtol=1e-12)
    assert (out["Q_L [W]"] == 0).all()
    np.testing.assert_allclose(out["nu_op [mm^2/s]"],
                               viscosity_from_two_points(68, 40, 8.6, 100, out["T_op [degC]"].to_numpy()),
                               rtol=1e-12)


def test_iso_vg_fills_nu_at_the_operating_temperature_without_T_bearing():
    out = calc(supports(**{"iso_vg": [68, 68], "T_amb [degC]": [20, 20]}))
    assert "n_per [1/min]" not in out.columns
    assert out["status"].tolist() == ["ok", "ok"]
    T_op = out["T_op [degC]"].to_numpy()
    np.testing.assert_allclose(out["nu_op [mm^2/s]"], iso_vg_viscosity(68, T_op), rtol=1e-12)
    # the friction pass ran at nu(T_op): N_R equals the heat carried away at T_op
    carried = out["Q_S [W]"].to_numpy()
    assert out["NR [W]"].to_numpy() == pytest.approx(carried, rel=1e-3)  # engine N_R uses n/9550


def test_temperature_header_units_and_fahrenheit():
    a = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}))
    b = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [K]": [293.15, 293.15], "T_bearing [degF]": [158, 158]}))
    np.testing.assert_allclose(a["n_per [1/min]"], b["n_per [1/min]"], rtol=1e-9)
    np.testing.assert_allclose(a["T_op [degC]"], b["T_op [degC]"], rtol=1e-9)


def test_oil_temperature_rise_in_degC_is_refused():
    table = supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "V_oil [l/min]": [0.5, 0.5],
                        "dT_oil [degC]": [5, 5]})
    with pytest.raises(InputError) as exc:
        calc(table)
    assert str(exc.value) == ("column 'dT_oil [degC]': unit degree_Celsius cannot be converted to delta_degC")


def test_circulating_oil_and_external_heat():
    base = {"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}
    plain = calc(supports(**base))
    oil = calc(supports(**base, **{"V_oil [l/min]": [0.5, 0.5], "dT_oil [K]": [4, 4]}))
    hot = calc(supports(**base, **{"Q_E [W]": [10, 10]}))
    np.testing.assert_allclose(oil["Q_L [W]"], 28.6 * 0.5 * 4, rtol=1e-12)
    assert (oil["n_per [1/min]"] > plain["n_per [1/min]"]).all()
    assert (hot["n_per [1/min]"] < plain["n_per [1/min]"]).all()
    assert (hot["T_op [degC]"] > plain["T_op [degC]"]).all()


def test_catalogue_reference_speed_and_limiting_speed():
    out = calc(supports(**{"nu [mm^2/s]": [20, 20], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70],
                           "n_thr_catalogue [1/min]": [14400, 9800], "n_G [1/min]": [5000, np.nan]}))
    assert out["n_thr_catalogue [1/min]"].tolist() == [14400, 9800]
    np.testing.assert_allclose(out["n_thr [1/min]"], [14416.18, 9850.52], rtol=1e-6)
    assert out.loc[0, "n_per [1/min]"] == 5000.0
    assert out.loc[0, "status"] == "warning"
    assert out.loc[0, "message"] == ("n_per: the thermal value 8050 1/min is above the limiting speed "
                                     "n_G = 5000 1/min; n_per = n_G")
    assert out.loc[1, "status"] == "ok"


def test_row_problems_are_messages_not_exceptions():
    table = pd.DataFrame({
        "designation": ["6205-2RSR", "6205", "6205", "6205"], "d [mm]": [25] * 4, "D [mm]": [52] * 4,
        "B [mm]": [15, 15, 15, 15], "C0 [kN]": [7.8] * 4, "lubrication": ["oil_bath"] * 4,
        "n [rpm]": [3000, 3000, np.nan, 3000], "Fr [kN]": [2] * 4,
        "nu40 [mm^2/s]": [68, 68, 68, 68], "nu100 [mm^2/s]": [8.6, np.nan, 8.6, 8.6],
        "T_amb [degC]": [20, 20, 20, 80], "T_bearing [degC]": [70, 70, np.nan, 70],
    })
    out = calc(table)
    assert out["status"].tolist() == ["warning", "error", "error", "error"]
    assert out.loc[0, "message"] == (
        "contact seals: their friction comes on top of the catalogue model (seed 002, p. 64); n_thr: the thermal "
        "method (ISO 15312, DIN 732) does not apply to bearings with contact seals")
    assert "nu100 [mm^2/s]: missing; nu40 alone does not fix the viscosity-temperature line (ASTM D341)" \
        in out.loc[1, "message"]
    assert ("n [1/min]: missing; nu from nu40/nu100 or iso_vg is taken at the operating temperature T_op, which "
            "needs n and T_amb (or give T_bearing)") in out.loc[2, "message"]
    assert "T_bearing [degC]: 70 must be above T_amb = 80 degC for heat to leave through the seat" \
        in out.loc[3, "message"]
    assert out.loc[1:, THERMAL_COLUMNS].isna().all().all()


def test_calc_cli_writes_thermal_columns(tmp_path, capsys):
    source = tmp_path / "supports.csv"
    supports(**{"iso_vg": [68, 68], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}).to_csv(source,
                                                                                                    index=False)
    target = tmp_path / "out.csv"
    assert main(["calc", str(source), "-o", str(target), "-q"]) == 0
    written = pd.read_csv(target)
    for column in THERMAL_COLUMNS:
        assert column in written.columns
    assert written["n_per [1/min]"].notna().all()


# ---- bearingheat plot --------------------------------------------------------------------------------

def plot_table(tmp_path, **extra):
    path = tmp_path / "supports.csv"
    supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                "T_bearing [degC]": [70, 70]}, **extra).to_csv(path, index=False)
    return path


def test_plot_writes_a_png(tmp_path, capsys):
    path = plot_table(tmp_path)
    png = tmp_path / "heat.png"
    assert main(["plot", str(path), "--id", "b", "-o", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert capsys.readouterr().out.strip() == f"wrote {png}"


def test_plot_curves_cross_at_n_per_and_T_op(tmp_path):
    from bearingheat.cli.plot import heat_balance_curves

    table = pd.read_csv(plot_table(tmp_path)).iloc[[0]]
    curves = heat_balance_curves(table)
    out = calc(table)
    assert curves["n_cross"] == pytest.approx(out.loc[0, "n_per [1/min]"], rel=1e-12)
    assert curves["T_op"] == pytest.approx(out.loc[0, "T_op [degC]"], rel=1e-12)
    # the friction curve rises with speed and falls with temperature (thinner oil)
    assert np.all(np.diff(curves["friction_vs_speed"]) > 0)
    assert np.all(np.diff(curves["friction_vs_temperature"]) < 0)


def test_plot_usage_errors(tmp_path, capsys):
    path = plot_table(tmp_path)
    assert main(["plot", str(path), "--row", "5", "-o", str(tmp_path / "x.png")]) == 2
    assert capsys.readouterr().err.strip() == "bearingheat plot: error: --row 5: the table has rows 0 to 1"
    assert main(["plot", str(path), "--id", "zz", "-o", str(tmp_path / "x.png")]) == 2
    assert capsys.readouterr().err.strip() == f"bearingheat plot: error: {path}: no row with id 'zz'"
    assert main(["plot", str(tmp_path / "none.csv"), "-o", str(tmp_path / "x.png")]) == 2
    assert capsys.readouterr().err.strip() == f"bearingheat plot: error: {tmp_path / 'none.csv'}: no such file"


def test_plot_row_in_error_exits_1(tmp_path, capsys):
    path = plot_table(tmp_path, **{"Fr [kN]": [-2, 5]})
    assert main(["plot", str(path), "--row", "0", "-o", str(tmp_path / "x.png")]) == 1
    assert capsys.readouterr().err.startswith("bearingheat plot: row in error: Fr [kN]: -2 must be >= 0")


def test_plot_subprocess(tmp_path):
    path = plot_table(tmp_path)
    png = tmp_path / "sub.png"
    done = subprocess.run([sys.executable, "-m", "bearingheat", "plot", str(path), "-o", str(png)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert png.is_file()


def test_docs_image_of_the_heat_balance():
    """Regenerates docs/_static/thermal_heat_balance.png (the figure of docs/thermal.md)."""
    from pathlib import Path

    from bearingheat.cli.plot import draw_heat_balance, heat_balance_curves

    table = supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                        "T_bearing [degC]": [70, 70]}).iloc[[0]]
    target = Path(__file__).resolve().parents[1] / "docs" / "_static" / "thermal_heat_balance.png"
    draw_heat_balance(heat_balance_curves(table), target)
    assert target.stat().st_size < 100_000


def test_friction_only_tables_get_n_thr_quietly():
    table = supports(**{"nu [mm^2/s]": [12, 20]})
    table.loc[1, "designation"] = "NU206-E"
    table["C0 [kN]"] = [7.8, np.nan]
    table["lubrication"] = ["oil_bath", "oil_bath"]
    out = calc(table)
    assert out["status"].tolist() == ["ok", "ok"]
    assert out["message"].tolist() == ["", ""]
    assert out.loc[0, "n_thr [1/min]"] == pytest.approx(14416.18, rel=1e-6)
    assert math.isnan(out.loc[1, "n_thr [1/min]"])
