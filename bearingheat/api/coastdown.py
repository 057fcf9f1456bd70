"""Coast-down analysis with pint Quantities (the TMM-7M lab sheet; the Schaeffler catalogue rolling form): the unit boundary.

Times, speeds and rig data come in as Quantities and are converted once to
the units of :mod:`bearingheat.analysis.coastdown` (t [s], n [1/min],
I [kg·m²], G [N], r [mm], ν [mm²/s], dM [mm], P [N]); the results are its
dataclasses, :class:`~bearingheat.analysis.coastdown.CoastdownResult` and
:class:`~bearingheat.analysis.coastdown.SpindleFit`.
"""
from __future__ import annotations

import enum

import numpy as np

from bearingheat.analysis.coastdown import CoastdownResult, SpindleFit, coastdown_analysis, spindle_coastdown_fit
from bearingheat.errors import CoastdownError
from bearingheat.kernels.coastdown import TMM_7M
from bearingheat.units import Quantity, magnitude, speed_rpm

__all__ = ["analyse_coastdown", "analyse_spindle_coastdown"]


class _Rig(enum.Enum):
    """The default of I, G and r: the value of the TMM-7M rig."""

    TMM_7M = "TMM-7M"

    def __repr__(self) -> str:
        return "TMM-7M"


_TMM = _Rig.TMM_7M


def _rig_value(value: Quantity | _Rig | None, default: float, unit: str, name: str) -> float | None:
    if value is _TMM:
        return default
    if value is None:
        return None
    return magnitude(value, unit, name)


def analyse_coastdown(t: Quantity, n: Quantity, *, I: Quantity | _Rig = _TMM, G: Quantity | _Rig | None = _TMM,
                      r: Quantity | _Rig | None = _TMM, window: int | None = None,
                      interval_dn: Quantity | None = None, interval_dt: Quantity | None = None,
                      interval_count: int = 10) -> CoastdownResult:
    """Coast-down analysis with pint Quantities.

    t: times (Quantity array), n: shaft speeds (1/min, rpm, Hz or rad/s).
    I, G, r default to the TMM-7M rig (2.6 kg·m², 1100 N, 25 mm); pass
    G=None, r=None when the journal load is unknown (torques only).
    interval_dn / interval_dt: interval steps for formula (2) as Quantities.

    Source: the laboratory sheet «Определение приведенного коэффициента
    трения в подшипниках скольжения методом выбега» (the TMM-7M rig): the
    equation of motion I·dω/dt = −M and its reduced friction coefficient
    f = M/(G·r), formulas (1) and (2). The resisting torque is fitted as the
    nested models M = M_c (Coulomb), + c_v·ω, + c_a·ω² by least squares on
    n(t) and chosen by cross-validation and the Bayesian information
    criterion (:func:`bearingheat.analysis.coastdown.coastdown_analysis`).

    Parameters
    ----------
    t : pint.Quantity [time]
        Sample times, a 1-D array strictly increasing, at least 10 samples.
    n : pint.Quantity [1/min]
        Shaft speeds at ``t`` (1/min, rpm, Hz or rad/s), finite and >= 0,
        falling from the first to the last sample.
    I : pint.Quantity [kg·m²], optional
        Moment of inertia about the shaft, > 0; default 2.6 kg·m² (TMM-7M).
        None is refused.
    G : pint.Quantity [force] or None, optional
        Journal load (rotor weight), > 0; default 1100 N (TMM-7M). None: no
        friction coefficient, torques only.
    r : pint.Quantity [length] or None, optional
        Journal radius, > 0; default 25 mm (TMM-7M). None: torques only.
    window : int, optional
        Savitzky-Golay window in samples for the derivative (default about
        a tenth of the samples, odd, 7 to 51).
    interval_dn : pint.Quantity [1/min], optional
        Speed step of the interval table of formula (2), > 0; give this or
        ``interval_dt``, not both.
    interval_dt : pint.Quantity [time], optional
        Time step of the interval table, > 0.
    interval_count : int, optional
        Number of intervals where neither step is given; default 10.

    Returns
    -------
    bearingheat.analysis.coastdown.CoastdownResult
        The chosen model and every fit (parameters in N·m, N·m·s, N·m·s²
        with 95 % intervals), ``f_constant`` (the source's single
        coefficient, NaN without G and r), the smoothed samples, the
        interval table, the run-down time [s] and the energies [J];
        ``rig_defaults`` names the rig values taken from the TMM-7M defaults.

    Raises
    ------
    bearingheat.errors.CoastdownError
        For a record that cannot be analysed: t and n not 1-D or of unequal
        length, fewer than 10 samples (or fewer than 4 above 2 % of the top
        speed), a non-finite time, a negative or non-finite speed, times
        that do not increase strictly, a speed that does not fall, I, G or
        r not > 0, I = None, both interval steps or a step not > 0, an
        interval_count that is not a whole number >= 1.
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension (a speed must be revolutions or radians per time).

    Examples
    --------
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
    result = coastdown_analysis(t_s, n_rpm, I_kgm2, G_n, r_mm, window=window, interval_dn=dn, interval_dt=dt,
                                interval_count=interval_count)
    result.rig_defaults = tuple(name for name, value in (("I", I), ("G", G), ("r", r)) if value is _TMM)
    return result


def analyse_spindle_coastdown(t: Quantity, n: Quantity, *, I: Quantity, nu: Quantity, dM: Quantity, bearings: int = 2,
                              P: Quantity | None = None, f0_catalogue: float | None = None) -> SpindleFit:
    """Fit the catalogue M0 + M1 form to a rolling-bearing spindle run-down, with pint Quantities.

    The torque of a shaft on z identical rolling bearings is taken in the
    form of the Schaeffler rolling bearing catalogue (Russian edition),
    chapter «Трение и нагрев» (Friction and increases in temperature),
    p. 64: M = z·(M0 + M1), M0 = f0·(ν·n)^(2/3)·dM³·1e-7 N·mm for
    ν·n >= 2000 (f0·160·dM³·1e-7 below), M1 = f1·P·dM constant during the
    run-down. f0 and M1 are fitted to n(t) by least squares, so that a
    catalogue f0 can be audited. Seals and windage are lumped into the fit.

    Parameters
    ----------
    t : pint.Quantity [time]
        Sample times, a 1-D array strictly increasing, at least 10 samples.
    n : pint.Quantity [1/min]
        Shaft speeds at ``t`` (1/min, rpm, Hz or rad/s), finite and >= 0,
        falling; ν·n must reach 2000 mm²/s·1/min.
    I : pint.Quantity [kg·m²]
        Moment of inertia of the rotor about the shaft, > 0.
    nu : pint.Quantity [mm²/s]
        Oil viscosity at the operating temperature, taken as constant; > 0.
    dM : pint.Quantity [length]
        Mean bearing diameter (d + D)/2, > 0.
    bearings : int, optional
        Number z of identical bearings on the shaft, a whole number >= 1;
        default 2.
    P : pint.Quantity [force], optional
        Bearing load, > 0; gives f1 = M1/(P·dM).
    f0_catalogue : float, optional
        The catalogue f0 to compare the fitted one with, finite and > 0.

    Returns
    -------
    bearingheat.analysis.coastdown.SpindleFit
        The fit: ``f0``, ``M1`` [N·mm] of one bearing, ``f1`` (NaN without
        P), confidence intervals in ``fit`` and ``summary()``.

    Raises
    ------
    bearingheat.errors.CoastdownError
        For a record that cannot be analysed (as for
        :func:`analyse_coastdown`), nu, dM, I, P or f0_catalogue not > 0, a number of
        bearings that is not a whole number >= 1, or a run-down whose ν·n
        stays below 2000 (M0 is then constant and cannot be told apart
        from M1).
    bearingheat.errors.UnitError
        For a plain number where a Quantity is needed, or a unit of the
        wrong dimension.

    Examples
    --------
    A synthetic run-down of a shaft on two bearings with f0 = 2 and
    M1 = 30 N·mm each:

    >>> import numpy as np
    >>> from bearingheat.kernels.coastdown import rolling_bearing_M0_schaeffler, rundown_speed
    >>> from bearingheat.units import ureg
    >>> u = ureg()
    >>> def torque(omega):  # N*m of both bearings at omega [rad/s]
    ...     return 2 * (rolling_bearing_M0_schaeffler(omega * 30 / np.pi, 20.0, 50.0, 2.0) + 30.0) / 1000
    >>> t = np.linspace(0.0, 20.0, 41)
    >>> n = rundown_speed(t, 0.0, 6000.0, torque, 0.01)
    >>> fit = analyse_spindle_coastdown(t * u.s, n * u.rpm, I=0.01 * u("kg*m^2"), nu=20 * u("mm^2/s"),
    ...                                 dM=50 * u.mm, P=1 * u.kN)
    >>> round(fit.f0, 2), round(fit.M1, 1), round(fit.f1, 5)
    (2.0, 30.0, 0.0006)
    """
    return spindle_coastdown_fit(
        np.atleast_1d(magnitude(t, "s", "t")), np.atleast_1d(speed_rpm(n, "n")), magnitude(I, "kg*m^2", "I"),
        magnitude(nu, "mm^2/s", "nu"), magnitude(dM, "mm", "dM"), bearings,
        None if P is None else magnitude(P, "N", "P"), f0_catalogue,
    )
