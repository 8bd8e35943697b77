"""Geometry as arrays in every layer (issue 39, item 4): many screws in one evaluation.

``friction_torques`` runs the complete model on all screws of one nut arrangement at
once, their geometry as broadcast arrays (:class:`ballscrew.geometry.ScrewArray`)
through the kinematics, the loads, the Hertz contacts, the film, the helix's slip
share and the ball train. The reference is independent of that path: one
``friction_torque`` call per screw, on scalar geometry. The two run the same
equations on the same numbers; whole-array functions may round the last bit
otherwise (numpy's sine against the math module's, a secant iteration that stops
when every screw has converged), so the torques are held to 1e-12 relative, what
issue 39 asks (measured: 2e-15).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from ballscrew import BallScrew, friction_torque, friction_torques, reference_screw
from ballscrew.errors import BallScrewInputError
from ballscrew.friction import MODELS
from ballscrew.geometry import ScrewArray
from shared import MINERAL, PAO

RTOL = 1e-12


def _random_screws(count: int, seed: int) -> list[BallScrew]:
    """Screws of every nut arrangement and ball separation, sizes drawn across the range."""
    rng = np.random.default_rng(seed)
    base = reference_screw()
    screws = []
    for i in range(count):
        nut = ("double", "single-4point", "single")[i % 3]
        separation = ("none", "none", "spacer-balls", "cage")[i % 4]
        d = rng.uniform(0.016, 0.063)
        ball = rng.uniform(0.08, 0.16) * d
        screws.append(
            base.replace(
                pitch_diameter=d, ball_diameter=ball, lead=rng.uniform(max(1.1 * ball, 4e-3), 0.04),
                preload=0.0 if nut == "single" else rng.uniform(200.0, 5000.0), nut=nut,
                ball_separation=separation, conformity_screw=rng.uniform(0.52, 0.57),
                conformity_nut=rng.uniform(0.52, 0.57),
                contact_angle=math.radians(rng.uniform(40.0, 50.0)),
                loaded_turns=float(rng.choice([1.5, 2.5, 3.5])), circuits=int(rng.integers(1, 4)),
            )
        )  # fmt: skip
    return screws


def _close(batch: np.ndarray, single: np.ndarray) -> None:
    np.testing.assert_allclose(batch, single, rtol=RTOL, atol=0.0)


POINTS = {
    "speeds, both signs, one load": {
        "speed": np.linspace(-300.0, 300.0, 7), "temperature": 40.0, "axial_load": 1500.0,
    },
    "speeds x loads of both directions": {
        "speed": np.linspace(1.0, 300.0, 300)[:, None], "temperature": 30.0,
        "axial_load": np.linspace(-4000.0, 4000.0, 13)[None, :],
    },
    "temperatures, a pulling load": {
        "speed": 50.0, "temperature": np.array([20.0, 60.0]), "axial_load": -800.0,
    },
}  # fmt: skip


@pytest.mark.parametrize("name", list(POINTS))
def test_many_screws_at_once_equal_each_screws_own_call(name: str) -> None:
    # 36 screws: double, 4-point and single nuts, full trains, spacer balls and cages.
    screws = _random_screws(36, seed=5)
    points = POINTS[name]
    batch = friction_torques(screws, PAO, warn=False, **points)  # type: ignore[arg-type]
    for i, screw in enumerate(screws):
        one = friction_torque(screw, PAO, warn=False, **points)  # type: ignore[arg-type]
        _close(batch.total[i], one.total)
        for component, value in one.components.items():
            # A component against the total: a zero one (seals) has no relative scale.
            np.testing.assert_allclose(
                batch.components[component][i], value, rtol=0.0, atol=RTOL * one.total.max()
            )
        _close(batch.efficiency[i], one.efficiency)


def test_paired_points_of_many_screws_equal_each_screws_own_call() -> None:
    # A Monte Carlo sample: each screw at its own 20 speeds and its own load.
    rng = np.random.default_rng(11)
    screws = _random_screws(24, seed=7)
    speed = rng.uniform(1.0, 300.0, (24, 20))
    load = rng.uniform(-3000.0, 3000.0, (24, 1))
    batch = friction_torques(screws, MINERAL, speed=speed, temperature=40.0, axial_load=load,
                             paired=True, warn=False)  # fmt: skip
    assert batch.total.shape == (24, 20)
    for i, screw in enumerate(screws):
        one = friction_torque(screw, MINERAL, speed=speed[i], temperature=40.0,
                              axial_load=load[i], warn=False)  # fmt: skip
        _close(batch.total[i], one.total)


def test_the_batch_warns_of_what_the_screw_by_screw_loop_warns_of(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The validity checks of all screws at once keep, per quantity, the worst screw's
    # value: the issues of the loop over the screws (the model told not to batch).
    screws = _random_screws(18, seed=3)
    kw = {"speed": [5.0, 600.0], "temperature": [15.0, 70.0], "axial_load": 6000.0}
    batch = friction_torques(screws, MINERAL, warn=False, **kw)  # type: ignore[arg-type]
    monkeypatch.setitem(MODELS, "complete", replace(MODELS["complete"], batches=None))
    loop = friction_torques(screws, MINERAL, warn=False, **kw)  # type: ignore[arg-type]
    _close(batch.total, loop.total)
    got = {(w.quantity, w.model): w.value for w in batch.warnings}
    expected = {(w.quantity, w.model): w.value for w in loop.warnings}
    assert got.keys() == expected.keys() and got
    for key, value in expected.items():
        assert got[key] == pytest.approx(value, rel=1e-12)


def test_chunks_split_the_screws_not_their_points() -> None:
    # A chunk of 2000 points holds two screws of 1000 points: the batches of two give the
    # torques of one batch of all.
    screws = _random_screws(7, seed=1)
    speed = np.linspace(1.0, 300.0, 1000)
    whole = friction_torques(screws, PAO, speed=speed, temperature=40.0, warn=False)
    parts = friction_torques(screws, PAO, speed=speed, temperature=40.0, chunk_size=2000,
                             warn=False)  # fmt: skip
    _close(parts.total, whole.total)


def test_a_screw_array_holds_each_screws_own_numbers() -> None:
    screws = [
        s.replace(ball_separation="none") for s in _random_screws(9, seed=2) if s.nut == "double"
    ]
    arr = ScrewArray.of(screws, ndim=3)
    assert arr.lead_angle.shape == (len(screws), 1, 1)
    for name in ("lead_angle", "rx_screw", "ry_nut", "reduced_modulus", "balls_per_nut"):
        assert arr.values[name].ravel().tolist() == [getattr(s, name) for s in screws]
    with pytest.raises(BallScrewInputError) as info:
        ScrewArray.of([reference_screw(), reference_screw().replace(nut="single", preload=0.0)])
    assert info.value.field == "screws"
