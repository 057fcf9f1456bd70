"""calc on a big table file a block of rows at a time: the same results as one calc of the whole table."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingheat.io.arrow import column_units, write_arrow
from bearingheat.io.pipeline import calc_file, ordered_union
from bearingheat.io.tables import calc_csv

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def mixed_table(path: Path) -> Path:
    """The demo and the SKF example together, shuffled: rows of both models (SKF columns only in some blocks),
    an M2 row, rows in error, a blank ambient temperature, and a column calc does not know."""
    demo, skf = pd.read_csv(EXAMPLES / "gearbox_shaft.csv"), pd.read_csv(EXAMPLES / "gearbox_shaft_skf.csv")
    table = pd.concat([demo, skf, demo.head(2).assign(**{"n [rpm]": "abc"})], ignore_index=True)
    table.loc[3, "T_amb [degC]"] = np.nan
    table["model"] = ["skf" if i % 4 == 0 else "" for i in range(len(table))]
    table["note [x"] = [f"n{i}" for i in range(len(table))]  # brackets that are no unit: set aside, put back
    table = table.sample(frac=1, random_state=3).reset_index(drop=True)
    table.to_csv(path, index=False)
    return path


def assert_same(blocks: pd.DataFrame, whole: pd.DataFrame) -> None:
    assert list(blocks.columns) == list(whole.columns)
    for column in whole.columns:
        if pd.api.types.is_float_dtype(whole[column]):
            np.testing.assert_array_equal(blocks[column].to_numpy(dtype=float), whole[column].to_numpy(dtype=float),
                                          err_msg=column)
        else:
            assert blocks[column].fillna("").astype(str).tolist() == whole[column].fillna("").astype(str).tolist(), \
                column


@pytest.mark.parametrize("rows_per_block", [1, 3, 7, 100])
def test_blocks_give_the_result_of_one_calc(tmp_path, rows_per_block):
    path = mixed_table(tmp_path / "mixed.csv")
    whole = calc_csv(path)
    assert {"M_rr [N*mm]", "n_thr [1/min]", "note [x"} <= set(whole.columns)  # the case is what it should be
    assert (whole["status"] == "error").sum() >= 2 and (whole["status"] == "ok").any()
    assert_same(calc_file(path, rows_per_block=rows_per_block).to_pandas(), whole)


def test_blocks_of_a_parquet_file_and_the_units_of_the_results(tmp_path):
    source = tmp_path / "in.parquet"
    write_arrow(pd.read_csv(EXAMPLES / "gearbox_shaft.csv"), source)
    results = calc_file(source, rows_per_block=4)
    assert_same(results.to_pandas(), calc_csv(source))
    assert results.schema.field("MR [N*mm]").metadata == {b"unit": b"N*mm"}
    assert results.schema.field("Fr [kN]").metadata == {b"unit": b"kN"}
    write_arrow(results, tmp_path / "out.parquet")
    assert column_units(tmp_path / "out.parquet")["n_thr [1/min]"] == "1/min"


def test_the_progress_advances_block_by_block(tmp_path):
    events = []

    class Recorder:
        def start(self, total, label):
            events.append(("start", total, label))

        def update(self, done):
            events.append(("update", done))

        def finish(self):
            events.append(("finish",))

    calc_file(EXAMPLES / "gearbox_shaft.csv", rows_per_block=4, progress=Recorder())
    assert events == [("start", 6, "calc"), ("update", 4), ("update", 6), ("finish",)]


def test_ordered_union_keeps_every_blocks_order():
    assert ordered_union([["a", "c"], ["a", "b", "c"], ["a", "d"]]) == ["a", "b", "c", "d"]
    # columns no block puts in order follow the tie-break (calc's contract order), then first appearance
    assert ordered_union([["a", "y", "z"], ["a", "x", "z"]], tie_break=["x", "y"]) == ["a", "x", "y", "z"]
    assert ordered_union([["a", "y", "z"], ["a", "x", "z"]]) == ["a", "y", "x", "z"]
