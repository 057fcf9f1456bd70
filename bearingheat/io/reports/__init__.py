"""Figures (matplotlib Figure API, never ``matplotlib.use``) and report writers.

matplotlib is an optional extra (``pip install 'bearingheat[plot]'``): every
figure gets its class from :func:`matplotlib_figure`, which says what to
install where it is missing.
"""
from __future__ import annotations

from bearingheat.errors import MissingExtraError

__all__ = ["matplotlib_figure", "FIGURE_DPI"]

#: the resolution of every PNG figure bearingheat writes: sharp on paper at its printed size
FIGURE_DPI = 150


def matplotlib_figure() -> type:
    """matplotlib's ``Figure`` class; :class:`~bearingheat.errors.MissingExtraError` when matplotlib is not installed."""
    try:
        from matplotlib.figure import Figure
    except ImportError as exc:
        raise MissingExtraError("plotting needs matplotlib, which is not installed: pip install "
                                "'bearingheat[plot]'") from exc
    return Figure
