"""Live Excel formulas for the results sheet (``bearingheat calc --formulas``).

Every result of the catalogue model has a closed form, so every one is a
formula that refers to the input cells: ``f0``, ``f1``, ``P0``, ``P1``,
``M0``, ``M1``, ``M2``, ``MR`` and ``NR``, and the helper columns ``f2``,
``dM`` and the operating point ``n``, ``nu``, ``Fr``, ``Fa`` in catalogue
units (:data:`HELPER_COLUMNS`; each input cell is read once). A designer changes n, Fr, Fa, ν, d, D, B, C0, X0, Y0, Y, e,
the lubrication or an f0/f1/f2 override in Excel and the results follow
without Python. The inputs are in the user's units; every reference is
multiplied by the factor to the catalogue unit, computed with pint from the
units row (kN -> ``*1000``, Hz -> ``*60``, lbf -> ``*4.4482216152605``).

The catalogue's tables are keyed by the bearing: the f0 values of the
row's bearing for grease/oil mist and for oil bath/circulating oil (the
lubrication cell picks one), f1's a and x (its ratio P0/C0 or Fa/C0 stays
live), X0 and Y0 of table 1 of the DP11A laboratory rig manual, the P1
rule of the bearing type and arrangement. They are numbers in the formulas, so a change of the
designation, type, series, arrangement, model or contact angle is one the
formulas do not follow: the live check of :mod:`.freshness` then strikes
every result of the row. A blank input cell reads as calc reads it: 0 for
the loads, the table value for X0, Y0 and the overrides, the bearing
table's value (:func:`bearingheat.calc.fill.catalogue_values`) or the
designation's bore and width for d, D, B, C0, Y, e; a cell that calc had
from the user and that is cleared shows ``#N/A`` until calc runs again.

Values that are no closed form of the row's inputs stay values: an f2 read
off the digitised chart (``--f2-chart``) and a viscosity that calc took
from the oil's viscosity-temperature curve. A row that uses one gets its
formulas, and any change of its inputs strikes all of its results. Before
a row gets formulas, M0 is recomputed from the formulas' inputs (f0, ν, n,
dM, the bearings of a pair) and compared with calc's; a row whose inputs
would differ (a viscosity calc took at another temperature) keeps its
values.

Formulas (Schaeffler rolling bearing catalogue, «Трение и нагрев», pp. 64-69; DP11A laboratory rig
manual, table 1; catalogue units N, mm, 1/min, mm²/s)::

    f0 = IF(f0 given, f0, value of the lubrication [*B/(33+d) for needle roller bearings])
    f1 = IF(f1 given, f1, a*(P0/C0)^x | a*(Fa/C0)^x | a)
    P0 = IF(Fa > 0, MAX(X0*Fr + Y0*Fa, Fr), Fr)
    P1 = MAX(rule(Fr, Fa, Y, e), Fr)
    dM = (d + D)/2
    M0 = f0 · IF(ν·n >= 2000, (ν·n)^(2/3), 160) · dM³ · 1e-7
    M1 = f1 · (Fr | Fa | P1) · dM
    M2 = f2 · Fa · dM
    MR = M0 + M1 + M2
    NR = MR · n / 9550
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from openpyxl.utils import get_column_letter

from bearingheat.calc.contract import output_header
from bearingheat.calc.fill import catalogue_values, fill_from_catalogue
from bearingheat.calc.friction import F0_EXCEL, F1_EXCEL, P1_EXCEL
from bearingheat.calc.messages import at
from bearingheat.calc.models import DEFAULT_MODEL, RESULT_UNITS, get_model, support_arrays_of
from bearingheat.calc.supports import SupportArrays, text_column
from bearingheat.calc.conversion import to_catalogue_units
from bearingheat.catalogue.contact import y0_for_contact_angle
from bearingheat.catalogue.friction import LUBRICATION_F0_COLUMN, ResolvedBearing, resolve
from bearingheat.errors import DesignationError, ExcelError
from bearingheat.kernels import friction
from bearingheat.units import convert_column
from bearingheat.io.tables import set_aside

__all__ = ["live_formulas", "LiveSheet", "unit_factor", "excel_number", "HELPER_COLUMNS"]

_CATALOGUE = {"d": "mm", "D": "mm", "B": "mm", "n": "1/min", "nu": "mm^2/s", "Fr": "N", "Fa": "N", "C0": "N",
              "Y": "1", "e": "1", "X0": "1", "Y0": "1", "f0": "1", "f1": "1", "f2": "1"}
#: what calc reads in a blank cell where that is a constant of the row (others: the catalogue's value)
_BLANK_IS_ZERO = ("Fr", "Fa")
#: the helper columns written after f1: f2 (0 where the row has no M2), the load of M1 (text), and dM and the
#: operating point in catalogue units as the formulas read them (contract name -> header; grouped and collapsed)
HELPER_COLUMNS = {"f2": "f2", "M1 load": "M1 load", "dM": "dM [mm]", "n": "n [1/min]", "nu": "nu [mm^2/s]",
                  "Fr": "Fr [N]", "Fa": "Fa [N]"}
#: relative agreement of the formulas' inputs with calc's own numbers before a row gets formulas
_AGREEMENT = 1e-9


def excel_number(value: float) -> str:
    """A float as Excel formula text that reads back to the same double; NaN as ``NA()``.

    >>> excel_number(1000.0), excel_number(4.4482216152605), excel_number(1e-07), excel_number(float("nan"))
    ('1000', '4.4482216152605', '1E-07', 'NA()')
    """
    if not math.isfinite(value):
        return "NA()"
    text = repr(float(value))
    if text.endswith(".0"):
        text = text[:-2]
    return text.replace("e", "E")


def unit_factor(unit_text: str | None, target: str, name: str) -> float:
    """Catalogue units per user unit, e.g. ('kN', 'N') -> 1000, ('Hz', '1/min') -> 60, ('rad/s', '1/min') -> 60/2π.

    >>> unit_factor('kN', 'N', 'Fr'), unit_factor('U/min', '1/min', 'n'), unit_factor(None, '1', 'Y')
    (1000.0, 1.0, 1.0)
    """
    if unit_text is None or unit_text.strip() in ("", "-", "1"):
        return 1.0
    return convert_column(np.ones(1), unit_text, target, name=name)[1]


@dataclass
class LiveSheet:
    """The results sheet of ``calc --formulas``: its table (with the helper columns), the formulas by
    (column, row position), the columns that hold formulas, and per row the input columns (contract names)
    whose change makes every result of the row stale (None: a change of any input does)."""

    table: pd.DataFrame
    formulas: dict[tuple[str, int], str]
    live_columns: list[str]
    every: list[frozenset[str] | None]
    collapsed: list[str] = field(default_factory=list)


def _given(table: pd.DataFrame, info, name: str) -> np.ndarray:
    header = info.headers.get(name)
    if header is None:
        return np.zeros(len(table), dtype=bool)
    values = table[header].to_numpy(dtype=object)
    numbers = pd.to_numeric(pd.Series(values), errors="coerce").to_numpy(dtype=float)
    logical = np.array([isinstance(v, (bool, np.bool_)) for v in values], dtype=bool)
    return ~np.isnan(numbers) & ~logical


def _prepared(table: pd.DataFrame, info) -> tuple[pd.DataFrame, SupportArrays, dict[str, np.ndarray]]:
    """The table as calc's friction model saw it (:func:`bearingheat.calc.table.calc`): catalogue units, blank
    dimensions and ratings filled from the bearing table; its support arrays (the catalogue constants of every
    row); and per row the bearing table's values, which a cell cleared later reads as. A viscosity calc took
    from the oil's curve is not filled here: calc's result says it (``nu_used``)."""
    usable, _ = set_aside(table)  # columns whose header is no 'name [unit]' are passed through by calc: not inputs
    converted = to_catalogue_units(usable, units=info.units, cell=info.cell)
    frame, _, _ = fill_from_catalogue(converted.frame, converted.labels)
    frame = frame.reset_index(drop=True)
    catalogue, _ = catalogue_values(text_column(frame, "designation"))
    return frame, support_arrays_of(frame), catalogue


class _Row:
    """The formula texts of one row: input references with their blank values, and which inputs they read."""

    def __init__(self, info, factors: dict[str, float], source_row: int):
        self.info, self.factors, self.source_row = info, factors, source_row
        self.read: set[str] = set()

    def ref(self, name: str, blank: str) -> str:
        """The input ``name`` in catalogue units: the cell (scaled) or, where it is blank, ``blank``."""
        header = self.info.headers.get(name)
        if header is None:
            return blank
        self.read.add(name)
        cell = f"{self.info.sheet_ref}!{self.info.letters[header]}{self.source_row}"
        factor = self.factors[name]
        scaled = cell if factor == 1.0 else f"({cell}*{excel_number(factor)})"
        # blank as calc reads it: an empty cell, or one of only spaces (ISBLANK is false there, and the
        # arithmetic would give #VALUE!)
        return f'IF(TRIM({cell}&"")="",{blank},{scaled})'

    def text(self, name: str) -> str | None:
        header = self.info.headers.get(name)
        if header is None:
            return None
        self.read.add(name)
        return f"TRIM({self.info.sheet_ref}!{self.info.letters[header]}{self.source_row})"


def _lubrication_choice(row: _Row, entry) -> str:
    """f0 of the bearing for the lubrication cell: the grease/oil mist or the oil bath/circulating oil value."""
    cell = row.text("lubrication")
    if cell is None:
        return "NA()"
    groups: dict[str, list[str]] = {}
    for lubrication, column in LUBRICATION_F0_COLUMN.items():
        groups.setdefault(column, []).append(lubrication)
    expression = "NA()"
    for column, names in reversed(list(groups.items())):
        test = ",".join(f'EXACT({cell},"{name}")' for name in names)
        expression = f"IF(OR({test}),{excel_number(getattr(entry, column))},{expression})"
    return expression


def _angular_y0(bearing_type, alpha: float, contact_angle: float) -> float:
    """Y0 calc takes for a blank Y0 cell of an angular contact ball bearing: from the contact angle."""
    if bearing_type != "angular_contact_ball":
        return math.nan
    angle = alpha if not math.isnan(alpha) else contact_angle
    try:
        return float(y0_for_contact_angle(angle))
    except ValueError:
        return math.nan


def live_formulas(out_table: pd.DataFrame, table: pd.DataFrame, info, result: pd.DataFrame, *,
                  model: str = DEFAULT_MODEL) -> LiveSheet:
    """The formulas of the results sheet (:class:`LiveSheet`).

    ``out_table`` is the results sheet as values (its row i is sheet row
    i + 3); ``table``/``info`` the input sheet of :func:`bearingheat.io.excel.reader.read_supports`;
    ``result`` the output of calc; ``model`` the model of rows whose model
    cell is blank. Rows in error, plain bushings and rows whose formulas
    would not reproduce calc's numbers keep their values.
    """
    headers = {name: output_header(name, unit) for name, unit in RESULT_UNITS.items()}
    out = out_table.copy()
    n_rows = len(out)
    frame, s, catalogue = _prepared(table, info)
    factors = {name: unit_factor(info.unit_of(name), target, name) for name, target in _CATALOGUE.items()}
    given = {name: _given(table, info, name) for name in _CATALOGUE}
    status = result["status"].to_numpy()
    results = {name: result[header].to_numpy(dtype=float) for name, header in headers.items()}
    nu_used = result[output_header("nu_used")].to_numpy(dtype=float) if output_header("nu_used") in result.columns \
        else np.full(n_rows, np.nan)
    models = [str(v).strip() if isinstance(v, str) and v.strip() else model
              for v in (frame["model"] if "model" in frame.columns else [None] * n_rows)]

    def used(name: str, i: int) -> float:
        value = at(getattr(s, name), i) if hasattr(s, name) else (frame[name].iloc[i] if name in frame else math.nan)
        return float(value)

    load_text: list[str | None] = [None] * n_rows
    helpers = {name: np.full(n_rows, np.nan) for name in ("f2", "dM", "n", "nu", "Fr", "Fa")}
    plans: dict[int, dict[str, str]] = {}
    every: list[frozenset[str] | None] = [None] * n_rows
    keys = list(zip(*(text_column(frame, name) for name in ("designation", "type", "series"))))
    bearings: dict[tuple, ResolvedBearing | None] = {}  # each distinct bearing resolved once
    for i in range(n_rows):
        if status[i] == "error" or bool(at(s.plain, i)) or not bool(at(s.resolved, i)):
            continue
        templates = get_model(models[i]).excel_formulas
        if templates is None:
            raise ExcelError(f"--formulas: the friction model {models[i]!r} of row {info.rows[i]} has no Excel "
                             f"formulas: {get_model(models[i]).no_formulas}; run calc without --formulas")
        if keys[i] not in bearings:
            try:
                bearings[keys[i]] = resolve(*keys[i])
            except DesignationError:
                bearings[keys[i]] = None
        resolved = bearings[keys[i]]
        if resolved is None:
            continue
        entry = resolved.entry
        row = _Row(info, factors, info.rows[i])

        bore = float(resolved.designation.bore) if resolved.designation and resolved.designation.bore else math.nan
        width = float(resolved.designation.width) if resolved.designation and resolved.designation.width \
            else math.nan
        printed = {"d": bore, "B": width}  # what the designation itself says

        def blank(name: str, calc_value: float) -> str:
            """What calc reads in a blank cell of ``name``: its constant, the bearing table's value, the
            designation's, or (a cell calc filled otherwise) its value here; NA() where it would be missing."""
            if name in _BLANK_IS_ZERO:
                return "0"
            for value in (catalogue[name][i] if name in catalogue else math.nan, printed.get(name, math.nan)):
                if not math.isnan(value):
                    return excel_number(value)
            return excel_number(calc_value) if not given[name][i] else "NA()"

        d = row.ref("d", blank("d", used("d", i)))
        D = row.ref("D", blank("D", used("D", i)))
        nu_live = bool(given["nu"][i]) and math.isnan(nu_used[i])  # else calc took it from the oil's curve
        texts: dict[str, str] = {"n": f"={row.ref('n', blank('n', used('n', i)))}", "Fr": f"={row.ref('Fr', '0')}",
                                 "Fa": f"={row.ref('Fa', '0')}"}
        if nu_live:  # else the viscosity calc took from the oil's curve, a value of the operating point
            texts["nu"] = f"={row.ref('nu', 'NA()')}"
        n, nu, Fr, Fa = "{n}", "{nu}", "{Fr}", "{Fa}"
        X0 = row.ref("X0", excel_number(float(at(s.X0_table, i))))
        y0_blank = catalogue["Y0"][i] if "Y0" in catalogue else math.nan
        if math.isnan(y0_blank):
            y0_blank = _angular_y0(at(s.bearing_type, i), used("alpha", i), float(at(s.contact_angle, i)))
        Y0 = row.ref("Y0", excel_number(y0_blank if not math.isnan(y0_blank) else float(at(s.Y0_table, i))))
        cells = {name: f"{{{name}}}" for name in ("f0", "f1", "P0", "P1", "M0", "M1", "M2", "MR", "f2", "dM")}
        # f0: the lubrication's table value (needle roller bearings: value*B/(33+d)), or the override
        f0_template = F0_EXCEL[entry.f0_basis]
        B = row.ref("B", blank("B", used("B", i))) if "{B}" in f0_template else ""
        f0_table = f0_template.format(value=_lubrication_choice(row, entry), B=B, d=d)
        f0_override = row.ref("f0", f0_table)
        texts["f0"] = f"={f0_override}"
        f1_key = "constant" if entry.f1_x == 0 else entry.f1_basis
        C0 = row.ref("C0", blank("C0", used("C0", i))) if f1_key != "constant" else "NA()"
        f1_table = F1_EXCEL[f1_key].format(a=excel_number(entry.f1_a), x=excel_number(entry.f1_x), P0=cells["P0"],
                                           Fa=Fa, C0=C0)
        texts["f1"] = f"={row.ref('f1', f1_table)}"
        texts["P0"] = templates["P0"].format(Fa=Fa, Fr=Fr, X0=X0, Y0=Y0)
        texts["dM"] = f"=({d}+{D})/2"
        rule = str(at(s.p1_rule, i))
        values = dict(cells, n=n, nu=nu, Fr=Fr, Fa=Fa, dM=cells["dM"],
                      bearings="2*" if float(at(s.bearings, i)) == 2.0 else "")
        if rule:
            values["p1_rule"] = P1_EXCEL[rule].format(Fr=Fr, Fa=Fa, Y=row.ref("Y", blank("Y", used("Y", i))),
                                                      e=row.ref("e", blank("e", used("e", i))))
            texts["P1"] = templates["P1"].format(**values)
            values["load"] = cells["P1"]
            load_text[i] = f"P1: {friction.P1_RULES[rule][1]} (P1 >= Fr)"
        else:
            values["load"] = Fa if entry.m1_load == "Fa" else Fr
            load_text[i] = entry.m1_load
        for name in ("M0", "M1", "M2", "MR", "NR"):
            texts[name] = templates[name].format(**values)
        # f2: the user's value, the chart's (a value of the operating point) or 0 where the row has no M2
        Fa_used, dM_used = used("Fa", i), friction.mean_diameter(used("d", i), used("D", i))
        strict = not nu_live
        if bool(at(s.no_axial, i)):
            texts["f2"] = f"=IF({Fa}>0,NA(),0)"
        elif bool(at(s.m2, i)):
            if Fa_used > 0 and not given["f2"][i]:
                chart = results["M2"][i] / (Fa_used * dM_used)
                texts["f2"] = f"={row.ref('f2', excel_number(chart))}"
                strict = True
            else:
                texts["f2"] = f"={row.ref('f2', f'IF({Fa}>0,NA(),0)' if Fa_used == 0 else 'NA()')}"
        # the formulas' inputs reproduce calc's numbers, or the row keeps its values
        nu_value = used("nu", i) if nu_live else nu_used[i]
        f2_value = results["M2"][i] / (Fa_used * dM_used) if Fa_used > 0 else 0.0
        M0 = float(at(s.bearings, i)) * friction.speed_dependent_torque(results["f0"][i], nu_value, used("n", i),
                                                                        dM_used)
        if not math.isclose(float(M0), results["M0"][i], rel_tol=_AGREEMENT, abs_tol=1e-12) or \
                not math.isfinite(f2_value):
            continue
        plans[i] = texts
        for name, value in (("f2", f2_value), ("dM", dM_used), ("n", used("n", i)), ("nu", nu_value),
                            ("Fr", used("Fr", i)), ("Fa", Fa_used)):
            helpers[name][i] = value
        inputs = set(get_model(models[i]).inputs) | {"model"}
        every[i] = None if strict else frozenset(inputs - row.read)

    position = list(out.columns).index(headers["f1"]) + 1
    for offset, (name, header) in enumerate(HELPER_COLUMNS.items()):
        column = pd.Series(load_text, dtype=object, index=out.index) if name == "M1 load" else helpers[name]
        out.insert(position + offset, header, column)
    letter = {header: get_column_letter(k) for k, header in enumerate(out.columns, start=1)}
    column_of = dict(headers, **{name: header for name, header in HELPER_COLUMNS.items() if name != "M1 load"})
    formulas: dict[tuple[str, int], str] = {}
    for i, texts in plans.items():
        refs = {name: f"{letter[column_of[name]]}{i + 3}" for name in column_of}
        for name, text in texts.items():
            formulas[(column_of[name], i)] = text.format(**refs)
    live = [h for h in out.columns if any((h, i) in formulas for i in plans)]
    collapsed = [HELPER_COLUMNS[name] for name in ("dM", "n", "nu", "Fr", "Fa")]
    return LiveSheet(out, formulas, live, every, collapsed)
