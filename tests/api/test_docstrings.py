"""Every public function has a numpydoc docstring: Parameters, Returns and Raises sections.

The docs build them with napoleon (numpy style), so a section counts only with
its underline of dashes, as numpydoc writes it.
"""
from __future__ import annotations

import inspect
import re

import pytest

import bearingheat.api
from bearingheat.calc.table import calc

FUNCTIONS = {name: getattr(bearingheat.api, name) for name in bearingheat.api.__all__
             if not inspect.isclass(getattr(bearingheat.api, name))}
FUNCTIONS["calc"] = calc


def sections(function) -> set[str]:
    """The numpydoc section headers of the docstring: a title line underlined by dashes of its length."""
    lines = (inspect.getdoc(function) or "").splitlines()
    return {title.strip() for title, underline in zip(lines, lines[1:])
            if title.strip() and re.fullmatch(r"-+", underline.strip())
            and len(underline.strip()) == len(title.strip())}


def test_the_public_functions_are_found():
    # classes (FrictionResult, F2Chart ...) are left out; lru_cache wrappers (parse_designation) are kept
    assert {"friction_torque", "heat_balance", "parse_designation", "decode_gost", "designations",
            "calc"} <= set(FUNCTIONS)
    assert "FrictionResult" not in FUNCTIONS and "F2Chart" not in FUNCTIONS


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_parameters_and_returns_sections(name):
    found = sections(FUNCTIONS[name])
    assert {"Parameters", "Returns"} <= found, f"{name}: numpydoc sections {sorted(found)}"


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_raises_section(name):
    assert "Raises" in sections(FUNCTIONS[name]), f"{name}: no numpydoc 'Raises' section"


def test_a_docstring_without_sections_is_caught():
    def bare(x):
        """Parameters are described in prose only.

        Returns x.
        """
        return x

    assert sections(bare) == set()
