"""A machine file's axis cases and a study's run record are read as regular files only."""

from __future__ import annotations

from pathlib import Path

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import load_machine
from ballscrew.report.study import load_record
from shared import ROOT


def test_an_axis_case_that_is_a_device_is_refused_naming_the_axis(tmp_path: Path) -> None:
    # The machine file names its axes' case files; '/dev/zero' there read until memory ran
    # out. The package's one input reader refuses it by the machine file's key.
    text = (ROOT / "examples" / "machine_vmc.toml").read_text(encoding="utf-8")
    head = text.split("[axes.X.case]")[0]  # the machine and X's limits, then X's case by path
    machine = tmp_path / "m.toml"
    machine.write_text(head.replace("[axes.X]\n", '[axes.X]\ncase = "/dev/zero"\n'), "utf-8")
    with pytest.raises(BallScrewInputError, match="a regular file") as info:
        load_machine(machine)
    assert info.value.field.startswith("axes.") and info.value.field.endswith(".case")


def test_a_run_record_that_is_a_device_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match="a regular file") as info:
        load_record("/dev/zero")
    assert info.value.field == "record"
