"""Report of a coast-down analysis: the markdown report, the run-down figure and ``summary.json``.

The figure is drawn with matplotlib's Figure API (no pyplot, no global
backend); matplotlib is imported when a figure is drawn.
"""
from __future__ import annotations

import json
from functools import partial
from pathlib import Path

from bearingheat.analysis.coastdown import CoastdownResult
from bearingheat.io.files import write_outputs
from bearingheat.io.json import json_safe
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["draw_coastdown", "plot_coastdown", "render_report", "coastdown_summary", "write_coastdown_outputs"]

#: legend label of the formula (2) intervals in the lower panel
INTERVALS_LABEL = "formula (2), intervals"


def plot_coastdown(result: CoastdownResult, path) -> None:
    """n(t) with the constant-f and the chosen fit, and f (or M) against n; PNG at ``path``."""
    draw_coastdown(result).savefig(path, format="png", dpi=FIGURE_DPI)


def draw_coastdown(result: CoastdownResult):
    """The matplotlib Figure of :func:`plot_coastdown`: each formula (2) interval is a horizontal segment from its
    n_from to its n_to (the interval's mean f or M holds over that whole speed step)."""
    Figure = matplotlib_figure()

    s = result.samples
    use_f = result.f_computed
    fig = Figure(figsize=(6.4, 6.4), dpi=80)
    top, bottom = fig.subplots(2, 1)
    top.plot(s["t [s]"], s["n [1/min]"], ".", ms=3, color="0.4", label="data")
    top.plot(s["t [s]"], s["n_constant_f [1/min]"], "--", label=f"constant f (RMSE {result.rmse_before:.3g} 1/min)")
    if result.model != "coulomb":
        top.plot(s["t [s]"], s["n_model [1/min]"], "-", label=f"{result.model} (RMSE {result.rmse_after:.3g} 1/min)")
    if result.spindle is not None:
        top.plot(s["t [s]"], result.spindle.fit.fitted, ":", label="rolling M0+M1 (the Schaeffler catalogue)")
    top.set_xlabel("t [s]")
    top.set_ylabel("n [1/min]")
    top.legend(fontsize=8)
    column, label = ("f_formula1", "f") if use_f else ("M_formula1 [N*m]", "M [N*m]")
    model_column = "f_model" if use_f else "M_model [N*m]"
    bottom.plot(s["n_smooth [1/min]"], s[column], ".", ms=3, color="0.4", label="formula (1), Savitzky-Golay slope")
    bottom.plot(s["n_smooth [1/min]"], s[model_column], "-", label=result.model)
    iv = result.intervals
    if len(iv):
        values = iv["f"] if use_f else iv["M [N*m]"]
        bottom.hlines(values, iv["n_to [1/min]"], iv["n_from [1/min]"], colors="tab:green", label=INTERVALS_LABEL)
    bottom.set_xlabel("n [1/min]")
    bottom.set_ylabel(label)
    bottom.legend(fontsize=8)
    fig.tight_layout()
    return fig


def _ci(fit, name, digits=4):
    low, high = fit.interval(name)
    cut = ", cut at 0: it is not negative" if fit.interval_cut(name) else ""
    return f"{fit.value(name):.{digits}g} (95 % CI {low:.{digits}g} to {high:.{digits}g}{cut})"


def render_report(result: CoastdownResult, source: str, png: str | None) -> str:
    """Markdown report of a coast-down analysis (also printed to stdout by ``bearingheat coastdown``)."""
    fit = result.chosen
    lines = [f"# Coast-down analysis of {source}", ""]
    rig = f"I = {result.I:g} kg·m²"
    if result.f_computed:
        rig += f", G = {result.G:g} N, r = {result.r:g} mm"
    else:
        rig += " (G and r not given: torques only, f is not computed)"
    defaults = [name for name in ("I", "G", "r") if name in result.rig_defaults]
    if defaults:
        rig += f"; {', '.join(defaults)}: the TMM-7M rig's default{'s' if len(defaults) > 1 else ''}"
    lines += [f"Rig: {rig}. Samples: {len(result.samples)}; Savitzky–Golay window {result.window} samples.", ""]
    if result.f_computed and "I" not in result.rig_defaults and {"G", "r"} & set(result.rig_defaults):
        lines += ["**Note:** f is computed with the TMM-7M rig's journal load G and radius r (not given) for a rotor "
                  "of another inertia: it is not the f of that rotor. Give its G and r, or analyse torques only.", ""]
    lines += ["## Models of the resisting torque M(ω) = M_c + c_v·ω + c_a·ω²", "",
              "| model | M_c [N·m] | c_v [N·m·s] | c_a [N·m·s²] | RMSE [1/min] | CV RMSE [1/min] | BIC |",
              "|---|---|---|---|---|---|---|"]
    for name, f in result.fits.items():
        lines.append(f"| {name} | {f.value('M_c'):.4g} | {f.value('c_v'):.4g} | {f.value('c_a'):.4g} | "
                     f"{f.rmse:.4g} | {f.cv_rmse:.4g} | {f.bic:.1f} |")
    lines += ["", f"Chosen model: **{result.model}** (the simpler of the lowest-BIC and the lowest-CV-error model).", ""]
    for name, unit in (("M_c", "N·m"), ("c_v", "N·m·s"), ("c_a", "N·m·s²")):
        if name in fit.parameters:
            lines.append(f"- {name} = {_ci(fit, name)} {unit}")
    if fit.value("c_v") < 0 or fit.value("c_a") < 0:
        lines.append("- A negative component means the torque falls with speed over part of the range; "
                     "it is a curve shape, not a physical viscous or windage drag.")
    f_text = f"{result.f_constant:.4g}" if result.f_computed else "not computed (no G and r: torques only)"
    lines += ["", f"- Constant f (the TMM-7M lab sheet's single coefficient, from the Coulomb-only fit): {f_text}",
              f"- RMSE of n(t): {result.rmse_before:.4g} 1/min with constant f (before), "
              f"{result.rmse_after:.4g} 1/min with {result.model} (after)"]
    stop = result.rundown_time
    when = "extrapolated past the last sample" if result.rundown_extrapolated else "within the record"
    lines.append(f"- Run-down time to standstill: {stop:.4g} s ({when})" if stop != float("inf")
                 else "- The fitted torque does not bring the rotor to rest")
    if result.rundown_warning:
        lines.append(f"- **Warning:** {result.rundown_warning}")
    e = result.energy
    lines.append(f"- Energy dissipated over the record: {e['total']:.4g} J (Coulomb {e['coulomb']:.4g} J, "
                 f"viscous {e['viscous']:.4g} J, aerodynamic {e['aero']:.4g} J); to standstill {e['to_standstill']:.4g} J")
    lines += ["", "## f against n, formula (2) over intervals", "",
              "| n from [1/min] | n to [1/min] | Δt [s] | M [N·m] | f |", "|---|---|---|---|---|"]
    for _, row in result.intervals.iterrows():
        f_cell = f"{row['f']:.4g}" if result.f_computed else "not computed"
        lines.append(f"| {row['n_from [1/min]']:.4g} | {row['n_to [1/min]']:.4g} | {row['dt [s]']:.4g} | "
                     f"{row['M [N*m]']:.4g} | {f_cell} |")
    if result.spindle is not None:
        s = result.spindle
        lines += ["", "## Rolling-bearing form of the Schaeffler catalogue: M = z·(M0 + M1)", "",
                  f"- bearings z = {s.bearings}, ν = {s.nu:g} mm²/s, dM = {s.dM:g} mm",
                  f"- f0 = {_ci(s.fit, 'f0')}", f"- M1 = {_ci(s.fit, 'M1')} N·mm per bearing",
                  f"- RMSE of n(t): {s.fit.rmse:.4g} 1/min"]
        if s.P:
            lines.append(f"- f1 = M1/(P·dM) = {s.f1:.4g} (P = {s.P:g} N)")
        if s.f0_catalogue is not None:
            lines.append(f"- catalogue f0 = {s.f0_catalogue:g}; fitted/catalogue = {s.f0 / s.f0_catalogue:.3g}")
    if png:
        lines += ["", f"![run-down data, constant-f fit and {result.model} fit]({png})"]
    return "\n".join(lines) + "\n"


def coastdown_summary(result: CoastdownResult) -> dict:
    """The content of ``summary.json``: :meth:`CoastdownResult.summary` as strict JSON (non-finite -> null)."""
    return json_safe(result.summary())


def write_coastdown_outputs(result: CoastdownResult, out_dir, source: str, *, force: bool = False,
                            inputs=()) -> list[str]:
    """Write ``coastdown.png``, ``report.md`` and ``summary.json`` into ``out_dir``; returns their paths.

    Existing files are not replaced unless ``force``; none of them may be one of ``inputs``; each file is
    written atomically (:func:`bearingheat.io.files.write_outputs`).
    """
    report = render_report(result, source, png="coastdown.png")
    summary = json.dumps(coastdown_summary(result), indent=2) + "\n"
    files = write_outputs(out_dir, {
        "coastdown.png": partial(plot_coastdown, result),
        "report.md": lambda path: Path(path).write_text(report, encoding="utf-8"),
        "summary.json": lambda path: Path(path).write_text(summary, encoding="utf-8"),
    }, force=force, inputs=inputs)
    return [str(f) for f in files]
