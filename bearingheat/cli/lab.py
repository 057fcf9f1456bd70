"""``bearingheat lab``: process DP11A lab rig readings after the DP11A manual (tasks 1-3, tables 4 and 5)."""
from __future__ import annotations

import argparse
import math
import json

from bearingheat.analysis.lab import process_lab
from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.cli.options import add_force, add_json, add_out_dir, add_quiet
from bearingheat.io.json import json_safe
from bearingheat.errors import BearingheatError, UnitError
from bearingheat.io.console import print_table
from bearingheat.io.files import check_outputs
from bearingheat.io.reports.lab import write_lab_outputs
from bearingheat.io.tables import read_table
from bearingheat.units import magnitude, parse_quantity


DESCRIPTION = """\
Process friction torque readings of the DP11A rig (the DP11A manual).

Input (CSV or .xlsx), one reading per row:
  bearing         the DP11A manual table 3: 1000095, 18 or 101
  Q [kg]          weight (0.5, 1, 2 kg on the rig)
  beta [deg]      inclination of the spindle axis, 0 (axial) .. 90 (radial)
  n [1/min]       speed
  T [N*mm]        friction torque (any torque unit)
  nu [mm^2/s]     optional viscosity for the Schaeffler catalogue comparison (or --nu)

Loads Fa = 9.81*Q*cos(beta), Fr = 9.81*Q*sin(beta), P0 from the DP11A manual table 1.
Task 1: mu for each speed; task 2: f0 and T_F for each beta (N = n^(2/3));
task 3: f and T0 for each speed (N = P0^1.55).

Output in --out-dir DIR: report.md (tables 4 and 5 filled, task results, the
comparison with the catalogue model of the Schaeffler catalogue), CSV of each task, PNG plots.
Existing files in DIR are replaced only with --force; each file is written
atomically.
Exit codes: 0 done; 2 unusable input or a file fault.
"""


#: files every run writes (the plots depend on the readings), checked before the work starts
_KNOWN_FILES = ("readings.csv", "task1_mu.csv", "task2_f0_TF.csv", "task3_f_T0.csv", "comparison.csv", "report.md")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("input", metavar="READINGS", help="CSV (.csv) or Excel (.xlsx) of readings")
    add_out_dir(parser, "report.md, the CSVs and plots", required=True)
    add_json(parser)
    parser.add_argument("--nu", metavar="VISCOSITY",
                        help="viscosity for the Schaeffler catalogue comparison, e.g. 20mm^2/s")
    parser.add_argument("--lubrication", default="grease",
                        help="lubrication of the Schaeffler catalogue comparison (default grease)")
    parser.add_argument("--sheet", metavar="NAME", help="sheet of an Excel workbook")
    add_force(parser)
    add_csv_arguments(parser)
    add_quiet(parser)


def run(args: argparse.Namespace) -> int:
    nu = None
    if args.nu is not None:
        try:
            viscosity = parse_quantity(args.nu, name="--nu", example="mm^2/s")
        except UnitError as exc:
            raise UsageError(str(exc)) from exc
        try:
            nu = float(magnitude(viscosity, "mm^2/s", "--nu"))
        except UnitError as exc:
            raise UsageError(f"--nu: {args.nu!r} is not a kinematic viscosity (e.g. 20mm^2/s)") from exc
        if not (math.isfinite(nu) and nu > 0):
            raise UsageError(f"--nu: {args.nu.strip()} must be a viscosity > 0")
    check_outputs(args.out_dir, _KNOWN_FILES, force=args.force, inputs=(args.input,), create=False)
    table = read_table(args.input, args.sheet, sep=args.sep, decimal=args.decimal)
    try:
        result = process_lab(table, nu=nu, lubrication=args.lubrication)
    except BearingheatError as exc:
        raise UsageError(str(exc)) from exc
    files = write_lab_outputs(result, args.out_dir, force=args.force, inputs=(args.input,))
    if args.json:
        print(json.dumps(json_safe({"task1": result.task1.to_dict(orient="records"),
                                    "comparison": result.comparison.to_dict(orient="records"),
                                    "notes": list(result.notes), "files": [str(f) for f in files]}),
                         ensure_ascii=False))
    elif not args.quiet:
        print_table(result.task1, float_format=".4g")
        print_table(result.comparison, float_format=".4g")
        for note in result.notes:
            print(f"note: {note}")
        print(f"{len(files)} files written to {args.out_dir}")
    return 0
