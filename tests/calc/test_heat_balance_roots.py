"""The heat balance of a model without a closed speed law: the generic bracketed root.

A model registered without a speed law is solved by bracketing. Declaring the
catalogue model itself that way must give the same n_per and T_op as its
exact 5/3 root (a first-principles check of both), and a model with another
speed law must give the speed that its own power formula balances.
"""
import dataclasses

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingheat.calc import models
from bearingheat.calc.table import calc
from bearingheat.kernels.roots import bracketed_root

ROWS = pd.DataFrame({
    "id": ["ball", "tapered", "roller"], "designation": ["6208", "30208-A", "NU208-E"],
    "d [mm]": [40, 40, 40], "D [mm]": [80, 80, 80], "B [mm]": [18, 18, 18], "T [mm]": [None, 19.75, None],
    "C0 [kN]": [18, 66, 53], "Y": [None, 1.6, None], "lubrication": ["oil_bath"] * 3,
    "n [1/min]": [1480, 310, 2900], "Fr [kN]": [3.2, 6.0, 4.0], "Fa [kN]": [0.9, 2.4, 0],
    "nu40 [mm^2/s]": [68] * 3, "nu100 [mm^2/s]": [8.6] * 3,
    "T_amb [degC]": [20] * 3, "T_bearing [degC]": [70] * 3,
})


@pytest.fixture
def generic_catalogue(monkeypatch):
    """The catalogue model once more, registered without its speed law."""
    twin = dataclasses.replace(models.MODELS["schaeffler"], name="catalogue_bracketed", speed_exponent=None)
    monkeypatch.setitem(models.MODELS, twin.name, twin)
    return twin.name


def test_bracketed_root_reproduces_the_exact_root(generic_catalogue):
    exact = calc(ROWS)
    bracketed = calc(ROWS.assign(model=generic_catalogue))
    assert exact["status"].tolist() == ["ok"] * 3
    assert bracketed["status"].tolist() == ["ok"] * 3
    for column in ("n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "MR [N*mm]", "Q_S [W]"):
        assert bracketed[column].to_numpy() == pytest.approx(exact[column].to_numpy(), rel=1e-9), column


def test_a_model_with_another_speed_law(monkeypatch):
    """M = c·n^0.6 (a SKF-like rolling term): n_per where N_R = π·n/30e3·c·n^0.6 equals the heat carried away."""
    base = models.MODELS["schaeffler"]
    c = 0.5

    def evaluate(supports, labels, f2_chart):
        results, problems = base.evaluate(supports, labels, f2_chart)
        MR = c * np.power(supports.n, 0.6)
        return {**results, "MR": MR, "NR": MR * supports.n / 9550.0}, problems

    monkeypatch.setitem(models.MODELS, "power_law", dataclasses.replace(base, name="power_law", evaluate=evaluate,
                                                                      speed_exponent=None))
    out = calc(ROWS.iloc[:1].assign(model="power_law"))
    Q = out["Q_S [W]"].iat[0] + out["Q_L [W]"].iat[0]    # at T_bearing, where n_per is defined
    n_per = out["n_per [1/min]"].iat[0]
    assert np.pi * n_per / 30.0 * 1e-3 * c * n_per ** 0.6 == pytest.approx(Q, rel=1e-9)
    assert n_per == pytest.approx((Q / (np.pi / 30.0 * 1e-3 * c)) ** (1 / 1.6), rel=1e-9)


def test_bracketed_root_kernel():
    x, status = bracketed_root(lambda x: x ** 3 - 8.0, np.array([0.0, 3.0, 2.0, -1.0]),
                               np.array([10.0, 10.0, 5.0, np.nan]))
    assert x[0] == pytest.approx(2.0, rel=1e-12) and x[2] == 2.0
    assert status.tolist() == [0, 1, 0, 2] and np.isnan(x[1]) and np.isnan(x[3])


@pytest.mark.parametrize("func, low, high, root", [
    (lambda x: x ** 3 - 8.0, 0.0, 10.0, 2.0),
    (lambda x: x ** 10 - 1.0, 0.0, 1.5, 1.0),  # strongly curved: the retained end stays many times
    (lambda x: np.exp(x) - 2.0, -5.0, 5.0, np.log(2.0)),
    (lambda x: 60.0 - x - 0.001 * x ** 2, -30.0, 150.0, (-1.0 + np.sqrt(1.0 + 0.24)) / 0.002),
])
def test_bracketed_root_converges_in_few_evaluations(func, low, high, root):
    """Chandrupatla's method keeps the bracket (the root is inside [low, high]) and reaches it to 1e-14 in 6-10
    steps on these brackets (after f at the two ends), the strongly curved x^10 - 1 included (the Illinois
    regula falsi used before took 8-17 steps here and 16 on the heat balance of the demo with oil data, where
    this takes 10; the Anderson-Björck variant 11 there, but 58 on x^10 - 1)."""
    calls = []

    def counted(x):
        calls.append(1)
        return func(x)

    x, status = bracketed_root(counted, np.array([low]), np.array([high]), rtol=1e-14)
    assert status.tolist() == [0] and low <= x[0] <= high
    assert x[0] == pytest.approx(root, rel=1e-13)
    assert len(calls) <= 2 + 10


@pytest.mark.parametrize("func", [
    lambda x: np.where(x < 1.0, -1.0, 1.0),  # a step: no interpolation helps
    lambda x: np.cbrt(x - 1.0),  # infinite slope at the root
    lambda x: (x - 1.0) ** 3,  # flat at the root
])
def test_bracketed_root_falls_back_to_bisection_on_rough_functions(func):
    """Where the last three points do not allow an interpolation the method bisects: rough functions still
    converge, in about as many steps as bisection (log2(7/1e-14) = 49)."""
    calls = []

    def counted(x):
        calls.append(1)
        return func(x)

    x, status = bracketed_root(counted, np.array([-2.0]), np.array([5.0]), rtol=1e-14)
    assert status.tolist() == [0] and x[0] == pytest.approx(1.0, rel=2e-14)
    assert len(calls) <= 2 + 60


@settings(max_examples=200, deadline=None)
@given(root=st.floats(-100.0, 100.0), rate=st.floats(1e-3, 10.0), sign=st.sampled_from([-1.0, 1.0]),
       below=st.floats(1e-3, 200.0), above=st.floats(1e-3, 200.0))
def test_bracketed_root_finds_the_root_of_monotone_functions(root, rate, sign, below, above):
    """f = ±(exp(rate·(x − root)) − 1) on [root − below, root + above]: the root found is inside the bracket and
    within the tolerance of the true one (or within 1e-12 where the root is near 0, where a relative tolerance
    cannot be met and the method ends after its iterations at the best end)."""
    low, high = np.array([root - below]), np.array([root + above])

    def f(x):
        with np.errstate(over="ignore"):  # (an end far above the root: f = ±inf there, still of its sign)
            return sign * np.expm1(rate * (x - root))

    x, status = bracketed_root(f, low, high, rtol=1e-14)
    assert status.tolist() == [0] and low[0] <= x[0] <= high[0]
    assert abs(x[0] - root) <= 1e-13 * max(abs(root), 1.0)
