r"""Jerk-limited feed along a part program's path, and each axis's motion over time.

The path is planned as a CNC look-ahead does, in three steps:

1. **Limits per block.** A line with unit direction :math:`u` may run at the
   programmed feed (the rapid feed for G0) capped by every axis,
   :math:`v \le v_i/|u_i|`, and accelerate at :math:`a \le a_i/|u_i|` with jerk
   :math:`j \le j_i/|u_i|`. On an arc of radius :math:`R` the in-plane axes
   also carry the centripetal acceleration :math:`v^2/R` and its rate
   :math:`v^3/R^2`: half of the smaller in-plane limit is given to each, so
   :math:`v \le \sqrt{a R/2}`, :math:`v \le (j R^2/2)^{1/3}`, and the
   tangential acceleration and jerk get the other half.
2. **Junction speeds.** Where two blocks meet at an angle, the controller
   blends the corner within the path tolerance :math:`\delta`. The blend is
   the circle tangent to both blocks whose distance from the corner is
   :math:`\delta`, of radius :math:`r = \delta \sin(\theta/2)/(1 -
   \sin(\theta/2))` with :math:`\cos\theta = -u_1\cdot u_2`; the speed through
   it is bounded by the centripetal acceleration along the blend's direction
   :math:`d = (u_2 - u_1)/|u_2 - u_1|`, :math:`v^2/r \le \min_i a_i/|d_i|`
   (Grbl's junction-deviation rule: S. K. Jeon, Grbl v0.8 to v1.1 planner,
   ``planner.c``, 2011-2016), and here also by its jerk, :math:`v^3/r^2 \le
   \min_i j_i/|d_i|`. The blend itself (shorter than the tolerance) is not
   drawn: the samples turn the corner sharply, and the axis velocity steps
   there by :math:`v|u_{2,i} - u_{1,i}|`. The program may set :math:`\delta`
   itself (``Program.tolerance``): ``G64 P``, and 0 under ``G61`` and in
   canned cycles, where every corner is stopped at.
3. **Look-ahead.** A backward pass lowers every junction speed to what the
   following block can brake from, a forward pass to what the preceding
   block can reach, both with the distance of a jerk-limited speed change
   that starts and ends without acceleration: from :math:`v_0` to
   :math:`v_1 > v_0` over :math:`\Delta v \ge a^2/j`,
   :math:`s = \tfrac12(v_0 + v_1)(\Delta v/a + a/j)`, else
   :math:`s = (v_0 + v_1)\sqrt{\Delta v/j}`.

Each block is then the time-optimal jerk-limited profile from its entry to
its exit speed computed by `ruckig <https://ruckig.com>`_ (Berscheid and
Kröger, "Jerk-limited real-time trajectory generation with arbitrary target
states", RSS 2021); its seven phases are polynomials in time, sampled
exactly (phase ends are samples; interior samples at most ``sample_time``
apart, cruises on lines without interior samples since nothing changes
there, arcs at least every 5°). Every block is sampled at both ends, so a
junction has two samples at one time, the end of one block and the start of
the next (an axis's speed steps there), and an arc also where one of its
axes turns. Between two samples every axis then moves one way along one
phase's polynomial: its distance is exactly the sum of the changes of
position, and no integral over the samples mixes two blocks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from .gcode import ARC, DWELL, RAPID, Program

__all__ = ["Limits", "Motion", "at_rest", "least_samples", "plan", "speed_change_distance"]

ARC_STEP = math.radians(5.0)
"""Largest angle between two samples on an arc [rad]."""
TURN_ROUNDING = 1e-9
"""An axis turn this close to an arc's end [quarter turns] is the end itself."""
MARGIN = 1.0 - 1e-7
"""Entry and exit speeds are kept this far inside what the look-ahead allows."""

MAX_SAMPLES = 3_000_000
"""The most samples a program's motion may take (about a kilobyte each through the axes):
a 100 000-block program takes about 1.2 million at 5 ms. Past it the program is refused
before a sample is made, with the estimate."""

RETRY_LOWER = (0.0, 1e-7, 1e-6, 1e-5, 1e-4)
"""Shares by which a block's exit speed is lowered, one after the other, while ruckig cannot
plan the block (a speed at a limit to the last digit): at most 1.1e-4 of it in all."""


def _no_rotary() -> FloatArray:
    return np.full(3, np.nan)


@dataclass(frozen=True)
class Limits:
    """The axes' limits, X, Y, Z (SI); an axis the machine lacks has NaN.

    ``rotary_feed``, ``rotary_acceleration``, ``rotary_jerk``: those of A, B, C
    [rad/s, rad/s², rad/s³], NaN for an axis without limits (a program moving it
    is refused).
    """

    feed: FloatArray
    acceleration: FloatArray
    jerk: FloatArray
    rapid_feed: float
    path_tolerance: float
    sample_time: float = 5e-3
    rotary_feed: FloatArray = field(default_factory=_no_rotary)
    rotary_acceleration: FloatArray = field(default_factory=_no_rotary)
    rotary_jerk: FloatArray = field(default_factory=_no_rotary)


@dataclass(frozen=True)
class Motion:
    """The planned motion, sampled (SI).

    Attributes
    ----------
    time : numpy.ndarray, shape (n,)
        [s], increasing; the time of each junction of two blocks twice, the end
        of the one and the start of the other (an axis's velocity steps there).
    position, velocity, acceleration, jerk : numpy.ndarray, shape (n, 3)
        Of X, Y, Z [m, m/s, m/s², m/s³].
    block : numpy.ndarray of int, shape (n,)
        The program block each sample lies in (a block's end sample: that block).
    feeding : numpy.ndarray of bool, shape (n,)
        Whether the sample lies in a feed block (G1, G2, G3).
    path_speed : numpy.ndarray, shape (n,)
        Speed along the path [m/s].
    entry_speed, exit_speed : numpy.ndarray, shape (blocks,)
        Path speed at each block's start and end [m/s].
    block_limit : numpy.ndarray, shape (blocks,)
        Each block's top speed [m/s] (feed and axis limits).
    block_time : numpy.ndarray, shape (blocks,)
        Duration of each block [s].
    nominal_time : float
        The program at its programmed feeds without acceleration [s].
    """

    time: FloatArray
    position: FloatArray
    velocity: FloatArray
    acceleration: FloatArray
    jerk: FloatArray
    block: np.ndarray
    feeding: np.ndarray
    path_speed: FloatArray
    entry_speed: FloatArray
    exit_speed: FloatArray
    block_limit: FloatArray
    block_time: FloatArray
    nominal_time: float

    @property
    def duration(self) -> float:
        """Program time [s]."""
        return float(self.time[-1] - self.time[0])


def speed_change_distance(v0: FloatArray, v1: FloatArray, a: FloatArray, j: FloatArray
                          ) -> FloatArray:  # fmt: skip
    r"""Shortest distance of a jerk-limited speed change from rest acceleration to rest [m].

    :math:`s = \tfrac12(v_0+v_1)(\Delta v/a + a/j)` when :math:`\Delta v \ge
    a^2/j` (the acceleration reaches :math:`a`), else :math:`(v_0 + v_1)
    \sqrt{\Delta v/j}`; :math:`\Delta v = |v_1 - v_0|`. Broadcasts.

    Examples
    --------
    From rest to 0.5 m/s at 2 m/s² and 50 m/s³: 0.5 × 0.5 × (0.25 + 0.04) = 0.0725 m.

    >>> round(float(speed_change_distance(0.0, 0.5, 2.0, 50.0)), 6)
    0.0725
    """
    v0, v1 = np.asarray(v0, dtype=float), np.asarray(v1, dtype=float)
    dv = np.abs(v1 - v0)
    full = dv >= a * a / j
    out: FloatArray = np.where(
        full, 0.5 * (v0 + v1) * (dv / a + a / j), (v0 + v1) * np.sqrt(dv / j)
    )
    return out


def _reach(v0: float, length: float, a: float, j: float) -> float:
    """The highest speed reachable from ``v0`` over ``length`` (the inverse of the above)."""
    # Acceleration reaches a: (v1^2 - v0^2)/(2a) + (v0 + v1) a/(2j) = L, a quadratic in v1.
    k = a * a / j
    c = v0 * k - v0 * v0 - 2.0 * a * length
    v1 = 0.5 * (-k + math.sqrt(k * k - 4.0 * c))
    if v1 - v0 >= k:
        return v1
    # Otherwise v1 = v0 + j s^2 with j s^3 + 2 v0 s - L = 0 (Cardano, one real root).
    p, q = 2.0 * v0 / (3.0 * j), length / (2.0 * j)
    root = math.sqrt(q * q + p**3)
    s = math.cbrt(q + root) + math.cbrt(q - root)
    return v0 + j * s * s


def _geometry(program: Program) -> dict[str, FloatArray]:
    """Length, unit tangents at both ends, and the arcs' radius and in-plane share."""
    d = program.end - program.start
    n = program.size
    length = np.linalg.norm(d, axis=1)
    t0 = np.divide(d, length[:, None], out=np.zeros_like(d), where=length[:, None] > 0)
    t1 = t0.copy()
    radius = np.full(n, np.inf)
    share = np.zeros(n)  # in-plane share of the arc's length
    normal_share = np.zeros(n)
    for plane, (ia, ib, inn) in ((17, (0, 1, 2)), (18, (2, 0, 1)), (19, (1, 2, 0))):
        m = (program.kind == ARC) & (program.plane == plane)
        if not np.any(m):
            continue
        c, s0, sw = program.centre[m], program.start[m], program.sweep[m]
        r = np.hypot(s0[:, ia] - c[:, ia], s0[:, ib] - c[:, ib])
        theta0 = np.arctan2(s0[:, ib] - c[:, ib], s0[:, ia] - c[:, ia])
        h = d[m, inn]
        arc_len = r * np.abs(sw)
        total = np.hypot(arc_len, h)
        length[m] = total
        radius[m] = r
        share[m] = arc_len / total
        normal_share[m] = h / total
        for idx, theta in ((t0, theta0), (t1, theta0 + sw)):
            tan = np.zeros((int(m.sum()), 3))
            sgn = np.sign(sw)
            tan[:, ia] = -np.sin(theta) * sgn * share[m]
            tan[:, ib] = np.cos(theta) * sgn * share[m]
            tan[:, inn] = normal_share[m]
            idx[m] = tan
    # Rotary axes (lines only): their angle per unit of path; a block turning them alone
    # has its path in radians.
    turn = np.zeros((n, 3))
    if program.rotary_start is not None and program.rotary_end is not None:
        dr = program.rotary_end - program.rotary_start
        alone = (length == 0.0) & np.any(dr != 0.0, axis=1)
        length = np.where(alone, np.linalg.norm(dr, axis=1), length)
        turn = np.divide(dr, length[:, None], out=turn, where=length[:, None] > 0)
    return {"length": length, "t0": t0, "t1": t1, "radius": radius, "share": share,
            "turn": turn}  # fmt: skip


def _block_limits(program: Program, g: dict[str, FloatArray], lim: Limits
                  ) -> tuple[FloatArray, FloatArray, FloatArray]:  # fmt: skip
    """Top speed, acceleration and jerk along the path of each block."""
    with np.errstate(divide="ignore", invalid="ignore"):
        comp = np.maximum(np.abs(g["t0"]), np.abs(g["t1"]))
        arc = program.kind == ARC
        # An arc's in-plane axes see the whole in-plane share at some point of a long arc.
        for plane, (ia, ib, _) in ((17, (0, 1, 2)), (18, (2, 0, 1)), (19, (1, 2, 0))):
            m = arc & (program.plane == plane)
            comp[m, ia] = g["share"][m]
            comp[m, ib] = g["share"][m]
        v = np.nanmin(np.where(comp > 0, lim.feed / comp, np.inf), axis=1)
        a = np.nanmin(np.where(comp > 0, lim.acceleration / comp, np.inf), axis=1)
        j = np.nanmin(np.where(comp > 0, lim.jerk / comp, np.inf), axis=1)
        feed = np.where(program.kind == RAPID, lim.rapid_feed, program.feed)
        v = np.minimum(v, feed)
        if np.any(arc):
            r = g["radius"][arc]
            a_plane = np.full(int(arc.sum()), np.inf)
            j_plane = np.full(int(arc.sum()), np.inf)
            for plane, (ia, ib, _) in ((17, (0, 1, 2)), (18, (2, 0, 1)), (19, (1, 2, 0))):
                sel = program.plane[arc] == plane
                a_plane[sel] = min(lim.acceleration[ia], lim.acceleration[ib])
                j_plane[sel] = min(lim.jerk[ia], lim.jerk[ib])
            share = g["share"][arc]
            v[arc] = np.minimum(v[arc], np.sqrt(0.5 * a_plane * r) / share)
            v[arc] = np.minimum(v[arc], np.cbrt(0.5 * j_plane * r * r) / share)
            a[arc] = 0.5 * a[arc]
            j[arc] = 0.5 * j[arc]
    turning = np.abs(g["turn"])
    if np.any(turning > 0.0):
        lacking = (turning > 0.0) & np.isnan(lim.rotary_feed)
        if np.any(lacking):
            k = int(np.argmax(np.any(lacking, axis=1)))
            letter = "ABC"[int(np.argmax(lacking[k]))]
            raise BallScrewInputError(f"program line {int(program.line[k])}", letter,
                                      "a rotary axis with limits in the machine file")  # fmt: skip
        alone = np.all(program.end == program.start, axis=1) & (program.kind == RAPID)
        v = np.where(alone, np.inf, v)  # the rapid feed is a linear speed
        with np.errstate(divide="ignore", invalid="ignore"):
            for cap, mine in ((lim.rotary_feed, v), (lim.rotary_acceleration, a),
                              (lim.rotary_jerk, j)):  # fmt: skip
                mine[:] = np.minimum(mine, np.min(np.where(turning > 0, cap / turning, np.inf),
                                                  axis=1))  # fmt: skip
    dwell = program.kind == DWELL
    v[dwell], a[dwell], j[dwell] = 0.0, 1.0, 1.0
    return v, a, j


def _junctions(program: Program, g: dict[str, FloatArray], v: FloatArray, lim: Limits
               ) -> FloatArray:  # fmt: skip
    """The highest speed at the start of each block (0 at the first, after a dwell)."""
    n = program.size
    vj = np.zeros(n)
    if n < 2:
        return vj
    u1, u2 = g["t1"][:-1], g["t0"][1:]
    cos = np.clip(-np.sum(u1 * u2, axis=1), -1.0, 1.0)
    sin_half = np.sqrt(0.5 * (1.0 - cos))
    # The tolerance in force at each junction: G64 P's or G61's (0: a stop) where the
    # program set one, else the machine's.
    tol = np.full(n - 1, lim.path_tolerance)
    if program.tolerance is not None:
        tol = np.where(np.isnan(program.tolerance[1:]), tol, program.tolerance[1:])
    with np.errstate(divide="ignore", invalid="ignore"):
        r = tol * sin_half / (1.0 - sin_half)
        dvec = u2 - u1
        dn = np.linalg.norm(dvec, axis=1)
        dunit = dvec / np.where(dn > 0, dn, 1.0)[:, None]
        absd = np.abs(dunit)
        a_j = np.nanmin(np.where(absd > 1e-12, lim.acceleration / absd, np.inf), axis=1)
        j_j = np.nanmin(np.where(absd > 1e-12, lim.jerk / absd, np.inf), axis=1)
        corner = np.minimum(np.sqrt(a_j * r), np.cbrt(j_j * r * r))
    straight = cos < -1.0 + 1e-12
    corner = np.where(straight, np.inf, np.where(tol > 0.0, corner, 0.0))
    corner = np.where(cos > 1.0 - 1e-12, 0.0, corner)  # a reversal of the path
    stop = (program.kind[:-1] == DWELL) | (program.kind[1:] == DWELL)
    turning = np.any(g["turn"] != 0.0, axis=1)  # a rotary axis: a stop on either side
    stop |= turning[:-1] | turning[1:]
    vj[1:] = np.where(stop, 0.0, np.minimum(np.minimum(v[:-1], v[1:]), corner))
    return vj


def plan(
    program: Program, limits: Limits, progress: object = None, max_samples: int = MAX_SAMPLES
) -> Motion:
    """Plan the program's motion and sample it (module docstring).

    ``progress``, when given, is called as ``progress(done, total)`` while
    the blocks' profiles are computed. A program of more than ``max_samples``
    samples is refused: before its blocks are planned when :func:`least_samples`
    already passes the bound, else once the plan gives the exact count, before
    a sample is made.
    """
    n = program.size
    if n == 0:
        return at_rest(program)
    g = _geometry(program)
    length = g["length"]
    v, a, j = _block_limits(program, g, limits)
    en, ex = _look_ahead(program, length, a, j, _junctions(program, g, v, limits))
    _check_least(program, length, v, a, j, (en, ex), limits.sample_time, max_samples)
    from ruckig import InputParameter, Result, Ruckig, RuckigError, Trajectory

    lengths, accs, jerks = length.tolist(), a.tolist(), j.tolist()
    otg, inp, traj = Ruckig(1), InputParameter(1), Trajectory(1)
    inp.current_acceleration = [0.0]
    inp.target_acceleration = [0.0]
    phases = np.zeros((n, 7, 5))  # duration, jerk, a0, v0, p0
    feeds = v.tolist()
    dwell = program.dwell.tolist()
    kinds = program.kind.tolist()
    step = max(1, n // 100)
    for k in range(n):
        if progress is not None and k % step == 0:
            progress(k, n)  # type: ignore[operator]
        if kinds[k] == DWELL:
            phases[k, 0, 0] = dwell[k]
            continue
        inp.current_position, inp.current_velocity = [0.0], [en[k]]
        inp.target_position = [lengths[k]]
        inp.max_acceleration, inp.max_jerk = [accs[k]], [jerks[k]]
        for lower in RETRY_LOWER:
            # An exit speed at the feed cap to the last digit can be one ruckig refuses (it
            # raises): the exit is lowered a little, and the next block enters at it.
            ex[k] *= 1.0 - lower
            if k + 1 < n:
                en[k + 1] = min(en[k + 1], ex[k])
            inp.target_velocity = [ex[k]]
            inp.max_velocity = [max(feeds[k], en[k], ex[k])]
            try:
                result = otg.calculate(inp, traj)
            except RuckigError:
                result = None
            prof = traj.profiles[0][0]
            if result == Result.Working and prof.brake.duration <= 0.0 >= prof.accel.duration:
                break
        else:
            raise BallScrewInputError(
                f"program line {int(program.line[k])}", f"{result}",
                "a block ruckig can plan (please report this program)",
            )  # fmt: skip
        phases[k, :, 0] = prof.t
        phases[k, :, 1] = prof.j
        phases[k, :, 2] = prof.a[:7]
        phases[k, :, 3] = prof.v[:7]
        phases[k, :, 4] = prof.p[:7]
    if progress is not None:
        progress(n, n)  # type: ignore[operator]
    if not float(phases[:, :, 0].sum()) > 0.0:
        return at_rest(program)
    return _sample(program, g, phases, limits.sample_time, np.array(en), np.array(ex), v,
                   max_samples)  # fmt: skip


def at_rest(program: Program) -> Motion:
    """The motion of a program that takes no time: one sample, at rest, at time 0.

    A program without blocks (a subroutine file run alone, only M, S or T
    words), or whose blocks all take no time (dwells of 0 s), leaves the axes
    where they are, as a controller runs it: one sample at the program's start
    (the machine's origin without blocks), its block 0.
    """
    n = program.size
    where = program.start[:1] if n else np.zeros((1, 3))
    still = np.zeros((1, 3))
    return Motion(
        time=np.zeros(1), position=where.astype(float), velocity=still, acceleration=still,
        jerk=still, block=np.zeros(1, dtype=int), feeding=np.zeros(1, dtype=bool),
        path_speed=np.zeros(1), entry_speed=np.zeros(n), exit_speed=np.zeros(n),
        block_limit=np.zeros(n), block_time=np.zeros(n), nominal_time=0.0,
    )  # fmt: skip


def _sample(
    program: Program, g: dict[str, FloatArray], phases: FloatArray, sample_time: float,
    entry: FloatArray, exit_: FloatArray, vmax: FloatArray, max_samples: int = MAX_SAMPLES,
) -> Motion:  # fmt: skip
    """Sample every phase exactly and map the path to the axes.

    Each phase is sampled from its start (interior samples at most
    ``sample_time`` apart, arcs every :data:`ARC_STEP`), each block also at its
    end, so a junction has two samples at one time: the end of one block and
    the start of the next. Within an arc, the points where an in-plane axis
    turns (the angle a multiple of 90°) are samples too. Between two samples
    every axis then moves one way along one phase's polynomial.
    """
    dur = phases[:, :, 0]
    count = np.where(dur > 0.0, np.maximum(1, np.ceil(dur / sample_time)), 0).astype(int)
    cruise = (phases[:, :, 1] == 0.0) & (np.abs(phases[:, :, 2]) < 1e-12)
    line = program.kind != ARC
    count = np.where(cruise & line[:, None] & (dur > 0.0), 1, count)
    arc = program.kind == ARC
    if np.any(arc):
        # At least one sample every ARC_STEP of the arc's angle within each phase.
        travelled = (
            phases[:, :, 3] * dur + 0.5 * phases[:, :, 2] * dur**2
            + phases[:, :, 1] * dur**3 / 6.0
        )  # fmt: skip
        with np.errstate(divide="ignore", invalid="ignore"):
            angle = np.abs(program.sweep)[:, None] * travelled / g["length"][:, None]
        need = np.ceil(np.nan_to_num(angle) / ARC_STEP).astype(int)
        count = np.where(arc[:, None] & (dur > 0.0), np.maximum(count, need), count)
    flat = count.ravel()
    total = int(flat.sum())
    # Each block's end: the end of its last phase that takes time.
    timed = dur > 0.0
    ends = np.flatnonzero(timed.any(axis=1))
    last_phase = 6 - np.argmax(timed[ends, ::-1], axis=1)
    end_phase = ends * 7 + last_phase
    turn_phase, turn_tau = _arc_turns(program, g, phases)
    if total + end_phase.size + turn_phase.size > max_samples:
        moving = float(dur[program.kind != DWELL].sum())
        _too_many(f"about {total + end_phase.size + turn_phase.size:.3g} samples ({moving:.4g}"
                  " s of motion", sample_time, max_samples, "counted from the plan")  # fmt: skip
    phase_of = np.repeat(np.arange(flat.size), flat)
    first = np.cumsum(flat) - flat
    k_in = np.arange(total) - np.repeat(first, flat)
    tau = dur.ravel()[phase_of] * k_in / flat[phase_of]
    phase_of = np.concatenate([phase_of, end_phase, turn_phase])
    tau = np.concatenate([tau, dur.ravel()[end_phase], turn_tau])
    is_end = np.concatenate([np.zeros(total, bool), np.ones(end_phase.size, bool),
                             np.zeros(turn_phase.size, bool)])  # fmt: skip
    order = np.lexsort((is_end, tau, phase_of))
    phase_of, tau, is_end = phase_of[order], tau[order], is_end[order]
    jj, a0 = phases[:, :, 1].ravel()[phase_of], phases[:, :, 2].ravel()[phase_of]
    v0, p0 = phases[:, :, 3].ravel()[phase_of], phases[:, :, 4].ravel()[phase_of]
    block = phase_of // 7
    start_time = np.concatenate([[0.0], np.cumsum(dur.ravel())])[:-1]
    time = start_time[phase_of] + tau
    s = p0 + v0 * tau + 0.5 * a0 * tau**2 + jj * tau**3 / 6.0
    sd = v0 + a0 * tau + 0.5 * jj * tau**2
    sdd = a0 + jj * tau
    sddd = jj.copy()
    # A block ends where it was planned to: its whole length, its exit speed, no acceleration.
    b_end = block[is_end]
    s[is_end] = np.where(program.kind[b_end] == DWELL, 0.0, g["length"][b_end])
    sd[is_end], sdd[is_end] = exit_[b_end], 0.0
    if is_end[-1]:  # the program's end, at rest
        sddd[-1] = 0.0
    pos, vel, acc, jerk = _axes(program, g, block, s, sd, sdd, sddd)
    pos[is_end] = program.end[b_end]  # where the next block starts, without rounding
    block_time = dur.sum(axis=1)
    feed = np.where(program.kind == RAPID, np.nan, program.feed)
    nominal = np.where(program.kind == DWELL, program.dwell, g["length"] / np.where(
        program.kind == RAPID, vmax, feed))  # fmt: skip
    return Motion(
        time=time, position=pos, velocity=vel, acceleration=acc, jerk=jerk, block=block,
        feeding=np.isin(program.kind[block], (1, ARC)), path_speed=sd, entry_speed=entry,
        exit_speed=exit_, block_limit=vmax, block_time=block_time,
        nominal_time=float(np.sum(nominal)),
    )  # fmt: skip


def _arc_turns(program: Program, g: dict[str, FloatArray], phases: FloatArray
               ) -> tuple[np.ndarray, FloatArray]:  # fmt: skip
    r"""(flat phase index, time in the phase) of every point where an arc's axis turns.

    An in-plane axis stands still, and may reverse, where the arc's angle is a
    multiple of 90°: the path position :math:`s^*` of each such point inside
    the arc, then the time at which the phase's cubic :math:`s(\tau)` reaches
    it (bisection; the path speed is never negative, so the cubic rises).
    """
    arc = np.flatnonzero((program.kind == ARC) & (np.abs(program.sweep) > 0.0))
    if arc.size == 0:
        return np.zeros(0, int), np.zeros(0)
    quarter = 0.5 * math.pi
    c, s0, sw = program.centre[arc], program.start[arc], program.sweep[arc]
    theta0 = np.zeros(arc.size)
    for plane, (ia, ib) in ((17, (0, 1)), (18, (2, 0)), (19, (1, 2))):
        m = program.plane[arc] == plane
        theta0[m] = np.arctan2(s0[m, ib] - c[m, ib], s0[m, ia] - c[m, ia])
    lo = np.minimum(theta0, theta0 + sw) / quarter
    hi = np.maximum(theta0, theta0 + sw) / quarter
    # A turn at an end of the arc, to rounding (an end at 90 deg, a sweep a hair longer), is
    # that end's own sample: the arc's formula there may miss the end point by the arc's
    # radius mismatch, two positions at one time.
    k_lo = np.floor(lo + TURN_ROUNDING).astype(int) + 1
    k_hi = np.ceil(hi - TURN_ROUNDING).astype(int) - 1
    many = np.maximum(k_hi - k_lo + 1, 0)
    if not many.any():
        return np.zeros(0, int), np.zeros(0)
    which = np.repeat(np.arange(arc.size), many)
    k = np.repeat(k_lo, many) + (np.arange(int(many.sum())) - np.repeat(np.cumsum(many) - many,
                                                                         many))  # fmt: skip
    b = arc[which]
    target = (k * quarter - theta0[which]) / sw[which] * g["length"][b]
    dur, jj, a0, v0, p0 = (phases[b, :, i] for i in range(5))
    # The phase holding the point: the last phase taking time that starts at or before it.
    holds = (dur > 0.0) & (p0 <= target[:, None])
    holds[:, 0] |= dur[:, 0] > 0.0  # rounding at the arc's start
    p = 6 - np.argmax(holds[:, ::-1], axis=1)
    rows = np.arange(b.size)
    d, j, a, v, x = dur[rows, p], jj[rows, p], a0[rows, p], v0[rows, p], p0[rows, p]
    low, high = np.zeros(b.size), d.copy()
    for _ in range(60):  # 2^-60 of a phase: to the time's rounding
        mid = 0.5 * (low + high)
        below = x + v * mid + 0.5 * a * mid**2 + j * mid**3 / 6.0 < target
        low, high = np.where(below, mid, low), np.where(below, high, mid)
    return b * 7 + p, 0.5 * (low + high)


def _axes(
    program: Program, g: dict[str, FloatArray], block: np.ndarray, s: FloatArray,
    sd: FloatArray, sdd: FloatArray, sddd: FloatArray,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:  # fmt: skip
    """Position, velocity, acceleration and jerk of X, Y, Z from the path's."""
    start = program.start[block]
    u = g["t0"][block]
    pos = start + s[:, None] * u
    vel = sd[:, None] * u
    acc = sdd[:, None] * u
    jerk = sddd[:, None] * u
    kind = program.kind[block]
    for plane, (ia, ib, inn) in ((17, (0, 1, 2)), (18, (2, 0, 1)), (19, (1, 2, 0))):
        m = (kind == ARC) & (program.plane[block] == plane)
        if not np.any(m):
            continue
        b = block[m]
        c, s0, sw = program.centre[b], program.start[b], program.sweep[b]
        length = g["length"][b]
        r = np.hypot(s0[:, ia] - c[:, ia], s0[:, ib] - c[:, ib])
        w = sw / length  # dθ/ds
        theta = np.arctan2(s0[:, ib] - c[:, ib], s0[:, ia] - c[:, ia]) + w * s[m]
        hs = (program.end[b, inn] - s0[:, inn]) / length
        sin, cos = np.sin(theta), np.cos(theta)
        v1, a1, j1 = sd[m], sdd[m], sddd[m]
        pos[m, ia] = c[:, ia] + r * cos
        pos[m, ib] = c[:, ib] + r * sin
        pos[m, inn] = s0[:, inn] + hs * s[m]
        vel[m, ia] = -r * sin * w * v1
        vel[m, ib] = r * cos * w * v1
        vel[m, inn] = hs * v1
        acc[m, ia] = -r * (sin * w * a1 + cos * w * w * v1 * v1)
        acc[m, ib] = r * (cos * w * a1 - sin * w * w * v1 * v1)
        acc[m, inn] = hs * a1
        jerk[m, ia] = -r * (sin * w * j1 + 3 * cos * w**2 * v1 * a1 - sin * w**3 * v1**3)
        jerk[m, ib] = r * (cos * w * j1 - 3 * sin * w**2 * v1 * a1 - cos * w**3 * v1**3)
        jerk[m, inn] = hs * j1
    return pos, vel, acc, jerk


def _look_ahead(
    program: Program, length: FloatArray, a: FloatArray, j: FloatArray, vj: FloatArray
) -> tuple[list[float], list[float]]:
    """Each block's entry and exit speed after the look-ahead's two passes (module docstring)."""
    n = program.size
    lengths, accs, jerks = length.tolist(), a.tolist(), j.tolist()
    en, ex = vj.tolist(), np.append(vj[1:], 0.0).tolist()
    for k in range(n - 1, -1, -1):  # backward: every block can brake to its exit speed
        if program.kind[k] == DWELL:
            en[k] = 0.0
            continue
        en[k] = min(en[k], _reach(ex[k], lengths[k], accs[k], jerks[k]) * MARGIN)
        if k:
            ex[k - 1] = min(ex[k - 1], en[k])
    for k in range(n):  # forward: every block can reach its exit speed
        if program.kind[k] != DWELL:
            ex[k] = min(ex[k], _reach(en[k], lengths[k], accs[k], jerks[k]) * MARGIN)
        if k + 1 < n:
            en[k + 1] = min(en[k + 1], ex[k])
    return en, ex


def _change_time(dv: float, a: float, j: float) -> float:
    """Shortest time of a jerk-limited speed change by ``dv`` from rest acceleration to rest [s].

    ``dv/a + a/j`` when the acceleration reaches ``a`` (``dv >= a^2/j``), else ``2 sqrt(dv/j)``.
    """
    dv = abs(dv)
    return dv / a + a / j if dv >= a * a / j else 2.0 * math.sqrt(dv / j)


def _least(
    program: Program, length: FloatArray, v: FloatArray, a: FloatArray, j: FloatArray,
    speeds: tuple[list[float], list[float]], sample_time: float,
) -> tuple[float, int]:  # fmt: skip
    """:func:`least_samples` from the blocks' limits and look-ahead speeds."""
    en, ex = speeds
    seconds, busy, ends = 0.0, 0.0, 0
    kinds = program.kind.tolist()
    for k, (size, top, acc, jerk) in enumerate(
        zip(length.tolist(), v.tolist(), a.tolist(), j.tolist(), strict=True)
    ):
        if kinds[k] == DWELL:
            pause = float(program.dwell[k])
            seconds += pause
            ends += pause > 0.0
            continue
        if not (size > 0.0 and top > 0.0 and acc > 0.0 and jerk > 0.0):
            continue
        if not all(map(math.isfinite, (size, acc, jerk))):
            continue
        # The speed within the block stays below what it reaches from either end.
        peak = min(top, _reach(en[k], size, acc, jerk), _reach(ex[k], size, acc, jerk))
        least = size / peak
        seconds += least
        ends += 1
        if kinds[k] == ARC or peak < top * (1.0 - 1e-9):
            busy += least  # an arc is sampled throughout; a block short of its top never cruises
        else:  # the speed changes to the top and back
            busy += _change_time(top - en[k], acc, jerk) + _change_time(top - ex[k], acc, jerk)
    return seconds, int(busy / sample_time) + ends


def least_samples(program: Program, limits: Limits) -> tuple[float, int]:
    r"""A lower bound of the program's time [s] and of its samples, before any block is planned.

    From each block's limits and its look-ahead speeds (steps 1 to 3 of the module
    docstring), without ruckig: a block's speed stays below the least of its top speed
    and what it can reach over its length from its entry speed and from its exit speed
    (the look-ahead's speed change, inverted), so the block takes at least its length
    over that speed. A block that cannot reach its top speed never cruises, and a line's
    speed change to the top and back takes at least the jerk-limited change's time: at
    least one sample every ``limits.sample_time`` of those, and one at each block's end.
    The plan itself (:func:`plan`) counts exactly; this bound lets a program far past
    :data:`MAX_SAMPLES` be refused at once. It is a bound, not an estimate of the time: a
    jerk of 1e-9 m/s³ stretches a 700 mm move from rest to rest over
    :math:`(32 L/j)^{1/3}` = 2819 s, of which it sees 888 s (the peak speed over the
    whole length, where the move reaches it only at its middle).

    >>> import numpy as np
    >>> from ballscrew.program.gcode import read_program
    >>> prog = read_program("G21 G90\nG1 X700 F3000\nM30\n")
    >>> slow = Limits(np.full(3, 0.5), np.full(3, 3.0), np.array([1e-9, 60.0, 60.0]),
    ...               rapid_feed=0.5, path_tolerance=2e-5)
    >>> seconds, samples = least_samples(prog, slow)
    >>> round(seconds), samples
    (888, 177581)
    """
    n = program.size
    if n == 0:
        return 0.0, 1
    g = _geometry(program)
    v, a, j = _block_limits(program, g, limits)
    speeds = _look_ahead(program, g["length"], a, j, _junctions(program, g, v, limits))
    return _least(program, g["length"], v, a, j, speeds, limits.sample_time)


def _check_least(
    program: Program, length: FloatArray, v: FloatArray, a: FloatArray, j: FloatArray,
    speeds: tuple[list[float], list[float]], sample_time: float, max_samples: int,
) -> None:  # fmt: skip
    """Refuse a program whose :func:`least_samples` already passes ``max_samples``."""
    seconds, samples = _least(program, length, v, a, j, speeds, sample_time)
    if samples > max_samples:
        _too_many(f"at least {samples:.3g} samples (at least {seconds:.4g} s", sample_time,
                  max_samples, "a lower bound estimated before planning")  # fmt: skip


def _too_many(estimate: str, sample_time: float, max_samples: int, how: str) -> None:
    raise BallScrewInputError(
        "program", f"{estimate}, a sample at most every {sample_time * 1e3:g} ms)",
        f"at most {max_samples:.3g} samples (about a kilobyte each; {how}): a longer "
        "machine.sample_time, lower feeds or the program in parts; raise the axes' "
        "max_acceleration and max_jerk if they are mistyped",
    )  # fmt: skip
