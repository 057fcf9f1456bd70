"""The synthetic example of measured torque: the committed file is the script's, and diagnose finds its effect."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pandas as pd
import pytest

from bearingheat.analysis.diagnose import diagnose_table

ROOT = Path(__file__).resolve().parents[2]


def _script():
    spec = importlib.util.spec_from_file_location("make_example_measured", ROOT / "scripts" / "make_example_measured.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_committed_file_is_the_scripts_output(tmp_path):
    script = _script()
    fresh = tmp_path / "example.csv"
    script.measured_example().to_csv(fresh, index=False)
    assert fresh.read_text() == (ROOT / "examples" / "measured_torque_example.csv").read_text()


def test_diagnose_finds_the_seal_drag_it_was_made_with():
    script = _script()
    diagnosis = diagnose_table(pd.read_csv(ROOT / "examples" / "measured_torque_example.csv"))
    assert diagnosis.effect == "seal_drag"
    found = diagnosis.summary()["parameters"]["M_seal [N*mm]"]
    for designation, torque in script.SEAL_DRAG.items():
        # the data carry the seal torque plus 5 % at the top speed: about 2.5 % more on average
        assert found[designation] == pytest.approx(torque * 1.025, rel=0.06)
