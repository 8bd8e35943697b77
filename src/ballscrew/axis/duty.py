"""The energy of an axis over a motion cycle, every model at once.

What ``ballscrew energy`` and the web page compute.

:func:`run_energy` takes a case (with its ``[axis]``), a motion profile and the
models, and returns an :class:`EnergyRun`: per model a :class:`ModelEnergy`
with the cycle's energies and torques (:func:`ballscrew.axis.energy.axis_cycle`,
run once per model), the weight's back-driving verdict, the temperature the
repeated cycle reaches and the energy at it (:mod:`ballscrew.axis.thermal`), and
optionally the steady temperature of continuous running at given speeds.
:meth:`EnergyRun.as_dict` is the JSON document the command writes.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from .._moved import renamed
from ..design.ratings import Finding, plausibility, raise_errors, stroke_findings
from ..errors import BallScrewInputError, FloatArray
from ..geometry import nut_length
from ..io.case import Case
from ..io.files import read_input_text
from ..kinematics import rad_s_to_rpm
from .drive import DriveSpec, MotorConstants, drive_energy
from .energy import (
    Axis,
    CycleResult,
    axis_cycle,
    friction_energy,
    screw_motion,
    self_locking,
    weight_back_driving,
)
from .motion import Profile, back_and_forth, chain, check_force_window, read_trajectory
from .setup import axis_setup
from .thermal import (
    SteadyAtSpeed,
    SteadyState,
    ThermalNode,
    steady_at_speeds,
    steady_temperature,
    temperature_history,
)

__all__ = [
    "EnergyRun",
    "ModelEnergy",
    "motion_plausibility",
    "profile_from_file",
    "profile_from_move",
    "run_energy",
    "run_inputs",
]


def profile_from_move(move: dict[str, float], cycles: int) -> Profile:
    """Back-and-forth cycles of a move given as SI values by key.

    The keys are those of :func:`ballscrew.axis.motion.parse_move`.
    """
    window = None
    if "force_from" in move or "force_to" in move:
        window = (move.get("force_from", 0.0), move.get("force_to", abs(move["stroke"])))
        check_force_window(window, abs(move["stroke"]), "--move force_from, force_to")
    try:
        return back_and_forth(
            move["stroke"], move["feed"], move["acceleration"], jerk=move.get("jerk"),
            dwell_time=move.get("dwell", 0.0), cycles=cycles,
            process_force=move.get("force", 0.0), force_window=window,
        )  # fmt: skip
    except BallScrewInputError as exc:
        if exc.field != "move":
            raise
        raise BallScrewInputError("--move, --cycles", exc.value, exc.allowed) from None


def profile_from_file(path: str, cycles: int, standstill_speed: float | None = None) -> Profile:
    """A trajectory CSV (units in the header) repeated ``cycles`` times.

    ``standstill_speed`` [m/s]: the width of the friction's sign near rest
    (:func:`~ballscrew.axis.motion.read_trajectory`; None: from the noise of the file's
    positions).
    """
    text = read_input_text("--profile", path)
    one = read_trajectory(text, path, standstill_speed)
    return chain(*([one] * cycles))


@dataclass(frozen=True)
class ModelEnergy:
    """One model over the cycle: the cycle itself, the back-driving verdicts, the heat.

    ``cycle`` is :func:`~ballscrew.axis.energy.axis_cycle`'s result, run once.
    The temperatures [°C] are those the repeated cycle reaches
    (:mod:`ballscrew.axis.thermal`): the steady one and the one after the run
    time, with ``history`` (times [s], temperatures [°C]) and the friction
    energy of the cycle at the latter [J]. They are None, and
    ``thermal_error`` says why, when the heat balance could not be solved and
    the run was asked to go on (:func:`run_energy`'s ``thermal_failure``).
    """

    cycle: CycleResult
    cycles: int
    duration: float
    weight_reverse_efficiency: float
    self_locking: bool | None
    history: tuple[FloatArray, FloatArray] | None = field(default=None, repr=False)
    steady_temperature: float | None = None
    final_temperature: float | None = None
    friction_energy_at_final_temperature: float | None = None
    steady_at_speed: SteadyAtSpeed | None = None
    thermal_error: BallScrewInputError | None = None

    def as_dict(self) -> dict[str, Any]:
        """The model's figures as ``ballscrew energy --json`` gives them, per model."""
        figures = self.cycle.as_dict()
        warnings_ = figures.pop("warnings")
        doc: dict[str, Any] = {
            "friction_energy_J": self.cycle.friction_energy,
            "friction_energy_per_cycle_J": self.cycle.friction_energy / self.cycles,
        }
        doc |= figures
        doc |= {
            "weight_reverse_efficiency": self.weight_reverse_efficiency,
            "self_locking": self.self_locking,
            "duration_s": self.duration,
            "warnings": warnings_,
            "steady_temperature_C": self.steady_temperature,
            "final_temperature_C": self.final_temperature,
            "friction_energy_at_final_temperature_J": self.friction_energy_at_final_temperature,
        }
        at = self.steady_at_speed
        if at is not None:
            doc["steady_at_speed"] = {
                "speed_rpm": rad_s_to_rpm(at.speed).tolist(),
                "temperature_C": at.temperature.tolist(),
                "torque_Nm": at.torque.tolist(),
                "power_W": at.power.tolist(),
            }
        return doc


@dataclass(frozen=True)
class EnergyRun:
    """Everything ``ballscrew energy`` reports, per model (:func:`run_energy`)."""

    case: Case
    profile: Profile
    cycles: int
    temperature: float
    axis: Axis
    node: ThermalNode
    thermal: dict[str, float]
    assumptions: list[str]
    move: dict[str, float]
    results: dict[str, ModelEnergy] = field(default_factory=dict)
    findings: list[Finding] = field(default_factory=list)
    """Plausibility warnings: the motion's loads and stroke against the screw (errors raise)."""
    run_time: float = 3600.0
    """How long the cycle repeats for the temperature reached [s]."""
    derived: dict[str, tuple[float, str]] = field(default_factory=dict)
    """The ``[axis]`` values the case left out and the run filled, with how
    (:attr:`ballscrew.axis.setup.AxisSetup.derived`)."""

    @property
    def cycles_by_model(self) -> dict[str, CycleResult]:
        """Each model's cycle (:func:`~ballscrew.axis.energy.axis_cycle`)."""
        return {name: r.cycle for name, r in self.results.items()}

    @property
    def histories(self) -> dict[str, tuple[FloatArray, FloatArray]]:
        """Each model's temperature over the run time: (times [s], temperatures [°C])."""
        return {name: r.history for name, r in self.results.items() if r.history is not None}

    @property
    def steady(self) -> dict[str, SteadyAtSpeed]:
        """Each model's steady temperatures of continuous running, where asked for."""
        return {n: r.steady_at_speed for n, r in self.results.items() if r.steady_at_speed}

    @property
    def speed_warnings(self) -> list[str]:
        """The speed limits the cycle passes (the same for every model), in words."""
        last = next(reversed(self.results.values()), None)
        return [] if last is None else list(last.cycle.speed_warnings)

    def motor_losses(self, cycle: CycleResult) -> dict[str, Any]:
        """The motor's copper and iron loss over the cycles [J] (:mod:`.drive`).

        None where ``[motor]`` lacks the constant, and ``motor_losses_left_out`` says
        which; the drive and the DC link belong to a machine (``ballscrew program``).
        """
        e = drive_energy(self.profile.time, cycle.motor_torque, cycle.motor_speed,
                         MotorConstants.from_case(self.case.motor), DriveSpec(),
                         name="the case")  # fmt: skip
        return {
            "copper_loss_J": e.copper_loss,
            "motor_iron_loss_J": e.iron_loss,
            "motor_losses_left_out": [n for n in e.left_out
                                      if n.startswith(("copper", "motor iron"))],
        }  # fmt: skip

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew energy --json``: the first model at the top.

        Without the package's version, which the JSON writer adds
        (:func:`ballscrew.report.outputs.result_json`).
        """
        models = {name: r.as_dict() | self.motor_losses(r.cycle)
                  for name, r in self.results.items()}  # fmt: skip
        first_name = next(iter(models))
        return {
            "case": self.case.title,
            "model": first_name,
            **{k: v for k, v in models[first_name].items() if k != "steady_at_speed"},
            "move": self.move,
            "cycles": self.cycles,
            "temperature_C": self.temperature,
            "axis": {k: getattr(self.axis, k) for k in self.axis.__dataclass_fields__},
            "thermal": self.thermal,
            "assumptions": self.assumptions,
            "plausibility": [str(f) for f in self.findings],
            "models": models,
            "inputs": run_inputs(self, first_name),
        }


def _unreliable_fit_notes(case: Case) -> list[str]:
    """A warning for a case written from an unreliable fit (``fitted-case.toml``)."""
    mark = "UNRELIABLE FIT"  # ballscrew.fit.calibration.UNRELIABLE_FIT (a wing above this one)
    fitted = [a.field for a in case.assumptions if a.reason.startswith(mark)]
    if not (fitted or case.description.startswith(mark)):
        return []
    where = ", ".join(fitted) if fitted else "its model parameters"
    return [f"WARNING: this case comes from an unreliable fit ({where}): "
            f"{case.description or 'see the file'}; the results that use those values are "
            "not established"]  # fmt: skip


def run_inputs(run: EnergyRun, model: str) -> dict[str, Any]:
    """The inputs of a run (``energy``, ``check``), enough to compute it again.

    The case as written (its text and SHA-256) and as read: each key's SI value,
    unit and source, and how the run found those it filled (the screw's inertia
    from its geometry, its length from the bearing span):
    :meth:`ballscrew.io.case.Case.input_values`, the list ``torque`` writes too.
    Then the move, the model and the run time.
    """
    import hashlib

    case = run.case
    values = case.input_values(run.derived)
    ratings = case.ratings
    return {
        "case": {
            "title": case.title,
            "text": case.text,
            "sha256": hashlib.sha256(case.text.encode("utf-8")).hexdigest(),
            "values": values,
            "ratings_source": None if ratings is None else {
                "dynamic": ratings.dynamic_source, "static": ratings.static_source},
        },
        "move": dict(run.move),
        "profile": None if run.move else {
            "samples": int(run.profile.time.size), "duration_s": run.profile.duration},
        "cycles": run.cycles,
        "run_time_s": run.run_time,
        "temperature_C": run.temperature,
        "model": model,
    }  # fmt: skip


MAX_RUN_TIME = 100_000 * 3600.0
"""The longest run time [s] for the temperature reached (100 000 h, about 11 years of
running; a repeated cycle settles within hours)."""

HISTORY_POINTS = 50
"""The times at which a run keeps the temperature history."""

MAX_STEADY_SPEEDS = 1000
"""The most speeds of continuous running a run solves the steady temperature for (each costs
a friction call per bisection step: 1000 take about a second)."""


def run_energy(
    case: Case,
    profile: Profile,
    model_names: Sequence[str],
    *,
    cycles: int = 1,
    temperature: float | None = None,
    run_time: float = 3600.0,
    steady_speeds: npt.ArrayLike | None = None,
    move: dict[str, float] | None = None,
    motion_field: str = "--move",
    thermal_failure: str = "raise",
    steady: Mapping[str, SteadyState] | None = None,
    for_check: bool = False,
) -> EnergyRun:
    """Each model's energy, torques and temperatures over ``profile`` (module docstring).

    Each model's cycle is computed once (:func:`~ballscrew.axis.energy.axis_cycle`).

    Parameters
    ----------
    case : Case
        The screw, lubricant, model parameters and ``[axis]``.
    profile : Profile
        The motion (all its cycles).
    model_names : sequence of str
        Friction models.
    cycles : int
        How many cycles ``profile`` holds (for the energy per cycle).
    temperature : float, optional
        Lubricant temperature [°C]; default the case's first.
    run_time : float
        How long the cycle repeats for the temperature reached [s].
    steady_speeds : array_like, optional
        Speeds of continuous running [rad/s] for the steady temperatures.
    move : dict, optional
        The move's keys (SI), kept in the result; its ``force`` is the load of
        continuous running.
    motion_field : str
        What the motion was given as, named by the plausibility errors: the
        largest axial force of the cycle (weight, inertia and process force)
        against the screw's ratings and contact pressure
        (:func:`ballscrew.design.ratings.plausibility`), the travel against the
        screw's length where ``[axis]`` gives it (bearing span, else screw length),
        the largest speed and acceleration against ``[axis]`` ``max_feed`` and
        ``max_acceleration`` where given.
    thermal_failure : str
        "raise": a heat balance that cannot be solved (a cycle whose friction
        the screw cannot shed) raises its input error; "keep": the error is
        kept in each :class:`ModelEnergy` and the cycle's figures are returned
        (the web page shows the energy, and the check says why it cannot run).
    steady : mapping, optional
        Model name -> its :func:`~ballscrew.axis.thermal.steady_temperature` of
        this case over ``profile``, already solved (``ballscrew select`` solves
        many screws' together, :func:`~ballscrew.axis.thermal.steady_temperatures`);
        a model not in it is solved here.
    for_check : bool
        True: only what :func:`~ballscrew.axis.check.run_check` reads. The
        back-driving verdicts (``weight_reverse_efficiency`` NaN, ``self_locking``
        None) and the cycle's friction energy at the final temperature (None) are
        left out: three friction calls a candidate of ``ballscrew select`` spares.
    """
    if thermal_failure not in ("raise", "keep"):
        raise BallScrewInputError("thermal_failure", thermal_failure, "'raise' or 'keep'")
    if not 0.0 < run_time <= MAX_RUN_TIME:
        raise BallScrewInputError(
            "--run-time", f"{run_time / 3600.0:g} h", "more than 0 and at most 100 000 h"
        )
    if steady_speeds is not None and np.size(steady_speeds) > MAX_STEADY_SPEEDS:
        raise BallScrewInputError(
            "--steady-speeds", f"{np.size(steady_speeds)} speeds",
            f"at most {MAX_STEADY_SPEEDS} speeds (a range 'a..b:n rpm' with n <= "
            f"{MAX_STEADY_SPEEDS})",
        )  # fmt: skip
    m = dict(move or {})
    temp = float(case.temperature.flat[0]) if temperature is None else float(temperature)
    setup = axis_setup(case.screw, case.axis, case.thermal, float(np.ptp(profile.position)))
    node = setup.node
    found = motion_plausibility(case, profile, setup.axis, motion_field)
    setup_notes = _unreliable_fit_notes(case) + list(setup.notes)
    run = EnergyRun(
        case, profile, cycles, temp, setup.axis, node,
        {k: getattr(node, k) for k in ("screw_length", "ambient", "machine_resistance",
                                       "nut_mass")},
        setup_notes, m, findings=found, run_time=run_time, derived=setup.derived,
    )  # fmt: skip
    results = {
        name: _one_model(
            run,
            name,
            run_time,
            steady_speeds,
            thermal_failure,
            (steady or {}).get(name),
            for_check,
        )
        for name in model_names
    }
    return dataclasses.replace(run, results=results)


def motion_plausibility(
    case: Case, profile: Profile, axis: Axis, motion_field: str
) -> list[Finding]:
    """The motion's largest axial force and its travel against the screw; raises on an error."""
    force = screw_motion(profile, case.screw, axis)[2]
    found = plausibility(case.screw, case.load_ratings(), force,
                         load_field=f"{motion_field} (axial force of the cycle)")  # fmt: skip
    for key, where in (("bearing_span", case.axis), ("screw_length", case.thermal)):
        if where.get(key) is not None:
            found += stroke_findings(float(np.ptp(profile.position)), float(where[key]),
                                     nut_length(case.screw), field=f"{motion_field} stroke",
                                     length_field=f"axis.{key}")  # fmt: skip
    found += _axis_limits(profile, axis, motion_field)
    found.sort(key=lambda f: not f.error)
    return raise_errors(found)


def _shown(value: float, unit: str) -> str:
    """``value`` [SI] with its unit, a feed in m/min too (the unit machine tools give)."""
    trade = f" ({value * 60.0:.4g} m/min)" if unit == "m/s" else ""
    return f"{value:.4g} {unit}{trade}"


def _axis_limits(profile: Profile, axis: Axis, motion_field: str) -> list[Finding]:
    """The motion's largest speed and acceleration against the axis' limits, where given."""
    found = []
    speed = "feed" if motion_field == "--move" else "speed"
    for name, key, values, unit in (
        (speed, "max_feed", profile.speed, "m/s"),
        ("acceleration", "max_acceleration", profile.acceleration, "m/s^2"),
    ):
        limit = getattr(axis, key)
        peak = float(np.max(np.abs(values))) if np.size(values) else 0.0
        if limit is not None and peak > limit * (1.0 + 1e-9):
            found.append(Finding(f"{motion_field} {name}", _shown(peak, unit),
                                 f"axis.{key} = {_shown(limit, unit)}", "the case's [axis]",
                                 True))  # fmt: skip
    return found


def _one_model(
    run: EnergyRun, name: str, run_time: float, steady_speeds: npt.ArrayLike | None,
    thermal_failure: str, solved: SteadyState | None = None, for_check: bool = False,
) -> ModelEnergy:  # fmt: skip
    """One model's cycle (run once), back-driving verdicts and temperatures."""
    case, profile, axis, node = run.case, run.profile, run.axis, run.node
    params = case.parameters_for(name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the speed limits are kept in the result
        cycle = axis_cycle(profile, case.screw, case.lubricant, axis,
                           temperature=run.temperature, model=name, **params)  # fmt: skip
    weight, locking = math.nan, None
    if not for_check:
        weight = weight_back_driving(
            case.screw, case.lubricant, axis, temperature=run.temperature, model=name, **params
        )
        locking = self_locking(
            case.screw, case.lubricant, temperature=run.temperature, model=name, **params
        )
    base = ModelEnergy(cycle, run.cycles, profile.duration, weight, locking)
    try:
        steady = solved or steady_temperature(profile, case.screw, case.lubricant, axis, node,
                                              model=name, **params)  # fmt: skip
        times, history = temperature_history(profile, case.screw, case.lubricant, axis, node,
                                             run_time, model=name, points=HISTORY_POINTS,
                                             steady=steady, **params)  # fmt: skip
    except BallScrewInputError as exc:
        if thermal_failure == "raise":
            raise
        return dataclasses.replace(base, thermal_error=exc)
    warm = None if for_check else friction_energy(
        profile, case.screw, case.lubricant, axis, temperature=float(history[-1]), model=name,
        **params)  # fmt: skip
    at = None
    if steady_speeds is not None:
        at = steady_at_speeds(case.screw, case.lubricant, node, steady_speeds,
                              axial_load=run.move.get("force", 0.0), model=name,
                              **params)  # fmt: skip
    return dataclasses.replace(
        base, history=(times, history), steady_temperature=steady.temperature,
        final_temperature=float(history[-1]), friction_energy_at_final_temperature=warm,
        steady_at_speed=at,
    )  # fmt: skip


def __getattr__(name: str) -> Any:
    """The entry point's name before 0.3.0, kept for one release with a DeprecationWarning."""
    return renamed(__name__, name, {"energy_run": run_energy})
