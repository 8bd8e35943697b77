r"""Torques, powers and energies of a feed axis over a motion profile.

An :class:`Axis` is the ball screw with what it moves and drives: the moving
mass, the inertias of screw, coupling and motor, a gear ratio, the incline of
the axis (gravity) and the lubricant temperature. :func:`axis_cycle` runs one
friction model over every sample of a :class:`~ballscrew.axis.motion.Profile` in
one vectorised call and returns, in SI:

* the screw speed :math:`\omega = 2\pi v/l` and acceleration;
* the axial force the nut must deliver, :math:`F = m(a + g\sin\theta) + F_p`
  (inertia, gravity on an axis inclined by :math:`\theta`, process force);
* the friction torque :math:`T_f \ge 0` (it opposes the rotation) and the
  torque that moves the load, :math:`T_F = F l/2\pi`;
* the support bearings' friction :math:`T_b` (:mod:`ballscrew.bearings`,
  reported separately from the screw's);
* the motor torque :math:`T_m = [T_F + s(\omega)(T_f + T_b) +
  (J_s + J_c)\dot\omega]/i + J_m i\dot\omega` with gear ratio :math:`i`
  (motor turns per screw turn), where :math:`s` is the sign of the speed,
  ramped over the profile's ``standstill_speed`` for a measured trajectory
  (:mod:`ballscrew.axis.standstill`; exact for a planned one);
* friction power :math:`T_f\,s(\omega)\,\omega` (:math:`T_f|\omega|` when moving)
  and energy :math:`\int T_f s(\omega)\omega\,dt`
  (trapezoidal rule over the samples), split by direction of travel, and the
  same with the catalogue's constant-efficiency rule for comparison;
* the peak and RMS motor torque, :math:`\sqrt{\int T_m^2\,dt / t}`;
* the forward and back-driving efficiencies at the working point
  (:func:`reverse_efficiency`);
* a :class:`~ballscrew.errors.BallScrewSpeedWarning` where the profile's
  top speed passes the nut's d·n limit or 80 % of the shaft's critical speed
  (:mod:`ballscrew.limits`; the latter when the span between the supports
  is given).

The friction torque is the model's at the axial load and speed of each
sample; the model sees the load through its ball loads, so load-dependent
friction is in :math:`T_f` and is not counted again.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..bearings import (
    PALMGREN_BEARINGS,
    SKF_FRICTION_COEFFICIENTS,
    palmgren_bearing_torque,
    simplified_bearing_torque,
)
from ..chain import FrictionResult, friction_torque
from ..design.limits import DEFAULT_DN_LIMIT, SUPPORT_EIGENVALUES, speed_limit_issues
from ..errors import (
    BallScrewInputError,
    BallScrewSpeedWarning,
    FloatArray,
    check_finite,
    check_nonnegative,
    check_positive,
)
from ..geometry import BallScrew
from ..lubricant import Lubricant
from ..materials import STANDARD_GRAVITY
from .motion import Profile
from .standstill import regularised_sign

__all__ = [
    "Axis",
    "CycleResult",
    "axis_cycle",
    "distinct_pairs",
    "friction_energy",
    "friction_sign",
    "reverse_efficiency",
    "screw_motion",
    "self_locking",
    "weight_back_driving",
]


@dataclass(frozen=True)
class Axis:
    """A feed axis driven by a ball screw (SI units).

    Attributes
    ----------
    moving_mass : float
        Table, workpiece and nut [kg], >= 0.
    screw_inertia, coupling_inertia, motor_inertia : float
        Mass moments of inertia [kg·m²] about the screw's axis (screw and
        coupling) and the motor's axis, >= 0.
    gear_ratio : float
        Motor turns per screw turn [-], > 0 (1 for a direct drive).
    incline : float
        Angle of the axis above the horizontal [rad], in [-π/2, π/2]; +x
        climbs for a positive angle (π/2: a vertical axis moving up at +x).
    bearing_bore : float, optional
        Bore of the fixed-end support bearings [m]; None leaves their friction out.
    bearing_type : str
        A type of :data:`ballscrew.bearings.SKF_FRICTION_COEFFICIENTS` (SKF's
        simplified estimate) or, with ``bearing_outer_diameter``, of
        :data:`ballscrew.bearings.PALMGREN_BEARINGS`.
    bearing_outer_diameter : float, optional
        Outside diameter of the support bearings [m]; given, their friction is
        Palmgren's (it rises with speed and viscosity) and needs
        ``bearing_static_rating``.
    bearing_static_rating : float, optional
        Their basic static load rating :math:`C_0` [N], for Palmgren's load term.
    bearing_lubrication : str
        "grease" (or oil mist) or "oil" (bath or recirculating), for
        Palmgren's :math:`f_0`; the lubricant's viscosity is taken at the
        cycle's temperature (for grease, give the base oil as the lubricant
        or accept the screw oil's viscosity as an estimate).
    support : str
        End mounting of the screw, a key of
        :data:`ballscrew.limits.SUPPORT_EIGENVALUES`.
    bearing_span : float, optional
        Distance between the screw's supports [m]; None skips the
        critical-speed check.
    root_diameter : float, optional
        Root diameter of the thread [m]; None estimates it from the groove
        (:func:`ballscrew.limits.root_diameter`).
    dn_limit : float
        The nut's d·n limit [mm·rpm] (catalogue value).
    max_feed, max_acceleration : float, optional
        The axis' speed [m/s] and acceleration [m/s²] limits; a motion beyond
        them is refused (:func:`ballscrew.axis.duty.motion_plausibility`).
    """

    moving_mass: float
    screw_inertia: float = 0.0
    coupling_inertia: float = 0.0
    motor_inertia: float = 0.0
    gear_ratio: float = 1.0
    incline: float = 0.0
    bearing_bore: float | None = None
    bearing_type: str = "angular-contact ball, single row"
    bearing_outer_diameter: float | None = None
    bearing_static_rating: float | None = None
    bearing_lubrication: str = "grease"
    support: str = "fixed-supported"
    bearing_span: float | None = None
    root_diameter: float | None = None
    dn_limit: float = DEFAULT_DN_LIMIT
    max_feed: float | None = None
    max_acceleration: float | None = None

    def __post_init__(self) -> None:
        for name in ("moving_mass", "screw_inertia", "coupling_inertia", "motor_inertia"):
            check_nonnegative(name, getattr(self, name))
        check_positive("gear_ratio", self.gear_ratio)
        if not -math.pi / 2 <= check_finite("incline", self.incline) <= math.pi / 2:
            raise BallScrewInputError("incline", self.incline, "an angle in [-90°, 90°] (rad)")
        if self.support not in SUPPORT_EIGENVALUES:
            raise BallScrewInputError(
                "support", self.support, f"one of {list(SUPPORT_EIGENVALUES)}"
            )
        for name in ("bearing_span", "root_diameter", "bearing_bore", "bearing_outer_diameter"):
            if getattr(self, name) is not None:
                check_positive(name, getattr(self, name), "m")
        palmgren = self.bearing_outer_diameter is not None
        types = PALMGREN_BEARINGS if palmgren else SKF_FRICTION_COEFFICIENTS
        if self.bearing_type not in types:
            model = "Palmgren's model" if palmgren else "SKF's simplified estimate"
            raise BallScrewInputError("bearing_type", self.bearing_type,
                                      f"one of {list(types)} for {model}")  # fmt: skip
        if palmgren:
            if self.bearing_bore is None:
                raise BallScrewInputError(
                    "bearing_bore", None, "the bore, given with bearing_outer_diameter"
                )
            if self.bearing_static_rating is None:
                raise BallScrewInputError(
                    "bearing_static_rating", None,
                    "the support bearing's C0 from its catalogue, needed with "
                    "bearing_outer_diameter for Palmgren's load term",
                )  # fmt: skip
            check_positive("bearing_static_rating", self.bearing_static_rating, "N")
        if self.bearing_lubrication not in ("grease", "oil"):
            raise BallScrewInputError(
                "bearing_lubrication", self.bearing_lubrication, "'grease' or 'oil'"
            )
        check_positive("dn_limit", self.dn_limit, "mm*rpm")
        for name, unit in (("max_feed", "m/s"), ("max_acceleration", "m/s^2")):
            if getattr(self, name) is not None:
                check_positive(name, getattr(self, name), unit)


@dataclass(frozen=True)
class CycleResult:
    """Everything :func:`axis_cycle` computes (arrays per sample of the profile).

    Energies in J, torques in N·m, powers in W, speeds in rad/s, forces in N.
    ``friction_energy_by_mechanism`` splits ``friction_energy`` by the model's
    components (for the complete model: EHL rolling, sliding, the helix's
    transverse slip, hysteresis, ball-ball sliding, recirculation, ...); its
    values add up to it.
    """

    model: str
    time: FloatArray
    screw_speed: FloatArray
    axial_force: FloatArray
    friction_torque: FloatArray
    load_torque: FloatArray
    inertia_torque: FloatArray
    motor_torque: FloatArray
    motor_speed: FloatArray
    friction_power: FloatArray
    friction_energy: float
    friction_energy_out: float
    friction_energy_back: float
    bearing_torque: FloatArray
    bearing_energy: float
    constant_efficiency_energy: float
    load_work: float
    peak_motor_torque: float
    rms_motor_torque: float
    forward_efficiency: float
    reverse_efficiency: float
    friction: FrictionResult = field(repr=False)
    friction_energy_by_mechanism: dict[str, float] = field(default_factory=dict)
    speed_warnings: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, Any]:
        """The cycle's figures as JSON-ready values (the arrays per sample left out).

        The energies [J], the peak and RMS motor torque [N·m], the efficiencies
        at the working point, whether the load back-drives the screw there, and
        the model's validity issues and the speed limits passed, as text.
        """
        return {
            "friction_energy_J": self.friction_energy,
            "friction_energy_out_J": self.friction_energy_out,
            "friction_energy_back_J": self.friction_energy_back,
            "friction_energy_by_mechanism_J": self.friction_energy_by_mechanism,
            "bearing_energy_J": self.bearing_energy,
            "constant_efficiency_energy_J": self.constant_efficiency_energy,
            "load_work_J": self.load_work,
            "peak_motor_torque_Nm": self.peak_motor_torque,
            "rms_motor_torque_Nm": self.rms_motor_torque,
            "forward_efficiency": self.forward_efficiency,
            "reverse_efficiency": self.reverse_efficiency,
            "back_drives_at_working_point": self.reverse_efficiency > 0.0,
            "warnings": [str(issue) for issue in self.friction.warnings]
            + list(self.speed_warnings),
        }


def reverse_efficiency(result: FrictionResult, lead: float) -> FloatArray:
    r"""Back-driving efficiency: the load drives the screw [-].

    The load's power :math:`|F|l\omega/2\pi` reaches the screw less the
    friction :math:`T_f\omega`: :math:`\eta' = 1 - 2\pi T_f/(|F| l)`. Zero
    or negative means self-locking: the load cannot turn the screw. With the
    catalogue model this is :math:`2 - 1/\eta`, which agrees with THK's
    :math:`\tan(\beta-\rho)/\tan\beta` to first order in :math:`\mu`.
    NaN where there is no axial load.
    """
    f = np.abs(np.asarray(result.axial_load, dtype=float))
    with np.errstate(divide="ignore", invalid="ignore"):
        out: FloatArray = np.where(
            f > 0.0, 1.0 - 2.0 * math.pi * result.total / (f * lead), math.nan
        )
    return out


def weight_back_driving(
    screw: BallScrew,
    lubricant: Lubricant | str,
    axis: Axis,
    *,
    temperature: float = 40.0,
    creep_speed: float = 0.1,
    model: str = "complete",
    **parameters: Any,
) -> float:
    r"""Reverse efficiency under the axis's weight alone, motor off [-].

    The load is the weight's component along the axis,
    :math:`F = m g \sin\theta`, and the screw turns at ``creep_speed``
    [rad/s] (the friction of breaking away, without the film of a fast
    move): :math:`\eta' = 1 - 2\pi T_f/(F l)`. Positive: the weight turns
    the screw, and a vertical axis needs a brake; zero or negative: the screw's
    drag holds this weight (which is not self-locking: see
    :func:`self_locking`). NaN for a horizontal axis or no moving mass.
    The support bearings' friction, which also holds, is left out (the
    conservative side).
    """
    weight = axis.moving_mass * STANDARD_GRAVITY * abs(math.sin(axis.incline))
    if weight <= 0.0:
        return math.nan
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fr = friction_torque(
            screw, lubricant, speed=creep_speed, temperature=temperature, axial_load=weight,
            model=model, **parameters,
        )  # fmt: skip
    return float(np.ravel(reverse_efficiency(fr, screw.lead))[0])


def self_locking(
    screw: BallScrew,
    lubricant: Lubricant | str,
    *,
    temperature: float = 40.0,
    creep_speed: float = 0.1,
    model: str = "complete",
    **parameters: Any,
) -> bool:
    r"""Whether no axial load, however large, can turn the screw [-].

    A screw is self-locking when its friction angle exceeds its lead angle,
    :math:`\rho \ge \beta`: the friction that a load adds then outweighs the
    torque it exerts. With the catalogue's :math:`T = F l/(2\pi)(1/\eta - 1)`
    that is the reverse efficiency :math:`2 - 1/\eta \le 0`, THK's
    :math:`\tan(\beta - \rho) \le 0`. For any model the test is the load's
    share of the friction: the reverse efficiency of the friction *a load adds*,

    .. math:: \eta'_\infty = 1 - \frac{2\pi}{l}\,\frac{T(F_2) - T(F_1)}{F_2 - F_1},

    at two loads past the preload's lift-off (:math:`F_1 = 4\cdot 2^{1.5}F_{pr}
    + 1` kN, :math:`F_2 = 2F_1`), where the preload no longer adds to the drag.
    Ball screws, with :math:`\mu \approx 0.003` against :math:`\tan\beta \ge
    0.03`, are never self-locking: a light load that does not back-drive is held
    by the preload's drag, which wear lowers.
    """
    f1 = 4.0 * 2.0**1.5 * screw.preload + 1000.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fr = friction_torque(
            screw, lubricant, speed=creep_speed, temperature=temperature,
            axial_load=[f1, 2.0 * f1], model=model, **parameters,
        )  # fmt: skip
    added = float(fr.total[1] - fr.total[0]) / f1
    return bool(1.0 - 2.0 * math.pi * added / screw.lead <= 0.0)


def screw_motion(
    profile: Profile, screw: BallScrew, axis: Axis
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Screw speed [rad/s], its acceleration [rad/s²] and the nut's axial force [N] per sample."""
    omega = 2.0 * math.pi * profile.speed / screw.lead
    alpha = 2.0 * math.pi * profile.acceleration / screw.lead
    g_axial = STANDARD_GRAVITY * math.sin(axis.incline)
    force = axis.moving_mass * (profile.acceleration + g_axial) + profile.process_force
    return omega, alpha, force


def _bearing_torque(
    axis: Axis, lubricant: Lubricant | str, omega: FloatArray, force: FloatArray,
    temperature: float,
) -> FloatArray:  # fmt: skip
    """The support bearings' friction [N·m] at each sample (0 without a bearing bore)."""
    if axis.bearing_bore is None:
        return np.zeros_like(omega)
    if axis.bearing_outer_diameter is None:
        return simplified_bearing_torque(force, axis.bearing_bore, axis.bearing_type)
    from .. import lubricants

    oil = lubricants.get(lubricant) if isinstance(lubricant, str) else lubricant
    assert axis.bearing_static_rating is not None  # checked by Axis
    return palmgren_bearing_torque(
        omega, force, oil.kinematic_viscosity(temperature), bore=axis.bearing_bore,
        outer_diameter=axis.bearing_outer_diameter, static_rating=axis.bearing_static_rating,
        bearing_type=axis.bearing_type, lubrication=axis.bearing_lubrication,
    )  # fmt: skip


def distinct_pairs(
    omega: FloatArray, force: FloatArray
) -> tuple[FloatArray, FloatArray, npt.NDArray[np.intp]]:
    """The distinct (screw speed, axial force) pairs of the samples, and each sample's pair.

    Returns the pairs' speeds [rad/s] and forces [N] (sorted by speed, then force)
    and, for each sample, the index of its pair (shaped as ``omega``): the points
    :func:`axis_cycle` evaluates the friction model at.
    """
    keys = np.empty(omega.shape, dtype=complex)
    keys.real, keys.imag = omega, force
    pairs, inverse = np.unique(keys, return_inverse=True)
    return pairs.real.copy(), pairs.imag.copy(), inverse.reshape(omega.shape)


def _per_sample(
    screw: BallScrew, lubricant: Lubricant | str, omega: FloatArray, force: FloatArray,
    temperature: float, model: str, parameters: dict[str, Any],
) -> FrictionResult:  # fmt: skip
    """:func:`friction_torque` at every sample, the model run once per distinct (speed, force).

    A profile repeats its samples (constant feed, dwells, every cycle after
    the first); the result is spread back to the samples, so it is the
    sample-by-sample call's, without the contact state (``state`` None).
    """
    speeds, forces, index = distinct_pairs(omega, force)
    if speeds.size == omega.size:
        return friction_torque(
            screw, lubricant, speed=omega, temperature=temperature, axial_load=force,
            model=model, **parameters,
        )  # fmt: skip
    fr = friction_torque(
        screw, lubricant, speed=speeds, temperature=temperature, axial_load=forces,
        model=model, **parameters,
    )  # fmt: skip

    def spread(a: FloatArray) -> FloatArray:
        result: FloatArray = np.broadcast_to(a, speeds.shape)[index]
        return result

    return dataclasses.replace(
        fr,
        total=spread(fr.total),
        components={name: spread(part) for name, part in fr.components.items()},
        power_loss=spread(fr.power_loss),
        efficiency=spread(fr.efficiency),
        speed=omega.copy(),
        temperature=spread(fr.temperature),
        axial_load=force.copy(),
        state=None,
    )


def _integral(y: FloatArray, t: FloatArray) -> float:
    """Trapezoidal rule (exact for piecewise-linear samples)."""
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(t)))


def axis_cycle(
    profile: Profile,
    screw: BallScrew,
    lubricant: Lubricant | str,
    axis: Axis,
    *,
    temperature: float = 40.0,
    model: str = "complete",
    **parameters: Any,
) -> CycleResult:
    """Torques, powers and energies of ``axis`` driven through ``profile``.

    One call of the friction model over all samples. ``temperature`` [°C]
    is the lubricant's (constant over the profile).

    Examples
    --------
    >>> from ballscrew import reference_screw
    >>> from ballscrew.axis.motion import move
    >>> r = axis_cycle(move(0.3, 0.25, 2.0), reference_screw(), "PAO ISO VG 68",
    ...                Axis(moving_mass=200.0), model="catalog")
    >>> round(r.friction_energy, 2)  # catalogue drag 0.564 N·m over 30 screw turns, plus load
    106.82
    """
    lead = screw.lead
    omega, alpha, force = screw_motion(profile, screw, axis)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # recorded in the result's friction.warnings
        fr = _per_sample(screw, lubricant, omega, force, temperature, model, parameters)
        catalog = _per_sample(screw, lubricant, omega, force, temperature, "catalog", {})
    t_f = fr.total
    t_load = force * lead / (2.0 * math.pi)
    t_inertia = (axis.screw_inertia + axis.coupling_inertia) * alpha
    t_b = np.broadcast_to(_bearing_torque(axis, lubricant, omega, force, temperature), t_f.shape)
    sign = friction_sign(profile, omega, lead)
    t_screw = t_load + sign * (t_f + t_b) + t_inertia
    i = axis.gear_ratio
    t_motor = t_screw / i + axis.motor_inertia * i * alpha
    slip = sign * omega  # |omega| when moving; less inside the standstill ramp
    power = t_f * slip
    time = profile.time
    limits = _speed_limits(screw, omega, axis)
    for message in limits:
        warnings.warn(message, BallScrewSpeedWarning, stacklevel=2)
    forward, backward = _working_point_efficiencies(fr, force * profile.speed, lead)
    out = np.where(omega > 0.0, power, 0.0)
    back = np.where(omega < 0.0, power, 0.0)
    return CycleResult(
        model=fr.model,
        time=time,
        screw_speed=omega,
        axial_force=force,
        friction_torque=t_f,
        load_torque=t_load,
        inertia_torque=t_inertia,
        motor_torque=t_motor,
        motor_speed=omega * i,
        friction_power=power,
        friction_energy=_integral(power, time),
        friction_energy_out=_integral(out, time),
        friction_energy_back=_integral(back, time),
        bearing_torque=t_b,
        bearing_energy=_integral(t_b * slip, time),
        constant_efficiency_energy=_integral(catalog.total * slip, time),
        load_work=_load_work(axis, profile),
        peak_motor_torque=float(np.max(np.abs(t_motor))),
        rms_motor_torque=math.sqrt(_integral(t_motor**2, time) / profile.duration),
        forward_efficiency=forward,
        reverse_efficiency=backward,
        friction=fr,
        speed_warnings=tuple(limits),
        friction_energy_by_mechanism=_energy_by_mechanism(fr, slip, time),
    )


def friction_energy(
    profile: Profile, screw: BallScrew, lubricant: Lubricant | str, axis: Axis, *,
    temperature: float = 40.0, model: str = "complete", **parameters: Any,
) -> float:  # fmt: skip
    """The screw's friction energy over ``profile`` [J]: :func:`axis_cycle`'s alone.

    The same friction call and the same trapezoidal rule, without the
    catalogue rule, the bearings and the motor; for the energy of a cycle at
    another temperature (the one it warms up to).
    """
    omega, _, force = screw_motion(profile, screw, axis)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # as axis_cycle: kept out of this figure
        fr = _per_sample(screw, lubricant, omega, force, temperature, model, parameters)
    slip = friction_sign(profile, omega, screw.lead) * omega
    return _integral(fr.total * slip, profile.time)


def friction_sign(profile: Profile, omega: FloatArray, lead: float) -> FloatArray:
    r"""The sign the friction torque takes at each sample [-].

    :func:`~ballscrew.axis.standstill.regularised_sign` of the screw speed
    ``omega`` [rad/s] over the profile's ``standstill_speed`` taken to the
    screw, :math:`2\pi v_s/l` (``lead`` :math:`l` [m]); the exact sign for a
    planned profile (``standstill_speed`` 0).
    """
    return regularised_sign(omega, 2.0 * math.pi * profile.standstill_speed / lead)


def _energy_by_mechanism(
    fr: FrictionResult, slip: FloatArray, time: FloatArray
) -> dict[str, float]:
    r"""The friction energy of each loss mechanism over the profile [J].

    ``slip`` is the screw speed times the friction's sign, :math:`|\omega|` when moving.
    """
    return {
        name: _integral(np.broadcast_to(part, fr.total.shape) * slip, time)
        for name, part in fr.components.items()
    }


def _speed_limits(screw: BallScrew, omega: FloatArray, axis: Axis) -> list[str]:
    """The speed limits the profile's fastest screw speed passes, in words."""
    return speed_limit_issues(
        screw, float(np.max(np.abs(omega))), span=axis.bearing_span, support=axis.support,
        dn_limit=axis.dn_limit, root=axis.root_diameter,
    )  # fmt: skip


def _working_point_efficiencies(
    fr: FrictionResult, load_power: FloatArray, lead: float
) -> tuple[float, float]:
    """Forward and reverse efficiency at the working point.

    The working point is the sample of largest ``|F v|`` (the process force at
    feed, or the peak of acceleration).
    """
    k = int(np.argmax(np.abs(load_power)))
    forward = float(np.ravel(fr.efficiency)[k])
    backward = float(np.ravel(reverse_efficiency(fr, lead))[k])
    return forward, backward


def _load_work(axis: Axis, profile: Profile) -> float:
    """Work on the load over the profile [J].

    The change of kinetic and potential energy (exact, whatever the sampling of
    steps in acceleration) plus the process force's work.
    """
    g_axial = STANDARD_GRAVITY * math.sin(axis.incline)
    return (
        0.5 * axis.moving_mass * float(profile.speed[-1] ** 2 - profile.speed[0] ** 2)
        + axis.moving_mass * g_axial * float(profile.position[-1] - profile.position[0])
        + _integral(profile.process_force * profile.speed, profile.time)
    )
