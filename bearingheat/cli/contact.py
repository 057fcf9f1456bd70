"""``bearingheat contact``: contact angle, stiffness C* and minimum axial load of ball bearings (Zaitsev & Voronkin)."""
from __future__ import annotations

import argparse
import csv
import io
import json
import sys
from pathlib import Path
from typing import Any

from bearingheat.api.contact import ball_bearing_contact
from bearingheat.calc.contract import parse_header
from bearingheat.cli import UsageError
from bearingheat.cli.options import add_json, add_quiet
from bearingheat.errors import BearingheatError, InputError, UnitError
from bearingheat.io.console import print_record
from bearingheat.io.tables import escape_cell, read_text, sniff_format
from bearingheat.units import parse_quantity, parse_unit, ureg


DESCRIPTION = """\
Contact of a ball bearing after Zaitsev & Voronkin (2009): the initial contact
angle alpha0 (given, or from the mean radial clearance), the stiffness
characteristic C*, the working contact angle alpha under the axial load Fa, the
dimensionless axial displacement xi_a, and the minimum axial load Fa_min against
gyroscopic sliding of the balls at the speed n.

One bearing from arguments (every length, angle, force and speed with its unit):

  bearingheat contact --z 7 --dw 2mm --dm 8.7355mm --ri 1.05mm --ro 1.16mm \\
      --alpha0 12deg --Fa 2kgf --n 3000rpm

  --z        number of balls (plain number)
  --dw       ball diameter                 --dm  pitch diameter (ball centres)
  --ri, --ro groove radius of the inner / outer ring
  --alpha0   initial contact angle (deg, rad) or --clearance, mean radial clearance
  --Fa       axial load (N, kN, kgf); default 0 N, which gives alpha = alpha0
  --n        inner-ring speed (1/min, rpm, Hz, rad/s); needed for Fa_min

Several bearings from a CSV file (the TABLE argument), one bearing a row. Header cells are
'name [unit]' with any unit of the right dimension; unknown columns are ignored:

  z, Dw [mm], dm_pitch [mm], ri [mm], ro [mm], alpha0 [deg] or clearance [mm],
  optional Fa [N], n [1/min] and designation (a text label).

Output: 'key: value' lines (one bearing) or CSV (a TABLE); --json prints one JSON
object (one bearing) or a list of objects (a TABLE). Keys: alpha0 [deg], Fa [N],
alpha [deg], xi_a, delta_a [mm], C_star [N], sum_rho_i [1/mm], sum_rho_o [1/mm],
cos_tau_i, cos_tau_o, 2K/(mu*pi)_i, 2K/(mu*pi)_o, and with n: n [1/min], Fa_min [N]
(at alpha0, Zaitsev & Voronkin's rule) and Fa_min at alpha [N] (at the working angle, the
stricter). A warning goes to stderr when a given Fa is below Fa_min or below Fa_min at alpha.
With -q nothing is printed but errors (--json still prints its JSON).

Exit codes: 0 ok (warnings included), 1 some CSV rows in error (reported in the
'error' column / key and on stderr), 2 unusable input (bad argument, impossible
geometry of the one bearing, missing file or column).
"""

# option -> (keyword of ball_bearing_contact, CSV column, kind)
_FIELDS = {
    "z": ("z", "z", "count"),
    "dw": ("d_w", "Dw", "length"),
    "dm": ("d_m", "dm_pitch", "length"),
    "ri": ("r_i", "ri", "length"),
    "ro": ("r_o", "ro", "length"),
    "alpha0": ("alpha0", "alpha0", "angle"),
    "clearance": ("clearance", "clearance", "length"),
    "Fa": ("Fa", "Fa", "force"),
    "n": ("n", "n", "speed"),
}
_REQUIRED = ("z", "dw", "dm", "ri", "ro")
_CHECK_UNIT = {"length": "mm", "angle": "deg", "force": "N", "speed": "1/min"}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    for option, (_, _, kind) in _FIELDS.items():
        example = {"count": "7", "length": "2mm", "angle": "12deg", "force": "2kgf", "speed": "3000rpm"}[kind]
        parser.add_argument(f"--{option}", metavar="N" if kind == "count" else "VALUE",
                            help=f"{kind}, e.g. {example}")
    parser.add_argument("input", metavar="TABLE", nargs="?",
                        help="CSV file with one bearing a row (see above); without it one bearing from the options")
    add_json(parser)
    add_quiet(parser)


def run(args: argparse.Namespace) -> int:
    if args.input is not None:
        given = [f"--{option}" for option in _FIELDS if getattr(args, option) is not None]
        if given:
            raise UsageError(f"TABLE gives the bearings; drop {', '.join(given)}")
        return _run_csv(args.input, args.json, args.quiet)

    missing = [f"--{option}" for option in _REQUIRED if getattr(args, option) is None]
    if missing:
        raise UsageError(f"missing {', '.join(missing)} (or give a TABLE of bearings)")
    if (args.alpha0 is None) == (args.clearance is None):
        raise UsageError("give exactly one of --alpha0 (e.g. 12deg) or --clearance (e.g. 0.01mm)")
    try:
        inputs = {_FIELDS[o][0]: _parse_argument(o, getattr(args, o)) for o in _FIELDS if getattr(args, o) is not None}
        record, warning = _evaluate(inputs)
    except BearingheatError as exc:  # UnitError, ContactInputError: unusable input, exit 2
        raise UsageError(str(exc)) from exc
    if warning:
        record["warning"] = warning
        if not args.quiet:
            print(f"bearingheat contact: warning: {warning}", file=sys.stderr)
    if args.json:
        print(json.dumps(record, ensure_ascii=False))
    elif not args.quiet:
        print_record(record)
    return 0


def _parse_argument(option: str, text: str) -> Any:
    kind = _FIELDS[option][2]
    if kind == "count":
        try:
            return float(text)
        except ValueError:
            raise UnitError(f"--{option}: {text!r} is not a number") from None
    return parse_quantity(text, name=f"--{option}", example={"length": "mm", "angle": "deg", "force": "N",
                                                             "speed": "rpm"}.get(kind))


def _evaluate(inputs: dict[str, Any]) -> tuple[dict[str, Any], str | None]:
    """Run ball_bearing_contact on one bearing; return the output record and its warning (or None): a given Fa
    below the minimum axial load Fa_min at alpha0 or at alpha, the result's status."""
    result = ball_bearing_contact(**inputs)
    return result.to_dict(), result.messages[0] or None


def _run_csv(path: str, as_json: bool, quiet: bool = False) -> int:
    file = Path(path)
    if not file.is_file():
        raise UsageError(f"no such file: {path}")
    if not file.read_bytes().strip():
        raise UsageError(f"{path}: the file is empty")
    text = read_text(file)
    sep, decimal = sniff_format(text)
    rows = [row for row in csv.reader(io.StringIO(text, newline=""), delimiter=sep)]
    while rows and not rows[0]:
        rows.pop(0)
    if not rows:
        raise UsageError(f"{path}: the file is empty")
    header = [parse_header(cell, strict=False) for cell in rows[0]]
    by_column = {name: option for option, (_, name, _) in _FIELDS.items()}
    columns: dict[str, tuple[int, Any]] = {}  # option -> (position, pint unit or None for a count)
    label_position = None
    for position, (name, unit_text) in enumerate(header):
        if name == "designation":
            label_position = position
            continue
        option = by_column.get(name)
        if option is None:
            continue
        kind = _FIELDS[option][2]
        if kind == "count":
            columns[option] = (position, None)
            continue
        if unit_text is None:
            raise UsageError(f"{path}: column {name!r} has no unit; write it as '{name} [{_CHECK_UNIT[kind]}]'")
        try:
            unit = parse_unit(unit_text, name=f"column {name!r}")
        except UnitError as exc:
            raise UsageError(f"{path}: {exc}") from exc
        unitless_angle = kind == "angle" and ureg().Quantity(1.0, unit).unitless
        if unitless_angle or not ureg().Quantity(1.0, unit).is_compatible_with(_CHECK_UNIT[kind]):
            raise UsageError(f"{path}: column {name!r}: unit {unit_text!r} is not a{'n' if kind[0] in 'ae' else ''} "
                             f"{kind}; write it as '{name} [{_CHECK_UNIT[kind]}]'")
        columns[option] = (position, unit)
    missing = [_FIELDS[o][1] for o in _REQUIRED if o not in columns]
    if "alpha0" not in columns and "clearance" not in columns:
        missing.append("alpha0 [deg] or clearance [mm]")
    if missing:
        raise UsageError(f"{path}: missing column(s) {', '.join(missing)}")
    if not any(any(cell.strip() for cell in row) for row in rows[1:]):
        raise UsageError(f"{path}: no bearings (only a header row)")

    records: list[dict[str, Any]] = []
    failures = 0
    for number, cells in enumerate(rows[1:], start=1):
        if not any(cell.strip() for cell in cells):
            continue
        record: dict[str, Any] = {"row": number}
        if label_position is not None and label_position < len(cells):
            record["designation"] = cells[label_position].strip()
        try:
            inputs: dict[str, Any] = {}
            for option, (position, unit) in columns.items():
                text = cells[position].strip() if position < len(cells) else ""
                column = _FIELDS[option][1]
                if not text:
                    if option in _REQUIRED:
                        raise InputError(f"{column} is empty")
                    continue
                try:
                    value = float(text.replace(",", ".") if decimal == "," else text)
                except ValueError:
                    raise InputError(f"{column}: {text!r} is not a number") from None
                inputs[_FIELDS[option][0]] = value if unit is None else ureg().Quantity(value, unit)
            result, warning = _evaluate(inputs)
            record.update(result)
            if warning:
                record["warning"] = warning
                if not quiet:
                    print(f"bearingheat contact: warning: row {number}: {warning}", file=sys.stderr)
        except BearingheatError as exc:  # a row in error: reported in its record, exit 1
            failures += 1
            record["error"] = str(exc)
            print(f"bearingheat contact: error: row {number}: {exc}", file=sys.stderr)
        records.append(record)

    if as_json:
        print(json.dumps(records, ensure_ascii=False))
    elif not quiet:
        keys: list[str] = []
        for record in records:
            keys.extend(k for k in record if k not in keys and k not in ("warning", "error"))
        keys += ["warning", "error"]
        writer = csv.DictWriter(sys.stdout, fieldnames=keys, lineterminator="\n")
        writer.writeheader()
        for record in records:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else escape_cell(v)) for k, v in record.items()})
    return 1 if failures else 0
