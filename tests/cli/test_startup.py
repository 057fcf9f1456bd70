"""The command line and the package load only what they use: no command module for --help or --version, one for
its own command; ``import bearingheat`` loads neither numpy nor pandas until a function is used."""
import json
import subprocess
import sys

import pytest

PROBE = """
import contextlib, io, json, sys
import bearingheat
by_import = sorted(m for m in ("numpy", "pandas", "scipy", "pint") if m in sys.modules)
from bearingheat.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    try:
        main({argv!r})
    except SystemExit:
        pass
print(json.dumps({{"import": by_import, "commands": sorted(m for m in sys.modules if m.startswith("bearingheat.cli.")),
                  "stats": "scipy.stats" in sys.modules}}))
"""


@pytest.mark.parametrize("argv, commands", [
    (["--version"], []),
    (["--help"], []),
    (["lookup", "6205"], ["bearingheat.cli.lookup", "bearingheat.cli.options"]),
    (["bushing", "--help"], ["bearingheat.cli.bushing", "bearingheat.cli.options"]),
])
def test_only_the_command_that_runs_is_imported(argv, commands):
    out = subprocess.run([sys.executable, "-c", PROBE.format(argv=argv)], capture_output=True, text=True,
                         check=True).stdout
    loaded = json.loads(out)
    assert loaded["import"] == []        # import bearingheat alone: no numpy, pandas, scipy or pint
    assert loaded["commands"] == commands
    assert loaded["stats"] is False      # scipy.stats (0.6 s) only for the commands that fit statistics


def test_the_function_calc_survives_the_import_of_its_subpackage():
    import bearingheat as bh
    import bearingheat.calc.models  # noqa: F401  (sets the package's 'calc' attribute to the subpackage, ignored)
    from bearingheat.calc.table import calc
    assert bh.calc is calc and callable(bh.calc)


def test_calc_of_a_table_loads_neither_the_excel_bridge_nor_scipy_optimize(tmp_path):
    """A CSV calc without ball geometry or --effects does not import openpyxl (the Excel bridge) or
    scipy.optimize (the contact kernel, the fitted effects): 0.4 s of start-up a run."""
    table = tmp_path / "in.csv"
    table.write_text("designation,d [mm],D [mm],C0 [kN],lubrication,n [rpm],Fr [kN],nu [mm^2/s]\n"
                     "6205,25,52,7.8,oil_bath,3000,2,12\n")
    probe = (f"import sys\nfrom bearingheat.cli import main\nstatus = main(['calc', {str(table)!r}, '-q'])\n"
             "print(status, 'openpyxl' in sys.modules, 'scipy.optimize' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["0", "False", "False"]


def _program(argv, cache_home):
    """``python -m bearingheat`` in a process of its own, with the user's cache folder at ``cache_home``."""
    env = {**__import__("os").environ, "XDG_CACHE_HOME": str(cache_home)}
    return subprocess.run([sys.executable, "-m", "bearingheat", *argv], capture_output=True, text=True, env=env)


def test_the_program_keeps_pints_parsed_definitions_in_the_users_cache_and_gives_the_same_output(tmp_path, capsys):
    from bearingheat.cli import main
    main(["lookup", "6205"])
    expected = capsys.readouterr().out
    first, again = _program(["lookup", "6205"], tmp_path), _program(["lookup", "6205"], tmp_path)
    assert (first.returncode, first.stdout, again.returncode, again.stdout) == (0, expected, 0, expected)
    assert {p.suffix for p in (tmp_path / "pint").iterdir()} == {".json", ".pickle"}  # pint's own cache files


def test_a_damaged_definition_cache_is_built_again_and_other_cache_files_stay(tmp_path):
    import pickle
    assert _program(["lookup", "6205"], tmp_path).returncode == 0
    folder = tmp_path / "pint"
    written = sorted(folder.glob("*.pickle"))
    for pickled in written:
        pickled.write_bytes(pickled.read_bytes()[:100])  # cut short, as by a run killed while it wrote
    other = folder / "another_registry.pickle"
    other.write_bytes(pickle.dumps({"kept": 1}))  # a readable cache file of other definitions
    damaged = _program(["lookup", "6205"], tmp_path)
    assert (damaged.returncode, damaged.stderr) == (0, "")
    assert "6205" in damaged.stdout and "C0" in damaged.stdout
    assert sorted(folder.glob("*.pickle")) == sorted([*written, other])
    for pickled in written:  # whole again: the next start reads them
        with pickled.open("rb") as file:
            pickle.load(file)
    assert pickle.loads(other.read_bytes()) == {"kept": 1}
    stamps = {path: path.stat().st_mtime_ns for path in written}
    assert _program(["lookup", "6205"], tmp_path).stdout == damaged.stdout
    assert {path: path.stat().st_mtime_ns for path in written} == stamps  # read, not written again


def test_the_definition_cache_leaves_a_registry_in_use_alone():
    import pint
    from bearingheat.units import use_definition_cache, ureg
    ureg().parse_units("mm")  # the application registry, loaded
    registry = pint.get_application_registry().get()
    assert use_definition_cache() is False
    assert pint.get_application_registry().get() is registry
