"""``bearingheat calc``: friction torque and power loss of every support in a table."""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from bearingheat.calc.contract import help_text
from bearingheat.calc.duty import duty_cycle, has_duty_cycle, support_headers
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.calc.thermal import (DEFAULT_SPEED_FACTOR_METHOD, DEFAULT_VISCOSITY_AT, SPEED_FACTOR_METHODS,
                                     VISCOSITY_AT)
import pandas as pd
import pyarrow.compute as pc

from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.errors import ExcelError, F2ChartError, InputError, VMChartError
# the Excel bridge (openpyxl) and the fitted effects (scipy.optimize) are imported by the runs that use them:
# calc of a CSV or Parquet file starts 0.4 s sooner without them
from bearingheat.cli.options import add_f2_chart, add_force, add_json, add_output, add_quiet, add_vm_chart
from bearingheat.io.console import Progress, print_summary, print_table, summary_columns
from bearingheat.io.dataset import (check_scheduler, compute_dataset, dask_client, dataset_columns, plan_dataset,
                                   read_dataset_columns, recover_target)
from bearingheat.io.fleet import dataset_files, is_dataset
from bearingheat.io.arrow import ARROW_SUFFIXES
from bearingheat.io.pipeline import calc_file
from bearingheat.io.json import results_json
from bearingheat.io.files import EXCEL_SUFFIXES, safe_output, workbook_lock
from bearingheat.io.tables import calc_csv, check_table_suffix, read_table, write_csv, write_table


DESCRIPTION = f"""\
Compute a friction model for one support per row: the catalogue model of the
Schaeffler rolling bearing catalogue (default, 'schaeffler'), or the model a
'model' column or --model names ({', '.join(MODELS)}).

Input columns, headed 'name [unit]' (any pint unit of the right dimension; the
unit in brackets is the catalogue unit the numbers are converted to):

{help_text()}

Output: the input columns, then the results above where their inputs are
present, status (ok|warning|error) and message. Rows with M2 also get Fa/A
and nu*n*dM [mm^3/(s*min)] to read f2 off the chart. Row messages of a CSV
begin with the row's line in the file: 'row 7 (id "spindle rear"): ...'.

A CSV may be separated by ',', ';' or tabs, with decimal points or commas
(found from the file; --sep and --decimal set them). Its units may also stand
in a units row under a header of bare names ('d' over 'mm'), as a CSV saved
from the Excel template's sheet Supports has them; the output then names them
in its headers ('d [mm]'). Columns calc does not know are passed through
untouched.

Output files: -o never replaces an existing file without --force, never
writes over the input, and is written atomically (a temporary file beside it,
renamed when complete; with --dask a hidden folder beside the output folder,
swapped in by renames). CSV cells of text that a spreadsheet would run as a
formula (starting with =, +, -, @, tab or CR) get a leading apostrophe;
--no-csv-escape writes them as they are.

Exit codes: 0 all rows ok or warning; 1 some row has an error; 2 unusable
input (file missing, required column missing, unit of the wrong dimension)
or a file fault (cannot read or write, disk full, damaged workbook).
"""


#: errors that make the input unusable: one line and exit 2 (ExcelError is an InputError)
UNUSABLE_INPUT = (InputError, F2ChartError, VMChartError)

def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="INPUT",
                        help="table of supports: CSV (.csv), Parquet (.parquet), Arrow/Feather (.arrow, .feather) or "
                             "an Excel workbook (.xlsx); with --dask a folder or a glob pattern of Parquet files")
    add_output(parser, ".csv, .parquet, .arrow, .feather or .xlsx; with --dask a folder for the Parquet dataset",
               without="the results are printed (--dask needs it)")
    add_f2_chart(parser)
    add_vm_chart(parser)
    parser.add_argument("--effects", metavar="SUMMARY_JSON",
                        help="apply an effect fitted by 'bearingheat diagnose' (its summary.json); a row outside the "
                             "speeds, sizes or loads it was fitted on gets a warning, a row of another friction "
                             "model than the one it was fitted on an error")
    parser.add_argument("--sheet", metavar="NAME", help="input sheet of an Excel workbook")
    parser.add_argument("--in-place", action="store_true",
                        help="Excel: write the results sheet into the input workbook (atomic)")
    parser.add_argument("--formulas", action="store_true",
                        help="Excel: write live formulas for f0, f1, P0, P1, M0, M1, M2, MR and NR, and a live "
                             "check that marks the other results once an input changes")
    parser.add_argument("--pdf", action="store_true",
                        help="Excel: also print the results sheet to a PDF beside the workbook (OUTPUT.pdf; "
                             "needs LibreOffice)")
    parser.add_argument("--n-per-method", choices=list(SPEED_FACTOR_METHODS), default=DEFAULT_SPEED_FACTOR_METHOD,
                        help="how n_per is found where a row's n_per_method is blank: the exact root of the heat "
                             "balance or the catalogue approximation (default exact); the column n_per_method_used "
                             "says which was used")
    parser.add_argument("--viscosity-at", choices=list(VISCOSITY_AT), default=DEFAULT_VISCOSITY_AT,
                        help="where a viscosity from nu40/nu100 or iso_vg is taken for the friction results of rows "
                             "whose viscosity_at is blank: auto (T_op where T_amb and n are given; T_bearing where "
                             "they are not, or where T_op has no solution; default), operating (T_op) or bearing "
                             "(T_bearing); nu_used and nu_at say which")
    parser.add_argument("--coefficients", metavar="CSV",
                        help="the coefficients.csv of 'bearingheat audit': its 95-percent intervals of f0 and f1 give "
                             "the rows of those designations the bands MR_low, MR_high, n_per_low, ...")
    parser.add_argument("--model", choices=sorted(MODELS), default=DEFAULT_MODEL,
                        help=f"friction model of rows whose 'model' cell is blank (default {DEFAULT_MODEL})")
    add_force(parser, "OUTPUT")
    parser.add_argument("--no-csv-escape", action="store_true",
                        help="CSV output: write text starting with =, +, -, @ as it is (no leading apostrophe)")
    add_csv_arguments(parser)
    add_json(parser)
    add_quiet(parser)
    dask = parser.add_argument_group("fleet scale (needs pip install 'bearingheat[dask]'; docs/scale.md)")
    dask.add_argument("--dask", action="store_true",
                      help="compute a folder or glob of Parquet files on a Dask cluster and write the results as a "
                           "Parquet dataset, one part per input file (or run of row groups of a big file), into the "
                           "folder -o names; a duty cycle's summary goes beside it as FOLDER.duty.parquet")
    dask.add_argument("--scheduler", metavar="ADDRESS",
                      help="--dask: the scheduler of an existing dask.distributed cluster (tcp://host:8786); "
                           "default a local cluster of worker processes")
    dask.add_argument("--workers", metavar="N", type=_worker_count,
                      help="--dask without --scheduler: worker processes of the local cluster (default one per CPU "
                           "core)")


def _worker_count(text: str) -> int:
    """--workers: a whole number >= 1 (a usage error naming the value otherwise)."""
    try:
        count = int(text)
    except ValueError:
        count = 0
    if count < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of worker processes (a whole number >= 1)")
    return count


def _load_effects(path: str | None):
    if path is None:
        return None
    from bearingheat.analysis.effects import FittedEffect  # scipy.optimize: imported only where --effects is given
    try:
        return FittedEffect.from_summary(path)
    except (OSError, ValueError, KeyError) as exc:
        raise UsageError(f"--effects {path}: {exc}") from exc


def _inputs(args: argparse.Namespace, source: Path) -> tuple:
    """Every file the run reads: the table and the files of --f2-chart, --vm-chart, --effects, --coefficients
    (no output may overwrite one of them)."""
    return (source, args.f2_chart, args.vm_chart, args.effects, args.coefficients)


def _output(args: argparse.Namespace, source: Path) -> Path | None:
    """The real file -o names, checked before any work: exists (needs --force), is the input, read-only ..."""
    if not args.output:
        return None
    try:
        check_table_suffix(args.output, also=EXCEL_SUFFIXES)
    except InputError as exc:
        raise UsageError(str(exc)) from exc
    return safe_output(args.output, force=args.force, inputs=_inputs(args, source))


def _pdf(args: argparse.Namespace, workbook: Path | None, source: Path) -> Path | None:
    """The PDF of --pdf beside the results workbook, checked before any work (None without --pdf)."""
    if not getattr(args, "pdf", False):
        return None
    if workbook is None or workbook.suffix.lower() not in EXCEL_SUFFIXES:
        raise UsageError("--pdf prints the results sheet of a workbook: give -o OUTPUT.xlsx (or --in-place)")
    from bearingheat.io.excel.printing import pdf_output
    return pdf_output(workbook, force=args.force, inputs=_inputs(args, source))


def _calc_options(args: argparse.Namespace) -> dict:
    """calc's options from the command line."""
    # the coefficients file read as any table of the command line is: a damaged or empty one is named
    coefficients = read_table(args.coefficients) if args.coefficients else None
    return dict(model=args.model, f2_chart=args.f2_chart, vm_chart=args.vm_chart, n_per_method=args.n_per_method,
                effects=_load_effects(args.effects), viscosity_at=args.viscosity_at, coefficients=coefficients)


def run(args: argparse.Namespace) -> int:
    if args.dask or is_dataset(args.input):
        return run_dask(args)
    if args.scheduler or args.workers:
        raise UsageError("--scheduler and --workers apply with --dask only")
    source = Path(args.input)
    if not source.is_file():
        raise UsageError(f"{source}: no such file")
    if source.suffix.lower() in EXCEL_SUFFIXES:
        return run_calc_workbook(args)
    if args.in_place or args.formulas or args.sheet:
        raise UsageError("--in-place, --formulas and --sheet apply to Excel workbooks only")
    if (args.sep or args.decimal) and source.suffix.lower() in ARROW_SUFFIXES:
        raise UsageError("--sep and --decimal apply to CSV input only (a Parquet or Arrow file holds numbers)")
    target = _output(args, source)
    pdf = _pdf(args, target, source)
    if target is None or target.suffix.lower() not in EXCEL_SUFFIXES:
        return run_table(args, source, target)
    from bearingheat.io.excel.printing import export_pdf
    from bearingheat.io.excel.writer import write_results_workbook
    try:
        result = calc_csv(source, sep=args.sep, decimal=args.decimal, **_calc_options(args))
        duty = duty_cycle(result) if has_duty_cycle(result) else None
        if duty is not None and target is not None and target.suffix.lower() not in EXCEL_SUFFIXES:
            _write_duty_beside(duty, target, source, args)
        if target is not None:
            if target.suffix.lower() in EXCEL_SUFFIXES:
                write_results_workbook(result, target, source, duty)
                if pdf is not None:
                    export_pdf(target, "Results", pdf)
            else:
                write_table(result, target, escape=not args.no_csv_escape)
    except UNUSABLE_INPUT as exc:
        raise UsageError(str(exc)) from exc
    errors = int((result["status"] == "error").sum())
    if args.json:
        print(results_json(result, duty))
    elif not args.quiet:
        _print_results(result, duty, args.output)
    else:
        _quiet_errors(errors, len(result), args.output)
    return 1 if errors else 0


def _write_duty_beside(duty: pd.DataFrame, target: Path, source: Path, args: argparse.Namespace) -> None:
    """The duty-cycle summary per support beside the results: <name>.duty.<suffix>."""
    duty_target = safe_output(target.with_name(f"{target.stem}.duty{target.suffix}"), force=args.force,
                              inputs=_inputs(args, source))
    write_table(duty, duty_target, escape=not args.no_csv_escape)


def _print_results(results, duty: pd.DataFrame | None, output: str | None) -> None:
    """The summary of the results (first rows, counts) and the duty-cycle table where there is one."""
    print_summary(results, output)
    if duty is not None:
        print()
        print_table(duty, title="duty cycle (time-weighted per support):")


def run_table(args: argparse.Namespace, source: Path, target: Path | None) -> int:
    """``bearingheat calc IN.csv|parquet|arrow [-o OUT.csv|parquet|arrow|feather]``: calc a block of rows at a
    time (:func:`bearingheat.io.pipeline.calc_file`, with a progress bar on a terminal), the results held as Arrow
    and written by pyarrow; at most the first rows and the counts are printed."""
    try:
        results = calc_file(source, sep=args.sep, decimal=args.decimal, progress=Progress(enabled=not args.quiet),
                            **_calc_options(args))
        supports = support_headers(results.column_names)  # (only its support column tells a duty cycle)
        has_duty = bool(supports) and has_duty_cycle(results.select(supports).to_pandas())
        result = results.to_pandas() if args.json or has_duty else None
        duty = duty_cycle(result) if result is not None and has_duty else None
        if duty is not None and target is not None:
            _write_duty_beside(duty, target, source, args)
        if target is not None:
            write_table(results, target, escape=not args.no_csv_escape)
    except UNUSABLE_INPUT as exc:
        raise UsageError(str(exc)) from exc
    errors = pc.sum(pc.equal(results.column("status"), "error")).as_py() or 0
    if args.json:
        print(results_json(result if result is not None else results.to_pandas(), duty))
    elif not args.quiet:
        _print_results(results, duty, args.output)
    else:
        _quiet_errors(errors, results.num_rows, args.output)
    return 1 if errors else 0


def run_dask(args: argparse.Namespace) -> int:
    """``bearingheat calc FOLDER|GLOB --dask -o OUT_FOLDER [--scheduler ADDRESS]``: a Parquet dataset of results."""
    if not args.dask:
        raise UsageError(f"{args.input}: a folder or glob of Parquet files is computed with --dask (on a Dask "
                         "cluster); give one file otherwise")
    if not args.output:
        raise UsageError("--dask writes a Parquet dataset: give -o FOLDER")
    if args.json or args.in_place or args.formulas or args.sheet or args.pdf or args.sep or args.decimal:
        raise UsageError("--dask reads Parquet files and writes a Parquet dataset: --json, --in-place, --formulas, "
                         "--sheet, --pdf, --sep and --decimal do not apply")
    if args.scheduler and args.workers:
        raise UsageError("--workers sets up a local cluster; with --scheduler the cluster has its own workers")
    for note in recover_target(args.output):  # what a run that was stopped left beside the folder
        print(f"note: {note}", file=sys.stderr)
    try:
        if args.scheduler:
            check_scheduler(args.scheduler)
        files = dataset_files(args.input)
        plan = plan_dataset(files, args.output, overwrite=args.force, **_calc_options(args))  # before the cluster
        target = plan.target
        with dask_client(args.scheduler, args.workers):
            run = compute_dataset(plan)
        shown = read_dataset_columns(target, summary_columns(dataset_columns(target)))
    except UNUSABLE_INPUT as exc:
        raise UsageError(str(exc)) from exc
    errors = pc.sum(pc.equal(shown.column("status"), "error")).as_py() or 0
    if not args.quiet and shown.num_rows == 0:
        print(f"0 supports: the {len(files)} input files have no rows; {target}/ holds a Parquet dataset of empty "
              "parts")
    elif not args.quiet:
        _print_results(shown, run.duty, f"{target}/ (Parquet dataset of {len(files)} input files)")
    else:
        _quiet_errors(errors, shown.num_rows, f"{target}/")
    return 1 if errors else 0


def run_calc_workbook(args: argparse.Namespace) -> int:
    """``bearingheat calc IN.xlsx ...``: exit 0 (rows ok), 1 (some row in error); UsageError for exit 2."""
    from bearingheat.io.excel.printing import export_pdf
    from bearingheat.io.excel.workbook import calc_workbook
    if args.sep or args.decimal:
        raise UsageError("--sep and --decimal apply to CSV input only")
    source = Path(args.input)
    if args.in_place and args.output:
        raise UsageError("give either --in-place or -o OUTPUT, not both")
    if args.formulas and args.output and Path(args.output).suffix.lower() == ".csv":
        raise UsageError("--formulas needs an Excel output (.xlsx), not a CSV")
    if args.output and os.path.exists(args.output) and os.path.samefile(args.output, source):
        raise UsageError(f"-o {args.output} is the input workbook; use --in-place to write into it")
    target = _output(args, source)
    pdf = _pdf(args, source if args.in_place else target, source)
    csv_target = target if target is not None and target.suffix.lower() == ".csv" else None
    progress = Progress(enabled=not args.quiet)
    options = dict(sheet=args.sheet, formulas=args.formulas, model=args.model, n_per_method=args.n_per_method,
                   viscosity_at=args.viscosity_at,
                   f2_chart=args.f2_chart, vm_chart=args.vm_chart, effects=_load_effects(args.effects),
                   progress=progress)
    try:
        if args.in_place:
            real = safe_output(source, force=True)  # refuses a read-only workbook; writes through a link
            with workbook_lock(source):
                run = calc_workbook(real, None, in_place=True, **options)
        else:
            run = calc_workbook(source, None if csv_target is not None else target, **options)
        if csv_target is not None:
            write_csv(run.csv_table(), csv_target, escape=not args.no_csv_escape)  # units in the headers
            if run.duty is not None:
                _write_duty_beside(run.duty, csv_target, source, args)
        if pdf is not None and run.results_sheet is not None:  # a workbook written has its results sheet
            export_pdf(real if args.in_place else target, run.results_sheet, pdf)
    except ExcelError as exc:
        raise UsageError(str(exc)) from exc
    if args.json:
        print(results_json(run.result))
    elif not args.quiet:
        where = None
        output = args.input if args.in_place else args.output
        if output is not None:
            where = f"{output}" + (f", sheet {run.results_sheet!r}" if run.results_sheet else "")
        _print_results(run.result, run.duty, where)
        for note in run.notes:
            print(f"note: {note}", file=sys.stderr)
        if run.dropped:
            print(f"note: {args.output} lacks or has altered the {', '.join(run.dropped)} of {args.input} (openpyxl "
                  f"cannot copy them as they are); {args.input} is unchanged", file=sys.stderr)
    errors = int((run.result["status"] == "error").sum())
    if args.quiet and not args.json:
        _quiet_errors(errors, len(run.result), args.input if args.in_place else args.output)
    return 1 if errors else 0


def _quiet_errors(errors: int, total: int, output) -> None:
    """-q prints nothing but errors: with rows in error, one line on stderr that says how many and where their
    messages are (the exit code 1 says only that there are some)."""
    if errors:
        where = f"the message column of {output}" if output else "their messages (run without -q to see them)"
        print(f"error: {errors} of {total} supports are in error; see {where}", file=sys.stderr)
