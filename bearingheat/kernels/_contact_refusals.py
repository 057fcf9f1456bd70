"""Input checks of the ball bearing contact kernels (:mod:`bearingheat.kernels.contact`): the refusals and the
wrapper that names the Series row of a refused value.

Each check raises :class:`~bearingheat.errors.ContactInputError` (a ValueError) at the first bad element, with a
message naming the argument, its value and the range expected (Zaitsev & Voronkin's formulas hold there); NaN
is never refused (a row without geometry gives NaN out).
"""
from __future__ import annotations

import functools

import numpy as np

from bearingheat.errors import ContactInputError
from bearingheat.kernels._series import series_aware


def _broadcast(*values):
    """Float arrays of one broadcast shape (Series were made arrays by :func:`_kernel`)."""
    arrays = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in values])
    return [np.array(a, dtype=float) for a in arrays]


def _refuse(bad, template: str, **values):
    """Raise ContactInputError for the first element where ``bad`` holds (NaN never counts as bad).

    The message names the element of an array; :func:`_kernel` renames it to
    the row label when the kernel was called with a Series.
    """
    bad = np.asarray(bad, dtype=bool)
    if not bad.any():
        return
    flat = int(np.flatnonzero(bad.ravel())[0])
    cells = {k: np.broadcast_to(np.asarray(v, dtype=float), bad.shape).ravel()[flat] for k, v in values.items()}
    message = template.format(**cells)
    if bad.ndim == 0:
        raise ContactInputError(message)
    position = np.unravel_index(flat, bad.shape)
    row = position[0] if len(position) == 1 else tuple(int(p) for p in position)
    error = ContactInputError(f"{message} (element {row})", row)
    setattr(error, "_refusal", (message, flat))
    raise error


def _row_labels(values):
    """Row labels (the index) of the first pandas Series among ``values``, else None.

    Duck-typed on a non-callable ``index`` attribute (a list's ``index`` is a
    method), so that the kernels need no pandas of their own.
    """
    for value in values:
        labels = getattr(value, "index", None)
        if labels is not None and not callable(labels):
            return labels
    return None


def _kernel(func):
    """:func:`series_aware` (Series in, Series out), and a refusal that names the Series row, not the element."""
    inner = series_aware(func)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        try:
            return inner(*args, **kwargs)
        except ContactInputError as exc:
            # read, not popped: a kernel called inside another one with the arrays of its Series (no labels here)
            # leaves the element for the outer kernel to rename; the renamed error carries no _refusal
            refusal = getattr(exc, "_refusal", None)
            labels = _row_labels((*args, *kwargs.values()))
            if refusal is None or labels is None:
                raise
            message, flat = refusal
            row = labels[flat]
            raise ContactInputError(f"{message} (row {row})", row) from None

    return wrapper


def _ball_refusal(d_w):
    """(bad, message template, values) of a check: the kernels raise on the first bad element
    (:func:`_refuse`), :func:`minimum_axial_load_rows` tells each bad row."""
    return d_w <= 0, "d_w = {d_w:g} mm: the ball diameter must be positive", {"d_w": d_w}


def _check_ball(d_w):
    bad, template, values = _ball_refusal(d_w)
    _refuse(bad, template, **values)


def _check_groove_sum(r_i, r_o, d_w):
    total = r_i + r_o
    _refuse(total <= d_w,
            "impossible geometry: r_i + r_o = {total:g} mm must exceed d_w = {d_w:g} mm",
            total=total, d_w=d_w)


def _check_grooves(r_i, r_o, d_w):
    _check_groove_sum(r_i, r_o, d_w)
    half = d_w / 2.0
    _refuse(r_i <= half,
            "impossible geometry: r_i = {r:g} mm must exceed d_w/2 = {half:g} mm (groove narrower than the ball)",
            r=r_i, half=half)
    _refuse(r_o <= half,
            "impossible geometry: r_o = {r:g} mm must exceed d_w/2 = {half:g} mm (groove narrower than the ball)",
            r=r_o, half=half)


def _pitch_refusal(d_m, d_w, name="d_m"):
    return (d_m <= d_w, "impossible geometry: pitch diameter " + name + " = {d_m:g} mm must exceed d_w = {d_w:g} mm",
            {"d_m": d_m, "d_w": d_w})


def _check_pitch(d_m, d_w, name="d_m"):
    bad, template, values = _pitch_refusal(d_m, d_w, name)
    _refuse(bad, template, **values)


def _check_alpha0(alpha0):
    _refuse((alpha0 < 0) | (alpha0 >= 90),
            "alpha0 = {a:g} deg must lie in [0, 90) deg", a=alpha0)


def _check_working_angle(alpha, alpha0):
    """α0 ≤ α < 90°: the working angle under an axial load (Zaitsev & Voronkin, p. 2) is turned up from α0."""
    _check_alpha0(alpha0)
    _refuse((alpha < alpha0) | (alpha >= 90),
            "alpha = {a:g} deg must lie in [alpha0, 90) deg = [{a0:g}, 90) deg", a=alpha, a0=alpha0)


def _balls_refusal(z):
    return (z < 1) | (z != np.round(z)), "z = {z:g}: the number of balls must be a whole number of at least 1", {"z": z}


def _check_balls(z):
    bad, template, values = _balls_refusal(z)
    _refuse(bad, template, **values)


#: Largest load ratio Fa/C* the working angle is solved for: the angle is then within 0.01 deg of 90 deg (at
#: alpha0 = 0: 89.994 deg), far past the Hertz contact of Zaitsev & Voronkin; above about 1e24 the residual of
#: the angle equation no longer changes sign below 90 deg in floating point.
LOAD_RATIO_MAX = 1e6


def _check_load(Fa, C_star):
    _refuse(Fa < 0, "Fa = {Fa:g} N: the axial load must not be negative", Fa=Fa)
    _refuse(np.isinf(Fa), "Fa = {Fa:g} N: the axial load must be finite", Fa=Fa)
    _refuse(C_star <= 0, "C_star = {C:g} N: the stiffness characteristic must be positive", C=C_star)
    _refuse(np.isinf(C_star), "C_star = {C:g} N: the stiffness characteristic must be finite", C=C_star)
    with np.errstate(invalid="ignore"):
        ratio = Fa / C_star
    _refuse(ratio > LOAD_RATIO_MAX,
            "Fa = {Fa:g} N with C_star = {C:g} N: Fa/C_star = {ratio:g} must lie in [0, " + f"{LOAD_RATIO_MAX:g}"
            + "] (the working angle is then within 0.01 deg of 90 deg)", Fa=Fa, C=C_star, ratio=ratio)


def _check_outer_groove(d_w, d_m, alpha0, r_o):
    """cos τ_o >= 0 (Zaitsev & Voronkin, p. 2): 1/f_o >= 2γ/(1 + γ), that is r_o no larger than the outer raceway's
    radius in the rolling direction, (d_m + d_w·cos α0)/(2·cos α0): the groove must curve across at least as much
    as the race curves along (otherwise the principal planes of the contact swap and F(ρ) < 0)."""
    cos0 = np.cos(np.radians(alpha0))
    with np.errstate(divide="ignore"):
        race = (d_m + d_w * cos0) / (2.0 * cos0)
    _refuse(r_o > race * (1.0 + 1e-12),
            "impossible geometry: r_o = {r:g} mm must not exceed (d_m + d_w*cos(alpha0))/(2*cos(alpha0)) = {race:g} mm"
            " with d_w = {d_w:g} mm, d_m = {d_m:g} mm, alpha0 = {a:g} deg (the outer groove would be flatter "
            "across than the race is along it)", r=r_o, race=race, d_w=d_w, d_m=d_m, a=alpha0)


def _check_deflection_coefficients(inner, outer):
    """2K/(μπ) of a Hertz contact lies in (0, 1]: 1 for a circle (κ = 1), falling towards 0 as the ellipse lengthens."""
    for side, value in (("inner", inner), ("outer", outer)):
        value = np.asarray(value, dtype=float)
        _refuse(~((value > 0) & (value <= 1)) & ~np.isnan(value),
                "deflection_coefficients: " + side + " 2K/(mu*pi) = {c:g} must lie in (0, 1] "
                "(1 for a circular contact, falling towards 0 as the contact ellipse lengthens)", c=value)


SERIES_ALPHA0_MIN = 0.5
"""Smallest initial angle α0 [deg] of the series method
(:func:`~bearingheat.kernels.contact.working_contact_angle_series`)."""

SERIES_LOAD_RATIO_MAX = 0.01
"""Largest Fa/C* of the series method: x = α − α0 is the paper's small parameter; up to here its Newton steps
converge from α0 = 0.5° on (tests), beyond it they can leave [α0, 90°)."""

SERIES_TOLERANCE_RAD = 1e-12
"""The series method stops when a Newton step of x is at most this [rad] (2e-7 arc seconds)."""

SERIES_MAX_NEWTON_STEPS = 20
"""Cap of the Newton steps of the series method (its range needs at most eight)."""


def _check_series_range(Fa, C_star, alpha0):
    """The range of the series method of :mod:`bearingheat.kernels.contact` (α0 = 0 is refused before)."""
    _refuse(alpha0 < SERIES_ALPHA0_MIN,
            "alpha0 = {a:g} deg: the series method of Zaitsev & Voronkin is used from alpha0 = "
            f"{SERIES_ALPHA0_MIN:g}" + " deg on (below it its Newton steps can leave [alpha0, 90) deg); "
            "use working_contact_angle", a=alpha0)
    with np.errstate(invalid="ignore"):
        ratio = Fa / C_star
    _refuse(ratio > SERIES_LOAD_RATIO_MAX,
            "Fa = {Fa:g} N with C_star = {C:g} N: Fa/C_star = {ratio:g}; the series method of Zaitsev & Voronkin "
            f"(a small x = alpha - alpha0) is used up to Fa/C_star = {SERIES_LOAD_RATIO_MAX:g} (beyond it its "
            "Newton steps can leave [alpha0, 90) deg); use working_contact_angle", Fa=Fa, C=C_star, ratio=ratio)
