"""Every command's --help follows one convention: the same option names, an exit-code paragraph, no seed numbers."""
from __future__ import annotations

import pytest

from bearingheat.cli import COMMANDS, build_parser

#: commands that print results (--json), and those that write files (-o/--output or --out-dir)
PRINTS = {"calc", "coastdown", "bushing", "contact", "lab", "audit", "diagnose", "lookup"}
WRITES_FILE = {"calc", "template", "plot"}
WRITES_FOLDER = {"coastdown", "lab", "audit", "diagnose"}


def _help(command: str) -> tuple[str, dict]:
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices[command]  # noqa: SLF001 (argparse)
    return sub.format_help(), {o: a for a in sub._actions for o in a.option_strings}  # noqa: SLF001


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_help_convention(command):
    text, options = _help(command)
    assert "Exit codes" in text
    assert "seed 00" not in text.lower()
    assert ("--json" in options) == (command in PRINTS)
    if command in WRITES_FILE:
        assert "-o" in options and "--output" in options and "--out-dir" not in options
    if command in WRITES_FOLDER:
        assert "--out-dir" in options and "--out" not in options
    for option, help_text in (("-q", "print nothing"), ("--json", "print the results as JSON")):
        if option in options and command not in ("calc", "contact", "bushing", "lookup", "plot", "coastdown"):
            assert options[option].help.startswith(help_text)


def test_version():
    parser = build_parser()
    with pytest.raises(SystemExit) as info:
        parser.parse_args(["--version"])
    assert info.value.code == 0
