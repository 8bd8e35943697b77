r"""The dynamic model of a ball screw feed axis: two masses, a spring, friction with pre-sliding.

All quantities are taken to the table side through the lead :math:`l` and the
gear ratio :math:`i` (motor turns per screw turn), :math:`x = \theta_s\,l/2\pi
= \theta_m\,l/(2\pi i)`, so that one model serves every axis:

* **motor side** :math:`m_1 = (J_m i^2 + J_c + J_s)\,(2\pi/l)^2` [kg]: the
  motor rotor through the gear, the coupling and the screw shaft, at position
  :math:`x_1` (what the motor encoder reads);
* **table side** :math:`m_2` [kg]: the moving mass (table, workpiece, nut),
  at position :math:`x_2` (what a ballbar or a linear scale reads);
* **the spring between them**, :math:`1/k = 1/k_s + 1/k_t + 1/k_n + 1/k_b`:
  the shaft in tension (:func:`~ballscrew.design.stiffness.shaft_axial_stiffness`),
  in torsion (:func:`~ballscrew.design.stiffness.torsional_axial_stiffness`),
  the nut (:func:`~ballscrew.design.stiffness.design_nut_stiffness`, the value
  ``ballscrew check`` prints and LuGre's bristles take) and the thrust bearings
  (``[check] support_stiffness``, rigid when not given), with the nut at
  mid-span; a structural damping ratio :data:`STRUCTURAL_DAMPING` on the
  reduced mass;
* **screw friction** on the motor side (:math:`\dot x_1`): the screw's drag
  is a torque between screw and nut that the motor supplies through the
  coupling and the shaft in torsion; it makes no axial force on the nut, so
  the axial spring does not carry it (the shaft's wind-up under it is tens
  of nanometres, ``ballscrew check``'s torsion share). The nut takes no
  axial share of the drag in this model: the axial force through it is the
  table's inertia, the guideways' friction and the weight. The drag is the
  chosen model's torque at the axis load and temperature, evaluated once
  over a grid of speeds (:func:`ballscrew.servo.friction_map.friction_map`)
  and interpolated, with the pre-rolling of a LuGre bristle (Canudas de Wit
  et al., IEEE TAC 40, 1995):
  :math:`\dot z = v - \sigma_0|v|z/g(v)`, :math:`F = \sigma_0 z + \sigma_1\dot z`,
  whose steady state is the map :math:`g(v)\,\mathrm{sgn}\,v` itself. Its
  stiffness is the creep friction over the **pre-rolling length**
  :math:`\delta`, :math:`\sigma_0 = g(0^+)/\delta` (the friction reaches 63 %
  of its rolling value after :math:`\delta` of travel from rest, 95 % after
  :math:`3\delta`): ``[axis] pre_rolling_length``, by default
  :data:`PRE_ROLLING_LENGTH`. Rolling contacts build their traction over a
  rolling distance set by the contacts' elastic slip (Al-Bender and De
  Moerlooze, "A model of the transient behavior of tractive rolling
  contacts", Adv. Tribol. 2008, 214894; De Moerlooze and Al-Bender,
  "Experimental investigation into the tractive prerolling behavior of balls
  in V-grooved tracks", Adv. Tribol. 2008, 561280), longer than the nut's
  normal compliance alone gives (:math:`g/k_{nut}` = 0.66 µm on the
  example). The default and its range are read from a measured rolling ball
  guide (:data:`PRE_ROLLING_RANGE`);
  ``drag_side="table"`` puts the drag on the table instead, the lumped
  upper bound whose lost motion is :math:`2F/k`;
* **guideway friction** on the table side, Coulomb plus viscous with its own
  bristle, when given; left out otherwise (noted);
* the weight of an inclined axis on the table side.

The **rigid model** joins both masses (:math:`k \to \infty`): one mass
:math:`m_1 + m_2` at one position. It misses the table's lag behind the
motor under friction and acceleration (:math:`F/k`, the lost motion a
motor encoder does not see), the axis' resonance that bounds the velocity
loop's bandwidth, and the difference between the position the loop
controls (the motor's) and the one the ballbar measures (the table's).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..axis.setup import axis_setup
from ..design.limits import root_diameter
from ..design.stiffness import (
    design_nut_stiffness,
    series_stiffness,
    shaft_axial_stiffness,
    torsional_axial_stiffness,
)
from ..errors import BallScrewInputError, FloatArray
from ..io.case import Case
from ..materials import STANDARD_GRAVITY
from .friction_map import friction_map

__all__ = [
    "DRAG_SIDES",
    "GUIDE_PRESLIDING",
    "PRE_ROLLING_LENGTH",
    "PRE_ROLLING_RANGE",
    "STRUCTURAL_DAMPING",
    "AxisDynamics",
    "axis_dynamics",
    "frictionless",
]

STRUCTURAL_DAMPING = 0.02
"""Damping ratio of the axis' axial mode [-]: a bolted steel structure with rolling
contacts; measured axes lie between about 0.01 and 0.05."""

PRE_ROLLING_LENGTH = 5e-6
"""Default pre-rolling length of the screw's drag [m], table travel: the bristle's
stiffness is the creep friction over it (module docstring). The geometric middle (4.5 µm,
rounded) of :data:`PRE_ROLLING_RANGE`: linear within 5 % up to 0.5 µm of travel and at 99 %
of the rolling friction after 23 µm. The glitch's dependence on it is in the docs
(positioning-accuracy.md, "The pre-rolling length")."""

PRE_ROLLING_RANGE = (1e-6, 20e-6)
r"""The pre-rolling lengths [m] a single exponential build-up can take from a measured
rolling contact. Futami, Furutani and Yoshida, "Nanometer positioning and its
micro-dynamics", Nanotechnology 1 (1990) 31-37, measured a rolling ball guide: its balls act
as a linear spring within about 0.1 µm of travel, and normal rolling takes place beyond
about 100 µm. LuGre's build-up from rest, :math:`F/g = 1 - e^{-x/\delta}`, is linear within
5 % for :math:`x < 0.1\delta` and within 1 % of rolling for :math:`x > 4.6\delta`: the
linear end gives :math:`\delta` = 1 µm, the rolling end 22 µm (rounded to 20). One
exponential cannot meet both ends (they are 1000 apart, its two ends 46), so the range
brackets the lengths that fit either; the lower end is also about the nut's normal
compliance (0.66 µm on the example). The measurement is of a guide, not a ball screw's nut:
no measured pre-rolling length of a ball screw was found."""

DRAG_SIDES = ("motor", "table")
"""Where the screw's drag acts: on the motor side (the torque it is) or on the table (the
lumped upper bound of earlier versions)."""

GUIDE_PRESLIDING = 1e-6
"""Pre-sliding distance of the guideways [m]: their bristle stiffness is the
Coulomb force over it (rolling guides yield a few micrometres before they roll)."""


@dataclass(frozen=True)
class AxisDynamics:
    r"""One feed axis as the servo simulation takes it, table side (module docstring).

    Attributes
    ----------
    name : str
        Label (the case's title).
    motor_mass, table_mass : float
        :math:`m_1`, :math:`m_2` [kg].
    stiffness : float
        :math:`k` [N/m]; ``inf`` makes the axis rigid.
    damping : float
        Damping of the spring [N·s/m].
    speeds : numpy.ndarray
        Table speeds of the friction map [m/s], signed, ascending.
    friction : numpy.ndarray
        Screw friction force at those speeds [N], signed like the speed.
    bristle_stiffness, bristle_damping : float
        :math:`\sigma_0` [N/m], :math:`\sigma_1` [N·s/m] of the screw friction.
    guide_coulomb, guide_viscous : float
        Guideway friction [N], [N·s/m] (0: none).
    external_force : float
        Constant force on the table along +x [N] (the weight of an inclined axis).
    lead, gear_ratio : float
        [m], motor turns per screw turn: the motor side is ``(2 pi / lead) / gear_ratio``
        table metres per motor radian away.
    drag_side : str
        Where the screw's drag acts, one of :data:`DRAG_SIDES`.
    notes : tuple of str
        What was assumed or left out.
    """

    name: str
    motor_mass: float
    table_mass: float
    stiffness: float
    damping: float
    speeds: FloatArray
    friction: FloatArray
    bristle_stiffness: float
    bristle_damping: float
    guide_coulomb: float = 0.0
    guide_viscous: float = 0.0
    external_force: float = 0.0
    lead: float = 0.01
    gear_ratio: float = 1.0
    drag_side: str = "motor"
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        if self.drag_side not in DRAG_SIDES:
            raise BallScrewInputError("drag_side", self.drag_side, f"one of {list(DRAG_SIDES)}")

    @property
    def drag_mass(self) -> float:
        """The mass the screw's drag acts on [kg]: the motor side, the table, or the whole."""
        if self.rigid:
            return self.mass
        return self.motor_mass if self.drag_side == "motor" else self.table_mass

    @property
    def pre_rolling_length(self) -> float:
        """The screw bristle's characteristic length, creep friction over its stiffness [m]."""
        return self.coulomb_force() / self.bristle_stiffness

    @property
    def mass(self) -> float:
        """Total moving mass seen from the table [kg]."""
        return self.motor_mass + self.table_mass

    @property
    def rigid(self) -> bool:
        """True for the one-mass model."""
        return not math.isfinite(self.stiffness)

    def as_rigid(self) -> AxisDynamics:
        """The same axis with an infinitely stiff spring (the one-mass model).

        The bristle stays critically damped, now on the whole mass.
        """
        s1 = 2.0 * math.sqrt(self.bristle_stiffness * self.mass)
        return replace(self, stiffness=math.inf, damping=0.0, bristle_damping=s1)

    @property
    def eigenfrequency(self) -> float:
        r"""The two-mass axis' axial eigenfrequency :math:`\sqrt{k(1/m_1 + 1/m_2)}/2\pi` [Hz]."""
        if self.rigid:
            return math.inf
        return math.sqrt(self.stiffness * (1.0 / self.motor_mass + 1.0 / self.table_mass)) / (
            2.0 * math.pi
        )

    @property
    def antiresonance(self) -> float:
        r"""The table on the spring with the motor held, :math:`\sqrt{k/m_2}/2\pi` [Hz]."""
        return (
            math.inf
            if self.rigid
            else math.sqrt(self.stiffness / self.table_mass) / (2.0 * math.pi)
        )

    def coulomb_force(self) -> float:
        """The screw friction at the map's slowest speeds [N] (mean of both directions)."""
        return _creep(self.speeds, self.friction)

    def motor_torque(self, force: FloatArray | float) -> FloatArray:
        """Motor torque [N·m] that makes a table-side force [N]."""
        return np.asarray(force, dtype=float) * self.lead / (2.0 * math.pi * self.gear_ratio)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready figures of the model."""
        return {
            "name": self.name,
            "motor_side_mass_kg": self.motor_mass,
            "table_mass_kg": self.table_mass,
            "stiffness_N_per_um": None if self.rigid else self.stiffness / 1e6,
            "damping_N_s_per_m": self.damping,
            "eigenfrequency_Hz": None if self.rigid else self.eigenfrequency,
            "antiresonance_Hz": None if self.rigid else self.antiresonance,
            "friction_at_creep_N": self.coulomb_force(),
            "bristle_stiffness_N_per_um": self.bristle_stiffness / 1e6,
            "bristle_damping_N_s_per_m": self.bristle_damping,
            "pre_rolling_length_um": self.pre_rolling_length * 1e6,
            "drag_side": self.drag_side,
            "guide_coulomb_N": self.guide_coulomb,
            "guide_viscous_N_s_per_m": self.guide_viscous,
            "external_force_N": self.external_force,
            "lead_m": self.lead,
            "gear_ratio": self.gear_ratio,
            "notes": list(self.notes),
        }


def _creep(speeds: FloatArray, friction: FloatArray) -> float:
    """A friction map's force at its slowest speeds [N], the mean of both directions."""
    return 0.5 * (float(np.abs(friction[speeds < 0][-1]))
                  + float(np.abs(friction[speeds > 0][0])))  # fmt: skip


def frictionless(axis: AxisDynamics) -> AxisDynamics:
    """The axis without any friction (screw or guideway)."""
    return replace(axis, friction=np.zeros_like(axis.friction), guide_coulomb=0.0,
                   guide_viscous=0.0)  # fmt: skip


def _axis_spring(case: Case, axis: Any, nut_load: float, notes: list[str]) -> tuple[float, float]:
    """The axis spring between motor and table and the nut's part of it [N/m].

    Shaft tension and torsion with the nut at mid-span, the nut (at ``nut_load`` [N] for
    a single nut), the thrust bearings: in series, as ``ballscrew check`` adds them.
    """
    screw = case.screw
    lead = screw.lead
    span: float | None = axis.bearing_span or case.thermal.get("screw_length")
    d_r = root_diameter(screw) if axis.root_diameter is None else float(axis.root_diameter)
    position = 0.5 * span if span else None
    if screw.nut == "single":
        if nut_load == 0.0:
            raise BallScrewInputError(
                "screw.nut", "single", "a preloaded nut or an axial load: a single nut "
                "without either has no stiffness",
            )  # fmt: skip
        k_nut = design_nut_stiffness(screw, abs(nut_load))
    else:
        k_nut = design_nut_stiffness(screw)
    k_bearing = case.check.get("support_stiffness")
    k_shaft: float | None = None
    k_twist: float | None = None
    if position is None or span is None:
        notes.append("no span: the shaft taken as rigid (give axis.bearing_span)")
    else:
        k_shaft = float(shaft_axial_stiffness(d_r, span, position, axis.support))
        k_twist = float(torsional_axial_stiffness(d_r, position, lead))
        notes.append(f"nut at mid-span ({position * 1e3:.0f} mm from the thrust bearing): "
                     "shaft tension and torsion there")  # fmt: skip
    if k_bearing is None:
        notes.append("thrust bearings rigid (give check.support_stiffness)")
    k = float(series_stiffness(k_shaft, k_twist, k_nut, k_bearing))
    return k, k_nut


def axis_dynamics(
    case: Case,
    model: str = "complete",
    *,
    max_speed: float = 0.5,
    guide_coulomb: float | None = None,
    guide_viscous: float = 0.0,
    axial_load: float | None = None,
    temperature: float | None = None,
    pre_rolling_length: float | None = None,
    drag_side: str = "motor",
) -> AxisDynamics:
    """The two-mass model of ``case``'s axis (module docstring).

    Parameters
    ----------
    case : Case
        Screw, lubricant, ``[axis]`` (moving mass, inertias, gear, support,
        span, incline), ``[check] support_stiffness``.
    model : str
        Friction model of the screw.
    max_speed : float
        Fastest table speed of the friction map [m/s].
    guide_coulomb, guide_viscous : float, optional
        Guideway friction [N], [N·s/m]; None leaves it out with a note.
    axial_load : float, optional
        Process force on the nut [N] (default: the case's first); an inclined
        axis' weight is added.
    temperature : float, optional
        [°C] (default: the case's first).
    pre_rolling_length : float, optional
        [m] of the screw's drag (default: the case's ``[axis] pre_rolling_length``, else
        :data:`PRE_ROLLING_LENGTH`, 5 µm, within :data:`PRE_ROLLING_RANGE`, 1 to 20 µm, read
        from Futami, Furutani and Yoshida, Nanotechnology 1 (1990) 31-37).
    drag_side : {"motor", "table"}
        Where the screw's drag acts (module docstring).
    """
    if not case.axis.get("moving_mass"):
        raise BallScrewInputError(
            "axis.moving_mass", case.axis.get("moving_mass", 0.0),
            f"a positive moving mass in the [axis] of '{case.title}' (the servo model needs "
            "the table it moves)",
        )  # fmt: skip
    if not max_speed > 0.0:
        raise BallScrewInputError("max_speed", max_speed, "a positive table speed [m/s]")
    screw = case.screw
    setup = axis_setup(screw, case.axis, case.thermal, 0.0)
    axis = setup.axis
    notes = [n for n in setup.notes if "inertia" in n or "screw_length" in n]
    lead, ratio = screw.lead, axis.gear_ratio
    to_table = (2.0 * math.pi / lead) ** 2
    m1 = (axis.motor_inertia * ratio**2 + axis.coupling_inertia + axis.screw_inertia) * to_table
    m2 = axis.moving_mass
    if not axis.motor_inertia:
        notes.append("no motor inertia in the case (axis.motor_inertia): the motor side is the "
                     "screw and coupling only")  # fmt: skip
    weight = -m2 * STANDARD_GRAVITY * math.sin(axis.incline)
    load = float(case.axial_load.flat[0]) if axial_load is None else float(axial_load)
    k, k_nut = _axis_spring(case, axis, load + weight, notes)
    reduced = m1 * m2 / (m1 + m2)
    damping = 2.0 * STRUCTURAL_DAMPING * math.sqrt(k * reduced)
    notes.append(f"structural damping ratio {STRUCTURAL_DAMPING:g} of the axial mode (assumed)")
    temp = float(case.temperature.flat[0]) if temperature is None else float(temperature)
    # The friction map over table speeds 1e-5 m/s .. max_speed, both ways, at the nut's load.
    table_speeds = np.geomspace(1e-5, max_speed, 48)
    screw_speeds = table_speeds * 2.0 * math.pi / lead
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fmap = friction_map(case, model, speeds=screw_speeds, loads=[load + weight],
                            temperatures=[temp])  # fmt: skip
    force = np.asarray(fmap.force[0, 0, :], dtype=float)
    speeds = np.asarray(fmap.table_speeds, dtype=float)
    notes.append(f"screw friction: {fmap.model} at {load + weight:.4g} N and {temp:g} degC, "
                 f"{speeds.size} speeds up to {max_speed:g} m/s, interpolated in the "
                 "loop")  # fmt: skip
    if weight:
        notes.append(f"the weight along the axis, {weight:.4g} N, acts on the table and loads "
                     "the nut")  # fmt: skip
    if drag_side not in DRAG_SIDES:
        raise BallScrewInputError("drag_side", drag_side, f"one of {list(DRAG_SIDES)}")
    given = case.axis.get("pre_rolling_length")
    delta = float(pre_rolling_length if pre_rolling_length is not None else
                  given if given is not None else PRE_ROLLING_LENGTH)  # fmt: skip
    if not (math.isfinite(delta) and delta > 0.0):
        raise BallScrewInputError("axis.pre_rolling_length", delta,
                                  "a positive length [m], e.g. '5 um'")  # fmt: skip
    creep = _creep(speeds, force)
    s0 = creep / delta if creep > 0.0 else k_nut
    on = m1 if drag_side == "motor" else m2
    s1 = 2.0 * math.sqrt(s0 * on)
    source = ("given" if pre_rolling_length is not None or given is not None
              else "the default, from a measured rolling guide: 1 to 20 um")  # fmt: skip
    where = "motor side (a torque)" if drag_side == "motor" else "table (lumped upper bound)"
    notes.append(f"screw drag on the {where}; pre-rolling length {delta * 1e6:.3g} um "
                 f"({source}; its LuGre bristle {s0 / 1e6:.4g} N/um, critically damped on "
                 f"{on:.4g} kg)")  # fmt: skip
    if guide_coulomb is None:
        notes.append("guideway friction left out (give it: it adds to the glitch, and the "
                     "screw's compensation does not remove it)")  # fmt: skip
        guide_coulomb = 0.0
    return AxisDynamics(case.title, m1, m2, k, damping, speeds, force, s0, s1,
                        float(guide_coulomb), float(guide_viscous), weight, lead, ratio,
                        drag_side, tuple(notes))  # fmt: skip
