"""The package works outside the source tree: built as an sdist and a wheel, installed into a
fresh virtual environment, run from a folder that is not the repository.

With the core dependencies only, a torque calculation, a case template and ``import
ballscrew`` work, the bundled data files are found, the extras' libraries are absent and
``ballscrew sweep`` says which extra to install (``ballscrew validate`` runs there too);
with ``[all]``, a small sweep runs and the web application is made. pip takes the
dependencies from its cache or the package index.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path
from typing import Any

import pytest

from ballscrew import __version__
from ballscrew.io.extras import EXTRAS

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "ballscrew"

SMALL_SWEEP = """\
models = ["complete"]
outputs = ["torque"]

[case]
title = "40 x 10 mm double nut, PAO ISO VG 68"
[case.screw]
designation = "40x10 double 2.5x2 6.35"
preload = "2 kN"
[case.lubricant]
name = "PAO ISO VG 68"

[axes]
speed = "100..1000:3 rpm"
"screw.preload" = "1, 2 kN"
"""


def _env() -> dict[str, str]:
    """This environment without what would point the venv's Python back at the repository."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "PYTHONSAFEPATH")}  # fmt: skip
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["BALLSCREW_TRACEBACK"] = "1"  # an internal error shows where
    return env


def _run(
    args: list[str | Path], cwd: Path, timeout: float = 600
) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, cwd=cwd,
                          env=_env(), timeout=timeout, stdin=subprocess.DEVNULL)  # fmt: skip


def _ok(args: list[str | Path], cwd: Path, timeout: float = 600) -> str:
    done = _run(args, cwd, timeout)
    assert done.returncode == 0, f"{args}: {done.returncode}\n{done.stdout}\n{done.stderr}"
    return done.stdout


@pytest.fixture(scope="module")
def dist(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """The wheel and the sdist (the wheel built from the sdist, as ``python -m build`` does)."""
    out = tmp_path_factory.mktemp("dist")
    _ok([sys.executable, "-m", "build", "--outdir", out, ROOT], out)
    (wheel,) = out.glob("ballscrew-*.whl")
    (sdist,) = out.glob("ballscrew-*.tar.gz")
    return wheel, sdist


def _venv(where: Path, requirement: str) -> Path:
    """A fresh virtual environment with ``requirement`` installed; its bin folder."""
    _ok([sys.executable, "-m", "venv", where / "venv"], where)
    bin_ = where / "venv" / "bin"
    _ok([bin_ / "python", "-m", "pip", "install", "--quiet", requirement], where, timeout=1800)
    return bin_


def test_twine_accepts_the_wheel_and_the_sdist(dist: tuple[Path, Path]) -> None:
    # What PyPI would check on upload: the metadata and that the README renders.
    out = _ok([sys.executable, "-m", "twine", "check", "--strict", *dist], ROOT)
    assert out.count("PASSED") == 2, out


def test_wheel_and_sdist_hold_every_file_of_the_package(dist: tuple[Path, Path]) -> None:
    wheel, sdist = dist
    assert wheel.name == f"ballscrew-{__version__}-py3-none-any.whl"
    files = [p.relative_to(PACKAGE.parent).as_posix() for p in PACKAGE.rglob("*")
             if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc"]  # fmt: skip
    # The bundled data, the web page's template and static files among them.
    for needed in ("ballscrew/data/catalog_screws.csv", "ballscrew/data/lubricants.csv",
                   "ballscrew/data/validation_cases.csv", "ballscrew/data/kamalzadeh_stage.toml",
                   "ballscrew/web/templates/index.html", "ballscrew/web/static/app.js",
                   "ballscrew/py.typed"):  # fmt: skip
        assert needed in files
    in_wheel = set(zipfile.ZipFile(wheel).namelist())
    assert sorted(set(files) - in_wheel) == []
    top = f"ballscrew-{__version__}/"
    with tarfile.open(sdist) as tar:
        in_sdist = {n.removeprefix(top) for n in tar.getnames()}
    assert sorted({f"src/{f}" for f in files} - in_sdist) == []
    for name in ("README.md", "LICENSE", "pyproject.toml", "CITATION.cff", "CHANGELOG.md"):
        assert name in in_sdist


def test_the_wheel_with_core_dependencies_only_runs_outside_the_source_tree(
    dist: tuple[Path, Path], tmp_path: Path
) -> None:
    wheel, _ = dist
    bin_ = _venv(tmp_path, str(wheel))
    installed = json.loads(_ok([bin_ / "python", "-m", "pip", "list", "--format=json"], tmp_path))
    names = {p["name"].lower() for p in installed}
    assert not names & {m.lower() for modules in EXTRAS.values() for m in modules}, names

    where = _ok([bin_ / "python", "-c", "import ballscrew; print(ballscrew.__file__)"], tmp_path)
    assert Path(where.strip()).is_relative_to(tmp_path / "venv"), where
    assert _ok([bin_ / "ballscrew", "--version"], tmp_path).strip() == (
        f"ballscrew, version {__version__}"
    )
    torque = _ok([bin_ / "ballscrew", "torque", "--speed", "100 rpm"], tmp_path)
    assert "complete" in torque
    assert _ok([bin_ / "ballscrew", "case", "--template"], tmp_path).startswith("# ballscrew")
    # The bundled data: catalogue screws, lubricants, the validation cases and scorecard, the
    # study's case (the default of torque above), the web page's files.
    assert "HIWIN" in _ok([bin_ / "ballscrew", "screws"], tmp_path)
    assert "PAO" in _ok([bin_ / "ballscrew", "lubricants"], tmp_path)
    _ok([bin_ / "ballscrew", "validate", "--out", "v"], tmp_path)
    assert (tmp_path / "v" / "report.html").is_file()
    static = _ok([bin_ / "python", "-c", "import importlib.resources as r; print(sorted(p.name "
                  "for p in r.files('ballscrew').joinpath('web', 'static').iterdir()))"],
                 tmp_path)  # fmt: skip
    assert "app.js" in static

    (tmp_path / "s.toml").write_text(SMALL_SWEEP, "utf-8")
    done = _run([bin_ / "ballscrew", "sweep", "s.toml", "--out", "s.zarr"], tmp_path)
    assert done.returncode == 2, done.stderr
    assert done.stderr.splitlines() == [
        "error: ballscrew sweep needs the sweep extra (xarray is not installed): "
        "pip install 'ballscrew[sweep]'"
    ]
    done = _run([bin_ / "ballscrew", "serve"], tmp_path)
    assert done.returncode == 2 and "pip install 'ballscrew[web]'" in done.stderr, done.stderr
    assert not (tmp_path / "s.zarr").exists()


def test_the_wheel_with_all_extras_sweeps_and_serves(
    dist: tuple[Path, Path], tmp_path: Path
) -> None:
    wheel, _ = dist
    bin_ = _venv(tmp_path, f"ballscrew[all] @ {wheel.as_uri()}")
    (tmp_path / "s.toml").write_text(SMALL_SWEEP, "utf-8")
    _ok([bin_ / "ballscrew", "sweep", "s.toml", "--out", "s.zarr"], tmp_path)
    shape = _ok([bin_ / "python", "-c", "import xarray; "
                 "print(dict(xarray.open_zarr('s.zarr')['torque'].sizes))"], tmp_path)  # fmt: skip
    assert "'speed': 3" in shape and "'screw.preload': 2" in shape, shape
    _ok([bin_ / "python", "-c", "from ballscrew.web import create_app; create_app()"], tmp_path)


def test_check_manifest_finds_the_sdist_complete() -> None:
    # Every file under version control is in the sdist (MANIFEST.in), or named as left out.
    if not (ROOT / ".git").exists():
        pytest.skip("not a git checkout (an unpacked sdist): nothing to compare with")
    out = _ok([Path(sys.executable).parent / "check-manifest", ROOT],
              ROOT)  # fmt: skip
    assert "lists of files in version control and sdist match" in out, out


def test_the_unpacked_sdist_runs_its_own_tests(dist: tuple[Path, Path], tmp_path: Path) -> None:
    # What a distribution's packager does: unpack the sdist and run the tests there, against
    # the sdist's own sources (PYTHONPATH), with the extras of this environment. Every test
    # collects (no data file missing), and the ground and physics tests pass.
    _, sdist = dist
    with tarfile.open(sdist) as tar:
        tar.extractall(tmp_path, filter="data")
    (top,) = tmp_path.iterdir()
    # A packager's run is not this project's CI: without CI set, what the unpacked sdist
    # cannot hold (the built docs site, system packages) is skipped, not failed.
    env = {k: v for k, v in _env().items() if k != "CI"}
    env["PYTHONPATH"] = str(top / "src")
    pytest_ = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q"]

    def run(*args: str) -> str:
        done = subprocess.run([*pytest_, *args], capture_output=True, text=True, cwd=top,
                              env=env, timeout=1200, stdin=subprocess.DEVNULL)  # fmt: skip
        assert done.returncode == 0, f"{args}\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
        return done.stdout

    collected = run("--collect-only")
    assert " error" not in collected.splitlines()[-1], collected.splitlines()[-1]
    where = run("-m", "not slow", "tests/ground", "tests/physics", "tests/test_citation.py")
    assert " passed" in where.splitlines()[-1]
    imported = subprocess.run([sys.executable, "-c", "import ballscrew; print(ballscrew.__file__)"],
                              capture_output=True, text=True, cwd=top, env=env)  # fmt: skip
    assert Path(imported.stdout.strip()).is_relative_to(top), imported.stdout


def test_grayskull_writes_the_recipes_requirements_from_the_sdist(
    dist: tuple[Path, Path], tmp_path: Path
) -> None:
    # conda-forge's own recipe generator, in its strict conda-forge form, run on the sdist
    # built here: the packaged recipe asks for what it finds (python_min, host, run, the test's
    # requirements), so the recipe follows the package and not an older copy of it.
    import yaml

    _, sdist = dist
    exe = Path(sys.executable).parent / "grayskull"
    _ok([exe, "pypi", "--strict-conda-forge", "--no-use-v1-format", sdist, "-o", tmp_path],
        tmp_path)  # fmt: skip
    import jinja2

    def load(path: Path) -> dict[str, Any]:
        text = jinja2.Template(path.read_text("utf-8")).render(PYTHON="python")
        loaded: dict[str, Any] = yaml.safe_load(text)
        return loaded

    made = load(tmp_path / "ballscrew" / "meta.yaml")
    ours = load(ROOT / "packaging" / "conda-forge" / "meta.yaml")
    for section in ("host", "run"):
        assert sorted(made["requirements"][section]) == sorted(ours["requirements"][section])
    assert sorted(made["test"]["requires"]) == sorted(ours["test"]["requires"])
    assert made["build"]["entry_points"] == ours["build"]["entry_points"]
    assert made["build"]["noarch"] == ours["build"]["noarch"] == "python"
