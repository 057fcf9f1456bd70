"""The heat balance's roots for all rows at once: the lowest equilibrium, and a bracket that closes quickly."""
import numpy as np

from bearingheat.calc.thermal import lowest_operating_temperature
from bearingheat.kernels.roots import bracketed_root


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
