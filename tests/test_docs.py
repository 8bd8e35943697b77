"""The docs ship with the package: nothing points at files a user's clone does not have,
and the docs pages cannot go stale silently."""

from __future__ import annotations

import csv
import importlib
import io
import re
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = sorted((ROOT / "docs").glob("*.md"))
PHRASES = ("shared/reference", "shared/seed", "research notes", "../shared")

# A dotted name such as ``ballscrew.ehl.hamrock_dowson_1977_minimum``.
DOTTED = re.compile(r"\bballscrew(?:\.[A-Za-z_][A-Za-z0-9_]*)+")
# A Markdown link's target: ``[text](target)``.
LINK = re.compile(r"\]\(([^)\s]+)\)")


def test_no_reference_to_files_outside_the_repository() -> None:
    files = [ROOT / "README.md", *DOCS, *sorted((ROOT / "src" / "ballscrew").rglob("*.py"))]
    # The bundled data files that are text (the helix's stored tables are binary numbers).
    data = (ROOT / "src" / "ballscrew" / "data").iterdir()
    files += sorted(p for p in data if p.suffix != ".npz")
    for path in files:
        text = path.read_text("utf-8")
        for phrase in PHRASES:
            assert phrase not in text, f"{path.relative_to(ROOT)} mentions {phrase!r}"


def test_docs_pages_exist_and_point_at_no_shared_folder() -> None:
    names = {p.name for p in DOCS}
    assert {"models.md", "layers.md", "axis-energy.md", "calibration-and-control.md"} <= names
    for path in DOCS:
        assert "shared/" not in path.read_text("utf-8"), path.name


def _resolve(dotted: str) -> Any:
    """The object a dotted name refers to: the longest importable module, then attributes."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj: Any = importlib.import_module(".".join(parts[:i]))
        except ModuleNotFoundError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr)
        return obj
    raise ModuleNotFoundError(dotted)  # pragma: no cover - "ballscrew" always imports


def _dotted_names() -> list[tuple[str, str]]:
    found = set()
    for path in DOCS:
        for name in DOTTED.findall(path.read_text("utf-8")):
            found.add((path.name, name))
    return sorted(found)


def test_the_docs_name_functions() -> None:
    # Guards the test below against a regex that silently finds nothing.
    names = {name for _, name in _dotted_names()}
    assert "ballscrew.ehl.hamrock_dowson_1977_minimum" in names
    assert len(names) > 100


@pytest.mark.parametrize(("page", "name"), _dotted_names())
def test_every_dotted_name_in_the_docs_exists(page: str, name: str) -> None:
    try:
        _resolve(name)
    except (ImportError, AttributeError) as exc:
        pytest.fail(f"docs/{page} names {name}, which does not exist: {exc}")


def test_relative_links_in_the_docs_point_at_files() -> None:
    for path in [ROOT / "README.md", *DOCS]:
        for target in LINK.findall(path.read_text("utf-8")):
            if "://" in target or target.startswith(("#", "mailto:")):
                continue
            file = target.split("#", 1)[0]
            assert (path.parent / file).exists(), f"{path.relative_to(ROOT)} links {target}"


def _section(text: str, heading: str) -> str:
    start = text.index(heading)
    rest = text[start + len(heading) :]
    ends = [i for i in (rest.find("\n### "), rest.find("\n## ")) if i >= 0]
    return rest[: min(ends)] if ends else rest


def test_models_page_documents_every_parameter_of_every_model() -> None:
    from ballscrew import models

    text = (ROOT / "docs" / "models.md").read_text("utf-8")
    for spec in models():
        section = _section(text, f"### `{spec.name}`")
        for parameter in spec.parameters:
            assert f"`{parameter}`" in section, f"models.md: {spec.name} lacks {parameter}"


def test_models_page_scorecard_and_constant_match_the_package() -> None:
    from ballscrew.friction.complete import BALL_TRAIN_CONSTANT

    text = (ROOT / "docs" / "models.md").read_text("utf-8")
    data = ROOT / "src" / "ballscrew" / "data" / "scorecard_summary.csv"
    for row in csv.reader(io.StringIO(data.read_text("utf-8"))):
        if row[0] == "model":
            continue
        line = "| " + " | ".join(row) + " |"
        assert line in text, f"models.md scorecard lacks or misstates: {line}"
    assert f"= {BALL_TRAIN_CONSTANT}" in text


def test_no_control_characters_in_sources_and_docs() -> None:
    # A non-raw docstring once turned \alpha, \frac and \nu into BEL, form feed and a
    # newline; ruff's invalid-character rules do not cover BEL or form feed.
    import re

    files = [*sorted((ROOT / "src" / "ballscrew").rglob("*.py")), *sorted(ROOT.glob("docs/*.md"))]
    files += [ROOT / "README.md", *sorted((ROOT / "tests").glob("*.py"))]
    bad = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
    for path in files:
        text = path.read_text("utf-8")
        assert not bad.search(text), f"{path.relative_to(ROOT)} holds a control character"
