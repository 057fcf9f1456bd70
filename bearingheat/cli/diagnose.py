"""``bearingheat diagnose``: find the effect the catalogue model lacks in measured torque."""
from __future__ import annotations

import argparse
import json
import sys

from bearingheat.analysis.comparison import ALL_MODELS, compare_models, model_names
from bearingheat.analysis.diagnose import diagnose_measurements, read_measurements
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.cli.options import add_force, add_json, add_out_dir, add_quiet
from bearingheat.io.json import json_safe
from bearingheat.errors import DiagnoseError
from bearingheat.io.files import check_outputs
from bearingheat.io.reports.comparison import COMPARISON_FILES, comparison_lines, write_comparison
from bearingheat.io.reports.diagnose import summary_lines, write_outputs
from bearingheat.io.tables import read_table


DESCRIPTION = """\
Compare measured friction torque with the catalogue model of the Schaeffler rolling
bearing catalogue (Russian edition, chapter «Трение и нагрев»), look at the
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

--model skf or --model all compares the friction models on the same rows: each
model's error as published and with its scalable terms fitted (the catalogue
model's M0 and M1, the SKF model's phi_ish*phi_rs*M_rr and M_sl), held out by the
same grouped cross-validation, and which model fits better and by how much
(models.md, models.json, models.png). The candidate effects extend the catalogue
model, so they are searched when it is among the models.

Output in --out-dir DIR: summary.json (effect, parameters, rmse_before, rmse_after,
cv_rmse_after [N*mm], mape_before, mape_after [%], candidates ...), report.md,
residuals.png, measured_vs_predicted.png. Use the fitted effect in predictions
with 'bearingheat calc INPUT --effects DIR/summary.json'. Existing files in DIR
are replaced only with --force; each file is written atomically.

The report also lists the readings of the largest studentised residual under
the chosen effect, flags outliers (Bonferroni test), and makes the choice again
without the most outlying flagged reading: where that changes the effect, a
warning says so (on stderr, in summary.json 'warnings' and report.md).

Exit codes: 0 done; 1 done, but some rows were excluded (errors listed in the
report) or one reading decides the choice (the warning); 2 unusable input
(file, columns, units, too few rows) or a file fault.
"""


#: the files of the effect search on the catalogue model, written into --out-dir DIR
_FILES = ("residuals.png", "measured_vs_predicted.png", "summary.json", "report.md")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="DATA", help="measured torque, CSV (.csv) or Excel (.xlsx)")
    add_out_dir(parser, "summary.json, report.md and the plots (models.* with --model)", required=True)
    parser.add_argument("--model", choices=[*MODELS, ALL_MODELS], default=DEFAULT_MODEL,
                        help=f"friction model(s) to check: one of {', '.join(MODELS)}, or {ALL_MODELS} to compare "
                             f"them (default {DEFAULT_MODEL})")
    parser.add_argument("--folds", type=int, default=5, help="k of the grouped k-fold cross-validation (default 5)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the fold assignment (default 0)")
    parser.add_argument("--sheet", metavar="NAME", help="sheet of an Excel workbook")
    add_force(parser, "the files in DIR")
    add_csv_arguments(parser)
    add_json(parser)
    add_quiet(parser)


def run(args: argparse.Namespace) -> int:
    if args.folds < 2:
        raise UsageError(f"--folds: {args.folds} must be >= 2")
    models = model_names(args.model)
    search = DEFAULT_MODEL in models
    compare = models != (DEFAULT_MODEL,)
    files = (_FILES if search else ()) + (COMPARISON_FILES if compare else ())
    check_outputs(args.out_dir, files, force=args.force, inputs=(args.input,), create=False)
    table = read_table(args.input, args.sheet, sep=args.sep, decimal=args.decimal)
    flagged = 0  # rows excluded, or a warning: exit 1
    try:
        measured = read_measurements(table)
        comparison = compare_models(measured, models, k=args.folds, seed=args.seed) if compare else None
        diagnosis = diagnose_measurements(measured, k=args.folds, seed=args.seed) if search else None
    except DiagnoseError as exc:
        raise UsageError(str(exc)) from exc
    printed: dict = {}
    if comparison is not None:
        write_comparison(comparison, args.out_dir, force=args.force, inputs=(args.input,))
        flagged = len(comparison.excluded)
        printed["model_comparison"] = comparison.summary()
        if not args.quiet and not args.json:
            for line in comparison_lines(comparison):
                print(line)
    if diagnosis is not None:
        summary = write_outputs(diagnosis, args.out_dir, force=args.force, inputs=(args.input,))
        flagged = summary["n_excluded"] + len(summary["warnings"])
        printed["diagnosis"] = summary
        if not args.quiet and not args.json:
            for line in summary_lines(summary, args.out_dir):
                print(line)
        if not args.quiet:
            for warning in summary["warnings"]:
                print(f"bearingheat diagnose: warning: {warning}", file=sys.stderr)
    if args.json:
        print(json.dumps(json_safe(printed), ensure_ascii=False))
    return 1 if flagged else 0
