"""The built documentation site reads offline: its equations render with no network (issue 40).

``make test`` builds the site (``make docs``) before pytest runs, so these tests open the
pages it built. MathJax is served from the site's own ``_static/mathjax``; a page opened
in Chromium with every network request refused must still show typeset equations (MathJax
turns each into an ``mjx-container`` element). Without a built site the tests are skipped
on a developer's machine (``make test-fast``) and fail on CI, where the site is built first.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from browser import CHROMIUM, chromium

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "docs" / "_build" / "html"

if not (SITE / "index.html").is_file():
    if os.environ.get("CI"):
        pytest.fail("CI builds the docs before pytest (make test): no docs/_build/html")
    pytest.skip("the site is not built (make docs)", allow_module_level=True)

# Pages whose Markdown holds display equations, and one API page whose docstrings do.
PAGES = ["calibration-and-control.html", "models.html", "api/ballscrew.ehl.html"]


def test_no_page_loads_mathjax_from_elsewhere() -> None:
    assert (SITE / "_static" / "mathjax" / "tex-chtml.js").is_file()
    remote = re.compile(r"<script[^>]+src=\"https?://[^\"]*mathjax", re.IGNORECASE)
    offenders = [
        str(p.relative_to(SITE))
        for p in SITE.rglob("*.html")
        if remote.search(p.read_text("utf-8", errors="replace"))
    ]
    assert not offenders, offenders[:5]


# A script, style sheet, font or image the browser would fetch from another host; links a
# reader clicks (<a href>) may point anywhere.
_REMOTE = re.compile(
    r"<(?:script|link|img|iframe|source)\b[^>]*\b(?:src|href)\s*=\s*[\"']?(?:https?:)?//",
    re.IGNORECASE,
)
_CSS_REMOTE = re.compile(r"(?:@import|url\()\s*[\"']?(?:https?:)?//", re.IGNORECASE)


def test_no_page_loads_anything_from_another_host() -> None:
    # Every HTML page of the site (sphinx-gallery's computation-time pages loaded jQuery,
    # DataTables and Bootstrap from CDNs), and the site's own style sheets.
    offenders = [
        str(p.relative_to(SITE))
        for p in SITE.rglob("*.html")
        if _REMOTE.search(p.read_text("utf-8", errors="replace"))
    ]
    offenders += [
        str(p.relative_to(SITE))
        for p in (SITE / "_static").rglob("*.css")
        if _CSS_REMOTE.search(p.read_text("utf-8", errors="replace"))
    ]
    assert not offenders, offenders[:10]


@pytest.fixture(scope="module")
def offline_page() -> Iterator[object]:
    if CHROMIUM is None and not os.environ.get("CI"):
        pytest.skip("no chromium on this machine (make test installs Debian's)")
    with chromium() as browser:
        context = browser.new_context()
        refused: list[str] = []

        def block(route: object) -> None:
            url = route.request.url  # type: ignore[attr-defined]
            if url.startswith("file://"):
                route.continue_()  # type: ignore[attr-defined]
            else:
                refused.append(url)
                route.abort()  # type: ignore[attr-defined]

        context.route("**/*", block)
        page = context.new_page()
        page.refused = refused  # type: ignore[attr-defined]
        yield page


@pytest.mark.parametrize("name", PAGES)
def test_equations_render_with_the_network_blocked(offline_page: object, name: str) -> None:
    page = offline_page
    page.goto((SITE / name).as_uri())  # type: ignore[attr-defined]
    page.wait_for_selector("mjx-container", timeout=20_000)  # type: ignore[attr-defined]
    rendered = page.locator("mjx-container").count()  # type: ignore[attr-defined]
    raw = page.locator("text=/\\\\\\[|\\\\\\(/").count()  # type: ignore[attr-defined]
    assert rendered > 0 and raw == 0, (rendered, raw)
    mathjax = [u for u in page.refused if "mathjax" in u.lower()]  # type: ignore[attr-defined]
    assert not mathjax, mathjax
