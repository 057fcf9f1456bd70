"""``bearingheat`` command line: one subcommand per module, looked up in a registry.

Each subcommand module defines ``HELP`` (one line), ``DESCRIPTION`` (the
long help: columns, units, exit codes), ``add_arguments(parser)`` and
``run(args) -> int``. Modules import their heavy dependencies inside ``run``
so that ``bearingheat --help`` stays fast.

Exit codes shared by all subcommands: 0 success (rows ok or warning),
1 some rows had errors, 2 unusable input (missing file, missing column,
bad argument).
"""
from __future__ import annotations

import argparse
import importlib
import sys

from bearingheat.errors import BearingheatError, UsageError

__all__ = ["main", "COMMANDS", "UsageError"]

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


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args._module.run(args))
    except BearingheatError as exc:  # unusable input or argument (UsageError included): exit 2
        print(f"bearingheat {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
