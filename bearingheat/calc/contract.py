"""The column contract of ``calc``: every input and output column, once.

Each :class:`Column` says its name, its catalogue unit, what it means, who
reads or writes it (``owner``: the friction model, an extension, or the
table itself) and, for inputs, whether a designer must fill it and which
values a drop-down list offers. Everything else is generated from here:

- the unit conversion of ``name [unit]`` headers (:func:`input_units`),
- the result headers (:func:`output_header`),
- ``bearingheat calc --help`` (:func:`help_text`),
- the Excel template's columns, comments and drop-down lists (``io/excel/template.py``),
- the column table of the docs (:func:`markdown_table`).

Catalogue units: ``''`` is text, ``'1'`` a dimensionless number, anything
else a pint unit (temperature differences are ``delta_degC`` so that a
header in ``degC`` is refused for them).

>>> input_units()["Fr"], output_units()["MR"]
('N', 'N*mm')
>>> output_header("nu_n_dM")
'nu*n*dM [mm^3/(s*min)]'
>>> columns(owner="contact", kind="input")
('z', 'Dw', 'dm_pitch')
"""
from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd

from bearingheat.catalogue.designation import BEARING_TYPES
from bearingheat.catalogue.friction import LUBRICATION_F0_COLUMN
from bearingheat.errors import InputError

__all__ = [
    "Column",
    "CONTRACT",
    "OWNERS",
    "PLAIN_TYPES",
    "ARRANGEMENTS",
    "LABEL_COLUMNS",
    "column",
    "columns",
    "readable_header",
    "input_units",
    "output_units",
    "output_header",
    "TEXT_DTYPE",
    "parse_header",
    "result_column",
    "register_choices",
    "inside_ranges",
    "range_problems",
    "RANGES",
    "RANGE_SOURCES",
    "choices",
    "template_columns",
    "help_text",
    "markdown_table",
]

#: who reads or writes a column -> what it is, for the help and the docs
OWNERS = {
    "table": "the table itself",
    "friction": "the friction model",
    "thermal": "the heat balance (ISO 15312 reference speed, permissible speed, operating temperature)",
    "contact": "ball contact (minimum axial load)",
    "plain": "plain bushings (type plain_bushing)",
    "skf": "the SKF model (model skf: SKF General Catalogue 6000, SKF Rolling bearings 10000/3)",
    "uncertainty": "95 % bands from the scatter of f0 and f1 (calc --coefficients, or the columns below)",
    "duty": "duty cycles (several operating cases of one support; bearingheat.duty_cycle)",
}
#: support types that are not rolling bearings
PLAIN_TYPES = ("plain_bushing",)
#: how a bearing is mounted
ARRANGEMENTS = ("single", "paired")
#: input columns that label a row for the user: calc passes them through and no calculation reads them
LABEL_COLUMNS = ("id",)


@dataclass(frozen=True)
class Column:
    """One column of the calc contract.

    ``template`` is the (unit shown in the units row, column width) of the
    column in the Excel template, or None where the template has no such
    column; ``required`` marks the columns a designer must fill for a
    rolling bearing (bold headers in the template). ``shown`` is the
    header name where it differs from ``name`` (``Fa/A`` for ``Fa_over_A``).
    ``valid`` and ``plausible`` are (low, high) in the catalogue unit: a
    number outside ``valid`` makes its row an error, one outside
    ``plausible`` gives a warning (usually a unit mix-up); None: no bound
    beyond the model's own checks.
    """

    name: str
    unit: str
    meaning: str
    owner: str
    kind: str = "input"
    required: bool = False
    template: tuple[str, int] | None = None
    shown: str = ""
    valid: tuple[float, float] | None = None
    plausible: tuple[float, float] | None = None

    @property
    def header(self) -> str:
        """The header calc writes: ``name [unit]``, or the bare name of a text or dimensionless column."""
        name = self.shown or self.name
        return name if self.unit in ("", "1") else f"{name} [{self.unit}]"


def _in(name, unit, meaning, owner="friction", *, required=False, template=None):
    return Column(name, unit, meaning, owner, "input", required, template)


def _out(name, unit, meaning, owner="friction", shown=""):
    return Column(name, unit, meaning, owner, "output", shown=shown)


#: every column, inputs in the order of the Excel template, then the optional inputs, then the results
CONTRACT: tuple[Column, ...] = (
    # --- inputs of the template, in its column order (Fr lands in column F)
    _in("id", "", "your label of the support, e.g. 'input shaft A (locating)'", "table", template=("-", 26)),
    _in("designation", "", "bearing designation, e.g. 6208, NU208-E, 30208-A, 7210-B, 6205-2Z",
        required=True, template=("-", 14)),
    _in("d", "mm", "bore; blank: read from the designation (6208 -> 40 mm)", template=("mm", 8)),
    _in("D", "mm", "outside diameter", required=True, template=("mm", 8)),
    _in("n", "1/min", "shaft speed (1/min, rpm, U/min, min^-1, Hz, rad/s)", required=True,
        template=("1/min", 9)),
    _in("Fr", "N", "radial load (N, kN, lbf, kgf); blank = 0", required=True, template=("kN", 9)),
    _in("Fa", "N", "axial load; blank = 0", template=("kN", 9)),
    _in("nu", "mm^2/s", "operating viscosity (base oil viscosity for grease); mm^2/s = cSt", required=True,
        template=("mm^2/s", 10)),
    _in("lubrication", "", "grease, oil_mist, oil_bath or circulating_oil (drop-down list)", required=True,
        template=("-", 16)),
    _in("arrangement", "", "single (blank) or paired (drop-down list): a pair in X or O arrangement is one "
        "support, and its results are the pair's (SKF model: each bearing at Fr/2, and Fa = 0 only)",
        template=("-", 13)),
    _in("B", "mm", "width; needed for the f0 formula of needle roller bearings", template=("mm", 8)),
    _in("C0", "N", "static load rating; needed where f1 depends on P0/C0 or Fa/C0", template=("kN", 9)),
    _in("Y", "1", "catalogue axial factor of tapered roller bearings (P1 under axial load)", template=("1", 7)),
    _in("e", "1", "catalogue factor e of spherical roller bearings (P1 under axial load)", template=("1", 7)),
    _in("X0", "1", "static radial factor; blank: the DP11A manual table 1", template=("1", 7)),
    _in("Y0", "1", "static axial factor; blank: the DP11A manual table 1 or the contact angle", template=("1", 7)),
    _in("alpha", "deg", "working contact angle of angular contact ball bearings", template=("deg", 8)),
    _in("type", "", "bearing type instead of a designation (drop-down list), with series", template=("-", 30)),
    _in("series", "", "dimension series with type, e.g. 62, 302, 222", template=("-", 9)),
    _in("f0", "1", "override of the table f0", template=("1", 7)),
    _in("f1", "1", "override of the table f1", template=("1", 9)),
    _in("f2", "1", "f2 of axially loaded cylindrical roller bearings (read off the chart)", template=("1", 7)),
    # --- optional inputs outside the template
    _in("model", "", "friction model of the row (blank: the table's --model, default schaeffler)", "table",
        template=("-", 11)),
    _in("f_plain", "1", "friction coefficient of a plain bushing (blank: the middle of the catalogue band)",
        "plain"),
    _in("T", "mm", "total width of tapered roller bearings: A_r = pi*T*(D+d)", "thermal", template=("mm", 8)),
    _in("d1", "mm", "outside diameter of the shaft washer of an axial spherical roller bearing (A_r)", "thermal",
        template=("mm", 8)),
    _in("D1", "mm", "bore of the housing washer of an axial spherical roller bearing (A_r)", "thermal",
        template=("mm", 8)),
    _in("k_q", "W/(mm^2*K)", "heat transfer coefficient of the seat; default q_r/50 K", "thermal",
        template=("W/(mm^2*K)", 11)),
    _in("T_amb", "degC", "ambient temperature", "thermal", template=("degC", 8)),
    _in("T_bearing", "degC", "bearing (outer ring) temperature for n_per", "thermal", template=("degC", 10)),
    _in("V_oil", "l/min", "circulating oil flow", "thermal", template=("l/min", 8)),
    _in("dT_oil", "delta_degC", "oil temperature rise; default T - T_amb (oil fed at ambient, leaving at the bearing "
        "temperature T: T_bearing for n_per, Q_S and Q_L, each trial temperature for T_op)", "thermal",
        template=("K", 8)),
    _in("Q_E", "W", "external heat flowing INTO the bearing (negative: cooling)", "thermal", template=("W", 8)),
    _in("nu40", "mm^2/s", "oil viscosity at 40 degC (ASTM D341 with nu100)", "thermal", template=("mm^2/s", 9)),
    _in("nu100", "mm^2/s", "oil viscosity at 100 degC (ASTM D341 with nu40)", "thermal", template=("mm^2/s", 9)),
    _in("iso_vg", "1", "ISO VG grade instead of nu40/nu100", "thermal", template=("1", 8)),
    _in("VI", "1", "viscosity index of an ISO VG oil (default 95)", "thermal", template=("1", 6)),
    _in("n_G", "1/min", "limiting speed: n_per is capped at it (warning)", "thermal", template=("1/min", 9)),
    _in("n_thr_catalogue", "1/min", "catalogue n_thr; n_per then uses it instead of the computed one", "thermal",
        template=("1/min", 9)),
    _in("viscosity_at", "", "where the viscosity of nu40/nu100 or iso_vg is taken: auto (T_op where T_amb and n "
        "are given; T_bearing where they are not, or where T_op has no solution), operating (T_op) or bearing "
        "(T_bearing); blank: the table's --viscosity-at, default auto", "thermal"),
    _in("n_per_method", "", "how n_per is found: exact (root of the heat balance) or approximation (the "
        "catalogue's formula for f_n); blank: the table's --n-per-method, default exact", "thermal",
        template=("-", 14)),
    _in("oil", "", "SKF model: mineral (default), synthetic or transmission_fluid (sets mu_EHL)", "skf",
        template=("-", 12)),
    _in("mu_sl", "1", "SKF model: fixed sliding friction coefficient (the catalogue example: 0.05 at full film)",
        "skf", template=("1", 7)),
    _in("mu_bl", "1", "SKF model: boundary friction coefficient (default 0.15)", "skf",
        template=("1", 7)),
    _in("oil_level", "mm", "SKF model: oil level H above the lowest contact point of the outer ring raceway "
        "(required in an oil bath)", "skf", template=("mm", 8)),
    _in("VM", "1", "SKF model: drag loss factor read off the edition's diagram (required in an oil bath)", "skf",
        template=("1", 9)),
    _in("skf_edition", "", "SKF model: 6000 or 10000, the catalogue edition of the drag formula (default 10000)",
        "skf", template=("-", 10)),
    _in("seal", "", "SKF model: seal type of SKF table 4 (RSL, RZ, RSH, RS1, LS, CS, CS2, CS5); blank: "
        "from the designation", "skf", template=("-", 8)),
    _in("seals", "1", "SKF model: number of seals, 0, 1 or 2 (blank: from the designation)", "skf",
        template=("1", 6)),
    _in("d_s", "mm", "SKF model: seal counterface diameter (required for contact seals; with it the seal friction "
        "is in the heat balance, and a sealed bearing gets n_per and T_op)", "skf",
        template=("mm", 8)),
    _in("C", "N", "basic dynamic load rating: a load below the bearing's minimum load is a warning (the catalogue "
        "model: C/100, or C0/60 of cylindrical roller bearings, Schaeffler HR 1; the SKF model: 0.01 C of ball and "
        "0.02 C of roller bearings); blank: the bearing table", template=("kN", 9)),
    _in("f0_rel_unc", "1", "relative half-width of the 95 % interval of f0 (0.1: +-10 %); gives the bands "
        "MR_low, MR_high, ...", "uncertainty"),
    _in("f1_rel_unc", "1", "relative half-width of the 95 % interval of f1", "uncertainty"),
    _in("support", "", "the physical bearing a row is a case of (rows of one support form its duty cycle)", "duty",
        template=("-", 16)),
    _in("case", "", "name of the operating case, e.g. 'full load'", "duty", template=("-", 12)),
    _in("time_share", "1", "fraction of the time the support runs in this case (the shares of a support sum to 1)",
        "duty", template=("1", 10)),
    _in("duration", "h", "time the support runs in this case, instead of time_share", "duty", template=("h", 9)),
    _in("z", "1", "number of balls", "contact"),
    _in("Dw", "mm", "rolling element diameter (ball diameter of the contact check; SKF model: decides a low "
        "oil level)", "contact"),
    _in("dm_pitch", "mm", "ball pitch diameter", "contact"),
    # --- results
    _out("f0", "1", "speed-dependent friction coefficient (table, formula or override)"),
    _out("f1", "1", "load-dependent friction coefficient"),
    _out("P0", "N", "static equivalent load (f1 in P0/C0)"),
    _out("P1", "N", "equivalent load of M1"),
    _out("M0", "N*mm", "speed-dependent friction torque (of both bearings of a pair)"),
    _out("M1", "N*mm", "load-dependent friction torque"),
    _out("M2", "N*mm", "axial-load torque of cylindrical roller bearings"),
    _out("MR", "N*mm", "total friction torque (of the pair where arrangement is paired)"),
    *(_out(f"{name}_{edge}", unit, f"{'lower' if edge == 'low' else 'upper'} end of the 95 % band of {name}",
           "uncertainty")
      for name, unit in (("MR", "N*mm"), ("NR", "W"), ("n_thr", "1/min"), ("n_per", "1/min"), ("T_op", "degC"))
      for edge in ("low", "high")),
    _out("NR", "W", "friction power loss (of the pair where arrangement is paired)"),
    _out("Fa_over_A", "1", "Fa/A, to read f2 off the chart (rows with M2)", shown="Fa/A"),
    _out("nu_n_dM", "mm^3/(s*min)", "nu*n*dM, to read f2 off the chart (rows with M2)", shown="nu*n*dM"),
    _out("p_plain", "N/mm^2", "bearing pressure of a plain bushing", "plain", shown="p"),
    _out("V_plain", "m/s", "sliding speed of a plain bushing", "plain", shown="V"),
    _out("n_thr", "1/min", "thermal reference speed (ISO 15312)", "thermal"),
    _out("n_per", "1/min", "thermally permissible speed at T_bearing", "thermal"),
    _out("n_per_method_used", "", "how n_per was found: exact root or catalogue approximation", "thermal"),
    _out("nu_used", "mm^2/s", "viscosity the friction results (M0, MR, NR) are computed at, where it comes from "
         "oil data (nu40/nu100 or iso_vg)", "thermal"),
    _out("nu_at", "", "the temperature nu_used is taken at: T_op (the operating temperature, with T_op and nu_op "
         "one operating state) or T_bearing (viscosity_at bearing, or T_op has no solution)", "thermal"),
    _out("T_op", "degC", "operating temperature at the speed n", "thermal"),
    _out("nu_op", "mm^2/s", "viscosity at T_op", "thermal"),
    _out("Q_S", "W", "heat carried away through the seat", "thermal"),
    _out("Q_L", "W", "heat carried away by the circulating oil", "thermal"),
    _out("Fa_min", "N", "minimum axial load against ball skidding", "contact"),
    _out("G_rr", "1", "SKF model: rolling frictional variable (of one bearing of a pair)", "skf"),
    _out("G_sl", "1", "SKF model: sliding frictional variable (of one bearing of a pair)", "skf"),
    _out("M_rr", "N*mm", "SKF model: rolling frictional moment (before phi_ish, phi_rs; of both bearings of a "
         "pair)", "skf"),
    _out("M_sl", "N*mm", "SKF model: sliding frictional moment (of both bearings of a pair)", "skf"),
    _out("M_seal", "N*mm", "SKF model: frictional moment of the seals (of both bearings of a pair)", "skf"),
    _out("M_drag", "N*mm", "SKF model: frictional moment of drag losses (oil bath, oil jet; of both bearings of a "
         "pair)", "skf"),
    _out("phi_ish", "1", "SKF model: inlet shear heating reduction factor (of one bearing of a pair)", "skf"),
    _out("phi_rs", "1", "SKF model: kinematic replenishment/starvation reduction factor (of one bearing of a "
         "pair)", "skf"),
    _out("phi_bl", "1", "SKF model: weighting factor of the sliding friction coefficient (of one bearing of a "
         "pair)", "skf"),
    _out("mu_sl", "1", "SKF model: the sliding friction coefficient used (of one bearing of a pair)", "skf",
         shown="mu_sl_used"),
    _out("M_start", "N*mm", "SKF model: starting torque (of both bearings of a pair)", "skf"),
    _out("VM_chart", "1", "SKF model: the drag loss factor VM read off the digitised VM chart (calc --vm-chart) "
         "at the row's H/dm; blank where VM was given or not needed", "skf"),
    _out("status", "", "ok | warning | error", "table"),
    _out("message", "", "what is wrong or uncertain, naming the column (and the cell in a workbook)", "table"),
)

_INF = float("inf")
#: input -> (valid, plausible) ranges in the catalogue unit. The lower bounds the friction model checks itself
#: (d > 0, n >= 0, ν > 0, loads >= 0, C0 > 0) are left to it; these catch what no formula check sees: a
#: number far outside any bearing (often a unit mix-up) and absurd magnitudes that overflow the formulas.
RANGES: dict[str, tuple[tuple[float, float] | None, tuple[float, float] | None]] = {
    "d": ((-_INF, 1e5), (0.5, 5000.0)),           # mm: bores of catalogue bearings 0.6 mm to about 5 m
    "D": ((-_INF, 1e5), (1.0, 6000.0)),
    "B": ((-_INF, 1e5), (0.5, 2000.0)),
    "T": ((-_INF, 1e5), (0.5, 2000.0)),
    "d1": ((-_INF, 1e5), (0.5, 6000.0)),
    "D1": ((-_INF, 1e5), (0.5, 6000.0)),
    "C0": ((-_INF, 1e10), (10.0, 1e8)),           # N
    "C": ((-_INF, 1e10), (10.0, 1e8)),
    "Fr": ((-_INF, 1e10), (-_INF, 1e8)),
    "Fa": ((-_INF, 1e10), (-_INF, 1e8)),
    "n": ((-_INF, 1e7), (-_INF, 2e5)),            # 1/min
    "nu": ((-_INF, 1e7), (1.0, 1e5)),             # mm²/s
    "alpha": ((0.0, 90.0), None),                 # deg
    "T_amb": ((-60.0, 200.0), None),              # degC
    "T_bearing": ((-60.0, 300.0), (-60.0, 200.0)),
    "dT_oil": ((0.0, 200.0), None),               # K
    "V_oil": ((-_INF, 1e4), None),                # l/min
    "nu40": ((-_INF, 1e7), (1.0, 1e5)),
    "nu100": ((-_INF, 1e7), (1.0, 1e5)),
    "iso_vg": ((1.0, 10000.0), None),
    "VI": ((-100.0, 400.0), None),
    "n_G": ((-_INF, 1e7), None),
    "n_thr_catalogue": ((-_INF, 1e7), None),
    "z": ((1.0, 1000.0), None),
    "Dw": ((-_INF, 1e4), None),
    "oil_level": ((-_INF, 1e5), (-_INF, 5000.0)),   # mm: above 1.2 dm the drag is that of 1.2 dm (10000/3 p. 111)
    "dm_pitch": ((-_INF, 1e5), None),
    "f0_rel_unc": ((0.0, 1.0), (0.0, 0.5)),      # a half-width above 50 % is usually a percent typed as 1
    "f1_rel_unc": ((0.0, 1.0), (0.0, 0.5)),
    "f_plain": ((0.0, 1.0), None),
    "VM": (None, (-_INF, 1e-2)),
    "mu_sl": (None, (-_INF, 0.3)),
    "mu_bl": (None, (-_INF, 0.3)),
    "k_q": (None, (2e-5, 1e-2)),                  # W/(mm²·K): see RANGE_SOURCES
    "Q_E": (None, (-1e5, 1e5)),                   # W: see RANGE_SOURCES
}
#: input -> where its plausible range comes from, said in the warning (ranges that are no plain unit check)
RANGE_SOURCES = {
    "VM": "over 300 times the 0.3·10⁻⁴ the worked example of SKF 6000 pp. 104-105 reads off diagram 2; the diagram's "
          "data are not in bearingheat, so the bound is wide",
    **dict.fromkeys(("mu_sl", "mu_bl"), "twice μbl ≈ 0.15 of SKF 6000 p. 101 and 10000/3 p. 103, the largest sliding "
                                        "coefficient of the model"),
    "k_q": ("a tenth to ten times the 0.2e-3 to 1.0e-3 W/(mm^2*K) of the Schaeffler HR 1 catalogue for seats up to "
            "25 000 mm^2; its default q_r/50 K is 3.2e-4"),
    "Q_E": ("the heat q_r*A_r the seat of a bearing of plausible size (D up to 6000 mm, B up to 2000 mm) carries away "
            "at the ISO 15312 reference conditions is below 1e5 W"),
}
CONTRACT = tuple(dataclasses.replace(c, valid=RANGES[c.name][0], plausible=RANGES[c.name][1])
                 if c.kind == "input" and c.name in RANGES else c for c in CONTRACT)

_BY_KIND = {kind: {c.name: c for c in CONTRACT if c.kind == kind} for kind in ("input", "output")}

#: drop-down lists: input column -> the values it takes (the model names are added by calc/models.py)
_CHOICES: dict[str, Callable[[], tuple[str, ...]]] = {
    "lubrication": lambda: tuple(LUBRICATION_F0_COLUMN),
    "arrangement": lambda: ARRANGEMENTS,
    "type": lambda: tuple(BEARING_TYPES),
}


def register_choices(name: str, values: Callable[[], tuple[str, ...]]) -> None:
    """Let a registry (the friction models) supply the drop-down values of an input column."""
    column(name, "input")
    _CHOICES[name] = values


def column(name: str, kind: str = "input") -> Column:
    """The contract entry of a column; an unknown name is an :class:`InputError` listing the known ones.

    >>> column("T_amb").unit
    'degC'
    >>> column("speed")
    Traceback (most recent call last):
    ...
    bearingheat.errors.InputError: 'speed' is not an input column of calc; known: id, designation, ...
    """
    try:
        return _BY_KIND[kind][name]
    except KeyError:
        known = ", ".join(_BY_KIND[kind])
        raise InputError(f"{name!r} is not an {kind} column of calc; known: {known}") from None


def columns(*, owner: str | None = None, kind: str = "input") -> tuple[str, ...]:
    """Names of the columns of one kind (and one owner), in contract order."""
    return tuple(c.name for c in CONTRACT if c.kind == kind and (owner is None or c.owner == owner))


def input_units(owner: str | None = None) -> dict[str, str]:
    """Input column -> catalogue unit (of one owner, or all)."""
    return {c.name: c.unit for c in CONTRACT if c.kind == "input" and (owner is None or c.owner == owner)}


def output_units(owner: str | None = None) -> dict[str, str]:
    """Result column -> unit (of one owner, or all; without status and message)."""
    return {c.name: c.unit for c in CONTRACT
            if c.kind == "output" and c.owner != "table" and (owner is None or c.owner == owner)}


#: the dtype of a text result column: the one pandas gives a column of text (its Arrow-backed 'str' since pandas 3,
#: object before)
TEXT_DTYPE = pd.Series(["text"]).dtype


def output_header(name: str, unit: str | None = None) -> str:
    """The header of a result column: ``MR [N*mm]``, ``f0``, ``Fa/A``."""
    entry = _BY_KIND["output"].get(name)
    shown = entry.shown or name if entry else name
    unit = (entry.unit if entry else "") if unit is None else unit
    return shown if unit in ("", "1") else f"{shown} [{unit}]"


_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]+?)\s*(?:\[\s*(?P<unit>[^\]]*?)\s*\])?\s*$")


def readable_header(header) -> bool:
    """Whether a header reads as ``name`` or ``name [unit]`` (calc passes the other columns through untouched).

    >>> readable_header("Fr [kN]"), readable_header("remark [see note]]")
    (True, False)
    """
    return _HEADER.match(str(header)) is not None


def parse_header(header, *, strict: bool = True) -> tuple[str, str | None]:
    """``'Fr [kN] '`` -> ``('Fr', 'kN')``; ``'id'`` -> ``('id', None)``.

    A header that is not ``name [unit]`` raises :class:`InputError`, or with
    ``strict=False`` comes back whole as a name without a unit.

    >>> parse_header(' n [U/min] ')
    ('n', 'U/min')
    >>> parse_header('a] b', strict=False)
    ('a] b', None)
    """
    match = _HEADER.match(str(header))
    if not match:
        if not strict:
            return str(header).strip(), None
        raise InputError(f"column {header!r}: cannot read the header; write it as 'name [unit]'")
    return match.group("name").strip(), match.group("unit")


def result_column(header) -> str | None:
    """The result column of calc that an input header names (None for any other header): calc writes that column
    itself, so an input column of that name would be hidden by it or overwrite it ('status' of a designer's
    released/draft list replaced by ok/error). Names that are inputs as well (f0, f1, mu_sl) are inputs.

    >>> result_column("status"), result_column("MR [N*mm]"), result_column("Fa/A"), result_column("f0")
    ('status', 'MR', 'Fa/A', None)
    """
    name, _ = parse_header(header, strict=False)
    if name in _BY_KIND["input"]:
        return None
    written = {c.shown or c.name for c in _BY_KIND["output"].values()} | set(_BY_KIND["output"])
    return name if name in written else None


def choices(name: str) -> tuple[str, ...]:
    """The values a drop-down list offers for an input column (empty: free input)."""
    provider = _CHOICES.get(name)
    return provider() if provider else ()


def template_columns() -> tuple[Column, ...]:
    """The input columns of the Excel template, in sheet order."""
    return tuple(c for c in CONTRACT if c.kind == "input" and c.template is not None)


def _unit_text(unit: str) -> str:
    return {"": "text", "1": "1"}.get(unit, unit)


def help_text() -> str:
    """The column part of ``bearingheat calc --help``, grouped by owner."""
    lines = []
    for owner, title in OWNERS.items():
        ins = [c for c in CONTRACT if c.owner == owner and c.kind == "input"]
        outs = [c for c in CONTRACT if c.owner == owner and c.kind == "output"]
        if not ins and not outs:
            continue
        lines.append(f"{title[0].upper()}{title[1:]}:")
        for c in ins:
            flag = " (required)" if c.required else ""
            lines.append(f"  {c.name + ' [' + _unit_text(c.unit) + ']':<26} {c.meaning}{flag}")
            if choices(c.name) and c.name != "type":  # the bearing types are many: the template lists them
                lines.append(f"  {'':<26} one of: {' | '.join(choices(c.name))}")
        if outs:
            lines.append("  -> " + ", ".join(c.header for c in outs))
    return "\n".join(lines)


def markdown_table(kind: str = "input") -> str:
    """The docs table of the contract's columns of one kind.

    >>> print(markdown_table("output").splitlines()[2])
    | f0 | 1 | the friction model | speed-dependent friction coefficient (table, formula or override) |
    """
    rows = ["| column | unit | owner | meaning |", "|---|---|---|---|"]
    for c in CONTRACT:
        if c.kind == kind:
            rows.append(f"| {c.shown or c.name} | {_unit_text(c.unit)} | {OWNERS[c.owner]} | {c.meaning}"
                        f"{_range_text(c)} |")
    return "\n".join(rows)


def inside_ranges(name: str, low: float, high: float) -> bool:
    """Whether numbers from ``low`` to ``high`` are finite and inside the contract's narrower range of ``name``
    (plausible lies inside valid), so that none of them has a range problem.

    >>> inside_ranges("T_amb", 20.0, 40.0), inside_ranges("T_amb", 20.0, 250.0), inside_ranges("T_amb", 20.0, np.nan)
    (True, False, False)
    """
    entry = column(name)
    inner = entry.plausible or entry.valid
    return bool(np.isfinite(low) and np.isfinite(high) and (inner is None or inner[0] <= low and high <= inner[1]))


def range_problems(name: str, values: np.ndarray, describe: Callable[[int], str]
                   ) -> tuple[list[tuple[int, str]], list[tuple[int, str]]]:
    """(errors, warnings) of the numbers of an input column against its contract ranges (catalogue units).

    An infinite number, or one outside ``valid``, is an error; one outside
    ``plausible`` a warning. NaN means 'not given' and is not checked.
    ``describe(i)`` words the value of entry i, e.g. ``'T_amb [K]: 20 (-253.15 degC)'``.

    >>> range_problems("T_amb", np.array([20.0, 250.0]), lambda i: f"T_amb: {[20, 250][i]}")
    ([(1, 'T_amb: 250 is outside the valid range -60 to 200 degC')], [])
    """
    entry = column(name)
    values = np.asarray(values, dtype=float)
    # NaN (not given) left out of the smallest and the largest; NaN if all are
    if len(values) and inside_ranges(name, np.fmin.reduce(values), np.fmax.reduce(values)):
        return [], []
    unit = {"1": "", "delta_degC": "K"}.get(entry.unit, entry.unit)
    errors = [(int(i), f"{describe(int(i))} is not a finite number") for i in np.flatnonzero(np.isinf(values))]
    warnings: list[tuple[int, str]] = []
    reported = np.isinf(values)
    for bounds, level, found in ((entry.valid, "valid", errors), (entry.plausible, "plausible", warnings)):
        if bounds is None:
            continue
        low, high = bounds
        with np.errstate(invalid="ignore"):
            outside = np.isfinite(values) & ((values < low) | (values > high)) & ~reported
        reported |= outside
        span = f"{low:g} to {high:g}" if low > -_INF else f"up to {high:g}"
        source = f" ({RANGE_SOURCES[name]})" if level == "plausible" and name in RANGE_SOURCES else ""
        hint = f"{source}; check the number and its unit" if level == "plausible" else ""
        for i in np.flatnonzero(outside):
            found.append((int(i), f"{describe(int(i))} is outside the {level} range {span} {unit}".rstrip() + hint))
    return errors, warnings


def _range_text(c: Column) -> str:
    """'; valid -60 to 200, plausible ...' in the catalogue unit (empty where the contract sets no range)."""
    parts = []
    for word, bounds in (("valid", c.valid), ("plausible", c.plausible)):
        if bounds is not None:
            low, high = bounds
            text = f"{low:g} to {high:g}" if low > -_INF else f"up to {high:g}"
            parts.append(f"{word} {text}")
    return f" ({', '.join(parts)} {_unit_text(c.unit)})" if parts else ""
