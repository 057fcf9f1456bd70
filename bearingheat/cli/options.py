"""The options every ``bearingheat`` command spells the same way, with the same help text.

- ``-o/--output FILE``: the one file a command writes (its format from the suffix);
- ``--out-dir DIR``: the folder of a command that writes several files (report, tables, figures);
- ``--json``: print the results as JSON on stdout instead of text;
- ``-q/--quiet``: print nothing but errors;
- ``--force``: replace output files that exist (without it they are refused, exit 2);
- ``--f2-chart CSV``: the digitised f2 chart of the commands that compute M2 (calc, plot, select);
- ``--vm-chart CSV``: the digitised VM chart of the SKF model in an oil bath (calc, select);
- a number with its unit (``--F 2kN``, ``--n 3000rpm``): :func:`option_quantity` reads it.

A command adds these options with the functions below and never writes their help itself;
``tests/cli/test_conventions.py`` checks every command against the texts here.
"""
from __future__ import annotations

import argparse
from collections.abc import Mapping

from bearingheat.errors import UnitError, UsageError
from bearingheat.units import Quantity, parse_quantity

__all__ = ["option_quantity", "add_output", "add_out_dir", "add_json", "add_quiet", "add_force", "add_f2_chart",
           "add_vm_chart", "output_help", "out_dir_help", "JSON_HELP", "QUIET_HELP", "FORCE_FILE_HELP", "FORCE_DIR_HELP",
           "F2_CHART_HELP", "VM_CHART_HELP"]

JSON_HELP = "print the results as JSON instead of text"
QUIET_HELP = "print nothing but errors"
#: --force of a command with -o/--output FILE, and of one with --out-dir DIR
FORCE_FILE_HELP = "replace FILE if it exists"
FORCE_DIR_HELP = "replace the files in DIR that exist"
F2_CHART_HELP = "digitised f2 chart (docs/friction.md gives the format)"
VM_CHART_HELP = ("digitised chart of the SKF drag loss factor VM against H/dm: oil-bath rows of the SKF model with a "
                 "blank VM read it off (docs/skf.md gives the format)")


def output_help(formats: str, *, required: bool = False, without: str = "the results are printed") -> str:
    """The help of ``-o/--output FILE``."""
    return f"file to write ({formats})" + ("" if required else f"; without it {without}")


def out_dir_help(contents: str) -> str:
    """The help of ``--out-dir DIR``."""
    return f"folder to write {contents} into"


def add_output(parser: argparse.ArgumentParser, formats: str, *, required: bool = False,
               without: str = "the results are printed") -> None:
    """``-o/--output FILE``; ``formats`` lists the suffixes it accepts (e.g. '.csv, .xlsx or .parquet')."""
    parser.add_argument("-o", "--output", metavar="FILE", required=required,
                        help=output_help(formats, required=required, without=without))


def add_out_dir(parser: argparse.ArgumentParser, contents: str, *, required: bool = False) -> None:
    """``--out-dir DIR``; ``contents`` says what the folder receives."""
    parser.add_argument("--out-dir", metavar="DIR", required=required, help=out_dir_help(contents))


def add_json(parser: argparse.ArgumentParser) -> None:
    """``--json``: the results as JSON on stdout."""
    parser.add_argument("--json", action="store_true", help=JSON_HELP)


def add_quiet(parser: argparse.ArgumentParser) -> None:
    """``-q/--quiet``."""
    parser.add_argument("-q", "--quiet", action="store_true", help=QUIET_HELP)


def add_force(parser: argparse.ArgumentParser, what: str | None = None) -> None:
    """``--force``: replace existing output files (without it an existing file is refused, exit 2).

    The help follows the output option added before it: :data:`FORCE_DIR_HELP` with ``--out-dir``,
    :data:`FORCE_FILE_HELP` with ``-o/--output``, so that every command says it alike; ``what`` names the
    target only of a command that has neither.
    """
    options = {option for action in parser._actions for option in action.option_strings}  # noqa: SLF001
    if "--out-dir" in options:
        text = FORCE_DIR_HELP
    elif "--output" in options:
        text = FORCE_FILE_HELP
    else:
        text = f"replace {what or 'the output file'} if it exists"
    parser.add_argument("--force", action="store_true", help=text)


def add_vm_chart(parser: argparse.ArgumentParser) -> None:
    """``--vm-chart CSV``: the SKF model's drag loss factor VM read off the user's digitised chart."""
    parser.add_argument("--vm-chart", metavar="CSV", help=VM_CHART_HELP)


def add_f2_chart(parser: argparse.ArgumentParser) -> None:
    """``--f2-chart CSV``: f2 of axially loaded cylindrical roller bearings read off the user's digitised chart."""
    parser.add_argument("--f2-chart", metavar="CSV", help=F2_CHART_HELP)


def option_quantity(text: str, option: str, examples: Mapping[str, str]) -> Quantity:
    """The number with its unit an option was given (``'2kN'`` for ``--F``); :class:`UsageError` naming the option
    where it has no unit or pint cannot read it, suggesting ``examples[option]`` (a unit of the option's kind)."""
    try:
        return parse_quantity(text, name=option, example=examples.get(option))
    except UnitError as exc:
        raise UsageError(str(exc)) from exc
