"""A run's outputs are put in place together, or none of them (issue 52).

A killed ``program`` left a new CSV beside the old JSON and report in 18 of 22 kills: each
output was swapped in as soon as it was written. Now the CSV, the JSON and the report are
staged first and renamed into place together (SIGTERM waits during the renames), so a run
stopped at any moment leaves the earlier run's three outputs, or this run's three.
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from shared import ROOT

MACHINE = ROOT / "examples" / "machine_vmc.toml"
PROGRAMS = {
    "a": "G21 G90\nG1 X100 Y50 F3000\nG1 X0 Y0\nM30\n",
    "b": "G21 G90\nG1 X200 F6000\nG1 Y100\nG1 X0 Y0\nG1 X50\nM30\n",
}


def _run(where: Path, name: str) -> subprocess.Popen[str]:
    program = where / f"{name}.nc"
    program.write_text(PROGRAMS[name], encoding="utf-8")
    return subprocess.Popen(
        [sys.executable, "-m", "ballscrew", "program", str(program), "--machine", str(MACHINE),
         "--csv", str(where / "t.csv"), "--json", str(where / "r.json"),
         "--out", str(where / "rep")],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, text=True,
    )  # fmt: skip


def _which(where: Path) -> tuple[int, int, int]:
    """What each output says of its run: the JSON's blocks, the CSV's rows, the report's blocks."""
    doc = json.loads((where / "r.json").read_text("utf-8"))
    rows = len((where / "t.csv").read_text("utf-8").splitlines())
    report = (where / "rep" / "report.md").read_text("utf-8")
    blocks = int(report.split(" blocks")[0].split()[-1])
    return doc["blocks"], rows, blocks


@pytest.mark.slow
def test_a_program_stopped_at_any_moment_leaves_one_set_of_outputs(tmp_path: Path) -> None:
    sets = {}
    for name in ("a", "b"):  # each run's own set of outputs, whole
        start = time.monotonic()
        run = _run(tmp_path, name)
        assert run.wait(timeout=300) == 0
        took = time.monotonic() - start
        sets[name] = _which(tmp_path)
    assert sets["a"][0] == 2 and sets["b"][0] == 4 and sets["a"][1] != sets["b"][1]
    stopped = 0
    for k in range(5):  # stopped from early to late in a run, over the other's outputs
        before, now = ("a", "b") if k % 2 == 0 else ("b", "a")
        assert _run(tmp_path, before).wait(timeout=300) == 0
        proc = _run(tmp_path, now)
        time.sleep(took * (0.3 + 0.15 * k))
        proc.send_signal(signal.SIGTERM)
        stopped += proc.wait(timeout=120) == 130
        state = _which(tmp_path)
        assert state in (sets[before], sets[now]), state  # never a mix
        assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no leftover
    assert stopped >= 1  # some runs were stopped before they finished
