"""The unit boundary for Python callers: pint Quantities in, results of Quantities out.

Argument and result names are those of the column contract
(:mod:`bearingheat.calc.contract`): ``designation``, ``T_amb``, ``VI``,
``MR``, ``NR``. The results of friction_torque, heat_balance,
ball_bearing_contact, size_bushing and size_thrust_washer are frozen
dataclasses (:class:`~bearingheat.api.results.Result`) with one value per
operating point, ``status`` and ``messages`` per point, ``to_frame()`` (the
headers of ``calc``), a short ``repr`` and an HTML view in notebooks.
oil_viscosity and thermal_reference_speed return Quantities (one value per
point, nothing to flag); the coast-down analyses return their fits
(:class:`~bearingheat.analysis.coastdown.CoastdownResult`), which are not
per point.

Error policy (the same for every function here): input that cannot be used
at all (an unknown designation or model, a plain number where a Quantity is
needed, a unit of the wrong dimension, a number outside its valid range)
raises a :class:`~bearingheat.errors.BearingheatError` subclass naming the
argument (and the index of an array). A point that can be computed but
deserves a look (a number outside its plausible range, a value that differs
from the bearing table, a contact seal) gets status 'warning' and its
message; the heat balance gives a point it cannot solve (no equilibrium, a
method that does not apply) status 'error' and NaN, and the other points
their values.
"""
from __future__ import annotations

import importlib
import sys
from collections.abc import Callable
from types import ModuleType
from typing import TYPE_CHECKING, Any

#: public name -> the module that defines it; imported on first use (PEP 562), so ``import bearingheat`` and the
#: command line load only what they use (scipy.stats alone takes 0.6 s)
_EXPORTS = {
    "friction_torque": "bearingheat.api.friction", "FrictionResult": "bearingheat.api.friction",
    "heat_balance": "bearingheat.api.thermal", "HeatBalanceResult": "bearingheat.api.thermal",
    "thermal_reference_speed": "bearingheat.api.thermal", "oil_viscosity": "bearingheat.api.viscosity",
    "ball_bearing_contact": "bearingheat.api.contact", "BallContact": "bearingheat.api.contact",
    "contact_angle_from_clearance": "bearingheat.api.contact",
    "size_bushing": "bearingheat.api.bushing", "BushingSize": "bearingheat.api.bushing",
    "size_thrust_washer": "bearingheat.api.bushing", "ThrustWasherSize": "bearingheat.api.bushing",
    "analyse_coastdown": "bearingheat.api.coastdown", "analyse_spindle_coastdown": "bearingheat.api.coastdown",
    "bearing": "bearingheat.api.bearings", "BearingData": "bearingheat.api.bearings",
    "bearing_table": "bearingheat.api.bearings", "designations": "bearingheat.api.bearings",
    "bearings_with_bore": "bearingheat.api.bearings",
    "rank_bearings": "bearingheat.api.selection", "temperature_curves": "bearingheat.api.selection",
    "parse_designation": "bearingheat.catalogue.designation", "decode_gost": "bearingheat.catalogue.designation",
    "F2Chart": "bearingheat.catalogue.f2chart", "VMChart": "bearingheat.catalogue.vm_chart",
}

__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # what type checkers and IDEs see; at run time each name is imported on first use
    from bearingheat.api.bearings import BearingData, bearing, bearing_table, bearings_with_bore, designations
    from bearingheat.api.bushing import BushingSize, ThrustWasherSize, size_bushing, size_thrust_washer
    from bearingheat.api.coastdown import analyse_coastdown, analyse_spindle_coastdown
    from bearingheat.api.selection import rank_bearings, temperature_curves
    from bearingheat.api.contact import BallContact, ball_bearing_contact, contact_angle_from_clearance
    from bearingheat.api.friction import FrictionResult, friction_torque
    from bearingheat.api.thermal import HeatBalanceResult, heat_balance, thermal_reference_speed
    from bearingheat.api.viscosity import oil_viscosity
    from bearingheat.catalogue.designation import decode_gost, parse_designation
    from bearingheat.catalogue.f2chart import F2Chart
    from bearingheat.catalogue.vm_chart import VMChart


def lazy_exports(package: str, exports: dict[str, str]) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """The module ``__getattr__`` and ``__dir__`` (PEP 562) of ``package`` whose public names are ``exports``
    (name -> defining module): a name is imported on first use and kept in the package's namespace. ``dir``
    (and so an editor's completion) lists the public names, ``__all__``, the package's own modules that are
    loaded and the dunder names, not the helpers the package imports for itself (``sys``, ``Any`` ...)."""
    namespace = sys.modules[package].__dict__

    def __getattr__(name: str) -> Any:
        module = exports.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(module), name)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        own_modules = {name for name, value in namespace.items()
                       if isinstance(value, ModuleType) and value.__name__.startswith(package + ".")}
        dunder = {name for name in namespace if name.startswith("__") and name.endswith("__")}
        return sorted({*exports, *namespace.get("__all__", ()), *own_modules, *dunder})

    return __getattr__, __dir__


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)
