"""Reference conditions of the thermal reference speed and the bearing types the thermal method covers.

The method is the published one of the Schaeffler HR 1 catalogue (2006,
after ISO 15312 and the draft of DIN 732); the Schaeffler catalogue
(p. 63, "Теплоотвод") names it, its page 72 with the formulas is missing
from the text. The reference conditions are ``tables/thermal_reference_conditions.csv``.

>>> reference_conditions("radial").temperature_rise
50.0
>>> THERMAL_KIND["tapered_roller"], THERMAL_KIND["thrust_ball"]
('tapered', None)
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

from bearingheat.catalogue.tables import load_table
from bearingheat.errors import HeatBalanceError

__all__ = [
    "THERMAL_KIND",
    "THERMAL_KINDS",
    "REFERENCE_KIND",
    "REFUSED_TYPES",
    "CONTACT_SEAL_REASON",
    "SEAL_FRICTION_REASON",
    "ReferenceConditions",
    "reference_conditions",
    "method_refusal",
]

#: bearing type -> geometry of the heat flow area and reference conditions; None: the method does not apply
THERMAL_KIND: dict[str, str | None] = {
    "needle_roller": "radial",
    "cylindrical_roller_full_complement": "radial",
    "cylindrical_roller": "radial",
    "tapered_roller": "tapered",
    "spherical_roller": "radial",
    "deep_groove_ball": "radial",
    "angular_contact_ball": "radial",
    "angular_contact_ball_double_row": "radial",
    "self_aligning_ball": "radial",
    "four_point_contact_ball": "radial",
    "thrust_roller": "thrust",
    "axial_spherical_roller": "axial_spherical",  # A_r of HR 1 p. 64 with d1, D1; thrust reference conditions
    "thrust_ball": None,
    "combined": None,
}
#: the kinds of heat flow area, in the order rows are grouped by them
THERMAL_KINDS = ("radial", "tapered", "thrust", "axial_spherical")
#: kind of heat flow area -> the reference conditions it takes (tables/thermal_reference_conditions.csv)
REFERENCE_KIND = {"radial": "radial", "tapered": "radial", "thrust": "thrust", "axial_spherical": "thrust"}
#: why THERMAL_KIND is None for a type
REFUSED_TYPES = {
    "thrust_ball": "the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings",
    "combined": ("combined radial/thrust bearings have no single heat flow area A_r in the method "
                 "(radial: pi*B*(D+d), thrust: (pi/2)*(D^2-d^2))"),
}
#: why a bearing with contact seals gets no n_thr, n_per or T_op: ISO 15312's reference conditions have no seal
#: friction, HR 1 prints '–' for the n_B of its -2RSR and -2RS bearings, and the model has no seal term
CONTACT_SEAL_REASON = ("the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its "
                       "reference conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; "
                       "n_per and T_op, whose heat balance would leave the seal friction out, are not computed either")
#: why a bearing with contact seals whose friction model has a seal term (the SKF model's M_seal) gets no n_thr, and
#: what its n_per and T_op are: the heat balance of DIN 732 with the seal friction in N_R, bearingheat's extension
SEAL_FRICTION_REASON = ("ISO 15312 defines no thermal reference speed for bearings with contact seals (its reference "
                        "conditions have no seal friction; Schaeffler HR 1 prints none for them); n_per and T_op are "
                        "the heat balance's with the seal friction M_seal of the friction model in N_R (bearingheat's "
                        "extension of the method, whose sources leave sealed bearings out)")


@dataclass(frozen=True)
class ReferenceConditions:
    """Reference conditions of the thermal reference speed for radial or thrust bearings."""

    kind: str               # 'radial' (also tapered) or 'thrust'
    load_ratio: float       # P1/C0 (radial) or Fa/C0 (thrust) [-]
    nu: float               # oil-bath viscosity [mm²/s]
    q_r: float              # heat flux density up to A_r_limit [W/mm²]
    A_r_limit: float        # [mm²]
    q_r_exponent: float     # q_r·(A_r/A_r_limit)^exponent above the limit [-]
    T_ambient: float        # [°C]
    T_bearing: float        # outer ring [°C]

    @property
    def temperature_rise(self) -> float:
        """Δθ_A of the reference conditions [K] (70 °C − 20 °C = 50 K)."""
        return self.T_bearing - self.T_ambient


@functools.lru_cache(maxsize=None)
def reference_conditions(kind: str) -> ReferenceConditions:
    """Reference conditions for 'radial', 'tapered' (radial conditions) or 'thrust' bearings.

    >>> r = reference_conditions("radial")
    >>> r.load_ratio, r.nu, r.q_r, r.temperature_rise
    (0.05, 12.0, 0.016, 50.0)
    >>> reference_conditions("thrust").q_r_exponent
    -0.16
    """
    if kind not in REFERENCE_KIND:
        raise HeatBalanceError(f"kind: {kind!r} is not one of {', '.join(REFERENCE_KIND)}")
    key = REFERENCE_KIND[kind]
    table = load_table("thermal_reference_conditions")
    hit = table[table["kind"] == key]
    row = hit.iloc[0]
    return ReferenceConditions(kind=key, load_ratio=float(row["load_ratio"]), nu=float(row["nu_ref"]),
                               q_r=float(row["q_r"]), A_r_limit=float(row["A_r_limit"]),
                               q_r_exponent=float(row["q_r_exponent"]), T_ambient=float(row["T_ambient"]),
                               T_bearing=float(row["T_bearing"]))


def method_refusal(bearing_type: str, seal: str = "open") -> str:
    """Why the thermal method does not apply to a bearing ('' when it does).

    >>> method_refusal("thrust_ball")
    'the thermal method (ISO 15312, DIN 732) does not apply to thrust ball bearings'
    >>> print(method_refusal("deep_groove_ball", "contact"))
    the thermal method (ISO 15312, DIN 732) does not apply to bearings with contact seals: its reference
    conditions have no seal friction, and Schaeffler HR 1 prints no n_thr for them; n_per and T_op, whose heat
    balance would leave the seal friction out, are not computed either
    >>> method_refusal("deep_groove_ball", "shield")
    ''
    """
    if THERMAL_KIND.get(bearing_type, None) is None:
        return REFUSED_TYPES.get(bearing_type, f"no thermal reference conditions for {bearing_type!r}")
    if seal == "contact":
        return CONTACT_SEAL_REASON
    return ""
