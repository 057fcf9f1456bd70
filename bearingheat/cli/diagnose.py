"""``bearingheat diagnose``: find the effect the catalogue model lacks in measured torque."""
from __future__ import annotations

import argparse

from bearingheat.analysis.diagnose import diagnose_table
from bearingheat.cli import UsageError, add_csv_arguments, add_force_argument
from bearingheat.errors import DiagnoseError
from bearingheat.io.files import check_outputs
from bearingheat.io.reports.diagnose import summary_lines, write_outputs
from bearingheat.io.tables import read_table

HELP = "trace the residuals of measured torque to a missing effect; model error before and after"

DESCRIPTION = """\
Compare measured friction torque with the catalogue model (seed 002), look at the
structure of the residuals, fit each candidate effect (seal_drag, f0_scale,
viscosity_heating, drag_losses, run_in, preload) by least squares, choose one by
grouped k-fold cross-validation and BIC under a stated significance rule, or
answer 'none' when no candidate earns its parameters.

Input (CSV or .xlsx): the columns of 'bearingheat calc' (designation, d, D, C0,
lubrication, n, Fr, Fa, nu, ...) plus
  M [N*mm]        measured friction torque (any torque unit: N*m, N*cm ...)
  T_oil [degC]    optional oil temperature
  t [h]           optional running time (needed by the run_in candidate)
  group           optional label of rows that must stay in one fold (a test run)

Output in --out DIR: summary.json (effect, parameters, rmse_before, rmse_after,
cv_rmse_after [N*mm], mape_before, mape_after [%], candidates ...), report.md,
residuals.png, measured_vs_predicted.png. Use the fitted effect in predictions
with 'bearingheat calc INPUT --effects DIR/summary.json'. Existing files in DIR
are replaced only with --force; each file is written atomically.

Exit codes: 0 done; 1 done, but some rows were excluded (errors listed in the
report); 2 unusable input (file, columns, units, too few rows) or a file fault.
"""


#: the files written into --out DIR
_FILES = ("residuals.png", "measured_vs_predicted.png", "summary.json", "report.md")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="DATA", help="measured torque, CSV (.csv) or Excel (.xlsx)")
    parser.add_argument("--out", metavar="DIR", required=True, help="folder for summary.json, report.md, plots")
    parser.add_argument("--folds", type=int, default=5, help="k of the grouped k-fold cross-validation (default 5)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the fold assignment (default 0)")
    parser.add_argument("--sheet", metavar="NAME", help="sheet of an Excel workbook")
    add_force_argument(parser, "the files in DIR")
    add_csv_arguments(parser)
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing")


def run(args: argparse.Namespace) -> int:
    if args.folds < 2:
        raise UsageError(f"--folds: {args.folds} must be >= 2")
    check_outputs(args.out, _FILES, force=args.force, inputs=(args.input,), create=False)
    table = read_table(args.input, args.sheet, sep=args.sep, decimal=args.decimal)
    try:
        diagnosis = diagnose_table(table, k=args.folds, seed=args.seed)
    except DiagnoseError as exc:
        raise UsageError(str(exc)) from exc
    summary = write_outputs(diagnosis, args.out, force=args.force, inputs=(args.input,))
    if not args.quiet:
        for line in summary_lines(summary, args.out):
            print(line)
    return 1 if summary["n_excluded"] else 0
