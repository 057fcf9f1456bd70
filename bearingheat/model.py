"""Transitional alias of the old row model while the package moves to its layers (removed when the move is done)."""
from bearingheat.calc.contract import input_units as _input_units
from bearingheat.calc.messages import Labels, Problem
from bearingheat.calc.models import M2_REPORT_UNITS, PLAIN_REPORT_UNITS, RESULT_UNITS, compute_supports
from bearingheat.calc.supports import SupportArrays, bearing_constants
from bearingheat.calc.friction import evaluate_catalogue_model

INPUT_UNITS = {k: v for k, v in _input_units().items() if k not in _input_units("thermal") and k not in
               _input_units("contact") and k != "model"}
PLAIN_TYPES = ("plain_bushing",)


def check_and_evaluate(a: dict, labels, f2_chart=None):
    """The old dict interface of the catalogue model's evaluation."""
    import dataclasses
    import numpy as np

    fields = {f.name for f in dataclasses.fields(SupportArrays)}
    values = {k: v for k, v in a.items() if k in fields}
    values.setdefault("size", len(a["n"]))
    values.setdefault("series", "")
    values.setdefault("error", "")
    values.setdefault("resolved", True)
    values.setdefault("plain", np.zeros(len(a["n"]), dtype=bool))
    values.setdefault("notes", [])
    if values.get("p1_rule") is None:
        values["p1_rule"] = ""
    if values.get("contact_angle") is None:
        values["contact_angle"] = float("nan")
    return evaluate_catalogue_model(SupportArrays(**values), labels, f2_chart)
