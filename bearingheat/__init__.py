"""bearingheat: friction torque, power loss and thermal speed limits of shaft supports.

The public face: the unit-aware functions of :mod:`bearingheat.api`, :func:`calc`
over a table of supports, and the errors of :mod:`bearingheat.errors`.

- :func:`friction_torque`, :func:`heat_balance`, ... — one bearing, unit-aware (pint), scalar or vectorised.
- :func:`calc` — a DataFrame of supports with ``name [unit]`` headers, as ``bearingheat calc``;
  :func:`duty_cycle` — its time-weighted summary per support.
- The layers below (``catalogue``, ``kernels``, ``calc``, ``analysis``, ``io``) are documented in
  ``docs/architecture.md``.
"""
from __future__ import annotations

import copyreg
import importlib
import sys
import types
from typing import TYPE_CHECKING, Any

from bearingheat import errors
from bearingheat.api import _EXPORTS as _API_EXPORTS
from bearingheat.api import lazy_exports
from bearingheat.errors import *  # noqa: F401,F403  (every error and warning class)
from bearingheat.errors import __all__ as _errors_all

__version__ = "0.1.0"

#: public name -> the module that defines it, imported on first use (PEP 562): the command line and a script
#: that needs one function do not load the rest (scipy.stats, the Excel bridge)
_EXPORTS = {**_API_EXPORTS, "calc": "bearingheat.calc.table", "duty_cycle": "bearingheat.calc.duty"}

__all__ = [*_EXPORTS, "errors", *_errors_all]

if TYPE_CHECKING:  # what type checkers and IDEs see; at run time each name is imported on first use
    from bearingheat.api import *  # noqa: F401,F403
    from bearingheat.calc.duty import duty_cycle
    from bearingheat.calc.table import calc


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)


class _Package(types.ModuleType):
    """The package's module object. ``bearingheat.calc`` is the function :func:`calc`, not the subpackage of the
    same name: importing ``bearingheat.calc.*`` sets the package's ``calc`` attribute to the subpackage, which
    the setter ignores (the subpackage stays in ``sys.modules``, where imports look it up)."""

    @property
    def calc(self) -> Any:
        return importlib.import_module("bearingheat.calc.table").calc

    @calc.setter
    def calc(self, value: Any) -> None:
        if not isinstance(value, types.ModuleType):
            raise AttributeError("bearingheat.calc is the function calc; it cannot be replaced")


sys.modules[__name__].__class__ = _Package
# pickled by name, as plain modules are (cloudpickle and dask ship functions that refer to ``bearingheat``)
def _reduce_package(package: _Package) -> tuple[Any, tuple[str]]:
    return importlib.import_module, (package.__name__,)


copyreg.pickle(_Package, _reduce_package)
