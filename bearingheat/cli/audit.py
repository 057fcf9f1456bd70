"""``bearingheat audit``: fitted coefficients against the tables; table speeds against the catalogue."""
from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from functools import partial
from pathlib import Path

from bearingheat.analysis.comparison import ALL_MODELS, compare_models_table, model_names
from bearingheat.analysis.audit import (REFERENCE_SPEED_COLUMNS, audit_coefficients, audit_reference_speeds,
                                        classify_reference_speeds)
from bearingheat.calc.contract import parse_header
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.cli.options import add_force, add_json, add_out_dir, add_quiet
from bearingheat.io.console import print_table
from bearingheat.io.json import json_safe
from bearingheat.errors import AuditError, DiagnoseError
from bearingheat.io.files import check_outputs
from bearingheat.io.reports.comparison import COMPARISON_FILES, comparison_lines, write_comparison
from bearingheat.io.reports.audit import (COEFFICIENT_TITLE, EXCLUDED_FILE, REFERENCE_SPEED_FILES, excluded_lines,
                                          reference_speed_lines, write_coefficients, write_reference_speeds)
from bearingheat.io.tables import read_table


DESCRIPTION = """\
Two audits; DATA may be either kind (told apart by its columns), and a catalogue
list can also be given with --reference-speeds.

1. Measured torque (DATA has 'M [N*mm]'): the columns of 'bearingheat calc' plus
   M [N*mm] (any torque unit), optional T_oil [degC] and t [h]. For each bearing
   f0 and f1 (f1_a where f1 = f1_a*(P0/C0)^x; f2 where a cylindrical roller
   bearing with ribs carries Fa) are fitted by least squares on relative
   residuals, with 95 % confidence intervals; table values outside are flagged.
   --model skf or --model all compares the friction models on the same rows:
   each model's error as published and with its scalable terms fitted (the
   catalogue model's M0 and M1, the SKF model's phi_ish*phi_rs*M_rr and M_sl),
   held out by a grouped cross-validation, and which fits better and by how
   much (models.md, models.json, models.png with --out-dir). The f0/f1 audit
   is of the catalogue model's tables, so it runs when that model is selected.
2. Catalogue list (DATA or --reference-speeds has a published thermal reference
   speed column n_thr / n_B [1/min]): designation (or type and series), d, D, B,
   T [mm] (tapered), C0 [N]; optional family, series, shield name the series.
   n_thr is computed from the tables for every bearing. Each series is pooled
   over its shield and seal variants and split into size classes where only
   some sizes deviate; groups that deviate systematically are flagged with the
   f0 that reproduces their published speeds (95 % interval, allowing for the
   catalogue's rounding of speeds); single misprinted rows are listed as
   outliers. A bearing with contact seals (6205-2RSR), or one HR 1 prints
   without n_thr (7004-B-TVP, 71810-B-TVH, NU1992-M1), and a blank n_thr is
   skipped and named, not a row error: the catalogue prints no n_thr for it.

Output: tables on stdout (flagged groups and their implied f0 first; the rows
left out, the first 20 and how many more); with --out-dir DIR also
coefficients.csv and, where rows were excluded, excluded.csv (each with its
reason), or reference_speeds.csv (per bearing), reference_speed_series.csv (per
series and size class) and reference_speeds.png (existing files are replaced
only with --force; each file is written atomically).
Exit codes: 0 done, nothing flagged; 1 done, but something was flagged, a
coefficient could not be fitted, or a row is in error: a measured row excluded
from the fit, a catalogue row whose n_thr could not be computed (an excluded row
is a row error, as in diagnose; -q prints none of them, the exit code and the
files tell); 2 unusable input or a file fault.
"""


#: the files each audit writes into --out-dir DIR
_FILES = {"coefficients": ("coefficients.csv", EXCLUDED_FILE),
          "models": COMPARISON_FILES,
          "speeds": REFERENCE_SPEED_FILES}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="DATA", nargs="?", help="measured torque or a catalogue list (.csv/.xlsx)")
    parser.add_argument("--reference-speeds", metavar="CSV", help="catalogue list with published n_thr")
    parser.add_argument("--speed-column", metavar="NAME", help="name of the published n_thr column")
    add_out_dir(parser, "the audit tables (CSV) and figures")
    parser.add_argument("--model", choices=[*MODELS, ALL_MODELS], default=DEFAULT_MODEL,
                        help=f"measured torque: friction model(s) to audit, one of {', '.join(MODELS)}, or "
                             f"{ALL_MODELS} to compare them (default {DEFAULT_MODEL})")
    parser.add_argument("--folds", type=int, default=5,
                        help="k of the grouped k-fold cross-validation of the model comparison (default 5)")
    parser.add_argument("--sheet", metavar="NAME", help="sheet of an Excel workbook")
    add_force(parser, "the files in DIR")
    add_csv_arguments(parser)
    add_json(parser)
    add_quiet(parser)


def run(args: argparse.Namespace) -> int:
    if args.input is None and args.reference_speeds is None:
        raise UsageError("give DATA, --reference-speeds CSV, or both")
    if args.folds < 2:
        raise UsageError(f"--folds: {args.folds} must be >= 2")
    out_dir = Path(args.out_dir) if args.out_dir else None
    models = model_names(args.model)
    silent = args.quiet or args.json
    say = (lambda text: None) if silent else (lambda text: sys.stdout.write(text + "\n"))
    printed: dict = {}
    flagged = False
    speed_names = [args.speed_column] if args.speed_column else list(REFERENCE_SPEED_COLUMNS)
    jobs = []
    if args.input is not None:
        table = read_table(args.input, args.sheet, sep=args.sep, decimal=args.decimal)
        names = {parse_header(h, strict=False)[0] for h in table.columns}  # ('remark [see note]]': passed through)
        if "M" in names:
            if DEFAULT_MODEL in models:
                jobs.append(("coefficients", table))
            if models != (DEFAULT_MODEL,):
                jobs.append(("models", table))
        elif names & set(speed_names):
            jobs.append(("speeds", table))
        else:
            raise UsageError(f"{args.input}: neither a measured torque column 'M [N*mm]' nor a published "
                             f"thermal reference speed column ({', '.join(speed_names)})")
    if args.reference_speeds is not None:
        jobs.append(("speeds", read_table(args.reference_speeds, sep=args.sep, decimal=args.decimal)))
    inputs = (args.input, args.reference_speeds)
    if out_dir:
        check_outputs(out_dir, [name for kind, _ in jobs for name in _FILES[kind]], force=args.force, inputs=inputs,
                      create=False)
    writes: list[Callable[[], object]] = []  # every job is computed before any file is written: a job that fails leaves no file of another
    try:
        for kind, table in jobs:
            if kind == "coefficients":
                result = audit_coefficients(table)
                if not silent:
                    print_table(result, float_format=".4g", title=COEFFICIENT_TITLE)
                for line in excluded_lines(result, out_dir):
                    say(line)
                # an excluded row is a row error, as in diagnose: exit 1
                flagged |= bool((result["flag"] != "").any() or (result["status"] != "ok").any()
                                or result.attrs.get("excluded"))
                printed["coefficients"] = result.to_dict(orient="records")
                printed["excluded"] = list(result.attrs.get("excluded", []))
                writes.append(partial(write_coefficients, result, out_dir, force=True, inputs=inputs))
            elif kind == "models":
                try:
                    comparison = compare_models_table(table, args.model, k=args.folds)
                except DiagnoseError as exc:
                    raise AuditError(str(exc)) from exc
                for line in comparison_lines(comparison):
                    say(line)
                flagged |= bool(comparison.excluded)
                printed["model_comparison"] = comparison.summary()
                writes.append(partial(write_comparison, comparison, out_dir, force=True, inputs=inputs))
            else:
                speeds = classify_reference_speeds(audit_reference_speeds(table, speed_column=args.speed_column))
                for line in reference_speed_lines(speeds):
                    say(line)
                not_computed = speeds.not_computed
                flagged |= bool(len(speeds.flagged) or not_computed)   # a row not computed is a row error
                printed["reference_speed_rows_not_computed"] = not_computed
                printed["reference_speed_rows_skipped"] = list(speeds.skipped)
                printed["reference_speed_groups"] = speeds.groups.to_dict(orient="records")
                writes.append(partial(write_reference_speeds, speeds, out_dir, force=True, inputs=inputs))
    except AuditError as exc:
        raise UsageError(str(exc)) from exc
    if out_dir:
        for write in writes:  # (the files were checked before any work: force=True replaces only what was allowed)
            write()
    if args.json:
        print(json.dumps(json_safe(printed), ensure_ascii=False, default=str))
    return 1 if flagged else 0
