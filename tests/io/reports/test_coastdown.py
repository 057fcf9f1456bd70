"""The coast-down report (io/reports/coastdown.py): report.md, coastdown.png and a strict-JSON summary.json."""
from __future__ import annotations

import json
import math

import numpy as np

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
