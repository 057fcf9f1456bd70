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
