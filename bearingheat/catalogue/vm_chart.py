"""User-digitised charts of the SKF drag loss factor VM against the oil level H/dm.

The drag torque of the SKF model in an oil bath needs VM, which both SKF
editions give only as a diagram: SKF General Catalogue 6000, diagram 2
(p. 99), and SKF «Rolling bearings» 10000/3, diagram 4 (p. 112), each with
one curve for ball bearings and one for roller bearings. The diagrams are
not in the public catalogue texts, so bearingheat never ships VM values:
the user digitises the diagram of their edition and passes the points as a
CSV (``calc --vm-chart FILE``). A VM read off one edition's diagram belongs
to that edition's drag formula, so every curve names its edition.

CSV format (one row per digitised point, a units row under the header)::

    edition,curve,H_over_dm,VM,source
    -,-,1,1,-
    10000,ball,0.05,0.00002,my copy of SKF 10000/3 p. 112 diagram 4
    10000,ball,0.5,0.00012,my copy of SKF 10000/3 p. 112 diagram 4
    10000,roller,0.05,0.00004,my copy of SKF 10000/3 p. 112 diagram 4
    ...

- ``edition``: ``6000`` or ``10000`` (the ``skf_edition`` of the rows it serves).
- ``curve``: ``ball`` or ``roller``.
- ``H_over_dm``: the oil level H over the mean diameter dm = (d + D)/2; ``VM``
  the factor (the units row may scale it: ``percent``; no other unit fits).
- at least two points per curve, ``H_over_dm`` strictly increasing, every
  value >= 0; ``source`` is optional.

VM is interpolated linearly in H/dm along the row's curve (the diagrams have
linear axes) and never extrapolated: a level outside the digitised range is
refused.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bearingheat.catalogue.digitised import read_chart_csv
from bearingheat.catalogue.skf import EDITIONS
from bearingheat.errors import UnitError, VMChartError
from bearingheat.units import convert_column

__all__ = ["VMChart", "CURVES"]

#: the two curves of each edition's diagram
CURVES = ("ball", "roller")


@dataclass(frozen=True)
class _Curve:
    H_over_dm: np.ndarray
    VM: np.ndarray


class VMChart:
    """Curves VM(H/dm) per SKF edition and bearing kind, interpolated linearly and never extrapolated.

    Read one with :meth:`from_csv` (format in the module docstring) and pass
    it to :func:`~bearingheat.calc.table.calc` (``vm_chart``), which fills a
    blank VM of every oil-bath row of the SKF model from it; :meth:`lookup`
    reads VM.

    Parameters
    ----------
    points : dict of (str, str) to (list of float, list of float)
        (edition, curve) -> ([H/dm], [VM]): edition '6000' or '10000', curve
        'ball' or 'roller'; at least two points per curve, H/dm strictly
        increasing, every value >= 0.
    name : str, optional
        Name of the chart in messages (the CSV path for :meth:`from_csv`);
        default 'VM chart'.

    Raises
    ------
    bearingheat.errors.VMChartError
        For no curves, an edition or curve name that is not known, a curve
        with fewer than two points, a negative value, or H/dm not strictly
        increasing along a curve.

    Examples
    --------
    >>> chart = VMChart({("10000", "ball"): ([0.0, 0.5, 1.0], [0.0, 1.0e-4, 1.6e-4])})   # made-up points
    >>> VM, refused = chart.lookup("10000", "ball", [0.25, 1.2])
    >>> VM.tolist(), refused[1]
    ([5e-05, nan], "H/dm = 1.2 is outside the VM chart's ball bearing curve of SKF 10000/3 (0 to 1); the chart is not extrapolated")
    """

    def __init__(self, points: dict[tuple[str, str], tuple[list[float], list[float]]], name: str = "VM chart"):
        self.name = name
        curves: dict[tuple[str, str], _Curve] = {}
        for (edition, kind), (given_x, given_vm) in points.items():
            where = f"{name}, edition {edition!r} curve {kind!r}"
            if edition not in EDITIONS:
                raise VMChartError(f"{where}: the edition must be one of {', '.join(EDITIONS)}")
            if kind not in CURVES:
                raise VMChartError(f"{where}: the curve must be one of {', '.join(CURVES)}")
            x = np.asarray(given_x, dtype=float)
            vm = np.asarray(given_vm, dtype=float)
            if len(x) < 2:
                raise VMChartError(f"{where}: needs at least two points, has {len(x)}")
            if not (np.all(np.isfinite(x)) and np.all(np.isfinite(vm)) and np.all(x >= 0) and np.all(vm >= 0)):
                raise VMChartError(f"{where}: H_over_dm and VM must all be numbers >= 0")
            if np.any(np.diff(x) <= 0):
                raise VMChartError(f"{where}: H_over_dm must increase strictly from point to point")
            curves[(edition, kind)] = _Curve(x, vm)
        if not curves:
            raise VMChartError(f"{name}: no curves")
        self._curves = curves

    @classmethod
    def from_csv(cls, path: str | Path) -> "VMChart":
        """Read a digitised chart in the format of the module docstring."""
        path = Path(path)
        col, units, rows = read_chart_csv(path, ["edition", "curve", "H_over_dm", "VM"], "a VM chart", VMChartError)
        scales = {}
        for column in ("H_over_dm", "VM"):
            try:
                scales[column] = convert_column(np.ones(1), units[col[column]], "1", name=column)[1]
            except (UnitError, IndexError) as exc:
                unit = units[col[column]] if col[column] < len(units) else ""
                raise VMChartError(f"{path}: units row: {column} unit {unit!r} is not dimensionless") from exc
        points: dict[tuple[str, str], tuple[list[float], list[float]]] = {}
        for line_no, row in rows:
            try:
                key = (row[col["edition"]].strip(), row[col["curve"]].strip().lower())
                x, vm = float(row[col["H_over_dm"]]), float(row[col["VM"]])
            except (ValueError, IndexError) as exc:
                raise VMChartError(f"{path}, line {line_no}: not a number in {row!r}") from exc
            known = points.setdefault(key, ([], []))
            known[0].append(x * scales["H_over_dm"])
            known[1].append(vm * scales["VM"])
        return cls(points, name=str(path))

    @property
    def curves(self) -> list[tuple[str, str]]:
        """The (edition, curve) pairs the chart has."""
        return sorted(self._curves)

    def lookup(self, edition, kind, H_over_dm) -> tuple[np.ndarray, np.ndarray]:
        """VM at each query, and a refusal message per query ('' where VM is valid; VM NaN where refused).

        ``edition`` ('6000' or '10000') and ``kind`` ('ball' or 'roller')
        are one value or one per query.
        """
        x = np.atleast_1d(np.asarray(H_over_dm, dtype=float))
        editions = np.broadcast_to(np.asarray(edition, dtype=object), x.shape)
        kinds = np.broadcast_to(np.asarray(kind, dtype=object), x.shape)
        VM = np.full(x.shape, np.nan)
        reasons = np.full(x.shape, "", dtype=object)
        for key in set(zip(editions.tolist(), kinds.tolist())):
            rows = (editions == key[0]) & (kinds == key[1])
            what = f"the VM chart's {key[1]} bearing curve of SKF {'10000/3' if key[0] == '10000' else key[0]}"
            curve = self._curves.get(key)
            if curve is None:
                reasons[rows] = f"{self.name} has no {key[1]} bearing curve for SKF edition {key[0]}"
                continue
            lo, hi = float(curve.H_over_dm[0]), float(curve.H_over_dm[-1])
            inside = rows & (x >= lo) & (x <= hi)
            VM[inside] = np.interp(x[inside], curve.H_over_dm, curve.VM)
            for i in np.flatnonzero(rows & ~inside):
                reasons[i] = (f"H/dm = {x[i]:.4g} is outside {what} ({lo:g} to {hi:g}); "
                              "the chart is not extrapolated")
        return VM, reasons
