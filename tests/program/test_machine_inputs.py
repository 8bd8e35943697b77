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


def test_a_travel_longer_than_the_screw_is_refused(tmp_path: Path) -> None:
    # Issue 52: an X travel of 5 m on a 1.1 m bearing span ran the nut metres off its thread.
    # X's HIWIN R40-10K5 double nut (K5: 5 circuits of one loaded turn) is (1 + 1) turns x 5
    # circuits x 10 mm long, twice: 200 mm. So 1100 - 200 = 900 mm is the longest travel (the
    # nut must stay inside the span); the example's 800 mm passes.
    text = (ROOT / "examples" / "machine_vmc.toml").read_text(encoding="utf-8")
    text = text.replace(
        'case = "vertical_32x5.toml"',
        f'case = "{(ROOT / "examples" / "vertical_32x5.toml").as_posix()}"',
    )
    for travel, refused in (('"5 m"', True), ('"900 mm"', True), ('"899 mm"', False)):
        file = tmp_path / "m.toml"
        file.write_text(text.replace('travel = ["0 mm", "800 mm"]', f'travel = ["0 mm", {travel}]'),
                        encoding="utf-8")  # fmt: skip
        if refused:
            with pytest.raises(BallScrewInputError) as info:
                load_machine(file)
            assert info.value.field == "axes.X.travel" and "less than 900 mm" in str(info.value)
        else:
            assert load_machine(file).axes["X"].travel[1] == pytest.approx(0.899)
