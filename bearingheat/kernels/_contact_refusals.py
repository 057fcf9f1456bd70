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


def _balls_refusal(z):
    return (z < 1) | (z != np.round(z)), "z = {z:g}: the number of balls must be a whole number of at least 1", {"z": z}


def _check_balls(z):
    bad, template, values = _balls_refusal(z)
    _refuse(bad, template, **values)



def _check_load(Fa, C_star):
    _refuse(Fa < 0, "Fa = {Fa:g} N: the axial load must not be negative", Fa=Fa)
    _refuse(C_star <= 0, "C_star = {C:g} N: the stiffness characteristic must be positive", C=C_star)
