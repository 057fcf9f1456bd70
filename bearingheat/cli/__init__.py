"""``bearingheat`` command line: one subcommand per module, looked up in a registry.

Each subcommand module defines ``HELP`` (one line), ``DESCRIPTION`` (the
long help: columns, units, exit codes), ``add_arguments(parser)`` and
``run(args) -> int``. Modules import their heavy dependencies inside ``run``
so that ``bearingheat --help`` stays fast.

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
import importlib.metadata
import sys
import xml.etree.ElementTree as ElementTree
import zipfile
import zlib

from lxml.etree import LxmlError

from bearingheat.errors import BearingheatError, UsageError

__all__ = ["main", "COMMANDS", "UsageError", "FAULTS", "describe_fault"]

#: faults of the machine or of a file rather than of the input's content: exit 2 with one line, no traceback
FAULTS: tuple[type[BaseException], ...] = (OSError, zipfile.BadZipFile, zlib.error, ElementTree.ParseError,
                                           LxmlError, EOFError, UnicodeError)

#: the arguments that name a command's input file, in the order they are looked for
_INPUT_ARGUMENTS = ("input", "data", "table", "reference_speeds", "csv")

# name -> module implementing it
COMMANDS: dict[str, str] = {
    "calc": "bearingheat.cli.calc",
    "coastdown": "bearingheat.cli.coastdown",
    "bushing": "bearingheat.cli.bushing",
    "contact": "bearingheat.cli.contact",
    "template": "bearingheat.cli.template",
    "plot": "bearingheat.cli.plot",
    "lab": "bearingheat.cli.lab",
    "audit": "bearingheat.cli.audit",
    "diagnose": "bearingheat.cli.diagnose",
    "lookup": "bearingheat.cli.lookup",
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="bearingheat",
        description="Friction torque, power loss and thermal speed limits of shaft supports.",
        epilog="Run 'bearingheat COMMAND --help' for the columns and units of each command.",
    )
    parser.add_argument("--version", action="version", version=f"bearingheat {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, module_path in COMMANDS.items():
        module = importlib.import_module(module_path)
        cmd = sub.add_parser(
            name, help=module.HELP, description=module.DESCRIPTION,
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )
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


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args._module.run(args))
    except BearingheatError as exc:  # unusable input or argument (UsageError included): exit 2
        print(f"bearingheat {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except FAULTS as exc:  # a file that cannot be read or written, a full disk, a damaged workbook: exit 2
        print(f"bearingheat {args.command}: error: {describe_fault(exc, args)}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
