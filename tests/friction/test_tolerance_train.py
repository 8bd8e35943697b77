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
    s = reference_screw().replace(ball_diameter=3.969e-3)  # 5/32 in fits the 5 mm lead
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


# --- load cases, nut kinds, the return path ---------------------------------------------
def test_a_lifted_off_half_nut_adds_no_train() -> None:
    # Past 2^1.5 times the preload one half-nut carries nothing: its balls have no contact
    # area, so no creep coefficient, no stiffness and no train; the loaded half alone
    # remains. Its term is what a single nut with the same load gives: the same balls,
    # the same ball load (the load falls on one family in both).
    s = reference_screw()
    load = 3.5 * s.preload
    lifted = float(_train(s, axial_load=load)["ball_ball"])
    single = float(_train(s.replace(nut="single", preload=0.0), axial_load=load)["ball_ball"])
    assert math.isfinite(lifted) and lifted > 0.0
    assert lifted == pytest.approx(single, rel=1e-9)


def test_four_point_train_is_one_train_of_both_pairs() -> None:
    # A 4-point ball creeps at four contacts under the 4-point spin (about 9 times the
    # 2-point one on this screw): a softer train than the double nut's at the same
    # preload, though both contact pairs push it.
    s = reference_screw()
    four = float(_train(s.replace(nut="single-4point"))["ball_ball"])
    double = float(_train(s)["ball_ball"])
    assert 0.0 < four < double
    # Equal pairs (no external load): twice one pair's stiffness, so twice the push of a
    # train whose balls had one such pair; the 4-point term is thus linear in the scatter.
    one = float(_train(s.replace(nut="single-4point"), contact_angle_scatter=0.002)["ball_ball"])
    two = float(_train(s.replace(nut="single-4point"), contact_angle_scatter=0.004)["ball_ball"])
    assert two / one == pytest.approx(2.0, rel=0.02)


def test_recirculation_of_a_spacer_ball_nut_is_the_push_round_the_return() -> None:
    # Spacer balls: no ball-ball sliding, so the return costs the push F_r = mu_bl m v_c^2
    # Theta / D_w at the centre speed v_c, per circuit of each loaded half: T = P / omega.
    from ballscrew.kinematics import kinematics
    from ballscrew.materials import STEEL_DENSITY

    s = reference_screw().replace(ball_separation="spacer-balls")
    omega = 3000.0 * RPM
    parts = _train(s, speed=omega)
    v_c = float(kinematics(s, omega).orbital_speed) * s.pitch_diameter / 2.0
    v_c /= math.cos(s.lead_angle)
    mass = STEEL_DENSITY * math.pi / 6.0 * s.ball_diameter**3
    push = 0.1 * mass * v_c**2 * 2.0 * math.pi / s.ball_diameter
    expected = 2 * s.circuits * push * v_c / omega
    assert float(parts["recirculation"]) == pytest.approx(expected, rel=1e-9)
    # Touching balls add the ball-ball sliding of the push's mean compression.
    full = _train(reference_screw(), speed=omega)
    assert float(full["recirculation"]) > float(parts["recirculation"])


@pytest.mark.parametrize("separation", ["none", "spacer-balls", "cage"])
@pytest.mark.parametrize("nut", ["double", "single", "single-4point"])
@pytest.mark.parametrize(
    "speed, temperature, shape",
    [(100.0, 40.0, ()), (np.array([10.0, 300.0]), 40.0, (2,)),
     (np.array([[10.0], [100.0]]), np.array([20.0, 40.0, 60.0]), (2, 3))],
)  # fmt: skip
def test_every_nut_and_separation_keeps_the_inputs_shape(
    separation: str, nut: str, speed: Any, temperature: Any, shape: tuple[int, ...]
) -> None:
    preload = 0.0 if nut == "single" else 2000.0
    s = reference_screw().replace(nut=nut, preload=preload, ball_separation=separation)
    parts = _train(s, speed=speed, temperature=temperature, axial_load=500.0)
    assert all(np.shape(v) == shape for v in parts.values())
    assert np.all(np.isfinite(parts["ball_ball"])) and np.all(parts["ball_ball"] > 0.0)


@pytest.mark.slow
@pytest.mark.parametrize("separation", ["none", "cage"])
def test_model_train_term_is_the_mean_of_ball_by_ball_trains(separation: str) -> None:
    # The model's term (closed-form forces, the ball-ball coefficient at the mean force)
    # against 200 drawn trains of the reference screw at the fitted scatter, each solved
    # ball by ball (nonlinear creep law, tables of direct quadrature) and slid contact by
    # contact at its own force's coefficient. The standard error of the draws' mean is
    # about 2 %; the coefficient's curvature over the forces met adds well under 1 %.
    # Pass: four standard errors plus 1 %.
    from ballscrew.ball_train import orbital_sensitivity, train_by_ball
    from ballscrew.friction.complete import ball_ball_friction
    from ballscrew.kinematics import kinematics
    from ballscrew.rolling_losses import (
        limiting_traction_coefficient,
        mixed_friction_coefficient,
    )
    from ballscrew.state import operating_state

    screw = reference_screw().replace(ball_separation=separation)
    oil = get_lubricant(OIL)
    omega = 100.0 * RPM
    st = operating_state(screw, oil, speed=omega, temperature=40.0, hertz_method="exact")
    unit = kinematics(screw, 1.0)
    spin = {"screw": abs(float(unit.spin_screw)), "nut": abs(float(unit.spin_nut))}
    contacts = []
    for c in st.contacts[:2]:
        limit = limiting_traction_coefficient(
            oil.limiting_shear_stress, oil.limiting_shear_coefficient, 2.0 / 3.0 * c.hertz.p_max
        )
        mu = float(mixed_friction_coefficient(c.asperity_share, 0.1, limit))
        contacts.append(
            (mu * float(c.load), spin[c.side] * float(c.hertz.a), 1.0 / float(c.hertz.ellipticity))
        )
    centre = float(unit.orbital_speed) * 0.5 * screw.pitch_diameter / math.cos(screw.lead_angle)
    k = orbital_sensitivity(screw.ball_diameter, screw.pitch_diameter, screw.contact_angle)
    spread = centre * k * CONTACT_ANGLE_SCATTER
    sliding = float(unit.ball_speed) * screw.ball_diameter
    n = screw.balls_per_circuit
    rng = np.random.default_rng(5)
    per_train = []
    for _ in range(200):
        sol = train_by_ball(spread * rng.standard_normal(n), (contacts[0], contacts[1]))
        if separation == "cage":
            force, speed = np.abs(sol.traction), 0.5 * sliding
        else:
            force, speed = sol.compression, sliding
        mu_bb = ball_ball_friction(st, st.contacts[0], force, 0.1, oil.limiting_shear_stress,
                                   oil.limiting_shear_coefficient, asperity_b=1.42,
                                   asperity_c=0.8)  # fmt: skip
        per_train.append(float(np.sum(mu_bb * force)) * speed + sol.creep_power)
    trains = 2 * screw.circuits  # both halves of the double nut, unloaded: equal
    reference = trains * np.mean(per_train)
    error = trains * np.std(per_train) / math.sqrt(len(per_train))
    model = float(_train(screw, speed=omega)["ball_ball"])
    assert model == pytest.approx(reference, abs=4.0 * error + 0.01 * reference)


def test_touching_balls_add_the_ball_ball_sliding_of_the_push() -> None:
    # Over the spacer-ball nut's push, touching balls slide on each other under the push's
    # mean compression, F_r / 2 over the circuit's N balls, at omega_b D_w and the
    # ball-ball coefficient of the train's mean compression (the spacer nut's train has
    # the same balls and forces; only the sliding differs).
    from ballscrew.ball_train import creep_slope, expected_train, orbital_sensitivity
    from ballscrew.friction.complete import ball_ball_friction
    from ballscrew.kinematics import kinematics
    from ballscrew.materials import STEEL_DENSITY
    from ballscrew.rolling_losses import (
        limiting_traction_coefficient,
        mixed_friction_coefficient,
    )
    from ballscrew.state import operating_state

    s = reference_screw()
    oil = get_lubricant(OIL)
    omega = 3000.0 * RPM
    full = float(_train(s, speed=omega)["recirculation"])
    spacer = float(_train(s.replace(ball_separation="spacer-balls"), speed=omega)["recirculation"])
    st = operating_state(s, oil, speed=omega, temperature=40.0, hertz_method="exact")
    unit = kinematics(s, 1.0)
    spin = {"screw": abs(float(unit.spin_screw)), "nut": abs(float(unit.spin_nut))}
    coefficients = []
    for c in st.contacts[:2]:
        limit = limiting_traction_coefficient(
            oil.limiting_shear_stress, oil.limiting_shear_coefficient, 2.0 / 3.0 * c.hertz.p_max
        )
        mu = float(mixed_friction_coefficient(c.asperity_share, 0.1, limit))
        slope = float(creep_slope(1.0 / float(c.hertz.ellipticity)))
        coefficients.append(mu * float(c.load) * slope / (spin[c.side] * float(c.hertz.a)))
    c_s, c_n = coefficients
    v_c = float(unit.orbital_speed) * s.pitch_diameter / 2.0 / math.cos(s.lead_angle)
    k = orbital_sensitivity(s.ball_diameter, s.pitch_diameter, s.contact_angle)
    n = s.balls_per_circuit
    mean = expected_train(4.0 * c_s * c_n / (c_s + c_n), v_c * k * CONTACT_ANGLE_SCATTER, n)
    mu_bb = float(ball_ball_friction(st, st.contacts[0], mean.compression, 0.1,
                                     oil.limiting_shear_stress, oil.limiting_shear_coefficient,
                                     asperity_b=1.42, asperity_c=0.8))  # fmt: skip
    mass = STEEL_DENSITY * math.pi / 6.0 * s.ball_diameter**3
    push = 0.1 * mass * (v_c * omega) ** 2 * 2.0 * math.pi / s.ball_diameter  # F_r [N]
    sliding = float(unit.ball_speed) * omega * s.ball_diameter
    extra = 2 * s.circuits * mu_bb * 0.5 * push * n * sliding / omega
    assert full - spacer == pytest.approx(extra, rel=1e-9)
