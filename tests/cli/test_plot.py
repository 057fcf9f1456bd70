"""``bearingheat plot``: the heat-balance figure of one support, exit codes and messages."""
from __future__ import annotations

import subprocess
import sys

import pandas as pd
import pytest
from thermal_helpers import NJ208_ROW, nj208_chart, plot_table

import bearingheat as bh
from bearingheat.cli import main
from bearingheat.io.reports.thermal import heat_balance_curves


def test_plot_writes_a_png(tmp_path, capsys):
    path = plot_table(tmp_path)
    png = tmp_path / "heat.png"
    assert main(["plot", str(path), "--id", "b", "-o", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert capsys.readouterr().out.strip() == f"wrote {png}"


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
    assert capsys.readouterr().err == "bearingheat plot: row in error: Fr [kN]: -2 must be >= 0\n"


def test_plot_subprocess(tmp_path):
    path = plot_table(tmp_path)
    png = tmp_path / "sub.png"
    done = subprocess.run([sys.executable, "-m", "bearingheat", "plot", str(path), "-o", str(png)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert png.is_file()


def test_plot_reads_f2_off_a_chart(tmp_path, capsys):
    """An axially loaded NJ208-E: refused without f2 (exit 1, saying what to give), drawn with --f2-chart; a chart
    that cannot be read is unusable input (exit 2)."""
    path = tmp_path / "nj.csv"
    pd.DataFrame([NJ208_ROW]).to_csv(path, index=False)
    png = tmp_path / "nj.png"
    assert main(["plot", str(path), "-o", str(png)]) == 1
    assert capsys.readouterr().err.startswith("bearingheat plot: row in error: f2: missing; ")
    assert main(["plot", str(path), "-o", str(png), "--f2-chart", str(nj208_chart(tmp_path))]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert capsys.readouterr().out.strip() == f"wrote {png}"
    missing = tmp_path / "none.csv"
    assert main(["plot", str(path), "-o", str(png), "--force", "--f2-chart", str(missing)]) == 2
    assert capsys.readouterr().err.strip() == (f"bearingheat plot: error: {missing}: cannot read the f2 chart "
                                               "(No such file or directory)")


def test_plot_never_writes_over_its_f2_chart(tmp_path, capsys):
    path = plot_table(tmp_path)
    chart = nj208_chart(tmp_path)
    assert main(["plot", str(path), "-o", str(chart.with_suffix(".png")), "--f2-chart", str(chart)]) == 0
    capsys.readouterr()
    before = chart.read_bytes()
    assert main(["plot", str(path), "-o", str(chart), "--force", "--f2-chart", str(chart)]) == 2
    assert chart.read_bytes() == before


def test_a_row_of_designations_is_drawn_as_calc_computes_it(tmp_path, capsys):
    """The plot computes its row as calc does: a designation fills d, D, B and C0 from the bearing table, oil data
    give ν at T_op, and the crossings of the curves are calc's n_per and T_op."""
    row = {"designation": "6208", "lubrication": "oil_bath", "n [rpm]": 3000.0, "Fr [kN]": 2.0, "iso_vg": 68.0,
           "T_amb [degC]": 20.0, "T_bearing [degC]": 70.0}
    path = tmp_path / "designations.csv"
    pd.DataFrame([row]).to_csv(path, index=False)
    assert main(["plot", str(path), "-o", str(tmp_path / "heat.png")]) == 0
    assert capsys.readouterr() == (f"wrote {tmp_path / 'heat.png'}\n", "")
    curves = heat_balance_curves(pd.DataFrame([row]))
    alone = bh.calc(pd.DataFrame([row]))
    assert (curves["status"], curves["message"]) == ("ok", "")
    assert curves["T_op"] == alone["T_op [degC]"].iat[0] and curves["n_per"] == alone["n_per [1/min]"].iat[0]
    # the friction heat at n_per (at T_bearing) is the heat carried away there: the curves cross at calc's n_per
    assert curves["n_cross"] == pytest.approx(alone["n_per [1/min]"].iat[0], rel=1e-9)


def test_a_sealed_bearing_with_the_skf_seal_friction_is_drawn(tmp_path, capsys):
    row = {"designation": "6208-2RSR", "lubrication": "grease", "model": "skf", "n [rpm]": 3000.0, "Fr [kN]": 2.0,
           "nu [mm^2/s]": 20.0, "seal": "RS1", "d_s [mm]": 49.0, "T_amb [degC]": 20.0, "T_bearing [degC]": 70.0}
    path = tmp_path / "sealed.csv"
    pd.DataFrame([row]).to_csv(path, index=False)
    assert main(["plot", str(path), "-o", str(tmp_path / "sealed.png")]) == 0
    assert capsys.readouterr().err.startswith("bearingheat plot: warning: n_thr: ISO 15312 defines no thermal "
                                              "reference speed for bearings with contact seals")
    curves = heat_balance_curves(pd.DataFrame([row]))
    assert round(curves["T_op"], 1) == 48.6 and round(curves["n_per"]) == 4995
    assert curves["heat_at_T_op"] == pytest.approx(curves["friction_vs_temperature"][0], rel=1e-9)  # ν fixed
