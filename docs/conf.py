"""Sphinx configuration: the docs are MyST Markdown pages; build with `make docs`.

The column tables of ``columns.md`` are generated here from the column
contract (``bearingheat.calc.contract``), so the docs cannot drift from the
columns calc reads and writes. The side-by-side table of the friction
models in ``skf.md`` is computed here from ``examples/gearbox_shaft_skf.csv``.
"""
from pathlib import Path

import pandas as pd

from bearingheat.analysis.comparison import side_by_side
from bearingheat.calc import contract
from bearingheat.io.reports.figures import write_doc_figures

project = "bearingheat"
author = "bearingheat developers"
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".md": "markdown"}
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3
exclude_patterns = ["_build", "_generated"]
html_static_path = ["_static"]
html_theme = "alabaster"
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
napoleon_google_docstring = False

_generated = Path(__file__).parent / "_generated"
_generated.mkdir(exist_ok=True)
for _kind in ("input", "output"):
    _text = contract.markdown_table(_kind) + "\n"
    _path = _generated / f"contract_{_kind}.md"
    if not _path.exists() or _path.read_text(encoding="utf-8") != _text:
        _path.write_text(_text, encoding="utf-8")


def _write_if_changed(path: Path, text: str) -> None:
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


_demo = pd.read_csv(Path(__file__).parent.parent / "examples" / "gearbox_shaft_skf.csv")
_write_if_changed(_generated / "skf_side_by_side.md",
                  side_by_side(_demo).to_markdown(index=False, floatfmt=".4g") + "\n")

# the pictures of friction.md, bushing.md and coastdown.md, drawn from the package's own calculations
write_doc_figures(_generated, Path(__file__).parent.parent / "examples")
