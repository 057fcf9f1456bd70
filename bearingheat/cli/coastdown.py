"""``bearingheat coastdown``: friction coefficient and torque components from a run-down diagram (the TMM-7M lab sheet)."""
from __future__ import annotations

import argparse
import functools
import json
from typing import Any

from bearingheat.api.coastdown import analyse_coastdown, analyse_spindle_coastdown
from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.cli.options import add_force, add_json, add_out_dir, add_quiet, option_quantity
from bearingheat.errors import BearingheatError
from bearingheat.io.coastdown import read_rundown
from bearingheat.io.files import check_outputs
from bearingheat.io.reports.coastdown import coastdown_summary, render_report, write_coastdown_outputs
from bearingheat.units import ureg


DESCRIPTION = """\
Analyse a run-down diagram n(t) of a rotor after its drive is disconnected
(the TMM-7M lab sheet, TMM-7M rig): I*dw/dt = -M, M = f*G*r for a plain bearing.

Input DATA.csv: one column 't [UNIT]' (a time unit, e.g. 't [s]') and one
column 'n [UNIT]' (a shaft speed: 1/min, rpm, Hz or rad/s), one sample a row,
times increasing. Other columns are ignored.

Output (stdout): the model chosen among coulomb, coulomb_viscous and
coulomb_viscous_aero (M = M_c + c_v*w + c_a*w^2, chosen by 5-fold
cross-validation and BIC: the simpler of the two choices), the components with
95 % confidence intervals, the TMM-7M lab sheet's constant f, the RMSE of n(t) with
constant f (before) and with the chosen model (after), the run-down time, the
energy dissipated, and f against n by formula (2) over intervals.

Rig parameters with units (defaults: TMM-7M): --I 2.6kg*m^2 --G 1100N --r 25mm.
f = M/(G*r) is that of the rotor only with its own G and r: a value left out is
the TMM-7M rig's, and the report says so. --torque-only (for a rotor whose
journal load or radius is unknown) computes the torques without f: the report
says f is not computed and summary.json has f_constant null.
Intervals for formula (2): --dn 100rpm (speed steps) or --dt 10s (time steps);
default 10 equal speed steps. --window: Savitzky-Golay window in samples.

Rolling-bearing spindle (the Schaeffler catalogue M0 + M1 form): --spindle --nu 20mm^2/s
--dM 50mm [--bearings 2] [--P 1000N] [--f0 1.7] fits f0 and M1 (and f1 = M1/(P*dM))
so that f0 can be audited against the catalogue value given by --f0.

--out-dir DIR writes DIR/report.md, DIR/coastdown.png and DIR/summary.json
(keys include model, 'M_c [N*m]', 'c_v [N*m*s]', 'c_a [N*m*s^2]' with their
95 % intervals, e.g. 'M_c_ci95 [N*m]' (null for a component the chosen model
does not have: it is 0 there, not measured), f_constant (null with
--torque-only), f_computed, rig_defaults (the rig values left at the TMM-7M
defaults), 'rmse_before [1/min]', 'rmse_after [1/min]', rundown_time_warning
(a run-down time extrapolated more than 10 times the record's duration past
it, else null)). Existing files in DIR are
replaced only with --force; each file is written atomically. --json prints
the summary instead of the report; -q prints nothing but errors.

Exit codes: 0 done; 2 unusable input (missing file or column, bad cell, bad
unit, too few samples, speed not falling, --f0 not > 0) or a file fault."""


#: the files written into --out-dir DIR
_FILES = ("coastdown.png", "report.md", "summary.json")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("data", metavar="DATA.csv", help="run-down samples: columns 't [s]' and 'n [1/min]'")
    parser.add_argument("--I", default=None, help="moment of inertia about the shaft (default 2.6kg*m^2, TMM-7M)")
    parser.add_argument("--G", default=None, help="rotor weight = journal load (default 1100N, TMM-7M)")
    parser.add_argument("--r", default=None, help="journal radius (default 25mm, TMM-7M)")
    parser.add_argument("--torque-only", action="store_true",
                        help="no friction coefficient f, torques only (journal load or radius unknown); "
                             "not with --G or --r")
    parser.add_argument("--window", type=int, default=None, help="Savitzky-Golay window, odd number of samples")
    intervals = parser.add_mutually_exclusive_group()
    intervals.add_argument("--dn", default=None, help="speed step of the formula (2) intervals, e.g. 100rpm")
    intervals.add_argument("--dt", default=None, help="time step of the formula (2) intervals, e.g. 10s")
    add_out_dir(parser, "report.md, coastdown.png and summary.json")
    add_json(parser)
    add_quiet(parser)
    add_force(parser)
    add_csv_arguments(parser)
    parser.add_argument("--spindle", action="store_true", help="also fit the Schaeffler catalogue rolling-bearing form")
    parser.add_argument("--nu", default=None, help="oil viscosity at operating temperature, e.g. 20mm^2/s")
    parser.add_argument("--dM", default=None, help="bearing mean diameter (d + D)/2, e.g. 50mm")
    parser.add_argument("--bearings", type=int, default=2, help="number of identical bearings (default 2)")
    parser.add_argument("--P", default=None, help="load that sets M1 of one bearing, e.g. 1000N (gives f1)")
    parser.add_argument("--f0", type=float, default=None, help="catalogue f0 to audit against (> 0)")


#: a unit of each option's kind, for the message of a number typed without one
_EXAMPLE_UNITS = {"--I": "kg*m^2", "--G": "N", "--r": "mm", "--dn": "rpm", "--dt": "s", "--nu": "mm^2/s",
                  "--dM": "mm", "--P": "N"}


_quantity = functools.partial(option_quantity, examples=_EXAMPLE_UNITS)


def run(args: argparse.Namespace) -> int:
    if args.out_dir:
        check_outputs(args.out_dir, _FILES, force=args.force, inputs=(args.data,), create=False)
    try:
        t, n = read_rundown(args.data, sep=args.sep, decimal=args.decimal)
    except BearingheatError as exc:
        raise UsageError(str(exc)) from exc
    if args.torque_only and (args.G is not None or args.r is not None):
        raise UsageError("--torque-only computes no f and takes no --G or --r")
    # a value left out is the API's TMM-7M default (and the result names it in rig_defaults)
    rig: dict[str, Any] = {name: _quantity(getattr(args, name), f"--{name}") for name in ("I", "G", "r")
                           if getattr(args, name) is not None}
    if args.torque_only:
        rig.update(G=None, r=None)
    dn = None if args.dn is None else _quantity(args.dn, "--dn")
    dt = None if args.dt is None else _quantity(args.dt, "--dt")
    try:
        result = analyse_coastdown(t, n, interval_dn=dn, interval_dt=dt, window=args.window, **rig)
        if args.spindle:
            missing = [flag for flag, value in (("--nu", args.nu), ("--dM", args.dM)) if value is None]
            if missing:
                raise UsageError(f"--spindle needs {' and '.join(missing)}")
            result.spindle = analyse_spindle_coastdown(
                t, n, I=result.I * ureg()("kg*m^2"), nu=_quantity(args.nu, "--nu"), dM=_quantity(args.dM, "--dM"),
                bearings=args.bearings, P=None if args.P is None else _quantity(args.P, "--P"),
                f0_catalogue=args.f0)
    except BearingheatError as exc:
        raise UsageError(str(exc)) from exc
    if args.json:
        print(json.dumps(coastdown_summary(result), ensure_ascii=False))
    elif not args.quiet:
        print(render_report(result, args.data, png=None))
    if args.out_dir:
        write_coastdown_outputs(result, args.out_dir, args.data, force=args.force, inputs=(args.data,))
    return 0
