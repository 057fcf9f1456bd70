"""Benchmark: the SKF friction model on 10^6 mixed operating points against the catalogue model (issue 14).

Timed in one run on the same points:

1. the catalogue model's array kernel :func:`bearingheat.kernels.friction.catalogue_friction_torque`
   (coefficients resolved, M_R = M0 + M1);
2. the SKF model's array kernel :func:`bearingheat.kernels.skf.skf_friction_torque`
   (constants resolved, M = φish·φrs·Mrr + Msl from the loads, speed and viscosity);
3. both models' evaluations over support arrays with every input check
   (:func:`bearingheat.calc.friction.evaluate_catalogue_model`,
   :func:`bearingheat.calc.skf.evaluate_skf_model`; one bearing at many points per call, as the API does).

Target: (2) within 3x of (1). The points mix six bearing types (the SKF rows use six
different formula families), n in 10..10 000 1/min, ν in 2..300 mm²/s, loads up to 20 kN.
The SKF kernel is checked against the composition of the per-formula kernels.

    .venv/bin/python benchmarks/bench_skf.py [POINTS]
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from bearingheat.calc.friction import evaluate_catalogue_model
from bearingheat.calc.messages import Labels
from bearingheat.calc.skf import evaluate_skf_model
from bearingheat.calc.supports import build_support_arrays
from bearingheat.catalogue import skf as skf_catalogue
from bearingheat.kernels import friction, skf
from common import best_of, operating_points, size_argument, verdict

# SKF designation, catalogue-model designation, dimensions and catalogue values (d, D mm; C0 N; Y)
BEARINGS = [
    ("6205", "6205", dict(d=25.0, D=52.0, C0=7800.0)),
    ("NU 206 ECP", "NU206-E", dict(d=30.0, D=62.0, C0=36000.0)),
    ("30205", "30205-A", dict(d=25.0, D=52.0, C0=34500.0, Y=1.6)),
    ("22210 E", "22210-E1", dict(d=50.0, D=90.0, C0=134000.0, e=0.24, X0=1.0, Y0=2.8)),
    ("7205 BE", "7205", dict(d=25.0, D=52.0, C0=9300.0, alpha=30.0)),
    ("C 2210", "NA4905", dict(d=50.0, D=90.0, C0=30000.0)),
]


def skf_kernel_inputs(designation, dims, n, nu, Fr, Fa):
    """The resolved SKF constants of one bearing (grease: Krs = 6e-8, mineral oil) and its points."""
    b = skf_catalogue.skf_bearing(designation)
    constants = {k: getattr(b, k) for k in ("R1", "R2", "R3", "R4", "S1", "S2", "S3", "S4", "S5")}
    mu_ehl = b.mu_EHL_type if not math.isnan(b.mu_EHL_type) else skf_catalogue.mu_ehl("mineral")
    axial = b.family not in ("cylindrical_roller", "carb")
    return dict(family=b.family, constants=constants, d=dims["d"], D=dims["D"], Fr=Fr, Fa=Fa if axial else 0.0 * Fa,
                n=n, nu=nu, Kz=b.Kz, mu_EHL=mu_ehl, K_rs=skf_catalogue.k_rs("grease"),
                mu_bl=skf_catalogue.mu_bl_default(), C0=dims["C0"], Y=dims.get("Y", math.nan))


def skf_by_formulas(a):
    """The same M from the per-formula kernels, one after the other (the check of the fused kernel)."""
    dm = 0.5 * (a["d"] + a["D"])
    Grr, Gsl = skf.rolling_sliding_variables(a["family"], a["constants"], dm, a["Fr"], a["Fa"], a["n"], a["nu"],
                                             a["C0"], a["Y"])
    phi_bl = skf.boundary_weighting_factor(a["n"], a["nu"], dm)
    mu_sl = skf.sliding_coefficient(phi_bl, a["mu_bl"], a["mu_EHL"])
    return skf.total_torque(skf.inlet_shear_heating_factor(a["n"], a["nu"], dm),
                            skf.kinematic_replenishment_factor(a["K_rs"], a["Kz"], a["nu"], a["n"], a["d"], a["D"]),
                            skf.rolling_torque(Grr, a["nu"], a["n"]), skf.sliding_torque(Gsl, mu_sl))


def catalogue_kernel_inputs(designation, dims, n, nu, Fr):
    """f0, f1 and the load of the catalogue model (grease column, f1 at its table constant)."""
    return dict(f0=2.0, f1=0.0003, load=Fr, dM=0.5 * (dims["d"] + dims["D"]), nu=nu, n=n)


def support_arrays(designation, dims, n, nu, Fr, Fa):
    keys = pd.DataFrame({"designation": [designation], "lubrication": ["grease"]})
    numbers = {"n": n, "nu": nu, "Fr": Fr, "Fa": Fa, **{k: v for k, v in dims.items()}}
    return build_support_arrays(keys, numbers)


def main(points: int = 1_000_000, repeats: int = 3) -> dict[str, float]:
    n, nu, Fr, Fa = operating_points(points)
    chunks = np.array_split(np.arange(points), len(BEARINGS))
    skf_args = [skf_kernel_inputs(des, dims, n[idx], nu[idx], Fr[idx], Fa[idx])
                for (des, _, dims), idx in zip(BEARINGS, chunks)]
    cat_args = [catalogue_kernel_inputs(des, dims, n[idx], nu[idx], Fr[idx])
                for (_, des, dims), idx in zip(BEARINGS, chunks)]
    radial_only = ("NU206-E", "NA4905")
    cat_supports = [support_arrays(des, dims, n[idx], nu[idx], Fr[idx], 0.0 * Fa[idx] if des in radial_only
                                   else Fa[idx]) for (_, des, dims), idx in zip(BEARINGS, chunks)]
    skf_supports = [(support_arrays(des, dims, n[idx], nu[idx], Fr[idx], a["Fa"]),
                     {"designation": des, "lubrication": "grease"})
                    for (des, _, dims), idx, a in zip(BEARINGS, chunks, skf_args)]

    def run_catalogue():
        return np.concatenate([friction.catalogue_friction_torque(**a) for a in cat_args])

    def run_skf():
        return np.concatenate([skf.skf_friction_torque(**a) for a in skf_args])

    def run_catalogue_model():
        out = []
        for s in cat_supports:
            with np.errstate(all="ignore"):
                results, problems = evaluate_catalogue_model(s, Labels())
            assert not [p for p in problems if p.level == "error"]
            out.append(results["MR"])
        return np.concatenate(out)

    def run_skf_model():
        out = []
        for s, extra in skf_supports:
            with np.errstate(all="ignore"):
                results, problems = evaluate_skf_model(s, Labels(), None, extra)
            assert not [p for p in problems if p.level == "error"], [p.message(0) for p in problems]
            out.append(results["MR"])
        return np.concatenate(out)

    t_cat, _ = best_of(run_catalogue, repeats)
    t_skf, m_skf = best_of(run_skf, repeats)
    t_cat_model, _ = best_of(run_catalogue_model, repeats)
    t_skf_model, m_skf_model = best_of(run_skf_model, repeats)
    np.testing.assert_allclose(m_skf, np.concatenate([skf_by_formulas(a) for a in skf_args]), rtol=1e-9)
    np.testing.assert_allclose(m_skf_model, m_skf, rtol=1e-9)
    figures = {"points": points, "catalogue_kernel_s": t_cat, "skf_kernel_s": t_skf,
               "skf_over_catalogue_kernel": t_skf / t_cat, "catalogue_model_s": t_cat_model,
               "skf_model_s": t_skf_model, "skf_over_catalogue_model": t_skf_model / t_cat_model}
    print(f"friction torque, {points:,} mixed points ({len(BEARINGS)} bearings, grease)")
    print(f"  catalogue model kernel        : {t_cat:8.3f} s")
    print(f"  SKF model kernel              : {t_skf:8.3f} s   ({figures['skf_over_catalogue_kernel']:.2f}x the "
          f"catalogue kernel; {verdict(figures['skf_over_catalogue_kernel'], 3)})")
    print(f"  catalogue model, with checks  : {t_cat_model:8.3f} s")
    print(f"  SKF model, with checks        : {t_skf_model:8.3f} s   ({figures['skf_over_catalogue_model']:.2f}x)")
    return figures


if __name__ == "__main__":
    main(size_argument(1_000_000, 1_000_000))
