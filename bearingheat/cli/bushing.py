"""``bearingheat bushing``: size a DU/DP self-lubricating bushing or thrust washer by pV (the DU/DP bushing handbook)."""
from __future__ import annotations

import argparse
import functools
import json
import re
import sys

import numpy as np

from bearingheat.api.bushing import BushingSize, ThrustWasherSize, size_bushing, size_thrust_washer
from bearingheat.catalogue.bushing import KGF_PER_CM2
from bearingheat.cli import UsageError
from bearingheat.cli.options import add_json, add_quiet, option_quantity
from bearingheat.io.json import json_safe
from bearingheat.errors import BearingheatError, OutsideMethodError, UnitError
from bearingheat.kernels.bushing import oscillating_speed_du_dp
from bearingheat.units import magnitude, quantity, speed_rpm


DESCRIPTION = """\
Size a self-lubricating DU/DP bushing (length) or thrust washer (outer
diameter) by the DU/DP bushing handbook: l = pi*n*F/(60000*K) from the admissible K = pV,
checked against the admissible pressure [p]; lengthened from [p] when needed;
rounded up to the next standard size from --standard.

Values take units: --F 2kN --n 500rpm --d 25mm. The DU/DP bushing handbook works in kgf/cm^2
and m/s; 1 kgf/cm^2 = 0.0980665 N/mm^2, and the output shows the conversion.

--application: bushing_constant_load, bushing_rotating_load,
  bushing_oscillating, guide, thrust_washer (d = inner diameter, F axial).
--shaft soft|hardened and --life 1000h|10000h pick K from the DU/DP bushing handbook table 25
  (some cells were lost in the DU/DP bushing handbook's OCR: then give --K, e.g. 0.5N/mm^2*m/s).
--load-type: static (1410 kgf/cm^2), rotating_fixed_load_point (565),
  moving_load_moderate (282), moving_load_severe (141).
--T 150degC derates K: 1 up to 120 degC, linear to 0.5 at 280 degC
  (range -200 to +280 degC).
Oscillation: --cycles 30/min --amplitude 90deg instead of --n
  (n = cycles x amplitude in revolutions, the DU/DP bushing handbook).
--f: friction coefficient for the power loss N = f*F*V; default the handbook's
  range (0.05-0.1 at 0.05-0.1 m/s, 0.1-0.2 at 0.2-5 m/s).
--json prints the result as JSON; -q prints nothing but errors (a duty outside
  the method is one: its message goes to stderr, exit 1).

Below V = 0.05 m/s or above n = 15 000 1/min the handbook allows a smaller size
than calculated: the size is given with a note that it is conservative.

Exit codes: 0 sized; 1 the duty lies outside the DU/DP bushing handbook's method (T
outside -200..280 degC, no standard size large enough); 2 unusable input (bad
value, unit or name)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--F", required=True, help="load (radial for a bushing, axial for a washer), e.g. 2kN")
    parser.add_argument("--n", default=None, help="shaft speed, e.g. 500rpm")
    parser.add_argument("--cycles", default=None, help="oscillation frequency, e.g. 30/min (with --amplitude)")
    parser.add_argument("--amplitude", default=None, help="oscillation amplitude, e.g. 90deg")
    parser.add_argument("--d", required=True, help="bore (inner diameter), e.g. 25mm")
    parser.add_argument("--application", default="bushing_constant_load",
                        help="duty of the DU/DP bushing handbook table 25 (default bushing_constant_load)")
    parser.add_argument("--shaft", default=None, help="soft or hardened (table 25)")
    parser.add_argument("--life", default=None, help="1000h or 10000h (table 25)")
    parser.add_argument("--K", default=None, help="admissible pV instead of table 25, e.g. 0.5N/mm^2*m/s")
    parser.add_argument("--load-type", required=True, help="load type for [p]")
    parser.add_argument("--p-adm", default=None, help="admissible pressure instead of the load type, e.g. 20N/mm^2")
    parser.add_argument("--T", default=None, help="operating temperature, e.g. 150degC")
    parser.add_argument("--standard", default=None, help="standard lengths (outer diameters), e.g. 10,15,20,25mm")
    parser.add_argument("--f", type=float, default=None, help="friction coefficient for the power loss")
    add_json(parser)
    add_quiet(parser)


#: a unit of each option's kind, for the message of a number typed without one
_EXAMPLE_UNITS = {"--F": "kN", "--n": "rpm", "--d": "mm", "--life": "h", "--T": "degC", "--K": "N/mm^2*m/s",
                  "--p-adm": "N/mm^2", "--cycles": "1/min", "--amplitude": "deg"}


_quantity = functools.partial(option_quantity, examples=_EXAMPLE_UNITS)


def parse_list(text: str, name: str):
    """'10,15,20mm' -> Quantity array [10, 15, 20] mm."""
    match = re.match(r"^\s*([-+0-9.eE,\s]+?)\s*([A-Za-z].*)$", text)
    if not match:
        raise UsageError(f"{name}: {text!r} is not a list of numbers with one unit, e.g. 10,15,20mm")
    numbers, unit = match.groups()
    try:
        values = [float(v) for v in numbers.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"{name}: {text!r} is not a list of numbers with one unit, e.g. 10,15,20mm") from None
    quantity = _quantity(f"1{unit}", name)
    return np.array(values) * quantity


def _speed(args):
    if args.n is not None:
        if args.cycles or args.amplitude:
            raise UsageError("give either --n or --cycles with --amplitude, not both")
        return _quantity(args.n, "--n")
    if args.cycles is None or args.amplitude is None:
        raise UsageError("give the shaft speed --n, or --cycles and --amplitude for an oscillating shaft")
    try:
        cycles_text = re.sub(r"^([-+0-9.eE]+)\s*/", r"\1 1/", args.cycles.strip())  # '30/min' -> '30 1/min'
        cycles = speed_rpm(_quantity(cycles_text, "--cycles"), "--cycles")
        amplitude_rev = magnitude(_quantity(args.amplitude, "--amplitude"), "turn", "--amplitude")
    except UnitError as exc:
        raise UsageError(str(exc)) from exc
    return quantity(oscillating_speed_du_dp(cycles, amplitude_rev), "1/min")


def run(args: argparse.Namespace) -> int:
    common = {
        "shaft": args.shaft,
        "life": None if args.life is None else _quantity(args.life, "--life"),
        "load_type": args.load_type,
        "T": None if args.T is None else _quantity(args.T, "--T"),
        "K": None if args.K is None else _quantity(args.K, "--K"),
        "p_adm": None if args.p_adm is None else _quantity(args.p_adm, "--p-adm"),
        "f": args.f,
    }
    F, d, n = _quantity(args.F, "--F"), _quantity(args.d, "--d"), _speed(args)
    standard = None if args.standard is None else parse_list(args.standard, "--standard")
    result: BushingSize | ThrustWasherSize
    try:
        if args.application == "thrust_washer":
            result = size_thrust_washer(F, n, d, standard_diameters=standard, **common)
        else:
            result = size_bushing(F, n, d, application=args.application, standard_lengths=standard, **common)
    except OutsideMethodError as exc:  # NoStandardSizeError included: the duty lies outside the method, exit 1
        print(f"bearingheat bushing: {exc}", file=sys.stderr)
        return 1
    except BearingheatError as exc:  # UnitError, BushingInputError: unusable input, exit 2
        raise UsageError(str(exc)) from exc
    plain = result.to_dict()
    if args.json:
        print(json.dumps(json_safe({k: (float(v) if isinstance(v, (int, float)) else v) for k, v in plain.items()}),
                         indent=2))
    elif not args.quiet:
        print(render(plain, args.application))
    return 0


def render(r: dict, application: str) -> str:
    """Text report of the sizing steps."""
    k_table = r["K_table [N/mm^2*m/s]"]
    lines = [f"DU/DP {'thrust washer' if r['kind'] == 'thrust_washer' else 'bushing'} sizing, the DU/DP bushing handbook ({application})",
             f"  load F = {r['F [N]']:g} N, speed n = {r['n [1/min]']:.4g} 1/min, bore d = {r['d [mm]']:g} mm",
             f"  1. K = pV = {k_table / KGF_PER_CM2:.4g} kgf/cm²·m/s × 0.0980665 = {k_table:.4g} N/mm²·m/s"]
    if r["temperature_factor"] != 1.0:
        lines.append(f"     derated at T = {r['T [degC]']:g} °C by {r['temperature_factor']:.3g}: "
                     f"K = {r['K [N/mm^2*m/s]']:.4g} N/mm²·m/s")
    p_adm = r["p_adm [N/mm^2]"]
    if r["kind"] == "bushing":
        lines += [f"  2. l = π·n·F/(60000·K) = {r['l_pV [mm]']:.4g} mm (p there = {r['p_at_l_pV [N/mm^2]']:.4g} N/mm²)",
                  f"  3. [p] = {p_adm / KGF_PER_CM2:.4g} kgf/cm² = {p_adm:.4g} N/mm²; l from [p] = F/([p]·d) = "
                  f"{r['l_p [mm]']:.4g} mm -> governed by {r['governing']}: l = {r['l_required [mm]']:.4g} mm"]
        if r["l_standard [mm]"] == r["l_standard [mm]"]:
            lines.append(f"  4. standard length: {r['l_standard [mm]']:g} mm")
    else:
        lines += [f"  2. width b = (D - d)/2 = n·F/(60000·K) = {r['b_pV [mm]']:.4g} mm -> D = {r['D_pV [mm]']:.4g} mm",
                  f"  3. [p] = {p_adm / KGF_PER_CM2:.4g} kgf/cm² = {p_adm:.4g} N/mm²; D from [p] = "
                  f"sqrt(d² + 4F/(π[p])) = {r['D_p [mm]']:.4g} mm -> governed by {r['governing']}: "
                  f"D = {r['D_required [mm]']:.4g} mm"]
        if r["D_standard [mm]"] == r["D_standard [mm]"]:
            lines.append(f"  4. standard outer diameter: {r['D_standard [mm]']:g} mm")
    lines += [f"  at the chosen size: p = {r['p [N/mm^2]']:.4g} N/mm², V = {r['V [m/s]']:.4g} m/s, "
              f"pV = {r['pV [N/mm^2*m/s]']:.4g} N/mm²·m/s"]
    life = r["life_fig86 [h]"]
    lines.append(f"  life by fig. 86 (two-point fit): {life:.4g} h" if life == life else
                 f"  life by fig. 86: not estimated ({r['life_note']})")
    if r["f_low"] == r["f_low"]:
        if r["f_low"] == r["f_high"]:
            lines.append(f"  friction loss N = f·F·V = {r['N_low [W]']:.4g} W (f = {r['f_low']:g})")
        else:
            lines.append(f"  friction loss N = f·F·V = {r['N_low [W]']:.4g} to {r['N_high [W]']:.4g} W "
                         f"(f = {r['f_low']:g} to {r['f_high']:g}, the DU/DP bushing handbook)")
    else:
        lines.append(f"  friction loss: the DU/DP bushing handbook gives no f "
                     f"{'below 0.05' if r['V [m/s]'] < 0.05 else 'above 5'} m/s; give --f")
    if r["size_note"]:
        lines.append(f"  note: {r['size_note']}")
    return "\n".join(lines)
