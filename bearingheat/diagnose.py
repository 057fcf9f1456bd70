"""Transitional alias of ``diagnose`` while the package moves to its layers (removed when the move is done).

The analysis is in :mod:`bearingheat.analysis.diagnose`, the report (summary.json, report.md, plots) in
:mod:`bearingheat.io.reports.diagnose`.
"""
from bearingheat.analysis.diagnose import (MEASURED_UNITS, REGRESSOR_UNITS, SIGNIFICANCE_RULE, CandidateScore,
                                           DiagnoseError, Diagnosis, FittedEffect, MeasuredData, bearing_keys,
                                           diagnose, diagnose_table, error_metrics, model_data, read_measurements,
                                           residual_structure)
from bearingheat.io.reports.diagnose import (plot_measured_vs_predicted, plot_residuals, report_markdown,
                                             write_outputs)

__all__ = [
    "DiagnoseError",
    "SIGNIFICANCE_RULE",
    "MEASURED_UNITS",
    "REGRESSOR_UNITS",
    "MeasuredData",
    "CandidateScore",
    "Diagnosis",
    "read_measurements",
    "model_data",
    "diagnose",
    "diagnose_table",
    "error_metrics",
    "residual_structure",
    "write_outputs",
    "report_markdown",
    "plot_residuals",
    "plot_measured_vs_predicted",
    "bearing_keys",
    "FittedEffect",
]
