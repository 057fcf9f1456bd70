"""``bearingheat template``: write the designer's Excel template."""
from __future__ import annotations

import argparse
from pathlib import Path

from bearingheat.cli import UsageError
from bearingheat.io.excel.template import build_template
from bearingheat.io.excel.writer import atomic_save

HELP = "write an Excel template (.xlsx) to fill in with shaft supports"

DESCRIPTION = """\
Write a workbook a designer fills in without reading docs, then runs
'bearingheat calc OUT.xlsx -o RESULTS.xlsx' on.

Sheets: Supports (header row, editable units row: kN, lbf, 1/min, rpm, Hz ...;
drop-down lists for lubrication, arrangement and bearing type; two example
rows), Results (filled by calc), Instructions (every column and its unit).

An existing file is never overwritten unless --force is given.

Exit codes: 0 written; 2 the file exists (without --force) or is not .xlsx.
"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("output", metavar="OUT.xlsx", help="where to write the template")
    parser.add_argument("--force", action="store_true", help="overwrite OUT.xlsx if it exists")
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing")


def run(args: argparse.Namespace) -> int:
    target = Path(args.output)
    if target.suffix.lower() != ".xlsx":
        raise UsageError(f"{target}: the template is an .xlsx workbook; name it e.g. supports.xlsx")
    if target.exists() and not args.force:
        raise UsageError(f"{target} exists; it is not overwritten (give --force to replace it)")
    if not target.parent.is_dir():
        raise UsageError(f"{target.parent}: no such folder")
    atomic_save(build_template(), target)
    if not args.quiet:
        print(f"template written to {target}; fill in the sheet 'Supports', then run: "
              f"bearingheat calc {target} -o results.xlsx")
    return 0
