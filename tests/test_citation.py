"""What a citable package has: a valid CITATION.cff, a changelog, one version everywhere,
and a CONTRIBUTING.md whose commands and paths exist."""

from __future__ import annotations

import re
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest

import ballscrew
from ballscrew._version import __version__
from cli_runner import run

ROOT = Path(__file__).resolve().parents[1]
CFF = ROOT / "CITATION.cff"
CFFCONVERT = Path(sys.executable).with_name("cffconvert")  # installed with .[test]


def _validate(path: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(CFFCONVERT), "--validate", "-i", str(path)],
                          capture_output=True, text=True, timeout=120)  # fmt: skip


def _field(text: str, key: str) -> str:
    found = re.search(rf'^{key}:\s*"?([^"\n]+)"?\s*$', text, re.MULTILINE)
    assert found, key
    return found.group(1)


def test_citation_cff_validates_against_the_schema() -> None:
    done = _validate(CFF)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "valid" in done.stdout


def test_the_validator_refuses_a_citation_without_authors(tmp_path: Path) -> None:
    text = CFF.read_text("utf-8")
    broken = re.sub(r"^authors:\n(  - .*\n)+", "", text, flags=re.MULTILINE)
    assert "authors:" not in broken.split("references:")[0]
    (tmp_path / "CITATION.cff").write_text(broken, "utf-8")
    assert _validate(tmp_path / "CITATION.cff").returncode != 0


def test_one_version_everywhere(capsys: pytest.CaptureFixture[str]) -> None:
    assert ballscrew.__version__ == __version__ == version("ballscrew"), (
        "the installed metadata is stale: reinstall (make test does when _version.py changes)"
    )
    code, out, _ = run(["--version"], capsys)
    assert code == 0 and out == f"ballscrew, version {__version__}\n"
    cff = CFF.read_text("utf-8")
    assert _field(cff, "version") == __version__
    newest = re.search(r"^## \[([^]]+)\] - (\d{4}-\d\d-\d\d)$", (ROOT / "CHANGELOG.md").read_text(
        "utf-8"), re.MULTILINE)  # fmt: skip
    assert newest, "CHANGELOG.md has no '## [VERSION] - DATE' section"
    assert newest.group(1) == __version__
    assert _field(cff, "date-released") == newest.group(2)


def test_the_version_is_written_once() -> None:
    import tomllib

    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))
    assert "version" not in pyproject["project"] and "version" in pyproject["project"]["dynamic"]
    dynamic = pyproject["tool"]["setuptools"]["dynamic"]
    assert dynamic["version"] == {"attr": "ballscrew._version.__version__"}


def test_contributing_names_the_commands_and_files_that_exist() -> None:
    text = (ROOT / "CONTRIBUTING.md").read_text("utf-8")
    makefile = (ROOT / "Makefile").read_text("utf-8")
    for target in ("run", "test", "test-fast"):
        assert f"make {target}" in text and re.search(rf"^{target}:", makefile, re.MULTILINE)
    paths = set(re.findall(r"\b((?:src|tests|scripts|docs)/[\w./-]+\.(?:py|md))", text))
    paths |= set(re.findall(r"\]\(([^)#]+)\)", text))
    assert "scripts/mutate.py" in paths and "tests/friction/test_new_model.py" in paths
    for path in paths:
        assert (ROOT / path).exists(), path
