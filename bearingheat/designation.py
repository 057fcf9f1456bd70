"""Transitional alias of :mod:`bearingheat.catalogue.designation` while the package moves to its layers (removed when the move is done)."""
import sys

import importlib

_target = importlib.import_module("bearingheat.catalogue.designation")

sys.modules[__name__] = _target
