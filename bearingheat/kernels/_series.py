"""Series in, Series out: the decorator the kernels share."""
from __future__ import annotations

import functools

import numpy as np
import pandas as pd

__all__ = ["series_aware"]


def series_aware(func):
    """Run a numpy kernel on Series arguments and give a Series back.

    Series arguments become float arrays; if any argument was a Series, the
    result (or each array of a tuple or dict result) becomes a Series with
    that index. All Series arguments must share one index. A scalar-only
    call returns Python floats.
    """

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        index = None

        def strip(value):
            nonlocal index
            if isinstance(value, pd.Series):
                if index is None:
                    index = value.index
                elif not value.index.equals(index):
                    raise ValueError(f"{func.__name__}: Series arguments must share one index")
                return value.to_numpy(dtype=float)
            return value

        args = tuple(strip(a) for a in args)
        kwargs = {k: strip(v) for k, v in kwargs.items()}
        out = func(*args, **kwargs)
        return _wrap(out, index)

    return wrapper


def _wrap(out, index):
    if isinstance(out, tuple):
        return tuple(_wrap(o, index) for o in out)
    if isinstance(out, dict):
        return {k: _wrap(v, index) for k, v in out.items()}
    if index is not None:
        return pd.Series(np.broadcast_to(out, (len(index),)).astype(float), index=index)
    if np.ndim(out) == 0:
        return float(out)
    return out
