"""Sizing of self-lubricating DU/DP bushings and thrust washers with units (seed 004).

The unit boundary of :mod:`bearingheat.kernels.bushing`: loads, speeds,
lengths, temperatures and the admissible K = pV and [p] are pint Quantities,
converted once to catalogue units; K and [p] come from the tables of
:mod:`bearingheat.catalogue.bushing` unless given. The result is a dict of
Quantities keyed 'name [unit]' (text and factors stay plain).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from bearingheat.catalogue.bushing import pressure_limit_seed004, pv_limit_seed004_table25
from bearingheat.errors import BushingInputError
from bearingheat.kernels.bushing import size_bushing_kernel, size_thrust_washer_kernel, temperature_factor_seed004
from bearingheat.units import magnitude, quantity

__all__ = ["size_bushing", "size_thrust_washer"]

_RESULT_UNITS = {"[N]": "N", "[1/min]": "1/min", "[mm]": "mm", "[N/mm^2]": "N/mm^2", "[N/mm^2*m/s]": "N/mm^2*m/s",
                 "[m/s]": "m/s", "[W]": "W", "[h]": "h", "[degC]": "degC"}


def _admissible(application, shaft, life, load_type, T, K, p_adm):
    if K is None:
        if None in (shaft, life):
            raise BushingInputError("give either K, or shaft and life to read K from seed 004 table 25")
        K_table = pv_limit_seed004_table25(application, shaft, float(magnitude(life, "h", "life")))
    else:
        K_table = float(magnitude(K, "N/mm^2*m/s", "K"))
    T_c = None if T is None else float(magnitude(T, "degC", "T"))
    factor = 1.0 if T_c is None else temperature_factor_seed004(T_c)
    p = pressure_limit_seed004(load_type) if p_adm is None else float(magnitude(p_adm, "N/mm^2", "p_adm"))
    return K_table, factor, T_c, p


def _wrap(result: dict[str, Any]) -> dict[str, Any]:
    wrapped = {}
    for key, value in result.items():
        unit = next((u for tag, u in _RESULT_UNITS.items() if key.endswith(tag)), None)
        wrapped[key] = quantity(value, unit) if unit and value is not None else value
    return wrapped


def size_bushing(F, n, d, *, application="bushing_constant_load", shaft=None, life=None, load_type,
                 T=None, K=None, p_adm=None, standard_lengths=None, f=None) -> dict[str, Any]:
    """Size a cylindrical DU bushing (seed 004) with pint Quantities.

    K comes from table 25 (application, shaft 'soft'/'hardened', life 1000 h
    or 10 000 h) unless given; it is derated for T. [p] comes from the load
    type unless given. Returns a dict of Quantities keyed 'name [unit]'.

    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> out = size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
    ...                    load_type="rotating_fixed_load_point", standard_lengths=[20, 30, 50, 100] * u.mm)
    >>> round(out["l_pV [mm]"].to("mm").magnitude, 1), out["l_standard [mm]"], out["governing"]
    (94.5, <Quantity(100.0, 'millimeter')>, 'pV')
    """
    K_table, factor, T_c, p = _admissible(application, shaft, life, load_type, T, K, p_adm)
    lengths = None if standard_lengths is None else np.atleast_1d(magnitude(standard_lengths, "mm", "standard_lengths"))
    result = size_bushing_kernel(float(magnitude(F, "N", "F")), float(magnitude(n, "1/min", "n")),
                                 float(magnitude(d, "mm", "d")), K_table * factor, p, lengths, f)
    result.update({"K_table [N/mm^2*m/s]": K_table, "temperature_factor": factor, "T [degC]": T_c})
    return _wrap(result)


def size_thrust_washer(F, n, d, *, shaft=None, life=None, load_type, T=None, K=None, p_adm=None,
                       standard_diameters=None, f=None) -> dict[str, Any]:
    """Size a DU thrust washer (seed 004) with pint Quantities; d is the inner diameter.

    K comes from table 25 (application thrust_washer) unless given, derated for
    T; [p] from the load type unless given. V and pV are taken at the mean
    diameter. Returns a dict of Quantities keyed 'name [unit]'.

    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> out = size_thrust_washer(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h, load_type="static")
    >>> round(out["D_required [mm]"].to("mm").magnitude, 2), out["governing"]
    (104.98, 'pV')
    """
    K_table, factor, T_c, p = _admissible("thrust_washer", shaft, life, load_type, T, K, p_adm)
    diameters = None if standard_diameters is None else np.atleast_1d(
        magnitude(standard_diameters, "mm", "standard_diameters"))
    result = size_thrust_washer_kernel(float(magnitude(F, "N", "F")), float(magnitude(n, "1/min", "n")),
                                       float(magnitude(d, "mm", "d")), K_table * factor, p, diameters, f)
    result.update({"K_table [N/mm^2*m/s]": K_table, "temperature_factor": factor, "T [degC]": T_c})
    return _wrap(result)
