"""``bearingheat calc`` writes the heat-balance columns (extension bearingheat.calc.thermal)."""
from __future__ import annotations

import pandas as pd
from thermal_helpers import THERMAL_COLUMNS, supports

from bearingheat.cli import main


def test_calc_cli_writes_thermal_columns(tmp_path, capsys):
    source = tmp_path / "supports.csv"
    supports(**{"iso_vg": [68, 68], "T_amb [degC]": [20, 20], "T_bearing [degC]": [70, 70]}).to_csv(source,
                                                                                                    index=False)
    target = tmp_path / "out.csv"
    assert main(["calc", str(source), "-o", str(target), "-q"]) == 0
    written = pd.read_csv(target)
    for column in THERMAL_COLUMNS:
        assert column in written.columns
    assert written["n_per [1/min]"].notna().all()
