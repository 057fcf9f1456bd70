"""-q/--quiet prints nothing but errors, and the files are still written: bushing, lookup, plot, coastdown, audit."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
from synthetic_torque import measured_set
from thermal_helpers import plot_table

from bearingheat.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BUSHING = ["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
           "--load-type", "static"]


@pytest.mark.parametrize("quiet", ["-q", "--quiet"])
def test_bushing_quiet_prints_nothing(capsys, quiet):
    assert main([*BUSHING, quiet]) == 0
    assert capsys.readouterr() == ("", "")


def test_bushing_quiet_still_says_why_the_duty_is_outside_the_method(capsys):
    argv = [*BUSHING, "-q", "--T", "300degC"]
    assert main(argv) == 1
    assert capsys.readouterr() == ("", (
        "bearingheat bushing: T = 300 °C is outside the range of the DU/DP bushing handbook table 25 "
        "(-200 to +280 °C)\n"))


def test_bushing_json_wins_over_quiet(capsys):
    assert main([*BUSHING, "--K", "0.5N/mm^2*m/s", "--json", "-q"]) == 0
    assert json.loads(capsys.readouterr().out)["l_required [mm]"] == pytest.approx(104.72, rel=1e-4)


def test_lookup_quiet_prints_nothing_and_the_exit_code_tells(capsys):
    assert main(["lookup", "6208", "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    assert main(["lookup", "6208-2ZZ", "--quiet"]) == 2
    assert capsys.readouterr() == ("", (
        "bearingheat lookup: error: designation: '6208-2ZZ' is not in the bearing table (Schaeffler HR 1, 2006); "
        "close matches: 6208-2Z, 6208-2RSR, 6208, 608-2Z, 6320-2Z\n"))


def test_plot_quiet_writes_the_figure_and_prints_nothing(tmp_path, capsys):
    png = tmp_path / "heat.png"
    assert main(["plot", str(plot_table(tmp_path)), "--id", "b", "-o", str(png), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_quiet_leaves_out_the_warning(tmp_path, capsys):
    source = plot_table(tmp_path, **{"n [rpm]": [30000, 30000]})
    assert main(["plot", str(source), "--row", "0", "-o", str(tmp_path / "loud.svg")]) == 0
    assert capsys.readouterr() == (f"wrote {tmp_path / 'loud.svg'}\n", (
        "bearingheat plot: warning: n [rpm]: 30000 is above the limiting speed n_G = 17000 1/min of 6205 (Schaeffler "
        "HR 1, 2006); check the speed and its unit; "
        "T_op: no equilibrium up to 150 degC, the upper end of the search: the friction heat still exceeds the heat "
        "carried away there; with the catalogue model the friction heat stays bounded as the temperature rises while "
        "the heat carried away grows with it, so an equilibrium lies above; T_op is not computed\n"))
    assert main(["plot", str(source), "--row", "0", "-o", str(tmp_path / "quiet.svg"), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    assert (tmp_path / "quiet.svg").read_text().lstrip().startswith("<?xml")


def test_plot_quiet_still_prints_errors(tmp_path, capsys):
    png = tmp_path / "heat.png"
    png.write_bytes(b"old")
    assert main(["plot", str(plot_table(tmp_path)), "-o", str(png), "-q"]) == 2
    assert capsys.readouterr() == ("", f"bearingheat plot: error: {png} exists; give --force to replace it\n")
    assert png.read_bytes() == b"old"


def test_coastdown_quiet_writes_the_files_and_prints_nothing(tmp_path, capsys):
    out = tmp_path / "run"
    out.mkdir()
    assert main(["coastdown", str(EXAMPLES / "coastdown_example.csv"), "--out-dir", str(out), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    assert sorted(p.name for p in out.iterdir()) == ["coastdown.png", "report.md", "summary.json"]
    assert json.loads((out / "summary.json").read_text())["model"] == "coulomb_viscous_aero"


def test_coastdown_quiet_with_json_prints_the_summary(capsys):
    assert main(["coastdown", str(EXAMPLES / "coastdown_example.csv"), "--json", "-q"]) == 0
    assert json.loads(capsys.readouterr().out)["model"] == "coulomb_viscous_aero"


def test_audit_coefficients_quiet_writes_the_table_and_prints_nothing(tmp_path, capsys):
    table, _, _ = measured_set("none", 3, designations=["6004", "6310"])
    source = tmp_path / "m.csv"
    table.to_csv(source, index=False)
    out = tmp_path / "out"
    out.mkdir()
    assert main(["audit", str(source), "--out-dir", str(out), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    assert sorted(p.name for p in out.iterdir()) == ["coefficients.csv"]


def test_contact_quiet_prints_only_errors(tmp_path, capsys):
    """contact -q: no record and no warning; a row in error is still reported on stderr (exit 1)."""
    args = ["contact", "--z", "7", "--dw", "2mm", "--dm", "8.7355mm", "--ri", "1.05mm", "--ro", "1.16mm",
            "--alpha0", "12deg", "--Fa", "0.1gf", "--n", "3000rpm"]
    assert main(args) == 0
    loud = capsys.readouterr()
    assert "Fa_min" in loud.out and loud.err.startswith("bearingheat contact: warning: Fa = 0.0009807 N is below")
    assert main([*args, "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    table = tmp_path / "bearings.csv"
    table.write_text("z,Dw [mm],dm_pitch [mm],ri [mm],ro [mm],alpha0 [deg]\n7,2,8.7355,1.05,1.16,12\n7,2,x,1,1,12\n")
    assert main(["contact", str(table), "-q"]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err == "bearingheat contact: error: row 2: dm_pitch: 'x' is not a number\n"


def test_calc_quiet_says_how_many_rows_are_in_error_and_where(tmp_path, capsys):
    """-q prints nothing but errors: nothing for a table without row errors, one line for rows in error (the exit
    code alone says only that there are some), in each of the three ways calc writes."""
    source = tmp_path / "in.csv"
    source.write_text((EXAMPLES / "gearbox_shaft.csv").read_text())
    assert main(["calc", str(source), "-q"]) == 0
    assert capsys.readouterr() == ("", "")
    text = source.read_text().splitlines()
    text[2] = text[2].replace("oil_bath", "oil", 1)
    source.write_text("\n".join(text) + "\n")
    assert main(["calc", str(source), "-q"]) == 1
    assert capsys.readouterr() == ("", "error: 1 of 6 supports are in error; see their messages (run without -q to see "
                                       "them)\n")
    out = tmp_path / "out.parquet"
    assert main(["calc", str(source), "-q", "-o", str(out)]) == 1
    assert capsys.readouterr().err == f"error: 1 of 6 supports are in error; see the message column of {out}\n"
