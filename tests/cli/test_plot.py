"""``bearingheat plot``: the heat-balance figure of one support, exit codes and messages."""
from __future__ import annotations

import subprocess
import sys

import pandas as pd
from thermal_helpers import NJ208_ROW, nj208_chart, plot_table

from bearingheat.cli import main


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
