r"""A CNC's servo cascade: position P with feed-forward, velocity PI, current loop as a lag.

The loops, from the outside in, run at one sampling time :math:`T_s`:

* **position**: :math:`v_c = k_v(x_r - x) + k_{vff}\,v_r`, with the position
  :math:`x` read by the motor encoder (semi-closed loop) or a linear scale on
  the table (closed loop; the speed still comes from the motor's encoder);
* **velocity PI**: :math:`F_c = K_p(v_c - v) + K_i\int(v_c - v)\,dt + k_{aff}\,m\,a_r
  + F_{comp}(v_r)`, the speed :math:`v` the backward difference of the
  position over one sample, :math:`m` the axis' whole mass, :math:`F_{comp}`
  the friction feed-forward (a controller's table at the commanded velocity,
  :func:`ballscrew.servo.contour.controller_compensation`);
* **current** (the force the motor makes): a first-order lag of time constant
  :math:`\tau_c` behind :math:`F_c`.

Everything is table side (forces in N, speeds in m/s);
:meth:`Gains.as_dict` also gives the motor-side gains through the lead and gear.

**Tuning** (:func:`tune`) by the symmetric optimum (Kessler, 1958; e.g.
Schröder, *Elektrische Antriebe – Regelung von Antriebssystemen*): the
velocity loop sees the mass :math:`m` and a small lag
:math:`\tau_\Sigma = \tau_c + T_s` (the current loop, the zero-order hold
and the speed's backward difference, half a sample each); with
:math:`a = (1 + \sin\varphi_m)/\cos\varphi_m` for the phase margin
:math:`\varphi_m`, the crossover is :math:`\omega_c = 1/(a\tau_\Sigma)`,
:math:`K_p = m\,\omega_c` and :math:`T_i = a^2\tau_\Sigma = a/\omega_c`,
:math:`K_i = K_p/T_i`. On a two-mass axis the crossover is held below half
the antiresonance :math:`\sqrt{k/m_2}` (the rule of thumb that keeps the
velocity loop off the axis' mode), with a note. :math:`k_v` is given
(machine tools run 15 to 70 1/s).

**Figures** (:func:`loop_figures`): each loop's crossover, phase and gain
margins and closed-loop bandwidth (−3 dB), computed with the Python Control
Systems Library on the linear loop (friction left out, the sampling delay
:math:`T_s` as a second-order Padé approximant).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Any

from ..errors import BallScrewInputError
from .plant import AxisDynamics

__all__ = ["Gains", "LoopFigures", "loop_figures", "loop_systems", "tune"]

FEEDBACKS = ("motor", "table")


@dataclass(frozen=True)
class Gains:
    r"""The cascade's gains, table side (module docstring).

    Attributes
    ----------
    sampling_time : float
        :math:`T_s` [s] of the position and velocity loops.
    kv : float
        Position gain :math:`k_v` [1/s].
    velocity_ff, acceleration_ff : float
        Feed-forward shares [-] (1: ideal; 0: none).
    kp : float
        Velocity proportional gain [N·s/m].
    ki : float
        Velocity integral gain [N/m].
    current_lag : float
        :math:`\tau_c` [s].
    feedback : str
        "motor" (encoder on the motor) or "table" (a linear scale).
    notes : tuple of str
        How they were chosen.
    """

    sampling_time: float
    kv: float
    velocity_ff: float
    acceleration_ff: float
    kp: float
    ki: float
    current_lag: float
    feedback: str = "motor"
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        for name in ("sampling_time", "kv", "kp", "current_lag"):
            value = getattr(self, name)
            if not (value > 0.0 and math.isfinite(value)):
                raise BallScrewInputError(name, value, "a positive finite number")
        if not self.ki >= 0.0:
            raise BallScrewInputError("ki", self.ki, "a number >= 0")
        if self.feedback not in FEEDBACKS:
            raise BallScrewInputError("feedback", self.feedback, f"one of {list(FEEDBACKS)}")

    def as_dict(self, axis: AxisDynamics | None = None) -> dict[str, Any]:
        """JSON-ready gains; with ``axis``, the velocity gains at the motor too."""
        out = asdict(self)
        out["notes"] = list(self.notes)
        if axis is not None:
            r = (axis.lead / (2.0 * math.pi * axis.gear_ratio)) ** 2
            out["motor_side"] = {"kp_N_m_s_per_rad": self.kp * r, "ki_N_m_per_rad": self.ki * r}
        return out


def tune(
    axis: AxisDynamics,
    *,
    sampling_time: float = 250e-6,
    current_lag: float = 1.0 / (2.0 * math.pi * 1000.0),
    phase_margin: float = math.radians(45.0),
    kv: float = 40.0,
    velocity_ff: float = 1.0,
    acceleration_ff: float = 1.0,
    feedback: str = "motor",
) -> Gains:
    r"""Gains by the symmetric optimum for ``phase_margin`` [rad] (module docstring).

    The defaults: a 250 µs loop, a current loop of 1 kHz bandwidth
    (:math:`\tau_c = 1/(2\pi\,1000)` s), 45° of phase margin, :math:`k_v` = 40 1/s,
    full velocity and acceleration feed-forward.
    """
    if not 0.0 < phase_margin < math.pi / 2:
        raise BallScrewInputError("phase_margin", math.degrees(phase_margin),
                                  "between 0 and 90 degrees")  # fmt: skip
    if not sampling_time > 0.0:
        raise BallScrewInputError("sampling_time", sampling_time, "a positive time [s]")
    a = (1.0 + math.sin(phase_margin)) / math.cos(phase_margin)
    lag = current_lag + sampling_time
    wc = 1.0 / (a * lag)
    notes = [f"velocity PI by the symmetric optimum, a = {a:.3g} for {math.degrees(phase_margin):g}"
             f" deg, small lag {lag * 1e3:.3g} ms (current loop + one sample)"]  # fmt: skip
    limit = 0.5 * 2.0 * math.pi * axis.antiresonance
    if wc > limit:
        notes.append(f"crossover lowered from {wc / (2 * math.pi):.0f} Hz to half the axis' "
                     f"antiresonance, {limit / (2 * math.pi):.0f} Hz")  # fmt: skip
        wc = limit
    kp = axis.mass * wc
    ti = a / wc  # = a^2 tau_sum unless the crossover was lowered: the PI's corner a below it
    return Gains(sampling_time, kv, velocity_ff, acceleration_ff, kp, kp / ti, current_lag,
                 feedback, tuple(notes))  # fmt: skip


@dataclass(frozen=True)
class LoopFigures:
    """Crossover [Hz], margins (phase [deg], gain [dB]) and closed-loop bandwidth [Hz]."""

    velocity_crossover_hz: float
    velocity_phase_margin_deg: float
    velocity_gain_margin_db: float
    velocity_bandwidth_hz: float
    position_crossover_hz: float
    position_phase_margin_deg: float
    position_gain_margin_db: float
    position_bandwidth_hz: float

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready figures (an infinite gain margin as None)."""
        return {k: (v if math.isfinite(v) else None) for k, v in asdict(self).items()}


def loop_systems(axis: AxisDynamics, gains: Gains) -> dict[str, Any]:
    """The linear loops as ``control`` transfer functions: open and closed, velocity and position.

    Keys: ``plant`` (motor force to measured speed), ``velocity_open``,
    ``velocity_closed``, ``position_open``, ``position_closed``.
    """
    import control

    s = control.tf("s")
    m1, m2, k, c = axis.motor_mass, axis.table_mass, axis.stiffness, axis.damping
    if axis.rigid:
        plant = 1 / (axis.mass * s)
    else:
        # x1 = F (m2 s^2 + c s + k) / (s^2 [m1 (m2 s^2 + c s + k) + m2 (c s + k)]); x2 follows
        # x1 through (c s + k)/(m2 s^2 + c s + k).
        spring = m2 * s**2 + c * s + k
        x1 = spring / (s**2 * (m1 * spring + m2 * (c * s + k)))
        plant = s * x1
    num, den = control.pade(gains.sampling_time, 2)
    delay = control.tf(num, den)
    pi = gains.kp + gains.ki / s
    lag = 1 / (gains.current_lag * s + 1)
    velocity_open = control.minreal(pi * lag * delay * plant, verbose=False)
    velocity_closed = control.feedback(velocity_open, 1)
    # The position read on the motor (x1), or on the table (x2 = x1 (c s + k)/(m2 s^2 + c s + k)).
    scale = 1 if axis.rigid or gains.feedback == "motor" else (c * s + k) / spring
    position_open = control.minreal(gains.kv * velocity_closed * scale / s, verbose=False)
    return {"plant": plant, "velocity_open": velocity_open, "velocity_closed": velocity_closed,
            "position_open": position_open,
            "position_closed": control.feedback(position_open, 1)}  # fmt: skip


def loop_figures(axis: AxisDynamics, gains: Gains) -> LoopFigures:
    """Margins and bandwidths of both loops, computed with ``control`` (module docstring)."""
    import control

    loops = loop_systems(axis, gains)
    out: list[float] = []
    for name in ("velocity", "position"):
        gm, pm, _, _, wpc, _ = control.stability_margins(loops[f"{name}_open"])
        bw = float(control.bandwidth(loops[f"{name}_closed"]))
        gm_db = 20.0 * math.log10(gm) if gm and math.isfinite(gm) else math.inf
        out += [float(wpc) / (2 * math.pi), float(pm), gm_db, bw / (2 * math.pi)]
    return LoopFigures(*out)
