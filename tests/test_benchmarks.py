"""The friction benchmark's four paths give the same M_R (a small run; no timing is asserted)."""
from bench_friction import main


def test_friction_benchmark_paths_agree(capsys):
    figures = main(points=6000, repeats=1, loop_sample=600)
    assert figures["points"] == 6000
    assert "unit-aware API" in capsys.readouterr().out


def test_pipeline_benchmark_runs_on_a_small_table(capsys):
    from bench_pipeline import main as pipeline
    figures = pipeline(rows=2000, repeats=1, cli=True)
    printed = capsys.readouterr().out
    assert "minimal numpy" in printed and "bh.calc with heat-balance columns" in printed
    assert figures["cli_peak_mb"] > 0 and figures["kernel"] > 0


def test_the_runner_goes_on_after_a_script_that_exits(tmp_path):
    import subprocess
    import sys
    from pathlib import Path
    runner = (Path(__file__).resolve().parents[1] / "benchmarks" / "__main__.py").read_text()
    (tmp_path / "bench_a.py").write_text("import sys\nprint('a ran')\nsys.exit(0)\n")
    (tmp_path / "bench_b.py").write_text("print('b ran')\n")
    (tmp_path / "__main__.py").write_text(runner)
    done = subprocess.run([sys.executable, str(tmp_path / "__main__.py")], capture_output=True, text=True)
    assert done.returncode == 0 and "a ran" in done.stdout and "b ran" in done.stdout
    (tmp_path / "bench_c.py").write_text("raise RuntimeError('broken')\n")
    done = subprocess.run([sys.executable, str(tmp_path / "__main__.py")], capture_output=True, text=True)
    assert done.returncode == 1 and "failed: bench_c.py" in done.stderr
