"""bh.calc on a Dask DataFrame: a LocalCluster of two worker processes gives the pandas result row for row."""
from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import bearingheat as bh

dd = pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("distributed")

DEMO = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"


def demo_rows(count: int = 240) -> pd.DataFrame:
    demo = pd.read_csv(DEMO)
    table = pd.concat([demo] * (count // len(demo)), ignore_index=True)
    rng = np.random.default_rng(7)
    table["Fr [kN]"] = table["Fr [kN]"] * rng.uniform(0.5, 1.5, len(table))
    table["n [rpm]"] = table["n [rpm]"] * rng.uniform(0.5, 1.5, len(table))
    return table


def same_as_pandas(distributed_result: pd.DataFrame, table: pd.DataFrame) -> None:
    expected = bh.calc(table)
    got = distributed_result.reset_index(drop=True)
    expected = expected.reset_index(drop=True)
    assert len(got) == len(expected)
    for column in expected.columns:
        if pd.api.types.is_float_dtype(expected[column]):
            np.testing.assert_allclose(got[column].to_numpy(dtype=float), expected[column].to_numpy(dtype=float),
                                       rtol=1e-12, equal_nan=True, err_msg=column)
        else:
            assert got[column].fillna("").astype(str).tolist() == expected[column].fillna("").astype(str).tolist(), \
                column


@pytest.fixture(scope="module")
def client():
    # silence_logs: a worker that outlives the closed scheduler for a moment logs a failed heartbeat to the test
    # process's stderr (its file descriptor), where a later test that captures it would read it as its own output
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       silence_logs=logging.CRITICAL)
    with distributed.Client(cluster) as connected:
        yield connected
    cluster.close()


def test_two_worker_processes_give_the_pandas_result(client):
    table = demo_rows()
    lazy = bh.calc(dd.from_pandas(table, npartitions=4))
    assert type(lazy).__module__.startswith("dask")
    same_as_pandas(lazy.compute(), table)
    # the layout is fixed: every contract result column, whatever a partition holds
    assert "Fa/A" in lazy.columns and "M_rr [N*mm]" in lazy.columns


def test_empty_partitions(client):
    table = demo_rows()
    ddf = dd.from_pandas(table, npartitions=6)
    fast = ddf[ddf["n [rpm]"] > 5000]  # the gearbox rows are slow: some partitions hold nothing
    result = bh.calc(fast).compute()
    same_as_pandas(result, table[table["n [rpm]"] > 5000])


def test_pyarrow_strings_and_missing_values_behave_as_pandas_input(client):
    table = demo_rows(24)
    typed = table.astype({"designation": "string[pyarrow]", "id": "string[pyarrow]", "Fa [kN]": "Float64"})
    typed.loc[3, "Fa [kN]"] = pd.NA
    typed.loc[5, "designation"] = pd.NA
    plain = table.astype({"Fa [kN]": float}).copy()
    plain.loc[3, "Fa [kN]"] = np.nan
    plain.loc[5, "designation"] = None
    from_pandas, from_typed = bh.calc(plain), bh.calc(typed)
    np.testing.assert_allclose(from_typed["MR [N*mm]"].to_numpy(dtype=float),
                               from_pandas["MR [N*mm]"].to_numpy(dtype=float), rtol=1e-12, equal_nan=True)
    assert from_typed["message"].tolist() == from_pandas["message"].tolist()
    same_as_pandas(bh.calc(dd.from_pandas(typed, npartitions=3)).compute(), typed)


def test_a_partition_that_holds_result_columns_gets_them_once():
    """A table calc wrote before (its MR and status among the inputs) gets each result column once, in the
    input's place, with the new values: the partition's frame is built from calc's result, not the input's
    columns followed by the layout's."""
    from bearingheat.calc.distributed import calc_partition, result_layout
    from bearingheat.calc.table import calc

    table = pd.read_csv(DEMO)
    earlier = bh.calc(table)[[*table.columns, "MR [N*mm]", "status"]].assign(**{"MR [N*mm]": -1.0})
    out = calc_partition(earlier, calc, result_layout(earlier.columns), {})
    assert not out.columns.duplicated().any()
    assert list(out.columns[:len(earlier.columns)]) == list(earlier.columns)
    np.testing.assert_allclose(out["MR [N*mm]"].to_numpy(dtype=float),
                               bh.calc(table)["MR [N*mm]"].to_numpy(dtype=float), rtol=1e-15)


def test_a_partition_with_f0_headed_with_its_unit_gets_f0_once():
    """'f0 [1]' (the contract's bare f0 with the template's unit 1) gets the result f0 in its place, as pandas calc
    writes it; an empty partition (the meta of the Dask frame) has the same columns."""
    from bearingheat.calc.distributed import calc_partition, result_layout
    from bearingheat.calc.table import calc

    table = pd.read_csv(DEMO).assign(**{"f0 [1]": 2.5})
    layout = result_layout(table.columns)
    out = calc_partition(table, calc, layout, {})
    empty = calc_partition(table.iloc[:0], calc, layout, {})
    assert not out.columns.duplicated().any()
    assert list(out.columns) == list(empty.columns)
    assert list(out.columns[:len(table.columns)]) == [*table.columns[:-1], "f0"]
    assert out["f0"].tolist() == [2.5] * len(table)
    expected = bh.calc(table)
    np.testing.assert_allclose(out["MR [N*mm]"].to_numpy(dtype=float), expected["MR [N*mm]"].to_numpy(dtype=float),
                               rtol=1e-15)
    assert "f0 [1]" not in expected.columns
