"""Typed, cached lookups of the catalogue tables in ``tables/``; designations. No physics."""
