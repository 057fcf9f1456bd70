"""``bearingheat calc``: friction torque and power loss of every support in a table."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from bearingheat.analysis.diagnose import FittedEffect
from bearingheat.calc.contract import help_text
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.calc.table import calc
from bearingheat.cli import UsageError
from bearingheat.errors import ExcelError, F2ChartError, InputError
from bearingheat.io.console import Progress, print_summary
from bearingheat.io.excel.reader import EXCEL_SUFFIXES
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.excel.writer import write_results_workbook
from bearingheat.io.tables import read_csv, write_csv

HELP = "friction torque, power loss (and thermal speeds) of supports in a CSV or Excel table"

DESCRIPTION = f"""\
Compute a friction model for one support per row: the catalogue model of the
Schaeffler rolling bearing catalogue (default, 'schaeffler'), or the model a
'model' column or --model names ({', '.join(MODELS)}).

Input columns, headed 'name [unit]' (any pint unit of the right dimension; the
unit in brackets is the catalogue unit the numbers are converted to):

{help_text()}

Output: the input columns, then the results above where their inputs are
present, status (ok|warning|error) and message. Rows with M2 also get Fa/A
and nu*n*dM [mm^3/(s*min)] to read f2 off the chart.

Exit codes: 0 all rows ok or warning; 1 some row has an error; 2 unusable
input (file missing, required column missing, unit of the wrong dimension).
"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="INPUT", help="CSV (.csv) or Excel workbook (.xlsx) of supports")
    parser.add_argument("-o", "--output", metavar="OUTPUT",
                        help="where to write the results (.csv or .xlsx); without it a table is printed")
    parser.add_argument("--f2-chart", metavar="CSV",
                        help="digitised f2 chart (docs/friction.md gives the format)")
    parser.add_argument("--effects", metavar="SUMMARY_JSON",
                        help="apply an effect fitted by 'bearingheat diagnose' (its summary.json)")
    parser.add_argument("--sheet", metavar="NAME", help="input sheet of an Excel workbook")
    parser.add_argument("--in-place", action="store_true",
                        help="Excel: write the results sheet into the input workbook (atomic)")
    parser.add_argument("--formulas", action="store_true",
                        help="Excel: write live formulas for M0, M1, M2, MR and NR")
    parser.add_argument("--model", choices=sorted(MODELS), default=DEFAULT_MODEL,
                        help=f"friction model of rows whose 'model' cell is blank (default {DEFAULT_MODEL})")
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing")


def _load_effects(path: str | None):
    if path is None:
        return None
    try:
        return FittedEffect.from_summary(path)
    except (OSError, ValueError, KeyError) as exc:
        raise UsageError(f"--effects {path}: {exc}") from exc


def run(args: argparse.Namespace) -> int:
    source = Path(args.input)
    if not source.is_file():
        raise UsageError(f"{source}: no such file")
    if source.suffix.lower() in EXCEL_SUFFIXES:
        return run_calc_workbook(args)
    if args.in_place or args.formulas or args.sheet:
        raise UsageError("--in-place, --formulas and --sheet apply to Excel workbooks only")
    try:
        table = read_csv(source)
        result = calc(table, model=args.model, f2_chart=args.f2_chart, effects=_load_effects(args.effects))
        if args.output:
            target = Path(args.output)
            if target.suffix.lower() in EXCEL_SUFFIXES:
                write_results_workbook(result, target)
            else:
                write_csv(result, target)
    except (InputError, F2ChartError) as exc:  # ExcelError is an InputError
        raise UsageError(str(exc)) from exc
    if not args.quiet:
        print_summary(result, args.output)
    return 1 if (result["status"] == "error").any() else 0


def run_calc_workbook(args: argparse.Namespace) -> int:
    """``bearingheat calc IN.xlsx ...``: exit 0 (rows ok), 1 (some row in error); UsageError for exit 2."""
    progress = Progress(enabled=not args.quiet)
    try:
        run = calc_workbook(args.input, args.output, sheet=args.sheet, in_place=args.in_place,
                            formulas=args.formulas, model=args.model, f2_chart=args.f2_chart,
                            effects=_load_effects(args.effects),
                            progress=progress)
    except ExcelError as exc:
        raise UsageError(str(exc)) from exc
    if not args.quiet:
        where = None
        if run.output is not None:
            where = f"{run.output}" + (f", sheet {run.results_sheet!r}" if run.results_sheet else "")
        print_summary(run.result, where)
        if run.dropped:
            print(f"note: {run.output} lacks the {', '.join(run.dropped)} of {args.input} (openpyxl cannot copy "
                  f"them); {args.input} is unchanged", file=sys.stderr)
    return 1 if (run.result["status"] == "error").any() else 0
