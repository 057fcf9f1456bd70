"""The model comparison of ``audit --model`` and ``diagnose --model``: models.md, models.json, models.png.

:func:`write_comparison` writes a :class:`~bearingheat.analysis.comparison.ModelComparison`
into a folder; :func:`comparison_lines` is its console text.
"""
from __future__ import annotations

import json
from functools import partial
from pathlib import Path

import numpy as np

from bearingheat.analysis.comparison import ModelComparison
from bearingheat.io.files import write_outputs
from bearingheat.io.json import json_safe
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["COMPARISON_FILES", "comparison_lines", "comparison_markdown", "plot_comparison", "write_comparison"]

#: the files :func:`write_comparison` writes
COMPARISON_FILES = ("models.md", "models.json", "models.png")


def comparison_lines(comparison: ModelComparison) -> list[str]:
    """The verdict and one line per model, for the console."""
    lines = [comparison.verdict()]
    for fit in comparison.fits.values():
        scales = ", ".join(f"{name} x {value:.3g}" for name, value in fit.scales.items())
        lines.append(f"  {fit.model}: relative RMSE {fit.before['rel_rmse']:.1%} as published, "
                     f"{fit.cv_after['rel_rmse']:.1%} held out after fitting ({scales})")
    return lines


def comparison_markdown(comparison: ModelComparison) -> str:
    """models.md: the verdict, the table of errors before and after fitting, how the scales were fitted."""
    lines = ["# Friction models against the measured torque", "", comparison.verdict(), "",
             "| model | RMSE as published [N·mm] | rel. RMSE as published | bias as published [N·mm] "
             "| RMSE fitted [N·mm] | held-out RMSE fitted [N·mm] | held-out rel. RMSE fitted | fitted scales |",
             "|---|---|---|---|---|---|---|---|"]
    for fit in comparison.fits.values():
        scales = ", ".join(f"{name} × {value:.3g}" for name, value in fit.scales.items())
        lines.append(f"| {fit.model} | {fit.before['rmse']:.3g} | {fit.before['rel_rmse']:.1%} "
                     f"| {fit.before['bias']:+.3g} | {fit.after['rmse']:.3g} | {fit.cv_after['rmse']:.3g} "
                     f"| {fit.cv_after['rel_rmse']:.1%} | {scales} |")
    lines += ["", f"{comparison.n_rows} rows usable in every model; the bias is the mean of measured − model. "
              "Each model's scalable terms (the catalogue model's M0 and M1, the SKF model's φish·φrs·M_rr and "
              "M_sl) are fitted by non-negative least squares on relative residuals; its other terms stay as "
              f"computed. Held-out errors come from a grouped {comparison.k}-fold cross-validation: a group is "
              "one operating point (bearing, n, ν, Fr, Fa, T_oil) or the data's 'group' column.", "",
              "![measured against each model](models.png)", ""]
    if comparison.excluded:
        lines += ["## Excluded rows", ""] + [f"- {m}" for m in comparison.excluded[:50]] + [""]
    return "\n".join(lines)


def plot_comparison(comparison: ModelComparison, path: Path) -> None:
    """Measured against predicted torque of each model, as published and fitted, on log axes."""
    Figure = matplotlib_figure()

    fits = list(comparison.fits.values())
    fig = Figure(figsize=(4.2 * len(fits), 4.2))
    axes = np.atleast_1d(fig.subplots(1, len(fits), sharex=True, sharey=True))
    M = comparison.measured
    for ax, fit in zip(axes, fits):
        ax.scatter(fit.predicted, M, s=6, alpha=0.5, marker="o", label=f"as published ({fit.before['rel_rmse']:.1%})")
        ax.scatter(fit.fitted, M, s=6, alpha=0.5, marker="^",
                   label=f"scales fitted ({fit.cv_after['rel_rmse']:.1%} held out)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(fit.model, fontsize=10)
        ax.set_xlabel("M model [N·mm]")
        ax.legend(fontsize=7, loc="upper left")
    values = np.concatenate([M] + [np.concatenate([f.predicted, f.fitted]) for f in fits])
    low, top = float(np.min(values[values > 0])), float(np.max(values))
    for ax in axes:
        ax.plot([low, top], [low, top], "k-", lw=0.8)
    axes[0].set_ylabel("M measured [N·mm]")
    fig.tight_layout()
    fig.savefig(path, dpi=FIGURE_DPI, format="png")


def write_comparison(comparison: ModelComparison, out_dir, *, force: bool = False, inputs=()) -> None:
    """Write models.md, models.json and models.png into ``out_dir`` (atomically; existing files only with force)."""
    text = json.dumps(json_safe(comparison.summary()), indent=2, ensure_ascii=False)  # strict JSON
    report = comparison_markdown(comparison)
    write_outputs(out_dir, {
        "models.md": lambda path: Path(path).write_text(report, encoding="utf-8"),
        "models.json": lambda path: Path(path).write_text(text, encoding="utf-8"),
        "models.png": partial(plot_comparison, comparison),
    }, force=force, inputs=inputs)
