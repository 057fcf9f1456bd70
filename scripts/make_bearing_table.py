"""Generate ``tables/bearings_hr1_2006.csv`` from ``../shared/data/hr1_2006_reference_speeds.csv``.

The source file holds the dimensions, load ratings, calculation factors, limiting
and thermal reference speeds of 1034 bearings of the catalogue

    Schaeffler KG (INA/FAG), HR 1 "Rolling bearings", edition June 2006,

as extracted from the plain-text conversion in the public GitHub repository
ArtemFilin1990/Mar (file ``02_Термины_и_основы/Теория/типы подшипников/ROlling Bearings.md``,
commit 68b9707fc46f43fa4d0c070323c23237becbce8b); its companion
``hr1_2006_reference_speeds.md`` gives the extraction, the checks and the caveats.
``../shared/data/README.md`` asks that the data files are not copied into the project; the
package ships this derived table instead, generated here and kept in sync by
``tests/catalogue/test_bearings.py``.

What the script does, and nothing else:

- keeps every row, in the order of the source (catalogue page, row on the page);
- copies every number digit for digit as text (no float formatting, no rounding,
  no unit conversion: the catalogue's units mm, N and 1/min are the package's catalogue units);
- adds the package's bearing type and prefix from :func:`bearingheat.catalogue.designation.parse_designation`,
  and refuses to write when the parser disagrees with the source's family, series, type or bore;
- renames ``n_B`` (the catalogue's thermal reference speed) to ``n_thr``;
- writes a units row under the header (a pint unit, ``1`` dimensionless, ``-`` text) and a
  ``source`` column naming catalogue, edition, pages, table and row.

Usage (deterministic: the same source gives the same bytes)::

    .venv/bin/python scripts/make_bearing_table.py
    .venv/bin/python scripts/make_bearing_table.py --source PATH.csv --output PATH.csv
"""
from __future__ import annotations

import argparse
import csv
import io
import sys
from pathlib import Path

from bearingheat.catalogue.designation import parse_designation
from bearingheat.errors import DesignationError

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT.parent / "shared" / "data" / "hr1_2006_reference_speeds.csv"
OUTPUT = ROOT / "tables" / "bearings_hr1_2006.csv"

SOURCE_HEADER = [
    "designation", "family", "series", "type", "shield", "d [mm]", "D [mm]", "B [mm]", "T [mm]", "C [N]", "C0 [N]",
    "n_G [1/min]", "n_B [1/min]", "e [-]", "Y [-]", "Y0 [-]", "page", "page_ratings", "row_on_page",
]

# output column -> (unit of the units row, source column or None for a derived column)
COLUMNS = {
    "designation": ("-", "designation"),
    "family": ("-", "family"),
    "bearing_type": ("-", None),
    "series": ("-", "series"),
    "prefix": ("-", None),
    "shield": ("-", "shield"),
    "d": ("mm", "d [mm]"),
    "D": ("mm", "D [mm]"),
    "B": ("mm", "B [mm]"),
    "T": ("mm", "T [mm]"),
    "C": ("N", "C [N]"),
    "C0": ("N", "C0 [N]"),
    "e": ("1", "e [-]"),
    "Y": ("1", "Y [-]"),
    "Y0": ("1", "Y0 [-]"),
    "n_G": ("1/min", "n_G [1/min]"),
    "n_thr": ("1/min", "n_B [1/min]"),
    "source": ("-", None),
}

# source family -> the package's bearing type (bearingheat.catalogue.designation.BEARING_TYPES)
FAMILY_TYPES = {
    "deep groove ball": "deep_groove_ball",
    "angular contact ball": "angular_contact_ball",
    "cylindrical roller": "cylindrical_roller",
    "tapered roller": "tapered_roller",
}

# catalogue page ranges of the tables used (hr1_2006_reference_speeds.md, "Catalogue pages used")
PAGE_TABLES = [
    (196, 223, "deep groove ball bearings, single row"),
    (240, 247, "angular contact ball bearings, single row"),
    (366, 381, "cylindrical roller bearings with cage, N, NU"),
    (382, 401, "cylindrical roller bearings with cage, NJ, NUP"),
    (476, 491, "tapered roller bearings, single row, metric"),
]

CATALOGUE = "Schaeffler HR 1 (June 2006)"
COPY = "text copy ArtemFilin1990/Mar@68b9707"

ALWAYS = ("d [mm]", "D [mm]", "B [mm]", "C [N]", "C0 [N]", "n_G [1/min]", "n_B [1/min]")
TAPERED_ONLY = ("T [mm]", "e [-]", "Y [-]", "Y0 [-]")


class SourceError(Exception):
    """The source file is not what this script was written for."""


def _table_of(page: int, page_ratings: int, designation: str) -> str:
    for first, last, title in PAGE_TABLES:
        if first <= page <= last and first <= page_ratings <= last:
            return title
    raise SourceError(f"{designation}: pages {page}/{page_ratings} are in none of the tables {PAGE_TABLES}")


def _check_number(text: str, designation: str, column: str) -> None:
    try:
        value = float(text)
    except ValueError:
        raise SourceError(f"{designation}: {column} = {text!r} is not a number") from None
    if not value > 0:
        raise SourceError(f"{designation}: {column} = {text!r} is not positive")


def convert_row(row: dict[str, str]) -> list[str]:
    """One source row -> one output row (text cells in the order of :data:`COLUMNS`)."""
    name = row["designation"]
    family = row["family"]
    if family not in FAMILY_TYPES:
        raise SourceError(f"{name}: unknown family {family!r}")
    tapered = family == "tapered roller"
    for column in ALWAYS + TAPERED_ONLY:
        text = row[column]
        if column in ALWAYS or tapered:
            if text == "":
                raise SourceError(f"{name}: {column} is blank")
            _check_number(text, name, column)
        elif text != "":
            raise SourceError(f"{name}: {column} = {text!r} given for a {family} bearing")
    try:
        parsed = parse_designation(name)
    except DesignationError as exc:
        raise SourceError(f"{name}: the package's parser refuses it: {exc}") from None
    checks = {
        "bearing type": (parsed.bearing_type, FAMILY_TYPES[family]),
        "series": (parsed.series, row["series"]),
        "prefix": (parsed.prefix, row["type"]),
        "bore": (parsed.bore, float(row["d [mm]"])),
        "shield": (parsed.seal, {"open": "open", "2Z": "shield"}.get(row["shield"], row["shield"])),
    }
    for what, (ours, theirs) in checks.items():
        if ours != theirs:
            raise SourceError(f"{name}: the parser gives {what} {ours!r}, the source {theirs!r}")
    page, page_ratings, row_on_page = (int(row[c]) for c in ("page", "page_ratings", "row_on_page"))
    table = _table_of(page, page_ratings, name)
    source = (f"{CATALOGUE}, p. {page} (dimensions) and p. {page_ratings} (ratings), table '{table}', "
              f"row {row_on_page}; {COPY}")
    derived = {"bearing_type": parsed.bearing_type, "prefix": parsed.prefix, "source": source}
    return [row[column] if column is not None else derived[out] for out, (_, column) in COLUMNS.items()]


def build_table(source_text: str) -> str:
    """The text of the bearing table for the text of the source CSV."""
    reader = csv.DictReader(io.StringIO(source_text))
    if reader.fieldnames != SOURCE_HEADER:
        raise SourceError(f"unexpected header {reader.fieldnames}; expected {SOURCE_HEADER}")
    rows = [convert_row(row) for row in reader]
    names = [r[0] for r in rows]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise SourceError(f"designations given twice: {', '.join(duplicates)}")
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(list(COLUMNS))
    writer.writerow([unit for unit, _ in COLUMNS.values()])
    writer.writerows(rows)
    return out.getvalue()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", type=Path, default=SOURCE, help=f"source CSV (default {SOURCE})")
    parser.add_argument("--output", type=Path, default=OUTPUT, help=f"table to write (default {OUTPUT})")
    args = parser.parse_args(argv)
    try:
        text = build_table(args.source.read_text(encoding="utf-8"))
    except (OSError, SourceError) as exc:
        print(f"make_bearing_table: error: {exc}", file=sys.stderr)
        return 2
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_bytes(text.encode("utf-8"))
    print(f"wrote {args.output} ({text.count(chr(10)) - 2} bearings)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
