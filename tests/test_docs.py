"""The docs ship with the package: nothing points at files a user's clone does not have."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_no_reference_to_files_outside_the_repository() -> None:
    files = [ROOT / "README.md", *sorted((ROOT / "src" / "ballscrew").rglob("*.py"))]
    files += sorted((ROOT / "src" / "ballscrew" / "data").iterdir())
    for path in files:
        text = path.read_text("utf-8")
        for phrase in ("shared/reference", "research notes", "../shared"):
            assert phrase not in text, f"{path.relative_to(ROOT)} mentions {phrase!r}"
