"""The rows the candidate effects work on: measured torque with the catalogue model's kernel outputs
(:class:`ModelData`, for diagnose's fits) and calc's results as a fitted effect changes them (:class:`CalcRows`,
for ``calc --effects``), with the catalogue model's arrays they re-evaluate M1 on.

The candidates themselves are :mod:`bearingheat.analysis.effects`, which imports these names too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np
import pandas as pd

from bearingheat.calc.friction import evaluate_catalogue_model
from bearingheat.calc.messages import Labels
from bearingheat.calc.models import support_arrays_of
from bearingheat.calc.supports import SupportArrays
from bearingheat.kernels import friction

__all__ = ["ModelData", "CalcRows", "catalogue_arrays", "evaluate_with_axial_load", "bearing_keys", "m1_load"]


# ---------------------------------------------------------------------------------------------
# The catalogue model arrays (to re-evaluate M1 under a changed axial load)
# ---------------------------------------------------------------------------------------------

def catalogue_arrays(frame: pd.DataFrame) -> tuple[SupportArrays, np.ndarray]:
    """The support arrays of a catalogue-unit frame, and the rows whose bearing did not resolve.

    Built as calc builds them (:func:`bearingheat.calc.models.support_arrays_of`,
    bearings resolved once per distinct key); a row whose designation,
    lubrication or arrangement cannot be used is flagged in the mask.
    """
    supports = support_arrays_of(frame)
    unresolved = ~np.broadcast_to(supports.resolved, (supports.size,)) | \
        (np.broadcast_to(supports.error, (supports.size,)) != "")
    return supports, unresolved


def evaluate_with_axial_load(supports: SupportArrays, rows: np.ndarray, Fa: np.ndarray) -> np.ndarray:
    """M1 + M2 [N·mm] of ``rows`` of the support arrays with the axial load replaced by ``Fa``."""
    sub = supports.take(np.asarray(rows)).replace(Fa=np.asarray(Fa, dtype=float))
    with np.errstate(all="ignore"):
        results, _ = evaluate_catalogue_model(sub, Labels())
    return results["M1"] + results["M2"]


def m1_load(P1: np.ndarray, arrays: SupportArrays) -> np.ndarray:
    """The load M1 works with [N]: P1, or F (Fr of radial, Fa of thrust bearings) where P1 is not given."""
    return np.where(~np.isnan(P1), P1, np.where(arrays.m1_load == "Fa", arrays.Fa, arrays.Fr))


def bearing_keys(frame: pd.DataFrame) -> np.ndarray:
    """The name of each row's bearing: its designation, else 'type series dxD'.

    The seal torque and preload of ``diagnose`` are fitted per key, and
    ``calc --effects`` looks them up by the same key.
    """
    def text(col: str) -> list[str | None]:
        if col not in frame.columns:
            return [None] * len(frame)
        return [None if v is None or (isinstance(v, float) and math.isnan(v)) or str(v).strip() == ""
                else str(v).strip() for v in frame[col]]

    def number(col: str) -> np.ndarray:
        if col not in frame.columns:
            return np.full(len(frame), np.nan)
        return pd.to_numeric(frame[col], errors="coerce").to_numpy(dtype=float)

    d, D = number("d"), number("D")
    out: list[str] = []
    for des, typ, ser, di, Di in zip(text("designation"), text("type"), text("series"), d, D):
        if des:
            out.append(des)
        else:
            size = f" {di:g}x{Di:g}" if not (np.isnan(di) or np.isnan(Di)) else ""
            out.append(f"{typ} {ser}{size}")
    return np.array(out, dtype=object)


# ---------------------------------------------------------------------------------------------
# Data the candidates work on
# ---------------------------------------------------------------------------------------------

@dataclass
class ModelData:
    """Measured torque with the catalogue model's kernel outputs, one entry per usable row.

    All arrays share one length; ``bearing`` holds integer codes into
    ``bearing_names``. ``arrays`` are the support arrays of the same rows
    (for the preload candidate), ``t`` and ``T_oil`` are NaN when not measured.
    """

    M: np.ndarray
    M0: np.ndarray
    M1: np.ndarray
    M2: np.ndarray
    f0: np.ndarray
    n: np.ndarray
    nu: np.ndarray
    dM: np.ndarray
    Fr: np.ndarray
    Fa: np.ndarray
    load: np.ndarray
    t: np.ndarray
    T_oil: np.ndarray
    bearing: np.ndarray
    bearing_names: list[str]
    arrays: SupportArrays | None = field(repr=False, default=None)

    @property
    def MR(self) -> np.ndarray:
        return self.M0 + self.M1 + self.M2

    @property
    def NR(self) -> np.ndarray:
        return friction.power_loss(self.MR, self.n)

    def __len__(self) -> int:
        return len(self.M)

    def take(self, rows: np.ndarray) -> ModelData:
        """The entries at positions ``rows`` (the bearing codes and names as they are)."""
        per_row = {f.name: getattr(self, f.name)[rows] for f in fields(self)
                   if isinstance(getattr(self, f.name), np.ndarray)}
        return replace(self, **per_row, arrays=self.arrays.take(rows) if self.arrays is not None else None)


@dataclass
class CalcRows:
    """The results of ``calc`` as a fitted effect changes them (catalogue units, one entry per row).

    ``ok`` marks the rows not in error, the only rows an effect changes.
    ``MR`` starts as the catalogue model's torque and is changed in place;
    ``notes`` maps a row position to the note its message gets (every ``ok``
    row starts with the effect's description). ``keys`` are the rows'
    :func:`bearing_keys`, ``arrays`` their support arrays (:func:`catalogue_arrays`),
    ``results`` the calc results (read only).
    """

    frame: pd.DataFrame
    results: pd.DataFrame
    ok: np.ndarray
    MR: np.ndarray
    M0: np.ndarray
    n: np.ndarray
    nu: np.ndarray
    dM: np.ndarray
    keys: np.ndarray
    arrays: SupportArrays = field(repr=False)
    notes: dict[int, str] = field(default_factory=dict)

    @property
    def positions(self) -> np.ndarray:
        return np.flatnonzero(self.ok)
