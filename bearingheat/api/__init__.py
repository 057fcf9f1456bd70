"""The unit boundary for Python callers: pint Quantities in, results of Quantities out."""
from bearingheat.api.friction import FrictionResult, friction_torque

__all__ = ["FrictionResult", "friction_torque"]
