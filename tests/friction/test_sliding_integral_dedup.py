"""The sliding integral's de-duplication (issue 25): the same values as the row-wise unique.

``complete._unique_integral`` evaluates the spin-sliding integral once per distinct
(kappa, aspect) pair and interpolates it above ``DIRECT_INTEGRALS`` pairs. It used to count
the pairs with a row-wise ``np.unique(..., axis=0)``; it now counts them on 1-D keys.
The references here are independent of the new code: the direct quadrature rule at
every point, and the former row-wise algorithm written out below. Tolerances: the
direct rule agrees to a relative 1e-13 (the rule's matrix product may round a row's
last bit differently in a batch of another size); the spline path is the same spline
evaluated at the same points (1e-13 too, 1e-7 against the direct rule as in
``test_complete.py``); whole torques through ``friction_torque`` to 1e-13.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew.friction.complete as module
from ballscrew import friction_torque, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.errors import FloatArray
from shared import MINERAL

RTOL = 1e-13


def _row_wise_unique_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    """The former implementation: distinct pairs by a row-wise ``np.unique``."""
    kappa, aspect = np.broadcast_arrays(kappa, aspect)
    pairs = np.stack([kappa, aspect], axis=-1).reshape(-1, 2)
    unique, inverse = np.unique(pairs, axis=0, return_inverse=True)
    if len(unique) <= module.DIRECT_INTEGRALS:
        values = rl.spin_sliding_integral(unique[:, 0], unique[:, 1])
    else:
        values = module._interpolated_integral(unique[:, 0], unique[:, 1])
    result: FloatArray = values[inverse.reshape(-1)].reshape(kappa.shape)
    return result


def test_a_grid_of_few_pairs_is_the_direct_rule_at_every_point() -> None:
    # 3 contact sizes x 3 aspects, broadcast over a 2-D grid with repeats: 9 pairs.
    assert module.DIRECT_INTEGRALS >= 9
    kappa = np.repeat(np.linspace(0.1, 0.6, 3), 200 // 3 + 1)[:200, None] * np.ones((1, 3))
    aspect = np.array([0.15, 0.2, 0.25])[None, :] * np.ones((200, 1))
    got = module._unique_integral(kappa, aspect)
    assert got.shape == (200, 3)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=RTOL)
    np.testing.assert_allclose(got, _row_wise_unique_integral(kappa, aspect), rtol=RTOL)


def test_scattered_pairs_take_the_same_spline() -> None:
    rng = np.random.default_rng(11)
    kappa, aspect = rng.uniform(0.2, 0.5, 5000), rng.uniform(0.18, 0.22, 5000)
    got = module._unique_integral(kappa, aspect)
    np.testing.assert_allclose(got, _row_wise_unique_integral(kappa, aspect), rtol=RTOL)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=1e-7)


def test_few_values_of_each_but_many_pairs_take_the_spline() -> None:
    # 20 kappas x 20 aspects: each coordinate has few values, the pairs (400) are many.
    kappa, aspect = np.meshgrid(np.linspace(0.2, 0.5, 20), np.linspace(0.18, 0.22, 20))
    kappa, aspect = np.tile(kappa.ravel(), 3), np.tile(aspect.ravel(), 3)
    got = module._unique_integral(kappa, aspect)
    np.testing.assert_allclose(got, _row_wise_unique_integral(kappa, aspect), rtol=RTOL)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=1e-7)


def test_many_points_with_few_values_after_a_varied_prefix() -> None:
    # The first values are all distinct (the prefix test cannot decide), the rest repeat them.
    kappa = np.concatenate([np.linspace(0.2, 0.5, 200), np.full(5000, 0.3)])
    aspect = np.full_like(kappa, 0.2)
    got = module._unique_integral(kappa, aspect)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=RTOL)


@pytest.mark.parametrize(
    "kind",
    ["grid", "scattered", "chunked-grid", "chunked-scattered"],
)
def test_torques_equal_the_row_wise_algorithm(kind: str, monkeypatch: pytest.MonkeyPatch) -> None:
    # Whole torques (every component) on a grid, on scattered points, and on both cut into
    # chunks whose boundaries fall inside the grid's rows and change the spline's range.
    rng = np.random.default_rng(5)
    if kind.endswith("grid"):
        kwargs = {
            "speed": np.linspace(1.0, 300.0, 7)[:, None, None],
            "temperature": np.linspace(20.0, 45.0, 3)[None, :, None],
            "axial_load": np.linspace(-4000.0, 4000.0, 150)[None, None, :],
        }
    else:
        kwargs = {
            "speed": rng.uniform(1.0, 300.0, 3000),
            "temperature": rng.uniform(20.0, 45.0, 3000),
            "axial_load": rng.uniform(-4000.0, 4000.0, 3000),
        }
    chunk = 1000 if kind.startswith("chunked") else None
    screw = reference_screw()
    new = friction_torque(screw, MINERAL, chunk_size=chunk, **kwargs)  # type: ignore[arg-type]
    monkeypatch.setattr(module, "_unique_integral", _row_wise_unique_integral)
    old = friction_torque(screw, MINERAL, chunk_size=chunk, **kwargs)  # type: ignore[arg-type]
    assert new.total.shape == old.total.shape
    np.testing.assert_allclose(new.total, old.total, rtol=RTOL)
    for name, value in old.components.items():
        np.testing.assert_allclose(new.components[name], value, rtol=RTOL, atol=0.0)
    assert math.isfinite(float(np.max(new.total)))


@pytest.mark.parametrize("span", [(0.2, 0.5), (0.6, 1.2)])
def test_exactly_direct_integrals_pairs_are_integrated_directly(span: tuple[float, float]) -> None:
    # "Up to DIRECT_INTEGRALS distinct pairs" includes the bound: exactly that many distinct
    # contact sizes at one aspect, repeated so that the 1-D prefix looked at first holds all of
    # them too, are the direct rule at every point; one more pair takes the spline, as the
    # row-wise algorithm does. Past SMOOTH_KAPPA (0.6 to 1.2) the interpolation would err by
    # far more than 1e-13 (the spline's 1e-8), so only the direct rule passes there.
    n = module.DIRECT_INTEGRALS
    kappa = np.tile(np.linspace(*span, n), 5)
    assert kappa.size > 4 * n
    aspect = np.full_like(kappa, 0.2)
    got = module._unique_integral(kappa, aspect)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=RTOL)
    more = np.append(kappa, 0.5 * (span[0] + span[1]) + 1e-6)
    aspect = np.full_like(more, 0.2)
    got = module._unique_integral(more, aspect)
    np.testing.assert_allclose(got, _row_wise_unique_integral(more, aspect), rtol=RTOL)


def test_spline_of_one_aspect_matches_the_direct_rule() -> None:
    # Many distinct sizes at one aspect (a load sweep: b/a does not depend on the load) take
    # the spline along kappa alone: 1e-8 over one contact's range (test_complete.py), 1e-7.
    kappa = np.linspace(0.2, 0.5, 1000)
    aspect = np.full_like(kappa, 0.2)
    got = module._unique_integral(kappa, aspect)
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=1e-7)


@pytest.mark.parametrize("aspect", [0.05, 0.2, 1.0])
@pytest.mark.parametrize("span", [(0.0, 0.004), (0.0, 0.5), (0.2, 0.45)])
def test_chebyshev_along_kappa_is_the_direct_rule(aspect: float, span: tuple[float, float]) -> None:
    # One aspect and kappa <= SMOOTH_KAPPA: degree-10 Chebyshev interpolation over the span,
    # measured at 2e-13 of the rule (5e-13: the Clenshaw sum's rounding on top).
    kappa = np.linspace(*span, 3001)
    got = module._unique_integral(kappa, np.full_like(kappa, aspect))
    np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=5e-13)
    # Past SMOOTH_KAPPA the spline of 65 nodes (1e-4 over kappa to 2, test_complete.py).
    wide = np.linspace(0.0, 2.0, 3001)
    got = module._unique_integral(wide, np.full_like(wide, aspect))
    np.testing.assert_allclose(got, rl.spin_sliding_integral(wide, aspect), rtol=2e-4)
    assert np.max(np.abs(got / rl.spin_sliding_integral(wide, aspect) - 1.0)) > 1e-12


@pytest.mark.parametrize("spread", [1e-14, 0.2])
def test_one_kappa_over_many_aspects_is_the_direct_rule(spread: float) -> None:
    # More distinct aspects than DIRECT_INTEGRALS at a single kappa (within 1e-12 of each
    # other, taken as one aspect, or spread over 0.1 to 0.3): no kappa span to interpolate
    # over, so the integral is the direct rule at every point (1e-13, RTOL).
    aspect = 0.1 + spread * np.linspace(0.0, 1.0, 3 * module.DIRECT_INTEGRALS)
    for k in (0.3, 0.7):
        kappa = np.full_like(aspect, k)
        got = module._unique_integral(kappa, aspect)
        np.testing.assert_allclose(got, rl.spin_sliding_integral(kappa, aspect), rtol=RTOL)
