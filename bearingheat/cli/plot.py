"""``bearingheat plot``: heat generated and heat carried away of one bearing, against speed and temperature."""
from __future__ import annotations

HELP = "plot friction heat and heat carried away of one support against speed and temperature (PNG)"

DESCRIPTION = """\
Draws, for one support of a calc table (CSV, the columns of 'bearingheat calc'),
two panels of the heat balance N_R + Q_E = Q_S + Q_L (issue 3, after Schaeffler HR 1):

  left   against speed n, at the bearing temperature T_bearing (or at the
         operating temperature T_op where T_bearing is not given): the friction
         heat N_R(n) and the heat carried away Q_S + Q_L - Q_E; their crossing is
         the permissible speed n_per, marked.
  right  against temperature, at the operating speed n: the friction heat with
         the viscosity at that temperature plus Q_E, and Q_S(T) + Q_L(T); their
         crossing is the operating temperature T_op, marked.

The row needs: designation (or type and series), d [mm], D [mm], B [mm] (or T [mm]
for tapered roller bearings), lubrication, n [1/min], Fr/Fa as needed, T_amb [degC],
and nu [mm^2/s] or nu40/nu100 or iso_vg. Optional: T_bearing, k_q, V_oil, dT_oil,
Q_E, C0 (for n_thr).

  bearingheat plot supports.csv --row 0 -o heat_balance.png
  bearingheat plot supports.csv --id "spindle rear" -o heat_balance.png

Exit codes: 0 plot written, 1 the row is in error (the message goes to stderr),
2 unusable input (missing file, missing column, no such row).
"""


def add_arguments(parser) -> None:
    parser.add_argument("table", help="CSV table of supports (calc columns with units in the headers)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--row", type=int, default=None, help="row position (0 = first data row); default 0")
    which.add_argument("--id", default=None, help="the row whose 'id' column has this text")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")


def run(args) -> int:
    import sys
    from pathlib import Path

    import pandas as pd

    from bearingheat.cli import UsageError
    from bearingheat.frame import InputError

    path = Path(args.table)
    if not path.is_file():
        raise UsageError(f"{path}: no such file")
    try:
        table = pd.read_csv(path, skipinitialspace=True)
    except (pd.errors.ParserError, UnicodeDecodeError, pd.errors.EmptyDataError) as exc:
        raise UsageError(f"{path}: not a readable CSV ({exc})") from exc
    table = _select_row(table, args.row, args.id, path)
    try:
        curves = heat_balance_curves(table)
    except InputError as exc:
        raise UsageError(str(exc)) from exc
    if curves["status"] == "error":
        print(f"bearingheat plot: row in error: {curves['message']}", file=sys.stderr)
        return 1
    draw_heat_balance(curves, args.output)
    if curves["message"]:
        print(f"bearingheat plot: warning: {curves['message']}", file=sys.stderr)
    print(f"wrote {args.output}")
    return 0


def _select_row(table, row, row_id, path):
    from bearingheat.cli import UsageError

    if row_id is not None:
        id_columns = [c for c in table.columns if str(c).split("[")[0].strip() == "id"]
        if not id_columns:
            raise UsageError(f"{path}: --id needs an 'id' column")
        hits = table[table[id_columns[0]].astype(str).str.strip() == row_id.strip()]
        if hits.empty:
            raise UsageError(f"{path}: no row with id {row_id!r}")
        return hits.iloc[[0]]
    position = 0 if row is None else row
    if not 0 <= position < len(table):
        raise UsageError(f"--row {position}: the table has rows 0 to {len(table) - 1}")
    return table.iloc[[position]]


def heat_balance_curves(table, points: int = 200) -> dict:
    """Curves of the heat balance of the first row of ``table`` (calc columns with units) in catalogue units."""
    import numpy as np

    from bearingheat import thermal
    from bearingheat.frame import _require, to_catalogue_units
    from bearingheat.model import compute_supports

    converted = to_catalogue_units(table.reset_index(drop=True))
    frame, problems = thermal.fill_viscosity(converted.frame)
    _require(frame)
    results = compute_supports(frame, labels=converted.labels)
    columns, more = thermal.heat_balance_rows(frame, results)
    messages = [m for m in [results["message"].iloc[0]] if m] + [m for _, _, m in problems + more]
    status = results["status"].iloc[0]
    if any(level == "error" for _, level, _ in problems + more):
        status = "error"
    out = {"status": status, "message": "; ".join(messages), "label": _label(table)}
    if status == "error":
        return out
    if "T_amb" not in frame.columns:
        out.update(status="error", message="; ".join(messages + ["T_amb [degC]: missing; the plot needs the "
                                                                  "ambient temperature"]))
        return out
    details, k_q, T_amb, Q_E, Q_S, Q_L = thermal._heat_flow_setup(frame)
    if np.isnan(details["A_r"].iloc[0]) or np.isnan(T_amb[0]):
        out.update(status="error", message=out["message"] or "the heat flow area A_r cannot be computed")
        return out
    A, B, _ = thermal._walther_columns(frame)
    nu_at = thermal._viscosity_of_rows(frame, A, B)
    f0 = float(results["f0"].iloc[0])
    load_torque = float(results["M1"].iloc[0]) + float(np.nan_to_num(results["M2"].iloc[0]))
    dM = float((frame["d"].iloc[0] + frame["D"].iloc[0]) / 2.0)
    n = float(frame["n"].iloc[0])
    T_op = float(columns["T_op"].iloc[0])
    n_per = float(columns["n_per"].iloc[0]) if "n_per" in columns.columns else float("nan")
    T_bearing = float(frame["T_bearing"].iloc[0]) if "T_bearing" in frame.columns else float("nan")
    theta = T_bearing if not np.isnan(T_bearing) else T_op
    nu_theta = float(nu_at(np.array([theta]))[0]) if not np.isnan(theta) else float("nan")
    carried_theta = float(Q_S(np.array([theta]))[0] + Q_L(np.array([theta]))[0] - Q_E[0])
    n_cross = float(thermal.balance_speed(f0, nu_theta, dM, load_torque, carried_theta)) if carried_theta > 0 \
        else float("nan")
    n_top = 1.5 * np.nanmax([n, n_cross, n_per, 1.0])
    speeds = np.linspace(0.0, n_top, points)
    temperatures = np.linspace(T_amb[0], thermal.OPERATING_TEMPERATURE_LIMIT, points)
    ones = np.ones(points)
    out.update(
        n=n, n_per=n_per, n_cross=n_cross, theta=theta, T_op=T_op, T_amb=float(T_amb[0]),
        speeds=speeds,
        friction_vs_speed=thermal.friction_heat(f0, nu_theta, speeds, dM, load_torque),
        carried_vs_speed=carried_theta * ones,
        temperatures=temperatures,
        friction_vs_temperature=thermal.friction_heat(f0, nu_at(temperatures), n * ones, dM, load_torque) + Q_E[0],
        carried_vs_temperature=Q_S(temperatures) + Q_L(temperatures),
        heat_at_T_op=float(Q_S(np.array([T_op]))[0] + Q_L(np.array([T_op]))[0]) if not np.isnan(T_op) else np.nan,
    )
    return out


def _label(table) -> str:
    for name in ("id", "designation"):
        hits = [c for c in table.columns if str(c).split("[")[0].strip() == name]
        if hits:
            return str(table[hits[0]].iloc[0])
    return "support"


def draw_heat_balance(curves: dict, path) -> None:
    """Write the two panels of :func:`heat_balance_curves` to a PNG file."""
    import math

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.6), dpi=90)
    left.plot(curves["speeds"], curves["friction_vs_speed"], label="friction heat N_R")
    left.plot(curves["speeds"], curves["carried_vs_speed"], "--", label="carried away Q_S + Q_L − Q_E")
    if not math.isnan(curves["n_cross"]):
        left.plot([curves["n_cross"]], [curves["carried_vs_speed"][0]], "o", color="black")
        left.annotate(f"{curves['n_cross']:.0f} 1/min", (curves["n_cross"], curves["carried_vs_speed"][0]),
                      textcoords="offset points", xytext=(6, -14))
    left.set_xlabel("speed n [1/min]")
    left.set_ylabel("heat flow [W]")
    left.set_title(f"at {curves['theta']:.1f} °C", fontsize=10)
    left.legend(fontsize=8, loc="upper left")
    right.plot(curves["temperatures"], curves["friction_vs_temperature"], label="N_R(ν(T)) + Q_E")
    right.plot(curves["temperatures"], curves["carried_vs_temperature"], "--", label="Q_S(T) + Q_L(T)")
    if not math.isnan(curves["T_op"]):
        right.plot([curves["T_op"]], [curves["heat_at_T_op"]], "o", color="black")
        right.annotate(f"T_op = {curves['T_op']:.1f} °C", (curves["T_op"], curves["heat_at_T_op"]),
                       textcoords="offset points", xytext=(6, -14))
    right.set_xlabel("bearing temperature [°C]")
    right.set_title(f"at n = {curves['n']:.0f} 1/min", fontsize=10)
    right.legend(fontsize=8, loc="upper left")
    fig.suptitle(f"Heat balance of {curves['label']}", fontsize=11)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
