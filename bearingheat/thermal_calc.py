"""``bearingheat calc`` extension: the heat balance of every support (issue 3).

Optional input columns (any unit of the right dimension in the header):

=================  ===============  ==============================================================
column             catalogue unit   meaning
=================  ===============  ==============================================================
B                  mm               width (radial bearings): A_r = π·B·(D+d)
T                  mm               total width of tapered roller bearings: A_r = π·T·(D+d)
k_q                W/(mm^2*K)       heat transfer coefficient of the seat; default q_r/50 K
T_amb              degC             ambient temperature
T_bearing          degC             bearing (outer ring) temperature for n_per
V_oil              l/min            circulating oil flow
dT_oil             K                oil temperature rise; default T − T_amb (oil fed at ambient)
Q_E                W                external heat flowing INTO the bearing (negative: cooling)
nu40, nu100        mm^2/s           oil viscosity at 40 and 100 °C (ASTM D341 between them)
iso_vg             1                ISO VG grade instead of nu40/nu100; VI (default 95) overrides
n_G                1/min            limiting speed: n_per is capped at it (warning)
n_thr_catalogue    1/min            catalogue n_θr; n_per then uses it instead of the computed one
=================  ===============  ==============================================================

Output columns, each where its inputs are present: ``n_thr [1/min]`` (B or
T, C0), ``n_per [1/min]`` (T_bearing, T_amb), ``T_op [degC]`` and
``nu_op [mm^2/s]`` (T_amb; the operating temperature at the speed n),
``Q_S [W]`` and ``Q_L [W]`` (heat carried away at T_bearing, or at T_op
where T_bearing is not given).

When ``nu`` is left out and ``nu40``/``nu100`` or ``iso_vg`` are given,
:func:`prepare` fills it before the friction pass: at ``T_bearing`` where
the row gives it, otherwise at the operating temperature T_op solved at the
operating speed (this needs ``n`` and ``T_amb``). A ``nu`` the user gives
is kept as it is.
"""
from __future__ import annotations

import pandas as pd

from bearingheat.thermal import OPERATING_TEMPERATURE_LIMIT, fill_viscosity, heat_balance_rows

__all__ = ["INPUT_UNITS", "OUTPUT_UNITS", "prepare", "extend"]

#: input column -> catalogue unit (temperature differences in delta_degC, so '10 degC' is refused)
INPUT_UNITS = {
    "B": "mm", "T": "mm", "k_q": "W/(mm^2*K)", "T_amb": "degC", "T_bearing": "degC",
    "V_oil": "l/min", "dT_oil": "delta_degC", "Q_E": "W", "nu40": "mm^2/s", "nu100": "mm^2/s",
    "iso_vg": "1", "VI": "1", "n_G": "1/min", "n_thr_catalogue": "1/min",
}
#: output column -> unit
OUTPUT_UNITS = {
    "n_thr": "1/min", "n_per": "1/min", "T_op": "degC", "nu_op": "mm^2/s", "Q_S": "W", "Q_L": "W",
}


def prepare(frame: pd.DataFrame):
    """Fill ``nu`` from nu40/nu100 or iso_vg (at T_bearing, else at T_op); returns (frame, problems)."""
    return fill_viscosity(frame, viscosity_at="auto", t_limit=OPERATING_TEMPERATURE_LIMIT)


def extend(frame: pd.DataFrame, results: pd.DataFrame):
    """The heat balance columns of every row whose friction succeeded; returns (columns, problems)."""
    columns, problems = heat_balance_rows(frame, results, method="exact", t_limit=OPERATING_TEMPERATURE_LIMIT)
    columns.index = frame.index
    return columns, problems
