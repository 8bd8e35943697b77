"""Pins of ``program/axes.py``, ``program/sinumerik.py`` and ``program/rs274.py`` (issue 49).

Written from the survivors of their mutation runs (docs/mutation.md). Every expected number
is worked out here by hand from the inputs: the S-curve of a single move (its phases from
the feed, acceleration and jerk), the process force times the distance fed, the weight's
share along an incline, the mean of a linear acceleration over a window, the shaft's EA/a in
series with the nut, a SINUMERIK block written out as RS274/NGC, and the canonical commands
LinuxCNC's ``rs274`` prints, written as it prints them.
"""

from __future__ import annotations

import dataclasses
import math
import shutil
import warnings
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from ballscrew.axis.check import CREEP_SPEED
from ballscrew.axis.setup import axis_setup
from ballscrew.axis.thermal import estimated_screw_length
from ballscrew.chain import friction_torque
from ballscrew.design.limits import root_diameter
from ballscrew.design.stiffness import design_nut_stiffness
from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import Machine, load_machine
from ballscrew.materials import STANDARD_GRAVITY
from ballscrew.program import run_program
from ballscrew.program.axes import ProgramResult, Reversal, _limits, _torques_at
from ballscrew.program.gcode import FEED, Program, program_from_rows, read_program
from ballscrew.program.planner import plan
from ballscrew.program.rs274 import (
    LINE_MARK,
    _blocks,
    _marked,
    _refusal,
    read_part_program,
    read_program_rs274,
)
from ballscrew.program.sinumerik import drilling_cycle, to_rs274

MASS = 300.0  # kg
JERK = 50.0  # m/s^3
FORCE = 500.0  # N, the process force
MODULUS = 206e9  # Pa, the screw shaft's Young's modulus as the makers' catalogues take it

CASE = """
title = "X for the pins"
[screw]
designation = "HIWIN R40-10K5-FDC"
{nut}
contact_angle = "45 deg"
[lubricant]
name = "PAO ISO VG 68"
[operation]
temperature = "40 degC"
[axis]
moving_mass = "300 kg"
incline = "{incline}"
{span}
{length}
screw_inertia = "2.4e-3 kg*m**2"
motor_inertia = "1.8e-3 kg*m**2"
bearing_bore = "30 mm"
dn_limit = "130000 mm*rpm"
[motor]
rated_torque = "20 N*m"
peak_torque = "60 N*m"
rated_speed = "2000 rpm"
"""

MACHINE = """
[machine]
rapid_feed = "30 m/min"
ambient = "40 degC"
start_temperature = "40 degC"
sample_time = "10 ms"
[axes.X]
case = "x.toml"
max_feed = "30 m/min"
max_acceleration = "2 m/s^2"
max_jerk = "50 m/s^3"
travel = [{travel}]
process_force = "{force}"
"""


def _machine(
    folder: Path, *, travel: str = '"-100 mm", "700 mm"', force: str = "500 N",
    incline: str = "0 deg", span: str | None = "1100 mm", length: bool = True,
    nut: str = 'preload_share = "6 %"', letters: str = "X",
) -> Machine:  # fmt: skip
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "x.toml").write_text(
        CASE.format(nut=nut, incline=incline,
                    span="" if span is None else f'bearing_span = "{span}"',
                    length='screw_length = "1200 mm"' if length else ""),
        encoding="utf-8",
    )  # fmt: skip
    text = MACHINE.format(travel=travel, force=force)
    axis = text[text.index("[axes.X]") :]
    text = text[: text.index("[axes.X]")] + "".join(
        axis.replace("[axes.X]", f"[axes.{k}]") for k in letters
    )
    (folder / "m.toml").write_text(text, encoding="utf-8")
    return load_machine(folder / "m.toml")


@pytest.fixture(scope="module")
def out_and_back(tmp_path_factory: pytest.TempPathFactory) -> tuple[Machine, ProgramResult]:
    """A rapid 300 mm out and a feed back, both at 30 m/min (0.5 m/s), 2 m/s^2, 50 m/s^3."""
    machine = _machine(tmp_path_factory.mktemp("out_and_back"))
    return machine, run_program(machine, "G0 X300\nG1 X0 F30000\nM30\n")


# The S-curve of 300 mm at v = 0.5 m/s, a = 2 m/s^2, j = 50 m/s^3: each of its two ramps
# takes v/a + a/j = 0.29 s over v (v/a + a/j) / 2 = 72.5 mm, the 155 mm between at 0.5 m/s
# take 0.31 s: 0.89 s a move.
MOVE_TIME = 2 * 0.29 + 0.31


def test_a_single_moves_process_work_distances_and_speed_by_hand(
    out_and_back: tuple[Machine, ProgramResult],
) -> None:
    _, r = out_and_back
    x = r.axes["X"]
    assert r.motion.duration == pytest.approx(2 * MOVE_TIME, abs=1e-9)
    # The process force acts in the feed block only: 500 N x 0.3 m (1e-12: rounding).
    assert x.process_work == pytest.approx(FORCE * 0.3, rel=1e-12)
    doc = x.as_dict()
    assert doc["process_work_J"] == pytest.approx(150.0, rel=1e-12)
    assert doc["distance_mm"] == pytest.approx(600.0, rel=1e-12)
    assert doc["feed_distance_mm"] == pytest.approx(300.0, rel=1e-12)
    assert doc["travel_mm"] == pytest.approx(300.0, rel=1e-12)
    # 0.5 m/s on a 10 mm lead: 50 rev/s, 3000 rpm; the motor's rated 2000 rpm as typed.
    assert doc["peak_motor_speed_rpm"] == pytest.approx(3000.0, rel=1e-9)
    assert doc["motor_rated_speed_rpm"] == pytest.approx(2000.0, rel=1e-12)
    assert x.potential_energy == 0.0  # horizontal
    # The travel row: 300 mm used of the 800 mm from -100 to 700 mm.
    row = next(c for c in x.verdicts if c.key == "travel")
    assert (row.value, row.limit) == pytest.approx((300.0, 800.0), rel=1e-12)
    assert row.utilisation == pytest.approx(0.375, rel=1e-12)


def test_the_axial_force_is_inertia_plus_the_process_force_against_feed_motion(
    out_and_back: tuple[Machine, ProgramResult],
) -> None:
    _, r = out_and_back
    ds = r.data
    a = ds["acceleration"].sel(axis="X").values
    v = ds["velocity"].sel(axis="X").values
    feeding = ds["feeding"].values.astype(bool)
    force = ds["axial_force"].sel(axis="X").values
    # m a, and in the feed block, while the axis moves, 500 N against the motion; in the
    # rapid and at rest nothing else (1e-9 N: the sum's rounding).
    expected = MASS * a + np.where(feeding & (v != 0.0), FORCE * np.sign(v), 0.0)
    np.testing.assert_allclose(force, expected, rtol=0, atol=1e-9)


def test_the_reversal_by_hand(out_and_back: tuple[Machine, ProgramResult]) -> None:
    machine, r = out_and_back
    (rev,) = r.axes["X"].reversals
    t = r.motion.time
    # At the end of the first block, where the axis stops: time and place exact.
    assert rev.time == pytest.approx(MOVE_TIME, abs=1e-12)
    assert rev.position == pytest.approx(0.3, abs=1e-12)
    assert rev.line == 2  # the block it reverses into
    # The samples on either side of the stop: the last one moving before it, the first after.
    t_b = float(t[t < MOVE_TIME - 1e-12].max())
    t_a = float(t[t > MOVE_TIME + 1e-12].min())
    # The acceleration ramps linearly to 0 at the stop and from 0 after it, at the jerk:
    # a = -j (t_stop - t) before, -j (t - t_stop) after. Its mean over 20 ms of motion on
    # either side, times the mass; the rapid has no process force, the feed back 500 N
    # against its motion (-X): the load on the nut is -500 N more.
    before = MASS * -JERK * ((MOVE_TIME - t_b) + 0.01)
    after = MASS * -JERK * ((t_a - MOVE_TIME) + 0.01) - FORCE
    assert rev.load_before == pytest.approx(before, rel=1e-9)
    assert rev.load_after == pytest.approx(after, rel=1e-9)
    assert rev.load_direction == "-/-"
    # The friction at the creep speed under the mean of the two samples' loads, as a force.
    load = 0.5 * (MASS * -JERK * (MOVE_TIME - t_b) + MASS * -JERK * (t_a - MOVE_TIME) - FORCE)
    case = machine.axes["X"].case
    screw = case.screw
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t_f = float(friction_torque(screw, case.lubricant, speed=CREEP_SPEED, temperature=40.0,
                                    axial_load=abs(load), model=machine.model).total)  # fmt: skip
    f_f = 2.0 * math.pi * t_f / screw.lead
    assert rev.friction_force == pytest.approx(f_f, rel=1e-9)
    # At 300 mm, the middle of the travel (-100 to 700 mm), which is centred in the 1100 mm
    # span: 550 mm from the thrust bearing. Shaft EA/a in series with the (preloaded,
    # double) nut.
    ea = MODULUS * math.pi * root_diameter(screw) ** 2 / 4.0
    k = 1.0 / (0.55 / ea + 1.0 / design_nut_stiffness(screw, 0.0))
    assert rev.stiffness == pytest.approx(k, rel=1e-12)
    assert rev.lost_motion == pytest.approx(2.0 * f_f / k, rel=1e-9)
    doc = rev.as_dict()
    assert doc["position_mm"] == pytest.approx(300.0, rel=1e-12)
    assert doc["stiffness_N_per_um"] == pytest.approx(k / 1e6, rel=1e-12)
    assert doc["lost_motion_um"] == pytest.approx(2e6 * f_f / k, rel=1e-9)


def test_the_screw_warms_by_its_friction_heat_over_its_heat_capacity(
    out_and_back: tuple[Machine, ProgramResult],
) -> None:
    machine, r = out_and_back
    x = r.axes["X"]
    case = machine.axes["X"].case
    thermal = {**case.thermal, "ambient": machine.ambient}
    node = axis_setup(case.screw, case.axis, thermal, 0.8).node
    # 1.78 s is short against the node's time constant (C = 5.4 kJ/K against h pi d L of a
    # few W/K: half an hour): the screw and bearing friction's heat, 383 J, stays in the
    # node, Delta T = E / C (0.5 %: what the air takes meanwhile and the step rule; the
    # bearings' 4.4 J alone are 1.2 %).
    heat = x.friction_energy + x.bearing_energy
    rise = heat / node.heat_capacity(case.screw)
    assert x.max_temperature - x.start_temperature == pytest.approx(rise, rel=5e-3)
    assert x.final_temperature == x.max_temperature  # the last sample is the warmest


def test_the_weight_along_an_incline_is_potential_energy(tmp_path: Path) -> None:
    machine = _machine(tmp_path, incline="30 deg", force="0 N")
    # From 100 to 200 mm: m g sin(30 deg) x 0.1 m = 147.1 J (1e-12: rounding).
    program = read_program("G1 X200 F6000\nM30\n", start=(0.1, 0.0, 0.0))
    x = run_program(machine, program).axes["X"]
    assert x.potential_energy == pytest.approx(MASS * STANDARD_GRAVITY * 0.5 * 0.1, rel=1e-12)


def _shaft_k(screw: Any, a: float) -> float:
    return MODULUS * math.pi * root_diameter(screw) ** 2 / 4.0 / a


def test_a_single_nut_takes_the_programs_peak_load(tmp_path: Path) -> None:
    # Travel 0 to 650 mm centred between supports 800 mm apart: the nut is 75 mm + its
    # position from the thrust bearing.
    machine = _machine(tmp_path, travel='"0 mm", "650 mm"', force="0 N", span="800 mm",
                       nut='nut = "single"\npreload_share = "0 %"')  # fmt: skip
    r = run_program(machine, "G1 X100 F6000\nG1 X0\nG1 X50\nM30\n")
    screw = machine.axes["X"].case.screw
    # A single nut without preload at the program's largest axial load: 300 kg x 2 m/s^2.
    k_nut = design_nut_stiffness(screw, MASS * 2.0)
    revs = r.axes["X"].reversals
    assert [round(v.position, 9) for v in revs] == [0.1, 0.0]
    for rev, a in zip(revs, [0.175, 0.075], strict=True):
        k = 1.0 / (1.0 / _shaft_k(screw, a) + 1.0 / k_nut)
        assert rev.stiffness == pytest.approx(k, rel=1e-12), a


@pytest.mark.parametrize(("preload", "loaded"), [("0 N", True), ("0.5 N", False)])
def test_a_double_nut_without_preload_takes_the_programs_peak_load(
    tmp_path: Path, preload: str, loaded: bool
) -> None:
    # A double nut set to 0 N has no preloaded contacts: like a single nut, one half at the
    # program's largest axial load (300 kg x 2 m/s^2). Any preload, however small (0.5 N),
    # is a preloaded nut taken at rest.
    # Travel 0 to 500 mm centred between supports 800 mm apart (a double nut is 200 mm
    # long): the reversal at X100 is 150 + 100 mm from the thrust bearing.
    machine = _machine(tmp_path, travel='"0 mm", "500 mm"', force="0 N", span="800 mm",
                       nut=f'preload = "{preload}"')  # fmt: skip
    r = run_program(machine, "G1 X100 F6000\nG1 X0\nM30\n")
    screw = machine.axes["X"].case.screw
    k_nut = design_nut_stiffness(screw, MASS * 2.0 if loaded else 0.0)
    rev = r.axes["X"].reversals[0]
    assert round(rev.position, 9) == 0.1
    k = 1.0 / (1.0 / _shaft_k(screw, 0.25) + 1.0 / k_nut)
    assert rev.stiffness == pytest.approx(k, rel=1e-12)


def test_the_screw_length_estimated_from_the_machines_travel(tmp_path: Path) -> None:
    # No screw length or bearing span in the case: estimated from the travel of the machine
    # file (800 mm from -100 to 700 mm), also for an axis standing through a program of no
    # motion.
    machine = _machine(tmp_path, force="0 N", length=False, span=None)
    moved = run_program(machine, "G1 X100 F6000\nM30\n").axes["X"]
    standing = run_program(machine, "M3 S100\nM5\n").axes["X"]
    length = estimated_screw_length(machine.axes["X"].case.screw, 0.8)
    for x in (moved, standing):
        assert any(f"screw_length = {length * 1e3:.0f} mm (estimated" in n for n in x.notes)


def test_an_axis_standing_through_a_program_of_no_motion(tmp_path: Path) -> None:
    machine = _machine(tmp_path, force="0 N")
    x = run_program(machine, "M3 S100\nM5\n").axes["X"]
    assert (x.peak_speed, x.travel, x.thermal_lead_error) == (0.0, 0.0, 0.0)
    assert (x.distance, x.feed_distance) == (0.0, 0.0)
    assert x.start_temperature == x.final_temperature == x.max_temperature == 40.0
    assert x.peak_torque == x.rms_torque == 0.0  # horizontal, at rest: no torque


class _Cycle(SimpleNamespace):
    pass


def test_the_torques_interpolate_in_temperature_above_a_twentieth_of_a_kelvin() -> None:
    first = _Cycle(friction_torque=np.array([1.0, 1.0, 1.0]),
                   motor_torque=np.array([2.0, 2.0, -2.0]),
                   screw_speed=np.array([1.0, 1.0, -1.0]))  # fmt: skip
    warm = _Cycle(friction_torque=np.array([0.8, 0.8, 0.8]))

    def refuse() -> Any:
        raise AssertionError("the warm cycle is not needed")

    # 0.04 K of warming: the start's torques, the warm cycle not even run.
    t_f, t_m = _torques_at(np.array([40.0, 40.02, 40.04]), first, refuse, 2.0)  # type: ignore[arg-type]
    assert t_f is first.friction_torque and t_m is first.motor_torque
    # 0.052 K: the friction in proportion to each sample's warming, 1 to 0.8 N*m; the motor
    # torque follows through the gear of 2, with the sign of the motion.
    temp = np.array([40.0, 40.026, 40.052])
    t_f, t_m = _torques_at(temp, first, lambda: warm, 2.0)  # type: ignore[arg-type]
    share = np.array([0.0, 0.5, 1.0])
    np.testing.assert_allclose(t_f, 1.0 - 0.2 * share, rtol=1e-9)
    np.testing.assert_allclose(t_m, [2.0, 2.0 - 0.05, -2.0 + 0.1], rtol=1e-9)


def test_the_friction_share_by_hand(out_and_back: tuple[Machine, ProgramResult]) -> None:
    _, r = out_and_back
    x = r.axes["X"]
    # Losses 10 + 2 J over what is turned over: the losses, 5 J of process work, 3 J taken
    # back; a weight lowered (-4 J) adds nothing: 12 / 20.
    hand = dataclasses.replace(x, friction_energy=10.0, bearing_energy=2.0, process_work=5.0,
                               regenerated_energy=3.0, potential_energy=-4.0)  # fmt: skip
    assert hand.friction_share == pytest.approx(0.6, rel=1e-12)
    # Negative process work counts as nothing, a weight lifted (4 J) counts.
    lifted = dataclasses.replace(hand, process_work=-5.0, potential_energy=4.0)
    assert lifted.friction_share == pytest.approx(12.0 / 19.0, rel=1e-12)
    # Below 1 J turned over: still a share.
    tiny = dataclasses.replace(hand, friction_energy=0.2, bearing_energy=0.1, process_work=0.0,
                               regenerated_energy=0.0, potential_energy=0.0)  # fmt: skip
    assert tiny.friction_share == pytest.approx(1.0, rel=1e-12)
    # The machine's totals: two axes, 12 of 20 and 0.3 of 0.3.
    both = dataclasses.replace(r, axes={"X": hand, "Y": tiny})
    totals = both.as_dict()["machine_totals"]
    assert totals["friction_share"] == pytest.approx(12.3 / 20.3, rel=1e-12)
    lone = dataclasses.replace(r, axes={"X": tiny})
    assert lone.as_dict()["machine_totals"]["friction_share"] == pytest.approx(1.0, rel=1e-12)
    lifted_totals = dataclasses.replace(r, axes={"X": lifted}).as_dict()["machine_totals"]
    assert lifted_totals["friction_share"] == pytest.approx(12.0 / 19.0, rel=1e-12)


def test_a_reversals_json_units() -> None:
    rev = Reversal(time=1.0, position=0.25, load_before=10.0, load_after=-10.0,
                   friction_force=50.0, stiffness=2e8, lost_motion=5e-7, line=3)  # fmt: skip
    doc = rev.as_dict()
    assert (doc["position_mm"], doc["stiffness_N_per_um"], doc["lost_motion_um"]) == \
        pytest.approx((250.0, 200.0, 0.5), rel=1e-12)  # fmt: skip
    assert doc["load_direction"] == "+/-"
    assert dataclasses.replace(rev, load_before=0.0, load_after=-0.0).load_direction == "0/0"
    assert dataclasses.replace(rev, load_before=-1e-9, load_after=1e-9).load_direction == "-/+"


@pytest.mark.parametrize(
    ("text", "line", "word"),
    [
        ("G1 X10 F1000\nG1 X-150\n", "program line 2", "X-150 mm"),
        ("G1 X10 F1000\nG1 X750\n", "program line 2", "X750 mm"),
    ],
)
def test_a_block_past_the_travel_is_named_in_millimetres(
    out_and_back: tuple[Machine, ProgramResult], text: str, line: str, word: str
) -> None:
    machine, _ = out_and_back
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, text)
    assert (info.value.field, info.value.value) == (line, word)
    assert "-100 to 700 mm" in info.value.allowed


@pytest.mark.parametrize(
    ("text", "line"),
    [
        # An arc in a plane with an axis the machine lacks names its line, even when that
        # axis ends where it started (the arc moves it on the way).
        ("G1 X10 F1000\nG18 G2 X10 Z0 I5 K0\n", "program line 2"),
        ("G1 X10 F1000\nG19 G2 Y0 Z0 J5 K0\n", "program line 2"),
        ("G1 X10 F1000\nG17 G2 X10 Y0 I5 J0\n", "program line 2"),
    ],
)
def test_an_arc_in_a_plane_of_a_missing_axis_names_its_line(
    out_and_back: tuple[Machine, ProgramResult], text: str, line: str
) -> None:
    machine, _ = out_and_back
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, text)
    assert info.value.field == line


# SINUMERIK 840D blocks written out by hand as RS274/NGC (the module's references: Siemens'
# Fundamentals and Cycles manuals).


def test_the_g_and_m_codes_both_languages_write_alike_pass_through() -> None:
    text = "G18\nG19\nG17\nM0\nM1\nM4\nM7\nM2\n"
    assert to_rs274(text)[0].splitlines() == ["G18", "G19", "G17", "M0", "M1", "M4", "M7", "M2"]
    with pytest.raises(BallScrewInputError, match="not G19"):
        to_rs274("G0 Z10\nG19\nCYCLE81(10,0,2,-5)\n")  # the plane is tracked through G19


def test_gear_stages_m40_to_m45_are_dropped_and_m46_refused() -> None:
    out, notes = to_rs274("M40\nM45\n")
    assert out.splitlines() == ["", ""]
    assert any("M40 (gear stage)" in n for n in notes)
    with pytest.raises(BallScrewInputError) as info:
        to_rs274("M46\n")
    assert info.value.value == "M46"


def test_a_tool_change_forgets_the_tool_axis_position() -> None:
    # After M6 the new tool's length may move the tip: a cycle needs Z programmed again.
    with pytest.raises(BallScrewInputError, match="not known"):
        to_rs274("G0 Z10\nM6\nCYCLE81(10,0,2,-15)\n")


def test_t0_has_no_length_to_apply() -> None:
    # D1 after T0 (no tool): dropped, not G43 H0.
    out, notes = to_rs274("T0\nD1\n")
    assert out.splitlines() == ["T0", ""]
    assert any("named or unknown tool" in n for n in notes)


def test_a_dwell_of_zero_seconds() -> None:
    assert to_rs274("G4 F0\n")[0] == "G4 P0\n"


def test_a_depth_at_the_approach_plane_is_refused() -> None:
    # CYCLE81(10, 0, 2, 2): RFP + SDIS = 2 and DP = 2, no drilling at all.
    with pytest.raises(BallScrewInputError, match=r"a final depth \(2\) below"):
        drilling_cycle("CYCLE81", "10,0,2,2")
    with pytest.raises(BallScrewInputError) as info:
        drilling_cycle("CYCLE81", "10,0,2,5")
    assert info.value.field == "program line 0"  # called without a line


def test_inch_cycles_track_the_tool_axis_in_inches() -> None:
    # G70: Z1 is 25.4 mm; CYCLE81(1, 0, 0.1, -0.5) starts at RTP = 1 in: G98, back to the
    # start height; the second cycle starts from there again (RTP, in inches).
    out, _ = to_rs274("G70\nG0 Z1\nCYCLE81(1,0,0.1,-0.5)\nCYCLE81(1,0,0.1,-0.25)\n")
    assert out.splitlines() == ["G20", "G0 Z1", "G98 G81 Z-0.5 R0.1", "G98 G81 Z-0.25 R0.1"]
    # Incremental Z in inches adds to the position: 0.5 + 0.5 in = RTP 1 in.
    out, _ = to_rs274("G70\nG0 Z0.5\nG91 G0 Z0.5\nG90\nCYCLE81(1,0,0.1,-0.5)\n")
    assert out.splitlines()[-1] == "G98 G81 Z-0.5 R0.1"


def test_text_in_quotes_keeps_its_case_and_the_rest_is_read_in_capitals() -> None:
    out, notes = to_rs274('T="Drill_a" m6\n')
    assert out == "T1 M6\n"
    assert any('T="Drill_a"' in n for n in notes)


def test_notes_name_their_first_line_and_count_the_others() -> None:
    _, notes = to_rs274("\ufeffG0 X1\n")
    assert "a byte-order mark at the start: dropped: line 1" in notes
    assert any(n.startswith("no G70, G71, G700 or G710") and n.endswith(": line 1")
               for n in notes)  # fmt: skip
    assert not any("(and" in n for n in notes)  # each kind once: no count
    _, notes = to_rs274("G90 G710\n")
    assert "G710 (metric, feeds in mm/min): read as G21: line 1" in notes


def test_two_cycle_calls_in_a_block_name_the_second() -> None:
    with pytest.raises(BallScrewInputError) as info:
        to_rs274("G0 Z10\nCYCLE81(10,0,2,-5) CYCLE82(10,0,2,-5)\n")
    assert info.value.value == "CYCLE82"


def test_an_inch_cycle_away_from_rtp_says_where_the_tool_is_in_inches() -> None:
    with pytest.raises(BallScrewInputError, match="it is at 2 here"):
        to_rs274("G70\nG0 Z2\nCYCLE81(1,0,0.1,-0.5)\n")


def test_a_modal_cycle_from_its_approach_plane_needs_no_lift() -> None:
    # RTP = RFP + SDIS = 2 (G99) and the tool at Z2: not below R, so the X move comes first
    # in both languages.
    out, _ = to_rs274("G0 Z2\nMCALL CYCLE81(2,0,2,-5)\nX1 F250\n")
    assert out.splitlines()[2] == "G99 G81 X1 Z-5 R2 F250"


def test_work_offsets_and_their_notes() -> None:
    out, notes = to_rs274("G55\nG56\nG57\nG505\nG53 G0 Z0\n")
    assert out.splitlines() == ["G55", "G56", "G57", "G58", "G53 G0 Z0"]
    assert "G505 (settable work offset 5): read as G58, RS274/NGC's 5th: line 4" in notes
    assert not any("G57 (" in n for n in notes)
    _, notes = to_rs274("G90 G506\n")  # the note names the offset's own word
    assert "G506 (settable work offset 6): read as G59, RS274/NGC's 6th: line 1" in notes


def test_path_modes_exact_stop_ends_and_rounding() -> None:
    out, notes = to_rs274("G64\nG641\nG643\nG644\nG645\nG602\nG603\n")
    assert out.splitlines() == ["G64"] * 5 + ["", ""]
    told = "\n".join(notes)
    for code in ("G641", "G643", "G644", "G645", "G602", "G603"):
        assert f"{code} (" in told
    assert "G64 (" not in told


def test_the_motion_mode_plane_and_distance_mode_are_tracked() -> None:
    # G3 is a motion mode: the line after a single cycle restores it.
    out, _ = to_rs274("G0 Z10\nG3 X0 Y0 I1 J0 F100\nCYCLE81(10,0,2,-5)\n\n")
    assert out.splitlines()[3] == "G3"
    # G90 after G91, and G17 after G18, allow a cycle.
    assert to_rs274("G91\nG90\nG0 Z10\nCYCLE81(10,0,2,-5)\n")[0].splitlines()[3] == \
        "G98 G81 Z-5 R2"  # fmt: skip
    assert to_rs274("G18\nG17\nG0 Z10\nCYCLE81(10,0,2,-5)\n")[0].splitlines()[3] == \
        "G98 G81 Z-5 R2"  # fmt: skip


def test_d1_after_t1_is_its_length() -> None:
    assert to_rs274("T1\nD1\n")[0].splitlines() == ["T1", "G43 H1"]


def test_g4_s_without_a_spindle_speed_names_the_word_as_typed() -> None:
    with pytest.raises(BallScrewInputError) as info:
        to_rs274("G4 S10\n")
    assert info.value.value == "G4 S10"


# LinuxCNC's canonical commands, written as ``rs274 -g`` prints them (its 2.9 output format:
# the sequence number, the block's N word or dots, the command).


def _canon(*commands: str, line: int = 1) -> list[str]:
    return [f"{k + 1:5d} N{LINE_MARK + line} {c}" for k, c in enumerate(commands)]


def _rows(*commands: str, rotary: str = "", max_blocks: int | None = None) -> Program:
    rows, notes, used, _ = _blocks(_canon(*commands), ["line one"], max_blocks, rotary=rotary)
    return program_from_rows(rows, notes, used, "")


def _refused(*commands: str, rotary: str = "") -> BallScrewInputError:
    with pytest.raises(BallScrewInputError) as info:
        _rows(*commands, rotary=rotary)
    return info.value


def test_centimetres_and_the_first_move_from_the_origin() -> None:
    p = _rows("USE_LENGTH_UNITS(CANON_UNITS_CM)",
              "STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)")  # fmt: skip
    np.testing.assert_allclose(p.start[0], [0.0, 0.0, 0.0], atol=0)
    np.testing.assert_allclose(p.end[0], [0.01, 0.02, 0.03], rtol=1e-15)
    # Millimetres before any USE_LENGTH_UNITS, the XY plane, no rotary motion.
    p = _rows("SET_FEED_RATE(600.0000)",
              "STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)")  # fmt: skip
    np.testing.assert_allclose(p.end[0], [0.001, 0.0, 0.0], rtol=1e-15)
    assert p.feed[0] == pytest.approx(0.01, rel=1e-15)  # 600 mm/min
    assert p.plane[0] == 17
    assert p.rotary_start is None or not np.any(p.rotary_start)


def test_an_arc_in_the_yz_plane() -> None:
    # G19 G3 from Y0 Z0 to Y2 Z0 about Y1 Z0 (ARC_FEED's first coordinate is Y, its second
    # Z, then the centre's, the turn, X at the end): half a turn counter-clockwise.
    p = _rows(
        "SET_FEED_RATE(100.0000)",
        "SELECT_PLANE(CANON_PLANE_YZ)",
        "ARC_FEED(2.0000, 0.0000, 1.0000, 0.0000, 1, 3.0000, 0.0000, 0.0000, 0.0000)",
    )
    assert p.plane[0] == 19
    np.testing.assert_allclose(p.end[0], [0.003, 0.002, 0.0], atol=1e-15)
    np.testing.assert_allclose(p.centre[0], [0.0, 0.001, 0.0], atol=1e-15)
    assert p.sweep[0] == pytest.approx(math.pi, rel=1e-12)


def test_turn_counts_of_clockwise_arcs() -> None:
    # G2 P2 around (1, 0) from the origin back to it: two full turns clockwise, -4 pi; a
    # half circle with P2: -pi - 2 pi.
    p = _rows(
        "SET_FEED_RATE(100.0000)",
        "ARC_FEED(0.0000, 0.0000, 1.0000, 0.0000, -2, 0.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(2.0000, 0.0000, 1.0000, 0.0000, -2, 0.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(0.0000, 0.0000, 1.0000, 0.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)",
    )
    np.testing.assert_allclose(p.sweep, [-4 * math.pi, -3 * math.pi, -math.pi], rtol=1e-12)


def test_an_arc_of_one_metre_radius_and_one_of_none() -> None:
    # A quarter circle of radius 1000 mm, counter-clockwise.
    p = _rows(
        "SET_FEED_RATE(100.0000)",
        "ARC_FEED(-1000.0000, 1000.0000, -1000.0000, 0.0000, 1, 0.0000, 0.0, 0.0, 0.0)",
    )
    assert p.sweep[0] == pytest.approx(math.pi / 2, rel=1e-12)
    # Radius 0 (the centre on the start, here at X1 Y1): LinuxCNC's straight feed along
    # the normal axis.
    p = _rows("SET_FEED_RATE(100.0000)",
              "STRAIGHT_FEED(1.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
              "ARC_FEED(1.0000, 1.0000, 1.0000, 1.0000, 1, -2.0000, 0.0, 0.0, 0.0)")  # fmt: skip
    assert p.kind.tolist() == [FEED, FEED]
    np.testing.assert_allclose(p.end[1], [0.001, 0.001, -0.002], atol=1e-15)
    # A turn count of 0 is no arc.
    error = _refused(
        "SET_FEED_RATE(100.0000)",
        "ARC_FEED(2.0000, 0.0000, 1.0000, 0.0000, 0, 0.0000, 0.0, 0.0, 0.0)",
    )
    assert "at least one turn" in error.allowed


def test_a_rotation_turns_xy_arcs_and_points_by_hand() -> None:
    # SET_XY_ROTATION(30): (10, 5) is (10 cos 30 - 5 sin 30, 10 sin 30 + 5 cos 30).
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    p = _rows("SET_XY_ROTATION(30.0000)", "SET_FEED_RATE(100.0000)",
              "STRAIGHT_TRAVERSE(10.0000, 5.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
              "ARC_FEED(10.0000, 5.0000, 10.0000, 6.0000, 1, 0.0000, 0.0, 0.0, 0.0)")  # fmt: skip
    np.testing.assert_allclose(p.end[0], [(10 * c - 5 * s) * 1e-3, (10 * s + 5 * c) * 1e-3, 0],
                               rtol=1e-12)  # fmt: skip
    np.testing.assert_allclose(p.centre[1][:2], [(10 * c - 6 * s) * 1e-3,
                                                 (10 * s + 6 * c) * 1e-3], rtol=1e-12)  # fmt: skip
    assert p.sweep[1] == pytest.approx(2 * math.pi, rel=1e-12)
    # Out of the XY plane a rotated arc is refused.
    error = _refused(
        "SET_XY_ROTATION(30.0000)",
        "SET_FEED_RATE(100.0000)",
        "SELECT_PLANE(CANON_PLANE_XZ)",
        "ARC_FEED(0.0000, 2.0000, 0.0000, 1.0000, 1, 0.0000, 0.0, 0.0, 0.0)",
    )
    assert "XY rotation" in error.allowed


def test_offsets_given_without_rotary_values_turn_nothing() -> None:
    p = _rows("SET_G5X_OFFSET(1, 1.0000, 0.0000, 0.0000)",
              "SET_G92_OFFSET(0.0000, 1.0000, 0.0000)",
              "USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 1.0000)",
              "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)")  # fmt: skip
    np.testing.assert_allclose(p.end[0], [0.001, 0.001, 0.001], rtol=1e-15)


def test_feeds_per_revolution_and_rotary_feeds_need_positive_values() -> None:
    for commands in [
        ("SET_FEED_MODE(0, 1)", "SET_FEED_RATE(0.2000)"),  # no spindle speed
        ("SET_SPINDLE_SPEED(0, 600.0000)", "SET_FEED_MODE(0, 1)", "SET_FEED_RATE(0.0000)"),
        ("SET_FEED_RATE(0.0000)",),
        ("SET_SPINDLE_SPEED(0, 600.0000)", "SET_SPINDLE_MODE(0 2000.0000)",
         "SET_FEED_MODE(0, 1)", "SET_FEED_RATE(0.2000)"),  # G96: the speed varies
    ]:  # fmt: skip
        _refused(*commands, "STRAIGHT_FEED(0.0000, 0.0000, -5.0000, 0.0000, 0.0000, 0.0000)")
    error = _refused("SET_FEED_RATE(0.0000)",
                     "STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 90.0000, 0.0000, 0.0000)",
                     rotary="A")  # fmt: skip
    assert "feed > 0" in error.allowed
    # G96 switched off again (SET_SPINDLE_MODE(0 0)) and G94: a feed per minute.
    p = _rows("SET_SPINDLE_SPEED(0, 600.0000)", "SET_SPINDLE_MODE(0 2000.0000)",
              "SET_SPINDLE_MODE(0 0.0000)", "SET_FEED_MODE(0, 1)", "SET_FEED_RATE(0.2000)",
              "STRAIGHT_FEED(0.0000, 0.0000, -5.0000, 0.0000, 0.0000, 0.0000)")  # fmt: skip
    assert p.feed[0] == pytest.approx(0.2e-3 * 10.0, rel=1e-12)  # 0.2 mm x 10 rev/s
    error = _refused("SET_FEED_MODE()", "STRAIGHT_FEED(0.0000, 0.0000, -5.0, 0.0, 0.0, 0.0)")
    assert "finite numbers" in error.allowed


def test_a_block_number_of_the_file_carries_the_line_before_it() -> None:
    # A line too long for the mark keeps its own N word (here N5): its commands carry the
    # line of the block before.
    output = [*_canon("SET_FEED_RATE(100.0000)", line=3),
              "    2 N5 STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)"]  # fmt: skip
    rows, _, _, _ = _blocks(output, ["a", "b", "c", "d"], None)
    assert [r[1] for r in rows] == [3]


def test_the_block_bound_is_inclusive() -> None:
    moves = [f"STRAIGHT_TRAVERSE({k}.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)"
             for k in (1, 2)]  # fmt: skip
    assert _rows(*moves, max_blocks=2).size == 2
    with pytest.raises(BallScrewInputError, match="at most 1 blocks"):
        _rows(*moves, max_blocks=1)


def test_the_interpreters_complaint_and_its_line() -> None:
    lines = ["G21", "G1 X1", "G2 X3"]
    error = _refusal(f"executing\nbad arc\nN{LINE_MARK + 3} G2 X3\n", lines, 1)
    assert (error.field, error.value) == ("program line 3", "G2 X3")
    assert error.allowed.endswith("rs274 says: bad arc")
    # No line named: the last one read.
    assert _refusal("bad arc\n", lines, 2).field == "program line 2"


def test_line_lengths_at_rs274s_limit_of_252_characters() -> None:
    mark = f"N{LINE_MARK + 1} "
    fits = "G1 X1 (" + "a" * (252 - len(mark) - 8) + ")"
    assert _marked(fits).splitlines() == [mark + fits]  # 252 characters marked
    longest = "G1 X1 (" + "a" * (252 - 8) + ")"  # 252 characters: kept
    assert _marked(longest).splitlines() == [longest]
    past = longest + " "  # 253: rs274 refuses it either way; marked, the refusal names it
    assert _marked(past).splitlines() == [mark + past]


def test_a_reversal_at_a_corner_is_at_the_corners_instant() -> None:
    # X turns back where two lines meet (100, 100 mm): its speed jumps there from +v to -v
    # between two samples of one instant; the reversal is that instant, at 100 mm.
    vmc = load_machine(Path(__file__).resolve().parents[2] / "examples" / "machine_vmc.toml")
    r = run_program(vmc, "G64 P0.5\nG1 X100 Y100 F3000\nG1 X0 Y200\nM30\n")
    (rev,) = r.axes["X"].reversals
    t, x = r.motion.time, r.motion.position[:, 0]
    corner = float(t[np.flatnonzero(x >= 0.1 - 1e-15)[0]])
    assert rev.position == pytest.approx(0.1, abs=1e-12)
    assert rev.time == pytest.approx(corner, abs=1e-12)
    assert rev.line == 3


def test_a_reversal_near_the_far_support(out_and_back: tuple[Machine, ProgramResult]) -> None:
    # At 690 mm the nut is 550 + 390 = 940 mm from the thrust bearing of the 1100 mm span.
    machine, _ = out_and_back
    (rev,) = run_program(machine, "G1 X690 F6000\nG1 X600\nM30\n").axes["X"].reversals
    screw = machine.axes["X"].case.screw
    k = 1.0 / (1.0 / _shaft_k(screw, 0.94) + 1.0 / design_nut_stiffness(screw, 0.0))
    assert rev.position == pytest.approx(0.69, abs=1e-12)
    assert rev.stiffness == pytest.approx(k, rel=1e-12)


def test_the_load_of_a_reversal_right_after_the_start(
    out_and_back: tuple[Machine, ProgramResult],
) -> None:
    # 1 um out and back at rapid: the reversal comes 8.6 ms after the start, within the
    # 20 ms window. Before the start the axis stood unloaded, so the window's mean force is
    # the momentum gained over the window: m (v_b - 0) / 20 ms, with v_b the speed at the
    # last moving sample; after the stop likewise m (0 - v_a) / 20 ms. Exact (1e-9): the
    # acceleration is linear between samples, its trapezoidal integral the speed.
    machine, _ = out_and_back
    r = run_program(machine, "G0 X0.001\nG0 X0\nM30\n")
    (rev,) = r.axes["X"].reversals
    t, v = r.motion.time, r.motion.velocity[:, 0]
    moving = np.flatnonzero(np.abs(v) > 0.0)
    v_b = v[moving[moving < np.searchsorted(t, rev.time)][-1]]
    v_a = v[moving[moving >= np.searchsorted(t, rev.time, side="right")][0]]
    assert rev.time < 0.02
    assert rev.load_before == pytest.approx(MASS * v_b / 0.02, rel=1e-9)
    assert rev.load_after == pytest.approx(MASS * -v_a / 0.02, rel=1e-9)


def test_an_arc_bulging_past_the_travel_names_its_first_sample_in_millimetres(
    tmp_path: Path,
) -> None:
    # G3 from (-90, 300) about (-90, 285) mm to (-90, 270): its left side reaches X -105 mm,
    # past the travel's -100 mm, though both its ends are inside.
    machine = _machine(tmp_path, force="0 N", letters="XY")
    text = "G1 X-90 Y300 F1000\nG3 X-90 Y270 I0 J-15\nM30\n"
    motion = plan(read_program(text), _limits(machine, read_program(text)))
    x = motion.position[:, 0]
    first = float(x[np.flatnonzero(x < -0.1 - 1e-9)[0]])
    assert -0.105 <= first < -0.1
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, text)
    assert (info.value.field, info.value.value) == ("program line 2", f"X{first * 1e3:.4g} mm")
    assert info.value.allowed == "within axes.X.travel, -100 to 700 mm"


@pytest.mark.parametrize(
    ("letters", "text", "missing"),
    [
        ("Y", "G1 Y10 F1000\nG2 X0 Y10 I5 J0\n", "X"),  # in the XY plane
        ("Z", "G1 Z10 F1000\nG18 G2 X0 Z10 I5 K0\n", "X"),  # in the ZX plane
        ("XY", "G1 Y10 F1000\nG19 G2 Y10 Z0 J5 K0\n", "Z"),  # in the YZ plane
    ],
)
def test_a_full_circle_through_a_missing_axis_names_its_line(
    tmp_path: Path, letters: str, text: str, missing: str
) -> None:
    # The missing axis ends where it started, yet the circle moves it: its line is named.
    machine = _machine(tmp_path, force="0 N", letters=letters)
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, text)
    assert (info.value.field, info.value.value) == ("program line 2", missing)


def test_an_inch_modal_cycle_below_its_approach_plane_is_refused() -> None:
    # Z0.05 in is below RFP + SDIS = 0.1 in: RS274/NGC's G99 cycle would lift first.
    with pytest.raises(BallScrewInputError) as info:
        to_rs274("G70\nG0 Z0.05\nMCALL CYCLE81(0.1,0,0.1,-0.5)\nX1\n")
    assert (info.value.field, info.value.value) == ("program line 4", "X/Y")


def test_a_rotary_axis_alone_at_half_a_degree_a_minute() -> None:
    p = _rows(
        "SET_FEED_RATE(0.5000)",
        "STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 1.0000, 0.0000, 0.0000)",
        rotary="A",
    )
    assert p.feed[0] == pytest.approx(math.radians(0.5) / 60.0, rel=1e-12)


def test_a_command_of_a_called_file_before_any_program_line() -> None:
    # rs274 prints a command outside the program's marked lines with dots for its N word.
    with pytest.raises(BallScrewInputError) as info:
        _blocks(["    1 N..... NURBS_FEED(1.0000, 2.0000)"], ["G5"], None)
    assert info.value.field == "a subroutine file called after program line 1"


def test_the_readers_default_arc_tolerance_is_2_um() -> None:
    # G2 about (1, 0) mm from the origin to X2.0021: its end is 2.1 um off the 1 mm circle,
    # past the 2 um allowed (0.1 % of the radius is 1 um).
    with pytest.raises(BallScrewInputError):
        read_part_program("G21 G17 G2 X2.0021 Y0 I1 J0 F100\n", reader="builtin")
    assert read_part_program("G21 G17 G2 X2.0019 Y0 I1 J0 F100\n", reader="builtin").program


@pytest.mark.skipif(shutil.which("rs274") is None, reason="no LinuxCNC rs274 on this machine")
def test_rs274_reads_past_a_byte_order_mark() -> None:
    p = read_program_rs274("\ufeffG21 G1 X1 F100\nM2\n")
    np.testing.assert_allclose(p.end[0], [0.001, 0.0, 0.0], atol=1e-12)


def test_the_tool_offsets_angle_adds_to_a_rotary_axis() -> None:
    # A tool offset of A 10 deg with G5x A 5 and G92 A 1: A0 in the program is 16 deg.
    p = _rows(
        "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 5.0000, 0.0000, 0.0000)",
        "SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 1.0000, 0.0000, 0.0000)",
        "USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 0.0000, 10.0000, 0.0000, 0.0000)",
        "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        rotary="A",
    )
    assert p.rotary_end is not None
    assert math.degrees(p.rotary_end[0, 0]) == pytest.approx(16.0, rel=1e-12)


def test_a_feed_per_revolution_at_30_rpm() -> None:
    # 0.5 rev/s x 0.2 mm: 0.1 mm/s.
    p = _rows("SET_SPINDLE_SPEED(0, 30.0000)", "SET_FEED_MODE(0, 1)", "SET_FEED_RATE(0.2000)",
              "STRAIGHT_FEED(0.0000, 0.0000, -5.0000, 0.0000, 0.0000, 0.0000)")  # fmt: skip
    assert p.feed[0] == pytest.approx(1e-4, rel=1e-12)
