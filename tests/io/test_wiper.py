"""The [screw] wiper_drag key: read with its unit, fed to the models with a seal term only."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import BallScrewInputError
from ballscrew.chain import FrictionResult, torque_table
from ballscrew.friction import get_model
from ballscrew.io.case import WIPER_PARAMETERS, Case, parse_case
from ballscrew.report.torque import warning_lines
from shared import BUILT_IN_MODELS


def run_models(case: Case, models: list[str]) -> dict[str, FrictionResult]:
    """The case's models over its points, as ``ballscrew torque`` runs them."""
    return torque_table(
        case.screw, case.lubricant, models, case.speed, case.temperature, case.axial_load,
        parameters={m: case.parameters_for(m) for m in models}, wiper_drag=case.wiper_drag,
        wiper_models=WIPER_PARAMETERS,
    ).results  # fmt: skip


CASE = """
[screw]
designation = "HIWIN R40-10K5-FDC"
preload_share = "5 %"
{wiper}

[lubricant]
name = "SKF LGHP 2"

[operation]
speed = "100, 1000 rpm"
temperature = "40 degC"
axial_load = "0, 1 kN"
{study}
"""


def _case(wiper: str = "", study: str = "") -> str:
    return CASE.format(wiper=wiper, study=study)


def test_wiper_drag_is_read_with_its_unit() -> None:
    assert parse_case(_case()).wiper_drag == 0.0
    assert parse_case(_case('wiper_drag = "50 N*mm"')).wiper_drag == pytest.approx(0.05)
    assumed = parse_case(_case('wiper_drag = { value = "0.05 N*m", assumed = "two wipers" }'))
    assert assumed.wiper_drag == pytest.approx(0.05)
    (note,) = [a for a in assumed.assumptions if a.field == "screw.wiper_drag"]
    assert note.reason == "two wipers"


def test_only_the_models_with_a_seal_term_get_it() -> None:
    case = parse_case(_case('wiper_drag = "0.05 N*m"'))
    assert case.parameters_for("complete") == {"seal_torque": pytest.approx(0.05)}
    for model in BUILT_IN_MODELS:
        if model != "complete":
            assert "seal_torque" not in case.parameters_for(model)
    assert parse_case(_case()).parameters_for("complete") == {}


def test_the_wiper_list_matches_the_models_seal_terms() -> None:
    # io reaches no model, so WIPER_PARAMETERS is kept by hand: it must name every built-in
    # model with a seal parameter, and only parameters those models have.
    with_seal = {m for m in BUILT_IN_MODELS if "seal_torque" in get_model(m).parameters}
    assert set(WIPER_PARAMETERS) == with_seal
    for model, parameter in WIPER_PARAMETERS.items():
        assert parameter in get_model(model).parameters


def test_the_wiper_adds_exactly_its_torque_as_the_seals_component() -> None:
    plain, wiped = parse_case(_case()), parse_case(_case('wiper_drag = "0.05 N*m"'))
    models = ["complete", "catalog", "olaru"]
    before = run_models(plain, models)
    after = run_models(wiped, models)
    np.testing.assert_array_equal(after["complete"].components["seals"], 0.05)
    np.testing.assert_allclose(
        after["complete"].total - before["complete"].total, 0.05, rtol=0, atol=1e-15
    )
    for name, part in before["complete"].components.items():
        if name != "seals":
            np.testing.assert_array_equal(after["complete"].components[name], part)
    for model in ("catalog", "olaru"):  # no seal term: the same torque, and a note
        np.testing.assert_array_equal(after[model].total, before[model].total)
        (note,) = [i for i in after[model].warnings if i.quantity == "wiper drag [N*m]"]
        assert note.model == model and note.value == pytest.approx(0.05)
        assert "left out" in str(note)
    assert not [i for i in after["complete"].warnings if i.quantity == "wiper drag [N*m]"]
    assert not [i for r in before.values() for i in r.warnings if "wiper" in i.quantity]
    (line,) = [x for x in warning_lines(after) if "wiper drag" in x]
    assert line.startswith("note: wiper drag [N*m] = 0.05: left out") and "catalog, olaru" in line


@pytest.mark.parametrize(
    ("value", "allowed"),
    [
        ('"-0.05 N*m"', ">= 0"),
        ("0.05", "unit"),
        ('"0.05"', "unit"),
        ('"0.05 N"', "N*m"),
        ('"nan N*m"', "finite"),
        ('"inf N*m"', "finite"),
    ],
)
def test_a_bad_wiper_drag_is_refused_naming_the_field(value: str, allowed: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case(f"wiper_drag = {value}"))
    assert info.value.field == "screw.wiper_drag"
    assert allowed in info.value.allowed


def test_the_wiper_drag_is_given_once() -> None:
    study = "[study.model_parameters.complete]\nseal_torque = 0.02"
    assert parse_case(_case(study=study)).parameters_for("complete") == {"seal_torque": 0.02}
    with pytest.raises(BallScrewInputError, match="seal_torque gives it too") as info:
        parse_case(_case('wiper_drag = "0.05 N*m"', study))
    assert info.value.field == "screw.wiper_drag"


def test_with_wiper_drag_replaces_it_naming_the_option() -> None:
    case = parse_case(_case('wiper_drag = "0.05 N*m"'))
    assert case.with_wiper_drag("0.1 N*m").parameters_for("complete")["seal_torque"] == 0.1
    assert case.with_wiper_drag("0 N*m").parameters_for("complete") == {}
    assert case.wiper_drag == pytest.approx(0.05)  # the case itself is unchanged
    with pytest.raises(BallScrewInputError) as info:
        case.with_wiper_drag("-1 N*m", field="--wiper-drag")
    assert info.value.field == "--wiper-drag"
