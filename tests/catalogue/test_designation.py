"""Designations to bearing types and table rows; GOST numbers of the DP11A manual."""
import pytest

from bearingheat.catalogue.friction import resolve
from bearingheat.catalogue.designation import bore_from_code, decode_gost, parse_designation
from bearingheat.errors import DesignationError

# designation -> (type, series, prefix, bore mm, seal)
EXPECTED = {
    "6205": ("deep_groove_ball", "62", "", 25.0, "open"),
    "6205-2RSR": ("deep_groove_ball", "62", "", 25.0, "contact"),
    "62..-2Z": ("deep_groove_ball", "62", "", None, "shield"),
    "6205ZZ": ("deep_groove_ball", "62", "", 25.0, "shield"),
    "61805": ("deep_groove_ball", "618", "", 25.0, "open"),
    "16005": ("deep_groove_ball", "160", "", 25.0, "open"),
    "62305-2RSR": ("deep_groove_ball", "623", "", 25.0, "contact"),
    "623": ("deep_groove_ball", "62", "", 3.0, "open"),
    "6000": ("deep_groove_ball", "60", "", 10.0, "open"),
    "6230": ("deep_groove_ball", "62", "", 150.0, "open"),
    "4205-B": ("deep_groove_ball", "42", "", 25.0, "open"),
    "7205-B": ("angular_contact_ball", "72", "", 25.0, "open"),
    "7205-B-2RS": ("angular_contact_ball", "72", "", 25.0, "contact"),
    "71805-B": ("angular_contact_ball", "718", "", 25.0, "open"),
    "3205-B": ("angular_contact_ball_double_row", "32", "", 25.0, "open"),
    "NU206-E": ("cylindrical_roller", "2", "NU", 30.0, "open"),
    "NU 206 E": ("cylindrical_roller", "2", "NU", 30.0, "open"),
    "NJ2210-E": ("cylindrical_roller", "22", "NJ", 50.0, "open"),
    "NUP312-E": ("cylindrical_roller", "3", "NUP", 60.0, "open"),
    "NU2232-E": ("cylindrical_roller", "22", "NU", 160.0, "open"),
    "NN3010": ("cylindrical_roller", "30", "NN", 50.0, "open"),
    "SL182205": ("cylindrical_roller_full_complement", "SL1822", "", 25.0, "open"),
    "30205-A": ("tapered_roller", "302", "", 25.0, "open"),
    "32210": ("tapered_roller", "322", "", 50.0, "open"),
    "320/28-X": ("tapered_roller", "320", "", 28.0, "open"),
    "T4CB100": ("tapered_roller", "T4CB", "", 100.0, "open"),
    "22210-E1": ("spherical_roller", "222", "", 50.0, "open"),
    "29412-E": ("axial_spherical_roller", "294", "", 60.0, "open"),
    "51105": ("thrust_ball", "511", "", 25.0, "open"),
    "81105": ("thrust_roller", "811", "", 25.0, "open"),
    "AXK2035": ("thrust_roller", "AXK", "", 20.0, "open"),
    "QJ210": ("four_point_contact_ball", "QJ2", "", 50.0, "open"),
    "1205": ("self_aligning_ball", "12", "", 25.0, "open"),
    "2205": ("self_aligning_ball", "22", "", 25.0, "open"),
    "NA4905": ("needle_roller", "NA49", "", 25.0, "open"),
    "HK2016": ("needle_roller", "HK", "", 20.0, "open"),
    "NK25/20": ("needle_roller", "NK", "", 25.0, "open"),
    "K20x24x10": ("needle_roller", "K", "", 20.0, "open"),
    "ZARN2052": ("combined", "ZARN", "", None, "open"),
    "1000095": ("deep_groove_ball", "619", "", 5.0, "open"),
    "18": ("deep_groove_ball", "60", "", 8.0, "open"),
    "101": ("deep_groove_ball", "60", "", 12.0, "open"),
}


@pytest.mark.parametrize("text", list(EXPECTED))
def test_designation(text):
    d = parse_designation(text)
    assert (d.bearing_type, d.series, d.prefix, d.bore, d.seal) == EXPECTED[text]
    resolve(text)  # every example resolves to a table row


def test_widths_and_angles():
    assert parse_designation("HK2016").width == 16.0
    assert parse_designation("NK25/20").width == 20.0
    assert parse_designation("7205-B").contact_angle == 40.0
    assert parse_designation("7205-AC").contact_angle == 25.0
    assert parse_designation("7205").contact_angle is None


def test_bore_codes():
    assert [bore_from_code(c) for c in ("00", "01", "02", "03", "04", "05", "64")] == [10, 12, 15, 17, 20, 25, 320]


def test_gost_seed_000():
    """The DP11A manual p. 4: digits from the right: bore, diameter series, type, design (2), width series."""
    g = decode_gost("1000095")
    assert (g.bore, g.diameter_series, g.diameter_series_name, g.type_digit, g.bearing_type, g.design,
            g.width_series) == (5.0, "9", "ultra light", "0", "deep_groove_ball", "00", "1")
    g = decode_gost("18")
    assert (g.bore, g.diameter_series, g.diameter_series_name, g.bearing_type) == (8.0, "1", "extra light",
                                                                                  "deep_groove_ball")
    g = decode_gost("101")
    assert (g.bore, g.diameter_series, g.bearing_type) == (12.0, "1", "deep_groove_ball")
    assert decode_gost("36205").bore == 25.0 and decode_gost("36205").bearing_type == "angular_contact_ball"
    assert decode_gost("7208").bearing_type == "tapered_roller"


def test_gost_errors():
    with pytest.raises(DesignationError) as exc:
        decode_gost("12a")
    assert str(exc.value) == "designation: '12a' is not a GOST 3189 number (2 to 7 digits)"
    with pytest.raises(DesignationError) as exc:
        decode_gost("5205")
    assert str(exc.value) == "designation: '5205' has type digit '5', not a GOST 3189 type"


def test_unknown_designation_lists_close_matches():
    with pytest.raises(DesignationError) as exc:
        parse_designation("7905")
    # difflib's closest designations of the bearing table: the ISO 355 codes T7FC0.. share 7, 9, 0 with it
    assert str(exc.value) == ("designation: '7905' matches no row of the Schaeffler catalogue tables (close matches: T7FC090, "
                              "T7FC085, T7FC075, T7FC055, T7FC050); give type and series explicitly instead")
    with pytest.raises(DesignationError) as exc:
        parse_designation("6208X")
    assert str(exc.value) == ("designation: '6208X' matches no row of the Schaeffler catalogue tables (close matches: 6208, 6208-2Z, "
                              "6208-2RSR, 608, 6320); give type and series explicitly instead")


def test_empty_designation():
    with pytest.raises(DesignationError) as exc:
        parse_designation("  ")
    assert str(exc.value) == "designation: '  ' is empty; give a designation or type and series"


def test_kb_from_designation():
    assert resolve("NJ2210-E").kB == 15.0
    assert resolve("NUP312-E").kB == 20.0
    assert resolve("NJ406").kB == 22.0
    assert resolve("SL182205").kB == 20.0
    assert resolve(bearing_type="cylindrical_roller", series="22").kB == 15.0
    assert resolve("NU206-E").cannot_take_axial and not resolve("NU206-E").takes_axial_m2
