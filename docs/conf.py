"""Sphinx configuration: the docs are MyST Markdown pages; build with `make docs`."""
project = "bearingheat"
author = "bearingheat developers"
extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3
exclude_patterns = ["_build"]
html_static_path = ["_static"]
html_theme = "alabaster"
suppress_warnings = ["myst.xref_missing"]
