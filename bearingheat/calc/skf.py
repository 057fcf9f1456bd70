"""The SKF four-component friction model over support arrays: checks, then the kernels.

The model's evaluation for the friction-model registry (:mod:`bearingheat.calc.models`):
constants come from :mod:`bearingheat.catalogue.skf`, the formulas from
:mod:`bearingheat.kernels.skf`; this module holds the checks, the choice of
constants per row (lubrication, oil level, seals, edition) and the order in
which the kernels are applied, and no formula of its own.

The inputs the catalogue model does not have are read from ``extra``, a
mapping of column name to a per-row array or one value for all rows
(:data:`EXTRA_INPUTS` lists them with unit, meaning and default). The
designation, type, series and lubrication are read from ``extra`` too:
:class:`~bearingheat.calc.supports.SupportArrays` keeps only what the
catalogue model resolved from them.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from bearingheat.calc import contract
from bearingheat.calc.messages import Labels, Problem, at, bearing_load
from bearingheat.calc.supports import SupportArrays, distinct_keys, number_column, per_distinct, text_codes, \
    object_column, text_or_default, value_codes
from bearingheat.catalogue import skf as catalogue
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.catalogue.vm_chart import VMChart
from bearingheat.errors import BearingheatError
from bearingheat.kernels import skf

__all__ = ["RESULTS", "EXTRA_INPUTS", "evaluate_skf_model", "skf_bearing_keys", "fill_vm_from_chart"]

#: the results of the SKF model, in the order calc writes them (catalogue units)
RESULTS = ("G_rr", "G_sl", "M_rr", "M_sl", "M_seal", "M_drag", "phi_ish", "phi_rs", "phi_bl", "mu_sl", "M_start",
           "MR", "NR")

#: the default of each input read from ``extra`` where its cell is blank or its column absent
_DEFAULTS = {
    "designation": "none", "type": "none", "series": "none", "lubrication": "required", "oil": "mineral",
    "mu_sl": "φbl·μbl + (1 − φbl)·μEHL", "mu_bl": "0.15", "oil_level": "required in an oil bath",
    "VM": "required in an oil bath", "skf_edition": "10000", "seal": "from the designation suffix",
    "seals": "from the designation (2RSH: 2), else 2 where seal is given", "d_s": "required for contact seals",
    "Dw": "none: H < (D − d)/4 counts as low", "T": "required for tapered roller bearings",
    "arrangement": "single; paired: the pair's moments, each bearing at Fr/2 (Fa = 0 only)",
}
#: inputs read from ``extra``: name -> (unit, meaning, default); unit and meaning from the column contract
EXTRA_INPUTS = {name: (contract.column(name).unit, contract.column(name).meaning, default)
                for name, default in _DEFAULTS.items()}

_DRAG_SOURCE = {
    "6000": "SKF 6000 diagram 2 (p. 99; red curve ball bearings, blue roller bearings)",
    "10000": "SKF 10000/3 diagram 4 (p. 112)",
}
#: None as a 0-d object array: np.equal(texts, _NONE) marks the blank cells of a text column
_NONE = np.array(None, dtype=object)
_OIL = ("oil_mist", "oil_bath", "circulating_oil")  # oil-air, oil bath, oil jet (10000/3 p. 100)
_CONSTANTS = ("R1", "R2", "R3", "R4", "S1", "S2", "S3", "S4", "S5", "Kz", "KL", "irw", "mu_EHL_type", "bore",
              "start_factor", "no_axial")
_TEXTS = ("bearing_type", "series", "family", "label", "prefix", "seal", "unknown_contact_seal")


class _Extra:
    """The extra inputs: per-row arrays or one value for all rows."""

    def __init__(self, extra: dict | None, size: int):
        self.values = dict(extra or {})
        self.size = size

    def text(self, name: str, upper: bool = False):
        """One stripped string (or None) for all rows, or an object array of them."""
        value = self.values.get(name)
        if value is None or np.ndim(value) == 0:
            return _clean(value, upper)
        # each distinct text cleaned once (calc's text columns are categoricals: their categories)
        return per_distinct(pd.Series(value, copy=False), lambda v: _clean(v, upper))

    def number(self, name: str) -> np.ndarray:
        value = self.values.get(name, math.nan)
        if value is None:
            value = math.nan
        if np.ndim(value) == 0:
            return np.full(self.size, _to_float(value))
        if isinstance(value, np.ndarray) and value.dtype == np.float64:  # calc's numbers (number_column)
            return value
        return pd.to_numeric(pd.Series(list(value)), errors="coerce").to_numpy(dtype=float)


def _clean(value, upper):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return None
    if isinstance(value, (float, np.floating)) and float(value).is_integer():
        value = int(value)  # 6000.0 from a numeric column -> '6000'
    text = str(value).strip()
    if not text:
        return None
    return text.upper() if upper else text


def _to_float(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def _per_row(value, size):
    return np.broadcast_to(np.asarray(value, dtype=object), (size,))


def _choice(x: _Extra, name: str, default: str):
    """A text input with its default where blank: one string for all rows, or an object array."""
    value = x.text(name)
    if np.ndim(value) == 0:
        return default if value is None else value
    return np.where(np.equal(value, _NONE), default, value)


#: the recommended minimum load per basic dynamic load rating C (SKF 6000 p. 75), by rolling element
_MINIMUM_LOAD_SHARE = {"ball": 0.01, "roller": 0.02}


def _minimum_load_warnings(add, labels: Labels, rows: np.ndarray, ball: np.ndarray, C: np.ndarray, Fr: np.ndarray,
                           Fa: np.ndarray, bearings: np.ndarray) -> None:
    """Warnings where a bearing's load is below the recommended minimum load, 0.01 C of ball and 0.02 C of roller
    bearings (SKF 6000 p. 75), under which the model does not hold (p. 89). A bearing's load is the larger of its
    radial load (Fr/2 on each bearing of a pair) and the axial load; with C unknown only a bearing without any
    load is warned of."""
    ball = np.broadcast_to(ball, Fr.shape)  # (one bearing's type for all its points)
    share = np.where(ball, _MINIMUM_LOAD_SHARE["ball"], _MINIMUM_LOAD_SHARE["roller"])
    below = rows & (np.maximum(Fr / bearings, Fa) < share * C)

    def light(i):
        column, load = bearing_load(labels, i, Fr[i], Fa[i], bearings[i])
        kind = "ball" if ball[i] else "roller"
        return (f"{load} is below the recommended minimum load "
                f"{labels.value(column, share[i] * C[i])} = {share[i]:g} C of a {kind} bearing (C = {C[i]:g} N, SKF "
                "6000 p. 75); the SKF model holds at loads at or above it (p. 89), and below it the rolling elements "
                "may skid")
    add(below, "warning", light)
    add(rows & np.isnan(C) & (Fr <= 0) & (Fa <= 0), "warning",
        lambda i: f"{labels.name('Fr', i)}: 0 and {labels.name('Fa', i)}: 0: without load the SKF model's rolling and "
                  "sliding moments are 0, but it holds only at loads at or above the recommended minimum load, 0.01 C "
                  "of ball and 0.02 C of roller bearings (SKF 6000 pp. 75 and 89); give C to check a light load too")


def _mapped(values, table: dict) -> np.ndarray | float:
    """table[value] per row (NaN for values not in the table)."""
    if np.ndim(values) == 0:
        return table.get(values, math.nan)
    return pd.Series(values, dtype=object).map(table).to_numpy(dtype=float)


def _each(values, mask) -> list:
    """The distinct values of the rows in ``mask`` (one value shared by all rows, or an array)."""
    if np.ndim(values) == 0:
        return [values] if np.any(mask) else []
    return sorted(set(np.asarray(values)[mask].tolist()))


def _resolve(x: _Extra, supports: SupportArrays, size: int):
    """SKF constants per row (arrays, or scalars for one bearing) and the resolution errors per row."""
    designation, bearing_type, series = x.text("designation"), x.text("type"), x.text("series")
    plain = np.broadcast_to(supports.plain, (size,))
    if all(np.ndim(v) == 0 for v in (designation, bearing_type, series)) and not plain.any():
        one = _constants_of(designation, bearing_type, series)
        return {k: one[k] for k in (*_CONSTANTS, *_TEXTS, "seals", "error")}, False
    codes, uniques = distinct_keys([value_codes(_per_row(v, size)) for v in (designation, bearing_type, series)]
                                   + [value_codes(plain)])
    per_key = [_constants_of(*key[:3]) if not key[3] else _blank("") for key in uniques]
    out = {}
    for name in (*_CONSTANTS, "seals"):
        out[name] = np.array([c[name] for c in per_key], dtype=float)[codes]
    for name in (*_TEXTS, "error"):
        out[name] = np.array([c[name] for c in per_key], dtype=object)[codes]
    return out, True


def _blank(error: str) -> dict:
    return {**{k: math.nan for k in (*_CONSTANTS, "seals")}, **{k: "" for k in _TEXTS}, "error": error}


def _constants_of(designation, bearing_type, series) -> dict:
    try:
        b = catalogue.skf_bearing(designation, bearing_type, series)
    except BearingheatError as exc:
        return _blank(str(exc))
    out = {k: getattr(b, k) for k in _CONSTANTS}
    out.update(bearing_type=b.bearing_type, series=b.series, family=b.family, label=b.label, prefix=b.prefix,
               seal=b.seal or "",
               unknown_contact_seal=b.unknown_contact_seal,
               seals=math.nan if b.seals is None else float(b.seals), error="")
    return out


def skf_bearing_keys(supports: SupportArrays):
    """The type and the series row of the SKF tables of every row (one pair of texts for one bearing, else
    arrays); '' where the bearing does not resolve. ``supports.extra`` holds the designation, type and series."""
    c, _ = _resolve(_Extra(supports.extra, supports.size), supports, supports.size)
    return c["bearing_type"], c["series"]


def evaluate_skf_model(supports: SupportArrays, labels: Labels, f2_chart: F2Chart | None = None,
                       extra: dict | None = None):
    """The SKF model (SKF 6000 pp. 87-105; 10000/3 pp. 97-114) on support arrays: checks, then the kernels.

    ``supports`` gives d, D, B, C0, Y, n, nu, Fr, Fa; ``extra`` the inputs of
    :data:`EXTRA_INPUTS`. ``f2_chart`` is not used (the catalogue model's
    chart). Returns (results, problems): every result of :data:`RESULTS`
    is an array of the rows' length in catalogue units (N·mm, W); problems
    name the rows that fail a check, the column and the expected value.
    """
    s = supports
    size = len(s.n)
    shape = (size,)
    x = _Extra(extra, size)
    problems: list[Problem] = []

    def add(mask, level, message, column=""):
        mask = np.broadcast_to(np.asarray(mask, dtype=bool), shape)
        if mask.any():
            problems.append(Problem(mask, level, message, column))

    def row(values):
        return np.broadcast_to(np.asarray(values, dtype=float), shape)

    c, many = _resolve(x, s, size)
    text = {k: c[k] for k in (*_TEXTS, "error")}
    unresolved = np.broadcast_to(np.not_equal(text["error"], ""), shape)
    add(unresolved, "error", lambda i: at(text["error"], i))
    ok = ~unresolved & ~np.broadcast_to(s.plain, shape)

    def label(i):
        return at(text["label"], i)

    def value_of(col, values, i):
        return labels.value(col, at(values, i))

    def missing(col, why, mask):
        add(mask & ok, "error", lambda i, col=col: f"{labels.name(col, i)}: missing; {why(i)}", col)

    def bad(col, values, condition, mask):
        add(mask & ok, "error",
            lambda i, col=col: f"{labels.name(col, i)}: {value_of(col, values, i)} {condition}")

    # --- geometry and operating point (6000 p. 90; 10000/3 p. 100)
    d = np.where(np.isnan(row(s.d)), row(c["bore"]), row(s.d))
    D, n, nu, Fr, Fa = row(s.D), row(s.n), row(s.nu), row(s.Fr), row(s.Fa)
    missing("d", lambda i: "the bore d gives dm = 0.5 (d + D) (SKF 6000 p. 90)", np.isnan(d))
    bad("d", d, "must be > 0", d <= 0)
    missing("D", lambda i: "the outside diameter D gives dm = 0.5 (d + D) (SKF 6000 p. 90)", np.isnan(D))
    add(ok & (D <= d), "error", lambda i: f"{labels.name('D', i)}: {labels.value('D', D[i])} must be larger than "
                                          f"{labels.name('d', i)} = {labels.value('d', d[i])}")
    missing("n", lambda i: "the operating speed is needed", np.isnan(n))
    bad("n", n, "must be >= 0 (speed magnitude)", n < 0)
    missing("nu", lambda i: "the operating viscosity (base oil viscosity for grease) is needed", np.isnan(nu))
    bad("nu", nu, "must be > 0", nu <= 0)
    bad("Fr", Fr, "must be >= 0", Fr < 0)
    bad("Fa", Fa, "must be >= 0", Fa < 0)
    # --- a pair (X or O arrangement): the model is of one bearing; the pair's moment is the sum of its bearings',
    # each at half the radial load; how a pair shares an axial load the model does not say
    arrangement = _choice(x, "arrangement", contract.ARRANGEMENTS[0])
    add(ok & ~np.isin(arrangement, contract.ARRANGEMENTS), "error",
        lambda i: f"{labels.name('arrangement', i)}: {at(arrangement, i)!r} is not one of "
                  f"{', '.join(contract.ARRANGEMENTS)}")
    paired = np.equal(arrangement, "paired")
    add(ok & paired & (Fa > 0), "error",
        lambda i: f"{labels.name('Fa', i)}: {labels.value('Fa', Fa[i])} on a pair: how a pair shares an axial load "
                  "depends on its arrangement and preload, which the SKF model does not cover; give the two bearings "
                  "as two rows, each with the loads it carries, or use the catalogue model (model = schaeffler)")
    bearings = row(np.where(paired, 2.0, 1.0))
    Fr_bearing = Fr / bearings
    family = text["family"]
    bearing_type = text["bearing_type"]
    C0, Y = row(s.C0), row(s.Y)
    missing("C0", lambda i: "the axial load of a deep groove ball bearing needs C0 for αF = 24.6·(Fa/C0)^0.24 "
                            "(SKF 6000 p. 91, table 2a)",
            np.equal(family, "deep_groove_ball") & (Fa > 0) & np.isnan(C0))
    bad("C0", C0, "must be > 0", C0 <= 0)
    missing("Y", lambda i: "the axial load of a tapered roller bearing needs its catalogue factor Y "
                           "(SKF 6000 p. 91, table 2a)", np.equal(family, "tapered_roller") & (Fa > 0) & np.isnan(Y))
    bad("Y", Y, "must be > 0", Y <= 0)
    thrust_only_fa = np.isin(family, ("thrust_ball", "thrust_cylindrical_roller"))
    carb = np.equal(family, "carb")
    add(ok & thrust_only_fa & (Fr > 0), "warning",
        lambda i: f"{labels.name('Fr', i)}: {labels.value('Fr', Fr[i])} on a {label(i)}: its formulas "
                  "(SKF 6000 p. 92, table 2b) use Fa only")
    add(ok & (row(c["no_axial"]) > 0) & (Fa > 0), "error",
        lambda i: f"{labels.name('Fa', i)}: {labels.value('Fa', Fa[i])} on {at(text['prefix'], i)} {label(i)}: one "
                  "ring has no ribs, the bearing takes no axial load (the term S1·dm^0.9·Fa of Gsl is the sliding at "
                  "the ribs; SKF 6000 p. 91, table 2a)")
    add(ok & carb & (Fa > 0), "warning",
        lambda i: f"{labels.name('Fa', i)}: {labels.value('Fa', Fa[i])} on a {label(i)}: CARB bearings take no "
                  "axial load; their formulas (SKF 6000 p. 91, table 2a) use Fr only")
    C = x.number("C")
    bad("C", C, "must be > 0", C <= 0)
    _minimum_load_warnings(add, labels, ok & ~(C <= 0), np.isin(bearing_type, tuple(catalogue.BALL_TYPES)), C, Fr,
                           Fa, bearings)

    # --- lubrication, oil, sliding coefficients (6000 pp. 98-101; 10000/3 pp. 102-103)
    lubrication = x.text("lubrication")
    known_lub = np.isin(lubrication, catalogue.LUBRICATIONS)
    add(ok & np.equal(lubrication, _NONE), "error",
        lambda i: f"{labels.name('lubrication', i)}: missing; expected one of {', '.join(catalogue.LUBRICATIONS)}")
    add(ok & ~known_lub & np.not_equal(lubrication, _NONE), "error",
        lambda i: f"{labels.name('lubrication', i)}: {at(lubrication, i)!r} is not one of "
                  f"{', '.join(catalogue.LUBRICATIONS)}")
    oil = _choice(x, "oil", catalogue.DEFAULT_OIL)
    add(ok & ~np.isin(oil, catalogue.OILS), "error",
        lambda i: f"{labels.name('oil', i)}: {at(oil, i)!r} is not one of {', '.join(catalogue.OILS)}")
    mu_sl_given, mu_bl = x.number("mu_sl"), x.number("mu_bl")
    bad("mu_sl", mu_sl_given, "must be >= 0", mu_sl_given < 0)
    bad("mu_bl", mu_bl, "must be >= 0", mu_bl < 0)
    mu_bl = np.where(np.isnan(mu_bl), catalogue.mu_bl_default(), mu_bl)
    mu_ehl_type = row(c["mu_EHL_type"])
    mu_ehl = np.where(np.isnan(mu_ehl_type), _mapped(oil, {o: catalogue.mu_ehl(o) for o in catalogue.OILS}),
                      mu_ehl_type)
    oil_lubricated = np.isin(lubrication, _OIL)
    add(ok & oil_lubricated & ((nu < 2) | (nu > 500)), "warning",
        lambda i: f"{labels.name('nu', i)}: {labels.value('nu', nu[i])} is outside 2 to 500 mm²/s, the range of "
                  "the SKF model for oil lubrication (SKF 10000/3 p. 100)")

    # --- oil level, low or high (φrs), drag inputs
    H, VM, Dw = x.number("oil_level"), x.number("VM"), x.number("Dw")
    bath = np.equal(lubrication, "oil_bath")
    jet_drag = np.equal(lubrication, "circulating_oil") & ~np.isnan(VM)
    drag_rows = ok & (bath | jet_drag)
    missing("oil_level", lambda i: "an oil bath needs the oil level H [mm] above the lowest contact point of the "
                                   "outer ring raceway (SKF 10000/3 p. 110, fig. 2)", bath & np.isnan(H))
    missing("oil_level", lambda i: "the drag of oil jet lubrication is the oil-bath drag at H = half the diameter "
                                   "of the lowest rolling element, doubled (SKF 6000 p. 100; 10000/3 p. 112): give "
                                   "that H", jet_drag & np.isnan(H))
    bad("oil_level", H, "must be >= 0", H < 0)
    bad("Dw", Dw, "must be > 0", Dw <= 0)
    add(ok & (Dw >= 0.5 * (D - d)), "error",
        lambda i: f"{labels.name('Dw', i)}: {labels.value('Dw', float(Dw[i]))} must be smaller than (D - d)/2 = "
                  f"{labels.value('Dw', 0.5 * (D[i] - d[i]))}, the section between bore and outside diameter")
    bad("VM", VM, "must be >= 0", VM < 0)
    edition = _choice(x, "skf_edition", catalogue.DEFAULT_EDITION)
    known_edition = np.isin(edition, catalogue.EDITIONS)
    add(ok & ~known_edition, "error",
        lambda i: f"{labels.name('skf_edition', i)}: {at(edition, i)!r} is not one of "
                  f"{', '.join(catalogue.EDITIONS)}")
    dm = 0.5 * (d + D)
    H_over_dm = H / dm

    def at_level(i):
        """' at H/dm = 0.0417' where the level and dm are known (their own messages say where not)."""
        return f" at H/dm = {H_over_dm[i]:.3g}" if np.isfinite(H_over_dm[i]) else ""

    missing("VM", lambda i: f"an oil bath needs the drag loss factor VM: read it off "
                            f"{_DRAG_SOURCE.get(at(edition, i), _DRAG_SOURCE['10000'])} for "
                            f"{'ball' if at(bearing_type, i) in catalogue.BALL_TYPES else 'roller'} bearings"
                            f"{at_level(i)}, or digitise the diagram (calc --vm-chart)",
            bath & np.isnan(VM) & known_edition)
    add(ok & ~np.isin(lubrication, ("oil_bath", "circulating_oil")) & ~np.isnan(VM), "warning",
        lambda i: f"{labels.name('VM', i)}: ignored; there is drag only in an oil bath or with oil jet")
    low_level = np.where(np.isnan(Dw), H < 0.25 * (D - d), H < 0.5 * Dw)
    K_rs = _mapped(lubrication, {v: catalogue.k_rs(v) for v in catalogue.LUBRICATIONS})
    K_rs = np.where(bath & ~low_level, 0.0, K_rs)   # above the centre of the lowest rolling element: φrs = 1

    # --- G variables per row of table 2 (one call per formula family)
    G_rr, G_sl, G_sl_start = (np.full(shape, np.nan) for _ in range(3))
    consts = {k: c[k] for k in ("R1", "R2", "R3", "R4", "S1", "S2", "S3", "S4", "S5")}
    for fam in _each(family, ok):
        rows = np.flatnonzero(ok & np.equal(family, fam))
        sub = {k: (v[rows] if many else v) for k, v in consts.items()}
        with np.errstate(all="ignore"):
            Grr, Gsl = skf.rolling_sliding_variables(fam, sub, dm[rows], Fr_bearing[rows], Fa[rows], n[rows],
                                                     nu[rows], C0[rows], Y[rows])
            G_rr[rows], G_sl[rows] = Grr, Gsl
            G_sl_start[rows] = (skf.rolling_sliding_variables(fam, sub, dm[rows], Fr_bearing[rows], Fa[rows],
                                                              0.0 * n[rows], nu[rows], C0[rows], Y[rows])[1]
                                if fam in skf.SPEED_DEPENDENT_GSL else Gsl)

    # --- seals (6000 p. 90, table 4 p. 96; 10000/3 p. 109)
    d_s = x.number("d_s")
    add(ok & (d_s > 0) & ((d_s <= d) | (d_s >= D)), "error",
        lambda i: f"{labels.name('d_s', i)}: {value_of('d_s', d_s, i)} must lie between {labels.name('d', i)} = "
                  f"{labels.value('d', d[i])} and {labels.name('D', i)} = {labels.value('D', D[i])}: the seal "
                  "counterface diameter is d1, d2 or E of the bearing tables (SKF 6000 table 4, p. 96)")
    M_seal = _seal_torques(x, text, ok, D, row(c["seals"]), labels, add, shape)

    # --- drag (6000 p. 99; 10000/3 pp. 110-112)
    M_drag = np.zeros(shape)
    if drag_rows.any():
        M_drag = _drag_torques(s, x, c, text, drag_rows, edition, d, D, dm, n, nu, H, VM, jet_drag, labels, add,
                               shape)

    # --- the four components
    Kz = row(c["Kz"])
    with np.errstate(all="ignore"):
        phi_ish = skf.inlet_shear_heating_factor(n, nu, dm)
        phi_rs = skf.kinematic_replenishment_factor(K_rs, Kz, nu, n, d, D)
        phi_bl = skf.boundary_weighting_factor(n, nu, dm)
        mu_sl = np.where(np.isnan(mu_sl_given), skf.sliding_coefficient(phi_bl, mu_bl, mu_ehl), mu_sl_given)
        M_rr = skf.rolling_torque(G_rr, nu, n)
        M_sl = skf.sliding_torque(G_sl, mu_sl)
        MR = skf.total_torque(phi_ish, phi_rs, M_rr, M_sl, M_seal, M_drag)
        M_start = skf.starting_torque(skf.sliding_torque(G_sl_start, mu_bl), M_seal)
        NR = skf.power_loss(MR, n)
    start_factor = row(c["start_factor"])
    add(ok & (start_factor > 1), "warning",
        lambda i: f"M_start of a {label(i)} may be up to {start_factor[i]:g} times Msl + Mseal "
                  "(SKF 6000 p. 103; 10000/3 p. 114)")
    # the moments and the power of both bearings of a pair; G, φ and μsl stay those of one bearing
    results = {"G_rr": G_rr, "G_sl": G_sl, "M_rr": bearings * M_rr, "M_sl": bearings * M_sl,
               "M_seal": bearings * M_seal, "M_drag": bearings * M_drag, "phi_ish": phi_ish, "phi_rs": phi_rs,
               "phi_bl": phi_bl, "mu_sl": mu_sl, "M_start": bearings * M_start, "MR": bearings * MR,
               "NR": bearings * NR}
    return {k: np.broadcast_to(np.asarray(v, dtype=float), shape) for k, v in results.items()}, problems


def _seal_torques(x, text, ok, D, seals_designation, labels, add, shape):
    """Mseal per row from the seal type, the count and d_s; rows without a seal get 0."""
    size = shape[0]
    seal_given = x.text("seal", upper=True)
    seals = x.number("seals")
    given_count = ~np.isnan(seals)
    M_seal = np.zeros(shape)
    unknown = text["unknown_contact_seal"]
    if (np.ndim(seal_given) == 0 and seal_given is None and np.ndim(text["seal"]) == 0 and not text["seal"]
            and not given_count.any() and np.ndim(unknown) == 0 and not unknown):
        return M_seal  # no seal anywhere: the common case of a table of open bearings
    seal_given = _per_row(seal_given, size)
    seal = np.where(np.equal(seal_given, _NONE), _per_row(text["seal"], size), seal_given)
    seal = np.where(seal == "", None, seal)
    seals = np.where(given_count, seals, np.where(~np.isnan(seals_designation), seals_designation,
                                                  np.where(np.equal(seal, _NONE), 0.0, 2.0)))
    d_s = x.number("d_s")
    add(ok & given_count & ~np.isin(seals, (0.0, 1.0, 2.0)), "error",
        lambda i: f"{labels.name('seals', i)}: {labels.value('seals', seals[i])} must be 0, 1 or 2")
    add(ok & (d_s <= 0), "error", lambda i: f"{labels.name('d_s', i)}: {labels.value('d_s', d_s[i])} must be > 0")
    add(ok & np.not_equal(unknown, "") & np.equal(seal_given, _NONE) & ~given_count, "error",
        lambda i: f"{labels.name('seal', i)}: missing; the designation's contact seal {at(unknown, i)!r} is not a "
                  f"seal type of SKF table 4 (6000 p. 96); give seal as one of {', '.join(catalogue.SEAL_TYPES)}, "
                  "or seals = 0 to leave the seal friction out")
    add(ok & np.equal(seal, _NONE) & given_count & (seals > 0), "error",
        lambda i: f"{labels.name('seal', i)}: missing; {labels.name('seals', i)} = {seals[i]:g} needs the seal type, "
                  f"one of {', '.join(catalogue.SEAL_TYPES)} (SKF 6000 table 4, p. 96)")
    sealed = ok & np.not_equal(seal, _NONE) & (seals > 0)
    if not sealed.any():
        return M_seal
    types = _per_row(text["bearing_type"], size)

    def label(i):
        return at(text["label"], i)

    for seal_type, bearing_type in sorted(set(zip(seal[sealed].tolist(), types[sealed].tolist()))):
        rows = np.flatnonzero(sealed & (seal == seal_type) & (types == bearing_type))
        mask = np.zeros(shape, dtype=bool)
        mask[rows] = True
        if seal_type not in catalogue.SEAL_TYPES:
            add(mask, "error", lambda i, v=seal_type: f"{labels.name('seal', i)}: {v!r} is not a seal type of SKF "
                                                      f"table 4; expected one of {', '.join(catalogue.SEAL_TYPES)}")
            continue
        table_rows = catalogue.seal_rows(seal_type, bearing_type)
        if not table_rows:
            offered = sorted(_types_with(seal_type))
            add(mask, "error", lambda i, v=seal_type, o=offered: (
                f"{labels.name('seal', i)}: {v} on a {label(i)}: SKF table 4 (6000 p. 96) has {v} seals only for "
                f"{', '.join(o)}"))
            continue
        found = catalogue.seal_lookup(seal_type, bearing_type, D[rows])
        outside = np.zeros(shape, dtype=bool)
        outside[rows[~found["found"] & ~np.isnan(D[rows])]] = True   # a missing D has its own message
        ranges = "; ".join(r.range_text for r in table_rows)
        add(outside, "error", lambda i, v=seal_type, ranges=ranges: (
            f"{labels.name('D', i)}: {labels.value('D', D[i])} is outside SKF table 4 (6000 p. 96) for {v} seals "
            f"on a {label(i)} ({ranges})"))
        needs_ds = np.zeros(shape, dtype=bool)
        needs_ds[rows] = (found["KS1"] > 0) & np.isnan(d_s[rows])
        dimension = table_rows[0].d_s_dimension
        add(needs_ds, "error", lambda i, v=seal_type, dim=dimension: (
            f"{labels.name('d_s', i)}: missing; {v} seals need the seal counterface diameter d_s ({dim} in the "
            f"bearing tables; SKF 6000 table 4, p. 96)"))
        with np.errstate(all="ignore"):
            torque = skf.seal_torque(found["KS1"], d_s[rows], found["beta"], found["KS2"])
            M_seal[rows] = skf.seal_count_factor(seals[rows], found["one_seal_factor"]) * torque
    return M_seal


def _types_with(seal_type: str) -> set[str]:
    return {catalogue.SKF_TYPES[t] for t in catalogue.SKF_TYPES if catalogue.seal_rows(seal_type, t)}


def _drag_torques(s, x, c, text, rows_mask, edition, d, D, dm, n, nu, H, VM, jet, labels, add, shape):
    """Mdrag per row of an oil bath (or oil jet with VM) by the edition's formula; checks of its inputs."""
    bearing_type = text["bearing_type"]
    ball = np.isin(bearing_type, tuple(catalogue.BALL_TYPES))
    tapered = np.equal(bearing_type, "tapered_roller")

    def label(i):
        return at(text["label"], i)

    B = np.broadcast_to(np.asarray(s.B, dtype=float), shape)
    T = x.number("T")
    e6000 = np.equal(edition, "6000")
    e10000 = np.equal(edition, "10000")
    roller = rows_mask & ~ball
    add(roller & e6000 & np.isnan(B), "error",
        lambda i: f"{labels.name('B', i)}: missing; the drag 10·VM·Kroll·B·dm⁴·n² of a {label(i)} needs the inner "
                  "ring width B (SKF 6000 p. 99)")
    add(roller & e10000 & ~tapered & np.isnan(B), "error",
        lambda i: f"{labels.name('B', i)}: missing; the drag of a {label(i)} needs the bearing width B (the height "
                  "of a thrust bearing; SKF 10000/3 p. 111)")
    add(roller & e10000 & tapered & np.isnan(T), "error",
        lambda i: f"{labels.name('T', i)}: missing; the drag of a tapered roller bearing needs the total width T "
                  "(SKF 10000/3 p. 111)")
    for col, values in (("B", B), ("T", T)):
        add(rows_mask & (values <= 0), "error",
            lambda i, col=col, values=values: f"{labels.name(col, i)}: {labels.value(col, values[i])} must be > 0")
    limit = skf.drag_viscosity_limit(H, D)
    add(rows_mask & e10000 & (nu > limit), "error",
        lambda i: f"{labels.name('nu', i)}: {labels.value('nu', nu[i])} is above {limit[i]:g} mm²/s, the limit of "
                  f"the SKF 10000/3 drag formula for an oil level H {'<=' if H[i] <= 0.5 * D[i] else '>'} D/2 "
                  "(p. 110); use skf_edition 6000 or a thinner oil")
    Kz = np.broadcast_to(np.asarray(c["Kz"], dtype=float), shape)
    KL = np.broadcast_to(np.asarray(c["KL"], dtype=float), shape)
    irw = np.broadcast_to(np.asarray(c["irw"], dtype=float), shape)
    width = np.where(tapered & e10000, T, B)
    with np.errstate(all="ignore"):
        K_ball = skf.ball_drag_constant(irw, Kz, d, D)
        K_roll = skf.roller_drag_constant(KL, Kz, d, D)
        old = np.where(ball, skf.drag_torque_ball_6000(VM, K_ball, dm, n),
                       skf.drag_torque_roller_6000(VM, K_roll, width, dm, n))
        new = np.where(ball, skf.drag_torque_ball_10000(VM, K_ball, dm, n, nu, H, Kz, d, D),
                       skf.drag_torque_roller_10000(VM, K_roll, width, dm, n, nu, H, Kz, KL, d, D))
    drag = np.where(e6000, old, new) * np.where(jet, 2.0, 1.0)
    return np.where(rows_mask, drag, 0.0)


def fill_vm_from_chart(frame: pd.DataFrame, chart: VMChart, skf_rows: np.ndarray
                       ) -> tuple[pd.DataFrame, list[tuple[int, str, str]], np.ndarray]:
    """A blank VM of every oil-bath row of the SKF model read off the user's digitised chart at H/dm.

    ``frame`` holds calc's inputs (contract names, catalogue units) after the
    bearing table's fill, ``skf_rows`` marks the rows the SKF model computes.
    A row is read where its lubrication is ``oil_bath``, VM is blank and the
    oil level H, d and D are given, on the curve of its edition
    (``skf_edition``, default 10000) and kind (ball or roller bearing, from
    the SKF tables); other rows are left to the model's own checks. Returns
    (frame with VM filled, (row position, 'error', message) where the chart
    refuses the level, VM read off the chart per row (NaN elsewhere)).
    """
    n_rows = len(frame)
    read = np.full(n_rows, np.nan)
    lubrication = text_or_default(frame, "lubrication", None)
    VM, H = number_column(frame, "VM"), number_column(frame, "oil_level")
    d, D = number_column(frame, "d"), number_column(frame, "D")
    rows = skf_rows & np.equal(lubrication, "oil_bath") & np.isnan(VM) & ~np.isnan(H) & ~np.isnan(d) & ~np.isnan(D)
    if not rows.any():
        return frame, [], read
    edition = per_distinct(frame["skf_edition"], lambda v: _clean(v, False) or catalogue.DEFAULT_EDITION) \
        if "skf_edition" in frame.columns else object_column(n_rows, catalogue.DEFAULT_EDITION)
    codes, distinct = distinct_keys([text_codes(frame, c) for c in ("designation", "type", "series")])
    kind = np.array([_kind(_constants_of(*key)) for key in distinct], dtype=object)[codes]
    rows &= (kind != "") & np.isin(edition, catalogue.EDITIONS)  # else the model's own message says why
    positions = np.flatnonzero(rows)
    values, reasons = chart.lookup(edition[positions], kind[positions], H[positions] / (0.5 * (d + D))[positions])
    read[positions] = values
    problems = [(int(i), "error", f"VM: not read off {chart.name}: {reason}; give VM")
                for i, reason in zip(positions.tolist(), reasons.tolist()) if reason]
    return frame.assign(VM=np.where(np.isnan(read), VM, read)), problems, read


def _kind(constants: dict) -> str:
    """'ball' or 'roller' for the curve of the VM diagram; '' where the bearing did not resolve."""
    if constants["error"] or not constants["bearing_type"]:
        return ""
    return "ball" if constants["bearing_type"] in catalogue.BALL_TYPES else "roller"
