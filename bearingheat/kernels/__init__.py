"""One function per published formula, in catalogue units (mm, N, 1/min, mm²/s, °C, N·mm, W).

Floats, numpy arrays and pandas Series in; no pint, no table rows, no files, no figures.
"""
