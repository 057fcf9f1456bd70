"""bearingheat calc FOLDER --dask -o OUT: Parquet files computed on a local cluster of two worker processes."""
from __future__ import annotations

import datetime
import decimal
import os
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as parquet
import pytest

import bearingheat as bh
from bearingheat.cli import main
from bearingheat.io.dataset import calc_dataset
from bearingheat.io.fleet import dataset_files
from bearingheat.io.pipeline import calc_file

dask = pytest.importorskip("dask")
pytest.importorskip("dask.dataframe")
pytest.importorskip("distributed")

DEMO = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"


def fleet(folder: Path) -> pd.DataFrame:
    """Three Parquet files of the demo's supports (varied loads, a blank id and designation-only blanks that
    Parquet keeps as missing values) and one file with no rows; the whole table as pandas reads the files."""
    folder.mkdir()
    demo = pd.read_csv(DEMO)
    table = pd.concat([demo] * 10, ignore_index=True)
    table["Fr [kN]"] = table["Fr [kN]"] * np.linspace(0.5, 1.5, len(table))
    table.loc[[3, 17], "id"] = None
    table.loc[25, "lubrication"] = None  # a row in error: no lubrication
    for i, (start, stop) in enumerate([(0, 25), (25, 40), (40, 60)]):
        table.iloc[start:stop].to_parquet(folder / f"part{i}.parquet", index=False)
    table.iloc[0:0].to_parquet(folder / "part3_empty.parquet", index=False)
    return pd.concat([pd.read_parquet(folder / f"part{i}.parquet") for i in range(3)], ignore_index=True)


def test_a_folder_of_parquet_files_on_two_worker_processes(tmp_path, capsys):
    table = fleet(tmp_path / "fleet")
    out = tmp_path / "results"
    assert main(["calc", str(tmp_path / "fleet"), "--dask", "--workers", "2", "-o", str(out)]) == 1
    printed = capsys.readouterr().out
    assert printed.splitlines()[-1] == (f"60 supports: 49 ok, 10 warning, 1 error; results written to {out}/ (Parquet "
                                        "dataset of 4 input files)")
    parts = sorted(p.name for p in out.glob("*.parquet"))
    assert len(parts) == 4  # one part per input partition, the empty one too
    got = pd.read_parquet(out)
    expected = bh.calc(table)
    assert len(got) == len(expected) == 60
    for column in expected.columns:  # row for row as pandas calc (the dataset has every contract column)
        if pd.api.types.is_float_dtype(expected[column]):
            np.testing.assert_allclose(got[column].to_numpy(dtype=float), expected[column].to_numpy(dtype=float),
                                       rtol=1e-12, equal_nan=True, err_msg=column)
        else:
            assert got[column].fillna("").astype(str).tolist() == expected[column].fillna("").astype(str).tolist(), \
                column
    assert expected["status"].iloc[25] == "error"
    assert parquet.read_schema(out / parts[0]).field("MR [N*mm]").metadata == {b"unit": b"N*mm"}


def test_dask_refusals(tmp_path, capsys):
    fleet(tmp_path / "fleet")
    folder = str(tmp_path / "fleet")
    assert main(["calc", folder, "-o", str(tmp_path / "out")]) == 2
    assert "a folder or glob of Parquet files is computed with --dask" in capsys.readouterr().err
    assert main(["calc", folder, "--dask"]) == 2
    assert "--dask writes a Parquet dataset: give -o FOLDER" in capsys.readouterr().err
    assert main(["calc", folder, "--dask", "-o", str(tmp_path / "out.parquet")]) == 2
    assert "--dask writes a folder of Parquet parts; give a folder name" in capsys.readouterr().err
    assert main(["calc", str(tmp_path / "nothing*.parquet"), "--dask", "-o", str(tmp_path / "out")]) == 2
    assert "no Parquet files (the pattern matches nothing)" in capsys.readouterr().err
    (tmp_path / "taken").mkdir()
    (tmp_path / "taken" / "x").write_text("")
    assert main(["calc", folder, "--dask", "-o", str(tmp_path / "taken")]) == 2
    assert f"-o {tmp_path / 'taken'} exists; give --force to replace it" in capsys.readouterr().err
    assert main(["calc", folder, "--dask", "-o", str(tmp_path / "taken"), "--force"]) == 2
    assert f"-o {tmp_path / 'taken'} holds 'x', which is no part of a Parquet dataset" in capsys.readouterr().err
    for above in (folder, str(tmp_path)):  # --force never removes the input files
        assert main(["calc", folder, "--dask", "-o", above, "--force"]) == 2
        assert "holds the input files" in capsys.readouterr().err
    assert main(["calc", str(DEMO), "--scheduler", "tcp://127.0.0.1:1"]) == 2
    assert "--scheduler and --workers apply with --dask only" in capsys.readouterr().err


def test_force_replaces_an_earlier_dataset_at_once_and_keeps_it_when_the_move_fails(tmp_path, monkeypatch):
    """An earlier dataset was replaced by deleting its parts and then moving the new ones in one by one: a failure
    in between (a full disk, a kill) left a mix or nothing. The folder is now swapped by renames: the earlier one
    aside, the new one into its place (the earlier one back if that fails), then the earlier one removed."""
    from bearingheat.io import dataset

    fleet(tmp_path / "fleet")
    out = tmp_path / "results"
    out.mkdir()
    for name in ("part.0.parquet", "part.1.parquet", "_metadata"):
        (out / name).write_bytes(b"old " + name.encode())
    out.chmod(0o750)
    earlier = {p.name: p.read_bytes() for p in out.iterdir()}
    renames = []
    real_rename = os.rename

    def failing(source, destination):
        renames.append((Path(source).name, Path(destination).name))
        if Path(destination) == out and ".bearingheat-" in Path(source).name and Path(source).suffix == ".tmp":
            raise OSError(28, "No space left on device")
        return real_rename(source, destination)

    monkeypatch.setattr(dataset.os, "rename", failing)
    with pytest.raises(bh.errors.OutputFileError) as info:
        calc_fleet(tmp_path / "fleet", out, overwrite=True)
    assert str(info.value) == f"cannot write {out}: No space left on device; the earlier dataset is as it was"
    assert [(source.split(".")[-1], destination.split(".")[-1]) for source, destination in renames] == \
        [("results", "old"), ("tmp", "results"), ("old", "results")]
    assert {p.name: p.read_bytes() for p in out.iterdir()} == earlier
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet", "results"]
    monkeypatch.setattr(dataset.os, "rename", real_rename)
    got = calc_fleet(tmp_path / "fleet", out, overwrite=True)
    assert got.num_rows == 60 and sorted(p.name for p in tmp_path.iterdir()) == ["fleet", "results"]
    assert "_metadata" not in {p.name for p in out.iterdir()} and out.stat().st_mode & 0o777 == 0o750


def test_a_failed_swap_whose_undoing_fails_too_says_where_the_earlier_dataset_is(tmp_path, monkeypatch):
    from bearingheat.io import dataset

    fleet(tmp_path / "fleet")
    out = tmp_path / "results"
    out.mkdir()
    (out / "part.0.parquet").write_bytes(b"old")
    real_rename = os.rename

    def failing(source, destination):
        if Path(destination) == out and Path(source).suffix in (".tmp", ".old"):
            raise OSError(5, "Input/output error")
        return real_rename(source, destination)

    monkeypatch.setattr(dataset.os, "rename", failing)
    with pytest.raises(bh.errors.OutputFileError) as info:
        calc_fleet(tmp_path / "fleet", out, overwrite=True)
    aside = next(p for p in tmp_path.iterdir() if p.suffix == ".old")
    assert str(info.value) == f"cannot write {out}: Input/output error; the earlier dataset is in {aside}"
    assert (aside / "part.0.parquet").read_bytes() == b"old"


def test_folders_left_by_a_run_that_was_stopped_are_put_right_with_a_note(tmp_path, capsys):
    """Only bearingheat's own hidden folders beside the target, of runs no longer alive: new parts are removed; an
    earlier dataset set aside is moved back when the target is missing, else removed."""
    import subprocess
    import time

    from bearingheat.io.dataset import recover_target

    process = subprocess.Popen(["true"])
    process.wait()
    dead = process.pid
    out = tmp_path / "results"
    staged = tmp_path / f".results.bearingheat-{dead}-0a1b2c3d.tmp"
    aside = tmp_path / f".results.bearingheat-{dead}-0a1b2c3e.old"
    young = tmp_path / f".results.bearingheat-{dead}-0a1b2c3f.tmp"
    other = tmp_path / f".other.bearingheat-{dead}-0a1b2c40.tmp"
    for folder in (staged, aside, young, other):
        folder.mkdir()
        (folder / "part.0.parquet").write_bytes(folder.name.encode())
    long_ago = time.time() - 3600
    for folder in (staged, aside, other):
        os.utime(folder, (long_ago, long_ago))
    assert recover_target(out) == [
        f"removed {staged.name}, the new parts of {out} left by a bearingheat run that was stopped",
        f"moved {aside.name} back to {out}: the earlier dataset, set aside by a bearingheat run that was stopped "
        "before its new one was in place"]
    assert (out / "part.0.parquet").read_bytes() == aside.name.encode()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([other.name, "results", young.name])
    aside.mkdir()
    os.utime(aside, (long_ago, long_ago))
    fleet(tmp_path / "fleet")
    assert main(["calc", str(tmp_path / "fleet"), "--dask", "--workers", "1", "-o", str(out), "-q"]) == 2
    assert capsys.readouterr().err == (
        f"note: removed {aside.name}, the earlier dataset of {out} left by a bearingheat run that was stopped\n"
        f"bearingheat calc: error: -o {out} exists; give --force to replace it\n")


def test_a_run_that_fails_keeps_the_earlier_dataset(tmp_path, capsys):
    """--force replaces an earlier dataset only once every new part is written: a fleet whose files differ in
    their columns, or whose units are wrong, is refused with the earlier parts as they were (and no staging
    folder left behind)."""
    fleet(tmp_path / "fleet")
    out = tmp_path / "results"
    assert main(["calc", str(tmp_path / "fleet"), "--dask", "--workers", "1", "-o", str(out), "-q"]) == 1
    assert capsys.readouterr().err == f"error: 1 of 60 supports are in error; see the message column of {out}/\n"
    earlier = {p.name: p.read_bytes() for p in out.iterdir()}
    demo = pd.read_csv(DEMO)
    (tmp_path / "bad").mkdir()
    demo.to_parquet(tmp_path / "bad" / "a.parquet", index=False)
    demo.rename(columns={"Fr [kN]": "Fr [kg]"}).to_parquet(tmp_path / "bad" / "b.parquet", index=False)
    assert main(["calc", str(tmp_path / "bad"), "--dask", "--workers", "1", "-o", str(out), "--force", "-q"]) == 2
    assert capsys.readouterr().err.strip() == (
        f"bearingheat calc: error: {tmp_path / 'bad' / 'b.parquet'}: its columns differ from those of "
        f"{tmp_path / 'bad' / 'a.parquet'} (lacks 'Fr [kN]'; has 'Fr [kg]' besides); every file of a fleet needs "
        "the same columns")
    (tmp_path / "bad" / "a.parquet").unlink()  # one file, a unit of the wrong kind: refused while computing
    assert main(["calc", str(tmp_path / "bad"), "--dask", "--workers", "1", "-o", str(out), "--force", "-q"]) == 2
    assert "kilogram is a mass, not a force" in capsys.readouterr().err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == earlier
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad", "fleet", "results"]


def same_as_the_single_file_path(got: pa.Table, single: pa.Table) -> None:
    """Every column of the single-file path's results is in the dataset, in the same type with the same values
    (the dataset has every contract column besides)."""
    assert got.num_rows == single.num_rows
    for field in single.schema:
        assert got.schema.field(field.name).type == field.type, field.name
        assert got.column(field.name).to_pylist() == single.column(field.name).to_pylist(), field.name


def calc_fleet(folder: Path, out: Path, **options) -> pa.Table:
    """calc_dataset of the Parquet files in ``folder`` on Dask's single-threaded scheduler (the parts are the
    ones a cluster writes: the same tasks); the dataset as one Arrow table."""
    with dask.config.set(scheduler="sync"):
        calc_dataset(dataset_files(str(folder)), out, **options)
    return parquet.read_table(out)


def typed_demo() -> pd.DataFrame:
    """The demo in pandas' nullable types (``convert_dtypes``), with a column of every other kind a Parquet file
    holds besides: nullable whole numbers, logical values, a category, durations, times with a time zone, dates
    and decimals."""
    table = pd.read_csv(DEMO).convert_dtypes()
    table["serial"] = pd.array([1, None, 3, 4, 5, 6], dtype="Int64")
    table["checked"] = pd.array([True, None, False, True, False, True], dtype="boolean")
    table["grade"] = pd.Categorical(["A", "B"] * 3)
    table["runtime"] = pd.to_timedelta(np.arange(6), unit="h")
    table["installed"] = pd.date_range("2024-01-01", periods=6, tz="Europe/Berlin")
    table["day"] = [datetime.date(2024, 1, i + 1) for i in range(6)]
    table["price"] = [decimal.Decimal("1.25"), None] + [decimal.Decimal("2.50")] * 4
    return table


def test_every_column_type_comes_back_as_the_single_file_path_writes_it(tmp_path):
    """The parts were written in a schema of text for every column pandas holds in no numpy type: nullable
    numbers, logical values, durations and times with a time zone stopped the run with an ArrowTypeError, dates,
    categories and decimals came back as text. Now every column has the type and the values of ``calc
    FILE.parquet -o OUT.parquet``."""
    table = typed_demo()
    (tmp_path / "fleet").mkdir()
    table.iloc[:3].to_parquet(tmp_path / "fleet" / "a.parquet", index=False)
    table.iloc[3:].to_parquet(tmp_path / "fleet" / "b.parquet", index=False)
    table.to_parquet(tmp_path / "whole.parquet", index=False)
    single_out, out = tmp_path / "single.parquet", tmp_path / "results"
    assert main(["calc", str(tmp_path / "whole.parquet"), "-o", str(single_out), "-q"]) == 0
    assert main(["calc", str(tmp_path / "fleet"), "--dask", "--workers", "1", "-o", str(out), "-q"]) == 0
    single, got = parquet.read_table(single_out), parquet.read_table(out)
    same_as_the_single_file_path(got, single)
    assert got.column("serial").to_pylist() == [1, None, 3, 4, 5, 6]
    assert got.column("checked").to_pylist() == [True, None, False, True, False, True]
    assert str(got.schema.field("grade").type) == "dictionary<values=string, indices=int8, ordered=0>"
    assert got.column("runtime").to_pylist()[2] == datetime.timedelta(hours=2)
    assert str(got.schema.field("installed").type) == "timestamp[us, tz=Europe/Berlin]"
    assert got.column("day").to_pylist()[5] == datetime.date(2024, 1, 6)
    assert got.column("price").to_pylist()[:2] == [decimal.Decimal("1.25"), None]
    expected = bh.calc(table)
    assert got.column("status").to_pylist() == expected["status"].tolist() == ["ok"] * 4 + ["warning", "ok"]
    np.testing.assert_allclose(got.column("MR [N*mm]").to_numpy(), expected["MR [N*mm]"].to_numpy(dtype=float),
                               rtol=1e-12)
    reread = pd.read_parquet(out)
    assert reread[single.column_names].dtypes.to_dict() == pd.read_parquet(single_out).dtypes.to_dict()


def test_a_first_file_without_rows_or_without_types_takes_the_types_of_the_others(tmp_path):
    """The fleet took its column types from its first file: a file without rows written from text columns, or
    one of blank rows only (Parquet's null type in every column), stopped the run. Now a column without a type in
    some file takes the type the others give it; a file without rows gives an empty part."""
    demo = pd.read_csv(DEMO)
    blank = pd.DataFrame({column: [None, None] for column in demo.columns})
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.iloc[:0].astype(object).to_parquet(fleet / "0_empty.parquet", index=False)
    blank.to_parquet(fleet / "1_blank.parquet", index=False)
    demo.iloc[:3].to_parquet(fleet / "2.parquet", index=False)
    demo.iloc[3:].to_parquet(fleet / "3.parquet", index=False)
    assert str(parquet.read_schema(fleet / "0_empty.parquet").field("d [mm]").type) == "null"
    got = calc_fleet(fleet, tmp_path / "out")
    parts = sorted((tmp_path / "out").glob("*.parquet"))
    assert [parquet.read_metadata(p).num_rows for p in parts] == [0, 2, 3, 3]
    assert parquet.read_schema(parts[0]) == parquet.read_schema(parts[3])
    tables = [parquet.read_table(fleet / name) for name in ("1_blank.parquet", "2.parquet", "3.parquet")]
    parquet.write_table(pa.concat_tables([tables[0].cast(tables[1].schema), *tables[1:]]), tmp_path / "whole.parquet")
    same_as_the_single_file_path(got, calc_file(tmp_path / "whole.parquet"))
    assert got.schema.field("d [mm]").type == pa.int64() and got.column("d [mm]").to_pylist()[:3] == [None, None, 40]
    assert got.column("status").to_pylist()[:2] == ["error", "error"]


def test_whole_numbers_in_one_file_and_decimals_in_another_are_one_number_column(tmp_path):
    """Column types that differ between the files stopped the run with an Arrow error (int64 loads in one file,
    float64 in the next). Now a column takes the type that holds every file's values (whole numbers and decimals:
    float64) and the results are those of the same rows in one file."""
    demo = pd.read_csv(DEMO)
    first, second = demo.iloc[:3].copy(), demo.iloc[3:].copy()
    first["Fa [kN]"] = [1, 0, 2]
    second["Fa [kN]"] = [0.5, 2.0, 0.0]
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    first.to_parquet(fleet / "a.parquet", index=False)
    second.to_parquet(fleet / "b.parquet", index=False)
    assert parquet.read_schema(fleet / "a.parquet").field("Fa [kN]").type == pa.int64()
    got = calc_fleet(fleet, tmp_path / "out")
    assert got.schema.field("Fa [kN]").type == pa.float64()
    assert got.column("Fa [kN]").to_pylist() == [1.0, 0.0, 2.0, 0.5, 2.0, 0.0]
    whole = pd.concat([first, second], ignore_index=True)
    whole.to_parquet(tmp_path / "whole.parquet", index=False)
    same_as_the_single_file_path(got, calc_file(tmp_path / "whole.parquet"))
    np.testing.assert_allclose(got.column("MR [N*mm]").to_numpy(), bh.calc(whole)["MR [N*mm]"].to_numpy(),
                               rtol=1e-12)


def test_a_column_of_numbers_in_one_file_and_of_text_in_another_is_refused_before_any_work(tmp_path, capsys):
    demo = pd.read_csv(DEMO)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.iloc[:3].to_parquet(fleet / "a.parquet", index=False)
    demo.iloc[3:].assign(id=[101, 102, 103]).to_parquet(fleet / "b.parquet", index=False)
    out = tmp_path / "out"
    assert main(["calc", str(fleet), "--dask", "--workers", "1", "-o", str(out), "-q"]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat calc: error: {fleet / 'b.parquet'}: column 'id' holds whole numbers (int64) where "
        f"{fleet / 'a.parquet'} holds text (large_string); every file of a fleet needs each column in one type\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet"]


def test_a_whole_number_a_float_cannot_hold_is_refused_naming_the_file_and_column(tmp_path):
    demo = pd.read_csv(DEMO)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.iloc[:3].assign(serial=[1.5, 2.5, 3.5]).to_parquet(fleet / "a.parquet", index=False)
    demo.iloc[3:].assign(serial=[2**53 + 1, 2, 3]).to_parquet(fleet / "b.parquet", index=False)
    with pytest.raises(bh.InputError) as info:
        calc_fleet(fleet, tmp_path / "out")
    assert str(info.value) == (
        f"{fleet / 'b.parquet'}: column 'serial': its whole numbers (int64) cannot all be held as numbers (double), "
        "the type of the fleet's other files (Integer value 9007199254740993 not in range: -9007199254740992 to "
        "9007199254740992)")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet"]


def test_ids_stored_as_pandas_index_come_back_as_the_id_column(tmp_path):
    """A file written by ``df.set_index('id').to_parquet()`` holds the ids as pandas' index: the fleet dropped
    them, and a file with an unnamed index (row labels after a filter) was refused as having a column
    '__index_level_0__' besides. Now a named index comes back as its column and an unnamed one is left out, as
    on the single-file path."""
    demo = pd.read_csv(DEMO)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.iloc[:3].set_index("id").to_parquet(fleet / "a.parquet")
    demo.iloc[3:].set_axis([13, 17, 21]).to_parquet(fleet / "b.parquet")  # row labels: pandas stores them
    assert "__index_level_0__" in parquet.read_schema(fleet / "b.parquet").names
    got = calc_fleet(fleet, tmp_path / "out")
    assert got.column_names[:2] == ["id", "designation"] and "__index_level_0__" not in got.column_names
    assert got.column("id").to_pylist() == demo["id"].tolist()
    demo.to_parquet(tmp_path / "whole.parquet", index=False)
    same_as_the_single_file_path(got, calc_file(tmp_path / "whole.parquet"))


def test_a_header_calc_cannot_read_passes_through_the_fleet(tmp_path):
    """'remark [see note]]' passed through 'calc FILE -o OUT.csv' but stopped --dask (calc refused the header in
    every partition). The fleet now sets such columns aside and puts them back, as the single-file path does."""
    demo = pd.read_csv(DEMO)
    demo.insert(3, "remark [see note]]", [f"r{i}" for i in range(len(demo))])
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.iloc[:4].to_parquet(fleet / "a.parquet", index=False)
    demo.iloc[4:].to_parquet(fleet / "b.parquet", index=False)
    got = calc_fleet(fleet, tmp_path / "out")
    assert got.column_names.index("remark [see note]]") == 3
    assert got.column("remark [see note]]").to_pylist() == ["r0", "r1", "r2", "r3", "r4", "r5"]
    demo.to_parquet(tmp_path / "whole.parquet", index=False)
    same_as_the_single_file_path(got, calc_file(tmp_path / "whole.parquet"))


def test_the_charts_are_read_once_on_the_client_and_sent_to_the_workers(tmp_path, monkeypatch):
    """--f2-chart and --vm-chart went to the workers as paths: a worker in another folder (or on another machine)
    could not read them, and every partition read them again. They are now read once, before any work, and the
    charts themselves go to the workers."""
    from bearingheat.catalogue.f2chart import F2Chart

    chart = tmp_path / "f2.csv"
    chart.write_bytes((Path(__file__).resolve().parents[2] / "docs" / "f2_chart_example.csv").read_bytes())
    reads = []
    original = F2Chart.from_csv.__func__

    def counted(cls, path):
        reads.append(str(path))
        return original(cls, path)

    monkeypatch.setattr(F2Chart, "from_csv", classmethod(counted))
    row = {"id": "NJ", "designation": "NJ206-E-XL", "d [mm]": 30, "D [mm]": 62, "B [mm]": 16, "C0 [kN]": 36,
           "lubrication": "oil_bath", "Fa [kN]": 0.05, "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6,
           "T_amb [degC]": 20, "T_bearing [degC]": 70}
    table = pd.DataFrame([{**row, "n [rpm]": 100, "Fr [kN]": load} for load in (5.0, 4.0, 6.0, 5.5)])
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    for i in range(2):
        table.iloc[2 * i:2 * i + 2].to_parquet(fleet / f"{i}.parquet", index=False)
    got = calc_fleet(fleet, tmp_path / "out", f2_chart=str(chart))
    assert reads == [str(chart)]
    expected = bh.calc(table, f2_chart=str(chart))
    assert (expected["M2 [N*mm]"] > 0).all()
    np.testing.assert_allclose(got.column("M2 [N*mm]").to_numpy(), expected["M2 [N*mm]"].to_numpy(), rtol=1e-12)
    # (n_per of these rows lies beyond the chart's speeds: a warning that says so, the same on both paths)
    assert got.column("status").to_pylist() == expected["status"].tolist()
    assert got.column("message").to_pylist() == expected["message"].tolist()


def test_a_fleet_is_checked_before_the_cluster_starts(tmp_path, capsys, monkeypatch):
    """docs/scale.md says a file whose columns differ is named before any work, but the check ran once the local
    cluster had started. The files' columns and types, the target folder and the charts are now checked first."""
    import bearingheat.cli.calc as command

    def no_cluster(*args, **kwargs):
        raise AssertionError("the cluster was started")

    monkeypatch.setattr(command, "dask_client", no_cluster)
    demo = pd.read_csv(DEMO)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    demo.to_parquet(fleet / "a.parquet", index=False)
    demo.rename(columns={"Fr [kN]": "Fr [kg]"}).to_parquet(fleet / "b.parquet", index=False)
    out = tmp_path / "out"
    assert main(["calc", str(fleet), "--dask", "-o", str(out)]) == 2
    assert capsys.readouterr().err == (
        f"bearingheat calc: error: {fleet / 'b.parquet'}: its columns differ from those of {fleet / 'a.parquet'} "
        "(lacks 'Fr [kN]'; has 'Fr [kg]' besides); every file of a fleet needs the same columns\n")
    (fleet / "b.parquet").unlink()
    chart = tmp_path / "chart.csv"
    chart.write_text("a,b\n")
    assert main(["calc", str(fleet), "--dask", "-o", str(out), "--f2-chart", str(chart)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {chart}: an f2 chart needs the columns curve, "
                                       "Fa_over_A, nu_n_dM, f2 and a units row\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["chart.csv", "fleet"]


def test_a_fleet_with_a_duty_cycle_gets_the_summary_of_the_single_file_path(tmp_path, capsys):
    """--dask skipped the duty-cycle summary that 'calc FILE -o OUT.parquet' writes beside its results
    (OUT.duty.parquet) without a word. The fleet now writes <folder>.duty.parquet beside its folder, from all its
    parts (a support's cases may lie in different files), and prints it as the single-file path does."""
    duty = pd.read_csv(Path(DEMO).with_name("gearbox_duty_cycle.csv"))
    assert duty["support"].nunique() == 2 and len(duty) == 6
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    duty.iloc[:2].to_parquet(fleet / "a.parquet", index=False)  # support A's third case is in b.parquet
    duty.iloc[2:].to_parquet(fleet / "b.parquet", index=False)
    duty.to_parquet(tmp_path / "whole.parquet", index=False)
    assert main(["calc", str(tmp_path / "whole.parquet"), "-o", str(tmp_path / "single.parquet"), "-q"]) == 0
    out = tmp_path / "results"
    assert main(["calc", str(fleet), "--dask", "--workers", "1", "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "duty cycle (time-weighted per support):" in printed
    got = pd.read_parquet(tmp_path / "results.duty.parquet")
    expected = pd.read_parquet(tmp_path / "single.duty.parquet")
    pd.testing.assert_frame_equal(got, expected, check_exact=False, rtol=1e-12)
    assert got["support"].tolist() == list(duty["support"].unique()) and got["cases"].tolist() == [3, 3]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet", "results", "results.duty.parquet",
                                                         "single.duty.parquet", "single.parquet", "whole.parquet"]
    # the summary is an output as any other: an existing one is refused without --force, before any work
    (tmp_path / "again.duty.parquet").write_bytes(b"mine")
    assert main(["calc", str(fleet), "--dask", "--workers", "1", "-o", str(tmp_path / "again")]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {tmp_path / 'again.duty.parquet'} exists; give "
                                       "--force to replace it\n")
    assert (tmp_path / "again.duty.parquet").read_bytes() == b"mine" and not (tmp_path / "again").exists()


def test_a_duty_cycle_whose_shares_do_not_sum_to_one_keeps_the_earlier_dataset(tmp_path):
    duty = pd.read_csv(Path(DEMO).with_name("gearbox_duty_cycle.csv"))
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    duty.to_parquet(fleet / "a.parquet", index=False)
    calc_fleet(fleet, tmp_path / "out")
    earlier = {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
    earlier_parts = {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir()}
    duty.loc[0, "time_share"] = 0.3
    duty.to_parquet(fleet / "a.parquet", index=False)
    with pytest.raises(bh.InputError) as info:
        calc_fleet(fleet, tmp_path / "out", overwrite=True)
    assert str(info.value) == ("support 'input shaft A': the time_share values of its cases (full load 0.3, part load "
                               "0.5, idle 0.3) sum to 1.1, not 1 (within 0.1%)")
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()} == earlier
    assert {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir()} == earlier_parts
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet", "out", "out.duty.parquet"]


def test_a_damaged_file_and_a_scheduler_that_is_no_address_are_one_line_errors(tmp_path, capsys, monkeypatch):
    """A damaged Parquet file in a fleet stopped --dask with a traceback (ArrowInvalid: Parquet magic bytes not
    found) where the single-file path names the file; --scheduler notanaddress with 'ValueError: missing port
    number'. Both are now one line, before the cluster starts."""
    import bearingheat.cli.calc as command

    def no_cluster(*args, **kwargs):
        raise AssertionError("the cluster was started")

    monkeypatch.setattr(command, "dask_client", no_cluster)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    pd.read_csv(DEMO).to_parquet(fleet / "a.parquet", index=False)
    (fleet / "b.parquet").write_bytes(b"not parquet at all")
    assert main(["calc", str(fleet / "b.parquet"), "-o", str(tmp_path / "single.csv")]) == 2
    single = capsys.readouterr().err
    assert single.startswith(f"bearingheat calc: error: {fleet / 'b.parquet'}: not a readable .parquet table (Parquet "
                             "magic bytes not found in footer")
    assert main(["calc", str(fleet), "--dask", "-o", str(tmp_path / "out")]) == 2
    assert capsys.readouterr().err == single
    (fleet / "b.parquet").unlink()
    assert main(["calc", str(fleet), "--dask", "--scheduler", "notanaddress", "-o", str(tmp_path / "out")]) == 2
    assert capsys.readouterr().err == (
        "bearingheat calc: error: --scheduler notanaddress: not the address of a Dask scheduler (missing port number "
        "in address 'notanaddress'); give it as tcp://HOST:PORT, such as tcp://scheduler:8786\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fleet"]


def test_misleading_messages_of_the_fleet(tmp_path, capsys, monkeypatch):
    """An existing file whose name holds brackets was taken for a glob pattern ('the pattern matches nothing'),
    and a missing parent of -o was named by a temporary file inside it ('nonexist/sub/.out.bearingheat-xxx.tmp: No
    such file or directory')."""
    import bearingheat.cli.calc as command

    demo = pd.read_csv(DEMO)
    folder = tmp_path / "fl br"
    folder.mkdir()
    named = folder / "supports [v2].parquet"
    demo.to_parquet(named, index=False)
    assert dataset_files(str(named)) == [str(named)]
    got = calc_fleet(named, tmp_path / "out")
    assert got.column("id").to_pylist() == demo["id"].tolist()

    def no_cluster(*args, **kwargs):
        raise AssertionError("the cluster was started")

    monkeypatch.setattr(command, "dask_client", no_cluster)
    missing = tmp_path / "nonexist" / "sub"
    assert main(["calc", str(named), "--dask", "-o", str(missing)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: -o {missing}: the folder {missing.parent} does not "
                                       "exist; create it or give another folder\n")


def test_a_fleet_without_rows_and_a_unit_of_the_wrong_kind_print_one_clear_line(tmp_path, capfd):
    """A fleet whose files have no rows printed pandas' 'Empty DataFrame' repr; an input error on the workers
    was preceded by the workers' 'Compute Failed' log of the task and its traceback. Both are one line now (the
    workers' output is captured at the file descriptors)."""
    demo = pd.read_csv(DEMO)
    empty = tmp_path / "empty"
    empty.mkdir()
    demo.iloc[:0].to_parquet(empty / "a.parquet", index=False)
    demo.iloc[:0].to_parquet(empty / "b.parquet", index=False)
    assert main(["calc", str(empty), "--dask", "--workers", "2", "-o", str(tmp_path / "out")]) == 0
    printed = capfd.readouterr()
    assert printed.out == (f"0 supports: the 2 input files have no rows; {tmp_path / 'out'}/ holds a Parquet dataset "
                           "of empty parts\n")
    assert [parquet.read_metadata(p).num_rows for p in sorted((tmp_path / "out").iterdir())] == [0, 0]
    wrong = tmp_path / "wrong"
    wrong.mkdir()
    for name, rows in (("a", slice(0, 3)), ("b", slice(3, 6))):
        demo.iloc[rows].rename(columns={"Fr [kN]": "Fr [kg]"}).to_parquet(wrong / f"{name}.parquet", index=False)
    assert main(["calc", str(wrong), "--dask", "--workers", "2", "-o", str(tmp_path / "out2"), "-q"]) == 2
    printed = capfd.readouterr()
    assert printed.out == ""
    assert printed.err == ("bearingheat calc: error: column 'Fr [kg]': kilogram is a mass, not a force; for "
                           "kilogram-force write kgf\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty", "out", "wrong"]


def test_the_parts_are_named_in_the_order_of_the_rows(tmp_path):
    """Dask named the parts part.0, part.1, ... part.10, which sort as part.0, part.1, part.10, part.2: a reader
    that takes the files by name got the rows out of order. The numbers are now zero-padded."""
    from bearingheat.io.dataset import part_name

    assert [part_name(i, 12) for i in (0, 9, 11)] == ["part.00.parquet", "part.09.parquet", "part.11.parquet"]
    assert part_name(3, 4) == "part.3.parquet" and part_name(0, 1) == "part.0.parquet"
    demo = pd.read_csv(DEMO)
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    table = pd.concat([demo] * 2, ignore_index=True).assign(id=[f"s{i:02d}" for i in range(12)])
    for i in range(12):
        table.iloc[[i]].to_parquet(fleet / f"{i:02d}.parquet", index=False)
    got = calc_fleet(fleet, tmp_path / "out")
    assert sorted(p.name for p in (tmp_path / "out").iterdir())[-3:] == ["part.09.parquet", "part.10.parquet",
                                                                          "part.11.parquet"]
    assert got.column("id").to_pylist() == table["id"].tolist()
    assert pd.read_parquet(tmp_path / "out")["id"].tolist() == table["id"].tolist()


def test_the_help_says_dask_needs_an_output_and_how_it_is_written(capsys):
    """-o's help said 'without it the results are printed', though --dask refuses to run without -o."""
    with pytest.raises(SystemExit):
        main(["calc", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert ("file to write (.csv, .parquet, .arrow, .feather or .xlsx; with --dask a folder for the Parquet dataset); "
            "without it the results are printed (--dask needs it)") in text
    assert ("is written atomically (a temporary file beside it, renamed when complete; with --dask a hidden folder "
            "beside the output folder, swapped in by renames)") in text


def test_the_users_own_metadata_is_kept_in_every_part(tmp_path):
    demo = pa.Table.from_pandas(pd.read_csv(DEMO), preserve_index=False)
    fields = [demo.schema.field(0).with_metadata({"description": "support label"}), *list(demo.schema)[1:]]
    demo = demo.cast(pa.schema(fields, metadata={**demo.schema.metadata, b"source": b"plant A"}))
    fleet = tmp_path / "fleet"
    fleet.mkdir()
    parquet.write_table(demo.slice(0, 3), fleet / "a.parquet")
    parquet.write_table(demo.slice(3), fleet / "b.parquet")
    calc_fleet(fleet, tmp_path / "out")
    for part in sorted((tmp_path / "out").iterdir()):
        schema = parquet.read_schema(part)
        assert schema.metadata == {b"source": b"plant A"}
        assert schema.field("id").metadata == {b"description": b"support label", b"unit": b""}
        assert schema.field("NR [W]").metadata == {b"unit": b"W"}


def test_a_big_file_is_computed_in_pieces_of_its_row_groups(tmp_path, monkeypatch):
    """A file above PIECE_BYTES is cut into runs of its row groups, each a part; the rows stay in order and a
    named range index (stored as its start and step only) gets each piece's own row numbers."""
    from bearingheat.io import fleet as fleet_module

    monkeypatch.setattr(fleet_module, "PIECE_BYTES", 1)  # every row group a piece
    demo = pd.read_csv(DEMO)
    table = pd.concat([demo] * 2, ignore_index=True).rename_axis("row")
    folder = tmp_path / "fleet"
    folder.mkdir()
    table.to_parquet(folder / "big.parquet", row_group_size=5)
    assert parquet.ParquetFile(folder / "big.parquet").metadata.num_row_groups == 3
    got = calc_fleet(folder, tmp_path / "out")
    assert [parquet.read_metadata(p).num_rows for p in sorted((tmp_path / "out").iterdir())] == [5, 5, 2]
    assert got.column("row").to_pylist() == list(range(12))
    assert got.column("id").to_pylist() == table["id"].tolist()
    np.testing.assert_allclose(got.column("MR [N*mm]").to_numpy(), bh.calc(table.reset_index())["MR [N*mm]"],
                               rtol=1e-12)


def test_the_duty_summary_follows_its_dataset(tmp_path, monkeypatch):
    """The summary beside the folder was written before the dataset was swapped in: a swap that failed left the
    earlier dataset beside the new summary, and a rerun of a fleet without rows left the earlier summary beside an
    empty dataset. It is now written once the dataset is in place, and removed where the new fleet has none."""
    from bearingheat.io import dataset

    duty = pd.read_csv(Path(__file__).resolve().parents[2] / "examples" / "gearbox_duty_cycle.csv")
    (tmp_path / "fleet").mkdir()
    duty.to_parquet(tmp_path / "fleet" / "a.parquet", index=False)
    out, summary = tmp_path / "out", tmp_path / "out.duty.parquet"
    calc_fleet(tmp_path / "fleet", out)
    earlier = summary.read_bytes()
    heavier = duty.assign(**{"Fr [kN]": duty["Fr [kN]"] * 3})
    heavier.to_parquet(tmp_path / "fleet" / "a.parquet", index=False)
    real_rename = os.rename

    def failing(source, destination):
        if Path(source).suffix == ".tmp":
            raise OSError(13, "Permission denied")
        return real_rename(source, destination)

    monkeypatch.setattr(dataset.os, "rename", failing)
    with pytest.raises(bh.errors.OutputFileError):
        calc_fleet(tmp_path / "fleet", out, overwrite=True)
    assert summary.read_bytes() == earlier
    monkeypatch.setattr(dataset.os, "rename", real_rename)
    calc_fleet(tmp_path / "fleet", out, overwrite=True)
    assert summary.read_bytes() != earlier
    heavier.iloc[0:0].to_parquet(tmp_path / "fleet" / "a.parquet", index=False)
    assert calc_fleet(tmp_path / "fleet", out, overwrite=True).num_rows == 0
    assert not summary.exists()


def test_the_scheduler_is_checked_and_the_target_recovered_once(tmp_path, capsys, monkeypatch):
    """The command checked the scheduler's address, and dask_client checked it again; it put right what a stopped
    run had left, and plan_dataset did it again. Each runs once now (counted on a scheduler of this process, with one
    worker thread); a malformed address given to dask_client directly is still named by check_scheduler."""
    from distributed import LocalCluster

    import bearingheat.cli.calc as command
    import bearingheat.io.dataset as dataset

    calls: list[str] = []

    def counted(name, real):
        def wrapper(value):
            calls.append(name)
            return real(value)
        return wrapper

    for name in ("check_scheduler", "recover_target"):
        wrapper = counted(name, getattr(dataset, name))
        monkeypatch.setattr(command, name, wrapper)
        monkeypatch.setattr(dataset, name, wrapper)
    fleet(tmp_path / "fleet")
    out = tmp_path / "results"
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp://",
                      dashboard_address=None) as cluster:
        assert main(["calc", str(tmp_path / "fleet"), "--dask", "--scheduler", cluster.scheduler_address,
                     "-o", str(out), "-q"]) == 1
    assert sorted(calls) == ["check_scheduler", "recover_target"]
    assert len(pd.read_parquet(out)) == 60
    capsys.readouterr()
    with pytest.raises(bh.errors.InputError) as info:
        with dataset.dask_client("notanaddress"):
            pass
    assert str(info.value) == ("--scheduler notanaddress: not the address of a Dask scheduler (missing port number in "
                               "address 'notanaddress'); give it as tcp://HOST:PORT, such as tcp://scheduler:8786")


def test_text_columns_of_a_dictionary_are_text_in_the_fleet_as_plain_strings_are(tmp_path):
    """A fleet whose designation, lubrication and id are dictionaries (pandas categories; in one file of two, the
    other plain strings, as well as in both) gives the results of the fleet in plain strings, and every text column
    of the parts is dictionary encoded: the parts' writer took a dictionary for no text (io.arrow) where io.fleet
    took it for text."""
    from bearingheat.io.arrow import is_text_type
    demo = pd.read_csv(DEMO)
    categorical = demo.astype({c: "category" for c in ("id", "designation", "lubrication")})
    for name, halves in (("plain", (demo, demo)), ("dictionary", (categorical, categorical)),
                         ("mixed", (categorical, demo))):
        (tmp_path / name).mkdir()
        for i, frame in enumerate(halves):
            frame.iloc[3 * i:3 * i + 3].to_parquet(tmp_path / name / f"part{i}.parquet", index=False)
    plain = calc_fleet(tmp_path / "plain", tmp_path / "out_plain")
    for name in ("dictionary", "mixed"):
        got = calc_fleet(tmp_path / name, tmp_path / f"out_{name}")
        assert got.column_names == plain.column_names
        for column in plain.column_names:
            assert got.column(column).to_pylist() == plain.column(column).to_pylist(), (name, column)
        for part in sorted((tmp_path / f"out_{name}").glob("*.parquet")):
            file = parquet.ParquetFile(part)
            group = file.metadata.row_group(0)
            for i, field in enumerate(file.schema_arrow):
                if is_text_type(field.type):
                    assert "RLE_DICTIONARY" in group.column(i).encodings, (name, part.name, field.name)
    assert pa.types.is_dictionary(parquet.read_schema(tmp_path / "out_dictionary" / "part.0.parquet")
                                  .field("designation").type)
    assert pa.types.is_large_string(parquet.read_schema(tmp_path / "out_mixed" / "part.0.parquet")
                                    .field("designation").type)


def test_a_fleet_whose_support_column_is_blank_in_every_row_has_no_duty_cycle(tmp_path):
    """The fleet of a CSV written from the example workbook: its support, case and time_share columns are blank in
    every row. As calc FILE does, the fleet gets no duty-cycle summary (it stopped at 'row 1: support is blank')."""
    demo = pd.read_csv(DEMO).assign(support=None, case=None, time_share=np.nan)
    (tmp_path / "fleet").mkdir()
    demo.to_parquet(tmp_path / "fleet" / "a.parquet", index=False)
    got = calc_fleet(tmp_path / "fleet", tmp_path / "out")
    assert got.num_rows == len(demo) and got.column("support").null_count == len(demo)
    assert got.column("MR [N*mm]").to_pylist() == bh.calc(demo)["MR [N*mm]"].tolist()
    assert not (tmp_path / "out.duty.parquet").exists()


def test_the_local_cluster_s_workers_close_without_logging_errors(tmp_path):
    """dask_client's local cluster quiets its workers' own log before it closes them: a heartbeat that meets the
    closed scheduler (dask/distributed issue 7891) logged an ERROR with a traceback on the command's stderr after
    its one line (seen once in a run of the whole suite). Each worker records its log level as it closes."""
    import logging

    from distributed.diagnostics.plugin import WorkerPlugin

    from bearingheat.io import dataset

    class LevelAtClose(WorkerPlugin):  # (defined here: the workers get it by value)
        def __init__(self, folder):
            self.folder = str(folder)

        def setup(self, worker):
            self.name = str(worker.name)

        def teardown(self, worker):
            level = logging.getLogger("distributed.worker").getEffectiveLevel()
            Path(self.folder, f"worker-{self.name}").write_text(str(level))

    with dataset.dask_client(workers=2) as client:
        client.register_plugin(LevelAtClose(tmp_path))
        working = set(client.run(lambda: logging.getLogger("distributed.worker").getEffectiveLevel()).values())
    assert working != {logging.CRITICAL}  # (while they work, their errors are logged)
    levels = {p.name: p.read_text() for p in tmp_path.iterdir()}
    assert levels == {"worker-0": str(logging.CRITICAL), "worker-1": str(logging.CRITICAL)}
