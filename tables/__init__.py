"""Coefficient tables of the catalogue friction model, shipped as CSV data.

Each CSV has a header row, a units row under it, and a ``source`` column
(seed, table, page). :mod:`bearingheat.catalogue.tables` loads them.
"""
