"""One run owns its outputs: two output options on one place are refused before anything runs.

The reproducers of the hostile-input audit: ``--out x.fmu --json x.fmu`` left only the JSON,
``program --csv a --json a`` lost the CSV, a JSON inside the report folder was lost when the
folder was replaced. Each is now a usage error (exit 2) naming both options, and nothing is
written.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from cli_runner import run

MOVE = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["torque", "--csv", "{d}/a", "--json", "{d}/a"],
         "--csv '{d}/a' and --json '{d}/a' are one file"),
        (["torque", "--csv", "-", "--json", "-"], "--csv and --json both write to standard output"),
        (["torque", "--csv", "{d}/t.csv", "--json", "{d}/t.csv.meta.json"], "are one file"),
        (["export-friction", "--form", "stribeck", "--out", "{d}/x.json", "--json", "{d}/x.json"],
         "--out '{d}/x.json' and --json '{d}/x.json' are one file"),
        (["check", "--case", "study", "--move", MOVE, "--out", "{d}/rep",
          "--json", "{d}/rep/c.json"], "lies inside --out"),
    ],
)  # fmt: skip
def test_two_outputs_on_one_place_are_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], args: list[str], said: str
) -> None:
    argv = [a.format(d=tmp_path) for a in args]
    before = sorted(os.listdir(tmp_path))
    code, out, err = run(argv, capsys)
    assert code == 2, err
    assert said.format(d=tmp_path) in err, err
    assert sorted(os.listdir(tmp_path)) == before  # refused before anything is written
    assert out == ""


def test_a_symlink_to_the_same_file_is_the_same_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "b").symlink_to(tmp_path / "a")
    code, _, err = run(["torque", "--csv", str(tmp_path / "a"), "--json", str(tmp_path / "b")],
                       capsys)  # fmt: skip
    assert code == 2 and "are one file" in err


def test_distinct_outputs_are_all_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(["torque", "--speed", "100 rpm", "--csv", str(tmp_path / "t.csv"),
                        "--json", str(tmp_path / "t.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert {p.name for p in tmp_path.iterdir()} == {"t.csv", "t.csv.meta.json", "t.json"}
