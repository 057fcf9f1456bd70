"""Lubricant tables (issue 3): ISO 3448 grades and ASTM D2270 table 1."""
from __future__ import annotations

import numpy as np

from bearingheat.catalogue.tables import load_table, table_units


def test_iso_vg_table_reads_back():
    table = load_table("iso_vg_grades")
    assert table["grade"].tolist() == [2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000,
                                       1500, 2200, 3200]
    assert table["nu40"].tolist() == [2.2, 3.2, 4.6, 6.8, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680,
                                      1000, 1500, 2200, 3200]
    np.testing.assert_allclose(table["nu40_min"], 0.9 * table["nu40"], rtol=1e-9)
    np.testing.assert_allclose(table["nu40_max"], 1.1 * table["nu40"], rtol=1e-9)
    assert table_units("iso_vg_grades")["nu40"] == "mm^2/s"
    assert all("ISO 3448" in s for s in table["source"])


def test_astm_d2270_table_reads_back():
    table = load_table("astm_d2270_viscosity_index")
    assert len(table) == 311
    rows = table.set_index("nu100")[["L", "H"]]
    assert rows.loc[2.0].tolist() == [7.994, 6.394]
    assert rows.loc[8.8].tolist() == [118.5, 68.79]
    assert rows.loc[20.0].tolist() == [493.2, 229.5]
    assert rows.loc[70.0].tolist() == [4905.0, 1558.0]
    assert table["nu100"].is_monotonic_increasing and table["L"].is_monotonic_increasing
    assert (table["L"] > table["H"]).all()
