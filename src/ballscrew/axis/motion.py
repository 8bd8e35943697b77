r"""Motion profiles of a feed axis: moves, dwells, back-and-forth cycles, measured trajectories.

A :class:`Profile` samples the table's motion at increasing times: position,
speed and acceleration (SI: s, m, m/s, m/s²) and the axial process force on
the table [N] (positive when it pushes against the +x direction). Build one
with

* :func:`move`: a point-to-point move of a given stroke at a feed rate
  (speed limit), an acceleration limit and, optionally, a jerk limit (an
  S-curve); without a jerk limit the speed profile is a trapezoid (a
  triangle when the stroke is too short to reach the feed rate);
* :func:`dwell`: standing still;
* :func:`chain`: profiles one after another (times and positions continue);
* :func:`back_and_forth`: a move out, a dwell, the move back, a dwell,
  repeated;
* :func:`read_trajectory`: a CSV of time and position or speed (units in the
  header), with an optional process force.

Every phase of a move is a polynomial in time, so the samples are exact (no
numerical integration): the position at the end is the stroke to rounding.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ..errors import BallScrewInputError, FloatArray, check_nonnegative, check_positive

__all__ = [
    "Profile",
    "back_and_forth",
    "chain",
    "check_force_window",
    "dwell",
    "move",
    "parse_move",
    "read_trajectory",
]


MAX_SAMPLES = 5_000_000
"""The most samples :func:`back_and_forth` makes (5000 s of motion at 1 ms)."""


STEP_POSITION = 1e-9
"""The most a profile's position may differ across a time given twice [m] (rounding)."""


@dataclass(frozen=True)
class Profile:
    """A sampled motion of the table (arrays of equal length, times increasing).

    Attributes
    ----------
    time : numpy.ndarray
        [s], increasing; a time given twice is a step, the values just
        before and just after it (a part program's junction of two blocks).
    position, speed, acceleration : numpy.ndarray
        Table position [m], speed [m/s] and acceleration [m/s²].
    process_force : numpy.ndarray
        Axial process force on the table [N], positive against +x.
    standstill_speed : float
        Width [m/s] of the ramp that replaces the sign of the speed in the
        friction (:func:`ballscrew.axis.standstill.regularised_sign`): 0 (a
        planned motion, exact) or the noise's of a measured trajectory.
    """

    time: FloatArray
    position: FloatArray
    speed: FloatArray
    acceleration: FloatArray
    process_force: FloatArray
    standstill_speed: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.standstill_speed) and self.standstill_speed >= 0.0):
            raise BallScrewInputError("standstill_speed", self.standstill_speed, "a speed >= 0")
        n = self.time.size
        for name in ("position", "speed", "acceleration", "process_force"):
            if getattr(self, name).shape != (n,):
                raise BallScrewInputError(name, f"shape {getattr(self, name).shape}", f"({n},)")
        if n < 2:
            raise BallScrewInputError("time", f"{n} sample(s)", "at least 2 increasing times")
        dt = np.diff(self.time)
        if not np.all(dt >= 0.0):
            k = int(np.flatnonzero(~(dt >= 0.0))[0])
            raise BallScrewInputError(
                "time", f"{self.time[k + 1]:g} s at sample {k + 2}, after {self.time[k]:g} s",
                "times that do not decrease (a time given twice is a step in speed)",
            )  # fmt: skip
        if not float(np.sum(dt)) > 0.0:
            raise BallScrewInputError("time", f"{self.time[0]:g} s throughout",
                                      "at least 2 increasing times")  # fmt: skip
        jump = (dt == 0.0) & (np.abs(np.diff(self.position)) > STEP_POSITION)
        if np.any(jump):
            k = int(np.argmax(jump))
            raise BallScrewInputError(
                "position", f"{self.position[k]:g} m then {self.position[k + 1]:g} m at "
                f"{self.time[k]:g} s", "one position at a time given twice",
            )  # fmt: skip

    @property
    def duration(self) -> float:
        """Total time [s]."""
        return float(self.time[-1] - self.time[0])


def _phases(
    stroke: float, feed: float, accel: float, jerk: float
) -> list[tuple[float, float, float]]:
    """(duration, acceleration at its start, jerk) of each phase of a rest-to-rest move.

    Symmetric S-curve: jerk +j, 0, -j (accelerating), cruise, then the
    mirror; ``jerk = inf`` gives the trapezoid (constant +a, cruise, -a). The
    peak speed is lowered (and with it, for an S-curve, the peak
    acceleration) when the stroke is too short to reach the feed rate.
    """
    smooth = math.isfinite(jerk)

    def shape(v: float) -> tuple[float, float, float]:
        a = min(accel, math.sqrt(v * jerk)) if smooth else accel
        t_j = a / jerk if smooth else 0.0
        return a, t_j, max(v / a - t_j, 0.0)

    def distance(v: float) -> float:  # accelerating and braking, no cruise
        _, t_j, t_a = shape(v)
        return v * (2.0 * t_j + t_a)

    v = feed
    reached = distance(v) <= stroke
    if not reached:  # the feed rate is not reached: bisect the peak speed
        lo, hi = 0.0, feed
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if distance(mid) < stroke else (lo, mid)
        v = 0.5 * (lo + hi)
    a, t_j, t_a = shape(v)
    # No cruise where the feed is not reached: the bisection's remainder (1e-17 s) made a
    # phase no sample can hold, and a triangular move's times repeated once chained.
    t_v = max((stroke - distance(v)) / v, 0.0) if reached else 0.0
    if not smooth:
        return [(t_a, a, 0.0), (t_v, 0.0, 0.0), (t_a, -a, 0.0)]
    return [
        (t_j, 0.0, jerk), (t_a, a, 0.0), (t_j, a, -jerk), (t_v, 0.0, 0.0),
        (t_j, 0.0, -jerk), (t_a, -a, 0.0), (t_j, -a, jerk),
    ]  # fmt: skip


def move(
    stroke: float,
    feed: float,
    acceleration: float,
    *,
    jerk: float | None = None,
    process_force: float = 0.0,
    force_window: tuple[float, float] | None = None,
    sample_time: float = 1e-3,
) -> Profile:
    r"""A rest-to-rest move of the table: trapezoidal, or an S-curve with a jerk limit.

    Parameters
    ----------
    stroke : float
        Distance [m]; negative to move towards -x.
    feed : float
        Feed rate (speed limit) [m/s], > 0.
    acceleration : float
        Acceleration limit [m/s²], > 0.
    jerk : float, optional
        Jerk limit [m/s³]; None for a trapezoidal speed profile.
    process_force : float
        Axial process force [N] while the table is inside ``force_window``.
    force_window : (float, float), optional
        Distances from the start [m] between which the force acts (e.g. the
        middle 200 mm of a 300 mm stroke: ``(0.05, 0.25)``); the whole move
        when None.
    sample_time : float
        Spacing of the samples [s]; the phase boundaries are always samples.

    Returns
    -------
    Profile

    Examples
    --------
    A 300 mm move at 30 m/min and 2 m/s² takes s/v + v/a = 0.6 + 0.25 s:

    >>> p = move(0.3, 0.5, 2.0)
    >>> round(p.duration, 6), round(float(p.position[-1]), 12), round(float(p.speed.max()), 12)
    (0.85, 0.3, 0.5)
    """
    s = float(check_nonnegative("stroke", abs(stroke), "m"))
    v = float(check_positive("feed", feed, "m/s"))
    a = float(check_positive("acceleration", acceleration, "m/s²"))
    j = math.inf if jerk is None else float(check_positive("jerk", jerk, "m/s³"))
    dt = float(check_positive("sample_time", sample_time, "s"))
    sign = 1.0 if stroke >= 0 else -1.0
    if s == 0.0:
        return dwell(dt, sample_time=dt)
    # A phase a billionth of a sample long is rounding (an S-curve's constant-acceleration
    # phase where the jerk limits the acceleration): it holds no sample of its own.
    phases = [ph for ph in _phases(s, v, a, j) if ph[0] > 1e-9 * dt]
    times, pos, spd, acc = [0.0], [0.0], [0.0], [0.0]
    t0, x0, v0 = 0.0, 0.0, 0.0
    for duration, a_start, jj in phases:
        n = max(1, math.ceil(duration / dt))
        tau = np.linspace(0.0, duration, n + 1)[1:]
        x = x0 + v0 * tau + 0.5 * a_start * tau**2 + jj * tau**3 / 6.0
        vv = v0 + a_start * tau + 0.5 * jj * tau**2
        aa = a_start + jj * tau
        times += list(t0 + tau)
        pos += list(x)
        spd += list(vv)
        acc += list(aa)
        t0, x0, v0 = t0 + duration, float(x[-1]), float(vv[-1])
    t = np.asarray(times)
    x_arr = sign * np.asarray(pos)
    v_arr = sign * np.clip(np.asarray(spd), 0.0, None)
    a_arr = sign * np.asarray(acc)
    a_arr[-1] = 0.0
    v_arr[-1] = 0.0
    lo, hi = (0.0, s) if force_window is None else check_force_window(force_window, s)
    inside = (np.abs(x_arr) >= lo) & (np.abs(x_arr) <= hi)
    force = np.where(inside, float(process_force), 0.0)
    return Profile(t, x_arr, v_arr, a_arr, force)


def check_force_window(
    window: tuple[float, float], stroke: float, field: str = "force_window"
) -> tuple[float, float]:
    """The force window [m], checked: its start before its end, both inside the stroke.

    A reversed window would make the process force act nowhere, silently; it is
    refused, naming ``field``.
    """
    lo, hi = (float(v) for v in window)
    shown = f"{lo * 1e3:g} mm to {hi * 1e3:g} mm"
    if not 0.0 <= lo < hi:
        raise BallScrewInputError(
            field, shown, "a start before the end, both distances from the start of the "
            "move (e.g. force_from=50 mm, force_to=250 mm); reversed, the force never acts",
        )  # fmt: skip
    if hi > stroke * (1.0 + 1e-9):
        raise BallScrewInputError(field, shown, f"inside the stroke, {stroke * 1e3:g} mm")
    return lo, hi


def dwell(duration: float, *, position: float = 0.0, sample_time: float = 1e-3) -> Profile:
    """Standing still for ``duration`` [s] at ``position`` [m]."""
    d = float(check_positive("duration", duration, "s"))
    n = max(1, math.ceil(d / float(check_positive("sample_time", sample_time, "s"))))
    t = np.linspace(0.0, d, n + 1)
    zero = np.zeros_like(t)
    return Profile(t, zero + position, zero, zero.copy(), zero.copy())


def chain(*profiles: Profile) -> Profile:
    """Profiles one after another; each starts where the previous one ended (time and place)."""
    if not profiles:
        raise BallScrewInputError("profiles", "()", "at least one profile")
    parts: dict[str, list[FloatArray]] = {k: [] for k in ("t", "x", "v", "a", "f")}
    t_end, x_end = 0.0, 0.0
    for i, p in enumerate(profiles):
        skip = 0 if i == 0 else 1  # the first sample repeats the previous end
        parts["t"].append(p.time[skip:] - p.time[0] + t_end)
        parts["x"].append(p.position[skip:] - p.position[0] + x_end)
        parts["v"].append(p.speed[skip:])
        parts["a"].append(p.acceleration[skip:])
        parts["f"].append(p.process_force[skip:])
        t_end = float(parts["t"][-1][-1])
        x_end = float(parts["x"][-1][-1])
    width = max(p.standstill_speed for p in profiles)
    t, x, v, a, f = (np.concatenate(parts[k]) for k in ("t", "x", "v", "a", "f"))
    return Profile(t, x, v, a, f, standstill_speed=width)


def back_and_forth(
    stroke: float,
    feed: float,
    acceleration: float,
    *,
    jerk: float | None = None,
    dwell_time: float = 0.0,
    cycles: int = 1,
    process_force: float = 0.0,
    force_window: tuple[float, float] | None = None,
    sample_time: float = 1e-3,
) -> Profile:
    """``cycles`` times: the move out, a dwell, the move back, a dwell.

    The process force acts on the way out only (a cut), inside ``force_window``.
    """
    if isinstance(cycles, bool) or not isinstance(cycles, int) or cycles < 1:
        raise BallScrewInputError("cycles", cycles, "a whole number >= 1")
    if feed > 0.0 and acceleration > 0.0 and sample_time > 0.0:
        # Refused before any array is made: a stroke of 1e30 m asked for more memory than
        # there is. s/v + v/a is the duration of a move without jerk limit, the shortest.
        seconds = 2.0 * cycles * (abs(stroke) / feed + feed / acceleration + max(dwell_time, 0.0))
        if not seconds / sample_time <= MAX_SAMPLES:
            raise BallScrewInputError(
                "move",
                f"{cycles} cycle(s) of {seconds / cycles:.3g} s",
                f"at most {MAX_SAMPLES:,} samples of {sample_time:g} s in all "
                f"({MAX_SAMPLES * sample_time:g} s of motion): fewer cycles or a shorter move",
            )
    out = move(stroke, feed, acceleration, jerk=jerk, process_force=process_force,
               force_window=force_window, sample_time=sample_time)  # fmt: skip
    back = move(-stroke, feed, acceleration, jerk=jerk, sample_time=sample_time)
    one = [out, back] if dwell_time <= 0.0 else [
        out, dwell(dwell_time, sample_time=sample_time), back,
        dwell(dwell_time, sample_time=sample_time),
    ]  # fmt: skip
    return chain(*(one * cycles))


def read_trajectory(
    text: str, source: str = "trajectory", standstill_speed: float | None = None
) -> Profile:
    """A profile from CSV text: time, and position or table speed, and optionally force.

    The header names each column with its unit in brackets, e.g. ``time [s],
    position [mm], force [kN]`` or ``time [ms];speed [m/min]`` (semicolons
    or tabs allow decimal commas). Speed and acceleration (or position) are
    derived by finite differences (central, second order) on the given times.
    ``standstill_speed`` [m/s] is the width of the friction's sign near rest
    (:mod:`ballscrew.axis.standstill`); None takes it from the noise of the
    positions (:func:`~ballscrew.axis.standstill.standstill_speed`), or of the
    speeds given (8 times their noise), so a measured axis at rest holds
    instead of chattering by the full friction.
    """
    import re

    from ..io.files import csv_rows
    from ..io.units import parse_unit, to_si_array

    rows, delimiter = csv_rows(text, source)
    rows = [r for r in rows if r]
    if not rows:
        raise BallScrewInputError(source, "(empty)", "a header and at least 3 data rows")
    header = re.compile(r"^\s*(\w[\w ]*?)\s*\[([^\]]+)\]\s*$")
    columns: dict[str, tuple[int, str]] = {}
    for i, cell in enumerate(rows[0]):
        m = header.match(cell)
        if not m:
            raise BallScrewInputError(f"{source}: header", cell, "'name [unit]', e.g. 'time [s]'")
        unit = m.group(2).strip()
        parsed = parse_unit(f"{source}: header '{cell.strip()}'", unit)
        for kind, si in (("time", "s"), ("position", "m"), ("speed", "m/s"), ("force", "N")):
            if parsed.is_compatible_with(si) and kind not in columns:
                columns[kind] = (i, unit)
                break
    if "time" not in columns or not ({"position", "speed"} & set(columns)):
        raise BallScrewInputError(
            f"{source}: header", ",".join(rows[0]),
            "a time column and a position or speed column, each with its unit",
        )  # fmt: skip
    if len(rows) < 4:
        # Speeds and accelerations are second-order differences: three samples at least.
        raise BallScrewInputError(source, "(too short)", "a header and at least 3 data rows")

    def column(kind: str, si: str) -> FloatArray:
        i, unit = columns[kind]
        try:
            raw = [float(r[i].replace(",", ".") if delimiter != "," else r[i]) for r in rows[1:]]
        except (ValueError, IndexError):
            raise BallScrewInputError(f"{source}: column {kind}", "(data)", "numbers") from None
        bad = [k for k, value in enumerate(raw) if not math.isfinite(value)]
        if bad:
            line = bad[0] + 2  # the header is line 1
            raise BallScrewInputError(
                f"{source}: line {line}, column {kind}", raw[bad[0]], "a finite number"
            )
        return np.asarray(to_si_array(f"{source}: column {kind}", raw, unit, si), dtype=float)

    t = column("time", "s")
    if not np.all(np.diff(t) > 0.0):
        k = int(np.argmax(np.diff(t) <= 0.0)) + 3
        raise BallScrewInputError(f"{source}: line {k}", float(t[k - 2]), "times increasing")
    if "position" in columns:
        x = column("position", "m")
        v = np.gradient(x, t, edge_order=2)
    else:
        v = column("speed", "m/s")
        x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
    a = np.gradient(v, t, edge_order=2)
    f = column("force", "N") if "force" in columns else np.zeros_like(t)
    if standstill_speed is None:
        from .standstill import NOISE_MULTIPLE, noise_scatter
        from .standstill import standstill_speed as width_of

        standstill_speed = (width_of(x, t) if "position" in columns
                            else NOISE_MULTIPLE * noise_scatter(v, order=2) if t.size >= 6
                            else 0.0)  # fmt: skip
    return Profile(t, x, v, a, f, standstill_speed=float(standstill_speed))


MOVE_KEYS: dict[str, tuple[str, bool]] = {  # key: (SI unit, required)
    "stroke": ("m", True),
    "feed": ("m/s", True),
    "acceleration": ("m/s**2", True),
    "jerk": ("m/s**3", False),
    "dwell": ("s", False),
    "force": ("N", False),
    "force_from": ("m", False),
    "force_to": ("m", False),
}


def parse_move(text: str) -> dict[str, float]:
    """``"stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"`` to SI values by key.

    Keys: stroke, feed, acceleration (required); jerk, dwell, force (the
    process force on the way out), force_from, force_to (its window, distances
    from the start).
    """
    from ..io.units import to_si  # the unit library only when text is read

    out: dict[str, float] = {}
    typed: dict[str, str] = {}  # each value as written, for a refusal's message
    parts = [p.strip() for p in text.split(",") if p.strip()]
    for before, after in itertools.pairwise(parts):
        # "force=1,2 kN": a decimal comma, which also separates the keys here.
        if "=" not in after and before[-1:].isdigit() and after[:1].isdigit():
            key = before.partition("=")[0].strip()
            raise BallScrewInputError(
                f"--move {key}", f"{before.partition('=')[2].strip()},{after}",
                "a decimal point: commas separate the keys of --move (e.g. '1.2 kN')",
            )  # fmt: skip
    for part in parts:
        key, sep, value = part.partition("=")
        key = key.strip()
        if value.count("=") and key in MOVE_KEYS:  # 'stroke=400 mm feed=6 m/min': no comma
            raise BallScrewInputError(
                "--move", part, "one key=value between commas, e.g. 'stroke=400 mm, feed=6 "
                "m/min, acceleration=2 m/s^2' (two keys here without a comma between them)",
            )  # fmt: skip
        if not sep or key not in MOVE_KEYS:
            raise BallScrewInputError(
                "--move", part, f"key=value with a unit; keys: {', '.join(MOVE_KEYS)}"
            )
        if key in out:
            raise BallScrewInputError(
                f"--move {key}", text, f"{key} once (it is given twice; which one is meant?)"
            )
        typed[key] = value.strip()
        out[key] = to_si(f"--move {key}", typed[key], MOVE_KEYS[key][0])
    missing = [k for k, (_, needed) in MOVE_KEYS.items() if needed and k not in out]
    if missing:
        raise BallScrewInputError("--move", text, f"also {', '.join(missing)} (with units)")
    for key in ("feed", "acceleration", "jerk"):
        if key in out and not out[key] > 0.0:
            raise BallScrewInputError(f"--move {key}", typed[key], "more than 0")
    if out["stroke"] == 0.0:
        raise BallScrewInputError("--move stroke", typed["stroke"], "a stroke, not 0")
    if out.get("dwell", 0.0) < 0.0:
        raise BallScrewInputError("--move dwell", typed["dwell"], "0 s or more")
    return out
