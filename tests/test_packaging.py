"""The docs build without warnings, the README example runs, and the wheel ships the tables."""
import doctest
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_docs_build_without_warnings(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", str(ROOT / "docs"),
                           str(tmp_path / "html")], capture_output=True, text=True, check=False)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "html" / "friction.html").exists()


def test_readme_examples_run():
    result = doctest.testfile(str(ROOT / "README.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


def test_readme_starts_with_the_two_commands():
    lines = [line for line in (ROOT / "README.md").read_text().splitlines() if line.strip()]
    fence = lines.index("```sh")
    assert lines[fence + 1:fence + 3] == ["make demo", "make test"]


@pytest.mark.integration
def test_wheel_ships_every_table(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(ROOT)],
                          capture_output=True, text=True, check=False, env={**os.environ, "PIP_NO_INPUT": "1"})
    assert proc.returncode == 0, proc.stderr
    wheel = next(tmp_path.glob("bearingheat-*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
    for table in (ROOT / "tables").glob("*.csv"):
        assert f"bearingheat/tables/{table.name}" in names


def _wheel_in_fresh_venv(tmp_path, prepare=None) -> tuple[Path, Path, Path]:
    """(wheel, python of a fresh venv with the wheel installed, its site-packages); ``prepare(site)`` runs
    before the install. The dependencies come from this interpreter's site-packages (a path entry, so its
    editable finder of bearingheat is not activated); bearingheat itself only from the wheel."""
    import sysconfig
    import venv

    proc = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path / "dist"),
                           str(ROOT)], capture_output=True, text=True, check=False,
                          env={**os.environ, "PIP_NO_INPUT": "1"})
    assert proc.returncode == 0, proc.stderr
    wheel = next((tmp_path / "dist").glob("bearingheat-*.whl"))
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(with_pip=False).create(env_dir)
    python = env_dir / "bin" / "python"
    site = Path(subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                               capture_output=True, text=True, check=True).stdout.strip())
    (site / "dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    if prepare is not None:
        prepare(site)
    install = subprocess.run([sys.executable, "-m", "pip", "install", "--no-deps", "--no-index", "-q", "--target",
                              str(site), str(wheel)], capture_output=True, text=True, check=False)
    assert install.returncode == 0, install.stderr
    return wheel, python, site


@pytest.mark.integration
def test_wheel_installs_into_a_fresh_venv_and_runs_the_demo(tmp_path):
    """The built wheel (not the editable checkout) holds every subpackage and table the demo needs."""
    wheel, python, site = _wheel_in_fresh_venv(tmp_path)
    names = set(zipfile.ZipFile(wheel).namelist())
    for package in sorted(p.parent for p in (ROOT / "bearingheat").rglob("__init__.py")):
        relative = package.relative_to(ROOT).as_posix()
        assert f"{relative}/__init__.py" in names, relative
    out = tmp_path / "results.csv"
    run = subprocess.run([str(python), "-m", "bearingheat", "calc", str(ROOT / "examples" / "gearbox_shaft.csv"),
                          "-o", str(out)], capture_output=True, text=True, cwd=tmp_path, check=False)
    assert run.returncode == 0, run.stderr
    assert "6 supports: 5 ok, 1 warning, 0 error" in run.stdout
    where = subprocess.run([str(python), "-c", "import bearingheat; print(bearingheat.__file__)"],
                           capture_output=True, text=True, cwd=tmp_path, check=True).stdout
    assert where.startswith(str(site))


@pytest.mark.integration
def test_wheel_and_sdist_contents(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "build", "--wheel", "--sdist", "--outdir", str(tmp_path), str(ROOT)],
                          capture_output=True, text=True, check=False, env={**os.environ, "PIP_NO_INPUT": "1"})
    assert proc.returncode == 0, proc.stderr[-2000:]
    wheel = zipfile.ZipFile(next(tmp_path.glob("bearingheat-*.whl")))
    names = set(wheel.namelist())
    version = __import__("bearingheat").__version__
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    assert "bearingheat/py.typed" in names  # PEP 561: type checkers use the package's own hints
    packages = {p.parent.relative_to(ROOT).as_posix() for p in (ROOT / "bearingheat").rglob("__init__.py")}
    assert {f"{package}/__init__.py" for package in packages} <= names
    assert not any(n.startswith(("tests/", ".venv/", "docs/", "benchmarks/")) for n in names)
    for table in (ROOT / "tables").glob("*.csv"):
        assert f"bearingheat/tables/{table.name}" in names
    metadata = wheel.read(f"bearingheat-{version}.dist-info/METADATA").decode()
    assert f"Version: {version}" in metadata and "License-Expression: MIT" in metadata
    assert "Provides-Extra: plot" in metadata and "Requires-Dist: matplotlib>=3.7; extra == \"plot\"" in metadata
    assert not any(line.startswith("Requires-Dist: matplotlib") and "extra" not in line for line in metadata.splitlines())
    import tarfile
    with tarfile.open(next(tmp_path.glob("bearingheat-*.tar.gz"))) as sdist:
        members = {m.split("/", 1)[1] for m in sdist.getnames() if "/" in m}
    for needed in ("LICENSE", "README.md", "pyproject.toml", "bearingheat/__init__.py", "bearingheat/cli/calc.py",
                   "bearingheat/py.typed"):
        assert needed in members, needed
    assert {f"bearingheat/tables/{t.name}" for t in (ROOT / "tables").glob("*.csv")} <= members


@pytest.mark.integration
def test_the_core_runs_without_matplotlib_and_plots_name_the_extra(tmp_path):
    def hide_matplotlib(site: Path) -> None:
        # matplotlib is not installed in this environment: its package is shadowed by one that cannot be imported
        (site / "matplotlib").mkdir()
        (site / "matplotlib" / "__init__.py").write_text("raise ImportError(\"No module named 'matplotlib'\")\n")

    _, python, _ = _wheel_in_fresh_venv(tmp_path, hide_matplotlib)
    demo = str(ROOT / "examples" / "gearbox_shaft.csv")
    calc = subprocess.run([str(python), "-m", "bearingheat", "calc", demo, "-q"], capture_output=True, text=True,
                          cwd=tmp_path, check=False)
    assert calc.returncode == 0, calc.stderr
    plot = subprocess.run([str(python), "-m", "bearingheat", "plot", demo, "-o", str(tmp_path / "p.png")],
                          capture_output=True, text=True, cwd=tmp_path, check=False)
    assert plot.returncode == 2
    assert plot.stderr.strip().endswith("plotting needs matplotlib, which is not installed: pip install "
                                        "'bearingheat[plot]'")


def test_dir_lists_the_public_names_not_the_helpers():
    """dir(bearingheat) and dir(bearingheat.api) (an editor's completion) show the public API, the package's own
    modules and the dunder names; the helpers the packages import for themselves are left out."""
    import bearingheat
    import bearingheat.api

    for package in (bearingheat, bearingheat.api):
        names = set(dir(package))
        assert set(package.__all__) <= names and "__doc__" in names
        assert not names & {"sys", "types", "importlib", "copyreg", "Any", "Callable", "TYPE_CHECKING",
                            "annotations", "lazy_exports", "ModuleType", "_EXPORTS"}
    assert {"calc", "friction_torque", "errors", "api", "__version__"} <= set(dir(bearingheat))
    assert callable(bearingheat.calc)  # the function, although a subpackage of that name is loaded
