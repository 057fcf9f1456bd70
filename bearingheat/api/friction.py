"""Unit-aware friction API: pint Quantities in, Quantities out.

>>> import pint
>>> u = pint.get_application_registry()
>>> r = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
...                     n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"))
>>> print(f"MR = {r.MR.to('N*mm').magnitude:.3f} N*mm, NR = {r.NR.to('W').magnitude:.3f} W, {r.status}")
MR = 47.535 N*mm, NR = 14.932 W, ['ok']

Scalars, numpy arrays and pint-pandas Series all work; arrays broadcast
against each other (one bearing, many operating points) and a Series in
gives a Series out. Shaft speed is revolutions per time: ``50 * u.Hz`` is
3000 1/min and ``u('rad/s')`` is divided by 2π.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
import pandas as pd

from bearingheat.api._checks import (ARGUMENT_LABELS, broadcast_shape, converted_model_inputs, dimensionless_number,
                                     point_status, point_warnings, shared_index, where)
from bearingheat.api.results import Result
from bearingheat.calc.messages import Labels
from bearingheat.calc.contract import column
from bearingheat.calc.fill import below_minimum_load, fill_arrays, implausible_values
from bearingheat.calc.models import DEFAULT_MODEL, MODEL_REPORT_UNITS, get_model
from bearingheat.calc.supports import build_support_arrays
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.errors import FrictionInputError
from bearingheat.units import Magnitude, QuantityLike, magnitude, quantity, speed_rpm

__all__ = ["FrictionResult", "friction_torque"]


@dataclass(frozen=True, repr=False)
class FrictionResult(Result):
    """Results of the catalogue friction model as Quantities, as :func:`friction_torque` returns them.

    The model is the one of the Schaeffler rolling bearing catalogue (Russian
    edition), chapter «Трение и нагрев» (Friction and increases in
    temperature), pp. 64–70: M_R = M_0 + M_1 (+ M_2), N_R = M_R·n/9550.
    Every value has the shape of the broadcast arguments: a float or pint
    Quantity for scalar arguments, a numpy array (in a Quantity) for array
    arguments, a pandas Series (pint dtype) when a Series went in.

    Parameters
    ----------
    f0 : float or numpy.ndarray or pandas.Series [1]
        Coefficient of the speed-dependent torque M0 (from the catalogue
        table for the bearing type, series and lubrication, or as given).
    f1 : float or numpy.ndarray or pandas.Series [1]
        Coefficient of the load-dependent torque M1.
    P0 : pint.Quantity or pandas.Series [N]
        Static equivalent load, for f1 in P0/C0.
    P1 : pint.Quantity or pandas.Series [N]
        Load of M1 = f1·P1·dM (by the P1 rule of the bearing type).
    M0 : pint.Quantity or pandas.Series [N·mm]
        Speed-dependent friction torque.
    M1 : pint.Quantity or pandas.Series [N·mm]
        Load-dependent friction torque.
    M2 : pint.Quantity or pandas.Series [N·mm]
        Torque of an axial load on a cylindrical roller bearing, f2·Fa·dM
        (0 where the bearing carries no axial load).
    MR : pint.Quantity or pandas.Series [N·mm]
        Total friction torque M0 + M1 + M2.
    NR : pint.Quantity or pandas.Series [W]
        Friction power loss MR·n/9550.
    Fa_over_A : float or numpy.ndarray or pandas.Series [1]
        The abscissa parameter Fa/A of the f2 chart where M2 applies, NaN
        elsewhere.
    nu_n_dM : pint.Quantity or pandas.Series [mm³/(s·min)]
        The viscosity-speed figure ν·n·dM of the f2 chart where M2 applies,
        NaN elsewhere.
    status : list of str
        Per operating point: 'ok', or 'warning' where the point has messages.
    messages : list of str
        Per operating point, joined by '; ': implausible magnitudes
        (probably a unit mix-up), a load above C0 or a speed above the
        bearing table's limiting speed n_G (as calc warns of them), a load
        below the bearing's minimum load, a
        contact seal whose friction is not in the
        model, a cylindrical roller bearing above Fa/Fr = 0.4, notes on the
        designation, values that differ from the bearing table.
    bearing_type : str
        The bearing type of the coefficient tables, e.g. 'deep_groove_ball'.
    series : str
        The series row of the coefficient tables, e.g. '62'.
    model_results : dict
        The other results of a model besides the catalogue model's, by
        contract name (the SKF model: M_rr, M_sl, M_seal, M_drag, M_start
        [N·mm], of both bearings of a pair; G_rr, G_sl, phi_ish, phi_rs,
        phi_bl, mu_sl [1], of one bearing).

    See Also
    --------
    friction_torque : computes it.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
    ...                     n=3000 * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"))
    >>> r.bearing_type, r.series, r.f0, r.P1
    ('deep_groove_ball', '62', 2.0, <Quantity(2000.0, 'newton')>)
    """

    f0: Magnitude
    f1: Magnitude
    P0: QuantityLike
    P1: QuantityLike
    M0: QuantityLike
    M1: QuantityLike
    M2: QuantityLike
    MR: QuantityLike
    NR: QuantityLike
    Fa_over_A: Magnitude
    nu_n_dM: QuantityLike
    status: list[str] = field(default_factory=lambda: ["ok"])
    messages: list[str] = field(default_factory=lambda: [""])
    bearing_type: str = ""
    series: str = ""
    model_results: dict[str, Magnitude | QuantityLike] = field(default_factory=dict)


_LENGTHS = ("d", "D", "B")
_FACTORS = ("Y", "e", "X0", "Y0", "f0", "f1", "f2")
#: the columns a model reads that are arguments of friction_torque: column -> argument
_ARGUMENTS = {"designation": "designation", "type": "bearing_type", "series": "series", "lubrication": "lubrication",
              "arrangement": "arrangement",
              **{name: name for name in ("n", "nu", "Fr", "Fa", "C0", "alpha", *_LENGTHS, *_FACTORS)}}


def _dimensionless(value: QuantityLike | npt.ArrayLike | None, name: str) -> Magnitude:
    return math.nan if value is None else dimensionless_number(value, name, FrictionInputError)


def _optional(value: QuantityLike | None, unit: str, name: str) -> Magnitude:
    return math.nan if value is None else magnitude(value, unit, name)


def friction_torque(designation: str | None = None, *, n: QuantityLike, nu: QuantityLike,
                    lubrication: str | None = None, Fr: QuantityLike | None = None, Fa: QuantityLike | None = None,
                    d: QuantityLike | None = None, D: QuantityLike | None = None, B: QuantityLike | None = None,
                    C0: QuantityLike | None = None, bearing_type: str | None = None, series: str | None = None,
                    arrangement: str = "single", Y: QuantityLike | npt.ArrayLike | None = None,
                    e: QuantityLike | npt.ArrayLike | None = None, X0: QuantityLike | npt.ArrayLike | None = None,
                    Y0: QuantityLike | npt.ArrayLike | None = None, alpha: QuantityLike | None = None,
                    f0: QuantityLike | npt.ArrayLike | None = None, f1: QuantityLike | npt.ArrayLike | None = None,
                    f2: QuantityLike | npt.ArrayLike | None = None, f2_chart: F2Chart | None = None,
                    model: str = DEFAULT_MODEL,
                    model_inputs: Mapping[str, QuantityLike | npt.ArrayLike | None] | None = None) -> FrictionResult:
    """Friction torque and power loss of one bearing at one or many operating points.

    The catalogue friction model of the Schaeffler rolling bearing catalogue
    (Russian edition), chapter «Трение и нагрев» (Friction and increases in
    temperature), pp. 64–70, whose f0 and f1 are the averaged values of
    ISO 15312: M_R = M_0 + M_1 (+ M_2 for axially loaded cylindrical roller
    bearings), N_R = M_R·n/9550. The static factors X0, Y0 of P0 are those of
    Е.П. Жильников, В.П. Тукмаков, «Исследование момента сил трения в
    шарикоподшипниках при комбинированном нагружении» (Samara University,
    2016), table 1, unless given.

    Every dimensional argument is a pint Quantity, converted once to the
    catalogue units (mm, N, 1/min, mm²/s); numpy arrays and pint-pandas
    Series broadcast against each other (one bearing, many operating points)
    and a Series in gives a Series out. A number outside its valid range
    raises; one outside its plausible range (usually a unit mix-up) is
    returned as a warning in :attr:`FrictionResult.messages`, as is a load
    above C0 or a speed above the bearing table's n_G, and a load below the
    bearing's minimum load (C/100, or C0/60 of cylindrical roller bearings,
    Schaeffler HR 1; the SKF model: its own rule).

    Parameters
    ----------
    designation : str, optional
        Designation such as ``"6205-2Z"`` or ``"NU206-E"``
        (:func:`~bearingheat.catalogue.designation.parse_designation`); or
        leave it out and give ``bearing_type`` and ``series`` for an explicit
        row of the coefficient tables.
    n : pint.Quantity [1/min]
        Shaft speed, revolutions per time (1/min, rpm, Hz) or an angular
        speed (rad/s, divided by 2π). Valid 0 to 1e7 1/min; above 2e5 1/min
        a warning.
    nu : pint.Quantity [mm²/s]
        Operating viscosity (the base oil viscosity of a grease); mm²/s = cSt.
        Valid > 0 and up to 1e7 mm²/s; outside 1 to 1e5 mm²/s a warning.
    lubrication : str, optional
        'grease', 'oil_mist', 'oil_bath' or 'circulating_oil'; selects f0.
        Not needed when ``f0`` is given.
    Fr : pint.Quantity [force], optional
        Radial load; default 0. Valid 0 to 1e10 N; above 1e8 N a warning.
    Fa : pint.Quantity [force], optional
        Axial load; default 0. Valid 0 to 1e10 N; above 1e8 N a warning.
        On cylindrical roller bearings it is refused where a ring has no
        ribs (NU, N, NN) and where Fr is 0; above Fa/Fr = 0.4 a warning.
    d : pint.Quantity [length], optional
        Bore; defaults to the bearing table (Schaeffler HR 1, 2006), else the
        bore code of the designation. Valid > 0 and up to 1e5 mm; outside
        0.5 to 5000 mm a warning.
    D : pint.Quantity [length], optional
        Outside diameter (dM = (d + D)/2); defaults to the bearing table, as
        do B, C0, Y, e and Y0 (a value given that differs from the table's
        is a warning); required for a designation the table does not know.
        Valid > d and up to 1e5 mm; outside 1 to 6000 mm a warning.
    B : pint.Quantity [length], optional
        Width, for the f0 formula of needle roller bearings; defaults to the
        width of drawn cups (HK2016). Valid > 0 and up to 1e5 mm; outside
        0.5 to 2000 mm a warning.
    C0 : pint.Quantity [force], optional
        Basic static load rating; required where f1 depends on P0/C0 or
        Fa/C0. Valid > 0 and up to 1e10 N; outside 10 to 1e8 N a warning.
    bearing_type : str, optional
        Bearing type of the coefficient tables instead of a designation, a
        key of :data:`~bearingheat.catalogue.designation.BEARING_TYPES`
        (e.g. 'deep_groove_ball'); give it with ``series``.
    series : str, optional
        Dimension series with ``bearing_type``, e.g. '62', '302', '222'.
    arrangement : str, optional
        'single' (default) or 'paired': a pair in X or O arrangement is one
        support, and the results are the pair's (the SKF model: each bearing
        at Fr/2; an axial load on a pair is refused).
    Y : float or pint.Quantity [1], optional
        Catalogue axial load factor of tapered roller bearings (P1 under
        axial load); valid > 0.
    e : float or pint.Quantity [1], optional
        Catalogue factor e of spherical roller bearings (P1 under axial
        load); valid > 0.
    X0 : float or pint.Quantity [1], optional
        Static radial factor; default from table 1 of the Samara lab manual.
    Y0 : float or pint.Quantity [1], optional
        Static axial factor; default from the same table or the contact angle.
    alpha : pint.Quantity [angle], optional
        Working contact angle of angular contact ball bearings (e.g. from
        :func:`~bearingheat.api.contact.ball_bearing_contact`). Valid 0 to 90°.
    f0 : float or pint.Quantity [1], optional
        Override of the tabulated coefficient f0; valid >= 0.
    f1 : float or pint.Quantity [1], optional
        Override of the tabulated coefficient f1; valid >= 0.
    f2 : float or pint.Quantity [1], optional
        Coefficient of M2 = f2·Fa·dM of an axially loaded cylindrical roller
        bearing (read from the catalogue's charts, figs. 3 and 4 of p. 70);
        valid >= 0.
    f2_chart : F2Chart, optional
        A user-digitised f2 chart (:class:`~bearingheat.catalogue.f2chart.F2Chart`)
        to read f2 from where ``f2`` is not given; never extrapolated.
    model : str, optional
        The friction model, a name of :data:`bearingheat.calc.models.MODELS`:
        'schaeffler' (default; the catalogue model above) or 'skf' (the SKF
        four-component model of the SKF General Catalogue 6000, chapter
        Friction, and SKF Rolling bearings 10000/3, 2017).
    model_inputs : dict, optional
        The inputs a model reads beyond the catalogue model's, by contract
        column name: for the SKF model ``oil_level`` and ``d_s`` [length],
        ``VM``, ``mu_sl``, ``mu_bl``, ``seals`` (numbers), ``skf_edition``,
        ``oil``, ``seal`` (text), ``Dw``, ``T`` [length]; for either model
        ``C`` [force], the basic dynamic load rating (not given: the bearing
        table's by designation), under whose minimum load a point gets a
        warning (the catalogue model: C/100, or C0/60 of cylindrical roller
        bearings, Schaeffler HR 1; the SKF model: 0.01 C of ball and 0.02 C
        of roller bearings). Scalars or arrays,
        broadcast with the other arguments. A name the model does not read,
        or one that is an argument of friction_torque (``Fr``, ``arrangement``
        ...), is refused.

    Returns
    -------
    FrictionResult
        f0, f1, P0, P1, M0, M1, M2, MR [N·mm], NR [W], the f2 chart
        coordinates, ``status`` ('ok' or 'warning') and the warning
        ``messages``, in the shape of the broadcast arguments.

    Raises
    ------
    bearingheat.errors.FrictionInputError
        For an argument the model cannot use, naming the argument and the
        value (and the index for arrays): NaN or infinite, not a number, an
        array that does not broadcast with the others, outside its valid
        range, a required one missing (D; C0 or f2 where the model needs
        them), an unknown designation, lubrication or arrangement, an axial
        load on a bearing that takes none, a Fa/A or ν·n·dM outside the
        ``f2_chart``, a ``model_inputs`` name the model does not read or that
        is an argument, or a result that is not a finite number.
    bearingheat.errors.ModelError
        For an unknown model name.
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension.

    Examples
    --------
    >>> import pint
    >>> u = pint.get_application_registry()
    >>> r = friction_torque("6205", d=25 * u.mm, D=52 * u.mm, C0=7.8 * u.kN, lubrication="oil_bath",
    ...                     n=[1000, 3000] * u.rpm, Fr=2 * u.kN, nu=12 * u("mm^2/s"))
    >>> r.MR.to("N*mm").magnitude.round(3), r.status
    (array([41.074, 47.535]), ['ok', 'ok'])
    >>> r.to_frame()[["MR [N*mm]", "NR [W]", "status"]].round(3)
       MR [N*mm]  NR [W] status
    0     41.074   4.301     ok
    1     47.535  14.932     ok
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
    for name, length in zip(_LENGTHS, (d, D, B)):
        inputs[name] = _optional(length, "mm", name)
    for name, factor in zip(_FACTORS, (Y, e, X0, Y0, f0, f1, f2)):
        inputs[name] = _dimensionless(factor, name)

    extra = converted_model_inputs(model_inputs or {}, friction_model.inputs, _ARGUMENTS, "friction_torque",
                                   FrictionInputError)
    # the model's own inputs are paired with the others by their index and broadcast with them
    index = shared_index({**inputs, **extra}, FrictionInputError)
    arrays = {k: (v.to_numpy(dtype=float) if isinstance(v, pd.Series) else np.asarray(v, dtype=float))
              for k, v in inputs.items()}
    extra_arrays = {k: (v.to_numpy(dtype=object if column(k).unit == "" else float) if isinstance(v, pd.Series)
                        else np.asarray(v, dtype=object if column(k).unit == "" else float))
                    for k, v in extra.items() if v is not None}
    # blank dimensions, ratings and factors from the bearing table (Schaeffler HR 1, 2006)
    typed = {k for k, v in {"d": d, "D": D, "B": B, "C0": C0, "Y": Y, "e": e, "Y0": Y0}.items() if v is not None}
    # (n_G, no friction input, only for the warning of a speed above it, and C, for the minimum load: filled in the
    # same lookup; a C given in model_inputs is compared with the table's)
    table_only = {"n_G": np.asarray(np.nan), "C": extra_arrays.get("C", np.asarray(np.nan))}
    arrays, fill_notes, unknown = fill_arrays(designation, {**arrays, **table_only},
                                              typed | ({"C"} & set(extra_arrays)))
    n_G = arrays.pop("n_G")
    rating = arrays.pop("C")
    if unknown is not None and D is None:
        raise FrictionInputError(f"{unknown}; or give d, D (and C0)")
    shape = broadcast_shape({**arrays, **extra_arrays}, FrictionInputError)
    given = {"n": n, "nu": nu, "Fr": Fr, "Fa": Fa, "C0": C0, "alpha": alpha, "d": d, "D": D, "B": B, "Y": Y,
             "e": e, "X0": X0, "Y0": Y0, "f0": f0, "f1": f1, "f2": f2}
    numbers = {**{k: arrays[k] for k, v in given.items() if v is not None},
               **{k: v for k, v in extra_arrays.items() if column(k).unit != ""}}  # the model's numbers too
    every, some = point_warnings(numbers, shape, FrictionInputError)
    # arrays become one row axis; scalars stay scalars (no copies of constants), but the speed spans the rows (its
    # length is the rows' count, also where only a model input varies)
    flat: dict[str, object] = {k: (v if v.ndim == 0 and k != "n" else np.broadcast_to(v, shape).ravel())
                               for k, v in arrays.items()}
    keys = {"designation": designation, "type": bearing_type, "series": series, "lubrication": lubrication,
            "arrangement": arrangement}
    supports = build_support_arrays(keys, flat)
    if supports.error and friction_model.catalogue_keys:
        raise FrictionInputError(str(supports.error))
    supports.extra = {"designation": designation, "type": bearing_type, "series": series, "lubrication": lubrication,
                      "arrangement": arrangement,
                      **{k: (extra[k] if v.ndim == 0 else np.broadcast_to(v, shape).ravel())
                         for k, v in extra_arrays.items()}}
    if "C" in friction_model.inputs and "C" not in extra_arrays:
        supports.extra["C"] = float(rating)  # the bearing table's (NaN where it has none)
    with np.errstate(all="ignore"):
        results, problems = friction_model.evaluate(supports, Labels(), f2_chart)
    errors = [p for p in problems if p.level == "error"]
    if errors:
        first = errors[0]
        i = int(np.flatnonzero(first.mask)[0])
        raise FrictionInputError(first.message(i) + where(i, shape))
    size = int(np.prod(shape)) if shape else 1
    for problem in problems:  # warnings of the points they concern
        for point in np.flatnonzero(np.broadcast_to(problem.mask, (size,))):
            some.setdefault(int(point), []).append(problem.message(int(point)))
    # a load above C0, a speed above the bearing table's n_G: calc's warnings, point by point
    # (read only: reshape keeps a broadcast number a view where the points are one row, ravel would copy it)
    related = {name: np.broadcast_to(value, shape).reshape(size)
               for name, value in (("n", arrays["n"]), ("n_G", n_G), ("Fr", arrays["Fr"]), ("Fa", arrays["Fa"]),
                                   ("C0", arrays["C0"]))}
    every_point = np.broadcast_to(True, (size,))  # (read-only views: nothing per point to allocate)
    for position, _, message in implausible_values(related, ARGUMENT_LABELS, every_point,
                                                   lambda: [designation] * size):
        some.setdefault(position, []).append(message)
    if not friction_model.own_minimum_load:  # a load below the bearing table's minimum load (the SKF model: its own)
        loads = {**{name: related[name] for name in ("Fr", "Fa", "C0")},
                 "C": np.broadcast_to(np.asarray(rating, dtype=float), shape).reshape(size)}
        types = np.broadcast_to(np.asarray(friction_model.bearing_keys(supports)[0], dtype=object), (size,))
        # every point is of bearing 0, whose first point is 0: its minimum worked out once
        one_bearing = (np.broadcast_to(np.intp(0), (size,)), np.zeros(1, dtype=np.intp))
        for position, _, message in below_minimum_load(loads, types, ARGUMENT_LABELS, every_point,
                                                       2.0 if arrangement == "paired" else 1.0, one_bearing):
            some.setdefault(position, []).append(message)
    # notes on the bearing, on every point: the designation's notes of the catalogue model's tables where the model
    # uses them, and the bearing table's (the dimensions both models read)
    every = every + (list(supports.notes[0]) if friction_model.catalogue_keys else []) + fill_notes
    status, messages = point_status(size, every, some)
    for name in ("MR", "NR"):
        bad = ~np.isfinite(results[name])
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise FrictionInputError(f"{name}: the result is not a finite number for these inputs; check their "
                                     f"magnitudes and units{where(i, shape)}")

    bearing_type_used, series_used = friction_model.bearing_keys(supports)  # of the tables the model used

    def number(name: str) -> Magnitude:
        """A dimensionless result in the shape of the arguments."""
        values = np.broadcast_to(results.get(name, np.nan), (int(np.prod(shape)),)).reshape(shape)
        if index is not None:
            return pd.Series(values, index=index)
        return values if shape else float(values)

    def out(name: str, unit: str) -> QuantityLike:
        """A result in ``unit`` in the shape of the arguments."""
        values = np.broadcast_to(results.get(name, np.nan), (int(np.prod(shape)),)).reshape(shape)
        if index is not None:
            return quantity(pd.Series(values, index=index), unit)
        return quantity(values if shape else float(values), unit)

    return FrictionResult(
        f0=number("f0"), f1=number("f1"), P0=out("P0", "N"), P1=out("P1", "N"),
        M0=out("M0", "N*mm"), M1=out("M1", "N*mm"), M2=out("M2", "N*mm"), MR=out("MR", "N*mm"),
        NR=out("NR", "W"), Fa_over_A=number("Fa_over_A"), nu_n_dM=out("nu_n_dM", "mm^3/(s*min)"),
        status=status, messages=messages,
        bearing_type=str(bearing_type_used), series=str(series_used),
        model_results={name: number(name) if unit in ("", "1") else out(name, unit)
                       for name, unit in MODEL_REPORT_UNITS.items()
                       if name in results and name in friction_model.outputs},
    )
