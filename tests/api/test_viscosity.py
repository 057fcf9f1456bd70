"""The unit-aware oil viscosity (issue 3): units, range warnings, refusals."""
from __future__ import annotations

import re
import warnings

import numpy as np
import pint
import pytest

from bearingheat.api.viscosity import oil_viscosity
from bearingheat.errors import UnitError, ViscosityError, ViscosityRangeWarning

u = pint.get_application_registry()


def test_oil_viscosity_units_and_warning():
    a = oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"), nu100=28 * u.cSt)
    b = oil_viscosity(u.Quantity(333.15, "K"), nu40=4.04e-4 * u("m^2/s"), nu100=0.28 * u.St)
    assert a.units == u("mm^2/s").units
    assert a.magnitude == pytest.approx(b.magnitude, rel=1e-9)
    with pytest.warns(ViscosityRangeWarning, match=re.escape(
            "nu = 1.402 mm^2/s at 200 degC is below 2 mm^2/s, outside ASTM D341 (an extrapolation)")):
        oil_viscosity(u.Quantity(200, "degC"), nu40=32 * u("mm^2/s"), nu100=5.4 * u("mm^2/s"))
    with pytest.warns(ViscosityRangeWarning, match=re.escape("-30 degC is below the pour point -24 degC")):
        oil_viscosity(u.Quantity(-30, "degC"), iso_vg=68, pour_point=u.Quantity(-24, "degC"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        oil_viscosity(u.Quantity(70, "degC"), iso_vg=68, viscosity_index=140)


def test_oil_viscosity_errors():
    with pytest.raises(ViscosityError, match=re.escape(
            "oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got nu40 only)")):
        oil_viscosity(u.Quantity(60, "degC"), nu40=404 * u("mm^2/s"))
    with pytest.raises(ViscosityError, match=re.escape(
            "oil_viscosity: give nu40 and nu100 together, or points, or iso_vg (got nu40, nu100, iso_vg)")):
        oil_viscosity(u.Quantity(60, "degC"), nu40=68 * u("mm^2/s"), nu100=8 * u("mm^2/s"), iso_vg=68)
    with pytest.raises(ViscosityError, match=re.escape(
            "iso_vg: 70 is not an ISO VG grade; expected one of 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, "
            "220, 320, 460, 680, 1000, 1500, 2200, 3200")):
        oil_viscosity(u.Quantity(60, "degC"), iso_vg=70)
    with pytest.raises(UnitError, match=re.escape(
            "temperature: 60 delta_degree_Celsius is a temperature difference; give an absolute temperature "
            "(degC, K)")):
        oil_viscosity(u.Quantity(60, "delta_degC"), iso_vg=68)


MM2S = u("mm^2/s")


@pytest.mark.parametrize("temperature, data, message", [
    (u.Quantity(70, "degC"), dict(nu40=68 * MM2S, nu100=80 * MM2S),
     "nu40 and nu100: the viscosity must fall as the temperature rises (68 mm^2/s at 40 degC, 80 mm^2/s at 100 degC)"),
    (u.Quantity(70, "degC"), dict(nu40=68 * MM2S, nu100=1 * MM2S), "nu100: 1 mm^2/s must be >= 2 (ASTM D341)"),
    (u.Quantity(70, "degC"), dict(nu40=-68 * MM2S, nu100=8 * MM2S), "nu40: -68 mm^2/s must be >= 2 (ASTM D341)"),
    (u.Quantity(70, "degC"), dict(nu40=float("nan") * MM2S, nu100=8 * MM2S),
     "nu40: nan mm^2/s must be >= 2 (ASTM D341)"),
    (u.Quantity(70, "degC"), dict(points=((68 * MM2S, u.Quantity(40, "degC")), (30 * MM2S, u.Quantity(40, "degC")))),
     "points: both at 40 degC; two temperatures fix the line"),
    (u.Quantity(70, "degC"), dict(points=((30 * MM2S, u.Quantity(40, "degC")), (68 * MM2S, u.Quantity(80, "degC")))),
     "points: the viscosity must fall as the temperature rises (30 mm^2/s at 40 degC, 68 mm^2/s at 80 degC)"),
    (u.Quantity(-200, "degC"), dict(nu40=68 * MM2S, nu100=8.6 * MM2S),
     "temperature: -200 degC is so far below the oil's data that its viscosity line overflows (ASTM D341 holds down "
     "to about the pour point)"),
    (u.Quantity(-10, "K"), dict(nu40=68 * MM2S, nu100=8.6 * MM2S),
     "temperature: -283.15 degC is at or below absolute zero"),
    (u.Quantity(70, "degC"), dict(nu40=np.array([68.0, 5.0]) * MM2S, nu100=8.6 * MM2S),
     "nu40 and nu100: the viscosity must fall as the temperature rises (5 mm^2/s at 40 degC, 8.6 mm^2/s at 100 degC) "
     "(at index 1)"),
])
def test_oil_data_that_fix_no_line_are_refused(temperature, data, message):
    """No NaN or infinite viscosity comes back: data that fix no Walther line, and temperatures it cannot reach,
    raise with the value (calc refuses the same oil data per row)."""
    with pytest.raises(ViscosityError, match=f"^{re.escape(message)}$"):
        oil_viscosity(temperature, **data)
