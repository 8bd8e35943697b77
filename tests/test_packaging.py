"""What a packager checks: the metadata is valid, the repository follows the Scientific
Python development guidelines (or says in pyproject.toml why not), and the conda-forge
recipe in packaging/ asks for what pyproject.toml asks for.

``twine check`` on the built sdist and wheel is in tests/test_package.py, which builds them.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any

import jinja2
import yaml
from packaging.requirements import Requirement

from ballscrew import __version__

ROOT = Path(__file__).resolve().parents[1]
RECIPE = ROOT / "packaging" / "conda-forge" / "meta.yaml"
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))
# pip's name -> conda-forge's, where they differ.
CONDA_NAME = {"matplotlib": "matplotlib-base"}


def _recipe() -> dict[str, Any]:
    text = jinja2.Template(RECIPE.read_text("utf-8")).render(PYTHON="python")
    recipe: dict[str, Any] = yaml.safe_load(text)
    return recipe


def _specs(lines: list[str]) -> dict[str, str]:
    """A recipe's requirement lines ('numpy >=1.26') as name -> version specifier."""
    out = {}
    for line in lines:
        name, _, spec = line.partition(" ")
        out[name] = spec.replace(" ", "")
    return out


def test_pyproject_is_valid() -> None:
    from validate_pyproject import api

    api.Validator()(PYPROJECT)  # raises naming the field on an invalid pyproject.toml


def test_the_repository_passes_sp_repo_review() -> None:
    # Checks that do not apply are listed with the reason under [tool.repo-review] ignore.
    done = subprocess.run(
        [sys.executable, "-m", "repo_review", str(ROOT), "--format", "json"],
        capture_output=True, text=True, check=False, timeout=300,
    )  # fmt: skip
    report = json.loads(done.stdout)
    failed = {k: v["description"] for k, v in report["checks"].items() if v["result"] is False}
    assert not failed, failed
    assert len(report["checks"]) > 40  # the sp-repo-review checks ran (not an empty plugin)


def test_every_ignored_repo_review_check_says_why() -> None:
    text = (ROOT / "pyproject.toml").read_text("utf-8")
    ignored = PYPROJECT["tool"]["repo-review"]["ignore"]
    for check in ignored:
        (line,) = [x for x in text.splitlines() if x.strip().startswith(f'"{check}"')]
        assert "#" in line and len(line.split("#", 1)[1].strip()) > 20, check


def test_the_conda_recipe_is_this_version_and_runs_the_command() -> None:
    recipe = _recipe()
    assert recipe["package"] == {"name": "ballscrew", "version": __version__}
    assert recipe["build"]["noarch"] == "python"
    entry = [f"{k} = {v}" for k, v in PYPROJECT["project"]["scripts"].items()]
    assert recipe["build"]["entry_points"] == entry
    assert recipe["about"]["license"] == PYPROJECT["project"]["license"]


def test_the_conda_recipe_requires_what_pyproject_requires() -> None:
    run = _specs(_recipe()["requirements"]["run"])
    assert run.pop("python") == PYPROJECT["project"]["requires-python"]
    wanted = {}
    for line in PYPROJECT["project"]["dependencies"]:
        req = Requirement(line)
        wanted[CONDA_NAME.get(req.name, req.name)] = str(req.specifier)
    assert run == wanted


def test_the_conda_recipe_builds_with_pyprojects_backend() -> None:
    host = _specs(_recipe()["requirements"]["host"])
    (backend,) = PYPROJECT["build-system"]["requires"]
    req = Requirement(backend)
    assert host[req.name] == str(req.specifier)
    # conda-forge's noarch rule (CFEP-25): built and tested on the oldest Python the package
    # supports, python_min, and run on it or newer; python_min is pyproject's lower bound.
    python_min = PYPROJECT["project"]["requires-python"].removeprefix(">=")
    assert host["python"] == f"{python_min}.*"
    assert _specs(_recipe()["requirements"]["run"])["python"] == f">={python_min}"
    assert _specs(_recipe()["test"]["requires"])["python"] == f"{python_min}.*"


# conda-forge's linter (conda-smithy) is not installable here (its PyPI name is an empty
# placeholder), so the lints a meta.yaml can fail offline are checked as its LINTER.md
# states them, by code; the maintainers' GitHub names are checked by conda-forge's bot.
TOP_ORDER = ["package", "source", "build", "requirements", "test", "outputs", "about", "extra"]


def test_the_conda_recipe_passes_conda_forges_offline_lints() -> None:
    text = RECIPE.read_text("utf-8")
    recipe = _recipe()
    keys = list(recipe)
    assert set(keys) <= set(TOP_ORDER), keys  # no unexpected top-level key
    assert keys == sorted(keys, key=TOP_ORDER.index), keys  # R-001: the sections' order
    for item in ("home", "license", "summary"):
        assert recipe["about"].get(item), item
    maintainers = recipe["extra"]["recipe-maintainers"]  # a list of names
    assert (
        isinstance(maintainers, list)
        and maintainers
        and all(isinstance(m, str) for m in maintainers)
    )
    assert recipe["test"]["imports"] and recipe["test"]["commands"]
    assert isinstance(recipe["build"]["number"], int)
    sections = list(recipe["requirements"])
    order = ["build", "host", "run", "run_constrained"]
    assert sections == sorted(sections, key=order.index), sections
    assert "license" not in recipe["about"]["license"].lower()
    assert text.endswith("\n") and not text.endswith("\n\n")
    assert recipe["about"]["license_file"]
    assert len(recipe["source"]["sha256"]) == 64
    for section in ("host", "run"):  # 'name [version]', no space after '>='
        for line in recipe["requirements"][section]:
            assert re.fullmatch(r"[a-z0-9_.\-]+( [^ ]+)?", line), line
    assert recipe["build"]["noarch"] == "python"  # R-020, and R-026's lower bound below
    assert _specs(recipe["requirements"]["run"])["python"].startswith(">=")
    # R0-005: '{% set name = value %}', one space around each part.
    for line in text.splitlines():
        if line.startswith("{%"):
            assert re.fullmatch(r"\{% set \w+ = \S.* %\}", line), line
    # '{{ name }}', one space inside the braces.
    assert not re.search(r"\{\{\S|\S\}\}", text)
