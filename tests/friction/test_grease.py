"""A grease in the chain: its base oil's friction, the note of what is left out, pour and flash."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.validity import GREASE_SOURCE, ValidityIssue, lubricant_limits, outside
from shared import ALL_MODELS

GREASE = lubricants.get("SKF LGHP 2")
#: The same base oil, described as an oil.
BASE_OIL = GREASE.replace(kind="oil", thickener="", nlgi_grade="")
SPEED = np.array([10.0, 100.0, 300.0])
#: The models that use the lubricant's data (the others ignore it).
USES_OIL = [m for m in ALL_MODELS if m not in ("catalog", "viscoelastic")]


def _quiet(**kwargs: object) -> object:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        return friction_torque(reference_screw(), speed=SPEED, **kwargs)  # type: ignore[arg-type]


def _grease_notes(issues: tuple[ValidityIssue, ...]) -> list[ValidityIssue]:
    return [i for i in issues if i.quantity == "grease (base oil only)"]


@pytest.mark.parametrize("model", ALL_MODELS)
def test_a_grease_gives_the_friction_of_its_base_oil(model: str) -> None:
    # Same model path: the base oil's data are all the models see of a grease.
    greased = _quiet(lubricant=GREASE, temperature=40.0, axial_load=500.0, model=model)
    # The complete model's lubrication method follows the lubricant's kind ("auto": a grease
    # starves its track as SKF's grease constant says); given as "grease", the oil matches.
    method = {"lubrication": "grease"} if model == "complete" else {}
    oiled = _quiet(lubricant=BASE_OIL, temperature=40.0, axial_load=500.0, model=model, **method)
    np.testing.assert_array_equal(greased.total, oiled.total)  # type: ignore[attr-defined]
    for name, part in oiled.components.items():  # type: ignore[attr-defined]
        np.testing.assert_array_equal(greased.components[name], part)  # type: ignore[attr-defined]


@pytest.mark.parametrize("model", USES_OIL)
def test_the_grease_note_is_recorded_by_the_models_that_use_the_oil(model: str) -> None:
    greased = _quiet(lubricant=GREASE, temperature=40.0, model=model)
    (note,) = _grease_notes(greased.warnings)  # type: ignore[attr-defined]
    assert note.model == model and note.routine and note.source == GREASE_SOURCE
    text = str(note)
    for told in ("SKF LGHP 2", "polyurea", "NLGI 2-3", "base oil", "not modelled", "starvation"):
        assert told in text, told
    assert math.isnan(note.low) and math.isnan(note.high)  # a statement, not a range
    oiled = _quiet(lubricant=BASE_OIL, temperature=40.0, model=model)
    assert not _grease_notes(oiled.warnings)  # type: ignore[attr-defined]


def test_the_grease_note_is_told_once_and_recorded_every_time() -> None:
    from ballscrew import chain

    chain._NOTED.clear()
    told = []
    for _ in range(3):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", BallScrewValidityWarning)
            r = friction_torque(reference_screw(), GREASE, speed=SPEED, temperature=40.0)
        told += [w for w in caught if "grease (base oil only)" in str(w.message)]
        assert len(_grease_notes(r.warnings)) == 1
    assert len(told) == 1
    assert "(usual for ball screws: many ball screws run on grease)" in str(told[0].message)


def test_the_torque_table_tells_the_grease_note_once() -> None:
    from ballscrew.report.torque import warning_lines

    results = {m: _quiet(lubricant=GREASE, temperature=40.0, model=m) for m in USES_OIL}
    lines = [line for line in warning_lines(results) if "grease (base oil only)" in line]  # type: ignore[arg-type]
    assert len(lines) == 1 and lines[0].startswith("note: grease (base oil only): SKF LGHP 2")
    assert all(m in lines[0] for m in USES_OIL)
    assert "nan" not in lines[0]


LIMITED = BASE_OIL.replace(pour_point=-30.0, flash_point=210.0)


def _limits(temperature: object, model: str) -> list[ValidityIssue]:
    column = np.asarray(temperature, dtype=float)[:, None]  # every temperature at every speed
    r = _quiet(lubricant=LIMITED, temperature=column, model=model)
    return [i for i in r.warnings if "point)" in i.quantity]  # type: ignore[attr-defined]


@pytest.mark.parametrize("model", ALL_MODELS)
def test_pour_and_flash_points_warn_on_their_own_side(model: str) -> None:
    # Every model: beyond these points there is no lubricant, whatever the model.
    assert _limits([-30.0, 20.0, 210.0], model) == []  # the points themselves are inside
    (cold,) = _limits([-40.0, 20.0], model)
    assert (cold.quantity, cold.value, cold.low, cold.high) == (
        "temperature [degC] (pour point)",
        -40.0,
        -30.0,
        math.inf,
    )
    (hot,) = _limits([20.0, 250.0], model)
    assert (hot.quantity, hot.value, hot.low, hot.high) == (
        "temperature [degC] (flash point)",
        250.0,
        -math.inf,
        210.0,
    )
    both = _limits([-45.0, 260.0], model)
    assert [i.value for i in both] == [-45.0, 260.0]


def test_the_limit_messages_name_field_value_limit_and_source() -> None:
    cold, hot = _limits([-40.0, 250.0], "complete")
    cold_text, hot_text = str(cold), str(hot)
    assert "= -40 is below -30" in cold_text and "pour_point = -30 degC" in cold_text
    assert "= 250 is above 210" in hot_text and "flash_point = 210 degC" in hot_text
    for text in (cold_text, hot_text):
        assert LIMITED.source in text and LIMITED.name in text
        assert text.startswith("complete: temperature [degC] (")
        assert "results there do not hold" in text
    assert not cold.routine and not hot.routine  # warnings, not notes
    assert cold.excess == pytest.approx(10.0 / 30.0) and hot.excess == pytest.approx(40.0 / 210.0)


def test_no_limits_without_pour_or_flash_point() -> None:
    assert lubricant_limits(BASE_OIL.replace(flash_point=None)) == []
    assert [r.quantity for r in lubricant_limits(GREASE)] == ["temperature [degC] (flash point)"]


def test_a_bound_of_either_sign_is_inside_itself() -> None:
    (pour, flash) = lubricant_limits(LIMITED)
    assert outside(pour, [-30.0, -30.0 * (1 + 1e-13)]) == []
    assert outside(flash, [210.0]) == []
    assert [i.value for i in outside(pour, [-30.001, -31.0, 0.0])] == [-31.0]
