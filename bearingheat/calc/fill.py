"""Blank dimensions, ratings and factors filled from the bearing table by designation.

The bearing table is the Schaeffler catalogue HR 1 "Rolling bearings"
(edition June 2006), :mod:`bearingheat.catalogue.bearings`. For every row
with a designation the table knows, the columns of :data:`FILLED` that are
absent or blank take the catalogue's value; a value the user typed wins,
and one that differs from the catalogue's by more than the catalogue's
rounding (:func:`~bearingheat.catalogue.bearings.disagrees`) gets a row
warning naming both. A designation the table does not know is fine where
the row gives its outside diameter D (as before the table existed); where
it does not, the row is an error that lists close designations of the
table. Each distinct designation is looked up once.

The rows' loads and speeds are then checked against the bearing's ratings
and limits (warnings): a load above C0 or a speed above n_G
(:func:`implausible_relations`, usually a unit mix-up), and a load below
the minimum load the bearing needs for slippage-free running
(:func:`minimum_load_relations`, HR 1's C/100 or C0/60).
"""
from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import numpy as np
import pandas as pd

from bearingheat.calc.messages import Labels, bearing_load
from bearingheat.calc.contract import input_units
from bearingheat.calc.models import failed_rows, rows_of_models
from bearingheat.calc.supports import (bearing_rows, blanks_filled, group_rows,
                                      number_column, text_codes, text_column, with_columns)
from bearingheat.catalogue.bearings import CATALOGUE, bearing, disagreeing, half_steps, minimum_loads
from bearingheat.catalogue.designation import BEARING_TYPES
from bearingheat.errors import DesignationError

__all__ = ["FILLED", "fill_from_catalogue", "fill_arrays", "catalogue_values", "implausible_relations",
           "implausible_values", "below_minimum_load", "minimum_load_relations"]

#: the columns the bearing table fills (catalogue units: mm, N, 1, 1/min)
FILLED = ("d", "D", "B", "T", "C0", "C", "e", "Y", "Y0", "n_G")


def catalogue_values(designations: Sequence[str | None] | np.ndarray
                     ) -> tuple[dict[str, np.ndarray], list[str | None]]:
    """Per row, the bearing table's value of each :data:`FILLED` column (NaN where it has none) and the
    lookup's error message for designations it does not know (None where found or blank); each distinct
    designation is looked up once."""
    codes, uniques = pd.factorize(np.asarray(designations, dtype=object), use_na_sentinel=True)
    per_key, messages = _catalogue_entries([*uniques.tolist(), None])  # code -1 (blank) takes the last entry
    return {name: column[codes] for name, column in per_key.items()}, messages[codes].tolist()


def _catalogue_entries(designations: Sequence[str | None]) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """The bearing table's :data:`FILLED` values of each designation (NaN where it has none, or where the
    designation is blank or unknown) and the lookup's error message of each unknown one (else None)."""
    per_key = {name: np.full(len(designations), np.nan) for name in FILLED}
    messages = np.full(len(designations), None, dtype=object)
    for code, text in enumerate(designations):
        if not text:
            continue
        try:
            entry = bearing(text)
        except DesignationError as exc:
            messages[code] = str(exc)
            continue
        for name in FILLED:
            per_key[name][code] = getattr(entry, name)
    return per_key, messages


def fill_from_catalogue(frame: pd.DataFrame, labels: Labels
                        ) -> tuple[pd.DataFrame, list[tuple[int, str, str]], dict[str, np.ndarray]]:
    """The frame (contract names, catalogue units) with blank :data:`FILLED` cells taken from the bearing
    table, (row position, 'error' | 'warning', message) problems for the rows that have them, and per
    column the table filled somewhere the mask of the rows whose value came from the table."""
    if "designation" not in frame.columns or len(frame) == 0:
        return frame, [], {}
    codes, designations = text_codes(frame, "designation")  # each distinct designation looked up once
    per_key, lookup_errors = _catalogue_entries(designations)
    # rows alike in designation and in every given value of FILLED have one fill and one verdict: each such group
    # is worked out on its first row and spread to its rows by the group codes
    given_names = [name for name in FILLED if name in frame.columns]
    groups, first = group_rows(frame, ["designation", *given_names])
    key = codes[first]
    problems: list[tuple[int, str, str]] = []
    filled: dict[str, np.ndarray] = {}
    from_table: dict[str, np.ndarray] = {}
    for name in FILLED:
        if name not in frame.columns and np.isnan(per_key[name]).all():
            continue
        given = number_column(frame, name)
        catalogue = per_key[name][key]
        blank = np.isnan(given[first])
        taken = blank & ~np.isnan(catalogue)
        if taken.any():  # (a group's rows share their given values: each row takes its group's value)
            from_table[name] = taken[groups]
            filled[name] = np.where(blank, catalogue, given[first])[groups]
        steps = half_steps(name, per_key[name])[key]
        differing = ~blank & disagreeing(name, given[first], catalogue, steps)
        if differing.any():  # the words after the column's name, once a group; the name is the row's own cell
            typed, printed = given[first].tolist(), catalogue.tolist()  # Python floats format fast
            said = {g: f": {labels.value(name, typed[g])} differs from {_in_the_user_s_unit(labels, name, printed[g])} "
                       f"of {designations[key[g]]} in the bearing table ({CATALOGUE}); the value given is used"
                    for g in np.flatnonzero(differing).tolist()}
            header = labels.name(name) if labels.cell is None else None
            problems.extend((i, "warning", f"{header or labels.name(name, i)}{said[groups[i]]}")
                            for i in np.flatnonzero(differing[groups]).tolist())
    D = filled.get("D", number_column(frame, "D"))
    unknown = np.array([message is not None for message in lookup_errors], dtype=bool)[codes]
    for i in np.flatnonzero(np.isnan(D) & unknown):
        problems.append((int(i), "error", f"{lookup_errors[codes[i]]}; or type the dimensions d, D (and C0)"))
    if not filled:
        return frame, problems, from_table
    return with_columns(frame, filled), problems, from_table


def _in_the_user_s_unit(labels: Labels, name: str, value: float) -> str:
    """A catalogue value as the user's column shows it, the catalogue unit's value after it where the units differ:
    '18 (18000 N)' under 'C0 [kN]', '15 mm' under 'B [mm]'."""
    shown, unit = labels.value(name, value), _unit(name).rstrip()
    return f"{value:g} {unit}".rstrip() if shown == f"{value:g}" else f"{shown} ({value:g} {unit})"


def _unit(name: str) -> str:
    unit = input_units()[name]  # (the column contract's catalogue unit; none for factors)
    return f"{unit} " if unit not in ("", "1") else ""


def fill_arrays(designation: str | None, arrays: dict[str, np.ndarray], given: set[str]
                ) -> tuple[dict[str, np.ndarray], list[str], str | None]:
    """The unit-aware API's fill of one bearing: ``arrays`` (catalogue units) with the :data:`FILLED` entries
    that are not in ``given`` taken from the bearing table; the warnings where a given value differs from the
    catalogue's; and the lookup's error message where the table does not know the designation (else None)."""
    if not designation:
        return arrays, [], None
    values, errors = catalogue_values([designation])
    out, notes = dict(arrays), []
    for name in FILLED:
        if name not in arrays:
            continue
        catalogue = values[name][0]
        if name not in given:
            if not np.isnan(catalogue):
                out[name] = np.asarray(catalogue)
        elif disagreeing(name, np.asarray(arrays[name], dtype=float), np.asarray(catalogue)).any():
            shown = np.ravel(arrays[name])[0]
            notes.append(f"{name}: {shown:g} {_unit(name)}differs from {catalogue:g} {_unit(name)}of {designation} in "
                         f"the bearing table ({CATALOGUE}); the value given is used")
    return out, notes, errors[0]


def implausible_relations(frame: pd.DataFrame, labels: Labels, from_table: dict[str, np.ndarray]
                          ) -> list[tuple[int, str, str]]:
    """Warnings (row position, 'warning', message) where inputs are each possible but not together: a load
    above C0, a speed above n_G (catalogue units, contract names).

    Both are usual signs of a unit mix-up (rpm typed under a header in Hz, N under kN); ``from_table``
    marks the values the bearing table filled (:func:`fill_from_catalogue`), whose messages name the catalogue.
    """
    numbers = {name: number_column(frame, name) for name in ("n", "n_G", "Fr", "Fa", "C0")}
    catalogue_n_G = from_table.get("n_G", np.zeros(len(frame), dtype=bool))
    return implausible_values(numbers, labels, catalogue_n_G, lambda: text_column(frame, "designation"))


def implausible_values(numbers: Mapping[str, np.ndarray], labels: Labels, catalogue_n_G: np.ndarray,
                       designations: Callable[[], Sequence[str | None]]) -> list[tuple[int, str, str]]:
    """The warnings of :func:`implausible_relations` from the rows' numbers (``numbers``: n, n_G, Fr, Fa, C0, arrays
    of one length, catalogue units) without a frame: the Python API's points. ``catalogue_n_G`` marks the rows
    whose n_G is the bearing table's; ``designations()`` gives each row's designation (asked only where a
    speed is too high)."""
    problems = []

    def user(name, value):
        shown = labels.value(name, value)
        return shown if shown == f"{value:g}" else f"{shown} ({value:g} {input_units()[name]})"

    C0 = numbers["C0"]
    for name in ("Fr", "Fa"):
        load = numbers[name]
        with np.errstate(invalid="ignore"):
            rows = np.flatnonzero(load > C0)  # (NaN is above nothing; the few rows found are then checked finite)
        rows = rows[np.isfinite(load[rows]) & np.isfinite(C0[rows])]
        # (Python floats: numpy numbers format slower; 0.31 s against 0.41 s for 10^5 messages)
        for i, value, rating in zip(rows.tolist(), load[rows].tolist(), C0[rows].tolist()):
            problems.append((i, "warning", f"{labels.name(name, i)}: {user(name, value)} is above the static load "
                                            f"rating C0 = {rating:g} N; check the load and its unit"))
    n, n_G = numbers["n"], numbers["n_G"]
    with np.errstate(invalid="ignore"):
        rows = np.flatnonzero(n > n_G)
    rows = rows[np.isfinite(n[rows])]
    named = designations() if len(rows) else []  # (a Python text per row)
    for i, speed, limit in zip(rows.tolist(), n[rows].tolist(), n_G[rows].tolist()):
        of = f" of {named[i]} ({CATALOGUE})" if catalogue_n_G[i] else ""
        problems.append((i, "warning", f"{labels.name('n', i)}: {user('n', speed)} is above the limiting speed "
                                        f"n_G = {limit:g} 1/min{of}; check the speed and its unit"))
    return problems


def _minimum_loads(bearing_types, C: np.ndarray, C0: np.ndarray):
    """Per row the minimum load [N] of its bearing type (NaN where HR 1 gives none or the rating is missing), and
    what the messages need: each row's code into ``types`` and the rule of each type (None: not checked)."""
    if isinstance(bearing_types, pd.Categorical):
        codes, types = bearing_types.codes, bearing_types.categories.to_numpy(dtype=object)
    else:  # (an object array: a Series of it would become pandas 3's string dtype, text by text)
        codes, types = pd.factorize(np.asarray(bearing_types, dtype=object), use_na_sentinel=True)
    rules = [minimum_loads().get(t) if isinstance(t, str) else None for t in types]
    # per code (the last entry: code -1, no type) the rating's divisor (NaN: not checked) and whether it is C0
    divisor = np.array([rule.divisor if rule else np.nan for rule in rules] + [np.nan])[codes]
    of_C0 = np.array([rule is not None and rule.rating == "C0" for rule in rules] + [False])[codes]
    return np.where(of_C0, C0, C) / divisor, codes, types, rules


def below_minimum_load(numbers: Mapping[str, np.ndarray],
                       bearing_types: Sequence[str | None] | pd.Categorical | np.ndarray,
                       labels: Labels, rows: np.ndarray, bearings: np.ndarray | float = 1.0,
                       bearing: tuple[np.ndarray, np.ndarray] | None = None) -> list[tuple[int, str, str]]:
    """Warnings (row position, 'warning', message) where a bearing's load is below the minimum load its type needs
    for slippage-free running in continuous operation: C/100, or C0/60 of cylindrical roller bearings (Schaeffler
    HR 1, 2006, :func:`~bearingheat.catalogue.bearings.minimum_loads`).

    ``numbers``: Fr, Fa, C, C0 (arrays of one length in catalogue units; a blank load, NaN, is 0);
    ``bearings``: 2 on the rows of a pair in X or O arrangement, else 1 (or one number for all rows);
    ``bearing_types`` the type of each row (types without a minimum load in HR 1 are not checked, nor rows
    without the rating); ``rows`` the rows to check; ``bearing`` (each row's bearing, the first row of each)
    where rows of one bearing share type, C and C0 (calc's frame): the minimum is worked out once a bearing.
    The catalogue's P is the equivalent dynamic load, which needs X and Y the tables do not give: the bearing's
    load here is the larger of its radial load (Fr/2 on each bearing of a pair) and Fa, the least P can be
    where Y >= 1.
    """
    C, C0 = numbers["C"], numbers["C0"]
    if bearing is None:
        each_row = None
        minimum, codes, types, rules = _minimum_loads(bearing_types, C, C0)
    else:
        each_row, first = bearing
        first_types = bearing_types.take(first) if isinstance(bearing_types, pd.Categorical) \
            else np.asarray(bearing_types, dtype=object)[first]
        minimum, codes, types, rules = _minimum_loads(first_types, C[first], C0[first])
        # (one bearing, as in the API: its minimum as a view, not gathered to every row)
        minimum = minimum[each_row] if len(first) > 1 else np.broadcast_to(minimum, np.shape(each_row))
    if not any(rules):
        return []
    Fr, Fa = numbers["Fr"], numbers["Fa"]
    Fr_bearing = Fr / bearings if np.ndim(bearings) or bearings != 1 else Fr
    each_bearing = np.broadcast_to(bearings, np.shape(Fr))
    with np.errstate(invalid="ignore"):
        # a blank load is 0: NaN where both are blank, below any minimum (one that is NaN is no minimum); the few
        # rows below are then checked against the rows asked for and a minimum > 0
        rows_below = np.flatnonzero(~(np.fmax(Fr_bearing, Fa) >= minimum))
        rows_below = rows_below[rows[rows_below] & (minimum[rows_below] > 0)]
    # the words after the minimum's value, once per type
    rule_texts = [f"{rule.formula} of {'an' if kind[0] in 'aeiou' else 'a'} {kind} for slippage-free running "
                  f"({CATALOGUE}, p. {rule.page}): the bearing may slip, the more so at high speeds and accelerations"
                  if rule else "" for rule, kind in zip(rules, (BEARING_TYPES.get(t, "") for t in types))]
    problems = []
    row_codes = codes[rows_below if each_row is None else each_row[rows_below]]
    for i, code, Fr_i, Fa_i, bearings_i, minimum_i in zip(
            rows_below.tolist(), row_codes.tolist(), Fr[rows_below].tolist(), Fa[rows_below].tolist(),
            each_bearing[rows_below].tolist(), minimum[rows_below].tolist()):
        column, load = bearing_load(labels, i, Fr_i, Fa_i, bearings_i)
        problems.append((i, "warning", f"{load} is below the minimum load {labels.value(column, minimum_i)} = "
                                        f"{rule_texts[code]}"))
    return problems


def minimum_load_relations(frame: pd.DataFrame, results: pd.DataFrame, labels: Labels, model: str
                           ) -> list[tuple[int, str, str]]:
    """:func:`below_minimum_load` of calc's rows (catalogue units, contract names; ``results`` of
    :func:`~bearingheat.calc.models.compute_supports`): the rows whose friction model does not check the minimum
    load itself (``model``: that of rows without a ``model`` cell) and whose friction succeeded."""
    rows = rows_of_models(frame, model, lambda m: not m.own_minimum_load) & ~failed_rows(results)
    if not rows.any() or "bearing_type" not in results.columns:
        return []
    paired = np.asarray(blanks_filled(frame, "arrangement", "single") == "paired")
    numbers = {name: number_column(frame, name) for name in ("Fr", "Fa", "C", "C0")}
    # (the type and the ratings are the bearing's: calc's frame numbers its bearings)
    return below_minimum_load(numbers, results["bearing_type"].array, labels, rows,
                              np.where(paired, 2.0, 1.0) if paired.any() else 1.0, bearing_rows(frame))
