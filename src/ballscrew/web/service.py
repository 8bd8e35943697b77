"""What the web calculator computes, without the web: request data in, plain data out.

Every request is turned into a case file's TOML text and read by
:func:`ballscrew.io.case.parse_case`, so the rules, units and one-line messages
are the command line's; the models run through
:func:`ballscrew.chain.torque_table` and the tables through
:mod:`ballscrew.report.outputs`, so the numbers and files are those of ``ballscrew
torque``; the energy and the check of a move are
:func:`ballscrew.axis.run_energy` (the cycle computed once) and
:func:`ballscrew.axis.run_check` on the move of ``ballscrew energy --move``, as
the commands compute them.

The work a request may ask for is bounded before any of it is done: the
request's fields and sizes in :mod:`ballscrew.web.inputs`
(:class:`~ballscrew.web.inputs.Limits`), the length of a move here. Nothing
here opens a file.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..axis import EnergyRun, run_check, run_energy
from ..axis.motion import Profile, back_and_forth, parse_move
from ..chain import FrictionResult, model_named, models, torque_table
from ..errors import BallScrewInputError, BallScrewSpeedWarning, BallScrewValidityWarning
from ..io.case import WIPER_PARAMETERS, Case
from ..io.display import label_text, shown, system_note, unit_system
from ..io.units import Reading, parse_range, parse_speed_range
from ..kinematics import rad_s_to_rpm
from ..report.outputs import (
    INPUT_DIGITS,
    csv_text,
    finite_or_null,
    json_text,
    provenance,
    result_rows,
    round_significant,
)
from ..report.torque import warning_lines
from .inputs import (
    LIMITS,
    ApiError,
    Limits,
    case_toml,
    check_points,
    load_case,
    read_case_file,
    read_json,
)

__all__ = [
    "LIMITS",
    "ApiError",
    "Limits",
    "case_toml",
    "display",
    "evaluate",
    "load_case",
    "model_choices",
    "read_case_file",
    "read_json",
    "torque",
]


WARM_UP: dict[str, Any] = {
    "case": {
        "screw": {"designation": "40x10 double 2.5x2 6.35", "preload": "2 kN"},
        "lubricant": {"name": "PAO ISO VG 68"},
        "operation": {"speed": "10..3000:50 rpm", "temperature": "40 degC", "axial_load": "1 kN"},
        "axis": {"moving_mass": "200 kg"},
    },
    "models": ["complete"],
    "move": {"stroke": "300 mm", "feed": "15 m/min", "acceleration": "2 m/s**2"},
}
"""A request like the page's first, run once when the server starts."""


_OVERRIDES = {"speed": "rad/s", "temperature": "degC", "axial_load": "N"}


def _operating_points(
    case: Case, given: Mapping[str, Any], limits: Limits, read: list[Reading] | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Speeds, temperatures and loads: those given as text with units, else the case's.

    How a text that could be meant two ways was read (a speed in Hz) is added to
    ``read``, for the answer's warnings, as the command line prints it.
    """
    arrays = {"speed": case.speed, "temperature": case.temperature, "axial_load": case.axial_load}
    for key, unit in _OVERRIDES.items():
        value = given.get(key)
        if value is None:
            continue
        if not isinstance(value, str):
            raise BallScrewInputError(key, value, "text with a unit, e.g. '100, 1000 rpm'")
        check_points(key, value, limits)
        arrays[key] = np.asarray(
            parse_speed_range(key, value, case.screw.lead, notes=read)
            if key == "speed"
            else parse_range(key, value, unit, notes=read)
        )
    sizes = {key: a.size for key, a in arrays.items()}
    total = math.prod(sizes.values())
    if total > limits.points:
        largest = max(sizes, key=lambda k: sizes[k])
        raise BallScrewInputError(
            largest,
            f"{sizes[largest]} values",
            f"at most {limits.points} operating points per request in all: "
            f"{' x '.join(str(n) for n in sizes.values())} = {total}",
        )
    return arrays["speed"], arrays["temperature"], arrays["axial_load"]


def _floats(values: Any) -> list[float | None]:
    """Numbers for JSON: non-finite ones as null."""
    return [float(v) if math.isfinite(v) else None for v in np.ravel(values).tolist()]


def _inputs(values: Any) -> list[float | None]:
    """Operating points for JSON, to the digits the CSV gives them (100 rpm, not 99.999...)."""
    return _floats([round_significant(v, INPUT_DIGITS) for v in np.ravel(values).tolist()])


def _quiet_run(
    case: Case,
    names: Sequence[str],
    w: np.ndarray,
    t: np.ndarray,
    f: np.ndarray,
    load_field: str = "operation.axial_load",
) -> tuple[dict[str, FrictionResult], list[str]]:
    """The models' results and the plausibility warnings; a plausibility error raises."""
    table = torque_table(
        case.screw, case.lubricant, names, w, t, f,
        parameters={name: case.parameters_for(name) for name in names},
        ratings=case.load_ratings(), load_field=load_field, wiper_drag=case.wiper_drag,
        wiper_models=WIPER_PARAMETERS,
    )  # fmt: skip
    return table.results, [f"warning: {x}" for x in table.findings]


def torque(payload: Mapping[str, Any], limits: Limits = LIMITS) -> dict[str, Any]:
    """``POST /api/torque``: one model over the operating points of a case.

    ``payload`` holds the fields of a case file, and optionally ``model``
    (default ``"complete"``) and ``speed``, ``temperature``, ``axial_load``
    as text with units, which replace the case's ``[operation]`` values as
    ``ballscrew torque --speed`` does. The points are every combination, the
    speed varying slowest (the rows of ``ballscrew torque``).
    """
    model = payload.get("model")
    model = "complete" if model is None else model
    fields = {k: v for k, v in payload.items() if k not in {"model", *_OVERRIDES}}
    try:
        if not isinstance(model, str):
            raise BallScrewInputError("model", model, "the name of one model")
        model_named(model)
        case = load_case(fields, limits)
        read: list[Reading] = []
        w, t, f = _operating_points(case, payload, limits, read)
        field = "axial_load" if "axial_load" in payload else "operation.axial_load"
        results, plausible = _quiet_run(case, [model], w, t, f, field)
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    r = results[model]
    return {
        "model": r.model,
        "speed_rpm": _inputs(rad_s_to_rpm(r.speed)),
        "temperature_C": _inputs(r.temperature),
        "axial_load_N": _inputs(r.axial_load),
        "torque_Nm": _floats(r.total),
        "power_loss_W": _floats(r.power_loss),
        "efficiency": _floats(r.efficiency),
        "components": {k: _floats(v) for k, v in r.components.items()},
        "warnings": [f"warning: {x}" for x in [*case.warned, *read]]
        + plausible
        + warning_lines(results),
    }


def _models(value: Any, limits: Limits) -> list[str]:
    """The models asked for, each checked, with the catalogue rule last as the reference."""
    names = value if isinstance(value, list) else ["complete"] if value is None else value
    if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
        raise BallScrewInputError("models", value, "a list of model names")
    if len(names) > limits.models:
        raise BallScrewInputError("models", value, f"at most {limits.models} models")
    for name in names:
        model_named(name)
    return [*dict.fromkeys(n for n in names if n != "catalog"), "catalog"]


_MOVE_KEYS = ("stroke", "feed", "acceleration")


def _move_profile(move: Any, limits: Limits) -> tuple[str, dict[str, float], Profile]:
    """The move's text, its SI values and its back-and-forth profile, within the page's limit."""
    if not isinstance(move, Mapping) or not all(isinstance(move.get(k), str) for k in _MOVE_KEYS):
        raise BallScrewInputError("--move", move, "stroke, feed and acceleration as text")
    text = ", ".join(f"{k}={move[k]}" for k in _MOVE_KEYS)
    m = parse_move(text)
    seconds = 2.0 * (abs(m["stroke"]) / m["feed"] + m["feed"] / m["acceleration"])
    if seconds > limits.move_seconds:
        raise BallScrewInputError(
            "--move stroke",
            move["stroke"],
            f"a move out and back within {limits.move_seconds:g} s on the page "
            f"(this one takes {seconds:.3g} s; the command line has no such limit)",
        )
    return text, m, back_and_forth(m["stroke"], m["feed"], m["acceleration"])


_ENERGY_SHOWN = (
    "friction_energy_J", "friction_energy_out_J", "friction_energy_back_J",
    "constant_efficiency_energy_J", "bearing_energy_J", "load_work_J", "peak_motor_torque_Nm",
    "rms_motor_torque_Nm", "forward_efficiency", "reverse_efficiency",
)  # fmt: skip
"""The figures of the cycle (:meth:`ballscrew.axis.CycleResult.as_dict`) the page shows."""


def _energy(case: Case, move: Any, limits: Limits, flag: str = "") -> dict[str, Any]:
    """The energy and the check of one back-and-forth move, complete model.

    ``ballscrew energy --move`` and ``ballscrew check --move``: one
    :func:`~ballscrew.axis.run_energy` (the cycle computed once), whose result
    the check reads. A heat balance that cannot be solved is the check's
    verdict, not an error of the page: the energy is still shown. ``flag``: the
    commands' ``--units`` flag for the page's unit system ("" when the case's).
    """
    text, m, profile = _move_profile(move, limits)
    temperature = float(case.temperature.flat[0])
    with warnings.catch_warnings():
        # The speed limits are returned in the result, as the command line reports them.
        warnings.simplefilter("ignore", BallScrewSpeedWarning)
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        run = run_energy(case, profile, ["complete"], temperature=temperature, move=m,
                         thermal_failure="keep")  # fmt: skip
    cycle = run.results["complete"].cycle
    figures = cycle.as_dict()
    result: dict[str, Any] = finite_or_null(
        {
            "move": text,
            "temperature_C": temperature,
            "duration_s": profile.duration,
            **{key: figures[key] for key in _ENERGY_SHOWN},
            "warnings": [str(x) for x in run.findings] + list(cycle.speed_warnings),
            # The page shows no temperature: the heat balance's notes do not apply.
            "notes": [n for n in run.assumptions if "machine_resistance" not in n],
            "command": f'ballscrew energy --case case.toml --move "{text}"{flag}',
        }
    )
    result["check"] = _check(run, text, flag)
    return result


def _check(run: EnergyRun, text: str, flag: str = "") -> dict[str, Any]:
    """``ballscrew check`` of the same move (complete model): the verdict table's rows.

    An input the check needs and the case lacks is not an error of the page: the
    check says what it is, as its verdict, and the energy is still shown.
    """
    command = f'ballscrew check --case case.toml --move "{text}"{flag}'
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewSpeedWarning)
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            check = run_check(run, "complete")
    except BallScrewInputError as exc:
        return {"error": str(exc), "command": command}
    doc = check.as_dict()
    rows: dict[str, Any] = finite_or_null({
        "verdict": doc["verdict"], "not_checked": doc["not_checked"],
        "criteria": doc["criteria"], "assumptions": list(check.assumptions),
        "command": command,
    })  # fmt: skip
    return rows


def _curves(results: Mapping[str, FrictionResult]) -> list[dict[str, Any]]:
    """Torque, efficiency and power against speed: one curve per model, temperature and load."""
    curves = []
    for name, r in results.items():
        w, t, f = (np.ravel(x) for x in (r.speed, r.temperature, r.axial_load))
        total, eff, power = (np.ravel(x) for x in (r.total, r.efficiency, r.power_loss))
        for temp in dict.fromkeys(t.tolist()):
            for load in dict.fromkeys(f.tolist()):
                at = (t == temp) & (f == load)
                curves.append(
                    {
                        "model": name,
                        "temperature_C": temp,
                        "axial_load_N": load,
                        "speed_rpm": _inputs(rad_s_to_rpm(w[at])),
                        "torque_Nm": _floats(total[at]),
                        "efficiency": _floats(eff[at]),
                        "power_W": _floats(power[at]),
                    }
                )
    return curves


def _budget(r: FrictionResult) -> dict[str, Any]:
    """The complete model's torque by loss mechanism at the first temperature and load."""
    w, t, f = (np.ravel(x) for x in (r.speed, r.temperature, r.axial_load))
    at = (t == t[0]) & (f == f[0])
    return {
        "model": r.model,
        "temperature_C": float(t[0]),
        "axial_load_N": float(f[0]),
        "speed_rpm": _inputs(rad_s_to_rpm(w[at])),
        "components": {k: _floats(np.ravel(v)[at]) for k, v in r.components.items()},
    }


def _screw_summary(case: Case) -> dict[str, Any]:
    s = case.screw
    return {
        "pitch_diameter_mm": s.pitch_diameter * 1e3,
        "lead_mm": s.lead * 1e3,
        "ball_diameter_mm": s.ball_diameter * 1e3,
        "contact_angle_deg": math.degrees(s.contact_angle),
        "nut": s.nut,
        "preload_N": s.preload,
        "loaded_balls": s.balls_per_nut,
        "lubricant": case.lubricant.name,
        "source": case.screw_source,
        "assumptions": [f"{a.field} = {a.value}: {a.reason}" for a in case.assumptions],
    }


_SHOWN_UNITS = {"torque": "N*m", "force": "N", "length": "mm", "temperature": "degC",
                "power": "W", "speed": "rpm"}  # fmt: skip
"""The units of the figures the page shows, as computed (SI; lengths of the screw in mm)."""


def _shown(values: Any, unit: str, system: str) -> Any:
    """Figures in ``unit`` as the page shows them in ``system`` (null stays null)."""
    if values is None:
        return None
    array = np.asarray(values, dtype=float)  # null (None) becomes NaN, and null again
    converted = np.asarray(shown(array, unit, system)[0], dtype=float)
    return _floats(converted) if array.ndim else _floats([converted])[0]


def display(answer: Mapping[str, Any], system: str) -> dict[str, Any]:
    """The figures of an answer of :func:`evaluate` as the page shows them in ``system``.

    Converted by :func:`ballscrew.io.display.shown` (the command line's
    ``--units``); the answer itself stays SI. Efficiencies, speeds (rpm), powers
    (W) and energies (J) are the same in every system, as the command line prints
    them, and the page reads them from the answer.
    """

    def at(values: Any, kind: str) -> Any:
        return _shown(values, _SHOWN_UNITS[kind], system)

    curves = [
        {"temperature": at(c["temperature_C"], "temperature"),
         "axial_load": at(c["axial_load_N"], "force"), "torque": at(c["torque_Nm"], "torque")}
        for c in answer["curves"]
    ]  # fmt: skip
    budget = answer["budget"]
    if budget is not None:
        budget = {
            "temperature": at(budget["temperature_C"], "temperature"),
            "axial_load": at(budget["axial_load_N"], "force"),
            "components": {k: at(v, "torque") for k, v in budget["components"].items()},
        }
    s = answer["screw"]
    screw = {
        "pitch_diameter": at(s["pitch_diameter_mm"], "length"),
        "lead": at(s["lead_mm"], "length"),
        "ball_diameter": at(s["ball_diameter_mm"], "length"),
        "preload": at(s["preload_N"], "force"),
    }
    energy = answer["energy"]
    shown_energy = None
    criteria = None
    if energy is not None:
        shown_energy = {
            "temperature": at(energy["temperature_C"], "temperature"),
            "peak_motor_torque": at(energy["peak_motor_torque_Nm"], "torque"),
            "rms_motor_torque": at(energy["rms_motor_torque_Nm"], "torque"),
        }
        criteria = [_criterion(c, system) for c in energy["check"].get("criteria", [])]
    return {
        "system": system,
        "note": system_note(system),
        "units": {kind: shown(1.0, unit, system)[1] for kind, unit in _SHOWN_UNITS.items()},
        "curves": curves,
        "budget": budget,
        "screw": screw,
        "energy": shown_energy,
        "check": criteria,
    }


def _criterion(row: Mapping[str, Any], system: str) -> dict[str, Any]:
    """A row of the check as ``ballscrew check --units`` prints it (with the row's key)."""
    value, unit = shown(_nan(row["value"]), row["unit"], system)
    limit, _ = shown(_nan(row["limit"]), row["unit"], system)
    return {"key": row["key"], "name": label_text(row["name"], system),
            "value": _floats([value])[0],
            "limit": _floats([limit])[0], "unit": unit}  # fmt: skip


def _nan(value: float | None) -> float:
    return math.nan if value is None else float(value)


def evaluate(payload: Mapping[str, Any], limits: Limits = LIMITS) -> dict[str, Any]:
    """``POST /api/evaluate``: everything the page shows, and the files it offers.

    ``payload``: ``case`` (the fields of a case file), ``models`` (names; the
    catalogue rule is always added as the reference) and optionally ``move``
    (``stroke``, ``feed``, ``acceleration`` as text with units) and ``units``
    (``"si"`` or ``"imperial"``: the system the page shows results in, as the
    command line's ``--units``; default the case's ``[output] units``). The
    answer's figures are SI, their units in their names; ``display`` holds
    those the page shows, in the system asked for (:func:`display`).
    """
    start = time.perf_counter()
    fields = payload.get("case")
    try:
        if not isinstance(fields, Mapping):
            raise BallScrewInputError("case", fields, "the fields of a case file (an object)")
        names = _models(payload.get("models"), limits)
        case = load_case(fields, limits)
        system = unit_system("units", payload.get("units"), case.output_units)
        # The commands print what the page shows: --units when the case file says otherwise.
        flag = "" if system == case.output_units else f" --units {system}"
        w, t, f = _operating_points(case, {}, limits)
        results, plausible = _quiet_run(case, names, w, t, f)
        move = payload.get("move")
        energy = None if move is None else _energy(case, move, limits, flag)
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    flags = " ".join(f"--model {n}" for n in names)
    rows = result_rows(results)
    command = f"ballscrew torque --case case.toml {flags} --csv results.csv{flag}"
    meta = provenance(case, results, command.split())
    meta["display_units"] = system_note(system)
    chosen = names[0]
    answer: dict[str, Any] = {
        "title": case.title,
        "screw": _screw_summary(case),
        "models": names,
        "curves": _curves(results),
        "budget": _budget(results[chosen]) if chosen != "catalog" else None,
        "warnings": [f"warning: {x}" for x in case.warned] + plausible + warning_lines(results),
        "energy": energy,
        "case_toml": case.text,
        "csv": csv_text(rows),
        "provenance": json_text([], meta),
        "command": command,
        "points": int(results[chosen].total.size),
        "units": system,
    }
    answer["display"] = display(answer, system)
    answer["compute_ms"] = (time.perf_counter() - start) * 1e3
    return answer


def model_choices() -> list[dict[str, str]]:
    """The registered models (name, title, purpose), for the page's check boxes."""
    return [
        {"name": m.name, "title": m.title, "purpose": m.purpose}
        for m in sorted(models(), key=lambda m: (m.name != "complete", m.name))
    ]
