"""The candidate pool's bound of 10 000 and its estimate, pinned by hand (ballscrew.select.pool).

Found by mutation (docs/mutation.md, "The candidate pool"): the bound itself, its edge
(exactly 10 000 candidates are built, one more screw's worth refused), the count without a
motor table (one motor, the case's) and the CPU minutes the refusal states were not checked.

The pool is counted by hand: the bundled catalogue (data/catalog_screws.csv) holds five nuts of
32 x 10 mm, each tried at the light class as the one kind it is sold as (a double nut as
double, a single nut as 4-point), so five candidates per oil and motor.
"""

from __future__ import annotations

from typing import Any

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.motors import MotorRow
from ballscrew.select.pool import Candidate, candidates
from shared import ROOT

TEXT = (ROOT / "examples" / "vertical_32x5.toml").read_text(encoding="utf-8")
FIVE = {  # the 32 x 10 mm rows of data/catalog_screws.csv, with the kind each is tried as
    "HIWIN R32-10K5-FSC": "single-4point",
    "HIWIN R32-10K5-FDC": "double",
    "HIWIN R32-10T4-FDI": "double",
    "THK BIF3210A-5": "double",
    "NBS VFI 3210": "single-4point",
}


def _pool(**options: Any) -> list[Candidate]:
    # The 32 x 10 mm screws at the light class.
    return candidates(TEXT, diameter=(0.032, 0.032), lead=(0.010, 0.010), preloads=["light"],
                      **options)  # fmt: skip


def _motors(n: int) -> list[MotorRow]:
    # n motors alike in all but their name (a 1.5 kW servo: 6 N*m, 18 N*m, 3000 1/min).
    return [MotorRow(f"M{k}", 6.0, 18.0, 314.159, 9e-4) for k in range(n)]


def test_the_five_nuts_of_32_x_10_mm_are_five_candidates_a_motor() -> None:
    found = _pool()
    assert {c.row.name: c.nut for c in found} == FIVE
    assert len(found) == 5


def test_exactly_ten_thousand_candidates_are_built() -> None:
    # 5 nuts x 2000 motors = 10 000: the bound, allowed ("at most 10000").
    found = _pool(motors=_motors(2000))
    assert len(found) == 10_000


def test_one_motor_more_is_refused_before_any_candidate_is_built() -> None:
    # 5 x 2001 = 10 005 > 10 000.
    with pytest.raises(BallScrewInputError) as info:
        _pool(motors=_motors(2001))
    assert info.value.field == "candidates"
    assert info.value.value.startswith("10005 (5 screws x ")
    assert info.value.value.endswith("x 1 oils x 2001 motors)")
    assert info.value.allowed.startswith("at most 10000 a selection")


def test_without_a_motor_table_the_case_s_motor_counts_once() -> None:
    # No motor table: each screw and oil is one candidate (the case's own motor), so
    # 5 nuts x 2001 oils = 10 005 is refused as 2001 oils x 1 motors. (The oils are only
    # counted: the refusal comes before any candidate is built.)
    oils = [f"oil {k}" for k in range(2001)]
    with pytest.raises(BallScrewInputError) as info:
        _pool(oils=oils)
    assert info.value.value == (
        "10005 (5 screws x preload classes and nut kinds x 2001 oils x 1 motors)"
    )


def test_the_refusal_states_the_cpu_minutes_at_fifty_candidates_a_second() -> None:
    # 5 nuts x 3 oils x 2000 motors = 30 000 candidates; at 50 a CPU-second
    # (benchmarks/bench_select.py) that is 600 s = 10 min. (A rate of 55 would say 9 min.)
    with pytest.raises(BallScrewInputError) as info:
        _pool(oils=["a", "b", "c"], motors=_motors(2000))
    assert info.value.value.startswith("30000 (")
    assert "(about 10 min of CPU at 50 candidates a second)" in info.value.allowed
