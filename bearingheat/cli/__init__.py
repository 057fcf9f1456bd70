"""``bearingheat`` command line: one subcommand per module, looked up in a registry.

Each subcommand module defines ``DESCRIPTION`` (the long help: columns,
units, exit codes), ``add_arguments(parser)`` and ``run(args) -> int``; its
one-line help is in :data:`COMMANDS`. Only the module of the command that
runs is imported, so ``bearingheat --help`` and ``--version`` stay fast.

Exit codes shared by all subcommands: 0 success (rows ok or warning),
1 some rows had errors, 2 unusable input (missing file, missing column,
bad argument) or a fault (a file that cannot be read or written, a full
disk, a damaged workbook). Errors are chosen by their type, once, in
:func:`main`: a :class:`~bearingheat.errors.BearingheatError` or one of
:data:`FAULTS` prints one line naming the file and the cause and exits 2;
no traceback.
"""
from __future__ import annotations

import argparse
import importlib
from collections.abc import Collection
import importlib.metadata
import os
import sys
import xml.etree.ElementTree as ElementTree
import zipfile
import zlib

from lxml.etree import LxmlError

from bearingheat.errors import BearingheatError, UsageError

__all__ = ["main", "command_line", "COMMANDS", "UsageError", "FAULTS", "describe_fault"]

#: faults of the machine or of a file rather than of the input's content: exit 2 with one line, no traceback
FAULTS: tuple[type[BaseException], ...] = (OSError, zipfile.BadZipFile, zlib.error, ElementTree.ParseError,
                                           LxmlError, EOFError, UnicodeError)

#: the arguments that name a command's input file, in the order they are looked for
_INPUT_ARGUMENTS = ("input", "data", "table", "reference_speeds", "csv")

#: name -> (module implementing it, the one line of ``bearingheat --help``); a command's module is imported only
#: when that command runs or shows its help, so the command line starts without loading the others
COMMANDS: dict[str, tuple[str, str]] = {
    "calc": ("bearingheat.cli.calc",
        "friction torque, power loss (and thermal speeds) of supports in a CSV or Excel table"),
    "coastdown": ("bearingheat.cli.coastdown",
        "coast-down (run-down) analysis: reduced friction coefficient and torque components (the TMM-7M lab sheet)"),
    "bushing": ("bearingheat.cli.bushing",
        "size a DU/DP self-lubricating bushing or thrust washer by pV and [p] (the DU/DP bushing handbook)"),
    "contact": ("bearingheat.cli.contact",
        "contact angle from clearance, working angle under Fa, stiffness C*, minimum axial load (Zaitsev & Voronkin)"),
    "template": ("bearingheat.cli.template",
        "write an Excel template (.xlsx) to fill in with shaft supports"),
    "plot": ("bearingheat.cli.plot",
        "plot friction heat and heat carried away of one support against speed and temperature (PNG, SVG, PDF)"),
    "lab": ("bearingheat.cli.lab",
        "process DP11A lab rig readings (the DP11A manual): mu, f0 and T_F, f and T0, tables 4 and 5, plots"),
    "audit": ("bearingheat.cli.audit",
        "fit f0, f1 (f2) to measured torque with 95-percent intervals; audit n_thr against a catalogue list"),
    "diagnose": ("bearingheat.cli.diagnose",
        "trace the residuals of measured torque to a missing effect; model error before and after"),
    "lookup": ("bearingheat.cli.lookup",
        "a bearing's dimensions, load ratings, e, Y, Y0 and speeds by designation (Schaeffler HR 1, 2006)"),
    "select": ("bearingheat.cli.select",
        "the bearings of the table for a shaft seat, ranked at an operating point by power loss, T_op or n_per"),
}


def build_parser(commands: Collection[str] | None = None) -> argparse.ArgumentParser:
    """The parser with the arguments of ``commands`` (None: every command); the others are listed by name and
    help line only, their modules not imported."""
    parser = argparse.ArgumentParser(
        prog="bearingheat",
        description="Friction torque, power loss and thermal speed limits of shaft supports.",
        epilog="Run 'bearingheat COMMAND --help' for the columns and units of each command.",
    )
    parser.add_argument("--version", action="version", version=f"bearingheat {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, (module_path, help_line) in COMMANDS.items():
        if commands is not None and name not in commands:
            sub.add_parser(name, help=help_line)
            continue
        module = importlib.import_module(module_path)
        cmd = sub.add_parser(name, help=help_line, description=module.DESCRIPTION,
                             formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(cmd)
        cmd.set_defaults(_module=module)
    return parser


def _version() -> str:
    """The installed distribution's version (the package's own where it is not installed)."""
    try:
        return importlib.metadata.version("bearingheat")
    except importlib.metadata.PackageNotFoundError:
        return "unknown (not installed)"


def add_csv_arguments(parser: argparse.ArgumentParser) -> None:
    """``--sep`` and ``--decimal`` of a CSV input (found from the file when not given)."""
    parser.add_argument("--sep", metavar="SEP", choices=(",", ";", "tab", "\t"),
                        help="CSV column separator: ',', ';' or tab (default: found from the header)")
    parser.add_argument("--decimal", metavar="MARK", choices=(".", ","),
                        help="CSV decimal mark: '.' or ',' (default: found from the numbers)")


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def describe_fault(exc: BaseException, args: argparse.Namespace | None = None) -> str:
    """One line naming the file and the cause of a fault (one of :data:`FAULTS`)."""
    if isinstance(exc, OSError) and exc.filename is not None:
        where = f"{exc.filename} -> {exc.filename2}" if exc.filename2 is not None else f"{exc.filename}"
        cause = exc.strerror or str(exc)
        return _one_line(f"{where}: {cause}")
    source = next((getattr(args, name) for name in _INPUT_ARGUMENTS if getattr(args, name, None)), None)
    if isinstance(exc, OSError):
        cause = exc.strerror or str(exc)
    elif isinstance(exc, (zipfile.BadZipFile, zlib.error)):
        cause = f"damaged workbook, its zip package cannot be read ({exc})"
    elif isinstance(exc, (ElementTree.ParseError, LxmlError)):
        cause = f"damaged workbook, an XML part cannot be read ({exc})"
    elif isinstance(exc, EOFError):
        cause = "the file ends too early (truncated, or still being written)"
    elif isinstance(exc, UnicodeDecodeError):
        cause = f"not UTF-8 text (byte 0x{exc.object[exc.start]:02x} at position {exc.start}); save it as 'CSV UTF-8'"
    else:
        cause = str(exc) or type(exc).__name__
    return _one_line(f"{source}: {cause}" if source else cause)


def _command_of(arguments: list[str]) -> str | None:
    """The command named in ``arguments`` (the options before it are --help, --version)."""
    return next((a for a in arguments if not a.startswith("-")), None)


def command_line() -> int:
    """The ``bearingheat`` program (and ``python -m bearingheat``): :func:`main` in a process of its own, where pint
    may keep its parsed unit definitions in the user's cache folder (a faster start; see
    :func:`bearingheat.units.use_definition_cache`). :func:`main` alone leaves the caller's registry as it is."""
    arguments = sys.argv[1:]
    if _command_of(arguments) in COMMANDS:  # (--help and --version load no units)
        from bearingheat.units import use_definition_cache
        use_definition_cache()
    return main(arguments)


def main(argv: list[str] | None = None) -> int:
    arguments = sys.argv[1:] if argv is None else list(argv)
    command = _command_of(arguments)
    parser = build_parser([command] if command in COMMANDS else [])  # --help and --version load no command
    args = parser.parse_args(arguments)
    try:
        return int(args._module.run(args))
    except BrokenPipeError:  # the reader of a pipe stopped early ('| head'): nothing more to say, and nowhere to
        devnull = os.open(os.devnull, os.O_WRONLY)  # (Python would complain again when it flushes stdout at exit)
        os.dup2(devnull, sys.stdout.fileno())
        return 0
    except BearingheatError as exc:  # unusable input or argument (UsageError included): exit 2
        print(f"bearingheat {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except FAULTS as exc:  # a file that cannot be read or written, a full disk, a damaged workbook: exit 2
        print(f"bearingheat {args.command}: error: {describe_fault(exc, args)}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
