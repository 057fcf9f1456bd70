"""The support arrays: every input and catalogue constant of many supports, built once.

One builder, :func:`build_support_arrays`, serves the table (``calc``), the
unit-aware API (one bearing at many operating points) and the effect
candidates of ``diagnose``. Bearings are resolved once per distinct key
(designation, type, series, lubrication, arrangement), not once per row;
where every row is one bearing the catalogue constants stay scalars, so an
API call over 10^6 operating points copies no constant 10^6 times.

Numbers are in catalogue units (mm, N, 1/min, mm²/s, deg) with NaN for
"not given"; Fr and Fa default to 0.
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Callable, TypeAlias

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc

from bearingheat.calc.contract import ARRANGEMENTS, PLAIN_TYPES
from bearingheat.catalogue.friction import LUBRICATION_F0_COLUMN, ResolvedBearing, resolve
from bearingheat.errors import DesignationError

__all__ = ["SupportArrays", "build_support_arrays", "bearing_constants", "NUMBER_INPUTS", "KEY_INPUTS",
           "text_column", "number_column", "zero_where_blank", "text_codes", "distinct_keys", "group_codes",
           "group_rows", "text_or_default", "value_codes", "text_categorical", "fill_blank", "blanks_filled",
           "object_column", "column_codes", "per_distinct", "coded_categorical", "first_rows", "nonblank", "text_in",
           "BEARING_INPUTS", "BEARING_GROUP", "with_columns", "with_bearing_groups", "bearing_rows", "printed_size"]

#: numeric inputs of the friction model, in catalogue units
NUMBER_INPUTS = ("d", "D", "B", "C0", "Y", "e", "X0", "Y0", "alpha", "f0", "f1", "f2", "n", "nu", "Fr", "Fa")
#: text inputs that select a bearing's catalogue constants
KEY_INPUTS = ("designation", "type", "series", "lubrication", "arrangement")

_F1_BASIS_CODE = {"constant": 0, "P0/C0": 1, "Fa/C0": 2}

#: constants of a row that did not resolve (its error is reported; the kernels see neutral values)
_BLANK = {"bearing_type": "", "series": "", "f0_table": math.nan, "f0_basis": "", "f1_a": math.nan,
          "f1_x": math.nan, "f1_basis": 0, "m1_load": "Fr", "p1_rule": "", "X0_table": math.nan,
          "Y0_table": math.nan, "kB": math.nan, "m2": False, "no_axial": False, "seal": "open",
          "contact_angle": math.nan, "label": "", "prefix": "", "notes": (), "bore": math.nan,
          "width": math.nan, "error": "", "resolved": False, "bearings": 1.0}
_TEXT = ("bearing_type", "series", "f0_basis", "m1_load", "p1_rule", "seal", "label", "prefix", "error")
_FLOAT = ("f0_table", "f1_a", "f1_x", "X0_table", "Y0_table", "kB", "contact_angle", "bearings")
_BOOL = ("m2", "no_axial", "resolved")

#: a bearing constant: one value where every row has the same bearing, else an array with one value per row
PerRow: TypeAlias = Any


@dataclass
class SupportArrays:
    """Inputs and catalogue constants of ``size`` supports (catalogue units).

    Every field is an array of length ``size`` or a scalar shared by all
    rows. ``error`` holds the reason a row's bearing could not be resolved
    ('' where it could); ``resolved`` is False where no catalogue entry was
    found (its other errors are then not reported); ``plain`` marks plain
    bushings, which the rolling-bearing models skip. ``notes`` holds the
    designation notes per row, or one entry shared by all rows.
    """

    size: int
    d: np.ndarray
    D: np.ndarray
    B: np.ndarray
    C0: np.ndarray
    Y: np.ndarray
    e: np.ndarray
    X0: np.ndarray
    Y0: np.ndarray
    alpha: np.ndarray
    f0: np.ndarray
    f1: np.ndarray
    f2: np.ndarray
    n: np.ndarray
    nu: np.ndarray
    Fr: np.ndarray
    Fa: np.ndarray
    bearing_type: PerRow
    series: PerRow
    f0_basis: PerRow
    m1_load: PerRow
    p1_rule: PerRow
    seal: PerRow
    label: PerRow
    prefix: PerRow
    f0_table: PerRow
    f1_a: PerRow
    f1_x: PerRow
    X0_table: PerRow
    Y0_table: PerRow
    kB: PerRow
    contact_angle: PerRow
    bearings: PerRow
    f1_basis: PerRow
    m2: PerRow
    no_axial: PerRow
    error: PerRow
    resolved: PerRow
    plain: np.ndarray
    #: per row the notes of its designation (a tuple of texts; one entry where one bearing spans the rows)
    notes: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=object))
    #: whether ``notes`` has a note, in the same shape (a bool per row, without looking at the tuples)
    noted: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    #: model-specific inputs by contract name (per-row arrays or one value), e.g. the SKF model's oil level
    extra: dict = field(default_factory=dict)

    def take(self, rows: np.ndarray) -> SupportArrays:
        """The supports at positions ``rows`` (scalars stay scalars)."""
        rows = np.asarray(rows)
        changes: dict[str, Any] = {}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if f.name == "size":
                changes["size"] = len(rows)
            elif f.name in ("notes", "noted"):
                changes[f.name] = value[rows] if len(value) == self.size else value
            elif f.name == "extra":
                changes["extra"] = {k: (v[rows] if np.ndim(v) == 1 and len(v) == self.size else v)
                                    for k, v in value.items()}
            elif (isinstance(value, np.ndarray) and value.ndim == 1) or isinstance(value, pd.Categorical):
                changes[f.name] = value[rows]
        return dataclasses.replace(self, **changes)

    def replace(self, **values: Any) -> SupportArrays:
        """A copy with some fields replaced (e.g. another axial load)."""
        return dataclasses.replace(self, **values)


def object_column(size: int, value: Any) -> np.ndarray:
    """An object array of ``size`` cells that all hold ``value``. ``np.full`` converts a text value cell by cell:
    76 ms for 10^6 cells against 4 ms here."""
    column = np.empty(size, dtype=object)
    column.fill(value)
    return column


def column_codes(values: pd.Series) -> tuple[np.ndarray, np.ndarray]:
    """pd.factorize of a column (missing values: code -1), by pyarrow for an Arrow text column of one chunk (a
    column of one text without hashing it), fast on Arrow columns of many chunks; a categorical
    column (calc's text columns, :func:`text_categorical`) gives its own codes and categories."""
    if isinstance(values.dtype, pd.CategoricalDtype):
        return values.cat.codes.to_numpy(), values.cat.categories.to_numpy(dtype=object)
    arrow = getattr(values.array, "__arrow_array__", None)
    chunked = arrow() if arrow is not None else None
    if chunked is not None and getattr(chunked, "num_chunks", 0) == 1 and (
            pa.types.is_string(chunked.type) or pa.types.is_large_string(chunked.type)):
        if _holds_one_text(chunked.chunk(0)):  # (a table of one lubrication or arrangement, say)
            return np.zeros(len(chunked), dtype=np.intp), np.array([chunked.chunk(0)[0].as_py()], dtype=object)
        # pyarrow's own hash of its strings: codes in order of first appearance as pd.factorize's, null -1
        encoded = chunked.chunk(0).dictionary_encode()
        codes = pc.fill_null(encoded.indices, -1).to_numpy().astype(np.intp)
        return codes, np.array(encoded.dictionary.to_pylist(), dtype=object)
    if chunked is not None and getattr(chunked, "num_chunks", 1) > 16:
        # pandas factorizes an Arrow array chunk by chunk: a column concatenated from many frames holds one
        # chunk per frame (10^6 rows in 4*10^4 chunks: 0.16 s a column), as Python objects 0.015 s
        values = pd.Series(values.to_numpy(dtype=object), index=values.index)
    codes, uniques = pd.factorize(values, use_na_sentinel=True)
    return codes, np.asarray(uniques, dtype=object)


def _holds_one_text(texts: pa.Array) -> bool:
    """Whether an Arrow text array holds one text in every cell (no null): compared with its first cell, 64 cells
    spread over it first, then all (4 ms for 10^6 cells, against 16 ms for hashing them)."""
    size = len(texts)
    if size == 0 or texts.null_count:
        return False
    first = texts[0]
    sample = texts.take(pa.array(np.linspace(0, size - 1, min(size, 64)).astype(np.int64)))
    return bool(pc.all(pc.equal(sample, first)).as_py()) and bool(pc.all(pc.equal(texts, first)).as_py())


def per_distinct(values: pd.Series, convert: Callable) -> np.ndarray:
    """``convert(value)`` of every cell as an object array, computed once per distinct value (NaN, None and
    pandas' missing values are one value: ``convert(None)``)."""
    codes, uniques = column_codes(values)
    converted = np.array([convert(v) for v in uniques] + [convert(None)], dtype=object)
    return converted[codes]  # code -1 (missing) takes the last entry


def coded_categorical(codes: np.ndarray, values: list, shared: dict | None = None) -> pd.Categorical:
    """``values[codes]`` per row as a categorical: equal values share one category (two codes may stand for one
    value), a None value is missing. ``values`` is short (one entry per distinct key); no Python object per row.

    ``shared`` (a dict kept by the caller across calls with the same ``codes``) lends the per-row codes of an
    earlier call whose values were split alike (a bearing's label and series, say) instead of taking them again;
    those codes are read-only."""
    value_codes, distinct = pd.factorize(np.array(values, dtype=object), use_na_sentinel=True)
    # the smallest signed code type (int8 up to 128 categories): an eighth of the bytes to take and write; the
    # codes come from factorize (-1 or a category's position): nothing to validate
    small = value_codes.astype(np.min_scalar_type(-max(len(distinct), 1)))
    if shared is None:
        per_row = small[codes]
    else:
        key = (small.dtype.str, small.tobytes())
        per_row = shared.get(key)
        if per_row is None:
            # one value for every key: a fill, not a take
            per_row = np.full(len(codes), small[0]) if len(small) and (small == small[0]).all() else small[codes]
            per_row.flags.writeable = False
            shared[key] = per_row
    return pd.Categorical.from_codes(per_row, categories=pd.Index(distinct, dtype=object), validate=False)


def text_categorical(values: pd.Series, clean: Callable[[Any], str | None]) -> pd.Categorical:
    """A text column as a categorical of its cleaned distinct texts (``clean(value)``, None for a blank cell:
    a missing value), each distinct cell cleaned once. calc's text columns are kept so: every later
    factorization reads the codes instead of hashing the strings again."""
    codes, uniques = column_codes(values)
    # code -1 (missing) takes the last entry; cleaning can merge cells ('62', ' 62')
    return coded_categorical(codes, [clean(v) for v in uniques] + [None])


def blanks_filled(frame: pd.DataFrame, name: str, default: str) -> pd.Categorical:
    """A text column of calc (categorical, :func:`text_categorical`) with its blank cells ``default`` (a
    column of ``default`` where it is absent)."""
    if name not in frame.columns:
        return pd.Categorical.from_codes(np.zeros(len(frame), dtype=np.int8), categories=pd.Index([default]))
    cells = pd.Categorical(frame[name])
    if default not in cells.categories:
        cells = cells.add_categories([default])
    return cells.fillna(default)


def _stripped_or_none(value):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return None
    text = str(value).strip()
    return text or None


def text_column(frame: pd.DataFrame, name: str) -> list:
    """A text column as stripped strings, None for blank cells (or a column of None where it is absent)."""
    if name not in frame.columns:
        return [None] * len(frame)
    return per_distinct(frame[name], _stripped_or_none).tolist()


def number_column(frame: pd.DataFrame, name: str, default: float = math.nan) -> np.ndarray:
    """A numeric column as floats (NaN for blanks and text), or ``default`` where it is absent. A float column
    gives its own values, read-only (as pd.to_numeric's would be), without the copy to_numeric makes."""
    if name in frame.columns:
        column = frame[name]
        if column.dtype == np.float64:
            return column.to_numpy()
        return pd.to_numeric(column, errors="coerce").to_numpy(dtype=float)
    return np.full(len(frame), default, dtype=float)


def zero_where_blank(frame: pd.DataFrame, name: str) -> np.ndarray:
    """A numeric column with 0 for its blank cells (:func:`number_column`), or zeros where the frame has no
    such column (without a pass over NaNs)."""
    if name not in frame.columns:
        return np.zeros(len(frame))
    return np.nan_to_num(number_column(frame, name), nan=0.0)


def bearing_constants(resolved: ResolvedBearing, lubrication: str | None, arrangement: str) -> dict:
    """Row-constant coefficients of one bearing, with an 'error' entry saying why they cannot be used.

    ``lubrication`` None means f0 comes from the user (no table column).
    """
    entry = resolved.entry
    parsed = resolved.designation
    out = {
        "bearing_type": entry.bearing_type, "series": entry.series,
        "f0_table": math.nan, "f0_basis": entry.f0_basis,
        "f1_a": entry.f1_a, "f1_x": entry.f1_x, "f1_basis": _F1_BASIS_CODE[entry.f1_basis],
        "m1_load": entry.m1_load, "p1_rule": "",
        "X0_table": entry.X0, "Y0_table": entry.Y0, "kB": resolved.kB,
        "m2": resolved.takes_axial_m2, "no_axial": resolved.cannot_take_axial,
        "seal": resolved.seal,
        "contact_angle": math.nan if resolved.contact_angle is None else resolved.contact_angle,
        "label": entry.label, "prefix": resolved.prefix,
        "notes": parsed.notes if parsed else (), "error": "", "resolved": True,
        # a paired row is one support of two bearings (X or O arrangement): its P1 is the pair's (the Schaeffler catalogue,
        # p. 68) and its M0 is that of both bearings, each of which churns its own lubricant
        "bearings": 2.0 if arrangement == "paired" else 1.0,
        "bore": printed_size(parsed, "bore"),
        "width": printed_size(parsed, "width"),
    }
    if lubrication is not None:
        if lubrication not in LUBRICATION_F0_COLUMN:
            out["error"] = (f"lubrication: {lubrication!r} is not one of "
                            f"{', '.join(LUBRICATION_F0_COLUMN)}")
            return out
        f0 = entry.f0_for(lubrication)
        if math.isnan(f0):
            out["error"] = (f"lubrication: {lubrication!r} has no f0 for {entry.label} (the Schaeffler catalogue prints a dash); "
                            "use grease or oil_mist, or give f0")
            return out
        out["f0_table"] = f0
    if arrangement not in ARRANGEMENTS:
        out["error"] = f"arrangement: {arrangement!r} is not one of {', '.join(ARRANGEMENTS)}"
        return out
    if entry.m1_load == "P1":
        rule = entry.p1_single if arrangement == "single" else entry.p1_paired
        if rule is None:
            out["error"] = (f"arrangement: {arrangement!r} has no P1 rule for {entry.label} "
                            "(the Schaeffler catalogue, p. 68, prints no rule for a pair)")
            return out
        out["p1_rule"] = rule
    return out


def _constants_of_key(designation, bearing_type, series, lubrication, arrangement, f0_given) -> dict:
    """Catalogue constants of one distinct key; an unresolved key gives the blank constants with its error."""
    if (bearing_type or "").lower() in PLAIN_TYPES:
        return dict(_BLANK)
    try:
        resolved = resolve(designation, bearing_type, series)
    except DesignationError as exc:
        return {**_BLANK, "error": str(exc)}
    if lubrication is None and not f0_given:
        return {**_BLANK, "error": "lubrication: missing; expected one of " + ", ".join(LUBRICATION_F0_COLUMN)}
    return bearing_constants(resolved, lubrication, arrangement)


def printed_size(designation: Any, what: str) -> float:
    """The ``bore`` or ``width`` [mm] a parsed designation prints (HK2016: d = 20, B = 16); NaN where there is no
    designation or it prints none (or a size of 0, which no bearing has: the cell stays blank and says so)."""
    value = getattr(designation, what, None) if designation is not None else None
    return float(value) if value else math.nan


def fill_blank(given, printed):
    """``given`` where it is a number, ``printed`` where it is NaN (scalars stay scalars)."""
    return np.where(np.isnan(given), printed, given)


def text_or_default(frame: pd.DataFrame, name: str, default: str | None) -> np.ndarray:
    """A text column as stripped strings, ``default`` for blank cells and where the column is absent (an object
    array; each distinct cell is cleaned once)."""
    if name not in frame.columns:
        return object_column(len(frame), default)
    return per_distinct(frame[name], lambda v: _stripped_or_none(v) or default)


def value_codes(values: np.ndarray) -> tuple[np.ndarray, list]:
    """An array of values as codes into its distinct values (missing values are one value, None), for
    :func:`distinct_keys`."""
    codes, uniques = pd.factorize(np.asarray(values, dtype=object), use_na_sentinel=True)
    return np.where(codes < 0, len(uniques), codes), [*uniques.tolist(), None]


def text_codes(frame: pd.DataFrame, name: str) -> tuple[np.ndarray, list[str | None]]:
    """A text column as codes into its distinct stripped texts (None for blank cells; a column of None where
    it is absent), factorized once."""
    if name not in frame.columns:
        return np.zeros(len(frame), dtype=np.int64), [None]
    if len(frame) == 1:  # one bearing: no factorization machinery for one cell
        return _one_text_code(frame[name].iat[0])
    codes, raw = column_codes(frame[name])
    texts = [_stripped_or_none(v) for v in raw] + [None]  # code -1 (missing) takes the last entry
    return np.where(codes < 0, len(raw), codes), texts


def _one_text_code(value) -> tuple[np.ndarray, list[str | None]]:
    """:func:`text_codes` of one cell: code 0 for its stripped text (None where blank)."""
    return np.zeros(1, dtype=np.int64), [_stripped_or_none(value)]


def _combined_codes(parts: list[tuple[np.ndarray, int]], size: int) -> np.ndarray:
    """One code per row for the combination of the columns' codes ((codes, number of codes) per column), in
    order of first appearance. The codes are mixed as digits of one integer and factorized once at the end;
    before the integer could pass 2^62 it is factorized, so its codes fall below the row count again."""
    combined = np.zeros(size, dtype=np.int64)
    span = 1  # the combined codes so far are below span
    for column_codes, count in parts:
        if span * count >= 1 << 62:
            combined = pd.factorize(combined, sort=False)[0].astype(np.int64)
            span = int(combined.max()) + 1 if size else 1
        combined = combined * count + column_codes
        span *= count
    return pd.factorize(combined, sort=False)[0].astype(np.int64)


#: inputs that describe a bearing and how it is mounted and lubricated, not its operating point: calc numbers its
#: rows by them once (:func:`with_bearing_groups`), and every later grouping by some of them reads those numbers
BEARING_INPUTS = ("designation", "type", "series", "lubrication", "arrangement", "d", "D", "B", "T", "d1", "D1",
                  "C0", "C", "e", "Y", "X0", "Y0", "alpha", "n_G", "f0")
#: the hidden column of calc's frame that holds those numbers
BEARING_GROUP = "_bearing_group"


def with_columns(frame: pd.DataFrame, columns: dict[str, Any]) -> pd.DataFrame:
    """``frame`` with ``columns`` (name -> per-row values) added at the end or put in place of its columns of
    those names, as ``frame.assign`` would, the arrays taken as they are: assign copies the frame's blocks first
    (4 ms for a frame of 14 columns of 10^6 rows, 0.5 ms so)."""
    merged = {name: frame[name] for name in frame.columns}
    merged.update(columns)
    return pd.DataFrame(merged, index=frame.index, copy=False)


def with_bearing_groups(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` (contract names) with the hidden column :data:`BEARING_GROUP`: one code per row for its values
    in the :data:`BEARING_INPUTS` it has. Only what is a function of those values (the catalogue's fill) may
    change them afterwards: :func:`group_codes` trusts the codes."""
    names = [name for name in BEARING_INPUTS if name in frame.columns]
    codes = group_codes(frame, names) if names else np.zeros(len(frame), dtype=np.int64)
    return with_columns(frame, {BEARING_GROUP: codes})


def bearing_rows(frame: pd.DataFrame) -> tuple[np.ndarray, np.ndarray] | None:
    """(each row's bearing, numbered 0, 1, ... in order of first appearance; the first row of each bearing) of a
    frame of more than one row that numbers its bearings (:func:`with_bearing_groups`), else None. The numbers
    are made dense again: a subset of calc's frame lacks some."""
    if BEARING_GROUP not in frame.columns or len(frame) < 2:
        return None
    numbers = frame[BEARING_GROUP].to_numpy()
    first = _first_rows_in_order(numbers)
    if first is not None:
        # the numbers are what factorizing them would give (calc's whole frame): no hash table
        return numbers, first
    bearings = pd.factorize(numbers, sort=False)[0]
    return bearings, first_rows(bearings)


def group_codes(frame: pd.DataFrame, names: list[str]) -> np.ndarray:
    """One code per row for its values in the columns ``names`` (missing values are one value), numbered in
    order of first appearance: ``groupby(names).ngroup()`` without pandas' groupby machinery
    (:func:`group_rows`)."""
    return group_rows(frame, names)[0]


def group_rows(frame: pd.DataFrame, names: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """(:func:`group_codes`, the first row of each group, as :func:`first_rows` finds it): found on the way, not
    looked for again. The text columns' codes are combined first; a number column that holds one value in each
    of those groups (a bearing's d, D, C0 for its designation) adds nothing and is only checked; from the first
    that varies inside a group on, the groups and the numbers are hashed together (:func:`_hashed_codes`).
    Where the frame numbers its bearings (:func:`with_bearing_groups`) and ``names`` are all
    :data:`BEARING_INPUTS`, only the first row of each bearing is looked at."""
    numbered = bearing_rows(frame) if set(names) <= set(BEARING_INPUTS) else None
    if numbered is not None:
        bearings, first = numbered
        codes, first_bearings = group_rows(frame[list(names)].iloc[first], names)
        # (bearings are numbered in order of first appearance: a group's first row is that of its first bearing)
        return codes[bearings], first[first_bearings]
    size = len(frame)
    text_parts = []  # (codes + 1, count + 1) of each text column: missing (-1) is a code of its own
    number_bits = []  # float columns by their bits: -0.0 and other NaNs are values of their own
    for name in names:
        if frame[name].dtype == np.float64:
            number_bits.append(np.ascontiguousarray(frame[name].to_numpy()).view(np.uint64))
        else:
            codes, uniques = column_codes(frame[name])
            text_parts.append((codes.astype(np.int64) + 1, len(uniques) + 1))
    codes = _combined_codes(text_parts, size) if text_parts else np.zeros(size, dtype=np.int64)
    first = first_rows(codes)
    for k, bits in enumerate(number_bits):
        if not np.array_equal(bits, bits[first][codes]):  # (a gather and a comparison: no hash table)
            codes = _hashed_codes(([codes.view(np.uint64)] if text_parts else []) + number_bits[k:])
            return codes, first_rows(codes)
    return codes, first


#: odd 64-bit multiplier of the hash that mixes key columns (2^64 / golden ratio)
_MIX = np.uint64(0x9E3779B97F4A7C15)
#: rows hashed at a time (two arrays of it fit a core's cache)
_HASH_BLOCK = 1 << 14


def _hashed_codes(columns: list[np.ndarray]) -> np.ndarray:
    """One code per row for its values in the 64-bit ``columns`` (a float's bits, a text's code), in order of
    first appearance: the columns mixed into one 64-bit hash, factorized once (one pass instead of one per
    column). Rows of one code are checked to hold the same bits in every column; on a hash collision the
    columns are factorized one by one. Equal floats of other bits (0.0 and -0.0, NaNs of other payloads) get
    codes of their own: more groups, never fewer."""
    if len(columns) == 1:
        return pd.factorize(columns[0], sort=False)[0].astype(np.int64)
    size = len(columns[0])
    mixed = np.zeros(size, dtype=np.uint64)
    shifted = np.empty(min(size, _HASH_BLOCK), dtype=np.uint64)
    for start in range(0, size, _HASH_BLOCK):  # a block stays in the cache through all the columns
        block = mixed[start:start + _HASH_BLOCK]
        high = shifted[:len(block)]
        for column in columns:
            block ^= column[start:start + _HASH_BLOCK]
            block *= _MIX  # wraps modulo 2^64; a product carries bits upwards only ...
            np.right_shift(block, np.uint64(31), out=high)
            block ^= high  # ... so the high ones (a float's exponent) are folded down
    codes = pd.factorize(mixed, sort=False)[0].astype(np.int64)
    first = first_rows(codes)
    if all(np.array_equal(column, column[first][codes]) for column in columns):
        return codes
    parts = [(c, int(c.max()) + 1 if len(c) else 1)
             for c in (pd.factorize(column, sort=False)[0] for column in columns)]
    return _combined_codes(parts, len(columns[0]))


def nonblank(values: Any, size: int) -> np.ndarray:
    """Where a per-row text (a categorical by its codes, an object array, or one value for all rows) is neither
    missing nor empty, as a bool array of ``size``."""
    if isinstance(values, pd.Categorical):
        filled = np.array([bool(c) for c in values.categories] + [False], dtype=bool)  # code -1: missing
        return filled[values.codes]
    cells = np.broadcast_to(np.asarray(values, dtype=object), (size,))
    return (cells != "") & (cells != None)  # noqa: E711 (element-wise)


def text_in(values: Any, names) -> np.ndarray:
    """Where a per-row text (a categorical by its codes, an object array, or one value) is one of ``names``."""
    if isinstance(values, pd.Categorical):
        member = np.isin(values.categories.to_numpy(dtype=object), list(names))
        return np.append(member, False)[values.codes]  # code -1 (missing): the appended False
    return np.isin(np.asarray(values, dtype=object), list(names))


def first_rows(codes: np.ndarray) -> np.ndarray:
    """The position of the first row of each code, for codes numbered 0, 1, ... in order of first appearance
    (:func:`group_codes`): no sort, no hash table."""
    first = _first_rows_in_order(codes)
    if first is None:  # codes 0, 1, ... in another order: each code's last write from the end is its first row
        first = np.empty(int(codes.max()) + 1, dtype=np.intp)
        first[codes[::-1]] = np.arange(len(codes))[::-1]
    return first


def _first_rows_in_order(codes: np.ndarray) -> np.ndarray | None:
    """The first row of each code where the codes are 0, 1, ... in order of first appearance (what pd.factorize
    gives), else None. Such a code first appears where the running maximum grows, and it grows by one each time:
    K codes, K steps (a running maximum and a comparison: a third of the time of scattering the positions)."""
    if not len(codes):
        return np.zeros(0, dtype=np.intp)
    running = np.maximum.accumulate(codes)
    grows = np.empty(len(codes), dtype=bool)
    grows[0] = True
    np.not_equal(running[1:], running[:-1], out=grows[1:])
    first = np.flatnonzero(grows)
    if codes[0] != 0 or len(first) != int(running[-1]) + 1 or codes.min() < 0:
        return None
    return first


def distinct_keys(parts: list[tuple[np.ndarray, list]]) -> tuple[np.ndarray, list[tuple]]:
    """Per row the code of its key, and the distinct keys (tuples) in order of first appearance.

    ``parts`` are (codes, values) of each key column (:func:`text_codes`).
    The codes are combined column by column and re-factorized after each, so
    they stay below the row count: no Python object per row.
    """
    size = len(parts[0][0])
    combined = _combined_codes([(column_codes, len(values)) for column_codes, values in parts], size)
    uniques = [tuple(values[column_codes[row]] for column_codes, values in parts)
               for row in first_rows(combined).tolist()]
    return combined, uniques


def build_support_arrays(keys: pd.DataFrame | Mapping[str, Any], numbers: dict[str, Any]) -> SupportArrays:
    """The support arrays of a table (one row per support) or of one bearing at many operating points.

    ``keys`` holds the text columns of :data:`KEY_INPUTS` that are given,
    one row per support, or a single row for one bearing, or one bearing's
    texts as a mapping (the unit-aware API: no frame of one row); ``numbers``
    maps the names of :data:`NUMBER_INPUTS` to float arrays of one length or
    scalars (missing names are NaN, Fr and Fa default to 0). The rows'
    count is the length of the arrays (of ``keys`` where all are scalars).
    """
    key_rows = 1 if isinstance(keys, Mapping) else len(keys)
    lengths = {np.size(v) for v in numbers.values() if np.ndim(v) > 0}
    size = lengths.pop() if lengths else key_rows
    if lengths or (key_rows not in (1, size)):
        raise ValueError("build_support_arrays: keys and numbers must have one length (or one key row)")
    num: dict[str, Any] = {}
    for name in NUMBER_INPUTS:
        value = numbers.get(name, math.nan)
        value = np.asarray(value, dtype=float)  # 0-d for a scalar: numpy division rules (x/0 = inf) everywhere
        if name in ("Fr", "Fa") and np.isnan(value).any():
            value = np.where(np.isnan(value), 0.0, value)  # a blank load is 0
        num[name] = value
    if key_rows == size:
        f0_given = ~np.isnan(np.broadcast_to(num["f0"], (size,)))
    else:  # one bearing: f0 is given for all its points or for none
        f0_given = np.array([not np.all(np.isnan(num["f0"]))])
    one_key_row = key_rows == 1
    numbered = None
    if isinstance(keys, pd.DataFrame) and key_rows == size:  # (the isinstance narrows keys for the type checker)
        numbered = bearing_rows(keys)
        if numbered is not None:  # calc's frame: the keys of each bearing's first row
            bearings, first = numbered
            keys, f0_given = keys.iloc[first], f0_given[first]
    if isinstance(keys, Mapping):
        parts = [_one_text_code(keys.get(name)) for name in KEY_INPUTS]
    else:
        parts = [text_codes(keys, name) for name in KEY_INPUTS]
    arrangement = KEY_INPUTS.index("arrangement")
    parts[arrangement] = (parts[arrangement][0], [text or "single" for text in parts[arrangement][1]])
    codes, uniques = distinct_keys([*parts, (f0_given.astype(np.int64), [False, True])])
    if numbered is not None:
        codes = codes[bearings]
    per_key = [_constants_of_key(*key) for key in uniques]
    plain_keys = np.array([(key[1] or "").lower() in PLAIN_TYPES for key in uniques], dtype=bool)
    notes_of_key = np.empty(len(per_key), dtype=object)
    for k, constants_of_key in enumerate(per_key):  # one by one: numpy would read a list of tuples as 2-D
        notes_of_key[k] = tuple(constants_of_key["notes"])
    noted_key = np.array([bool(n) for n in notes_of_key], dtype=bool)

    if len(uniques) == 1 and one_key_row:
        def spread(name, dtype):
            return np.asarray(per_key[0][name], dtype=dtype)[()]

        def spread_text(name):
            return spread(name, object)
        plain = np.broadcast_to(plain_keys[0], (size,))
        notes, noted = notes_of_key, noted_key
    else:
        def spread(name, dtype):
            values = np.array([c[name] for c in per_key], dtype=dtype)
            if len(values) and np.array_equal(values, np.full_like(values, values[0]), equal_nan=dtype is float):
                return values[0]  # one value for every key: a scalar, not a copy per row
            return values[codes]

        split_alike: dict = {}

        def spread_text(name):
            # a categorical: numpy compares it by its codes (np.equal(s.seal, 'contact') 0.1 ms, not 20 ms, for
            # 10^6 rows) and takes rows of it without touching a Python object
            return coded_categorical(codes, [c[name] for c in per_key], shared=split_alike)
        plain = plain_keys[codes]
        noted = noted_key[codes]
        # a key's notes on every row of it; where no key has notes, the empty notes of the first key on all rows
        notes = notes_of_key[codes] if noted_key.any() else np.broadcast_to(notes_of_key[:1], (size,))
    constants = {name: spread_text(name) for name in _TEXT}
    constants.update({name: spread(name, float) for name in _FLOAT})
    constants.update({name: spread(name, bool) for name in _BOOL})
    constants["f1_basis"] = spread("f1_basis", int)
    # bore and width printed in the designation fill empty cells (HK2016: d = 20, B = 16)
    for name, printed in (("d", "bore"), ("B", "width")):
        if np.isnan(num[name]).any():
            num[name] = fill_blank(num[name], spread(printed, float))
    if np.ndim(num["n"]) == 0:
        num["n"] = np.full(size, num["n"])  # the speed spans the rows
    return SupportArrays(size=size, **num, **constants, plain=np.asarray(plain, dtype=bool), notes=notes,
                         noted=noted)
