"""Constants of the SKF four-component friction model: typed, cached lookups of ``tables/skf_*.csv``.

Designations and explicit (type, series) pairs resolve to a row of the
geometry constants R1..R4, S1..S5 (tables 3, 3a..3g), the constants Kz and
KL (table 5), the sliding coefficients μEHL and μbl, the starvation constant
Krs, and the seal constants KS1, KS2, β (table 4). No formula of the model
lives here: :mod:`bearingheat.kernels.skf` holds them.

Sources: SKF General Catalogue 6000 RU (Russian edition, «Общий каталог
SKF»), chapter «Трение», pp. 87-105; SKF «Подшипники качения» PUB BU/P1
10000/3 RU (August 2017), pp. 97-114. Every table row names its page.

Bearing types are the names of :data:`bearingheat.catalogue.designation.BEARING_TYPES`
where the two models share a type (``thrust_roller`` is the cylindrical
roller thrust bearing here), plus ``carb_toroidal_roller`` and
``carb_toroidal_roller_full_complement``. Needle roller bearings (and the
combined needle bearings) have no published constants: they are refused
with a :class:`~bearingheat.errors.ModelError` naming the model.

>>> b = skf_bearing("22208 E")
>>> b.bearing_type, b.series, b.R1, b.S2, b.Kz, b.KL
('spherical_roller', '222 E', 1.6e-06, 508.0, 5.5, 0.8)
>>> skf_bearing("C 2208 TN9").series
'C 22'
"""
from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

import numpy as np

from bearingheat.catalogue.designation import Designation, _split, bore_from_code, parse_designation
from bearingheat.catalogue.tables import load_table
from bearingheat.errors import DesignationError, ModelError

__all__ = [
    "MODEL",
    "EDITIONS",
    "DEFAULT_EDITION",
    "EDITION_TITLES",
    "SKF_TYPES",
    "FORMULA_FAMILY",
    "BALL_TYPES",
    "LUBRICATIONS",
    "OILS",
    "DEFAULT_OIL",
    "SEAL_TYPES",
    "SKFBearing",
    "SealRow",
    "skf_bearing",
    "geometry_row",
    "series_keys",
    "type_constants",
    "mu_ehl",
    "mu_bl_default",
    "k_rs",
    "seal_rows",
    "seal_lookup",
    "designation_seal",
]

#: the model's name in the friction-model registry
MODEL = "skf"
#: catalogue editions whose drag formula the model offers (skf_edition)
EDITIONS = ("6000", "10000")
DEFAULT_EDITION = "10000"
EDITION_TITLES = {
    "6000": "SKF General Catalogue 6000 RU",
    "10000": "SKF Rolling bearings 10000/3 RU (2017)",
}

#: SKF bearing type -> plain-language label
SKF_TYPES = {
    "deep_groove_ball": "deep groove ball bearing",
    "angular_contact_ball": "single row angular contact ball bearing",
    "angular_contact_ball_double_row": "double row angular contact ball bearing",
    "four_point_contact_ball": "four-point contact ball bearing",
    "self_aligning_ball": "self-aligning ball bearing",
    "cylindrical_roller": "cylindrical roller bearing with cage",
    "cylindrical_roller_full_complement": "cylindrical roller bearing without cage",
    "tapered_roller": "tapered roller bearing",
    "spherical_roller": "spherical roller bearing",
    "carb_toroidal_roller": "CARB toroidal roller bearing with cage",
    "carb_toroidal_roller_full_complement": "CARB toroidal roller bearing without cage",
    "thrust_ball": "thrust ball bearing",
    "thrust_roller": "cylindrical roller thrust bearing",
    "axial_spherical_roller": "spherical roller thrust bearing",
}

#: bearing type -> the row of table 2a/2b whose Grr and Gsl formulas apply (keys of bearingheat.kernels.skf.G_VARIABLES)
FORMULA_FAMILY = {
    "deep_groove_ball": "deep_groove_ball",
    "angular_contact_ball": "angular_contact_ball",
    "angular_contact_ball_double_row": "angular_contact_ball",
    "four_point_contact_ball": "angular_contact_ball",  # table 2a: the same formulas as angular contact
    "self_aligning_ball": "self_aligning_ball",
    "cylindrical_roller": "cylindrical_roller",
    "cylindrical_roller_full_complement": "cylindrical_roller",
    "tapered_roller": "tapered_roller",
    "spherical_roller": "spherical_roller",
    "carb_toroidal_roller": "carb",
    "thrust_ball": "thrust_ball",
    "thrust_roller": "thrust_cylindrical_roller",
    "axial_spherical_roller": "spherical_roller_thrust",
}

#: types whose drag uses Kball (rows of balls); the others use Kroll
BALL_TYPES = frozenset({"deep_groove_ball", "angular_contact_ball", "angular_contact_ball_double_row",
                        "four_point_contact_ball", "self_aligning_ball", "thrust_ball"})

#: lubrication methods (the contract's values) and their meaning in the SKF text
LUBRICATIONS = ("grease", "oil_mist", "oil_bath", "circulating_oil")
#: base oils of μEHL (SKF 6000 p. 101; 10000/3 p. 103)
OILS = ("mineral", "synthetic", "transmission_fluid")
DEFAULT_OIL = "mineral"
#: seal types of table 4 (6000 p. 96; 10000/3 p. 109 has no RZ row)
SEAL_TYPES = ("RSL", "RZ", "RSH", "RS1", "LS", "CS", "CS2", "CS5")

#: types the model refuses, with the reason
_REFUSED = {
    "needle_roller": "needle roller bearings have no published constants in the SKF model (SKF 10000/3 p. 113 "
                     "refers them to SKF's online calculation tools)",
    "combined": "combined needle roller bearings have no published constants in the SKF model",
}
_NEEDLE_THRUST = {"AXK", "AXW"}
#: types with one row of constants for every series (tables 3, 3c full complement)
_ALL_SERIES = {"angular_contact_ball", "angular_contact_ball_double_row", "four_point_contact_ball",
               "cylindrical_roller_full_complement", "thrust_ball", "thrust_roller"}
#: double row ball series (Kball counts the rows irw)
_DOUBLE_ROW_SERIES = {"deep_groove_ball": {"42", "43"}, "thrust_ball": {"522", "523", "542", "543"}}
#: cylindrical roller designs with one ring (or the shaft or housing in its place) without ribs; NN is refused
_NO_AXIAL_PREFIXES = {"NU", "N", "RNU", "RN"}
#: seal table 4 names bearing types by family; these types use the row of another
_SEAL_TABLE_TYPE = {"angular_contact_ball_double_row": "angular_contact_ball",
                    "cylindrical_roller_full_complement": "cylindrical_roller"}
#: tapered series whose starting torque may be up to four times Msl + Mseal (6000 p. 103; 10000/3 p. 114)
_START_X4_SERIES = {"313", "313 X", "322 B", "323 B", "T7FC"}
_START_X4_KEYS = frozenset(re.sub(r"\s+", "", s) for s in _START_X4_SERIES)
_TAPERED_INCH = re.compile(r"^(?P<series>LL|LM|L|HM|HH|H|M)\d{3,}")
#: an ISO 355 tapered designation as SKF prints it, a space between the series code and the bore: 'T7FC 045'
_ISO_355_SPACED = re.compile(r"^(?P<series>T\d[B-G][B-E])\s+(?P<bore>\d{3})(?=$|[\s/-])")


def _key(text: str) -> str:
    return re.sub(r"\s+", "", str(text)).upper()


@dataclass(frozen=True)
class SKFBearing:
    """One bearing's constants of the SKF model (NaN where the tables print none)."""

    bearing_type: str
    series: str
    family: str
    R1: float
    R2: float
    R3: float
    R4: float
    S1: float
    S2: float
    S3: float
    S4: float
    S5: float
    Kz: float
    KL: float
    irw: float                   # rows of balls (ball bearings), NaN for roller bearings
    mu_EHL_type: float           # μEHL fixed by the type (cylindrical 0.02, tapered 0.002), NaN otherwise
    bore: float                  # mm, from the designation, NaN where it gives none
    seal: str | None             # seal type from the designation suffix (RSH in -2RSH), None where none
    seals: int | None            # number of seals from the suffix (2RSH -> 2), None where none
    unknown_contact_seal: str    # a contact seal suffix table 4 does not list (2RS, 2RSR), '' otherwise
    source: str
    start_factor: float = 1.0    # the starting torque may be up to this many times Msl + Mseal (6000 p. 103)
    prefix: str = ""             # the designation's prefix of a cylindrical roller bearing (NU, NJ, ...), '' otherwise

    @property
    def label(self) -> str:
        name = SKF_TYPES[self.bearing_type]
        return name if self.series == "all" else f"{name} series {self.series}"

    @property
    def is_ball(self) -> bool:
        return self.bearing_type in BALL_TYPES

    @property
    def no_axial(self) -> bool:
        """One ring has no ribs (NU, N, RNU, RN): the bearing takes no axial load."""
        return self.prefix in _NO_AXIAL_PREFIXES


@dataclass(frozen=True)
class SealRow:
    """One row of table 4: seal, bearing type, the range of D (over, incl.], β, KS1, KS2, where d_s is read."""

    seal: str
    bearing_type: str
    D_over: float
    D_incl: float
    beta: float
    KS1: float
    KS2: float
    d_s_dimension: str
    one_seal_factor: float
    source: str

    @property
    def range_text(self) -> str:
        low = "" if math.isnan(self.D_over) else f"{self.D_over:g} < "
        high = "" if math.isnan(self.D_incl) else f" <= {self.D_incl:g}"
        return f"{low}D{high} mm"


# ---- tables ----------------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def _geometry() -> dict[tuple[str, str], dict]:
    table = load_table("skf_geometry_constants")
    return {(r["bearing_type"], _key(r["series"])): r for r in table.to_dict("records")}


@functools.lru_cache(maxsize=None)
def series_keys(bearing_type: str) -> tuple[str, ...]:
    """The series rows of one type in the geometry tables, as printed ('222 E', 'C 22', 'all').

    >>> series_keys("carb_toroidal_roller")[:3]
    ('C 22', 'C 23', 'C 30')
    """
    table = load_table("skf_geometry_constants")
    return tuple(table.loc[table["bearing_type"] == bearing_type, "series"])


def geometry_row(bearing_type: str, series: str) -> dict:
    """R1..R4, S1..S5 and the source of one series (blank -> NaN); a series without a row is a DesignationError.

    >>> geometry_row("tapered_roller", "302")["S1"]
    0.017
    """
    row = _geometry().get((bearing_type, _key(series)))
    if row is None:
        choices = ", ".join(series_keys(bearing_type)) or "none"
        raise DesignationError(f"series: {series!r} has no row of SKF geometry constants for the type "
                               f"{SKF_TYPES.get(bearing_type, bearing_type)} (SKF 6000 pp. 92-95, tables 3a-3g); "
                               f"expected one of {choices}")
    return row


@functools.lru_cache(maxsize=None)
def _types() -> dict[str, dict]:
    return {r["bearing_type"]: r for r in load_table("skf_type_constants").to_dict("records")}


def type_constants(bearing_type: str) -> tuple[float, float, float]:
    """(Kz, KL, irw) of table 5 (SKF 6000 p. 98; 10000/3 p. 112); NaN where the table prints a dash.

    >>> type_constants("spherical_roller")
    (5.5, 0.8, nan)
    """
    row = _types()[bearing_type]
    return float(row["Kz"]), float(row["KL"]), float(row["irw"])


@functools.lru_cache(maxsize=None)
def _friction() -> dict[tuple[str, str], float]:
    rows = load_table("skf_friction_constants").to_dict("records")
    return {(r["constant"], r["case"]): float(r["value"]) for r in rows}


def mu_ehl(oil: str, bearing_type: str | None = None) -> float:
    """μEHL: 0.02 for cylindrical, 0.002 for tapered roller bearings, else by oil (SKF 6000 p. 101; 10000/3 p. 103).

    >>> mu_ehl("mineral"), mu_ehl("synthetic", "tapered_roller")
    (0.05, 0.002)
    """
    by_type = _mu_ehl_type(bearing_type)
    if not math.isnan(by_type):
        return by_type
    try:
        return _friction()[("mu_EHL", oil)]
    except KeyError:
        raise ModelError(f"oil: {oil!r} is not one of {', '.join(OILS)}") from None


def _mu_ehl_type(bearing_type: str | None) -> float:
    family = {"cylindrical_roller": "cylindrical_roller", "cylindrical_roller_full_complement": "cylindrical_roller",
              "tapered_roller": "tapered_roller"}.get(bearing_type or "")
    return _friction()[("mu_EHL", family)] if family else math.nan


def mu_bl_default() -> float:
    """μbl ≈ 0.15 (SKF 6000 p. 101; 10000/3 p. 103).

    >>> mu_bl_default()
    0.15
    """
    return _friction()[("mu_bl", "default")]


def k_rs(lubrication: str) -> float:
    """Krs: 6e-8 grease and oil-air/oil spot, 3e-8 oil jet and a low-level oil bath (SKF 6000 p. 98; 10000/3 p. 102).

    The oil-bath value applies below the centre of the lowest rolling
    element; at a higher level the text names no starvation (the caller
    sets φrs = 1 there).

    >>> k_rs("grease"), k_rs("oil_bath")
    (6e-08, 3e-08)
    """
    try:
        return _friction()[("K_rs", lubrication)]
    except KeyError:
        raise ModelError(f"lubrication: {lubrication!r} is not one of {', '.join(LUBRICATIONS)}") from None


# ---- seals -----------------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def _seals() -> tuple[SealRow, ...]:
    rows = []
    for r in load_table("skf_seal_constants").to_dict("records"):
        rows.append(SealRow(r["seal"], r["bearing_type"], float(r["D_over"]), float(r["D_incl"]), float(r["beta"]),
                            float(r["KS1"]), float(r["KS2"]), r["d_s_dimension"], float(r["one_seal_factor"]),
                            r["source"]))
    return tuple(rows)


@functools.lru_cache(maxsize=None)
def seal_rows(seal: str, bearing_type: str) -> tuple[SealRow, ...]:
    """The rows of table 4 for a seal type on a bearing type (empty where the table offers none).

    Double row angular contact ball bearings use the row of angular contact
    ball bearings, full complement cylindrical roller bearings that of
    cylindrical roller bearings (the table names types, not cage variants).

    >>> [r.range_text for r in seal_rows("RS1", "deep_groove_ball")]
    ['D <= 62 mm', '62 < D <= 80 mm', '80 < D <= 100 mm', '100 < D mm']
    """
    if seal not in SEAL_TYPES:
        raise ModelError(f"seal: {seal!r} is not a seal type of SKF table 4; expected one of {', '.join(SEAL_TYPES)}")
    table_type = _SEAL_TABLE_TYPE.get(bearing_type, bearing_type)
    return tuple(r for r in _seals() if r.seal == seal and r.bearing_type == table_type)


def seal_lookup(seal: str, bearing_type: str, D) -> dict[str, np.ndarray]:
    """β, KS1, KS2, the one-seal factor and ``found`` for outside diameters ``D`` [mm] (arrays of D's shape).

    ``found`` is False where no row of table 4 covers D (over < D <= incl.).

    >>> out = seal_lookup("RS1", "deep_groove_ball", [52.0, 72.0, 120.0])
    >>> out["KS2"].tolist(), out["found"].tolist()
    ([2.0, 20.0, 0.0], [True, True, True])
    """
    D = np.asarray(D, dtype=float)
    out = {name: np.full(D.shape, np.nan) for name in ("beta", "KS1", "KS2", "one_seal_factor")}
    found = np.zeros(D.shape, dtype=bool)
    for row in seal_rows(seal, bearing_type):
        low = -np.inf if math.isnan(row.D_over) else row.D_over
        high = np.inf if math.isnan(row.D_incl) else row.D_incl
        inside = (D > low) & (D <= high) & ~found
        for name in out:
            out[name][inside] = getattr(row, name)
        found |= inside
    out["found"] = found
    return out


_SEAL_SUFFIX = re.compile(r"^(?P<two>2)?(?P<seal>RSL|RSH|RS1|RZ|LS|CS5|CS2|CS)(?P<rest>[A-Z0-9/]*)$")


def designation_seal(suffixes: tuple[str, ...]) -> tuple[str | None, int | None]:
    """Seal type and count from designation suffixes: ('2RSH',) -> ('RSH', 2); ('RS1',) -> ('RS1', 1).

    >>> designation_seal(("2CS5V",)), designation_seal(("C3",))
    (('CS5', 2), (None, None))
    """
    for suffix in suffixes:
        match = _SEAL_SUFFIX.match(suffix.upper())
        if match:
            return match.group("seal"), 2 if match.group("two") else 1
    return None, None


# ---- designations ----------------------------------------------------------------------------

_BORE = r"(?P<bore>\d{2}|/\d+(?:\.\d+)?)"
_CARB = re.compile(r"^C\s*(?P<series>\d{2})\s*" + _BORE + r"(?:[\s-]+(?P<suffix>.*))?$")
_CARB_FULL = re.compile(r"^(?:2?CS[25]?)?K?V(?:/.*)?$")

#: rules for series the Schaeffler catalogue designation parser does not know: (regex on the body, type, series group)
_EXTRA_RULES = (
    (re.compile(r"^(?P<series>630|161|617|628|637|638|639)" + _BORE + "$"), "deep_groove_ball"),
    (re.compile(r"^(?P<series>719)" + _BORE + "$"), "angular_contact_ball"),
    (re.compile(r"^(?P<series>112|130|139)" + _BORE + "$"), "self_aligning_ball"),
    (re.compile(r"^(?P<series>238|248|249)" + _BORE + "$"), "spherical_roller"),
    (re.compile(r"^(?P<prefix>NUP|NJ|NU|N)(?P<series>12|20)" + _BORE + "$"), "cylindrical_roller"),
    (re.compile(r"^(?P<prefix>NCF|NJF|RNU|RN|NUH)(?P<series>22|23)" + _BORE + "$"), "cylindrical_roller"),
    (re.compile(r"^(?P<prefix>NNCL|NNCF|NNC|NNF|NCF|NJG)(?P<series>\d{2})" + _BORE + "$"),
     "cylindrical_roller_full_complement"),
)
_HIGH_CAPACITY = ("ECJB", "ECJA", "ECMH")


@dataclass(frozen=True)
class _Parsed:
    bearing_type: str
    series: str
    prefix: str
    bore: float
    suffixes: tuple[str, ...]
    contact_seal: bool


def _bore_of(code: str | None) -> float:
    if not code or code == "..":
        return math.nan
    return float(code[1:]) if code.startswith("/") else bore_from_code(code)


def _parse(text: str) -> _Parsed:
    """A designation to (type, raw series, prefix, bore, suffixes).

    CARB designations and the inch tapered series first, then the designation
    parser of the catalogue model, then the series it does not know.
    """
    clean = re.sub(r"\s+", " ", text.strip().upper())
    if _ISO_355_SPACED.match(clean):
        text = clean = _ISO_355_SPACED.sub(r"\g<series>\g<bore>", clean)   # 'T7FC 045' is 'T7FC045'
    carb = _CARB.match(clean)
    if carb:
        suffixes = tuple(s for s in re.split(r"[-\s]", carb.group("suffix") or "") if s)
        full = any(_CARB_FULL.match(s) for s in suffixes)
        return _Parsed("carb_toroidal_roller_full_complement" if full else "carb_toroidal_roller",
                       f"C {carb.group('series')}", "", _bore_of(carb.group("bore")), suffixes, False)
    body, suffixes = _split(clean)
    inch = _TAPERED_INCH.match(body)
    if inch:
        return _Parsed("tapered_roller", inch.group("series"), "", math.nan, suffixes, False)
    try:
        parsed: Designation = parse_designation(text)
    except DesignationError:
        for pattern, bearing_type in _EXTRA_RULES:
            match = pattern.match(body)
            if match:
                groups = match.groupdict()
                return _Parsed(bearing_type, groups["series"], groups.get("prefix") or "", _bore_of(groups["bore"]),
                               suffixes, False)
        raise DesignationError(f"designation: {text!r} matches no bearing type of the SKF model; "
                               "give type and series explicitly instead") from None
    return _Parsed(parsed.bearing_type, parsed.series, parsed.prefix, parsed.bore or math.nan,
                   parsed.suffixes, parsed.seal == "contact")


def _series_of(p: _Parsed) -> str:
    """The geometry-table series of a parsed designation (E designs, B designs, inch series, 'all')."""
    t, series = p.bearing_type, p.series
    e_design = any(s.startswith("E") for s in p.suffixes)
    if t in _ALL_SERIES:
        return "all"
    if t == "cylindrical_roller":
        if p.prefix == "NN":
            raise ModelError(f"type: double row cylindrical roller bearings with cage (NN {series}..) have no "
                             "constants in the SKF model (table 3c lists N, NU, NJ and NUP with cage)")
        if p.prefix in ("NCF", "NJF", "RNU", "RN", "NUH"):
            if any(s.startswith(_HIGH_CAPACITY) for s in p.suffixes):
                return f"{series} high capacity"
            raise DesignationError(f"designation: {p.prefix} {series}.. without the suffix ECJB, ECJA or ECMH "
                                   "is no cylindrical roller bearing of SKF table 3c; give type and series")
        return series
    if t == "tapered_roller":
        return _tapered_series(series, p.suffixes)
    if t in ("spherical_roller", "axial_spherical_roller") and e_design and _key(series + "E") in _series_index(t):
        return f"{series} E"
    return series


@functools.lru_cache(maxsize=None)
def _series_index(bearing_type: str) -> frozenset[str]:
    return frozenset(_key(s) for s in series_keys(bearing_type))


def _tapered_series(series: str, suffixes: tuple[str, ...]) -> str:
    """Table 3d: 313 (X), 320 X, 322 B, 323 B, the inch series; everything else 'other' ('Все прочие')."""
    b_design = any(s.startswith("B") for s in suffixes)
    if series in ("322", "323") and b_design:
        return f"{series} B"
    if series == "320":
        return "320 X"
    if _key(series) in _series_index("tapered_roller"):
        return series
    return "other"


def _check_type(bearing_type: str, series: str | None) -> None:
    if bearing_type in _REFUSED:
        raise ModelError(f"type: {_REFUSED[bearing_type]}; use model 'schaeffler' for them")
    if bearing_type == "thrust_roller" and series and _key(series).lstrip("K") in _NEEDLE_THRUST:
        raise ModelError(f"type: needle roller thrust bearings ({series}) have no published constants in the SKF "
                         "model; use model 'schaeffler' for them")
    if bearing_type == "carb_toroidal_roller_full_complement":
        raise ModelError("type: CARB toroidal roller bearings without cage (suffix V) have no geometry constants "
                         "in the SKF model (SKF 10000/3 p. 108, table 3f is for CARB bearings with cage)")
    if bearing_type not in SKF_TYPES:
        raise DesignationError(f"type: {bearing_type!r} is not a bearing type of the SKF model; expected one of "
                               f"{', '.join(SKF_TYPES)}")


def _explicit_series(bearing_type: str, series: str) -> str:
    if bearing_type in _ALL_SERIES:
        return "all"
    if bearing_type == "tapered_roller":
        return _tapered_series(series, ())
    return series


@functools.lru_cache(maxsize=4096)
def skf_bearing(designation: str | None = None, bearing_type: str | None = None,
                series: str | None = None) -> SKFBearing:
    """The SKF constants of a designation, or of an explicit type and series (which win over the designation).

    >>> b = skf_bearing(bearing_type="angular_contact_ball_double_row", series="32")
    >>> b.series, b.R2, b.Kz, b.irw
    ('all', 1.41, 3.1, 2.0)
    >>> skf_bearing("6205-2RSH").seal, skf_bearing("6205-2RSH").seals
    ('RSH', 2)
    >>> skf_bearing("NA4905")
    Traceback (most recent call last):
    ...
    bearingheat.errors.ModelError: type: needle roller bearings have no published constants in the SKF model ...
    """
    parsed = None
    if designation is not None and str(designation).strip():
        parsed = _parse(str(designation))
    if bearing_type or series:
        if not (bearing_type and series):
            missing = "series" if bearing_type else "type"
            raise DesignationError(f"{missing}: missing; give type and series together")
        _check_type(bearing_type, series)
        table_series = _explicit_series(bearing_type, str(series))
        named_series = str(series)
    elif parsed is not None:
        bearing_type = parsed.bearing_type
        _check_type(bearing_type, parsed.series)
        table_series = _series_of(parsed)
        named_series = parsed.series
    else:
        raise DesignationError("designation: missing; give a designation, or type and series")
    row = geometry_row(bearing_type, table_series)
    Kz, KL, irw = type_constants(bearing_type)
    # the series as named, not its table row ('all' for thrust ball bearings): 42 and 522 have two rows of balls
    if _key(named_series) in _DOUBLE_ROW_SERIES.get(bearing_type, ()):
        irw = 2.0
    suffixes = parsed.suffixes if parsed else ()
    seal, seals = designation_seal(suffixes)
    unknown = ""
    if seal is None and parsed is not None and parsed.contact_seal:
        unknown = next((s for s in suffixes if "RS" in s or s in ("LLU", "DDU", "2LS")), "contact seal")
    R = [float(row[f"R{k}"]) for k in range(1, 5)]
    S = [float(row[f"S{k}"]) for k in range(1, 6)]
    start = 1.0
    # the row or the series as named: T7FC takes the row 'other' but starts up to four times higher
    if bearing_type == "tapered_roller" and {_key(row["series"]), _key(named_series)} & _START_X4_KEYS:
        start = 4.0
    elif bearing_type == "axial_spherical_roller":
        start = 8.0
    return SKFBearing(bearing_type, row["series"], FORMULA_FAMILY[bearing_type], *R, *S, Kz, KL, irw,  # type: ignore[arg-type, call-arg]
                      _mu_ehl_type(bearing_type), parsed.bore if parsed else math.nan, seal, seals, unknown,
                      row["source"], start, parsed.prefix if parsed and parsed.bearing_type == bearing_type else "")
