"""The reader's numbers pinned against independent ones, from program/gcode.py's mutation run.

Each expected value is written out from RS274/NGC's definitions (NIST IR 6556, 2000) or a
closed form of the circle (the chord of a half circle is 2R; a centre given by I/J is the
start plus the offsets; the end radius must equal the start's), not computed by the reader.
Positions are compared in mm rounded to the picometre: the sums of mm converted to m differ
from the decimal numbers by rounding only.
"""

from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.program.gcode import ARC, DWELL, FEED, RAPID, Program, Skipped, read_program


def machine(**given: Any) -> SimpleNamespace:
    """A machine file's reader data: RS274/NGC, no tools, offsets or references by default."""
    data: dict[str, Any] = {"dialect": "rs274", "tool_change_time": None, "tools": {},
                            "offsets": {}, "reference": {}, "rotary": {}}  # fmt: skip
    data.update(given)
    return SimpleNamespace(**data)


def ends_mm(p: Program) -> list[list[float]]:
    return [[round(v * 1000.0, 9) for v in row] for row in p.end]


def refused(text: str, **kwargs: Any) -> BallScrewInputError:
    with pytest.raises(BallScrewInputError) as info:
        read_program(text, **kwargs)
    return info.value


# -- arcs --------------------------------------------------------------------------------


def test_an_r_arc_whose_chord_is_2r_within_the_tolerance_is_a_half_circle() -> None:
    # Chord 10.001 mm with R5: over 2R by 1 um, within the 2 um arc tolerance; the centre
    # is the chord's midpoint and G2 sweeps -pi.
    p = read_program("G21 G17 G0 X0 Y0\nG2 X10.001 Y0 R5 F100\nM30\n")
    assert p.kind[-1] == ARC
    assert [round(v * 1000.0, 9) for v in p.centre[-1, :2]] == [5.0005, 0.0]
    assert p.sweep[-1] == pytest.approx(-math.pi, abs=1e-12)


def test_an_r_arc_shorter_than_half_its_chord_is_refused_naming_half_the_chord() -> None:
    # Chord 10.003 mm > 2 x 5 mm + 2 um: refused; half the chord is 5.0015 mm.
    error = refused("G21 G17 G0 X0 Y0\nG2 X10.003 Y0 R5 F100\nM30\n")
    assert error.value == "R5"
    assert error.allowed == "a radius of at least half the chord (5.0015)"


def test_the_half_circle_allowance_is_1e_9_of_the_diameter() -> None:
    # With no arc tolerance, a chord may pass 2R by 1e-9 relative (rounding of the end
    # points): 2R (1 + 0.5e-9) is read, 2R (1 + 1.05e-9) is refused (0.5e-11 m apart
    # from the limit at R = 5 mm, far above a double's 1e-18 m there).
    read_program("G21 G0 X0 Y0\nG2 X10.000000005 Y0 R5 F100\n", arc_tolerance=0.0)
    error = refused("G21 G0 X0 Y0\nG2 X10.0000000105 Y0 R5 F100\n", arc_tolerance=0.0)
    assert error.allowed.startswith("a radius of at least half the chord")


@pytest.mark.parametrize("arc", ["G2 X0 Y0 R5", "G2 X10 Y0 R0"])
def test_an_r_arc_without_two_end_points_or_a_radius_is_refused(arc: str) -> None:
    # A full circle cannot be given by R (RS274/NGC), nor an arc by R0.
    error = refused(f"G21 G0 X0 Y0\n{arc} F100\n")
    assert error.value == "R"
    assert error.allowed.startswith("an arc with distinct end points")


def test_absolute_centres_are_in_program_coordinates() -> None:
    # G90.1 under G55 (X +100, Y +200 mm): the centre I5 J-3 is the point (5, -3) of the
    # program, (105, 197) mm of the machine; from (15, -3) to (5, 7) counter-clockwise is a
    # quarter circle of 10 mm.
    m = machine(offsets={55: {"X": 0.1, "Y": 0.2, "Z": 0.0}})
    p = read_program("G21 G17 G55 G90.1 G0 X15 Y-3\nG3 X5 Y7 I5 J-3 F100\nM30\n", machine=m)
    assert [round(v * 1000.0, 9) for v in p.centre[-1, :2]] == [105.0, 197.0]
    assert ends_mm(p)[-1][:2] == [105.0, 207.0]
    assert p.sweep[-1] == pytest.approx(math.pi / 2, abs=1e-12)


@pytest.mark.parametrize(
    ("start", "arc"),
    [("X10 Y0", "G3 X0 Y10 I0"), ("X0 Y10", "G3 X-10 Y0 J0")],
)  # fmt: skip
def test_an_absolute_centre_word_left_out_is_0(start: str, arc: str) -> None:
    # RS274/NGC: a centre word not given is 0; G90.1 with I0 (J left out) is the centre
    # (0, 0): from (10, 0) to (0, 10) a quarter circle.
    p = read_program(f"G21 G17 G90.1 G0 {start}\n{arc} F100\nM30\n")
    assert [round(v * 1000.0, 9) for v in p.centre[-1, :2]] == [0.0, 0.0]
    assert p.sweep[-1] == pytest.approx(math.pi / 2, abs=1e-12)


@pytest.mark.parametrize(
    ("start", "arc"),
    [("X10 Y0", "G3 X0 Y10 I-10"), ("X0 Y10", "G3 X-10 Y0 J-10")],
)  # fmt: skip
def test_an_incremental_centre_word_left_out_is_0(start: str, arc: str) -> None:
    # G91.1 (the default): the centre is the start plus I, J; the one left out is 0.
    p = read_program(f"G21 G17 G0 {start}\n{arc} F100\nM30\n")
    assert [round(v * 1000.0, 9) for v in p.centre[-1, :2]] == [0.0, 0.0]
    assert p.sweep[-1] == pytest.approx(math.pi / 2, abs=1e-12)


def test_a_centre_on_the_start_point_is_refused_as_such() -> None:
    error = refused("G21 G0 X10 Y0\nG2 X0 Y10 I0 J0 F100\n")
    assert (error.value, error.allowed) == ("I/J/K", "a centre away from the start point")


def test_an_end_point_off_the_circle_is_refused_past_0_1_percent_of_the_radius() -> None:
    # R = 100 mm: 0.1 % is 0.1 mm (over the 2 um tolerance); the end at 100.105 mm from the
    # centre is refused, naming both radii and the tolerance; at 100.095 mm it is read.
    text = "G21 G17 G0 X100 Y0\nG3 X0 Y{} I-100 J0 F100\nM30\n"
    error = refused(text.format("100.105"))
    assert error.allowed == ("end point on the arc: radius 100.105 at the end, 100 at the "
                             "start (tolerance 0.1)")  # fmt: skip
    assert read_program(text.format("100.095")).kind[-1] == ARC


def test_below_2_mm_of_radius_the_arc_tolerance_is_2_um() -> None:
    # R = 1 mm: 0.1 % is 1 um, under the default arc tolerance of 2 um = 2e-6 m.
    text = "G21 G17 G0 X1 Y0\nG3 X0 Y{} I-1 J0 F100\nM30\n"
    assert refused(text.format("1.0021")).allowed.startswith("end point on the arc")
    assert read_program(text.format("1.0019")).kind[-1] == ARC


def test_an_arc_without_centre_or_its_plane_names_the_plane_s_words() -> None:
    error = refused("G21 G17 G0 X0 Y0\nG2 X10 F100\n")
    assert error.allowed == "I and/or J (the centre offsets in G17) or R"
    error = refused("G21 G17 G0 X0 Y0\nG2 X10 I5 K1 F100\n")
    assert (error.value, error.allowed) == ("K", "I, J in G17")


def test_a_g3_with_a_centre_and_no_axis_word_is_a_full_circle() -> None:
    p = read_program("G21 G17 G0 X10 Y0\nG3 I-10 F100\nM30\n")
    assert p.sweep[-1] == pytest.approx(2.0 * math.pi, abs=1e-12)
    assert ends_mm(p)[-1] == [10.0, 0.0, 0.0]


# -- canned cycles -----------------------------------------------------------------------


def test_an_incremental_cycle_repeats_its_step_from_where_it_starts() -> None:
    # RS274/NGC under G91: R is measured from the starting Z (5 - 3 = 2 mm), Z from R
    # (2 - 4 = -2 mm), and L3 drills three holes, each X2 Y1 from the last: from
    # (0.5, 0.25) the holes are at (2.5, 1.25), (4.5, 2.25), (6.5, 3.25); G98 clears to 5.
    p = read_program("G21 G90 G0 X0.5 Y0.25 Z5\nG91 G98 G81 X2 Y1 Z-4 R-3 L3 F100\nM30\n")
    expected = [[0.5, 0.25, 5.0]]
    for x, y in [(2.5, 1.25), (4.5, 2.25), (6.5, 3.25)]:
        expected += [[x, y, 5.0], [x, y, 2.0], [x, y, -2.0], [x, y, 5.0]]
    assert ends_mm(p) == expected
    assert "".join("RFAD"[k] for k in p.kind[1:]) == "RRFR" * 3


def test_an_incremental_cycle_s_axis_left_out_does_not_move() -> None:
    # X2 only: Y stays at 0.25 mm for both holes.
    p = read_program("G21 G90 G0 X0.5 Y0.25 Z5\nG91 G98 G81 X2 Z-4 R-3 L2 F100\nM30\n")
    assert [row[:2] for row in ends_mm(p)[1::4]] == [[2.5, 0.25], [4.5, 0.25]]


def test_g99_clears_to_r_and_r_may_equal_z() -> None:
    # G99: back to the R plane (1 mm), not the starting 5 mm.
    p = read_program("G21 G90 G0 X0 Y0 Z5\nG99 G81 X1 Y0 Z-3 R1 F100\nM30\n")
    assert ends_mm(p)[-1] == [1.0, 0.0, 1.0]
    # R at the bottom: the hole is drilled to R (the feed of no length is left out).
    p = read_program("G21 G90 G0 X0 Y0 Z5\nG98 G81 X1 Y0 Z-3 R-3 F100\nM30\n")
    assert ends_mm(p)[1:] == [[1.0, 0.0, 5.0], [1.0, 0.0, -3.0], [1.0, 0.0, 5.0]]


@pytest.mark.parametrize("code", ["G73", "G83"])
def test_a_peck_cycle_needs_a_peck_depth_above_0(code: str) -> None:
    error = refused(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 Q0 F100\n")
    assert (error.value, error.allowed) == ("Q0", "a peck depth Q > 0")
    error = refused(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 F100\n")
    assert error.allowed == f"Q in the cycle's first block ({code} needs Z, R, Q)"


@pytest.mark.parametrize("code", ["G82", "G89"])
def test_a_dwelling_cycle_needs_p_and_dwells_it(code: str) -> None:
    error = refused(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 F100\n")
    assert error.allowed == f"P in the cycle's first block ({code} needs Z, R, P)"
    p = read_program(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 P1.5 F100\nM30\n")
    assert list(p.dwell[p.kind == DWELL]) == [1.5]
    # P0 is a dwell of no time (read); over a minute it is noted, at a minute not.
    read_program(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 P0 F100\nM30\n")
    assert read_program(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 P60 F100\nM30\n").notes[1:] == ()
    assert "a dwell of 61 s at each hole" in "".join(
        read_program(f"G21 G0 X0 Y0 Z5\n{code} X1 Z-3 R1 P61 F100\nM30\n").notes
    )


def test_a_cycle_s_repeats_are_1_or_more() -> None:
    p = read_program("G21 G0 X0 Y0 Z5\nG98 G81 X1 Z-3 R1 L1 F100\nM30\n")
    assert p.size == 5
    error = refused("G21 G0 X0 Y0 Z5\nG98 G81 X1 Z-3 R1 L0 F100\n")
    assert (error.value, error.allowed) == ("L0", "a number of repeats L >= 1")


def test_a_cycle_outside_g17_or_without_axes_is_refused() -> None:
    error = refused("G21 G18 G0 X0 Y0 Z5\nG81 X1 Z-3 R1 F100\n")
    assert error.allowed == "a canned cycle in G17 (the XY plane)"
    error = refused("G21 G0 X0 Y0 Z5\nG81 R1 F100\n")
    assert (error.value, error.allowed) == ("G81", "X, Y or Z with a canned cycle")


# -- modal state, offsets, tools ---------------------------------------------------------


def test_g54_is_the_work_offset_at_the_start() -> None:
    # RS274/NGC starts in G54: its offset applies to a program that does not name it.
    m = machine(offsets={54: {"X": 0.1, "Y": 0.0, "Z": 0.0}})
    assert ends_mm(read_program("G21 G0 X10\nM30\n", machine=m)) == [[110.0, 0.0, 0.0]]


def test_a_tool_length_adds_to_z_until_g49_and_h0_is_none() -> None:
    # G43 H1 with a 50 mm tool: Z10 of the program is Z60 of the machine; G49 and G43 H0
    # cancel it.
    m = machine(tools={1: 0.05})
    text = "G21 G43 H1 G0 Z10\nG49 G0 X1 Z10\nG43 H1 G0 Z10\nG43 H0 G0 Z10\nM30\n"
    assert [row[2] for row in ends_mm(read_program(text, machine=m))] == [60.0, 10.0, 60.0, 10.0]


def test_g53_moves_in_machine_coordinates_with_g0_or_g1() -> None:
    m = machine(offsets={54: {"X": 0.1, "Y": 0.0, "Z": 0.0}})
    p = read_program("G21 G53 G0 X10\nG53 G1 X20 F100\nM30\n", machine=m)
    assert ends_mm(p) == [[10.0, 0.0, 0.0], [20.0, 0.0, 0.0]]
    assert list(p.kind) == [RAPID, FEED]


@pytest.mark.parametrize("code", ["G28", "G30"])
def test_a_reference_return_goes_to_the_machine_file_s_position(code: str) -> None:
    m = machine(reference={28: {"X": 0.0, "Y": 0.0, "Z": 0.5}, 30: {"X": 0.2, "Y": 0.3, "Z": 0.4}})
    p = read_program(f"G21 G0 X10 Y10 Z10\n{code}\nM30\n", machine=m)
    want = {"G28": [0.0, 0.0, 500.0], "G30": [200.0, 300.0, 400.0]}[code]
    assert ends_mm(p)[-1] == want and p.kind[-1] == RAPID
    error = refused(f"G21 {code} G0 X1\n", machine=m)
    assert (error.value, error.allowed) == (f"{code} G0", "one code using the axis words per block")


def test_path_modes_set_the_blending_tolerance() -> None:
    # G61: exact stop (0); G64 P0.01 mm: 1e-5 m; G64 P0.5: 5e-4 m; G64 P0: 0.
    text = "G21 G61 G0 X1\nG64 P0.01 G0 X2\nG64 P0.5 G0 X3\nG64 P0 G0 X4\nM30\n"
    tolerance = read_program(text).tolerance
    assert tolerance is not None
    assert list(tolerance) == pytest.approx([0.0, 1e-5, 5e-4, 0.0], abs=1e-15)


def test_a_feed_of_0_is_refused_and_t0_is_read() -> None:
    error = refused("G21 G1 X1 F0\n")
    assert error.allowed.startswith("a feed > 0")
    assert Skipped("T", 1) in read_program("T0 G0 X1\nM30\n").skipped


def test_the_codes_read_without_effect_are_listed_as_skipped() -> None:
    p = read_program("G21 G40 G97 G15 G69 G50.1 M8 G0 X1\nM9\nM30\n")
    words = [s.word for s in p.skipped]
    for word in ("G40", "G97", "G15", "G69", "G50.1", "M8", "M9"):
        assert word in words


def test_g80_after_a_motion_code_cancels_it_and_rs274_refuses_it_in_one_block() -> None:
    error = refused("G21 G80 G0 X1\n")
    assert error.allowed.endswith(
        '(Fanuc puts G80 in a group of its own: [machine] dialect = "fanuc")'
    )


@pytest.mark.parametrize("motion", ["G0 X1", "G1 X1", "G2 X2 I1", "G3 X2 I1"])
@pytest.mark.parametrize("order", [0, 1])
def test_fanuc_reads_g80_with_a_motion_code_as_that_motion(motion: str, order: int) -> None:
    code, rest = motion.split(" ", 1)
    pair = f"G80 {code}" if order == 0 else f"{code} G80"
    p = read_program(f"G21 G17 F100\n{pair} {rest}\nM30\n", machine=machine(dialect="fanuc"))
    kind = {"G0": RAPID, "G1": FEED, "G2": ARC, "G3": ARC}[code]
    assert list(p.kind) == [kind] and ends_mm(p)[-1][0] == float(rest.split()[0][1:])


def test_g80_with_an_axis_word_has_no_motion() -> None:
    error = refused("G21 G80 X1\n")
    assert error.allowed.startswith("a motion code (G0, G1, G2, G3 or a cycle)")
    error = refused("G21 G1 X1\n")
    assert error.value == "G1"


def test_a_fanuc_dwell_p_is_milliseconds() -> None:
    p = read_program("G4 P1500\nM30\n", machine=machine(dialect="fanuc"))
    assert list(p.dwell) == [1.5]


@pytest.mark.parametrize("text", ["G4 X1\n", "G4 P1 Y1\n"])
def test_a_g4_with_an_axis_word_is_refused_naming_it(text: str) -> None:
    error = refused(text)
    assert error.value == text.split()[-1]
    assert error.allowed.startswith("no axis words with G4 (Fanuc's G4 X<seconds>")


def test_a_g4_without_p_is_refused() -> None:
    error = refused("G4\n")
    assert (error.value, error.allowed) == ("G4", "G4 P<seconds>")
    error = refused("G4\n", machine=machine(dialect="fanuc"))
    assert error.allowed == "G4 P<seconds> or P<ms>, X<seconds>"


def test_m2_ends_the_program() -> None:
    p = read_program("G21 G0 X1\nM2\nG0 X2\n")
    assert p.size == 1 and any("after M2/M30" in note for note in p.notes)


def test_a_byte_order_mark_is_skipped() -> None:
    p = read_program("\ufeffG21 G0 X1\nM30\n")
    assert ends_mm(p) == [[1.0, 0.0, 0.0]]


def test_max_blocks_counts_the_blocks() -> None:
    read_program("G21 G0 X1\nG0 X2\nM30\n", max_blocks=2)
    error = refused("G21 G0 X1\nG0 X2\nG0 X3\nM30\n", max_blocks=2)
    assert error.value == "3 blocks"


# -- rotary axes -------------------------------------------------------------------------


def test_a_rotary_move_alone_reads_f_in_degrees_per_minute() -> None:
    # F360 deg/min = one turn a minute = 2 pi / 60 rad/s; G91 adds 90 deg twice: pi.
    m = machine(rotary={"A": None})
    p = read_program("G21 G91 G1 A90 F360\nA90\nG0 A-90\nM30\n", machine=m)
    assert p.feed[0] == pytest.approx(2.0 * math.pi / 60.0, rel=1e-15)
    assert p.rotary_end is not None
    assert list(p.rotary_end[:, 0]) == pytest.approx([math.pi / 2, math.pi, math.pi / 2], abs=1e-15)
    assert list(p.kind) == [FEED, FEED, RAPID]
    assert np.isnan(p.feed[2])


def test_a_cycle_s_moves_stop_exactly_and_start_below_r_by_going_up() -> None:
    # RS274/NGC: a cycle starting below R first goes straight up to R. Its moves are not
    # blended (path tolerance 0), whatever G64 says; the G0 before it has the machine's
    # (NaN).
    p = read_program("G21 G64 G90 G0 X0 Y0 Z-5\nG98 G81 X1 Y0 Z-3 R1 F100\nM30\n")
    assert ends_mm(p) == [[0.0, 0.0, -5.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0],
                          [1.0, 0.0, -3.0], [1.0, 0.0, 1.0]]  # fmt: skip
    assert p.tolerance is not None
    assert np.isnan(p.tolerance[0]) and list(p.tolerance[1:]) == [0.0] * 4


def test_a_rotary_feed_move_needs_an_f_word_and_a_rapid_does_not() -> None:
    m = machine(rotary={"A": None})
    error = refused("G21 G1 A90\n", machine=m)
    assert (error.value, error.allowed) == ("G1", "an F word before the first feed move")
    assert list(read_program("G21 G0 A90\nM30\n", machine=m).kind) == [RAPID]
