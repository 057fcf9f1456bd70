"""The catalogue friction model of Schaeffler's "Friction and heating" chapter over support arrays.

The model's evaluation for the friction-model registry (:mod:`bearingheat.calc.models`):
coefficients come from :mod:`bearingheat.catalogue.friction` (built into
:class:`~bearingheat.calc.supports.SupportArrays`), the torques from
:mod:`bearingheat.kernels.friction`; this module holds the checks and the
order in which the kernels are applied, and no formula of its own.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from bearingheat.calc.messages import Labels, Problem, at
from bearingheat.calc.supports import SupportArrays, text_in
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.catalogue.contact import TABLE_SOURCES, y0_for_contact_angle
from bearingheat.kernels import friction

__all__ = ["RESULTS", "EXCEL_FORMULAS", "P1_EXCEL", "F0_EXCEL", "F1_EXCEL", "evaluate_catalogue_model",
           "catalogue_model_at_viscosity"]

#: the results of the catalogue model, in the order calc writes them
RESULTS = ("f0", "f1", "P0", "P1", "M0", "M1", "M2", "MR", "NR")

#: live Excel formulas of the model's results (the Schaeffler catalogue, pp. 64-69) in catalogue units. The placeholders are
#: cell references or numbers: {f0}, {f1}, {f2}, {M0}, {M1}, {M2}, {MR} on the results sheet, {n}, {nu}, {Fa}
#: and {load} (Fr, Fa or the P1 cell) scaled from the user's units, {dM} = ((d + D)/2), {bearings} '' or '2*'
#: (a paired row: M0 of both bearings).
EXCEL_FORMULAS = {
    "M0": f"={{bearings}}{{f0}}*IF({{nu}}*{{n}}>={friction.REGIME_LIMIT:g},({{nu}}*{{n}})^(2/3),{friction.LOW_REGIME_FACTOR:g})"
          "*{dM}^3*1E-07",
    "P0": "=IF({Fa}>0,MAX(IFERROR({X0}*{Fr}+{Y0}*{Fa},{Fr}),{Fr}),{Fr})",  # fmax: no X0, Y0 gives Fr
    "P1": "=MAX({p1_rule},{Fr})",
    "M1": "={f1}*{load}*{dM}",
    "M2": "={f2}*{Fa}*{dM}",
    "MR": "={M0}+{M1}+{M2}",
    "NR": "={MR}*{n}/9550",
}
#: f0 by its basis (the Schaeffler catalogue, p. 66): {value} is the table value for the row's lubrication, {B} and {d} in mm
F0_EXCEL = {"constant": "{value}", "B/(33+d)": "{value}*{B}/(33+{d})"}
#: f1 = a*ratio^x by its basis (the Schaeffler catalogue, pp. 66-68); x = 0 is the constant a
F1_EXCEL = {"constant": "{a}", "P0/C0": "{a}*({P0}/{C0})^{x}", "Fa/C0": "{a}*({Fa}/{C0})^{x}"}
#: P1 rule of the Schaeffler catalogue p. 68 -> Excel expression before the "P1 >= Fr" rule (names as in friction.P1_RULES)
P1_EXCEL = {
    "radial_ball": "3.3*{Fa}-0.1*{Fr}",
    "angular_single": "{Fa}-0.1*{Fr}",
    "angular_paired": "1.4*{Fa}-0.1*{Fr}",
    "angular_double_row": "1.4*{Fa}-0.1*{Fr}",
    "four_point": "1.5*{Fa}+3.6*{Fr}",
    "tapered_single": "IF({Fa}>0,2*{Y}*{Fa},{Fr})",
    "tapered_paired": "IF({Fa}>0,1.21*{Y}*{Fa},{Fr})",
    "spherical": "IF({Fa}<=0,{Fr},IF(OR({Fr}<=0,{Fa}>{e}*{Fr}),1.6*{Fa}/{e},{Fr}*(1+0.6*({Fa}/({e}*{Fr}))^3)))",
}


def evaluate_catalogue_model(s: SupportArrays, labels: Labels, f2_chart: F2Chart | None = None):
    """The catalogue model (the Schaeffler catalogue, pp. 64-70) on support arrays: checks, then the kernels.

    ``s`` holds the inputs (NaN for 'not given') and the row constants of
    :func:`bearingheat.calc.supports.bearing_constants`, as per-row arrays
    (many bearings) or scalars (one bearing, many operating points).
    Returns (results, problems): every result is an array of the rows'
    length in catalogue units; problems name the rows that fail a check.
    """
    n_rows = len(s.n)  # the operating speed spans the rows; other inputs are arrays of that length or scalars
    shape = (n_rows,)
    problems: list[Problem] = []

    def add(mask, level, message, column=""):
        mask = np.broadcast_to(np.asarray(mask, dtype=bool), shape)
        if mask.any():
            problems.append(Problem(mask, level, message, column))

    def value_of(col, i):
        return labels.value(col, at(getattr(s, col), i))

    def bad_value(col, condition_text, mask):
        add(mask, "error", lambda i, c=col: f"{labels.name(c, i)}: {value_of(c, i)} {condition_text}")

    def missing(col, why, mask):
        add(mask, "error", lambda i, c=col: f"{labels.name(c, i)}: missing; {why(i)}", col)

    def label(i):
        return at(s.label, i)

    d, D, n, nu, Fr, Fa = s.d, s.D, s.n, s.nu, s.Fr, s.Fa
    # --- geometry and operating point (the Schaeffler catalogue, p. 64: units and ranges of the formulas)
    missing("d", lambda i: "the bore d gives dM = (d + D)/2", np.isnan(d))
    bad_value("d", "must be > 0", d <= 0)
    missing("D", lambda i: "the outside diameter D gives dM = (d + D)/2", np.isnan(D))
    add(~np.isnan(D) & ~np.isnan(d) & (D <= d) & (d > 0), "error",
        lambda i: f"{labels.name('D', i)}: {value_of('D', i)} must be larger than "
                  f"{labels.name('d', i)} = {value_of('d', i)}")
    missing("n", lambda i: "the operating speed is needed", np.isnan(n))
    bad_value("n", "must be >= 0 (speed magnitude)", n < 0)
    missing("nu", lambda i: "the operating viscosity (base oil viscosity for grease) is needed", np.isnan(nu))
    bad_value("nu", "must be > 0", nu <= 0)
    bad_value("Fr", "must be >= 0", Fr < 0)
    bad_value("Fa", "must be >= 0", Fa < 0)
    for col in ("f0", "f1", "f2", "X0", "Y0"):  # (a negative X0 or Y0 would hide behind P0 = max(..., Fr))
        bad_value(col, "must be >= 0", getattr(s, col) < 0)

    # --- f0: user value, or the table column of the lubrication (needle formulas need B)
    f0_given = ~np.isnan(s.f0)
    needle_formula = np.equal(s.f0_basis, "B/(33+d)") & ~f0_given
    missing("B", lambda i: f"f0 of {label(i)} is value*B/(33+d) (the Schaeffler catalogue, p. 66)", needle_formula & np.isnan(s.B))
    bad_value("B", "must be > 0", s.B <= 0)
    f0 = np.where(f0_given, s.f0, s.f0_table)
    if np.any(needle_formula):
        f0 = np.where(needle_formula, friction.f0_needle(s.f0_table, s.B, d), f0)

    # --- P0 (only where f1 depends on P0/C0 and there is axial load)
    f1_given = ~np.isnan(s.f1)
    f1_basis = s.f1_basis
    needs_c0 = (f1_basis > 0) & ~f1_given
    missing("C0", lambda i: f"f1 of {label(i)} depends on "
                            f"{'P0/C0' if at(f1_basis, i) == 1 else 'Fa/C0'} (the Schaeffler catalogue, pp. 66-68)",
            needs_c0 & np.isnan(s.C0))
    bad_value("C0", "must be > 0", s.C0 <= 0)
    X0 = np.broadcast_to(np.where(np.isnan(s.X0), s.X0_table, s.X0), shape)
    Y0 = np.broadcast_to(np.where(np.isnan(s.Y0), s.Y0_table, s.Y0), shape)
    Y0, angle_reported = _angular_contact_y0(s, Y0, add, shape)
    needs_p0 = (f1_basis == 1) & ~f1_given & (Fa > 0)
    angular = np.equal(s.bearing_type, "angular_contact_ball")
    for col, values in (("X0", X0), ("Y0", Y0)):
        missing(col, lambda i, c=col: f"P0 of {label(i)} under axial load needs the catalogue value {c}"
                                      + (f" or the contact angle alpha ({TABLE_SOURCES})"
                                         if at(angular, i) else " (the DP11A manual, table 1 has none for this type)"),
                needs_p0 & np.isnan(values) & ~angle_reported)
    P0 = friction.static_equivalent_load(Fr, Fa, X0, Y0)

    # --- P1 rules (the Schaeffler catalogue, p. 68): tapered needs Y, spherical needs e
    rules = s.p1_rule
    is_p1 = np.equal(s.m1_load, "P1") & np.not_equal(rules, "")
    for col, rule_names in (("Y", ("tapered_single", "tapered_paired")), ("e", ("spherical",))):
        wanted = text_in(rules, rule_names) & (Fa > 0)
        missing(col, lambda i, c=col: f"P1 of {label(i)} under axial load needs the catalogue value {c} "
                                      "(the Schaeffler catalogue, p. 68)", wanted & np.isnan(getattr(s, col)))
        bad_value(col, "must be > 0", getattr(s, col) <= 0)
    if np.ndim(rules) == 0:
        P1 = (friction.effective_load(rules, Fr, Fa, s.Y, s.e) if is_p1 else np.full(shape, np.nan))
    else:
        P1 = np.full(shape, np.nan)
        if is_p1.any():
            Y, e = (np.broadcast_to(getattr(s, c), shape) for c in ("Y", "e"))
            # the rows of each rule together (the kernel's own loop over rule names, without a text per row)
            codes, names = (rules.codes, rules.categories) if isinstance(rules, pd.Categorical) \
                else pd.factorize(np.asarray(rules, dtype=object))
            for code, name in enumerate(names):
                rows = is_p1 & (codes == code)
                count = np.count_nonzero(rows)
                if count * 5 > n_rows:  # a rule of many rows: on all rows, kept where it applies (no gathering)
                    np.copyto(P1, friction.effective_load(name, Fr, Fa, Y, e), where=rows)
                elif count:
                    P1[rows] = friction.effective_load(name, Fr[rows], Fa[rows], Y[rows], e[rows])
    load = np.where(np.equal(s.m1_load, "Fa"), Fa, np.where(is_p1, P1, Fr))

    # --- f1
    ratio = np.where(f1_basis == 1, P0 / s.C0, np.where(f1_basis == 2, Fa / s.C0, 1.0))
    f1 = np.where(f1_given, s.f1, friction.f1_from_load_ratio(s.f1_a, s.f1_x, ratio))

    # --- axial load on cylindrical roller bearings (the Schaeffler catalogue, p. 69)
    add(s.no_axial & (Fa > 0), "error",
        lambda i: f"{labels.name('Fa', i)}: {value_of('Fa', i)} on {at(s.prefix, i)} {label(i)}: "
                  "one ring has no ribs, the bearing takes no axial load")
    # --- radial load on thrust ball and thrust roller bearings: they support axial loads only (M1 takes Fa)
    add(text_in(s.bearing_type, ("thrust_ball", "thrust_roller")) & (Fr > 0), "error",
        lambda i: f"{labels.name('Fr', i)}: {value_of('Fr', i)} on {label(i)}: thrust ball and thrust roller "
                  "bearings take no radial load (their M1 is f1*Fa*dM)")
    m2_rows = np.broadcast_to(s.m2 & (Fa > 0), shape)
    dM = friction.mean_diameter(d, D)
    # without M2 rows: scalars, spread to the rows as read-only views at the end (no memory per row)
    f2: np.ndarray | float = 0.0
    Fa_over_A: np.ndarray | float = np.nan
    nu_n_dM: np.ndarray | float = np.nan
    if m2_rows.any():
        add(m2_rows & (Fr <= 0), "error",
            lambda i: f"{labels.name('Fa', i)}: {value_of('Fa', i)} without radial load on {label(i)}: "
                      "axially loaded cylindrical roller bearings need Fr > 0 (the Schaeffler catalogue, p. 69)")
        fa_fr = Fa / Fr
        add(m2_rows & (Fr > 0) & (fa_fr > 0.4), "warning",
            lambda i: f"Fa/Fr = {at(fa_fr, i):.3g} is above 0.4: M2 is uncertain there (bearingheat's caution for "
                      "cylindrical roller bearings; the Schaeffler catalogue, p. 69, prints no limit)")
        A = friction.axial_load_parameter(s.kB, dM)
        Fa_over_A = np.where(m2_rows, Fa / A, np.nan)
        nu_n_dM = np.where(m2_rows, nu * n * dM, np.nan)
        f2 = np.where(m2_rows, s.f2, 0.0)
        need_f2 = m2_rows & np.isnan(f2)
        if f2_chart is not None and need_f2.any():
            no_kb = need_f2 & np.isnan(s.kB)
            missing("kB", lambda i: f"{label(i)} has no kB in the Schaeffler catalogue p. 70, so Fa/A for the f2 chart is "
                                    "unknown; give f2", no_kb)
            rows = np.flatnonzero(need_f2 & ~no_kb & ~np.isnan(nu_n_dM))  # (no nu or n: their own error)
            chart_f2, reasons = f2_chart.lookup(Fa_over_A[rows], nu_n_dM[rows])
            f2[rows] = chart_f2
            refused = np.zeros(shape, dtype=bool)
            refused[rows] = reasons != ""
            reason_of = dict(zip(rows.tolist(), reasons.tolist()))
            add(refused, "error", lambda i: f"f2: {reason_of[i]}")
        elif need_f2.any():
            add(need_f2, "error",
                lambda i: f"f2: missing; {label(i)} carries Fa, so M2 = f2*Fa*dM needs f2: give f2, or a "
                          "digitised f2 chart (f2_chart; --f2-chart on the command line); read it at "
                          f"Fa/A = {Fa_over_A[i]:.4g}, nu*n*dM = {nu_n_dM[i]:.4g} mm^3/(s*min) "
                          "(the Schaeffler catalogue, p. 70, figs. 3 and 4)")
    add(np.equal(s.seal, "contact"), "warning",
        lambda i: "contact seals: their friction comes on top of the catalogue model (the Schaeffler catalogue, p. 63, "
                  "lists seal friction among the components; its formulas have no term for it)")

    M0 = s.bearings * friction.speed_dependent_torque(f0, nu, n, dM)  # a pair: both bearings (see supports)
    M1 = friction.load_dependent_torque(f1, load, dM)
    M2 = friction.axial_load_torque(f2, Fa, dM)
    MR = friction.total_torque(M0, M1, M2)
    results = {
        "f0": f0, "f1": f1, "P0": P0, "P1": P1, "M0": M0, "M1": M1, "M2": M2, "MR": MR,
        "NR": friction.power_loss(MR, n), "Fa_over_A": Fa_over_A, "nu_n_dM": nu_n_dM,
    }
    return {k: v if np.shape(v) == shape else np.broadcast_to(np.asarray(v, dtype=float), shape)
            for k, v in results.items()}, problems


def catalogue_model_at_viscosity(s: SupportArrays, results: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """M0, MR and NR of the catalogue model at the viscosity ``s.nu``, from the results of an evaluation at
    another viscosity (:func:`evaluate_catalogue_model`) of rows without M2.

    Only M0 depends on ν (the Schaeffler catalogue, p. 64: M0 = f0·(ν·n)^(2/3)·dM³·10⁻⁷); f0, M1 and the checks
    do not. M2 does where f2 is read off the chart at ν·n·dM (p. 70): rows with M2 are evaluated again instead.
    The same kernels as :func:`evaluate_catalogue_model`, so the numbers are those of a new evaluation.
    """
    M0 = s.bearings * friction.speed_dependent_torque(results["f0"], s.nu, s.n, friction.mean_diameter(s.d, s.D))
    MR = friction.total_torque(M0, results["M1"], results["M2"])
    return {"M0": M0, "MR": MR, "NR": friction.power_loss(MR, s.n)}


def _angular_contact_y0(s, Y0, add, shape):
    """Y0 of single row angular contact ball bearings from the contact angle (the DP11A manual, table 1)."""
    rows = np.broadcast_to(np.equal(s.bearing_type, "angular_contact_ball") & np.isnan(s.Y0)
                           & (s.Fa > 0), shape)
    reported = np.zeros(shape, dtype=bool)
    if not rows.any():
        return Y0, reported
    angle = np.broadcast_to(np.where(np.isnan(s.alpha), np.asarray(s.contact_angle, dtype=float),
                                     s.alpha), shape)
    Y0 = np.array(Y0, dtype=float)
    wanted = rows & ~np.isnan(angle)
    unique_angles, inverse = np.unique(angle[wanted], return_inverse=True)
    rows_at = np.flatnonzero(wanted)
    for k, alpha in enumerate(unique_angles):
        these = rows_at[inverse == k]
        try:
            Y0[these] = y0_for_contact_angle(alpha)
        except ValueError as exc:
            mask = np.zeros(shape, dtype=bool)
            mask[these] = True
            reported |= mask
            add(mask, "error", lambda j, text=str(exc): f"Y0: missing; {text}; give Y0 from the catalogue")
    return Y0, reported
