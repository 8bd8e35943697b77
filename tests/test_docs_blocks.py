"""The docs' code blocks run in the tests (tests/docs_blocks.py): a broken one fails.

Each test writes a small Markdown page into a temporary folder and runs it the way
``pytest`` runs README.md and docs/*.md, through the same Sybil set-up.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path
from unittest import SkipTest

import pytest

from docs_blocks import ROOT, make_sybil

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
RUN = {"python", "sh", "output"}  # the languages whose blocks run or are compared
SHOWN = {"text", "toml", "json"}  # shown only (a toml or text block may be a `% write:` file)
FENCE = re.compile(r"[ \t]*(`{3,})([^`]*)")


def _run_page(tmp_path: Path, text: str) -> list[str]:
    """Evaluate a page's blocks in order; what happened to each ('ok' or 'skip')."""
    page = tmp_path / "page.md"
    page.write_text(text, "utf-8")
    sybil = make_sybil(patterns=["*.md"])
    document = sybil.parse(page)
    sybil.setup(document.namespace)
    done = []
    try:
        for example in document.examples():
            try:
                example.evaluate()
                done.append("ok")
            except SkipTest:
                done.append("skip")
    finally:
        sybil.teardown(document.namespace)
    return done


def test_a_good_page_runs(tmp_path: Path) -> None:
    page = (
        '% write: case.toml\n```toml\n[screw]\ndesignation = "40x10 double 2.5x2 6.35"\n'
        'preload = "2 kN"\n[lubricant]\nname = "PAO ISO VG 68"\n```\n\n'
        "```sh\nballscrew case --check case.toml   # a comment\npip install '.[sweep,web]'\n```\n\n"
        "```python\nprint(2 + 2)\n```\n\n```output\n4\n```\n\n"
        '% skip: next "never runs"\n```sh\nmake everything\n```\n'
    )
    assert _run_page(tmp_path, page) == ["ok", "ok", "ok", "ok", "ok", "skip"]


@pytest.mark.parametrize(
    ("block", "message"),
    [
        ("```python\nraise RuntimeError('a broken snippet')\n```\n", "a broken snippet"),
        ("```python\nprint(3)\n```\n\n```output\n4\n```\n", "differs from the docs"),
        ("```sh\nballscrew torque --speed '100 parsecs'\n```\n", "exited with 2"),
        ("```sh\nballscrew no-such-command\n```\n", "exited with 2"),
        ("```sh\nmake run\n```\n", "cannot run `make run`"),
        ("```sh\npip install '.[no-such-extra]'\n```\n", "no such extra"),
        ("```sh\npython -c 'import sys; sys.exit(3)'\n```\n", "exited with 3"),
    ],
)
def test_a_broken_block_fails(tmp_path: Path, block: str, message: str) -> None:
    with pytest.raises(Exception, match=re.escape(message)):
        _run_page(tmp_path, block)


def test_pytest_collects_and_fails_a_broken_page(tmp_path: Path) -> None:
    # The root conftest's way (Sybil's pytest integration) on a page with one good and
    # one broken block: pytest reports one passed and one failed, and exits with 1.
    here = f"Path({str(tmp_path)!r})"
    (tmp_path / "conftest.py").write_text(
        f"import sys\nsys.path.insert(0, {str(ROOT)!r})\n"
        "from pathlib import Path\nfrom tests.docs_blocks import make_sybil\n"
        f"pytest_collect_file = make_sybil(patterns=['*.md'], path={here}).pytest()\n",
        "utf-8",
    )
    (tmp_path / "broken.md").write_text(
        "```python\nx = 1\n```\n\n```python\nassert x == 2, 'the page broke'\n```\n", "utf-8"
    )
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--rootdir",
         str(tmp_path), str(tmp_path / "broken.md")],
        capture_output=True, text=True, cwd=tmp_path, check=False,
    )  # fmt: skip
    assert done.returncode == 1, done.stdout + done.stderr
    assert "1 failed, 1 passed" in done.stdout and "the page broke" in done.stdout


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_block_runs_or_is_only_shown(page: Path) -> None:
    # A block in a language the docs test does not know would be silently left out.
    fence = ""
    for line, text in enumerate(page.read_text("utf-8").splitlines(), 1):
        match = FENCE.fullmatch(text)
        if match is None:
            continue
        if fence:  # inside a block: only its own fence closes it
            fence = "" if match.group(1) == fence and not match.group(2).strip() else fence
            continue
        fence, language = match.group(1), match.group(2).strip()
        if language.startswith("{"):  # a MyST directive (a toctree)
            continue
        assert language in RUN | SHOWN, f"{page.name}:{line}: a ```{language} block"


def test_the_docs_run_many_blocks() -> None:
    sybil = make_sybil()
    blocks = [
        e
        for p in PAGES
        for e in sybil.parse(p).examples()
        if "skip" not in repr(e.region.evaluator)
    ]
    assert len(blocks) > 40
