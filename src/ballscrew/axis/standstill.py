r"""Friction at and near standstill: the sign of the speed, regularised over a stated width.

Friction opposes the sliding, so an axis model books it as
:math:`T_f\,\mathrm{sgn}(\omega)`. On a *measured* trajectory the speed is a
derivative of noisy positions: while the axis stands still, the estimate
scatters about zero and :math:`\mathrm{sgn}` flips the full friction from
:math:`+T_f` to :math:`-T_f` at every sample, a chattering torque the real
axis, held by static friction, never shows.

The package replaces :math:`\mathrm{sgn}(v)` by a ramp over the speeds
below a width :math:`v_s`,

.. math:: s(v) = \mathrm{sgn}(v)\,\min\!\Bigl(1, \max\!\bigl(0,
          \frac{2|v|}{v_s} - 1\bigr)\Bigr),

zero below :math:`v_s/2` (the axis holds: static friction takes whatever
holds it, and for the energy that is no sliding), rising linearly to the
full friction at :math:`v_s`, and the unregularised model's exactly above it
(no change to the energy of motion at working feeds, unlike
:math:`\tanh(v/v_s)`, which is 0.76 of the full value at :math:`v = v_s`).
:math:`v_s = 0` is the exact sign. The width is tied to the speed noise of the
trajectory (:func:`standstill_speed`): :math:`v_s = k\,\sigma_v` with
:data:`NOISE_MULTIPLE` :math:`k = 8`, so the dead band holds the noise of an
axis at rest to :math:`4\sigma_v` (passed by a Gaussian noise at
:math:`6\times10^{-5}` of the samples), and the torque at rest is the holding
torque. A speed estimated from noise-free samples of a motion does not start
exactly at rest, so a ramp rather than a step keeps the friction continuous
where a move begins. A machine's slowest feeds (:math:`\ge` 1 mm/min = 17
µm/s) lie above :math:`v_s` for positions known to a tenth of a micrometre
at 1 kHz or a micrometre at 50 Hz (see :func:`standstill_speed`).

The servo wing models the same region with a LuGre bristle (pre-sliding,
:mod:`ballscrew.servo.plant`), which needs the time history of the contact;
the ramp is its rate-free limit for a trajectory that is given, not simulated:
what the torque at rest is, not how the table creeps.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray

__all__ = [
    "NOISE_MULTIPLE",
    "noise_scatter",
    "regularised_sign",
    "standstill_speed",
]

NOISE_MULTIPLE = 8.0
"""The ramp's width over the speed noise's standard deviation, :math:`k = v_s/\\sigma_v` [-]."""

_MAD_TO_SIGMA = 1.482602218505602
"""Standard deviation of a Gaussian over its median absolute deviation, 1/Φ⁻¹(3/4)."""


def regularised_sign(speed: npt.ArrayLike, width: float) -> FloatArray:
    r"""The sign of ``speed``, zero below ``width``/2 and ramped to ±1 at ``width`` [-].

    :math:`s(v) = \mathrm{sgn}(v)\,\mathrm{clip}(2|v|/v_s - 1, 0, 1)` (module
    docstring); ``width`` :math:`v_s` in the unit of ``speed``, 0 for the exact
    :math:`\mathrm{sgn}(v)` (0 at 0).

    Examples
    --------
    >>> regularised_sign([-2.0, -0.75, -0.3, 0.0, 0.625, 1.0, 3.0], 1.0).tolist()
    [-1.0, -0.5, -0.0, 0.0, 0.25, 1.0, 1.0]
    >>> regularised_sign([-1e-9, 0.0, 1e-9], 0.0).tolist()
    [-1.0, 0.0, 1.0]
    """
    v = np.asarray(speed, dtype=float)
    w = float(width)
    if not (math.isfinite(w) and w >= 0.0):
        raise BallScrewInputError("standstill width", width, "a speed >= 0 (0: the exact sign)")
    if w == 0.0:
        out: FloatArray = np.sign(v)
        return out
    ramp: FloatArray = np.sign(v) * np.clip(2.0 * np.abs(v) / w - 1.0, 0.0, 1.0)
    return ramp


def noise_scatter(values: npt.ArrayLike, order: int = 3) -> float:
    r"""Standard deviation of white noise on a smooth signal, robustly [unit of ``values``].

    The differences of order :math:`n` of independent noise of standard
    deviation :math:`\sigma` have the variance :math:`\binom{2n}{n}\sigma^2`
    (20 for :math:`n = 3`); a motion made of pieces of constant speed or
    acceleration has no third difference, so the median absolute deviation of
    the third differences, :math:`\sigma = 1.4826\,\mathrm{MAD}/\sqrt{20}`, is
    the noise's wherever more than half the samples are not in a jerk phase.
    Positions read in steps of :math:`q` (an encoder's resolution, the digits
    of an export) have at least the quantisation noise :math:`q/\sqrt{12}`
    (:math:`q` the smallest step between two samples, when every step is a
    whole multiple of it), used where the median finds less (an axis at rest
    on one count).

    Examples
    --------
    >>> rng = np.random.default_rng(1)
    >>> t = np.linspace(0.0, 10.0, 20001)
    >>> x = 0.1 * t**2 + rng.normal(0.0, 1e-6, t.size)  # constant acceleration, 1 µm noise
    >>> round(noise_scatter(x) * 1e6, 1)  # to the sampling error of 20 000 samples, 1 %
    1.0
    """
    y = np.asarray(values, dtype=float).ravel()
    if isinstance(order, bool) or not isinstance(order, int) or order < 1:
        raise BallScrewInputError("order", order, "a whole number >= 1")
    if y.size < order + 2:
        raise BallScrewInputError("values", f"{y.size} samples", f"at least {order + 2}")
    d = np.diff(y, n=order)
    gain = math.sqrt(math.comb(2 * order, order))
    kept = d
    for _ in range(3):  # the jerk phases out (beyond 4 sigma), the median again
        spread = _MAD_TO_SIGMA * float(np.median(np.abs(kept - np.median(kept))))
        inside = np.abs(d - np.median(kept)) <= 4.0 * spread
        if spread == 0.0 or inside.sum() < 5:
            break
        kept = d[inside]
    sigma = spread / gain
    return max(sigma, _quantum(y) / math.sqrt(12.0))


def _quantum(y: FloatArray) -> float:
    """The step ``y`` is read in (every change a whole multiple of it, to 1 %), else 0."""
    steps = np.abs(np.diff(y))
    steps = steps[steps > 0.0]
    if not steps.size:
        return 0.0
    q = float(np.min(steps))
    ratio = steps / q
    whole = np.abs(ratio - np.round(ratio)) <= 0.01
    return q if float(np.mean(whole)) >= 0.99 else 0.0


def standstill_speed(
    position: npt.ArrayLike, time: npt.ArrayLike, *, gain: float = 1.0 / math.sqrt(2.0),
    multiple: float = NOISE_MULTIPLE,
) -> float:  # fmt: skip
    r"""The ramp's width :math:`v_s = k\,\sigma_v` for a measured trajectory [m/s].

    :math:`\sigma_v = g\,\sigma_x/\Delta t`: the positions' noise
    :math:`\sigma_x` (:func:`noise_scatter`) through the derivative filter,
    whose coefficients (times :math:`\Delta t`) have the Euclidean norm
    :math:`g` (:math:`1/\sqrt2` for the central difference of
    :func:`numpy.gradient`; for a Savitzky–Golay derivative the norm of its
    coefficients), at the median sample spacing :math:`\Delta t`.

    Examples
    --------
    1 µm of noise at 50 Hz: :math:`\sigma_v = 0.707 \cdot 10^{-6}/0.02 = 35`
    µm/s, :math:`v_s = 0.28` mm/s (0.017 m/min).

    >>> rng = np.random.default_rng(2)
    >>> t = np.arange(0.0, 60.0, 0.02)
    >>> x = rng.normal(0.0, 1e-6, t.size)
    >>> round(standstill_speed(x, t) * 1e3, 2)
    0.28
    """
    t = np.asarray(time, dtype=float).ravel()
    if t.size < 6:
        return 0.0  # too few samples to tell noise from motion: the exact sign
    dt = float(np.median(np.diff(t)))
    if not dt > 0.0:
        raise BallScrewInputError("time", "(not increasing)", "times increasing")
    return float(multiple) * float(gain) * noise_scatter(position) / dt
