"""The support arrays: one builder for tables, for one bearing at many points, and for subsets."""
import dataclasses
import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, strategies as st

from bearingheat.calc import supports as sp
from bearingheat.calc.table import calc
from bearingheat.catalogue import friction as catalogue


def _table():
    keys = pd.DataFrame({"designation": ["6208", "NU208-E", "6208", "nonsense", "30208-A"],
                         "lubrication": ["oil_bath"] * 5})
    numbers = {"D": np.array([80.0, 80.0, 80.0, 80.0, 80.0]), "n": np.full(5, 1500.0),
               "Fr": np.array([1000.0, np.nan, 2000.0, 0.0, 500.0])}
    return sp.build_support_arrays(keys, numbers)


def test_table_rows_get_their_catalogue_constants():
    s = _table()
    assert s.size == 5
    assert list(s.bearing_type) == ["deep_groove_ball", "cylindrical_roller", "deep_groove_ball", "",
                                    "tapered_roller"]
    assert s.d[:3].tolist() == [40.0, 40.0, 40.0]           # the bore printed in the designation
    assert s.Fr.tolist() == [1000.0, 0.0, 2000.0, 0.0, 500.0]   # a blank load is 0
    assert s.f0_table[0] == s.f0_table[2] == 2.0
    assert list(s.resolved) == [True, True, True, False, True]
    assert s.error[3] == ("designation: 'nonsense' matches no row of the Schaeffler catalogue tables; give type and series "
                          "explicitly instead") and s.error[0] == ""
    assert s.p1_rule[0] == "radial_ball" and s.p1_rule[1] == ""


def test_each_distinct_bearing_is_resolved_once(monkeypatch):
    calls = []
    real = catalogue.resolve

    def counting(*args, **kwargs):
        calls.append(args)
        return real(*args, **kwargs)

    monkeypatch.setattr(sp, "resolve", counting)
    keys = pd.DataFrame({"designation": ["6208", "6210"] * 500, "lubrication": ["grease"] * 1000})
    sp.build_support_arrays(keys, {"n": np.full(1000, 100.0)})
    assert sorted(calls) == [("6208", None, None), ("6210", None, None)]


def test_one_bearing_keeps_its_constants_scalar():
    keys = pd.DataFrame({"designation": ["6205"], "lubrication": ["grease"]})
    s = sp.build_support_arrays(keys, {"n": np.linspace(10, 5000, 1000), "D": 52.0})
    assert s.size == 1000 and s.n.shape == (1000,)
    assert np.ndim(s.f0_table) == 0 and float(s.f0_table) == 1.3
    assert np.ndim(s.D) == 0 and np.ndim(s.d) == 0 and float(s.d) == 25.0
    assert len(s.notes) == 1


def test_a_constant_every_bearing_shares_stays_scalar():
    keys = pd.DataFrame({"designation": ["6208", "6210"] * 3, "lubrication": ["grease"] * 6})
    s = sp.build_support_arrays(keys, {"n": np.full(6, 100.0)})
    assert np.ndim(s.bearings) == 0 and float(s.bearings) == 1.0   # both single bearings
    assert np.ndim(s.m2) == 0 and not s.m2                          # neither is a cylindrical roller bearing
    assert np.ndim(s.kB) == 0 and np.isnan(s.kB)
    assert s.d.tolist() == [40.0, 50.0] * 3                         # bores differ: one per row


def test_an_empty_table_gives_the_friction_columns_of_a_full_one():
    """No bearing to resolve: the constants of no key. (The heat balance's n_thr comes only where the catalogue
    filled B into some row; bearingheat.calc.distributed gives an empty partition the columns of the others.)"""
    table = pd.DataFrame({"designation": ["6208"], "D [mm]": [80.0], "lubrication": ["grease"],
                          "n [rpm]": [1500.0], "Fr [kN]": [1.0], "nu [mm^2/s]": [20.0]})
    full, empty = calc(table), calc(table.iloc[:0])
    assert len(empty) == 0
    assert list(empty.columns) == [c for c in full.columns if c != "n_thr [1/min]"]
    assert all(str(empty[c].dtype) == str(full[c].dtype) for c in empty.columns)


def test_texts_that_split_the_keys_alike_share_their_row_codes():
    codes = np.array([0, 1, 2, 1, 0, 2])
    shared: dict = {}
    label = sp.coded_categorical(codes, ["6208", "6210", "NU208"], shared=shared)
    series = sp.coded_categorical(codes, ["62", "62x", "NU2"], shared=shared)
    seal = sp.coded_categorical(codes, ["open", "open", "open"], shared=shared)
    kind = sp.coded_categorical(codes, ["ball", "ball", None], shared=shared)
    assert list(label) == ["6208", "6210", "NU208", "6210", "6208", "NU208"]
    assert list(series) == ["62", "62x", "NU2", "62x", "62", "NU2"]
    assert list(seal) == ["open"] * 6 and list(kind.isna()) == [False, False, True, False, False, True]
    assert np.shares_memory(label.codes, series.codes) and not label.codes.flags.writeable
    assert len(shared) == 3  # label and series, seal, kind


def test_take_keeps_rows_and_scalars():
    s = _table()
    sub = s.take(np.array([4, 0]))
    assert sub.size == 2 and list(sub.bearing_type) == ["tapered_roller", "deep_groove_ball"]
    assert sub.Fr.tolist() == [500.0, 1000.0] and len(sub.notes) == 2
    one = sp.build_support_arrays(pd.DataFrame({"designation": ["6205"], "lubrication": ["grease"]}),
                                  {"n": np.array([1.0, 2.0, 3.0])})
    assert one.take(np.array([2])).n.tolist() == [3.0] and np.ndim(one.take(np.array([2])).f0_table) == 0


@pytest.mark.parametrize("keys, error", [
    ({"designation": ["6205"]}, "lubrication: missing; expected one of grease, oil_mist, oil_bath, circulating_oil"),
    ({"designation": ["6205"], "lubrication": ["water"]},
     "lubrication: 'water' is not one of grease, oil_mist, oil_bath, circulating_oil"),
    ({"designation": ["6205"], "lubrication": ["grease"], "arrangement": ["stacked"]},
     "arrangement: 'stacked' is not one of single, paired"),
    ({"type": ["deep_groove_ball"], "lubrication": ["grease"]}, "series: missing; give type and series together"),
])
def test_key_errors(keys, error):
    s = sp.build_support_arrays(pd.DataFrame(keys), {"n": np.array([100.0])})
    assert str(s.error[0] if np.ndim(s.error) else s.error) == error


def test_f0_given_needs_no_lubrication():
    s = sp.build_support_arrays(pd.DataFrame({"designation": ["6205"]}), {"n": np.array([100.0]), "f0": 2.0})
    assert (s.error[0] if np.ndim(s.error) else s.error) == "" and math.isnan(float(s.f0_table))


def test_plain_bushings_are_marked_and_not_resolved():
    keys = pd.DataFrame({"type": ["plain_bushing", None], "designation": [None, "6205"],
                         "lubrication": [None, "grease"]})
    s = sp.build_support_arrays(keys, {"n": np.array([100.0, 100.0])})
    assert s.plain.tolist() == [True, False]
    assert s.error[0] == "" and not s.resolved[0]


def test_calc_result_cells_can_be_changed_and_the_input_stays_as_it_was():
    """calc builds its frames from its own arrays without copying them into blocks: every cell of the result can
    be set (no read-only view of calc's internal frames), and that changes neither the input table nor a second
    result."""
    import bearingheat as bh

    table = pd.DataFrame({"designation": ["6205", "6206"], "d [mm]": [25.0, 30.0], "D [mm]": [52.0, 62.0],
                          "C0 [kN]": [7.8, 11.2], "lubrication": ["oil_bath", "grease"], "n [rpm]": [3000.0, 1500.0],
                          "Fr [kN]": [2.0, 3.0], "nu [mm^2/s]": [12.0, 20.0], "f1": [np.nan, np.nan],
                          "T_amb [degC]": [20.0, 20.0], "B [mm]": [15.0, 16.0]})
    before = table.copy()
    first, second = bh.calc(table), bh.calc(table)
    for column in first.columns:
        first.loc[0, column] = 0 if pd.api.types.is_numeric_dtype(first[column]) else "changed"
    pd.testing.assert_frame_equal(table, before)
    pd.testing.assert_frame_equal(second, bh.calc(table))
    assert set(first.iloc[0].tolist()) == {0, "changed"} and second.loc[0, "status"] == "ok"


@pytest.mark.parametrize("distinct", [3, 50_000])
def test_group_codes_are_pandas_groups_in_order_of_first_appearance(distinct):
    """group_codes mixes the columns' codes as digits of one integer (factorized once, or again before it could
    pass 2^62: five columns of 50 000 distinct numbers): the groups of pandas' groupby, numbered as they first
    appear, missing values one group."""
    rng = np.random.default_rng(7)
    rows = 60_000
    frame = pd.DataFrame({f"x{k}": rng.integers(0, distinct, rows).astype(float) for k in range(5)})
    frame.loc[rng.integers(0, rows, 500), "x2"] = np.nan
    frame["text"] = pd.Categorical.from_codes(rng.integers(-1, 3, rows), categories=["a", "b", "c"])
    names = [*frame.columns]
    expected = frame.groupby(names, sort=False, dropna=False, observed=True).ngroup().to_numpy()
    assert np.array_equal(sp.group_codes(frame, names), expected)
    codes, first = sp.group_rows(frame, names)  # (the first rows found on the way are those of the codes)
    assert np.array_equal(codes, expected) and np.array_equal(first, sp.first_rows(expected))


_TEXTS = st.sampled_from(["6205", "6206", "NU208-E", None])
_NUMBERS = st.sampled_from([25.0, 30.0, np.nan, 0.0, -0.0])


@given(st.lists(st.tuples(_TEXTS, _TEXTS, _NUMBERS, _NUMBERS), max_size=30), st.booleans())
def test_group_codes_are_the_distinct_keys_in_order_of_first_appearance(rows, numbers_follow_texts):
    """Texts combined first, numbers checked inside their groups, hashed with them from the first that varies:
    whichever way, one code per distinct (texts, float bits) key, numbered as the keys first appear (a blank
    text is one value; 0.0 and -0.0 have other bits, so they are other keys)."""
    if numbers_follow_texts:  # d and D a function of the designation: no number splits a group
        rows = [(t, u, {"6205": 25.0, "6206": 30.0}.get(t, np.nan), 52.0) for t, u, _, _ in rows]
    frame = pd.DataFrame(rows, columns=["designation", "series", "d", "D"]).astype({"d": float, "D": float})
    frame["designation"] = pd.Categorical(frame["designation"])
    keys = [(None if pd.isna(t) else t, None if pd.isna(u) else u, np.float64(x).view(np.uint64).item(),
             np.float64(y).view(np.uint64).item())
            for t, u, x, y in zip(frame["designation"], frame["series"], frame["d"], frame["D"])]
    numbering: dict = {}
    expected = [numbering.setdefault(key, len(numbering)) for key in keys]
    assert sp.group_codes(frame, ["designation", "series", "d", "D"]).tolist() == expected
    codes, first = sp.group_rows(frame, ["designation", "series", "d", "D"])
    assert codes.tolist() == expected and first.tolist() == [expected.index(k) for k in range(len(numbering))]
    # where the frame numbers its bearings, the groups of some of their inputs are found from each bearing's first row
    numbered = sp.with_bearing_groups(frame)
    for names in (["designation"], ["series", "D"], ["d"]):
        codes, first = sp.group_rows(numbered, names)
        assert np.array_equal(codes, sp.group_codes(frame, names)) and np.array_equal(first, sp.first_rows(codes))


def test_group_codes_survive_a_hash_collision(monkeypatch):
    """Rows whose hashes collide are told apart by the check against their group's first row: with a hash that
    maps everything to one value, group_codes still gives pandas' groups."""
    rng = np.random.default_rng(11)
    frame = pd.DataFrame({"a": rng.integers(0, 4, 1000).astype(float), "b": rng.integers(0, 3, 1000).astype(float),
                          "text": pd.Categorical.from_codes(rng.integers(-1, 2, 1000), categories=["x", "y"])})
    monkeypatch.setattr(sp, "_MIX", np.uint64(0))  # every row hashes to 0
    names = [*frame.columns]
    expected = frame.groupby(names, sort=False, dropna=False, observed=True).ngroup().to_numpy()
    assert np.array_equal(sp.group_codes(frame, names), expected)
    assert np.array_equal(sp.group_rows(frame, names)[1], sp.first_rows(expected))


def test_bearing_groups_give_the_groups_of_the_columns_themselves():
    """A frame that numbers its bearings (with_bearing_groups) groups by any of the bearing inputs through those
    numbers; the groups are the ones of the columns themselves, for the whole frame and for a subset of its rows
    (whose numbers are no longer 0, 1, ...)."""
    rng = np.random.default_rng(5)
    rows = 3000
    frame = pd.DataFrame({"designation": pd.Categorical.from_codes(rng.integers(-1, 4, rows),
                                                                   categories=["6205", "6206", "NU208-E", "30208-A"]),
                          "d": rng.integers(0, 3, rows) * 5.0 + 25, "C0": rng.choice([7.8, np.nan, 11.2], rows),
                          "n": rng.uniform(0, 3000, rows)})
    numbered = sp.with_bearing_groups(frame)
    assert sp.BEARING_GROUP in numbered.columns and "n" not in sp.BEARING_INPUTS
    # the support arrays read the numbers for their keys and f0_given, the reference speed and the fill for theirs
    from bearingheat.calc.fill import FILLED
    from bearingheat.calc.reference_speed import REFERENCE_KEYS
    assert {*sp.KEY_INPUTS, "f0", *REFERENCE_KEYS, "designation", *FILLED} <= set(sp.BEARING_INPUTS)
    subset = np.sort(rng.choice(rows, 700, replace=False))
    for names in (["designation", "d", "C0"], ["designation"], ["d", "C0"], ["C0"]):
        assert np.array_equal(sp.group_codes(numbered, names), sp.group_codes(frame, names))
        assert np.array_equal(sp.group_codes(numbered.iloc[subset], names), sp.group_codes(frame.iloc[subset], names))
    # a grouping by an operating input does not read the bearing numbers
    assert np.array_equal(sp.group_codes(numbered, ["d", "n"]), sp.group_codes(frame, ["d", "n"]))
    with_keys = numbered.assign(lubrication="oil_bath")
    supports = sp.build_support_arrays(with_keys[["designation", "lubrication", sp.BEARING_GROUP]],
                                       {"d": numbered["d"].to_numpy(), "n": numbered["n"].to_numpy()})
    plain = sp.build_support_arrays(with_keys[["designation", "lubrication"]],
                                    {"d": numbered["d"].to_numpy(), "n": numbered["n"].to_numpy()})
    for name in ("f0_table", "f1_a", "f1_x", "X0_table", "Y0_table"):
        assert np.array_equal(getattr(supports, name), getattr(plain, name), equal_nan=True), name
    assert list(supports.bearing_type) == list(plain.bearing_type)


@pytest.mark.parametrize("dtype", ["str", object, "string[python]", "string[pyarrow]"])
def test_column_codes_are_pandas_factorize(dtype):
    """column_codes hashes an Arrow text column of one chunk with pyarrow: the same codes and distinct values, in
    order of first appearance, as pd.factorize; missing cells -1, an empty text a value of its own."""
    column = pd.Series(["b", None, "a", "b", " b", "", np.nan, "a"], dtype=dtype)
    codes, uniques = sp.column_codes(column)
    expected_codes, expected_uniques = pd.factorize(column, use_na_sentinel=True)
    assert codes.tolist() == expected_codes.tolist() == [0, -1, 1, 0, 2, 3, -1, 1]
    assert list(uniques) == list(expected_uniques) == ["b", "a", " b", ""]


def _oil(table):
    return table.drop(columns=["nu [mm^2/s]"]).assign(**{"nu40 [mm^2/s]": 68.0, "nu100 [mm^2/s]": 8.6})


@pytest.mark.parametrize("case", ["demo", "skf", "mixed", "oil", "filled"])
def test_calc_groups_by_its_bearing_numbers_as_by_the_columns(case, monkeypatch):
    """calc numbers its rows by bearing once and every later grouping reads those numbers: the fill, the
    reference speed and the support arrays group exactly as they would by their own columns at that point
    (nothing between the numbering and them changes a bearing input except the fill, which fills by bearing).
    Checked on the demos, a mixed-model table, oil data and a table whose blank cells the catalogue fills."""
    from pathlib import Path

    import bearingheat as bh
    from bearingheat.calc import fill, models, reference_speed

    examples = Path(__file__).resolve().parents[2] / "examples"
    demo = pd.read_csv(examples / "gearbox_shaft.csv")
    skf = pd.read_csv(examples / "gearbox_shaft_skf.csv")
    tables = {"demo": (pd.concat([demo] * 3, ignore_index=True), {}), "skf": (skf, {"model": "skf"}),
              "mixed": (skf.assign(model=["skf", "schaeffler"] * (len(skf) // 2) + ["skf"] * (len(skf) % 2)), {}),
              "oil": (_oil(pd.concat([demo] * 2, ignore_index=True)), {})}
    filled = pd.concat([demo] * 4, ignore_index=True)
    filled.loc[::3, "D [mm]"] = np.nan
    filled.loc[1::4, "C0 [kN]"] = np.nan
    filled.loc[::5, "B [mm]"] = 99.0
    tables["filled"] = (filled, {})
    checked = []

    def checked_group_rows(frame, names):
        codes, first = sp.group_rows(frame, names)
        if sp.BEARING_GROUP in frame.columns:
            by_columns, first_by_columns = sp.group_rows(frame.drop(columns=[sp.BEARING_GROUP]), names)
            assert np.array_equal(codes, by_columns) and np.array_equal(first, first_by_columns), names
            checked.append(tuple(names))
        return codes, first

    original_build = sp.build_support_arrays

    def checked_build(keys, numbers):
        supports = original_build(keys, numbers)
        if sp.BEARING_GROUP in keys.columns:
            plain = original_build(keys.drop(columns=[sp.BEARING_GROUP]), numbers)
            for name in ("f0_table", "f1_a", "f1_x", "X0_table", "Y0_table", "kB", "bearings", "f1_basis", "m2"):
                assert np.array_equal(np.broadcast_to(getattr(supports, name), (supports.size,)),
                                      np.broadcast_to(getattr(plain, name), (plain.size,)), equal_nan=True), name
            for name in ("bearing_type", "p1_rule", "f0_basis", "label", "error"):
                assert list(np.broadcast_to(np.asarray(getattr(supports, name), dtype=object), (supports.size,))) \
                    == list(np.broadcast_to(np.asarray(getattr(plain, name), dtype=object), (plain.size,))), name
            checked.append("support arrays")
        return supports

    monkeypatch.setattr(fill, "group_rows", checked_group_rows)
    monkeypatch.setattr(reference_speed, "group_rows", checked_group_rows)
    monkeypatch.setattr(models, "build_support_arrays", checked_build)
    table, options = tables[case]
    assert (bh.calc(table, **options)["status"] != "error").all()
    assert "support arrays" in checked and any(isinstance(c, tuple) for c in checked)


def test_a_printed_size_of_zero_is_no_size():
    """HK2000 parses to d = 20 and B = 0: the width stays blank (and the row says B is missing) in the friction
    model and in the reference speed alike, which read it through this one function."""
    from bearingheat.catalogue.designation import parse_designation
    hk = parse_designation("HK2000")
    assert sp.printed_size(hk, "bore") == 20.0 and math.isnan(sp.printed_size(hk, "width"))
    assert sp.printed_size(parse_designation("HK2016"), "width") == 16.0
    assert math.isnan(sp.printed_size(None, "bore")) and math.isnan(sp.printed_size(parse_designation("6208"), "width"))


@pytest.mark.parametrize("numbers, bearings, first", [
    ([0, 1, 0, 2, 1], [0, 1, 0, 2, 1], [0, 1, 3]),   # calc's whole frame: its own numbers
    ([1, 2, 1, 2], [0, 1, 0, 1], [0, 1]),             # a subset that lacks bearing 0
    ([2, 0, 1, 0], [0, 1, 2, 1], [0, 1, 2]),          # a subset whose bearings come in another order
    ([0, 2, 2, 0], [0, 1, 1, 0], [0, 1]),             # one that lacks a number in between
])
def test_bearing_rows_are_dense_in_order_of_first_appearance(numbers, bearings, first):
    frame = pd.DataFrame({sp.BEARING_GROUP: np.array(numbers, dtype=np.int64)})
    got_bearings, got_first = sp.bearing_rows(frame)
    assert got_bearings.tolist() == bearings and got_first.tolist() == first
    assert got_bearings.tolist() == pd.factorize(np.array(numbers), sort=False)[0].tolist()


@pytest.mark.parametrize("codes", [
    [0, 0, 1, 0, 2, 2, 1, 3],   # in order of first appearance (pd.factorize's numbering): the running maximum
    [1, 0, 1, 2],               # dense, another order: the scatter
    [0, 2, 1, 2, 0],            # code 2 before code 1
    [0],
    [],
])
def test_first_rows_is_the_first_position_of_each_code(codes):
    codes = np.array(codes, dtype=np.int64)
    by_hand = [codes.tolist().index(k) for k in range(int(codes.max()) + 1 if len(codes) else 0)]
    assert sp.first_rows(codes).tolist() == by_hand


@given(st.lists(st.integers(-3, 6), max_size=40), st.permutations(range(10)))
def test_first_rows_and_bearing_rows_agree_with_factorize(values, relabel):
    """Codes from pd.factorize (in order of first appearance) and the same codes relabelled (dense, other
    order): first_rows gives each code's first position; bearing_rows numbers a frame as factorize does."""
    codes = pd.factorize(np.array(values, dtype=np.int64), sort=False)[0].astype(np.int64)
    relabelled = np.array(relabel, dtype=np.int64)[codes] if len(codes) else codes
    for numbering in (codes, relabelled):
        dense = pd.factorize(numbering, sort=False)[0]
        present = sorted(set(numbering.tolist()))
        if present == list(range(len(present))):  # every code there: first_rows' contract
            assert sp.first_rows(numbering).tolist() == [numbering.tolist().index(k) for k in present]
        if len(numbering) >= 2:
            bearings, first = sp.bearing_rows(pd.DataFrame({sp.BEARING_GROUP: numbering}))
            assert bearings.tolist() == dense.tolist()
            assert first.tolist() == [dense.tolist().index(k) for k in range(dense.max() + 1)]


def test_one_bearings_texts_as_a_mapping_give_the_arrays_of_a_one_row_frame():
    texts = {"designation": " 6208 ", "type": None, "series": None, "lubrication": "grease", "arrangement": None}
    numbers = {"n": np.linspace(100.0, 5000.0, 7), "nu": 20.0, "Fr": np.array([1.0, np.nan, 3, 4, 5, 6, 7]) * 1e3}
    from_mapping = sp.build_support_arrays(texts, numbers)
    from_frame = sp.build_support_arrays(pd.DataFrame({k: [v] for k, v in texts.items()}), numbers)
    for f in dataclasses.fields(sp.SupportArrays):
        a, b = getattr(from_mapping, f.name), getattr(from_frame, f.name)
        if f.name == "extra":
            assert a == b
        elif isinstance(a, np.ndarray) and a.dtype.kind == "f" or isinstance(a, float):
            np.testing.assert_array_equal(a, b, err_msg=f.name)  # NaN equals NaN here
        else:
            assert np.asarray(a, dtype=object).tolist() == np.asarray(b, dtype=object).tolist(), f.name
    assert from_mapping.Fr.tolist() == [1000.0, 0.0, 3000.0, 4000.0, 5000.0, 6000.0, 7000.0]  # a blank load is 0


@pytest.mark.parametrize("cells", [
    ["oil_bath"] * 200,                      # one text: no hashing
    [""] * 5,
    ["oil_bath"] * 199 + ["grease"],          # one other text at the end: the full comparison finds it
    ["oil_bath"] * 100 + [None] * 100,        # a blank cell is missing (code -1), not the text
    ["grease", "oil_bath"] * 100,
    ["x"],
])
def test_column_codes_of_an_arrow_text_column_are_factorize_codes(cells):
    column = pd.Series(pd.array(cells, dtype="string[pyarrow]"))
    codes, uniques = sp.column_codes(column)
    expected_codes, expected_uniques = pd.factorize(pd.Series(cells, dtype=object), use_na_sentinel=True)
    assert codes.tolist() == expected_codes.tolist() and list(uniques) == list(expected_uniques)
