"""The report of diagnose (io/reports/diagnose.py): the docs image of the residual plot."""
from __future__ import annotations

from diagnose_cases import CASES, run_case

from bearingheat.io.reports.diagnose import plot_residuals


def test_docs_image(tmp_path):
    """docs/measured.md shows the residual plot of a synthetic seal-drag set (committed as
    docs/_static/diagnose_seal_drag_residuals.png); drawn here into a temporary folder."""
    table, noise, diagnosis = run_case(*CASES[0])
    target = tmp_path / "diagnose_seal_drag_residuals.png"
    assert plot_residuals(diagnosis, target) == "n"
    assert target.stat().st_size < 150_000
