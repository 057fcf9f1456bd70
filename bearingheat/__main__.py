import sys

from bearingheat.cli import command_line

sys.exit(command_line())
