"""The reader's modal groups against RS274/NGC's table of them (NIST IR 6556, 2000, table 4),
and its canned cycles' moves, the peck's back-off and the long dwell's note.

Two codes of one modal group in a block are an error there; the reader refuses them and
names the group. Each group is taken with two of its codes (or one code twice), so that a
code moved out of its group, or a group given another's number, is seen.
"""

from __future__ import annotations

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.program.gcode import read_program

G_GROUPS = {
    "non-modal (G4, G28, G30, G53)": ("G4", "G28", "G30", "G53"),
    "motion": ("G0", "G1", "G2", "G3", "G73", "G80", "G81", "G82", "G83", "G85", "G89"),
    "plane": ("G17", "G18", "G19"),
    "distance mode": ("G90", "G91"),
    "arc centre mode": ("G90.1", "G91.1"),
    "feed mode": ("G94",),
    "units": ("G20", "G21"),
    "cutter compensation": ("G40",),
    "tool length offset": ("G43", "G49"),
    "cycle retract": ("G98", "G99"),
    "work offset": ("G54", "G55", "G56", "G57", "G58", "G59"),
    "path mode": ("G61", "G64"),
    "spindle speed mode": ("G96", "G97"),
    "rotation": ("G69",),
    "polar coordinates": ("G15",),
    "mirror image": ("G50.1",),
}
"""The G codes the reader reads, by the group RS274/NGC (and Fanuc for G15, G50.1, G69) puts
them in."""

M_GROUPS = (("M0", "M1", "M2", "M30"), ("M6",), ("M3", "M4", "M5", "M19"), ("M7", "M8", "M9"))
"""Stopping, tool change, spindle, coolant (M19, the spindle orient, with the spindle)."""


@pytest.mark.parametrize(("name", "codes"), list(G_GROUPS.items()))
def test_two_g_codes_of_a_group_are_refused_naming_it(name: str, codes: tuple[str, ...]) -> None:
    for other in codes[1:] or codes:
        with pytest.raises(BallScrewInputError) as info:
            read_program(f"{codes[0]} {other}\n")
        assert info.value.value == f"{codes[0]} {other}"
        assert info.value.allowed.startswith(f"one code of the {name} group per block")


@pytest.mark.parametrize("codes", M_GROUPS)
def test_two_m_codes_of_a_group_are_refused(codes: tuple[str, ...]) -> None:
    import itertools

    for one, other in itertools.combinations(codes, 2) if len(codes) > 1 else [codes * 2]:
        if {one, other} == {"M7", "M8"}:
            continue  # mist and flood together: allowed
        with pytest.raises(BallScrewInputError) as info:
            read_program(f"{one} {other}\n")
        assert info.value.value == f"{one} {other}"


def test_codes_of_different_groups_share_a_block() -> None:
    # One code of every group in one block (and mist with flood): read, nothing refused.
    read_program("G17 G21 G40 G49 G54 G64 G69 G15 G90 G90.1 G94 G97 G98 G0 X1 M3 M7 M8\nM30\n")


def test_a_peck_cycle_comes_back_down_to_0_010_inch_above_its_last_depth() -> None:
    # G83 from Z5 to Z-3 by 1 mm pecks, R1: each peck feeds 1 mm deeper, retracts to R, and
    # comes back down rapidly to 0.010 in = 0.254 mm above the depth reached (LinuxCNC's).
    p = read_program("G21 G90 G0 X0 Y0 Z5\nG98 G83 X0 Y0 Z-3 R1 Q1 F100\nM30\n")
    z_mm = [round(z * 1000.0, 9) for z in p.end[:, 2]]
    assert z_mm == [5.0, 1.0, 0.0, 1.0, 0.254, -1.0, 1.0, -0.746, -2.0, 1.0, -1.746, -3.0, 5.0]


def test_a_dwell_over_a_minute_is_noted_with_its_reading() -> None:
    # 60 s is the limit: 61 s is noted (with Fanuc's milliseconds as the other reading), 60 s
    # is not.
    (note,) = read_program("G4 P61\nM30\n").notes
    assert "a dwell of 61 s" in note and "reads 0.061 s" in note
    assert read_program("G4 P60\nM30\n").notes == ()


@pytest.mark.parametrize(
    ("cycle", "kinds"),
    [("G81", "RRFR"), ("G82 P1", "RRFDR"), ("G85", "RRFFR"), ("G89 P1", "RRFDF"),
     ("G73 Q2", "RRFRFR"), ("G83 Q2", "RRFRRFR")],
)  # fmt: skip
def test_each_canned_cycle_makes_its_moves(cycle: str, kinds: str) -> None:
    # From Z5, a hole at X1 to Z-3 with R1 under G98: to the hole (rapid), down to R (rapid),
    # then each cycle's moves (RS274/NGC, LinuxCNC's G85): G81 feeds to the bottom and
    # rapids out to Z5; G82 dwells before; G85 feeds back to R, then rapids out; G89 dwells
    # and feeds out all the way; G73 and G83 peck 2 mm (G73 backs off 0.254 mm, G83
    # retracts to R first).
    p = read_program(f"G21 G90 G0 X0 Y0 Z5\nG98 {cycle} X1 Y0 Z-3 R1 F100\nM30\n")
    letters = "RFAD"  # RAPID, FEED, ARC, DWELL
    assert "".join(letters[k] for k in p.kind[1:]) == kinds
