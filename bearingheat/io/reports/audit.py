"""What ``bearingheat audit`` writes: the audit tables as text, CSV files and the reference speed figure.

The coefficient audit (:func:`bearingheat.analysis.audit.audit_coefficients`)
is printed as one table and written to ``coefficients.csv``; the rows it
left out are counted and listed (the first 20) and written to
``excluded.csv``. The reference speed audit
(:func:`bearingheat.analysis.audit.audit_reference_speeds`, grouped by
:func:`~bearingheat.analysis.audit.classify_reference_speeds`) is printed
with the rows it skipped (no published speed where the catalogue prints none),
the flagged groups and their implied f0 first, then the outliers, then
every group and the rows not computed with their reasons; it is written to
``reference_speeds.csv`` (one row per bearing: its group, deviation and
outlier mark), ``reference_speed_series.csv`` (one row per series and size
class) and ``reference_speeds.png`` (deviation against bore for every series, drawn
with matplotlib's Figure API).
"""
from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.analysis.reference_speeds import (MIN_CONSISTENT, SKIPPED_WITHOUT_SPEED, SYSTEMATIC_RULE,
                                                   ReferenceSpeedAudit)
from bearingheat.io.files import write_outputs
from bearingheat.io.tables import escape_formulas
from bearingheat.io.reports import FIGURE_DPI, matplotlib_figure

__all__ = ["coefficient_lines", "excluded_lines", "EXCLUDED_FILE", "COEFFICIENT_TITLE", "reference_speed_lines",
           "not_computed_lines", "write_coefficients", "write_reference_speeds", "draw_reference_speeds", "REFERENCE_SPEED_FILES"]

#: at most this many excluded rows are listed under the coefficient table (and rows not computed under the
#: reference speed tables)
SHOWN_EXCLUDED = 20
#: the files of the reference speed audit
REFERENCE_SPEED_FILES = ("reference_speeds.csv", "reference_speed_series.csv", "reference_speeds.png")
#: resolution of the figure [dots per inch]


#: the line before the table of fitted coefficients
COEFFICIENT_TITLE = "Coefficients fitted to the measured torque (95 % confidence intervals):"


#: the file of the rows the coefficient fit left out, with their reasons
EXCLUDED_FILE = "excluded.csv"


def excluded_lines(result: pd.DataFrame, out_dir=None) -> list[str]:
    """The rows the coefficient fit left out: a count (naming ``out_dir``/excluded.csv where it is written),
    then a line each, at most :data:`SHOWN_EXCLUDED` and '... N more'."""
    excluded = list(result.attrs.get("excluded", []))
    if not excluded:
        return []
    where = f", all listed with their reasons in {Path(out_dir) / EXCLUDED_FILE}" if out_dir is not None else ""
    lines = [f"{len(excluded)} row{'s' if len(excluded) > 1 else ''} excluded from the fit{where}:"]
    lines += [f"excluded: {message}" for message in excluded[:SHOWN_EXCLUDED]]
    if len(excluded) > SHOWN_EXCLUDED:
        lines.append(f"... {len(excluded) - SHOWN_EXCLUDED} more")
    return lines


def coefficient_lines(result: pd.DataFrame) -> list[str]:
    """The coefficient audit as text lines: the title, the table, then the rows that were excluded."""
    return [COEFFICIENT_TITLE, result.to_string(index=False, float_format=lambda x: f"{x:.4g}"),
            *excluded_lines(result)]


def _percent(value: float) -> str:
    return f"{value * 100:+.1f} %" if pd.notna(value) else "-"


def _f0(value: float) -> str:
    return f"{value:.3f}" if pd.notna(value) else "-"


def _f1(value: float) -> str:
    return f"{value:.2e}" if pd.notna(value) else "-"


def not_computed_lines(reasons: list[str]) -> list[str]:
    """The rows of a catalogue list whose n_thr was not computed, by their ``reasons``
    (:attr:`ReferenceSpeedAudit.not_computed`: the first :data:`SHOWN_EXCLUDED`, then '... N more'); none where every
    row was computed."""
    if not reasons:
        return []
    lines = [f"Rows not computed ({len(reasons)}), left out of every group:"]
    lines += [f"  {reason}" for reason in reasons[:SHOWN_EXCLUDED]]
    if len(reasons) > SHOWN_EXCLUDED:
        lines.append(f"  ... {len(reasons) - SHOWN_EXCLUDED} more")
    return lines


def reference_speed_lines(audit: ReferenceSpeedAudit) -> list[str]:
    """The reference speed audit as text lines: flagged groups with their implied f0, outliers, every group, rule."""
    groups = audit.groups
    if audit.consistent:
        scale = (f"sigma = {audit.scale:.2%} (robust scale of the median deviations of the {audit.consistent} "
                 "series that agree with the tables)")
    else:
        scale = (f"sigma = {audit.scale:.2%} (the floor, not estimated from the data: of the {audit.series} series, "
                 f"fewer than {MIN_CONSISTENT} agree with the tables, too few for a robust scale)")
    lines = ["Thermal reference speed from the tables against the published value "
             "(deviation = n_thr(tables)/n_thr(published) - 1).",
             f"{scale}; threshold = +/-{audit.threshold:.2%}."]
    if audit.skipped:
        more = len(audit.skipped) - SHOWN_EXCLUDED
        lines.append(f"Rows skipped ({len(audit.skipped)}), {SKIPPED_WITHOUT_SPEED}: "
                     f"{', '.join(audit.skipped[:SHOWN_EXCLUDED])}{f', ... {more} more' if more > 0 else ''}")
    flagged = audit.flagged
    if len(flagged):
        lines.append(f"Flagged groups ({len(flagged)}), with the f0 that reproduces their published speeds "
                     "(median, 95 % interval; f1 holding f0 as the alternative):")
        shown = pd.DataFrame({
            "group": flagged["group"].to_numpy(),
            "bearings": flagged["bearings"].to_numpy(),
            "variants": flagged["variants"].to_numpy(),
            "median": flagged["median_deviation"].map(_percent).to_numpy(),
            "f0 table": flagged["f0_table"].map(_f0).to_numpy(),
            "f0 implied [95 %]": [f"{_f0(r['f0_implied'])} [{_f0(r['f0_implied_low'])}, "
                                  f"{_f0(r['f0_implied_high'])}]" for _, r in flagged.iterrows()],
            "f1 table": flagged["f1_table"].map(_f1).to_numpy(),
            "f1 implied [95 %]": [f"{_f1(r['f1_implied'])} [{_f1(r['f1_implied_low'])}, "
                                  f"{_f1(r['f1_implied_high'])}]" for _, r in flagged.iterrows()],
        })
        lines += ["  " + line for line in shown.to_string(index=False).splitlines()]
        lines += [f"  note: {g}: {n}" for g, n in zip(flagged["group"], flagged["note"]) if n]
    else:
        lines.append("Flagged groups: none.")
    outliers = audit.outliers
    if len(outliers):
        lines.append(f"Outliers ({len(outliers)}): single bearings off their own series (misprints?), left out of "
                     "the group statistics:")
        shown = pd.DataFrame({
            "designation": outliers["designation"].to_numpy(), "group": outliers["group"].to_numpy(),
            "published": outliers["n_thr_published"].map(lambda v: f"{v:.0f}").to_numpy(),
            "tables": outliers["n_thr_tables"].map(lambda v: f"{v:.0f}").to_numpy(),
            "deviation": outliers["deviation"].map(_percent).to_numpy(),
            "vs neighbours": outliers["local_deviation"].map(_percent).to_numpy()})
        lines += ["  " + line for line in shown.to_string(index=False).splitlines()]
    table = pd.DataFrame({
        "group": groups["group"].to_numpy(),
        "bearings": groups["bearings"].to_numpy(), "outliers": groups["outliers"].to_numpy(),
        "median": groups["median_deviation"].map(_percent).to_numpy(),
        "min": groups["min_deviation"].map(_percent).to_numpy(),
        "max": groups["max_deviation"].map(_percent).to_numpy(),
        "systematic": groups["systematic"].to_numpy(),
        "f0 table": groups["f0_table"].map(_f0).to_numpy(),
        "f0 implied": groups["f0_implied"].map(_f0).to_numpy()})
    lines += ["All series and size classes:", table.to_string(index=False)]
    lines += not_computed_lines(audit.not_computed)
    lines.append(f"rule: {SYSTEMATIC_RULE}")
    lines += [f"systematic: {g}" for g in flagged["group"]]
    return lines


def _csv(frame: pd.DataFrame):
    return lambda path: escape_formulas(frame).to_csv(path, index=False)


def write_coefficients(result: pd.DataFrame, out_dir, *, force: bool = False, inputs=()) -> list[Path]:
    """``coefficients.csv`` in ``out_dir``, and ``excluded.csv`` (column ``reason``, a row each) where rows were
    excluded or an earlier run left one (replaced, so that it never lists another run's rows); each atomically,
    an existing file replaced only with ``force``."""
    writers = {"coefficients.csv": _csv(result)}
    excluded = list(result.attrs.get("excluded", []))
    if excluded or (Path(out_dir) / EXCLUDED_FILE).exists():
        writers[EXCLUDED_FILE] = _csv(pd.DataFrame({"reason": pd.Series(excluded, dtype=object)}))
    return write_outputs(out_dir, writers, force=force, inputs=inputs)


def write_reference_speeds(audit: ReferenceSpeedAudit, out_dir, *, force: bool = False, inputs=()) -> list[Path]:
    """``reference_speeds.csv``, ``reference_speed_series.csv`` and ``reference_speeds.png`` in ``out_dir``,
    each atomically; existing files are replaced only with ``force``."""
    writers = {"reference_speeds.csv": _csv(audit.bearings), "reference_speed_series.csv": _csv(audit.groups),
               "reference_speeds.png": lambda path: draw_reference_speeds(audit, path)}
    return write_outputs(out_dir, writers, force=force, inputs=inputs)


def unflagged_outside_the_band(audit: ReferenceSpeedAudit) -> dict[str, str]:
    """The groups whose median deviation lies outside the band ± the threshold but that are not flagged (too few
    bearings to judge, or no common direction), each with its deviation and the reason: group -> '+19.7% (3
    bearings: too few to judge)'. The figure draws them apart from the groups that agree. A series split into
    size classes is judged by its classes (its bearings belong to them), so it is not one of these."""
    groups = audit.groups
    outside = groups[~groups["systematic"].astype(bool) & groups["group"].isin(audit.bearings["group"])
                     & (groups["median_deviation"].abs().to_numpy(dtype=float) > audit.threshold)]
    return {row["group"]: f"{row['median_deviation']:+.1%}" + (f" ({row['note']})" if row["note"] else "")
            for row in outside.to_dict("records")}


#: characters of a legend line of the reference-speed figure (a longer entry is wrapped: the panels keep their width)
_LEGEND_WIDTH = 70


def _legend_text(text: str) -> str:
    return textwrap.fill(text, _LEGEND_WIDTH, subsequent_indent="  ")


def draw_reference_speeds(audit: ReferenceSpeedAudit, path, *, dpi: int = FIGURE_DPI) -> None:
    """Deviation against bore for every series, one panel per family, written as a PNG (150 dpi).

    Series and size classes that agree with the tables are grey; flagged
    groups are coloured and named in the legend with their implied f0;
    groups outside the band that are not flagged (too few bearings to judge)
    are dashed and named with their deviation and the reason;
    outliers are red crosses labelled with their designation; the band is
    ± the systematic threshold.
    """
    Figure = matplotlib_figure()
    from matplotlib.ticker import FixedLocator, NullFormatter, ScalarFormatter

    bearings = audit.bearings[np.isfinite(audit.bearings["deviation"].to_numpy(dtype=float))]
    families = list(dict.fromkeys(bearings["family"]))
    if not families:
        families = ["(no bearing computed)"]
    fig = Figure(figsize=(11.0, 2.9 * len(families) + 0.6), dpi=dpi, layout="constrained")
    axes = fig.subplots(len(families), 1, squeeze=False, sharex=True)[:, 0]
    flagged = audit.flagged
    unflagged = unflagged_outside_the_band(audit)
    palette = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan"]
    colour = 0
    for ax, family in zip(axes, families):
        mine = bearings[bearings["family"] == family]
        ax.axhspan(-audit.threshold * 100, audit.threshold * 100, color="0.9", zorder=0,
                   label=f"±{audit.threshold:.1%}: agrees with the tables")
        ax.axhline(0.0, color="0.5", lw=0.6, zorder=1)
        agreeing, unjudged = [], []
        for group, rows in mine.groupby("group", sort=False):
            rows = rows.sort_values("d")
            use = rows[~rows["outlier"]]
            flag = flagged[flagged["group"] == group]
            per_bore = use.groupby("d")["deviation"].median() * 100
            if len(flag):
                f = flag.iloc[0]
                c = palette[colour % len(palette)]
                colour += 1
                label = (f"{f['series']} {f['subgroup']}".strip() + f": {f['median_deviation']:+.1%}, f0 "
                         f"{f['f0_table']:.2f} → {f['f0_implied']:.2f} [{f['f0_implied_low']:.2f}, "
                         f"{f['f0_implied_high']:.2f}]" + ("" if f["single_f0"] else ", spread: no single f0"))
                ax.plot(per_bore.index, per_bore.to_numpy(), "-o", color=c, lw=1.8, ms=3.5, label=label, zorder=3)
            else:
                name = str(rows["series"].iloc[0]) + (f" {rows['subgroup'].iloc[0]}" if rows["subgroup"].iloc[0]
                                                      else "")
                outside = group in unflagged
                if outside:
                    unjudged.append(f"{name} {unflagged[group]}")
                else:
                    agreeing.append(name)
                ax.plot(per_bore.index, per_bore.to_numpy(), "--o" if outside else "-", color="0.3" if outside
                        else "0.55", lw=0.9, ms=3, mfc="none", zorder=2, label="_nolegend_")  # (a point: one bore)
        if agreeing:
            ax.plot([], [], "-", color="0.55", lw=0.9, label=_legend_text("agree: " + ", ".join(agreeing)))
        if unjudged:
            ax.plot([], [], "--o", color="0.3", lw=0.9, ms=3, mfc="none",
                    label="outside the band, not flagged:\n" + "\n".join(map(_legend_text, unjudged)))
        out = mine[mine["outlier"]]
        if len(out):
            ax.plot(out["d"], out["deviation"] * 100, "x", color="red", ms=7, mew=1.8, zorder=4,
                    label="outlier (left out)")
            for k, (_, r) in enumerate(out.sort_values("d").iterrows()):
                ax.annotate(r["designation"], (r["d"], r["deviation"] * 100), textcoords="offset points",
                            xytext=((5, 5), (5, -12), (5, 15))[k % 3], fontsize=7, color="red",
                            bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
        ax.set_xscale("log")
        ax.xaxis.set_major_locator(FixedLocator([1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000]))
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.tick_params(labelbottom=True)
        ax.set_title(f"{family}", fontsize=10, loc="left")
        ax.set_ylabel("deviation of n_θr [%]", fontsize=9)
        ax.grid(True, which="both", color="0.85", lw=0.5)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
        if len(mine):
            low, high = mine["deviation"].min() * 100, mine["deviation"].max() * 100
            pad = max(1.0, 0.08 * (high - low))
            ax.set_ylim(min(low, -audit.threshold * 100) - pad, max(high, audit.threshold * 100) + pad)
    axes[-1].set_xlabel("bore d [mm]")
    fig.suptitle("Thermal reference speed: n_θr(tables)/n_θr(published) − 1 against bore, per series", fontsize=11)
    fig.savefig(path, format="png")
