"""Reading part programs: the words supported, and every other word refused with its line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.program.gcode import ARC, DWELL, FEED, RAPID, read_program


def test_blocks_modal_words_comments_and_numbers() -> None:
    p = read_program(
        "%\nO12 (name)\nN10 G21 G90 G17\nN20 G0 X10. Y0 Z5 ; rapid\nN30 G1 Z-1 F300\n"
        "X20 (modal G1)\nG4 P0.5\nM3 S1000\nM30\nG1 X99\n"
    )
    assert p.kind.tolist() == [RAPID, FEED, FEED, DWELL]
    assert p.line.tolist() == [4, 5, 6, 7]
    np.testing.assert_allclose(p.end[-2], [0.020, 0.0, -0.001])
    assert p.feed[1] == pytest.approx(300e-3 / 60)
    assert p.dwell[-1] == 0.5
    # Never skipped silently: every word not run is kept with its line, and told in one line.
    assert [(s.word, s.line) for s in p.skipped] == [("%", 1), ("O", 2), ("S", 8), ("M3", 8)]
    assert p.notes[0] == (
        "skipped, no motion of the feed axes: % (line 1), O (line 2), S (line 8), M3 (line 8)"
    )
    assert any("line 10 and on, after M2/M30: not run" in n for n in p.notes)


def test_r_and_ijk_arcs_agree() -> None:
    # A quarter circle of R 10 from (0, 0) to (10, 10) about (10, 0): clockwise, G2.
    a = read_program("G1 X0 Y0 F100\nG2 X10 Y10 I10 J0\n")
    b = read_program("G1 X0 Y0 F100\nG2 X10 Y10 R10\n")
    assert a.kind[-1] == ARC and b.kind[-1] == ARC
    np.testing.assert_allclose(a.centre[-1, :2], [0.010, 0.0])
    np.testing.assert_allclose(b.centre[-1, :2], a.centre[-1, :2], atol=1e-12)
    assert a.sweep[-1] == pytest.approx(-math.pi / 2)
    # A negative R takes the arc over 180 degrees: the other centre.
    c = read_program("G1 X0 Y0 F100\nG2 X10 Y10 R-10\n")
    np.testing.assert_allclose(c.centre[-1, :2], [0.0, 0.010], atol=1e-12)
    assert c.sweep[-1] == pytest.approx(-1.5 * math.pi)


def test_full_circle_and_planes() -> None:
    p = read_program("G1 X10 Y0 Z0 F100\nG3 X10 Y0 I-10 J0\nG18 G2 X10 Z0 I-5 K0\n")
    assert p.sweep[1] == pytest.approx(2 * math.pi)
    assert p.plane[2] == 18 and abs(p.sweep[2]) == pytest.approx(2 * math.pi)


def test_inch_is_millimetres_times_25_4() -> None:
    mm = read_program("G21 G1 X25.4 Y50.8 F254\n")
    inch = read_program("G20 G1 X1 Y2 F10\n")
    np.testing.assert_allclose(inch.end, mm.end, rtol=1e-12)
    np.testing.assert_allclose(inch.feed, mm.feed, rtol=1e-12)


@pytest.mark.parametrize(
    ("text", "line", "word"),
    [
        ("G1 X1 F100\nG84 X1 Y1 Z-2 R1\n", 2, "G84"),  # a tapping cycle
        ("G1 X1 F100\n#1=5\n", 2, "#1=5"),  # a variable
        ("G1 X1 F100\nG1 X[1+2]\n", 2, "X"),  # an expression
        ("G0 X1\nG43 H1 Z5\n", 2, "H1"),  # a tool length offset without a tool table
        ("G0 X1\nG64.1\n", 2, "G64.1"),  # a decimal code not read
        ("G0 X1\nM6\n", 2, "M6"),  # a tool change without a tool change time
        ("G0 X5\nG1 X10\n", 2, "G1"),  # a feed move before any F
        ("G1 X0 Y0 F100\nG2 X10 Y0.5 I5 J0\n", 2, "G2"),  # end point off the arc
        ("G1 X1 A30 F100\n", 1, "A30"),  # a rotary axis
        ("X1\n", 1, "X1"),  # a move before any motion code
        ("G1 X1 F100 (open comment\n", 1, "(open comment"),
    ],
)
def test_refused_words_name_the_line(text: str, line: int, word: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        read_program(text)
    assert info.value.field == f"program line {line}"
    assert word in str(info.value.value)


def test_radius_mismatch_within_the_tolerance_is_read() -> None:
    # R 5 mm: the end 1 um further out is inside the tolerance (the larger of 2 um and
    # 0.1 % of R = 5 um); 10 um further out is outside it.
    read_program("G1 X0 Y0 F100\nG2 X10.001 Y0 I5 J0\n", arc_tolerance=2e-6)
    with pytest.raises(BallScrewInputError):
        read_program("G1 X0 Y0 F100\nG2 X10.01 Y0 I5 J0\n", arc_tolerance=2e-6)


def test_a_program_without_time_stands_at_its_start() -> None:
    from ballscrew.program.planner import Limits, plan

    lim = Limits(np.ones(3), np.ones(3), np.ones(3), 1.0, 1e-5)
    for text in ("M30\n", "G0 X0\n", "G4 P0\n"):
        # As a controller runs it: nothing moves, no time passes (tests/program/test_standing.py).
        motion = plan(read_program(text), lim)
        assert motion.time.tolist() == [0.0] and motion.duration == 0.0
        assert not np.any(motion.position) and not np.any(motion.velocity)


def test_a_centre_without_axis_words_is_a_full_circle_as_linuxcnc_reads_it() -> None:
    # LinuxCNC's 3dtest.ngc writes 'g17 g02 i.5 j.5'; rs274 prints it as
    # ARC_FEED(1.0000, 0.0000, 1.5000, 0.5000, -1, ...): a whole clockwise turn about
    # (1.5, 0.5) mm back to (1, 0), and the same for a following 'I0.5 J0.5' in G2's mode.
    from ballscrew.program.gcode import ARC, read_program

    p = read_program("G21\nG1 X1 F100\ng02 i.5 j.5\nI0.5 J0.5\nM2\n")
    assert p.kind.tolist()[1:] == [ARC, ARC]
    np.testing.assert_allclose(p.sweep[1:], [-2 * np.pi] * 2)
    np.testing.assert_allclose(p.centre[1:, :2], [[1.5e-3, 0.5e-3]] * 2, atol=1e-15)
    np.testing.assert_allclose(p.end[1:], [[1e-3, 0.0, 0.0]] * 2, atol=1e-15)


def test_a_form_feed_does_not_shift_the_line_numbers() -> None:
    # Issue 52: Python's splitlines breaks at a form feed (a post's page break), so every
    # error after it named the wrong line. Lines are counted at CR LF, LF and CR only.
    from ballscrew.program.gcode import read_program

    with pytest.raises(BallScrewInputError) as info:
        read_program("G21\r\nG1 X1 F100\n\fG1 X2\nG1 X3 Q\nM2\n")
    assert info.value.field == "program line 4"
    p = read_program("G21\nG1 X1 F100\n\f\x0bG1 X2\rG1 X3\nM2\n")
    assert p.line.tolist() == [2, 3, 4]


@pytest.mark.parametrize(("line", "letter"), [("G01X10F", "F"), ("G1 X10 Y", "Y")])
def test_a_letter_without_its_number_is_named(line: str, letter: str) -> None:
    # A typo a CAM post or a hand never meant: the letter is named, and what it lacks.
    with pytest.raises(BallScrewInputError) as info:
        read_program(f"G21 G90\n{line}\n")
    message = str(info.value)
    assert "line 2" in message and f"a number after the letter {letter}" in message, message
