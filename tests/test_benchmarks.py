"""The friction benchmark's four paths give the same M_R (a small run; no timing is asserted)."""
from bench_friction import main


def test_friction_benchmark_paths_agree(capsys):
    figures = main(points=6000, repeats=1, loop_sample=600)
    assert figures["points"] == 6000
    assert "unit-aware API" in capsys.readouterr().out
