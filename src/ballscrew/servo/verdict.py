r"""Whether the simulated circle can run at all: the loops' margins, the sampling, the drive.

``ballscrew contour`` says a loop that cannot run instead of drawing it. Before
any circle is simulated, each axis is checked against stated limits:

* **phase margin** of the velocity and the position loop at least
  :data:`MIN_PHASE_MARGIN` (30°) and **gain margin** at least
  :data:`MIN_GAIN_MARGIN` (6 dB), the lower ends of the range a loop is
  usually tuned to (e.g. Ogata, *Modern Control Engineering*, 5th ed., 2010,
  §7-6: a phase margin between 30° and 60° and a gain margin above 6 dB for
  satisfactory performance). Below them the loop rings or diverges; a
  negative margin is an unstable loop whose "circle" is no measurement;
* **sampling**: the sampling frequency :math:`1/T_s` at least
  :data:`SAMPLES_PER_BANDWIDTH` (10) times each loop's closed-loop bandwidth.
  Nyquist's theorem needs 2; a digital loop that is to behave like the
  continuous one it was designed as needs far more (Franklin, Powell and
  Workman, *Digital Control of Dynamic Systems*, 3rd ed., 1998, §11.2, put
  smooth responses at 20 to 40 times and the rough limit near 6 to 10). The
  loops' figures treat the sample delay as a Padé approximant, which holds
  only well below the sampling frequency;
* **the drive** (the case's ``[motor]``): the motor speed the feed needs,
  :math:`n = v\,i/l`, at most ``rated_speed``; the peak motor torque, of the
  axis' whole mass (motor side and table) at the path's peak acceleration
  (:math:`v^2/R` on the circle, the ramp's at the start) plus the friction at
  the feed, the guideways and the weight, at most ``peak_torque``; and that
  peak acceleration at most what the peak torque can give after the
  friction, :math:`(2\pi i\,T_{peak}/l - F_{fric})/m`. A case without
  ``[motor]`` is noted, not checked.

Each :class:`Check` holds the value, the limit and the margin, and says OK,
CHECK or NOT OK. A loop past the stated minimum but still stable (a phase or
gain margin between 0 and its minimum, a sampling frequency between
:data:`NYQUIST` (2) and 10 times a bandwidth) is CHECK: it runs, poorly
damped or coarsely sampled, and the circle is drawn with the verdict beside
it. A loop that cannot run, an unstable one (a margin of 0 or less), one
sampled below Nyquist's rate, or a feed past the motor's speed, torque or
acceleration, is NOT OK: no circle is simulated. The verdict is the worst
check's.

**Size.** :data:`MAX_SAMPLES` bounds the samples the circles and reversals
simulate, estimated before any is (:func:`circle_samples`): each sample costs
a Python step per sub-step and about 60 bytes per axis kept for the report.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import BallScrewInputError
from ..io.numbers import text as num
from .cascade import Gains, LoopFigures
from .plant import AxisDynamics

__all__ = [
    "MAX_SAMPLES",
    "MIN_GAIN_MARGIN",
    "MIN_PHASE_MARGIN",
    "NYQUIST",
    "SAMPLES_PER_BANDWIDTH",
    "Check",
    "check_size",
    "drive_checks",
    "loop_checks",
    "verdict",
]

MIN_PHASE_MARGIN = 30.0
"""Least phase margin of the velocity and position loops [deg] (module docstring)."""

MIN_GAIN_MARGIN = 6.0
"""Least gain margin of the velocity and position loops [dB] (module docstring)."""

SAMPLES_PER_BANDWIDTH = 10.0
"""Least ratio of the sampling frequency to each loop's closed-loop bandwidth [-]."""

NYQUIST = 2.0
"""The ratio below which a sampled loop cannot follow its bandwidth at all (NOT OK) [-]."""

MAX_SAMPLES = 4_000_000
"""The most samples (all circles and reversals, both axes) ``contour`` simulates without
``--max-samples``: about 15 s of CPU and 550 MB on the example (3.0 M samples: 10 s, 406 MB)."""


@dataclass(frozen=True)
class Check:
    """One check of one axis: ``value`` against ``limit`` (a floor or a ceiling).

    ``floor`` True: the value must be at least the limit; else at most. ``advice``:
    what to change when it fails.
    """

    axis: str
    name: str
    value: float
    limit: float
    unit: str
    floor: bool
    advice: str
    hard: float | None = None
    """Where CHECK ends and NOT OK begins (None: at the limit itself)."""
    hard_included: bool = True
    """Whether a value exactly at ``hard`` is still CHECK (False: a margin of exactly 0,
    a loop at the edge of stability, is NOT OK)."""

    def _within(self, limit: float) -> bool:
        if math.isnan(self.value):
            return False
        return self.value >= limit if self.floor else self.value <= limit

    @property
    def ok(self) -> bool:
        """True when the value is on the right side of the limit (NaN is not)."""
        return self._within(self.limit)

    @property
    def status(self) -> str:
        """OK; CHECK (past the stated limit, short of the hard one); NOT OK."""
        if self.ok:
            return "OK"
        if self.hard is None or not self._within(self.hard):
            return "NOT OK"
        return "CHECK" if self.hard_included or self.value != self.hard else "NOT OK"

    @property
    def margin(self) -> float:
        """Value minus limit for a floor, limit minus value for a ceiling (negative: NOT OK)."""
        return self.value - self.limit if self.floor else self.limit - self.value

    def text(self) -> str:
        """One line: 'x: position-loop phase margin -4.28 deg < 30 deg (lower --kv)'."""
        sign = (">=" if self.floor else "<=") if self.ok else ("<" if self.floor else ">")
        line = (f"{self.axis}: {self.name} {num(self.value)} {self.unit} {sign} "
                f"{num(self.limit)} {self.unit}")  # fmt: skip
        return line if self.ok else f"{line} ({self.advice})"

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready check (a non-finite number as None)."""

        def finite(v: float) -> float | None:
            return v if math.isfinite(v) else None

        return {"axis": self.axis, "check": self.name, "value": finite(self.value),
                "limit": self.limit, "unit": self.unit,
                "kind": "at least" if self.floor else "at most",
                "margin": finite(self.margin), "verdict": self.status,
                "not_ok_past": self.hard, "advice": self.advice}  # fmt: skip


def loop_checks(name: str, figures: LoopFigures, gains: Gains) -> list[Check]:
    """Margins and sampling of one axis' loops (module docstring)."""
    fs = 1.0 / gains.sampling_time
    out = []
    for loop, pm, gm, bw, advice in (
        ("velocity", figures.velocity_phase_margin_deg, figures.velocity_gain_margin_db,
         figures.velocity_bandwidth_hz, "raise --phase-margin or shorten --sampling-time"),
        ("position", figures.position_phase_margin_deg, figures.position_gain_margin_db,
         figures.position_bandwidth_hz, "lower --kv, or make the velocity loop faster "
         "with a shorter --sampling-time"),
    ):  # fmt: skip
        # An infinite margin (no crossover) sets no limit; NaN (no figure) fails.
        out.append(Check(name, f"{loop}-loop phase margin", float(pm), MIN_PHASE_MARGIN,
                         "deg", True, advice, 0.0, False))  # fmt: skip
        out.append(Check(name, f"{loop}-loop gain margin", float(gm), MIN_GAIN_MARGIN,
                         "dB", True, advice, 0.0, False))  # fmt: skip
        known = bw > 0 and math.isfinite(bw)
        fix = (f"shorten --sampling-time below {num(1.0 / (SAMPLES_PER_BANDWIDTH * bw))} s"
               if known else "the loop has no bandwidth: lower --kv or shorten "
               "--sampling-time")  # fmt: skip
        out.append(Check(name, f"sampling frequency over the {loop}-loop bandwidth",
                         fs / bw if known else math.nan, SAMPLES_PER_BANDWIDTH, "x", True,
                         fix, NYQUIST))  # fmt: skip
    return out


def drive_checks(
    name: str, axis: AxisDynamics, motor: Mapping[str, float], feed: float, acceleration: float
) -> list[Check]:
    """Motor speed, peak torque and acceleration of one axis at ``feed`` [m/s] (module docstring).

    ``acceleration``: the axis' peak reference acceleration [m/s²]; ``motor``: the
    case's ``[motor]`` in SI (empty: nothing to check).
    """
    out = []
    per_rad = axis.lead / (2.0 * math.pi * axis.gear_ratio)  # table metres per motor radian
    speed = feed / per_rad
    if "rated_speed" in motor:
        out.append(Check(name, "motor speed at the feed", speed * 30.0 / math.pi,
                         motor["rated_speed"] * 30.0 / math.pi, "rpm", False,
                         "lower --feed: the case's [motor] rated_speed"))  # fmt: skip
    if "peak_torque" in motor:
        friction = float(np.interp(feed, axis.speeds, np.abs(axis.friction)))
        drag = friction + axis.guide_coulomb + axis.guide_viscous * feed + abs(axis.external_force)
        force = axis.mass * acceleration + drag
        peak = motor["peak_torque"]
        out.append(Check(name, "peak motor torque", float(axis.motor_torque(force)), peak, "N*m",
                         False, "lower --feed or raise --radius: the case's [motor] "
                         "peak_torque"))  # fmt: skip
        allowed = (peak / per_rad - drag) / axis.mass
        out.append(Check(name, "peak acceleration of the path (start-up ramp, v^2/R)", acceleration,
                         allowed, "m/s^2", False, "what the peak torque gives after the "
                         "friction: lower --feed or raise --radius"))  # fmt: skip
    return out


def verdict(checks: Sequence[Check]) -> str:
    """The worst of the checks' statuses: "OK", "CHECK" or "NOT OK"."""
    statuses = {c.status for c in checks}
    return next((s for s in ("NOT OK", "CHECK") if s in statuses), "OK")


def check_size(samples: int, limit: int = MAX_SAMPLES) -> None:
    """Refuse a run of more than ``limit`` samples, with the estimate and how to lower it."""
    if samples > limit:
        raise BallScrewInputError(
            "simulated samples", f"{samples:,} (estimated)",
            f"at most {limit:,}: each circle is a lead-in of 15/k_v and a revolution of "
            "2 pi R/(v T_s) samples; lower --radius, raise --feed or --kv, lengthen "
            "--sampling-time, run one --direction, or raise the limit with --max-samples",
        )  # fmt: skip
