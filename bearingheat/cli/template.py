"""``bearingheat template``: write the designer's Excel template."""
from __future__ import annotations

import argparse
from pathlib import Path

from bearingheat.cli import UsageError
from bearingheat.cli.options import add_force, add_output, add_quiet
from bearingheat.io.excel.template import build_template
from bearingheat.io.files import atomic_write, safe_output


DESCRIPTION = """\
Write a workbook a designer fills in without reading docs (-o FILE.xlsx), then
runs 'bearingheat calc FILE.xlsx -o RESULTS.xlsx' on.

Sheets: Supports (header row, editable units row: kN, lbf, 1/min, rpm, Hz ...;
drop-down lists for lubrication, arrangement and bearing type; two example
rows), Results (filled by calc), Instructions (every column and its unit).

An existing file is never overwritten unless --force is given.

Exit codes: 0 written; 2 the file exists (without --force) or is not .xlsx.
"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_output(parser, ".xlsx", required=True)
    add_force(parser, "FILE")
    add_quiet(parser)


def run(args: argparse.Namespace) -> int:
    target = Path(args.output)
    if target.suffix.lower() != ".xlsx":
        raise UsageError(f"{target}: the template is an .xlsx workbook; name it e.g. supports.xlsx")
    real = safe_output(target, force=args.force)
    workbook = build_template()
    atomic_write(real, workbook.save)
    if not args.quiet:
        print(f"template written to {target}; fill in the sheet 'Supports', then run: "
              f"bearingheat calc {target} -o results.xlsx")
    return 0
