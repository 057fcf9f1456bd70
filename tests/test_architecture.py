"""The layered layout of ../shared/ARCHITECTURE.md holds: contracts, no cycles, no private reach, no lazy imports."""
from __future__ import annotations

import ast
import shutil
import subprocess
import sys
from pathlib import Path

import grimp
import pytest

from bearingheat.calc import contract, models

PACKAGE = Path(__file__).resolve().parents[1] / "bearingheat"
LAYERS = ("catalogue", "kernels", "calc", "analysis", "api", "io", "cli")
#: the only imports allowed inside a function: heavy optional dependencies, loaded when a feature needs them
LAZY_ALLOWED = ("matplotlib", "pint_pandas", "dask", "distributed")
#: modules of the package a function may import where it needs them, so that ``calc`` of a CSV or Parquet file
#: starts without their heavy dependencies (tests/cli/test_startup.py): module -> what it would load
DEFERRED = {
    "bearingheat.io.excel": "openpyxl (the Excel bridge: workbooks only)",
    "bearingheat.analysis.effects": "scipy.optimize (calc --effects only)",
    "bearingheat.kernels.contact": "scipy.optimize (tables with ball geometry only)",
    "bearingheat.units": "pint, pandas and numpy (the program's own entry point: --help and --version load none)",
}
MAX_LINES = 700


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        name = ".".join(("bearingheat",) + path.relative_to(PACKAGE).with_suffix("").parts)
        yield name.removesuffix(".__init__"), path


def _folder(module: str) -> str:
    """The package folder a module lives in (``bearingheat.calc`` for ``bearingheat.calc.table``)."""
    parts = module.split(".")
    return ".".join(parts[:2]) if len(parts) > 2 else "bearingheat"


def test_every_layer_exists_as_a_package():
    for layer in LAYERS:
        assert (PACKAGE / layer / "__init__.py").is_file(), layer
    assert (PACKAGE / "units.py").is_file() and (PACKAGE / "errors.py").is_file()


def test_the_top_level_holds_only_the_leaves_and_the_public_face():
    flat = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert flat == ["__init__.py", "__main__.py", "errors.py", "units.py"]


def test_no_module_imports_a_private_name_from_another_folder():
    offences = []
    for module, path in _modules():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imported_modules = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("bearingheat"):
                target_parts = node.module.split(".")
                for alias in node.names:
                    full = f"{node.module}.{alias.name}"
                    private_module = any(p.startswith("_") and not p.startswith("__") for p in target_parts)
                    private_name = alias.name.startswith("_") and not alias.name.startswith("__")
                    if (private_module or private_name) and _folder(node.module if not private_module
                                                                    else node.module) != _folder(module):
                        offences.append(f"{module}: from {node.module} import {alias.name}")
                    imported_modules[alias.asname or alias.name] = full
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.startswith("bearingheat"):
                        imported_modules[alias.asname or alias.name.split(".")[0]] = alias.name
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                    and node.value.id in imported_modules and node.attr.startswith("_")
                    and not node.attr.startswith("__")
                    and _folder(imported_modules[node.value.id]) != _folder(module)):
                offences.append(f"{module}: {node.value.id}.{node.attr}")
    assert offences == []


def test_no_function_level_imports_except_heavy_optional_dependencies():
    offences = []
    for module, path in _modules():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for func in ast.walk(tree):
            if not isinstance(func, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            for node in ast.walk(func):
                if isinstance(node, ast.Import):
                    names = [a.name for a in node.names]
                elif isinstance(node, ast.ImportFrom):
                    names = [node.module or ""]
                else:
                    continue
                for name in names:
                    deferred = any(name == m or name.startswith(m + ".") for m in DEFERRED)
                    if not name.split(".")[0] in LAZY_ALLOWED and not deferred:
                        offences.append(f"{module}.{func.name}: import {name}")
    assert offences == []


def test_no_module_is_over_700_lines():
    long = {module: n for module, path in _modules()
            if (n := len(path.read_text(encoding="utf-8").splitlines())) > MAX_LINES}
    assert long == {}


def test_no_import_cycles():
    graph = grimp.build_graph("bearingheat")
    modules = sorted(graph.modules)
    cycles = []
    for module in modules:
        if module == "bearingheat":
            continue  # the public face re-exports the layers; nothing in the package imports it
        for imported in graph.find_modules_directly_imported_by(module):
            if imported == "bearingheat" or imported == module:
                continue
            chain = graph.find_shortest_chain(importer=imported, imported=module)
            if chain:
                cycles.append(" -> ".join((module,) + tuple(chain)))
    assert cycles == []


def test_nothing_in_the_package_imports_the_public_face():
    graph = grimp.build_graph("bearingheat")
    importers = sorted(m for m in graph.find_modules_that_directly_import("bearingheat")
                       if m not in ("bearingheat.__main__",))
    assert importers == []


@pytest.mark.skipif(shutil.which("lint-imports", path=str(Path(sys.executable).parent)) is None,
                    reason="import-linter is in the dev extra")
def test_import_linter_contracts_are_kept():
    exe = shutil.which("lint-imports", path=str(Path(sys.executable).parent))
    proc = subprocess.run([exe, "--no-cache"], capture_output=True, text=True,
                          cwd=PACKAGE.parent, check=False)
    assert proc.returncode == 0, proc.stdout[-3000:]


def test_models_read_and_write_contract_columns():
    for model in models.MODELS.values():
        assert set(model.inputs) <= set(contract.columns(kind="input")), model.name
        assert set(model.outputs) <= set(contract.columns(kind="output")), model.name


def test_contract_names_each_column_once_per_kind():
    for kind in ("input", "output"):
        names = [c.name for c in contract.CONTRACT if c.kind == kind]
        assert len(names) == len(set(names)), kind
    assert all(c.owner in contract.OWNERS for c in contract.CONTRACT)
