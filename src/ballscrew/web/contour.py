"""``POST /api/contour``: the circular test of the page's axis (``ballscrew contour``).

Request: ``case`` (the fields of a case file, with the axis' moving mass),
``radius`` and ``feed`` as text with units. The answer: the radial deviation
by angle without and with the model's friction compensation, the circular
deviation G, the quadrant glitches, the reduction and the loops' figures,
computed by :func:`ballscrew.servo.run_contour` counter-clockwise. The
revolution is bounded by the page's move limit, like a move. A circle whose
loops or drive fail a check (:mod:`ballscrew.servo.verdict`) is refused (422)
with the failed checks, as the command line refuses it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..errors import BallScrewInputError
from ..io.units import to_si
from ..report.outputs import finite_or_null
from .inputs import LIMITS, ApiError, Limits, load_case

__all__ = ["contour"]


def contour(payload: Mapping[str, Any], limits: Limits = LIMITS) -> dict[str, Any]:
    """The circular test of the payload's case (module docstring)."""
    from ..servo import run_contour

    fields = payload.get("case")
    try:
        if not isinstance(fields, Mapping):
            raise BallScrewInputError("case", fields, "the fields of a case file (an object)")
        radius = to_si("--radius", str(payload.get("radius", "10 mm")), "m")
        feed = to_si("--feed", str(payload.get("feed", "1 m/min")), "m/s")
        if radius > 0 and feed > 0 and 2 * math.pi * radius / feed > limits.move_seconds:
            raise BallScrewInputError(
                "--radius", payload.get("radius"), f"a revolution within "
                f"{limits.move_seconds:g} s on the page (the command line has no such limit)",
            )  # fmt: skip
        case = load_case(fields, limits)
        result = run_contour([case], radius=radius, feed=feed, directions=("CCW",))
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    if result.verdict == "NOT OK":  # a loop or a drive that cannot run the circle: said, not drawn
        failed = [c.text() for c in result.checks if c.status == "NOT OK"]
        raise ApiError(422, "NOT OK, no circle drawn: " + "; ".join(failed), "feed")
    doc = result.as_dict()
    keys = ("compensated", "circular_deviation_G_um", "largest_glitch_um", "glitches",
            "radial_deviation")  # fmt: skip
    runs = [{k: c[k] for k in keys} for c in doc["circles"]]
    text = f'--radius "{payload.get("radius", "10 mm")}" --feed "{payload.get("feed", "1 m/min")}"'
    out: dict[str, Any] = finite_or_null({
        "runs": runs, "reduction": doc["glitch_reduction"], "loops": doc["axes"]["x"]["loops"],
        "notes": doc["notes"], "cpu_seconds": doc["cpu_seconds"],
        "verdict": doc["verdict"],
        "command": f"ballscrew contour --case case.toml {text} --direction CCW",
    })  # fmt: skip
    return out
