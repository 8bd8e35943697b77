"""Collect the code blocks of README.md and docs/*.md as tests (tests/docs_blocks.py).

``pytest`` runs them with the rest (pyproject's testpaths name the pages); the blocks
marked slow in the Markdown run unless ``-m "not slow"`` deselects the slow tests.
"""

from __future__ import annotations

from collections.abc import Generator
from pathlib import Path
from typing import Any

import pytest
from tests.docs_blocks import make_sybil

# The docs folder holds more than its pages: the Sphinx configuration, the build, the
# generated API pages and gallery are not tests.
collect_ignore_glob = ["docs/*.py", "docs/_build", "docs/api", "docs/gallery", "docs/notebooks"]

_SLOW = {"run": True}


def pytest_configure(config: pytest.Config) -> None:
    """Run the docs' slow blocks unless the slow tests are deselected (``-m "not slow"``)."""
    _SLOW["run"] = "not slow" not in (config.getoption("markexpr") or "")


pytest_collect_file = make_sybil(lambda: _SLOW["run"]).pytest()


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(
    item: pytest.Item, call: pytest.CallInfo[None]
) -> Generator[None, Any, None]:
    """A docs block's skip is reported at its page and line, not inside unittest."""
    outcome = yield
    report = outcome.get_result()
    example = getattr(item, "example", None)
    if example is not None and report.skipped and isinstance(report.longrepr, tuple):
        report.longrepr = (example.path, example.line, report.longrepr[2])


# A run that writes to "-" means standard output; a file of that name (or its ".meta.json"
# sidecar) left in the project's folder is a bug of the run that wrote it.
_STRAY = ("-", "-.meta.json")


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    """Fail the run when a test left a file named ``-`` (or its sidecar) in the project root."""
    root = Path(str(session.config.rootpath))
    left = [name for name in _STRAY if (root / name).exists()]
    if left:
        session.config.get_terminal_writer().line(
            f"\nerror: the run left {', '.join(left)} in {root}: a '-' output was written "
            "as a file instead of standard output",
            red=True,
        )
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
