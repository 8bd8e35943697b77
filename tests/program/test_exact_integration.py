"""Every axis's distance and process work against the program's geometry, on random programs."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.io.machine import load_machine
from ballscrew.program import read_program, run_program

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MACHINE = load_machine(EXAMPLES / "machine_vmc.toml")
FORCE = {k: a.process_force for k, a in MACHINE.axes.items()}


def _geometric_distances(text: str) -> tuple[np.ndarray, np.ndarray]:
    """Each axis's distance over the program and in its feed blocks, from the blocks' ends.

    Lines only: an axis moves one way along a line, its distance is |end - start|.
    """
    p = read_program(text)
    step = np.abs(p.end - p.start)
    feed = np.isin(p.kind, (1,))
    return step.sum(axis=0), step[feed].sum(axis=0)


def _trapezoid_of_speed(r: object, letter: str) -> float:
    ds = r.data  # type: ignore[attr-defined]
    v = np.abs(ds["velocity"].sel(axis=letter).values)
    return float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(ds["time"].values)))


def test_a_corner_at_speed_keeps_each_axis_on_its_own_block() -> None:
    # The reproducer: a 10 degree corner at 6 m/min. Y travels 52.9 mm; the
    # trapezoid across the junction gave 78.6 mm (the second block's Y speed in the
    # first block's cruise), and Y's process work and friction 49 % too much.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = run_program(MACHINE, "G1 X300 Y0 F6000\nG1 X600 Y52.9\nM30\n")
    assert r.motion.entry_speed[1] > 0.01  # the corner is taken at speed
    y = r.axes["Y"]
    assert y.distance == pytest.approx(0.0529, rel=1e-12)
    assert y.process_work == pytest.approx(600.0 * 0.0529, rel=1e-12)
    # The samples' own trapezoid (what a reader of the CSV computes) here too: both blocks
    # reach the acceleration, so their jerk phases come in pairs of +j and -j of one length
    # and sample count, whose rule errors cancel (not so on a move too short for that).
    assert _trapezoid_of_speed(r, "Y") == pytest.approx(0.0529, rel=1e-9)
    # The junction has two samples at one time: the first block's end, the second's start.
    t = r.motion.time
    junction = np.flatnonzero(np.diff(r.motion.block) != 0)
    assert junction.size == 1 and t[junction[0]] == t[junction[0] + 1]
    assert r.motion.velocity[junction[0], 1] == 0.0 < r.motion.velocity[junction[0] + 1, 1]


points = st.tuples(st.integers(0, 600), st.integers(0, 400), st.integers(-300, 0))


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.tuples(points, st.booleans()), min_size=2, max_size=10),
    st.integers(1000, 20_000),
)
def test_process_work_is_force_times_distance_on_random_polylines(
    pts: list[tuple[tuple[int, int, int], bool]], feed: int
) -> None:
    # Random polylines within the example machine's travel, at feeds up to 20 m/min (the
    # corners within 0.02 mm are taken at speed), some blocks rapid (no process force).
    text = f"F{feed}\n" + "".join(
        f"{'G0' if rapid else 'G1'} X{x} Y{y} Z{z}\n" for (x, y, z), rapid in pts
    )
    total, fed = _geometric_distances(text)
    if not total.any():
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = run_program(MACHINE, text)
    for i, letter in enumerate("XYZ"):
        a = r.axes[letter]
        # 1e-9 of the distance (and 1 nm): the positions' rounding over up to 10 blocks.
        assert a.distance == pytest.approx(total[i], rel=1e-9, abs=1e-12)
        assert a.process_work == pytest.approx(FORCE[letter] * fed[i], rel=1e-6, abs=1e-9)


def _arc_distance(centre: tuple[float, float], start: tuple[float, float], sweep: float
                  ) -> np.ndarray:  # fmt: skip
    """X and Y distance along an arc from a million points of the circle (chords)."""
    theta0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    r = math.hypot(start[0] - centre[0], start[1] - centre[1])
    theta = theta0 + np.linspace(0.0, sweep, 1_000_001)
    xy = np.stack([centre[0] + r * np.cos(theta), centre[1] + r * np.sin(theta)], axis=1)
    result: np.ndarray = np.abs(np.diff(xy, axis=0)).sum(axis=0)
    return result


@pytest.mark.parametrize(
    ("block", "centre", "start", "sweep"),
    [
        ("G2 X200 Y200 I50 J0", (250.0, 200.0), (200.0, 200.0), -2.0 * math.pi),
        ("G3 X280 Y240 I50 J0", (250.0, 200.0), (200.0, 200.0), None),
    ],
    ids=["full-circle-cw", "arc-ccw-past-two-turns"],
)  # fmt: skip
def test_an_arcs_axes_move_their_geometric_distance(
    block: str, centre: tuple[float, float], start: tuple[float, float], sweep: float | None
) -> None:
    if sweep is None:  # counter-clockwise from 180 deg to the end point's angle (past 270 deg)
        end = math.atan2(240.0 - 200.0, 280.0 - 250.0)
        sweep = end + 2.0 * math.pi - math.pi
    text = f"G1 X200 Y200 F3000\n{block}\nM30\n"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = run_program(MACHINE, text)
    arc = _arc_distance((centre[0] / 1e3, centre[1] / 1e3), (start[0] / 1e3, start[1] / 1e3),
                        sweep)  # fmt: skip
    line = np.array([0.2, 0.2])
    for i, letter in enumerate("XY"):
        a = r.axes[letter]
        # The million chords of the circle: short of the arc's distance by < 1e-11 relative.
        assert a.distance == pytest.approx(line[i] + arc[i], rel=1e-9)
        assert a.process_work == pytest.approx(600.0 * (line[i] + arc[i]), rel=1e-9)


@settings(max_examples=12, deadline=None)
@given(
    st.floats(300.0, 500.0), st.floats(200.0, 300.0), st.floats(10.0, 80.0),
    st.floats(-math.pi, math.pi), st.floats(0.1, 6.1), st.booleans(), st.integers(3000, 12_000),
)  # fmt: skip
def test_an_arcs_process_work_is_force_times_its_distance(
    cx: float, cy: float, radius: float, a0: float, sweep: float, ccw: bool, feed: int
) -> None:
    # A random arc (either way, up to 350 degrees, past up to four turns of X or Y) after
    # a rapid to its start: the rapid moves the axes without process force.
    a1 = a0 + (sweep if ccw else -sweep)
    sx, sy = round(cx + radius * math.cos(a0), 4), round(cy + radius * math.sin(a0), 4)
    ex, ey = round(cx + radius * math.cos(a1), 4), round(cy + radius * math.sin(a1), 4)
    i, j = round(cx - sx, 4), round(cy - sy, 4)
    text = (f"G0 X{sx:.4f} Y{sy:.4f}\nG{3 if ccw else 2} X{ex:.4f} Y{ey:.4f} I{i:.4f} "
            f"J{j:.4f} F{feed}\nM30\n")  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = run_program(MACHINE, text)
    centre = ((sx + i) / 1e3, (sy + j) / 1e3)
    start = (sx / 1e3, sy / 1e3)
    theta0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    theta1 = math.atan2(ey / 1e3 - centre[1], ex / 1e3 - centre[0])
    swept = (theta1 - theta0) % (2.0 * math.pi) if ccw else -((theta0 - theta1) % (2.0 * math.pi))
    arc = _arc_distance(centre, start, swept)
    for k, letter in enumerate("XY"):
        a = r.axes[letter]
        # The million chords are short by < 1e-11. The end point and the centre offsets,
        # each rounded to 0.0001 mm, put the end up to 0.14 um off the circle through the
        # start (the axes reach the end at the block's end): 1e-6, and 0.2 um.
        assert a.feed_distance == pytest.approx(arc[k], rel=1e-6, abs=2e-7)
        assert a.process_work == pytest.approx(600.0 * arc[k], rel=1e-6, abs=600.0 * 2e-7)
        assert a.distance == pytest.approx(start[k] + arc[k], rel=1e-6, abs=2e-7)
