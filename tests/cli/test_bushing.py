"""CLI of ``bearingheat bushing``: sizing text and JSON, exit codes by type, oscillation, ``python -m bearingheat``."""
from __future__ import annotations

import json
import pathlib
import subprocess
import sys

import pytest

from bearingheat.cli import main

REPO = pathlib.Path(__file__).resolve().parents[2]


def test_bushing_text_shows_the_kgf_conversion(capsys):
    code = main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "rotating_fixed_load_point", "--standard", "20,30,50,100mm"])
    assert code == 0
    out = capsys.readouterr().out
    assert "K = pV = 5.65 kgf/cm²·m/s × 0.0980665 = 0.5541 N/mm²·m/s" in out
    assert "4. standard length: 100 mm" in out


def test_bushing_json(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--K", "0.5N/mm^2*m/s",
                 "--load-type", "static", "--f", "0.12", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["l_required [mm]"] == pytest.approx(104.72, rel=1e-4)
    assert result["N_low [W]"] == result["N_high [W]"] == pytest.approx(0.12 * 2000 * 0.654498, rel=1e-5)


def test_bushing_below_minimum_speed_is_sized_with_a_note(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "20rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "static"]) == 0
    out = capsys.readouterr().out
    assert "  friction loss: the DU/DP bushing handbook gives no f below 0.05 m/s; give --f\n" in out
    assert out.endswith("  note: V = 0.02618 m/s is below 0.05 m/s: the DU/DP bushing handbook allows a smaller "
                        "size than calculated there (the size is conservative)\n")


def test_bushing_temperature_outside_table_exit_1(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "static", "--T", "300degC"]) == 1
    assert capsys.readouterr().err == (
        "bearingheat bushing: T = 300 °C is outside the range of the DU/DP bushing handbook table 25 "
        "(-200 to +280 °C)\n")


def test_bushing_lost_table_value_exit_2(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "hardened", "--life", "10000h",
                 "--load-type", "static"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat bushing: error: the DU/DP bushing handbook table 25: K for bushing_constant_load, hardened shaft, 10000 h "
        "was lost in the OCR of the DU/DP bushing handbook; give K directly\n")


def test_bushing_oscillation_speed(capsys):
    # 600 cycles/min x 90 deg (0.25 rev) = 150 1/min
    assert main(["bushing", "--F", "1kN", "--cycles", "600/min", "--amplitude", "90deg", "--d", "25mm",
                 "--application", "bushing_oscillating", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "rotating_fixed_load_point", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["n [1/min]"] == pytest.approx(150.0)


def test_subprocess_python_m_bearingheat():
    proc = subprocess.run([sys.executable, "-m", "bearingheat", "bushing", "--F", "2kN", "--n", "500rpm",
                           "--d", "25mm", "--shaft", "soft", "--life", "1000h", "--load-type", "static"],
                          capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "governed by pV: l = 94.5 mm" in proc.stdout


@pytest.mark.parametrize("option, text, shown", [("--n", "500", "500rpm"), ("--T", "150", "150degC"),
                                                 ("--life", "1000", "1000h")])
def test_a_number_without_a_unit_is_shown_with_a_unit_of_its_kind(capsys, option, text, shown):
    args = {"--F": "2kN", "--n": "500rpm", "--d": "25mm", "--shaft": "soft", "--life": "1000h",
            "--load-type": "static", option: text}
    assert main(["bushing", *[part for pair in args.items() for part in pair]]) == 2
    assert capsys.readouterr().err.strip() == (f"bearingheat bushing: error: {option}: {text!r} has no unit; write it "
                                               f"with one, e.g. {shown}")


def test_an_unknown_load_type_is_refused_with_p_adm_too(capsys):
    assert main(["bushing", "--F", "2kN", "--n", "500rpm", "--d", "25mm", "--shaft", "soft", "--life", "1000h",
                 "--load-type", "bogus", "--p-adm", "20N/mm^2"]) == 2
    assert "load type 'bogus' unknown" in capsys.readouterr().err


def test_a_closed_pipe_ends_the_output_quietly(tmp_path):
    import subprocess
    import sys
    done = subprocess.run(f"{sys.executable} -m bearingheat lookup 6208 | head -1", shell=True, capture_output=True,
                          text=True)
    assert done.stdout == "designation: 6208\n" and done.stderr == ""
