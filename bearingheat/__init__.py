"""bearingheat: friction torque, power loss and thermal speed limits of shaft supports.

Python entry points:

- :func:`friction_torque` — one bearing, unit-aware (pint), scalar or vectorised.
- :func:`calc` — a DataFrame of supports with ``name [unit]`` headers, as ``bearingheat calc``.
- :mod:`bearingheat.kernels.friction` — the kernels in catalogue units (mm, N, 1/min, mm²/s, N·mm, W).
"""
from bearingheat.api.friction import FrictionResult, friction_torque
from bearingheat.calc.table import calc
from bearingheat.catalogue.designation import decode_gost, parse_designation
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import (BearingheatError, BearingheatWarning, DesignationError, F2ChartError,
                                FrictionInputError, InputError, UnitError)

__version__ = "0.1.0"

__all__ = [
    "friction_torque", "FrictionResult", "FrictionInputError",
    "calc", "InputError",
    "parse_designation", "decode_gost", "DesignationError",
    "F2Chart", "F2ChartError", "UnitError", "BearingheatError", "BearingheatWarning",
]
