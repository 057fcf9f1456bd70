"""calc --formulas refuses a row of the SKF model and says why."""
from __future__ import annotations

import shutil
from pathlib import Path

from bearingheat.cli import main

EXAMPLE = Path(__file__).resolve().parents[3] / "spreadsheets" / "gearbox_shaft_example.xlsx"


def test_formulas_refuse_the_skf_model_with_the_reason(tmp_path, capsys):
    source = tmp_path / "example.xlsx"
    shutil.copyfile(EXAMPLE, source)
    assert main(["calc", str(source), "-o", str(tmp_path / "out.xlsx"), "--formulas", "--model", "skf"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat calc: error: --formulas: the friction model 'skf' of row 8 has no Excel formulas: its "
        "per-type geometry constants (R1-R4, S1-S5), the seal and drag tables, the inlet shear and replenishment "
        "factors and the edition's drag formula would take some forty helper cells a row, too many to check by "
        "eye; bearingheat writes its results as numbers; run calc without --formulas\n")
    assert not (tmp_path / "out.xlsx").exists()
