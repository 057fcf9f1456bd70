"""Uncertainty bands: the scatter of the friction coefficients f0 and f1 carried to the results.

A row's ``f0_rel_unc`` and ``f1_rel_unc`` are the relative half-widths of
the 95 % intervals of its f0 and f1 (0.1: the coefficient lies within
±10 % of its value with 95 % confidence), the same kind of interval
``bearingheat audit`` fits; :func:`coefficient_uncertainties` reads them
from an audit's ``coefficients.csv``. The two are taken as independent.

:func:`uncertainty_bands` gives ``X_low`` and ``X_high`` for X in MR, NR,
n_thr, n_per and T_op:

- ``linearised`` (the default): each coefficient is moved to the edge of its
  interval, f → f·(1 + u), and the results are computed again; the changes
  ΔX₀, ΔX₁ combine as ΔX = √(ΔX₀² + ΔX₁²) and the band is X ± ΔX (a secant
  over the half-width rather than a tangent, so it is exact for the
  results that are linear in f0 and f1, such as MR);
- ``sampled``: f0 and f1 are drawn from normal distributions with standard
  deviation u/1.96 (``samples`` draws, all rows in one vectorised calc), and
  the band is the 2.5 and 97.5 percentiles.

n_thr, of the ISO 15312 reference conditions, takes the catalogue's f0 and
f1, not the operating ones: they are scaled alike (to the interval's edge,
or by the same draws).

Both are monotone where the physics is: a higher f0 or f1 never lowers MR
and never raises n_per.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.contract import output_header, parse_header
from bearingheat.calc.reference_speed import thermal_reference_speed_details
from bearingheat.calc.supports import number_column, text_column, zero_where_blank
from bearingheat.errors import InputError

__all__ = ["UNCERTAINTY_INPUTS", "BANDED", "METHODS", "Z95", "has_uncertainty", "coefficient_uncertainties",
           "fill_from_coefficients", "uncertainty_bands"]

#: the input columns of the relative 95 % half-widths
UNCERTAINTY_INPUTS = ("f0_rel_unc", "f1_rel_unc")
#: the results that get bands -> unit
BANDED = {"MR": "N*mm", "NR": "W", "n_thr": "1/min", "n_per": "1/min", "T_op": "degC"}
#: the ways the bands are computed
METHODS = ("linearised", "sampled")
#: the two-sided 95 % quantile of the normal distribution
Z95 = 1.959963984540054


def has_uncertainty(table: pd.DataFrame) -> bool:
    """True when the table has a column of :data:`UNCERTAINTY_INPUTS`."""
    return any(_name(h) in UNCERTAINTY_INPUTS for h in table.columns)


def _name(header) -> str:
    try:
        return parse_header(str(header))[0]
    except InputError:
        return str(header)


def coefficient_uncertainties(coefficients: pd.DataFrame) -> dict[tuple[str, str | None], dict[str, float]]:
    """(bearing, lubrication) -> {'f0_rel_unc': .., 'f1_rel_unc': ..} from the ``coefficients.csv`` of
    ``bearingheat audit``: the half-width of each fitted coefficient's 95 % interval over the fitted value (f1_a
    counts as f1). The audit fits a bearing once per lubrication (their table coefficients differ); a file of an
    older audit, without the ``lubrication`` column, gives the key (bearing, None): any lubrication."""
    missing = {"bearing", "coefficient", "fitted", "ci_low", "ci_high"} - set(coefficients.columns)
    if missing:
        raise InputError(f"coefficients: missing column(s) {', '.join(sorted(missing))}; expected the "
                         "coefficients.csv of 'bearingheat audit'")
    out: dict[tuple[str, str | None], dict[str, float]] = {}
    fitted, low, high = (pd.to_numeric(coefficients[c], errors="coerce").to_numpy(dtype=float)
                         for c in ("fitted", "ci_low", "ci_high"))
    names = coefficients["coefficient"].astype(str).map({"f0": "f0_rel_unc", "f1": "f1_rel_unc", "f1_a": "f1_rel_unc"})
    lubrications = text_column(coefficients, "lubrication")  # (None in every row of an older file)
    for i in np.flatnonzero(names.notna().to_numpy() & np.isfinite(fitted) & (fitted != 0)):  # a short table
        row = int(i)
        bearing = str(coefficients["bearing"].iat[row]).strip()
        # one fit may hold lubrications of equal table coefficients: 'circulating_oil, oil_mist'
        for lubrication in (lubrications[row].split(", ") if lubrications[row] else [None]):
            out.setdefault((bearing, lubrication), {})[str(names.iat[row])] = \
                float((high[i] - low[i]) / 2.0 / abs(fitted[i]))
    return out


def _with_coefficients(table: pd.DataFrame, f0: np.ndarray, f1: np.ndarray) -> pd.DataFrame:
    """The table with its f0 and f1 overridden (unit-free columns) and without the uncertainty columns."""
    drop = [h for h in table.columns if _name(h) in UNCERTAINTY_INPUTS + ("f0", "f1")]
    return table.drop(columns=drop).assign(f0=f0, f1=f1)


def _results(result: pd.DataFrame) -> dict[str, np.ndarray]:
    return {name: (result[output_header(name, unit)].to_numpy(dtype=float)
                   if output_header(name, unit) in result.columns else np.full(len(result), np.nan))
            for name, unit in BANDED.items()}


def uncertainty_bands(table: pd.DataFrame, result: pd.DataFrame, frame: pd.DataFrame, run, *,
                      method: str = "linearised", samples: int = 400, seed: int = 0) -> pd.DataFrame:
    """``X_low``, ``X_high`` columns for X in :data:`BANDED` (headers with units; NaN where a row has no
    uncertainty, is in error, or lacks the result).

    ``table`` is calc's input, ``result`` its output, ``frame`` the input in catalogue units (contract names,
    with ``f0_rel_unc``, ``f1_rel_unc``), ``run(table) -> result`` runs calc again with the same options.
    """
    if method not in METHODS:
        raise InputError(f"uncertainty method: {method!r} is not one of {', '.join(METHODS)}")
    u0 = zero_where_blank(frame, "f0_rel_unc")
    u1 = zero_where_blank(frame, "f1_rel_unc")
    f0 = result["f0"].to_numpy(dtype=float)
    f1 = result["f1"].to_numpy(dtype=float)
    usable = (result["status"].to_numpy() != "error") & ((u0 > 0) | (u1 > 0)) & np.isfinite(f0) & np.isfinite(f1)
    base = _results(result)
    if method == "linearised":
        n_thr = _reference_speed_band(frame, u0, u1, base["n_thr"])
        moved = [_results(run(_with_coefficients(table, f0 * (1 + u0), f1))),
                 _results(run(_with_coefficients(table, f0, f1 * (1 + u1))))]
        low, high = {}, {}
        for name in BANDED:
            if name == "n_thr":
                low[name], high[name] = n_thr
                continue
            delta = np.sqrt(sum((m[name] - base[name]) ** 2 for m in moved))
            low[name], high[name] = base[name] - delta, base[name] + delta
    else:
        rng = np.random.default_rng(seed)
        s0 = 1.0 + (u0 / Z95)[None, :] * rng.standard_normal((samples, len(table)))
        s1 = 1.0 + (u1 / Z95)[None, :] * rng.standard_normal((samples, len(table)))
        tiled = pd.concat([table] * samples, ignore_index=True)
        drawn = _results(run(_with_coefficients(tiled, np.tile(f0, samples) * s0.ravel(),
                                                np.tile(f1, samples) * s1.ravel())))
        # n_thr is of the catalogue's f0 and f1 (the reference conditions): the same draws scale them
        drawn["n_thr"] = _reference_speed_samples(frame, s0, s1, base["n_thr"])
        low, high = {}, {}
        for name in BANDED:
            values = drawn[name].reshape(samples, len(table))
            finite = np.isfinite(values).any(axis=0)  # rows without the result stay NaN (no all-NaN percentile)
            low[name], high[name] = np.full(len(table), np.nan), np.full(len(table), np.nan)
            if finite.any():
                low[name][finite] = np.nanpercentile(values[:, finite], 2.5, axis=0)
                high[name][finite] = np.nanpercentile(values[:, finite], 97.5, axis=0)
    out = {}
    for name, unit in BANDED.items():
        if output_header(name, unit) not in result.columns:
            continue
        for edge, values in (("low", low[name]), ("high", high[name])):
            out[output_header(f"{name}_{edge}", unit)] = np.where(usable & np.isfinite(base[name]), values, np.nan)
    return pd.DataFrame(out, index=result.index)


def _reference_speed_samples(frame: pd.DataFrame, s0: np.ndarray, s1: np.ndarray, n_thr: np.ndarray) -> np.ndarray:
    """n_thr of every row with the table f0 and f1 scaled by each draw (``s0``, ``s1``: samples x rows), flat
    in the order of the draws (NaN throughout where no row has n_thr)."""
    if np.isnan(n_thr).all():
        return np.full(s0.size, np.nan)
    tiled = pd.concat([frame] * len(s0), ignore_index=True)
    return thermal_reference_speed_details(tiled, f0_scale=s0.ravel(), f1_scale=s1.ravel(),
                                           names=("n_thr",))["n_thr"].to_numpy(dtype=float)


def _reference_speed_band(frame: pd.DataFrame, u0: np.ndarray, u1: np.ndarray,
                          n_thr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """n_thr at the interval edges of the table f0 and f1 (higher coefficients: lower n_thr), combined as ΔX."""
    if np.isnan(n_thr).all():
        return n_thr, n_thr
    up0 = thermal_reference_speed_details(frame, f0_scale=1 + u0)["n_thr"].to_numpy(dtype=float)
    up1 = thermal_reference_speed_details(frame, f1_scale=1 + u1)["n_thr"].to_numpy(dtype=float)
    delta = np.sqrt((up0 - n_thr) ** 2 + (up1 - n_thr) ** 2)
    return n_thr - delta, n_thr + delta


def fill_from_coefficients(table: pd.DataFrame, coefficients: pd.DataFrame) -> pd.DataFrame:
    """The table with blank or missing ``f0_rel_unc``/``f1_rel_unc`` taken from an audit's coefficients by
    designation and lubrication (the audit's 'bearing' and 'lubrication'); a value in the table wins."""
    known = coefficient_uncertainties(coefficients)
    named = table.rename(columns={h: _name(h) for h in table.columns})
    # each distinct (designation, lubrication) looked up once (missing texts come back as NaN)
    codes, pairs = pd.factorize(pd.MultiIndex.from_arrays([text_column(named, "designation"),
                                                           text_column(named, "lubrication")]))
    texts = [(d if isinstance(d, str) else "", lub if isinstance(lub, str) else None) for d, lub in pairs]
    # a row takes the fit of its bearing in its lubrication (an older file's fit of the bearing in any)
    found = [known.get((d, lub), known.get((d, None), {})) for d, lub in texts]
    out = table.copy()
    for name in UNCERTAINTY_INPUTS:
        header = next((h for h in table.columns if _name(h) == name), name)
        given = number_column(out.rename(columns={header: name}), name)
        fitted = np.array([fit.get(name, np.nan) for fit in found], dtype=float)[codes]
        out[header] = np.where(np.isnan(given), fitted, given)
    return out
