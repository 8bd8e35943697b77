"""What a packager checks: the metadata is valid, the repository follows the Scientific
Python development guidelines (or says in pyproject.toml why not), and the conda-forge
recipe in packaging/ asks for what pyproject.toml asks for.

``twine check`` on the built sdist and wheel is in tests/test_package.py, which builds them.
"""

from __future__ import annotations

import json
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
    assert host["python"] == PYPROJECT["project"]["requires-python"]
