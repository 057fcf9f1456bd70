"""JSON writing helpers shared by the report writers and the command line."""
from __future__ import annotations

import math

import numpy as np

__all__ = ["json_safe"]


def json_safe(value):
    """Replace non-finite floats by None so that the summary is strict JSON.

    Dicts, lists and tuples are walked (tuples become lists); numpy floats and
    integers become Python numbers.

    >>> json_safe({"f": float("nan"), "t": [1.5, float("inf")], "k": np.int64(3)})
    {'f': None, 't': [1.5, None], 'k': 3}
    """
    if isinstance(value, dict):
        return {k: json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    return value
