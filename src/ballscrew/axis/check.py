r"""The whole axis check: life, safety, speed, stiffness, thermal lead error and the motor.

(A long module, about 970 lines: each row's text (label, source, advice and the notes
that state its defaults) is written beside the figures it is built from, one function
per group of rows; the drawn formulas themselves are in :mod:`.criteria`.)

What ``ballscrew check`` computes. :func:`run_check` takes an
:class:`~ballscrew.axis.duty.EnergyRun` (the case, the motion cycle, the torques
and the temperature the cycle reaches, as ``ballscrew energy`` computes them)
and sets every criterion of a feed-drive designer's sizing against its limit,
with the formulas of :mod:`ballscrew.sizing`, :mod:`ballscrew.stiffness` and
:mod:`ballscrew.limits`:

* **fatigue life** (ISO 3408-5): the load spectrum is the nut's axial force at
  every sample of the cycle (inertia, gravity, process force) weighted by the
  screw turns made under it; a preloaded nut's halves carry the preload
  changed by it, each half has its cubic mean load and its life, and the nut's
  life is the two in series;
* **static safety** :math:`C_{0a}/F_{max}` on the most loaded half;
* **buckling**, the **yield** of the root section, the **critical speed** and
  **d·n**;
* **stiffness**: shaft, nut (Hertz at the preload, or at the cycle's peak load
  without one, brought to the makers' printed
  rigidity and derated to 80 %) and thrust bearings in
  series over the stroke, the **axial eigenfrequency** with the moving mass
  and the **lost motion** at a reversal, :math:`2F_f/k`, with :math:`F_f` the
  screw's drag torque at creep speed as an axial force, :math:`2\pi T_f/l`: an
  upper bound, as if the whole axis carried the drag (the lumped two-mass model of
  :mod:`ballscrew.servo`); the drag torque itself twists the shaft and strains
  the nut's contacts before they roll (both printed beside it), and only a
  guideway's friction loads the whole axis;
* **thermal lead error**: :math:`\alpha\,\Delta T\cdot 300` mm, with
  :math:`\Delta T` the rise the heat balance reaches over the run time (less
  what a pre-tension absorbs), against the accuracy grade's :math:`v_{300p}`;
* **the motor**: inertia ratio, peak and RMS torque, speed, and the
  acceleration the peak torque allows.

Each row has a stable key (:data:`~.criteria.KEYS`); the criteria with an
uncertain input are one function each in :mod:`.criteria`, called with a draw
of ones for the row and with the draws for its P(NOT OK).

Each :class:`Criterion` has a value, a limit, their ratio (the utilisation,
oriented so that above 1 fails), a verdict, the formula's source and what to
change when it fails. Verdicts: ``OK`` below :data:`CHECK_FROM` of the limit,
``CHECK`` up to the limit, ``NOT OK`` past it, ``INFO`` for a figure without
a limit, ``NOT CHECKED`` where an input is missing (the row names it).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .._moved import renamed
from ..chain import friction_torque
from ..design.catalog_formulas import (
    DRAG_TORQUE_TOLERANCE,
    drag_torque_tolerance,
    preload_torque,
)
from ..design.limits import SAFETY_FACTOR, critical_speed, root_diameter
from ..design.sizing import (
    STEEL_EXPANSION,
    TRAVEL_VARIATION_300,
    buckling_load,
    cubic_mean_load,
    life_distance,
    reflected_inertia,
    reliability_factor,
    thermal_elongation,
)
from ..design.stiffness import (
    CATALOGUE_RIGIDITY_RATIO,
    CATALOGUE_RIGIDITY_SCATTER,
    DESIGN_ALLOWANCE,
    axial_eigenfrequency,
    design_nut_stiffness,
    lost_motion,
    series_stiffness,
    shaft_axial_stiffness,
    torsional_axial_stiffness,
)
from ..errors import BallScrewInputError, FloatArray
from ..geometry import nut_length
from ..io.case import Case
from ..kinematics import rad_s_to_rpm
from ..loads import LIFT_OFF_RATIO
from .criteria import CRITERIA, Inputs, Sample, drawn, nominal, nut_halves, ones
from .duty import EnergyRun, ModelEnergy, run_inputs
from .energy import CycleResult
from .uncertainty import SAMPLES, SEED, Draws, VerdictUncertainty, draws, judge, model_error

__all__ = [
    "CHECK_FROM",
    "AxisCheck",
    "Criterion",
    "check_inputs",
    "criterion_inputs",
    "run_check",
    "verdict",
]

DEFAULT_LOAD_FACTOR = 1.2
"""Load factor f_w of the life when the case gives none [-]: 1.2, where THK's normal
running (1.2 to 1.5, A15-40) begins and its smooth running (1.0 to 1.2) ends, as HIWIN
and NSK size a machine-tool feed axis; ISO 3408-5's own life (f_w = 1) would be the
optimistic one. Said in the row and the notes."""

CHECK_FROM = 0.9
"""Utilisation from which a criterion is flagged CHECK rather than OK [-]."""

DEFAULT_LIFE_HOURS = 20_000.0
"""Nominal life asked when the case gives none [h]: THK's and NSK's figure for machine tools."""

INERTIA_RATIO_LIMIT = 10.0
"""Largest load-to-rotor inertia ratio of a responsive servo axis [-] (a sizing rule of the
servo makers, e.g. Siemens and Yaskawa: 10 or less; not a standard)."""

YIELD_STRESS = 147e6
"""Permissible tensile/compressive stress of the screw shaft [Pa] (THK General Catalog,
Permissible Axial Load, A15-30, equation 6)."""

DEFAULT_AXIAL_PLAY = 20e-6
"""Axial play of a nut without preload when the case gives none [m]: THK's clearance G2 of a
precision ball screw, 0.02 mm or less (General Catalog, "Axial Clearance", A15-19)."""

CREEP_SPEED = 0.1
"""Screw speed of a reversal's friction [rad/s] (the drag without a fast move's film)."""


def verdict(utilisation: float) -> str:
    """OK, CHECK or NOT OK for a utilisation (value over limit, above 1 fails; NaN fails)."""
    if math.isnan(utilisation) or utilisation > 1.0:
        return "NOT OK"
    return "CHECK" if utilisation >= CHECK_FROM else "OK"


@dataclass(frozen=True)
class Criterion:
    """One row of the verdict table (values in the unit named, for display and JSON)."""

    name: str
    value: float | None
    limit: float | None
    unit: str
    utilisation: float | None
    verdict: str
    source: str
    advice: str = ""
    uncertainty: VerdictUncertainty | None = None
    """P(NOT OK), the utilisation's 95 % interval and the guarded verdict (rows with a limit)."""
    key: str = ""
    """The row's stable key (``life``, ``peak_torque``, ...: :data:`~.criteria.KEYS`): readers
    find a row by it, never by its label, which carries the state and the grade."""

    def as_dict(self) -> dict[str, Any]:
        """The row as JSON-ready values (the uncertainty's keys null for a row without a limit)."""
        u = self.uncertainty
        return {
            "key": self.key,
            "name": self.name,
            "value": self.value,
            "limit": self.limit,
            "unit": self.unit,
            "utilisation": self.utilisation,
            "verdict": self.verdict,
            "p_not_ok": None if u is None else u.p_not_ok,
            "utilisation_95": None if u is None else [u.low, u.high],
            "guarded_verdict": None if u is None else u.guarded,
            "source": self.source,
            "advice": self.advice,
        }


def _at_most(
    key: str, name: str, value: float, limit: float, unit: str, source: str, advice: str
) -> Criterion:
    u = value / limit
    v = verdict(u)
    return Criterion(name, value, limit, unit, u, v, source, advice if v != "OK" else "",
                     key=key)  # fmt: skip


def _at_least(
    key: str, name: str, value: float, limit: float, unit: str, source: str, advice: str
) -> Criterion:
    u = limit / value if value > 0.0 else math.inf
    v = verdict(u)
    return Criterion(name, value, limit, unit, u, v, source, advice if v != "OK" else "",
                     key=key)  # fmt: skip


def _info(key: str, name: str, value: float, unit: str, source: str, advice: str = "") -> Criterion:
    return Criterion(name, value, None, unit, None, "INFO", source, advice, key=key)


def _missing(key: str, name: str, unit: str, source: str, needed: str) -> Criterion:
    return Criterion(name, None, None, unit, None, "NOT CHECKED", source, needed, key=key)


@dataclass(frozen=True)
class AxisCheck:
    """The verdict table of an axis over a cycle, the figures behind it and the assumptions."""

    title: str
    model: str
    criteria: list[Criterion]
    assumptions: list[str]
    life: dict[str, Any] = field(default_factory=dict)
    stiffness: dict[str, Any] = field(default_factory=dict)
    motor: dict[str, Any] = field(default_factory=dict)
    thermal: dict[str, Any] = field(default_factory=dict)
    inputs: dict[str, Any] = field(default_factory=dict)
    """What the verdicts were computed from (:func:`check_inputs`); the face adds the command."""
    p_not_ok: float | None = None
    """The probability that one row or more is NOT OK, over the same draws as the rows' (None
    when the Monte Carlo was not drawn)."""

    @property
    def verdict(self) -> str:
        """The worst verdict of the rows that have a limit."""
        order = ("NOT OK", "CHECK", "OK")
        found = {c.verdict for c in self.criteria}
        return next((v for v in order if v in found), "OK")

    def row(self, key: str) -> Criterion | None:
        """The row of stable key ``key`` (:data:`~.criteria.KEYS`), None when the check has none.

        The one way to find a row: its label carries the state and the grade and may change.
        """
        return next((c for c in self.criteria if c.key == key), None)

    @property
    def not_checked(self) -> list[str]:
        """The criteria left out for a missing input."""
        return [c.name for c in self.criteria if c.verdict == "NOT CHECKED"]

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew check --json``.

        Without the package's version, which the JSON writer adds
        (:func:`ballscrew.report.outputs.result_json`).
        """
        return {
            "case": self.title,
            "model": self.model,
            "verdict": self.verdict,
            "p_not_ok": self.p_not_ok,
            "not_checked": self.not_checked,
            "criteria": [c.as_dict() for c in self.criteria],
            "life": self.life,
            "stiffness": self.stiffness,
            "motor": self.motor,
            "thermal": self.thermal,
            "assumptions": self.assumptions,
            "inputs": self.inputs,
        }


def _weights(time: FloatArray) -> FloatArray:
    """Trapezoidal weights of the samples [s]: sum(w * y) is the integral of y."""
    dt = np.diff(time)
    w = np.zeros_like(time)
    w[:-1] += 0.5 * dt
    w[1:] += 0.5 * dt
    return w


def _span(run: EnergyRun, notes: list[str]) -> float:
    """Distance between the supports [m]: the given span, else the screw length (stated)."""
    if run.axis.bearing_span is not None:
        return float(run.axis.bearing_span)
    span = float(run.node.screw_length)
    notes.append(
        f"span between the supports taken as the screw length {span * 1e3:.0f} mm (give "
        "axis.bearing_span for buckling, critical speed and shaft stiffness)"
    )
    return span


def run_check(
    run: EnergyRun,
    model: str | None = None,
    *,
    draws_when_failing: bool = True,
    draws: bool = True,
) -> AxisCheck:
    """Every criterion of the axis over ``run``'s cycle for ``model`` (module docstring).

    ``model`` defaults to the run's first. The verdicts are those of the rows'
    nominal values; the Monte Carlo adds each row's P(NOT OK). With
    ``draws_when_failing=False`` it is left out when a row already fails at its
    nominal value (the verdict, every row's value and the binding row are the
    same; no row carries an uncertainty): ``ballscrew select`` rejects such a
    candidate without drawing. With ``draws=False`` it is never drawn
    (``ballscrew program``: a long program's load spectrum makes the draws
    cost seconds an axis). Raises
    :class:`~ballscrew.errors.BallScrewInputError` naming the field when the
    stroke does not fit between the supports or a motor is given without its
    rotor inertia, and the heat balance's error when ``run`` kept one
    (:func:`~ballscrew.axis.duty.run_energy`'s ``thermal_failure``).
    """
    name = model or next(iter(run.results))
    energy = run.results[name]
    if energy.thermal_error is not None:
        raise energy.thermal_error
    cycle = energy.cycle
    case, axis, screw = run.case, run.axis, run.case.screw
    notes: list[str] = []
    if "moving_mass" not in case.axis_given:
        notes.append(
            f"axis.moving_mass = {axis.moving_mass:g} kg (not given): the moving mass's "
            "inertia and weight are left out of the fatigue life, static safety, lift-off "
            "and motor torque rows, and there is no axial eigenfrequency; give "
            "axis.moving_mass"
        )
    rows: list[Criterion] = []
    span = _span(run, notes)
    stroke = float(np.ptp(run.profile.position))
    nut = nut_length(screw)
    if stroke + nut >= span:
        raise BallScrewInputError(
            "axis.bearing_span" if axis.bearing_span is not None else "axis.screw_length",
            f"{span * 1e3:g} mm",
            f"a span longer than the stroke {stroke * 1e3:g} mm plus the nut {nut * 1e3:.0f} mm",
        )
    d_r = root_diameter(screw) if axis.root_diameter is None else float(axis.root_diameter)
    if axis.root_diameter is None:
        notes.append(f"root diameter {d_r * 1e3:.2f} mm estimated from the groove "
                     "(give axis.root_diameter from the catalogue)")  # fmt: skip
    force = np.asarray(cycle.axial_force, dtype=float)
    omega = np.asarray(cycle.screw_speed, dtype=float)
    turns = _turns(run, omega)
    inputs = _criterion_inputs(run, energy, force, turns)
    life_rows, life = _life_rows(run, inputs, force, turns, notes)
    rows += life_rows
    rows += _load_rows(run, inputs, d_r, span)
    rows += _speed_rows(run, omega, d_r, span)
    rows += _lift_off_row(run, inputs)
    stiff_rows, stiffness = _stiffness_rows(run, name, force, d_r, span, stroke, nut, notes)
    rows += stiff_rows
    thermal_rows, thermal = _thermal_rows(run, name, inputs, stroke, notes)
    rows += thermal_rows
    motor_rows, motor = _motor_rows(run, inputs, cycle)
    rows += motor_rows
    notes.append(
        "axial loads: inertia, gravity and the process force of the move; no guideway "
        "friction (not in the case)"
    )
    p_any: float | None = None
    if not draws:
        notes.append("uncertainty: not drawn (the verdicts of the nominal values)")
    elif draws_when_failing or all(r.verdict != "NOT OK" for r in rows):
        rows, p_any = _with_uncertainty(run, name, energy, inputs, rows, stiffness, notes)
    else:
        notes.append("uncertainty: not drawn (a row fails at its nominal value)")
    marked = [f"{a.field} = {a.value} ({a.reason})" for a in case.assumptions]
    return AxisCheck(case.title, name, rows, marked + list(run.assumptions) + notes, life,
                     stiffness, motor, thermal, check_inputs(run, name), p_any)  # fmt: skip


def check_inputs(run: EnergyRun, model: str) -> dict[str, Any]:
    """The inputs of a check, enough to compute it again (:func:`~.duty.run_inputs`).

    With the draws of the uncertainty (their number and seed).
    """
    return {**run_inputs(run, model), "uncertainty": {"samples": SAMPLES, "seed": SEED}}


def _life_rows(
    run: EnergyRun, inputs: Inputs, force: FloatArray, turns: FloatArray, notes: list[str]
) -> tuple[list[Criterion], dict[str, Any]]:
    """The fatigue life row (ISO 3408-5) and its figures: the halves' mean loads, L10."""
    case, screw = run.case, run.case.screw
    reliability = float(case.check.get("reliability", 0.9))
    f_w = case.check.get("load_factor")
    f_w_origin = "given"
    if f_w is None:
        f_w, f_w_origin = DEFAULT_LOAD_FACTOR, "default"
        notes.append(
            f"load factor f_w = {DEFAULT_LOAD_FACTOR:g} (default: the start of normal running; "
            "THK A15-40: 1.0 to 1.2 smooth without impact, 1.2 to 1.5 normal, 1.5 to 3 with "
            "impact or vibration; 1 is ISO 3408-5's own life): give check.load_factor"
        )
    elif any(a.field == "check.load_factor" for a in case.assumptions):
        f_w_origin = "assumed"
    f_w = float(f_w)
    source = (
        "ISO 3408-5:2006 cl. 7 with the makers' load factor: L10 = a1 (Ca/(f_w Fm))^3 1e6, "
        f"f_w = {f_w:g} ({f_w_origin}; THK A15-40: 1.0-1.2 smooth, 1.2-1.5 normal running), "
        f"a1 = {reliability_factor(reliability):g} ({reliability:.0%}), halves in series (10/9)"
    )
    half_1, half_2 = nut_halves(force, screw.preload, preloaded=inputs.preloaded)
    total_turns = float(np.sum(turns))
    if total_turns <= 0.0:
        return [
            _missing("life", "fatigue life", "h", source, "a move: the cycle makes no turn")
        ], {}
    fm1 = float(cubic_mean_load(half_1, turns))
    fm2 = float(cubic_mean_load(half_2, turns))
    turns_per_second = total_turns / run.profile.duration
    ca = case.dynamic_load_rating
    life: dict[str, Any] = {
        "mean_load_N": [fm1, fm2],
        "turns_per_cycle": total_turns / run.cycles,
        "mean_speed_rpm": turns_per_second * 60.0,
        "reliability": reliability,
        "load_factor": f_w,
        "load_factor_source": f_w_origin,
        "dynamic_load_rating_N": ca,
        "static_load_rating_N": case.static_load_rating,
    }
    if ca is None:
        return [_missing("life", "fatigue life", "h", source,
                         "give screw.dynamic_load_rating (C_a from the catalogue) or a "
                         "catalogue designation")], life  # fmt: skip
    req = case.check.get("required_life")
    if req is None:
        req = DEFAULT_LIFE_HOURS * 3600.0
        notes.append("required life 20000 h (THK's and NSK's figure for machine tools; give "
                     "check.required_life)")  # fmt: skip
    hours = nominal("life", inputs)
    revs = hours * 3600.0 * turns_per_second
    km = float(life_distance(revs, screw.lead)) / 1e3
    life |= {"L10_revolutions": revs, "L10_hours": hours, "L10_km": km}
    notes.append(
        f"L10 in hours of this cycle repeated without a break ({revs:.3g} revolutions, "
        f"{km:.4g} km of travel); an axis that runs it a share D of its hours lasts L10/D "
        "hours of the calendar, and the required life is compared with the running hours"
    )
    advice = (
        "a nut with a higher C_a (more circuits, larger balls or diameter), a lower "
        "preload, lighter moves, or a longer lead (fewer turns per metre)"
    )
    if f_w_origin == "default":
        advice += (f"; the life is ISO's with f_w = {DEFAULT_LOAD_FACTOR:g}: give "
                   "check.load_factor for the running conditions")  # fmt: skip
    return [_at_least("life", "fatigue life L10", hours, req / 3600.0, "h", source, advice)], life


def _load_rows(run: EnergyRun, inputs: Inputs, d_r: float, span: float) -> list[Criterion]:
    """Static safety, buckling and the root section's yield under the peak axial force."""
    case, axis = run.case, run.axis
    rows: list[Criterion] = []
    source = (
        "ISO 3408-5:2006 cl. 6: f_s = C0a / F_max (most loaded half, preload included); "
        "least f_s: THK, Static Safety Factor, Table 18, A-703 (machine tools: 1 to 1.5, "
        "2.5 to 7 with vibration or impact)"
    )
    if case.static_load_rating is None:
        rows.append(_missing("static_safety", "static safety C0a/F_max", "-", source,
                             "give screw.static_load_rating (C_0a from the catalogue) or a "
                             "catalogue designation"))  # fmt: skip
    else:
        fs = nominal("static_safety", inputs)
        rows.append(_at_least("static_safety", "static safety C0a/F_max", fs,
                              float(case.check["static_safety"]), "-", source,
                              "a nut with a higher C_0a, or lower peak loads "
                              "(gentler accelerations)"))  # fmt: skip
    p_buckle = float(buckling_load(d_r, span, axis.support))
    rows.append(_at_most(
        "buckling", "buckling load", nominal("buckling", inputs), p_buckle / 1e3, "kN",
        "Euler on the root diameter x 0.5, mounting factor (THK General Catalog, Permissible "
        "Axial Load, A15-30, eq. 5); span taken as the buckling length, load as compressive",
        "a larger diameter, a shorter span, or a fixed-fixed mounting",
    ))  # fmt: skip
    p_yield = YIELD_STRESS * math.pi * d_r**2 / 4.0
    rows.append(_at_most(
        "root_section", "axial load, root section", nominal("root_section", inputs),
        p_yield / 1e3, "kN",
        "147 MPa on the root section (THK, Permissible Axial Load, A15-30, eq. 6)",
        "a larger diameter",
    ))  # fmt: skip
    return rows


def _speed_rows(run: EnergyRun, omega: FloatArray, d_r: float, span: float) -> list[Criterion]:
    """The top screw speed against the critical speed, and d·n against the nut's limit."""
    axis, screw = run.axis, run.case.screw
    rpm = float(rad_s_to_rpm(np.max(np.abs(omega))))
    allowed = SAFETY_FACTOR * float(rad_s_to_rpm(critical_speed(d_r, span, axis.support)))
    dn_note = "" if "dn_limit" in run.case.axis_given else " (default: give axis.dn_limit)"
    return [
        _at_most("critical_speed", "speed / critical speed", rpm, allowed, "rpm",
                 f"0.8 x first bending speed, {axis.support} (THK, Permissible Rotational Speed, "
                 "A15-32, eq. 7)",
                 "a longer lead (fewer turns for the feed), a larger diameter, a shorter span "
                 "or a stiffer mounting"),
        _at_most("dn", "d*n", screw.pitch_diameter * 1e3 * rpm, axis.dn_limit, "mm*rpm",
                 f"the nut's catalogue d*n limit{dn_note}",
                 "a longer lead, or a nut with a higher d*n rating"),
    ]  # fmt: skip


def _lift_off_row(run: EnergyRun, inputs: Inputs) -> list[Criterion]:
    """The relieved half of a preloaded nut against lift-off at 2^1.5 F_pr (ISO 3408-5)."""
    screw = run.case.screw
    if screw.nut == "single" or screw.preload <= 0.0:
        return []
    f_max = nominal("lift_off", inputs)
    lift = LIFT_OFF_RATIO * screw.preload
    return [_at_most(
        "lift_off", "lift-off F_max / (2^1.5 F_pr)", f_max, lift, "N",
        f"ISO 3408-5:2006 (the preloaded halves, F2 = 0 at |F| = 2^1.5 F_pr = {lift:.4g} N "
        f"with F_pr = {screw.preload:.4g} N); THK A15-20: a preload holds up to about three "
        "times itself",
        f"a preload of at least F_max / 2^1.5 = {f_max / LIFT_OFF_RATIO:.4g} N, or a lower peak "
        "load (process force, acceleration, weight); past lift-off the nut is one half: the "
        "stiffness, lost motion and eigenfrequency rows below are the lifted-off state's",
    )]  # fmt: skip


def _stiffness_rows(
    run: EnergyRun, model: str, force: FloatArray, d_r: float, span: float, stroke: float,
    nut: float, notes: list[str],
) -> tuple[list[Criterion], dict[str, Any]]:  # fmt: skip
    """The axis stiffness, the lost motion at a reversal and the axial eigenfrequency.

    Shaft, nut and thrust bearings in series at 21 nut positions over the stroke
    (centred in the span), the nut in the state the cycle's peak load leaves it
    (:func:`_nut_state`); the figures behind the rows for the JSON and the report.
    """
    case, axis, screw = run.case, run.axis, run.case.screw
    notes.append("the stroke lies in the middle of the span")
    position = np.linspace(0.5 * (span - stroke), 0.5 * (span + stroke), 21)
    k_shaft = shaft_axial_stiffness(d_r, span, position, axis.support)
    peak = float(np.max(np.abs(force)))
    k_nut, k_nut_preloaded, play = _nut_state(case, peak, notes)
    lifted = k_nut_preloaded is not None
    notes.append(
        "nut stiffness: the Hertz contacts' (all balls sharing the load) over "
        f"{CATALOGUE_RIGIDITY_RATIO:g}, the level of THK's and HIWIN's printed rigidity "
        f"(those nuts' printed values are {1 / CATALOGUE_RIGIDITY_SCATTER[1]:.2f} to "
        f"{1 / CATALOGUE_RIGIDITY_SCATTER[0]:.2f} of their contacts'), times THK's design "
        f"allowance {DESIGN_ALLOWANCE:g}"
    )
    k_bearing = case.check.get("support_stiffness")
    if k_bearing is None:
        notes.append("thrust bearings taken as rigid (give check.support_stiffness from their "
                     "catalogue; the axis is softer than shown)")  # fmt: skip
    k_axis = series_stiffness(k_shaft, k_nut, k_bearing)
    f_f = _creep_drag(run, model)
    mass = axis.moving_mass
    freq = axial_eigenfrequency(k_axis, mass) if mass > 0.0 else None
    elastic = lost_motion(f_f, k_axis)
    lost = elastic + play
    # The drag torque also twists the shaft between the drive (at the thrust end) and the nut.
    twist = lost_motion(f_f, torsional_axial_stiffness(d_r, position, screw.lead))
    pre_rolling = float(lost_motion(f_f, k_nut))  # the nut's contacts, LuGre's bristles
    figures: dict[str, Any] = {
        "position_mm": (position * 1e3).tolist(),
        "shaft_N_per_um": (k_shaft / 1e6).tolist(),
        "nut_N_per_um": k_nut / 1e6,
        "lifted_off": lifted,
        "bearings_N_per_um": None if k_bearing is None else k_bearing / 1e6,
        "axis_N_per_um": (k_axis / 1e6).tolist(),
        "eigenfrequency_Hz": None if freq is None else freq.tolist(),
        "friction_force_N": f_f,
        "axial_play_um": play * 1e6,
        "lost_motion_um": (lost * 1e6).tolist(),
        "lost_motion_torsion_um": (twist * 1e6).tolist(),
        "nut_length_mm": nut * 1e3,
    }
    if k_nut_preloaded is not None:
        figures["nut_preloaded_N_per_um"] = k_nut_preloaded / 1e6
    state = ", lifted off" if lifted else ""
    at = "the preload" if screw.nut != "single" and screw.preload > 0.0 else (
        "the cycle's peak load (no preload)")  # fmt: skip
    source = (
        "ISO 3408-4; shaft EA/a or EAL/(a(L-a)) (THK, Axial Rigidity of the Feed Screw "
        f"System, A15-43); nut: Hertz at {at}, at the makers' printed level, x 0.8 "
        "(THK A-709)" + ("; past lift-off one half at the peak load" if lifted else "")
    )
    play_text = f" + the axial play {play * 1e6:.3g} um" if play > 0.0 else ""
    rows = [
        _info("stiffness", f"axis stiffness (least over the stroke{state})",
              float(np.min(k_axis)) / 1e6, "N/um", source + f"; nut {k_nut / 1e6:.4g} N/um"),
        _info("lost_motion", f"lost motion at reversal (most{state})", float(np.max(lost)) * 1e6,
              "um",
              f"2 F_f / k{play_text}, F_f = 2 pi T_f / l = {f_f:.3g} N (drag at creep speed) "
              "as if the whole axis carried it: an upper bound ('ballscrew contour' puts the "
              "drag on the motor side). The drag torque itself loads no part axially: it twists "
              f"the shaft, up to {float(np.max(twist)) * 1e6:.2g} um, and strains the nut's "
              f"contacts before they roll, 2 F_f / k_nut = {pre_rolling * 1e6:.2g} um; a "
              "guideway's friction would load the whole axis"),
    ]  # fmt: skip
    if freq is None:
        rows.append(_missing("eigenfrequency", "axial eigenfrequency", "Hz", "sqrt(k/m) / 2 pi",
                             "give axis.moving_mass"))  # fmt: skip
    else:
        rows.append(_info("eigenfrequency", f"axial eigenfrequency (least{state})",
                          float(np.min(freq)), "Hz",
                          "sqrt(k/m) / 2 pi with the moving mass"))  # fmt: skip
    return rows, figures


def _nut_state(case: Case, peak: float, notes: list[str]) -> tuple[float, float | None, float]:
    """The nut's stiffness [N/m] as the cycle leaves it, its preloaded one past lift-off.

    Returns the stiffness, the preloaded stiffness where the nut lifts off (else None)
    and the axial play [m] of a nut without preload.
    """
    screw = case.screw
    play, k_nut_preloaded = 0.0, None
    if screw.nut == "single" or not screw.preload > 0.0:
        # No preload (a single nut, or a double or 4-point nut set to 0 N): the contacts have
        # no stiffness at rest; one side carries the load, at its tangent stiffness.
        if peak <= 0.0:
            raise BallScrewInputError(
                "screw.nut", screw.nut, "a load on the nut: a nut without preload and "
                "without load has no stiffness (give a move with a force or a preloaded nut)",
            )  # fmt: skip
        k_nut = design_nut_stiffness(screw, peak)
        given = case.check.get("axial_play")
        play = DEFAULT_AXIAL_PLAY if given is None else float(given)
        origin = "default" if given is None else "given"
        kind = "single nut" if screw.nut == "single" else f"{screw.nut} nut without preload"
        notes.append(
            f"{kind}: stiffness at the cycle's peak load {peak:.4g} N; its axial play "
            f"{play * 1e6:.3g} um ({origin}) is added to the lost motion"
        )
        if given is None:
            notes.append(
                f"axial play {DEFAULT_AXIAL_PLAY * 1e6:g} um (default: THK's clearance G2 of a "
                "precision nut without preload, 0.02 mm or less, General Catalog A15-19; give "
                "check.axial_play from the nut's catalogue)"
            )
    else:
        k_nut = design_nut_stiffness(screw)
        if screw.preload > 0.0 and peak > LIFT_OFF_RATIO * screw.preload:
            # Past lift-off one half carries the load alone: its tangent stiffness at the peak.
            k_lifted = design_nut_stiffness(screw, peak)
            notes.append(
                f"lift-off: the peak load {peak:.4g} N is {peak / screw.preload:.3g} times the "
                f"preload (past 2^1.5 = {LIFT_OFF_RATIO:.3g}); the nut's stiffness in that state "
                f"is one half's at the peak load, {k_lifted / 1e6:.4g} N/um against "
                f"{k_nut / 1e6:.4g} N/um preloaded, and the stiffness, lost motion and "
                "eigenfrequency rows take it"
            )
            k_nut_preloaded, k_nut = k_nut, min(k_nut, k_lifted)
    return k_nut, k_nut_preloaded, play


def _creep_drag(run: EnergyRun, model: str) -> float:
    """The screw's drag at :data:`CREEP_SPEED` without load, as an axial force [N]: 2π T_f / l."""
    case, screw = run.case, run.case.screw
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t_f = float(friction_torque(screw, case.lubricant, speed=CREEP_SPEED,
                                    temperature=run.temperature, axial_load=0.0, model=model,
                                    **case.parameters_for(model)).total.flat[0])  # fmt: skip
    return 2.0 * math.pi * t_f / screw.lead


def _thermal_rows(
    run: EnergyRun, model: str, inputs: Inputs, stroke: float, notes: list[str]
) -> tuple[list[Criterion], dict[str, Any]]:
    """The thermal lead error per 300 mm against the grade, the growth over the stroke."""
    case, axis = run.case, run.axis
    rise, pre = inputs.temperature_rise, inputs.pretension
    if pre > 0.0 and axis.support != "fixed-fixed":
        raise BallScrewInputError(
            "check.pretension_temperature", f"{pre:g} K",
            f"0 K for a {axis.support} mounting (a pre-tension needs fixed-fixed)",
        )  # fmt: skip
    effective = max(rise - pre, 0.0)
    error = nominal("thermal_error", inputs)
    source = (f"alpha dT 300 mm, alpha = {STEEL_EXPANSION:g}/K, dT = {rise:.3g} K"
              + (f" less {pre:g} K of pre-tension" if pre else "")
              + " (heat balance after the run time)")  # fmt: skip
    growth = _info("thermal_growth", "thermal growth over the stroke",
                   float(thermal_elongation(effective, stroke)) * 1e6, "um",
                   "alpha dT x stroke: the position error at the stroke's far "
                   "end against its near end")  # fmt: skip
    figures: dict[str, Any] = {"temperature_rise_K": rise, "pretension_K": pre,
                               "error_per_300mm_um": error}  # fmt: skip
    if model in run.histories:
        times, temps = run.histories[model]
        rises = np.maximum(np.asarray(temps) - float(run.node.ambient) - pre, 0.0)
        figures |= {
            "time_s": np.asarray(times).tolist(),
            "temperature_C": np.asarray(temps).tolist(),
            "error_per_300mm_over_time_um": (thermal_elongation(rises, 0.3) * 1e6).tolist(),
        }
    grade = case.check.get("accuracy_grade")
    if grade is None:
        notes.append("no accuracy grade: the thermal lead error is not set against a tolerance "
                     "(give check.accuracy_grade)")  # fmt: skip
        return [
            _info("thermal_error", "thermal lead error per 300 mm", error, "um", source),
            growth,
        ], figures
    limit = TRAVEL_VARIATION_300[grade] * 1e6
    row = _at_most(
        "thermal_error", f"thermal lead error per 300 mm ({grade})", error, limit, "um",
        source + "; v300p of ISO 3408-3 / JIS B 1192",
        "cool the screw or the nut, pre-tension a fixed-fixed screw, lower the preload or "
        "the duty, or compensate in the control",
    )  # fmt: skip
    return [row, growth], figures


def _motor_rows(
    run: EnergyRun, inputs: Inputs, cycle: CycleResult
) -> tuple[list[Criterion], dict[str, Any]]:
    """The motor: inertia ratio, peak and RMS torque, speed, the acceleration it allows."""
    case, axis, screw = run.case, run.axis, run.case.screw
    motor = case.motor
    if not motor:
        return [_missing("motor", "motor", "-", "[motor]",
                         "give [motor] rated_torque, peak_torque, "
                         "rated_speed and axis.motor_inertia")], {}  # fmt: skip
    if "motor_inertia" not in case.axis_given or axis.motor_inertia <= 0.0:
        raise BallScrewInputError(
            "axis.motor_inertia", "(missing)" if "motor_inertia" not in case.axis_given else 0,
            "the rotor inertia from the motor's data sheet (> 0), needed by the motor check",
        )  # fmt: skip
    i = axis.gear_ratio
    j_load = reflected_inertia(axis.moving_mass, screw.lead, axis.screw_inertia,
                               axis.coupling_inertia, i)  # fmt: skip
    ratio = nominal("inertia_ratio", inputs)
    torque = np.asarray(cycle.motor_torque, dtype=float)
    peak, rms = nominal("peak_torque", inputs), nominal("rms_torque", inputs)
    top = float(rad_s_to_rpm(np.max(np.abs(cycle.motor_speed))))
    rows = [
        _at_most("inertia_ratio", "inertia ratio J_load/J_motor", ratio, INERTIA_RATIO_LIMIT, "-",
                 "J_load = [J_s + J_c + m (l/2 pi)^2] / i^2; limit 10, a servo sizing rule",
                 "a motor with a larger rotor, a gear (i > 1), or a shorter lead"),
    ]  # fmt: skip
    figures: dict[str, Any] = {
        "load_inertia_kgm2": j_load,
        "inertia_ratio": ratio,
        "peak_torque_Nm": peak,
        "rms_torque_Nm": rms,
        "top_speed_rpm": top,
    }
    for row_key, key, label, value, unit, advice in (
        ("peak_torque", "peak_torque", "peak torque", peak, "N*m",
         "a larger motor, gentler accelerations, or a gear"),
        ("rms_torque", "rated_torque", "RMS torque / rated torque", rms, "N*m",
         "a larger motor, longer dwells, or less friction (lower preload)"),
        ("motor_speed", "rated_speed", "motor speed", top, "rpm", "a longer lead or a lower feed"),
    ):  # fmt: skip
        if key not in motor:
            rows.append(_missing(row_key, label, unit, "[motor]", f"give motor.{key}"))
            continue
        limit = float(rad_s_to_rpm(motor[key])) if unit == "rpm" else motor[key]
        rows.append(_at_most(row_key, label, value, limit, unit,
                             "the cycle's torques (energy) against the motor's ratings",
                             advice))  # fmt: skip
    if "peak_torque" in motor:
        # Torque per unit of table acceleration at the motor: (J_m + J_load) 2 pi i / l.
        per_accel = (axis.motor_inertia + j_load) * 2.0 * math.pi * i / screw.lead
        accel = np.asarray(run.profile.acceleration, dtype=float)
        static = float(np.max(np.abs(torque - per_accel * accel)))
        allowed = (motor["peak_torque"] - static) / per_accel
        figures["allowed_acceleration_m_s2"] = allowed
        rows.append(_info("acceleration", "acceleration the peak torque allows", allowed, "m/s^2",
                          "(T_peak - T_no inertia) / ((J_m + J_load) 2 pi i / l)"))  # fmt: skip
    return rows, figures


def __getattr__(name: str) -> Any:
    """The entry point's name before 0.3.0, kept for one release with a DeprecationWarning."""
    return renamed(__name__, name, {"axis_check": run_check})


def _tolerances(run: EnergyRun, notes: list[str]) -> tuple[float, float, float, float, bool]:
    """The case's tolerances of mass, process force, preload and ratings (shares, ±).

    The last item says whether the preload's is the default (the makers' drag-torque band).
    """
    case, screw = run.case, run.case.screw
    check = case.check
    given = {k: check.get(f"{k}_tolerance") for k in ("mass", "force", "preload", "rating")}
    # An assumed value's own range stands in for a tolerance [check] does not state.
    ranges = {a.field: a.tolerance for a in case.assumptions if a.tolerance is not None}
    preloads = ("screw.preload", "screw.preload_share", "screw.preload_drag_torque")
    ratings = ("screw.dynamic_load_rating", "screw.static_load_rating")
    for key, fields in (("mass", ("axis.moving_mass",)), ("preload", preloads),
                        ("rating", ratings)):  # fmt: skip
        found = [(ranges[f], f) for f in fields if f in ranges]
        if given[key] is None and found:
            given[key], where = max(found)
            notes.append(f"{key} tolerance +-{given[key]:.0%} from the range of the assumed "
                         f"{where}")  # fmt: skip
    preload = given["preload"]
    if preload is None and screw.preload > 0.0:
        rows = DRAG_TORQUE_TOLERANCE["C3"]
        torque = float(preload_torque(screw.preload, screw.lead, screw.lead_angle))
        inside = min(max(torque, rows[0][0]), rows[-1][1])
        preload = drag_torque_tolerance(inside)[2]
        notes.append(
            f"preload tolerance +-{preload:.0%} (default: the makers' drag-torque band of grade "
            f"C3 at the catalogue drag torque {torque:.3g} N*m, THK A-688 Table 13: a maker "
            "sets the preload by that torque, which is proportional to it, and accepts the nut "
            "within the band, so the preload is known to the same share; give "
            "check.preload_tolerance, e.g. from the nut's measured drag torque)"
        )
    names = {"mass": "moving mass", "force": "process force", "rating": "load ratings"}
    missing = [k for k in names if given[k] is None]
    if missing:
        keys = ", ".join(f"check.{k}_tolerance" for k in missing)
        notes.append(f"no tolerance given for the {', '.join(names[k] for k in missing)}: "
                     f"taken as exact (give {keys})")  # fmt: skip
    return (float(given["mass"] or 0.0), float(given["force"] or 0.0), float(preload or 0.0),
            float(given["rating"] or 0.0), given["preload"] is None)  # fmt: skip


def _with_uncertainty(
    run: EnergyRun, model: str, energy: ModelEnergy, inputs: Inputs, rows: list[Criterion],
    stiffness: dict[str, Any], notes: list[str],
) -> tuple[list[Criterion], float]:  # fmt: skip
    """Every row with a limit, with its P(NOT OK) and interval (:mod:`.uncertainty`).

    And the probability that one row or more is NOT OK in the same draw (a NaN counts
    as NOT OK, as in :func:`~.uncertainty.judge`). A row of :data:`~.criteria.CRITERIA`
    is its function at the draws; any other row has no uncertain input.
    """
    screw = run.case.screw
    t_mass, t_force, t_pre, t_rating, default_preload = _tolerances(run, notes)
    creep_torque = float(stiffness.get("friction_force_N", 0.0)) * screw.lead / (2.0 * math.pi)
    # The speed at which the cycle's friction heat is made (heat-weighted mean): which speed
    # range the model's error is wanted in.
    omega = np.abs(np.asarray(energy.cycle.screw_speed, dtype=float))
    heat = np.abs(np.asarray(energy.cycle.friction_torque, dtype=float)) * omega
    heat = heat * _weights(np.asarray(run.profile.time, dtype=float))
    speed = float(rad_s_to_rpm(np.sum(heat * omega) / np.sum(heat))) if np.sum(heat) > 0 else None
    error = model_error(model, screw.nut, creep_torque, speed)
    notes.append(error.text)
    sigma, bias = (0.0, 0.0) if math.isnan(error.sigma) else (error.sigma, error.bias)
    d = draws(t_mass, t_force, t_pre, t_rating, sigma, friction_bias=bias)
    notes.append(
        f"uncertainty: Monte Carlo over {SAMPLES} draws (seed {SEED}): mass +-{t_mass:.0%}, "
        f"process force +-{t_force:.0%}, preload +-{t_pre:.0%}, load ratings +-{t_rating:.0%} "
        f"(uniform), the model's friction x exp({-bias:+.3g} + N(0, {sigma:.3g})), its bias "
        "moving the median; the friction factor scales "
        "the heat and the motor's friction torque, not the preload's share of it; P(NOT OK) "
        "beside each verdict, 'OK (95 %)' when P <= 5 %, 'NOT OK (95 %)' when P >= 95 %, "
        "else 'undecided'"
    )
    samples = _row_samples(inputs, rows, d)
    life = next((r for r in rows if r.key == "life"), None)
    if default_preload and t_pre > 0.0 and life is not None and life.key in samples:
        _preload_effect(inputs, life, t_pre, notes)
    out = []
    fails = np.zeros(SAMPLES, dtype=bool)
    for row in rows:
        u = samples.get(row.key)
        if u is None and row.utilisation is not None:
            u = np.full(SAMPLES, row.utilisation)  # no uncertain input in its formula
        if u is not None:
            fails |= np.isnan(u) | (u > 1.0)
        out.append(row if u is None else replace(row, uncertainty=judge(u)))
    return out, float(np.mean(fails))


def _preload_effect(inputs: Inputs, life: Criterion, t_pre: float, notes: list[str]) -> None:
    """A note: the fatigue life row's utilisation at the default preload band's two ends."""
    if not inputs.preloaded:
        return
    ends = replace(ones(2), preload=np.array([1.0 - t_pre, 1.0 + t_pre]))
    low, high = drawn("life", Sample(inputs, ends), float(life.limit or 0.0))
    notes.append(
        f"the default preload band alone moves the fatigue life row's utilisation from "
        f"{low:.3g} (preload -{t_pre:.0%}) to {high:.3g} (+{t_pre:.0%}), nominal "
        f"{life.utilisation:.3g}: where the preload carries the load the life goes as about "
        "the preload to the power -3, so this band is most of the life row's interval"
    )


def _row_samples(inputs: Inputs, rows: list[Criterion], d: Draws) -> dict[str, FloatArray]:
    """The utilisation of each row of :data:`~.criteria.CRITERIA` with a limit, one per draw.

    By key; the draws are taken in blocks of about 2 million (draw, sample) pairs per
    array, whatever the cycle's length, so that a long profile does not hold gigabytes.
    """
    drawn_rows = [r for r in rows if r.utilisation is not None and r.key in CRITERIA]
    n = d.mass.size
    out = {r.key: np.empty(n) for r in drawn_rows}
    size = max(int(inputs.motor_torque.size), int(inputs.turns.size), 1)
    chunk = max(1, min(n, 2_000_000 // size))
    for start in range(0, n, chunk):
        sl = slice(start, min(start + chunk, n))
        block = Sample(inputs, d[sl])
        for row in drawn_rows:
            out[row.key][sl] = drawn(row.key, block, float(row.limit or math.inf))
    return out


def _turns(run: EnergyRun, omega: FloatArray) -> FloatArray:
    """The screw turns made at each sample of the run [-] (trapezoidal weights)."""
    return np.asarray(np.abs(omega) / (2.0 * math.pi) * _weights(run.profile.time), dtype=float)


def criterion_inputs(run: EnergyRun, model: str | None = None) -> Inputs:
    """The inputs of the drawn criteria over ``run``'s cycle for ``model`` (default the first).

    What :func:`run_check` computes those rows from: each row of
    :data:`~.criteria.CRITERIA` is its function at a draw of ones
    (:func:`~.criteria.nominal`), its P(NOT OK) the same function at the draws.
    """
    energy = run.results[model or next(iter(run.results))]
    if energy.thermal_error is not None:
        raise energy.thermal_error
    force = np.asarray(energy.cycle.axial_force, dtype=float)
    turns = _turns(run, np.asarray(energy.cycle.screw_speed, dtype=float))
    return _criterion_inputs(run, energy, force, turns)


def _criterion_inputs(
    run: EnergyRun, energy: ModelEnergy, force: FloatArray, turns: FloatArray
) -> Inputs:
    """What the drawn criteria are computed from (:class:`~.criteria.Inputs`).

    Every formula takes a sample through its forces (mass part, process force) and
    turns, or its torques (and weight), alone: the samples that share them (a cruise,
    a dwell, a constant acceleration) are taken once, with their turns or weights
    added up (:func:`_distinct_samples`).
    """
    case, axis, screw = run.case, run.axis, run.case.screw
    cycle = energy.cycle
    assert energy.final_temperature is not None  # a kept thermal error raised in run_check
    process = np.asarray(run.profile.process_force, dtype=float)
    mass_part = np.asarray(force, dtype=float) - process
    omega = np.asarray(cycle.screw_speed, dtype=float)
    t_motor = np.asarray(cycle.motor_torque, dtype=float)
    t_fric = np.sign(omega) * np.asarray(cycle.friction_torque, dtype=float) / axis.gear_ratio
    t_mass, t_process, t_motor, t_fric, weights = _distinct_samples(
        (mass_part, process, t_motor, t_fric), (_weights(run.profile.time),)
    )
    f_mass, f_process, f_turns = _distinct_samples((mass_part, process), (turns,))
    f_w = case.check.get("load_factor")
    return Inputs(
        mass_force=f_mass, process_force=f_process, turns=f_turns, motor_torque=t_motor,
        torque_mass_force=t_mass, torque_process_force=t_process, motor_friction=t_fric,
        weights=weights, duration=float(run.profile.duration),
        rms_torque=float(cycle.rms_motor_torque), lead=screw.lead,
        gear_ratio=axis.gear_ratio, preload=screw.preload, preloaded=screw.nut != "single",
        dynamic_rating=case.dynamic_load_rating, static_rating=case.static_load_rating,
        load_factor=DEFAULT_LOAD_FACTOR if f_w is None else float(f_w),
        reliability=float(case.check.get("reliability", 0.9)),
        temperature_rise=float(energy.final_temperature) - float(run.node.ambient),
        pretension=float(case.check.get("pretension_temperature", 0.0)),
        moving_mass=axis.moving_mass, screw_inertia=axis.screw_inertia,
        coupling_inertia=axis.coupling_inertia, motor_inertia=axis.motor_inertia,
    )  # fmt: skip


def _distinct_samples(
    keys: tuple[FloatArray, ...], sums: tuple[FloatArray, ...]
) -> tuple[FloatArray, ...]:
    """The distinct rows of the columns ``keys``, and the columns ``sums`` added up by row.

    Each output column has one entry per distinct row of ``keys`` (in sorted order);
    the values of ``sums`` of the samples that share it are added, in the samples'
    order.
    """
    columns = [np.asarray(k, dtype=float).reshape(-1) for k in keys]
    order = np.lexsort(columns[::-1])
    ordered = [c[order] for c in columns]
    starts = np.ones(order.size, dtype=bool)
    for c in ordered:
        starts[1:] &= c[1:] == c[:-1]
    starts = ~starts
    starts[:1] = True
    group = np.cumsum(starts) - 1
    inverse = np.empty(order.size, dtype=np.intp)
    inverse[order] = group
    added = [np.bincount(inverse, weights=np.asarray(w, dtype=float).reshape(-1)) for w in sums]
    return (*(c[starts] for c in ordered), *added)
