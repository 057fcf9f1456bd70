"""Figures (matplotlib Figure API, never ``matplotlib.use``) and report writers."""
