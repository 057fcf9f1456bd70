"""``bearingheat contact``: Zaitsev & Voronkin example from arguments and from a CSV, exit codes, exact messages."""
import json
import subprocess
import sys

import pytest

from bearingheat.cli import main

GEOMETRY = ["--z", "7", "--dw", "2mm", "--dm", "8.7355mm", "--ri", "1.05mm", "--ro", "1.16mm"]
KGF = 9.80665


def run_json(capsys, *extra):
    code = main(["contact", *GEOMETRY, *extra, "--json"])
    captured = capsys.readouterr()
    return code, json.loads(captured.out), captured.err


def test_seed_example_json(capsys):
    code, record, err = run_json(capsys, "--alpha0", "12deg", "--Fa", "2kgf", "--n", "3000rpm")
    assert code == 0 and err == ""
    for key in ("alpha0 [deg]", "alpha [deg]", "xi_a", "C_star [N]", "Fa_min [N]"):
        assert key in record
    assert record["alpha0 [deg]"] == 12.0
    assert abs(record["alpha [deg]"] - (14 + 28 / 60)) * 3600 <= 10
    assert record["xi_a"] == pytest.approx(0.04447, abs=2e-4)
    assert record["C_star [N]"] / KGF == pytest.approx(7.79e3, rel=0.003)
    assert record["Fa [N]"] == pytest.approx(2 * KGF)
    expected_kgf = 5.75e-12 * 7 * 8 * 8.7355 * 3000**2 * 0.0432272712 * (1 - (2 / 8.7355) ** 2 * 0.9567727288)
    assert record["Fa_min [N]"] == pytest.approx(expected_kgf * KGF, rel=1e-6)
    assert record["Fa_min at alpha [N]"] > record["Fa_min [N]"]


def test_text_output(capsys):
    assert main(["contact", *GEOMETRY, "--alpha0", "12deg", "--Fa", "19.6133N"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "alpha0 [deg]: 12"
    assert "alpha [deg]: 14.4658" in lines
    assert "sum_rho_i [1/mm]: 1.33619" in lines
    assert "cos_tau_o: 0.711127" in lines
    assert not any(line.startswith("Fa_min") for line in lines)


def test_clearance_and_no_load(capsys):
    e_um = 2 * 0.21 * (1 - 0.9781476007338057) * 1000  # clearance giving alpha0 = 12 deg
    code, record, _ = run_json(capsys, "--clearance", f"{e_um!r}um")
    assert code == 0
    assert record["alpha0 [deg]"] == pytest.approx(12.0, abs=1e-9)
    assert record["alpha [deg]"] == record["alpha0 [deg]"] and record["xi_a"] == 0.0 and record["Fa [N]"] == 0.0


def test_warning_below_minimum_axial_load(capsys):
    code, record, err = run_json(capsys, "--alpha0", "12deg", "--Fa", "0.5N", "--n", "30000rpm")
    assert code == 0
    message = ("Fa = 0.5 N is below the minimum axial load Fa_min = 1.019 N at n = 30000 1/min "
               "(gyroscopic sliding of the balls, Zaitsev & Voronkin)")
    assert err == f"bearingheat contact: warning: {message}\n"
    assert record["warning"] == message


def test_warning_between_the_minimum_at_alpha0_and_at_the_working_angle(capsys):
    """Both minimum loads are printed; Fa = 1.05 N at 30 000 1/min meets 1.019 N (at α0) but not 1.091 N (at α)."""
    code, record, err = run_json(capsys, "--alpha0", "12deg", "--Fa", "1.05N", "--n", "30000rpm")
    assert code == 0
    assert (round(record["Fa_min [N]"], 3), round(record["Fa_min at alpha [N]"], 3)) == (1.019, 1.091)
    message = ("Fa = 1.05 N meets the minimum axial load at the initial angle alpha0 = 12 deg, Fa_min = 1.019 N "
               "(Zaitsev & Voronkin's rule), but not the stricter one at the working angle alpha = 12.42 deg under "
               "this load, Fa_min at alpha = 1.091 N, at n = 30000 1/min: the balls may slide under their "
               "gyroscopic moment")
    assert err == f"bearingheat contact: warning: {message}\n"
    assert record["warning"] == message


@pytest.mark.parametrize("argv, message", [
    ([*GEOMETRY, "--alpha0", "12deg", "--clearance", "0.01mm"],
     "give exactly one of --alpha0 (e.g. 12deg) or --clearance (e.g. 0.01mm)"),
    (["--z", "7", "--dw", "2mm", "--alpha0", "12deg"], "missing --dm, --ri, --ro (or give a TABLE of bearings)"),
    ([*GEOMETRY[:2], "--dw", "2", *GEOMETRY[4:], "--alpha0", "12deg"],
     "--dw: '2' has no unit; write it with one, e.g. 2mm"),
    (["--z", "7", "--dw", "2mm", "--dm", "8.7355mm", "--ri", "0.9mm", "--ro", "1.0mm", "--alpha0", "12deg"],
     "impossible geometry: r_i + r_o = 1.9 mm must exceed d_w = 2 mm"),
    ([*GEOMETRY, "--clearance=-0.01mm"], "e = -0.01 mm: the radial clearance must not be negative"),
    ([*GEOMETRY, "--alpha0", "12deg", "--Fa", "2kg"],
     "Fa: 2 kilogram is a mass, not a force; for kilogram-force write 2 kgf"),
    (["--z", "seven", *GEOMETRY[2:], "--alpha0", "12deg"], "--z: 'seven' is not a number"),
    (["x.csv", "--z", "7"], "TABLE gives the bearings; drop --z"),
    (["/nonexistent/bearings.csv"], "no such file: /nonexistent/bearings.csv"),
])
def test_usage_errors_exit_2(capsys, argv, message):
    assert main(["contact", *argv]) == 2
    assert capsys.readouterr().err == f"bearingheat contact: error: {message}\n"


CSV_TEXT = """designation,z,Dw [mm],dm_pitch [mm],ri [mm],ro [mm],alpha0 [deg],Fa [kgf],n [1/min],note
4-1006095,7,2,8.7355,1.05,1.16,12,2,3000,Zaitsev & Voronkin example
bad grooves,7,2,8.7355,0.9,1.0,12,2,3000,
no load,7,0.2cm,8.7355,1.05,1.16,12,,,
"""


def test_csv_rows_and_errors(tmp_path, capsys):
    path = tmp_path / "bearings.csv"
    path.write_text(CSV_TEXT, encoding="utf-8")
    assert main(["contact", str(path), "--json"]) == 1
    captured = capsys.readouterr()
    records = json.loads(captured.out)
    assert [r["row"] for r in records] == [1, 2, 3]
    first = records[0]
    assert first["designation"] == "4-1006095"
    assert abs(first["alpha [deg]"] - (14 + 28 / 60)) * 3600 <= 10
    assert first["C_star [N]"] / KGF == pytest.approx(7.79e3, rel=0.003)
    assert records[1]["error"] == "impossible geometry: r_i + r_o = 1.9 mm must exceed d_w = 2 mm"
    assert records[2]["error"] == "Dw: '0.2cm' is not a number"
    assert captured.err == (
        "bearingheat contact: error: row 2: impossible geometry: r_i + r_o = 1.9 mm must exceed d_w = 2 mm\n"
        "bearingheat contact: error: row 3: Dw: '0.2cm' is not a number\n")


def test_csv_units_from_header_and_csv_output(tmp_path, capsys):
    path = tmp_path / "bearings.csv"
    path.write_text("z,Dw [um],dm_pitch [cm],ri [mm],ro [mm],clearance [um],Fa [N]\n"
                    "7,2000,0.87355,1.05,1.16,9.178008,19.6133\n", encoding="utf-8")
    assert main(["contact", str(path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    header, row = lines[0].split(","), lines[1].split(",")
    values = dict(zip(header, row))
    assert header[0] == "row" and header[-2:] == ["warning", "error"]
    assert float(values["alpha0 [deg]"]) == pytest.approx(12.0, abs=1e-4)
    assert float(values["alpha [deg]"]) == pytest.approx(14.4658, abs=1e-4)
    assert values["error"] == ""


@pytest.mark.parametrize("text, message", [
    ("z,Dw [mm],ri [mm],ro [mm]\n7,2,1.05,1.16\n", "missing column(s) dm_pitch, alpha0 [deg] or clearance [mm]"),
    ("z,Dw,dm_pitch [mm],ri [mm],ro [mm],alpha0 [deg]\n", "column 'Dw' has no unit; write it as 'Dw [mm]'"),
    ("z,Dw [N],dm_pitch [mm],ri [mm],ro [mm],alpha0 [deg]\n",
     "column 'Dw': unit 'N' is not a length; write it as 'Dw [mm]'"),
    ("z,Dw [mm],dm_pitch [mm],ri [mm],ro [mm],alpha0 [1]\n", "column 'alpha0': unit '1' is not an angle; "
     "write it as 'alpha0 [deg]'"),
    ("", "the file is empty"),
])
def test_csv_unusable_exit_2(tmp_path, capsys, text, message):
    path = tmp_path / "bearings.csv"
    path.write_text(text, encoding="utf-8")
    assert main(["contact", str(path)]) == 2
    assert capsys.readouterr().err == f"bearingheat contact: error: {path}: {message}\n"


def test_subprocess_python_m_bearingheat():
    done = subprocess.run(
        [sys.executable, "-m", "bearingheat", "contact", *GEOMETRY, "--alpha0", "12deg", "--Fa", "2kgf", "--json"],
        capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    record = json.loads(done.stdout)
    assert abs(record["alpha [deg]"] - (14 + 28 / 60)) * 3600 <= 10


def test_a_table_with_only_a_header_is_refused(tmp_path, capsys):
    path = tmp_path / "head.csv"
    path.write_text("designation,z,Dw [mm],dm_pitch [mm],ri [mm],ro [mm],alpha0 [deg],Fa [kgf],n [rpm]\n")
    assert main(["contact", str(path)]) == 2
    assert capsys.readouterr().err == f"bearingheat contact: error: {path}: no bearings (only a header row)\n"


@pytest.mark.parametrize("z", [True, "7"])
def test_a_count_of_balls_is_a_number(z):
    from bearingheat.api.contact import ball_bearing_contact
    from bearingheat.errors import ContactInputError
    from bearingheat.units import ureg
    u = ureg()
    with pytest.raises(ContactInputError) as exc:
        ball_bearing_contact(z=z, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm, alpha0=12 * u.deg)
    assert str(exc.value) == f"z: {z!r} is not a number of balls"
