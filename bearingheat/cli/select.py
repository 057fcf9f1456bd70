"""``bearingheat select``: the bearings of the bearing table for a shaft seat, ranked at an operating point."""
from __future__ import annotations

import argparse
import json
import math

import numpy as np
import pandas as pd

from bearingheat.api.bearings import bearings_with_bore
from bearingheat.calc.contract import column, range_problems
from bearingheat.calc.models import DEFAULT_MODEL, MODELS
from bearingheat.calc.table import calc
from bearingheat.catalogue.bearings import FAMILIES, SHIELDS, units_of_table
from bearingheat.catalogue.friction import LUBRICATION_F0_COLUMN
from bearingheat.cli import UsageError
from bearingheat.cli.options import add_f2_chart, add_force, add_json, add_output, add_quiet, add_vm_chart
from bearingheat.errors import DesignationError, UnitError
from bearingheat.io.console import print_summary, print_table
from bearingheat.io.files import EXCEL_SUFFIXES, atomic_write, safe_output
from bearingheat.io.json import json_safe
from bearingheat.io.reports.selection import draw_candidates
from bearingheat.io.reports.thermal import figure_format
from bearingheat.io.tables import check_table_suffix, write_table
from bearingheat.units import Quantity, celsius, magnitude, parse_quantity

DESCRIPTION = """\
The bearings of the bearing table (Schaeffler HR 1, June 2006; 'bearingheat
lookup --help' lists its series) that fit a shaft: bore --d, and optionally the
largest outside diameter --D-max and width --B-max the housing takes (the total
width T of a tapered roller bearing), the families and shields wanted:

  bearingheat select --d 40mm --D-max 80mm
  bearingheat select --d 40mm --family "deep groove ball" --shield open --shield 2Z \\
      --n 6000rpm --Fr 2kN --nu 20mm^2/s --lubrication oil_bath --T-amb 20degC --T-bearing 70degC

Without an operating point: the candidates' dimensions, load ratings and speeds,
in catalogue order. With one (--n, --nu and --lubrication; --Fr, --Fa default to
0): each candidate computed by 'bearingheat calc' from its designation, ranked by
its power loss NR, the least first (the bearings that could not be computed last,
with the reason: a cylindrical roller bearing without ribs under axial load, an
angular contact bearing whose Y0 is not known). With --T-amb and --T-bearing also
n_per, the speed at which the bearing reaches T_bearing, n_per/n (above 1: it
runs below that temperature) and T_op, its operating temperature at n; --rank-by
T_op puts the coolest first, --rank-by n_per the fastest (a larger bearing makes
more heat but also gives more of it off). A bearing with contact seals (-2RSR,
-2RS) is computed without its seal friction, which the catalogue model lacks (a
warning says so), and without n_thr, n_per and T_op.

Columns: designation, family, shield, d, D, B, T [mm], C, C0 [N], n_G (limiting
speed), n_thr_catalogue (the catalogue's thermal reference speed) [1/min]; with
an operating point also the point (lubrication, model, n, Fr, Fa, nu ...), the
results of calc (f0, f1, P0, P1, M0, M1, M2, MR, NR, n_thr, n_per, T_op ...),
n_per/n, status and message.

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
                  "--nu": "mm^2/s", "--T-amb": "degC", "--T-bearing": "degC", "--oil-level": "mm"}
#: operating-point option -> its calc column (converted to the column's catalogue unit)
_OPERATING = {"n": "--n", "Fr": "--Fr", "Fa": "--Fa", "nu": "--nu", "T_amb": "--T-amb", "T_bearing": "--T-bearing",
              "oil_level": "--oil-level"}
#: the model's bounds of the operating point (the Schaeffler catalogue, p. 64): name -> (lowest, whether it counts)
_LOWEST = {"n": (0.0, True), "Fr": (0.0, True), "Fa": (0.0, True), "nu": (0.0, False), "oil_level": (0.0, True)}
#: --rank-by -> (the column ranked, whether the largest comes first)
RANKINGS = {"NR": ("NR [W]", False), "T_op": ("T_op [degC]", False), "n_per": ("n_per [1/min]", True)}
#: the catalogue columns shown beside the results
_CATALOGUE_SHOWN = ("designation", "D", "B", "T", "C0", "n_G")
#: candidates drawn by --plot (the leading ones of the ranking), and the speeds of their curves
PLOTTED, PLOT_SPEEDS = 8, 60
#: the column of the speed at which the bearing reaches T_bearing over the operating speed
MARGIN = "n_per/n"
#: the column of the catalogue's thermal reference speed (the contract's name for it)
CATALOGUE_SPEED = column("n_thr_catalogue").name


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


def _value(args: argparse.Namespace, name: str) -> float | None:
    """The option of calc column ``name`` in the column's catalogue unit (None when not given), checked against
    the model's bounds and the contract's valid range."""
    option = _OPERATING[name]
    text = getattr(args, option[2:].replace("-", "_"))
    if text is None:
        return None
    unit = column(name).unit
    try:
        given = parse_quantity(text, name=option, example=_EXAMPLE_UNITS[option])
        value = float(celsius(given, option) if unit == "degC" else magnitude(given, unit, option))
    except UnitError as exc:
        raise UsageError(str(exc)) from exc
    lowest, inclusive = _LOWEST.get(name, (-math.inf, True))
    if value < lowest or (value == lowest and not inclusive):
        raise UsageError(f"{option}: {text} must be {'>=' if inclusive else '>'} 0")
    errors, _ = range_problems(name, np.array([value]), lambda i: f"{option}: {text}")
    if errors:
        raise UsageError(errors[0][1])
    return value


def _length(text: str, option: str) -> Quantity:
    try:
        return parse_quantity(text, name=option, example=_EXAMPLE_UNITS[option])
    except UnitError as exc:
        raise UsageError(str(exc)) from exc


def candidates(args: argparse.Namespace) -> pd.DataFrame:
    """The bearings of the table the options leave, in catalogue order, headers 'name [unit]'."""
    try:
        limits = {name: None if text is None else _length(text, option)
                  for name, text, option in (("D_max", args.D_max, "--D-max"), ("B_max", args.B_max, "--B-max"))}
        found = bearings_with_bore(_length(args.d, "--d"), family=args.family, shield=args.shield, **limits)
    except (DesignationError, UnitError) as exc:
        raise UsageError(str(exc)) from exc
    units = units_of_table()
    headers = {}
    for name in found.columns:
        shown = CATALOGUE_SPEED if name == "n_thr" else name  # (calc's own n_thr stands beside the catalogue's)
        headers[name] = shown if units[name] in ("-", "1") else f"{shown} [{units[name]}]"
    return found.rename(columns=headers).reset_index(drop=True)


def ranked(table: pd.DataFrame, point: dict[str, float], lubrication: str, model: str, rank_by: str = "NR", *,
           f2_chart: str | None = None, vm_chart: str | None = None) -> pd.DataFrame:
    """The candidates computed by calc at the operating point ``point`` (calc columns in catalogue units) with
    ``lubrication`` and the friction ``model`` (``f2_chart``, ``vm_chart``: the digitised charts' CSV files, as
    calc takes them), ranked by
    :data:`RANKINGS` ``rank_by`` (the power loss NR by default, the least first); the rows without that result
    (calc could not compute them, or their heat balance) come last, in catalogue order."""
    supports = pd.DataFrame({"designation": table["designation"], "lubrication": lubrication, "model": model})
    for name, value in point.items():
        supports[column(name).header] = value
    results = calc(supports, f2_chart=f2_chart, vm_chart=vm_chart)
    # the operating point stays beside each candidate's results: a file of them says what they were computed at
    merged = pd.concat([table, results.drop(columns="designation")], axis=1)
    if "n_per [1/min]" in merged.columns and point["n"] > 0:
        merged.insert(merged.columns.get_loc("n_per [1/min]") + 1, MARGIN, merged["n_per [1/min]"] / point["n"])
    name, largest_first = RANKINGS[rank_by]
    values = merged[name].to_numpy(dtype=float)
    missing = (merged["status"] == "error").to_numpy() | np.isnan(values)
    order = np.lexsort((np.arange(len(merged)), -values if largest_first else values, missing))
    return merged.iloc[order].reset_index(drop=True)


def _alike(table: pd.DataFrame) -> list[list[int]]:
    """The positions of ``table``'s candidates with an operating temperature, grouped where calc gives them the
    same T_op and n_per (6008 and 6008-2Z, NU308-E and NJ308-E: one curve), in the table's order."""
    groups: dict[tuple[float, float], list[int]] = {}
    T_op, n_per = (table[name].to_numpy(dtype=float) for name in ("T_op [degC]", "n_per [1/min]"))
    for position in np.flatnonzero(np.isfinite(T_op)).tolist():
        key = (round(T_op[position], 9), round(n_per[position], 6) if math.isfinite(n_per[position]) else math.inf)
        groups.setdefault(key, []).append(position)
    return list(groups.values())


def temperature_curves(table: pd.DataFrame, point: dict[str, float], lubrication: str, model: str, *,
                       f2_chart: str | None = None, vm_chart: str | None = None) -> dict:
    """The T_op curves over speed of the leading candidates of ``table`` (ranked, with the heat balance) for
    :func:`bearingheat.io.reports.selection.draw_candidates`: the first :data:`PLOTTED` groups of candidates
    alike (:func:`_alike`, one curve named by all of them), each computed by calc at :data:`PLOT_SPEEDS` speeds
    from near 0 to past the highest n_per (at least 1.5 n); NaN above the first bearing's n_G."""
    groups = _alike(table)[:PLOTTED]
    leading = table.iloc[[group[0] for group in groups]]
    n = point["n"]
    top = max(1.5 * n, 1.1 * float(np.nanmax(leading["n_per [1/min]"].to_numpy(dtype=float), initial=0.0)))
    if not top > 0:
        raise UsageError("--plot: at n = 0 without a permissible speed n_per of any candidate there is no range of "
                         "speeds to draw; give the operating speed")
    speeds = np.linspace(top / PLOT_SPEEDS, top, PLOT_SPEEDS)
    grid = pd.DataFrame({"designation": np.repeat(leading["designation"].to_numpy(), len(speeds)),
                         "lubrication": lubrication, "model": model})
    for name, value in point.items():
        grid[column(name).header] = np.tile(speeds, len(leading)) if name == "n" else value
    computed = calc(grid, f2_chart=f2_chart, vm_chart=vm_chart)["T_op [degC]"].to_numpy(dtype=float, copy=True)
    temperatures = computed.reshape(len(leading), len(speeds))
    limits = leading["n_G [1/min]"].to_numpy(dtype=float)
    temperatures[speeds[None, :] > limits[:, None]] = np.nan  # (above n_G the bearing does not run)
    names = [", ".join(table["designation"].iloc[group]) for group in groups]
    words = (f"{lubrication}, Fr {point['Fr'] / 1e3:g} kN, Fa {point['Fa'] / 1e3:g} kN, nu {point['nu']:g} mm²/s, "
             f"T_amb {point['T_amb']:g} °C; {model} model")
    return {"speeds": speeds, "T_op": dict(zip(names, temperatures)), "n": n,
            "n_per": dict(zip(names, leading["n_per [1/min]"].to_numpy(dtype=float))),
            "T_op_at_n": dict(zip(names, leading["T_op [degC]"].to_numpy(dtype=float))),
            "T_bearing": point["T_bearing"], "T_amb": point["T_amb"], "title": words}


def _shown(table: pd.DataFrame) -> list[str]:
    """The columns of the printed table: the candidates' size and ratings, the main results, status."""
    wanted = [c for c in table.columns if c.split(" [")[0] in _CATALOGUE_SHOWN and table[c].notna().any()]
    results: tuple[str, ...] = ("MR [N*mm]", "NR [W]", "n_thr [1/min]", "n_per [1/min]", MARGIN, "T_op [degC]",
                                "status")
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
    table = candidates(args)
    point = {name: value for name in _OPERATING if (value := _value(args, name)) is not None}
    given = [option for name, option in _OPERATING.items() if name in point] + (
        ["--lubrication"] if args.lubrication else [])
    missing = [option for option in ("--n", "--nu", "--lubrication") if option not in given]
    if given and missing:
        raise UsageError(f"the operating point ({', '.join(given)}) needs {' and '.join(missing)} too")
    heat_balance = "T_amb" in point and "T_bearing" in point
    if args.rank_by != "NR" and not heat_balance:
        raise UsageError(f"--rank-by {args.rank_by} needs the heat balance: give --T-amb and --T-bearing")
    if figure is not None and not (given and heat_balance):
        raise UsageError("--plot draws T_op against speed: give the operating point (--n, --nu, --lubrication) and "
                         "--T-amb and --T-bearing")
    if given:
        point.setdefault("Fr", 0.0)
        point.setdefault("Fa", 0.0)
        table = ranked(table, point, args.lubrication, args.model, args.rank_by, f2_chart=args.f2_chart,
                       vm_chart=args.vm_chart)
    if figure is not None:
        if not np.isfinite(table["T_op [degC]"].to_numpy(dtype=float)).any():
            raise UsageError(f"--plot: no candidate has an operating temperature at this point; {figure.name} is not "
                             "written")
        curves = temperature_curves(table, point, args.lubrication, args.model, f2_chart=args.f2_chart,
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
