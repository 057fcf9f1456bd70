"""bearingheat: friction torque, power loss and thermal speed limits of shaft supports.

Python entry points:

- :func:`friction_torque` — one bearing, unit-aware (pint), scalar or vectorised.
- :func:`calc` — a DataFrame of supports with ``name [unit]`` headers, as ``bearingheat calc``.
- :mod:`bearingheat.friction` — the kernels in catalogue units (mm, N, 1/min, mm²/s, N·mm, W).
"""
from bearingheat.api import FrictionInputError, FrictionResult, friction_torque
from bearingheat.designation import DesignationError, decode_gost, parse_designation
from bearingheat.f2chart import F2Chart, F2ChartError
from bearingheat.frame import InputError, calc
from bearingheat.units import UnitError

__version__ = "0.1.0"

__all__ = [
    "friction_torque", "FrictionResult", "FrictionInputError",
    "calc", "InputError",
    "parse_designation", "decode_gost", "DesignationError",
    "F2Chart", "F2ChartError", "UnitError",
]
