"""Generate ``tables/bearings_hr1_2006.csv`` from ``../shared/data/hr1_2006_reference_speeds.csv``
and ``scripts/hr1_2006_sealed_rows.csv``.

The first source file holds the dimensions, load ratings, calculation factors, limiting
and thermal reference speeds of 1034 bearings of the catalogue

    Schaeffler KG (INA/FAG), HR 1 "Rolling bearings", edition June 2006,

as extracted from the plain-text conversion in the public GitHub repository
ArtemFilin1990/Mar (file ``02_Термины_и_основы/Теория/типы подшипников/ROlling Bearings.md``,
commit 68b9707fc46f43fa4d0c070323c23237becbce8b); its companion
``hr1_2006_reference_speeds.md`` gives the extraction, the checks and the caveats.
``../shared/data/README.md`` asks that the data files are not copied into the project; the
package ships this derived table instead, generated here and kept in sync by
``tests/catalogue/test_bearings.py``.

That data set leaves out the bearings with contact seals, because HR 1 prints no thermal
reference speed for them. ``scripts/hr1_2006_sealed_rows.csv`` holds them, read from the same
text copy (its header comment gives the method, the checks and the one row left out): 87 deep
groove ball bearings ``-2RSR`` and 16 angular contact ball bearings ``72..-B-2RS-TVP`` and
``73..-B-2RS-TVP``, with dimensions, load ratings and limiting speed; their ``n_thr`` is blank.

It also leaves out, as out of its scope, series that the friction tables cover.
``scripts/hr1_2006_more_series_rows.csv`` holds them, read from the same text copy (its header
comment gives the method, the checks and the rows left out): 140 bearings, deep groove ball
619 (open, ``-2Z``, ``-2RSR``), ``622..-2RSR`` and ``623..-2RSR``, angular contact ball ``70..-B-TVP``,
``70..-B-2RS-TVP`` and ``718..-B-TVH``, cylindrical roller ``NU10..-M1`` and ``NU19..-M1``, tapered
roller 329 and those HR 1 designates by an ISO 355 code (T7FC, T4CB, T2EE, T5ED). HR 1 prints no
thermal reference speed for the open 70, 718 and NU19 bearings either (:data:`NO_REFERENCE_SPEED`):
their ``n_thr`` is blank too.

What the script does, and nothing else:

- keeps every row of the three sources, in catalogue order (page, row on the page);
- copies every number digit for digit as text (no float formatting, no rounding,
  no unit conversion: the catalogue's units mm, N and 1/min are the package's catalogue units);
- adds the package's bearing type and prefix from :func:`bearingheat.catalogue.designation.parse_designation`,
  and refuses to write when the parser disagrees with the source's family, series, type or bore;
- renames ``n_B`` (the catalogue's thermal reference speed) to ``n_thr``, blank for a sealed row and for the
  series of :data:`NO_REFERENCE_SPEED`;
- refuses to write a sealed row whose n_B is not "–", whose mounting dimensions d_a, D_a do not lie
  between d and D, or that differs from its open counterpart of the data set in d, D, B, C or C0;
- refuses to write a row of the more series whose n_B is "–" without contact seals (outside the series of
  :data:`NO_REFERENCE_SPEED`) or a number with them (or in those series), whose mounting dimensions do
  not lie between d and D, that differs from its open counterpart (when it has one) in d, D, B, C or
  C0, or, for a tapered bearing, whose T < B or whose e·Y is not
  0.6 ± 0.05 or Y0/Y not 0.55 ± 0.03 (the relations of HR 1's calculation factors);
- writes a units row under the header (a pint unit, ``1`` dimensionless, ``-`` text) and a
  ``source`` column naming catalogue, edition, pages, table and row.

Usage (deterministic: the same source gives the same bytes)::

    .venv/bin/python scripts/make_bearing_table.py
    .venv/bin/python scripts/make_bearing_table.py --source PATH.csv --sealed PATH.csv --more PATH.csv \
        --output PATH.csv
"""
from __future__ import annotations

import argparse
import csv
import io
import sys
from collections import Counter
from pathlib import Path

from bearingheat.catalogue.designation import parse_designation
from bearingheat.errors import DesignationError

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT.parent / "shared" / "data" / "hr1_2006_reference_speeds.csv"
SEALED = ROOT / "scripts" / "hr1_2006_sealed_rows.csv"
MORE = ROOT / "scripts" / "hr1_2006_more_series_rows.csv"
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

SEALED_HEADER = [
    "designation", "family", "series", "shield", "d [mm]", "D [mm]", "B [mm]", "C [N]", "C0 [N]", "n_G [1/min]",
    "n_B [1/min]", "d_a [mm]", "D_a [mm]", "open counterpart", "page", "page_ratings", "row_on_page", "line",
    "line_ratings",
]
# the contact seal of each family in HR 1 (the shield column of a sealed row)
SEALS = {"deep groove ball": "2RSR", "angular contact ball": "2RS"}
# the shield column -> the seal the package's parser reads from the designation
SEAL_KINDS = {"open": "open", "2Z": "shield", "2RSR": "contact", "2RS": "contact"}
# what a sealed row shares with its open counterpart (the same rings and balls)
SHARED = ("d [mm]", "D [mm]", "B [mm]", "C [N]", "C0 [N]")
# HR 1 prints this for a sealed bearing's n_B
NO_VALUE = "–"
# (family, series) whose open bearings HR 1 prints without n_B ("–") as well: angular contact ball 70..-B-TVP
# and 718..-B-TVH (pp. 240-245), cylindrical roller NU19..-M1 (p. 378/379); their n_thr is blank
NO_REFERENCE_SPEED = frozenset({("angular contact ball", "70"), ("angular contact ball", "718"),
                                ("cylindrical roller", "19")})

MORE_HEADER = [
    "designation", "family", "series", "type", "shield", "d [mm]", "D [mm]", "B [mm]", "T [mm]", "C [N]", "C0 [N]",
    "n_G [1/min]", "n_B [1/min]", "e [-]", "Y [-]", "Y0 [-]", "d_a [mm]", "D_a [mm]", "open counterpart", "page",
    "page_ratings", "row_on_page", "line", "line_ratings",
]
# the relations of HR 1's calculation factors of tapered roller bearings (hr1_2006_reference_speeds.md):
# e·Y and Y0/Y, each (value, tolerance)
TAPERED_E_Y = (0.6, 0.05)
TAPERED_Y0_Y = (0.55, 0.03)


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
    without_speed = _without_reference_speed(row)
    if without_speed and row["n_B [1/min]"] != "":
        raise SourceError(f"{name}: n_B = {row['n_B [1/min]']!r} given for a bearing with contact seals or of a "
                          "series HR 1 prints no n_B for")
    for column in ALWAYS + TAPERED_ONLY:
        text = row[column]
        if without_speed and column == "n_B [1/min]":
            continue
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
        "shield": (parsed.seal, SEAL_KINDS.get(row["shield"], row["shield"])),
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


def _without_reference_speed(row: dict[str, str]) -> bool:
    """HR 1 prints no n_B for the row's bearing: contact seals, or a series of :data:`NO_REFERENCE_SPEED`."""
    return SEAL_KINDS.get(row["shield"]) == "contact" or (row["family"], row["series"]) in NO_REFERENCE_SPEED


def _commented_rows(text: str, header: list[str], what: str) -> list[dict[str, str]]:
    """The rows of a CSV text whose comment lines begin with '#'; :class:`SourceError` unless its header is
    ``header``."""
    reader = csv.DictReader(line for line in io.StringIO(text) if not line.startswith("#"))
    if reader.fieldnames != header:
        raise SourceError(f"{what}: unexpected header {reader.fieldnames}; expected {header}")
    return list(reader)


def sealed_rows(sealed_text: str, source_rows: list[dict[str, str]]) -> list[dict[str, str]]:
    """The rows of the sealed-rows file (comment lines '#' skipped) as rows of the source CSV, each checked
    against the file's own values and against its open counterpart among ``source_rows``."""
    by_name = {row["designation"]: row for row in source_rows}
    out = []
    for row in _commented_rows(sealed_text, SEALED_HEADER, "sealed rows"):
        name = row["designation"]
        if row["shield"] != SEALS.get(row["family"]) or f"-{row['shield']}" not in name:
            raise SourceError(f"{name}: seal {row['shield']!r} is not the {row['family']!r} bearings' "
                              f"{SEALS.get(row['family'])!r} of HR 1, or not in the designation")
        if row["n_B [1/min]"] != NO_VALUE:
            raise SourceError(f"{name}: n_B = {row['n_B [1/min]']!r}; HR 1 prints {NO_VALUE!r} for a sealed bearing")
        _check_mounting(row)
        _check_counterpart(row, by_name)
        out.append({column: row.get(column, "") for column in SOURCE_HEADER} | {"n_B [1/min]": ""})
    return out


def _check_mounting(row: dict[str, str]) -> None:
    """d < d_a < D and d < D_a < D: the ratings row belongs to the bearing of the dimension row."""
    name = row["designation"]
    for column in ("d_a [mm]", "D_a [mm]"):
        _check_number(row[column], name, column)
        if not float(row["d [mm]"]) < float(row[column]) < float(row["D [mm]"]):
            raise SourceError(f"{name}: {column} = {row[column]} is not between d = {row['d [mm]']} and "
                              f"D = {row['D [mm]']}: the ratings row does not belong to this bearing")


def _check_counterpart(row: dict[str, str], by_name: dict[str, dict[str, str]]) -> None:
    """The row's open counterpart is an open bearing of ``by_name`` with the same d, D, B, C, C0."""
    name = row["designation"]
    counterpart = by_name.get(row["open counterpart"])
    if counterpart is None or counterpart["shield"] != "open":
        raise SourceError(f"{name}: its open counterpart {row['open counterpart']!r} is not an open bearing "
                          "of the source")
    differ = [c for c in SHARED if row[c] != counterpart[c]]
    if differ:
        raise SourceError(f"{name}: {', '.join(f'{c} = {row[c]}' for c in differ)} differ from "
                          f"{counterpart['designation']}'s {', '.join(counterpart[c] for c in differ)}")


def _check_tapered(row: dict[str, str]) -> None:
    """T >= B, and e·Y and Y0/Y within HR 1's relations (:data:`TAPERED_E_Y`, :data:`TAPERED_Y0_Y`)."""
    name = row["designation"]
    for column in ("B [mm]", "T [mm]", "e [-]", "Y [-]", "Y0 [-]"):
        _check_number(row[column], name, column)
    width, total, e, y, y0 = (float(row[c]) for c in ("B [mm]", "T [mm]", "e [-]", "Y [-]", "Y0 [-]"))
    if total < width:
        raise SourceError(f"{name}: T = {row['T [mm]']} is less than B = {row['B [mm]']}")
    for what, value, (target, tolerance) in (("e·Y", e * y, TAPERED_E_Y), ("Y0/Y", y0 / y, TAPERED_Y0_Y)):
        if abs(value - target) > tolerance:
            raise SourceError(f"{name}: {what} = {value:.3f} is not {target} ± {tolerance} (e = {row['e [-]']}, "
                              f"Y = {row['Y [-]']}, Y0 = {row['Y0 [-]']}): a calculation factor is misread")


def more_series_rows(more_text: str, known_rows: list[dict[str, str]]) -> list[dict[str, str]]:
    """The rows of the more-series file (comment lines '#' skipped) as rows of the source CSV, each checked
    against the file's own values and, where it names one, against its open counterpart among ``known_rows``
    and the file's own rows."""
    rows = _commented_rows(more_text, MORE_HEADER, "more series rows")
    by_name = {row["designation"]: row for row in known_rows + rows}
    out = []
    for row in rows:
        name = row["designation"]
        without_speed = _without_reference_speed(row)
        if without_speed != (row["n_B [1/min]"] == NO_VALUE):
            raise SourceError(f"{name}: n_B = {row['n_B [1/min]']!r} with shield {row['shield']!r}; HR 1 prints "
                              f"{NO_VALUE!r} for the bearings with contact seals and for the series "
                              f"{', '.join(sorted(series for _, series in NO_REFERENCE_SPEED))}, and for no other")
        _check_mounting(row)
        if row["open counterpart"]:
            _check_counterpart(row, by_name)
        elif row["shield"] != "open" and any(_body(n) == _body(name) and r["shield"] == "open"
                                             for n, r in by_name.items()):
            raise SourceError(f"{name}: names no open counterpart, but the sources hold an open bearing "
                              f"{_body(name)}")
        if row["family"] == "tapered roller":
            _check_tapered(row)
        out.append({column: row[column] for column in SOURCE_HEADER} | ({"n_B [1/min]": ""} if without_speed else {}))
    return out


def _body(designation: str) -> str:
    """The designation without suffixes: '61908-2RSR' -> '61908'."""
    return designation.split("-")[0]


def _catalogue_place(row: dict[str, str]) -> tuple[int, int]:
    return int(row["page"]), int(row["row_on_page"])


def build_table(source_text: str, sealed_text: str, more_text: str) -> str:
    """The text of the bearing table for the texts of the source CSV, of the sealed rows and of the more series."""
    reader = csv.DictReader(io.StringIO(source_text))
    if reader.fieldnames != SOURCE_HEADER:
        raise SourceError(f"unexpected header {reader.fieldnames}; expected {SOURCE_HEADER}")
    source_rows = list(reader)
    merged = source_rows + sealed_rows(sealed_text, source_rows)
    merged += more_series_rows(more_text, merged)
    twice = sorted(place for place, count in Counter(map(_catalogue_place, merged)).items() if count > 1)
    if twice:
        raise SourceError(f"catalogue places (page, row) given twice: {twice}")
    # catalogue order; the source is in it already (a stable sort keeps ties, which the check above excludes)
    rows = [convert_row(row) for row in sorted(merged, key=_catalogue_place)]
    names = [r[0] for r in rows]
    duplicates = sorted(name for name, count in Counter(names).items() if count > 1)
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
    parser.add_argument("--sealed", type=Path, default=SEALED, help=f"sealed rows CSV (default {SEALED})")
    parser.add_argument("--more", type=Path, default=MORE, help=f"more series rows CSV (default {MORE})")
    parser.add_argument("--output", type=Path, default=OUTPUT, help=f"table to write (default {OUTPUT})")
    args = parser.parse_args(argv)
    try:
        text = build_table(*(path.read_text(encoding="utf-8") for path in (args.source, args.sealed, args.more)))
    except (OSError, SourceError) as exc:
        print(f"make_bearing_table: error: {exc}", file=sys.stderr)
        return 2
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_bytes(text.encode("utf-8"))
    print(f"wrote {args.output} ({text.count(chr(10)) - 2} bearings)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
