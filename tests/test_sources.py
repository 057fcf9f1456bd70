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


def test_no_internal_names_of_sources_or_issues_in_user_facing_text():
    """'the seed' and 'issue 3' mean nothing to a user: README, docs and the package (docstrings, messages, help)
    name the source itself; comments (# ...) may keep the project's numbers."""
    files = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")), *sorted((ROOT / "bearingheat").rglob("*.py"))]
    pattern = re.compile(r"\bthe seed\b|\bseed's\b|\bissue \d+\b", flags=re.IGNORECASE)
    found = []
    for path in files:
        if path.name == "sources.md":
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
            text = line.split("  # ")[0] if path.suffix == ".py" else line
            if path.suffix == ".py" and text.strip().startswith("#"):
                continue
            if pattern.search(text):
                found.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()}")
    assert found == []
