"""``bearingheat calc``: friction torque and power loss of every support in a table."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from bearingheat.analysis.diagnose import FittedEffect
from bearingheat.calc.table import calc
from bearingheat.cli import UsageError
from bearingheat.errors import ExcelError, F2ChartError, InputError
from bearingheat.io.console import Progress, print_summary
from bearingheat.io.excel.reader import EXCEL_SUFFIXES
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.excel.writer import write_results_workbook
from bearingheat.io.tables import read_csv, write_csv

HELP = "friction torque, power loss (and thermal speeds) of supports in a CSV or Excel table"

DESCRIPTION = """\
Compute the catalogue friction model (seed 002) for one support per row.

Input columns, headed 'name [unit]' (any pint unit of the right dimension):
  id, designation            label and designation (6205-2Z, NU206-E, 30205-A ...)
  type, series               optional explicit table row instead of a designation
  d [mm], D [mm], B [mm]     bore, outside diameter, width (B for needle f0 formulas)
  C0 [N]                     static load rating (f1 formulas in P0/C0 or Fa/C0)
  Y, e, X0, Y0               catalogue factors (tapered: Y; spherical: e; P0: X0, Y0)
  alpha [deg]                working contact angle (angular contact ball bearings)
  arrangement                single (default) or paired
  f0, f1, f2                 coefficient overrides (f2: axially loaded NJ/NUP/SL)
  lubrication                grease | oil_mist | oil_bath | circulating_oil
  n [1/min]                  shaft speed (rpm, Hz = rev/s, rad/s is divided by 2 pi)
  Fr [N], Fa [N]             radial and axial load (blank = 0)
  nu [mm^2/s]                operating viscosity (base oil viscosity for grease)

Heat balance (optional; docs/thermal.md):
  B [mm] or T [mm] (tapered), k_q [W/(mm^2*K)], T_amb [degC], T_bearing [degC],
  V_oil [l/min], dT_oil [K], Q_E [W] (heat flowing into the bearing),
  nu40 [mm^2/s] and nu100 [mm^2/s] or iso_vg (then nu may be left out),
  n_G [1/min] (caps n_per), n_thr_catalogue [1/min]
  -> n_thr [1/min], n_per [1/min], T_op [degC], nu_op [mm^2/s], Q_S [W], Q_L [W]
Ball geometry (optional; seed 001): z, Dw [mm], dm_pitch [mm] -> Fa_min [N]
Plain bushings (type plain_bushing; seed 004): d, B (length), Fr, n, f_plain
  -> MR, NR, p [N/mm^2], V [m/s]

Output: the input columns, then f0, f1, P0 [N], P1 [N], M0 [N*mm], M1 [N*mm],
M2 [N*mm], MR [N*mm], NR [W], the columns above where their inputs are
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
        result = calc(table, f2_chart=args.f2_chart, effects=_load_effects(args.effects))
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
                            formulas=args.formulas, f2_chart=args.f2_chart, effects=_load_effects(args.effects),
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
