"""A toy friction model in one file: what adding a model to ballscrew takes.

A constant rolling-resistance coefficient on every loaded ball contact, at the
pitch radius. It is not physics anyone should use; it exists so that the test
suite can check that one module plus one ``register`` call is all a new model
needs: the chain, the generic tests, the CLI, the web page and the validation
pick it up (tests/friction/test_new_model.py).
"""

from __future__ import annotations

import numpy as np

from ballscrew.errors import FloatArray
from ballscrew.friction import register
from ballscrew.geometry import BallScrew
from ballscrew.loads import ball_loads
from ballscrew.lubricant import Lubricant


@register(
    "coulomb-toy",
    title="Toy: a constant coefficient on the ball loads",
    reference="none (a test fixture)",
    validity="none: a fixture of the test suite",
    purpose="to show what a new model needs",
)
def coulomb_toy(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    *,
    coefficient: float = 0.001,
) -> dict[str, FloatArray]:
    """Torque ``coefficient * sum(Q) * d_m / 2`` over both contact families [N·m]."""
    loads = ball_loads(screw, axial_load)
    total_load = loads.balls_1 * loads.normal_load_1 + loads.balls_2 * loads.normal_load_2
    torque = coefficient * total_load * screw.pitch_diameter / 2.0
    shape = np.broadcast_shapes(np.shape(speed), np.shape(temperature), np.shape(torque))
    return {"coulomb": np.broadcast_to(torque, shape)}
