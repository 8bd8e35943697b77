"""Tests of the friction chain: friction_torque, the registry and what all models share."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import ballscrew
from ballscrew import BallScrewInputError, friction_torque, lubricants, models, reference_screw
from shared import ALL_MODELS, BUILT_IN_MODELS, PAO

OIL = PAO
ALL = ALL_MODELS
SPEEDS = np.array([0.0, 1.0, 10.0, 100.0, 300.0])


def test_registry_lists_the_six_models_with_references() -> None:
    shipped = [m.name for m in models() if m.function.__module__.startswith("ballscrew.")]
    assert sorted(shipped) == list(BUILT_IN_MODELS)
    for spec in models():
        assert spec.reference and spec.validity and spec.title
        assert callable(spec.function)


def test_unknown_model_and_parameter_list_the_valid_ones() -> None:
    with pytest.raises(BallScrewInputError) as info:
        friction_torque(reference_screw(), OIL, speed=1.0, temperature=40.0, model="coulomb")
    for name in ALL:
        assert name in str(info.value)
    with pytest.raises(BallScrewInputError) as info:
        friction_torque(
            reference_screw(), OIL, speed=1.0, temperature=40.0, model="catalog", mu=0.1
        )
    assert "friction_coefficient" in str(info.value) and "mu" in str(info.value)


@pytest.mark.parametrize("model", ALL)
def test_components_finite_nonnegative_and_shaped(model: str) -> None:
    r = friction_torque(
        reference_screw(),
        OIL,
        speed=SPEEDS[:, None, None],
        temperature=np.array([20.0, 45.0])[None, :, None],
        axial_load=np.array([-2000.0, 0.0, 1000.0, 9000.0])[None, None, :],
        model=model,
    )
    assert r.total.shape == (5, 2, 4)
    for name, value in r.components.items():
        assert value.shape == (5, 2, 4), name
        assert np.all(np.isfinite(value)) and np.all(value >= 0.0), name
    assert np.all(r.total >= 0.0)


@pytest.mark.parametrize("model", ALL)
def test_torque_rises_with_preload(model: str) -> None:
    screw = reference_screw()
    torques = [
        float(
            friction_torque(
                screw.replace(preload=fpr), OIL, speed=50.0, temperature=40.0, model=model
            ).total
        )
        for fpr in (500.0, 1000.0, 2000.0, 4000.0)
    ]
    assert all(b > a for a, b in itertools.pairwise(torques)), torques


@pytest.mark.parametrize(
    ("model", "component"),
    [("harris-simplified", "lubricant"), ("olaru", "rolling"), ("harris-full", "lubricant")],
)
def test_fluid_part_falls_with_temperature(model: str, component: str) -> None:
    r = friction_torque(
        reference_screw(), OIL, speed=200.0, temperature=[20.0, 30.0, 40.0, 45.0], model=model
    )
    fluid = r.components[component]
    assert np.all(np.diff(fluid) < 0), fluid


@pytest.mark.parametrize("model", ALL)
def test_scalar_list_array_and_chunks_agree(model: str) -> None:
    speeds = [5.0, 50.0, 150.0]
    as_list = friction_torque(reference_screw(), OIL, speed=speeds, temperature=30.0, model=model)
    scalars = [
        float(friction_torque(reference_screw(), OIL, speed=w, temperature=30.0, model=model).total)
        for w in speeds
    ]
    chunked = friction_torque(
        reference_screw(), OIL, speed=np.array(speeds), temperature=30.0, model=model, chunk_size=2
    )
    np.testing.assert_allclose(as_list.total, scalars, rtol=1e-12)
    np.testing.assert_allclose(chunked.total, as_list.total, rtol=1e-12)


def test_efficiency_and_power() -> None:
    # Without preload the catalogue model's only loss is the load term, so the chain's
    # efficiency is the catalogues' closed form eta = tan(beta) / tan(beta + rho)
    # = (1 - mu tan(beta)) / (1 + mu / tan(beta)) (THK, "Driving torque"): the 40 x 10 mm
    # screw has tan(beta) = 10 / (40 pi) = 0.0795775, with mu = 0.003
    # eta = 0.99976127 / 1.03769908 = 0.963440.
    screw = reference_screw()
    loads = [0.0, 1000.0, 1e5]
    free = friction_torque(screw.replace(preload=0.0), OIL, speed=100.0, temperature=40.0,
                           axial_load=loads, model="catalog")  # fmt: skip
    assert free.efficiency[0] == 0.0  # no load, no useful output
    np.testing.assert_allclose(free.efficiency[1:], 0.963440, rtol=1e-6)
    # Power balance: the screw moves the 1 kN at 100 * 0.01 / 2 pi = 0.159155 m/s, 159.155 W
    # out, 159.155 / 0.963440 = 165.194 W in: 6.0394 W lost.
    assert free.power_loss[1] == pytest.approx(6.0394, rel=2e-5)
    # With the 2 kN preload the drag T_p = 0.05 / sqrt(tan beta) F_pr l / 2 pi = 0.564190 N m
    # (test_models) adds 56.4190 W at 100 rad/s: 62.4584 W lost, 159.155 / 221.613 = 0.718165.
    r = friction_torque(screw, OIL, speed=100.0, temperature=40.0, axial_load=loads[:2],
                        model="catalog")  # fmt: skip
    assert r.power_loss[1] == pytest.approx(62.4584, rel=2e-5)
    assert r.efficiency[1] == pytest.approx(0.718165, rel=2e-6)
    assert r.efficiency[0] == 0.0 and r.power_loss[0] == pytest.approx(56.4190, rel=2e-6)


def test_friction_torque_is_exported_at_top_level() -> None:
    assert ballscrew.friction_torque is friction_torque
    assert isinstance(
        friction_torque(reference_screw(), OIL, speed=1.0, temperature=40.0, model="catalog"),
        ballscrew.FrictionResult,
    )


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"speed": float("nan")}, "speed"),
        ({"temperature": "hot"}, "temperature"),
        ({"chunk_size": 0}, "chunk_size"),
        ({"axial_load": [1.0, float("inf")]}, "axial_load"),
    ],
)
def test_bad_operating_points(kwargs: dict[str, object], field: str) -> None:
    args: dict[str, object] = {"speed": 1.0, "temperature": 40.0}
    args.update(kwargs)
    with pytest.raises(BallScrewInputError, match=field):
        friction_torque(reference_screw(), OIL, **args)  # type: ignore[arg-type]


@pytest.mark.parametrize("model", ALL)
def test_outer_product_grid_equals_the_same_points_given_one_by_one(model: str) -> None:
    # The chain hands the models the operating points unexpanded (each layer
    # works on what it depends on); the numbers must be those of the same
    # points given as flat, fully expanded arrays, and those of the chunked
    # path, to rounding.
    import warnings

    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    w = np.array([0.0, -5.0, 30.0, 200.0])[:, None, None]
    t = np.array([20.0, 45.0])[None, :, None]
    fa = np.array([-3000.0, 0.0, 800.0, 9000.0])[None, None, :]
    flat = [x.ravel() for x in np.broadcast_arrays(w, t, fa)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        grid = friction_torque(screw, oil, speed=w, temperature=t, axial_load=fa, model=model)
        points = friction_torque(
            screw, oil, speed=flat[0], temperature=flat[1], axial_load=flat[2], model=model
        )
        chunked = friction_torque(
            screw, oil, speed=w, temperature=t, axial_load=fa, model=model, chunk_size=5
        )
    assert grid.total.shape == (4, 2, 4)
    for key in grid.components:
        np.testing.assert_allclose(
            grid.components[key].ravel(), points.components[key], rtol=1e-9, atol=1e-15
        )
        np.testing.assert_allclose(
            grid.components[key], chunked.components[key], rtol=1e-9, atol=1e-15
        )


def test_lubricant_by_name_and_wrong_objects_are_clear() -> None:
    by_name = friction_torque(reference_screw(), "PAO ISO VG 68", speed=10.0, temperature=40.0)
    by_object = friction_torque(reference_screw(), OIL, speed=10.0, temperature=40.0)
    assert OIL.name == "PAO ISO VG 68"
    assert float(by_name.total) == float(by_object.total)
    with pytest.raises(BallScrewInputError, match=r"lubricant = 'PAO 68'.*PAO ISO VG 68"):
        friction_torque(reference_screw(), "PAO 68", speed=10.0, temperature=40.0)
    with pytest.raises(BallScrewInputError, match="lubricant"):
        friction_torque(reference_screw(), 68, speed=10.0, temperature=40.0)  # type: ignore[arg-type]
    with pytest.raises(BallScrewInputError, match="screw"):
        friction_torque("40x10", OIL, speed=10.0, temperature=40.0)  # type: ignore[arg-type]


@pytest.mark.parametrize("model", ALL)
def test_below_absolute_zero_is_refused_by_every_model(model: str) -> None:
    with pytest.raises(BallScrewInputError, match="temperature = -300"):
        friction_torque(reference_screw(), OIL, speed=1.0, temperature=-300.0, model=model)


def test_the_chain_builds_the_contact_state_once_and_keeps_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The models that use a contact state get the chain's: with the models' own builder
    # disabled the chain still computes, and the result carries the state it used.
    from ballscrew import lubricants, reference_screw
    from ballscrew.friction import _common
    from ballscrew.state import operating_state

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("the model built a second state")

    monkeypatch.setattr(_common, "operating_state", refuse)
    oil = lubricants.get("mineral ISO VG 68")
    s = reference_screw()
    for model in ("complete", "olaru", "harris-simplified", "harris-full"):
        r = friction_torque(s, oil, speed=[10.0, 100.0], temperature=40.0, model=model)
        assert r.state is not None, model
    alone = operating_state(s, oil, speed=[10.0, 100.0], temperature=40.0, hertz_method="exact")
    np.testing.assert_allclose(r.state.contacts[0].film_parameter, alone.contacts[0].film_parameter)
    assert friction_torque(s, oil, speed=10.0, temperature=40.0, model="catalog").state is None
    chunked = friction_torque(s, oil, speed=[10.0, 100.0], temperature=40.0, chunk_size=1)
    assert chunked.state is None


@pytest.mark.parametrize("chunk", [None, 7])
def test_total_alone_is_the_sum_of_the_components(chunk: int | None) -> None:
    # components=False keeps the total only; it must equal the sum of the components a
    # full call gives, on a grid cut into chunks (7 does not divide its 5 x 3 x 4 points,
    # so chunks straddle rows of every axis) and in one piece. Same arithmetic, summed in
    # another order: equal to rounding (1e-12).
    w = SPEEDS[:, None, None]
    t = np.array([20.0, 40.0, 60.0])[None, :, None]
    fa = np.array([-3000.0, 0.0, 500.0, 4000.0])[None, None, :]
    full = friction_torque(reference_screw(), OIL, speed=w, temperature=t, axial_load=fa)
    alone = friction_torque(
        reference_screw(), OIL, speed=w, temperature=t, axial_load=fa,
        chunk_size=chunk, components=False,
    )  # fmt: skip
    assert alone.components == {}
    assert alone.total.shape == (5, 3, 4)
    summed = sum(full.components.values())
    np.testing.assert_allclose(alone.total, summed, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(alone.power_loss, summed * np.abs(w), rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(alone.efficiency, full.efficiency, rtol=1e-12)
