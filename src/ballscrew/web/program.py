"""``POST /api/program``: a short part program on the example machine (or a machine sent inline).

The request is ``{"program": "G-code text", "machine": "TOML text" (optional)}``.
Without a machine, the bundled example machine runs it
(:func:`ballscrew.io.machine.example_machine_text`). A machine sent here must
give every case inline: nothing here opens a file. The program is bounded to
:data:`MAX_BLOCKS` blocks, :data:`MAX_SECONDS` of motion at its feeds and
:data:`MAX_SAMPLES` samples, so that it stays within the server's time budget and a
worker's memory: the samples are bounded by the planner's estimate before any block
is planned (:func:`ballscrew.program.planner.least_samples`; an axis's jerk mistyped as
``1e-9 m/s^3`` stretches a move over hours), then by their count before any is made.
Each refusal is a 422 naming the bound. The answer is the summary the command line
prints: per axis the energies, friction share, torques against the motor,
temperature, and the reversals with their load directions.
"""

from __future__ import annotations

from typing import Any

from ..errors import BallScrewInputError
from ..io.extras import MissingExtraError
from ..io.machine import example_machine_text, parse_machine
from ..program import read_program, run_program
from ..program.planner import MAX_SAMPLES as PLAN_MAX_SAMPLES
from ..report.outputs import finite_or_null
from .inputs import ApiError, Limits

__all__ = ["MAX_BLOCKS", "MAX_SAMPLES", "MAX_SECONDS", "run"]

MAX_BLOCKS = 500
"""The most blocks of motion or dwell a request's program may hold."""
MAX_SECONDS = 600.0
"""The longest program a request may run at its feeds [s]."""
MAX_SAMPLES = 120_000
"""The most samples a request's program may take: :data:`MAX_SECONDS` at the example
machine's 5 ms (about 120 MB and a few seconds of a worker; the command line takes
:data:`ballscrew.program.planner.MAX_SAMPLES`)."""


def _text(payload: dict[str, Any], key: str, required: bool) -> str | None:
    value = payload.get(key)
    if value is None and not required:
        return None
    if not isinstance(value, str) or (required and not value.strip()):
        raise ApiError(422, f"{key}: the {key} as text", key)
    return value


def run(payload: dict[str, Any], limits: Limits) -> dict[str, Any]:
    """The program's summary on the machine (module docstring)."""
    text = _text(payload, "program", True)
    assert text is not None
    machine_text = _text(payload, "machine", False)
    machine = parse_machine(
        example_machine_text() if machine_text is None else machine_text,
        source="machine", folder=None,
    )  # fmt: skip
    program = read_program(
        text, arc_tolerance=machine.arc_tolerance, max_blocks=MAX_BLOCKS, machine=machine
    )
    nominal = float(sum(program.dwell)) + _path_time(program, machine.rapid_feed)
    if nominal > MAX_SECONDS:
        raise ApiError(
            422, f"program: about {nominal:.0f} s of motion; this server runs at most "
            f"{MAX_SECONDS:.0f} s (the command line has no bound)", "program",
        )  # fmt: skip
    try:
        r = run_program(machine, program, max_samples=MAX_SAMPLES)
    except MissingExtraError as exc:  # the server runs without the program extra
        raise ApiError(501, str(exc)) from None
    except BallScrewInputError as exc:
        if exc.field != "program" or "samples" not in str(exc.value):
            raise
        raise ApiError(
            422,
            f"program: {exc.value}; this server runs at most {MAX_SAMPLES:,} samples "
            f"(the command line {PLAN_MAX_SAMPLES:,}): {exc.allowed.split('): ', 1)[-1]}",
            "program",
        ) from None
    doc = r.as_dict()
    doc.pop("energy_per_block_J")
    for axis in doc["axes"].values():
        reversals = axis.pop("reversals")
        kinds = [v["load_direction"] for v in reversals]
        axis["reversals"] = len(reversals)
        axis["load_directions"] = {k: kinds.count(k) for k in sorted(set(kinds))}
        play = [v["lost_motion_um"] for v in reversals]
        axis["lost_motion_um"] = [min(play), max(play)] if play else None
    doc["limits"] = {"blocks": MAX_BLOCKS, "seconds": MAX_SECONDS, "samples": MAX_SAMPLES}
    result: dict[str, Any] = finite_or_null(doc)
    return result


def _path_time(program: Any, rapid: float) -> float:
    """The program's path length over its feeds [s] (a lower bound of its time)."""
    import numpy as np

    length = np.linalg.norm(program.end - program.start, axis=1)
    arcs = program.kind == 2
    # An arc's length is at least its chord; a full circle's chord is 0: take 2 pi R.
    radius = np.linalg.norm(program.start - np.nan_to_num(program.centre), axis=1)
    length = np.where(arcs, np.maximum(length, np.abs(program.sweep) * radius), length)
    feed = np.where(program.kind == 0, rapid, program.feed)
    with np.errstate(invalid="ignore", divide="ignore"):
        times = np.where(program.kind == 3, 0.0, length / feed)
    return float(np.sum(times[np.isfinite(times)]))
