"""Uncertainty bands of f0 and f1 carried to MR, NR, n_thr, n_per and T_op."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.analysis.audit import audit_coefficients
from synthetic_torque import measured_set

DEMO = Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft.csv"


@pytest.fixture(scope="module")
def demo():
    return pd.read_csv(DEMO).assign(f0_rel_unc=0.2, f1_rel_unc=0.1)


def test_the_torque_band_is_the_hand_quadrature(demo):
    out = bh.calc(demo)
    # MR = M0 + M1 (+ M2) is linear in f0 and f1: half-width sqrt((0.2 M0)^2 + (0.1 M1)^2)
    half = np.sqrt((0.2 * out["M0 [N*mm]"]) ** 2 + (0.1 * out["M1 [N*mm]"]) ** 2)
    np.testing.assert_allclose(out["MR_high [N*mm]"] - out["MR [N*mm]"], half, rtol=1e-9)
    np.testing.assert_allclose(out["MR [N*mm]"] - out["MR_low [N*mm]"], half, rtol=1e-9)
    np.testing.assert_allclose(out["NR_high [W]"] / out["MR_high [N*mm]"], out["NR [W]"] / out["MR [N*mm]"],
                               rtol=1e-12)


def test_linearised_and_sampled_bands_agree():
    # small uncertainties, where the linearisation holds (n_per goes as about f0^-0.6: a 20 % secant is
    # 15 % off the sampled band)
    demo = pd.read_csv(DEMO).assign(f0_rel_unc=0.05, f1_rel_unc=0.03)
    linear = bh.calc(demo)
    sampled = bh.calc(demo, uncertainty="sampled")
    for name in ("MR [N*mm]", "n_per [1/min]", "T_op [degC]", "n_thr [1/min]"):
        stem, unit = name.split(" ")
        width_l = (linear[f"{stem}_high {unit}"] - linear[f"{stem}_low {unit}"]).to_numpy()
        width_s = (sampled[f"{stem}_high {unit}"] - sampled[f"{stem}_low {unit}"]).to_numpy()
        finite = np.isfinite(width_l)
        # 400 draws: the percentiles scatter a few percent; the linearisation is a secant
        np.testing.assert_allclose(width_s[finite], width_l[finite], rtol=0.12, err_msg=name)


def test_bands_are_ordered_and_a_higher_f0_never_raises_n_per(demo):
    out = bh.calc(demo)
    for stem, unit in (("MR", "[N*mm]"), ("n_per", "[1/min]"), ("n_thr", "[1/min]"), ("T_op", "[degC]")):
        rows = np.isfinite(out[f"{stem} {unit}"])
        assert (out.loc[rows, f"{stem}_low {unit}"] <= out.loc[rows, f"{stem} {unit}"]).all()
        assert (out.loc[rows, f"{stem} {unit}"] <= out.loc[rows, f"{stem}_high {unit}"]).all()
    base = pd.read_csv(DEMO).head(1)
    n_per = [bh.calc(base.assign(f0=f0))["n_per [1/min]"].iat[0] for f0 in (1.0, 1.5, 2.0, 3.0, 4.0)]
    assert all(a >= b for a, b in zip(n_per, n_per[1:]))


def test_a_negative_uncertainty_is_a_row_error(demo):
    out = bh.calc(demo.assign(f0_rel_unc=[0.2, -0.1, 0.2, 0.2, 0.2, 0.2]))
    assert out["status"].iat[1] == "error"
    assert out["message"].iat[1] == "f0_rel_unc: -0.1 is outside the valid range 0 to 1"
    assert np.isnan(out["MR_low [N*mm]"].iat[1]) and np.isfinite(out["MR_low [N*mm]"].iat[0])


def test_an_audits_intervals_give_the_bands(tmp_path):
    table, _, _ = measured_set("none", 5, designations=["6205", "6208"])
    coefficients = audit_coefficients(table)
    path = tmp_path / "coefficients.csv"
    coefficients.to_csv(path, index=False)
    supports = pd.DataFrame({"designation": ["6205", "6208", "6310"], "lubrication": "oil_bath",
                             "n [rpm]": 3000, "Fr [kN]": 1.0, "nu [mm^2/s]": 12})
    out = bh.calc(supports, coefficients=str(path))
    f0 = coefficients[(coefficients["bearing"] == "6205") & (coefficients["coefficient"] == "f0")].iloc[0]
    u0 = (f0["ci_high"] - f0["ci_low"]) / 2 / f0["fitted"]
    assert 0 < u0 < 0.2
    assert out["MR_high [N*mm]"].iat[0] > out["MR [N*mm]"].iat[0]
    assert np.isnan(out["MR_high [N*mm]"].iat[2])  # the 6310 was not audited: no band
    half = out["MR_high [N*mm]"].iat[0] - out["MR [N*mm]"].iat[0]
    f1 = coefficients[(coefficients["bearing"] == "6205") & coefficients["coefficient"].isin(["f1", "f1_a"])].iloc[0]
    u1 = (f1["ci_high"] - f1["ci_low"]) / 2 / f1["fitted"]
    assert half == pytest.approx(np.hypot(u0 * out["M0 [N*mm]"].iat[0], u1 * out["M1 [N*mm]"].iat[0]), rel=1e-9)


def test_the_command_line_takes_the_audits_coefficients(tmp_path):
    from bearingheat.cli import main
    table, _, _ = measured_set("none", 5, designations=["6205"])
    audit_coefficients(table).to_csv(tmp_path / "coefficients.csv", index=False)
    pd.DataFrame({"designation": ["6205"], "lubrication": ["oil_bath"], "n [rpm]": [3000], "Fr [kN]": [1.0],
                  "nu [mm^2/s]": [12]}).to_csv(tmp_path / "in.csv", index=False)
    assert main(["calc", str(tmp_path / "in.csv"), "--coefficients", str(tmp_path / "coefficients.csv"), "-o",
                 str(tmp_path / "out.csv"), "-q"]) == 0
    out = pd.read_csv(tmp_path / "out.csv")
    assert out["MR_low [N*mm]"].iat[0] < out["MR [N*mm]"].iat[0] < out["MR_high [N*mm]"].iat[0]


def test_an_empty_or_missing_coefficients_file_is_named(tmp_path, capsys):
    from bearingheat.cli import main
    empty = tmp_path / "empty.csv"
    empty.write_text("")
    for path, why in ((empty, "not a readable CSV (the file is empty)"), (tmp_path / "none.csv", "no such file")):
        assert main(["calc", str(DEMO), "--coefficients", str(path), "-q"]) == 2
        assert capsys.readouterr().err == f"bearingheat calc: error: {path}: {why}\n"


def test_the_sampled_reference_speed_band_is_the_percentiles_of_its_draws():
    """In 'sampled' mode every band is the 2.5 and 97.5 percentiles of the draws, n_thr's too (it was the
    linearised band). By hand: the 6205 at the ISO 15312 reference with f0 = 2 s0, f1 = 0.0009 sqrt(0.05) s1, for
    the draws of numpy's default_rng(0) that calc makes (s0 first, then s1)."""
    import math

    from scipy.optimize import brentq

    row = pd.DataFrame([{"designation": "6205", "d [mm]": 25, "D [mm]": 52, "B [mm]": 15, "C0 [N]": 7800,
                         "lubrication": "oil_bath", "n [rpm]": 3000, "Fr [kN]": 2, "nu [mm^2/s]": 12,
                         "f0_rel_unc": 0.2, "f1_rel_unc": 0.1}])
    out = bh.calc(row, uncertainty="sampled")
    rng = np.random.default_rng(0)
    s0 = 1 + 0.2 / 1.959963984540054 * rng.standard_normal((400, 1)).ravel()
    s1 = 1 + 0.1 / 1.959963984540054 * rng.standard_normal((400, 1)).ravel()
    dM, A_r = 38.5, math.pi * 15 * (52 + 25)

    def n_thr(a, b):
        M1 = 0.0009 * math.sqrt(0.05) * b * 0.05 * 7800 * dM
        return brentq(lambda n: math.pi * n / 30e3 * (2 * a * (12 * n) ** (2 / 3) * dM ** 3 * 1e-7 + M1)
                      - 0.016 * A_r, 1, 1e6, xtol=1e-9)

    drawn = [n_thr(a, b) for a, b in zip(s0, s1)]
    assert out["n_thr_low [1/min]"].iat[0] == pytest.approx(np.percentile(drawn, 2.5), rel=1e-9)
    assert out["n_thr_high [1/min]"].iat[0] == pytest.approx(np.percentile(drawn, 97.5), rel=1e-9)


def test_the_bands_follow_the_lubrication_the_audit_fitted(tmp_path):
    """The audit fits a bearing once per lubrication (their table f0 differ); calc took the last fit of the bearing
    whatever its row's lubrication. Each row now takes its own lubrication's fit (one fit may name two lubrications
    of equal table coefficients), and a file of an older audit (no lubrication column) its bearing's fit in any
    lubrication."""
    rows = [{"bearing": "6208", "lubrication": lubrication, "coefficient": "f0", "fitted": fitted,
             "ci_low": fitted * (1 - half), "ci_high": fitted * (1 + half)}
            for lubrication, fitted, half in (("oil_bath", 2.0, 0.10), ("grease", 1.3, 0.30),
                                              ("circulating_oil, oil_mist", 2.0, 0.20))]
    path = tmp_path / "coefficients.csv"
    pd.DataFrame(rows).to_csv(path, index=False)
    supports = pd.DataFrame({"designation": "6208", "lubrication": ["oil_bath", "grease", "oil_mist"],
                             "n [rpm]": 3000, "Fr [kN]": 1.0, "nu [mm^2/s]": 12})
    out = bh.calc(supports, coefficients=str(path))
    # f0 alone is banded: MR_high - MR = u0 * M0, u0 the relative half-width of the row's own fit
    np.testing.assert_allclose(out["MR_high [N*mm]"] - out["MR [N*mm]"],
                               [0.10 * out["M0 [N*mm]"].iat[0], 0.30 * out["M0 [N*mm]"].iat[1],
                                0.20 * out["M0 [N*mm]"].iat[2]], rtol=1e-9)  # (a fit of two lubrications)
    older = tmp_path / "older.csv"
    pd.DataFrame(rows[1:2]).drop(columns="lubrication").to_csv(older, index=False)
    out = bh.calc(supports, coefficients=str(older))
    np.testing.assert_allclose(out["MR_high [N*mm]"] - out["MR [N*mm]"], 0.30 * out["M0 [N*mm]"], rtol=1e-9)
