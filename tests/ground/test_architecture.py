"""The house as docs/architecture.md draws it: a top of one kind, every folder under a contract.

The package's top holds physics, the chain and the contact state, and the package's own
entry points; a module added there without a row in the architecture page's table fails
here, and so does a top grown past 24 modules (issue 33). Every subpackage is named by an
import contract of pyproject.toml, so a new folder cannot sit outside the layering.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "ballscrew"
KINDS = {"physics", "physics (ground)", "chain and state", "entry point", "version"}
MAX_TOP_MODULES = 24


def _top_modules() -> list[str]:
    return sorted(p.name for p in PACKAGE.glob("*.py"))


def _subpackages() -> list[str]:
    return sorted(p.parent.name for p in PACKAGE.glob("*/__init__.py"))


def _table_rows() -> dict[str, str]:
    """The architecture page's table of the top: module -> kind."""
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    section = text.split("## The package's top", 1)[1].split("\n## ", 1)[0]
    return dict(re.findall(r"^\| `([\w.]+\.py)` \| ([^|]+?) \|", section, flags=re.M))


def test_the_top_holds_at_most_24_modules() -> None:
    assert len(_top_modules()) <= MAX_TOP_MODULES, _top_modules()


def test_every_top_module_has_its_row_and_kind() -> None:
    rows = _table_rows()
    missing = [m for m in _top_modules() if m not in rows]
    assert not missing, f"add these to docs/architecture.md's table of the top: {missing}"
    stale = [m for m in rows if m not in _top_modules()]
    assert not stale, f"docs/architecture.md names modules the top no longer has: {stale}"
    odd = {m: k for m, k in rows.items() if k not in KINDS}
    assert not odd, f"kinds must be one of {sorted(KINDS)}: {odd}"


def test_every_folder_is_described() -> None:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    folders = text.split("## The folders", 1)[1]
    missing = [p for p in _subpackages() if f"| `{p}/` |" not in folders]
    assert not missing, f"add these folders to docs/architecture.md: {missing}"


def test_every_folder_is_under_an_import_contract() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    named = " ".join(
        " ".join(str(v) for v in contract.values())
        for contract in config["tool"]["importlinter"]["contracts"]
    )
    missing = [p for p in _subpackages() if not re.search(rf"ballscrew\.{p}\b", named)]
    assert not missing, f"name these folders in an import contract: {missing}"


@pytest.mark.parametrize(
    ("old", "new"),
    [("sizing", "design.sizing"), ("units", "io.units"), ("case", "io.case")],
)
def test_an_old_module_path_still_imports_with_a_warning(old: str, new: str) -> None:
    import importlib
    import sys

    sys.modules.pop(f"ballscrew.{old}", None)
    with pytest.warns(DeprecationWarning, match=f"ballscrew.{old} moved to ballscrew.{new}"):
        module = importlib.import_module(f"ballscrew.{old}")
    assert module is importlib.import_module(f"ballscrew.{new}")
    assert module.__spec__ is not None and module.__spec__.name == f"ballscrew.{new}"
