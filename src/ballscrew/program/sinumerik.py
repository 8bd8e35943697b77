r"""SINUMERIK 840D part programs translated into the RS274/NGC the reader reads.

:func:`to_rs274` turns a SINUMERIK program (ISO dialect off, Siemens mode) into
RS274/NGC text, line by line: line *n* of the output is the translation of
line *n* of the input, so that every later error still names the user's own
line. What it translates, each as Siemens documents it ([1]_, [2]_, [3]_):

- ``;`` comments, ``N`` block numbers, the ``%_N_NAME_MPF`` and ``;$PATH=``
  header lines, ``MSG("…")`` messages (dropped, with a note);
- units: ``G71``/``G710`` metric (``G21``); ``G700`` inch with feeds in
  in/min (``G20``); ``G70`` inch for positions only, its feeds staying in the
  control's basic system, taken as metric (machine data
  ``MN_SCALING_SYSTEM_IS_METRIC = 1``, the delivery setting): each ``F`` is
  rewritten in in/min;
- ``G90``/``G91``, ``G94``, ``G17``/``G18``/``G19``, ``G40``, ``G0``–``G3``
  with ``I J K`` (incremental centre offsets, SINUMERIK's default as
  RS274/NGC's) or ``CR=`` (``R``; negative over 180°), axis words written
  ``X10`` or ``X=10``;
- ``G4 F<s>`` (``G4 P<s>``); ``G4 S<revolutions>`` at the programmed spindle
  speed (``G4 P``, with a note);
- work offsets: ``G54``–``G57`` as written, ``G505``/``G506`` (the 5th and
  6th settable offsets) as ``G58``/``G59``; ``G500`` (offsets off) before any
  offset is selected is noted and dropped; ``G53`` as written, ``G153`` and
  ``SUPA`` as ``G53`` (the reader has no base frames or handwheel offsets);
- tools: ``T1``/``T=1`` as written, ``T="name"`` numbered by first appearance
  (``T1``, ``T2``, …, with a note), ``M6``; ``D1``…``D9`` as ``G43 H<tool>``
  for a numbered tool, noted and dropped for a named one; ``D0`` as ``G49``;
- ``M0 M1 M2 M3 M4 M5 M6 M8 M9 M30`` as written, ``M17`` and ``RET`` (end of
  a subprogram run as a program) as ``M2``; ``S``;
- path modes: ``G60`` as ``G61``, ``G64`` and ``G641``–``G645`` as ``G64``
  (their own rounding tolerances are not carried over: the machine file's
  path tolerance applies); ``CYCLE832(_TOL, …)``, the high-speed settings, as
  ``G64 P<_TOL>`` (its compressor and dynamics settings are not modelled);
  ``G601``–``G603``, ``SOFT``, ``BRISK``, ``FFWON``, ``FFWOF``, ``COMPCAD``,
  ``COMPCURV``, ``COMPSURF``, ``COMPOF``, ``TRAFOOF``, ``STOPRE`` dropped with a
  note;
- rotary axes ``A``, ``B``, ``C`` (``B45`` or ``B=45``) as written: the
  reader takes them if the machine file lists them;
- the drilling cycles ``CYCLE81(RTP, RFP, SDIS, DP, DPR)`` and
  ``CYCLE82(RTP, RFP, SDIS, DP, DPR, DTB)``, called once at the current
  position or modally with ``MCALL CYCLE8x(…)`` … ``MCALL`` (see
  :func:`drilling_cycle`).

Everything else is refused with :class:`~ballscrew.errors.BallScrewInputError`
naming the line, the word and what is allowed: ``CYCLE83`` (its pecks, with
degression and the cycle's own anticipation distance, have no one-line
RS274/NGC equivalent), other cycles, R parameters, variables and expressions,
``AC()``/``IC()``, frames (``TRANS``, ``ROT``, …), subprogram calls, control
structures, radius compensation and the other G codes.

References
----------
.. [1] Siemens AG, *SINUMERIK 840D sl / 828D Fundamentals*, Programming Manual
   (6FC5398-1BP40): "Inch or metric dimensioning (G70/G700, G71/G710)",
   "Settable zero offset (G54 to G57, G505 to G599, G53, G500, SUPA, G153)",
   "Circular interpolation with radius (CR)", "Dwell time (G4)",
   "Tool change with M6", "Tool offset (D)", "Exact stop / continuous-path
   mode (G60, G64, G641 … G645)".
.. [2] Siemens AG, *SINUMERIK 840D sl / 828D Job Planning*, Programming Manual
   (6FC5398-2BP40): "Modal subprogram call (MCALL)", "Subprograms with SAVE
   mechanism" (a cycle restores the caller's G codes), "MSG".
.. [3] Siemens AG, *SINUMERIK 840D/840Di/810D Programming Guide Cycles (PGZ)*,
   11.02 edition, chapter 2 "Drilling cycles and drilling patterns":
   "Drilling, centering – CYCLE81", "Drilling, counterboring – CYCLE82",
   "Deep-hole drilling – CYCLE83", "Modal call of drilling cycles".
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..errors import BallScrewInputError
from ..io.files import program_lines

__all__ = ["DrillingCycle", "drilling_cycle", "to_rs274"]

_TOKEN = re.compile(
    r"""\s*(?:
      (?P<call>[A-Z_][A-Z0-9_]*)\s*\((?P<args>[^()"]*)\)
    | (?P<skey>[A-Z_][A-Z0-9_]*)\s*=\s*"(?P<str>[^"]*)"
    | (?P<key>[A-Z_][A-Z0-9_]*)\s*=\s*(?P<val>[-+]?(?:\d+\.?\d*|\.\d+))
    | (?P<letter>[A-Z])(?P<num>[-+]?(?:\d+\.?\d*|\.\d+))(?![=(])
    | (?P<name>[A-Z_][A-Z0-9_]*)(?!\s*[=(])
    )\s*""",
    re.X,
)
_MSG = re.compile(r'MSG\s*\(\s*(?:"[^"]*")?\s*\)', re.I)
_HEADER = re.compile(r"%_N_\w+_(?:MPF|SPF)\s*$", re.I)
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)$")

_PASS_G = {0, 1, 2, 3, 17, 18, 19, 40, 90, 91, 94}
"""G codes SINUMERIK and RS274/NGC write and mean alike."""
_PASS_M = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 30}
_AXES = "XYZABC"
_ALLOWED_G = (
    "G0-G4, G17-G19, G40, G53, G54-G57, G60, G64, G641-G645, G70, G71, G90, G91, G94, "
    "G153, G500, G505, G506, G601-G603, G700, G710"
)
_ALLOWED_WORDS = (
    "N, G, M, S, F, T, D, X, Y, Z, A, B, C, I, J, K, CR=, MCALL, SUPA, RET, "
    "CYCLE81(...), CYCLE82(...), CYCLE832(...)"
)
_DROPPED = {
    "STOPRE": "preprocessing stop", "SOFT": "jerk-limited acceleration: the machine file's "
    "limits apply", "BRISK": "acceleration without jerk limit: the machine file's limits "
    "apply", "FFWON": "feedforward", "FFWOF": "feedforward off", "COMPCAD": "compressor",
    "COMPCURV": "compressor", "COMPSURF": "compressor", "COMPOF": "compressor off",
    "TRAFOOF": "kinematic transformation off",
}  # fmt: skip
"""Keywords without motion of the feed axes or whose effect the planner has its own of."""
_TOL = 1e-9
"""[program unit] Two cycle heights closer than this are the same height."""


def _error(line: int, word: str, allowed: str) -> BallScrewInputError:
    return BallScrewInputError(f"program line {line}", word, allowed)


def _fmt(value: float) -> str:
    """A number as the reader's words take it: fixed point, no exponent, no '-0'."""
    text = f"{value:.9f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@dataclass(frozen=True)
class DrillingCycle:
    """One drilling cycle's heights along the tool axis [program unit] and dwell [s].

    Attributes
    ----------
    name : str
        ``CYCLE81`` or ``CYCLE82``.
    retraction : float
        RTP, where the tool is left.
    approach : float
        RFP + SDIS, reached at rapid traverse, where the feed starts.
    depth : float
        The final drilling depth, reached at the feed.
    dwell : float
        At the depth (CYCLE82's DTB) [s].
    """

    name: str
    retraction: float
    approach: float
    depth: float
    dwell: float


def _arguments(args: str, count: int, name: str, line: int) -> list[float]:
    """A cycle's arguments: an empty one is 0 (the cycles' own default); at most ``count``."""
    parts = [p.strip() for p in args.split(",")] if args.strip() else []
    if len(parts) > count:
        raise _error(line, f"{name}({args})", f"at most {count} parameters")
    values = []
    for part in parts:
        if part and not _NUMBER.match(part):
            raise _error(line, f"{name}({args})", "numbers or empty parameters (no "
                         "variables or expressions)")  # fmt: skip
        values.append(float(part) if part else 0.0)
    return values + [0.0] * (count - len(values))


def drilling_cycle(name: str, args: str, line: int = 0) -> DrillingCycle:
    """The moves of a SINUMERIK drilling cycle from its parameters, as Siemens documents them.

    ``CYCLE81(RTP, RFP, SDIS, DP, DPR)`` drills, ``CYCLE82(RTP, RFP, SDIS, DP,
    DPR, DTB)`` drills and dwells DTB seconds at the depth [1]_. From the position
    reached before the call (the hole's position in the plane), both

    1. approach the reference plane brought forward by the safety clearance,
       RFP + SDIS, at rapid traverse (G0);
    2. drill to the final depth at the feed programmed before the call (G1);
    3. (CYCLE82) dwell DTB seconds;
    4. retract to the retraction plane RTP at rapid traverse (G0).

    The depth is DP (absolute), or RFP − DPR when DPR (relative, without sign)
    is given: the manual has DPR win when both are. An empty parameter is 0.
    This follows the 11.02 edition's parameter lists. The later SINUMERIK
    Operate form (840D sl) appends DTB to CYCLE81 and ``_GMODE, _DMODE,
    _AMODE`` to both: a DTB is taken (CYCLE81 then dwells as CYCLE82); the
    modes are read only where they keep the 11.02 meaning (``_GMODE`` 0: the
    depth at the drill's tip; ``_DMODE`` 0 or 1: the plane active before the
    call, or G17; ``_AMODE`` 0 or 10: DP and DPR as written, DTB in seconds),
    other values are refused.

    Parameters
    ----------
    name : str
        ``CYCLE81`` or ``CYCLE82`` (case-insensitive).
    args : str
        The text between the parentheses, ``"10,0,2,-15,"``.
    line : int
        The program line, for the errors.

    Returns
    -------
    DrillingCycle

    Raises
    ------
    BallScrewInputError
        A negative SDIS, DPR or DTB; a depth not below RFP + SDIS; a
        retraction plane below RFP + SDIS (no RS274/NGC cycle retracts below
        its R; below RFP the manual's cycle stops with alarm 61101); a mode
        that changes the parameters' meaning.

    References
    ----------
    .. [1] Siemens AG, *SINUMERIK 840D/840Di/810D Programming Guide Cycles (PGZ)*,
       11.02 edition, chapter 2: "Drilling, centering – CYCLE81", "Drilling,
       counterboring – CYCLE82".

    Examples
    --------
    >>> drilling_cycle("CYCLE81", "10,0,2,-15,")
    DrillingCycle(name='CYCLE81', retraction=10.0, approach=2.0, depth=-15.0, dwell=0.0)
    >>> drilling_cycle("CYCLE82", "110, 102, 4, , 75, 2").depth  # DPR 75 below RFP 102
    27.0
    """
    name = name.upper()
    if name not in ("CYCLE81", "CYCLE82"):
        raise _error(line, name, "CYCLE81 or CYCLE82")
    rtp, rfp, sdis, dp, dpr, dtb, gmode, dmode, amode = _arguments(args, 9, name, line)
    word = f"{name}({args})"
    if gmode != 0.0 or dmode not in (0.0, 1.0) or amode not in (0.0, 10.0):
        raise _error(line, word, "_GMODE empty or 0 (depth at the drill's tip), _DMODE empty, "
                     "0 or 1 (the plane before the call, or G17), _AMODE empty, 0 or 10 (DP and "
                     "DPR as written, DTB in seconds): other modes change what the parameters "
                     "mean")  # fmt: skip
    if sdis < 0.0 or dpr < 0.0:
        raise _error(line, word, "SDIS and DPR without sign (>= 0)")
    if dtb < 0.0:
        raise _error(line, word, "DTB >= 0 s (a negative DTB counts spindle revolutions in "
                     "SINUMERIK Operate: not read)")  # fmt: skip
    depth = rfp - dpr if dpr != 0.0 else dp
    approach = rfp + sdis
    if not depth < approach:
        raise _error(line, word, f"a final depth ({_fmt(depth)}) below RFP + SDIS "
                     f"({_fmt(approach)}): drilling towards the negative tool axis")  # fmt: skip
    if rtp < approach - _TOL:
        raise _error(line, word, f"RTP ({_fmt(rtp)}) at or above RFP + SDIS "
                     f"({_fmt(approach)}): no RS274/NGC cycle retracts below its R (and "
                     "below RFP the cycle itself stops, alarm 61101)")  # fmt: skip
    return DrillingCycle(name, rtp, approach, depth, dtb)


_Item = tuple[str, str, str, float]
"""One word of a line: (kind, key, value as written, number)."""
_GROUP1 = frozenset({"G0", "G1", "G2", "G3", "G80", "G81", "G82"})
"""RS274/NGC's motion codes the translation writes."""


@dataclass
class _State:
    inch: bool = False
    feed_inch: bool = False
    incremental: bool = False
    plane: int = 17
    motion: int | None = None
    z: float | None = None  # tool-axis position [mm] in program coordinates, when known
    offset: str = ""
    tool: int | None = None
    names: dict[str, int] = field(default_factory=dict)
    spindle: float | None = None
    mcall: DrillingCycle | None = None
    units: bool = False  # a G70, G71, G700 or G710 was seen
    restore: int = 0  # the line of a cycle call whose next line restates the motion mode
    notes: dict[str, tuple[str, int]] = field(default_factory=dict)
    counts: dict[str, int] = field(default_factory=dict)

    def note(self, key: str, text: str, line: int) -> None:
        self.notes.setdefault(key, (text, line))
        self.counts[key] = self.counts.get(key, 0) + 1


def _tokens(raw: str, line: int, state: _State) -> tuple[list[_Item], bool]:
    """The words of a line (comments, header, MSG taken off); True when it is a header."""
    text, quoted = "", False
    for ch in raw:
        if ch == '"':
            quoted = not quoted
        elif ch == ";" and not quoted:
            break
        text += ch
    text = text.strip()
    if text.startswith("%"):
        if _HEADER.match(text):
            state.note("header", f"{text} (program header): dropped", line)
        else:
            state.note("%", f"'{text}' (tape start): dropped", line)
        return [], True
    if _MSG.search(text):
        state.note("MSG", "MSG(...) (a message on the screen): dropped", line)
        text = _MSG.sub(" ", text).strip()
    parts = text.split('"')
    text = '"'.join(p if i % 2 else p.upper() for i, p in enumerate(parts))
    if text.startswith("/"):
        raise _error(line, "/", "no block skip ('/' switches lines on the operator panel)")
    tokens: list[_Item] = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            bad = text[pos:].split()[0] if text[pos:].split() else text[pos:]
            raise _error(line, bad, f"SINUMERIK words the translation reads "
                         f"({_ALLOWED_WORDS}); no R parameters, variables, expressions, "
                         "AC()/IC() or labels")  # fmt: skip
        if m.group("call"):
            tokens.append(("call", m.group("call"), m.group("args"), 0.0))
        elif m.group("skey"):
            tokens.append(("string", m.group("skey"), m.group("str"), 0.0))
        elif m.group("key"):
            tokens.append(("word", m.group("key"), m.group("val"), float(m.group("val"))))
        elif m.group("letter"):
            tokens.append(("word", m.group("letter"), m.group("num"),
                                 float(m.group("num"))))  # fmt: skip
        else:
            tokens.append(("name", m.group("name"), "", 0.0))
        pos = m.end()
    return tokens, False


def to_rs274(text: str) -> tuple[str, list[str]]:
    r"""Translate a SINUMERIK 840D part program into RS274/NGC, line for line.

    The output has one line per input line (the translation of that line, or an
    empty line), so that the reader's errors name the user's own lines. Module
    docstring: what is translated, what is refused, the sources.

    Parameters
    ----------
    text : str
        The SINUMERIK program.

    Returns
    -------
    tuple of (str, list of str)
        The RS274/NGC program, and the notes: what was translated, dropped or
        assumed, one per kind, with its first line and how many lines had it.

    Raises
    ------
    BallScrewInputError
        Naming ``program line N``, the word and what is allowed.

    Examples
    --------
    >>> rs274, notes = to_rs274('G710 G57 ; part zero\nT="DRILL_8" M6\nG0 X10 Y20 Z10 B=45\n')
    >>> print(rs274)
    G21 G57
    T1 M6
    G0 X10 Y20 Z10 B45
    <BLANKLINE>
    """
    state = _State()
    if text.startswith("\ufeff"):
        text = text[1:]
        state.note("BOM", "a byte-order mark at the start: dropped", 1)
    out = [_line(raw, number, state) for number, raw in enumerate(program_lines(text), start=1)]
    if not state.units and any(out):
        state.note("units", "no G70, G71, G700 or G710: millimetres and mm/min, the basic "
                   "system taken as metric (the delivery setting)", 1)  # fmt: skip
    notes = []
    for key, (what, first) in state.notes.items():
        count = state.counts[key]
        notes.append(f"{what}: line {first}" + (f" (and {count - 1} more)" if count > 1 else ""))
    return "\n".join(out) + ("\n" if out else ""), notes


def _line(raw: str, number: int, state: _State) -> str:
    """One line's translation (the state carries the modes across lines)."""
    tokens, header = _tokens(raw, number, state)
    items = [t for t in tokens if not (t[0] == "word" and t[1] == "N")]
    calls = [t for t in items if t[0] == "call"]
    if calls or any(t[0] == "name" and t[1] == "MCALL" for t in items):
        words = _cycle_line(items, number, state)
    elif header or not items:
        words = []
    else:
        words = _words(items, number, state)
    if state.restore and state.restore != number:
        # A cycle restores its caller's G codes [2]; in RS274/NGC the G81 mode stays on.
        if not _GROUP1.intersection(words):
            words.insert(0, f"G{state.motion}" if state.motion is not None else "G80")
        state.restore = 0
    return " ".join(words)


def _cycle_line(
    items: list[_Item], number: int, state: _State
) -> list[str]:  # fmt: skip
    """A line with a cycle call or MCALL: alone in its block [2]."""
    others = [t for t in items if not (t[0] == "call" or (t[0] == "name" and t[1] == "MCALL"))]
    calls = [t for t in items if t[0] == "call"]
    modal = any(t[0] == "name" and t[1] == "MCALL" for t in items)
    if others or len(calls) > 1:
        bad = others[0] if others else calls[1]
        raise _error(number, bad[1], "a cycle call or MCALL alone in its block (with its N "
                     "number and comment)")  # fmt: skip
    if not calls:  # MCALL alone: the modal call ends
        if state.mcall is None:
            state.note("MCALL off", "MCALL with no modal call active: nothing to end", number)
            return []
        state.mcall = None
        state.note("MCALL end", "MCALL (end of the modal cycle call): the cycle mode ends "
                   "(the motion mode before it again)", number)  # fmt: skip
        return [f"G{state.motion}" if state.motion is not None else "G80"]
    _, name, args, _ = calls[0]
    if name == "CYCLE832":
        if modal:
            raise _error(number, "MCALL", "CYCLE832 without MCALL (it sets, it does not drill)")
        return _cycle832(args, number, state)
    if name == "CYCLE83":
        raise _error(number, f"CYCLE83({args})", "CYCLE81 or CYCLE82: CYCLE83's pecks "
                     "(degression, feed factor, the cycle's own anticipation distance) have no "
                     "one-line RS274/NGC equivalent; write them as G0/G1/G4 lines")  # fmt: skip
    if name not in ("CYCLE81", "CYCLE82"):
        raise _error(number, f"{name}({args})", "the drilling cycles CYCLE81 or CYCLE82 (other "
                     "cycles and subprogram calls are not read)")  # fmt: skip
    cycle = drilling_cycle(name, args, number)
    if state.mcall is not None:
        raise _error(number, name, "MCALL (end of the modal call) before another cycle call")
    if state.plane != 17:
        raise _error(number, name, f"G17 at the cycle call (tool along Z), not G{state.plane}")
    if state.incremental:
        raise _error(number, name, "G90 at the cycle call (the cycle's planes are absolute; "
                     "G91 would make RS274/NGC's R and Z incremental)")  # fmt: skip
    if modal:
        state.mcall = cycle
        state.note("MCALL", f"MCALL {name}(...) (modal cycle call): drilled after each X/Y "
                   "position that follows, as G81/G82 with R at RFP + SDIS and the retraction "
                   "at RTP", number)  # fmt: skip
        return []
    words = _drill(cycle, [], number, state)
    state.restore = number
    return words


def _drill(cycle: DrillingCycle, position: list[str], number: int, state: _State) -> list[str]:
    """The RS274/NGC canned cycle whose moves are the SINUMERIK cycle's, from here."""
    unit = 25.4 if state.inch else 1.0
    if abs(cycle.retraction - cycle.approach) <= _TOL:
        retract = "G99"  # back to R, which is RTP: any start height gives the same moves
    elif state.z is not None and abs(state.z / unit - cycle.retraction) <= _TOL:
        retract = "G98"  # back to the start height, which is RTP
    else:
        at = "not known" if state.z is None else _fmt(state.z / unit)
        raise _error(number, cycle.name, f"the tool axis at RTP (Z{_fmt(cycle.retraction)}) "
                     f"before the cycle (it is at {at} here; after a tool change, an offset or "
                     "D change, program Z again), or RTP = RFP + SDIS: the RS274/NGC cycle "
                     "retracts to its start height or to R")  # fmt: skip
    below = state.z is None or state.z / unit < cycle.approach - _TOL
    if position and retract == "G99" and below:
        # RS274/NGC first lifts to R, then moves in the plane; SINUMERIK moves first.
        raise _error(number, "X/Y", f"the tool axis at or above RFP + SDIS "
                     f"(Z{_fmt(cycle.approach)}) before the first position under "
                     "MCALL")  # fmt: skip
    code = "G81" if cycle.dwell == 0.0 else "G82"
    words = [retract, code, *position, f"Z{_fmt(cycle.depth)}", f"R{_fmt(cycle.approach)}"]
    if cycle.dwell:
        words.append(f"P{_fmt(cycle.dwell)}")
    state.note(cycle.name, f"{cycle.name} (drilling cycle): rapid to RFP + SDIS, feed to the "
               "depth, rapid to RTP, read as " + " ".join(w for w in words if w not in position)
               + (f" (a dwell of {_fmt(cycle.dwell)} s at the depth)" if cycle.dwell else ""),
               number)  # fmt: skip
    state.z = cycle.retraction * unit
    return words


def _g_codes(codes: list[tuple[int, str]], number: int, state: _State) -> tuple[list[str], bool]:
    """A line's G codes into the state; their RS274/NGC words, and whether G4 is among them."""
    out: list[str] = []
    dwell = False
    for code, text in codes:
        word = f"G{text}"
        if code in (70, 71, 700, 710):
            state.units = True
            state.inch = code in (70, 700)
            state.feed_inch = code == 700
            out.append("G20" if state.inch else "G21")
            what = {70: "inch positions, feeds in mm/min (metric basic system): F rewritten "
                    "in in/min", 71: "metric", 700: "inch, feeds in in/min",
                    710: "metric, feeds in mm/min"}[code]  # fmt: skip
            state.note(f"G{code}", f"G{code} ({what}): read as {out[-1]}", number)
        elif code == 4:
            dwell = True
        elif code in (54, 55, 56, 57, 505, 506):
            state.offset = word
            state.z = None
            out.append({505: "G58", 506: "G59"}.get(code, word))
            if code > 57:
                state.note(word, f"{word} (settable work offset {code - 500}): read as "
                           f"{out[-1]}, RS274/NGC's {code - 500}th", number)  # fmt: skip
        elif code == 500:
            if state.offset not in ("", "G500"):
                raise _error(number, word, f"G500 (offsets off) only before any work offset: "
                             f"after {state.offset} RS274/NGC has no code that switches it off "
                             "(select G54 with a zero offset)")  # fmt: skip
            state.offset = word
            state.note(word, "G500 (settable offsets off) before any offset: dropped, the "
                       "coordinates stay in the reader's starting work offset (G54: zero "
                       "unless the machine file's [offsets] sets it)", number)  # fmt: skip
        elif code in (53, 153):
            out.append("G53")
            if code == 153:
                state.note(word, "G153 (machine coordinates, base frames suppressed too): read "
                           "as G53 (the reader has no base frames)", number)  # fmt: skip
        elif code in (601, 602, 603):
            state.note(word, f"{word} (when an exact stop ends): dropped, the planner stops "
                       "exactly", number)  # fmt: skip
        elif code == 60:
            out.append("G61")
            state.note(word, "G60 (exact stop): read as G61", number)
        elif code in (64, 641, 642, 643, 644, 645):
            out.append("G64")
            if code != 64:
                state.note(word, f"{word} (continuous path with rounding): read as G64, the "
                           "machine file's path tolerance", number)  # fmt: skip
        elif code in _PASS_G:
            if code <= 3:
                state.motion = code
            elif code in (90, 91):
                state.incremental = code == 91
            elif code in (17, 18, 19):
                state.plane = code
            out.append(f"G{code}")  # 'G00' as 'G0'
        else:
            raise _error(number, word, _ALLOWED_G)
    return out, dwell


def _words(items: list[_Item], number: int, state: _State) -> list[str]:
    """An ordinary line (no cycle call) into RS274/NGC words."""
    codes: list[tuple[int, str]] = []
    for kind, key, text, value in items:
        if kind == "word" and key == "G":
            if "." in text or value < 0:
                raise _error(number, f"G{text}", _ALLOWED_G)
            codes.append((int(value), text.lstrip("+")))
    out, dwell = _g_codes(codes, number, state)
    words: dict[str, tuple[str, float]] = {}
    tail: list[str] = []
    machine = any(w == "G53" for w in out)
    for kind, key, text, value in items:
        if kind == "word" and key == "G":
            continue
        if kind == "name":
            if key == "SUPA":
                out.append("G53")
                machine = True
                state.note("SUPA", "SUPA (all offsets suppressed): read as G53", number)
            elif key == "RET":
                tail.append("M2")
                state.note("RET", "RET (end of a subprogram): read as M2", number)
            elif key in _DROPPED:
                state.note(key, f"{key} ({_DROPPED[key]}): dropped", number)
            else:
                raise _error(number, key, f"SINUMERIK words the translation reads "
                             f"({_ALLOWED_WORDS}); no frames, control structures, "
                             "subprogram calls or other keywords")  # fmt: skip
            continue
        if kind == "string":
            if key != "T":
                raise _error(number, f'{key}="{text}"', 'T="name" (the only text word read)')
            tool = state.names.setdefault(text, len(state.names) + 1)
            state.tool = None  # a named tool has no number for a tool table
            tail.append(f"T{tool}")
            state.note(f"T={text}", f'T="{text}" (tool by name): read as T{tool} (named tools '
                       "are numbered in order of first appearance)", number)  # fmt: skip
            continue
        if key in words:
            raise _error(number, f"{key}{text}", "each word once per line")
        if key not in ("X", "Y", "Z", "A", "B", "C", "I", "J", "K", "CR", "F", "S", "T", "D",
                       "M"):  # fmt: skip
            raise _error(number, f"{key}{'=' if len(key) > 1 else ''}{text}", "SINUMERIK words "
                         f"the translation reads ({_ALLOWED_WORDS}; no extended addresses such "
                         "as Z1= or M1=)")  # fmt: skip
        if key == "M":
            if "." in text or value < 0:
                raise _error(number, f"M{text}", "M0-M9, M17 or M30")
            tail.extend(_m_code(int(value), text, number, state))
            continue
        words[key] = (text.lstrip("+"), value)
    if dwell:
        return out + _dwell(words, number, state) + tail
    if "T" in words:
        t, v = words.pop("T")
        if v < 0 or v != int(v):
            raise _error(number, f"T{t}", 'a tool number >= 0 or T="name"')
        state.tool = int(v)
        tail.insert(0, f"T{int(v)}")
    if "D" in words:
        tail.extend(_d_word(*words.pop("D"), number, state))
    if "S" in words:
        state.spindle = words["S"][1]
    if "F" in words and state.inch and not state.feed_inch:
        v = words.pop("F")[1] / 25.4
        words["F"] = (_fmt(v), v)
    if "CR" in words:
        words["R"] = words.pop("CR")
        state.note("CR", "CR= (arc radius): read as R", number)
    moves = [k for k in _AXES if k in words]
    if state.mcall is not None and moves:
        return _position(out, words, tail, number, state)
    _track(words, machine, state)
    return out + [f"{k}{t}" for k, (t, _) in words.items()] + tail


def _cycle832(args: str, number: int, state: _State) -> list[str]:
    """CYCLE832(_TOL, _TOLM, ...), the high-speed settings: its tolerance as G64 P."""
    first = args.split(",")[0].strip()
    if first and not _NUMBER.match(first):
        raise _error(number, f"CYCLE832({args})", "a number or nothing as CYCLE832's first "
                     "parameter (the tolerance)")  # fmt: skip
    tolerance = float(first) if first else 0.0
    if tolerance < 0.0:
        raise _error(number, f"CYCLE832({args})", "a tolerance >= 0")
    if tolerance == 0.0:  # CYCLE832() or a zero tolerance: the settings are switched off
        state.note("CYCLE832", "CYCLE832 (high-speed settings) off: read as G64, the "
                   "machine file's path tolerance", number)  # fmt: skip
        return ["G64"]
    state.note("CYCLE832", "CYCLE832 (high-speed settings): its tolerance read as G64 P "
               "(the path tolerance corners are blended within); its compressor, "
               "smoothing and dynamics settings are not modelled", number)  # fmt: skip
    return ["G64", f"P{_fmt(tolerance)}"]


def _m_code(code: int, text: str, number: int, state: _State) -> list[str]:
    if code == 6:
        state.z = None  # the new tool's length may move the tool tip (SINUMERIK's default D1)
        return ["M6"]
    if code in _PASS_M:
        return [f"M{code}"]
    if code == 17:
        state.note("M17", "M17 (end of a subprogram): read as M2", number)
        return ["M2"]
    if 40 <= code <= 45:
        state.note(f"M{code}", f"M{code} (gear stage): dropped, no feed-axis motion", number)
        return []
    raise _error(number, f"M{text}", "M0-M9, M17, M30 or M40-M45")


def _d_word(text: str, value: float, number: int, state: _State) -> list[str]:
    """A tool offset D: G43 H<tool> for a numbered tool, G49 for D0."""
    if value < 0 or value != int(value):
        raise _error(number, f"D{text}", "a cutting edge number D0 to D9")
    state.z = None  # the tool tip moves in program coordinates
    if value == 0:
        state.note("D0", "D0 (tool offset off): read as G49", number)
        return ["G49"]
    if state.tool is not None and state.tool > 0:
        state.note("D", f"D{int(value)} (tool offset on): read as G43 H{state.tool}, the "
                   "tool's length from the machine file's tool table", number)  # fmt: skip
        return [f"G43 H{state.tool}"]
    state.note("D", f"D{int(value)} (tool offset of a named or unknown tool): dropped, the "
               "tool's length is not applied", number)  # fmt: skip
    return []


def _dwell(words: dict[str, tuple[str, float]], number: int, state: _State) -> list[str]:
    """G4 F<seconds> or G4 S<spindle revolutions> as G4 P<seconds>."""
    keys = set(words)
    if keys == {"F"}:
        seconds = words["F"][1]
        state.note("G4 F", "G4 F (dwell in seconds): read as G4 P", number)
    elif keys == {"S"}:
        if not state.spindle:
            raise _error(number, f"G4 S{words['S'][0]}", "G4 S<revolutions> after a spindle "
                         "speed S, or G4 F<seconds>")  # fmt: skip
        seconds = words["S"][1] * 60.0 / state.spindle
        state.note("G4 S", f"G4 S (dwell in spindle revolutions): read as G4 P at the "
                   f"programmed {_fmt(state.spindle)} rev/min", number)  # fmt: skip
    else:
        raise _error(number, "G4", "G4 F<seconds> or G4 S<revolutions> alone in its block")
    if not seconds >= 0.0:
        raise _error(number, "G4", "a dwell >= 0")
    return ["G4", f"P{_fmt(seconds)}"]


def _position(
    out: list[str], words: dict[str, tuple[str, float]], tail: list[str], number: int,
    state: _State,
) -> list[str]:  # fmt: skip
    """A position under MCALL: moved to at rapid, then the cycle runs there [2]."""
    cycle = state.mcall
    assert cycle is not None
    bad = [k for k in words if k not in ("X", "Y", "F", "S")]
    if bad:
        raise _error(number, bad[0], "X and/or Y only on a position under MCALL (a Z or rotary "
                     "move would be drilled again, I/J/K/CR make an arc)")  # fmt: skip
    if state.motion != 0:
        raise _error(number, "X/Y", "G0 for a position under MCALL (RS274/NGC's cycle moves "
                     "there at rapid traverse)")  # fmt: skip
    if state.incremental or state.plane != 17:
        raise _error(number, "X/Y", "G90 and G17 for a position under MCALL")
    kept = [w for w in out if w not in ("G0", "G00")]
    position = [f"{k}{words[k][0]}" for k in ("X", "Y") if k in words]
    extra = [f"{k}{words[k][0]}" for k in ("F", "S") if k in words]
    return kept + _drill(cycle, position, number, state) + extra + tail


def _track(words: dict[str, tuple[str, float]], machine: bool, state: _State) -> None:
    """The tool axis's position after the line, when it can be known."""
    if "Z" not in words:
        return
    if machine:
        state.z = None
        return
    z = words["Z"][1] * (25.4 if state.inch else 1.0)
    if state.incremental:
        state.z = None if state.z is None else state.z + z
    else:
        state.z = z
