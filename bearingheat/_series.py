"""Transitional alias of :mod:`bearingheat.kernels._series` while the package moves to its layers (removed when the move is done)."""
import sys

import importlib

_target = importlib.import_module("bearingheat.kernels._series")

sys.modules[__name__] = _target
