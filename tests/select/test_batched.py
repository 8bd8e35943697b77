"""The batched selection equals the one-by-one path (issue 51).

``run_select`` makes its candidates' friction calls many screws at a time and answers
repeated calls from memory (``chain.fill_friction_memo``, ``chain.friction_memo``);
``batched=False`` makes every candidate's calls by itself. The pool mixes catalogue rows
and ISO sizes, nut kinds and preload classes, candidates refused by an input error,
candidates a row fails, and exact ties (two motor rows alike in all but their name), at
a confidence where none passes (undecided) and one where some do. Not timed: the time
is in benchmarks/bench_select.py.
"""

from __future__ import annotations

import itertools
import math
import warnings

import numpy as np
import pytest

from ballscrew import lubricants, reference_screw
from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.axis.setup import axis_setup
from ballscrew.axis.thermal import steady_temperature
from ballscrew.chain import fill_friction_memo, friction_memo, friction_torque
from ballscrew.io.case import load_case
from ballscrew.io.motors import MotorRow
from ballscrew.select import candidates, run_select
from ballscrew.select.choose import _prepared
from shared import ROOT

pytest.importorskip("pymoo")

CASE = ROOT / "examples" / "vertical_32x5.toml"
MOVE = ("stroke=200 mm, feed=10 m/min, acceleration=2 m/s^2, force=1 kN, force_from=50 mm, "
        "force_to=150 mm, dwell=1 s")  # fmt: skip
MOTORS = (
    MotorRow("A 1.5 kW", 6.0, 18.0, 314.159, 9e-4),
    MotorRow("B 1.5 kW, A's twin", 6.0, 18.0, 314.159, 9e-4),  # ties with A on every figure
    MotorRow("C 0.1 kW", 0.3, 0.9, 314.159, 0.5e-4),  # too weak: its motor rows fail
)
RTOL = 1e-12
"""The batched friction calls equal a screw's own within 1e-12 relative (friction_torques);
the figures are sums and ratios of them."""


@pytest.fixture(scope="module")
def setting():  # type: ignore[no-untyped-def]
    case = load_case(CASE)
    move = parse_move(MOVE)
    pool = candidates(case.text, diameter=(0.025, 0.032), lead=(0.01, 0.02),
                      oils=["PAO ISO VG 68"], sources=("catalogue", "iso"), motors=MOTORS,
                      default_oil=case.lubricant.name)  # fmt: skip
    return case, move, profile_from_move(move, 1), pool


def _select(setting, confidence: float, batched: bool):  # type: ignore[no-untyped-def]
    case, move, profile, pool = setting
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return run_select(case, profile, objectives=["energy", "life", "motor_margin"],
                          move=move, pool=pool, confidence=confidence,
                          batched=batched)  # fmt: skip


def _same(a: float, b: float) -> bool:
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= RTOL * max(abs(a), abs(b))


@pytest.mark.parametrize("confidence", [0.95, 0.6])
def test_the_batched_selection_is_the_one_by_one_selection(setting, confidence):  # type: ignore[no-untyped-def]
    batched, alone = _select(setting, confidence, True), _select(setting, confidence, False)
    # The pool has what the test is about: input errors, failing rows, exact ties.
    evaluated = alone.evaluated
    assert any(math.isnan(e.figures["energy_J"]) for e in evaluated)  # refused by an error
    assert any(e.failing for e in evaluated)
    assert any(e.nominal for e in evaluated)
    twins = [(a, b) for a, b in itertools.pairwise(evaluated)
             if a.candidate.motor and a.candidate.motor.name == "A 1.5 kW"
             and b.candidate.motor and b.candidate.motor.name.startswith("B")]  # fmt: skip
    assert twins and all(a.figures["energy_J"] == b.figures["energy_J"] or math.isnan(
        a.figures["energy_J"]) for a, b in twins)  # fmt: skip
    assert batched.undecided == alone.undecided == (confidence == 0.95)
    assert [e.name for e in batched.evaluated] == [e.name for e in alone.evaluated]
    assert batched.front == alone.front
    assert batched.recommended == alone.recommended
    assert batched.reason == alone.reason
    assert batched.confidence == alone.confidence
    for b, a in zip(batched.evaluated, alone.evaluated, strict=True):
        assert (b.feasible, b.nominal, b.binding, b.failing, b.doubtful) == (
            a.feasible, a.nominal, a.binding, a.failing, a.doubtful), a.name  # fmt: skip
        for key, value in a.figures.items():
            if key != "seconds":  # the CPU time of its evaluation
                assert _same(b.figures[key], value), (a.name, key, b.figures[key], value)


def test_candidates_differing_only_in_their_motor_share_their_own_heat_balance(setting):  # type: ignore[no-untyped-def]
    """The shared balance is each twin's own, solved alone (Illinois to 1e-11 K)."""
    _, _, profile, pool = setting
    ready = _prepared(pool[:6], profile, "complete", 3600.0)
    a, b = ready[0], ready[1]  # motors A and B of the first screw
    assert pool[0].motor is MOTORS[0] and pool[1].motor is MOTORS[1]
    assert a[1] is b[1] is not None
    for case, shared in (a, b):
        assert case is not None and shared is not None
        setup = axis_setup(case.screw, case.axis, case.thermal, float(np.ptp(profile.position)))
        own = steady_temperature(profile, case.screw, case.lubricant, setup.axis, setup.node)
        # The batch's friction equals the screw's own to 1e-13 relative; the root's
        # tolerance is 1e-11 K.
        assert abs(shared.temperature - own.temperature) < 1e-9
        assert _same(shared.friction_power, own.friction_power) or abs(
            shared.friction_power - own.friction_power) < 1e-9 * own.friction_power  # fmt: skip


def test_filled_results_are_the_screws_own_calls() -> None:
    """fill_friction_memo's results against each screw's own friction_torque, field by field."""
    oil = lubricants.get("PAO ISO VG 68")
    base = reference_screw()
    screws = [base, base.replace(lead=0.01), base.replace(preload=800.0),
              base.replace(nut="single", preload=0.0)]  # fmt: skip
    speed = np.array([-50.0, 0.5, 20.0, 120.0])
    load = np.array([300.0, -2000.0, 0.0, 900.0])
    points = [(speed, 35.0, load), (speed[:3], 40.0, load[:3]), (0.1, 30.0, 0.0),
              (speed, 35.0, load)]  # fmt: skip
    own = [friction_torque(s, oil, speed=w, temperature=t, axial_load=f, warn=False)
           for s, (w, t, f) in zip(screws, points, strict=True)]  # fmt: skip
    assert fill_friction_memo(screws, oil, points) == 0  # no memo block: nothing kept
    with friction_memo(size=16):
        assert fill_friction_memo(screws, oil, points) == 4
        assert fill_friction_memo(screws, oil, points) == 0  # already kept
        kept = [friction_torque(s, oil, speed=w, temperature=t, axial_load=f, warn=False)
                for s, (w, t, f) in zip(screws, points, strict=True)]  # fmt: skip
        again = friction_torque(screws[0], oil, speed=speed, temperature=35.0, axial_load=load)
        assert again is kept[0]  # from memory
    for k, o in zip(kept, own, strict=True):
        assert k.model == o.model and k.parameters == o.parameters
        assert list(k.components) == list(o.components)  # the same mechanisms, same order
        assert k.warnings == o.warnings
        for name in ("total", "power_loss", "efficiency", "speed", "temperature", "axial_load"):
            x, y = getattr(k, name), getattr(o, name)
            assert x.shape == y.shape, name
            np.testing.assert_allclose(x, y, rtol=RTOL, atol=0.0, err_msg=name)
        for name, value in o.components.items():
            np.testing.assert_allclose(k.components[name], value, rtol=RTOL, atol=1e-300)
        assert not k.total.flags.writeable  # shared by every caller: read-only
