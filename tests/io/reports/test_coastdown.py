"""The coast-down report (io/reports/coastdown.py): report.md, coastdown.png and a strict-JSON summary.json."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from PIL import Image

from bearingheat.analysis.coastdown import coastdown_analysis
from bearingheat.io.reports import FIGURE_DPI
from bearingheat.io.reports.coastdown import coastdown_summary, render_report, write_coastdown_outputs


def _straight_rundown(G=None, r=None):
    t = np.arange(0.0, 61.0, 2.0)
    return coastdown_analysis(t, 600.0 - 10.0 * t, 2.6, G, r)


def test_summary_without_journal_load_is_strict_json():
    result = _straight_rundown()
    assert math.isnan(result.summary()["f_constant"])
    summary = coastdown_summary(result)
    assert summary["f_constant"] is None and summary["G [N]"] is None
    json.dumps(summary, allow_nan=False)


def test_outputs_written(tmp_path):
    result = _straight_rundown(1100.0, 25.0)
    files = write_coastdown_outputs(result, tmp_path / "run", "straight.csv")
    assert [p.rsplit("/", 1)[-1] for p in map(str, files)] == ["coastdown.png", "report.md", "summary.json"]
    assert (tmp_path / "run" / "coastdown.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with Image.open(tmp_path / "run" / "coastdown.png") as image:  # 6.4 in square at 150 dpi
        assert image.size == (960, 960) and round(image.info["dpi"][0]) == FIGURE_DPI == 150
    assert (tmp_path / "run" / "report.md").read_text(encoding="utf-8") == render_report(
        result, "straight.csv", png="coastdown.png")
    assert json.loads((tmp_path / "run" / "summary.json").read_text())["model"] == "coulomb"


def test_figure_draws_each_formula2_interval_from_n_from_to_n_to():
    """The intervals were drawn with step(n_mean, where='mid'), so the first and last were half as wide. By hand for
    the straight line: 10 steps of (600 - 20)/10 = 58 1/min from 600 1/min, f = 2.6*(pi/30)*10/(1100*0.025)."""
    from matplotlib.collections import LineCollection

    from bearingheat.io.reports.coastdown import INTERVALS_LABEL, draw_coastdown
    result = _straight_rundown(1100.0, 25.0)
    bottom = draw_coastdown(result).axes[1]
    drawn = [c for c in bottom.collections if isinstance(c, LineCollection) and c.get_label() == INTERVALS_LABEL]
    assert len(drawn) == 1
    segments = drawn[0].get_segments()
    assert len(segments) == 10
    f = 2.6 * math.pi / 30.0 * 10.0 / 27.5
    for k, segment in enumerate(segments):
        (x0, y0), (x1, y1) = segment
        assert sorted((x0, x1)) == pytest.approx([600.0 - 58.0 * (k + 1), 600.0 - 58.0 * k], abs=1e-6)
        assert y0 == y1 == pytest.approx(f, rel=1e-6)
