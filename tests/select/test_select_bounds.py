"""A selection is bounded before it runs (issue 52): a 1000-motor table made 1.29 million
candidates (about 14 hours of CPU) with no estimate, bound or progress."""

from __future__ import annotations

import time

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.motors import parse_motors
from ballscrew.select.pool import MAX_CANDIDATES, candidates
from shared import ROOT

CASE = (ROOT / "examples" / "xy_table_32x10.toml").read_text(encoding="utf-8")


def test_a_thousand_motors_are_refused_with_the_estimate_before_any_candidate_is_built() -> None:
    table = (
        "name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], rotor_inertia [kg*cm^2]\n"
    )
    table += "".join(f"M{k}, 2.4, 7.2, 3000, 3.1\n" for k in range(1000))
    motors = parse_motors(table)
    start = time.process_time()
    with pytest.raises(BallScrewInputError) as info:
        candidates(CASE, sources=("catalogue", "iso"), motors=motors)
    assert time.process_time() - start < 5.0  # counted, not built
    said = str(info.value)
    assert info.value.field == "candidates" and "x 1000 motors" in said
    count = int(said.split("candidates = '")[1].split(" ")[0])
    assert count > MAX_CANDIDATES and "min of CPU" in said and "narrow --diameter" in said


def test_a_selection_within_the_bound_is_built() -> None:
    # The catalogue's and ISO's rows on the example axis, two oils: about 800 candidates.
    found = candidates(CASE, sources=("catalogue", "iso"),
                       oils=("PAO ISO VG 68", "mineral ISO VG 68"))  # fmt: skip
    assert 100 < len(found) <= MAX_CANDIDATES
