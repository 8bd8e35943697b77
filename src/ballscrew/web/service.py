"""What the web calculator computes, without the web: request data in, plain data out.

Every request is turned into a case file's TOML text and read by
:func:`ballscrew.case.parse_case`, so the rules, units and one-line messages
are the command line's; the models run through
:func:`ballscrew.cli_torque.run_models` and the tables through
:mod:`ballscrew.outputs`, so the numbers and files are those of ``ballscrew
torque``; the energy of a move is :func:`ballscrew.energy.axis_cycle` on the
move of ``ballscrew energy --move``.

The work a request may ask for is bounded here, before any of it is done
(:class:`Limits`): operating points, the length of a move, the nesting of
the fields. Nothing here opens a file.
"""

from __future__ import annotations

import json
import math
import time
import tomllib
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import tomlkit

from ..case import Case, parse_case
from ..chain import FrictionResult
from ..cli_energy import parse_move
from ..cli_torque import run_models, warning_lines
from ..errors import BallScrewInputError, BallScrewSpeedWarning, BallScrewValidityWarning
from ..friction import MODELS, get_model
from ..outputs import (
    INPUT_DIGITS,
    csv_text,
    finite_or_null,
    json_text,
    provenance,
    result_rows,
    round_significant,
)
from ..units import parse_range, range_size

__all__ = [
    "LIMITS",
    "ApiError",
    "Limits",
    "case_toml",
    "evaluate",
    "load_case",
    "model_choices",
    "read_case_file",
    "read_json",
    "torque",
]


@dataclass(frozen=True)
class Limits:
    """What one request may ask for.

    Attributes
    ----------
    body_bytes : int
        Request body [bytes].
    points : int
        Operating points per model (speeds x temperatures x loads).
    models : int
        Models per request of the page.
    move_seconds : float
        Duration of the back-and-forth move whose energy is computed [s]
        (sampled every millisecond, as ``ballscrew energy`` does).
    depth : int
        Nesting of tables in the case fields (a case file needs 4).
    seconds : float
        Time a request may take, waiting included [s]: 503 past it, or after
        half of it waiting for the worker (one computation at a time).
    """

    body_bytes: int = 64 * 1024
    points: int = 2000
    models: int = 6
    move_seconds: float = 60.0
    depth: int = 6
    seconds: float = 10.0


LIMITS = Limits()

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


class ApiError(Exception):
    """A request refused: HTTP status and a one-line message (and the field, when one is at fault).

    A :class:`~ballscrew.errors.BallScrewInputError` becomes status 422 with its
    own message, the command line's.
    """

    def __init__(self, status: int, message: str, field: str = "") -> None:
        super().__init__(message)
        self.status = status
        self.message = message
        self.field = field

    @classmethod
    def from_input(cls, exc: BallScrewInputError) -> ApiError:
        """Status 422 with the message the command line prints after ``error:``."""
        return cls(422, str(exc), exc.field)

    def payload(self) -> dict[str, str]:
        """The JSON body of the refusal."""
        out = {"error": self.message}
        if self.field:
            out["field"] = self.field
        return out


def read_json(body: bytes) -> dict[str, Any]:
    """A request body as a JSON object (400 if it is not one)."""
    try:
        data = json.loads(body.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError):
        raise ApiError(400, "the request body is not JSON (UTF-8)") from None
    if not isinstance(data, dict):
        raise ApiError(400, "the request body must be a JSON object")
    return data


def _plain(value: Any, where: str, depth: int, limits: Limits) -> Any:
    """``value`` with JSON nulls left out, nesting bounded, assumed values as inline tables."""
    if depth > limits.depth:
        raise BallScrewInputError(where, "(nested tables)", f"at most {limits.depth} levels")
    if isinstance(value, Mapping):
        items = {str(k): _plain(v, f"{where}.{k}", depth + 1, limits) for k, v in value.items()}
        items = {k: v for k, v in items.items() if v is not None}
        if "assumed" in items:  # { value = "20 mm", assumed = "why" } stays on one line
            table = tomlkit.inline_table()
            table.update(items)
            return table
        return items
    if isinstance(value, list):
        return [_plain(v, f"{where}[{i}]", depth + 1, limits) for i, v in enumerate(value)]
    return value


def case_toml(fields: Mapping[str, Any], limits: Limits = LIMITS) -> str:
    """The case file (TOML text) with these fields; JSON nulls are keys left out.

    Examples
    --------
    >>> print(case_toml({"screw": {"designation": "40x10", "preload": "2 kN"},
    ...                  "lubricant": {"name": "PAO ISO VG 68", "nu40": None}}), end="")
    [screw]
    designation = "40x10"
    preload = "2 kN"
    <BLANKLINE>
    [lubricant]
    name = "PAO ISO VG 68"
    """
    plain = _plain(dict(fields), "case", 1, limits)
    try:
        return tomlkit.dumps(plain)
    except (TypeError, ValueError) as exc:  # e.g. a list mixing tables and values
        raise BallScrewInputError(
            "case", "(fields)", f"fields a TOML file can hold ({exc})"
        ) from None


def _points(field: str, value: Any, limits: Limits) -> int:
    """How many values the text of a range asks for, refused above the limit before parsing."""
    if isinstance(value, Mapping):  # an assumed value
        value = value.get("value", "")
    count = range_size(str(value))
    if count > limits.points:
        raise BallScrewInputError(
            field, value, f"at most {limits.points} values per request (this asks for {count})"
        )
    return count


def load_case(fields: Mapping[str, Any], limits: Limits = LIMITS) -> Case:
    """The case the fields describe, read as the command line reads a case file."""
    operation = fields.get("operation")
    if isinstance(operation, Mapping):
        for key in ("speed", "temperature", "axial_load"):
            if operation.get(key) is not None:
                _points(f"operation.{key}", operation[key], limits)
    return parse_case(case_toml(fields, limits), source="case")


_OVERRIDES = {"speed": "rad/s", "temperature": "degC", "axial_load": "N"}


def _operating_points(
    case: Case, given: Mapping[str, Any], limits: Limits
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Speeds, temperatures and loads: those given as text with units, else the case's."""
    arrays = {"speed": case.speed, "temperature": case.temperature, "axial_load": case.axial_load}
    for key, unit in _OVERRIDES.items():
        value = given.get(key)
        if value is None:
            continue
        if not isinstance(value, str):
            raise BallScrewInputError(key, value, "text with a unit, e.g. '100, 1000 rpm'")
        _points(key, value, limits)
        arrays[key] = np.asarray(parse_range(key, value, unit))
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
    case: Case, names: Sequence[str], w: np.ndarray, t: np.ndarray, f: np.ndarray
) -> dict[str, FrictionResult]:
    with warnings.catch_warnings():
        # The issues are kept in each result and returned as text.
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        return run_models(case, names, w, t, f)


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
        get_model(model)
        case = load_case(fields, limits)
        w, t, f = _operating_points(case, payload, limits)
        results = _quiet_run(case, [model], w, t, f)
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    r = results[model]
    return {
        "model": r.model,
        "speed_rpm": _inputs(r.speed * 30.0 / math.pi),
        "temperature_C": _inputs(r.temperature),
        "axial_load_N": _inputs(r.axial_load),
        "torque_Nm": _floats(r.total),
        "power_loss_W": _floats(r.power_loss),
        "efficiency": _floats(r.efficiency),
        "components": {k: _floats(v) for k, v in r.components.items()},
        "warnings": warning_lines(results),
    }


def _models(value: Any, limits: Limits) -> list[str]:
    """The models asked for, each checked, with the catalogue rule last as the reference."""
    names = value if isinstance(value, list) else ["complete"] if value is None else value
    if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
        raise BallScrewInputError("models", value, "a list of model names")
    if len(names) > limits.models:
        raise BallScrewInputError("models", value, f"at most {limits.models} models")
    for name in names:
        get_model(name)
    return [*dict.fromkeys(n for n in names if n != "catalog"), "catalog"]


_MOVE_KEYS = ("stroke", "feed", "acceleration")


def _energy(case: Case, move: Any, limits: Limits) -> dict[str, Any]:
    """The energy of one back-and-forth move (``ballscrew energy --move``), complete model."""
    from ..axis_setup import axis_setup
    from ..energy import axis_cycle
    from ..motion import back_and_forth

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
    profile = back_and_forth(m["stroke"], m["feed"], m["acceleration"])
    temperature = float(case.temperature.flat[0])
    params = dict(case.model_parameters.get("complete", {}))
    setup = axis_setup(case.screw, case.axis, case.thermal, abs(m["stroke"]))
    with warnings.catch_warnings():
        # The speed limits are returned in the result, as the command line reports them.
        warnings.simplefilter("ignore", BallScrewSpeedWarning)
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = axis_cycle(
            profile, case.screw, case.lubricant, setup.axis, temperature=temperature,
            model="complete", **params,
        )  # fmt: skip
    result: dict[str, Any] = finite_or_null(
        {
            "move": text,
            "temperature_C": temperature,
            "duration_s": profile.duration,
            "friction_energy_J": r.friction_energy,
            "friction_energy_out_J": r.friction_energy_out,
            "friction_energy_back_J": r.friction_energy_back,
            "constant_efficiency_energy_J": r.constant_efficiency_energy,
            "bearing_energy_J": r.bearing_energy,
            "load_work_J": r.load_work,
            "peak_motor_torque_Nm": r.peak_motor_torque,
            "rms_motor_torque_Nm": r.rms_motor_torque,
            "forward_efficiency": r.forward_efficiency,
            "reverse_efficiency": r.reverse_efficiency,
            "warnings": list(r.speed_warnings),
            # The page shows no temperature: the heat balance's notes do not apply.
            "notes": [n for n in setup.notes if "machine_resistance" not in n],
            "command": f'ballscrew energy --case case.toml --move "{text}"',
        }
    )
    return result


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
                        "speed_rpm": _inputs(w[at] * 30.0 / math.pi),
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
        "speed_rpm": _inputs(w[at] * 30.0 / math.pi),
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


def evaluate(payload: Mapping[str, Any], limits: Limits = LIMITS) -> dict[str, Any]:
    """``POST /api/evaluate``: everything the page shows, and the files it offers.

    ``payload``: ``case`` (the fields of a case file), ``models`` (names; the
    catalogue rule is always added as the reference) and optionally ``move``
    (``stroke``, ``feed``, ``acceleration`` as text with units).
    """
    start = time.perf_counter()
    fields = payload.get("case")
    try:
        if not isinstance(fields, Mapping):
            raise BallScrewInputError("case", fields, "the fields of a case file (an object)")
        names = _models(payload.get("models"), limits)
        case = load_case(fields, limits)
        w, t, f = _operating_points(case, {}, limits)
        results = _quiet_run(case, names, w, t, f)
        move = payload.get("move")
        energy = None if move is None else _energy(case, move, limits)
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    flags = " ".join(f"--model {n}" for n in names)
    rows = result_rows(results)
    command = f"ballscrew torque --case case.toml {flags} --csv results.csv"
    meta = provenance(case, results, command.split())
    chosen = names[0]
    return {
        "title": case.title,
        "screw": _screw_summary(case),
        "models": names,
        "curves": _curves(results),
        "budget": _budget(results[chosen]) if chosen != "catalog" else None,
        "warnings": warning_lines(results),
        "energy": energy,
        "case_toml": case.text,
        "csv": csv_text(rows),
        "provenance": json_text([], meta),
        "command": command,
        "points": int(results[chosen].total.size),
        "compute_ms": (time.perf_counter() - start) * 1e3,
    }


def read_case_file(body: bytes) -> dict[str, Any]:
    """``POST /api/case``: an uploaded case file's fields, read as TOML data (nothing else).

    The fields fill the page's form; they are checked when the page computes
    them, with the messages beside the fields. A file that is not UTF-8 TOML
    is refused with the command line's message.
    """
    try:
        text = body.decode("utf-8")
    except UnicodeDecodeError:
        raise ApiError.from_input(
            BallScrewInputError("case", "(file)", "a UTF-8 text file")
        ) from None
    try:
        fields = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ApiError.from_input(
            BallScrewInputError("case", "(file)", f"valid TOML ({exc})")
        ) from None
    # Dates and times (TOML has them, case files do not) and inf or nan become
    # text, which the form shows and the computation then refuses by name.
    return {"fields": _as_text_where_json_cannot(fields)}


def _as_text_where_json_cannot(data: Any) -> Any:
    if isinstance(data, float) and not math.isfinite(data):
        return repr(data)
    if isinstance(data, dict):
        return {k: _as_text_where_json_cannot(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_as_text_where_json_cannot(v) for v in data]
    if isinstance(data, str | int | float | bool):
        return data
    return str(data)


def model_choices() -> list[dict[str, str]]:
    """The registered models (name, title, purpose), for the page's check boxes."""
    return [
        {"name": m.name, "title": m.title, "purpose": m.purpose}
        for m in sorted(MODELS.values(), key=lambda m: (m.name != "complete", m.name))
    ]
