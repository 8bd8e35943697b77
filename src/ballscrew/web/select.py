"""``POST /api/select``: choose a screw for the page's case and move (``ballscrew select``).

Request: ``case`` (the fields of a case file: its axis, motor and limits stay,
its screw is replaced), ``move`` (stroke, feed and acceleration as text, the
page's back-and-forth move), and the filters as text or lists: ``diameter``
and ``lead`` ranges (e.g. ``"32..40 mm"``), ``makers``, ``preloads``,
``sources`` (``catalogue``, ``iso``), ``objectives`` and ``confidence`` (``"95 %"`` by
default). Each candidate runs
the whole check of the move, so the page takes at most
:data:`MAX_CANDIDATES` of them (the command line has no bound); more is
refused with the count, before any runs.

The answer: the recommendation first with the reason (``undecided`` when no
candidate passes with the confidence, the one least likely to fail named), then the rest of the
front, each with its figures and largest utilisation; the count of feasible
and rejected candidates and the closest rejected ones with what fails them;
the command that gives the same on the command line.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from typing import Any

from ..errors import BallScrewInputError, BallScrewSpeedWarning, BallScrewValidityWarning
from ..report.outputs import finite_or_null
from .inputs import LIMITS, ApiError, Limits, load_case

__all__ = ["MAX_CANDIDATES", "SHOWN", "choose"]

MAX_CANDIDATES = 24
"""The most candidates one request of the page may check (20 take 0.7 s of CPU on a 300 mm
move, well inside a request's time budget)."""

SHOWN = 5
"""The most front members and rejected candidates the answer lists."""

_FIGURES = ("energy_J", "L10_h", "stiffness_N_per_um", "lost_motion_um", "thermal_error_um",
            "max_utilisation", "p_not_ok")  # fmt: skip


def _names(payload: Mapping[str, Any], key: str, default: Sequence[str]) -> list[str]:
    value = payload.get(key)
    if value is None or value == []:
        return list(default)
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise BallScrewInputError(key, value, "a list of names")
    return value


def _row(e: Any) -> dict[str, Any]:
    return {"name": e.name, "estimated": e.candidate.estimated, "binding": e.binding,
            **{k: e.figures[k] for k in _FIGURES}}  # fmt: skip


def choose(payload: Mapping[str, Any], limits: Limits = LIMITS) -> dict[str, Any]:
    """The selection for the payload's case and move (module docstring)."""
    from ..axis.uncertainty import CONFIDENCE
    from ..io.extras import MissingExtraError, require
    from ..select import run_select
    from ..select.choose import parse_confidence
    from ..select.pool import DEFAULT_PRELOADS, candidates, length_range
    from .service import _move_profile

    try:
        require("select", "the page's screw selection", modules=("pymoo",))
    except MissingExtraError as exc:  # the server runs without the select extra
        raise ApiError(501, str(exc)) from None
    fields = payload.get("case")
    try:
        if not isinstance(fields, Mapping):
            raise BallScrewInputError("case", fields, "the fields of a case file (an object)")
        case = load_case(fields, limits)
        text, m, profile = _move_profile(payload.get("move"), limits)
        diameter = length_range("diameter", payload.get("diameter"))
        lead = length_range("lead", payload.get("lead"))
        makers = _names(payload, "makers", ())
        preloads = _names(payload, "preloads", DEFAULT_PRELOADS)
        sources = _names(payload, "sources", ("catalogue",))
        objectives = _names(payload, "objectives", ("energy", "life"))
        confidence = parse_confidence(payload.get("confidence", CONFIDENCE), "confidence")
        found = candidates(case.text, diameter=diameter, lead=lead, makers=makers,
                           preloads=preloads, sources=sources)  # fmt: skip
        if len(found) > MAX_CANDIDATES:
            raise BallScrewInputError(
                "diameter", payload.get("diameter"),
                f"filters leaving at most {MAX_CANDIDATES} candidates on the page (these leave "
                f"{len(found)}: narrow the diameter, lead, maker or preload classes; the "
                "command line has no such limit)",
            )  # fmt: skip
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewSpeedWarning)
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            result = run_select(case, profile, objectives=objectives, diameter=diameter,
                                lead=lead, makers=makers, preloads=preloads, move=m,
                                sources=sources, confidence=confidence)  # fmt: skip
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    best = result.recommended
    order = [best, *(i for i in result.front if i != best)]
    rejected = sorted(result.rejected, key=lambda e: e.figures["max_utilisation"]
                      if e.figures["max_utilisation"] == e.figures["max_utilisation"]
                      else float("inf"))  # fmt: skip
    flags = [f'--diameter "{payload["diameter"]}"' if diameter else "",
             f'--lead "{payload["lead"]}"' if lead else "",
             *(f"--maker {x}" for x in makers), *(f"--preload {x}" for x in preloads),
             *(f"--source {x}" for x in sources),
             *(f"--objective {x}" for x in objectives),
             f'--confidence "{confidence:.1%}"' if confidence != CONFIDENCE else ""]  # fmt: skip
    out: dict[str, Any] = finite_or_null({
        "objectives": list(result.objectives),
        "recommended": _row(result.evaluated[best]) | {"on_front": best in result.front},
        "reason": result.reason,
        "confidence": result.confidence,
        "undecided": result.undecided,
        "front": [_row(result.evaluated[i]) for i in order[:SHOWN] if i in result.front],
        "front_size": len(result.front),
        "candidates": len(result.evaluated),
        "feasible": len(result.feasible),
        "rejected": [_row(e) for e in rejected[:SHOWN]],
        "rating_estimates": result.inputs.get("rating_estimates"),
        "command": f'ballscrew select --case case.toml --move "{text}" '
        + " ".join(f for f in flags if f),
    })  # fmt: skip
    return out
