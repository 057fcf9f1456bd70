"""``bearingheat coastdown``: friction coefficient and torque components from a run-down diagram (seed 003)."""
from __future__ import annotations

import argparse

HELP = "coast-down (run-down) analysis: reduced friction coefficient and torque components (seed 003)"

DESCRIPTION = """\
Analyse a run-down diagram n(t) of a rotor after its drive is disconnected
(seed 003, TMM-7M rig): I*dw/dt = -M, M = f*G*r for a plain bearing.

Input DATA.csv: one column 't [UNIT]' (a time unit, e.g. 't [s]') and one
column 'n [UNIT]' (a shaft speed: 1/min, rpm, Hz or rad/s), one sample a row,
times increasing. Other columns are ignored.

Output (stdout): the model chosen among coulomb, coulomb_viscous and
coulomb_viscous_aero (M = M_c + c_v*w + c_a*w^2, chosen by 5-fold
cross-validation and BIC: the simpler of the two choices), the components with
95 % confidence intervals, the seed's constant f, the RMSE of n(t) with
constant f (before) and with the chosen model (after), the run-down time, the
energy dissipated, and f against n by formula (2) over intervals.

Rig parameters with units (defaults: TMM-7M): --I 2.6kg*m^2 --G 1100N --r 25mm.
Intervals for formula (2): --dn 100rpm (speed steps) or --dt 10s (time steps);
default 10 equal speed steps. --window: Savitzky-Golay window in samples.

Rolling-bearing spindle (seed 002 M0 + M1 form): --spindle --nu 20mm^2/s
--dM 50mm [--bearings 2] [--P 1000N] [--f0 1.7] fits f0 and M1 (and f1 = M1/(P*dM))
so that f0 can be audited against the catalogue value given by --f0.

--out DIR writes DIR/report.md, DIR/coastdown.png and DIR/summary.json
(keys include model, 'M_c [N*m]', 'c_v [N*m*s]', 'c_a [N*m*s^2]', f_constant,
'rmse_before [1/min]', 'rmse_after [1/min]').

Exit codes: 0 done; 2 unusable input (missing file or column, bad cell, bad
unit, too few samples, speed not falling)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("data", metavar="DATA.csv", help="run-down samples: columns 't [s]' and 'n [1/min]'")
    parser.add_argument("--I", default="2.6kg*m^2", help="moment of inertia about the shaft (default 2.6kg*m^2)")
    parser.add_argument("--G", default="1100N", help="rotor weight = journal load (default 1100N)")
    parser.add_argument("--r", default="25mm", help="journal radius (default 25mm)")
    parser.add_argument("--window", type=int, default=None, help="Savitzky-Golay window, odd number of samples")
    intervals = parser.add_mutually_exclusive_group()
    intervals.add_argument("--dn", default=None, help="speed step of the formula (2) intervals, e.g. 100rpm")
    intervals.add_argument("--dt", default=None, help="time step of the formula (2) intervals, e.g. 10s")
    parser.add_argument("--out", default=None, metavar="DIR", help="write report.md, coastdown.png, summary.json")
    parser.add_argument("--spindle", action="store_true", help="also fit the seed 002 rolling-bearing form")
    parser.add_argument("--nu", default=None, help="oil viscosity at operating temperature, e.g. 20mm^2/s")
    parser.add_argument("--dM", default=None, help="bearing mean diameter (d + D)/2, e.g. 50mm")
    parser.add_argument("--bearings", type=int, default=2, help="number of identical bearings (default 2)")
    parser.add_argument("--P", default=None, help="load that sets M1 of one bearing, e.g. 1000N (gives f1)")
    parser.add_argument("--f0", type=float, default=None, help="catalogue f0 to audit against")


def read_rundown(path: str):
    """Read DATA.csv into (t Quantity array, n Quantity array); UsageError on unusable input."""
    import csv

    import numpy as np

    from bearingheat.cli import UsageError
    from bearingheat.frame import parse_header
    from bearingheat.units import UnitError, parse_unit, ureg

    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            rows = list(csv.reader(handle))
    except OSError as exc:
        raise UsageError(f"cannot read {path}: {exc.strerror}") from exc
    if not rows:
        raise UsageError(f"{path}: empty file")
    header = rows[0]
    found = {}
    for col, name in enumerate(header):
        key, unit_text = parse_header(name, strict=False)
        if key in ("t", "n") and unit_text is not None:
            found[key] = (col, name.strip(), unit_text)
    for key, example in (("t", "t [s]"), ("n", "n [1/min]")):
        if key not in found:
            raise UsageError(f"{path}: no column '{example}' (a '{key} [unit]' column); columns are: "
                             f"{', '.join(repr(h) for h in header)}")
    out = {}
    for key, (col, name, unit_text) in found.items():
        try:
            unit = parse_unit(unit_text, name=f"column '{name}'")
        except UnitError as exc:
            raise UsageError(str(exc)) from exc
        values = []
        for line, row in enumerate(rows[1:], start=2):
            cell = row[col].strip() if col < len(row) else ""
            try:
                values.append(float(cell))
            except ValueError:
                raise UsageError(f"{path} line {line}, column '{name}': {cell!r} is not a number") from None
        out[key] = ureg().Quantity(np.array(values), unit)
    return out["t"], out["n"]


def _quantity(text, name):
    from bearingheat.cli import UsageError
    from bearingheat.units import UnitError, parse_quantity

    try:
        return parse_quantity(text, name=name)
    except UnitError as exc:
        raise UsageError(str(exc)) from exc


def run(args: argparse.Namespace) -> int:
    import json
    import os

    from bearingheat import coastdown as cd
    from bearingheat.cli import UsageError
    from bearingheat.units import UnitError

    t, n = read_rundown(args.data)
    rig = {name: _quantity(getattr(args, name), f"--{name}") for name in ("I", "G", "r")}
    dn = None if args.dn is None else _quantity(args.dn, "--dn")
    dt = None if args.dt is None else _quantity(args.dt, "--dt")
    try:
        result = cd.analyse_coastdown(t, n, interval_dn=dn, interval_dt=dt, window=args.window, **rig)
        if args.spindle:
            missing = [flag for flag, value in (("--nu", args.nu), ("--dM", args.dM)) if value is None]
            if missing:
                raise UsageError(f"--spindle needs {' and '.join(missing)}")
            result.spindle = cd.analyse_spindle_coastdown(
                t, n, I=rig["I"], nu=_quantity(args.nu, "--nu"), dM=_quantity(args.dM, "--dM"),
                bearings=args.bearings, P=None if args.P is None else _quantity(args.P, "--P"),
                f0_catalogue=args.f0)
    except (UnitError, ValueError) as exc:
        raise UsageError(str(exc)) from exc
    text = render_report(result, args.data, png=None)
    print(text)
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        cd.plot_coastdown(result, os.path.join(args.out, "coastdown.png"))
        with open(os.path.join(args.out, "report.md"), "w", encoding="utf-8") as handle:
            handle.write(render_report(result, args.data, png="coastdown.png"))
        with open(os.path.join(args.out, "summary.json"), "w", encoding="utf-8") as handle:
            json.dump(result.summary(), handle, indent=2)
            handle.write("\n")
    return 0


def _ci(fit, name, digits=4):
    low, high = fit.interval(name)
    return f"{fit.value(name):.{digits}g} (95 % CI {low:.{digits}g} to {high:.{digits}g})"


def render_report(result, source: str, png: str | None) -> str:
    """Markdown report of a coast-down analysis (also printed to stdout)."""
    fit = result.chosen
    lines = [f"# Coast-down analysis of {source}", ""]
    rig = f"I = {result.I:g} kg·m²"
    if result.G is not None and result.r is not None:
        rig += f", G = {result.G:g} N, r = {result.r:g} mm"
    lines += [f"Rig: {rig}. Samples: {len(result.samples)}; Savitzky–Golay window {result.window} samples.", ""]
    lines += ["## Models of the resisting torque M(ω) = M_c + c_v·ω + c_a·ω²", "",
              "| model | M_c [N·m] | c_v [N·m·s] | c_a [N·m·s²] | RMSE [1/min] | CV RMSE [1/min] | BIC |",
              "|---|---|---|---|---|---|---|"]
    for name, f in result.fits.items():
        lines.append(f"| {name} | {f.value('M_c'):.4g} | {f.value('c_v'):.4g} | {f.value('c_a'):.4g} | "
                     f"{f.rmse:.4g} | {f.cv_rmse:.4g} | {f.bic:.1f} |")
    lines += ["", f"Chosen model: **{result.model}** (the simpler of the lowest-BIC and the lowest-CV-error model).", ""]
    for name, unit in (("M_c", "N·m"), ("c_v", "N·m·s"), ("c_a", "N·m·s²")):
        if name in fit.parameters:
            lines.append(f"- {name} = {_ci(fit, name)} {unit}")
    if fit.value("c_v") < 0 or fit.value("c_a") < 0:
        lines.append("- A negative component means the torque falls with speed over part of the range; "
                     "it is a curve shape, not a physical viscous or windage drag.")
    lines += ["", f"- Constant f (the seed's single coefficient, from the Coulomb-only fit): {result.f_constant:.4g}",
              f"- RMSE of n(t): {result.rmse_before:.4g} 1/min with constant f (before), "
              f"{result.rmse_after:.4g} 1/min with {result.model} (after)"]
    stop = result.rundown_time
    when = "extrapolated past the last sample" if result.rundown_extrapolated else "within the record"
    lines.append(f"- Run-down time to standstill: {stop:.4g} s ({when})" if stop != float("inf")
                 else "- The fitted torque does not bring the rotor to rest")
    e = result.energy
    lines.append(f"- Energy dissipated over the record: {e['total']:.4g} J (Coulomb {e['coulomb']:.4g} J, "
                 f"viscous {e['viscous']:.4g} J, aerodynamic {e['aero']:.4g} J); to standstill {e['to_standstill']:.4g} J")
    lines += ["", "## f against n, formula (2) over intervals", "",
              "| n from [1/min] | n to [1/min] | Δt [s] | M [N·m] | f |", "|---|---|---|---|---|"]
    for _, row in result.intervals.iterrows():
        lines.append(f"| {row['n_from [1/min]']:.4g} | {row['n_to [1/min]']:.4g} | {row['dt [s]']:.4g} | "
                     f"{row['M [N*m]']:.4g} | {row['f']:.4g} |")
    if result.spindle is not None:
        s = result.spindle
        lines += ["", "## Rolling-bearing form of seed 002: M = z·(M0 + M1)", "",
                  f"- bearings z = {s.bearings}, ν = {s.nu:g} mm²/s, dM = {s.dM:g} mm",
                  f"- f0 = {_ci(s.fit, 'f0')}", f"- M1 = {_ci(s.fit, 'M1')} N·mm per bearing",
                  f"- RMSE of n(t): {s.fit.rmse:.4g} 1/min"]
        if s.P:
            lines.append(f"- f1 = M1/(P·dM) = {s.f1:.4g} (P = {s.P:g} N)")
        if s.f0_catalogue is not None:
            lines.append(f"- catalogue f0 = {s.f0_catalogue:g}; fitted/catalogue = {s.f0 / s.f0_catalogue:.3g}")
    if png:
        lines += ["", f"![run-down data, constant-f fit and {result.model} fit]({png})"]
    return "\n".join(lines) + "\n"
