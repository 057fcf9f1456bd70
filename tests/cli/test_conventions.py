"""Every command's --help follows one convention: the same option names, an exit-code paragraph, no seed numbers."""
from __future__ import annotations

import re

import pytest

from bearingheat.cli import COMMANDS, build_parser
from bearingheat.cli.options import (F2_CHART_HELP, FORCE_DIR_HELP, FORCE_FILE_HELP, JSON_HELP, QUIET_HELP,
                                     VM_CHART_HELP)

#: commands that print results (--json), and those that write files (-o/--output or --out-dir)
PRINTS = {"calc", "coastdown", "bushing", "contact", "lab", "audit", "diagnose", "lookup", "select"}
WRITES_FILE = {"calc", "template", "plot", "select"}
WRITES_FOLDER = {"coastdown", "lab", "audit", "diagnose"}
#: commands with -q/--quiet: every one that prints results or names the files it wrote
QUIET = PRINTS | WRITES_FILE | WRITES_FOLDER


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
    assert ("-q" in options) == (command in QUIET)
    assert ("--force" in options) == (command in WRITES_FILE | WRITES_FOLDER)


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_the_shared_options_have_one_help_text(command):
    """-q/--quiet, --json, -o/--output FILE, --out-dir DIR and --force read the same in every command."""
    _, options = _help(command)
    if "-q" in options:
        assert options["-q"].option_strings == ["-q", "--quiet"] and options["-q"].help == QUIET_HELP
    if "--json" in options:
        assert options["--json"].help == JSON_HELP
    if "--output" in options:
        output = options["--output"]
        assert output.option_strings == ["-o", "--output"] and output.metavar == "FILE"
        assert re.fullmatch(r"file to write \(\.[^()]+\)(; without it .+)?", output.help), output.help
    if "--out-dir" in options:
        assert options["--out-dir"].metavar == "DIR"
        assert re.fullmatch(r"folder to write .+ into", options["--out-dir"].help), options["--out-dir"].help
    if "--force" in options:
        expected = FORCE_DIR_HELP if "--out-dir" in options else FORCE_FILE_HELP
        assert options["--force"].help == expected


@pytest.mark.parametrize(("command", "option", "metavar", "help_text"), [
    ("bushing", "--json", None, "print the results as JSON instead of text"),
    ("bushing", "-q", None, "print nothing but errors"),
    ("lookup", "--json", None, "print the results as JSON instead of text"),
    ("lookup", "-q", None, "print nothing but errors"),
    ("plot", "-o", "FILE", "file to write (.png, .svg, .svgz, .pdf, .eps, .ps, .jpg, .jpeg, .tif, .tiff or .webp)"),
    ("plot", "--force", None, "replace FILE if it exists"),
    ("plot", "-q", None, "print nothing but errors"),
    ("coastdown", "--out-dir", "DIR", "folder to write report.md, coastdown.png and summary.json into"),
    ("coastdown", "--force", None, "replace the files in DIR that exist"),
    ("coastdown", "--json", None, "print the results as JSON instead of text"),
    ("coastdown", "-q", None, "print nothing but errors"),
])
def test_the_help_of_the_options_that_were_spelt_apart(command, option, metavar, help_text):
    """bushing, lookup, plot and coastdown once wrote these helps themselves ('print JSON instead of text',
    'PNG file to write', 'replace OUTPUT if it exists'); now they read as in every other command."""
    _, options = _help(command)
    assert (options[option].metavar, options[option].help) == (metavar, help_text)


def test_plot_output_is_required_and_named_alike():
    _, options = _help("plot")
    assert options["-o"].option_strings == ["-o", "--output"] and options["-o"].required


@pytest.mark.parametrize("command", ["calc", "plot", "select"])
def test_the_commands_that_compute_m2_take_one_f2_chart_option(command):
    _, options = _help(command)
    assert (options["--f2-chart"].metavar, options["--f2-chart"].help) == ("CSV", F2_CHART_HELP)
    assert F2_CHART_HELP == "digitised f2 chart (docs/friction.md gives the format)"


@pytest.mark.parametrize("command", ["calc", "select"])
def test_the_commands_of_the_skf_model_take_one_vm_chart_option(command):
    _, options = _help(command)
    assert (options["--vm-chart"].metavar, options["--vm-chart"].help) == ("CSV", VM_CHART_HELP)


def test_the_shared_help_texts():
    assert (QUIET_HELP, JSON_HELP) == ("print nothing but errors", "print the results as JSON instead of text")
    assert (FORCE_FILE_HELP, FORCE_DIR_HELP) == ("replace FILE if it exists", "replace the files in DIR that exist")


def test_version():
    parser = build_parser()
    with pytest.raises(SystemExit) as info:
        parser.parse_args(["--version"])
    assert info.value.code == 0
