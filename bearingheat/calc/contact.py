"""calc extension ``contact``: the minimum axial load of ball bearings (Zaitsev & Voronkin) for rows with ball geometry.

Optional calc inputs ``z``, ``Dw [mm]`` and ``dm_pitch [mm]`` (number of
balls, ball diameter, pitch diameter) with the contact angle ``alpha [deg]``
(or the nominal angle of the designation, e.g. 40° for 72..-B) give the
output column ``Fa_min [N]``; a row whose Fa is below it at its speed gets
a warning: the balls may skid (Zaitsev & Voronkin, p. 1). The formula is the kernel
:func:`bearingheat.kernels.contact.minimum_axial_load`.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.contract import columns
from bearingheat.calc.models import failed_rows
from bearingheat.calc.supports import text_codes
from bearingheat.catalogue.designation import parse_designation
from bearingheat.errors import DesignationError

__all__ = ["prepare", "extend"]

#: the contract inputs of the extension (owner "contact")
_GEOMETRY = columns(owner="contact", kind="input")  # z, Dw, dm_pitch


def prepare(frame: pd.DataFrame):
    """Nothing to do before the friction model: the frame unchanged, no problems."""
    return frame, []


def _nominal_angle(designation) -> float:
    if not isinstance(designation, str):
        return np.nan
    try:
        angle = parse_designation(designation).contact_angle
    except DesignationError:
        return np.nan
    return np.nan if angle is None else angle


def _misfits(z: np.ndarray, dw: np.ndarray, pitch: np.ndarray, d: np.ndarray, D: np.ndarray) -> np.ndarray:
    """Per row why its balls cannot sit in its bearing ('' where they can): the pitch circle lies between the bore d
    and the outside diameter D, a ball fits into the section (D - d)/2 between them, and z balls side by side
    around the pitch circle need Dw <= dm_pitch*sin(180°/z) (two neighbours touch there)."""
    reasons = np.full(len(z), "", dtype=object)
    with np.errstate(invalid="ignore"):
        widest = np.where(z >= 2, pitch * np.sin(np.pi / np.maximum(z, 2)), np.inf)
        checks = ((~((d < pitch) & (pitch < D)) & ~np.isnan(pitch),
                   lambda i: f"dm_pitch = {pitch[i]:g} mm must lie between d = {d[i]:g} mm and D = {D[i]:g} mm"),
                  (dw >= (D - d) / 2,
                   lambda i: f"Dw = {dw[i]:g} mm must be smaller than (D - d)/2 = {(D[i] - d[i]) / 2:g} mm, the "
                             "section between bore and outside diameter"),
                  (dw > widest,
                   lambda i: f"{z[i]:g} balls of Dw = {dw[i]:g} mm do not fit side by side on the pitch circle of "
                             f"dm_pitch = {pitch[i]:g} mm: at most Dw = dm_pitch*sin(180°/z) = {widest[i]:.4g} mm"))
    for bad, reason in checks:  # the first misfit of a row is its message
        for i in np.flatnonzero(bad & (reasons == "")).tolist():
            reasons[i] = reason(i)
    return reasons


def extend(frame: pd.DataFrame, results: pd.DataFrame, **compute):
    """The column ``Fa_min`` [N] of the ball bearing rows with geometry, and (row position, level, message) problems.

    No column at all when the table has no ``z``, ``Dw`` and ``dm_pitch``. The friction pass's options
    (``compute``) are not needed.
    """
    if not all(col in frame.columns for col in _GEOMETRY):
        return pd.DataFrame(index=frame.index), []
    from bearingheat.kernels.contact import minimum_axial_load_rows  # scipy (0.3 s to import): ball geometry only
    z, dw, pitch = (frame[c].to_numpy(dtype=float) for c in _GEOMETRY)
    alpha = frame["alpha"].to_numpy(dtype=float) if "alpha" in frame.columns else np.full(len(frame), np.nan)
    codes, designations = text_codes(frame, "designation")  # each distinct designation parsed once
    nominal = np.array([_nominal_angle(d) for d in designations], dtype=float)[codes]
    alpha = np.where(np.isnan(alpha), nominal, alpha)
    n = frame["n"].to_numpy(dtype=float)
    Fa = frame["Fa"].to_numpy(dtype=float) if "Fa" in frame.columns else np.zeros(len(frame))
    Fa = np.nan_to_num(Fa, nan=0.0)
    is_ball = results["bearing_type"].str.contains("ball").to_numpy()
    ok = ~failed_rows(results)
    has_geometry = ~np.isnan(z) & ~np.isnan(dw) & ~np.isnan(pitch)
    fa_min = np.full(len(frame), np.nan)
    d, D = frame["d"].to_numpy(dtype=float), frame["D"].to_numpy(dtype=float)
    misfit = _misfits(z, dw, pitch, d, D)
    checked = has_geometry & is_ball & ok & (misfit == "")
    rows = np.flatnonzero(checked & ~np.isnan(alpha))
    fa_min[rows], reasons = minimum_axial_load_rows(z[rows], dw[rows], pitch[rows], n[rows], alpha[rows])
    refused = np.zeros(len(frame), dtype=bool)
    refused[rows] = reasons != ""
    reason_of = dict(zip(rows.tolist(), reasons.tolist()))
    problems = []  # messages only for the rows that have them, in row order
    misfits = has_geometry & is_ball & ok & (misfit != "")
    for i in np.flatnonzero((checked & np.isnan(alpha)) | refused | (Fa < fa_min) | misfits).tolist():
        if misfits[i]:
            problems.append((i, "error", f"Fa_min: impossible geometry: {misfit[i]}"))
        elif np.isnan(alpha[i]):
            problems.append((i, "warning", "Fa_min: give alpha [deg] (the contact angle) to check the minimum "
                                           "axial load against ball skidding (Zaitsev & Voronkin)"))
        elif refused[i]:
            problems.append((i, "error", f"Fa_min: {reason_of[i]}"))
        else:
            problems.append((i, "warning", f"Fa = {Fa[i]:.4g} N is below the minimum axial load "
                                           f"{fa_min[i]:.4g} N at {n[i]:g} 1/min: the balls may skid (Zaitsev & Voronkin)"))
    return pd.DataFrame({"Fa_min": fa_min}, index=frame.index), problems
