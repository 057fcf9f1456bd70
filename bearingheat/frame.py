"""Transitional alias of the old DataFrame API while the package moves to its layers (removed when the move is done)."""
from bearingheat.calc.contract import input_units, output_header, parse_header
from bearingheat.calc.table import EXTENSIONS, calc, require_columns, to_catalogue_units
from bearingheat.errors import InputError
from bearingheat.calc.table import require_columns as _require  # noqa: F401
