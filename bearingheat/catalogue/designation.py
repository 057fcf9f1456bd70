"""Bearing designations to rows of the Schaeffler catalogue coefficient tables.

Schaeffler/ISO designations ("6205-2RSR", "NU206-E", "30205-A", "22210-E1",
"HK2016", "62..-2Z" ...) resolve to a bearing type and a series key of
``tables/friction_coefficients.csv``. The GOST designations of the DP11A manual
("1000095", "18", "101") decode to bore, series and type (:func:`decode_gost`).

Each rule of :data:`DESIGNATION_RULES` is a regular expression for the
designation body (without suffixes) with a function that returns the type and
series; the first rule that matches wins.
"""
from __future__ import annotations

import difflib
import functools
import re
from dataclasses import dataclass, field
from typing import Callable

from bearingheat.catalogue.tables import load_table
from bearingheat.errors import DesignationError

__all__ = [
    "DesignationError",
    "Designation",
    "parse_designation",
    "decode_gost",
    "bore_from_code",
    "BEARING_TYPES",
    "CONTACT_SEAL_SUFFIXES",
    "known_series",
]




# Bearing types of the Schaeffler catalogue tables, with a plain-language label.
BEARING_TYPES = {
    "needle_roller": "needle roller bearing",
    "cylindrical_roller_full_complement": "cylindrical roller bearing without cage",
    "cylindrical_roller": "cylindrical roller bearing with cage",
    "thrust_roller": "thrust roller bearing",
    "combined": "combined bearing",
    "tapered_roller": "tapered roller bearing",
    "spherical_roller": "spherical roller bearing",
    "axial_spherical_roller": "axial spherical roller bearing",
    "deep_groove_ball": "deep groove ball bearing",
    "angular_contact_ball": "single row angular contact ball bearing",
    "angular_contact_ball_double_row": "double row angular contact ball bearing",
    "self_aligning_ball": "self-aligning ball bearing",
    "four_point_contact_ball": "four-point contact ball bearing",
    "thrust_ball": "thrust ball bearing",
}

# Suffixes of contact seals (rubbing lips) and of non-contact shields.
CONTACT_SEAL_SUFFIXES = frozenset({"RS", "2RS", "RSR", "2RSR", "2RS1", "RS1", "2RSH", "RSH", "LLU", "2LS", "DDU", "2RZ"})
_SHIELDS = {"Z", "2Z", "ZZ", "ZR", "2ZR", "2ZRS", "LLB"}
# Contact angle implied by a suffix of a single row angular contact ball bearing (Schaeffler/ISO practice).
_CONTACT_ANGLE_SUFFIX = {"B": 40.0, "BE": 40.0, "AC": 25.0, "C": 15.0, "E": 25.0}


@dataclass(frozen=True)
class Designation:
    """A parsed designation: what the tables and the P1 rules need to know."""

    text: str
    bearing_type: str
    series: str
    prefix: str = ""                 # NU, NJ, NUP, N, NN ... for cylindrical roller bearings
    bore: float | None = None        # mm, from the bore code, when the designation gives it
    width: float | None = None       # mm, from drawn cup / needle designations (HK2016: B = 16)
    suffixes: tuple[str, ...] = ()
    seal: str = "open"               # open | shield | contact
    contact_angle: float | None = None  # deg, from the suffix of angular contact ball bearings
    notes: tuple[str, ...] = field(default=())


def bore_from_code(code: str) -> float:
    """Bore diameter in mm from the two-digit ISO/GOST bore code.

    00 -> 10, 01 -> 12, 02 -> 15, 03 -> 17, otherwise 5 x code (the DP11A manual, p. 4).

    >>> bore_from_code("05"), bore_from_code("00"), bore_from_code("03")
    (25.0, 10.0, 17.0)
    """
    special = {"00": 10.0, "01": 12.0, "02": 15.0, "03": 17.0}
    if code in special:
        return special[code]
    return 5.0 * int(code)


def _bore(code: str | None) -> float | None:
    if code is None:
        return None
    if code.startswith("/"):
        return float(code[1:])
    if len(code) == 1:  # miniature: the digit is the bore in mm
        return float(code)
    return bore_from_code(code)


# ---- rules: (name, regex on the body, function(match) -> (type, series, prefix, bore, width)) ----
Rule = tuple[str, "re.Pattern[str]", Callable[[re.Match], tuple]]

_BORE = r"(?P<bore>\d{2}|/\d+(?:\.\d+)?|\.\.)"


def _series_rule(bearing_type: str, group: str = "series", prefix: str = ""):
    def build(m: re.Match):
        code = m.group("bore")
        return bearing_type, m.group(group), prefix or (m.groupdict().get("prefix") or ""), _bore(None if code == ".." else code), None
    return build


def _needle_sized(bearing_type: str):
    """NK25/20, NKI20/16, HK2016, BK0306, K20x24x10: the numbers give d and B."""
    def build(m: re.Match):
        d = float(m.group("d")) if m.group("d") else None
        width = float(m.group("B")) if m.group("B") else None
        return bearing_type, m.group("series"), "", d, width
    return build


DESIGNATION_RULES: list[Rule] = [
    # cylindrical roller bearings with cage: NU206, NJ2210, NUP312, NN3010, N1010, NU1910
    ("cylindrical", re.compile(r"^(?P<prefix>NUP|NJ|NU|NN|NF|NH|N)(?P<series>22|23|10|19|30|2|3|4)" + _BORE + r"$"),
     _series_rule("cylindrical_roller")),
    # LSL192310, ZSL192310 (with cage) and SL182205, SL014830 (full complement)
    ("cylindrical with cage, L/ZSL", re.compile(r"^(?P<series>LSL1923|ZSL1923)" + _BORE + r"$"),
     _series_rule("cylindrical_roller")),
    ("cylindrical full complement", re.compile(r"^(?P<series>SL18(?:18|29|30|22|50)|SL0[12]4[89]|SL1923)" + _BORE + r"$"),
     _series_rule("cylindrical_roller_full_complement")),
    # needle roller bearings with ribs: NA4905, RNA6905
    ("needle NA", re.compile(r"^(?P<series>R?NA(?:48|49|69))" + _BORE + r"$"), _series_rule("needle_roller")),
    # drawn cups and needle bushes: HK2016 (Fw 20, C 16), BK0306, HN2520
    ("drawn cup", re.compile(r"^(?P<series>HK|BK|HN)(?P<d>\d{2})(?P<B>\d{2})$"), _needle_sized("needle_roller")),
    ("needle NK/NKI", re.compile(r"^(?P<series>NKIS|NKI|NKS|NK|NAO|RNO)(?P<d>\d+(?:\.\d+)?)/(?P<B>\d+(?:\.\d+)?)$"),
     _needle_sized("needle_roller")),
    ("needle NAO/RNO", re.compile(r"^(?P<series>NAO|RNO|K)(?P<d>\d+(?:\.\d+)?)X\d+(?:\.\d+)?X(?P<B>\d+(?:\.\d+)?)$"),
     _needle_sized("needle_roller")),
    # combined bearings: ZARN2052, NKX20, NX7, NKIA5905, ZKLN2052
    ("combined", re.compile(r"^(?P<series>ZARN|ZARF|NKXR|NKX|NX|ZKLN|ZKLF|NKIA|NKIB)(?P<bore>\d+)$"),
     lambda m: ("combined", m.group("series"), "", None, None)),
    # thrust roller: AXK2035, AXW20, 81105, K81105, 89310
    ("thrust needle", re.compile(r"^(?P<series>AXK|AXW)(?P<d>\d{2,3})(?P<B>\d{2,3})?$"),
     lambda m: ("thrust_roller", m.group("series"), "", float(m.group("d")), None)),
    ("thrust roller", re.compile(r"^(?P<series>K?(?:811|812|893|894))" + _BORE + r"$"), _series_rule("thrust_roller")),
    # four-point contact: QJ210, QJ310
    ("four-point", re.compile(r"^(?P<series>QJ[23])" + _BORE + r"$"), _series_rule("four_point_contact_ball")),
    # tapered roller, ISO 355 codes: T4CB100, T2ED045
    ("tapered ISO 355", re.compile(r"^(?P<series>T4CB|T7FC|T2EE|T2ED|T5ED)(?P<bore>\d{3})$"),
     lambda m: ("tapered_roller", m.group("series"), "", float(m.group("bore")), None)),
    # tapered roller: 30205, 32210, 31305, 320/28
    ("tapered", re.compile(r"^(?P<series>302|303|313|320|322|323|329|330|331|332)" + _BORE + r"$"),
     _series_rule("tapered_roller")),
    # axial spherical roller: 29412
    ("axial spherical", re.compile(r"^(?P<series>29[234])" + _BORE + r"$"), _series_rule("axial_spherical_roller")),
    # spherical roller: 22210, 21310, 23120, 24015
    ("spherical", re.compile(r"^(?P<series>213|222|223|230|231|232|239|240|241)" + _BORE + r"$"),
     _series_rule("spherical_roller")),
    # thrust ball: 51105, 52210, 53205, 54310
    ("thrust ball", re.compile(r"^(?P<series>51[1234]|52[234]|53[23]|54[23])" + _BORE + r"$"),
     _series_rule("thrust_ball")),
    # double row angular contact: 3205, 3306-DA, 3806 (4 digits)
    ("angular double row", re.compile(r"^(?P<series>30|32|33|38)" + _BORE + r"$"),
     _series_rule("angular_contact_ball_double_row")),
    # single row angular contact: 7205, 7305, 7005, 71805
    ("angular single row", re.compile(r"^(?P<series>718|70|72|73)" + _BORE + r"$"), _series_rule("angular_contact_ball")),
    # deep groove ball: 61805, 61905, 16005, 62205, 62305, 6205, 4205 (double row), 623 (miniature)
    ("deep groove 5 digits", re.compile(r"^(?P<series>618|619|160|622|623)" + _BORE + r"$"), _series_rule("deep_groove_ball")),
    ("deep groove", re.compile(r"^(?P<series>60|62|63|64|42|43)" + _BORE + r"$"), _series_rule("deep_groove_ball")),
    ("deep groove miniature", re.compile(r"^(?P<series>6[0234])(?P<bore>[1-9])$"), _series_rule("deep_groove_ball")),
    # self-aligning ball: 1205, 1305, 2205, 2305
    ("self-aligning", re.compile(r"^(?P<series>12|13|22|23)" + _BORE + r"$"), _series_rule("self_aligning_ball")),
]


def _split(text: str) -> tuple[str, tuple[str, ...]]:
    """Body and suffixes: '7205-B-2RS' -> ('7205', ('B', '2RS')); 'NU 206 E' -> ('NU206', ('E',))."""
    cleaned = re.sub(r"\s+", " ", str(text).strip().upper())
    cleaned = cleaned.replace("…", "..").replace("...", "..")
    # 'NU 206 E' / '6205 2RS': a space before the suffix works like a dash
    parts = [p for p in re.split(r"[-\s]", cleaned) if p]
    if not parts:
        return "", ()
    body = parts[0]
    rest = parts[1:]
    # 'NU 206' - a prefix separated by a space from the number
    if rest and re.fullmatch(r"[A-Z]+", body) and re.fullmatch(r"\d[\d/.]*", rest[0]):
        body, rest = body + rest[0], rest[1:]
    # 6205ZZ, 62052RS: suffix glued to the number
    glued = re.fullmatch(r"(.*\d)(2RSR|2RS1|2RSH|2RS|RSR|RS|2Z|ZZ|Z|LLU|LLB)", body)
    if glued and not re.fullmatch(r"(AXK|AXW|HK|BK|HN)\d+", body):
        body, rest = glued.group(1), [glued.group(2), *rest]
    return body, tuple(rest)


@functools.lru_cache(maxsize=4096)
def parse_designation(text: str) -> Designation:
    """Resolve a designation to a bearing type and a series row of the friction coefficient tables.

    The rows are those of ``tables/friction_coefficients.csv``, typed from
    the Schaeffler rolling bearing catalogue (Russian edition), chapter
    «Трение и нагрев» (Friction and increases in temperature), pp. 64–70.
    Schaeffler/ISO designations ("6205-2RSR", "NU206-E", "30205-A",
    "22210-E1", "HK2016", "62..-2Z" ...) are matched by the rules of
    :data:`DESIGNATION_RULES`, the first that matches wins; the GOST 3189
    numbers of the lab bearings of Е.П. Жильников, В.П. Тукмаков,
    «Исследование момента сил трения в шарикоподшипниках при
    комбинированном нагружении» (Samara University, 2016), table 3
    ("1000095", "18", "101"), take the ISO row named there. Results are
    cached.

    Parameters
    ----------
    text : str
        The designation; case, spaces and dashes before suffixes do not
        matter ("NU 206 E", "6205 2RS", "6205ZZ").

    Returns
    -------
    Designation
        ``bearing_type`` (a key of :data:`BEARING_TYPES`), ``series``,
        ``prefix`` (NU, NJ ...), ``bore`` [mm] from the bore code (None where
        the designation gives none), ``width`` [mm] of drawn cups, the
        ``suffixes``, ``seal`` ('open', 'shield' or 'contact'),
        ``contact_angle`` [deg] implied by the suffix of an angular contact
        ball bearing (B: 40, AC/E: 25, C: 15) and ``notes``.

    Raises
    ------
    bearingheat.errors.DesignationError
        For an empty designation or one no rule matches; the message names
        close designations of the bearing table.

    Examples
    --------
    >>> d = parse_designation("6205-2RSR")
    >>> d.bearing_type, d.series, d.bore, d.seal
    ('deep_groove_ball', '62', 25.0, 'contact')
    >>> parse_designation("NJ2210-E").series, parse_designation("NJ2210-E").prefix
    ('22', 'NJ')
    >>> parse_designation("7205-B").contact_angle
    40.0
    """
    if not isinstance(text, str) or not text.strip():
        raise DesignationError(f"designation: {text!r} is empty; give a designation or type and series")
    gost = _try_gost(text.strip())
    if gost is not None:
        return gost
    body, suffixes = _split(text)
    for _name, pattern, build in DESIGNATION_RULES:
        match = pattern.match(body)
        if match:
            bearing_type, series, prefix, bore, width = build(match)
            return _finish(text.strip(), bearing_type, series, prefix, bore, width, suffixes)
    raise DesignationError(_unknown_message(text, body))


def _finish(text, bearing_type, series, prefix, bore, width, suffixes) -> Designation:
    seal = "open"
    if any(s in CONTACT_SEAL_SUFFIXES for s in suffixes):
        seal = "contact"
    elif any(s in _SHIELDS for s in suffixes):
        seal = "shield"
    angle = None
    notes: list[str] = []
    if bearing_type == "angular_contact_ball":
        for s in suffixes:
            if s in _CONTACT_ANGLE_SUFFIX:
                angle = _CONTACT_ANGLE_SUFFIX[s]
                break
    if bearing_type == "cylindrical_roller" and series in {"2", "3", "22", "23"} and not any(
        s.startswith("E") for s in suffixes
    ):
        notes.append(f"the Schaeffler catalogue row for series {series} is for the E design ({series}..-E)")
    return Designation(text, bearing_type, series, prefix, bore, width, tuple(suffixes), seal, angle, tuple(notes))


# ---- GOST 3189 (the DP11A manual, p. 4) ---------------------------------------------------------------

# fourth digit from the right: bearing type (GOST 3189)
_GOST_TYPES = {
    "0": "deep_groove_ball",
    "1": "self_aligning_ball",
    "2": "cylindrical_roller",
    "3": "spherical_roller",
    "4": "needle_roller",
    "6": "angular_contact_ball",
    "7": "tapered_roller",
    "8": "thrust_ball",
    "9": "thrust_roller",
}
_GOST_DIAMETER_SERIES = {
    "1": "extra light", "2": "light", "3": "medium", "4": "heavy", "5": "light wide", "6": "medium wide",
    "7": "extra light", "8": "ultra light", "9": "ultra light",
}


@dataclass(frozen=True)
class GostCode:
    """A decoded GOST 3189 designation (the DP11A manual, p. 4)."""

    text: str
    bore: float
    diameter_series: str
    diameter_series_name: str
    type_digit: str
    bearing_type: str
    design: str
    width_series: str


def decode_gost(text: str) -> GostCode:
    """Decode a GOST 3189 designation: bore, diameter series, type, design, width series.

    Digits are counted from the right (GOST 3189, as restated in
    Е.П. Жильников, В.П. Тукмаков, «Исследование момента сил трения в
    шарикоподшипниках при комбинированном нагружении», Samara University,
    2016, p. 4): the first two give
    the bore (d >= 20 mm: code x 5; 00/01/02/03 -> 10/12/15/17 mm; below
    10 mm the first digit is the bore itself and the third place is 0), the
    third gives the diameter series, the fourth the type, the fifth and
    sixth the design, the seventh the width series.

    Parameters
    ----------
    text : str
        A GOST 3189 number of 2 to 7 digits (surrounding spaces ignored),
        e.g. "1000095", "18", "101", "7205".

    Returns
    -------
    GostCode
        ``bore`` [mm], ``diameter_series`` (a digit) and its name (e.g.
        'light', 'ultra light'; 'unknown' for a digit GOST 3189 does not
        name), ``type_digit`` and ``bearing_type`` (a key of
        :data:`BEARING_TYPES`), ``design`` (two digits) and
        ``width_series`` (a digit).

    Raises
    ------
    bearingheat.errors.DesignationError
        For text that is not 2 to 7 digits, or a type digit (the fourth
        from the right) outside the decoded types 0-4 and 6-9 (5, bearings
        with twisted rollers, is not decoded).

    Examples
    --------
    >>> g = decode_gost("1000095")
    >>> g.bore, g.diameter_series, g.bearing_type, g.width_series
    (5.0, '9', 'deep_groove_ball', '1')
    >>> decode_gost("101").bore, decode_gost("18").bore
    (12.0, 8.0)
    """
    digits = str(text).strip()
    if not re.fullmatch(r"\d{2,7}", digits):
        raise DesignationError(f"designation: {text!r} is not a GOST 3189 number (2 to 7 digits)")
    padded = digits.rjust(7, "0")
    width_series, design, type_digit, third, second, first = (
        padded[0], padded[1:3], padded[3], padded[4], padded[5], padded[6])
    # below 10 mm the bore is the last digit and the series moves to the second place
    small = len(digits) == 2 or (len(digits) >= 4 and third == "0" and second != "0")
    if small:
        bore = float(first)
        diameter_series = second
    else:
        bore = bore_from_code(second + first)
        diameter_series = third
    if type_digit not in _GOST_TYPES:
        raise DesignationError(f"designation: {text!r} has type digit {type_digit!r}, not a GOST 3189 type")
    return GostCode(digits, bore, diameter_series, _GOST_DIAMETER_SERIES.get(diameter_series, "unknown"),
                    type_digit, _GOST_TYPES[type_digit], design, width_series)


@functools.lru_cache(maxsize=None)
def _lab_bearings() -> dict[str, dict]:
    table = load_table("lab_bearings")
    return {row["designation"]: row for row in table.to_dict("records")}


def _try_gost(text: str) -> Designation | None:
    """The lab bearings of the DP11A manual table 3 are GOST numbers; other plain numbers are ISO."""
    lab = _lab_bearings().get(text)
    if lab is None:
        return None
    code = decode_gost(text)
    return Designation(text, lab["bearing_type"], lab["series"], "", code.bore, None, (), "open", None,
                       (f"GOST {text}: the DP11A manual table 3, friction row of ISO series {lab['series']}",))


# ---- close matches -------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def known_series() -> dict[str, list[str]]:
    """bearing type -> series keys of tables/friction_coefficients.csv."""
    table = load_table("friction_coefficients")
    out: dict[str, list[str]] = {}
    for bearing_type, series in zip(table["bearing_type"], table["series"]):
        out.setdefault(bearing_type, []).append(series)
    return out


@functools.lru_cache(maxsize=None)
def _full_designations() -> tuple[str, ...]:
    """Every full designation of the HR 1 bearing table (as :func:`bearingheat.catalogue.bearings.designations`)."""
    return tuple(str(d) for d in load_table("bearings_hr1_2006")["designation"])


def _unknown_message(text: str, body: str) -> str:
    """Close full designations of the bearing table: those with the same number first (closest first), then
    difflib's closest."""
    probe = "-".join(p for p in re.split(r"[-\s]+", str(text).strip().upper()) if p)
    names = _full_designations()
    cores = {body, re.sub(r"(?<=\d)[A-Z]+$", "", body)}  # '6208X' -> 6208, 6208-2Z ...
    same_body = sorted((n for n in names if n.split("-")[0] in cores),
                       key=lambda n: -difflib.SequenceMatcher(None, probe, n).ratio())
    close = list(dict.fromkeys(same_body + difflib.get_close_matches(probe, names, n=5, cutoff=0.5)))[:5]
    hint = f" (close matches: {', '.join(close)})" if close else ""
    return (f"designation: {text!r} matches no row of the Schaeffler catalogue tables{hint}; "
            "give type and series explicitly instead")
