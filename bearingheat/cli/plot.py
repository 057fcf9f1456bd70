"""``bearingheat plot``: heat generated and heat carried away of one bearing, against speed and temperature."""
from __future__ import annotations

import sys
from pathlib import Path

from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.cli import UsageError, add_csv_arguments
from bearingheat.cli.options import add_f2_chart, add_force, add_output, add_quiet
from bearingheat.errors import F2ChartError, InputError
from bearingheat.io.files import atomic_write, safe_output
from bearingheat.io.reports.thermal import FIGURE_FORMATS, draw_heat_balance, figure_format, heat_balance_curves
from bearingheat.io.tables import read_csv


DESCRIPTION = """\
Draws, for one support of a calc table (CSV, the columns of 'bearingheat calc'),
two panels of the heat balance N_R + Q_E = Q_S + Q_L (Schaeffler catalogue HR 1, edition 2006):

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
Q_E, C0 (for n_thr). An axially loaded cylindrical roller bearing needs f2, or
--f2-chart: the friction heat then takes f2 at each speed and temperature of
the curves, and is not drawn where nu*n*dM lies off the chart.

  bearingheat plot supports.csv --row 0 -o heat_balance.png
  bearingheat plot supports.csv --id "spindle rear" -o heat_balance.png

The figure format follows the ending of -o (.png, .svg, .pdf ...). An existing
file is replaced only with --force; the file is written atomically. It prints
'wrote FILE', and a warning about the row to stderr; with -q only errors.

Exit codes: 0 plot written, 1 the row is in error (the message goes to stderr),
2 unusable input (missing file, missing column, no such row) or a file fault.
"""


def add_arguments(parser) -> None:
    parser.add_argument("table", help="CSV table of supports (calc columns with units in the headers)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--row", type=int, default=None, help="row position (0 = first data row); default 0")
    which.add_argument("--id", default=None, help="the row whose 'id' column has this text")
    suffixes = [f".{suffix}" for suffix in FIGURE_FORMATS]
    add_output(parser, f"{', '.join(suffixes[:-1])} or {suffixes[-1]}", required=True)
    add_force(parser)
    add_f2_chart(parser)
    add_csv_arguments(parser)
    add_quiet(parser)


def run(args) -> int:
    path = Path(args.table)
    if not path.is_file():
        raise UsageError(f"{path}: no such file")
    try:
        fmt = figure_format(args.output)
        inputs = (path,) if args.f2_chart is None else (path, Path(args.f2_chart))
        target = safe_output(args.output, force=args.force, inputs=inputs)
        f2_chart = F2Chart.from_csv(args.f2_chart) if args.f2_chart is not None else None
        table = read_csv(path, sep=args.sep, decimal=args.decimal)
        table = _select_row(table, args.row, args.id, path)
        curves = heat_balance_curves(table, f2_chart=f2_chart)
    except (InputError, F2ChartError) as exc:
        raise UsageError(str(exc)) from exc
    if curves["status"] == "error":
        print(f"bearingheat plot: row in error: {curves['message']}", file=sys.stderr)
        return 1
    atomic_write(target, lambda temp: draw_heat_balance(curves, temp, format=fmt))
    if not args.quiet:
        if curves["message"]:
            print(f"bearingheat plot: warning: {curves['message']}", file=sys.stderr)
        print(f"wrote {args.output}")
    return 0


def _select_row(table, row, row_id, path):
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
