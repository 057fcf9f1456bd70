"""calc --effects: the fitted domain and the base model a diagnose effect records, and what calc does with rows
outside them (a warning per quantity outside the fitted range; an error on a row of another friction model)."""
from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest
from diagnose_cases import CASES, run_case

from bearingheat.analysis.diagnose import DiagnoseError, FittedEffect
from bearingheat.calc.table import calc

DRAG = next(c for c in CASES if c[0] == "drag_losses" and c[1] == 101)


def _exactly(message: str) -> str:
    return f"^{re.escape(message)}$"


def _rows(*rows):
    """Deep groove ball bearings in an oil bath at nu = 20 mm^2/s: (designation, n [1/min], Fr [N])."""
    return pd.DataFrame({"designation": [r[0] for r in rows], "lubrication": "grease",
                         "n [1/min]": [float(r[1]) for r in rows], "Fr [N]": [float(r[2]) for r in rows],
                         "nu [mm^2/s]": 20.0})


def test_the_summary_records_the_fitted_domain_and_the_base_model():
    table, _, diagnosis = run_case(*DRAG)
    summary = diagnosis.summary()
    data = diagnosis.data
    assert summary["base_model"] == "schaeffler"
    assert summary["domain"] == {"n [1/min]": [float(data.n.min()), float(data.n.max())],
                                 "dM [mm]": [float(data.dM.min()), float(data.dM.max())],
                                 "bearings": ["30206-A", "6205", "6310", "NU208-E"]}
    assert summary["domain"]["n [1/min]"] == [300.0, 5000.0]
    from bearingheat.io.reports.diagnose import report_markdown
    assert ("Fitted on the schaeffler model over n [1/min] 300 to 5000, dM [mm] 38.5 to 80; `calc --effects` refuses "
            "rows of another model and warns on rows outside these ranges.") in report_markdown(diagnosis, summary, "n")


def test_calc_warns_on_rows_outside_the_fitted_domain(tmp_path):
    """drag_losses fitted at n 300-5000 1/min and dM 38.5-80 mm changed a 6205 at 15 000 1/min from MR 63.55 to
    93.04 and a 6330 from 5686 to 15290 N*mm with status ok."""
    table, _, diagnosis = run_case(*DRAG)
    path = tmp_path / "summary.json"
    path.write_text(json.dumps(diagnosis.summary()))
    effect = FittedEffect.from_summary(path)
    within = calc(table, effects=effect)
    assert not within["message"].str.contains("outside the range").any()  # the fitted rows are inside their domain
    design = _rows(("6205", 3000, 500), ("6205", 15000, 500), ("6330", 3000, 5000))
    plain, out = calc(design), calc(design, effects=effect)
    c, p = diagnosis.summary()["parameters"]["c"], diagnosis.summary()["parameters"]["p"]
    note = f"diagnose effect drag_losses (c: {c:.4g}, p: {p:.4g})"
    assert out["status"].tolist() == ["ok", "warning", "warning"]
    assert out["message"].tolist() == [
        note,
        f"{note}; diagnose effect drag_losses: n = 15000 1/min is outside the range it was fitted on "
        "(300 to 5000 1/min): the effect is extrapolated there",
        f"{note}; diagnose effect drag_losses: dM = 235 mm is outside the range it was fitted on (38.5 to 80 mm): "
        "the effect is extrapolated there"]
    assert (out["MR [N*mm]"] > plain["MR [N*mm]"]).all()   # applied (and said to be extrapolated)


def test_each_quantity_outside_its_range_is_named():
    domain = {"n [1/min]": [1000.0, 3000.0], "nu*n [mm^2/s*1/min]": [20000.0, 60000.0], "dM [mm]": [30.0, 60.0],
              "load [N]": [100.0, 1000.0], "bearings": ["6205"]}
    effect = FittedEffect("viscosity_heating", {"R_th [K/W]": 0.5}, domain)
    out = calc(_rows(("6205", 500, 5000)), effects=effect)
    assert out["status"].iat[0] == "warning"
    assert out["message"].iat[0].split("; ")[1:] == [
        "diagnose effect viscosity_heating: n = 500 1/min is outside the range it was fitted on (1000 to 3000 1/min):"
        " the effect is extrapolated there",
        "diagnose effect viscosity_heating: nu*n = 10000 mm^2/s*1/min is outside the range it was fitted on "
        "(20000 to 60000 mm^2/s*1/min): the effect is extrapolated there",
        "diagnose effect viscosity_heating: load = 5000 N is outside the range it was fitted on (100 to 1000 N): the "
        "effect is extrapolated there"]


def test_an_old_summary_without_domain_loads_with_the_domain_unknown(tmp_path):
    path = tmp_path / "old.json"
    path.write_text(json.dumps({"effect": "drag_losses", "parameters": {"c": 0.05, "p": 1.8}}))
    effect = FittedEffect.from_summary(path)
    assert effect.domain is None and effect.base_model == "schaeffler"
    out = calc(_rows(("6205", 15000, 500)), effects=effect)
    assert out["status"].iat[0] == "ok"
    assert out["message"].iat[0] == ("diagnose effect drag_losses (c: 0.05, p: 1.8) (its fitted domain is unknown: "
                                     "rows outside it are not flagged)")


@pytest.mark.parametrize("domain,message", [
    ({"n [1/min]": [5000, 300]}, "'domain' of the summary: n [1/min] is [5000, 300]; expected [low, high], two "
                                 "finite numbers with low <= high"),
    ({"speed": [1, 2]}, "'domain' of the summary: 'speed' is not one of n [1/min], nu*n [mm^2/s*1/min], dM [mm], "
                        "load [N], bearings"),
    ([1, 2], "'domain' of the summary is list, not a table of ranges"),
])
def test_a_bad_domain_in_the_summary_is_refused(tmp_path, domain, message):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"effect": "drag_losses", "parameters": {"c": 0.05, "p": 1.8}, "domain": domain}))
    with pytest.raises(DiagnoseError, match=_exactly(message)):
        FittedEffect.from_summary(path)


@pytest.mark.parametrize("effect,parameters", [
    ("seal_drag", {"M_seal [N*mm]": {"6205": 15.0}}), ("f0_scale", {"k": 2.0}),
    ("viscosity_heating", {"R_th [K/W]": 0.5}), ("preload", {"F_pre [N]": {"6205": 200.0}}),
    ("drag_losses", {"c": 0.05, "p": 1.8}), ("run_in", {"a": 1.0, "tau [h]": 10.0}),
])
def test_an_effect_of_the_catalogue_model_is_refused_on_rows_of_the_skf_model(effect, parameters):
    """The seal torque was added on top of the SKF model's own seal term; f0_scale, viscosity_heating and preload
    made MR NaN ('the result is not a finite number')."""
    fitted = FittedEffect(effect, parameters, {"bearings": ["6205"]})
    design = _rows(("6205", 3000, 500), ("6205", 3000, 500)).assign(model=["schaeffler", "skf"])
    out = calc(design, effects=fitted)
    assert out["status"].tolist() == ["ok", "error"]
    assert np.isfinite(out["MR [N*mm]"].iat[0]) and np.isnan(out["MR [N*mm]"].iat[1])
    assert out["message"].iat[1] == (
        f"diagnose effect {effect} extends the schaeffler model it was fitted on, not the skf model of this row "
        "(compute the row with the schaeffler model, or without the effect)")
    whole = calc(_rows(("6205", 3000, 500)), effects=fitted, model="skf")
    assert whole["status"].iat[0] == "error" and whole["message"].iat[0] == out["message"].iat[1]


def test_the_none_effect_applies_to_any_model():
    out = calc(_rows(("6205", 3000, 500)), effects=FittedEffect("none", {}, {"bearings": []}), model="skf")
    plain = calc(_rows(("6205", 3000, 500)), model="skf")
    assert out["status"].iat[0] == plain["status"].iat[0] == "ok"
    assert out["MR [N*mm]"].iat[0] == plain["MR [N*mm]"].iat[0]


def test_an_unknown_base_model_in_the_summary_is_refused(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"effect": "f0_scale", "parameters": {"k": 2.0}, "base_model": "magic"}))
    with pytest.raises(DiagnoseError, match=_exactly(
            "base_model of the summary: model: 'magic' is not one of schaeffler, skf")):
        FittedEffect.from_summary(path)
