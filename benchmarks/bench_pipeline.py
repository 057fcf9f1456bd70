"""Benchmark: the whole pipeline against honest baselines (issue 16), each ratio measured in one run.

On the demo's supports (examples/gearbox_shaft.csv) tiled to ROWS rows with varied loads and speeds:

1. the friction kernel: the catalogue model's array evaluation with its input checks,
   :func:`bearingheat.calc.friction.evaluate_catalogue_model`, on calc's support arrays of these rows (the
   mixed-row path calc runs, not the per-type fast path). This is the kernel the issue's targets are stated
   against: when it was filed, the friction benchmark and the README called this function "the array kernel
   (with checks)"; the issue's figures are its figures (about 70 ms for 10^6 points, about 11x faster than a
   per-row loop of plain floats; the code of that day gives 51 ms and 13.4x on the AVX-512 machine, and calc
   took 32 s and 44 s there, the issue's 22 s and 44 s). Measured against the same formulas without
   checks, a minimal numpy version written here (P0, P1, f1, M0, M1, MR, NR in the model's order; checked
   against calc's MR and NR to 1e-12) and against the memory-bandwidth floor (copying the per-row arrays it
   reads);
2. its torque formula alone, :func:`bearingheat.kernels.friction.catalogue_friction_torque` (M0 + M1,
   coefficients resolved), against a minimal numpy version written here and against its floor (no target;
   the ratios of calc to it are printed too: until 2026-11-28 the targets were held against it);
3. ``bh.calc(df)`` against the kernel on the same rows: the overhead of the table API (designations,
   units, checks, messages), without and with the heat-balance columns (targets 10x and 30x), and with ν taken
   from oil data at each row's operating temperature (no target: T_op is bracketed there, not a secant);
4. ``bearingheat calc big.csv -o out.parquet -q`` against a bare ``pd.read_csv(engine='pyarrow')`` +
   ``to_parquet`` of the same file (with the heat-balance columns), each in its own process (target 5x,
   peak memory under 1 GB at 10^6 rows);
5. the peak memory of each (its own fresh process, VmHWM; Python with the package imported is the
   baseline, printed first), and the command line's peak above that of the same command on 100 rows against
   the size of its output table as Arrow (the issue: about twice).

    .venv/bin/python benchmarks/bench_pipeline.py [ROWS | --full]   (default 200 000; --full: the issue's 10^6)
"""
from __future__ import annotations

import dataclasses
import math
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow.parquet as pq

import bearingheat as bh
from bearingheat.calc.friction import evaluate_catalogue_model
from bearingheat.calc.messages import Labels
from bearingheat.kernels import friction
from common import best_in_turns, demo_rows, peak_run, size_argument, verdict

#: the targets of issue 16
CALC_FRICTION_TARGET, CALC_HEAT_TARGET, CLI_TARGET, CLI_PEAK_MB = 10.0, 30.0, 5.0, 1024.0


def numpy_torque(f0, f1, load, dM, nu, n):
    """The catalogue model's M0 + M1 in plain numpy, written here as the baseline."""
    nun = nu * n
    M0 = f0 * np.where(nun >= 2000.0, np.cbrt(nun * nun), 160.0) * (dM * dM * dM) * 1e-7
    return M0 + f1 * load * dM


def kernel_arrays(table, result):
    """The kernel's inputs for the rows of ``table``: f0, f1 as calc resolved them, the load, dM, nu, n."""
    f0, f1 = result["f0"].to_numpy(), result["f1"].to_numpy()
    load = np.where(result["P1 [N]"].isna(), table["Fr [kN]"].to_numpy() * 1e3, result["P1 [N]"].to_numpy())
    dM = (table["d [mm]"].to_numpy() + table["D [mm]"].to_numpy()) / 2
    return f0, f1, load, dM, table["nu [mm^2/s]"].to_numpy(dtype=float), table["n [rpm]"].to_numpy(dtype=float)


def model_arrays(table):
    """The support arrays of ``table`` as calc resolves them (its unit boundary, fill and bearing keys; not timed)."""
    from bearingheat.calc.fill import fill_from_catalogue
    from bearingheat.calc.models import support_arrays_of
    from bearingheat.calc.conversion import to_catalogue_units

    converted = to_catalogue_units(table)
    return support_arrays_of(fill_from_catalogue(converted.frame, converted.labels)[0].reset_index(drop=True))


def per_row_inputs(s) -> list[np.ndarray]:
    """The per-row arrays of support arrays ``s`` (numbers, and the codes of the text constants): what the
    model's evaluation reads at least once, so copying them is its memory-bandwidth floor (a field that is one
    number for every row is not an array of the rows)."""
    fields = (getattr(s, field.name) for field in dataclasses.fields(s))
    arrays = [field.codes if isinstance(field, pd.Categorical) else field for field in fields]
    return [array for array in arrays if isinstance(array, np.ndarray) and array.ndim == 1 and array.strides[0]
            and array.dtype != object]


def evaluate_model(s):
    """The friction kernel: the catalogue model's evaluation with its checks; (MR, NR) of the rows."""
    results, problems = evaluate_catalogue_model(s, Labels())
    assert not [problem for problem in problems if problem.level == "error"]
    return results["MR"], results["NR"]


#: P1 by the rule of each bearing type before "P1 >= Fr" (the Schaeffler catalogue, p. 68), written here for the
#: baseline
P1_FORMULAS = {
    "radial_ball": lambda Fr, Fa, Y, e: 3.3 * Fa - 0.1 * Fr,
    "angular_single": lambda Fr, Fa, Y, e: Fa - 0.1 * Fr,
    "angular_paired": lambda Fr, Fa, Y, e: 1.4 * Fa - 0.1 * Fr,
    "angular_double_row": lambda Fr, Fa, Y, e: 1.4 * Fa - 0.1 * Fr,
    "four_point": lambda Fr, Fa, Y, e: 1.5 * Fa + 3.6 * Fr,
    "tapered_single": lambda Fr, Fa, Y, e: np.where(Fa > 0, 2 * Y * Fa, Fr),
    "tapered_paired": lambda Fr, Fa, Y, e: np.where(Fa > 0, 1.21 * Y * Fa, Fr),
    "spherical": lambda Fr, Fa, Y, e: np.where(Fa > e * Fr, 1.6 * Fa / e, Fr * (1 + 0.6 * (Fa / (e * Fr)) ** 3)),
}


def model_formulas(s):
    """MR and NR of the catalogue model in plain numpy, written here without its checks, messages or text
    columns, in the order the model applies them (the Schaeffler catalogue, pp. 64-68): P0, P1 by each row's
    rule, f1 from its load ratio, M0, M1, MR, NR (the demo's rows: f0 and f1 from the tables, no M2). The
    minimal numpy version of the friction kernel's formulas, and what bh.calc computes per row."""
    Fr, Fa = s.Fr, s.Fa
    X0 = np.where(np.isnan(s.X0), s.X0_table, s.X0)
    Y0 = np.where(np.isnan(s.Y0), s.Y0_table, s.Y0)
    P0 = np.where(Fa > 0, np.fmax(X0 * Fr + Y0 * Fa, Fr), Fr)
    P1 = np.full(len(s.n), np.nan)
    with np.errstate(divide="ignore", invalid="ignore"):
        for code, name in enumerate(s.p1_rule.categories):
            if name:
                np.copyto(P1, np.fmax(P1_FORMULAS[name](Fr, Fa, s.Y, s.e), Fr), where=s.p1_rule.codes == code)
        load = np.where(np.equal(s.m1_load, "Fa"), Fa, np.where(np.isnan(P1), Fr, P1))
        ratio = np.where(s.f1_basis == 1, P0 / s.C0, np.where(s.f1_basis == 2, Fa / s.C0, 1.0))
        f1 = s.f1_a * ratio ** s.f1_x
    dM = (s.d + s.D) / 2
    nu_n = s.nu * s.n
    M0 = s.bearings * s.f0_table * np.where(nu_n >= 2000, np.cbrt(nu_n) ** 2, 160) * dM ** 3 * 1e-7
    MR = M0 + f1 * load * dM
    return MR, MR * s.n / 9550


def _peak_lines(rows: int, folder: Path) -> dict[str, str]:
    """The code of each peak-memory run, in a fresh process each."""
    source = folder / "big.csv"
    return {
        "python + package": "import bearingheat, bearingheat.cli",
        "torque formula (M0 + M1)": (f"import numpy as np; from bearingheat.kernels import friction; "
                                     f"r = np.random.default_rng(1); a = [r.uniform(1, 2, {rows}) for _ in range(6)]; "
                                     "friction.catalogue_friction_torque(*a)"),
        "bh.calc, friction only": f"import bearingheat as bh; from common import demo_rows; "
                                  f"bh.calc(demo_rows({rows}, heat_balance=False))",
        "bh.calc, with heat balance": f"import bearingheat as bh; from common import demo_rows; "
                                      f"bh.calc(demo_rows({rows}, heat_balance=True))",
        "bare read_csv + to_parquet": f"import pandas as pd; pd.read_csv({str(source)!r}, engine='pyarrow')"
                                      f".to_parquet({str(folder / 'bare.parquet')!r})",
        "bearingheat calc -o .parquet": _command_line(source, folder / "out.parquet"),
        # the same on 100 rows: what the program holds whatever the table's size (Python, pandas, pyarrow, ...)
        "bearingheat calc, 100 rows": _command_line(folder / "small.csv", folder / "small.parquet"),
    }


def _command_line(source: Path, target: Path) -> str:
    """The code of ``bearingheat calc SOURCE -o TARGET -q --force`` through the program's own entry point, as the
    shell runs it (sys.argv; pint's definition cache)."""
    return (f"import sys; sys.argv = ['bearingheat', 'calc', {str(source)!r}, '-o', {str(target)!r}, '-q', "
            f"'--force']; from bearingheat.cli import command_line; command_line()")


def main(rows: int = 200_000, repeats: int = 3, cli: bool = True) -> dict[str, float]:
    figures: dict[str, float] = {"rows": rows}
    table = demo_rows(rows, heat_balance=False)
    result = bh.calc(table)
    args = kernel_arrays(table, result)
    supports = model_arrays(table)
    inputs = per_row_inputs(supports)
    # the kernel and the baseline of its formulas compute what calc reports
    for MR, NR in (evaluate_model(supports), model_formulas(supports)):
        np.testing.assert_allclose(MR, result["MR [N*mm]"].to_numpy(), rtol=1e-12)
        np.testing.assert_allclose(NR, result["NR [W]"].to_numpy(), rtol=1e-12)
    np.testing.assert_allclose(friction.catalogue_friction_torque(*args), numpy_torque(*args), rtol=1e-12)
    tables = {heat_balance: demo_rows(rows, heat_balance=heat_balance) for heat_balance in (False, True)}
    oil_table = demo_rows(rows, heat_balance=True, oil=True)
    # every side of every ratio runs in turns, the shortest of each counts (the machine's speed comes and goes)
    timed = best_in_turns({
        "kernel": lambda: evaluate_model(supports),
        "formulas": lambda: model_formulas(supports),
        "memory_floor": lambda: [array.copy() for array in inputs],
        "torque_formula": lambda: friction.catalogue_friction_torque(*args),
        "torque_numpy": lambda: numpy_torque(*args),
        "torque_floor": lambda: [array.copy() for array in args],
        "calc_friction": lambda: bh.calc(tables[False]),
        "calc_heat": lambda: bh.calc(tables[True]),
        "calc_oil": lambda: bh.calc(oil_table),
    }, repeats)
    figures.update({name: elapsed for name, (elapsed, _) in timed.items()})
    kernel, formulas, floor = (figures[name] for name in ("kernel", "formulas", "memory_floor"))
    torque, torque_numpy, torque_floor = (figures[name] for name in ("torque_formula", "torque_numpy",
                                                                     "torque_floor"))
    print(f"on {rows:,} rows of the demo's supports (varied loads and speeds; every run in turns, the shortest of "
          f"{repeats} each):")
    print(f"  friction kernel (the catalogue model's evaluation with its input checks on calc's support arrays of "
          f"these rows, the mixed-row path) {kernel * 1e3:.1f} ms")
    print(f"    vs a minimal numpy version of the same formulas without checks (P0, P1, f1, M0, M1, MR, NR) "
          f"{formulas * 1e3:.1f} ms: {kernel / formulas:.2f}x (no target; the price of the checks)")
    print(f"    vs the memory-bandwidth floor (copying its {len(inputs)} per-row input arrays, {floor * 1e3:.1f} ms): "
          f"{kernel / floor:.1f}x (no target)")
    print(f"  its torque formula alone (M0 + M1, coefficients resolved) {torque * 1e3:.1f} ms vs a minimal numpy "
          f"version of the same formulas {torque_numpy * 1e3:.1f} ms: {torque / torque_numpy:.2f}x (no target; 1x "
          f"is the best); vs the memory-bandwidth floor (copying its 6 input arrays, {torque_floor * 1e3:.1f} ms): "
          f"{torque / torque_floor:.1f}x")
    for name, what, target in (("calc_friction", "without heat-balance columns", CALC_FRICTION_TARGET),
                               ("calc_heat", "with heat-balance columns", CALC_HEAT_TARGET),
                               ("calc_oil", "with heat-balance columns and nu from nu40/nu100 at T_op", None)):
        elapsed = figures[name]
        ratio = elapsed / kernel
        print(f"  bh.calc {what} {elapsed:.2f} s ({elapsed / rows * 1e6:.1f} us a row) vs the kernel on the same "
              f"rows: {ratio:.1f}x ({verdict(ratio, target) if target else 'no target'}); "
              f"{elapsed / torque:.0f}x the torque formula alone")
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        demo_rows(rows, heat_balance=True).to_csv(folder / "big.csv", index=False)
        demo_rows(100, heat_balance=True).to_csv(folder / "small.csv", index=False)
        peaks, times = {}, {}
        lines = {what: code for what, code in _peak_lines(rows, folder).items() if cli or "parquet" not in what}
        # the CLI and its baseline run in turns, the shortest time of each counts (a shared machine's load comes
        # and goes; both sides get the same chances)
        for _ in range(repeats if cli else 1):
            for what, code in lines.items():
                elapsed, peak = peak_run(code)
                times[what] = min(times.get(what, elapsed), elapsed)
                peaks[what] = max(peaks.get(what, peak), peak)
        output_mb = pq.read_table(folder / "out.parquet").nbytes / 2**20 if cli else math.nan
    if cli:
        bare, full = times["bare read_csv + to_parquet"], times["bearingheat calc -o .parquet"]
        figures.update(cli=full, cli_bare=bare, cli_peak_mb=peaks["bearingheat calc -o .parquet"],
                       bare_peak_mb=peaks["bare read_csv + to_parquet"])
        print(f"  bearingheat calc big.csv -o out.parquet -q {full:.2f} s vs a bare pd.read_csv(engine='pyarrow') "
              f"+ to_parquet of the same file {bare:.2f} s (both with heat-balance columns, each in its own process, "
              f"Python start included, the shortest of {repeats} runs in turns): {full / bare:.1f}x "
              f"({verdict(full / bare, CLI_TARGET)})")
        held = peaks["bearingheat calc -o .parquet"] - peaks["bearingheat calc, 100 rows"]
        figures.update(cli_output_mb=output_mb, cli_held_mb=held)
        print(f"  its peak memory above that of the same command on 100 rows (Python and its libraries): "
              f"{held:.0f} MB, {held / output_mb:.2f}x the output table ({output_mb:.0f} MB as Arrow; the issue: "
              "about twice)")
    print("  peak memory of each, in its own process (VmHWM):")
    for what, peak in peaks.items():
        note = f" (start and import: {times[what]:.2f} s)" if what == "python + package" else ""
        if what == "bearingheat calc -o .parquet":
            note = f" (target < {CLI_PEAK_MB:.0f} MB at 10^6 rows: {'met' if peak < CLI_PEAK_MB else 'NOT met'})"
        print(f"    {what:<30} {peak:7.0f} MB{note}")
    figures.update({f"peak_mb[{what}]": peak for what, peak in peaks.items()})
    return figures


if __name__ == "__main__":
    main(size_argument(200_000, 1_000_000))
