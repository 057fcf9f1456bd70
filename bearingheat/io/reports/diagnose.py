"""The report of ``bearingheat diagnose``: summary.json, report.md and two PNG plots.

:func:`write_outputs` writes a :class:`~bearingheat.analysis.diagnose.Diagnosis`
into a folder: ``summary.json`` (:meth:`Diagnosis.summary` with the key
regressor of the residual plot), ``report.md`` (:func:`report_markdown`),
``residuals.png`` (:func:`plot_residuals`) and ``measured_vs_predicted.png``
(:func:`plot_measured_vs_predicted`). The plots use matplotlib's Figure API
(no pyplot, no global backend); matplotlib is imported when a plot is drawn.
"""
from __future__ import annotations

import json
import os
from collections.abc import Iterable
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from bearingheat.analysis.diagnose import (REGRESSOR_UNITS, CandidateScore, Diagnosis, format_value, key_regressor,
                                           regressors)
from bearingheat.io.files import write_outputs as write_files
from bearingheat.io.json import json_safe
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["plot_residuals", "residuals_figure", "plot_measured_vs_predicted", "report_markdown", "write_outputs",
           "summary_lines", "bound_marks"]

#: at most this many points are drawn (a seeded random subset of larger data sets)
_PLOT_POINTS = 4000


def _plot_rows(n: int) -> np.ndarray:
    if n <= _PLOT_POINTS:
        return np.arange(n)
    return np.sort(np.random.default_rng(0).choice(n, _PLOT_POINTS, replace=False))


def _predicted(score: CandidateScore) -> np.ndarray:
    """The torque a candidate predicts (the catalogue model and the chosen effect always apply)."""
    assert score.predicted is not None, f"candidate {score.name!r} does not apply to the data"
    return score.predicted


#: bearings named in the legend of the residual plot (the ones with the most rows); the others share one entry
_LEGEND_BEARINGS = 10


def bound_marks(at_bound: dict[str, Any]) -> list[str]:
    """The fitted parameters that ended on a bound of their fit, as text: 'k (lower)', 'M_seal [N*mm] 6205 (lower)'.

    >>> bound_marks({"c": None, "p": "upper", "F_pre [N]": {"6205": "lower", "NU208-E": None}})
    ['p (upper)', 'F_pre [N] 6205 (lower)']
    """
    marks = []
    for name, side in at_bound.items():
        if isinstance(side, dict):
            marks += [f"{name} {bearing} ({each})" for bearing, each in side.items() if each]
        elif side:
            marks.append(f"{name} ({side})")
    return marks


#: what a parameter on a bound means, as the report says it
_ON_A_BOUND = ("the data would push it past the bound its fit keeps it within, so its value is that bound, not an "
               "estimate (at a lower bound of 0, or k = 1, the term is absent)")


def _percent(fraction: float | None) -> float | None:
    """A fraction in percent (None stays None: a score not computed)."""
    return None if fraction is None else 100.0 * fraction


def _influence_lines(influence: dict[str, Any] | None) -> list[str]:
    """The section on single readings: the rule, the readings of the largest studentised residual, the choice
    without the most outlying flagged one (a warning where it changes)."""
    if influence is None:
        return []
    lines = ["## Influence of single readings", "", influence["rule"], "",
             f"Readings of the largest studentised residual under the chosen effect ({influence['n_params']} "
             "parameter(s) not on a bound):", "",
             "| row | M [N·mm] | predicted [N·mm] | relative residual | leverage | studentised | Cook's distance "
             "| Bonferroni p | flagged |", "|---|---|---|---|---|---|---|---|---|"]
    for r in influence["readings"]:
        lines.append(f"| {r['row']} | {format_value(r['M'])} | {format_value(r['predicted'])} "
                     f"| {format_value(r['relative_residual'], 3)} | {format_value(r['leverage'], 3)} "
                     f"| {format_value(r['studentised'], 3)} | {format_value(r['cooks_distance'], 3)} "
                     f"| {format_value(r['p_value'], 2)} | {'yes' if r['flagged'] else 'no'} |")
    lines.append("")
    if influence["dropped"] is None:
        lines.append("No reading is flagged: the choice was not made again.")
    elif influence["warning"]:
        lines.append(f"**Warning: {influence['warning']}.**")
    else:
        lines.append(f"{influence['flagged']} reading(s) flagged; without {influence['dropped']} the choice is the "
                     f"same ('{influence['effect_without']}').")
    return lines + [""]


def _domain_lines(summary: dict[str, Any]) -> list[str]:
    """What calc --effects checks, as the report states it: the base model and the fitted ranges."""
    if summary["effect"] == "none":
        return []
    ranges = ", ".join(f"{key} {value[0]:g} to {value[1]:g}" for key, value in summary["domain"].items()
                       if key != "bearings")
    return [f"Fitted on the {summary['base_model']} model over {ranges}; `calc --effects` refuses rows of another "
            "model and warns on rows outside these ranges.", ""]


def residuals_figure(diagnosis: Diagnosis) -> tuple[Any, str]:
    """The figure of :func:`plot_residuals` and the key regressor's name.

    Every bearing's rows are drawn; the legend names the :data:`_LEGEND_BEARINGS` bearings with the most
    rows and draws the rest in one colour as 'other bearings'.
    """
    Figure = matplotlib_figure()

    data = diagnosis.data
    key = key_regressor(diagnosis)
    x = regressors(data)[key]
    rows = _plot_rows(len(data))
    before = (data.M - _predicted(diagnosis.scores["none"])) / data.M * 100.0
    after = (data.M - _predicted(diagnosis.chosen)) / data.M * 100.0
    counts = np.bincount(data.bearing, minlength=len(data.bearing_names))
    named = sorted(np.argsort(-counts, kind="stable")[:_LEGEND_BEARINGS].tolist())
    others = rows[~np.isin(data.bearing[rows], named)]
    fig = Figure(figsize=(9, 3.6))
    axes = fig.subplots(1, 2, sharey=True)
    for ax, residual, title in ((axes[0], before, "catalogue model"),
                                (axes[1], after, f"with {diagnosis.effect}")):
        for code in named:
            mine = rows[data.bearing[rows] == code]
            ax.scatter(x[mine], residual[mine], s=6, alpha=0.6, label=data.bearing_names[code])
        if len(others):
            rest = len(data.bearing_names) - len(named)
            ax.scatter(x[others], residual[others], s=6, alpha=0.4, color="0.5", label=f"{rest} other bearings")
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xlabel(f"{key} [{REGRESSOR_UNITS[key]}]")
        ax.set_title(title, fontsize=10)
    axes[0].set_ylabel("(M measured − M model)/M measured [%]")
    axes[1].legend(fontsize=7, loc="best")
    fig.tight_layout()
    return fig, key


def plot_residuals(diagnosis: Diagnosis, path: Path) -> str:
    """Relative residual against the key regressor, before and after; returns the regressor's name."""
    fig, key = residuals_figure(diagnosis)
    fig.savefig(path, dpi=FIGURE_DPI, format="png")
    return key


def plot_measured_vs_predicted(diagnosis: Diagnosis, path: Path) -> None:
    """Measured against predicted torque on log axes, the catalogue model and the model with the effect."""
    Figure = matplotlib_figure()

    data = diagnosis.data
    rows = _plot_rows(len(data))
    fig = Figure(figsize=(4.6, 4.4))
    ax = fig.subplots()
    catalogue, chosen = _predicted(diagnosis.scores["none"]), _predicted(diagnosis.chosen)
    ax.scatter(catalogue[rows], data.M[rows], s=6, alpha=0.5, label="catalogue model")
    if diagnosis.effect != "none":
        ax.scatter(chosen[rows], data.M[rows], s=6, alpha=0.5, label=f"with {diagnosis.effect}")
    top = float(max(np.max(data.M), np.max(catalogue), np.max(chosen)))
    low = float(min(np.min(data.M), np.min(catalogue)))
    ax.plot([low, top], [low, top], "k-", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("M predicted [N·mm]")
    ax.set_ylabel("M measured [N·mm]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=FIGURE_DPI, format="png")


def report_markdown(diagnosis: Diagnosis, summary: dict[str, Any], key: str) -> str:
    """report.md: the effect, the error before and after, the residual structure, the candidates, the plots."""
    lines = [
        "# bearingheat diagnose: report", "",
        f"{summary['n_rows']} measured rows of {len(summary['bearings'])} bearing(s) "
        f"({', '.join(summary['bearings'][:12])}{' ...' if len(summary['bearings']) > 12 else ''}); "
        f"{summary['n_excluded']} row(s) excluded.", "",
        f"**Effect found: `{summary['effect']}`**: {summary['description']}.", "",
        f"Parameters: {format_value(summary['parameters']) or '(none)'}", "",
        *([f"On a bound of its fit: {', '.join(marks)}: {_ON_A_BOUND}.", ""]
          if (marks := bound_marks(summary["at_bound"])) else []),
        *_domain_lines(summary),
        "## Error before and after", "",
        "| | RMSE [N·mm] | relative RMSE [%] | MAPE [%] | bias, measured − model [N·mm] |", "|---|---|---|---|---|",
        *[f"| {model}, {rows} | {format_value(summary[f'{cv}rmse_{when}'])} "
          f"| {format_value(_percent(summary[f'{cv}rel_rmse_{when}']))} | {format_value(summary[f'{cv}mape_{when}'])} "
          f"| {format_value(summary[f'bias_{when}']) if not cv else ''} |"
          for cv, rows in (("", "fitting data"), ("cv_", "held-out folds"))
          for model, when in (("catalogue model", "before"), ("with the effect", "after"))],
        "", summary["choice_metric_text"], "",
        "## Residual structure of the catalogue model", "",
        "Relative residual (M measured − M model)/M measured against each regressor.", "",
        "| regressor | statistic | value | p | note |", "|---|---|---|---|---|",
    ]
    for entry in summary["residual_structure"]:
        lines.append(f"| {entry['regressor']} | {entry['statistic']} | {format_value(entry['value'], 3)} "
                     f"| {format_value(entry['p_value'], 3)} | {entry['note']} |")
    lines += ["", "## Candidates", "",
              f"Grouped {summary['folds']}-fold cross-validation over {summary['groups']} groups "
              "(operating points).", "",
              "| candidate | parameters | RMSE [N·mm] | CV RMSE [N·mm] | rel. RMSE [%] | CV rel. RMSE [%] | ΔBIC | CV gain "
              "| p | significant |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for name, c in summary["candidates"].items():
        if not c["applicable"]:
            lines.append(f"| {name} | not applicable: {c['reason']} | | | | | | | | no |")
            continue
        params = format_value(c["parameters"]) if len(json.dumps(c["parameters"])) < 160 else "(per bearing, see summary.json)"
        if marks := bound_marks(c["at_bound"]):
            params += f"; on a bound: {', '.join(marks)}"
        gain = f"{c['cv_improvement'] * 100:.1f} %" if c["cv_improvement"] is not None else "–"
        lines.append(f"| {name} | {params} | {format_value(c['rmse'])} | {format_value(c['cv_rmse'])} "
                     f"| {format_value(_percent(c['rel_rmse']), 3)} | {format_value(_percent(c['cv_rel_rmse']), 3)} "
                     f"| {format_value(c['delta_bic'], 4)} | {gain} | {format_value(c['p_value'], 2)} | "
                     f"{'yes' if c['significant'] else 'no'} |")
    lines += ["", "Selection rule: " + summary["selection_rule"], "", summary["selection"], ""]
    lines += _influence_lines(summary["influence"])
    lines += ["## Plots", "",
              f"![residuals against {key}](residuals.png)", "",
              "![measured against predicted](measured_vs_predicted.png)", ""]
    if summary["n_excluded"]:
        lines += ["## Excluded rows", ""] + [f"- {m}" for m in summary["excluded"]] + [""]
    return "\n".join(lines)


def write_outputs(diagnosis: Diagnosis, out_dir: str | os.PathLike[str], *, force: bool = False,
                  inputs: Iterable[str | os.PathLike[str]] = ()) -> dict[str, Any]:
    """Write summary.json, report.md, residuals.png and measured_vs_predicted.png into ``out_dir``.

    Existing files are not replaced unless ``force``; none of them may be one of ``inputs``; each file is
    written atomically (:func:`bearingheat.io.files.write_outputs`). Returns the summary.
    """
    summary = diagnosis.summary()
    key = key_regressor(diagnosis)
    summary["key_regressor"] = key
    summary_text = json.dumps(json_safe(summary), indent=2, ensure_ascii=False)  # strict JSON: no Infinity, NaN
    report = report_markdown(diagnosis, summary, key)
    write_files(out_dir, {
        "residuals.png": partial(plot_residuals, diagnosis),
        "measured_vs_predicted.png": partial(plot_measured_vs_predicted, diagnosis),
        "summary.json": lambda path: Path(path).write_text(summary_text, encoding="utf-8"),
        "report.md": lambda path: Path(path).write_text(report, encoding="utf-8"),
    }, force=force, inputs=inputs)
    return summary


def summary_lines(summary: dict[str, Any], out_dir: str | os.PathLike[str]) -> list[str]:
    """The outcome in a few lines for the console: the effect, the error before and after, where the report is."""
    lines = [f"effect: {summary['effect']}  parameters: {format_value(summary['parameters']) or '(none)'}"]
    if marks := bound_marks(summary["at_bound"]):
        lines.append(f"on a bound of its fit (the value is the bound, not an estimate): {', '.join(marks)}")
    lines.append(f"RMSE {summary['rmse_before']:.4g} -> {summary['rmse_after']:.4g} N*mm "
                 f"(held-out {summary['cv_rmse_before']:.4g} -> {summary['cv_rmse_after']:.4g}); "
                 f"MAPE {summary['mape_before']:.3g} -> {summary['mape_after']:.3g} %")
    lines.append(f"relative RMSE {_percent(summary['rel_rmse_before']):.3g} -> {_percent(summary['rel_rmse_after']):.3g} % "
                 f"(held-out {_percent(summary['cv_rel_rmse_before']):.3g} -> "
                 f"{_percent(summary['cv_rel_rmse_after']):.3g} %): the error the choice is made on")
    influence = summary["influence"]
    if influence is not None and influence["flagged"]:
        top = influence["readings"][0]
        lines.append(f"{influence['flagged']} reading(s) flagged as outliers, the largest {top['row']} (studentised "
                     f"residual {top['studentised']:.3g}); without it the effect chosen is "
                     f"'{influence['effect_without']}'")
    if summary["n_excluded"]:
        lines.append(f"{summary['n_excluded']} row(s) excluded; see {out_dir}/report.md")
    lines.append(f"report: {out_dir}/report.md")
    return lines
