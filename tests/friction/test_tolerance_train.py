"""The complete model's ball train from a contact-angle tolerance (``ball_train="tolerance"``)."""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np
import pytest

from ballscrew import BallScrew, BallScrewInputError, friction_torque, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.friction.complete import CONTACT_ANGLE_SCATTER, CONTACT_ANGLE_SCATTER_RANGE
from ballscrew.lubricants import get as get_lubricant
from ballscrew.study.validation import ReferenceCase, load_cases

OIL = "mineral ISO VG 68"
RPM = math.pi / 30.0


def _train(screw: BallScrew | None = None, **kw: Any) -> dict[str, np.ndarray]:
    kw.setdefault("ball_train", "tolerance")
    speed = kw.pop("speed", 100.0 * RPM)
    temperature = kw.pop("temperature", 40.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(screw or reference_screw(), OIL, speed=speed,
                            temperature=temperature, model="complete", **kw)  # fmt: skip
    return r.components


def test_no_scatter_no_push() -> None:
    # Equal balls all want the same speed: no ball pushes another.
    parts = _train(contact_angle_scatter=0.0)
    assert float(parts["ball_ball"]) == 0.0


def test_train_term_is_proportional_to_the_scatter_up_to_the_ball_ball_film() -> None:
    # The compressions are linear in sigma_alpha; the ball-ball coefficient moves a little
    # with the force (its film thins, its mean pressure rises) and the creep is quadratic
    # but small: doubling the scatter doubles the term within 2 %.
    one = float(_train(contact_angle_scatter=0.004)["ball_ball"])
    two = float(_train(contact_angle_scatter=0.008)["ball_ball"])
    assert two / one == pytest.approx(2.0, rel=0.02)


def test_train_term_does_not_depend_on_the_lead() -> None:
    # Same balls, same grooves, lead 5 -> 20 mm (lead angle 2.3 -> 9 degrees): the
    # tolerance mechanism holds no lead; only the helix's cos(lambda) moves the ball load
    # (1/cos), the spins and the ball count, which add up to under 10 %. (The catalogue rule
    # rises by sqrt(4) = 2 over the same leads.)
    s = reference_screw()
    five = float(_train(s.replace(lead=5e-3))["ball_ball"])
    twenty = float(_train(s.replace(lead=20e-3))["ball_ball"])
    assert twenty / five == pytest.approx(1.0, abs=0.1)


def test_train_term_per_ball_grows_as_the_square_root_of_the_train() -> None:
    # 4 times the loaded turns and 4 times the preload (the same ball load): 4 times the
    # balls, each contact between them pushed about twice as hard (the bridge's sqrt N).
    # 15 %: M_N's discrete overshoot (0.58 of 2.5 at 12 balls) and the rounding of the
    # ball counts.
    s = reference_screw()
    short = s.replace(loaded_turns=1.5)
    long_ = s.replace(loaded_turns=6.0, preload=4.0 * s.preload)
    ratio = float(_train(long_)["ball_ball"]) / float(_train(short)["ball_ball"])
    n_short, n_long = short.balls_per_circuit, long_.balls_per_circuit
    # ball-ball power ~ (N - 1) M_N at equal load; M_N ~ sqrt(N) (the bridge)
    expected = (n_long - 1) * math.sqrt(n_long) / ((n_short - 1) * math.sqrt(n_short))
    assert ratio == pytest.approx(expected, rel=0.15)


def test_spacers_keep_the_push_and_cages_take_it_one_ball_at_a_time() -> None:
    # Spacer balls roll on their neighbours: only the creep is left (second order in the
    # scatter: far below the sliding). A cage takes each ball's own traction (not the
    # running sum of ~sqrt(N) of them) at half the sliding speed: a fraction of the
    # full-complement nut's, more than the spacer nut's.
    s = reference_screw()
    full = float(_train(s)["ball_ball"])
    spacer = float(_train(s.replace(ball_separation="spacer-balls"))["ball_ball"])
    cage = float(_train(s.replace(ball_separation="cage"))["ball_ball"])
    assert 0.0 < spacer < 0.02 * full
    assert spacer < cage < 0.2 * full


def test_train_force_follows_the_film() -> None:
    # The creep coefficient is each contact's mixed-film mu: as the film grows with speed,
    # mu falls from the boundary value towards the full-film traction, and the train
    # with it (at 10 -> 1000 rpm, 40 C).
    slow = float(_train(speed=10.0 * RPM)["ball_ball"])
    fast = float(_train(speed=1000.0 * RPM)["ball_ball"])
    assert fast < 0.9 * slow


def test_bad_ball_train_is_refused_with_its_name() -> None:
    with pytest.raises(BallScrewInputError) as info:
        _train(ball_train="guess")
    assert info.value.field == "ball_train"
    with pytest.raises(BallScrewInputError) as info:
        _train(contact_angle_scatter=-0.01)
    assert info.value.field == "contact_angle_scatter"


# --- the fitted scatter ------------------------------------------------------------------
def _case_torque(case: ReferenceCase, scatter: float) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw, get_lubricant(case.lubricant), speed=case.speed_rpm * RPM,
            temperature=case.temperature, axial_load=case.axial_load, model="complete",
            ball_train="tolerance", contact_angle_scatter=scatter,
        )  # fmt: skip
    return float(r.total)


def test_contact_angle_scatter_is_the_least_squares_fit_of_the_training_cases() -> None:
    # The same training rows and loss as the ball-train constant; given to 4 significant
    # figures, the minimum lies within 0.01 % of it, so the loss is lower there than 1 %
    # to either side (quadratic about its minimum).
    train = [c for c in load_cases() if c.kind == "catalog" and c.training]
    ref = np.log([c.reference for c in train])

    def loss(scatter: float) -> float:
        return float(np.sum((np.log([_case_torque(c, scatter) for c in train]) - ref) ** 2))

    at = loss(CONTACT_ANGLE_SCATTER)
    assert at < loss(0.99 * CONTACT_ANGLE_SCATTER)
    assert at < loss(1.01 * CONTACT_ANGLE_SCATTER)
    lo, hi = CONTACT_ANGLE_SCATTER_RANGE
    assert lo < CONTACT_ANGLE_SCATTER < hi
