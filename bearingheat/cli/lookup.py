"""``bearingheat lookup``: a bearing's dimensions, load ratings, factors and speeds by designation."""
from __future__ import annotations

import json
import math

from bearingheat.api.bearings import bearing
from bearingheat.catalogue.bearings import NUMERIC, table_header
from bearingheat.cli import UsageError
from bearingheat.cli.options import add_json, add_quiet
from bearingheat.errors import DesignationError
from bearingheat.io.console import print_record


DESCRIPTION = """\
Look a bearing up in the bearing table of the package (Schaeffler HR 1, June 2006:
deep groove ball 618, 619, 160, 60, 62, 63, 64 open, -2Z and -2RSR, 622 and 623 -2RSR;
angular contact ball 70..-B, 72..-B, 73..-B, open and -2RS, and 718..-B; cylindrical
roller N, NU, NJ, NUP of series 2, 3, 22, 23, E design, and NU10..-M1, NU19..-M1;
tapered roller 302, 303, 313, 320, 322, 323, 329, 330, 331, 332 and the ISO 355 codes
T7FC.., T4CB.., T2EE.., T5ED..):

  bearingheat lookup 6208
  bearingheat lookup NU208-E --json

The designation matches as printed first, then without cage, material, clearance and
tolerance suffixes (NU208-E finds NU208-E-TVP2), then, when it has no design suffix,
without the table's design suffix (NU208, 30208). Seal and shield suffixes must match.

Output: 'name [unit]: value' lines: designation, match (exact, cage or design), note
(how it was matched, when not exactly), family, bearing_type, series, prefix, shield,
d, D, B, T [mm], C, C0 [N], e, Y, Y0, n_G (limiting speed), n_thr (the catalogue's
thermal reference speed) [1/min], and source (catalogue, pages, table, row). Values the
catalogue does not give (T, e, Y, Y0 of a ball or cylindrical roller bearing) are left
out, but for n_thr of a bearing with contact seals (6205-2RSR) the line says that HR 1
gives none and why, and for the open bearings HR 1 prints without one (7004-B-TVP,
71810-B-TVH, NU1992-M1) that it gives none; --json prints one JSON object with the same
keys and null for them. With -q nothing is printed: the exit code alone says whether
the designation is in the table.

Exit codes: 0 found; 2 unknown or ambiguous designation (the message lists close
designations of the table).
"""

_TEXT = ("designation", "match", "note", "family", "bearing_type", "series", "prefix", "shield")
#: the n_thr line of a bearing with contact seals
SEALED_N_THR = ("not given: HR 1 prints no thermal reference speed for bearings with contact seals (the reference "
                "conditions of ISO 15312 have no seal friction)")
#: the n_thr line of an open bearing HR 1 prints without one (70..-B-TVP, 718..-B-TVH, NU19..-M1)
OPEN_WITHOUT_N_THR = "not given: HR 1 prints none for this bearing ('–')"


def add_arguments(parser) -> None:
    parser.add_argument("designation", help="bearing designation, e.g. 6208, 6208-2Z, 6208-2RSR, NU208-E-TVP2, "
                                                "30208-A")
    add_json(parser)
    add_quiet(parser)


def run(args) -> int:
    try:
        data = bearing(args.designation)
    except DesignationError as exc:  # unknown or ambiguous: unusable input, exit 2
        raise UsageError(str(exc)) from exc
    record = _record(data)
    if args.json:
        print(json.dumps(record, ensure_ascii=False))
    elif not args.quiet:
        if record["n_thr [1/min]"] is None:
            record["n_thr [1/min]"] = SEALED_N_THR if data.contact_sealed else OPEN_WITHOUT_N_THR
        print_record({key: value for key, value in record.items() if value is not None and value != ""},
                     float_format=".15g")
    return 0


def _record(data) -> dict:
    """The ordered output record: text fields, 'name [unit]' numbers (None for NaN), source."""
    record: dict = {key: getattr(data, key) for key in _TEXT}
    for name in NUMERIC:
        value = getattr(data, name)
        record[table_header(name)] = None if math.isnan(value) else value
    record["source"] = data.source
    return record
