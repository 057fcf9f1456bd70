"""Coast-down analysis with pint Quantities (seed 003; the seed 002 rolling form): the unit boundary.

Times, speeds and rig data come in as Quantities and are converted once to
the units of :mod:`bearingheat.analysis.coastdown` (t [s], n [1/min],
I [kg·m²], G [N], r [mm], ν [mm²/s], dM [mm], P [N]); the results are its
dataclasses, :class:`~bearingheat.analysis.coastdown.CoastdownResult` and
:class:`~bearingheat.analysis.coastdown.SpindleFit`.
"""
from __future__ import annotations

import numpy as np

from bearingheat.analysis.coastdown import CoastdownResult, SpindleFit, coastdown_analysis, spindle_coastdown_fit
from bearingheat.errors import CoastdownError
from bearingheat.kernels.coastdown import TMM_7M
from bearingheat.units import magnitude, speed_rpm

__all__ = ["analyse_coastdown", "analyse_spindle_coastdown"]

_TMM = object()


def _rig_value(value, default, unit, name):
    if value is _TMM:
        return default
    if value is None:
        return None
    return magnitude(value, unit, name)


def analyse_coastdown(t, n, *, I=_TMM, G=_TMM, r=_TMM, window=None, interval_dn=None, interval_dt=None,
                      interval_count=10) -> CoastdownResult:
    """Coast-down analysis with pint Quantities (seed 003).

    t: times (Quantity array), n: shaft speeds (1/min, rpm, Hz or rad/s).
    I, G, r default to the TMM-7M rig (2.6 kg·m², 1100 N, 25 mm); pass
    G=None, r=None when the journal load is unknown (torques only).
    interval_dn / interval_dt: interval steps for formula (2) as Quantities.

    >>> import numpy as np
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> t = np.arange(0.0, 61.0, 2.0)
    >>> n = 600.0 - 10.0 * t                    # straight line: 10 1/min per second
    >>> result = analyse_coastdown(t * u.s, n * u.rpm)
    >>> result.model, round(result.f_constant, 4)
    ('coulomb', 0.099)
    """
    t_s = np.atleast_1d(magnitude(t, "s", "t"))
    n_rpm = np.atleast_1d(speed_rpm(n, "n"))
    I_kgm2 = _rig_value(I, TMM_7M["I"], "kg*m^2", "I")
    if I_kgm2 is None:
        raise CoastdownError("coast-down: I is required (moment of inertia about the shaft, kg*m^2)")
    G_n = _rig_value(G, TMM_7M["G"], "N", "G")
    r_mm = _rig_value(r, TMM_7M["r"], "mm", "r")
    dn = None if interval_dn is None else float(speed_rpm(interval_dn, "interval_dn"))
    dt = None if interval_dt is None else float(magnitude(interval_dt, "s", "interval_dt"))
    return coastdown_analysis(t_s, n_rpm, I_kgm2, G_n, r_mm, window=window, interval_dn=dn, interval_dt=dt,
                              interval_count=interval_count)


def analyse_spindle_coastdown(t, n, *, I, nu, dM, bearings=2, P=None, f0_catalogue=None) -> SpindleFit:
    """Fit the seed 002 M0 + M1 form to a rolling-bearing spindle run-down, with pint Quantities."""
    return spindle_coastdown_fit(
        np.atleast_1d(magnitude(t, "s", "t")), np.atleast_1d(speed_rpm(n, "n")), magnitude(I, "kg*m^2", "I"),
        magnitude(nu, "mm^2/s", "nu"), magnitude(dM, "mm", "dM"), bearings,
        None if P is None else magnitude(P, "N", "P"), f0_catalogue,
    )
