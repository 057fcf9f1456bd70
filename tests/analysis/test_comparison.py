"""Model comparison on measured torque: each model before and after fitting, and the one that fits better."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from synthetic_torque import model_set

from bearingheat.analysis.comparison import compare_models_table, model_names
from bearingheat.errors import DiagnoseError, ModelError


@pytest.mark.parametrize("generator, other", [("schaeffler", "skf"), ("skf", "schaeffler")])
def test_the_comparison_picks_the_model_that_made_the_data(generator, other):
    comparison = compare_models_table(model_set(generator, seed=11), "all")
    assert comparison.best == generator and comparison.runner_up == other
    best = comparison.fits[generator]
    # the generating model's held-out error is the noise (5 % log-normal), its fitted scales ~1
    assert best.cv_after["rel_rmse"] == pytest.approx(0.05, abs=0.01)
    assert all(value == pytest.approx(1.0, abs=0.05) for value in best.scales.values())
    assert comparison.ratio > 3.0 and comparison.p_value < 1e-6
    assert comparison.verdict().startswith(f"{generator} fits these data better than {other}: held-out relative")


def test_a_fitted_scale_is_recovered_and_the_generating_model_still_wins():
    # the catalogue model with f0 25 % above the table: before fitting it is off, after fitting it is the noise
    comparison = compare_models_table(model_set("schaeffler", seed=12, f0_scale=1.25), "all")
    fit = comparison.fits["schaeffler"]
    assert fit.scales["M0"] == pytest.approx(1.25, rel=0.03)
    assert fit.scales["M1"] == pytest.approx(1.0, rel=0.05)
    assert fit.before["rel_rmse"] > 0.08 > fit.cv_after["rel_rmse"]
    assert fit.before["bias"] > 0  # measured − model: the table's f0 predicts too little
    assert comparison.best == "schaeffler"


def test_errors_before_are_the_hand_computed_ones():
    table = model_set("skf", seed=13)
    comparison = compare_models_table(table, "skf")
    fit = comparison.fits["skf"]
    residual = (comparison.measured - fit.predicted) / comparison.measured
    assert fit.before["rel_rmse"] == pytest.approx(float(np.sqrt(np.mean(residual ** 2))), rel=1e-12)
    assert comparison.runner_up is None and np.isnan(comparison.ratio)
    assert comparison.verdict().startswith("skf: held-out relative RMSE")


def test_one_row_in_error_in_one_model_is_left_out_of_every_model():
    table = model_set("schaeffler", seed=14)
    table["oil"] = "mineral"
    table.loc[3, "oil"] = "castor"  # an error of the SKF model only (the catalogue model does not read 'oil')
    comparison = compare_models_table(table, "all")
    assert comparison.n_rows == len(table) - 1
    assert comparison.excluded == ["row 4 (skf): oil: 'castor' is not one of mineral, synthetic, transmission_fluid"]
    assert len(comparison.fits["schaeffler"].predicted) == len(table) - 1


def test_model_names():
    assert model_names("all") == ("schaeffler", "skf")
    assert model_names("skf") == ("skf",)
    with pytest.raises(ModelError, match=r"^model: 'simple' is not one of schaeffler, skf$"):
        model_names("simple")


def test_too_few_rows():
    table = model_set("schaeffler", seed=15).head(10)
    with pytest.raises(DiagnoseError) as info:
        compare_models_table(table, "all")
    assert str(info.value) == ("the model comparison needs at least 20 rows usable in every model "
                               "(schaeffler, skf); got 10")


def test_side_by_side_of_the_demo_supports():
    from pathlib import Path

    from bearingheat.analysis.comparison import side_by_side
    from bearingheat.calc.table import calc

    table = pd.read_csv(Path(__file__).resolve().parents[2] / "examples" / "gearbox_shaft_skf.csv")
    both = side_by_side(table)
    assert list(both.columns) == ["id", "designation", "MR [N*mm] (schaeffler)", "NR [W] (schaeffler)",
                                  "MR [N*mm] (skf)", "NR [W] (skf)", "MR skf/schaeffler"]
    for model in ("schaeffler", "skf"):
        alone = calc(table, model=model)
        assert np.array_equal(both[f"MR [N*mm] ({model})"].to_numpy(), alone["MR [N*mm]"].to_numpy())
    ratio = both["MR [N*mm] (skf)"] / both["MR [N*mm] (schaeffler)"]
    assert np.allclose(both["MR skf/schaeffler"], ratio, rtol=1e-15)
    # the tapered roller bearing under 2.4 kN axial load at 310 r/min: the SKF model's sliding moment dominates
    assert both.loc[2, "MR skf/schaeffler"] > 2.5
