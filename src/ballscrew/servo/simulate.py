r"""Time simulation of one axis in its cascade, friction and pre-sliding included.

The controller (:mod:`ballscrew.servo.cascade`) updates once per sample
:math:`T_s` and holds its force command; the axis (:mod:`ballscrew.servo.plant`)
is integrated over :math:`n` sub-steps :math:`h = T_s/n` per sample, with
:math:`n` the least that keeps :math:`\omega h \le 0.1` for the fastest of
the axis' mode, the screw bristle and the guide bristle (semi-implicit
Euler: speeds, then positions). Within a sub-step:

* the motor force follows the current loop's lag exactly,
  :math:`F \leftarrow F_c + (F - F_c)e^{-h/\tau_c}`;
* each bristle state :math:`z` follows LuGre's equation at the frozen speed
  exactly, :math:`z \leftarrow z_{ss} + (z - z_{ss})e^{-\sigma_0|v|h/g}` with
  :math:`z_{ss} = g(v)\,\mathrm{sgn}\,v/\sigma_0` (it is stiff: the bristle
  relaxes within micrometres, far faster than a sample), and its force is
  :math:`\sigma_0 z + \sigma_1\Delta z/h`;
* :math:`g(v)` is the friction map's magnitude, interpolated linearly at the
  signed speed: the friction model is evaluated once, on the map's grid,
  never per step;
* the screw's drag acts on the motor side at the motor's speed (or on the
  table at its speed, ``AxisDynamics.drag_side``), the guideways' friction on
  the table at the table's speed.

The friction feed-forward :math:`F_{comp}(v_r)` and the acceleration
feed-forward are computed for every sample before the loop (vectorised).
"""

from __future__ import annotations

import math
from bisect import bisect_left
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray
from .cascade import Gains
from .plant import GUIDE_PRESLIDING, AxisDynamics

__all__ = ["Trace", "simulate_axis", "substeps"]


@dataclass(frozen=True)
class Trace:
    """One axis' simulated run, one value per sample.

    ``time`` [s]; reference ``x_ref``, ``v_ref`` [m, m/s]; ``motor`` and
    ``table`` positions [m]; ``force`` the motor's force [N] and ``friction``
    the screw friction [N], table side.
    """

    time: FloatArray
    x_ref: FloatArray
    v_ref: FloatArray
    motor: FloatArray
    table: FloatArray
    force: FloatArray
    friction: FloatArray

    @property
    def error(self) -> FloatArray:
        """Following error of the table, reference minus table position [m]."""
        out: FloatArray = self.x_ref - self.table
        return out


def substeps(axis: AxisDynamics, sampling_time: float) -> int:
    """Sub-steps per sample (module docstring)."""
    local = axis.mass if axis.rigid else axis.table_mass
    drag = axis.drag_mass
    rates = [math.sqrt(axis.bristle_stiffness / drag), axis.bristle_damping / drag]
    if not axis.rigid:
        rates.append(2.0 * math.pi * axis.eigenfrequency)
    if axis.guide_coulomb > 0.0:
        rates.append(2.0 * math.sqrt(axis.guide_coulomb / GUIDE_PRESLIDING / local))
    return max(1, math.ceil(sampling_time * max(rates) / 0.1))


def _interp(xs: list[float], ys: list[float], x: float) -> float:
    """Linear interpolation in ascending ``xs``, clamped at the ends."""
    i = bisect_left(xs, x)
    if i <= 0:
        return ys[0]
    if i >= len(xs):
        return ys[-1]
    x0, x1 = xs[i - 1], xs[i]
    return ys[i - 1] + (ys[i] - ys[i - 1]) * (x - x0) / (x1 - x0)


def simulate_axis(
    axis: AxisDynamics,
    gains: Gains,
    x_ref: npt.ArrayLike,
    v_ref: npt.ArrayLike,
    a_ref: npt.ArrayLike,
    compensation: npt.ArrayLike | None = None,
    position_offset: npt.ArrayLike | None = None,
) -> Trace:
    """Run the cascade on ``axis`` along the reference, one value per sample of ``gains``.

    Parameters
    ----------
    axis : AxisDynamics
        The axis.
    gains : Gains
        The cascade.
    x_ref, v_ref, a_ref : array_like
        Reference position [m], speed [m/s], acceleration [m/s²] at each sample.
    compensation : array_like, optional
        Friction feed-forward force [N] at each sample, as the controller sends
        it (:func:`ballscrew.servo.contour.controller_compensation`); none by default.
    position_offset : array_like, optional
        Added to the position reference the loop follows [m] (a controller's
        lost-motion compensation); the trace keeps ``x_ref`` itself.

    The axis starts at rest at ``x_ref[0]`` with its integrator holding the
    constant external force (a vertical axis' weight).
    """
    xr = np.asarray(x_ref, dtype=float)
    vr = np.asarray(v_ref, dtype=float)
    ar = np.asarray(a_ref, dtype=float)
    if not (xr.shape == vr.shape == ar.shape and xr.ndim == 1 and xr.size >= 2):
        raise BallScrewInputError("reference", list(xr.shape), "three 1-D arrays of one length")
    comp = np.zeros_like(xr) if compensation is None else np.asarray(compensation, dtype=float)
    # Per-sample inputs, vectorised: feed-forward force of the reference.
    ff = (gains.acceleration_ff * axis.mass * ar + comp).tolist()
    vff = (gains.velocity_ff * vr).tolist()
    target = xr if position_offset is None else xr + np.asarray(position_offset, dtype=float)
    out_motor, out_table, out_force, out_fric, diverged = _integrate(
        axis, gains, target.tolist(), ff, vff, float(xr[0])
    )
    if diverged:
        raise BallScrewInputError(
            "gains", f"kv {gains.kv:g} 1/s, kp {gains.kp:.4g} N*s/m", "a stable loop: the "
            "simulated axis diverged (lower k_v or the velocity loop's crossover)",
        )  # fmt: skip
    time = np.asarray(np.arange(xr.size) * gains.sampling_time, dtype=float)
    return Trace(time, xr, vr, np.asarray(out_motor), np.asarray(out_table),
                 np.asarray(out_force), np.asarray(out_fric))  # fmt: skip


def _guide_constants(axis: AxisDynamics) -> tuple[float, float, float, float]:
    """The guideway's friction constants, for the bristle model of the sample loop.

    Returns its Coulomb force [N], viscous coefficient [N·s/m], bristle stiffness
    [N/m] (0 without Coulomb friction) and critical bristle damping [N·s/m].
    """
    gc, gv = axis.guide_coulomb, axis.guide_viscous
    g0 = gc / GUIDE_PRESLIDING if gc > 0.0 else 0.0
    g1 = 2.0 * math.sqrt(g0 * (axis.mass if axis.rigid else axis.table_mass))
    return gc, gv, g0, g1


def _integrate(
    axis: AxisDynamics,
    gains: Gains,
    xr_l: list[float],
    ff: list[float],
    vff: list[float],
    x0: float,
) -> tuple[list[float], list[float], list[float], list[float], bool]:
    """The sample loop of :func:`simulate_axis`, in plain floats (the hot path).

    ``xr_l`` is the position the loop follows [m], ``ff`` the feed-forward force
    [N] and ``vff`` the speed feed-forward [m/s] of each sample; ``x0`` [m] the
    motor's position at rest at the start. Returns the motor and table positions
    [m], the motor force [N] and the screw's friction [N] at each sample, and
    whether the axis diverged (a non-finite final position).
    """
    ts = gains.sampling_time
    n = substeps(axis, ts)
    h = ts / n
    xs = axis.speeds.tolist()
    gs = np.abs(axis.friction).tolist()
    screw_friction = bool(np.any(axis.friction))
    s0, s1 = axis.bristle_stiffness, axis.bristle_damping
    gc, gv, g0, g1 = _guide_constants(axis)
    m1, m2, k, c = axis.motor_mass, axis.table_mass, axis.stiffness, axis.damping
    rigid, mass = axis.rigid, axis.mass
    on_motor = rigid or axis.drag_side == "motor"
    ext = axis.external_force
    alpha = math.exp(-h / gains.current_lag)
    kv, kp, ki = gains.kv, gains.kp, gains.ki
    motor_fb = gains.feedback == "motor"
    # Initial state: at rest at the first reference point, the spring carrying the
    # external force, the integrator and the motor holding it.
    x1 = x2 = x0
    if not rigid:
        x2 = x1 + ext / k
    v1 = v2 = 0.0
    z = zg = 0.0
    force = integ = -ext
    motor_prev = x1
    size = len(xr_l)
    out_motor = [0.0] * size
    out_table = [0.0] * size
    out_force = [0.0] * size
    out_fric = [0.0] * size
    fric = 0.0
    for i in range(size):
        out_motor[i] = x1
        out_table[i] = x2
        # The speed from the motor's encoder; the position from it or from a linear scale.
        measured = x1 if motor_fb or rigid else x2
        speed = (x1 - motor_prev) / ts
        motor_prev = x1
        ev = kv * (xr_l[i] - measured) + vff[i] - speed
        integ += ki * ts * ev
        command = kp * ev + integ + ff[i]
        for _ in range(n):
            force = command + (force - command) * alpha
            fric = 0.0
            speed_nut = v1 if rigid else v2
            speed_drag = v1 if on_motor else v2
            if screw_friction:
                g = _interp(xs, gs, speed_drag)
                z_old = z
                if speed_drag != 0.0 and g > 0.0:
                    zss = g / s0 if speed_drag > 0.0 else -g / s0
                    z = zss + (z - zss) * math.exp(-s0 * abs(speed_drag) * h / g)
                fric = s0 * z + s1 * (z - z_old) / h
            guide = 0.0
            if g0 > 0.0:
                zg_old = zg
                if speed_nut != 0.0:
                    zss = gc / g0 if speed_nut > 0.0 else -gc / g0
                    zg = zss + (zg - zss) * math.exp(-g0 * abs(speed_nut) * h / gc)
                guide = g0 * zg + g1 * (zg - zg_old) / h
            if rigid:
                acc = (force - fric - guide - gv * v1 + ext) / mass
                v1 += acc * h
                x1 += v1 * h
                v2, x2 = v1, x1
            elif on_motor:
                spring = k * (x1 - x2) + c * (v1 - v2)
                v1 += (force - fric - spring) / m1 * h
                v2 += (spring - guide - gv * v2 + ext) / m2 * h
                x1 += v1 * h
                x2 += v2 * h
            else:
                spring = k * (x1 - x2) + c * (v1 - v2)
                v1 += (force - spring) / m1 * h
                v2 += (spring - fric - guide - gv * v2 + ext) / m2 * h
                x1 += v1 * h
                x2 += v2 * h
        out_force[i] = force
        out_fric[i] = fric
    return out_motor, out_table, out_force, out_fric, not (math.isfinite(x1) and math.isfinite(x2))
