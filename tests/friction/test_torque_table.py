"""The torque table of the chain: each model over every combination of the operating points."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import BallScrewInputError, friction_torque, reference_screw
from ballscrew.chain import operating_grid, torque_table
from ballscrew.design.ratings import Ratings, static_rating_estimate
from shared import PAO

SPEEDS = np.array([10.0, 100.0, 300.0])
TEMPERATURES = np.array([30.0, 50.0])
LOADS = np.array([0.0, 1500.0])


def test_each_point_of_the_table_is_the_chains_torque_there_one_point_at_a_time() -> None:
    # Another route to the same numbers: friction_torque called on each point alone, in
    # the table's row order (speed slowest, then temperature, then load). The models
    # compute each point independently of the others, so the two agree to rounding
    # (1e-12: vectorised and scalar arithmetic differ in the last bits at most).
    screw = reference_screw()
    table = torque_table(screw, PAO, ["catalog", "complete"], SPEEDS, TEMPERATURES, LOADS)
    assert list(table.results) == ["catalog", "complete"]
    k = 0
    for w in SPEEDS:
        for t in TEMPERATURES:
            for f in LOADS:
                for name, r in table.results.items():
                    one = friction_torque(screw, PAO, speed=w, temperature=t, axial_load=f,
                                          model=name, warn=False)  # fmt: skip
                    assert r.speed[k] == w and r.temperature[k] == t and r.axial_load[k] == f
                    assert r.total[k] == pytest.approx(float(one.total), rel=1e-12)
                k += 1
    assert k == SPEEDS.size * TEMPERATURES.size * LOADS.size
    doc = table.as_dict()
    assert len(doc["models"]["complete"]["torque_Nm"]) == k and doc["plausibility"] == []


def test_the_grid_has_every_combination_once() -> None:
    w, t, f = operating_grid(SPEEDS, TEMPERATURES, LOADS)
    points = set(zip(w.tolist(), t.tolist(), f.tolist(), strict=True))
    assert len(points) == w.size == 12


def test_a_load_past_the_static_rating_is_refused_before_any_model_runs() -> None:
    screw = reference_screw()
    ratings = Ratings(None, "", static_rating_estimate(screw), "estimated")
    ran: list[str] = []
    with pytest.raises(BallScrewInputError) as info:
        torque_table(screw, PAO, ["complete"], SPEEDS, 40.0, [0.0, 10.0 * ratings.static],
                     ratings=ratings, load_field="--axial-load", on_model=ran.append)  # fmt: skip
    assert info.value.field == "--axial-load" and ran == []


def test_an_unknown_model_is_refused_before_any_model_runs() -> None:
    ran: list[str] = []
    with pytest.raises(BallScrewInputError) as info:
        torque_table(reference_screw(), PAO, ["catalog", "coulomb"], SPEEDS, 40.0, 0.0,
                     on_model=ran.append)  # fmt: skip
    assert info.value.field == "model" and ran == []
