"""fit, export-friction, monitor, acceptance, contour and sweep own their outputs (issue 52).

Each wrote its files one after the other in its own way (contour's report straight into the
folder): a run that failed or was stopped half-way left a new file beside an old one. Now
each puts its outputs in place together (:func:`ballscrew.cli.common.write_outputs`), and
refuses two of its options on one path before it runs. A failure is injected here while
the last output is staged (a full disk): every earlier output is left as it was, and no
temporary file or folder is left behind.
"""

from __future__ import annotations

import errno
import os
from pathlib import Path
from typing import Any

import pytest

from ballscrew.io.case import default_case_path
from ballscrew.io.files import OutputSet
from cli_runner import run
from shared import ROOT

SMALL = ROOT / "tests" / "data" / "small_case.toml"
XY = ROOT / "examples" / "xy_table_32x10.toml"
SERIES = ROOT / "examples" / "drag_torque_series.csv"
SWEEP = f"""
case = "{SMALL.as_posix()}"
models = ["catalog"]
[axes]
speed = "100, 1000 rpm"
axial_load = "1 kN"
[uncertainty]
samples = 8
seed = 5
sensitivity = "sobol"
[uncertainty.inputs]
"screw.preload" = {{ distribution = "normal", mean = "1.5 kN", std = "0.2 kN" }}
"lubricant.viscosity_scale" = {{ distribution = "uniform", low = 0.9, high = 1.1 }}
"""


def _measured(where: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    """A torque curve of the small case to fit (the model's own, written by torque)."""
    curve = where / "curve.csv"
    code, _, err = run(["torque", "--case", str(SMALL), "--speed", "100..2000:8 rpm",
                        "--table", "none", "--csv", str(curve)], capsys)  # fmt: skip
    assert code == 0, err
    return curve


def _sweep_file(where: Path) -> Path:
    file = where / "u.toml"
    file.write_text(SWEEP, "utf-8")
    return file


# (command line with {d} for the folder, the outputs it writes in the order it stages them)
COMMANDS: dict[str, tuple[list[str], list[str]]] = {
    "fit": (["fit", "--case", str(SMALL), "--measured", "{d}/curve.csv", "--free", "preload",
             "--out", "{d}/rep", "--json", "{d}/f.json"], ["f.json", "rep"]),
    "export-friction": (["export-friction", "--case", str(SMALL), "--form", "table",
                         "--out", "{d}/t.csv", "--json", "{d}/t.json"],
                        ["t.csv", "t.csv.meta.json", "t.json"]),
    "monitor": (["monitor", "--case", str(default_case_path()), "--measured", str(SERIES),
                 "--plot", "{d}/m.png", "--json", "{d}/m.json"], ["m.png", "m.json"]),
    "acceptance": (["acceptance", "--case", str(SMALL), "--torque", "0.30, 0.32 N*m",
                    "--plot", "{d}/a.svg", "--json", "{d}/a.json"], ["a.svg", "a.json"]),
    "contour": (["contour", "--case", str(XY), "--direction", "CCW", "--radius", "10 mm",
                 "--out", "{d}/rep", "--json", "{d}/c.json"], ["c.json", "rep"]),
    "sweep": (["sweep", "{d}/u.toml", "--out", "{d}/u.zarr", "--json", "{d}/s.json"],
              ["u.zarr.sensitivity-catalog.png", "u.zarr.sensitivity-catalog.svg", "s.json"]),
}  # fmt: skip

# Two options of each command on one path (or one inside the other): refused before it runs.
SHARED = {
    "fit": (["--out", "{d}/rep", "--json", "{d}/rep/f.json"], "lies inside --out"),
    "export-friction": (["--out", "{d}/t.csv", "--json", "{d}/t.csv.meta.json"],
                        "are one file"),
    "monitor": (["--plot", "{d}/m.png", "--json", "{d}/m.png"], "are one file"),
    "acceptance": (["--plot", "{d}/a.svg", "--json", "{d}/a.svg"], "are one file"),
    "contour": (["--out", "{d}/c", "--json", "{d}/c"], "are one file"),
    "sweep": (["--out", "{d}/u.zarr", "--json", "{d}/u.zarr"], "are one file"),
}  # fmt: skip


def _prepare(name: str, where: Path, capsys: pytest.CaptureFixture[str]) -> list[str]:
    if name == "fit":
        _measured(where, capsys)
    if name == "sweep":
        _sweep_file(where)
    return [a.format(d=where) for a in COMMANDS[name][0]]


def _without(args: list[str], options: tuple[str, ...]) -> list[str]:
    """``args`` without the given options and their values."""
    kept: list[str] = []
    skip = False
    for a in args:
        if skip:
            skip = False
        elif a in options:
            skip = True
        else:
            kept.append(a)
    return kept


@pytest.mark.parametrize("name", sorted(SHARED))
def test_two_options_on_one_path_are_refused_before_the_run(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    args = _prepare(name, tmp_path, capsys)
    flags, said = SHARED[name]
    first, second = flags[0], flags[2]
    argv = _without(args, (first, second)) + [f.format(d=tmp_path) for f in flags]
    before = sorted(os.listdir(tmp_path))
    code, out, err = run(argv, capsys)
    assert code == 2, err
    assert said in err and first in err and second in err, err
    assert sorted(os.listdir(tmp_path)) == before and out == ""  # nothing ran or was written


def _old(where: Path, outputs: list[str]) -> None:
    """Every output replaced by an earlier run's stand-in: a file 'old', a folder with old.txt."""
    for name in outputs:
        place = where / name
        if place.is_dir():
            import shutil

            shutil.rmtree(place)
            place.mkdir()
            (place / "old.txt").write_text("old")
        else:
            place.write_bytes(b"old")


def _is_old(where: Path, name: str) -> bool:
    place = where / name
    if place.is_dir():
        return sorted(p.name for p in place.iterdir()) == ["old.txt"]
    return place.read_bytes() == b"old"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_outputs_are_put_in_place_all_or_none(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:  # fmt: skip
    args = _prepare(name, tmp_path, capsys)
    outputs = COMMANDS[name][1]
    code, _, err = run(args, capsys)
    assert code == 0, err
    _old(tmp_path, outputs)
    before = sorted(os.listdir(tmp_path))
    # The disk fills while the last output is staged, after every other one is.
    staged = [0]
    real_file, real_folder = OutputSet.file, OutputSet.folder

    def count(real: Any) -> Any:
        def staging(self: OutputSet, *a: Any) -> None:
            real(self, *a)
            staged[0] += 1
            if staged[0] == len(outputs):
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

        return staging

    monkeypatch.setattr(OutputSet, "file", count(real_file))
    monkeypatch.setattr(OutputSet, "folder", count(real_folder))
    code, _, err = run(args, capsys)
    assert code == 2 and "No space left on device" in err and "internal error" not in err, err
    assert staged[0] == len(outputs)  # every output was staged before the failure
    if name == "sweep":
        # The store (resumable, swapped in by the run itself) is the new one: the figures and
        # the JSON of the store it replaced went with it, and the new ones were not put in
        # place. The new store stands alone, never beside the old run's files.
        assert not any((tmp_path / o).exists() for o in outputs)
        assert (tmp_path / "u.zarr" / "zarr.json").is_file() or (tmp_path / "u.zarr").is_dir()
        assert sorted(os.listdir(tmp_path)) == sorted(set(before) - set(outputs))
    else:
        assert all(_is_old(tmp_path, o) for o in outputs)  # none of them was put in place
        assert sorted(os.listdir(tmp_path)) == before  # no temporary file or folder left
    monkeypatch.undo()
    code, _, err = run(args, capsys)  # the disk has room again: all of them replaced
    assert code == 0, err
    assert not any(_is_old(tmp_path, o) for o in outputs)
    assert sorted(os.listdir(tmp_path)) == before
