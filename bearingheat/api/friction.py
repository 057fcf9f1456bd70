"""Unit-aware friction API: pint Quantities in, Quantities out.

>>> import pint
>>> u = pint.get_application_registry()
>>> r = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
...                     n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"))
>>> print(f"MR = {r.MR.to('N*mm').magnitude:.3f} N*mm, NR = {r.NR.to('W').magnitude:.3f} W, {r.status}")
MR = 47.535 N*mm, NR = 14.932 W, ok

Scalars, numpy arrays and pint-pandas Series all work; arrays broadcast
against each other (one bearing, many operating points) and a Series in
gives a Series out. Shaft speed is revolutions per time: ``50 * u.Hz`` is
3000 1/min and ``u('rad/s')`` is divided by 2π.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pandas as pd

from bearingheat.api._checks import check_ranges, where
from bearingheat.calc.messages import Labels
from bearingheat.calc.models import DEFAULT_MODEL, get_model
from bearingheat.calc.supports import build_support_arrays
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import FrictionInputError
from bearingheat.units import magnitude, quantity, speed_rpm

__all__ = ["FrictionResult", "friction_torque"]




@dataclass
class FrictionResult:
    """Results of the catalogue friction model (seed 002) as Quantities.

    f0, f1 are dimensionless floats or arrays; P0, P1 [N]; M0, M1, M2, MR
    [N·mm]; NR [W]. Fa_over_A and nu_n_dM are set where M2 applies, so the
    f2 chart can be read. ``status`` is 'ok' or 'warning'; ``messages``
    lists the warnings.
    """

    f0: Any
    f1: Any
    P0: Any
    P1: Any
    M0: Any
    M1: Any
    M2: Any
    MR: Any
    NR: Any
    Fa_over_A: Any
    nu_n_dM: Any
    status: str = "ok"
    messages: list[str] = field(default_factory=list)
    bearing_type: str = ""
    series: str = ""


_LENGTHS = ("d", "D", "B")
_FACTORS = ("Y", "e", "X0", "Y0", "f0", "f1", "f2")


def _dimensionless(value, name: str):
    if value is None:
        return math.nan
    if hasattr(value, "units") or (isinstance(value, pd.Series) and str(value.dtype).startswith("pint[")):
        return magnitude(value, "dimensionless", name)
    if isinstance(value, pd.Series):
        return value
    return np.asarray(value, dtype=float) if np.ndim(value) else float(value)


def _optional(value, unit: str, name: str):
    return math.nan if value is None else magnitude(value, unit, name)


def friction_torque(bearing: str | None = None, *, n, nu, lubrication: str | None = None, Fr=None, Fa=None,
                    d=None, D=None, B=None, C0=None, bearing_type: str | None = None, series: str | None = None,
                    arrangement: str = "single", Y=None, e=None, X0=None, Y0=None, alpha=None,
                    f0=None, f1=None, f2=None, f2_chart: F2Chart | None = None,
                    model: str = DEFAULT_MODEL) -> FrictionResult:
    """Friction torque and power loss of one bearing at one or many operating points.

    Parameters
    ----------
    bearing : designation such as ``"6205-2Z"`` or ``"NU206-E"`` (or give
        ``bearing_type`` and ``series`` for an explicit table row).
    n : shaft speed, revolutions per time [1/min, rpm, Hz] or angular [rad/s].
    nu : operating viscosity [mm²/s] (base oil viscosity of a grease).
    lubrication : 'grease', 'oil_mist', 'oil_bath' or 'circulating_oil'
        (not needed when f0 is given).
    Fr, Fa : radial and axial load [force]; default 0.
    d, D, B : bore, outside diameter, width [length]; d defaults to the
        bore in the designation, B to the width of drawn cups (HK2016).
    C0 : static load rating [force], for f1 in P0/C0 or Fa/C0.
    Y, e, X0, Y0 : catalogue factors; alpha : working contact angle [angle].
    f0, f1, f2 : coefficient overrides; f2_chart : a digitised
        :class:`~bearingheat.catalogue.f2chart.F2Chart`.
    model : the friction model, a name of :data:`bearingheat.calc.models.MODELS`.

    Raises
    ------
    FrictionInputError
        naming the argument and the value (and the index for arrays).
    bearingheat.errors.ModelError
        for an unknown model name.
    bearingheat.errors.UnitError
        for a plain number where a Quantity is needed, or a wrong dimension.
    """
    friction_model = get_model(model)
    inputs = {
        "n": speed_rpm(n, "n"),
        "nu": magnitude(nu, "mm^2/s", "nu"),
        "Fr": 0.0 if Fr is None else magnitude(Fr, "N", "Fr"),
        "Fa": 0.0 if Fa is None else magnitude(Fa, "N", "Fa"),
        "C0": _optional(C0, "N", "C0"),
        "alpha": _optional(alpha, "deg", "alpha"),
    }
    for name, value in zip(_LENGTHS, (d, D, B)):
        inputs[name] = _optional(value, "mm", name)
    for name, value in zip(_FACTORS, (Y, e, X0, Y0, f0, f1, f2)):
        inputs[name] = _dimensionless(value, name)

    index = next((v.index for v in inputs.values() if isinstance(v, pd.Series)), None)
    arrays = {k: (v.to_numpy(dtype=float) if isinstance(v, pd.Series) else np.asarray(v, dtype=float))
              for k, v in inputs.items()}
    shape = np.broadcast_shapes(*(v.shape for v in arrays.values()))
    given = {"n": n, "nu": nu, "Fr": Fr, "Fa": Fa, "C0": C0, "alpha": alpha, "d": d, "D": D, "B": B, "Y": Y,
             "e": e, "X0": X0, "Y0": Y0, "f0": f0, "f1": f1, "f2": f2}
    range_warnings = check_ranges({k: arrays[k] for k, v in given.items() if v is not None}, shape, FrictionInputError)
    # arrays become one row axis; scalars stay scalars (no copies of constants)
    flat = {k: (v if v.ndim == 0 else np.broadcast_to(v, shape).ravel()) for k, v in arrays.items()}
    keys = pd.DataFrame({"designation": [bearing], "type": [bearing_type], "series": [series],
                         "lubrication": [lubrication], "arrangement": [arrangement]})
    supports = build_support_arrays(keys, flat)
    if supports.error:
        raise FrictionInputError(str(supports.error))
    with np.errstate(all="ignore"):
        results, problems = friction_model.evaluate(supports, Labels(), f2_chart)
    errors = [p for p in problems if p.level == "error"]
    if errors:
        first = errors[0]
        i = int(np.flatnonzero(first.mask)[0])
        raise FrictionInputError(first.message(i) + where(i, shape))
    messages = range_warnings + [p.message(int(np.flatnonzero(p.mask)[0])) for p in problems]
    messages += list(supports.notes[0])
    for name in ("MR", "NR"):
        bad = ~np.isfinite(results[name])
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise FrictionInputError(f"{name}: the result is not a finite number for these inputs; check their "
                                     f"magnitudes and units{where(i, shape)}")

    def out(name, unit):
        values = results[name].reshape(shape)
        if index is not None:
            series = pd.Series(values, index=index)
            return series if unit is None else quantity(series, unit)
        if unit is None:
            return values if shape else float(values)
        return quantity(values if shape else float(values), unit)

    return FrictionResult(
        f0=out("f0", None), f1=out("f1", None), P0=out("P0", "N"), P1=out("P1", "N"),
        M0=out("M0", "N*mm"), M1=out("M1", "N*mm"), M2=out("M2", "N*mm"), MR=out("MR", "N*mm"),
        NR=out("NR", "W"), Fa_over_A=out("Fa_over_A", None), nu_n_dM=out("nu_n_dM", "mm^3/(s*min)"),
        status="warning" if messages else "ok", messages=messages,
        bearing_type=str(supports.bearing_type), series=str(supports.series),
    )
