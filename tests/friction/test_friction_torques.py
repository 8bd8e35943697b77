"""Many screws in one call (issue 25): ``friction_torques`` is ``friction_torque`` per screw.

The reference is independent of the batch: one ``friction_torque`` call per
screw on the same points. The complete model takes the screws together, their
geometry as arrays in every layer (issue 39): the same equations on the same
numbers, but whole-array functions (numpy's sine, a secant iteration that stops
when every screw has converged, a Chebyshev series per row) may round the last
bit otherwise, so the torques are held to 1e-12 relative (what issue 39 asks);
the models that loop over the screws give the same bits. The efficiency is
recomputed with each screw's own lead.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrew, friction_torque, friction_torques, reference_screw
from ballscrew.errors import BallScrewInputError
from shared import MINERAL, PAO

RPM = math.pi / 30.0


def _screws() -> list[BallScrew]:
    base = reference_screw()
    return [
        base,
        base.replace(lead=0.020, preload=1500.0),
        base.replace(pitch_diameter=0.032, ball_diameter=3.175e-3, lead=0.005),
        base.replace(nut="single-4point", preload=400.0),
        base.replace(nut="single", preload=0.0, conformity_nut=0.53),
    ]


def _same(batch: np.ndarray, single: np.ndarray) -> None:
    np.testing.assert_allclose(batch, single, rtol=1e-12, atol=0.0)


@pytest.mark.parametrize("model", ["complete", "olaru", "catalog"])
def test_every_screw_at_every_point_is_its_own_call(model: str) -> None:
    speed = np.array([30.0, 300.0, 3000.0])[:, None] * RPM
    load = np.linspace(-3000.0, 3000.0, 7)[None, :]
    screws = _screws()
    batch = friction_torques(
        screws, MINERAL, speed=speed, temperature=35.0, axial_load=load, model=model, warn=False
    )
    assert batch.total.shape == (len(screws), 3, 7)
    assert batch.speed.shape == batch.axial_load.shape == (len(screws), 3, 7)
    for i, screw in enumerate(screws):
        one = friction_torque(
            screw, MINERAL, speed=speed, temperature=35.0, axial_load=load, model=model, warn=False
        )
        _same(batch.total[i], one.total)
        for name, value in one.components.items():
            _same(batch.components[name][i], value)
        _same(batch.efficiency[i], one.efficiency)
        _same(batch.power_loss[i], one.power_loss)
    assert set(batch.components) == set(one.components)


def test_a_component_one_screw_lacks_is_zero_there() -> None:
    # Only the 4-point nut has the 4-point spin; the double nut's entry is 0, not garbage.
    screws = [reference_screw(), reference_screw().replace(nut="single-4point", preload=400.0)]
    batch = friction_torques(screws, MINERAL, speed=100.0, temperature=40.0, warn=False)
    four = batch.components["four_point"]
    assert four[0] == 0.0 and four[1] > 0.0
    np.testing.assert_allclose(sum(batch.components.values()), batch.total, rtol=1e-14, atol=0.0)


def test_paired_points_give_each_screw_its_own() -> None:
    # A Monte Carlo sample: screw i at speed i and load i; the temperature shared by all.
    rng = np.random.default_rng(8)
    base = reference_screw()
    screws = [base.replace(preload=p) for p in rng.uniform(1000.0, 3000.0, 6)]
    speed, load = rng.uniform(10.0, 300.0, 6), rng.uniform(-2000.0, 2000.0, 6)
    batch = friction_torques(
        screws, PAO, speed=speed, temperature=40.0, axial_load=load, paired=True, warn=False
    )
    assert batch.total.shape == (6,)
    for i, screw in enumerate(screws):
        one = friction_torque(screw, PAO, speed=speed[i], temperature=40.0,
                              axial_load=load[i], warn=False)  # fmt: skip
        _same(batch.total[i], one.total)
        _same(batch.efficiency[i], one.efficiency)
    # Own speeds (6, 1) against loads shared by all (1, 4): a (6, 4) result.
    grid = friction_torques(
        screws, PAO, speed=speed[:, None], temperature=40.0,
        axial_load=np.array([[-1e3, 0.0, 1e3, 2e3]]), paired=True, warn=False,
    )  # fmt: skip
    assert grid.total.shape == (6, 4)
    one = friction_torque(screws[2], PAO, speed=speed[2], temperature=40.0,
                          axial_load=[-1e3, 0.0, 1e3, 2e3], warn=False)  # fmt: skip
    _same(grid.total[2], one.total)


def test_paired_points_shared_by_all_screws_give_one_value_per_screw() -> None:
    # Every input a single value with paired=True: each screw at that one point.
    screws = _screws()[:3]
    batch = friction_torques(screws, PAO, speed=50.0, temperature=40.0, paired=True, warn=False)
    assert batch.total.shape == (3,)
    for i, screw in enumerate(screws):
        one = friction_torque(screw, PAO, speed=50.0, temperature=40.0, warn=False)
        _same(batch.total[i], one.total)
    # A first axis of 1 shared by all, against the screws' own speeds: (3, 2).
    own = friction_torques(screws, PAO, speed=[[10.0], [20.0], [30.0]],
                           temperature=[[30.0, 50.0]], paired=True, warn=False)  # fmt: skip
    assert own.total.shape == (3, 2)
    one = friction_torque(screws[1], PAO, speed=20.0, temperature=[30.0, 50.0], warn=False)
    _same(own.total[1], one.total)


def test_paired_points_of_the_wrong_length_are_refused_by_name() -> None:
    with pytest.raises(BallScrewInputError) as info:
        friction_torques(
            _screws(), PAO, speed=[10.0, 20.0], temperature=40.0, paired=True, warn=False
        )
    assert info.value.field == "speed"
    assert "first axis of length 5" in str(info.value)


def test_bad_screw_lists_are_refused_by_index() -> None:
    with pytest.raises(BallScrewInputError) as info:
        friction_torques([], PAO, speed=10.0, temperature=40.0)
    assert info.value.field == "screws"
    with pytest.raises(BallScrewInputError) as info:
        friction_torques([reference_screw(), "40x10"], PAO, speed=10.0, temperature=40.0)  # type: ignore[list-item]
    assert info.value.field == "screws[1]"
    # One screw alone is a batch of one.
    alone = friction_torques(reference_screw(), PAO, speed=10.0, temperature=40.0, warn=False)  # type: ignore[arg-type]
    assert alone.total.shape == (1,)


def test_a_point_one_screw_cannot_solve_names_the_screw() -> None:
    # Past the viscoelastic model's equations (see test_absurd_inputs.py) for the second
    # screw only: its index leads the field.
    screws = [reference_screw(), reference_screw().replace(preload=0.0, nut="single")]
    with pytest.raises(BallScrewInputError) as info:
        friction_torques(screws, PAO, speed=[100.0, 9.99e4], temperature=40.0,
                         model="viscoelastic", warn=False)  # fmt: skip
    assert info.value.field.startswith("screws[")
    assert "operating point" in info.value.field


def test_warnings_keep_each_quantitys_worst_screw() -> None:
    # Each screw's own call warns of its own extremes; the batch keeps, per quantity, the
    # issue of the screw farthest outside the range.
    screws = _screws()
    kw = {"speed": 6000.0 * RPM, "temperature": 10.0, "axial_load": 20000.0, "warn": False}
    batch = friction_torques(screws, MINERAL, **kw)  # type: ignore[arg-type]
    singles = [friction_torque(s, MINERAL, **kw).warnings for s in screws]  # type: ignore[arg-type]
    expected: dict[tuple[str, str], float] = {}
    for issues in singles:
        for issue in issues:
            key = (issue.quantity, issue.model)
            expected[key] = max(expected.get(key, -math.inf), issue.excess)
    assert expected  # the points leave some range
    got = {(i.quantity, i.model): i.excess for i in batch.warnings}
    assert got == expected


def test_paired_points_shared_by_all_screws_give_one_entry_per_screw() -> None:
    # Paired, with no input carrying the screw axis (scalars, or a first axis of 1, "shared
    # by all"): every screw at the same point, one entry each, as its own call gives.
    screws = _screws()
    for speed in (100.0, [100.0]):
        batch = friction_torques(
            screws, PAO, speed=speed, temperature=40.0, axial_load=500.0, paired=True, warn=False
        )
        assert batch.total.shape == batch.efficiency.shape == (len(screws),)
        for i, screw in enumerate(screws):
            one = friction_torque(screw, PAO, speed=100.0, temperature=40.0, axial_load=500.0,
                                  warn=False)  # fmt: skip
            _same(batch.total[i], one.total)
            _same(batch.efficiency[i], one.efficiency)
    # Shared along the first axis, own points along the second: (screws, 3).
    grid = friction_torques(
        screws, PAO, speed=[[10.0, 100.0, 300.0]], temperature=40.0, paired=True, warn=False
    )
    assert grid.total.shape == (len(screws), 3)
    one = friction_torque(screws[3], PAO, speed=[10.0, 100.0, 300.0], temperature=40.0,
                          warn=False)  # fmt: skip
    np.testing.assert_allclose(grid.total[3], one.total, rtol=1e-12, atol=0.0)


def test_without_an_axial_load_there_is_none() -> None:
    # The axial load defaults to 0 N, as for one screw: no useful work, efficiency 0, and
    # the torque of the unloaded (preloaded) nut.
    batch = friction_torques(_screws(), PAO, speed=[10.0, 100.0], temperature=40.0, warn=False)
    assert np.all(batch.axial_load == 0.0) and np.all(batch.efficiency == 0.0)
    one = friction_torque(_screws()[1], PAO, speed=[10.0, 100.0], temperature=40.0,
                          axial_load=0.0, warn=False)  # fmt: skip
    _same(batch.total[1], one.total)


def test_chunks_of_one_point_give_the_same_torques_and_none_is_refused() -> None:
    # A chunk bounds the points evaluated at once, down to one; the torques do not depend
    # on it. Not to the bit: the helix's share is solved by the plain-Python kernel for a
    # few points and by the numpy path for more, equal to 1e-12 (test_helix_kernel.py).
    kw = {"speed": [10.0, 100.0, 300.0, 600.0, 900.0], "temperature": 40.0, "warn": False}
    whole = friction_torques(_screws(), PAO, **kw)  # type: ignore[arg-type]
    single = friction_torques(_screws(), PAO, chunk_size=1, **kw)  # type: ignore[arg-type]
    np.testing.assert_allclose(single.total, whole.total, rtol=1e-12, atol=0.0)
    for bad in (0, -1, 2.5, True):
        with pytest.raises(BallScrewInputError) as info:
            friction_torques(_screws(), PAO, chunk_size=bad, **kw)  # type: ignore[arg-type]
        assert info.value.field == "chunk_size"


def test_a_batch_of_many_points_in_all_loads_the_compiled_loop(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Each screw's call is below JIT_LOAD_POINTS, the batch is not: the batch loads the
    # helix's compiled loop once, so that every screw's call takes it.
    pytest.importorskip("numba")
    from ballscrew import _helix_kernel, helix

    monkeypatch.setenv("BALLSCREW_JIT", "1")
    _helix_kernel._compiled.cache_clear()
    per_screw = helix.JIT_LOAD_POINTS // 4 + 1
    friction_torques(_screws()[:3], PAO, speed=np.linspace(1.0, 300.0, per_screw),
                     temperature=40.0, components=False, warn=False)  # fmt: skip
    assert _helix_kernel._compiled.cache_info().currsize == 0  # 3 x per_screw: below it
    friction_torques(_screws()[:4], PAO, speed=np.linspace(1.0, 300.0, per_screw),
                     temperature=40.0, components=False, warn=False)  # fmt: skip
    assert _helix_kernel.enabled(load=False)


def test_inputs_typed_as_text_or_a_bad_parameter_are_refused_by_their_own_name() -> None:
    # The API takes SI numbers: a speed typed with its unit is refused with the way to read
    # it; the message's recipe is checked to give the speed meant (3000 rpm in rad/s).
    from ballscrew.io.units import to_si

    with pytest.raises(BallScrewInputError) as info:
        friction_torques(_screws()[:2], PAO, speed="3000 1/min", temperature=40.0)
    assert info.value.field == "speed" and "ballscrew.io.units.to_si" in str(info.value)
    assert to_si("speed", "3000 1/min", "rad/s") == pytest.approx(3000 * RPM, rel=1e-12)
    # A model parameter is no screw's doing: named alone, not as screws[0].
    with pytest.raises(BallScrewInputError) as info:
        friction_torques(_screws()[:2], PAO, speed=10.0, temperature=40.0,
                         ball_train_constant=-1.0)  # fmt: skip
    assert info.value.field == "ball_train_constant"
