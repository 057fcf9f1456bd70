"""The heat balance's roots for all rows at once: the lowest equilibrium, and a bracket that closes quickly."""
import math
from pathlib import Path

import numpy as np
import pandas as pd

from bearingheat.calc.thermal import lowest_operating_temperature
from bearingheat.kernels.roots import bracketed_root

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_the_lowest_of_three_equilibria_is_found_where_bisection_of_the_whole_range_finds_the_highest():
    # balance -(T-40)(T-70)(T-100): heating below 40 °C, cooling 40..70, heating 70..100, cooling above 100.
    # Bisection of [0, 150] looks at 75 °C first (balance +4375 W, still heating) and ends at 100 °C;
    # a bearing warming up from ambient stops at the first equilibrium, 40 °C.
    def balance(T):
        return -(T - 40.0) * (T - 70.0) * (T - 100.0)

    T, status = lowest_operating_temperature(balance, np.array([0.0, 0.0, 50.0, 45.0]),
                                             np.array([150.0, 30.0, 150.0, 60.0]))
    assert status.tolist() == [0, 1, 0, -1]  # 0..30 heats throughout; 45..60 cools throughout
    np.testing.assert_allclose(T[[0, 2]], [40.0, 100.0], rtol=1e-13)  # from 50 °C the first is 100 °C
    assert np.isnan(T[[1, 3]]).all()


def test_a_row_in_balance_at_the_lower_end_and_a_row_without_a_balance():
    def balance(T):  # row 1 cools from 20 °C on; row 2 has no balance (a missing input)
        return (20.0 - T) * np.array([1.0, np.nan])

    T, status = lowest_operating_temperature(balance, np.array([20.0, 0.0]), np.array([150.0, 150.0]))
    assert status.tolist() == [0, 2]
    assert T[0] == 20.0 and np.isnan(T[1])


def test_a_secant_landing_on_the_root_closes_the_bracket_at_once():
    # f(x) = 0.7 (22.5 - x) + 1.3, root 22.5 + 1.3/0.7 = 24.357142857...: the first secant step lands on the
    # root to within rounding; the bracket used to be closed by halving from the other end (44 calls of f)
    calls = []

    def f(x):
        calls.append(1)
        return 0.7 * (22.5 - x) + 1.3

    x, status = bracketed_root(f, np.array([0.0]), np.array([100.0]))
    assert status.tolist() == [0]
    np.testing.assert_allclose(x, [22.5 + 1.3 / 0.7], rtol=1e-12)
    assert len(calls) <= 6


def test_rows_with_one_root_skip_the_scan_and_give_the_same_temperature(monkeypatch):
    """With the catalogue speed law (N_R falls with T through ν, Q_S and Q_L rise) the balance has one root:
    the ends of the range bracket it. The demo's rows give ν itself (no oil data), so N_R does not depend on T:
    the friction power is computed once, and the balance is a straight line whose root is the secant of the
    ends. T_op is the same as with the full 24-cell scan and refinement, to 1e-12; the balance is evaluated
    twice (the ends) instead of 27 times (25 grid points, 2 refining steps)."""
    import bearingheat as bh
    from bearingheat.calc import models, operating_temperature

    table = pd.read_csv(EXAMPLES / "gearbox_shaft.csv")
    power_calls, balance_calls = [], []
    original_power = models.FrictionPower.__call__

    def counted_power(self, *args, **options):
        power_calls.append(1)
        return original_power(self, *args, **options)

    def counted(balance):
        def wrapped(*args, **options):
            balance_calls.append(1)
            return balance(*args, **options)
        return wrapped

    monkeypatch.setattr(models.FrictionPower, "__call__", counted_power)
    original_search = operating_temperature.lowest_operating_temperature

    def fast_search(balance, T_low, T_high, **options):
        return original_search(counted(balance), T_low, T_high, **options)

    def scan_every_row(balance, T_low, T_high, **options):
        return original_search(counted(balance), T_low, T_high, cells=options.get("cells", 24), single_root=False)

    monkeypatch.setattr(operating_temperature, "lowest_operating_temperature", fast_search)
    fast = bh.calc(table)
    fast_counts = len(power_calls), len(balance_calls)
    monkeypatch.setattr(operating_temperature, "lowest_operating_temperature", scan_every_row)
    power_calls.clear(), balance_calls.clear()
    scanned = bh.calc(table)
    assert fast_counts == (1, 2) and (len(power_calls), len(balance_calls)) == (1, 27)
    np.testing.assert_allclose(fast["T_op [degC]"], scanned["T_op [degC]"], rtol=1e-12)
    assert fast["T_op [degC]"].notna().sum() >= 5


def test_a_single_root_row_does_not_depend_on_the_rows_beside_it():
    """A row marked single_root is refined between the ends of the range, with or without rows that need the
    scan beside it (calc in blocks gives the same T as one call)."""
    def balance(T):  # row 0 falls strictly (root 60 °C); row 1 has three equilibria
        return np.array([60.0 - T[0], -(T[1] - 40.0) * (T[1] - 70.0) * (T[1] - 100.0)])

    def one_row(T):
        return 60.0 - T

    together, status = lowest_operating_temperature(balance, np.array([0.0, 0.0]), np.array([150.0, 150.0]),
                                                    single_root=np.array([True, False]))
    alone, _ = lowest_operating_temperature(one_row, np.array([0.0]), np.array([150.0]), single_root=True)
    assert status.tolist() == [0, 0] and together[0] == alone[0]
    np.testing.assert_allclose(together, [60.0, 40.0], rtol=1e-13)


def test_rows_of_a_model_without_the_speed_law_keep_the_scan(monkeypatch):
    """SKF rows (N_R not ∝ (ν·n)^(2/3)) may have several equilibria: the whole range is scanned."""
    import bearingheat as bh
    from bearingheat.calc import operating_temperature

    table = pd.read_csv(EXAMPLES / "gearbox_shaft_skf.csv")
    marked = []
    original = operating_temperature.lowest_operating_temperature

    def recorded(balance, T_low, T_high, **options):
        marked.append(np.asarray(options["single_root"]))
        return original(balance, T_low, T_high, **options)

    monkeypatch.setattr(operating_temperature, "lowest_operating_temperature", recorded)
    bh.calc(table, model="skf")
    assert marked and not any(m.any() for m in marked)


def test_rows_with_oil_data_beside_rows_without_give_the_scanned_temperatures(monkeypatch):
    """Rows whose ν follows T (an ISO VG oil: Walther) are refined by bracketing, rows that give ν take the secant
    of a straight line; in one table together each row's T_op is the full scan's to 1e-12, and the same as when
    the row is computed alone."""
    import bearingheat as bh
    from bearingheat.calc import operating_temperature

    table = pd.read_csv(EXAMPLES / "gearbox_shaft.csv")
    table = table[table["arrangement"] == "single"].reset_index(drop=True)
    table["iso_vg"] = np.where(np.arange(len(table)) % 2 == 0, 68.0, np.nan)
    table.loc[table["iso_vg"].notna(), "nu [mm^2/s]"] = np.nan
    fast = bh.calc(table)
    alone = pd.concat([bh.calc(table.iloc[[i]]) for i in range(len(table))])
    original_search = operating_temperature.lowest_operating_temperature

    def scan_every_row(balance, T_low, T_high, **options):
        return original_search(balance, T_low, T_high, cells=options.get("cells", 24), single_root=False)

    monkeypatch.setattr(operating_temperature, "lowest_operating_temperature", scan_every_row)
    scanned = bh.calc(table)
    assert fast["T_op [degC]"].notna().all()
    assert (fast["nu_at"] == np.where(table["iso_vg"].notna(), "T_op", "given")).all()
    np.testing.assert_allclose(fast["T_op [degC]"], scanned["T_op [degC]"], rtol=1e-12)
    np.testing.assert_allclose(fast["T_op [degC]"], alone["T_op [degC]"], rtol=1e-12)


def test_the_friction_power_computed_once_gives_the_bits_of_the_balance_at_every_temperature():
    """Where no row's ν follows T, N_R + Q_E is summed once and the balance subtracts Q_S and Q_L from it: the
    same operations in the same order as the balance that evaluates N_R at every temperature. T_op and status
    of the demo's rows are bit for bit those of the general balance (forced by marking one row's ν as varying;
    that row itself then takes the scan instead of the secant)."""
    from bearingheat.calc import heat_flows, operating_temperature
    from bearingheat.calc.fill import fill_from_catalogue
    from bearingheat.calc.models import compute_supports
    from bearingheat.calc.conversion import to_catalogue_units

    table = pd.read_csv(EXAMPLES / "gearbox_shaft.csv")
    converted = to_catalogue_units(table)
    frame = fill_from_catalogue(converted.frame, converted.labels)[0].reset_index(drop=True)
    results = compute_supports(frame)
    _, _, T_amb, Q_E, Q_S, Q_L = heat_flows.heat_flow_setup(frame)
    A, B, _ = heat_flows.walther_columns(frame)
    nu_at = heat_flows.viscosity_of_rows(frame, A, B)
    constant = np.zeros(len(frame), dtype=bool)
    marked = constant.copy()
    marked[0] = True
    once = operating_temperature.operating_point(frame, results, nu_at, constant, Q_S, Q_L, Q_E, T_amb, 200.0)
    every = operating_temperature.operating_point(frame, results, nu_at, marked, Q_S, Q_L, Q_E, T_amb, 200.0)
    assert np.array_equal(once.T[1:], every.T[1:], equal_nan=True) and np.isfinite(once.T[1:]).sum() >= 4
    assert np.array_equal(once.status, every.status)
    theta = np.array([30.0, 60.0, 90.0])
    for T in theta:
        at_T = np.full(len(frame), T)
        assert np.array_equal(once.balance(at_T), every.balance(at_T), equal_nan=True)


def test_the_lowest_root_below_the_regime_step_of_m0_is_not_passed_over():
    """A 6208 at 100 1/min with ISO VG 68 oil (68 and 8.6 mm²/s at 40 and 100 °C): ν·n falls through 2000 at
    T_step = 69.949 °C, where the printed M0 steps up by 0.79 % (160 against 2000^(2/3) = 158.74). As T_amb
    rises the equilibrium rises with it until it reaches T_step, and only then jumps above it; a root search
    over the whole range found the crossing above the step while the one below still existed (T_amb
    69.564749 to 69.5648 °C gave T_op 0.26 mK too high)."""
    import bearingheat as bh

    # Walther's line through the two points, by hand: log10 log10(ν + 0.7) = A − B·log10(T / K)
    y40, y100 = (math.log10(math.log10(nu + 0.7)) for nu in (68.0, 8.6))
    x40, x100 = math.log10(313.15), math.log10(373.15)
    B = (y40 - y100) / (x100 - x40)
    A = y40 + B * x40
    T_step = 10 ** ((A - math.log10(math.log10(2000.0 / 100.0 + 0.7))) / B) - 273.15
    assert round(T_step, 3) == 69.949

    T_amb = np.linspace(69.5646, 69.5650, 401)  # steps of 1 µK
    rows = pd.DataFrame({"designation": "6208", "d [mm]": 40.0, "D [mm]": 80.0, "B [mm]": 18.0, "C0 [kN]": 18.0,
                         "lubrication": "oil_bath", "n [rpm]": 100.0, "Fr [kN]": 3.2, "Fa [kN]": 0.0,
                         "nu40 [mm^2/s]": 68.0, "nu100 [mm^2/s]": 8.6, "T_amb [degC]": T_amb})
    T_op = bh.calc(rows)["T_op [degC]"].to_numpy()
    assert (np.diff(T_op) > 0).all()
    above = np.flatnonzero(T_op > T_step)
    assert 0 < above[0] < len(T_op) - 1  # the sweep crosses the step
    last_below, step = T_op[above[0] - 1], T_op[above[0] - 1] - T_op[above[0] - 2]
    assert 0 < T_step - last_below <= step  # the root below the step ran up to it before the jump
