"""What ``bearingheat audit`` writes: the audit tables as text and as CSV files.

The coefficient audit (:func:`bearingheat.analysis.audit.audit_coefficients`)
is printed as one table and written to ``coefficients.csv``; the reference
speed audit (:func:`bearingheat.analysis.audit.audit_reference_speeds` and
:func:`~bearingheat.analysis.audit.series_deviation_summary`) is printed per
series with the rule and the systematic series, and written to
``reference_speeds.csv`` (one row per bearing) and
``reference_speed_series.csv`` (one row per series).
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd

from bearingheat.analysis.audit import SYSTEMATIC_RULE
from bearingheat.io.files import write_outputs
from bearingheat.io.tables import escape_formulas

__all__ = ["coefficient_lines", "reference_speed_lines", "write_coefficients", "write_reference_speeds"]

#: at most this many excluded rows are listed under the coefficient table
SHOWN_EXCLUDED = 20


def coefficient_lines(result: pd.DataFrame) -> list[str]:
    """The coefficient audit as text lines: the table, then the rows that were excluded."""
    lines = ["Coefficients fitted to the measured torque (95 % confidence intervals):",
             result.to_string(index=False, float_format=lambda x: f"{x:.4g}")]
    lines += [f"excluded: {message}" for message in result.attrs.get("excluded", [])[:SHOWN_EXCLUDED]]
    return lines


def reference_speed_lines(summary: pd.DataFrame) -> list[str]:
    """The per-series summary of the reference speed audit as text lines, with the rule and the flagged series."""
    shown = summary.copy()
    for col in ("median", "mean", "min", "max"):
        shown[col] = (shown[col] * 100).map(lambda v: f"{v:+.1f} %" if pd.notna(v) else "-")
    lines = ["Thermal reference speed from the tables against the published value, per series "
             "(deviation = tables/published - 1):",
             shown.to_string(index=False),
             f"rule: {SYSTEMATIC_RULE}"]
    lines += [f"systematic: {key}" for key in summary.loc[summary["systematic"], "series_key"]]
    return lines


def _csv(frame: pd.DataFrame):
    return lambda path: escape_formulas(frame).to_csv(path, index=False)


def write_coefficients(result: pd.DataFrame, out_dir, *, force: bool = False, inputs=()) -> list[Path]:
    """``coefficients.csv`` in ``out_dir``, atomically; an existing file is replaced only with ``force``."""
    return write_outputs(out_dir, {"coefficients.csv": _csv(result)}, force=force, inputs=inputs)


def write_reference_speeds(rows: pd.DataFrame, summary: pd.DataFrame, out_dir, *, force: bool = False,
                           inputs=()) -> list[Path]:
    """``reference_speeds.csv`` and ``reference_speed_series.csv`` in ``out_dir``, atomically; existing files
    are replaced only with ``force``."""
    return write_outputs(out_dir, {"reference_speeds.csv": _csv(rows), "reference_speed_series.csv": _csv(summary)},
                         force=force, inputs=inputs)
