r"""Reading a part program (RS274/NGC G-code) into blocks of motion.

The words of each line are read by `gcodeparser
<https://pypi.org/project/gcodeparser/>`_ (maintained, pure Python, one
regular expression per line: a 10 000-line program reads in a fraction of a
second). gcodeparser is lenient: it passes over what it does not recognise
(a line without G, M or T, ``#1=5``, ``O100``, a parenthesised comment) and
truncates ``G91.1`` to ``G91``. So every line is first checked to be nothing
but words (a letter and a number) after its comments and block number are
taken off, and the words gcodeparser returns are counted against those of the
line: nothing is dropped without a note or an error.

What is read:

- ``G0`` (rapid), ``G1`` (feed), ``G2``/``G3`` (arcs clockwise and
  counter-clockwise seen from the positive end of the plane's normal) in
  ``G17`` (XY), ``G18`` (ZX) or ``G19`` (YZ), with ``I``/``J``/``K``
  (incremental centre offsets) or ``R`` (negative: the arc over 180°); the
  third axis may move (a helix);
- ``G4 P`` dwell, P in seconds (RS274/NGC and LinuxCNC; Fanuc's P is in
  milliseconds: write the seconds);
- ``G20``/``G21`` (inch, mm), ``G90``/``G91`` (absolute, incremental),
  ``G94`` (feed per minute, the only mode), ``F`` in mm/min or in/min;
- comments in parentheses or after ``;``, ``N`` block numbers, ``%``,
  ``O`` program numbers, ``M2``/``M30`` (the end);
- skipped with a note, since they do not move the feed axes: spindle,
  coolant and stop codes ``M0 M1 M3 M4 M5 M7 M8 M9``, ``S``, ``T`` (without
  ``M6``), and the cancel codes ``G40 G49 G80`` and the first work offset
  ``G54`` (the program's coordinates are read as the machine's).

Everything else (canned cycles, macros and variables, subprograms, tool
length and radius compensation, tool changes, other work offsets) is refused
with the line number and the word.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import BallScrewInputError, FloatArray

__all__ = ["ARC", "DWELL", "FEED", "RAPID", "Program", "program_from_rows", "read_program"]

RAPID, FEED, ARC, DWELL = 0, 1, 2, 3
"""Kinds of block."""

INCH = 0.0254
"""[m]."""

_COMMENT = re.compile(r"\([^()]*\)")
_WORDS = re.compile(r"\s*([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*")

_SKIP_M = {
    0: "program stop", 1: "optional stop", 3: "spindle on (CW)", 4: "spindle on (CCW)",
    5: "spindle off", 7: "mist coolant", 8: "flood coolant", 9: "coolant off",
}  # fmt: skip
_SKIP_G = {
    40: "cutter compensation off", 49: "tool length offset off", 80: "canned cycle off",
    54: "first work offset (coordinates read as the machine's)", 94: "feed per minute",
}  # fmt: skip
_REFUSED_G = {
    **{g: "a canned cycle" for g in (73, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89)},
    41: "cutter radius compensation", 42: "cutter radius compensation",
    43: "a tool length offset", 28: "a return to a reference point",
    30: "a return to a reference point", 53: "a move in machine coordinates",
    92: "a coordinate system offset", 61: "a path control mode", 64: "a path control mode",
    93: "inverse time feed", 95: "feed per revolution",
}  # fmt: skip
_PLANES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}
"""Plane code -> (first axis, second axis, normal axis) indices of X, Y, Z (G18: Z, X)."""
_CENTRE = {0: "I", 1: "J", 2: "K"}


@dataclass(frozen=True)
class Program:
    """A part program read into blocks (SI: m, m/s, s).

    One row per block of motion or dwell, in program order.

    Attributes
    ----------
    kind : numpy.ndarray of int
        :data:`RAPID`, :data:`FEED`, :data:`ARC` or :data:`DWELL`.
    line : numpy.ndarray of int
        Line number (1-based) of each block in the program text.
    start, end : numpy.ndarray, shape (n, 3)
        X, Y, Z at the block's start and end [m].
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
        What was skipped, one note per kind of word, with its first line.
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

    @property
    def size(self) -> int:
        """The number of blocks."""
        return int(self.kind.size)


def _error(line: int, word: str, allowed: str) -> BallScrewInputError:
    return BallScrewInputError(f"program line {line}", word, allowed)


def _words(text: str, number: int) -> tuple[str, list[tuple[str, float]]]:
    """The line without comments and block number, and its words; refused when not words."""
    if "(" in text or ")" in text:
        if text.count("(") != text.count(")"):
            raise _error(number, text.strip(), "balanced parentheses around a comment")
        text = _COMMENT.sub(" ", text)
        if "(" in text:
            raise _error(number, text.strip(), "comments not nested")
    text = text.split(";", 1)[0].strip().upper()
    if text in ("", "%"):
        return "", []
    words: list[tuple[str, float]] = []
    pos = 0
    while pos < len(text):
        match = _WORDS.match(text, pos)
        if match is None:
            bad = text[pos:].split()[0] if text[pos:].split() else text[pos:]
            raise _error(number, bad, "words of a letter and a number only (no macros, "
                         "variables, expressions or block delete)")  # fmt: skip
        words.append((match.group(1), float(match.group(2))))
        if match.group(1) in "GM" and "." in match.group(2):
            raise _error(number, match.group(1) + match.group(2), "a supported G or M code "
                         "(no decimal codes such as G91.1 or G64.1)")  # fmt: skip
        pos = match.end()
    kept = [(k, v) for k, v in words if k != "N"]
    # Codes first: gcodeparser attaches a parameter to the code before it (and passes over
    # one before any code); the parameters of a line are merged anyway.
    codes = [f"{k}{int(v)}" for k, v in kept if k in "GMT"]
    text = " ".join(codes + [f"{k}{v:.9f}" for k, v in kept if k not in "GMT"])
    return text, kept


def _parsed(text: str, words: list[tuple[str, float]], number: int) -> dict[str, Any]:
    """The line's words through gcodeparser: codes in order, parameters merged."""
    from gcodeparser import parse_gcode_lines

    codes: list[tuple[str, int]] = []
    params: dict[str, float] = {}
    count = 0
    for gline in parse_gcode_lines(text):
        letter, value = gline.command
        codes.append((letter, int(value if value is not None else -1)))
        count += 1
        for key, v in gline.params.items():
            if key in params or not isinstance(v, int | float) or isinstance(v, bool):
                raise _error(number, f"{key}{v}", "each word once per line")
            params[key] = float(v)
            count += 1
    if not codes:  # a line of parameters only (modal motion, F, S)
        for key, v in words:
            if key in params:
                raise _error(number, f"{key}{v:g}", "each word once per line")
            params[key] = v
            count += 1
    if count != len(words):  # gcodeparser passed over a word: say so rather than guess
        raise _error(number, text, "words the reader can take apart (one code per letter)")
    return {"codes": codes, "params": params}


@dataclass
class _State:
    position: list[float]
    inch: bool = False
    incremental: bool = False
    plane: int = 17
    motion: int | None = None
    feed: float | None = None


def read_program(text: str, *, arc_tolerance: float = 2e-6, start: Any = (0.0, 0.0, 0.0),
                 max_blocks: int | None = None) -> Program:  # fmt: skip
    """Read a part program into blocks (module docstring).

    Parameters
    ----------
    text : str
        The program.
    arc_tolerance : float
        Largest difference of an arc's start and end radii [m]; 0.1 % of the
        radius is also accepted.
    start : sequence of 3 floats
        X, Y, Z at the start [m].
    max_blocks : int, optional
        Refuse a program with more blocks of motion or dwell.

    Raises
    ------
    BallScrewInputError
        Naming ``program line N`` and the word: an unsupported word, a feed
        move before any F, an arc whose radius does not fit its end points.
    """
    state = _State(position=[float(v) for v in start])
    rows: list[tuple[Any, ...]] = []
    notes: dict[str, str] = {}
    used: set[str] = set()
    ended = False
    for number, raw in enumerate(text.splitlines(), start=1):
        cleaned, words = _words(raw, number)
        if not words:
            if raw.strip().startswith("%"):
                notes.setdefault("%", f"'%' (tape delimiter, line {number}): skipped")
            continue
        if ended:
            notes.setdefault("after end", f"line {number} and on, after M2/M30: not run")
            break
        if any(k == "O" for k, _ in words):
            notes.setdefault("O", f"O (program number, line {number}): skipped, no motion")
            words = [(k, v) for k, v in words if k != "O"]
            cleaned = " ".join(w for w in cleaned.split() if not w.startswith("O"))
            if not words:
                continue
        parsed = _parsed(cleaned, words, number)
        ended = _apply(state, parsed, number, rows, notes, used, arc_tolerance)
        if max_blocks is not None and len(rows) > max_blocks:
            raise _error(number, f"{len(rows)} blocks", f"at most {max_blocks} blocks")
    if not ended:
        notes.setdefault("end", "no M2 or M30: the program ends at its last line")
    return program_from_rows(rows, notes, used, text)


def program_from_rows(
    rows: list[tuple[Any, ...]], notes: dict[str, str], used: set[str], text: str
) -> Program:
    """A :class:`Program` from its blocks, one tuple a block (the readers' common end).

    Each row is (kind, line, start, end, feed, centre, plane, sweep, dwell) in the
    order and units of :class:`Program`'s attributes; ``notes`` one note per key.
    """
    n = len(rows)
    cols = list(zip(*rows, strict=True)) if rows else [()] * 9
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
        notes=tuple(notes.values()),
        text=text,
    )


def _codes(
    state: _State, codes: list[tuple[str, int]], number: int, notes: dict[str, str]
) -> tuple[bool, bool]:
    """A line's G, M and T codes into the state; (a dwell, the program's end)."""
    dwell = ended = False
    for letter, code in codes:
        word = f"{letter}{code}"
        if letter == "T":
            notes.setdefault("T", f"T (tool select, line {number}): skipped, no motion")
        elif letter == "M":
            if code in (2, 30):
                ended = True
            elif code in _SKIP_M:
                notes.setdefault(word, f"{word} ({_SKIP_M[code]}, line {number}): skipped, "
                                 "no motion of the feed axes")  # fmt: skip
            else:
                allowed = (
                    "M0, M1, M2, M3, M4, M5, M7, M8, M9 or M30 "
                    "(a tool change M6 or other M codes move or wait: not read)"
                )
                raise _error(number, word, allowed)
        elif code in (0, 1, 2, 3):
            state.motion = code
        elif code == 4:
            dwell = True
        elif code in (20, 21):
            state.inch = code == 20
        elif code in (90, 91):
            state.incremental = code == 91
        elif code in _PLANES:
            state.plane = code
        elif code in _SKIP_G:
            notes.setdefault(word, f"{word} ({_SKIP_G[code]}, line {number}): no motion")
        else:
            what = _REFUSED_G.get(code, "a code the reader does not support")
            raise _error(number, word, f"G0-G4, G17-G21, G40, G49, G54, G80, G90, G91, G94 "
                         f"({word} is {what})")  # fmt: skip
    return dwell, ended


def _apply(
    state: _State, parsed: dict[str, Any], number: int, rows: list[tuple[Any, ...]],
    notes: dict[str, str], used: set[str], arc_tolerance: float,
) -> bool:  # fmt: skip
    """Apply one line's codes and words to the state; add its block; True at the end."""
    params: dict[str, float] = dict(parsed["params"])
    dwell, ended = _codes(state, parsed["codes"], number, notes)
    unit = INCH if state.inch else 1e-3
    for key in ("S",):
        if params.pop(key, None) is not None:
            notes.setdefault(key, f"S (spindle speed, line {number}): skipped, no motion")
    if "F" in params:
        word = params.pop("F")
        feed = word * unit / 60.0
        if not feed > 0.0:  # the word as written, 'F-500'
            raise _error(number, f"F{word:g}", "a feed > 0 (mm/min under G21, in/min under G20)")
        state.feed = feed
    for rotary in "ABC":
        if rotary in params:
            raise _error(number, f"{rotary}{params[rotary]:g}", "X, Y or Z: rotary axes are "
                         "left out of the computation")  # fmt: skip
    if dwell:
        if "P" not in params or any(k in params for k in "XYZIJKR"):
            raise _error(number, "G4", "G4 P<seconds> alone on its line")
        seconds = params.pop("P")
        if not seconds >= 0.0:
            raise _error(number, f"P{seconds:g}", "a dwell >= 0 s")
        p = list(state.position)
        rows.append((DWELL, number, p, p, math.nan, [math.nan] * 3, state.plane, 0.0, seconds))
        return ended
    moves = {k: params.pop(k) for k in "XYZ" if k in params}
    centre = {k: params.pop(k) for k in "IJKR" if k in params}
    if params:
        key = next(iter(params))
        raise _error(number, f"{key}{params[key]:g}", "X, Y, Z, I, J, K, R, F, S or P with G4")
    if not moves and not centre:
        return ended
    if state.motion is None:
        raise _error(number, "X/Y/Z", "a motion code (G0, G1, G2 or G3) before the first move")
    target = list(state.position)
    for i, k in enumerate("XYZ"):
        if k in moves:
            target[i] = moves[k] * unit + (state.position[i] if state.incremental else 0.0)
            used.add(k)
    if state.motion in (0, 1):
        if centre:
            raise _error(number, next(iter(centre)), "I, J, K or R only with G2 or G3")
        if state.motion == 1 and state.feed is None:
            raise _error(number, "G1", "an F word before the first feed move")
        if target != state.position:
            kind = RAPID if state.motion == 0 else FEED
            feed = math.nan if kind == RAPID or state.feed is None else state.feed
            rows.append((kind, number, list(state.position), target, feed, [math.nan] * 3,
                         state.plane, 0.0, 0.0))  # fmt: skip
    else:
        if state.feed is None:
            raise _error(number, f"G{state.motion}", "an F word before the first feed move")
        c, sweep = _arc(state, target, centre, unit, number, arc_tolerance)
        a, b, _ = _PLANES[state.plane]
        used.update("XYZ"[i] for i in (a, b))
        rows.append((ARC, number, list(state.position), target, state.feed, c, state.plane,
                     sweep, 0.0))  # fmt: skip
    state.position = target
    return ended


def _arc(
    state: _State, target: list[float], centre: dict[str, float], unit: float, number: int,
    tolerance: float,
) -> tuple[list[float], float]:  # fmt: skip
    """The arc's centre and signed sweep angle (positive counter-clockwise, G3)."""
    a, b, n = _PLANES[state.plane]
    p0 = state.position
    x0, y0, x1, y1 = p0[a], p0[b], target[a], target[b]
    ccw = state.motion == 3
    if "R" in centre:
        if any(k in centre for k in "IJK"):
            raise _error(number, "R", "either R or I/J/K, not both")
        r = centre["R"] * unit
        chord = math.hypot(x1 - x0, y1 - y0)
        if chord == 0.0 or abs(r) == 0.0:
            raise _error(number, "R", "an arc with distinct end points (R cannot make a circle)")
        if chord > 2.0 * abs(r) * (1.0 + 1e-9) + tolerance:
            raise _error(number, f"R{centre['R']:g}", f"a radius of at least half the chord "
                         f"({chord / 2 / unit:.6g})")  # fmt: skip
        h = math.sqrt(max(r * r - chord * chord / 4.0, 0.0))
        mx, my = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
        ux, uy = -(y1 - y0) / chord, (x1 - x0) / chord  # left of the chord
        # The centre lies left of the chord for a counter-clockwise arc under 180°.
        side = 1.0 if ccw == (r > 0.0) else -1.0
        cx, cy = mx + side * h * ux, my + side * h * uy
    else:
        keys = [_CENTRE[a], _CENTRE[b]]
        if not any(k in centre for k in keys):
            raise _error(number, f"G{state.motion}", f"{keys[0]} and/or {keys[1]} (the centre "
                         f"offsets in G{state.plane}) or R")  # fmt: skip
        other = _CENTRE[n]
        if other in centre:
            raise _error(number, other, f"{keys[0]}, {keys[1]} in G{state.plane}")
        cx = x0 + centre.get(keys[0], 0.0) * unit
        cy = y0 + centre.get(keys[1], 0.0) * unit
    r0, r1 = math.hypot(x0 - cx, y0 - cy), math.hypot(x1 - cx, y1 - cy)
    if r0 == 0.0:
        raise _error(number, "I/J/K", "a centre away from the start point")
    if abs(r1 - r0) > max(tolerance, 1e-3 * r0):
        raise _error(number, f"G{state.motion}", f"end point on the arc: radius {r1 / unit:.6g} "
                     f"at the end, {r0 / unit:.6g} at the start (tolerance "
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
