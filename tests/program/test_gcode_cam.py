"""What CAM posts write: tool changes, offsets, drilling cycles, reference returns, dialects.

The drilling cycles are checked against moves expanded by hand from RS274/NGC's
definitions (NIST IR 6556, 2000, section 3.5.16; the LinuxCNC G-code reference),
written out below as numbers, not computed.
"""

from __future__ import annotations

import dataclasses
import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import Machine, load_machine, parse_machine
from ballscrew.program.gcode import ARC, DWELL, FEED, RAPID, Program, Skipped, read_program

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BACK = 0.254  # G73/G83 come back down to 0.010 in above the last depth [mm]

FANUC_POST = """\
%
O1000 (DRILL PLATE)
(T1 D8 DRILL)
N10 G21 G17 G40 G49 G80 G90
N20 T1 M6
N30 G0 G90 G54 X20. Y20. S3000 M3
N40 G43 H1 Z50. M8
N50 G81 G98 X20. Y20. R2. Z-10. F200.
N60 X40.
N70 X60. Y30.
N80 G80
N90 M5 M9
N100 G28 G91 Z0.
N110 M30
%
"""


@pytest.fixture(scope="module")
def vmc() -> Machine:
    return load_machine(EXAMPLES / "machine_vmc.toml")


@pytest.fixture(scope="module")
def fixture_machine(vmc: Machine) -> Machine:
    """The example machine with its G54 on a part: X 100, Y 100, Z -380 mm."""
    return dataclasses.replace(vmc, offsets={54: {"X": 0.1, "Y": 0.1, "Z": -0.38}})


def moves(p: Program) -> list[tuple[int, int, list[float]]]:
    """(kind, line, end in mm) of each block, rounded to the picometre (the sums of mm
    converted to m differ from the decimal numbers by rounding only)."""
    return [
        (int(k), int(n), [round(float(v) * 1e3, 9) + 0.0 for v in e])
        for k, n, e in zip(p.kind, p.line, p.end, strict=True)
    ]


def same(p: Program, expected: list[tuple[int, int, list[float]]]) -> None:
    got = moves(p)
    assert [g[:2] for g in got] == [e[:2] for e in expected]
    np.testing.assert_allclose([g[2] for g in got], [e[2] for e in expected], atol=1e-9)


def test_the_fanuc_post_reads_as_hand_expanded(fixture_machine: Machine) -> None:
    p = read_program(FANUC_POST, machine=fixture_machine)
    # G54: X, Y + 100 mm; Z - 380 mm, and + 95 mm of T1 once G43 H1 is on: Z - 285 mm.
    # G81 G98 from Z50 (-235): R2 is -283, Z-10 is -295, out to the starting height -235.
    z0, r, bottom = -235.0, -283.0, -295.0
    expected = [
        (DWELL, 5, [0.0, 0.0, 0.0]),  # T1 M6: the tool change time, axes still
        (RAPID, 6, [120.0, 120.0, 0.0]),
        (RAPID, 7, [120.0, 120.0, z0]),
        # first hole: already over it, so no XY move
        (RAPID, 8, [120.0, 120.0, r]), (FEED, 8, [120.0, 120.0, bottom]),
        (RAPID, 8, [120.0, 120.0, z0]),
        (RAPID, 9, [140.0, 120.0, z0]), (RAPID, 9, [140.0, 120.0, r]),
        (FEED, 9, [140.0, 120.0, bottom]), (RAPID, 9, [140.0, 120.0, z0]),
        (RAPID, 10, [160.0, 130.0, z0]), (RAPID, 10, [160.0, 130.0, r]),
        (FEED, 10, [160.0, 130.0, bottom]), (RAPID, 10, [160.0, 130.0, z0]),
        # G28 G91 Z0: the intermediate point is where Z is; then Z to the reference, 0
        (RAPID, 13, [160.0, 130.0, 0.0]),
    ]  # fmt: skip
    same(p, expected)
    assert p.dwell[0] == 4.0  # machine.tool_change_time of the example
    assert p.feed[4] == pytest.approx(200e-3 / 60.0)
    # Every word not run is kept with its line.
    assert set(p.skipped) == {
        Skipped("%", 1), Skipped("O", 2), Skipped("G40", 4), Skipped("S", 6), Skipped("M3", 6),
        Skipped("M8", 7), Skipped("M5", 12), Skipped("M9", 12), Skipped("%", 15),
    }  # fmt: skip
    # The cycle's moves stop at every corner (exact path), the others blend.
    assert np.all(p.tolerance[3:14] == 0.0) and np.isnan(p.tolerance[1])  # type: ignore[index]


def test_the_fanuc_post_runs_as_written(fixture_machine: Machine) -> None:
    from ballscrew.program import run_program

    r = run_program(fixture_machine, FANUC_POST)
    # The tool change and the rapids and feeds: at least the tool change plus the drilling
    # at 200 mm/min (3 x 12 mm down, 3.6 s each at least).
    assert r.motion.duration > 4.0 + 3 * 12.0 / (200.0 / 60.0)
    z = r.motion.position[:, 2]
    assert z.min() == pytest.approx(-0.295) and z[-1] == pytest.approx(0.0)


def test_peck_cycles_with_g99_and_g98_as_hand_expanded() -> None:
    p = read_program(
        "G21 G90 G17\nG0 X10 Y10 Z20\nG99 G83 X10 Y10 R2 Z-7 Q3 F120\nX20\n"
        "G98 G81 X30 R2 Z-5\nG80\nG0 Z30\nG99 G73 X40 Y10 R1 Z-4 Q2.5 F100\nG80\nM30\n"
    )
    expected = [
        (RAPID, 2, [10.0, 10.0, 20.0]),
        # G83 under G99: down to R, then pecks of 3 mm: -1, -4, then the bottom -7. After
        # each peck up to R (2), back down to 0.254 mm above the last depth.
        (RAPID, 3, [10.0, 10.0, 2.0]),
        (FEED, 3, [10.0, 10.0, -1.0]), (RAPID, 3, [10.0, 10.0, 2.0]),
        (RAPID, 3, [10.0, 10.0, -1.0 + BACK]),
        (FEED, 3, [10.0, 10.0, -4.0]), (RAPID, 3, [10.0, 10.0, 2.0]),
        (RAPID, 3, [10.0, 10.0, -4.0 + BACK]),
        (FEED, 3, [10.0, 10.0, -7.0]), (RAPID, 3, [10.0, 10.0, 2.0]),  # out to R (G99)
        # The modal repeat at X20: over at the R height, then the same pecks.
        (RAPID, 4, [20.0, 10.0, 2.0]),
        (FEED, 4, [20.0, 10.0, -1.0]), (RAPID, 4, [20.0, 10.0, 2.0]),
        (RAPID, 4, [20.0, 10.0, -1.0 + BACK]),
        (FEED, 4, [20.0, 10.0, -4.0]), (RAPID, 4, [20.0, 10.0, 2.0]),
        (RAPID, 4, [20.0, 10.0, -4.0 + BACK]),
        (FEED, 4, [20.0, 10.0, -7.0]), (RAPID, 4, [20.0, 10.0, 2.0]),
        # G98 G81: over at R's height, drill, out to where the series began, Z20.
        (RAPID, 5, [30.0, 10.0, 2.0]), (FEED, 5, [30.0, 10.0, -5.0]),
        (RAPID, 5, [30.0, 10.0, 20.0]),
        (RAPID, 7, [30.0, 10.0, 30.0]),
        # G73 under G99 from Z30: pecks of 2.5 mm from R1: -1.5, back off 0.254 mm, -4.
        (RAPID, 8, [40.0, 10.0, 30.0]), (RAPID, 8, [40.0, 10.0, 1.0]),
        (FEED, 8, [40.0, 10.0, -1.5]), (RAPID, 8, [40.0, 10.0, -1.5 + BACK]),
        (FEED, 8, [40.0, 10.0, -4.0]), (RAPID, 8, [40.0, 10.0, 1.0]),
    ]  # fmt: skip
    same(p, expected)


def test_dwell_and_feed_out_cycles_and_repeats() -> None:
    p = read_program(
        "G21 G90 G0 X0 Y0 Z5\nG98 G82 X5 R1 Z-3 P0.5 F60\nG85 X10 R1 Z-3\nG89 X15 R1 Z-3 P2\n"
        "G80 G91\nG99 G81 X10 R-4 Z-3 L2\nM30\n"
    )
    expected = [
        (RAPID, 1, [0.0, 0.0, 5.0]),
        # G82: feed to the bottom, dwell 0.5 s, rapid out to the start height (G98).
        (RAPID, 2, [5.0, 0.0, 5.0]), (RAPID, 2, [5.0, 0.0, 1.0]), (FEED, 2, [5.0, 0.0, -3.0]),
        (DWELL, 2, [5.0, 0.0, -3.0]), (RAPID, 2, [5.0, 0.0, 5.0]),
        # G85: feed down, feed back to R, rapid to the start height.
        (RAPID, 3, [10.0, 0.0, 5.0]), (RAPID, 3, [10.0, 0.0, 1.0]),
        (FEED, 3, [10.0, 0.0, -3.0]), (FEED, 3, [10.0, 0.0, 1.0]), (RAPID, 3, [10.0, 0.0, 5.0]),
        # G89: feed down, dwell 2 s, feed out.
        (RAPID, 4, [15.0, 0.0, 5.0]), (RAPID, 4, [15.0, 0.0, 1.0]),
        (FEED, 4, [15.0, 0.0, -3.0]), (DWELL, 4, [15.0, 0.0, -3.0]),
        (FEED, 4, [15.0, 0.0, 5.0]),
        # G91 G81 L2 from Z5: R 4 mm below the start (1), Z 3 mm below R (-2); X steps 10.
        (RAPID, 6, [25.0, 0.0, 5.0]), (RAPID, 6, [25.0, 0.0, 1.0]),
        (FEED, 6, [25.0, 0.0, -2.0]), (RAPID, 6, [25.0, 0.0, 1.0]),
        (RAPID, 6, [35.0, 0.0, 1.0]), (FEED, 6, [35.0, 0.0, -2.0]), (RAPID, 6, [35.0, 0.0, 1.0]),
    ]  # fmt: skip
    same(p, expected)
    assert p.dwell[p.kind == DWELL].tolist() == [0.5, 2.0]


def test_a_cycle_below_r_goes_up_first_and_needs_its_words() -> None:
    p = read_program("G0 X0 Y0 Z-5\nG81 X3 R2 Z-8 F100\nM30\n")
    same(p, [(RAPID, 1, [0.0, 0.0, -5.0]), (RAPID, 2, [0.0, 0.0, 2.0]),
             (RAPID, 2, [3.0, 0.0, 2.0]), (FEED, 2, [3.0, 0.0, -8.0]),
             (RAPID, 2, [3.0, 0.0, 2.0])])  # fmt: skip
    for text, word in (
        ("G0 Z5\nG81 X3 Z-8 F100\n", "R"),  # no R in the first block
        ("G0 Z5\nG83 X3 R2 Z-8 F100\n", "Q"),  # a peck cycle without Q
        ("G0 Z5\nG81 X3 R-9 Z-8 F100\n", "R-9"),  # R below the bottom
        ("G0 Z5\nG18 G81 X3 R2 Z-8 F100\n", "G81"),  # not in G17
    ):
        with pytest.raises(BallScrewInputError) as info:
            read_program(text)
        assert info.value.field == "program line 2"
        assert word in str(info.value.value) + info.value.allowed


def test_work_offsets_tool_lengths_and_machine_coordinates(vmc: Machine) -> None:
    body = "G0 X10 Y20 Z30\nG43 H2 Z30\nG53 G0 Z-5\nG49 G91 G0 X1\nM30\n"
    p54 = read_program("G54\n" + body, machine=vmc)
    p55 = read_program("G55\n" + body, machine=vmc)
    # G55 is (250, 150, -420) mm from G54 (the machine's zero) in the example machine.
    assert moves(p54)[0][2] == [10.0, 20.0, 30.0]
    assert moves(p55)[0][2] == [260.0, 170.0, -390.0]
    # G43 H2 lifts the spindle by T2's 110 mm for the same tip position.
    assert moves(p55)[1][2] == [260.0, 170.0, -280.0]
    # G53: Z in machine coordinates whatever the offsets; then G91 moves by the increment.
    assert moves(p54)[2][2] == [10.0, 20.0, -5.0]
    assert moves(p55)[2][2] == [260.0, 170.0, -5.0]
    assert moves(p55)[3][2] == [261.0, 170.0, -5.0]
    for text, word in (
        ("G56\nG0 X1\n", "G56"),  # no [offsets] G56
        ("G43 H7 Z5\n", "H7"),  # no T7 in [tools]
        ("G0 X1\nG91 G53 X1\n", "G53"),  # G53 is absolute
        ("G0 X1\nG53 G2 X1 I1\n", "G53"),  # G53 moves G0 or G1 only
    ):
        with pytest.raises(BallScrewInputError) as info:
            read_program(text, machine=vmc)
        assert word in str(info.value.value)


def test_g28_and_g30_go_through_their_intermediate_point(vmc: Machine) -> None:
    p = read_program("G0 X100 Y100 Z-50\nG28 X50\nG30\nG28\nM30\n", machine=vmc)
    assert moves(p) == [
        (RAPID, 1, [100.0, 100.0, -50.0]),
        (RAPID, 2, [50.0, 100.0, -50.0]),  # the intermediate point, X only
        (RAPID, 2, [0.0, 100.0, -50.0]),  # X alone to G28's reference
        (RAPID, 3, [400.0, 480.0, 0.0]),  # no axis words: every axis to G30's
        (RAPID, 4, [0.0, 0.0, 0.0]),
    ]
    with pytest.raises(BallScrewInputError) as info:
        read_program("G28 Z0\n")  # no machine file: no reference position
    assert "[reference] G28" in info.value.allowed
    with pytest.raises(BallScrewInputError) as info:
        read_program("G28 G0 Z0\n", machine=vmc)  # two codes using the axis words
    assert info.value.value == "G28 G0"


@pytest.mark.parametrize(
    ("line", "both"),
    [("G0 G1 X10", "G0 G1"), ("G90 G91 X1", "G90 G91"), ("G17 G18", "G17 G18"),
     ("G4 P1 G28", "G4 G28"), ("M3 M5", "M3 M5"), ("G81 G0 X1", "G81 G0"),
     ("G1 X1 X2 F10", "X1 X2")],
)  # fmt: skip
def test_two_codes_of_one_modal_group_are_refused_naming_both(line: str, both: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        read_program(f"G0 X0\n{line}\n")
    assert info.value.field == "program line 2"
    assert info.value.value == both


def test_fanuc_dwell_in_milliseconds_rs274_in_seconds_with_a_note(vmc: Machine) -> None:
    fanuc = dataclasses.replace(vmc, dialect="fanuc")
    p = read_program("G4 P1500\nG4 X2.5\nG98 G82 X1 R1 Z-1 P250 F100\nM30\n", machine=fanuc)
    assert p.dwell[p.kind == DWELL].tolist() == [1.5, 2.5, 0.25]
    with pytest.raises(BallScrewInputError) as info:
        read_program("G4 P1.5\n", machine=fanuc)  # Fanuc's P is a whole number of ms
    assert "milliseconds" in info.value.allowed
    q = read_program("G4 P1500\nM30\n")
    assert q.dwell.tolist() == [1500.0]
    note = next(n for n in q.notes if "G4 P1500" in n)
    assert "1500 s" in note and "line 1" in note and "1.5 s" in note and "fanuc" in note
    cycle = read_program("G0 Z5\nG82 X1 R1 Z-1 P250 F100\nM30\n")  # 250 s: told
    assert any("G82 P250 (line 2): a dwell of 250 s" in n for n in cycle.notes)
    with pytest.raises(BallScrewInputError) as info:
        read_program("G4 X2\n")  # Fanuc's X for a dwell, in the RS274 dialect
    assert "fanuc" in info.value.allowed


def test_a_byte_order_mark_is_read(tmp_path: Path, vmc: Machine) -> None:
    nc = tmp_path / "bom.nc"
    nc.write_bytes("G21 G90\nG0 X10 Y10\nM30\n".encode("utf-8-sig"))
    from ballscrew.io.files import read_input_text

    p = read_program(read_input_text("PROGRAM", nc), machine=vmc)
    assert moves(p) == [(RAPID, 2, [10.0, 10.0, 0.0])]
    assert any("byte-order mark" in n for n in p.notes)


def test_g61_stops_at_corners_and_g64_p_sets_the_blend() -> None:
    from ballscrew.program.planner import Limits, plan

    lim = Limits(np.full(3, 0.5), np.full(3, 2.0), np.full(3, 50.0), 0.5, 1e-5)
    corner = "G1 X100 Y0 F6000\nG1 X100 Y100\nG1 X0 Y100\nM30\n"
    g61 = plan(read_program("G61\n" + corner), lim)
    assert g61.entry_speed[1] == 0.0 and g61.entry_speed[2] == 0.0
    for text, delta in (("", 1e-5), ("G64 P0.05\n", 5e-5), ("G64\n", 1e-5)):
        m = plan(read_program(text + corner), lim)
        # A 90-degree corner: blend radius r = delta sin45/(1 - sin45); along the blend's
        # direction (1, 1)/sqrt2 each axis sees a/cos45, so v = min(sqrt(a r/cos45),
        # (j r^2/cos45)^(1/3)), kept 1e-7 inside by the look-ahead's margin.
        s = math.sin(math.pi / 4)
        r = delta * s / (1 - s)
        v = min(math.sqrt(2.0 / s * r), (50.0 / s * r * r) ** (1 / 3))
        assert m.entry_speed[1] == pytest.approx(v, rel=1e-6)


def test_g90_1_centres_are_absolute(vmc: Machine) -> None:
    a = read_program("G55 G1 X10 Y0 F100\nG91.1 G3 X0 Y10 I-10 J0\nM30\n", machine=vmc)
    b = read_program("G55 G1 X10 Y0 F100\nG90.1 G3 X0 Y10 I0 J0\nM30\n", machine=vmc)
    assert b.kind[1] == ARC
    np.testing.assert_allclose(b.centre[1, :2], [0.25, 0.15], atol=1e-15)  # G55's zero
    np.testing.assert_allclose(a.centre, b.centre, atol=1e-15)


def test_m6_needs_a_tool_change_time_and_g43_a_tool(vmc: Machine) -> None:
    bare = dataclasses.replace(vmc, tool_change_time=None)
    with pytest.raises(BallScrewInputError) as info:
        read_program("T1 M6\n", machine=bare)
    assert info.value.value == "M6" and "tool_change_time" in info.value.allowed
    # G43 without H takes the tool M6 loaded.
    p = read_program("T2 M6\nG43 G0 Z10\nM30\n", machine=vmc)
    assert moves(p)[-1][2] == [0.0, 0.0, 120.0]
    with pytest.raises(BallScrewInputError):
        read_program("G43 G0 Z10\n", machine=vmc)


def test_machine_file_keys_are_checked() -> None:
    text = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    folder = EXAMPLES
    for old, new, key in (
        ('dialect = "rs274"', 'dialect = "heidenhain"', "machine.dialect"),
        ('T1 = { value = "95 mm"', 'X1 = { value = "95 mm"', "tools.X1"),
        ('G55 = { X = "250 mm", Y = "150 mm", Z = "-420 mm" }',
         'G55 = { X = "250 mm", Y = "150 mm" }', "offsets.G55.Z"),
        ('G30 = { X = "400 mm"', 'G30 = { X = "900 mm"', "reference.G30.X"),
        ('tool_change_time = { value = "4 s"', 'tool_change_time = { value = "-4 s"',
         "machine.tool_change_time"),
    ):  # fmt: skip
        assert old in text
        with pytest.raises(BallScrewInputError) as info:
            parse_machine(text.replace(old, new), folder=folder)
        assert info.value.field == key


def test_sinumerik_dispatch_refuses_clearly_without_the_translation(
    vmc: Machine, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "ballscrew.program.sinumerik", None)
    with pytest.raises(BallScrewInputError) as info:
        read_program("G0 X1\n", machine=dataclasses.replace(vmc, dialect="sinumerik"))
    assert info.value.field == "machine.dialect"


def test_sinumerik_programs_are_translated_line_for_line(vmc: Machine) -> None:
    pytest.importorskip("ballscrew.program.sinumerik")
    siemens = dataclasses.replace(vmc, dialect="sinumerik")
    p = read_program("G710 G90\nG0 X10 Y20 ; rapid\nM30\n", machine=siemens)
    assert moves(p) == [(RAPID, 2, [10.0, 20.0, 0.0])]


def test_what_posts_write_besides_is_skipped_with_its_line(vmc: Machine) -> None:
    fanuc = dataclasses.replace(vmc, dialect="fanuc")
    # Mastercam's posts start with G00 ... G80: two motion codes for RS274/NGC, while Fanuc
    # puts G80 in a group of its own.
    text = "G00 G17 G40 G49 G80 G90 G15 G69 G50.1\nG97 S2000 M3\nM19\nX1\nM30\n"
    p = read_program(text, machine=fanuc)
    assert moves(p) == [(RAPID, 4, [1.0, 0.0, 0.0])]
    assert {(s.word, s.line) for s in p.skipped} >= {
        ("G15", 1), ("G69", 1), ("G50.1", 1), ("G97", 2), ("M19", 3),
    }  # fmt: skip
    with pytest.raises(BallScrewInputError) as info:
        read_program(text, machine=vmc)
    assert info.value.value == "G00 G80" and "fanuc" in info.value.allowed
    for code in ("G16", "G68", "G51"):  # the modes themselves are refused
        with pytest.raises(BallScrewInputError):
            read_program(f"{code}\n", machine=vmc)
    # Fanuc's K repeats a cycle as L does.
    k = read_program("G0 Z5\nG91 G99 G81 X10 R-4 Z-3 K3 F100\nM30\n", machine=fanuc)
    l3 = read_program("G0 Z5\nG91 G99 G81 X10 R-4 Z-3 L3 F100\nM30\n", machine=vmc)
    np.testing.assert_array_equal(k.end, l3.end)
    assert k.end[:, 0].max() == pytest.approx(0.030)


_PIECES = [
    "G0", "G1", "G2", "G3", "G4", "G17", "G18", "G20", "G21", "G28", "G30", "G40", "G43",
    "G49", "G53", "G54", "G55", "G61", "G64", "G73", "G80", "G81", "G82", "G83", "G85", "G89",
    "G90", "G91", "G90.1", "G91.1", "G98", "G99", "G15", "G97", "X10", "X-4", "Y-5", "Z2",
    "Z-3", "A30", "I5", "J0", "R2", "R-1", "Q1", "P0.5", "P1500", "L2", "K2", "H1", "H0",
    "F200", "S1000", "T1", "M3", "M6", "M19", "M30", "N10", "(c)", ";c", "%", "O1",
]  # fmt: skip


@settings(max_examples=400, deadline=None)
@given(
    lines=st.lists(st.lists(st.sampled_from(_PIECES), max_size=5), max_size=10),
    dialect=st.sampled_from(["rs274", "fanuc"]),
)
def test_any_words_are_read_or_refused_naming_one_of_their_lines(
    lines: list[list[str]], dialect: str
) -> None:
    # Whatever a post writes: blocks, or a refusal naming a line of the text; never another
    # exception, and never a block from a line without a word that moves or waits.
    machine = dataclasses.replace(load_machine(EXAMPLES / "machine_vmc.toml"), dialect=dialect)
    text = "\n".join(" ".join(words) for words in lines)
    try:
        p = read_program(text, machine=machine)
    except BallScrewInputError as exc:
        assert exc.field.startswith("program line ")
        assert 1 <= int(exc.field.removeprefix("program line ")) <= len(lines)
        return
    movers = ("G", "X", "Y", "Z", "M6", "L", "K")
    for n in set(p.line.tolist()):
        assert any(w.startswith(movers) for w in lines[n - 1])
    assert np.all(np.isfinite(p.end)) and np.all(p.dwell >= 0.0)
