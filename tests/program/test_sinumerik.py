"""SINUMERIK programs translated into RS274/NGC line for line, and what is refused.

The expected texts are written by hand from Siemens' manuals (the module's
references): G710 is metric with feeds in mm/min, CR= is the arc radius, G4 F
dwells in seconds, a drilling cycle rapids to RFP + SDIS, feeds to the depth
and rapids to RTP.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.errors import BallScrewInputError
from ballscrew.io.files import program_lines
from ballscrew.program.sinumerik import DrillingCycle, drilling_cycle, to_rs274

PRODUCTION = """\
%_N_FLANSCH_01_MPF
;$PATH=/_N_WKS_DIR/_N_FLANSCH_WPD
; Flansch 01, Seite 1 (Aufspannung 1)
N10 G17 G40 G90 G94 G710 G500
N20 G57
N30 T="FRAESER_D16"
N40 M6
N50 D1
N60 S2000 M3 M8
N70 MSG("Kontur schlichten")
N80 G0 X-10 Y-10 Z10
N90 G1 Z-2 F400
N100 X60
N110 G2 X80 Y10 CR=20
N120 G1 Y50
N130 G3 X60 Y70 I=-20 J=0
N140 G1 X-10
N150 G0 Z10
N160 T="BOHRER_D8"
N170 M6
N180 D1
N190 S3000 M3 F250
N200 G0 X20 Y20 Z10
N210 MCALL CYCLE81(10,0,2,-15,)
N220 X20 Y20
N230 X40 Y20
N240 X40 Y40
N250 MCALL
N260 G0 Z50
N270 B45
N280 G0 X20 Y40 Z10
N290 CYCLE82(10,0,2,,12,0.5)
N300 X30
N310 G4 F1.5
N320 M5 M9
N330 M30
"""

PRODUCTION_RS274 = """\



G17 G40 G90 G94 G21
G57
T1
M6

S2000 M3 M8

G0 X-10 Y-10 Z10
G1 Z-2 F400
X60
G2 X80 Y10 R20
G1 Y50
G3 X60 Y70 I-20 J0
G1 X-10
G0 Z10
T2
M6

S3000 F250 M3
G0 X20 Y20 Z10

G98 G81 X20 Y20 Z-15 R2
G98 G81 X40 Y20 Z-15 R2
G98 G81 X40 Y40 Z-15 R2
G0
G0 Z50
B45
G0 X20 Y40 Z10
G98 G82 Z-12 R2 P0.5
G0 X30
G4 P1.5
M5 M9
M30
"""


def test_a_production_program_translates_line_for_line() -> None:
    out, notes = to_rs274(PRODUCTION)
    assert out == PRODUCTION_RS274
    assert len(out.splitlines()) == len(PRODUCTION.splitlines())  # errors name the user's line
    text = "\n".join(notes)
    for told in ("%_N_FLANSCH_01_MPF", "G710", "G500", 'T="FRAESER_D16"', "read as T1",
                 "D1", "MSG", "CR=", "MCALL", "CYCLE81", "CYCLE82", "G4 F"):  # fmt: skip
        assert told in text
    assert "line 8 (and 1 more)" in text  # both D1, the first line and the count


def test_words_written_with_equals_signs_zeros_and_without_spaces() -> None:
    out, _ = to_rs274("N10 G01 X=10 Y=-2.5 Z=.5 F=300\nG00X1Y2\nn20 g2 x0 y0 cr=-5\nT=3\n")
    assert out.splitlines() == ["G1 X10 Y-2.5 Z.5 F300", "G0 X1 Y2", "G2 X0 Y0 R-5", "T3"]


def test_units_feeds_and_dwells() -> None:
    # G70: inch positions, F still in mm/min (metric basic system): 254 mm/min is 10 in/min.
    out, notes = to_rs274("G70 G1 X1 F254\nG700 G1 X2 F10\nG71 G1 X3 F300\nS600 M3\nG4 S5\n")
    assert out.splitlines() == ["G20 G1 X1 F10", "G20 G1 X2 F10", "G21 G1 X3 F300",
                                "S600 M3", "G4 P0.5"]  # fmt: skip
    # 5 revolutions at 600 rev/min: 0.5 s.
    assert any("G4 S" in n and "600 rev/min" in n for n in notes)


def test_offsets_tools_and_path_modes() -> None:
    text = "G505\nG506\nG54\nT5 M6\nD1\nD0\nG153 G0 Z0\nSUPA G0 Z0\nG60\nG64\nG642\nM17\n"
    out, notes = to_rs274(text)
    assert out.splitlines() == ["G58", "G59", "G54", "T5 M6", "G43 H5", "G49", "G53 G0 Z0",
                                "G0 G53 Z0", "G61", "G64", "G64", "M2"]  # fmt: skip
    joined = "\n".join(notes)
    for told in ("G505", "G506", "D1 (tool offset on): read as G43 H5", "D0", "G153", "SUPA",
                 "G60", "G642", "M17"):  # fmt: skip
        assert told in joined


def test_high_speed_settings_and_keywords_without_feed_axis_motion() -> None:
    text = "CYCLE832(0.01,_FINISH,1)\nCYCLE832()\nSOFT FFWON COMPCAD\nG601\nSTOPRE\n"
    out, notes = to_rs274(text)
    assert out.splitlines() == ["G64 P0.01", "G64", "", "", ""]
    joined = "\n".join(notes)
    for told in ("CYCLE832", "SOFT", "FFWON", "COMPCAD", "G601", "STOPRE"):
        assert told in joined


def test_a_cycle_called_once_restores_the_motion_mode_on_the_next_line() -> None:
    out, _ = to_rs274("G0 X0 Y0 Z20 F100\nCYCLE81(20, 0, 2, -10)\n\nX5\n")
    # The cycle returns to Z20 = RTP, where it started: G98. SINUMERIK's cycle restores G0
    # [SAVE]; RS274/NGC's G81 stays modal, so the next line (here an empty one) says G0.
    assert out.splitlines() == ["G0 X0 Y0 Z20 F100", "G98 G81 Z-10 R2", "G0", "X5"]


def test_relative_depth_wins_and_rtp_at_the_safety_plane_needs_no_start_height() -> None:
    # DPR 12 below RFP 1 is -11 although DP says -15 (the manual: DPR wins); RTP = RFP +
    # SDIS = 3, so the cycle returns to R (G99) from any height, even one not known.
    out, _ = to_rs274("T1 M6\nCYCLE81(3,1,2,-15,12)\n")
    assert out.splitlines()[1] == "G99 G81 Z-11 R3"


def _manual_moves(z0: float, cycle: DrillingCycle) -> list[tuple[str, float]]:
    """SINUMERIK's sequence [3]: G0 to RFP + SDIS, G1 to the depth, (dwell), G0 to RTP."""
    moves = [("G0", cycle.approach), ("G1", cycle.depth)]
    if cycle.dwell:
        moves.append(("G4", cycle.dwell))
    return _moved(z0, [*moves, ("G0", cycle.retraction)])


def _moved(z0: float, moves: list[tuple[str, float]]) -> list[tuple[str, float]]:
    """The moves that move (a move to where the tool is, is none), and the dwells."""
    out, at = [], z0
    for kind, v in moves:
        if kind == "G4" or v != at:
            out.append((kind, v))
        at = v if kind != "G4" else at
    return out


def _rs274_moves(z0: float, words: list[str]) -> list[tuple[str, float]]:
    """RS274/NGC's G81/G82 along Z (Kramer et al., NISTIR 6556, 2000, sections 3.5.16.1-3).

    Written out from the standard, independently of the reader: a preliminary rapid up to
    R when the tool starts below it, a rapid to R, the feed to Z, the dwell P (G82), and
    the retraction at rapid to R (G99) or to the start height (G98, at least R).
    """
    value = {w[0]: float(w[1:]) for w in words if w[0] in "ZRP"}
    r, z = value["R"], value["Z"]
    moves, start = [], z0
    if start < r:
        moves.append(("G0", r))
        start = r
    moves += [("G0", r), ("G1", z)]
    if "G82" in words:
        moves.append(("G4", value["P"]))
    moves.append(("G0", r if "G99" in words else max(start, r)))
    return _moved(z0, moves)


@pytest.mark.parametrize(
    ("start", "args"),
    [
        (10.0, "10,0,2,-15,"),  # the production program's cycle, from RTP
        (50.0, "50,0,2,-15,"),  # a high retraction plane
        (12.5, "12.5,5,1.5,,20"),  # DPR
        (3.0, "3,1,2,-8"),  # RTP = RFP + SDIS: G99
        (40.0, "3,1,2,-8"),  # the same from high above: still G99, still the manual's moves
        (-2.0, "3,1,2,-8"),  # ... and from below R: RS274/NGC rises to R first, as the cycle
        (10.0, "10,0,0,-5,,2"),  # no safety clearance; a DTB in the Operate form's 6th place
        (10.0, "10,0,2,-15,,0,0,1,10"),  # Operate's modes that keep the 11.02 meaning
    ],
)
@pytest.mark.parametrize("name", ["CYCLE81", "CYCLE82"])
def test_the_cycle_moves_are_the_manuals(start: float, args: str, name: str) -> None:
    out, _ = to_rs274(f"G0 Z{start}\n{name}({args})\n")
    words = out.splitlines()[1].split()
    cycle = drilling_cycle(name, args)
    assert _rs274_moves(start, words) == _manual_moves(start, cycle)


def test_the_cycle_heights_by_hand() -> None:
    # CYCLE81(10,0,2,-15,): rapid to 0 + 2, feed to -15, rapid to 10 (no dwell).
    assert drilling_cycle("cycle81", "10,0,2,-15,") == DrillingCycle("CYCLE81", 10.0, 2.0,
                                                                     -15.0, 0.0)  # fmt: skip
    # The manual's CYCLE82 example shape: RTP 110, RFP 102, SDIS 4, DPR 75, DTB 2 s.
    assert drilling_cycle("CYCLE82", "110, 102, 4, , 75, 2") == DrillingCycle(
        "CYCLE82", 110.0, 106.0, 27.0, 2.0
    )


@pytest.mark.parametrize(
    ("text", "line", "word"),
    [
        ("G0 Z10\nCYCLE83(10,0,2,-40,,-10,,5,0,0,1,1)\n", 2, "CYCLE83(10,0,2,-40,,-10,,5,0,0,1,1)"),
        ("G0 Z10\nCYCLE84(10,0,2,-15,,0,3,,1.25,0,500,500)\n", 2, "CYCLE84"),
        ("G0 Z30\nCYCLE81(10,0,2,-15)\n", 2, "CYCLE81"),  # not at RTP: RS274 would return to 30
        ("M6\nCYCLE81(10,0,2,-15)\n", 2, "CYCLE81"),  # Z not known after a tool change
        ("G0 Z10\nCYCLE81(10,0,2,5)\n", 2, "CYCLE81(10,0,2,5)"),  # a depth above the approach
        ("G0 Z1\nCYCLE81(1,0,2,-5)\n", 2, "CYCLE81(1,0,2,-5)"),  # RTP below RFP + SDIS
        ("G0 Z10\nCYCLE81(10,0,-2,-5)\n", 2, "CYCLE81(10,0,-2,-5)"),  # SDIS with a sign
        ("G0 Z10\nCYCLE81(10,0,2,-5,,0,0,1,12)\n", 2, "CYCLE81(10,0,2,-5,,0,0,1,12)"),
        ("G0 Z10\nCYCLE81(RTP,0,2,-5)\n", 2, "CYCLE81(RTP,0,2,-5)"),  # a variable
        ("G0 Z10\nCYCLE81(10,0,2,-5) X10\n", 2, "X"),  # not alone in its block
        ("G91 G0 Z10\nCYCLE81(10,0,2,-5)\n", 2, "CYCLE81"),  # incremental
        ("G18 G0 Z10\nCYCLE81(10,0,2,-5)\n", 2, "CYCLE81"),  # another plane
        ("G0 Z10\nMCALL CYCLE81(10,0,2,-5)\nX1 Z5\n", 3, "Z"),  # Z under MCALL
        ("G0 Z10\nMCALL CYCLE81(10,0,2,-5)\nG1 X1 F100\n", 3, "X/Y"),  # at feed
        ("G0 Z10\nMCALL CYCLE81(10,0,2,-5)\nCYCLE82(10,0,2,-5)\n", 3, "CYCLE82"),
        ("G0 Z0\nMCALL CYCLE81(3,1,2,-5)\nX1\n", 3, "X/Y"),  # below R: RS274 would lift first
        ("R1=5\n", 1, "R1=5"),
        ("G0 X=IC(5)\n", 1, "X=IC(5)"),
        ("TRANS X10\n", 1, "TRANS"),
        ("L100\n", 1, "L100"),
        ("GOTOF ENDE\n", 1, "GOTOF"),
        ("/N10 G0 X1\n", 1, "/"),
        ("G41 G1 X1 F100\n", 1, "G41"),
        ("G507\n", 1, "G507"),
        ("G57\nG500\n", 2, "G500"),
        ("G4 S10\n", 1, "G4 S10"),  # no spindle speed to count revolutions at
        ("G4 F1 X5\n", 1, "G4"),
        ("G1 X1 F100 F200\n", 1, "F200"),
        ("M1=3\n", 1, "M1=3"),
        ("M19\n", 1, "M19"),
        ("D1.5\n", 1, "D1.5"),
        ('G0 X1\nP="A"\n', 2, 'P="A"'),
        ("G91.1\n", 1, "G91.1"),
        ("CYCLE832(TOL,_FINISH)\n", 1, "CYCLE832(TOL,_FINISH)"),
        ("MCALL CYCLE832(0.01)\n", 1, "MCALL"),
    ],
)
def test_what_cannot_be_translated_is_refused_naming_line_and_word(
    text: str, line: int, word: str
) -> None:
    with pytest.raises(BallScrewInputError) as info:
        to_rs274(text)
    assert info.value.field == f"program line {line}"
    assert word in str(info.value.value)
    assert info.value.allowed  # and says what is allowed


def test_comments_messages_and_a_byte_order_mark() -> None:
    out, notes = to_rs274('\ufeff; header; (x)\nMSG("a;b (c)") ; note\nG0 X1 ; go\nMSG()\n')
    assert out.splitlines() == ["", "", "G0 X1", ""]
    assert any("byte-order mark" in n for n in notes)
    assert any("MSG" in n and "(and 1 more)" in n for n in notes)


# The reader reads the translation as far as it goes today; the features another part of the
# work adds (the machine file's dialect, tool changes, work offsets, canned cycles, rotary
# axes) are probed, not assumed.


def _sinumerik_machine() -> Any:
    """The example machine with dialect = "sinumerik" and a G57 (or a skip, said why)."""
    import dataclasses
    import inspect

    from ballscrew.io.machine import load_machine
    from ballscrew.program.gcode import read_program
    from shared import ROOT

    if "machine" not in inspect.signature(read_program).parameters:
        pytest.skip("the reader takes no machine file yet (dialect, tools, offsets)")
    machine = load_machine(ROOT / "examples" / "machine_vmc.toml")
    names = {f.name for f in dataclasses.fields(machine)}
    if not {"dialect", "offsets", "tool_change_time"} <= names:
        pytest.skip("the machine file has no dialect, work offsets or tool change time yet")
    offsets = dict(machine.offsets)
    offsets[57] = {"X": 0.100, "Y": 0.050, "Z": -0.300}  # the part zero, machine coordinates
    more: dict[str, Any] = {}
    if "rotary" in names:  # a rotary table B: 20 rev/min, 1000 deg/s^2, 10 000 deg/s^3
        from ballscrew.io.machine import RotaryAxis

        turn = 2 * math.pi
        more["rotary"] = {**machine.rotary, "B": RotaryAxis("B", 20 * turn / 60,
                                                            math.radians(1000),
                                                            math.radians(10_000))}  # fmt: skip
    return dataclasses.replace(machine, dialect="sinumerik", offsets=offsets, tool_change_time=4.0,
                               **more)  # fmt: skip


def _reads(text: str, machine: Any = None) -> bool:
    from ballscrew.program.gcode import read_program

    try:
        read_program(text) if machine is None else read_program(text, machine=machine)
    except BallScrewInputError:
        return False
    return True


def test_the_reader_reads_the_translated_contour() -> None:
    from ballscrew.program.gcode import ARC, FEED, RAPID, read_program

    lines = PRODUCTION.splitlines()
    contour = "\n".join([*lines[:4], *lines[8:18]]) + "\n"  # header, units, spindle, contour
    out, _ = to_rs274(contour)
    p = read_program(out)
    assert p.kind.tolist() == [RAPID, FEED, FEED, ARC, FEED, ARC, FEED, RAPID]
    assert p.line.tolist() == [7, 8, 9, 10, 11, 12, 13, 14]  # the SINUMERIK file's own lines
    # N110 G2 X80 Y10 CR=20 from X60 Y-10: of the two centres 20 mm from both ends, (80, -10)
    # has the arc clockwise (from 180 deg to 90 deg about it), a quarter circle.
    np.testing.assert_allclose(p.centre[3, :2], [0.080, -0.010], atol=1e-12)
    assert p.sweep[3] == pytest.approx(-math.pi / 2)
    assert p.feed[1] == pytest.approx(400e-3 / 60)  # G710: F in mm/min


def test_the_machine_reads_the_production_program_and_drills_as_the_manual_says() -> None:
    from ballscrew.program.gcode import DWELL, FEED, RAPID, read_program

    machine = _sinumerik_machine()
    # Everything but the B move (probed in the next test), on the same line numbers.
    text = PRODUCTION.replace("N270 B45", "N270")
    for feature, probe in [
        ("tool change M6", 'T="A"\nM6\n'),
        ("work offset G57", "G57\n"),
        ("canned cycle G81", "G0 X0 Y0 Z10 F100\nCYCLE81(10,0,2,-5)\n"),
    ]:
        if not _reads(probe, machine):
            pytest.skip(f"the reader does not read a {feature} yet")
    p = read_program(text, machine=machine)
    off = np.array([0.100, 0.050, -0.300])  # G57; D1 of a named tool applies no length
    # The modal CYCLE81(10,0,2,-15,) at X20 Y20 (where the tool is), X40 Y20 and X40 Y40 from
    # Z10 = RTP, by hand from the manual: G0 to the position at RTP, G0 to RFP + SDIS = 2,
    # G1 to DP = -15 at F250, G0 back to RTP = 10. Then CYCLE82(10,0,2,,12,0.5) at X20 Y40:
    # G0 to 2, G1 to RFP - DPR = -12, a 0.5 s dwell, G0 to 10.
    expected = []
    for x, y, line in [(20, 20, 25), (40, 20, 26), (40, 40, 27)]:
        expected += [(RAPID, line, (x, y, 10)), (RAPID, line, (x, y, 2)),
                     (FEED, line, (x, y, -15)), (RAPID, line, (x, y, 10))]  # fmt: skip
    expected += [(RAPID, 32, (20, 40, 2)), (FEED, 32, (20, 40, -12)), (DWELL, 32, (20, 40, -12)),
                 (RAPID, 32, (20, 40, 10))]  # fmt: skip
    first = int(np.flatnonzero(p.line == 25)[0])
    got = [(int(k), int(n), tuple(np.round((e - off) * 1e3, 9)))
           for k, n, e in zip(p.kind[first:], p.line[first:], p.end[first:], strict=True)
           if 25 <= n <= 32 and n not in (28, 29, 30, 31)]  # fmt: skip
    # The X20 Y20 position is where the tool already is: its move there has no length.
    assert got == expected[1:]
    drill = np.flatnonzero((p.kind == FEED) & np.isin(p.line, [25, 26, 27]))
    np.testing.assert_allclose(p.feed[drill], 250e-3 / 60)  # the F before the cycle
    np.testing.assert_array_equal(p.dwell[(p.kind == DWELL) & (p.line == 32)], [0.5])
    np.testing.assert_array_equal(p.dwell[(p.kind == DWELL) & (p.line == 34)], [1.5])  # G4 F


def test_the_machine_reads_the_production_program_with_its_rotary_move() -> None:
    from ballscrew.program.gcode import read_program

    machine = _sinumerik_machine()
    for feature, probe in [
        ("tool change M6", 'T="A"\nM6\n'),
        ("work offset G57", "G57\n"),
        ("canned cycle G81", "G0 X0 Y0 Z10 F100\nCYCLE81(10,0,2,-5)\n"),
        ("rotary axis B", "G0 B45\n"),
    ]:
        if not _reads(probe, machine):
            pytest.skip(f"the reader does not read a {feature} yet")
    p = read_program(PRODUCTION, machine=machine)
    assert "B" in p.axes
    # And the whole program runs on the machine: the B move timed, left out of the energy.
    from ballscrew.program import run_program

    result = run_program(machine, p)
    assert set(result.axes) == {"X", "Y", "Z"}
    b = np.flatnonzero(p.line == 30)  # N270 B45
    assert b.size and p.rotary_end is not None
    assert math.degrees(p.rotary_end[b[-1], 1]) == pytest.approx(45.0)


_PIECES = [
    "N10", "G0", "G1", "G2", "G3", "G4", "G17", "G18", "G91", "G90", "G70", "G700", "G710",
    "G54", "G57", "G500", "G505", "G153", "X10", "Y=-5", "Z2", "Z=10", "B45", "I5", "J0",
    "CR=5", "F200", "S1000", "M3", "M6", "M30", 'T="A"', "T2", "D1", "D0", "MCALL",
    "CYCLE81(10,0,2,-15)", "CYCLE82(2,0,2,-5,,1)", "CYCLE83(10,0,2,-40)", "CYCLE832(0.01)",
    "SUPA", 'MSG("x")', "; c", "%_N_A_MPF", "(", ")", "=", '"', "R1=2", "X=IC(1)", "/",
    "G4.5", "AC(", ",", "\t", "", "\ufeff", "\r",
]  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(st.sampled_from(_PIECES), max_size=6), max_size=12))
def test_any_text_translates_line_for_line_or_is_refused_with_its_line(
    lines: list[list[str]],
) -> None:
    # Whatever is typed: the same number of lines back, or a refusal naming a line of the
    # text; never another exception.
    text = "\n".join(" ".join(words) for words in lines)
    try:
        out, notes = to_rs274(text)
    except BallScrewInputError as exc:
        number = int(exc.field.removeprefix("program line "))
        assert 1 <= number <= len(program_lines(text))
        return
    assert len(program_lines(out)) == len(program_lines(text.lstrip("\ufeff")))
    assert all(isinstance(n, str) for n in notes)
