"""Choosing a bearing for a shaft seat: the candidates of the bearing table ranked at an operating point.

:func:`rank_bearings` computes each candidate of
:func:`~bearingheat.api.bearings.bearings_with_bore` with ``calc`` from its
designation at one operating point (pint Quantities) and ranks them by power
loss, operating temperature or permissible speed; :func:`temperature_curves`
gives the operating temperature of the leading ones over a range of speeds
(``bearingheat select --plot`` draws it). The command line's ``bearingheat
select`` is these two functions.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np
import pandas as pd

from bearingheat.calc.contract import column, range_problems
from bearingheat.calc.models import DEFAULT_MODEL
from bearingheat.calc.table import calc
from bearingheat.calc.viscosity import viscosity_model_rows
from bearingheat.catalogue.bearings import table_header
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.catalogue.vm_chart import VMChart
from bearingheat.errors import SelectionError
from bearingheat.kernels.viscosity import DEFAULT_VISCOSITY_INDEX
from bearingheat.units import QuantityLike, celsius, magnitude

__all__ = ["rank_bearings", "temperature_curves", "candidate_table", "RANKINGS", "MARGIN", "CATALOGUE_SPEED"]

#: rank_by -> (the column ranked, whether the largest comes first)
RANKINGS = {"NR": ("NR [W]", False), "T_op": ("T_op [degC]", False), "n_per": ("n_per [1/min]", True)}
#: the column of the speed at which the bearing reaches T_bearing over the operating speed
MARGIN = "n_per/n"
#: the column of the catalogue's thermal reference speed (the contract's name for it: calc's own n_thr stands beside)
CATALOGUE_SPEED = column("n_thr_catalogue").name
#: the model's bounds of the operating point (the Schaeffler catalogue, p. 64): name -> (lowest, whether it counts)
_LOWEST = {"n": (0.0, True), "Fr": (0.0, True), "Fa": (0.0, True), "nu": (0.0, False), "oil_level": (0.0, True),
           "nu40": (0.0, False), "nu100": (0.0, False)}
#: the arguments that give the viscosity -> the way they give it (one way only): the operating viscosity, or the
#: oil's (calc takes ν at each bearing's T_op)
_VISCOSITY_SOURCE = {"nu": "nu", "iso_vg": "iso_vg", "nu40": "nu40 and nu100", "nu100": "nu40 and nu100"}
_ONE_VISCOSITY = ("the viscosity: give one of nu (the operating viscosity), iso_vg (the oil's grade, with VI) or nu40 "
                  "and nu100; got")


def _point_value(value: QuantityLike, name: str) -> float:
    """One operating-point Quantity in its column's catalogue unit, checked against the model's bounds and the
    column's valid range (:class:`SelectionError` naming the argument and the value)."""
    unit = column(name).unit
    converted = np.asarray(celsius(value, name) if unit == "degC" else magnitude(value, unit, name), dtype=float)
    if converted.ndim != 0:
        raise SelectionError(f"{name}: give one value (one operating point); got {converted.size} values")
    number, typed = float(converted), f"{value.magnitude:g} {value.units:~P}"
    lowest, inclusive = _LOWEST.get(name, (-math.inf, True))
    if math.isnan(number) or number < lowest or (number == lowest and not inclusive):
        raise SelectionError(f"{name}: {typed} must be {'>=' if inclusive else '>'} 0")
    return _in_valid_range(number, name, typed)


def _in_valid_range(number: float, name: str, typed: str) -> float:
    """``number`` if it lies in its column's valid range, else :class:`SelectionError` naming ``typed``."""
    errors, _ = range_problems(name, np.array([number]), lambda i: f"{name}: {typed}")
    if errors:
        raise SelectionError(errors[0][1])
    return number


def candidate_table(candidates: pd.DataFrame) -> pd.DataFrame:
    """Rows of the bearing table with 'name [unit]' headers; its n_thr is named :data:`CATALOGUE_SPEED`."""
    headers = {name: table_header(name, CATALOGUE_SPEED if name == "n_thr" else None) for name in candidates.columns}
    return candidates.rename(columns=headers).reset_index(drop=True)


def _oil_columns(iso_vg: float | None, VI: float | None, nu40: QuantityLike | None, nu100: QuantityLike | None,
                 T_bearing: QuantityLike | None) -> dict[str, float]:
    """The oil's columns of calc (iso_vg and VI, or nu40 and nu100 in mm²/s), checked by calc's own check of oil
    data (:func:`~bearingheat.calc.viscosity.viscosity_model_rows`; :class:`SelectionError`); {} without an oil."""
    oil = {name: _point_value(value, name) for name, value in (("nu40", nu40), ("nu100", nu100)) if value is not None}
    oil.update({name: _plain_number(value, name) for name, value in (("iso_vg", iso_vg), ("VI", VI))
                if value is not None})
    if not oil:
        return {}
    _, _, problems = viscosity_model_rows(pd.DataFrame({name: [value] for name, value in oil.items()}))
    if problems:
        raise SelectionError(problems[0][2])
    if T_bearing is None:
        raise SelectionError(f"the oil's viscosity ({'iso_vg' if 'iso_vg' in oil else 'nu40 and nu100'}) is taken at "
                             "each bearing's temperature: give T_bearing, and T_amb to take it at the operating "
                             "temperature T_op")
    if "iso_vg" in oil:
        oil.setdefault("VI", DEFAULT_VISCOSITY_INDEX)  # (calc's default, written beside the results)
    return oil


def _plain_number(value: Any, name: str) -> float:
    """A plain number argument (an ISO VG grade, a viscosity index) as a float, or :class:`SelectionError`."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = math.nan
    if math.isnan(number):
        raise SelectionError(f"{name}: {value!r} is not a number")
    return _in_valid_range(number, name, f"{number:g}")


def rank_bearings(candidates: pd.DataFrame, *, lubrication: str, n: QuantityLike, nu: QuantityLike | None = None,
                  Fr: QuantityLike | None = None, Fa: QuantityLike | None = None, T_amb: QuantityLike | None = None,
                  T_bearing: QuantityLike | None = None, iso_vg: float | None = None, VI: float | None = None,
                  nu40: QuantityLike | None = None, nu100: QuantityLike | None = None,
                  oil_level: QuantityLike | None = None,
                  model: str = DEFAULT_MODEL, rank_by: str = "NR", f2_chart: F2Chart | str | None = None,
                  vm_chart: VMChart | str | None = None) -> pd.DataFrame:
    """The candidates computed at one operating point and ranked.

    Parameters
    ----------
    candidates : pandas.DataFrame
        Rows of the bearing table (:func:`~bearingheat.api.bearings.bearings_with_bore`).
    lubrication : str
        grease, oil_mist, oil_bath or circulating_oil.
    n : pint.Quantity
        Shaft speed (revolutions per time).
    nu : pint.Quantity, optional
        Operating viscosity (of the base oil of a grease); or give the oil
        (``iso_vg``, or ``nu40`` and ``nu100``) instead.
    Fr, Fa : pint.Quantity, optional
        Loads (0 when not given).
    T_amb, T_bearing : pint.Quantity, optional
        Ambient and admissible bearing temperature: with both, the heat
        balance (n_thr, the permissible speed n_per, n_per/n and the
        operating temperature T_op).
    iso_vg, VI : float, optional
        The oil by its ISO 3448 grade and viscosity index (default 95),
        instead of ``nu``: calc takes each bearing's viscosity at its own
        operating temperature T_op (ASTM D341), or at T_bearing where there
        is no T_op (no T_amb; contact seals). Needs ``T_bearing``.
    nu40, nu100 : pint.Quantity, optional
        The oil by its viscosities at 40 and 100 °C, as ``iso_vg``.
    oil_level : pint.Quantity, optional
        The SKF model in an oil bath: the oil level H.
    model : str
        Friction model of calc (``schaeffler`` or ``skf``).
    rank_by : str
        ``NR`` (the least power loss first), ``T_op`` (the coolest first) or
        ``n_per`` (the highest permissible speed first; these two need
        T_amb and T_bearing).
    f2_chart, vm_chart : optional
        Digitised charts, as calc takes them.

    Returns
    -------
    pandas.DataFrame
        The candidates' table columns ('name [unit]' headers, the
        catalogue's n_thr as ``n_thr_catalogue``), the operating point, the
        results of calc and ``n_per/n``, ranked; the rows without the ranked
        result (calc could not compute them: status error with the reason;
        or no heat balance, as for contact seals) last, in catalogue order.

    Raises
    ------
    bearingheat.errors.SelectionError
        For an operating point outside the model's bounds or the valid
        ranges, an unknown ``rank_by``, or ranking by the heat balance
        without its temperatures; for no viscosity or more than one
        (``nu``, ``iso_vg``, ``nu40`` and ``nu100``), oil data that fix no
        viscosity line, or an oil without ``T_bearing``.
    bearingheat.errors.UnitError
        For a plain number or a unit of the wrong dimension.

    Examples
    --------
    >>> import pint, bearingheat as bh
    >>> u = pint.get_application_registry()
    >>> found = bh.bearings_with_bore(40 * u.mm, D_max=80 * u.mm, family="deep groove ball", shield="open")
    >>> ranked = bh.rank_bearings(found, lubrication="oil_bath", n=6000 * u.rpm, nu=20 * u.cSt, Fr=2 * u.kN,
    ...                           T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"), rank_by="T_op")
    >>> ranked[["designation", "NR [W]", "T_op [degC]"]].round(1).values.tolist()
    [['6008', 60.6, 57.2], ['6208', 88.6, 60.8], ['61908', 54.5, 64.3], ['16008', 61.9, 83.4]]
    """
    if rank_by not in RANKINGS:
        raise SelectionError(f"rank_by: {rank_by!r} is none of {', '.join(RANKINGS)}")
    typed = [name for name, value in (("nu", nu), ("iso_vg", iso_vg), ("nu40", nu40), ("nu100", nu100))
             if value is not None]
    if len({_VISCOSITY_SOURCE[name] for name in typed}) > 1:
        raise SelectionError(f"{_ONE_VISCOSITY} {' and '.join(typed)}")
    given = {"n": n, "nu": nu, "Fr": Fr, "Fa": Fa, "T_amb": T_amb, "T_bearing": T_bearing, "oil_level": oil_level}
    point = {name: _point_value(value, name) for name, value in given.items() if value is not None}
    point.update(_oil_columns(iso_vg, VI, nu40, nu100, T_bearing))
    if not typed:
        raise SelectionError(f"{_ONE_VISCOSITY} none")
    point.setdefault("Fr", 0.0)
    point.setdefault("Fa", 0.0)
    if rank_by != "NR" and not ("T_amb" in point and "T_bearing" in point):
        raise SelectionError(f"rank_by {rank_by} needs the heat balance: give T_amb and T_bearing")
    table = candidate_table(candidates)
    supports = pd.DataFrame({"designation": table["designation"], "lubrication": lubrication, "model": model})
    for name, value in point.items():
        supports[column(name).header] = value
    results = calc(supports, f2_chart=f2_chart, vm_chart=vm_chart)
    # the operating point stays beside each candidate's results: a file of them says what they were computed at
    merged = pd.concat([table, results.drop(columns="designation")], axis=1)
    if "n_per [1/min]" in merged.columns and point["n"] > 0:
        merged.insert(merged.columns.get_loc("n_per [1/min]") + 1, MARGIN, merged["n_per [1/min]"] / point["n"])
    name, largest_first = RANKINGS[rank_by]
    values = merged[name].to_numpy(dtype=float)
    missing = (merged["status"] == "error").to_numpy() | np.isnan(values)
    order = np.lexsort((np.arange(len(merged)), -values if largest_first else values, missing))
    return merged.iloc[order].reset_index(drop=True)


def _alike(ranked: pd.DataFrame) -> list[list[int]]:
    """The positions of the candidates with an operating temperature, grouped where calc gives them the same T_op
    and n_per (6008 and 6008-2Z, NU308-E and NJ308-E: one curve), in the ranking's order."""
    groups: dict[tuple[float, float], list[int]] = {}
    T_op, n_per = (ranked[name].to_numpy(dtype=float) for name in ("T_op [degC]", "n_per [1/min]"))
    for position in np.flatnonzero(np.isfinite(T_op)).tolist():
        key = (round(T_op[position], 9), round(n_per[position], 6) if math.isfinite(n_per[position]) else math.inf)
        groups.setdefault(key, []).append(position)
    return list(groups.values())


def _viscosity_words(point: dict[str, float]) -> str:
    """The viscosity of an operating point in words: 'nu 20 mm²/s', 'ISO VG 68 (VI 95) at T_op',
    'nu40 68, nu100 8.6 mm²/s at T_op'."""
    if "nu" in point:
        return f"nu {point['nu']:g} mm²/s"
    if "iso_vg" in point:
        return f"ISO VG {point['iso_vg']:g} (VI {point['VI']:g}) at T_op"
    return f"nu40 {point['nu40']:g}, nu100 {point['nu100']:g} mm²/s at T_op"


def temperature_curves(ranked: pd.DataFrame, *, count: int = 8, points: int = 60,
                       f2_chart: F2Chart | str | None = None, vm_chart: VMChart | str | None = None) -> dict:
    """The operating temperature over speed of the leading candidates, at the operating point of the ranking.

    Parameters
    ----------
    ranked : pandas.DataFrame
        The result of :func:`rank_bearings` with the heat balance (T_amb and
        T_bearing given); its columns hold the operating point.
    count : int
        How many curves: the first ``count`` groups of candidates alike,
        one curve named by all of them (``'6008, 6008-2Z'``: calc gives
        them the same T_op and n_per), in the ranking's order.
    points : int
        Speeds of each curve, evenly from near 0 to past the highest n_per
        of the curves (at least 1.5 n).
    f2_chart, vm_chart : optional
        Digitised charts, as calc takes them.

    Returns
    -------
    dict
        ``speeds`` [1/min]; ``T_op`` (name -> T_op [°C] at each speed from
        calc, NaN above the first bearing's limiting speed n_G); ``n_per``
        and ``T_op_at_n`` (name -> calc's value at the operating point);
        ``n``, ``T_bearing``, ``T_amb``; ``title`` (the operating point in
        words). :func:`bearingheat.io.reports.selection.draw_candidates`
        draws it (``bearingheat select --plot``).

    Raises
    ------
    bearingheat.errors.SelectionError
        When no candidate has an operating temperature, or at n = 0 without
        any n_per (no range of speeds).

    Examples
    --------
    >>> import pint, bearingheat as bh
    >>> u = pint.get_application_registry()
    >>> found = bh.bearings_with_bore(40 * u.mm, D_max=68 * u.mm, family="deep groove ball")
    >>> ranked = bh.rank_bearings(found, lubrication="oil_bath", n=6000 * u.rpm, nu=20 * u.cSt, Fr=2 * u.kN,
    ...                           T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"), rank_by="T_op")
    >>> curves = bh.temperature_curves(ranked, count=2)
    >>> list(curves["T_op"]), round(curves["n_per"]["6008, 6008-2Z"])
    (['6008, 6008-2Z', '61908, 61908-2Z'], 7343)
    """
    if "T_op [degC]" not in ranked.columns or not np.isfinite(ranked["T_op [degC]"].to_numpy(dtype=float)).any():
        raise SelectionError("no candidate has an operating temperature at this point (the heat balance needs "
                             "T_amb and T_bearing)")
    groups = _alike(ranked)[:count]
    leading = ranked.iloc[[group[0] for group in groups]]
    first = leading.iloc[0]
    operating = ("n", "Fr", "Fa", "nu", "iso_vg", "VI", "nu40", "nu100", "T_amb", "T_bearing", "oil_level")
    point = {name: float(first[column(name).header]) for name in operating if column(name).header in leading.columns}
    n = point["n"]
    top = max(1.5 * n, 1.1 * float(np.nanmax(leading["n_per [1/min]"].to_numpy(dtype=float), initial=0.0)))
    if not top > 0:
        raise SelectionError("at n = 0 without a permissible speed n_per of any candidate there is no range of "
                             "speeds to draw; give the operating speed")
    speeds = np.linspace(top / points, top, points)
    grid = pd.DataFrame({"designation": np.repeat(leading["designation"].to_numpy(), len(speeds)),
                         "lubrication": first["lubrication"], "model": first["model"]})
    for name, value in point.items():
        grid[column(name).header] = np.tile(speeds, len(leading)) if name == "n" else value
    computed = calc(grid, f2_chart=f2_chart, vm_chart=vm_chart)["T_op [degC]"].to_numpy(dtype=float, copy=True)
    temperatures = computed.reshape(len(leading), len(speeds))
    limits = leading["n_G [1/min]"].to_numpy(dtype=float)
    temperatures[speeds[None, :] > limits[:, None]] = np.nan  # (above n_G the bearing does not run)
    names = [", ".join(ranked["designation"].iloc[group]) for group in groups]
    words = (f"{first['lubrication']}, Fr {point['Fr'] / 1e3:g} kN, Fa {point['Fa'] / 1e3:g} kN, "
             f"{_viscosity_words(point)}, T_amb {point['T_amb']:g} °C; {first['model']} model")
    return {"speeds": speeds, "T_op": dict(zip(names, temperatures)), "n": n,
            "n_per": dict(zip(names, leading["n_per [1/min]"].to_numpy(dtype=float))),
            "T_op_at_n": dict(zip(names, leading["T_op [degC]"].to_numpy(dtype=float))),
            "T_bearing": point["T_bearing"], "T_amb": point["T_amb"], "title": words}
