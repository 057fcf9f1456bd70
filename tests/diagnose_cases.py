"""The synthetic data sets of the diagnose tests (tests/analysis, tests/cli, tests/io), each diagnosed once a session."""
from __future__ import annotations

import pandas as pd
from synthetic_torque import EFFECTS, measured_set

from bearingheat.analysis.diagnose import diagnose_table

# (effect, seed, bearings): two draws per effect with different bearings, three controls
CASES = [(e, s, b) for e in EFFECTS if e != "none" for s, b in (
    (101, ("6205", "6310", "30206-A", "NU208-E")), (202, ("6004", "6208", "7206-B", "NU206-E")))]
CONTROLS = [("none", 7, ("6205", "6208", "7206-B", "NU208-E")), ("none", 8, ("6004", "6310", "30206-A", "NU206-E")),
            ("none", 9, ("6205", "30206-A"))]

_cache: dict = {}


def run_case(effect, seed, bearings):
    """(table, noise, diagnosis) of a synthetic data set with ``effect``; cached for the session."""
    key = (effect, seed, bearings)
    if key not in _cache:
        table, noise, sigma = measured_set(effect, seed, designations=list(bearings))
        _cache[key] = (table, noise, diagnose_table(table))
    return _cache[key]


def small_table(rows=3):
    """Too few rows of one bearing at one operating point, with a measured torque."""
    return pd.DataFrame({"designation": ["6205"] * rows, "d [mm]": 25, "D [mm]": 52, "C0 [N]": 7800,
                         "lubrication": "oil_bath", "n [1/min]": 3000.0, "Fr [N]": 1000.0, "nu [mm^2/s]": 12.0,
                         "M [N*mm]": 20.0})
