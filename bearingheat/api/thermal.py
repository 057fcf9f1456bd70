"""The heat balance for Python callers: pint Quantities in, :class:`HeatBalanceResult` of Quantities out.

Thermal reference speed, permissible speed and operating temperature of a
bearing (after Schaeffler HR 1, ISO 15312 and DIN 732). The rows
are :mod:`bearingheat.calc.thermal`, the formulas
:mod:`bearingheat.kernels.thermal`; the friction comes from
:func:`bearingheat.calc.models.compute_supports`.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import pandas as pd

from bearingheat.api._checks import (ARGUMENT_LABELS, broadcast_shape, converted_model_inputs, dimensionless_number,
                                     point_status, point_warnings, shared_index, where)
from bearingheat.api.results import Result
from bearingheat.calc.contract import ARRANGEMENTS, column
from bearingheat.calc.fill import fill_from_catalogue, implausible_relations, minimum_load_relations
from bearingheat.calc.heat_flows import walther_columns
from bearingheat.calc.models import DEFAULT_MODEL, compute_supports, get_model
from bearingheat.calc.thermal import (OPERATING_TEMPERATURE_LIMIT, SPEED_FACTOR_METHODS, VISCOSITY_AT,
                                      fill_viscosity, heat_balance_rows, settle_viscosity, thermal_reference_speed_rows)
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import HeatBalanceError
from bearingheat.kernels.thermal import friction_power
from bearingheat.units import Magnitude, Quantity, QuantityLike, celsius, magnitude, quantity

__all__ = ["HeatBalanceResult", "heat_balance", "thermal_reference_speed"]


@dataclass(frozen=True, repr=False)
class HeatBalanceResult(Result):
    """Heat balance of one bearing or of many operating points, as Quantities.

    The values are pint Quantities of the shape of the broadcast arguments
    of :func:`heat_balance` (a pint-pandas Series when a Series went in).
    NaN where a value could not be computed: ``status`` and ``messages`` say
    why, per operating point.

    Parameters
    ----------
    n_thr : pint.Quantity or pandas.Series [1/min]
        Thermal reference speed n_θr (ISO 15312; Schaeffler catalogue HR 1
        "Rolling bearings", edition June 2006), by the catalogue model's
        tables whatever the friction model; NaN where the method does not
        apply (a pair, a contact seal, a thrust ball bearing) or the heat
        flow area lacks a width (B, or T of tapered roller bearings; thrust
        bearings need d and D only).
    n_per : pint.Quantity or pandas.Series [1/min]
        Thermally permissible speed n_θr·f_n at ``T_bearing`` (needs
        T_bearing and T_amb), capped at n_G where that is given.
    T_op : pint.Quantity or pandas.Series [degC]
        Operating temperature at the speed n, where the friction heat and
        the heat carried away balance (needs T_amb).
    nu_op : pint.Quantity or pandas.Series [mm²/s]
        Oil viscosity at T_op (from nu40/nu100 or iso_vg, or the given nu).
    Q_S : pint.Quantity or pandas.Series [W]
        Heat carried away through the bearing seat, at T_bearing where given,
        else at T_op.
    Q_L : pint.Quantity or pandas.Series [W]
        Heat carried away by circulating oil, at the same temperature
        (0 without V_oil).
    NR : pint.Quantity or pandas.Series [W]
        Friction power at the operating point, (π·n/30)·1e-3·M_R, with M_R
        of the friction model of the balance (``model``; a pair's for
        ``arrangement`` 'paired').
    status : list of str
        Per operating point: 'ok', 'warning' or 'error'.
    messages : list of str
        Per operating point: the warnings and errors, joined by '; ' ('' when
        ok).

    See Also
    --------
    heat_balance : computes it.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
    ...                  Fr=2 * u.kN, nu=12 * u("mm^2/s"), T_amb=u.Quantity(20, "degC"))
    >>> round(r.T_op.to("degC").magnitude, 1), round(r.NR.to("W").magnitude, 2), r.n_per.magnitude
    (32.9, 14.93, nan)
    """

    n_thr: QuantityLike
    n_per: QuantityLike
    T_op: QuantityLike
    nu_op: QuantityLike
    Q_S: QuantityLike
    Q_L: QuantityLike
    NR: QuantityLike
    status: list[str]
    messages: list[str]


def _plain_number(value: QuantityLike | npt.ArrayLike, name: str) -> Magnitude:
    return dimensionless_number(value, name, HeatBalanceError)


#: catalogue unit -> converter of the arguments in it that are no multiplicative unit (absolute
#: temperatures) or no unit at all (ISO VG grade, viscosity index); every other unit goes through magnitude
_CONVERTERS: dict[str, Callable[[QuantityLike | npt.ArrayLike, str], Magnitude]] = {
    "degC": celsius, "1": _plain_number}


def _frame_column(value: QuantityLike | npt.ArrayLike | None, unit: str, name: str) -> Magnitude | None:
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
    "T_amb": ("T_amb", "degC"), "T_bearing": ("T_bearing", "degC"), "k_q": ("k_q", "W/(mm^2*K)"),
    "V_oil": ("V_oil", "l/min"), "dT_oil": ("dT_oil", "delta_degC"), "Q_E": ("Q_E", "W"),
    "nu40": ("nu40", "mm^2/s"), "nu100": ("nu100", "mm^2/s"), "iso_vg": ("iso_vg", "1"),
    "VI": ("VI", "1"), "n_G": ("n_G", "1/min"), "n_thr_catalogue": ("n_thr_catalogue", "1/min"), "f2": ("f2", "1"),
}
#: the columns a model may read that are arguments of heat_balance: column -> argument
_ARGUMENTS = {"designation": "designation", "type": "bearing_type", "series": "series", "lubrication": "lubrication",
              "arrangement": "arrangement", **{name: name for name in _API_COLUMNS}}


def heat_balance(designation: str | None = None, *, d: QuantityLike | None = None, D: QuantityLike | None = None,
                 n: QuantityLike | None = None, C0: QuantityLike | None = None, B: QuantityLike | None = None,
                 T: QuantityLike | None = None, Fr: QuantityLike | None = None, Fa: QuantityLike | None = None,
                 lubrication: str = "oil_bath", nu: QuantityLike | None = None, nu40: QuantityLike | None = None,
                 nu100: QuantityLike | None = None, iso_vg: float | None = None, VI: float | None = None,
                 T_amb: Quantity | None = None, T_bearing: Quantity | None = None, k_q: QuantityLike | None = None,
                 V_oil: QuantityLike | None = None, dT_oil: QuantityLike | None = None,
                 Q_E: QuantityLike | None = None, n_G: QuantityLike | None = None,
                 n_thr_catalogue: QuantityLike | None = None, viscosity_at: str = "auto", method: str = "exact",
                 t_limit: Quantity | None = None, bearing_type: str | None = None,
                 series: str | None = None, f2: QuantityLike | npt.ArrayLike | None = None,
                 f2_chart: F2Chart | str | None = None, arrangement: str = "single", model: str = DEFAULT_MODEL,
                 model_inputs: Mapping[str, QuantityLike | npt.ArrayLike | None] | None = None
                 ) -> HeatBalanceResult:
    """Thermal reference speed, permissible speed and operating temperature of a bearing (Quantities).

    The heat balance NR + Q_E = Q_S + Q_L of the Schaeffler catalogue HR 1
    "Rolling bearings" (edition June 2006), after ISO 15312 (thermal
    reference speed) and the draft of DIN 732 (thermally permissible speed);
    the friction NR is that of :func:`friction_torque` with the same
    ``model``: by default the catalogue model (Schaeffler rolling bearing
    catalogue, chapter «Трение и нагрев», Friction and increases in
    temperature), or the SKF four-component model, which the balance
    evaluates at each speed and temperature it tries. n_thr is defined by
    the catalogue model's tables whatever the model (ISO 15312). Viscosity
    against temperature follows ASTM D341 (Walther), ISO 3448 grades and
    ASTM D2270.

    Every dimensional argument is a pint Quantity (arrays and pint-pandas
    Series broadcast: one bearing, many operating points). Temperatures are
    absolute (degC, K); ``dT_oil`` is a difference (K, delta_degC);
    ``iso_vg`` and ``VI`` are plain numbers. A number outside
    its valid range raises; one outside its plausible range is a warning in
    ``messages``, as is a load above C0, a speed above n_G or a load below
    the bearing's minimum load (as :func:`friction_torque`). A point the
    friction model or the balance cannot compute (a missing n, a negative
    load, an unknown designation) gets status
    'error' and NaN, and does not raise. A point whose balance has no
    equilibrium in the search gets T_op NaN and status 'warning' (with a
    given ``nu``, or with ``T_bearing`` to take ν at instead); it is an
    'error' only where ν was to be taken at T_op and nothing else gives it.

    Parameters
    ----------
    designation : str, optional
        Bearing designation such as ``"6205"`` or ``"30205-A"``; or give
        ``bearing_type`` and ``series``.
    d : pint.Quantity [length], optional
        Bore; valid up to 1e5 mm (outside 0.5 to 5000 mm a warning). Not
        given: from the bearing table (Schaeffler HR 1, 2006), as are D, B,
        T, C0 and n_G; a value given that differs from the table's is a
        warning.
    D : pint.Quantity [length], optional
        Outside diameter; valid up to 1e5 mm (outside 1 to 6000 mm a warning).
    n : pint.Quantity [1/min], optional
        Operating speed (1/min, rpm, Hz); needed for T_op, n_per and NR.
        Valid up to 1e7 1/min (above 2e5 1/min a warning).
    C0 : pint.Quantity [force], optional
        Basic static load rating; needed for n_thr (reference load
        P1 = 0.05·C0) and where f1 depends on P0/C0. Valid up to 1e10 N.
    B : pint.Quantity [length], optional
        Width; the heat flow area A_r = π·B·(D + d) of radial bearings
        (thrust bearings: (π/2)·(D² − d²)).
    T : pint.Quantity [length], optional
        Total width of tapered roller bearings: A_r = π·T·(D + d).
    Fr : pint.Quantity [force], optional
        Radial load at the operating point; default 0.
    Fa : pint.Quantity [force], optional
        Axial load at the operating point; default 0.
    lubrication : str, optional
        'grease', 'oil_mist', 'oil_bath' (default) or 'circulating_oil'.
    nu : pint.Quantity [mm²/s], optional
        Operating viscosity, used as it is; else give ``nu40`` and ``nu100``
        or ``iso_vg``.
    nu40 : pint.Quantity [mm²/s], optional
        Oil viscosity at 40 °C (with ``nu100``); valid up to 1e7 mm²/s
        (outside 1 to 1e5 mm²/s a warning).
    nu100 : pint.Quantity [mm²/s], optional
        Oil viscosity at 100 °C (with ``nu40``); same ranges.
    iso_vg : float, optional
        ISO 3448 viscosity grade (2 to 3200) instead of nu40/nu100; valid
        1 to 10 000.
    VI : float, optional
        Viscosity index of the ISO VG oil (ASTM D2270; default 95); valid
        -100 to 400.
    T_amb : pint.Quantity [temperature], optional
        Ambient temperature; needed for T_op, nu_op, Q_S, Q_L and n_per.
        Valid -60 to 200 °C.
    T_bearing : pint.Quantity [temperature], optional
        Bearing (outer ring) temperature, for n_per and the heat carried
        away. Valid -60 to 300 °C (above 200 °C a warning).
    k_q : pint.Quantity [W/(mm²·K)], optional
        Heat transfer coefficient of the seat; default q_r/50 K; must be > 0
        (outside 2e-5 to 1e-2 W/(mm²·K), a tenth to ten times the HR 1
        catalogue's 0.2e-3 to 1.0e-3, a warning).
    V_oil : pint.Quantity [l/min], optional
        Circulating oil flow; valid 0 to 1e4 l/min.
    dT_oil : pint.Quantity [temperature difference], optional
        Oil temperature rise; default T − T_amb (oil fed at ambient,
        leaving at the bearing temperature T: T_bearing for n_per, Q_S and
        Q_L, each trial temperature for T_op). Valid 0 to 200 K.
    Q_E : pint.Quantity [power], optional
        External heat flowing into the bearing (negative: cooling); default 0
        (beyond ±1e5 W a warning).
    n_G : pint.Quantity [1/min], optional
        Limiting speed: n_per is capped at it (with a warning). Valid up to
        1e7 1/min.
    n_thr_catalogue : pint.Quantity [1/min], optional
        The catalogue's n_θr; n_per then uses it instead of the computed one.
        Valid > 0 and up to 1e7 1/min.
    viscosity_at : str, optional
        Where ν is taken when it comes from nu40/nu100 or iso_vg: 'auto'
        (default; at T_op where T_amb and n are given, at T_bearing where
        they are not or where T_op has no solution), 'bearing' (T_bearing)
        or 'operating' (T_op). A given ``nu`` is always used as it is.
    method : str, optional
        How the speed factor f_n of n_per is found: 'exact' (default; the
        root of the f_n equation) or 'approximation' (the catalogue's
        formula, valid for 0.01 <= k_L, k_P <= 10).
    t_limit : pint.Quantity [temperature], optional
        Highest temperature searched for T_op; default 150 °C.
    bearing_type : str, optional
        Bearing type of the coefficient tables instead of a designation.
    series : str, optional
        Dimension series with ``bearing_type``.
    f2 : float or pint.Quantity [1], optional
        Coefficient of M2 = f2·Fa·dM of an axially loaded cylindrical roller
        bearing (the Schaeffler catalogue, p. 69), held at this value at
        every speed and temperature of the balance.
    f2_chart : F2Chart or str, optional
        A digitised f2 chart (:class:`~bearingheat.catalogue.f2chart.F2Chart`,
        or the path of its CSV) to read f2 off where ``f2`` is not given: M2
        then follows ν·n·dM at each speed and temperature the balance tries,
        as in :func:`~bearingheat.calc.table.calc`. The chart is never
        extrapolated: a root it does not reach is not computed, and the
        message names the chart's end.
    arrangement : str, optional
        'single' (default) or 'paired': a pair in X or O arrangement is one
        support, and NR is the pair's (the SKF model: each bearing at Fr/2;
        an axial load on a pair is the point's error). The sources define
        the heat balance of single bearings only, so a pair gets n_thr,
        n_per and T_op NaN with a warning saying so.
    model : str, optional
        The friction model of N_R, as in :func:`friction_torque`:
        'schaeffler' (default) or 'skf' (the SKF four-component model).
    model_inputs : dict, optional
        The inputs a model reads beyond the arguments of heat_balance, by
        contract column name: for the SKF model ``oil_level`` and ``d_s``
        [length], ``VM``, ``mu_sl``, ``mu_bl``, ``seals`` (numbers),
        ``skf_edition``, ``oil``, ``seal`` (text), ``Dw`` [length] (the
        total width of tapered roller bearings is the argument ``T``); for
        either model ``Y``, the axial load factor of tapered roller
        bearings, and ``C`` [force], the basic dynamic load rating (as
        :func:`friction_torque` takes it), and for the catalogue model
        ``e``, ``X0``, ``Y0``, ``f0``, ``f1`` (numbers) and ``alpha``
        [angle], as
        :func:`friction_torque` takes them. Scalars or arrays, broadcast
        with the other arguments. A name the model does not read, or one
        that is an argument of heat_balance (``T``, ``designation`` ...),
        is refused.

    Returns
    -------
    HeatBalanceResult
        n_thr, n_per [1/min], T_op [degC], nu_op [mm²/s], Q_S, Q_L, NR [W],
        and per operating point ``status`` and ``messages``.

    Raises
    ------
    bearingheat.errors.HeatBalanceError
        For an unknown ``method``, ``viscosity_at`` or ``arrangement``, a
        ``model_inputs`` name the model does not read or that is an
        argument, no viscosity at all (none of nu, nu40 with nu100, an ISO
        VG grade; or the reason the oil data give none), arrays of shapes
        that do not pair point by point (naming two of them), and a number
        that is NaN, infinite, outside its valid range or no number at all
        (naming the argument and, for arrays, the index).
    bearingheat.errors.ModelError
        For an unknown model name.
    bearingheat.errors.F2ChartError
        For an ``f2_chart`` file that cannot be read or used.
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, a unit of the wrong
        dimension, or a temperature difference where an absolute
        temperature is needed.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = heat_balance("6205", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN, n=3000 * u.rpm,
    ...                  Fr=2 * u.kN, nu40=68 * u("mm^2/s"), nu100=8.6 * u("mm^2/s"),
    ...                  T_amb=u.Quantity(20, "degC"), T_bearing=u.Quantity(70, "degC"))
    >>> round(r.n_thr.to("1/min").magnitude), round(r.n_per.to("1/min").magnitude), r.status
    (14416, 8053, ['ok'])
    >>> round(r.T_op.to("degC").magnitude, 1), round(r.nu_op.to("mm^2/s").magnitude, 1)
    (40.1, 67.5)
    """
    for name, choice, choices in (("method", method, SPEED_FACTOR_METHODS),
                                  ("viscosity_at", viscosity_at, VISCOSITY_AT),
                                  ("arrangement", arrangement, ARRANGEMENTS)):
        if choice not in choices:
            raise HeatBalanceError(f"{name}: {choice!r} is not one of {', '.join(choices)}")
    friction_model = get_model(model)
    model_values = converted_model_inputs(model_inputs or {}, friction_model.inputs, _ARGUMENTS, "heat_balance",
                                          HeatBalanceError)
    # the model's own inputs are frame columns by their contract names: numbers beside the arguments, text apart
    texts = {k: v for k, v in model_values.items() if v is not None and column(k).unit == ""}
    args = {"d": d, "D": D, "B": B, "T": T, "C0": C0, "n": n, "Fr": Fr, "Fa": Fa, "nu": nu,
            "T_amb": T_amb, "T_bearing": T_bearing, "k_q": k_q, "V_oil": V_oil, "dT_oil": dT_oil,
            "Q_E": Q_E, "nu40": nu40, "nu100": nu100, "iso_vg": iso_vg, "VI": VI,
            "n_G": n_G, "n_thr_catalogue": n_thr_catalogue, "f2": f2}
    if isinstance(f2_chart, str):
        f2_chart = F2Chart.from_csv(f2_chart)
    columns: dict[str, float | np.ndarray] = {}
    magnitudes = {name: _frame_column(value, _API_COLUMNS[name][1], name) for name, value in args.items()}
    numbers = {k: v for k, v in model_values.items() if v is not None and k not in texts}
    index = shared_index({**magnitudes, **numbers, **texts}, HeatBalanceError)
    for name, mag in magnitudes.items():
        if mag is None:
            continue
        columns[_API_COLUMNS[name][0]] = mag.to_numpy(dtype=float) if isinstance(mag, pd.Series) else mag
    for name, value in numbers.items():  # range-checked and broadcast as the arguments are
        columns[name] = value.to_numpy(dtype=float) if isinstance(value, pd.Series) else np.asarray(value, dtype=float)
    text_arrays = {k: v.to_numpy(dtype=object) if isinstance(v, pd.Series) else np.asarray(v, dtype=object)
                   for k, v in texts.items()}
    shape = broadcast_shape({**columns, **text_arrays}, HeatBalanceError)
    every, some = point_warnings(columns, shape, HeatBalanceError)  # a scalar's warnings: every point's
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
    frame["arrangement"] = arrangement
    for name, values in text_arrays.items():
        frame[name] = np.broadcast_to(values, shape).ravel()
    frame, fill_problems, from_table = fill_from_catalogue(frame, ARGUMENT_LABELS)  # blank d, D, B, T, C0 ... from
    # the bearing table; a load above C0 or a speed above n_G is calc's warning
    fill_problems += implausible_relations(frame, ARGUMENT_LABELS, from_table)
    limit = OPERATING_TEMPERATURE_LIMIT
    if t_limit is not None:
        limit = float(celsius(t_limit, "t_limit"))
    frame, problems = fill_viscosity(frame, viscosity_at=viscosity_at)
    # no point's oil data fix a viscosity line (or none were given): the oil data's own fault where they have one
    # (calc's row message). A point with a line but no temperature to take it at is a point in error, not a raise.
    no_line = "_walther_A" not in frame.columns or np.isnan(frame["_walther_A"].to_numpy(dtype=float)).all()
    if "nu" not in frame.columns or (no_line and frame["nu"].isna().all()):
        errors = [(i, message) for i, level, message in problems + walther_columns(frame)[2] if level == "error"]
        if errors:
            raise HeatBalanceError(errors[0][1] + where(errors[0][0], shape))
        raise HeatBalanceError("nu: missing; give nu, or nu40 and nu100, or iso_vg")
    frame, results, settled = settle_viscosity(frame, compute_supports(frame, f2_chart=f2_chart, model=model),
                                               t_limit=limit, f2_chart=f2_chart, model=model)
    problems += settled + minimum_load_relations(frame, results, ARGUMENT_LABELS, model)
    extra, more = heat_balance_rows(frame, results, method=method, t_limit=limit, reference_speed=True,
                                    f2_chart=f2_chart)
    problems = fill_problems + problems + more
    status, ranges = point_status(size, every, some)
    messages = [[m] if m else [] for m in ranges]
    for position, (level, message) in enumerate(zip(results["status"].tolist(), results["message"])):
        if message:
            messages[position].append(message)
        if level == "error" or (level == "warning" and status[position] == "ok"):
            status[position] = level
    for position, level, message in problems:
        messages[position].append(message)
        if level == "error":
            status[position] = "error"
        elif status[position] == "ok":
            status[position] = "warning"
    failed = np.array([s == "error" for s in status])

    def out(name: str, unit: str) -> QuantityLike:
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
                             nu_op=out("nu_op", "mm^2/s"), Q_S=out("Q_S", "W"), Q_L=out("Q_L", "W"), NR=N_R_q,
                             status=status, messages=["; ".join(m) for m in messages])


def thermal_reference_speed(designation: str | None = None, *, d: Quantity, D: Quantity, C0: Quantity,
                            B: Quantity | None = None, T: Quantity | None = None, bearing_type: str | None = None,
                            series: str | None = None) -> Quantity:
    """Thermal reference speed n_θr of catalogue bearings as a Quantity [1/min].

    The speed at which the friction heat under the reference conditions of
    ISO 15312 (20 °C ambient, 70 °C outer ring, oil bath of 12 mm²/s for
    radial and 24 mm²/s for thrust bearings, load 0.05·C0 radial or 0.02·C0
    axial) equals the heat q_r·A_r carried away, as in the Schaeffler
    catalogue HR 1 "Rolling bearings" (edition June 2006). The friction is
    the model of the Schaeffler rolling bearing catalogue, chapter «Трение и
    нагрев» (Friction and increases in temperature). Arguments are pint
    Quantities; arrays broadcast. The method does not apply to thrust ball
    bearings, bearings with contact seals or combined bearings.

    Parameters
    ----------
    designation : str, optional
        Bearing designation such as ``"6205"``; or give ``bearing_type`` and
        ``series``.
    d : pint.Quantity [length]
        Bore.
    D : pint.Quantity [length]
        Outside diameter.
    C0 : pint.Quantity [force]
        Basic static load rating; must be > 0.
    B : pint.Quantity [length], optional
        Width; A_r = π·B·(D + d) of radial bearings, which need B or T
        (thrust bearings: A_r = (π/2)·(D² − d²)).
    T : pint.Quantity [length], optional
        Total width of tapered roller bearings: A_r = π·T·(D + d).
    bearing_type : str, optional
        Bearing type of the coefficient tables instead of a designation.
    series : str, optional
        Dimension series with ``bearing_type``.

    Returns
    -------
    pint.Quantity [1/min]
        n_θr, a float or an array of the broadcast shape (a pint-pandas
        Series with their index for Series arguments, which must share one
        index).

    Raises
    ------
    bearingheat.errors.HeatBalanceError
        With the reason where n_θr cannot be computed (the first such row
        for arrays): the method does not apply to the bearing, B and T are
        missing, C0 is not > 0, the designation is missing or unknown.
        :func:`bearingheat.calc.thermal.thermal_reference_speed_rows`
        returns NaN and the reasons instead. Also for arrays of shapes that
        do not pair value by value (naming two of them).
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> round(thermal_reference_speed("30205-A", d=25 * u.mm, D=52 * u.mm, T=16.25 * u.mm, C0=34.5 * u.kN).magnitude)
    9132
    >>> thermal_reference_speed("6205-2RSR", d=25 * u.mm, D=52 * u.mm, B=15 * u.mm, C0=7.8 * u.kN)
    Traceback (most recent call last):
    ...
    bearingheat.errors.HeatBalanceError: 6205-2RSR: n_thr: the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its reference conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, whose heat balance would leave the seal friction out, are not computed either
    """
    columns = {"d": magnitude(d, "mm", "d"), "D": magnitude(D, "mm", "D"), "C0": magnitude(C0, "N", "C0")}
    if B is not None:
        columns["B"] = magnitude(B, "mm", "B")
    if T is not None:
        columns["T"] = magnitude(T, "mm", "T")
    index = shared_index(columns, HeatBalanceError)
    columns = {k: v.to_numpy(dtype=float) if isinstance(v, pd.Series) else v for k, v in columns.items()}
    shape = broadcast_shape(columns, HeatBalanceError)
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
    if index is not None:
        return quantity(pd.Series(values, index=index), "1/min")
    return quantity(values.reshape(shape) if shape else float(values[0]), "1/min")
