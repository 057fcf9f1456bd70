"""bearingheat: friction torque, power loss and thermal speed limits of shaft supports.

The public face: the unit-aware functions of :mod:`bearingheat.api`, :func:`calc`
over a table of supports, and the errors of :mod:`bearingheat.errors`.

- :func:`friction_torque`, :func:`heat_balance`, ... — one bearing, unit-aware (pint), scalar or vectorised.
- :func:`calc` — a DataFrame of supports with ``name [unit]`` headers, as ``bearingheat calc``;
  :func:`duty_cycle` — its time-weighted summary per support.
- The layers below (``catalogue``, ``kernels``, ``calc``, ``analysis``, ``io``) are documented in
  ``docs/architecture.md``.
"""
from bearingheat import errors
from bearingheat.api import *  # noqa: F401,F403  (the public API is api.__all__)
from bearingheat.api import __all__ as _api_all
from bearingheat.calc.duty import duty_cycle
from bearingheat.calc.table import calc
from bearingheat.errors import *  # noqa: F401,F403  (every error and warning class)
from bearingheat.errors import __all__ as _errors_all

__version__ = "0.1.0"

__all__ = [*_api_all, "calc", "duty_cycle", "errors", *_errors_all]
