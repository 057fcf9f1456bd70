"""Transitional alias of the effect candidates while the package moves to its layers (removed when the move is done).

The kernels are in :mod:`bearingheat.kernels.effects`, the candidates in :mod:`bearingheat.analysis.effects`.
"""
from bearingheat.analysis.effects import (CANDIDATES, EFFECT_NAMES, CalcRows, Candidate, ModelData, bearing_keys,
                                          catalogue_arrays, evaluate_with_axial_load)
from bearingheat.kernels.effects import (VISCOSITY_TEMPERATURE_COEFFICIENT, drag_loss_torque, heated_total_torque,
                                         run_in_factor, seal_drag_torque)

__all__ = [
    "EFFECT_NAMES",
    "CANDIDATES",
    "VISCOSITY_TEMPERATURE_COEFFICIENT",
    "ModelData",
    "CalcRows",
    "Candidate",
    "catalogue_arrays",
    "evaluate_with_axial_load",
    "bearing_keys",
    "seal_drag_torque",
    "drag_loss_torque",
    "run_in_factor",
    "heated_total_torque",
]
