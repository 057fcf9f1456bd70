"""Benchmark: the SKF friction model on 10^6 mixed operating points against the catalogue model (issue 14).

Timed in one run on the same points:

1. the catalogue model's kernel from the loads: P0, f1 from P0/C0 or Fa/C0, P1 by the type's rule
   and M_R = M0 + M1 (:func:`catalogue_chain`, the kernels of :mod:`bearingheat.kernels.friction`
   one after the other, table choices made once per bearing);
2. the SKF model's array kernel :func:`bearingheat.kernels.skf.skf_friction_torque`
   (constants resolved, M = φish·φrs·Mrr + Msl from the loads, speed and viscosity: Grr and Gsl
   from Fr and Fa, αF from Fa/C0);
3. the catalogue torque formula alone, :func:`bearingheat.kernels.friction.catalogue_friction_torque`
   with f1 and the load given (shown for scale: it leaves out the load formulas (1) and (2) contain);
4. both models' evaluations over support arrays with every input check
   (:func:`bearingheat.calc.friction.evaluate_catalogue_model`,
   :func:`bearingheat.calc.skf.evaluate_skf_model`; one bearing at many points per call, as the API does).

Target: (2) within 3x of (1), both from the same Fr, Fa, n and ν. The points mix six bearing types
(the SKF rows use six different formula families), n in 10..10 000 1/min, ν in 2..300 mm²/s, loads
up to 20 kN. The SKF kernel is checked against the composition of the per-formula kernels, and (1)
against the catalogue model with its checks (4) to 1e-12.
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


def _scalar(value):
    """The one value of a support-array field that holds one bearing (a scalar, or an array of one value)."""
    values = np.ravel(np.asarray(value))
    return values[0] if values.size else value


def catalogue_chain_inputs(supports, n, nu, Fr, Fa):
    """The catalogue model's resolved constants of one bearing and its points, for :func:`catalogue_chain`."""
    constants = {name: _scalar(getattr(supports, name)) for name in
                 ("f0_table", "f1", "f1_a", "f1_x", "f1_basis", "m1_load", "p1_rule", "X0_table", "Y0_table",
                  "X0", "Y0", "C0", "Y", "e", "d", "D")}
    return dict(constants, n=n, nu=nu, Fr=Fr, Fa=Fa)


def catalogue_chain(a):
    """M_R of the catalogue model from the loads, like the SKF kernel: P0, f1 from P0/C0 or Fa/C0, P1, M0 + M1.

    The catalogue model's kernels one after the other (the Schaeffler catalogue pp. 66-68; the DP11A manual
    for P0), with the per-bearing choices (f1 basis, P1 rule) made once per bearing, as the SKF kernel
    picks its table 2 row once per bearing.
    """
    Fr, Fa = a["Fr"], a["Fa"]
    f1 = a["f1"]
    if np.isnan(f1):
        if a["f1_basis"] == 1:
            X0 = a["X0"] if not np.isnan(a["X0"]) else a["X0_table"]
            Y0 = a["Y0"] if not np.isnan(a["Y0"]) else a["Y0_table"]
            ratio = friction.static_equivalent_load(Fr, Fa, X0, Y0) / a["C0"]
        else:
            ratio = Fa / a["C0"] if a["f1_basis"] == 2 else 1.0
        f1 = friction.f1_from_load_ratio(a["f1_a"], a["f1_x"], ratio)
    if a["m1_load"] == "Fa":
        load = Fa
    elif a["m1_load"] == "P1" and a["p1_rule"]:
        load = friction.effective_load(a["p1_rule"], Fr, Fa, a["Y"], a["e"])
    else:
        load = Fr
    return friction.catalogue_friction_torque(a["f0_table"], f1, load, friction.mean_diameter(a["d"], a["D"]),
                                              a["nu"], a["n"])


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

    chain_args = [catalogue_chain_inputs(sup, sup.n, sup.nu, sup.Fr, sup.Fa) for sup in cat_supports]

    def run_catalogue():
        return np.concatenate([friction.catalogue_friction_torque(**a) for a in cat_args])

    def run_catalogue_chain():
        return np.concatenate([catalogue_chain(a) for a in chain_args])

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
    t_chain, m_chain = best_of(run_catalogue_chain, repeats)
    t_skf, m_skf = best_of(run_skf, repeats)
    t_cat_model, m_cat_model = best_of(run_catalogue_model, repeats)
    np.testing.assert_allclose(m_chain, m_cat_model, rtol=1e-12)
    t_skf_model, m_skf_model = best_of(run_skf_model, repeats)
    np.testing.assert_allclose(m_skf, np.concatenate([skf_by_formulas(a) for a in skf_args]), rtol=1e-9)
    np.testing.assert_allclose(m_skf_model, m_skf, rtol=1e-9)
    figures = {"points": points, "catalogue_kernel_s": t_cat, "catalogue_chain_s": t_chain, "skf_kernel_s": t_skf,
               "skf_over_catalogue_kernel": t_skf / t_chain, "skf_over_catalogue_torque_formula": t_skf / t_cat,
               "catalogue_model_s": t_cat_model,
               "skf_model_s": t_skf_model, "skf_over_catalogue_model": t_skf_model / t_cat_model}
    print(f"friction torque, {points:,} mixed points ({len(BEARINGS)} bearings, grease)")
    print(f"  catalogue M0 + M1 formula     : {t_cat:8.3f} s   (f1 and the load given)")
    print(f"  catalogue model kernel        : {t_chain:8.3f} s   (from Fr, Fa: P0, f1, P1, M0 + M1)")
    print(f"  SKF model kernel              : {t_skf:8.3f} s   ({figures['skf_over_catalogue_kernel']:.2f}x the "
          f"catalogue kernel; {verdict(figures['skf_over_catalogue_kernel'], 3)}; "
          f"{figures['skf_over_catalogue_torque_formula']:.2f}x the M0 + M1 formula alone)")
    print(f"  catalogue model, with checks  : {t_cat_model:8.3f} s")
    print(f"  SKF model, with checks        : {t_skf_model:8.3f} s   ({figures['skf_over_catalogue_model']:.2f}x)")
    return figures


if __name__ == "__main__":
    main(size_argument(1_000_000, 1_000_000))
