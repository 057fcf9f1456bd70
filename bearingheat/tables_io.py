"""Transitional alias of :mod:`bearingheat.catalogue.tables` while the package moves to its layers (removed when the move is done)."""
import sys

import importlib

_target = importlib.import_module("bearingheat.catalogue.tables")

sys.modules[__name__] = _target
