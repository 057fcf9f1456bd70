"""``bearingheat select``: the bearings of the bearing table for a shaft seat, ranked at an operating point."""
from __future__ import annotations

import argparse
import functools
import json
from typing import Any

import pandas as pd

from bearingheat.api.bearings import bearings_with_bore
from bearingheat.api.selection import (CATALOGUE_SPEED, MARGIN, RANKINGS, candidate_table, rank_bearings,
                                       temperature_curves)
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.catalogue.bearings import FAMILIES, SHIELDS
from bearingheat.catalogue.friction import LUBRICATION_F0_COLUMN
from bearingheat.cli import UsageError
from bearingheat.cli.options import (add_f2_chart, add_force, add_json, add_output, add_quiet, add_vm_chart,
                                     option_quantity)
from bearingheat.io.console import print_summary, print_table
from bearingheat.io.files import EXCEL_SUFFIXES, atomic_write, safe_output
from bearingheat.io.json import json_safe
from bearingheat.io.reports.selection import draw_candidates
from bearingheat.io.reports.thermal import figure_format
from bearingheat.io.tables import check_table_suffix, write_table

DESCRIPTION = """\
The bearings of the bearing table (Schaeffler HR 1, June 2006; 'bearingheat
lookup --help' lists its series) that fit a shaft: bore --d, and optionally the
largest outside diameter --D-max and width --B-max the housing takes (the total
width T of a tapered roller bearing), the families and shields wanted:

  bearingheat select --d 40mm --D-max 80mm
  bearingheat select --d 40mm --family "deep groove ball" --shield open --shield 2Z \\
      --n 6000rpm --Fr 2kN --nu 20mm^2/s --lubrication oil_bath --T-amb 20degC --T-bearing 70degC
  bearingheat select --d 40mm --D-max 80mm --n 6000rpm --Fr 2kN --iso-vg 68 \\
      --lubrication oil_bath --T-amb 20degC --T-bearing 70degC --rank-by T_op

Without an operating point: the candidates' dimensions, load ratings and speeds,
in catalogue order. With one (--n, the viscosity and --lubrication; --Fr, --Fa
default to 0): each candidate computed by 'bearingheat calc' from its
designation, ranked by its power loss NR, the least first (the bearings that
could not be computed last, with the reason: a cylindrical roller bearing
without ribs under axial load, an angular contact bearing whose Y0 is not
known). With --T-amb and --T-bearing also n_per, the speed at which the bearing
reaches T_bearing, n_per/n (above 1: it runs below that temperature) and T_op,
its operating temperature at n; --rank-by T_op puts the coolest first, --rank-by
n_per the fastest (a larger bearing makes more heat but also gives more of it
off). A bearing with contact seals (-2RSR, -2RS) is computed without its seal
friction, which the catalogue model lacks (a warning says so), and without
n_thr, n_per and T_op; with --model skf it comes last with the reason (the SKF
model's seal friction needs a seal type of its table 4 and the counterface
diameter d_s, which the bearing table does not hold: give them to calc).

The viscosity is the operating viscosity --nu, the same for every candidate, or
the oil: its ISO VG grade --iso-vg (with --VI, default 95) or --nu40 and --nu100.
An oil needs --T-bearing: each candidate's viscosity is then taken at its own
operating temperature T_op (with --T-amb; a hotter bearing runs in thinner oil),
else at T_bearing (column nu_used; nu_at says where it was taken).

Columns: designation, family, shield, d, D, B, T [mm], C, C0 [N], n_G (limiting
speed), n_thr_catalogue (the catalogue's thermal reference speed) [1/min]; with
an operating point also the point (lubrication, model, n, Fr, Fa, nu or the
oil ...), the results of calc (f0, f1, P0, P1, M0, M1, M2, MR, NR, nu_used,
n_thr, n_per, T_op ...), n_per/n, status and message.

--plot FIGURE draws T_op against speed of the leading candidates (bearings that
compute alike, 6008 and 6008-2Z, share one curve), each up to its n_G, with
T_bearing and the operating speed as lines: a curve crosses T_bearing at its
n_per.

Output files: -o writes every column (CSV, a new Excel workbook, Parquet,
Arrow/Feather by the suffix); -o and --plot write atomically, never over an
existing file without --force.
Exit codes: 0 done, at least one candidate computed (or listed); 1 no candidate
could be computed at the operating point; 2 unusable input (no bearing of that
bore, an unknown family, a number without unit).
"""

#: a unit of each option's kind, for the message of a number typed without one
_EXAMPLE_UNITS = {"--d": "mm", "--D-max": "mm", "--B-max": "mm", "--n": "rpm", "--Fr": "kN", "--Fa": "kN",
                  "--nu": "mm^2/s", "--nu40": "mm^2/s", "--nu100": "mm^2/s", "--T-amb": "degC",
                  "--T-bearing": "degC", "--oil-level": "mm"}
#: operating-point argument of rank_bearings -> its option (a Quantity)
_OPERATING = {"n": "--n", "Fr": "--Fr", "Fa": "--Fa", "nu": "--nu", "nu40": "--nu40", "nu100": "--nu100",
              "T_amb": "--T-amb", "T_bearing": "--T-bearing", "oil_level": "--oil-level"}
#: the oil's plain numbers: argument of rank_bearings -> its option
_OIL_NUMBERS = {"iso_vg": "--iso-vg", "VI": "--VI"}
#: what an operating point needs (in words) -> the options that give it
_NEEDED = {"--n": ("--n",),
           "--nu (or the oil: --iso-vg, or --nu40 and --nu100)": ("--nu", "--iso-vg", "--nu40", "--nu100"),
           "--lubrication": ("--lubrication",)}
#: candidates drawn by --plot (the leading ones of the ranking), and the speeds of their curves
PLOTTED, PLOT_SPEEDS = 8, 60
#: the catalogue columns shown beside the results
_CATALOGUE_SHOWN = ("designation", "D", "B", "T", "C0", "n_G")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--d", required=True, help="bore (the shaft seat), e.g. 40mm")
    parser.add_argument("--D-max", help="largest outside diameter, e.g. 90mm")
    parser.add_argument("--B-max", help="largest width (T of a tapered roller bearing), e.g. 20mm")
    parser.add_argument("--family", action="append", choices=FAMILIES,
                        help="bearing family (repeat for several; all when not given)")
    parser.add_argument("--shield", action="append", choices=SHIELDS,
                        help="open, 2Z (shields), 2RSR or 2RS (contact seals); repeat for several")
    parser.add_argument("--n", help="shaft speed, e.g. 6000rpm or 100Hz (the operating point)")
    parser.add_argument("--Fr", help="radial load, e.g. 2kN (default 0)")
    parser.add_argument("--Fa", help="axial load, e.g. 0.5kN (default 0)")
    parser.add_argument("--nu", help="operating viscosity (base oil of a grease), e.g. 20mm^2/s")
    parser.add_argument("--iso-vg", type=float, help="instead of --nu: the oil's ISO VG grade, e.g. 68 (needs "
                                                     "--T-bearing; the viscosity at each bearing's T_op)")
    parser.add_argument("--VI", type=float, help="viscosity index of the --iso-vg oil (default 95)")
    parser.add_argument("--nu40", help="instead of --nu: the oil's viscosity at 40 degC, e.g. 68mm^2/s (with --nu100)")
    parser.add_argument("--nu100", help="the oil's viscosity at 100 degC, e.g. 8.6mm^2/s (with --nu40)")
    parser.add_argument("--lubrication", choices=tuple(LUBRICATION_F0_COLUMN), help="how the bearing is lubricated")
    parser.add_argument("--T-amb", help="ambient temperature for the heat balance, e.g. 20degC")
    parser.add_argument("--T-bearing", help="admissible bearing temperature for n_per, e.g. 70degC")
    parser.add_argument("--model", choices=list(MODELS), default=DEFAULT_MODEL, help="friction model")
    parser.add_argument("--rank-by", choices=list(RANKINGS), default="NR",
                        help="NR: the least power loss first (default); T_op: the coolest first; n_per: the highest "
                             "permissible speed first (these two need --T-amb and --T-bearing)")
    parser.add_argument("--oil-level", help="SKF model in an oil bath: oil level H above the lowest contact point of "
                                            "the outer ring raceway, e.g. 10mm")
    add_f2_chart(parser)
    add_vm_chart(parser)
    add_output(parser, ".csv, .xlsx, .parquet, .arrow or .feather")
    parser.add_argument("--plot", metavar="FIGURE",
                        help=f"draw T_op against speed of the {PLOTTED} leading candidates (needs the heat balance; "
                             "PNG, SVG, PDF ... by the suffix)")
    add_force(parser, "FILE")
    add_json(parser)
    add_quiet(parser)


_quantity = functools.partial(option_quantity, examples=_EXAMPLE_UNITS)


def _attribute(option: str) -> str:
    """argparse's attribute of an option: '--T-amb' -> 'T_amb'."""
    return option[2:].replace("-", "_")


def candidates(args: argparse.Namespace) -> pd.DataFrame:
    """The bearings of the table the options leave (rows of the bearing table), in catalogue order."""
    limits = {name: None if text is None else _quantity(text, option)
              for name, text, option in (("D_max", args.D_max, "--D-max"), ("B_max", args.B_max, "--B-max"))}
    return bearings_with_bore(_quantity(args.d, "--d"), family=args.family, shield=args.shield, **limits)


def _shown(table: pd.DataFrame) -> list[str]:
    """The columns of the printed table: the candidates' size and ratings, the main results, status."""
    wanted = [c for c in table.columns if c.split(" [")[0] in _CATALOGUE_SHOWN and table[c].notna().any()]
    results: tuple[str, ...] = ("MR [N*mm]", "NR [W]", "nu_used [mm^2/s]", "n_thr [1/min]", "n_per [1/min]", MARGIN,
                                "T_op [degC]", "status")
    if "status" not in table.columns:  # the candidates alone: the catalogue's speed
        results = (f"{CATALOGUE_SPEED} [1/min]",)
    return wanted + [c for c in results if c in table.columns]


def run(args: argparse.Namespace) -> int:
    target = figure = None
    if args.output:
        check_table_suffix(args.output, also=EXCEL_SUFFIXES)
        target = safe_output(args.output, force=args.force)
    if args.plot:
        fmt = figure_format(args.plot, example="candidates.png")
        figure = safe_output(args.plot, force=args.force, inputs=(target,) if target is not None else ())
    found = candidates(args)
    point: dict[str, Any] = {name: _quantity(text, option) for name, option in _OPERATING.items()
                             if (text := getattr(args, _attribute(option))) is not None}
    point.update({name: value for name, option in _OIL_NUMBERS.items()
                  if (value := getattr(args, _attribute(option))) is not None})
    given = ([option for option in (*_OPERATING.values(), *_OIL_NUMBERS.values())
              if getattr(args, _attribute(option)) is not None] + (["--lubrication"] if args.lubrication else []))
    missing = [words for words, options in _NEEDED.items() if not set(options) & set(given)]
    if given and missing:
        raise UsageError(f"the operating point ({', '.join(given)}) needs {' and '.join(missing)} too")
    heat_balance = "T_amb" in point and "T_bearing" in point
    if args.rank_by != "NR" and not heat_balance:
        raise UsageError(f"--rank-by {args.rank_by} needs the heat balance: give --T-amb and --T-bearing")
    if figure is not None and not (given and heat_balance):
        raise UsageError("--plot draws T_op against speed: give the operating point (--n, the viscosity, "
                         "--lubrication) and --T-amb and --T-bearing")
    table = candidate_table(found)
    if given:
        table = rank_bearings(found, lubrication=args.lubrication, model=args.model, rank_by=args.rank_by,
                              f2_chart=args.f2_chart, vm_chart=args.vm_chart, **point)
    if figure is not None:
        curves = temperature_curves(table, count=PLOTTED, points=PLOT_SPEEDS, f2_chart=args.f2_chart,
                                    vm_chart=args.vm_chart)
        atomic_write(figure, lambda temp: draw_candidates(curves, temp, format=fmt))
    if target is not None and target.suffix.lower() in EXCEL_SUFFIXES:
        from bearingheat.io.excel.writer import write_results_workbook  # (openpyxl only where a workbook is written)
        write_results_workbook(table, target)
    elif target is not None:
        write_table(table, target)
    if args.json:
        print(json.dumps(json_safe(table.to_dict("records")), ensure_ascii=False))
    elif not args.quiet:
        if given:
            print_summary(table, args.output, columns=_shown(table), rows="candidates")
        else:
            print_table(table[_shown(table)], float_format=".6g", na_rep="-",
                        title=f"{len(table)} candidates (catalogue order)"
                              + (f"; written to {args.output}" if args.output else ""))
    return 0 if not given or (table["status"] != "error").any() else 1
