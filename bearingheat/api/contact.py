"""Ball bearing contact with units (Zaitsev & Voronkin): lengths, angles, forces and speeds as pint Quantities.

The unit boundary of :mod:`bearingheat.kernels.contact`: every argument is
converted once to the kernels' catalogue units (mm, N, 1/min, deg), every
result comes back as a Quantity in a :class:`BallContact`.

Source: В.А. Зайцев, В.А. Воронкин, «Расчёт осевых усилий и рабочих
углов контакта подшипников качения при оценке их качества на стендах»
(ФГУП «НПП ВНИИЭМ», 2009).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from bearingheat.api._checks import point_status, point_warnings, shared_index, where
from bearingheat.api.results import Result
from bearingheat.errors import ContactInputError, UnitError
from bearingheat.kernels.contact import (axial_displacement, axial_displacement_ratio, hertz_coefficients,
                                         initial_contact_angle, minimum_axial_load, race_curvatures,
                                         stiffness_characteristic, working_contact_angle)
from bearingheat.units import Quantity, magnitude, quantity, speed_rpm

__all__ = ["BallContact", "ball_bearing_contact", "contact_angle_from_clearance"]


@dataclass(frozen=True, repr=False)
class BallContact(Result):
    """Contact of one ball bearing (Quantities). ``Fa_min`` needs n; it uses α0 (the source's rule),
    ``Fa_min_at_alpha`` the working angle under Fa.

    The method of В.А. Зайцев, В.А. Воронкин, «Расчёт осевых усилий и рабочих
    углов контакта подшипников качения при оценке их качества на стендах»
    (ФГУП «НПП ВНИИЭМ», 2009). Every value is a pint Quantity (float or
    array, of the shape of the broadcast arguments).

    Parameters
    ----------
    alpha0 : pint.Quantity [deg]
        Initial contact angle (given, or from the clearance).
    alpha : pint.Quantity [deg]
        Working contact angle under the axial load Fa.
    Fa : pint.Quantity [N]
        Axial load (0 when none was given: α = α0).
    xi_a : pint.Quantity [1]
        Dimensionless axial displacement ξ_a of the rings.
    delta_a : pint.Quantity [mm]
        Axial displacement of the rings, ξ_a·(r_i + r_o − d_w).
    C_star : pint.Quantity [N]
        Stiffness ("force") characteristic C* of the bearing.
    sum_rho_i : pint.Quantity [1/mm]
        Curvature sum Σρ of the inner ball-race contact.
    sum_rho_o : pint.Quantity [1/mm]
        Curvature sum Σρ of the outer ball-race contact.
    cos_tau_i : pint.Quantity [1]
        Auxiliary cos τ = F(ρ) of the inner contact.
    cos_tau_o : pint.Quantity [1]
        Auxiliary cos τ = F(ρ) of the outer contact.
    deflection_i : pint.Quantity [1]
        Hertz coefficient 2K/(μπ) (δ*) of the inner contact.
    deflection_o : pint.Quantity [1]
        Hertz coefficient 2K/(μπ) (δ*) of the outer contact.
    n : pint.Quantity [1/min], optional
        Inner-ring speed; None when not given.
    Fa_min : pint.Quantity [N], optional
        Minimum axial load against gyroscopic sliding of the balls at n and
        α0 (the source's rule); None without n.
    Fa_min_at_alpha : pint.Quantity [N], optional
        The same at the working angle α (the larger, stricter value); None
        without n.
    status, messages : list of str
        Per point (flattened): 'warning' where a given Fa is below Fa_min
        (the balls slide under gyroscopic moments) or below the stricter
        Fa_min_at_alpha, else 'ok'.

    See Also
    --------
    ball_bearing_contact : computes it.

    Examples
    --------
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> r = ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
    ...                          clearance=10 * u.um)
    >>> round(r.alpha0.to("deg").magnitude, 4), r.Fa, r.n
    (12.5279, <Quantity(0.0, 'newton')>, None)
    """

    alpha0: Quantity
    alpha: Quantity
    Fa: Quantity
    xi_a: Quantity
    delta_a: Quantity
    C_star: Quantity
    sum_rho_i: Quantity
    sum_rho_o: Quantity
    cos_tau_i: Quantity
    cos_tau_o: Quantity
    deflection_i: Quantity
    deflection_o: Quantity
    n: Quantity | None = None
    Fa_min: Quantity | None = None
    Fa_min_at_alpha: Quantity | None = None
    status: list[str] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)

    # key of to_dict() -> (attribute, unit)
    _KEYS: ClassVar[dict[str, tuple[str, str]]] = {
        "alpha0 [deg]": ("alpha0", "deg"),
        "Fa [N]": ("Fa", "N"),
        "alpha [deg]": ("alpha", "deg"),
        "xi_a": ("xi_a", ""),
        "delta_a [mm]": ("delta_a", "mm"),
        "C_star [N]": ("C_star", "N"),
        "sum_rho_i [1/mm]": ("sum_rho_i", "1/mm"),
        "sum_rho_o [1/mm]": ("sum_rho_o", "1/mm"),
        "cos_tau_i": ("cos_tau_i", ""),
        "cos_tau_o": ("cos_tau_o", ""),
        "2K/(mu*pi)_i": ("deflection_i", ""),
        "2K/(mu*pi)_o": ("deflection_o", ""),
        "n [1/min]": ("n", "1/min"),
        "Fa_min [N]": ("Fa_min", "N"),
        "Fa_min at alpha [N]": ("Fa_min_at_alpha", "N"),
    }

    def to_dict(self) -> dict[str, float | list[float]]:
        """Magnitudes under keys carrying their unit, e.g. ``'alpha [deg]'``; keys of absent values left out.

        Returns
        -------
        dict of str to float or list of float
            Keys 'alpha0 [deg]', 'Fa [N]', 'alpha [deg]', 'xi_a',
            'delta_a [mm]', 'C_star [N]', 'sum_rho_i [1/mm]',
            'sum_rho_o [1/mm]', 'cos_tau_i', 'cos_tau_o', '2K/(mu*pi)_i',
            '2K/(mu*pi)_o' and, with n, 'n [1/min]', 'Fa_min [N]',
            'Fa_min at alpha [N]'; arrays become lists.

        Examples
        --------
        >>> from bearingheat.units import ureg
        >>> u = ureg()
        >>> r = ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
        ...                          alpha0=12 * u.deg)
        >>> d = r.to_dict()
        >>> d["alpha [deg]"], d["Fa [N]"], "n [1/min]" in d
        (12.0, 0.0, False)
        """
        result: dict[str, float | list[float]] = {}
        for key, (attribute, unit) in self._KEYS.items():
            value = getattr(self, attribute)
            if value is None:
                continue
            mag = magnitude(value, unit or "dimensionless", key)  # (a Quantity, or a pint-pandas Series)
            result[key] = np.asarray(mag).tolist() if np.ndim(mag) else float(mag)
        return result


def _angle_deg(value: Quantity, name: str) -> float | np.ndarray:
    if getattr(value, "unitless", False):
        raise UnitError(f"{name}: {value.magnitude!r} has no unit; write it as an angle, e.g. {value.magnitude!r} deg")
    return magnitude(value, "deg", name)


def _require_finite(values: dict[str, Any]) -> None:
    """:class:`ContactInputError` for the first argument that holds NaN or an infinite number (a kernel would
    carry it into every result with status 'ok')."""
    for name, value in values.items():
        flat = np.ravel(np.asarray(value, dtype=float))
        bad = np.flatnonzero(~np.isfinite(flat))
        if len(bad):
            raise ContactInputError(f"{name}: {flat[bad[0]]:g} is not a finite number"
                                    + where(int(bad[0]), np.shape(value)))


def _count(value: float | Quantity, name: str) -> float:
    if isinstance(value, (bool, np.bool_, str, bytes)):  # (True is 1 to Python, '7' no number)
        raise ContactInputError(f"{name}: {value!r} is not a number of balls")
    if isinstance(value, Quantity):
        if not value.unitless:
            raise UnitError(f"{name}: {value} must be a plain number of balls, without a unit")
        return value.magnitude
    return value


def contact_angle_from_clearance(clearance: Quantity, r_i: Quantity, r_o: Quantity, d_w: Quantity) -> Quantity:
    """Initial contact angle α0 (Quantity in degrees) from the mean radial clearance.

    Unit-aware form of :func:`~bearingheat.kernels.contact.initial_contact_angle`: lengths are Quantities.
    α0 = arccos[1 − e / (2·(r_i + r_o − d_w))], after В.А. Зайцев, В.А. Воронкин,
    «Расчёт осевых усилий и рабочих углов контакта подшипников качения при
    оценке их качества на стендах» (ФГУП «НПП ВНИИЭМ», 2009), p. 1.

    Parameters
    ----------
    clearance : pint.Quantity [length]
        Mean radial clearance e (the catalogue value of the clearance group);
        valid 0 <= e <= 2·(r_i + r_o − d_w) (α0 up to 90°).
    r_i : pint.Quantity [length]
        Groove radius of the inner ring.
    r_o : pint.Quantity [length]
        Groove radius of the outer ring; r_i + r_o must exceed d_w.
    d_w : pint.Quantity [length]
        Ball diameter; must be > 0.

    Returns
    -------
    pint.Quantity [deg]
        α0, a float or an array of the broadcast shape.

    Raises
    ------
    bearingheat.errors.ContactInputError
        For d_w <= 0, r_i + r_o <= d_w, a negative clearance, or one above
        2·(r_i + r_o − d_w) (naming the value and, for arrays, the element).
    bearingheat.errors.UnitError
        For a plain number or a unit that is not a length.

    Examples
    --------
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> round(contact_angle_from_clearance(10 * u.um, 1.05 * u.mm, 1.16 * u.mm, 2 * u.mm).to('deg').magnitude, 4)
    12.5279
    """
    e = magnitude(clearance, "mm", "clearance")
    ri, ro, dw = (magnitude(q, "mm", nm) for q, nm in ((r_i, "r_i"), (r_o, "r_o"), (d_w, "d_w")))
    _require_finite({"clearance": e, "r_i": ri, "r_o": ro, "d_w": dw})
    return quantity(initial_contact_angle(e, ri, ro, dw), "deg")


def ball_bearing_contact(*, z: float, d_w: Quantity, d_m: Quantity, r_i: Quantity, r_o: Quantity,
                         alpha0: Quantity | None = None, clearance: Quantity | None = None, Fa: Quantity | None = None,
                         n: Quantity | None = None) -> BallContact:
    """Contact angles, stiffness and minimum axial load of a ball bearing, unit-aware.

    z: number of balls (plain number); d_w ball diameter, d_m pitch diameter,
    r_i, r_o groove radii: lengths; exactly one of alpha0 (angle) or clearance
    (mean radial clearance, length); Fa axial load (force, default 0: α = α0);
    n inner-ring speed (1/min, rpm, Hz, rad/s), optional, for the minimum
    axial load. Returns a :class:`BallContact` of Quantities.

    Source: В.А. Зайцев, В.А. Воронкин, «Расчёт осевых
    усилий и рабочих углов контакта подшипников качения при оценке их качества
    на стендах» (ФГУП «НПП ВНИИЭМ», 2009), pp. 1–3. The load is shared equally
    by all balls (pure axial load, no misalignment, no centrifugal force).

    Parameters
    ----------
    z : int or float [1]
        Number of balls, a whole number >= 1 without a unit.
    d_w : pint.Quantity [length]
        Ball diameter; must be > 0.
    d_m : pint.Quantity [length]
        Pitch diameter; must exceed d_w.
    r_i : pint.Quantity [length]
        Groove radius of the inner ring; must exceed d_w/2.
    r_o : pint.Quantity [length]
        Groove radius of the outer ring; must exceed d_w/2.
    alpha0 : pint.Quantity [angle], optional
        Initial contact angle, 0 <= α0 < 90°. Give this or ``clearance``.
    clearance : pint.Quantity [length], optional
        Mean radial clearance, 0 to 2·(r_i + r_o − d_w); α0 follows by
        :func:`contact_angle_from_clearance`. Give this or ``alpha0``.
    Fa : pint.Quantity [force], optional
        Axial load, >= 0; default 0 (α = α0).
    n : pint.Quantity [1/min], optional
        Inner-ring speed (1/min, rpm, Hz, rad/s), >= 0; needed for the
        minimum axial load.

    Returns
    -------
    BallContact
        α0, α, Fa, ξ_a, δ_a, C*, the curvature sums and Hertz coefficients
        of both contacts and, with n, Fa_min at α0 and at α.

    Raises
    ------
    bearingheat.errors.ContactInputError
        For neither or both of alpha0 and clearance, and a value outside the
        ranges above (impossible geometry, a negative load or speed, a
        clearance that turns α0 past 90°, a number of balls that is not a
        whole number >= 1).
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed (an angle without a
        unit), a unit of the wrong dimension, or a unit on ``z``.

    Examples
    --------
    >>> from bearingheat.kernels.contact import degrees_to_dms
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> r = ball_bearing_contact(z=7, d_w=2 * u.mm, d_m=8.7355 * u.mm, r_i=1.05 * u.mm, r_o=1.16 * u.mm,
    ...                          alpha0=12 * u.deg, Fa=2 * u.kgf, n=3000 * u.rpm)
    >>> round(r.C_star.to('kgf').magnitude), degrees_to_dms(r.alpha.to('deg').magnitude), round(r.xi_a.magnitude, 5)
    (7803, '14°27′57″', 0.04443)
    >>> r.Fa_min.to('mN')
    <Quantity(10.19..., 'millinewton')>
    """
    if (alpha0 is None) == (clearance is None):
        raise ContactInputError("give exactly one of alpha0 (an angle) or clearance (the mean radial clearance)")
    # pint-pandas Series are paired row by row: one index for all of them
    shared_index({"d_w": d_w, "d_m": d_m, "r_i": r_i, "r_o": r_o, "alpha0": alpha0, "clearance": clearance, "Fa": Fa,
                  "n": n}, ContactInputError)
    count = _count(z, "z")
    dw, dm, ri, ro = (magnitude(q, "mm", nm) for q, nm in ((d_w, "d_w"), (d_m, "d_m"), (r_i, "r_i"), (r_o, "r_o")))
    _require_finite({"z": count, "d_w": dw, "d_m": dm, "r_i": ri, "r_o": ro})
    if alpha0 is not None:
        angle0 = _angle_deg(alpha0, "alpha0")
        _require_finite({"alpha0": angle0})
    else:
        e = magnitude(clearance, "mm", "clearance")
        _require_finite({"clearance": e})
        angle0 = initial_contact_angle(e, ri, ro, dw)
    load = 0.0 if Fa is None else magnitude(Fa, "N", "Fa")
    rpm = None if n is None else speed_rpm(n, "n")
    # NaN, infinite and absurd loads and speeds (beyond the contract's valid ranges: Fa up to 1e10 N, where the
    # angle's root can still be bracketed) raise, naming the argument
    ranged = {"Fa": load} | ({"n": rpm} if rpm is not None else {})
    shape = np.broadcast_shapes(*(np.shape(v) for v in (count, dw, dm, ri, ro, angle0, *ranged.values())))
    every, some = point_warnings(ranged, shape, ContactInputError)  # and plausibility warnings (Fa, n) per point

    curv = race_curvatures(dw, dm, angle0, ri, ro)
    hertz_i, hertz_o = hertz_coefficients(curv.cos_tau_i), hertz_coefficients(curv.cos_tau_o)
    c_star = stiffness_characteristic(count, dw, dm, angle0, ri, ro,
                                      deflection_coefficients=(hertz_i.deflection, hertz_o.deflection))
    angle = working_contact_angle(load, c_star, angle0)
    xi_a = axial_displacement_ratio(angle, angle0)
    speed = fa_min = fa_min_working = None
    points = int(np.prod(shape))  # every argument's points, the speeds' too
    status, messages = point_status(points, every, some)
    if rpm is not None:
        speed = quantity(rpm, "1/min")
        minimum = minimum_axial_load(count, dw, dm, rpm, angle0)
        minimum_working = minimum_axial_load(count, dw, dm, rpm, angle)
        fa_min = quantity(minimum, "N")
        fa_min_working = quantity(minimum_working, "N")
        if Fa is not None:
            for i, low in enumerate(_below_minimum_load(load, minimum, minimum_working, rpm, angle0, angle)):
                if low:
                    status[i] = "warning"
                    messages[i] = f"{messages[i]}; {low}" if messages[i] else low
    return BallContact(
        alpha0=quantity(angle0, "deg"),
        alpha=quantity(angle, "deg"),
        Fa=quantity(load, "N"),
        xi_a=quantity(xi_a, "dimensionless"),
        delta_a=quantity(axial_displacement(xi_a, ri, ro, dw), "mm"),
        C_star=quantity(c_star, "N"),
        sum_rho_i=quantity(curv.sum_rho_i, "1/mm"),
        sum_rho_o=quantity(curv.sum_rho_o, "1/mm"),
        cos_tau_i=quantity(curv.cos_tau_i, "dimensionless"),
        cos_tau_o=quantity(curv.cos_tau_o, "dimensionless"),
        deflection_i=quantity(hertz_i.deflection, "dimensionless"),
        deflection_o=quantity(hertz_o.deflection, "dimensionless"),
        n=speed,
        Fa_min=fa_min,
        Fa_min_at_alpha=fa_min_working,
        status=status,
        messages=messages,
    )


def _below_minimum_load(load: float | np.ndarray, minimum: float | np.ndarray, minimum_working: float | np.ndarray,
                        rpm: float | np.ndarray, angle0: float | np.ndarray, angle: float | np.ndarray) -> list[str]:
    """Per point: the message where Fa < Fa_min at α0 (the source's rule), or where Fa lies between it and the
    stricter Fa_min at the working angle α under Fa; else ''.

    Zaitsev & Voronkin, p. 1: "as a rule" the initial angle α0 from the clearance is taken as the contact angle of
    the minimum load, but on test stands "the real working contact angle α at the actual axial load" must be
    computed; the minimum grows with the angle (sin²α), so at α it is the larger of the two.
    """
    arrays = np.broadcast_arrays(load, minimum, minimum_working, rpm, angle0, angle)
    messages = []
    for fa, low, high, n, a0, a in zip(*(np.ravel(values).tolist() for values in arrays)):
        if fa < low:
            messages.append(f"Fa = {fa:.4g} N is below the minimum axial load Fa_min = {low:.4g} N at n = {n:.6g} "
                            "1/min (gyroscopic sliding of the balls, Zaitsev & Voronkin)")
        elif fa < high:
            messages.append(f"Fa = {fa:.4g} N meets the minimum axial load at the initial angle alpha0 = {a0:.4g} deg, "
                            f"Fa_min = {low:.4g} N (Zaitsev & Voronkin's rule), but not the stricter one at the working "
                            f"angle alpha = {a:.4g} deg under this load, Fa_min at alpha = {high:.4g} N, at n = "
                            f"{n:.6g} 1/min: the balls may slide under their gyroscopic moment")
        else:
            messages.append("")
    return messages
