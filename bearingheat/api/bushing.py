"""Sizing of self-lubricating DU/DP bushings and thrust washers with units (the DU/DP bushing handbook).

The unit boundary of :mod:`bearingheat.kernels.bushing`: loads, speeds,
lengths, temperatures and the admissible K = pV and [p] are pint Quantities,
converted once to catalogue units; K and [p] come from the tables of
:mod:`bearingheat.catalogue.bushing` unless given. The results are frozen
dataclasses of Quantities (:class:`BushingSize`, :class:`ThrustWasherSize`)
with the API's common :class:`~bearingheat.api.results.Result` methods.
"""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, ClassVar, TypeVar

import numpy as np

from bearingheat.api.results import Result
from bearingheat.catalogue.bushing import pressure_limit_du_dp, pv_limit_du_dp_table25
from bearingheat.errors import BushingInputError
from bearingheat.kernels.bushing import size_bushing_kernel, size_thrust_washer_kernel, temperature_factor_du_dp
from bearingheat.units import Quantity, magnitude, quantity

__all__ = ["size_bushing", "size_thrust_washer", "BushingSize", "ThrustWasherSize"]

_Size = TypeVar("_Size", bound="_PlainBearingSize")


@dataclass(frozen=True, repr=False)
class _PlainBearingSize(Result):
    """The fields both sizings share; one sizing is one point of :class:`~bearingheat.api.results.Result`."""

    F: Quantity
    n: Quantity
    d: Quantity
    K: Quantity
    K_table: Quantity
    temperature_factor: float
    T: Quantity | None
    p_adm: Quantity
    governing: str
    V: Quantity
    p: Quantity
    pV: Quantity
    f_low: float
    f_high: float
    N_low: Quantity
    N_high: Quantity
    life_fig86: Quantity
    life_note: str
    #: '' or why the size is conservative (V below 0.05 m/s, n above 15 000 1/min: the handbook allows smaller)
    size_note: str
    status: list[str]
    messages: list[str]

    kind: ClassVar[str]
    #: field -> unit of the quantities (the catalogue units of the kernels)
    UNITS: ClassVar[dict[str, str]] = {
        "F": "N", "n": "1/min", "d": "mm", "K": "N/mm^2*m/s", "K_table": "N/mm^2*m/s", "T": "degC",
        "p_adm": "N/mm^2", "V": "m/s", "p": "N/mm^2", "pV": "N/mm^2*m/s", "N_low": "W", "N_high": "W",
        "life_fig86": "h", "l_pV": "mm", "p_at_l_pV": "N/mm^2", "l_p": "mm", "l_required": "mm",
        "l_standard": "mm", "b_pV": "mm", "D_pV": "mm", "D_p": "mm", "D_required": "mm", "D_standard": "mm",
    }

    @classmethod
    def _from_kernel(cls: type[_Size], values: dict[str, Any]) -> _Size:
        """The result of a sizing kernel's 'name [unit]' dict (units as :attr:`UNITS`)."""
        named: dict[str, Any] = {}
        for key, value in values.items():
            name = key.split(" [")[0]
            unit = cls.UNITS.get(name)
            named[name] = quantity(value, unit) if unit and value is not None else value
        named.pop("kind")
        notes = [values["size_note"]] if values["size_note"] else []  # a conservative size
        # the life line of fig. 86 covers part of the pV range: elsewhere the life is unknown, a warning
        if not np.isfinite(values["life_fig86 [h]"]):
            notes.append(f"life_fig86: {values['life_note']}")
        if not np.isfinite(values["N_low [W]"]):  # no coefficient outside 0.05-5 m/s: no power loss without f
            notes.append("N: the DU/DP bushing handbook gives no friction coefficient "
                         f"{'below V = 0.05' if values['V [m/s]'] < 0.05 else 'above V = 5'} m/s; give f for the "
                         "power loss")
        named["status"] = ["warning" if notes else "ok"]
        named["messages"] = ["; ".join(notes)]
        return cls(**named)

    def to_dict(self) -> dict[str, float | str | None]:
        """Magnitudes and texts keyed 'name [unit]' in the catalogue units (the keys of ``bushing --json``).

        Returns
        -------
        dict of str to float, str or None
            ``kind``, then every field under 'name [unit]' (unit-less
            factors and texts under their name); ``T [degC]`` is None
            without a temperature.
        """
        out: dict[str, float | str | None] = {"kind": self.kind}
        for item in fields(self):
            name = item.name
            if name in ("status", "messages"):
                continue
            value = getattr(self, name)
            unit = self.UNITS.get(name)
            if unit is None:
                out[name] = value
            else:
                out[f"{name} [{unit}]"] = None if value is None else float(magnitude(value, unit, name))
        return out


@dataclass(frozen=True, repr=False)
class BushingSize(_PlainBearingSize):
    """The length of a DU bushing by the DU/DP bushing handbook (:func:`size_bushing`).

    Quantities: ``F``, ``n``, ``d``; the derated ``K`` and the table's
    ``K_table`` with ``temperature_factor`` and ``T`` (None without a
    temperature); ``p_adm``; ``l_pV`` (the length from pV) with the pressure
    there ``p_at_l_pV``; ``l_p`` (the length from [p]); ``governing`` ('pV'
    or 'pressure'); ``l_required`` and ``l_standard`` (NaN without standard
    lengths); at the chosen length ``V``, ``p`` and ``pV``; the friction
    coefficients ``f_low``, ``f_high`` and the power losses ``N_low``,
    ``N_high``; the fig. 86 life ``life_fig86`` with ``life_note``. One
    point: ``status`` is 'warning' where fig. 86 gives no life.
    """

    l_pV: Quantity
    p_at_l_pV: Quantity
    l_p: Quantity
    l_required: Quantity
    l_standard: Quantity

    kind: ClassVar[str] = "bushing"


@dataclass(frozen=True, repr=False)
class ThrustWasherSize(_PlainBearingSize):
    """The outer diameter of a DU thrust washer by the DU/DP bushing handbook (:func:`size_thrust_washer`).

    The fields of :class:`BushingSize` without the lengths, and ``b_pV``
    (the radial width from pV), ``D_pV``, ``D_p`` (the outer diameter from
    [p]), ``D_required`` and ``D_standard`` (NaN without standard
    diameters); V, p and pV at the mean diameter of the chosen size.
    """

    b_pV: Quantity
    D_pV: Quantity
    D_p: Quantity
    D_required: Quantity
    D_standard: Quantity

    kind: ClassVar[str] = "thrust_washer"


def _one(value: Quantity, unit: str, name: str) -> float:
    """One value of a sizing in ``unit``: a sizing is of one bushing (its standard size is looked up once), so an
    array is refused with :class:`BushingInputError` rather than a TypeError."""
    number = magnitude(value, unit, name)
    if np.ndim(number) != 0 and np.size(number) != 1:
        raise BushingInputError(f"{name}: {np.size(number)} values; a sizing is of one bushing, so give one {name} "
                                "(and loop over the cases)")
    return float(np.ravel(number)[0])


def _friction(f: float | Quantity | None) -> float | None:
    """The friction coefficient the user gave, a plain number (or a dimensionless Quantity) in (0, 1]; None when
    not given (the handbook's range at V is used then)."""
    if f is None:
        return None
    value = f.to("dimensionless").magnitude if isinstance(f, Quantity) else f
    try:
        value = float(value)  # (an array or a text is no one coefficient)
    except (TypeError, ValueError):
        raise BushingInputError(f"f = {value!r}: expected one friction coefficient, a number > 0 and <= 1") from None
    if not 0.0 < value <= 1.0:  # (NaN fails too)
        raise BushingInputError(f"f = {value:g}: expected a friction coefficient > 0 and <= 1")
    return value


def _admissible(application: str, shaft: str | None, life: Quantity | None, load_type: str, T: Quantity | None,
                K: Quantity | None, p_adm: Quantity | None) -> tuple[float, float, float | None, float]:
    if K is None:
        if shaft is None or life is None:
            raise BushingInputError("give either K, or shaft and life to read K from the DU/DP bushing handbook table 25")
        K_table = pv_limit_du_dp_table25(application, shaft, float(magnitude(life, "h", "life")))
    else:
        K_table = float(magnitude(K, "N/mm^2*m/s", "K"))
    T_c = None if T is None else float(magnitude(T, "degC", "T"))
    factor = 1.0 if T_c is None else temperature_factor_du_dp(T_c)
    p_table = pressure_limit_du_dp(load_type)  # (an unknown load type is refused whether or not p_adm is given)
    p = p_table if p_adm is None else float(magnitude(p_adm, "N/mm^2", "p_adm"))
    return K_table, factor, T_c, p


def size_bushing(F: Quantity, n: Quantity, d: Quantity, *, application: str = "bushing_constant_load",
                 shaft: str | None = None, life: Quantity | None = None, load_type: str, T: Quantity | None = None,
                 K: Quantity | None = None, p_adm: Quantity | None = None, standard_lengths: Quantity | None = None,
                 f: float | None = None) -> BushingSize:
    """Size a cylindrical DU bushing with pint Quantities.

    K comes from table 25 (application, shaft 'soft'/'hardened', life 1000 h
    or 10 000 h) unless given; it is derated for T. [p] comes from the load
    type unless given.
    The length is the larger of l_pV = π·n·F/(60 000·K) and
    l_p = F/([p]·d), rounded up to ``standard_lengths`` where given.

    Source: the Russian book chapter on metal-fluoroplastic ("DU", "DP")
    bushings, section «Служебные свойства подшипников марки «DU»»: table 25
    (admissible K = pV by application, shaft and life), the admissible
    specific loads [p] on p. 167, the life line of fig. 86 and the
    friction coefficients; its units kgf/cm² are converted with
    1 kgf/cm² = 0.0980665 N/mm².

    Parameters
    ----------
    F : pint.Quantity [force]
        Radial load; must be > 0.
    n : pint.Quantity [1/min]
        Shaft speed (for an oscillating shaft: cycles per minute times the
        amplitude in revolutions); must be > 0. Above 15 000 1/min or below
        a sliding speed V = π·d·n/60 000 of 0.05 m/s the size is conservative
        (a warning: the handbook allows a smaller one there).
    d : pint.Quantity [length]
        Bore (shaft diameter); must be > 0.
    application : str, optional
        Row of table 25: 'bushing_constant_load' (default),
        'bushing_rotating_load', 'bushing_oscillating', 'guide' or
        'thrust_washer'.
    shaft : str, optional
        'soft' (mild steel, also cast iron, austenitic stainless, anodised
        aluminium, chromium-plated mild steel) or 'hardened' (HB 540);
        needed with ``life`` unless K is given.
    life : pint.Quantity [time], optional
        Required life, 1000 h or 10 000 h (the columns of table 25); needed
        with ``shaft`` unless K is given.
    load_type : str
        Load type for the admissible pressure [p] (p. 167): 'static',
        'rotating_fixed_load_point', 'moving_load_moderate' or
        'moving_load_severe'. Required even where ``p_adm`` is given.
    T : pint.Quantity [temperature], optional
        Operating temperature, -200 to +280 °C; K is derated linearly from
        1 at +120 °C to 0.5 at +280 °C. Default: no derating.
    K : pint.Quantity [N/mm²·m/s], optional
        Admissible pV instead of table 25; must be > 0.
    p_adm : pint.Quantity [N/mm²], optional
        Admissible specific load [p] instead of the load type's; must be > 0.
    standard_lengths : pint.Quantity [length], optional
        Standard bushing lengths (an array, all > 0); the result is rounded
        up to the next one.
    f : float, optional
        Friction coefficient for the power loss; default: the source's range
        at V (0.05-0.1 at 0.05-0.1 m/s, 0.1-0.2 at 0.2-5 m/s).

    Returns
    -------
    BushingSize
        The sizing as Quantities (see :class:`BushingSize`): the lengths
        from pV and from [p], the governing one, the standard length, p, V
        and pV there, the friction losses and the fig. 86 life;
        ``to_dict()`` gives the magnitudes keyed 'name [unit]'.

    Raises
    ------
    bearingheat.errors.BushingInputError
        For neither K nor shaft and life; an application, shaft, life or
        load type the tables do not have; a table 25 cell lost in the
        source's OCR; F, n, d, K or [p] not > 0; standard lengths not > 0.
    bearingheat.errors.OutsideMethodError
        For T outside -200 to +280 °C (the range of table 25). Below
        V = 0.05 m/s or above n = 15 000 1/min the size is computed and
        the result warns that the handbook allows a smaller one there.
    bearingheat.errors.NoStandardSizeError
        When no standard length is as long as the required one.
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension.

    Examples
    --------
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> out = size_bushing(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h,
    ...                    load_type="rotating_fixed_load_point", standard_lengths=[20, 30, 50, 100] * u.mm)
    >>> round(out.l_pV.to("mm").magnitude, 1), out.l_standard, out.governing, out.status
    (94.5, <Quantity(100.0, 'millimeter')>, 'pV', ['ok'])
    """
    K_table, factor, T_c, p = _admissible(application, shaft, life, load_type, T, K, p_adm)
    lengths = None if standard_lengths is None else np.atleast_1d(magnitude(standard_lengths, "mm", "standard_lengths"))
    result = size_bushing_kernel(_one(F, "N", "F"), _one(n, "1/min", "n"), _one(d, "mm", "d"), K_table * factor, p,
                                 lengths, _friction(f))
    result.update({"K_table [N/mm^2*m/s]": K_table, "temperature_factor": factor, "T [degC]": T_c})
    return BushingSize._from_kernel(result)


def size_thrust_washer(F: Quantity, n: Quantity, d: Quantity, *, shaft: str | None = None, life: Quantity | None = None,
                       load_type: str, T: Quantity | None = None, K: Quantity | None = None,
                       p_adm: Quantity | None = None, standard_diameters: Quantity | None = None,
                       f: float | None = None) -> ThrustWasherSize:
    """Size a DU thrust washer with pint Quantities; d is the inner diameter.

    K comes from table 25 (application thrust_washer) unless given, derated for
    T; [p] from the load type unless given. V and pV are taken at the mean
    diameter. The outer
    diameter is the larger of D_pV = d + 2·n·F/(60 000·K) and
    D_p = sqrt(d² + 4·F/(π·[p])), rounded up to ``standard_diameters`` where
    given.

    Source: the Russian book chapter on metal-fluoroplastic ("DU", "DP")
    bushings, section «Служебные свойства подшипников марки «DU»»: table 25
    (admissible K = pV by application, shaft and life), the admissible
    specific loads [p] on p. 167, the life line of fig. 86 and the
    friction coefficients; its units kgf/cm² are converted with
    1 kgf/cm² = 0.0980665 N/mm².

    Parameters
    ----------
    F : pint.Quantity [force]
        Axial load; must be > 0.
    n : pint.Quantity [1/min]
        Shaft speed; must be > 0. Above 15 000 1/min or below a sliding
        speed of 0.05 m/s at the mean diameter the size is conservative (a
        warning: the handbook allows a smaller one there).
    d : pint.Quantity [length]
        Inner diameter of the washer; must be > 0.
    shaft : str, optional
        'soft' or 'hardened' (HB 540) counterface; needed with ``life``
        unless K is given.
    life : pint.Quantity [time], optional
        Required life, 1000 h or 10 000 h; needed with ``shaft`` unless K
        is given. Only the soft and the hardened 1000 h cells of the
        thrust washer row survived the source's OCR.
    load_type : str
        Load type for [p] (p. 167): 'static', 'rotating_fixed_load_point',
        'moving_load_moderate' or 'moving_load_severe'.
    T : pint.Quantity [temperature], optional
        Operating temperature, -200 to +280 °C, for the derating of K.
    K : pint.Quantity [N/mm²·m/s], optional
        Admissible pV instead of table 25; must be > 0.
    p_adm : pint.Quantity [N/mm²], optional
        Admissible specific load [p] instead of the load type's; must be > 0.
    standard_diameters : pint.Quantity [length], optional
        Standard outer diameters (an array, all > 0); the result is rounded
        up to the next one.
    f : float, optional
        Friction coefficient for the power loss; default: the source's range
        at V.

    Returns
    -------
    ThrustWasherSize
        The sizing as Quantities (see :class:`ThrustWasherSize`): the outer
        diameters from pV and from [p], the governing one, the standard
        diameter, p, V and pV there, the friction losses and the fig. 86
        life; ``to_dict()`` gives the magnitudes keyed 'name [unit]'.

    Raises
    ------
    bearingheat.errors.BushingInputError
        For neither K nor shaft and life; a shaft, life or load type the
        tables do not have; a table 25 cell lost in the source's OCR; F, n,
        d, K or [p] not > 0; standard diameters not > 0.
    bearingheat.errors.OutsideMethodError
        For T outside -200 to +280 °C (the range of table 25). Below
        V = 0.05 m/s or above n = 15 000 1/min the size is computed and
        the result warns that the handbook allows a smaller one there.
    bearingheat.errors.NoStandardSizeError
        When no standard diameter is as large as the required one.
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension.

    Examples
    --------
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> out = size_thrust_washer(2 * u.kN, 500 * u.rpm, 25 * u.mm, shaft="soft", life=1000 * u.h, load_type="static")
    >>> round(out.D_required.to("mm").magnitude, 2), out.governing
    (104.98, 'pV')
    """
    K_table, factor, T_c, p = _admissible("thrust_washer", shaft, life, load_type, T, K, p_adm)
    diameters = None if standard_diameters is None else np.atleast_1d(
        magnitude(standard_diameters, "mm", "standard_diameters"))
    result = size_thrust_washer_kernel(_one(F, "N", "F"), _one(n, "1/min", "n"), _one(d, "mm", "d"), K_table * factor,
                                       p, diameters, _friction(f))
    result.update({"K_table [N/mm^2*m/s]": K_table, "temperature_factor": factor, "T [degC]": T_c})
    return ThrustWasherSize._from_kernel(result)
