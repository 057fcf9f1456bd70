"""The column contract: one entry per column, and everything generated from it agrees with it."""
import re

import pandas as pd
import pytest

from bearingheat.calc import contract
from bearingheat.calc.table import calc
from bearingheat.errors import InputError


def test_units_of_the_friction_model_inputs():
    units = contract.input_units(owner="friction")
    assert units["d"] == units["D"] == units["B"] == "mm"
    assert units["Fr"] == units["Fa"] == units["C0"] == "N"
    assert units["n"] == "1/min" and units["nu"] == "mm^2/s" and units["alpha"] == "deg"
    assert units["designation"] == units["lubrication"] == ""


def test_thermal_columns_are_temperatures_and_differences():
    units = contract.input_units(owner="thermal")
    assert units["T_amb"] == units["T_bearing"] == "degC"
    assert units["dT_oil"] == "delta_degC"      # a header in degC is refused for a difference
    assert set(contract.output_units(owner="thermal")) == {"n_thr", "n_per", "n_per_method_used", "T_op", "nu_op",
                                                            "Q_S", "Q_L", "nu_used", "nu_at"}


def test_output_headers():
    assert contract.output_header("MR") == "MR [N*mm]"
    assert contract.output_header("f0") == "f0"
    assert contract.output_header("Fa_over_A") == "Fa/A"
    assert contract.output_header("p_plain") == "p [N/mm^2]"
    assert contract.output_header("T_op") == "T_op [degC]"


def test_unknown_column_lists_the_known_ones():
    with pytest.raises(InputError) as exc:
        contract.column("speed")
    assert str(exc.value).startswith("'speed' is not an input column of calc; known: id, designation, d, D, n, Fr,")


def test_choices_feed_the_drop_down_lists():
    assert contract.choices("lubrication") == ("grease", "oil_mist", "oil_bath", "circulating_oil")
    assert contract.choices("arrangement") == ("single", "paired")
    assert "deep_groove_ball" in contract.choices("type")
    assert contract.choices("model") == ("schaeffler", "skf")
    assert contract.choices("d") == ()


def test_template_columns_keep_the_sheet_order():
    names = [c.name for c in contract.template_columns()]
    assert names[:6] == ["id", "designation", "d", "D", "n", "Fr"]     # Fr lands in column F
    assert [c.name for c in contract.template_columns() if c.required] == [
        "designation", "D", "n", "Fr", "nu", "lubrication"]


def test_help_names_every_input_column_with_its_unit():
    text = contract.help_text()
    for column in contract.CONTRACT:
        if column.kind == "input":
            unit = {"": "text"}.get(column.unit, column.unit)
            assert re.search(rf"^  {re.escape(column.name)} \[{re.escape(unit)}\]", text, re.M), column.name


def test_markdown_table_has_a_row_per_column():
    for kind in ("input", "output"):
        rows = contract.markdown_table(kind).splitlines()[2:]
        assert len(rows) == len(contract.columns(kind=kind))


def test_calc_writes_the_contract_headers():
    rows = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [kN]": [7.8],
                         "lubrication": ["oil_bath"], "n [rpm]": [3000], "Fr [kN]": [2], "nu [mm^2/s]": [12]})
    out = calc(rows)
    # n_thr: the bearing table gives the 6205's width B, so the reference speed comes quietly
    assert list(out.columns[len(rows.columns):]) == [contract.output_header(n) for n in
                                                      ("f0", "f1", "P0", "P1", "M0", "M1", "M2", "MR", "NR",
                                                       "n_thr")] + ["status", "message"]


@pytest.mark.parametrize("header, expected", [
    ("Fr [kN]", ("Fr", "kN")), (" n [U/min] ", ("n", "U/min")), ("id", ("id", None)), ("nu []", ("nu", "")),
])
def test_parse_header(header, expected):
    assert contract.parse_header(header) == expected


def test_unreadable_header():
    with pytest.raises(InputError) as exc:
        contract.parse_header("a] b")
    assert str(exc.value) == "column 'a] b': cannot read the header; write it as 'name [unit]'"


def test_a_text_column_read_as_numbers_keeps_its_text():
    """A CSV column of series with a blank cell comes as floats (62.0); it still names series 62."""
    rows = pd.DataFrame({"type": ["deep_groove_ball", "deep_groove_ball"], "series": [62.0, None],
                         "d [mm]": [25, 25], "D [mm]": [52, 52], "C0 [kN]": [7.8, 7.8], "lubrication": ["grease"] * 2,
                         "n [1/min]": [3000, 3000], "Fr [kN]": [2, 2], "nu [mm^2/s]": [12, 12]})
    out = calc(rows)
    assert out["status"].iat[0] == "ok"
    assert out["message"].iat[1] == "series: missing; give type and series together"


def test_every_plausible_range_lies_inside_the_valid_range():
    # range_problems says nothing without looking further when the numbers lie inside the narrower range
    from bearingheat.calc.contract import CONTRACT
    for c in CONTRACT:
        if c.valid and c.plausible:
            assert c.valid[0] <= c.plausible[0] and c.plausible[1] <= c.valid[1], c.name


def test_range_problems_finds_one_number_among_many_inside():
    import numpy as np

    from bearingheat.calc.contract import range_problems
    values = np.full(1000, 25.0)
    values[[3, 500]] = [np.nan, 250.0]
    assert range_problems("T_amb", values, lambda i: f"T_amb: {values[i]:g}") == (
        [(500, "T_amb: 250 is outside the valid range -60 to 200 degC")], [])
    values[500] = np.inf
    assert range_problems("T_amb", values, lambda i: "T_amb: inf")[0] == [(500, "T_amb: inf is not a finite number")]
    assert range_problems("T_amb", np.full(4, np.nan), str) == ([], [])


def test_a_dimensionless_input_headed_with_1_or_dash_is_that_column_written_once():
    """The contract names a dimensionless column bare (f0), the template's units row writes 1 for it, and calc
    reads 'f0 [1]' and 'f1 [-]' as f0 and f1. Their results used to come out beside them ('f0 [1]' and 'f0'): now
    the result takes the input column's place under its own header, as with a bare 'f0'. By hand (the Schaeffler
    catalogue, p. 66): M0 = f0·(ν·n)^(2/3)·dM³·1e-7 = 2.5·36000^(2/3)·38.5³·1e-7, M1 = f1·P1·dM = 5e-4·2000·38.5."""
    base = {"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [kN]": [7.8], "lubrication": ["oil_bath"],
            "n [rpm]": [3000], "Fr [kN]": [2], "nu [mm^2/s]": [12]}
    bare = calc(pd.DataFrame({**base, "f0": [2.5], "f1": [5e-4], "Y0": [0.5]}))
    for f0, f1, y0 in (("f0 [1]", "f1 [-]", "Y0 [1]"), ("f0 [-]", "f1 [1]", "Y0 [-]")):
        out = calc(pd.DataFrame({**base, f0: [2.5], f1: [5e-4], y0: [0.5]}))
        assert list(out.columns) == [*base, "f0", "f1", y0] + list(bare.columns[len(base) + 3:])
        assert (out["f0"].iat[0], out["f1"].iat[0]) == (2.5, 5e-4)
        assert out["M0 [N*mm]"].iat[0] == pytest.approx(2.5 * 36000 ** (2 / 3) * 38.5**3 * 1e-7, rel=1e-12)
        assert out["M1 [N*mm]"].iat[0] == pytest.approx(38.5, rel=1e-12)
        pd.testing.assert_frame_equal(out.rename(columns={y0: "Y0"}), bare)


def test_a_result_of_a_results_table_headed_in_another_unit_is_written_once_in_its_place():
    """A results table computed again whose MR the user turned into N*m ('MR [N*m]'): calc writes MR [N*mm] in that
    column's place, once, with the new values (it used to keep the old column and add MR [N*mm] at the end)."""
    rows = pd.DataFrame({"designation": ["6205"], "d [mm]": [25], "D [mm]": [52], "C0 [kN]": [7.8],
                         "lubrication": ["oil_bath"], "n [rpm]": [3000], "Fr [kN]": [2], "nu [mm^2/s]": [12]})
    first = calc(rows)
    earlier = first.assign(**{"MR [N*mm]": first["MR [N*mm]"] / 1000}).rename(columns={"MR [N*mm]": "MR [N*m]"})
    again = calc(earlier)
    assert list(again.columns) == list(first.columns)
    assert again["MR [N*mm]"].iat[0] == first["MR [N*mm]"].iat[0]
