"""What every result of the unit-aware API can do: a table, a short repr, an HTML view in notebooks.

A result is a frozen dataclass of pint Quantities (or plain numbers for
dimensionless values) with one entry per operating point, and ``status``
and ``messages`` with one entry per point: 'ok', 'warning' or 'error', and
the point's messages joined by '; '.
"""
from __future__ import annotations

import dataclasses
from typing import Any, ClassVar

import numpy as np
import pandas as pd

from bearingheat.calc.contract import output_header, output_units
from bearingheat.errors import UnitError
from bearingheat.units import magnitude, quantity_parts

__all__ = ["Result"]

#: fields that are not per-point numbers
_NOT_COLUMNS = ("status", "messages")


class Result:
    """Mixin of the API's result dataclasses: :meth:`to_frame`, a short ``repr`` and ``_repr_html_``."""

    status: list[str]
    messages: list[str]
    #: field -> unit for fields the column contract does not name (the contract's unit wins where it does)
    UNITS: ClassVar[dict[str, str]] = {}

    def _numbers(self) -> dict[str, tuple[np.ndarray, str]]:
        """Field name -> (flat magnitudes, unit) of the per-point values, in the contract's unit where the contract
        names the field, else in the class's :attr:`UNITS`."""
        units = {**self.UNITS, **output_units()}
        out = {}
        for item in dataclasses.fields(self):  # type: ignore[arg-type]
            value = getattr(self, item.name)
            if item.name in _NOT_COLUMNS or isinstance(value, (str, dict, list, tuple)) or value is None:
                continue
            unit = units.get(item.name)
            if unit not in (None, "", "1"):
                try:
                    numbers = np.ravel(np.asarray(magnitude(value, unit, item.name), dtype=float))
                except UnitError:
                    numbers, unit = quantity_parts(value)
            else:
                numbers, unit = quantity_parts(value)
            out[item.name] = (numbers, unit or "")
        return out

    def __len__(self) -> int:
        return len(self.status)

    def to_frame(self) -> pd.DataFrame:
        """One row per operating point: the values under ``name [unit]`` headers as ``calc`` writes them, then
        ``status`` and ``message``."""
        columns: dict[str, Any] = {}
        for name, (numbers, unit) in self._numbers().items():
            columns[output_header(name, unit) if unit else name] = np.broadcast_to(numbers, (len(self),))
        columns["status"] = list(self.status)
        columns["message"] = list(self.messages)
        # the index of pint-pandas Series arguments (a result field is then a Series of the points), else 0, 1 ...
        index = next((value.index for item in dataclasses.fields(self)  # type: ignore[arg-type]
                      if isinstance(value := getattr(self, item.name), pd.Series) and len(value) == len(self)), None)
        return pd.DataFrame(columns, index=index)

    def __repr__(self) -> str:
        counts = {s: self.status.count(s) for s in ("ok", "warning", "error") if self.status.count(s)}
        lines = [f"{type(self).__name__}: {len(self)} point{'s' if len(self) != 1 else ''} "
                 f"({', '.join(f'{n} {s}' for s, n in counts.items())})"]
        for name, (numbers, unit) in self._numbers().items():
            finite = numbers[np.isfinite(numbers)]
            if not len(finite):
                continue
            shown = f"{finite[0]:.4g}" if len(finite) == 1 or np.ptp(finite) == 0 else \
                f"{finite.min():.4g} to {finite.max():.4g}"
            lines.append(f"  {name} = {shown}{' ' + unit if unit else ''}")
        first = next((m for m in self.messages if m), "")
        if first:
            lines.append(f"  first message: {first}")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        return self.to_frame().to_html(index=False, na_rep="–", float_format=lambda x: f"{x:.4g}")
