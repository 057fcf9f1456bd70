"""Every benchmark runs on a tiny size and checks its own results (no timing is asserted: that is `make bench`)."""
import subprocess
import sys
from pathlib import Path

import pytest

RUNNER = Path(__file__).resolve().parents[1] / "benchmarks" / "__main__.py"


def test_friction_benchmark_paths_agree(capsys):
    from bench_friction import main
    figures = main(points=6000, repeats=1, loop_sample=600)
    assert figures["points"] == 6000 and figures["mixed_s"] > 0
    printed = capsys.readouterr().out
    assert "unit-aware API" in printed and "mixed rows, as calc gets them" in printed and "target >= 100x" in printed


def test_skf_benchmark_runs_on_a_small_size(capsys):
    from bench_skf import main
    figures = main(points=3000, repeats=1)
    assert figures["skf_kernel_s"] > 0 and "target <= 3x" in capsys.readouterr().out


def test_thermal_benchmark_runs_on_a_small_size(capsys):
    from bench_thermal import main
    figures = main(rows=300)
    assert figures["max_rel_diff"] < 1e-6 and "target >= 50x" in capsys.readouterr().out


def test_pipeline_benchmark_runs_on_a_small_table(capsys):
    from bench_pipeline import main
    figures = main(rows=2000, repeats=1, cli=True)
    printed = capsys.readouterr().out
    assert "minimal numpy version of the same formulas" in printed and "memory-bandwidth floor" in printed
    assert "bh.calc with heat-balance columns" in printed and "target <= 30x" in printed
    assert "nu from nu40/nu100 at T_op" in printed and figures["calc_oil"] > 0
    assert "vs a bare pd.read_csv(engine='pyarrow') + to_parquet" in printed and "target <= 5x" in printed
    assert figures["cli_peak_mb"] > figures["peak_mb[python + package]"] > 0 and figures["kernel"] > 0


def test_dask_benchmark_runs_on_a_small_table(capsys):
    pytest.importorskip("distributed")
    from bench_dask import main
    figures = main(rows=2000, partitions=4)
    assert figures["rows_per_s_1"] > 0 and figures["rows_per_s_2"] > 0
    assert "two workers vs one" in capsys.readouterr().out


def test_excel_benchmark_runs_on_a_small_workbook(capsys):
    from bench_excel import main
    figures = main(n_rows=30)
    assert figures["values"] > 0 and "30 supports" in capsys.readouterr().out


def test_diagnose_benchmark_runs_on_a_small_set(capsys):
    from bench_diagnose import main
    assert main(rows=1500) > 0 and "target < 60 s" in capsys.readouterr().out


def test_sizes_from_the_command_line(monkeypatch):
    from common import size_argument
    monkeypatch.setattr(sys, "argv", ["bench"])
    assert size_argument(200, 10**6) == 200
    monkeypatch.setattr(sys, "argv", ["bench", "--full"])
    assert size_argument(200, 10**6) == 10**6
    monkeypatch.setattr(sys, "argv", ["bench", "1e4"])
    assert size_argument(200, 10**6) == 10_000


@pytest.mark.parametrize("argument", ["many", "0", "2.5", "-3"])
def test_a_size_that_is_no_row_count_is_refused(monkeypatch, capsys, argument):
    from common import size_argument
    monkeypatch.setattr(sys, "argv", ["bench", argument] if not argument.startswith("-") else ["bench", "--", argument])
    with pytest.raises(SystemExit) as exc:
        size_argument(200, 10**6)
    assert exc.value.code == 2
    assert (f"argument rows: {argument!r} is not a number of rows (a whole number >= 1, e.g. 200000 or 1e6)"
            in capsys.readouterr().err)


def test_a_benchmark_prints_its_help():
    script = RUNNER.parent / "bench_pipeline.py"
    done = subprocess.run([sys.executable, str(script), "--help"], capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout.startswith("usage: bench_pipeline.py [-h] [--full] [rows]")
    assert "the whole pipeline against honest baselines" in done.stdout and "(default 200,000)" in done.stdout


def test_the_runner_goes_on_after_a_script_that_exits(tmp_path):
    runner = RUNNER.read_text()
    (tmp_path / "bench_a.py").write_text("import sys\nprint('a ran')\nsys.exit(0)\n")
    (tmp_path / "bench_b.py").write_text("print('b ran')\n")
    (tmp_path / "__main__.py").write_text(runner)
    done = subprocess.run([sys.executable, str(tmp_path / "__main__.py")], capture_output=True, text=True)
    assert done.returncode == 0 and "a ran" in done.stdout and "b ran" in done.stdout
    (tmp_path / "bench_c.py").write_text("raise RuntimeError('broken')\n")
    done = subprocess.run([sys.executable, str(tmp_path / "__main__.py")], capture_output=True, text=True)
    assert done.returncode == 1 and "failed: bench_c.py" in done.stderr
