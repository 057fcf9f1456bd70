"""The heat balance for Python callers: pint Quantities in, :class:`HeatBalanceResult` of Quantities out.

Thermal reference speed, permissible speed and operating temperature of a
bearing (issue 3, after Schaeffler HR 1, ISO 15312 and DIN 732). The rows
are :mod:`bearingheat.calc.thermal`, the formulas
:mod:`bearingheat.kernels.thermal`; the friction comes from
:func:`bearingheat.calc.models.compute_supports`.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from bearingheat.api._checks import check_ranges
from bearingheat.calc.models import compute_supports
from bearingheat.calc.thermal import (OPERATING_TEMPERATURE_LIMIT, SPEED_FACTOR_METHODS, VISCOSITY_AT,
                                      fill_viscosity, heat_balance_rows, thermal_reference_speed_rows)
from bearingheat.errors import HeatBalanceError
from bearingheat.kernels.thermal import friction_power
from bearingheat.units import celsius, magnitude, quantity

__all__ = ["HeatBalanceResult", "heat_balance", "thermal_reference_speed"]


@dataclass
class HeatBalanceResult:
    """Heat balance of one bearing or of many operating points, as Quantities.

    n_thr, n_per [1/min]; T_op [degC]; nu_op [mm²/s]; Q_S, Q_L [W] carried
    away (at T_bearing where given, else at T_op); N_R [W] friction power at
    the operating point. NaN where a value could not be computed:
    ``status`` ('ok' | 'warning' | 'error') and ``messages`` say why, per row.
    """

    n_thr: object
    n_per: object
    T_op: object
    nu_op: object
    Q_S: object
    Q_L: object
    N_R: object
    status: list
    messages: list


def _plain_number(value, name):
    return np.asarray(getattr(value, "magnitude", value), dtype=float)


#: catalogue unit -> converter of the arguments in it that are no multiplicative unit (absolute
#: temperatures) or no unit at all (ISO VG grade, viscosity index); every other unit goes through magnitude
_CONVERTERS = {"degC": celsius, "1": _plain_number}


def _frame_column(value, unit, name):
    if value is None:
        return None
    convert = _CONVERTERS.get(unit)
    if convert is not None:
        return convert(value, name)
    return magnitude(value, unit, name)


_API_COLUMNS = {
    # argument -> (frame column, catalogue unit)
    "d": ("d", "mm"), "D": ("D", "mm"), "B": ("B", "mm"), "T": ("T", "mm"), "C0": ("C0", "N"),
    "n": ("n", "1/min"), "Fr": ("Fr", "N"), "Fa": ("Fa", "N"), "nu": ("nu", "mm^2/s"),
    "T_ambient": ("T_amb", "degC"), "T_bearing": ("T_bearing", "degC"), "k_q": ("k_q", "W/(mm^2*K)"),
    "V_oil": ("V_oil", "l/min"), "dT_oil": ("dT_oil", "delta_degC"), "Q_E": ("Q_E", "W"),
    "nu40": ("nu40", "mm^2/s"), "nu100": ("nu100", "mm^2/s"), "iso_vg": ("iso_vg", "1"),
    "viscosity_index": ("VI", "1"), "n_G": ("n_G", "1/min"), "n_thr_catalogue": ("n_thr_catalogue", "1/min"),
}


def heat_balance(designation: str | None = None, *, d, D, n=None, C0=None, B=None, T=None, Fr=None, Fa=None,
                 lubrication: str = "oil_bath", nu=None, nu40=None, nu100=None, iso_vg=None, viscosity_index=None,
                 T_ambient=None, T_bearing=None, k_q=None, V_oil=None, dT_oil=None, Q_E=None, n_G=None,
                 n_thr_catalogue=None, viscosity_at: str = "auto", method: str = "exact",
                 t_limit=None, bearing_type: str | None = None, series: str | None = None) -> HeatBalanceResult:
    """Thermal reference speed, permissible speed and operating temperature of a bearing (Quantities).

    Every dimensional argument is a pint Quantity (arrays and pint-pandas
    Series broadcast: one bearing, many operating points). Temperatures are
    absolute (degC, K); ``dT_oil`` is a difference (K, delta_degC);
    ``iso_vg`` and ``viscosity_index`` are plain numbers. ``viscosity_at``:
    'auto' (ν at T_bearing where given, else at T_op), 'bearing' or
    'operating' — where ν comes from nu40/nu100 or iso_vg; a given ``nu``
    is always used as it is. ``method``: 'exact' root of the f_n equation
    or the catalogue 'approximation'. ``t_limit``: the highest temperature
    searched for T_op (default 150 °C).

    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
    ...                  Fr=2 * u.kN, nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"),
    ...                  T_ambient=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    >>> round(r.n_thr.to("1/min").magnitude), round(r.n_per.to("1/min").magnitude), r.status
    (14416, 8053, ['ok'])
    >>> round(r.T_op.to("degC").magnitude, 1), round(r.nu_op.to("mm^2/s").magnitude, 1)
    (40.1, 67.5)
    """
    if method not in SPEED_FACTOR_METHODS:
        raise HeatBalanceError(f"method: {method!r} is not one of {', '.join(SPEED_FACTOR_METHODS)}")
    if viscosity_at not in VISCOSITY_AT:
        raise HeatBalanceError(f"viscosity_at: {viscosity_at!r} is not one of {', '.join(VISCOSITY_AT)}")
    args = {"d": d, "D": D, "B": B, "T": T, "C0": C0, "n": n, "Fr": Fr, "Fa": Fa, "nu": nu,
            "T_ambient": T_ambient, "T_bearing": T_bearing, "k_q": k_q, "V_oil": V_oil, "dT_oil": dT_oil,
            "Q_E": Q_E, "nu40": nu40, "nu100": nu100, "iso_vg": iso_vg, "viscosity_index": viscosity_index,
            "n_G": n_G, "n_thr_catalogue": n_thr_catalogue}
    columns = {}
    index = None
    for name, value in args.items():
        column, unit = _API_COLUMNS[name]
        mag = _frame_column(value, unit, name)
        if mag is None:
            continue
        if isinstance(mag, pd.Series):
            index = mag.index if index is None else index
            mag = mag.to_numpy(dtype=float)
        columns[column] = mag
    shape = np.broadcast_shapes(*(np.shape(v) for v in columns.values()))
    range_warnings = check_ranges(columns, shape, HeatBalanceError)
    if "n" not in columns:
        columns["n"] = np.nan
    size = int(np.prod(shape)) if shape else 1
    frame = pd.DataFrame({k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for k, v in columns.items()},
                         index=range(size))
    frame["designation"] = designation
    if bearing_type or series:
        frame["type"] = bearing_type
        frame["series"] = series
    frame["lubrication"] = lubrication
    limit = OPERATING_TEMPERATURE_LIMIT
    if t_limit is not None:
        limit = float(celsius(t_limit, "t_limit"))
    frame, problems = fill_viscosity(frame, viscosity_at=viscosity_at, t_limit=limit)
    if "nu" not in frame.columns:
        raise HeatBalanceError("nu: missing; give nu, or nu40 and nu100, or iso_vg")
    results = compute_supports(frame)
    extra, more = heat_balance_rows(frame, results, method=method, t_limit=limit)
    problems = problems + more
    status = results["status"].tolist()
    messages = [[m] if m else [] for m in results["message"]]
    for position in range(size) if range_warnings else ():
        messages[position] = range_warnings + messages[position]
        status[position] = "warning" if status[position] == "ok" else status[position]
    for position, level, message in problems:
        messages[position].append(message)
        if level == "error":
            status[position] = "error"
        elif status[position] == "ok":
            status[position] = "warning"
    failed = np.array([s == "error" for s in status])

    def out(name, unit):
        values = extra[name].to_numpy(dtype=float) if name in extra.columns else np.full(size, np.nan)
        values = np.where(failed, np.nan, values)
        if index is not None:
            return quantity(pd.Series(values, index=index), unit)
        return quantity(values.reshape(shape) if shape else float(values[0]), unit)

    N_R = np.where(failed, np.nan, friction_power(results["MR"].to_numpy(dtype=float),
                                                  frame["n"].to_numpy(dtype=float)))
    N_R_q = (quantity(pd.Series(N_R, index=index), "W") if index is not None
             else quantity(N_R.reshape(shape) if shape else float(N_R[0]), "W"))
    return HeatBalanceResult(n_thr=out("n_thr", "1/min"), n_per=out("n_per", "1/min"), T_op=out("T_op", "degC"),
                             nu_op=out("nu_op", "mm^2/s"), Q_S=out("Q_S", "W"), Q_L=out("Q_L", "W"), N_R=N_R_q,
                             status=status, messages=["; ".join(m) for m in messages])


def thermal_reference_speed(designation: str | None = None, *, d, D, C0, B=None, T=None,
                            bearing_type: str | None = None, series: str | None = None):
    """Thermal reference speed n_θr of catalogue bearings as a Quantity [1/min].

    Arguments are pint Quantities (arrays broadcast). Raises
    :class:`~bearingheat.errors.HeatBalanceError` with the reason where n_θr
    cannot be computed; :func:`bearingheat.calc.thermal.thermal_reference_speed_rows`
    returns NaN and the reasons instead.

    >>> import pint
    >>> u = pint.get_application_registry()
    >>> round(thermal_reference_speed("30205-A", d=25 * u.mm, D=52 * u.mm, T=16.25 * u.mm, C0=34.5 * u.kN).magnitude)
    9132
    >>> thermal_reference_speed("6205-2RSR", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: 6205-2RSR: n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals
    """
    columns = {"d": magnitude(d, "mm", "d"), "D": magnitude(D, "mm", "D"), "C0": magnitude(C0, "N", "C0")}
    if B is not None:
        columns["B"] = magnitude(B, "mm", "B")
    if T is not None:
        columns["T"] = magnitude(T, "mm", "T")
    shape = np.broadcast_shapes(*(np.shape(v) for v in columns.values()))
    size = int(np.prod(shape)) if shape else 1
    frame = pd.DataFrame({k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for k, v in columns.items()})
    frame["designation"] = designation
    if bearing_type or series:
        frame["type"], frame["series"] = bearing_type, series
    result = thermal_reference_speed_rows(frame)
    reasons = result.attrs["reason"]
    bad = reasons[reasons != ""]
    if len(bad):
        label = designation or f"{bearing_type} {series}"
        where = f" (row {bad.index[0]})" if size > 1 else ""
        raise HeatBalanceError(f"{label}{where}: {bad.iloc[0]}")
    values = result.to_numpy(dtype=float)
    return quantity(values.reshape(shape) if shape else float(values[0]), "1/min")
