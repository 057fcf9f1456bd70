"""The SKF model as the registry's second model: per row or per table, through calc and the heat balance."""
import math

import pandas as pd
import pytest

from bearingheat.calc.models import MODELS
from bearingheat.calc.table import calc

# SKF General Catalogue 6000, pp. 104-105: 22208 E, 40 x 80 x 23, Fr 2990 N, Fa 100 N, n 3500 r/min,
# nu 68 mm^2/s, oil bath H = 2.5 mm, VM 0.3e-4, full film mu_sl 0.05: M = 334 N*mm (Grr rounded to 0.26)
EXAMPLE = {"id": "22208 E", "designation": "22208 E", "d [mm]": 40, "D [mm]": 80, "B [mm]": 23, "C0 [kN]": 90,
           "lubrication": "oil_bath", "n [1/min]": 3500, "Fr [N]": 2990, "Fa [N]": 100, "nu [mm^2/s]": 68,
           "oil_level [mm]": 2.5, "VM": 0.3e-4, "skf_edition": "6000", "mu_sl": 0.05}


def test_the_registry_holds_both_models():
    assert list(MODELS) == ["schaeffler", "skf"]
    assert MODELS["skf"].speed_exponent is None and MODELS["skf"].excel_formulas is None


def test_worked_example_through_calc_per_row_and_per_table():
    by_row = calc(pd.DataFrame([{**EXAMPLE, "model": "skf"}]))
    by_table = calc(pd.DataFrame([EXAMPLE]), model="skf")
    for out in (by_row, by_table):
        assert out["status"].tolist() == ["ok"]
        assert out["MR [N*mm]"].iat[0] == pytest.approx(334, rel=0.01)
        assert out["M_drag [N*mm]"].iat[0] == pytest.approx(14.5, abs=0.05)
        assert out["phi_ish"].iat[0] == pytest.approx(0.85, abs=0.005)
        assert out["mu_sl_used"].iat[0] == 0.05
        assert out["NR [W]"].iat[0] == pytest.approx(out["MR [N*mm]"].iat[0] * 3500 / 9550, rel=1e-12)
    assert by_row["MR [N*mm]"].iat[0] == by_table["MR [N*mm]"].iat[0]


def test_both_models_side_by_side_on_one_table():
    rows = pd.DataFrame([{**EXAMPLE, "designation": "22208-E1", "e": 0.28, "X0": 1, "Y0": 2.4,
                          "model": "schaeffler"}, {**EXAMPLE, "model": "skf"}])
    out = calc(rows)
    assert out["status"].tolist() == ["ok", "ok"]
    catalogue, skf = out["MR [N*mm]"]
    assert catalogue == pytest.approx(361.8, abs=0.1)   # the seed's model on the same example (the issue's figure)
    assert skf == pytest.approx(331.1, abs=0.1)
    assert math.isnan(out["M_rr [N*mm]"].iat[0]) and math.isnan(out["f0"].iat[1])


def test_a_carb_designation_gets_no_error_of_the_other_model():
    row = {**EXAMPLE, "designation": "C 2208 TN9", "model": "skf", "oil_level [mm]": None, "VM": None,
           "lubrication": "grease", "skf_edition": None}
    out = calc(pd.DataFrame([row]))
    assert "the Schaeffler catalogue" not in out["message"].iat[0]
    assert out["status"].iat[0] in ("ok", "warning") and out["MR [N*mm]"].iat[0] > 0


def test_the_heat_balance_of_the_skf_model_uses_the_bracketed_root():
    row = {**EXAMPLE, "model": "skf", "T_amb [degC]": 20, "T_bearing [degC]": 70}
    out = calc(pd.DataFrame([row]))
    assert out["status"].iat[0] in ("ok", "warning")
    n_per = out["n_per [1/min]"].iat[0]
    assert n_per > 0 and math.isfinite(out["T_op [degC]"].iat[0])
    # at n_per the SKF friction power (pi*n/30e3 * M) equals the heat carried away through the seat at T_bearing
    at_n_per = calc(pd.DataFrame([{**EXAMPLE, "model": "skf", "n [1/min]": n_per}]))
    power = math.pi * n_per / 30.0 * 1e-3 * at_n_per["MR [N*mm]"].iat[0]
    assert power == pytest.approx(out["Q_S [W]"].iat[0], rel=1e-9)


def test_a_pair_through_calc_gives_the_pair_the_heat_balance_message_names():
    """Both models report a paired row's MR and NR as the pair's, as the n_thr message of a pair says."""
    from bearingheat.calc.reference_speed import PAIR_REASON

    row = {"id": "spindle", "designation": "7210-B", "d [mm]": 50, "D [mm]": 90, "lubrication": "grease",
           "n [1/min]": 6000, "Fr [N]": 1500, "nu [mm^2/s]": 22, "T_amb [degC]": 20, "T_bearing [degC]": 70}
    out = calc(pd.DataFrame([{**row, "arrangement": "paired"}, {**row, "Fr [N]": 750}]), model="skf")
    assert out["MR [N*mm]"].iat[0] == pytest.approx(2 * out["MR [N*mm]"].iat[1], rel=1e-15)
    assert out["NR [W]"].iat[0] == pytest.approx(2 * out["NR [W]"].iat[1], rel=1e-15)
    assert out["message"].iat[0] == PAIR_REASON


def test_the_unit_aware_api_runs_the_skf_model():
    import pint

    import bearingheat as bh

    u = pint.get_application_registry()
    args = dict(d=40 * u.mm, D=80 * u.mm, B=23 * u.mm, lubrication="oil_bath", n=3500 * u.rpm,
                nu=68 * u("mm^2/s"), Fr=2990 * u.N, Fa=100 * u.N)
    r = bh.friction_torque("22208 E", model="skf", **args,
                           model_inputs={"oil_level": 0.25 * u.cm, "VM": 0.3e-4, "skf_edition": "6000", "mu_sl": 0.05})
    assert r.MR.to("N*mm").magnitude == pytest.approx(334, rel=0.01)
    assert r.model_results["M_drag"].to("N*mm").magnitude == pytest.approx(14.5, abs=0.05)
    with pytest.raises(bh.FrictionInputError) as exc:
        bh.friction_torque("22208 E", model="skf", **args, model_inputs={"f2": 0.01})
    assert str(exc.value).startswith("model_inputs: 'f2' is not an input of this model; it reads oil, mu_sl, mu_bl")


def test_a_numeric_edition_column_is_read_as_the_edition():
    """A CSV column of editions with a blank cell comes as floats (6000.0); it still names edition 6000."""
    out = calc(pd.DataFrame([{**EXAMPLE, "skf_edition": 6000.0}, {**EXAMPLE, "skf_edition": None}]), model="skf")
    assert out["status"].tolist() == ["ok", "ok"]
    assert out["MR [N*mm]"].iat[0] == pytest.approx(331.075, abs=1e-3)


def test_an_oil_level_far_beyond_any_bearing_is_refused_and_an_unlikely_one_said():
    """The drag of H > 1.2 dm is that of 1.2 dm (SKF 10000/3, p. 111), so a mistyped level would change nothing
    visible: 10^6 mm is outside the valid range, 8000 mm outside the plausible one."""
    table = pd.read_csv("examples/gearbox_shaft_skf.csv").iloc[[0]]
    rows = pd.concat([table.assign(**{"oil_level [mm]": level}) for level in (50.0, 8000.0, 1e6)], ignore_index=True)
    out = calc(rows, model="skf")
    assert out["status"].tolist() == ["ok", "warning", "error"]
    assert out["message"].iat[2] == "oil_level [mm]: 1e+06 is outside the valid range up to 100000 mm"
    assert out["message"].iat[1].startswith("oil_level [mm]: 8000 is outside the plausible range up to 5000 mm")


def test_implausible_drag_and_sliding_coefficients_are_said_with_their_source():
    """VM of the order 10^-4 (the worked example reads 0.3e-4 off diagram 2), mu_bl about 0.15 (6000 p. 101): a VM of
    0.3 or a mu_sl of 5 is a slip of the exponent or of percent, and gives a warning, not a quiet torque."""
    rows = pd.DataFrame([{**EXAMPLE, "VM": 0.3}, {**EXAMPLE, "mu_sl": 5}, {**EXAMPLE, "mu_bl": 3},
                         {**EXAMPLE, "VM": 2e-4, "mu_sl": 0.12, "mu_bl": 0.2}])
    out = calc(rows, model="skf")
    assert out["status"].tolist() == ["warning", "warning", "warning", "ok"]
    mu_source = "twice μbl ≈ 0.15 of SKF 6000 p. 101 and 10000/3 p. 103, the largest sliding coefficient of the model"
    assert out["message"].tolist()[:3] == [
        "VM: 0.3 is outside the plausible range up to 0.01 (over 300 times the 0.3·10⁻⁴ the worked example of SKF "
        "6000 pp. 104-105 reads off diagram 2; the diagram's data are not in bearingheat, so the bound is wide); "
        "check the number and its unit",
        f"mu_sl: 5 is outside the plausible range up to 0.3 ({mu_source}); check the number and its unit",
        f"mu_bl: 3 is outside the plausible range up to 0.3 ({mu_source}); check the number and its unit"]


def test_a_designation_note_of_the_catalogue_tables_only_on_rows_of_the_catalogue_model():
    row = {"designation": "NJ 208", "d [mm]": 40, "D [mm]": 80, "lubrication": "grease", "n [1/min]": 1500,
           "Fr [N]": 4000, "nu [mm^2/s]": 40}
    out = calc(pd.DataFrame([{**row, "model": "skf"}, {**row, "model": "schaeffler"}]))
    assert out["status"].tolist() == ["ok", "warning"]
    assert out["message"].tolist() == ["", "the Schaeffler catalogue row for series 2 is for the E design (2..-E)"]
