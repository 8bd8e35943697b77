"""Debian's Chromium for the browser tests, launched one way for every test that needs it.

Playwright's own browser download cannot be fetched everywhere, so the tests drive the
system's Chromium (``make test`` installs Debian's). Without it the tests are skipped on a
developer's machine and fail on CI, where it must be there.
"""

from __future__ import annotations

import contextlib
import os
import shutil
from collections.abc import Iterator
from typing import Any

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

# Chromium's own background connections are refused on a closed network; without these
# flags it waits on them. A fresh profile comes with every launch.
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]

needs_chromium = pytest.mark.skipif(
    CHROMIUM is None and not os.environ.get("CI"),
    reason="no chromium on this machine (make test installs Debian's); on CI these tests run",
)


@contextlib.contextmanager
def chromium() -> Iterator[Any]:
    """A launched headless Chromium (a Playwright ``Browser``), closed at the end."""
    sync_api = pytest.importorskip("playwright.sync_api")
    assert CHROMIUM is not None, "CI needs chromium: make test installs it"
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            browser.close()
