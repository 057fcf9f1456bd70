"""The DP11A lab report: figures worth printing (distinct markers, legend outside, units, 150 dpi), markdown tables."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
from PIL import Image

from bearingheat.analysis.lab import process_lab
from bearingheat.io.reports import FIGURE_DPI
from bearingheat.io.reports.lab import LabSeries, lab_task_figure, series_styles, write_lab_outputs

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "lab_dp11a_example.csv"


def test_series_styles_never_repeat_a_colour_and_marker_pair():
    assert len(set(series_styles(12))) == 12
    assert len(set(series_styles(70))) == 70
    assert series_styles(3) == [("C0", "o"), ("C1", "s"), ("C2", "^")]
    assert series_styles(11)[10] == ("C0", "D")       # colour 0 again, another marker
    assert series_styles(71)[70] == ("C0", "o")       # the first pair again after 70 series


def test_legend_stands_beside_the_axes_and_inside_the_figure():
    x = np.array([4.905, 9.81, 19.62])
    series = [LabSeries(f"series {k}", x, 0.04 + 0.001 * k + 0.0012 * x, np.array([0.0, 20.0]),
                        np.array([0.04, 0.064]) + 0.001 * k) for k in range(12)]
    fig = lab_task_figure(series, title="t", xlabel="P0 [N]", lines="lines: fitted with an intercept")
    fig.draw_without_rendering()
    ax = fig.axes[0]
    legend, axes, whole = ax.get_legend().get_window_extent(), ax.get_window_extent(), fig.bbox
    assert legend.x0 >= axes.x1 and legend.x1 <= whole.x1 and legend.y0 >= whole.y0
    assert ax.get_legend().get_title().get_text() == "lines: fitted with an intercept"
    markers = [(line.get_color(), line.get_marker()) for line in ax.lines if line.get_linestyle() == "None"]
    assert len(markers) == 12 and len(set(markers)) == 12
    assert ax.get_xlabel() == "P0 [N]" and ax.get_ylabel() == "T [N·mm]"


def test_report_of_the_example(tmp_path):
    result = process_lab(pd.read_csv(EXAMPLE), nu=20.0)
    write_lab_outputs(result, tmp_path)
    report = (tmp_path / "report.md").read_text(encoding="utf-8")
    assert "seed" not in report.lower()
    with Image.open(tmp_path / "task1_101.png") as image:
        assert image.size == (1140, 600)
        assert round(image.info["dpi"][0]) == FIGURE_DPI == 150
    # table 4 of bearing 101 at beta = 30 deg: rows Q, columns n, the mean torque to four digits
    block = report.split("### Table 4, β = 30°: friction torque T [N·mm]")[2].split("###")[0].strip().splitlines()
    cells = [[c.strip() for c in line.strip("|").split("|")] for line in block]
    assert cells[0] == ["Q [kg]", "n [1/min] = 2400", "n [1/min] = 2600", "n [1/min] = 2800", "n [1/min] = 3000"]
    assert all(re.fullmatch(r"-+:", c) for c in cells[1])
    table4 = result.table4[("101", 30.0)]
    assert cells[2][0] == "0.5" and cells[4][0] == "2"
    assert [float(c) for c in cells[2][1:]] == [float(f"{v:.4g}") for v in table4.loc[0.5]]
    assert cells[2][1:] == ["0.04636", "0.0471", "0.04839", "0.05082"]
    # task 1: the manual's mu through the origin, and the line with an intercept that the figure draws
    task1 = report.split("### Task 1")[3].split("![task 1]")[0].strip().splitlines()    # bearing 18
    header, last = ([c.strip() for c in line.strip("|").split("|")] for line in (task1[-14], task1[-1]))
    assert header == ["β [deg]", "n [1/min]", "μ", "μ (general least squares)", "μ_slope", "T_intercept [N·mm]"]
    assert last == ["90", "3000", "0.0005242", "0.0005242", "0.0003398", "0.01085"]
    # the comparison names its models, not seed numbers
    assert "| bearing | readings | T_mean [N*mm] | DP11A mu model / measured | catalogue MR / measured" in (
        re.sub(r" +", " ", report))
