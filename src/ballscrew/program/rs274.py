r"""Reading a part program with LinuxCNC's RS274/NGC interpreter, ``rs274``.

LinuxCNC's interpreter is the reference implementation of RS274/NGC. Its
standalone form, ``rs274`` (Debian's ``linuxcnc-uspace``), runs a program in
batch mode (``rs274 -g``) and prints the *canonical machining commands* the
controller would execute, one a line. Everything the language offers
(subroutines, ``#`` parameters and expressions, loops, canned cycles, cutter
and tool-length compensation, work and ``G92`` offsets, ``G28``/``G30``) is
resolved by the interpreter; this module turns its output into the same
:class:`~ballscrew.program.gcode.Program` the built-in reader
(:func:`~ballscrew.program.gcode.read_program`) returns, so that planning
and energy run unchanged.

How the commands are taken:

- ``STRAIGHT_TRAVERSE`` and ``STRAIGHT_FEED`` are rapid and feed lines,
  ``ARC_FEED`` an arc or helix (its first and second coordinates are X, Y in
  ``G17``, Z, X in ``G18``, Y, Z in ``G19``, as the built-in reader orders
  the plane; a rotation count above one adds full turns), ``DWELL`` a dwell;
  a move that does not change the position is left out, as the built-in
  reader does;
- the rotary axes A, B, C of a straight move (printed in degrees, plus the
  angles of the work, ``G92`` and tool offsets) turn when the machine file
  gives their limits (``machine.rotary``), as the built-in reader reads them:
  timed with those limits, left out of the ball-screw energy; alone in a
  feed move, F is in degrees per minute, with X, Y or Z the linear path's
  feed;
- ``STRAIGHT_PROBE`` (``G38.2`` to ``G38.5``) is a feed move to its target,
  with a note: the probe not tripping, the longest the move can be. The
  interpreter itself goes on from the target (``rs274`` has no probe);
- ``CHANGE_TOOL`` (``M6``) is a dwell of the machine file's
  ``tool_change_time`` at the position, with a note, as the built-in reader
  takes ``M6``; without that time it is skipped with a note (no time);
- coordinates are printed in the program's units (``USE_LENGTH_UNITS``) and
  in program coordinates: they become machine coordinates as LinuxCNC's
  motion controller makes them, rotated by ``SET_XY_ROTATION`` and shifted
  by the work offset (``SET_G5X_OFFSET``), the ``G92`` offset and the tool
  length offset (``USE_TOOL_LENGTH_OFFSET``), each converted in the units in
  force when it was set;
- ``SET_FEED_RATE`` in units per minute (inverse-time feeds, ``G93``, come
  already converted by the interpreter); a feed per revolution (``G95``) or
  spindle-synchronised motion (``G33``, ``G76``: ``START_SPEED_FEED_SYNCH``)
  is timed at the feed per revolution times the programmed spindle speed,
  with a note; rigid tapping (``G33.1``, ``RIGID_TAP``) is a feed in and out at the
  thread's pitch times the spindle speed;
- skipped with one note per kind and its first line, as they do not move the
  feed axes: spindle and coolant commands, tool selection (``T``, ``M61``),
  path control modes (``G61``, ``G64``: the machine file's
  ``path_tolerance`` is used), program stops, messages and comments;
- refused with the line: a move of a rotary axis (A, B, C) the machine file
  gives no limits for, or in an arc, a spline (``NURBS_FEED``, which
  ``rs274`` prints without its data), an arc in a rotated plane other than
  XY or in the U, V, W planes, a feed per revolution without a spindle
  speed, and whatever the interpreter itself refuses (its message and the
  line).

Line numbers. ``rs274`` prints a block's ``N`` word, not its line in the
file. Each line of the program is therefore given an ``N`` word carrying its
line number (:data:`LINE_MARK` plus the line, replacing an ``N`` word the
line has) in a copy the interpreter reads; blank lines and ``%`` lines are
left as they are. A block run from a subroutine file outside the program
carries the line of the last block before it in the program.

Each run of ``rs274`` has a home folder of its own (``HOME``): the
interpreter maps its tool table into ``$HOME/.tool.mmap``, and two runs at
once sharing that file read each other's tools.

Print precision: ``rs274`` prints four decimals of the program's unit,
0.1 µm in ``G21`` and 2.5 µm (0.0001 in) in ``G20``: coordinates are
as exact as that.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import tempfile
import threading
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import BallScrewInputError
from ..io.files import program_lines
from .gcode import ARC, DWELL, FEED, RAPID, Program, program_from_rows, read_program

__all__ = [
    "LINE_MARK",
    "MOST_BLOCKS",
    "READERS",
    "TIMEOUT",
    "ReadProgram",
    "read_part_program",
    "read_program_rs274",
    "rs274_path",
]

READERS = ("auto", "builtin", "rs274")
"""The program readers: ``auto`` takes the built-in reader, and ``rs274`` when it refuses."""
TIMEOUT = 60.0
"""Longest run of ``rs274`` [s] before the program is refused (an endless loop)."""
MOST_BLOCKS = 1_000_000
"""The most blocks read when no bound is given (an endless loop of moves stops here)."""
LINE_MARK = 10_000_000
"""The ``N`` word given to line ``k`` of the program is ``LINE_MARK + k``."""

_UNITS = {"CANON_UNITS_MM": 1e-3, "CANON_UNITS_INCHES": 0.0254, "CANON_UNITS_CM": 1e-2}
_PLANES = {"CANON_PLANE_XY": 17, "CANON_PLANE_XZ": 18, "CANON_PLANE_YZ": 19}
_AXES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}
"""Plane -> (first, second, normal) indices of X, Y, Z, as ``ARC_FEED`` orders them."""
_CANON = re.compile(r"^\s*\d+\s+N(\d+|\.+)\s*([A-Z][A-Z0-9_]*)\((.*)\)\s*$")
_LEAD = re.compile(r"^(\s*/?\s*)(?:[Nn]\s*\d[\d ]*(?:\.\d*)?)?")
_MARKED = re.compile(rf"^\s*/?\s*N(\d{{{len(str(LINE_MARK))},}})\s?")
_LONGEST = 252
"""The longest line rs274 reads [characters]."""

_SKIPPED = {
    **dict.fromkeys(
        ("SET_SPINDLE_SPEED", "START_SPINDLE_CLOCKWISE", "START_SPINDLE_COUNTERCLOCKWISE",
         "STOP_SPINDLE_TURNING", "SET_SPINDLE_MODE", "ORIENT_SPINDLE",
         "WAIT_SPINDLE_ORIENT_COMPLETE", "SPINDLE_RETRACT", "SPINDLE_RETRACT_TRAVERSE"),
        ("spindle", "spindle commands (M3, M4, M5, M19, S)", "no motion of the feed axes"),
    ),
    **dict.fromkeys(
        ("MIST_ON", "MIST_OFF", "FLOOD_ON", "FLOOD_OFF"),
        ("coolant", "coolant (M7, M8, M9)", "no motion of the feed axes"),
    ),
    **dict.fromkeys(
        ("SELECT_TOOL", "CHANGE_TOOL_NUMBER", "RELOAD_TOOLDATA"),
        ("tool", "tool selection (T, M61)", "no motion of the feed axes"),
    ),
    "CHANGE_TOOL": ("M6", "tool change (M6)", "the feed axes stand still; its time is not "
                    "counted without [machine] tool_change_time"),
    **dict.fromkeys(
        ("SET_MOTION_CONTROL_MODE", "SET_NAIVECAM_TOLERANCE"),
        ("path", "path control mode (G61, G61.1, G64)",
         "the machine file's path_tolerance is used"),
    ),
    **dict.fromkeys(
        ("PROGRAM_STOP", "OPTIONAL_PROGRAM_STOP", "PALLET_SHUTTLE", "WAIT"),
        ("stop", "program stop, pallet shuttle or wait for an input (M0, M1, M60, M66)",
         "no time is counted"),
    ),
}  # fmt: skip
"""Canonical commands without motion of the feed axes -> (kind, what, note)."""
_QUIET = frozenset(
    ("COMMENT", "MESSAGE", "LOG", "LOGOPEN", "LOGAPPEND", "LOGCLOSE", "ON_RESET",
     "SET_FEED_REFERENCE", "SET_TRAVERSE_RATE", "START_CHANGE", "STOP_SPEED_FEED_SYNCH",
     "ENABLE_FEED_OVERRIDE", "DISABLE_FEED_OVERRIDE", "ENABLE_SPEED_OVERRIDE",
     "DISABLE_SPEED_OVERRIDE", "ENABLE_ADAPTIVE_FEED", "DISABLE_ADAPTIVE_FEED",
     "ENABLE_FEED_HOLD", "DISABLE_FEED_HOLD", "SET_BLOCK_DELETE", "SET_OPTIONAL_PROGRAM_STOP",
     "START_CUTTER_RADIUS_COMPENSATION", "STOP_CUTTER_RADIUS_COMPENSATION",
     "SET_CUTTER_RADIUS_COMPENSATION", "USE_NO_SPINDLE_FORCE", "TURN_PROBE_ON",
     "TURN_PROBE_OFF", "INIT_CANON", "SET_FEED_MODE_SYNCHED", "SET_PARAMETER_FILE_NAME")
)  # fmt: skip
"""Canonical commands that set nothing the motion of the feed axes depends on."""
_REFUSED = {
    "NURBS_FEED": "a spline (G5, G5.1, G5.2)",
    "SPLINE_FEED": "a spline (G5, G5.1, G5.2)",
}
"""Moves this reader does not turn into blocks -> what they are."""


def rs274_path() -> str | None:
    """Where ``rs274`` is on the PATH, or None."""
    return shutil.which("rs274")


@dataclass
class _State:
    """The interpreter's settings as its canonical commands set them (SI, radians)."""

    unit: float = 1e-3
    plane: int = 17
    feed: float | None = None  # the F word [m per minute, or per revolution under G95]
    per_revolution: bool = False
    synchronised: float | None = None  # feed per revolution [m] while synchronised
    spindle: float = 0.0  # [rev/s]
    surface_speed: bool = False
    rotation: float = 0.0
    g5x: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    g92: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    tool: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    position: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    rate: float = math.nan  # the F word as written (degrees per minute for A, B, C alone)
    rotary: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])  # A, B, C [rad]
    g5x_abc: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])  # [degrees]
    g92_abc: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    tool_abc: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    rotary_axes: frozenset[str] = frozenset()  # the rotary axes the machine file gives limits
    change_time: float | None = None  # the machine file's tool change time [s]
    line: int = 1
    own: bool = True  # the command comes from a line of the program (not a called file)
    command: str = ""
    ended: bool = False

    def machine(self, x: float, y: float, z: float) -> list[float]:
        """A point of the program [program units] in machine coordinates [m]."""
        u = self.unit
        c, s = math.cos(self.rotation), math.sin(self.rotation)
        p = [(x * c - y * s) * u, (x * s + y * c) * u, z * u]
        return [p[i] + self.g5x[i] + self.g92[i] + self.tool[i] for i in range(3)]

    def turn(self, a: float, b: float, c: float) -> list[float]:
        """A, B, C of the program [degrees] in machine coordinates [rad].

        The sum of the printed angle and its offsets is rounded to 1e-9 degrees, so
        that an offset taken back (40.1 - 40.1) leaves the axis where it was.
        """
        return [math.radians(round(v + self.g5x_abc[i] + self.g92_abc[i] + self.tool_abc[i],
                                   9)) for i, v in enumerate((a, b, c))]  # fmt: skip


def _error(line: int, text: str, allowed: str) -> BallScrewInputError:
    return BallScrewInputError(f"program line {line}", text, allowed)


def _line_text(lines: list[str], number: int) -> str:
    return lines[number - 1].strip() if 0 < number <= len(lines) else ""


def _refuse(state: _State, lines: list[str], allowed: str) -> BallScrewInputError:
    """A refusal naming the program line, or the command of a called file after it."""
    if state.own:
        return _error(state.line, _line_text(lines, state.line), allowed)
    return BallScrewInputError(f"a subroutine file called after program line {state.line}",
                               state.command, allowed)  # fmt: skip


def _marked(text: str) -> str:
    """The program with every line that has words given the N word of its line number."""
    out = []
    for number, raw in enumerate(program_lines(text), start=1):
        stripped = raw.strip()
        if not stripped or stripped.startswith("%"):
            out.append(raw)
            continue
        lead = _LEAD.match(raw)
        assert lead is not None  # the pattern matches the empty string
        marked = f"{lead.group(1)}N{LINE_MARK + number} {raw[lead.end() :]}"
        # rs274 takes lines of up to 252 characters: one the mark would push past that
        # keeps its text (its blocks carry the line before it).
        out.append(marked if len(marked) <= _LONGEST or len(raw) > _LONGEST else raw)
    return "\n".join(out) + "\n"


def _numbers(args: str, least: int = 1) -> list[float]:
    """The numbers of a command's arguments, in order: at least ``least``, all finite."""
    values = [float(v) for v in re.split(r"[,\s]+", args.strip()) if v]
    if len(values) < least or not all(math.isfinite(v) for v in values):
        raise IndexError(args)
    return values


def _feed(state: _State, lines: list[str], notes: dict[str, str]) -> float:
    """The path feed of a feed move [m/s]."""
    per_rev = state.synchronised if state.synchronised is not None else None
    if per_rev is None and state.per_revolution:
        per_rev = state.feed
    if per_rev is not None:
        what = "spindle-synchronised motion (G33, G76)" if state.synchronised is not None \
            else "a feed per revolution (G95)"  # fmt: skip
        if state.surface_speed:
            raise _refuse(state, lines, f"{what} at a constant spindle speed (G97): "
                          "under G96 the speed depends on the radius")  # fmt: skip
        if not state.spindle > 0.0 or not per_rev > 0.0:
            raise _refuse(state, lines, f"{what} with a spindle "
                         "speed S > 0 and a feed per revolution > 0")  # fmt: skip
        notes.setdefault("per rev", f"{what}, line {state.line}: timed at the feed per "
                         "revolution times the programmed spindle speed")  # fmt: skip
        return per_rev * state.spindle
    if state.feed is None or not state.feed > 0.0:
        raise _refuse(state, lines, "a feed move at a feed > 0")
    return state.feed / 60.0


def _rotary(state: _State, values: list[float], lines: list[str], rotary: frozenset[str],
            straight: bool = True) -> list[float]:  # fmt: skip
    """A, B, C at the end of a move (the values after X, Y, Z) [rad, machine coordinates].

    A rotary axis may turn in a straight move when the machine file gives its
    limits (``rotary``); in an arc, or without its limits, the move is refused.
    """
    turn = state.turn(*values[3:6])
    for k, a, b in zip("ABC", turn, state.rotary, strict=True):
        if a == b:
            continue
        if not straight:
            raise _refuse(state, lines, f"A, B or C in a straight move ({k} turns in an arc)")
        if k not in rotary:
            raise _refuse(state, lines, f"a rotary axis of the machine file with its limits "
                          f"([axes.{k}] max_feed, max_acceleration, max_jerk), or moves of X, "
                          f"Y and Z ({k} turns here)")  # fmt: skip
    return turn


def _row(
    state: _State, rows: list[tuple[Any, ...]], kind: int, end: list[float], feed: float, *,
    centre: list[float] | None = None, sweep: float = 0.0, dwell: float = 0.0,
    turn: list[float] | None = None,
) -> None:  # fmt: skip
    """A block from the current position to ``end``, in the built-in reader's row layout.

    The corner at its start is blended within the machine's path tolerance (NaN):
    rs274 prints no tolerance of its own for ``G64 P``.
    """
    turn = state.rotary if turn is None else turn
    rows.append((kind, state.line, state.position, end, feed, centre or [math.nan] * 3,
                 state.plane, sweep, dwell, math.nan, state.rotary, turn))  # fmt: skip
    state.position, state.rotary = end, turn


def _rotary_feed(state: _State, lines: list[str]) -> float:
    """The feed of a rotary axis turning alone [rad/s]: F in degrees per minute."""
    if state.per_revolution or state.synchronised is not None:
        raise _refuse(state, lines, "a rotary axis turning alone at a feed per minute (G94)")
    if not state.rate > 0.0:
        raise _refuse(state, lines, "a feed move at a feed > 0")
    return math.radians(state.rate) / 60.0


def _command(
    state: _State, name: str, args: str, lines: list[str], rows: list[tuple[Any, ...]],
    notes: dict[str, str], used: set[str],
) -> None:  # fmt: skip
    """One canonical command into the state and the blocks."""
    if name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "STRAIGHT_PROBE"):
        _straight(state, name, _numbers(args, 6), lines, rows, notes, used)
    elif name == "RIGID_TAP":
        _rigid_tap(state, _numbers(args, 3), lines, rows, notes, used)
    elif name == "ARC_FEED":
        _arc(state, _numbers(args, 9), lines, rows, notes, used)
    elif name == "DWELL":
        seconds = _numbers(args)[0]
        _row(state, rows, DWELL, state.position, math.nan, dwell=seconds)
    elif name == "CHANGE_TOOL" and state.change_time is not None:
        notes.setdefault("M6", f"tool change (M6), line {state.line}: {state.change_time:g} s "
                         "with the feed axes still (machine.tool_change_time)")  # fmt: skip
        _row(state, rows, DWELL, state.position, math.nan, dwell=state.change_time)
    elif name in ("PROGRAM_END", "FINISH"):
        state.ended = True
    elif _setting(state, name, args, lines, notes):
        pass
    elif name in _SKIPPED:
        _skip(state, name, notes)
    elif name in _REFUSED:
        raise _refuse(state, lines, f"lines, arcs and dwells ({_REFUSED[name]} is not read)")
    elif name not in _QUIET:
        notes.setdefault(name, f"{name} (LinuxCNC canonical command, line {state.line}): "
                         "skipped, not a motion of the feed axes")  # fmt: skip


def _straight(
    state: _State, name: str, v: list[float], lines: list[str], rows: list[tuple[Any, ...]],
    notes: dict[str, str], used: set[str],
) -> None:  # fmt: skip
    """A straight traverse, feed or probing move (``X, Y, Z, A, B, C``) into a block."""
    turn = _rotary(state, v, lines, state.rotary_axes)
    end = state.machine(v[0], v[1], v[2])
    if end == state.position and turn == state.rotary:
        return
    kind = RAPID if name == "STRAIGHT_TRAVERSE" else FEED
    if name == "STRAIGHT_PROBE":
        notes.setdefault("probe", f"a probing move (G38.2 to G38.5), line {state.line}: "
                         "run as a feed move to its target, the probe not tripping "
                         "(the longest the move can be; a probe that trips stops "
                         "it short)")  # fmt: skip
    if kind == RAPID:
        feed = math.nan
    elif end != state.position:
        feed = _feed(state, lines, notes)
    else:  # a rotary axis alone: F in degrees per minute
        feed = _rotary_feed(state, lines)
    used.update(k for k, a, b in zip("XYZ", end, state.position, strict=True) if a != b)
    turned = [k for k, a, b in zip("ABC", turn, state.rotary, strict=True) if a != b]
    if turned:
        used.update(turned)
        notes.setdefault("rotary", f"{', '.join(turned)} (rotary, line {state.line}): "
                         "timed with the machine file's limits, left out of the "
                         "ball-screw energy")  # fmt: skip
    _row(state, rows, kind, end, feed, turn=turn)


def _rigid_tap(
    state: _State, v: list[float], lines: list[str], rows: list[tuple[Any, ...]],
    notes: dict[str, str], used: set[str],
) -> None:  # fmt: skip
    """G33.1, rigid tapping: in and out at the thread's pitch per spindle turn.

    In to the point, then out to the start at the same pitch as the spindle reverses
    (LinuxCNC's motion controller).
    """
    bottom, top = state.machine(v[0], v[1], v[2]), state.position
    if state.synchronised is None:
        raise _refuse(state, lines, "rigid tapping with its pitch (K)")
    feed = _feed(state, lines, notes)
    notes.setdefault("tap", f"rigid tapping (G33.1), line {state.line}: in and out at "
                     "the pitch times the spindle speed; the spindle's reversal is not "
                     "timed")  # fmt: skip
    for b in (bottom, top) if bottom != top else ():
        _row(state, rows, FEED, b, feed)
    used.update(k for k, p, q in zip("XYZ", top, bottom, strict=True) if p != q)


def _setting(state: _State, name: str, args: str, lines: list[str], notes: dict[str, str]) -> bool:
    """A command that sets the state (feed, units, plane, offsets, rotation); whether it was."""
    if name == "SET_FEED_RATE":
        state.rate = _numbers(args)[0]
        state.feed = state.rate * state.unit
    elif name == "SET_FEED_MODE":
        v = _numbers(args)
        state.per_revolution = len(v) > 1 and v[-1] == 1.0
    elif name == "START_SPEED_FEED_SYNCH" or name == "START_SPEED_FEED_SYNC":
        state.synchronised = _numbers(args)[0] * state.unit
    elif name == "STOP_SPEED_FEED_SYNCH":
        state.synchronised = None
    elif name == "SET_SPINDLE_SPEED":
        state.spindle = _numbers(args)[-1] / 60.0
        _skip(state, name, notes)
    elif name == "SET_SPINDLE_MODE":
        v = _numbers(args)
        state.surface_speed = len(v) > 1 and v[-1] != 0.0
        _skip(state, name, notes)
    elif name == "USE_LENGTH_UNITS":
        if args.strip() not in _UNITS:
            raise _refuse(state, lines, f"millimetres, centimetres or inches (rs274 printed "
                          f"{state.command})")  # fmt: skip
        state.unit = _UNITS[args.strip()]
    elif name == "SELECT_PLANE":
        state.plane = _PLANES.get(args.strip(), 0)
    elif name in ("SET_G5X_OFFSET", "SET_G92_OFFSET", "USE_TOOL_LENGTH_OFFSET"):
        _offset(state, name, args)
    elif name == "SET_XY_ROTATION":
        state.rotation = math.radians(_numbers(args)[0])
    else:
        return False
    return True


def _offset(state: _State, name: str, args: str) -> None:
    """A work (G5x), G92 or tool-length offset: linear in the program's unit, rotary as is."""
    if name == "SET_G5X_OFFSET":
        v = _numbers(args, 4)
        state.g5x = [x * state.unit for x in v[1:4]]
        state.g5x_abc = [*v[4:7], 0.0, 0.0, 0.0][:3]
    elif name == "SET_G92_OFFSET":
        v = _numbers(args, 3)
        state.g92 = [x * state.unit for x in v[0:3]]
        state.g92_abc = [*v[3:6], 0.0, 0.0, 0.0][:3]
    else:
        v = _numbers(args, 3)
        state.tool = [x * state.unit for x in v[0:3]]
        state.tool_abc = [*v[3:6], 0.0, 0.0, 0.0][:3]


def _skip(state: _State, name: str, notes: dict[str, str]) -> None:
    kind, what, note = _SKIPPED[name]
    notes.setdefault(kind, f"{what}, line {state.line}: skipped, {note}")


def _arc(
    state: _State, v: list[float], lines: list[str], rows: list[tuple[Any, ...]],
    notes: dict[str, str], used: set[str],
) -> None:  # fmt: skip
    """``ARC_FEED(end 1, end 2, centre 1, centre 2, turns, normal end, A, B, C)`` into a block."""
    if state.plane not in _AXES or (state.plane != 17 and state.rotation != 0.0):
        raise _refuse(state, lines, "arcs in the XY, ZX or YZ "
                     "plane (an arc in a U, V, W plane or in a plane the XY rotation "
                     "turns is not read)")  # fmt: skip
    _rotary(state, [0.0, 0.0, 0.0, *v[6:9]], lines, state.rotary_axes, straight=False)
    a, b, n = _AXES[state.plane]
    end_p, centre_p = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    end_p[a], end_p[b], end_p[n] = v[0], v[1], v[5]
    centre_p[a], centre_p[b] = v[2], v[3]
    end = state.machine(*end_p)
    centre = state.machine(*centre_p)
    p0 = state.position
    centre[n] = p0[n]
    turns = int(v[4])
    t0 = math.atan2(p0[b] - centre[b], p0[a] - centre[a])
    t1 = math.atan2(end[b] - centre[b], end[a] - centre[a])
    base = (t1 - t0) % (2.0 * math.pi)
    if turns > 0:
        sweep = (base if base > 1e-12 else 2.0 * math.pi) + 2.0 * math.pi * (turns - 1)
    elif turns < 0:
        sweep = (base - 2.0 * math.pi if base > 1e-12 else -2.0 * math.pi) \
            - 2.0 * math.pi * (-turns - 1)  # fmt: skip
    else:
        raise _refuse(state, lines, "an arc of at least one turn "
                     "count (rs274 printed 0)")  # fmt: skip
    if math.hypot(p0[a] - centre[a], p0[b] - centre[b]) == 0.0:
        # A circle of radius 0 (cutter compensation with a tool as wide as the hole):
        # LinuxCNC moves along the normal axis only, a line.
        if end[a] != p0[a] or end[b] != p0[b]:
            raise _refuse(state, lines, "an arc whose centre is away from its start")
        if end != p0:
            notes.setdefault("radius 0", f"an arc of radius 0, line {state.line}: run as the "
                             "straight feed along its axis LinuxCNC makes of it")  # fmt: skip
            used.add("XYZ"[n])
            _row(state, rows, FEED, end, _feed(state, lines, notes))
        return
    feed = _feed(state, lines, notes)
    used.update("XYZ"[i] for i in (a, b))
    if end[n] != p0[n]:
        used.add("XYZ"[n])
    _row(state, rows, ARC, end, feed, centre=centre, sweep=sweep)


def _blocks(
    output: Iterable[str], lines: list[str], max_blocks: int | None, *,
    rotary: Iterable[str] = (), tool_change_time: float | None = None,
) -> tuple[list[tuple[Any, ...]], dict[str, str], set[str], _State]:  # fmt: skip
    """The canonical commands ``rs274`` printed, into blocks.

    ``rotary``: the rotary axes whose moves are read (the machine file's with
    limits); ``tool_change_time``: the time of a tool change [s] (None: not
    counted, with a note).
    """
    state = _State(rotary_axes=frozenset(rotary), change_time=tool_change_time)
    rows: list[tuple[Any, ...]] = []
    notes: dict[str, str] = {}
    used: set[str] = set()
    fresh: list[str] = []  # the notes the current line started
    for raw in output:
        match = _CANON.match(raw)
        if match is None:
            continue
        number, name, args = match.groups()
        state.own = number[0] != "." and int(number) > LINE_MARK
        if state.own and int(number) - LINE_MARK != state.line:
            state.line = int(number) - LINE_MARK
            fresh = []
        state.command = f"{name}({args})"
        if state.ended:
            continue
        known = len(notes)
        try:
            _command(state, name, args, lines, rows, notes, used)
        except BallScrewInputError:
            raise
        except (IndexError, ValueError):  # not the numbers the command takes
            raise _refuse(state, lines, "finite numbers in the command rs274 printed, "
                          f"{state.command}") from None  # fmt: skip
        fresh += list(notes)[known:]
        if name in ("PROGRAM_END", "FINISH"):
            # M2 and M30 stop the spindle and coolant and reset the modes: not the
            # program's own words, not noted.
            for key in fresh:
                if key in ("spindle", "coolant", "path"):
                    del notes[key]
        if max_blocks is not None and len(rows) > max_blocks:
            raise _error(state.line, f"{len(rows)} blocks", f"at most {max_blocks} blocks")
    return rows, notes, used, state


def _refusal(stderr: str, lines: list[str], last: int) -> BallScrewInputError:
    """The interpreter's complaint: its message, the line it names."""
    said = [s.strip() for s in stderr.splitlines() if s.strip() and s.strip() != "executing"]
    message = said[0] if said else "rs274 stopped without a message"
    number = last
    for s in said[1:]:
        mark = _MARKED.match(s)
        if mark is not None and int(mark.group(1)) > LINE_MARK:
            number = int(mark.group(1)) - LINE_MARK
            break
    hint = " (give a tool table with that tool: tool_table, --tool-table)" \
        if "tool table" in message else ""  # fmt: skip
    return _error(number, _line_text(lines, number),
                  f"what LinuxCNC's interpreter accepts; rs274 says: {message}{hint}")  # fmt: skip


def read_program_rs274(
    text: str,
    *,
    directory: str | Path | None = None,
    tool_table: str | Path | None = None,
    max_blocks: int | None = None,
    timeout: float = TIMEOUT,
    executable: str | None = None,
    machine: Any = None,
) -> Program:
    """Read a part program with LinuxCNC's ``rs274`` (module docstring).

    Parameters
    ----------
    text : str
        The program.
    directory : str or Path, optional
        Where ``rs274`` runs: subroutine files the program calls by name
        (``o<name> call``) are looked for there. The current folder if None.
    tool_table : str or Path, optional
        A LinuxCNC tool table (``-t``: ``T1 P1 Z0.511 D0.125`` lines), whose
        lengths and diameters the standalone ``rs274`` reads in inches. Without
        it ``rs274`` knows its own three sample tools.
    max_blocks : int, optional
        Refuse a program with more blocks of motion or dwell
        (:data:`MOST_BLOCKS` if None).
    timeout : float
        Longest run of ``rs274`` [s].
    executable : str, optional
        The ``rs274`` to run; the one on the PATH if None.
    machine : ballscrew.io.machine.Machine, optional
        Its rotary axes with limits (``machine.rotary``: their moves are read,
        another rotary axis's refused) and its tool change time (the time of
        each ``M6``; not counted without one, with a note).

    Returns
    -------
    Program
        Machine coordinates [m], one row per move or dwell, each with the
        line of the program it comes from.

    Raises
    ------
    BallScrewInputError
        ``reader`` when ``rs274`` is missing; ``program line N`` with
        ``rs274``'s message when the interpreter refuses the program, or
        with the command when it prints one this reader does not turn into
        blocks; ``program`` when ``rs274`` runs over ``timeout``.
    """
    exe = executable or rs274_path()
    if exe is None:
        raise BallScrewInputError("reader", "rs274", "LinuxCNC's rs274 on the PATH "
                                  "(Debian: apt-get install linuxcnc-uspace), or the built-in "
                                  "reader")  # fmt: skip
    if text.startswith("\ufeff"):
        text = text[1:]
    lines = program_lines(text)
    cwd = Path(directory) if directory is not None else Path.cwd()
    with tempfile.TemporaryDirectory(prefix="ballscrew-rs274-") as tmp:
        source = Path(tmp) / "program.ngc"
        source.write_text(_marked(text), encoding="utf-8")
        errors = Path(tmp) / "stderr.txt"
        command = [exe, "-g"]
        if tool_table is not None:
            table = Path(tool_table)
            if not table.is_file():
                raise BallScrewInputError("tool_table", str(table), "a readable LinuxCNC tool "
                                          "table file")  # fmt: skip
            command += ["-t", str(table.resolve())]
        # rs274 keeps its tool table in a file mapped into memory, $HOME/.tool.mmap: one
        # home a run, so that runs at the same time do not read each other's tools.
        command.append(str(source))
        with open(errors, "w", encoding="utf-8") as err:
            proc = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.PIPE, stderr=err, text=True,
                                    encoding="utf-8", errors="replace",
                                    env={**os.environ, "LC_ALL": "C", "HOME": tmp})  # fmt: skip
            timer = threading.Timer(timeout, proc.kill)
            timer.start()
            try:
                assert proc.stdout is not None
                bound = MOST_BLOCKS if max_blocks is None else max_blocks
                rows, notes, used, state = _blocks(
                    proc.stdout, lines, bound, rotary=getattr(machine, "rotary", {}),
                    tool_change_time=getattr(machine, "tool_change_time", None),
                )  # fmt: skip
            finally:
                if proc.poll() is None and not timer.finished.is_set():
                    proc.kill()
                if proc.stdout is not None:
                    proc.stdout.close()
                status = proc.wait()
                timed_out = timer.finished.is_set()
                timer.cancel()
        stderr = errors.read_text(encoding="utf-8", errors="replace")
    if timed_out and not state.ended:
        raise BallScrewInputError("program", f"still running after {timeout:g} s",
                                  "a program LinuxCNC's rs274 finishes (an endless "
                                  "loop?)")  # fmt: skip
    if status != 0 and not state.ended:
        if "File ended with no percent sign or program end" in stderr:
            notes["end"] = "no M2 or M30: the program ends at its last line"
        else:
            raise _refusal(stderr, lines, state.line)
    return program_from_rows(rows, notes, used, text)


@dataclass(frozen=True)
class ReadProgram:
    """A program read, the reader that read it and why that one.

    Attributes
    ----------
    program : Program
        The blocks.
    reader : str
        ``"builtin"`` or ``"rs274"``.
    reason : str
        One sentence: why this reader.
    """

    program: Program
    reader: str
    reason: str


def read_part_program(
    text: str,
    *,
    reader: str = "auto",
    arc_tolerance: float = 2e-6,
    max_blocks: int | None = None,
    directory: str | Path | None = None,
    tool_table: str | Path | None = None,
    machine: Any = None,
) -> ReadProgram:
    """Read a part program with the reader asked for, or the one that reads it.

    ``auto``: the built-in reader (:func:`~ballscrew.program.gcode.read_program`);
    when it refuses the program and ``rs274`` is on the PATH,
    :func:`read_program_rs274`. ``builtin`` and ``rs274`` take that reader
    only. ``arc_tolerance`` and ``machine`` (its dialect, tools, offsets and
    reference positions) are the built-in reader's; ``directory`` and
    ``tool_table`` are ``rs274``'s. A machine whose programs are in another
    dialect than RS274/NGC (``fanuc``, ``sinumerik``) is read by the built-in
    reader only: LinuxCNC's interpreter would read its words another way.

    Raises
    ------
    BallScrewInputError
        ``reader`` for another name or a missing ``rs274``; ``tool_table``
        with the built-in reader; the refusal of the reader that read last
        (``rs274``'s when it was tried).
    """
    if reader not in READERS:
        raise BallScrewInputError("reader", reader, f"one of {', '.join(READERS)}")
    if reader == "builtin" and tool_table is not None:
        raise BallScrewInputError("tool_table", str(tool_table), "a tool table only with the "
                                  "rs274 reader (the built-in reader reads no tool "
                                  "offsets)")  # fmt: skip

    dialect = getattr(machine, "dialect", "rs274")
    if reader == "rs274" and dialect != "rs274":
        raise BallScrewInputError("reader", reader, f"the built-in reader for a machine whose "
                                  f"programs are in the {dialect} dialect (machine.dialect): "
                                  "LinuxCNC's interpreter reads RS274/NGC")  # fmt: skip

    def builtin() -> Program:
        return read_program(text, arc_tolerance=arc_tolerance, max_blocks=max_blocks,
                            machine=machine)  # fmt: skip

    def rs274() -> Program:
        return read_program_rs274(text, directory=directory, tool_table=tool_table,
                                  max_blocks=max_blocks, machine=machine)  # fmt: skip

    if reader == "builtin":
        return ReadProgram(builtin(), "builtin", "the built-in reader, as asked (--reader)")
    if reader == "rs274":
        return ReadProgram(rs274(), "rs274", "LinuxCNC's rs274, as asked (--reader)")
    try:
        return ReadProgram(builtin(), "builtin", "the built-in reader reads it")
    except BallScrewInputError as exc:
        if rs274_path() is None or dialect != "rs274":
            raise
        refusal = f"{exc.field}, {exc.value!r}"
    try:
        program = rs274()
    except BallScrewInputError as exc:
        raise BallScrewInputError(exc.field, exc.value, f"{exc.allowed} (LinuxCNC's rs274 "
                                  f"read it after the built-in reader refused {refusal})"
                                  ) from None  # fmt: skip
    return ReadProgram(program, "rs274", f"LinuxCNC's rs274, on the PATH (the built-in reader "
                       f"refuses {refusal})")  # fmt: skip
