r"""Reading a part program (RS274/NGC G-code, or a CAM post's Fanuc-style output) into blocks.

This module is long on purpose: one reader (``_Reader``) holds the modal state
that every word changes, so the order in which RS274/NGC applies a block's words,
and the few branches of each dialect (Fanuc, Sinumerik), are checked in one place.

Each line is taken apart into words (a letter and a number) once its comments
and block number are off; a line that is anything else (``#1=5``, ``[1+2]``,
``O100 call``) is refused with its line. Every word is then run, skipped with a
note, or refused with its line: nothing is dropped silently. The words of a
block are applied in the order RS274/NGC gives (Kramer, Proctor and Messina,
*The NIST RS274NGC Interpreter - Version 3*, NIST IR 6556, 2000, section 3.8):
feed, tool change, dwell, plane, units, tool length offset, work offset, path
mode, distance mode, retract mode, a return to a reference point, then the
motion.

What is read:

- ``G0`` (rapid), ``G1`` (feed), ``G2``/``G3`` (arcs clockwise and
  counter-clockwise seen from the positive end of the plane's normal) in
  ``G17`` (XY), ``G18`` (ZX) or ``G19`` (YZ), with ``I``/``J``/``K`` (centre
  offsets from the start, ``G91.1``, or the centre itself, ``G90.1``) or ``R``
  (negative: the arc over 180°); the third axis may move (a helix);
- ``G4`` dwell: ``P`` in seconds (RS274/NGC, LinuxCNC); in the ``fanuc``
  dialect ``P`` in milliseconds (a whole number) or ``X`` in seconds. A dwell
  over 60 s is noted with its reading;
- ``G20``/``G21`` (inch, mm), ``G90``/``G91`` (absolute, incremental),
  ``G94`` (feed per minute, the only mode), ``F`` in mm/min or in/min;
- tool changes ``T… M6`` (the machine's ``tool_change_time`` with the feed
  axes still), tool length offsets ``G43 H…``/``G49`` from the machine's tool
  table, work offsets ``G54``–``G59`` from the machine's ``[offsets]``:
  machine Z = program Z + work offset + tool length, and every block is kept
  in machine coordinates;
- ``G53`` (this block's ``G0``/``G1`` in machine coordinates), ``G28``/``G30``
  (a rapid through the intermediate point the axis words give, then the named
  axes, or all when none is named, to the machine's reference position);
- ``G61`` (exact path: every corner is stopped at) and ``G64`` (blending; ``P``
  sets the path tolerance the planner blends corners within, else the
  machine's);
- the drilling cycles ``G73 G81 G82 G83 G85 G89`` in ``G17`` with ``G98``
  (retract to the level the cycles started from) or ``G99`` (to ``R``), ``R``,
  ``Q`` (peck), ``P`` (dwell; milliseconds in the ``fanuc`` dialect), ``L``
  (repeats; also ``K`` in the ``fanuc`` dialect), cancelled by ``G80`` or another
  motion code, repeated on every following block with axis words. They are
  expanded into moves as RS274/NGC defines them (NIST IR 6556, 2000, section
  3.5.16, "Canned Cycles"; the LinuxCNC G-code reference's canned-cycle
  chapter): the XY position at the current height, down to ``R`` at the rapid
  feed, then

  - G81: feed to Z, rapid out;
  - G82: feed to Z, dwell P, rapid out;
  - G83: feed Q deeper, rapid up to R, rapid back down to 0.010 in above the
    last depth, repeated until Z, rapid out;
  - G73: as G83, but backing off 0.010 in only instead of going up to R;
  - G85: feed to Z, feed back up to R, rapid out (LinuxCNC; the 2000 report
    feeds out all the way, which differs only under G98);
  - G89: feed to Z, dwell P, feed out.

  "Out" is R under G99, and under G98 the higher of R and the height of the
  first block of the series (LinuxCNC's reading); in G91, R is counted from
  that height and Z from R. The moves of a cycle are taken with exact path
  (no corner blending), as LinuxCNC does;
- rotary axes ``A``, ``B``, ``C`` in ``G0``/``G1`` blocks, when the machine file
  gives their limits: in degrees (absolute, or incremental under ``G91``), timed
  with those limits and left out of the ball-screw energy. Alone in a ``G1``,
  ``F`` is in degrees per minute; with X, Y or Z, ``F`` is the linear path's
  feed and the rotary axes follow in proportion (as LinuxCNC);
- comments in parentheses or after ``;``, ``N`` block numbers, ``%``, ``O``
  program numbers, ``M2``/``M30`` (the end), a leading byte-order mark;
- skipped, each with its word and line in :attr:`Program.skipped`, and all told in
  one note (:func:`skipped_summary`):
  spindle, coolant and stop codes ``M0 M1 M3 M4 M5 M7 M8 M9 M19``, ``S``,
  ``T`` without ``M6`` in its block, the spindle modes ``G96 G97``, the cancel
  codes ``G15 G40 G50.1 G69`` of modes the reader does not take (polar
  coordinates, cutter compensation, mirror image, rotation), ``Q`` of ``G64``
  (a CAM path's own tolerance).

The ``sinumerik`` dialect is first translated into RS274/NGC by
:func:`ballscrew.program.sinumerik.to_rs274`, line for line.

Two codes of one modal group in a block (``G0 G1``, ``G90 G91``, ``M3 M5``)
are refused naming both. Everything else (macros and variables, subprograms,
cutter radius compensation, other cycles, ``G10 G92``, inverse-time feed,
a rotary axis the machine file gives no limits for) is refused with the line
number and the word.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..io.files import program_lines

__all__ = [
    "ARC", "DWELL", "FEED", "RAPID", "Program", "Skipped", "program_from_rows", "read_program",
    "skipped_summary",
]  # fmt: skip

RAPID, FEED, ARC, DWELL = 0, 1, 2, 3
"""Kinds of block."""

INCH = 0.0254
"""[m]."""
PECK_BACKOFF = 0.010 * INCH
"""How far above the last depth G73 and G83 come back down to before the next peck [m]
(0.010 in, as LinuxCNC; 0.254 mm)."""
LONG_DWELL = 60.0
"""A dwell longer than this is noted with how it was read [s]."""

_COMMENT = re.compile(r"\([^()]*\)")
_WORDS = re.compile(r"\s*([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*")

_G_GROUPS: dict[str, int] = {
    **dict.fromkeys(("0", "1", "2", "3", "73", "80", "81", "82", "83", "85", "89"), 1),
    **dict.fromkeys(("4", "28", "30", "53"), 0),
    **dict.fromkeys(("17", "18", "19"), 2), **dict.fromkeys(("90", "91"), 3),
    **dict.fromkeys(("90.1", "91.1"), 4), "94": 5, **dict.fromkeys(("20", "21"), 6),
    "40": 7, **dict.fromkeys(("43", "49"), 8), **dict.fromkeys(("98", "99"), 10),
    **dict.fromkeys(("54", "55", "56", "57", "58", "59"), 12),
    **dict.fromkeys(("61", "64"), 13), **dict.fromkeys(("96", "97"), 14),
    "15": 17, "69": 16, "50.1": 22,
}  # fmt: skip
"""The G codes read, by modal group (RS274/NGC's table of modal groups; 0: non-modal)."""
_GROUP_NAMES = {
    0: "non-modal (G4, G28, G30, G53)", 1: "motion", 2: "plane", 3: "distance mode",
    4: "arc centre mode", 5: "feed mode", 6: "units", 7: "cutter compensation",
    8: "tool length offset", 10: "cycle retract", 12: "work offset", 13: "path mode",
    14: "spindle speed mode", 16: "rotation", 17: "polar coordinates", 22: "mirror image",
}  # fmt: skip
_REFUSED_G = {
    **dict.fromkeys(("74", "76", "84", "86", "87", "88"), "a tapping, threading or boring cycle"),
    **dict.fromkeys(("41", "42", "41.1", "42.1"), "cutter radius compensation"),
    "43.1": "a dynamic tool length offset", "10": "setting offsets from the program",
    **dict.fromkeys(("92", "92.1", "92.2", "92.3", "52"), "a coordinate system offset"),
    "61.1": "exact stop mode", "93": "inverse time feed", "95": "feed per revolution",
    "33": "spindle-synchronised motion", "38.2": "probing", "5": "a spline",
    **dict.fromkeys(("59.1", "59.2", "59.3"), "a work offset past G59"),
    **dict.fromkeys(("68", "50", "51", "16", "51.1"), "a rotation, scaling or mirror image"),
}  # fmt: skip
_READ_G = (
    "G0-G4, G15, G17-G21, G28, G30, G40, G43, G49, G50.1, G53-G59, G61, G64, G69, G73, "
    "G80-G83, G85, G89, G90, G90.1, G91, G91.1, G94, G96-G99"
)
_M_GROUPS = {0: 4, 1: 4, 2: 4, 30: 4, 6: 6, 3: 7, 4: 7, 5: 7, 19: 7, 7: 8, 8: 8, 9: 8}
_CYCLES = (73, 81, 82, 83, 85, 89)
_PLANES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}
"""Plane code -> (first axis, second axis, normal axis) indices of X, Y, Z (G18: Z, X)."""
_CENTRE = {0: "I", 1: "J", 2: "K"}


class Skipped(NamedTuple):
    """A word read but not run, since it does not move the feed axes."""

    word: str
    """The code (``M3``, ``G40``) or the letter (``S``, ``T``, ``Q``, ``O``, ``%``)."""
    line: int
    """Its line (1-based)."""


@dataclass(frozen=True)
class Program:
    """A part program read into blocks (SI: m, m/s, s), in machine coordinates.

    One row per block of motion or dwell, in program order.

    Attributes
    ----------
    kind : numpy.ndarray of int
        :data:`RAPID`, :data:`FEED`, :data:`ARC` or :data:`DWELL` (a tool
        change is a dwell).
    line : numpy.ndarray of int
        Line number (1-based) of each block in the program text.
    start, end : numpy.ndarray, shape (n, 3)
        X, Y, Z at the block's start and end [m], machine coordinates.
    feed : numpy.ndarray
        Programmed path feed [m/s] (NaN for rapids and dwells).
    centre : numpy.ndarray, shape (n, 3)
        Arc centre [m] (NaN for other blocks); its normal coordinate is the start's.
    plane : numpy.ndarray of int
        17, 18 or 19 (the arc's plane).
    sweep : numpy.ndarray
        Signed angle of an arc about the plane's normal [rad] (positive: G3).
    dwell : numpy.ndarray
        Dwell time [s] (0 for moves).
    axes : frozenset of str
        The axis letters the program moves.
    notes : tuple of str
        The words skipped in one line (:func:`skipped_summary`), then what was read in a
        way to know (a long dwell, a tool change, a rotary axis), one note per kind with
        its first line.
    tolerance : numpy.ndarray or None
        The path tolerance the corner at each block's start may be blended within
        [m]: 0 under G61 and in canned cycles, ``G64 P``'s, NaN for the
        machine's (None: the machine's everywhere).
    skipped : tuple of Skipped
        Every word skipped, with its line.
    rotary_start, rotary_end : numpy.ndarray, shape (n, 3), or None
        A, B, C at the block's start and end [rad] (None: no rotary axis). A
        block that moves a rotary axis alone has its ``feed`` in rad/s (F is in
        degrees per minute there); with a linear axis, F is the linear path's
        feed and the rotary axes follow in proportion.
    """

    kind: np.ndarray
    line: np.ndarray
    start: FloatArray
    end: FloatArray
    feed: FloatArray
    centre: FloatArray
    plane: np.ndarray
    sweep: FloatArray
    dwell: FloatArray
    axes: frozenset[str]
    notes: tuple[str, ...] = ()
    text: str = field(default="", repr=False)
    tolerance: FloatArray | None = None
    skipped: tuple[Skipped, ...] = ()
    rotary_start: FloatArray | None = None
    rotary_end: FloatArray | None = None

    @property
    def size(self) -> int:
        """The number of blocks."""
        return int(self.kind.size)


class _Word(NamedTuple):
    letter: str
    value: float
    text: str


def _error(line: int, word: str, allowed: str) -> BallScrewInputError:
    return BallScrewInputError(f"program line {line}", word, allowed)


def _words(text: str, number: int) -> list[_Word]:
    """The line's words without comments and block number; refused when not words."""
    if "(" in text or ")" in text:
        if text.count("(") != text.count(")"):
            raise _error(number, text.strip(), "balanced parentheses around a comment")
        text = _COMMENT.sub(" ", text)
        if "(" in text:
            raise _error(number, text.strip(), "comments not nested")
    text = text.split(";", 1)[0].strip().upper()
    if text in ("", "%"):
        return []
    words: list[_Word] = []
    pos = 0
    while pos < len(text):
        match = _WORDS.match(text, pos)
        if match is None:
            bad = text[pos:].split()[0] if text[pos:].split() else text[pos:]
            if len(bad) == 1 and bad.isalpha():  # 'G1 X10 Y' or 'G01X10F': a letter alone
                raise _error(number, bad, f"a number after the letter {bad} (e.g. '{bad}10'); "
                             "the word has none")  # fmt: skip
            raise _error(number, bad, "words of a letter and a number only (no macros, "
                         "variables, expressions or block delete)")  # fmt: skip
        letter, digits = match.group(1), match.group(2)
        words.append(_Word(letter, float(digits), letter + digits))
        pos = match.end()
    return [w for w in words if w.letter != "N"]


@dataclass
class _Block:
    number: int
    g: dict[int, tuple[int | float, str]]  # group -> (code, word as written)
    m: dict[int, list[tuple[int, str]]]
    params: dict[str, _Word]

    def code(self, group: int) -> int | float | None:
        entry = self.g.get(group)
        return None if entry is None else entry[0]


def _block(words: list[_Word], number: int, fanuc: bool = False) -> _Block:
    """The words sorted into codes by modal group and parameters; a clash is refused.

    Fanuc puts ``G80`` in a group of its own: with ``fanuc``, ``G0 G80`` (as posts
    write it) is the motion ``G0`` after the cycle's cancel.
    """
    block = _Block(number, {}, {}, {})
    for w in words:
        if w.letter == "G":
            key = f"{w.value:g}"
            if key not in _G_GROUPS:
                what = _REFUSED_G.get(key, "a code the reader does not support")
                raise _error(number, w.text, f"{_READ_G} ({w.text} is {what})")
            group = _G_GROUPS[key]
            code = float(key) if "." in key else int(key)
            if group in block.g:
                pair = {block.g[group][0], code}
                if fanuc and 80 in pair and pair - {80} <= {0, 1, 2, 3}:
                    block.g[group] = max((block.g[group], (code, w.text)), key=_not_g80)
                    continue
                hint = ""
                if not fanuc and 80 in pair:
                    hint = ' (Fanuc puts G80 in a group of its own: [machine] dialect = "fanuc")'
                raise _error(number, f"{block.g[group][1]} {w.text}", f"one code of the "
                             f"{_GROUP_NAMES[group]} group per block{hint}")  # fmt: skip
            block.g[group] = (code, w.text)
        elif w.letter == "M":
            code = int(w.value)
            if code != w.value or code not in _M_GROUPS:
                raise _error(number, w.text, "M0-M9, M19 or M30")
            group = _M_GROUPS[code]
            same = block.m.setdefault(group, [])
            if same and not (group == 8 and {code, same[0][0]} == {7, 8}):
                raise _error(number, f"{same[0][1]} {w.text}", "one M code of a group per "
                             "block (M7 and M8 together excepted)")  # fmt: skip
            same.append((code, w.text))
        else:
            if w.letter in block.params:
                raise _error(number, f"{block.params[w.letter].text} {w.text}",
                             "each word once per block")  # fmt: skip
            block.params[w.letter] = w
    return block


def _not_g80(entry: tuple[int | float, str]) -> bool:
    return entry[0] != 80


@dataclass(frozen=True)
class _Setup:
    """What the machine file tells the reader (SI)."""

    dialect: str = "rs274"
    tool_change_time: float | None = None
    tools: dict[int, float] = field(default_factory=dict)
    offsets: dict[int, dict[str, float]] = field(default_factory=dict)
    reference: dict[int, dict[str, float]] = field(default_factory=dict)
    rotary: frozenset[str] = frozenset()  # the rotary axes with limits

    @classmethod
    def of(cls, machine: Any) -> _Setup:
        if machine is None:
            return cls()
        return cls(machine.dialect, machine.tool_change_time, dict(machine.tools),
                   dict(machine.offsets), dict(machine.reference),
                   frozenset(getattr(machine, "rotary", {})))  # fmt: skip


@dataclass
class _State:
    position: list[float]  # machine coordinates [m]
    rotary: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])  # A, B, C [rad]
    rate: float = math.nan  # the F word as written (degrees per minute for a rotary move)
    inch: bool = False
    incremental: bool = False
    centre_absolute: bool = False  # G90.1
    plane: int = 17
    motion: int | None = None
    feed: float | None = None
    work: int = 54
    tool_length: float = 0.0  # the active G43 offset [m]
    tool: int | None = None  # in the spindle
    selected: int | None = None  # by T
    tolerance: float = math.nan  # G64 without P: the machine's
    retract: int | None = None  # 98, 99
    cycle: dict[str, float] = field(default_factory=dict)  # R, Z, Q, P as written
    initial: float | None = None  # Z where the series of cycles began [m]


class _Reader:
    """One program's reading: the state, the blocks so far, the notes."""

    def __init__(self, setup: _Setup, start: Any, arc_tolerance: float) -> None:
        self.setup = setup
        self.state = _State(position=[float(v) for v in start])
        self.arc_tolerance = arc_tolerance
        self.rows: list[tuple[Any, ...]] = []
        self.notes: dict[str, str] = {}
        self.skipped: list[Skipped] = []
        self.used: set[str] = set()

    # -- bookkeeping --------------------------------------------------------------------
    def skip(self, word: str, number: int) -> None:
        self.skipped.append(Skipped(word, number))

    def note(self, key: str, text: str) -> None:
        self.notes.setdefault(key, text)

    @property
    def unit(self) -> float:
        return INCH if self.state.inch else 1e-3

    def offset(self, i: int) -> float:
        """Machine minus program coordinate of axis ``i`` [m] (work offset and tool length)."""
        work = self.setup.offsets.get(self.state.work, {})
        return work.get("XYZ"[i], 0.0) + (self.state.tool_length if i == 2 else 0.0)

    def emit(
        self, kind: int, number: int, target: list[float], *, tolerance: float | None = None,
        centre: list[float] | None = None, sweep: float = 0.0, dwell: float = 0.0,
        rotary: list[float] | None = None,
    ) -> None:  # fmt: skip
        """Add a block from the current position to ``target`` (a move of no length: none)."""
        st = self.state
        turn = st.rotary if rotary is None else rotary
        if kind in (RAPID, FEED) and target == st.position and turn == st.rotary:
            return
        if kind in (FEED, ARC) and st.feed is None:
            raise _error(number, "F", "an F word before the first feed move")
        feed = st.feed if kind in (FEED, ARC) else math.nan
        if kind == FEED and target == st.position:  # a rotary axis alone: F in deg/min
            feed = math.radians(st.rate) / 60.0
        tol = st.tolerance if tolerance is None else tolerance
        for i, k in enumerate("XYZ"):
            if target[i] != st.position[i]:
                self.used.add(k)
        for i, k in enumerate("ABC"):
            if turn[i] != st.rotary[i]:
                self.used.add(k)
        self.rows.append((kind, number, list(st.position), list(target), feed,
                          centre or [math.nan] * 3, st.plane, sweep, dwell, tol,
                          list(st.rotary), list(turn)))  # fmt: skip
        st.position = list(target)
        st.rotary = list(turn)

    # -- one block ----------------------------------------------------------------------
    def run(self, block: _Block) -> bool:
        """Apply one block in RS274/NGC's order; True at the program's end."""
        st, n, p = self.state, block.number, block.params
        if block.code(6) is not None:
            st.inch = block.code(6) == 20
        if "F" in p:
            word = p.pop("F")
            feed = word.value * self.unit / 60.0
            if not feed > 0.0:
                raise _error(n, word.text, "a feed > 0 (mm/min under G21, in/min under G20)")
            st.feed, st.rate = feed, word.value
        if "S" in p:
            p.pop("S")
            self.skip("S", n)
        change = 6 in block.m
        if "T" in p:
            word = p.pop("T")
            if word.value != int(word.value) or word.value < 0:
                raise _error(n, word.text, "a tool number T0, T1, ...")
            st.selected = int(word.value)
            if not change:
                self.skip("T", n)
        if change:
            self.tool_change(n)
        for group in (7, 8):
            for code, _ in block.m.get(group, []):
                self.skip(f"M{code}", n)
        if block.code(0) == 4:
            self.dwell(block)
        if block.code(2) is not None:
            st.plane = int(block.code(2))  # type: ignore[arg-type]
        if block.code(7) is not None:
            self.skip("G40", n)
        for group in (14, 16, 17, 22):
            if group in block.g:
                key = f"{block.g[group][0]:g}"
                self.skip(f"G{key}", n)
        self.tool_length(block)
        self.work_offset(block)
        self.path_mode(block)
        if block.code(3) is not None:
            st.incremental = block.code(3) == 91
        if block.code(4) is not None:
            st.centre_absolute = block.code(4) == 90.1
        if block.code(10) is not None:
            st.retract = int(block.code(10))  # type: ignore[arg-type]
        self.motion(block)
        ended = False
        for code, _ in block.m.get(4, []):
            if code in (2, 30):
                ended = True
            else:
                self.skip(f"M{code}", n)
        if p:
            word = next(iter(p.values()))
            raise _error(n, word.text, f"a word this block uses ({word.letter} is read with "
                         f"{_USES.get(word.letter, 'no code the reader supports')})")  # fmt: skip
        return ended

    def tool_change(self, n: int) -> None:
        time = self.setup.tool_change_time
        if time is None:
            raise _error(n, "M6", "a tool change time: [machine] tool_change_time in the "
                         "machine file")  # fmt: skip
        self.state.tool = self.state.selected
        self.note("M6", f"M6 (tool change, line {n}): {time:g} s with the feed axes still "
                  "(machine.tool_change_time)")  # fmt: skip
        self.emit(DWELL, n, list(self.state.position), dwell=time)

    def dwell(self, block: _Block) -> None:
        n, p = block.number, block.params
        axes = [w.text for k, w in p.items() if k in "YZIJKR" or (k == "X" and not self.fanuc)]
        if axes:
            hint = "" if self.fanuc else ' (Fanuc\'s G4 X<seconds>: [machine] dialect = "fanuc")'
            raise _error(n, axes[0], "no axis words with G4" + hint)
        if self.fanuc and "X" in p:
            word = p.pop("X")
            seconds, reading = word.value, "X in seconds (Fanuc)"
            if "P" in p:
                raise _error(n, p["P"].text, "either P or X with G4")
        elif "P" in p:
            word = p.pop("P")
            seconds, reading = self.dwell_seconds(word, n)
        else:
            raise _error(n, "G4", "G4 P<seconds>" + (" or P<ms>, X<seconds>" if self.fanuc else ""))
        if not seconds >= 0.0:
            raise _error(n, word.text, "a dwell >= 0 s")
        if seconds > LONG_DWELL:
            hint = (" (Fanuc's P is milliseconds: [machine] dialect = \"fanuc\" reads "
                    f"{seconds / 1000.0:g} s)" if not self.fanuc else "")  # fmt: skip
            self.note(f"dwell {n}", f"G4 {word.text} (line {n}): a dwell of {seconds:g} s, "
                      f"{reading}{hint}")  # fmt: skip
        self.emit(DWELL, n, list(self.state.position), dwell=seconds)

    @property
    def fanuc(self) -> bool:
        return self.setup.dialect == "fanuc"

    def dwell_seconds(self, word: _Word, n: int) -> tuple[float, str]:
        """A P word of G4, G82 or G89 in seconds, and how it was read."""
        if not self.fanuc:
            return word.value, "P read in seconds (RS274/NGC)"
        if word.value != int(word.value):
            raise _error(n, word.text, "P in milliseconds, a whole number (Fanuc), or G4 X "
                         "in seconds")  # fmt: skip
        return word.value / 1000.0, "P read in milliseconds (Fanuc)"

    def tool_length(self, block: _Block) -> None:
        code, n, p = block.code(8), block.number, block.params
        if code == 49:
            self.state.tool_length = 0.0
        if code != 43:
            return
        if "H" in p:
            word = p.pop("H")
            number = int(word.value)
            if number != word.value or number < 0:
                raise _error(n, word.text, "a tool number H0, H1, ...")
        elif self.state.tool is None:
            raise _error(n, "G43", "an H word, or a tool loaded by M6 before G43")
        else:
            number, word = self.state.tool, _Word("H", self.state.tool, f"T{self.state.tool}")
        if number == 0:
            self.state.tool_length = 0.0
        elif number in self.setup.tools:
            self.state.tool_length = self.setup.tools[number]
        else:
            have = ", ".join(f"T{k}" for k in sorted(self.setup.tools)) or "none"
            raise _error(n, word.text, f"a tool of the machine file's [tools] ({have})")

    def work_offset(self, block: _Block) -> None:
        code, n = block.code(12), block.number
        if code is None:
            return
        code = int(code)
        if code not in self.setup.offsets:
            if code != 54:
                raise _error(n, f"G{code}", f"a work offset of the machine file: [offsets] G{code}")
            self.note("G54", f"G54 (line {n}): no [offsets] G54 in the machine file, the "
                      "program's coordinates are read as the machine's")  # fmt: skip
        self.state.work = code

    def path_mode(self, block: _Block) -> None:
        code, n, p = block.code(13), block.number, block.params
        if code == 61:
            self.state.tolerance = 0.0
        elif code == 64:
            self.state.tolerance = math.nan
            if "P" in p:
                word = p.pop("P")
                if not word.value >= 0.0:
                    raise _error(n, word.text, "a path tolerance P >= 0")
                self.state.tolerance = word.value * self.unit
            if "Q" in p:
                p.pop("Q")
                self.skip("Q", n)

    # -- motion -------------------------------------------------------------------------
    def motion(self, block: _Block) -> None:
        st, n, p = self.state, block.number, block.params
        code = block.code(1)
        axes = {k: p.pop(k) for k in "XYZ" if k in p}
        turns = {k: p.pop(k) for k in "ABC" if k in p}
        for k in "UVW":
            if k in p:
                raise _error(n, p[k].text, "X, Y, Z (and A, B, C): parallel axes are not read")
        for k, word in turns.items():
            if k not in self.setup.rotary:
                allowed = (
                    f"a rotary axis of the machine file with its limits ([axes.{k}] "
                    "max_feed, max_acceleration, max_jerk)"
                )
                raise _error(n, word.text, allowed)
        home = block.code(0)
        if turns:
            motion = st.motion if block.code(1) is None else block.code(1)
            if home is not None or motion not in (0, 1):
                raise _error(n, next(iter(turns.values())).text, "A, B or C in a G0 or G1 "
                             "block (not with G2, G3, a cycle, G28, G30 or G53)")  # fmt: skip
            if block.code(1) is not None:
                self.set_motion(int(block.code(1)))  # type: ignore[arg-type]
            self.rotary_move(axes, turns, block)
            return
        if home in (28, 30):
            if code is not None and axes:
                raise _error(n, f"G{home} {block.g[1][1]}", "one code using the axis words "
                             "per block")  # fmt: skip
            self.home(int(home), axes, n)
            if code is not None:
                self.set_motion(int(code))
            return
        if code is not None:
            self.set_motion(int(code))
        if home == 53:
            self.machine_move(axes, block)
            return
        # G2/G3 with a centre and no axis word: a full circle back to where it starts (as
        # LinuxCNC reads it: 3dtest.ngc's 'g17 g02 i.5 j.5').
        full_circle = st.motion in (2, 3) and any(k in p for k in "IJK")
        if not axes and not full_circle:
            if code in _CYCLES:
                raise _error(n, block.g[1][1], "X, Y or Z with a canned cycle")
            return
        if st.motion in _CYCLES:
            self.cycle(st.motion, axes, block)
            return
        if st.motion is None or st.motion == 80:
            raise _error(n, next(iter(axes.values())).text, "a motion code (G0, G1, G2, G3 or "
                         "a cycle) before an axis word")  # fmt: skip
        target = self.target(axes)
        if st.motion in (0, 1):
            if any(k in p for k in "IJKR"):
                word = next(p[k] for k in "IJKR" if k in p)
                raise _error(n, word.text, "I, J, K or R only with G2, G3 or a cycle")
            if st.motion == 1 and st.feed is None:
                raise _error(n, "G1", "an F word before the first feed move")
            self.emit(RAPID if st.motion == 0 else FEED, n, target)
        else:
            if st.feed is None:
                raise _error(n, f"G{st.motion}", "an F word before the first feed move")
            centre = {k: p.pop(k).value for k in "IJKR" if k in p}
            c, sweep = self.arc(target, centre, n)
            a, b, _ = _PLANES[st.plane]
            self.used.update("XYZ"[i] for i in (a, b))
            self.emit(ARC, n, target, centre=c, sweep=sweep)

    def rotary_move(self, axes: dict[str, _Word], turns: dict[str, _Word], block: _Block) -> None:
        """A G0 or G1 that turns a rotary axis, with or without the linear ones."""
        st, n = self.state, block.number
        if any(k in block.params for k in "IJKR"):
            word = next(block.params[k] for k in "IJKR" if k in block.params)
            raise _error(n, word.text, "I, J, K or R only with G2, G3 or a cycle")
        if st.motion == 1 and st.feed is None:
            raise _error(n, "G1", "an F word before the first feed move")
        turn = list(st.rotary)
        for i, k in enumerate("ABC"):
            if k in turns:
                v = math.radians(turns[k].value)
                turn[i] = st.rotary[i] + v if st.incremental else v
        self.note("rotary", f"{', '.join(turns)} (rotary, line {n}): timed with the machine "
                  "file's limits, left out of the ball-screw energy")  # fmt: skip
        self.emit(RAPID if st.motion == 0 else FEED, n, self.target(axes), rotary=turn)

    def set_motion(self, code: int) -> None:
        st = self.state
        if code != st.motion:  # a new cycle needs its words again (RS274/NGC)
            st.cycle = {}
            if code not in _CYCLES:
                st.initial = None
        st.motion = code

    def target(self, axes: dict[str, _Word]) -> list[float]:
        """The machine position the axis words of a move name (G90 or G91)."""
        st, target = self.state, list(self.state.position)
        for i, k in enumerate("XYZ"):
            if k in axes:
                v = axes[k].value * self.unit
                target[i] = st.position[i] + v if st.incremental else v + self.offset(i)
        return target

    def machine_move(self, axes: dict[str, _Word], block: _Block) -> None:
        st, n = self.state, block.number
        if st.motion not in (0, 1):
            raise _error(n, "G53", "G53 with G0 or G1")
        if st.incremental:
            raise _error(n, "G53", "G53 under G90 (machine coordinates are absolute)")
        if any(k in block.params for k in "IJKR"):
            raise _error(n, "G53", "G53 with X, Y, Z only")
        target = list(st.position)
        for i, k in enumerate("XYZ"):
            if k in axes:
                target[i] = axes[k].value * self.unit
        self.emit(RAPID if st.motion == 0 else FEED, n, target)

    def home(self, code: int, axes: dict[str, _Word], n: int) -> None:
        """G28/G30: through the intermediate point to the reference position."""
        reference = self.setup.reference.get(code)
        if reference is None:
            raise _error(n, f"G{code}", f"a reference position: [reference] G{code} in the "
                         "machine file")  # fmt: skip
        if axes:
            self.emit(RAPID, n, self.target(axes))
        target = list(self.state.position)
        for i, k in enumerate("XYZ"):
            if axes and k not in axes:
                continue
            if k not in reference:
                if axes:
                    raise _error(n, axes[k].text, f"an axis of [reference] G{code}")
                continue
            target[i] = reference[k]
        self.emit(RAPID, n, target)

    def cycle(self, code: int, axes: dict[str, _Word], block: _Block) -> None:
        """A canned drilling cycle's moves (module docstring)."""
        st, n = self.state, block.number
        given, repeats = self._cycle_words(code, axes, block)
        x, y, step, r, bottom, clear, q = self._cycle_geometry(code, axes, n)
        dwell = self._cycle_dwell(code, given, n)

        def go(kind: int, z: float) -> None:
            self.emit(kind, n, [x, y, z], tolerance=0.0)

        if st.position[2] < r:  # below R: straight up first, where the tool is
            self.emit(RAPID, n, [*st.position[:2], r], tolerance=0.0)
        for _ in range(repeats):
            x, y = x + step[0], y + step[1]
            self.emit(RAPID, n, [x, y, st.position[2]], tolerance=0.0)
            go(RAPID, r)
            if code in (73, 83):
                depth = r - q
                while depth > bottom + 1e-12:  # 1 pm: a depth equal to Z is the last feed
                    go(FEED, depth)
                    if code == 83:
                        go(RAPID, r)
                    go(RAPID, depth + PECK_BACKOFF)
                    depth -= q
            go(FEED, bottom)
            if code in (82, 89):
                self.emit(DWELL, n, list(st.position), dwell=dwell)
            if code == 85:
                go(FEED, r)
            go(FEED if code == 89 else RAPID, clear)

    def _cycle_words(
        self, code: int, axes: dict[str, _Word], block: _Block
    ) -> tuple[dict[str, _Word], int]:
        """A cycle block's R, Q, P and L words (Fanuc's K as L), and its repeats.

        The modal Z, R, Q and P are kept in ``state.cycle``; the cycle needs the
        XY plane, a feed, and Z and R (Q for G73/G83, P for G82/G89) given in
        this block or an earlier one of the cycle.
        """
        st, n, p = self.state, block.number, block.params
        name = f"G{code}"
        if st.plane != 17:
            raise _error(n, name, "a canned cycle in G17 (the XY plane)")
        if st.feed is None:
            raise _error(n, name, "an F word before a canned cycle")
        given = {k: p.pop(k) for k in "RQPL" if k in p}
        if self.fanuc and "K" in p:  # Fanuc's count of repeats
            if "L" in given:
                raise _error(n, p["K"].text, "either K or L, the repeats")
            given["L"] = p.pop("K")
        if "Z" in axes:
            st.cycle["Z"] = axes["Z"].value
        for key in "RQP":
            if key in given:
                st.cycle[key] = given[key].value
        needs = "ZR" + ("Q" if code in (73, 83) else "") + ("P" if code in (82, 89) else "")
        for key in needs:
            if key not in st.cycle:
                raise _error(n, name, f"{key} in the cycle's first block ({name} needs "
                             f"{', '.join(needs)})")  # fmt: skip
        repeats = 1
        if "L" in given:
            repeats = int(given["L"].value)
            if repeats != given["L"].value or repeats < 1:
                raise _error(n, given["L"].text, "a number of repeats L >= 1")
        return given, repeats

    def _cycle_geometry(
        self, code: int, axes: dict[str, _Word], n: int
    ) -> tuple[float, float, list[float], float, float, float, float]:
        """Where a cycle drills, in m, in machine coordinates.

        Returns its first hole (x, y), the step between repeats (G91), the R
        plane, the hole's bottom, the height it clears to (G98/G99) and the peck
        depth; the first cycle of a run records the starting height.
        """
        st, u = self.state, self.unit
        name = f"G{code}"
        if st.initial is None:
            st.initial = st.position[2]
            if st.retract is None:
                self.note("G98", f"{name} (line {n}): no G98 or G99 before it, retract to the "
                          "starting height (G98)")  # fmt: skip
        if st.incremental:
            r = st.initial + st.cycle["R"] * u
            bottom = r + st.cycle["Z"] * u
            step = [axes[k].value * u if k in axes else 0.0 for k in "XY"]
            x, y = st.position[0], st.position[1]
        else:
            r = st.cycle["R"] * u + self.offset(2)
            bottom = st.cycle["Z"] * u + self.offset(2)
            step = [0.0, 0.0]
            x, y = (axes[k].value * u + self.offset(i) if k in axes else st.position[i]
                    for i, k in enumerate("XY"))  # fmt: skip
        if r < bottom:
            raise _error(n, f"R{st.cycle['R']:g}", f"R at or above the hole's bottom Z "
                         f"{st.cycle['Z']:g}")  # fmt: skip
        clear = r if st.retract == 99 else max(st.initial, r)
        q = st.cycle.get("Q", 0.0) * u
        if code in (73, 83) and not q > 0.0:
            raise _error(n, f"Q{st.cycle['Q']:g}", "a peck depth Q > 0")
        return x, y, step, r, bottom, clear, q

    def _cycle_dwell(self, code: int, given: dict[str, _Word], n: int) -> float:
        """The dwell at the hole's bottom [s] of G82/G89 (0 for the others)."""
        st, name = self.state, f"G{code}"
        dwell = 0.0
        if code in (82, 89):
            word = given.get("P", _Word("P", st.cycle["P"], f"P{st.cycle['P']:g}"))
            dwell, reading = self.dwell_seconds(word, n)
            if not dwell >= 0.0:
                raise _error(n, word.text, "a dwell >= 0")
            if dwell > LONG_DWELL:
                self.note(f"dwell {n}", f"{name} {word.text} (line {n}): a dwell of {dwell:g} s "
                          f"at each hole, {reading}")  # fmt: skip
        return dwell

    def arc(self, target: list[float], centre: dict[str, float], number: int
            ) -> tuple[list[float], float]:  # fmt: skip
        """The arc's centre and signed sweep angle (positive counter-clockwise, G3)."""
        st, unit, tolerance = self.state, self.unit, self.arc_tolerance
        a, b, n = _PLANES[st.plane]
        p0 = st.position
        x0, y0, x1, y1 = p0[a], p0[b], target[a], target[b]
        ccw = st.motion == 3
        if "R" in centre:
            if any(k in centre for k in "IJK"):
                raise _error(number, "R", "either R or I/J/K, not both")
            r = centre["R"] * unit
            chord = math.hypot(x1 - x0, y1 - y0)
            if chord == 0.0 or abs(r) == 0.0:
                raise _error(number, "R", "an arc with distinct end points (R cannot make a "
                             "circle)")  # fmt: skip
            if chord > 2.0 * abs(r) * (1.0 + 1e-9) + tolerance:
                raise _error(number, f"R{centre['R']:g}", f"a radius of at least half the "
                             f"chord ({chord / 2 / unit:.6g})")  # fmt: skip
            h = math.sqrt(max(r * r - chord * chord / 4.0, 0.0))
            mx, my = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
            ux, uy = -(y1 - y0) / chord, (x1 - x0) / chord  # left of the chord
            # The centre lies left of the chord for a counter-clockwise arc under 180°.
            side = 1.0 if ccw == (r > 0.0) else -1.0
            cx, cy = mx + side * h * ux, my + side * h * uy
        else:
            keys = [_CENTRE[a], _CENTRE[b]]
            if not any(k in centre for k in keys):
                raise _error(number, f"G{st.motion}", f"{keys[0]} and/or {keys[1]} (the centre "
                             f"offsets in G{st.plane}) or R")  # fmt: skip
            other = _CENTRE[n]
            if other in centre:
                raise _error(number, other, f"{keys[0]}, {keys[1]} in G{st.plane}")
            if st.centre_absolute:  # G90.1: the centre itself, in program coordinates
                cx = centre.get(keys[0], 0.0) * unit + self.offset(a)
                cy = centre.get(keys[1], 0.0) * unit + self.offset(b)
            else:
                cx = x0 + centre.get(keys[0], 0.0) * unit
                cy = y0 + centre.get(keys[1], 0.0) * unit
        r0, r1 = math.hypot(x0 - cx, y0 - cy), math.hypot(x1 - cx, y1 - cy)
        if r0 == 0.0:
            raise _error(number, "I/J/K", "a centre away from the start point")
        if abs(r1 - r0) > max(tolerance, 1e-3 * r0):
            raise _error(number, f"G{st.motion}", f"end point on the arc: radius "
                         f"{r1 / unit:.6g} at the end, {r0 / unit:.6g} at the start (tolerance "
                         f"{max(tolerance, 1e-3 * r0) / unit:.3g})")  # fmt: skip
        t0, t1 = math.atan2(y0 - cy, x0 - cx), math.atan2(y1 - cy, x1 - cx)
        sweep = (t1 - t0) % (2.0 * math.pi)
        if ccw:
            if sweep <= 1e-12:
                sweep = 2.0 * math.pi
        else:
            sweep = sweep - 2.0 * math.pi if sweep > 1e-12 else -2.0 * math.pi
        c = [math.nan] * 3
        c[a], c[b], c[n] = cx, cy, p0[n]
        return c, sweep


_USES = {
    "P": "G4, G64, G82 or G89", "Q": "G73, G83 or G64", "R": "G2, G3 or a cycle",
    "L": "a cycle", "I": "G2 or G3", "J": "G2 or G3", "K": "G2 or G3", "H": "G43",
    "D": "cutter radius compensation (not read)", "E": "no code (a lathe's thread lead)",
}  # fmt: skip


def _sinumerik(text: str) -> tuple[str, list[str]]:
    """A SINUMERIK program in RS274/NGC words, line for line, and the translation's notes."""
    import importlib

    name = f"{__package__}.sinumerik"
    try:
        module = importlib.import_module(name)
    except ModuleNotFoundError as exc:
        if exc.name != name:
            raise
        allowed = "rs274 or fanuc (this installation has no SINUMERIK translation)"
        raise BallScrewInputError("machine.dialect", "sinumerik", allowed) from None
    out: tuple[str, list[str]] = module.to_rs274(text)
    return out


def skipped_summary(skipped: Sequence[Skipped]) -> str:
    """One line for the words skipped: each with its count and first line, in order.

    Examples
    --------
    >>> skipped_summary([Skipped("S", 3), Skipped("M3", 3), Skipped("S", 9)])
    'skipped, no motion of the feed axes: S x2 (first line 3), M3 (line 3)'
    """
    first: dict[str, int] = {}
    count: dict[str, int] = {}
    for word, line in skipped:
        first.setdefault(word, line)
        count[word] = count.get(word, 0) + 1
    told = [
        f"{w} x{count[w]} (first line {first[w]})" if count[w] > 1 else f"{w} (line {first[w]})"
        for w in first
    ]
    return "skipped, no motion of the feed axes: " + ", ".join(told)


def read_program(text: str, *, arc_tolerance: float = 2e-6, start: Any = (0.0, 0.0, 0.0),
                 max_blocks: int | None = None, machine: Any = None) -> Program:  # fmt: skip
    """Read a part program into blocks in machine coordinates (module docstring).

    Parameters
    ----------
    text : str
        The program.
    arc_tolerance : float
        Largest difference of an arc's start and end radii [m]; 0.1 % of the
        radius is also accepted.
    start : sequence of 3 floats
        X, Y, Z at the start [m], machine coordinates.
    max_blocks : int, optional
        Refuse a program with more blocks of motion or dwell.
    machine : ballscrew.io.machine.Machine, optional
        Its dialect, tool change time, tool table, work offsets and reference
        positions (without one: RS274/NGC, and M6, G43 H, G55-G59, G28, G30 refused).

    Raises
    ------
    BallScrewInputError
        Naming ``program line N`` and the word: an unsupported word, two codes
        of one modal group, a feed move before any F, an arc whose radius does
        not fit its end points, a code the machine file gives no data for.
    """
    setup = _Setup.of(machine)
    reader = _Reader(setup, start, arc_tolerance)
    if text.startswith("\ufeff"):
        text = text[1:]
        reader.note("BOM", "a byte-order mark at the start: skipped")
    if setup.dialect == "sinumerik":
        text, extra = _sinumerik(text)
        for k, note in enumerate(extra):
            reader.note(f"sinumerik {k}", note)
    ended = False
    for number, raw in enumerate(program_lines(text), start=1):
        words = _words(raw, number)
        if not words:
            if raw.strip().startswith("%"):
                reader.skip("%", number)
            continue
        if ended:
            reader.note("after end", f"line {number} and on, after M2/M30: not run")
            break
        if any(w.letter == "O" for w in words):
            reader.skip("O", number)
            words = [w for w in words if w.letter != "O"]
            if not words:
                continue
        ended = reader.run(_block(words, number, reader.fanuc))
        if max_blocks is not None and len(reader.rows) > max_blocks:
            raise _error(number, f"{len(reader.rows)} blocks", f"at most {max_blocks} blocks")
    if not ended:
        reader.note("end", "no M2 or M30: the program ends at its last line")
    return program_from_rows(reader.rows, reader.notes, reader.used, text, reader.skipped)


def program_from_rows(
    rows: list[tuple[Any, ...]], notes: dict[str, str], used: set[str], text: str,
    skipped: Sequence[Skipped] = (),
) -> Program:  # fmt: skip
    """A :class:`Program` from its blocks, one tuple a block (the readers' common end).

    Each row is (kind, line, start, end, feed, centre, plane, sweep, dwell) in the
    order and units of :class:`Program`'s attributes, and optionally the blending
    tolerance and the rotary axes at the start and end (the built-in reader's);
    ``notes`` one note per key, the words ``skipped`` told first in one note.
    """
    n = len(rows)
    width = len(rows[0]) if rows else 9
    cols = list(zip(*rows, strict=True)) if rows else [()] * width
    more: dict[str, Any] = {}
    if width == 12:
        more = {"tolerance": np.array(cols[9], dtype=float),
                "rotary_start": np.array(cols[10], dtype=float).reshape(n, 3),
                "rotary_end": np.array(cols[11], dtype=float).reshape(n, 3)}  # fmt: skip
    return Program(
        kind=np.array(cols[0], dtype=int),
        line=np.array(cols[1], dtype=int),
        start=np.array(cols[2], dtype=float).reshape(n, 3),
        end=np.array(cols[3], dtype=float).reshape(n, 3),
        feed=np.array(cols[4], dtype=float),
        centre=np.array(cols[5], dtype=float).reshape(n, 3),
        plane=np.array(cols[6], dtype=int),
        sweep=np.array(cols[7], dtype=float),
        dwell=np.array(cols[8], dtype=float),
        axes=frozenset(used),
        notes=(skipped_summary(skipped),) * bool(skipped) + tuple(notes.values()),
        text=text,
        skipped=tuple(skipped),
        **more,
    )
