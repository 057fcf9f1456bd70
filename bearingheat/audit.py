"""Transitional alias of :mod:`bearingheat.analysis.audit` while the package moves to its layers (removed when the move is done)."""
import importlib
import sys

_target = importlib.import_module("bearingheat.analysis.audit")

sys.modules[__name__] = _target
