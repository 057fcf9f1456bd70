"""Live Excel formulas for the results sheet (``bearingheat calc --formulas``).

The result cells of P1, M0, M1, M2, M_R and N_R hold formulas that refer to
the input cells, so a designer can change n, Fr, Fa, ν, d or D in Excel and
see the torques and the power loss follow without Python. The inputs are in
the user's units; every reference is multiplied by the factor to the
catalogue unit, computed with pint from the units row (kN -> ``*1000``,
Hz -> ``*60``, lbf -> ``*4.4482216152605``).

The table lookups stay values in helper columns, because Excel cannot
repeat them sensibly: f0 (lubrication column, needle formula), f1 (table
rule in P0/C0 or Fa/C0), f2 (user value or digitised chart) and the load M1
uses ('M1 load': Fr, Fa or the P1 rule of the bearing type). They hold at
the computed operating point; a large change of load needs calc again.

Formulas (seed 002, pp. 64-69; catalogue units N, mm, 1/min, mm²/s)::

    dM = (d + D)/2
    M0 = f0 · IF(ν·n >= 2000, (ν·n)^(2/3), 160) · dM³ · 1e-7
    P1 = MAX(rule(Fr, Fa, Y, e), Fr)
    M1 = f1 · (Fr | Fa | P1) · dM
    M2 = f2 · Fa · dM
    MR = M0 + M1 + M2
    NR = MR · n / 9550
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
from openpyxl.utils import get_column_letter

from bearingheat.calc.contract import output_header
from bearingheat.calc.friction import P1_EXCEL
from bearingheat.calc.models import DEFAULT_MODEL, RESULT_UNITS, get_model
from bearingheat.catalogue.friction import resolve
from bearingheat.errors import DesignationError, ExcelError
from bearingheat.kernels import friction
from bearingheat.units import convert_column

__all__ = ["live_formulas", "unit_factor", "excel_number"]

_CATALOGUE = {"d": "mm", "D": "mm", "n": "1/min", "nu": "mm^2/s", "Fr": "N", "Fa": "N", "Y": "1", "e": "1"}


def excel_number(value: float) -> str:
    """A float as Excel formula text that reads back to the same double.

    >>> excel_number(1000.0), excel_number(4.4482216152605), excel_number(1e-07)
    ('1000', '4.4482216152605', '1E-07')
    """
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


def _resolved(designation, bearing_type, series):
    try:
        return resolve(designation, bearing_type, series)
    except DesignationError:
        return None


def _text_column(table: pd.DataFrame, info, name: str) -> list:
    header = info.headers.get(name)
    if header is None:
        return [None] * len(table)
    return [None if v is None or (isinstance(v, float) and math.isnan(v)) or not str(v).strip() else str(v).strip()
            for v in table[header]]


def _number_column(table: pd.DataFrame, info, name: str) -> np.ndarray:
    header = info.headers.get(name)
    if header is None:
        return np.full(len(table), np.nan)
    return pd.to_numeric(table[header], errors="coerce").to_numpy(dtype=float)


def live_formulas(out_table: pd.DataFrame, table: pd.DataFrame, info, result: pd.DataFrame):
    """Helper columns and formula texts for the results sheet.

    ``out_table`` is the results sheet as values (its row i is sheet row
    i + 3); ``table``/``info`` the input sheet of :func:`bearingheat.io.excel.reader.read_supports`;
    ``result`` the output of calc. Returns (results sheet table with the
    helper columns 'f2' and 'M1 load', {(column, row position): formula}).
    Rows in error keep their (empty) values.
    """
    headers = {name: output_header(name, unit) for name, unit in RESULT_UNITS.items()}
    out = out_table.copy()
    designation = _text_column(table, info, "designation")
    types = _text_column(table, info, "type")
    series = _text_column(table, info, "series")
    arrangement = [v or "single" for v in _text_column(table, info, "arrangement")]
    models = _text_column(table, info, "model")
    factors = {name: unit_factor(info.unit_of(name), target, name) for name, target in _CATALOGUE.items()}
    d_user = _number_column(table, info, "d")
    D_user = _number_column(table, info, "D")
    Fa_user = np.nan_to_num(_number_column(table, info, "Fa"), nan=0.0)
    f2_user = _number_column(table, info, "f2")
    status = result["status"].to_numpy()
    M2 = result[headers["M2"]].to_numpy(dtype=float)

    n_rows = len(out)
    f2_helper = np.full(n_rows, np.nan)
    load_text: list[str | None] = [None] * n_rows
    plans: dict[int, tuple] = {}
    for i in range(n_rows):
        if status[i] == "error":
            continue
        resolved = _resolved(designation[i], types[i], series[i])
        entry = resolved.entry
        rule = (entry.p1_single if arrangement[i] == "single" else entry.p1_paired) if entry.m1_load == "P1" else None
        bore = resolved.designation.bore if resolved.designation is not None else None
        d_cat = d_user[i] * factors["d"] if not np.isnan(d_user[i]) else float(bore)
        dM = (d_cat + D_user[i] * factors["D"]) / 2.0
        Fa_cat = Fa_user[i] * factors["Fa"]
        if resolved.takes_axial_m2 and Fa_cat > 0:
            f2_helper[i] = f2_user[i] if not np.isnan(f2_user[i]) else M2[i] / (Fa_cat * dM)
        else:
            f2_helper[i] = 0.0
        if rule:
            load_text[i] = f"P1: {friction.P1_RULES[rule][1]} (P1 >= Fr)"
        else:
            load_text[i] = entry.m1_load
        plans[i] = (entry.m1_load if not rule else "P1", rule, not np.isnan(d_user[i]), d_cat)

    position = list(out.columns).index(headers["f1"]) + 1
    out.insert(position, "f2", f2_helper)
    out.insert(position + 1, "M1 load", pd.Series(load_text, dtype=object, index=out.index))
    letter = {header: get_column_letter(k) for k, header in enumerate(out.columns, start=1)}

    def ref(name: str, row: int, literal: str = "0") -> str:
        header = info.headers.get(name)
        if header is None:
            return literal
        cell = f"{info.sheet_ref}!{info.letters[header]}{row}"
        factor = factors[name]
        return cell if factor == 1.0 else f"({cell}*{excel_number(factor)})"

    formulas: dict[tuple[str, int], str] = {}
    for i, (load_kind, rule, d_in_sheet, d_cat) in plans.items():
        model_name = models[i] or DEFAULT_MODEL
        templates = get_model(model_name).excel_formulas
        if templates is None:
            raise ExcelError(f"--formulas: the friction model {model_name!r} of row {info.rows[i]} has no Excel "
                             "formulas; run calc without --formulas")
        source_row = info.rows[i]
        row = i + 3
        n = ref("n", source_row)
        Fr, Fa = ref("Fr", source_row), ref("Fa", source_row)
        d = ref("d", source_row) if d_in_sheet else excel_number(d_cat)
        cells = {name: f"{letter[headers[name]]}{row}" for name in ("f0", "f1", "P1", "M0", "M1", "M2", "MR")}
        values = dict(cells, f2=f"{letter['f2']}{row}", n=n, nu=ref("nu", source_row), Fr=Fr, Fa=Fa,
                      dM=f"(({d}+{ref('D', source_row)})/2)", bearings="2*" if arrangement[i] == "paired" else "")
        if rule:
            values["p1_rule"] = P1_EXCEL[rule].format(Fr=Fr, Fa=Fa, Y=ref("Y", source_row, "NA()"),
                                                      e=ref("e", source_row, "NA()"))
            formulas[(headers["P1"], i)] = templates["P1"].format(**values)
            values["load"] = cells["P1"]
        else:
            values["load"] = Fa if load_kind == "Fa" else Fr
        for name in ("M0", "M1", "M2", "MR", "NR"):
            formulas[(headers[name], i)] = templates[name].format(**values)
    return out, formulas
