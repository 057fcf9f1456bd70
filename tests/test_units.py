"""units.py: speed as revolutions per time, unit spellings of engineers' sheets, the one header converter."""
import math
import re

import numpy as np
import pandas as pd
import pint
import pint_pandas  # noqa: F401  (registers the pint[...] dtype)
import pytest

from bearingheat.errors import UnitError
from bearingheat.units import convert_column, magnitude, parse_quantity, parse_unit, speed_rpm

u = pint.get_application_registry()

def test_speed_conversion_values():
    assert speed_rpm(50 * u.Hz) == 3000.0
    assert speed_rpm(2 * math.pi * u("rad/s")) == pytest.approx(60.0, rel=1e-15)
    assert speed_rpm(1 * u.rpm) == pytest.approx(1.0, rel=1e-15)
    with pytest.raises(UnitError, match=re.escape("n: 3 meter / second is not a shaft speed; expected revolutions "
                                                  "per time (1/min, rpm, Hz) or an angular speed (rad/s)")):
        speed_rpm(3 * u("m/s"))
def test_parse_helpers():
    assert parse_quantity("2.6kg*m^2").to("kg*m^2").magnitude == 2.6
    assert parse_quantity("3000 rpm").to("rpm").magnitude == 3000
    assert str(parse_unit("U/min")) == "1 / minute"
    assert str(parse_unit("min^-1")) == "1 / minute"
    with pytest.raises(UnitError, match=re.escape("--G: unknown unit 'flubs'")):
        parse_unit("flubs", name="--G")
    assert magnitude(pd.Series([1.0, 2.0], dtype="pint[kN]"), "N", "Fr").tolist() == [1000.0, 2000.0]



@pytest.mark.parametrize("unit, target, values, expected, factor", [
    ("kN", "N", [2.0, 3.5], [2000.0, 3500.0], 1000.0),
    ("lbf", "N", [1.0], [4.4482216152605], 4.4482216152605),
    ("rpm", "1/min", [3000.0], [3000.0], 1.0),
    ("Hz", "1/min", [50.0], [3000.0], 60.0),
    ("rad/s", "1/min", [2 * math.pi], [60.0], 60.0 / (2 * math.pi)),
    ("cSt", "mm^2/s", [12.0], [12.0], 1.0),
    ("percent", "1", [50.0], [0.5], 0.01),
    (None, "1", [0.3], [0.3], 1.0),
])
def test_convert_column_values_and_factor(unit, target, values, expected, factor):
    out, f = convert_column(np.array(values), unit, target, name="x")
    assert out == pytest.approx(expected, rel=1e-12)
    assert f == pytest.approx(factor, rel=1e-12)


def test_convert_column_copies_unless_told_not_to():
    """A column already in the catalogue unit is a new array by default (the caller may change it), and the
    numbers themselves with copy=False (calc copies a view of the user's table itself)."""
    numbers = np.array([25.0, 30.0])
    copied, factor = convert_column(numbers, "mm", "mm", name="d")
    assert factor == 1.0 and copied is not numbers and copied.tolist() == [25.0, 30.0]
    assert convert_column(numbers, "mm", "mm", name="d", copy=False)[0] is numbers
    assert convert_column(numbers, "m", "mm", name="d", copy=False)[0].tolist() == [25000.0, 30000.0]


def test_convert_column_absolute_temperature_has_no_factor():
    out, f = convert_column(np.array([293.15, 373.15]), "K", "degC", name="T_amb")
    assert out == pytest.approx([20.0, 100.0], abs=1e-12)
    assert math.isnan(f)


@pytest.mark.parametrize("unit, target, message", [
    (None, "mm", "needs a unit, e.g. 'd [mm]'"),
    ("-", "mm", "needs a unit, e.g. 'd [mm]'"),
    ("mm", "1", "d is dimensionless, 'mm' is not"),
    ("m/s", "1/min", "m/s is not a shaft speed; expected revolutions per time (1/min, rpm, Hz) or an angular "
                     "speed (rad/s)"),
    ("kg", "N", "kilogram is a mass, not a force; for kilogram-force write kgf"),
    ("N", "N*mm", "unit N cannot be converted to N*mm"),
    ("degC", "delta_degC", "unit degC cannot be converted to delta_degC"),
    ("flubs", "mm", "d [flubs]: unknown unit 'flubs'"),
])
def test_convert_column_refusals(unit, target, message):
    with pytest.raises(UnitError) as exc:
        convert_column(np.array([1.0]), unit, target, name="d")
    assert str(exc.value) == message


def test_units_follow_a_switched_application_registry():
    # parsed units and conversion factors are remembered; a new application registry gets its own units
    import pint

    from bearingheat.units import magnitude, quantity, speed_rpm
    before = pint.get_application_registry().get()
    fresh = pint.UnitRegistry()
    pint.set_application_registry(fresh)
    try:
        torque = quantity(2.0, "N*mm")
        assert torque._REGISTRY is fresh and torque.to("N*m").magnitude == pytest.approx(2e-3, rel=1e-15)
        assert magnitude(2.5 * fresh.kN, "N", "Fr") == 2500.0
        assert speed_rpm(50 * fresh.Hz) == 3000.0
    finally:
        pint.set_application_registry(before)
    assert quantity(1.0, "N")._REGISTRY is before


@pytest.mark.parametrize("value, unit, expected", [
    ((553.15, "K"), "degC", 280.0), ((0.0, "K"), "degC", -273.15), ((536.0, "degF"), "degC", 280.0),
    ((20.0, "degC"), "K", 293.15), ((10.0, "K"), "delta_degC", 10.0), ((1.0, "kN"), "N", 1000.0),
])
def test_magnitude_converts_absolute_temperatures_with_their_offset(value, unit, expected):
    """K to degC is no factor (1 K is not -272.15 degC per kelvin): the offset conversion is used wherever either
    side has an offset (a bushing at 553.15 K read as -1.5e5 degC before)."""
    from bearingheat.units import magnitude, ureg
    assert magnitude(ureg().Quantity(*value), unit, "T") == pytest.approx(expected, rel=1e-12)
