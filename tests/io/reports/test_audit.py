"""The reference speed report (io/reports/audit.py): its text, its figure and the docs image."""
from __future__ import annotations

import pandas as pd
import pytest
from PIL import Image

from bearingheat.analysis.audit import audit_reference_speeds, classify_reference_speeds
from bearingheat.catalogue.bearings import bearing_table
from bearingheat.io.reports.audit import draw_reference_speeds, reference_speed_lines, unflagged_outside_the_band

#: the shipped HR 1 (2006) table with the unit headers of a catalogue list
UNIT_HEADERS = {"d": "d [mm]", "D": "D [mm]", "B": "B [mm]", "T": "T [mm]", "C0": "C0 [N]", "n_thr": "n_thr [1/min]"}


@pytest.fixture(scope="module")
def hr1_audit():
    return classify_reference_speeds(audit_reference_speeds(bearing_table().rename(columns=UNIT_HEADERS)))


def test_lines_list_the_flagged_groups_first(hr1_audit):
    lines = reference_speed_lines(hr1_audit)
    start = next(i for i, line in enumerate(lines) if line.startswith("Flagged groups (9)"))
    table = "\n".join(lines[start + 1:start + 11])
    assert all(group in table for group in hr1_audit.flagged["group"])
    assert any(line.startswith("  note: deep groove ball 60 d 7-140 mm: implied f0 spreads") for line in lines)
    assert lines[-1].startswith("systematic: ")


def test_docs_image_of_the_hr1_audit(hr1_audit, tmp_path):
    """The figure of docs/measured.md (committed as docs/_static/audit_reference_speeds.png), drawn into a
    temporary folder: tests never write into the repository."""
    target = tmp_path / "audit_reference_speeds.png"
    draw_reference_speeds(hr1_audit, target, dpi=100)
    with Image.open(target) as image:
        assert image.size == (1100, 1220)
    assert target.stat().st_size < 250_000


def test_figure_of_a_list_without_flags(tmp_path):
    table = pd.DataFrame({"designation": ["6205", "6206", "6207"], "d [mm]": [25, 30, 35], "D [mm]": [52, 62, 72],
                          "B [mm]": [15, 16, 17], "C0 [N]": [7800, 11200, 15300], "n_B [1/min]": [14400, 12000, 10300]})
    audit = classify_reference_speeds(audit_reference_speeds(table))
    assert audit.flagged.empty
    draw_reference_speeds(audit, tmp_path / "f.png")
    assert (tmp_path / "f.png").stat().st_size > 10_000
    assert "Flagged groups: none." in reference_speed_lines(audit)


def test_groups_outside_the_band_that_are_not_flagged_are_not_drawn_as_agreeing(hr1_audit):
    """T4CB deviates by +19.7 % but has 3 bearings, too few to flag (at least 5): the figure names it apart from
    the series that agree, with its deviation and the reason."""
    unflagged = unflagged_outside_the_band(hr1_audit)
    assert unflagged == {"tapered roller T2EE": "+5.7% (1 bearing: too few to judge)",
                         "tapered roller T5ED": "+8.5% (2 bearings: too few to judge)",
                         "tapered roller T4CB": "+19.7% (3 bearings: too few to judge)"}
    assert not set(unflagged) & set(hr1_audit.flagged["group"])
