"""JSON writing helpers shared by the report writers and the command line."""
from __future__ import annotations

import datetime
import decimal
import json
import math

import numpy as np
import pandas as pd

__all__ = ["json_safe", "results_json"]


def json_safe(value):
    """Replace non-finite floats by None so that the summary is strict JSON.

    Dicts, lists and tuples are walked (tuples become lists); numpy floats and
    integers become Python numbers.

    Dates and times (a passed-through column) become ISO 8601 text, decimals
    floats, bytes UTF-8 text.

    >>> json_safe({"f": float("nan"), "t": [1.5, float("inf")], "k": np.int64(3)})
    {'f': None, 't': [1.5, None], 'k': 3}
    >>> json_safe([pd.Timestamp("2024-05-01"), datetime.date(2024, 5, 2), decimal.Decimal("1.25")])
    ['2024-05-01T00:00:00', '2024-05-02', 1.25]
    """
    if isinstance(value, dict):
        return {k: json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (np.bool_,)):
        return bool(value)
    if value is pd.NaT:
        return None
    if isinstance(value, np.datetime64):
        value = pd.Timestamp(value)
    if isinstance(value, (datetime.date, datetime.time)):  # (a pd.Timestamp is a datetime.datetime)
        return value.isoformat()
    if isinstance(value, decimal.Decimal):
        return float(value) if value.is_finite() else None
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return value


def results_json(result: pd.DataFrame, duty: pd.DataFrame | None = None) -> str:
    """calc results as JSON: ``{"results": [one object per row, keyed by the 'name [unit]' headers],
    "counts": {"ok": .., "warning": .., "error": ..}}`` and ``"duty_cycle"`` where there is one; NaN is null.

    >>> print(results_json(pd.DataFrame({"MR [N*mm]": [1.5, float("nan")], "status": ["ok", "error"]})))
    {"results": [{"MR [N*mm]": 1.5, "status": "ok"}, {"MR [N*mm]": null, "status": "error"}], "counts": {"ok": 1, "warning": 0, "error": 1}}
    """
    def records(frame: pd.DataFrame) -> list:
        return json_safe([{str(k): (None if v is pd.NA else v) for k, v in row.items()}
                          for row in frame.astype(object).to_dict(orient="records")])

    counts = result["status"].value_counts()
    out = {"results": records(result), "counts": {s: int(counts.get(s, 0)) for s in ("ok", "warning", "error")}}
    if duty is not None:
        out["duty_cycle"] = records(duty)
    return json.dumps(out, ensure_ascii=False)
