"""Transitional alias of :mod:`bearingheat.calc.table` while the package moves to its layers (removed when the move is done)."""
import sys

import importlib

_target = importlib.import_module("bearingheat.calc.table")

sys.modules[__name__] = _target
