"""Table lookups: a bearing type and series to its the Schaeffler catalogue coefficients.

:func:`catalogue_entry` returns everything the tables say about one series:
f0 for both lubrication columns, the f1 rule, the load M1 uses, the P1
rules (single and paired), kB and the X0/Y0 defaults of the DP11A manual table 1.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from bearingheat.catalogue.designation import BEARING_TYPES, Designation, known_series, parse_designation
from bearingheat.catalogue.tables import load_table
from bearingheat.errors import DesignationError

__all__ = [
    "LUBRICATION_F0_COLUMN",
    "CatalogueEntry",
    "catalogue_entry",
    "resolve",
    "p1_rule",
]

#: lubrication -> f0 column of the Schaeffler catalogue tables (first: grease/oil mist, second: oil bath/circulating oil)
LUBRICATION_F0_COLUMN = {
    "grease": "f0_grease",
    "oil_mist": "f0_grease",
    "oil_bath": "f0_oil",
    "circulating_oil": "f0_oil",
}

_CYLINDRICAL = {"cylindrical_roller", "cylindrical_roller_full_complement"}
# Cylindrical roller bearings whose ring lacks ribs on one side take no axial load.
_NO_AXIAL_PREFIXES = {"NU", "N", "NN"}


@dataclass(frozen=True)
class CatalogueEntry:
    """One row of the Schaeffler catalogue tables with the rules that go with it."""

    bearing_type: str
    series: str
    f0_grease: float
    f0_oil: float           # NaN where the catalogue prints a dash
    f0_basis: str           # 'constant' or 'B/(33+d)'
    f1_a: float
    f1_x: float
    f1_basis: str           # 'constant', 'P0/C0' or 'Fa/C0'
    m1_load: str            # 'Fr', 'Fa' or 'P1'
    source: str
    p1_single: str | None   # key of bearingheat.kernels.friction.P1_RULES
    p1_paired: str | None
    X0: float               # the DP11A manual table 1 default, NaN where it gives none
    Y0: float

    @property
    def label(self) -> str:
        return f"{BEARING_TYPES[self.bearing_type]} series {self.series}"

    def f0_for(self, lubrication: str) -> float:
        return getattr(self, LUBRICATION_F0_COLUMN[lubrication])


@functools.lru_cache(maxsize=None)
def _coefficient_rows() -> dict[tuple[str, str], dict]:
    table = load_table("friction_coefficients")
    return {(r["bearing_type"], r["series"]): r for r in table.to_dict("records")}


@functools.lru_cache(maxsize=None)
def _p1_rules() -> dict[tuple[str, str], str]:
    table = load_table("p1_rules")
    return {(r["bearing_type"], r["arrangement"]): r["rule"] for r in table.to_dict("records")}


@functools.lru_cache(maxsize=None)
def _static_defaults() -> dict[str, tuple[float, float]]:
    """The static load factors (the DP11A manual table 1; HR 1 p. 237 for 40°): X0 where every row of a type
    agrees, Y0 where the type has one row.

    Angular contact ball bearings get X0 = 0.5; their Y0 depends on the
    contact angle (:func:`bearingheat.catalogue.contact.y0_for_contact_angle`).
    """
    table = load_table("static_load_factors")
    out: dict[str, tuple[float, float]] = {}
    for bearing_type, rows in table.groupby("bearing_type"):
        x0 = float(rows["X0"].iloc[0]) if rows["X0"].nunique() == 1 else math.nan
        y0 = float(rows["Y0"].iloc[0]) if len(rows) == 1 else math.nan
        out[str(bearing_type)] = (x0, y0)
    return out


@functools.lru_cache(maxsize=None)
def kb_factor(bearing_type: str, prefix: str, series: str) -> float:
    """kB of the Schaeffler catalogue p. 70 for a cylindrical roller bearing, NaN where the table has none."""
    table = load_table("kb_factors")
    hit = table[(table["bearing_type"] == bearing_type) & (table["series"] == series)]
    if prefix:  # NJ and NUP rows of one series print the same kB; an explicit type matches either
        hit = hit[(hit["prefix"] == prefix) | (hit["prefix"] == "")]
    return float(hit["kB"].iloc[0]) if len(hit) else math.nan


def p1_rule(bearing_type: str, arrangement: str) -> str | None:
    """Name of the P1 rule for the type and arrangement ('single' or 'paired'); None where the catalogue has a dash."""
    return _p1_rules().get((bearing_type, arrangement))


@functools.lru_cache(maxsize=None)
def catalogue_entry(bearing_type: str, series: str) -> CatalogueEntry:
    """The the Schaeffler catalogue row of ``series`` in the table of ``bearing_type``.

    >>> e = catalogue_entry("deep_groove_ball", "62")
    >>> e.f0_grease, e.f0_oil, e.f1_a, e.f1_x, e.f1_basis, e.p1_single
    (1.3, 2.0, 0.0009, 0.5, 'P0/C0', 'radial_ball')
    """
    if bearing_type not in BEARING_TYPES:
        raise DesignationError(
            f"type: {bearing_type!r} is not a bearing type; expected one of {', '.join(BEARING_TYPES)}")
    row = _coefficient_rows().get((bearing_type, series))
    if row is None:
        choices = ", ".join(known_series()[bearing_type])
        raise DesignationError(f"series: {series!r} is not in the Schaeffler catalogue table of {BEARING_TYPES[bearing_type]}s; "
                               f"expected one of {choices}")
    X0, Y0 = _static_defaults().get(bearing_type, (math.nan, math.nan))
    return CatalogueEntry(
        bearing_type=bearing_type, series=series,
        f0_grease=float(row["f0_grease"]), f0_oil=float(row["f0_oil"]), f0_basis=row["f0_basis"],
        f1_a=float(row["f1_a"]), f1_x=float(row["f1_x"]), f1_basis=row["f1_basis"], m1_load=row["m1_load"],
        source=row["source"], p1_single=p1_rule(bearing_type, "single"), p1_paired=p1_rule(bearing_type, "paired"),
        X0=X0, Y0=Y0,
    )


@dataclass(frozen=True)
class ResolvedBearing:
    """A designation (or an explicit type and series) with its catalogue entry."""

    designation: Designation | None
    entry: CatalogueEntry
    prefix: str
    kB: float

    @property
    def takes_axial_m2(self) -> bool:
        """Radial cylindrical roller bearing with ribs that carry Fa: M2 applies (the Schaeffler catalogue, p. 69)."""
        return self.entry.bearing_type in _CYLINDRICAL and self.prefix not in _NO_AXIAL_PREFIXES

    @property
    def cannot_take_axial(self) -> bool:
        return self.entry.bearing_type in _CYLINDRICAL and self.prefix in _NO_AXIAL_PREFIXES

    @property
    def seal(self) -> str:
        return self.designation.seal if self.designation else "open"

    @property
    def contact_angle(self) -> float | None:
        return self.designation.contact_angle if self.designation else None


@functools.lru_cache(maxsize=4096)
def resolve(designation: str | None = None, bearing_type: str | None = None, series: str | None = None,
            prefix: str | None = None) -> ResolvedBearing:
    """Resolve a designation, or an explicit type and series (which win over the designation).

    >>> r = resolve("NJ2210-E")
    >>> r.entry.series, r.prefix, r.kB, r.takes_axial_m2
    ('22', 'NJ', 15.0, True)
    >>> resolve(bearing_type="tapered_roller", series="302").entry.f0_oil
    3.0
    """
    parsed = None
    if designation is not None and str(designation).strip():
        parsed = parse_designation(str(designation))
    if bearing_type or series:
        if not (bearing_type and series):
            missing = "series" if bearing_type else "type"
            raise DesignationError(f"{missing}: missing; give type and series together")
        entry = catalogue_entry(bearing_type, str(series))
    elif parsed is not None:
        entry = catalogue_entry(parsed.bearing_type, parsed.series)
    else:
        raise DesignationError("designation: missing; give a designation, or type and series")
    if prefix is None:
        prefix = parsed.prefix if parsed is not None else ""
    return ResolvedBearing(parsed, entry, prefix, kb_factor(entry.bearing_type, prefix, entry.series))
