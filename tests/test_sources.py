"""User-facing text names sources by their names: internal seed numbers appear only in docs/sources.md."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_no_seed_numbers_outside_the_sources_page():
    files = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")), *sorted((ROOT / "bearingheat").rglob("*.py"))]
    found = []
    for path in files:
        if path.name == "sources.md":
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
            if re.search(r"seed 00\d", line, flags=re.IGNORECASE):
                found.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()}")
    assert found == []


def test_the_sources_page_maps_every_internal_number():
    text = (ROOT / "docs" / "sources.md").read_text(encoding="utf-8")
    for number in ("000", "001", "002", "003", "004"):
        assert f"| seed {number} |" in text
