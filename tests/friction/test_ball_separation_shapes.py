"""Every ball separation gives results of the inputs' shape (issue 38, item 4).

A spacer-ball or caged nut at one scalar speed raised a ValueError: the train's
ball-ball coefficient was a one-element array where the inputs were scalars. The
shape rule is numpy's broadcasting of speed, temperature and axial load, for every
model and every separation.
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import friction_torque, models, reference_screw
from ballscrew.geometry import BALL_SEPARATIONS

INPUTS = {
    "scalar": (100.0, 40.0, 0.0, ()),
    "1-D": (np.array([10.0, 100.0, 300.0]), 40.0, 500.0, (3,)),
    "broadcast": (np.array([[10.0], [100.0]]), np.array([20.0, 40.0, 60.0]), 0.0, (2, 3)),
}


@pytest.mark.parametrize("separation", list(BALL_SEPARATIONS))
@pytest.mark.parametrize("inputs", list(INPUTS))
@pytest.mark.parametrize("model", [m.name for m in models()])
def test_every_separation_keeps_the_inputs_shape(separation: str, inputs: str, model: str) -> None:
    speed, temperature, load, shape = INPUTS[inputs]
    screw = reference_screw().replace(ball_separation=separation)
    r = friction_torque(screw, "mineral ISO VG 68", speed=speed, temperature=temperature,
                        axial_load=load, model=model)  # fmt: skip
    assert np.shape(r.total) == shape
    assert all(np.shape(v) == shape for v in r.components.values())
    assert np.all(np.isfinite(r.total)) and np.all(np.asarray(r.total) > 0.0)


def test_separated_balls_lose_the_ball_ball_sliding_only() -> None:
    # Spacer balls and cages take the ball-ball sliding away: no two loaded balls touch.
    base = friction_torque(reference_screw(), "mineral ISO VG 68", speed=100.0,
                           temperature=40.0, model="complete")  # fmt: skip
    for separation in ("spacer-balls", "cage"):
        screw = reference_screw().replace(ball_separation=separation)
        r = friction_torque(screw, "mineral ISO VG 68", speed=100.0, temperature=40.0,
                            model="complete")  # fmt: skip
        assert float(r.components["ball_ball"]) == 0.0 < float(base.components["ball_ball"])
