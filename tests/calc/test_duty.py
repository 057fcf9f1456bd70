"""Duty cycles: the gearbox example against a hand calculation, and the refusals."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.calc.duty import duty_cycle, has_duty_cycle
from bearingheat.errors import DutyCycleError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gearbox_duty_cycle.csv"
SHARES = {"full load": 0.2, "part load": 0.5, "idle": 0.3}


@pytest.fixture(scope="module")
def results():
    return bh.calc(pd.read_csv(EXAMPLE))


def test_the_example_summary_is_the_hand_weighted_mean(results):
    summary = bh.duty_cycle(results)
    assert summary["support"].tolist() == ["input shaft A", "input shaft B"]
    assert summary["designation"].tolist() == ["6208", "NU208-E"]
    for support, row in zip(summary["support"], summary.itertuples(index=False)):
        mine = results[results["support"] == support]
        weights = mine["case"].map(SHARES).to_numpy()
        MR = sum(w * m for w, m in zip(weights, mine["MR [N*mm]"]))
        NR = sum(w * p for w, p in zip(weights, mine["NR [W]"]))
        assert row[3] == pytest.approx(MR, rel=1e-12) and row[4] == pytest.approx(NR, rel=1e-12)
        assert row[5] == pytest.approx(NR * 1.0, rel=1e-12)  # W over one hour: W*h
        hottest = mine["T_op [degC]"].idxmax()
        assert row[6] == mine.loc[hottest, "T_op [degC]"] and row[7] == mine.loc[hottest, "case"]
        margins = (mine["n_per [1/min]"] / mine["n [rpm]"]).to_numpy()
        assert row[8] == pytest.approx(margins.min(), rel=1e-12)
        assert row[9] == mine["case"].iloc[int(np.argmin(margins))]
    # the NU208-E idles at 0.4 kN, below its minimum load C0/60 = 883 N (Schaeffler HR 1, p. 364): its support
    # says which case warns
    assert summary["status"].tolist() == ["ok", "warning"]
    assert summary["message"].tolist() == ["", "case(s) with a warning: idle"]


def test_one_row_from_first_principles(results):
    # 6208 at full load (Schaeffler catalogue, «Трение и нагрев»): P0 = max(0.6 Fr + 0.5 Fa, Fr) = 3200 N,
    # f1 = 0.0009 (P0/C0)^0.5 with C0 = 18 kN (bearing table), P1 = max(3.3 Fa - 0.1 Fr, Fr) = 3200 N,
    # M1 = f1 P1 dM with dM = (40 + 80)/2 mm
    f1 = 0.0009 * (3200.0 / 18000.0) ** 0.5
    assert results.loc[0, "M1 [N*mm]"] == pytest.approx(f1 * 3200.0 * 60.0, rel=1e-12)
    # NR = MR n / 9550 as the catalogue writes it (MR in N*mm, n in 1/min)
    assert results.loc[0, "NR [W]"] == pytest.approx(results.loc[0, "MR [N*mm]"] * 1480 / 9550, rel=1e-12)


def test_durations_weigh_like_shares(results):
    hours = results.drop(columns="time_share").assign(**{"duration [min]": results["case"].map(SHARES) * 600})
    by_time, by_share = duty_cycle(hours), duty_cycle(results)
    np.testing.assert_allclose(by_time["NR_mean [W]"], by_share["NR_mean [W]"], rtol=1e-12)
    # 600 min of cycle = 10 h: the energy of the cycle is 10 h times the mean power
    np.testing.assert_allclose(by_time["energy [W*h]"], 10.0 * by_share["NR_mean [W]"], rtol=1e-12)


def test_a_case_in_error_leaves_its_support_without_means(results):
    broken = results.copy()
    broken.loc[1, "status"] = "error"
    summary = duty_cycle(broken)
    assert summary["status"].tolist() == ["error", "warning"]  # (input shaft B: the idle case's minimum load)
    assert summary["message"].iat[0] == "case(s) in error, so the support has no means: part load"
    assert np.isnan(summary["MR_mean [N*mm]"].iat[0]) and np.isfinite(summary["MR_mean [N*mm]"].iat[1])


@pytest.mark.parametrize("change, message", [
    (lambda t: t.assign(time_share=[0.2, 0.5, 0.2, 0.2, 0.5, 0.3]),
     "support 'input shaft A': the time_share values of its cases (full load 0.2, part load 0.5, idle 0.2) sum to "
     "0.9, not 1 (within 0.1%)"),
    (lambda t: t.assign(time_share=[0.2, 0.9, -0.1, 0.2, 0.5, 0.3]),
     "support 'input shaft A', case 'idle': time_share is -0.1, negative; give a fraction from 0 to 1"),
    (lambda t: t.assign(designation=["6208", "6208", "6209", "NU208-E", "NU208-E", "NU208-E"]),
     "support 'input shaft A': its rows name different bearings in 'designation' (6208, 6209); one support is one "
     "bearing"),
    (lambda t: t.assign(**{"duration [h]": 1.0}),
     "a duty cycle needs one of the columns 'time_share' (fractions summing to 1 per support) or 'duration [h]', "
     "not both"),
    (lambda t: t.drop(columns="support"),
     "no 'support' column: a duty cycle names the physical bearing of each row in 'support' and its cases in "
     "'case'"),
])
def test_refusals(results, change, message):
    with pytest.raises(DutyCycleError) as info:
        duty_cycle(change(results))
    assert str(info.value) == message


def test_has_duty_cycle():
    assert has_duty_cycle(pd.read_csv(EXAMPLE)) and not has_duty_cycle(pd.DataFrame({"id": ["a"]}))


def test_a_support_column_blank_in_every_row_is_no_duty_cycle():
    """An entirely blank support column (a CSV written from the template or example workbook, whose unused duty
    columns a workbook already skipped) is no duty cycle; one support named in one row is; a table of headers
    only (the columns a fleet's files hold) is judged by its headers."""
    blank = pd.DataFrame({"support": [None, "", "  ", np.nan], "n [rpm]": [1000, 2000, 3000, 4000]})
    assert not has_duty_cycle(blank)
    assert not has_duty_cycle(pd.DataFrame({"support": [np.nan, np.nan], "time_share": [np.nan, np.nan]}))
    assert has_duty_cycle(blank.assign(support=[None, "A", None, None]))
    assert has_duty_cycle(pd.DataFrame(columns=["support", "n [rpm]"]))
    assert not has_duty_cycle(pd.DataFrame(columns=["id", "n [rpm]"]))
