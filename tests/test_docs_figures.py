"""The pictures of the README and the docs are drawn by the docs build from the current
version (scripts/docs_figures.py), and each says which version drew it."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest
from PIL import Image

from ballscrew import __version__

ROOT = Path(__file__).resolve().parents[1]
IMG = ROOT / "docs" / "img"
PICTURE = re.compile(r"!\[[^\]]*\]\(((?:docs/)?img/[^)\s]+\.png)\)")


def _shown() -> set[str]:
    """The names of the pictures the README and the docs pages show."""
    pages = [ROOT / "README.md", *(ROOT / "docs").glob("*.md")]
    return {Path(m).name for p in pages for m in PICTURE.findall(p.read_text("utf-8"))}


def test_the_pages_show_pictures_that_exist() -> None:
    shown = _shown()
    assert {"web-calculator.png", "web-program.png", "friction_signs.png"} <= shown
    assert all((IMG / name).is_file() for name in shown)


@pytest.mark.parametrize("name", sorted(p.name for p in IMG.glob("*.png")))
def test_each_picture_carries_the_current_version(name: str) -> None:
    with Image.open(IMG / name) as image:
        info = image.info
    assert info.get("Software") == f"ballscrew {__version__}", (
        f"docs/img/{name} was drawn by {info.get('Software')!r}: run make docs "
        "(scripts/docs_figures.py) and commit the pictures"
    )


def test_the_build_script_draws_every_picture_shown() -> None:
    sys.path.insert(0, str(ROOT / "scripts"))
    try:
        import docs_figures
    finally:
        sys.path.remove(str(ROOT / "scripts"))
    drawn = {name for f in docs_figures.FIGURES.values() for name in _names(f.__doc__ or "")}
    assert _shown() <= drawn
    assert "docs_figures.py" in (ROOT / "docs" / "conf.py").read_text("utf-8")


def _names(doc: str) -> list[str]:
    return re.findall(r"docs/img/([\w-]+\.png)", doc)
