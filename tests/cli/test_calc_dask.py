"""bearingheat calc FOLDER --dask -o OUT: Parquet files computed on a local cluster of two worker processes."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow.parquet as parquet
import pytest

import bearingheat as bh
from bearingheat.cli import main

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


def test_force_replaces_only_the_parts_of_an_earlier_dataset(tmp_path):
    from bearingheat.io.dataset import check_dataset_target, clear_dataset
    files = [str(tmp_path / "in" / "a.parquet")]
    earlier = tmp_path / "results"
    earlier.mkdir()
    for name in ("part.0.parquet", "part.1.parquet", "_metadata"):
        (earlier / name).write_bytes(b"old")
    assert check_dataset_target(earlier, files, force=True) == earlier
    clear_dataset(earlier)
    assert list(earlier.iterdir()) == []


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
