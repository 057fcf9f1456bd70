"""Benchmark: M_R of 10^6 mixed operating points (issue 2).

Ways to the same numbers, timed in one run:

1. a per-row Python loop calling the same formula kernels (:mod:`bearingheat.kernels.friction`) with
   scalars, as a user would loop over operating points; timed on a sample of the points
   (its cost per point is constant) and scaled to the full count;
2. a hand-inlined per-row loop of the catalogue's formulas in plain Python floats, no checks:
   the fastest a Python loop gets, reported for honesty;
3. the array evaluation :func:`bearingheat.calc.friction.evaluate_catalogue_model` on support
   arrays (catalogue units, all input checks included);
4. the unit-aware call :func:`bearingheat.friction_torque` with pint Quantity arrays.

Targets: (3) at least 100x faster than (1); (4) within 1.2x of (3). Also timed: (5) the mixed-row path calc
takes (one table of all six types, support arrays built from its rows' keys), against (3).
The points mix six bearing types, both ν·n regimes, and radial and axial loads between each bearing's minimum
load and its C0.

    .venv/bin/python benchmarks/bench_friction.py [POINTS]     (default 10^6)
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pint

from bearingheat import friction_torque
from bearingheat.calc.friction import evaluate_catalogue_model
from bearingheat.calc.messages import Labels
from bearingheat.calc.supports import bearing_constants, build_support_arrays
from bearingheat.catalogue.bearings import bearing, minimum_loads
from bearingheat.catalogue.friction import resolve
from bearingheat.errors import DesignationError
from bearingheat.kernels import friction
from common import best_in_turns, operating_points, size_argument, verdict

# bearing, dimensions and catalogue values (d, D mm; C0 N; extras), share of the points
BEARINGS = [
    ("6205", dict(d=25.0, D=52.0, C0=7800.0), {}),
    ("NU206-E", dict(d=30.0, D=62.0, C0=36000.0), {}),
    ("30205-A", dict(d=25.0, D=52.0, C0=34500.0), dict(Y=1.6)),
    ("22210-E1", dict(d=50.0, D=90.0, C0=134000.0), dict(e=0.24, X0=1.0, Y0=2.8)),
    ("7205", dict(d=25.0, D=52.0, C0=9300.0), dict(alpha=30.0)),
    ("NA4905", dict(d=25.0, D=42.0, C0=30000.0), {}),
]


def minimum_load(designation: str) -> float:
    """The bearing table's minimum load [N] of ``designation`` (Schaeffler HR 1), 0 where it has none."""
    try:
        data = bearing(designation)
    except DesignationError:  # (22210-E1 and NA4905: not in the bearing table)
        return 0.0
    rule = minimum_loads().get(data.bearing_type)
    return getattr(data, rule.rating) / rule.divisor if rule else 0.0


def _constants(designation, dims, extras):
    const = bearing_constants(resolve(designation), "oil_bath", "single")
    axial = designation not in ("NU206-E", "NA4905")
    return const, axial


def _loop_factors(designation, dims, extras):
    """What both per-row loops take once per bearing: constants, dM, X0, Y0, Y, e (7205 at 30°: Y0 = 0.33)."""
    const, axial = _constants(designation, dims, extras)
    dM = (dims["d"] + dims["D"]) / 2
    X0 = extras.get("X0", const["X0_table"])
    Y0 = extras.get("Y0", 0.33 if designation == "7205" else const["Y0_table"])
    return const, axial, dM, X0, Y0, extras.get("Y", math.nan), extras.get("e", math.nan)


def kernel_inputs(designation, dims, extras, n, nu, Fr, Fa):
    """The support arrays of one bearing at many points (its catalogue constants stay scalars)."""
    axial = designation not in ("NU206-E", "NA4905")
    keys = pd.DataFrame({"designation": [designation], "lubrication": ["oil_bath"]})
    return build_support_arrays(keys, {"n": n, "nu": nu, "Fr": Fr, "Fa": Fa if axial else 0.0, **dims, **extras})


def kernel_loop_torque(designation, dims, extras, n, nu, Fr, Fa):
    """Per-row loop over the scalar formula kernels of bearingheat.kernels.friction."""
    const, axial, dM, X0, Y0, Y, e = _loop_factors(designation, dims, extras)
    out = []
    for ni, nui, fr, fa in zip(n.tolist(), nu.tolist(), Fr.tolist(), Fa.tolist()):
        fa = fa if axial else 0.0
        M0 = friction.speed_dependent_torque(const["f0_table"], nui, ni, dM)
        P0 = friction.static_equivalent_load(fr, fa, X0, Y0)
        ratio = P0 / dims["C0"] if const["f1_basis"] == 1 else 1.0
        f1 = friction.f1_from_load_ratio(const["f1_a"], const["f1_x"], ratio)
        if const["m1_load"] == "P1":
            load = friction.effective_load(const["p1_rule"], fr, fa, Y, e)
        else:
            load = fa if const["m1_load"] == "Fa" else fr
        out.append(friction.total_torque(M0, friction.load_dependent_torque(f1, load, dM)))
    return np.array(out)


def loop_torque(designation, dims, extras, n, nu, Fr, Fa):
    """Per-row Python loop of the catalogue formulas inlined in plain floats, with the same coefficients."""
    const, axial, dM, X0, Y0, Y, e = _loop_factors(designation, dims, extras)
    f0, a, x, basis, load_kind = (const["f0_table"], const["f1_a"], const["f1_x"], const["f1_basis"],
                                  const["m1_load"])
    rule = const["p1_rule"]
    C0 = dims["C0"]
    out = []
    for ni, nui, fr, fa in zip(n.tolist(), nu.tolist(), Fr.tolist(), Fa.tolist()):
        fa = fa if axial else 0.0
        nun = nui * ni
        M0 = f0 * (nun ** (2 / 3) if nun >= 2000 else 160.0) * dM ** 3 * 1e-7
        P0 = max(X0 * fr + Y0 * fa, fr) if fa > 0 else fr
        f1 = a * (P0 / C0) ** x if basis == 1 else a
        if load_kind == "P1":
            if rule == "radial_ball":
                P1 = 3.3 * fa - 0.1 * fr
            elif rule == "angular_single":
                P1 = fa - 0.1 * fr
            elif rule == "tapered_single":
                P1 = max(2 * Y * fa, fr)
            else:  # spherical
                P1 = 1.6 * fa / e if fa > e * fr else fr * (1 + 0.6 * (fa / (e * fr)) ** 3)
            load = max(P1, fr)
        else:
            load = fa if load_kind == "Fa" else fr
        out.append(M0 + f1 * load * dM)
    return np.array(out)


def main(points: int = 1_000_000, repeats: int = 3, loop_sample: int = 30_000) -> dict[str, float]:
    u = pint.get_application_registry()
    n, nu, Fr, Fa = operating_points(points)
    chunks = np.array_split(np.arange(points), len(BEARINGS))
    # each bearing's loads between its minimum load and its C0: operating_points draws them from 100 N to 20 kN,
    # above C0 of the 6205 and the 7205 and below the minimum load of the NU206-E (C0/60 = 600 N), where
    # friction_torque warns at each point, as calc does, and (4) would time the texts of those warnings (some
    # 600 000 above C0, 10 000 below the minimum) instead of the unit boundary
    for (designation, dims, _), idx in zip(BEARINGS, chunks):
        low, top = minimum_load(designation), min(dims["C0"], 20_000.0)
        axial_share = Fa[idx] / Fr[idx]
        Fr[idx] = low + (Fr[idx] - 100.0) / 19_900.0 * (top - low)
        Fa[idx] = Fr[idx] * axial_share
    work = [(b, idx) for b, idx in zip(BEARINGS, chunks)]

    # inputs are built before the clocks start: both calls get ready arrays (or Quantities)
    kernel_args = [kernel_inputs(des, dims, extras, n[idx], nu[idx], Fr[idx], Fa[idx])
                   for (des, dims, extras), idx in work]
    unit_args = []
    for (des, dims, extras), idx in work:
        axial = des not in ("NU206-E", "NA4905")
        unit_args.append(dict(
            designation=des, d=dims["d"] * u.mm, D=dims["D"] * u.mm, C0=dims["C0"] * u.N, lubrication="oil_bath",
            n=n[idx] * u.rpm, nu=nu[idx] * u("mm^2/s"), Fr=Fr[idx] * u.N,
            Fa=(Fa[idx] if axial else 0.0) * u.N,
            **{k: (v * u.deg if k == "alpha" else v) for k, v in extras.items()}))

    def run_kernel():
        total = []
        for a in kernel_args:
            with np.errstate(all="ignore"):
                results, problems = evaluate_catalogue_model(a, Labels())
            assert not [p for p in problems if p.level == "error"]
            total.append(results["MR"])
        return np.concatenate(total)

    def run_units():
        return np.concatenate([friction_torque(**kw).MR.magnitude for kw in unit_args])

    def run_loop():
        return np.concatenate([loop_torque(des, dims, extras, n[idx], nu[idx], Fr[idx], Fa[idx])
                               for (des, dims, extras), idx in work])

    sample = min(loop_sample, points)
    every = max(1, points // sample)

    def run_kernel_loop():
        return np.concatenate([kernel_loop_torque(des, dims, extras, n[idx[::every]], nu[idx[::every]],
                                                  Fr[idx[::every]], Fa[idx[::every]])
                               for (des, dims, extras), idx in work])

    # the mixed-row path calc takes: one table of all six types, its support arrays built from the rows' keys
    order = np.concatenate([idx for _, idx in work])
    keys = pd.DataFrame({"designation": np.concatenate([[des] * len(idx) for (des, _, _), idx in work]),
                         "lubrication": "oil_bath"})
    mixed_numbers = {"n": n[order], "nu": nu[order], "Fr": Fr[order],
                     "Fa": np.concatenate([Fa[idx] if des not in ("NU206-E", "NA4905") else 0.0 * Fa[idx]
                                           for (des, _, _), idx in work])}
    for name in ("d", "D", "C0", "Y", "e", "X0", "Y0", "alpha"):
        mixed_numbers[name] = np.concatenate([np.full(len(idx), {**dims, **extras}.get(name, np.nan))
                                              for (_, dims, extras), idx in work])

    def run_mixed():
        supports = build_support_arrays(keys, mixed_numbers)
        with np.errstate(all="ignore"):
            results, problems = evaluate_catalogue_model(supports, Labels())
        assert not [p for p in problems if p.level == "error"]
        return results["MR"]

    # the array model and every way compared with it run in turns, the shortest of each counts (the machine's
    # speed comes and goes; a loop timed once at a slow moment made its ratio half as large again)
    timed = best_in_turns({"kernel": run_kernel, "mixed": run_mixed, "units": run_units, "loop": run_loop,
                           "kernel_loop": run_kernel_loop}, repeats)
    (t_kernel, m_kernel), (t_mixed, m_mixed), (t_units, m_units) = timed["kernel"], timed["mixed"], timed["units"]
    t_loop, m_loop = timed["loop"]
    sampled = sum(len(idx[::every]) for _, idx in work)
    t_kernel_loop, m_kernel_loop = timed["kernel_loop"][0] * points / sampled, timed["kernel_loop"][1]
    np.testing.assert_allclose(m_mixed, m_kernel, rtol=1e-12)
    np.testing.assert_allclose(m_units, m_kernel, rtol=1e-12)
    np.testing.assert_allclose(m_loop, m_kernel, rtol=1e-12)
    np.testing.assert_allclose(m_kernel_loop, np.concatenate([m_kernel[idx[::every]] for _, idx in work]),
                               rtol=1e-12)
    figures = {"points": points, "kernel_loop_s": t_kernel_loop, "inline_loop_s": t_loop, "kernel_s": t_kernel,
               "units_s": t_units, "kernel_speedup": t_kernel_loop / t_kernel,
               "inline_speedup": t_loop / t_kernel, "units_over_kernel": t_units / t_kernel, "mixed_s": t_mixed,
               "mixed_over_kernel": t_mixed / t_kernel}
    print(f"friction M_R, {points:,} mixed points ({len(BEARINGS)} bearing types, both regimes)")
    print(f"  per-row loop over the kernels : {t_kernel_loop:8.3f} s   (timed on {sampled:,} points, scaled)")
    print(f"  per-row loop, inlined floats  : {t_loop:8.3f} s")
    print(f"  array model per bearing type  : {t_kernel:8.3f} s   (the per-type fast path, with checks)")
    print(f"    vs the per-row kernel loop  : {figures['kernel_speedup']:.0f}x faster "
          f"({verdict(figures['kernel_speedup'], 100, at_most=False)})")
    print(f"    vs the inlined float loop   : {figures['inline_speedup']:.1f}x faster (no target; the honest loop)")
    print(f"  mixed rows, as calc gets them : {t_mixed:8.3f} s   (one table of all types, support arrays built "
          f"from its keys: {figures['mixed_over_kernel']:.2f}x the per-type path; no target)")
    print(f"  unit-aware API                : {t_units:8.3f} s   ({figures['units_over_kernel']:.2f}x the per-type "
          f"path; {verdict(figures['units_over_kernel'], 1.2)})")
    return figures


if __name__ == "__main__":
    main(size_argument(1_000_000, 1_000_000))
