"""The helix's compiled slip-share kernel gives the numpy path's numbers (issue 25).

The kernel (:mod:`ballscrew._helix_kernel`) runs the same bracketed Newton
iteration on the same tables as :func:`ballscrew.helix.transverse_slip_loss`'s
numpy path, one point at a time. Identical steps give identical shares up to
the order in which sums are rounded: 1e-12 is a thousand times the rounding of
the sums involved and a thousand times below the solver's own tolerance
(1e-9), so a kernel that stopped one step early or took another step would
fail it.
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import _helix_kernel, friction_torque, helix, reference_screw
from ballscrew.helix import SlipContact, transverse_slip_loss
from shared import MINERAL

ROUNDING = 1e-12


def _random_contacts(n: int, four_point: bool, seed: int = 4) -> list[SlipContact]:
    """Contacts of ``n`` balls over every regime: light to heavy, some unloaded."""
    rng = np.random.default_rng(seed)
    contacts = []
    for side, aspect in (("screw", 0.19), ("nut", 0.22)) * (2 if four_point else 1):
        load = rng.uniform(0.0, 400.0, n) * (rng.uniform(size=n) > 0.05)  # 5 % unloaded
        semi = 0.26e-3 * (load / 30.0) ** (1 / 3)
        mu = rng.uniform(0.03, 0.12, n)
        spin = rng.uniform(0.2, 0.5)
        contacts.append(SlipContact(side, mu, load, semi, aspect, spin))
    return contacts


def _numpy_path(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("BALLSCREW_JIT", "0")


@pytest.mark.parametrize("four_point", [False, True])
@pytest.mark.parametrize("slip", [0.0, 2e-5, 2.5e-4, 3e-3])
def test_python_kernel_takes_the_numpy_paths_steps(
    monkeypatch: pytest.MonkeyPatch, four_point: bool, slip: float
) -> None:
    # The kernel's source run as plain Python (no numba needed) on 60 balls.
    contacts = _random_contacts(60, four_point)
    _numpy_path(monkeypatch)
    expected = transverse_slip_loss(contacts, slip)
    args = helix._kernel_inputs(contacts, slip)
    x, power, force = np.empty(60), np.empty(60), np.empty(60)
    _helix_kernel.shares(*args, helix.SHARE_TOLERANCE, helix.MAX_ITERATIONS, x, power, force)
    np.testing.assert_allclose(x, expected.screw_share, rtol=0.0, atol=ROUNDING)
    np.testing.assert_allclose(power, expected.power, rtol=ROUNDING, atol=0.0)
    np.testing.assert_allclose(force, expected.force, rtol=ROUNDING, atol=0.0)
    assert 0.0 <= x.min() and x.max() <= 1.0
    if slip > 0.0:  # a real balance somewhere, not only the unloaded ends
        assert np.any((x > 0.01) & (x < 0.99))


def _python_kernel(contacts: list[SlipContact], slip: float, evaluations: int) -> np.ndarray:
    """The kernel's shares as plain Python, stopped after ``evaluations`` residuals at most."""
    n = np.size(contacts[0].load)
    x, power, force = np.empty(n), np.empty(n), np.empty(n)
    args = helix._kernel_inputs(contacts, slip)
    _helix_kernel.shares(*args, helix.SHARE_TOLERANCE, evaluations, x, power, force)
    return x


@pytest.mark.parametrize("evaluations", [0, 1, 2, 3, 5])
@pytest.mark.parametrize("four_point", [False, True])
def test_python_kernel_takes_the_numpy_paths_steps_one_at_a_time(
    monkeypatch: pytest.MonkeyPatch, four_point: bool, evaluations: int
) -> None:
    # Converged, a kernel that started elsewhere or stepped otherwise would still land on
    # the same root. Stopped after a few residual evaluations, both paths return their last
    # trial: with none, the start (where the straight line between the residuals at the
    # ends of [0, 1] crosses zero); then each Newton step or bisection. The same steps give
    # the same trials to rounding at every stage: 1e-12, as above.
    contacts = _random_contacts(60, four_point)
    _numpy_path(monkeypatch)
    monkeypatch.setattr(helix, "MAX_ITERATIONS", evaluations)
    for slip in (2e-5, 2.5e-4, 3e-3):
        expected = transverse_slip_loss(contacts, slip)
        x = _python_kernel(contacts, slip, evaluations)
        np.testing.assert_allclose(x, expected.screw_share, rtol=0.0, atol=ROUNDING)


@pytest.mark.parametrize("spins", [(1e-10, 0.3), (0.3, 1e-10), (1e-6, 1e-14), (1e-20, 1e-20)])
def test_python_kernel_takes_the_numpy_paths_steps_towards_coulomb_sliding(
    monkeypatch: pytest.MonkeyPatch, spins: tuple[float, float]
) -> None:
    # A spin far below the slip (slip ratios up to 1e20): the residual turns into a step,
    # which both paths bisect until the bracket is narrower than the tolerance, and the
    # weaker contact's share lies within 1e-9 of 0 or 1, where a Newton step can fall
    # below the rounding of the share. Both stopping rules, and the step that rounds away,
    # must be the numpy path's: the same shares to rounding (1e-12).
    rng = np.random.default_rng(9)
    n = 60
    contacts = []
    for side, spin in (("screw", spins[0]), ("nut", spins[1])):
        load = rng.uniform(1.0, 400.0, n)
        semi = 0.26e-3 * (load / 30.0) ** (1 / 3)
        contacts.append(SlipContact(side, rng.uniform(0.03, 0.12, n), load, semi, 0.2, spin))
    _numpy_path(monkeypatch)
    expected = transverse_slip_loss(contacts, 2.5e-4)
    x = _python_kernel(contacts, 2.5e-4, helix.MAX_ITERATIONS)
    np.testing.assert_allclose(x, expected.screw_share, rtol=0.0, atol=ROUNDING)
    assert min(x.min(), 1.0 - x.max()) < 1e-8  # the Coulomb end reached


@pytest.mark.parametrize("four_point", [False, True])
def test_compiled_kernel_equals_the_numpy_path_on_10000_balls(
    monkeypatch: pytest.MonkeyPatch, four_point: bool
) -> None:
    pytest.importorskip("numba")
    contacts = _random_contacts(10_000, four_point, seed=5)
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    assert _helix_kernel.enabled()
    fast = transverse_slip_loss(contacts, 2.5e-4)
    _numpy_path(monkeypatch)
    slow = transverse_slip_loss(contacts, 2.5e-4)
    np.testing.assert_allclose(fast.screw_share, slow.screw_share, rtol=0.0, atol=ROUNDING)
    np.testing.assert_allclose(fast.power, slow.power, rtol=ROUNDING, atol=0.0)
    np.testing.assert_allclose(fast.force, slow.force, rtol=ROUNDING, atol=0.0)


def test_kernel_is_used_from_its_threshold_and_switched_off_by_the_environment(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pytest.importorskip("numba")
    calls: list[tuple[int, bool]] = []
    real = _helix_kernel.run

    def spy(*args: object, compiled: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        calls.append((np.shape(args[0])[1], compiled))  # type: ignore[arg-type]
        return real(*args, compiled=compiled)  # type: ignore[arg-type]

    monkeypatch.setattr(_helix_kernel, "run", spy)
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    n, few = helix.JIT_MIN_POINTS, helix.PYTHON_MAX_POINTS
    # Not loaded yet: a call below JIT_LOAD_POINTS takes numpy's path and loads nothing;
    # one on JIT_LOAD_POINTS loads the kernel, which from then on serves n points.
    _helix_kernel._compiled.cache_clear()
    transverse_slip_loss(_random_contacts(helix.JIT_LOAD_POINTS - 1, False), 2.5e-4)
    assert calls == [] and _helix_kernel._compiled.cache_info().currsize == 0
    transverse_slip_loss(_random_contacts(helix.JIT_LOAD_POINTS, False), 2.5e-4)
    assert calls == [(helix.JIT_LOAD_POINTS, True)]
    calls.clear()
    transverse_slip_loss(_random_contacts(n - 1, False), 2.5e-4)
    transverse_slip_loss(_random_contacts(few + 1, False), 2.5e-4)
    assert calls == []  # the numpy path in between
    transverse_slip_loss(_random_contacts(n, False), 2.5e-4)
    transverse_slip_loss(_random_contacts(few, False), 2.5e-4)
    assert calls == [(n, True), (few, False)]  # compiled from n on, plain Python up to few
    for off in ("0", "off", "False"):
        monkeypatch.setenv("BALLSCREW_JIT", off)
        transverse_slip_loss(_random_contacts(n, False), 2.5e-4)
    transverse_slip_loss(_random_contacts(few, False), 2.5e-4)  # needs no compiler
    assert calls == [(n, True), (few, False), (few, False)]


@pytest.mark.parametrize("nut", ["double", "single-4point"])
def test_model_with_the_kernel_equals_the_model_without(
    monkeypatch: pytest.MonkeyPatch, nut: str
) -> None:
    # The done-when of issue 25: the same results on 10 000 scattered points.
    pytest.importorskip("numba")
    screw = reference_screw()
    if nut != "double":
        screw = screw.replace(nut=nut, preload=300.0)
    rng = np.random.default_rng(6)
    n = 10_000
    points = {
        "speed": rng.uniform(0.5, 320.0, n),
        "temperature": rng.uniform(20.0, 60.0, n),
        "axial_load": rng.uniform(-4000.0, 4000.0, n),
    }
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    assert helix.load_kernel()  # loaded, so that 10 000 points take it
    calls: list[int] = []
    real = _helix_kernel.run

    def spy(*args: object, compiled: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        calls.append(int(compiled))
        return real(*args, compiled=compiled)  # type: ignore[arg-type]

    monkeypatch.setattr(_helix_kernel, "run", spy)
    fast = friction_torque(screw, MINERAL, **points, warn=False)
    assert calls and all(calls)  # every ball family through the compiled loop
    _numpy_path(monkeypatch)
    slow = friction_torque(screw, MINERAL, **points, warn=False)
    assert fast.components["helix_slip"].max() > 0.0
    for name, value in slow.components.items():
        np.testing.assert_allclose(fast.components[name], value, rtol=ROUNDING, atol=0.0)


def test_without_numba_many_points_take_the_numpy_path(monkeypatch: pytest.MonkeyPatch) -> None:
    # The fast extra is optional: without numba the same call runs, on numpy.
    import sys

    contacts = _random_contacts(2 * helix.JIT_MIN_POINTS, False)
    monkeypatch.setenv("BALLSCREW_JIT", "0")
    expected = transverse_slip_loss(contacts, 2.5e-4)
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    monkeypatch.setitem(sys.modules, "numba", None)  # an import of it now fails
    _helix_kernel._compiled.cache_clear()
    try:
        assert not _helix_kernel.enabled()
        got = transverse_slip_loss(contacts, 2.5e-4)
    finally:
        _helix_kernel._compiled.cache_clear()
    np.testing.assert_array_equal(got.screw_share, expected.screw_share)
    np.testing.assert_array_equal(got.power, expected.power)


def test_load_kernel_says_whether_the_compiled_loop_is_used(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pytest.importorskip("numba")
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    _helix_kernel._compiled.cache_clear()
    assert not _helix_kernel.enabled(load=False)  # not loaded: not used below the load size
    assert helix.load_kernel() is True
    assert _helix_kernel.enabled(load=False)
    monkeypatch.setenv("BALLSCREW_JIT", "0")
    assert helix.load_kernel() is False


def test_a_kernel_scope_serves_its_block_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("numba")
    calls: list[int] = []
    real = _helix_kernel.run

    def spy(*args: object, compiled: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        calls.append(np.shape(args[0])[1])  # type: ignore[arg-type]
        return real(*args, compiled=compiled)  # type: ignore[arg-type]

    monkeypatch.setattr(_helix_kernel, "run", spy)
    monkeypatch.setenv("BALLSCREW_JIT", "1")
    monkeypatch.setattr(_helix_kernel, "_FOR_ALL", [False])
    n = helix.JIT_MIN_POINTS
    contacts = _random_contacts(n, False)
    _helix_kernel._compiled.cache_clear()
    before = transverse_slip_loss(contacts, 2.5e-4)  # a process without the kernel
    with helix.kernel_scope():
        transverse_slip_loss(contacts, 2.5e-4)
    assert calls == [n]  # inside: the kernel, loaded for the block, below JIT_LOAD_POINTS
    after = transverse_slip_loss(contacts, 2.5e-4)
    # outside: the numpy path again, its numbers bit for bit those before the block
    assert calls == [n]
    assert np.array_equal(after.power, before.power)
