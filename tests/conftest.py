"""Shared fixtures and helpers of the test suite (tests mirror the package: tests/kernels, tests/calc, ...)."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
# shared helper modules (excel_helpers, synthetic_torque) and the benchmarks are imported by name
for folder in (TESTS, ROOT / "benchmarks"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))


@pytest.fixture(scope="session")
def root() -> Path:
    """The repository root."""
    return ROOT


@pytest.fixture(scope="session")
def ureg():
    """pint's application registry, as the package uses it."""
    import pint

    return pint.get_application_registry()
