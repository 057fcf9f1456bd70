"""Parquet and Arrow/Feather tables: round trips with units, calc on them, and refusals."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow.parquet as parquet
import pytest

from bearingheat.cli import main
from bearingheat.errors import InputError
from bearingheat.io.arrow import column_units, read_arrow, write_arrow
from bearingheat.io.tables import calc_csv, write_table

DEMO = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"


@pytest.mark.parametrize("suffix", [".parquet", ".arrow", ".feather"])
def test_calc_results_round_trip_with_their_units(tmp_path, suffix):
    result = calc_csv(DEMO)
    path = write_table(result, tmp_path / f"out{suffix}")
    back = read_arrow(path)
    assert list(back.columns) == list(result.columns)
    for column in result.columns:
        if pd.api.types.is_float_dtype(result[column]):
            np.testing.assert_array_equal(back[column].to_numpy(), result[column].to_numpy())
        else:
            assert back[column].fillna("").astype(str).tolist() == result[column].fillna("").astype(str).tolist()
    units = column_units(path)
    assert units["MR [N*mm]"] == "N*mm" and units["Fr [kN]"] == "kN" and units["status"] == ""


def test_parquet_schema_carries_the_units(tmp_path):
    path = write_table(pd.DataFrame({"n [rpm]": [1500.0], "id": ["a"]}), tmp_path / "t.parquet")
    schema = parquet.read_schema(path)
    assert schema.field("n [rpm]").metadata == {b"unit": b"rpm"}


def test_calc_reads_parquet_as_it_reads_csv(tmp_path):
    source = tmp_path / "in.parquet"
    write_arrow(pd.read_csv(DEMO), source)
    from_csv, from_parquet = calc_csv(DEMO), calc_csv(source)
    np.testing.assert_array_equal(from_parquet["MR [N*mm]"].to_numpy(), from_csv["MR [N*mm]"].to_numpy())
    assert main(["calc", str(source), "-o", str(tmp_path / "out.parquet"), "-q"]) == 0
    assert read_arrow(tmp_path / "out.parquet")["status"].tolist() == from_csv["status"].tolist()


def test_an_unknown_output_suffix_is_refused_before_any_work(tmp_path, capsys):
    assert main(["calc", str(DEMO), "-o", str(tmp_path / "out.txt")]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat calc: error: {tmp_path / 'out.txt'}: cannot write a .txt; the output formats are .csv, "
        ".parquet, .arrow, .feather, .xlsx, .xlsm\n")
    assert not (tmp_path / "out.txt").exists()


def test_a_damaged_parquet_file_is_named(tmp_path):
    bad = tmp_path / "bad.parquet"
    bad.write_bytes(b"not parquet at all")
    with pytest.raises(InputError) as info:
        read_arrow(bad)
    assert str(info.value).startswith(f"{bad}: not a readable .parquet table (")


@pytest.mark.parametrize("suffix", [".parquet", ".arrow", ".feather"])
def test_a_column_named_twice_is_named(tmp_path, suffix):
    """As in a CSV: pyarrow keeps both columns of one name (Feather gave an AttributeError, Parquet a message of
    its own about dot paths)."""
    import pyarrow as pa
    import pyarrow.feather as feather

    demo = pd.read_csv(DEMO)
    columns = list(demo.columns)
    position = columns.index("Fr [kN]")
    arrays = [pa.array(demo[c]) for c in columns]
    arrays.insert(position + 1, pa.array(demo["Fr [kN]"]))
    table = pa.Table.from_arrays(arrays, names=columns[:position + 1] + ["Fr [kN]"] + columns[position + 1:])
    path = tmp_path / f"twice{suffix}"
    if suffix == ".parquet":
        parquet.write_table(table, path)
    else:
        feather.write_feather(table, path)
    with pytest.raises(InputError) as info:
        read_arrow(path)
    assert str(info.value) == (f"{path}: column 'Fr [kN]' appears twice (columns {position + 1} and {position + 2}); "
                               "keep one")


def test_an_index_pandas_stored_in_the_file_comes_back_as_columns(tmp_path, capsys):
    """``df.set_index('id').to_parquet()`` stores the ids as pandas' index: calc dropped them (read_arrow gave
    them as the index, calc's results have none). A named index now comes back as columns, first, as
    ``reset_index()`` puts them (a named range of row numbers too); an unnamed one (the row labels pandas keeps)
    is dropped, as ``to_csv(index=False)`` drops it."""
    demo = pd.read_csv(DEMO)
    demo.set_index("id").to_parquet(tmp_path / "named.parquet")
    back = read_arrow(tmp_path / "named.parquet")
    assert list(back.columns) == list(demo.columns) and back["id"].tolist() == demo["id"].tolist()
    assert list(back.index) == list(range(len(demo)))
    assert main(["calc", str(tmp_path / "named.parquet"), "-o", str(tmp_path / "out.csv"), "-q"]) == 0
    assert pd.read_csv(tmp_path / "out.csv")["id"].tolist() == demo["id"].tolist()
    assert calc_csv(tmp_path / "named.parquet")["id"].tolist() == demo["id"].tolist()
    demo.set_index(pd.Index([5, 3, 1, 0, 2, 4])).to_parquet(tmp_path / "unnamed.parquet")
    assert list(read_arrow(tmp_path / "unnamed.parquet").columns) == list(demo.columns)
    demo.set_index(["id", "designation"]).to_parquet(tmp_path / "two.parquet")
    assert list(read_arrow(tmp_path / "two.parquet").columns) == list(demo.columns)
    demo.rename_axis("row").to_parquet(tmp_path / "rows.parquet")
    rows = read_arrow(tmp_path / "rows.parquet")
    assert list(rows.columns) == ["row", *demo.columns] and rows["row"].tolist() == list(range(len(demo)))


@pytest.mark.parametrize("suffix", [".parquet", ".arrow", ".feather"])
def test_a_frame_round_trips_with_its_dtypes(tmp_path, suffix):
    """The module says a table round-trips unchanged, but write_arrow wrote no pandas description of the columns:
    Int64 came back as float64, boolean as object, Float64 as float64. Now the dtypes come back; the index is
    not written (as to_csv(index=False) does not write it)."""
    frame = pd.DataFrame({
        "id": pd.array(["a", None, "007"], dtype="str"),
        "Fr [kN]": [1.5, np.nan, 3.0],
        "count": pd.array([1, None, 3], dtype="Int64"),
        "checked": pd.array([True, None, False], dtype="boolean"),
        "share": pd.array([1.0, None, 2.5], dtype="Float64"),
        "grade": pd.Categorical(["u", "v", None]),
        "installed": pd.to_datetime(["2024-01-01", None, "2024-03-01"]).tz_localize("Europe/Berlin"),
        "runtime": pd.to_timedelta([1, None, 3], unit="h"),
    })
    path = write_arrow(frame.set_axis([10, 20, 30]), tmp_path / f"t{suffix}")
    back = read_arrow(path)
    pd.testing.assert_frame_equal(back, frame, check_exact=True)
    assert back["count"].tolist()[0] == 1 and back["checked"].tolist()[2] is False
    assert column_units(path)["Fr [kN]"] == "kN"


def test_the_users_own_metadata_is_kept_beside_the_units(tmp_path):
    """The unit metadata replaced the metadata a file had of its own: a field's 'description' and the schema's
    'source' were gone from calc's results. They are kept now, bearingheat's unit beside them; pandas'
    description of the input frame is not carried into results with other columns."""
    import pyarrow as pa

    from bearingheat.io.pipeline import calc_file

    table = pa.Table.from_pandas(pd.read_csv(DEMO), preserve_index=False)
    fields = [table.schema.field(0).with_metadata({"description": "support label"}), *list(table.schema)[1:]]
    table = table.cast(pa.schema(fields, metadata={**table.schema.metadata, b"source": b"plant A"}))
    parquet.write_table(table, tmp_path / "in.parquet")
    for rows_per_block in (100, 4):  # one block, and blocks joined
        results = calc_file(tmp_path / "in.parquet", rows_per_block=rows_per_block)
        assert results.schema.metadata == {b"source": b"plant A"}
        assert results.schema.field("id").metadata == {b"description": b"support label", b"unit": b""}
    assert main(["calc", str(tmp_path / "in.parquet"), "-o", str(tmp_path / "out.parquet"), "-q"]) == 0
    schema = parquet.read_schema(tmp_path / "out.parquet")
    assert schema.metadata == {b"source": b"plant A"}
    assert schema.field("id").metadata == {b"description": b"support label", b"unit": b""}
    assert schema.field("MR [N*mm]").metadata == {b"unit": b"N*mm"}


def _dictionary_encoded(path: Path) -> dict[str, bool]:
    """Column -> whether the Parquet file stores it dictionary encoded (first row group)."""
    file = parquet.ParquetFile(path)
    group = file.metadata.row_group(0)
    return {group.column(i).path_in_schema: "RLE_DICTIONARY" in group.column(i).encodings
            for i in range(group.num_columns)}


def test_text_columns_of_a_dictionary_are_text_as_plain_strings_are(tmp_path):
    """A Parquet input whose designation, lubrication and id are dictionaries (pandas categories) gives the results
    of the same input in plain strings, every text column dictionary encoded in the output as the plain strings
    are: io.arrow took a dictionary for no text (its columns were written without a dictionary) where io.fleet
    took it for text; both use is_text_type now."""
    import pyarrow as pa

    from bearingheat.io.arrow import is_text_type
    demo = pd.read_csv(DEMO)
    categorical = demo.astype({c: "category" for c in ("id", "designation", "lubrication")})
    assert [is_text_type(t) for t in (pa.string(), pa.large_string(), pa.dictionary(pa.int8(), pa.string()),
                                      pa.dictionary(pa.int8(), pa.int64()), pa.float64())] == [
        True, True, True, False, False]
    for name, frame in (("plain", demo), ("dictionary", categorical)):
        frame.to_parquet(tmp_path / f"{name}.parquet", index=False)
        assert main(["calc", str(tmp_path / f"{name}.parquet"), "-o", str(tmp_path / f"out_{name}.parquet"),
                     "-q"]) == 0
    plain, dictionary = (parquet.read_table(tmp_path / f"out_{name}.parquet") for name in ("plain", "dictionary"))
    assert dictionary.schema.field("designation").type == pa.dictionary(pa.int8(), pa.string())  # kept a category
    assert dictionary.column_names == plain.column_names
    for name in plain.column_names:
        assert dictionary.column(name).to_pylist() == plain.column(name).to_pylist(), name
    texts = [f.name for f in plain.schema if is_text_type(f.type)]
    assert {"id", "designation", "lubrication", "status", "message"} <= set(texts)
    encoded = _dictionary_encoded(tmp_path / "out_dictionary.parquet")
    assert all(encoded[name] for name in texts)
    assert not encoded["MR [N*mm]"]  # numbers without a dictionary, as before
