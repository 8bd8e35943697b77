"""select's objectives and its recommendation rule, pinned on candidates whose figures are set.

The rule (module docstring of ``ballscrew.select.choose``): the best on the first objective
among the front's members whose every utilisation is at most 0.8; else the least largest
utilisation, members within 0.01 of it tied, the tie to the best on the first objective.
Each test puts a candidate on either side of one threshold, so that the pick names it.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.select import candidates, evaluate
from ballscrew.select.choose import OBJECTIVES, Evaluated, _objective_key, _recommend
from shared import ROOT

pytest.importorskip("pymoo")


def member(name: str, utilisation: float, **figures: float) -> Evaluated:
    """A front member with the figures given (NaN for the others)."""
    values = {key: math.nan for key, _, _ in OBJECTIVES.values()}
    values.update(figures, max_utilisation=utilisation, p_not_ok=math.nan)
    candidate = SimpleNamespace(name=name)
    return Evaluated(candidate, values, True, f"{name}'s row ({utilisation:.0%})", True)  # type: ignore[arg-type]


def pick(members: list[Evaluated], first: str) -> str:
    best, _ = _recommend(members, list(range(len(members))), first)
    return members[best].name


def test_price_is_better_lower_and_a_missing_price_ranks_last() -> None:
    members = [member("dear", 0.5, price=900.0), member("cheap", 0.6, price=400.0),
               member("unpriced", 0.4)]  # fmt: skip
    rank = _objective_key(members, "price")
    assert sorted(range(3), key=rank) == [1, 0, 2]
    assert pick(members, "price") == "cheap"


@pytest.mark.parametrize(
    ("objective", "better", "worse"),
    [("energy", 10.0, 12.0), ("life", 3e4, 2e4), ("stiffness", 300.0, 200.0),
     ("lost_motion", 2.0, 3.0), ("thermal_error", 5.0, 6.0), ("motor_margin", 0.5, 0.3),
     ("price", 100.0, 200.0)],
)  # fmt: skip
def test_each_objective_prefers_its_own_direction(
    objective: str, better: float, worse: float
) -> None:
    # The published sense of each figure: less energy, lost motion, thermal error and price;
    # more life, stiffness and motor margin.
    key = OBJECTIVES[objective][0]
    members = [member("worse", 0.5, **{key: worse}), member("better", 0.5, **{key: better})]
    assert pick(members, objective) == "better"


def test_the_threshold_at_80_percent_is_inclusive() -> None:
    # At 0.8 exactly a candidate is below the threshold and its lower energy picks it; at
    # 0.8005 it is not, and the one at 0.79 is the only one below.
    assert pick([member("a", 0.79, energy_J=20.0), member("b", 0.8, energy_J=10.0)],
                "energy") == "b"  # fmt: skip
    assert pick([member("a", 0.79, energy_J=20.0), member("b", 0.8005, energy_J=10.0)],
                "energy") == "a"  # fmt: skip


def test_between_the_thresholds_the_least_utilised_and_its_tie_band_decide() -> None:
    # No member at or below 0.8: the least largest utilisation is 0.85; 0.855 is within its
    # 0.01 band and has less energy, so it is picked; 0.8605, with still less energy, lies
    # outside the band (by 0.0005, a twentieth of it) and is not.
    members = [member("least", 0.85, energy_J=30.0), member("tied", 0.855, energy_J=20.0),
               member("outside", 0.8605, energy_J=10.0)]  # fmt: skip
    best, why = _recommend(members, [0, 1, 2], "energy")
    assert members[best].name == "tied"
    assert "tied within 1% of utilisation with least" in why
    # Without the tied one the least utilised wins, though "outside" spends less.
    assert pick([members[0], members[2]], "energy") == "least"


def test_the_energy_objective_is_per_cycle() -> None:
    # One candidate over one cycle of a move and over two of it: the friction energy per
    # cycle and the life are the same (the cycles are identical and at the same steady
    # temperature; 1e-6 is the heat balance's tolerance on the temperature it runs at).
    case = ROOT / "examples" / "vertical_32x5.toml"
    m = parse_move("stroke=300 mm, feed=10 m/min, acceleration=2 m/s^2, force=1 kN, dwell=2 s")
    text = case.read_text("utf-8")
    found = candidates(text, diameter=(0.032, 0.032), lead=(0.010, 0.010), makers=["HIWIN"],
                       preloads=["light"])  # fmt: skip
    one, _ = evaluate(found[0], profile_from_move(m, 1), cycles=1, move=m)
    two, _ = evaluate(found[0], profile_from_move(m, 2), cycles=2, move=m)
    assert two.figures["energy_J"] == pytest.approx(one.figures["energy_J"], rel=1e-6)
    assert two.figures["friction_share"] == pytest.approx(one.figures["friction_share"],
                                                          rel=1e-6)  # fmt: skip
    assert two.figures["L10_h"] == pytest.approx(one.figures["L10_h"], rel=1e-6)
