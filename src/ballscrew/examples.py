"""Bundled example ball screws."""

from __future__ import annotations

import math

from .geometry import BallScrew

__all__ = ["reference_screw"]


def reference_screw() -> BallScrew:
    """A 40 mm x 10 mm lead double-nut ball screw with 6.35 mm balls and 2 kN preload.

    A typical machine-tool feed-drive screw, used as the project's reference
    case: pitch diameter 40 mm, lead 10 mm, ball diameter 6.35 mm (1/4 in),
    contact angle 45°, conformity 0.55 on screw and nut, 2.5 loaded turns per
    circuit, 2 circuits per half-nut, 2 kN preload, steel. These are
    representative catalogue values, not one manufacturer's part.

    Examples
    --------
    >>> reference_screw().balls_per_nut
    98
    """
    return BallScrew(
        pitch_diameter=0.040,
        lead=0.010,
        ball_diameter=6.35e-3,
        contact_angle=math.radians(45.0),
        conformity_screw=0.55,
        conformity_nut=0.55,
        loaded_turns=2.5,
        circuits=2,
        nut="double",
        preload=2000.0,
    )
