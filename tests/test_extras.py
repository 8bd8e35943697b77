"""A lean install: the core computes without the extras, and what needs one says which.

The missing libraries are simulated by ``sys.modules[name] = None`` (an import of the
name then fails as if it were not installed); tests/test_package.py checks the same
from a wheel installed with the core dependencies only.
"""

from __future__ import annotations

import importlib
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from ballscrew.io.extras import EXTRAS, MissingExtraError, MissingExtraWarning, missing, require
from cli_runner import run

ROOT = Path(__file__).resolve().parents[1]
CHECK_MOVE = "stroke=300 mm, feed=12 m/min, acceleration=3 m/s^2"
OPTIONAL = sorted({m for modules in EXTRAS.values() for m in modules})


def _pyproject_extras() -> dict[str, list[str]]:
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["project"]
    extras: dict[str, list[str]] = project["optional-dependencies"]
    extras["core"] = project["dependencies"]
    return extras


def _names(requirements: list[str]) -> set[str]:
    return {r.split(">")[0].split("[")[0].split(";")[0].strip().lower() for r in requirements}


def test_the_extras_of_pyproject_are_those_the_package_checks_for() -> None:
    extras = _pyproject_extras()
    assert _names(extras["sweep"]) == {m.lower() for m in EXTRAS["sweep"]}
    assert _names(extras["web"]) == {m.lower() for m in EXTRAS["web"]}
    assert _names(extras["fast"]) == {m.lower() for m in EXTRAS["fast"]}
    assert _names(extras["program"]) == {m.lower() for m in EXTRAS["program"]}
    assert _names(extras["servo"]) == {m.lower() for m in EXTRAS["servo"]}
    assert _names(extras["select"]) == {m.lower() for m in EXTRAS["select"]}
    assert not _names(extras["core"]) & {m.lower() for m in OPTIONAL}
    assert extras["all"] == ["ballscrew[sweep,web,fast,program,servo,select]"]
    assert "ballscrew[all]" in extras["test"]  # the README's two commands install everything


@pytest.mark.parametrize("module", EXTRAS["sweep"])
def test_sweep_without_its_extra_says_which_in_one_line(
    module: str, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    monkeypatch.setitem(sys.modules, module, None)
    code, _, err = run(
        ["sweep", str(ROOT / "examples" / "sweep_preload.toml"), "--out", str(tmp_path / "p.zarr")],
        capsys,
    )
    assert code == 2
    assert err == (
        f"error: ballscrew sweep needs the sweep extra ({module} is not installed): "
        "pip install 'ballscrew[sweep]'\n"
    )
    assert not (tmp_path / "p.zarr").exists()


@pytest.mark.parametrize("module", EXTRAS["web"])
def test_serve_without_its_extra_says_which_in_one_line(
    module: str, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(sys.modules, module, None)
    code, _, err = run(["serve", "--port", "0"], capsys)
    assert code == 2
    assert err == (
        f"error: ballscrew serve needs the web extra ({module} is not installed): "
        "pip install 'ballscrew[web]'\n"
    )


def test_contour_without_its_extra_says_which_in_one_line(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(sys.modules, "control", None)
    case = str(ROOT / "examples" / "xy_table_32x10.toml")
    code, _, err = run(["contour", "--case", case, "--radius", "5 mm"], capsys)
    assert code == 2
    assert err == (
        "error: ballscrew contour needs the servo extra (control is not installed): "
        "pip install 'ballscrew[servo]'\n"
    )


def test_the_web_package_without_its_extra_names_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "starlette", None)
    monkeypatch.delitem(sys.modules, "ballscrew.web", raising=False)
    with pytest.raises(MissingExtraError, match=r"pip install 'ballscrew\[web\]'") as info:
        importlib.import_module("ballscrew.web")
    assert isinstance(info.value, ImportError) and info.value.extra == "web"


def test_run_sweep_without_its_extra_names_it(monkeypatch: pytest.MonkeyPatch) -> None:
    from ballscrew.sweep.execute import run_sweep

    monkeypatch.setitem(sys.modules, "zarr", None)
    with pytest.raises(MissingExtraError, match=r"zarr is not installed.*ballscrew\[sweep\]"):
        run_sweep(None, "never.zarr")  # type: ignore[arg-type]  # refused before it is read


def test_the_study_without_salib_leaves_its_sobol_section_out_and_says_so(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from ballscrew.study.sensitivity import study_sensitivity

    monkeypatch.setitem(sys.modules, "SALib", None)
    with pytest.warns(MissingExtraWarning, match=r"SALib is not installed.*ballscrew\[sweep\]"):
        assert study_sensitivity(None, {}, 20.0, 0.0) is None  # type: ignore[arg-type]


def test_missing_and_require() -> None:
    assert missing("sweep") is None and missing("web") is None  # the test install has [all]
    assert missing("sweep", ("no_such_module_here",)) == "no_such_module_here"
    with pytest.raises(MissingExtraError) as info:
        require("sweep", "this", ("no_such_module_here.sub",))
    assert str(info.value) == (
        "this needs the sweep extra (no_such_module_here.sub is not installed): "
        "pip install 'ballscrew[sweep]'"
    )


_BLOCKED = """
import sys
for name in {optional!r}:
    sys.modules[name] = None
from ballscrew.cli import main
main({args!r})
"""


@pytest.mark.parametrize(
    "args",
    [
        ["torque", "--speed", "100 rpm"],
        ["case", "--template"],
        ["models"],
        ["screws"],
        ["check", "--case", str(ROOT / "examples" / "vertical_32x5.toml"), "--move", CHECK_MOVE],
    ],
    ids=lambda a: a[0],
)
def test_core_commands_run_without_any_extra(args: list[str], tmp_path: Path) -> None:
    # A fresh interpreter: in this one pint has already imported parts of Dask.
    code = textwrap.dedent(_BLOCKED.format(optional=OPTIONAL, args=args))
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, timeout=300
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip()
    assert "Traceback" not in done.stderr and "error" not in done.stderr
