"""calc --vm-chart: a blank VM of SKF oil-bath rows read off a digitised chart; an unusable chart is exit 2."""
from pathlib import Path

import pandas as pd
import pytest

from bearingheat.cli import main

ROOT = Path(__file__).resolve().parents[2]
CHART = ROOT / "docs" / "vm_chart_example.csv"   # made-up points; the 6000 roller curve gives 0.3e-4 at H/dm = 1/24

# the SKF 6000 worked example (pp. 104-105) without its VM: 22208 E in an oil bath, H = 2.5 mm, dm = 60 mm
ROW = ("designation,d [mm],D [mm],B [mm],lubrication,n [1/min],Fr [N],Fa [N],nu [mm^2/s],oil_level [mm],"
       "skf_edition,mu_sl,model\n22208 E,40,80,23,oil_bath,3500,2990,100,68,2.5,6000,0.05,skf\n")


def test_vm_read_off_the_chart(tmp_path):
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    src.write_text(ROW)
    assert main(["calc", str(src), "-o", str(out), "-q", "--vm-chart", str(CHART)]) == 0
    result = pd.read_csv(out)
    assert result.loc[0, "VM_chart"] == pytest.approx(0.3e-4, rel=1e-6)
    assert result.loc[0, "M_drag [N*mm]"] == pytest.approx(14.5, abs=0.05)   # printed: Mdrag = 14.5 N·mm
    assert result.loc[0, "MR [N*mm]"] == pytest.approx(334, rel=0.01)        # printed: M = 334 N·mm


def test_without_the_chart_the_row_names_what_to_read(tmp_path, capsys):
    src = tmp_path / "in.csv"
    src.write_text(ROW)
    assert main(["calc", str(src), "--json"]) == 1
    assert "an oil bath needs the drag loss factor VM: read it off SKF 6000 diagram 2" in capsys.readouterr().out


def test_an_unusable_chart_is_exit_2(tmp_path, capsys):
    src, chart = tmp_path / "in.csv", tmp_path / "vm.csv"
    src.write_text(ROW)
    chart.write_text("edition,curve,H_over_dm,VM\n-,-,1,1\n6000,roller,0,0\n")
    assert main(["calc", str(src), "--vm-chart", str(chart)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {chart}, edition '6000' curve 'roller': needs at "
                                       "least two points, has 1\n")
