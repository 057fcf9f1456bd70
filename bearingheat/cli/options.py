"""The options every ``bearingheat`` command spells the same way.

- ``-o/--output FILE``: the one file a command writes (its format from the suffix);
- ``--out-dir DIR``: the folder of a command that writes several files (report, tables, figures);
- ``--json``: print the results as JSON on stdout instead of the text table;
- ``-q/--quiet``: print nothing but errors;
- ``--force``: replace output files that exist (without it they are refused, exit 2).
"""
from __future__ import annotations

import argparse

__all__ = ["add_output", "add_out_dir", "add_json", "add_quiet", "add_force"]


def add_output(parser: argparse.ArgumentParser, formats: str, *, required: bool = False,
               without: str = "the results are printed") -> None:
    """``-o/--output FILE``; ``formats`` lists the suffixes it accepts (e.g. '.csv, .xlsx or .parquet')."""
    text = f"file to write ({formats})" + ("" if required else f"; without it {without}")
    parser.add_argument("-o", "--output", metavar="FILE", required=required, help=text)


def add_out_dir(parser: argparse.ArgumentParser, contents: str, *, required: bool = False) -> None:
    """``--out-dir DIR``; ``contents`` says what the folder receives."""
    parser.add_argument("--out-dir", metavar="DIR", required=required, help=f"folder to write {contents} into")


def add_json(parser: argparse.ArgumentParser) -> None:
    """``--json``: the results as JSON on stdout."""
    parser.add_argument("--json", action="store_true", help="print the results as JSON instead of a table")


def add_quiet(parser: argparse.ArgumentParser) -> None:
    """``-q/--quiet``."""
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")


def add_force(parser: argparse.ArgumentParser, what: str = "the output file") -> None:
    """``--force``: replace existing output files (without it an existing file is refused, exit 2)."""
    parser.add_argument("--force", action="store_true", help=f"replace {what} if it exists")
