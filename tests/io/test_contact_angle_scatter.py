"""The [screw] contact_angle_scatter key: read with its unit, it selects the tolerance train."""

from __future__ import annotations

import math

import pytest

from ballscrew import BallScrewInputError
from ballscrew.friction import get_model
from ballscrew.io.case import parse_case

CASE = """
[screw]
designation = "HIWIN R40-10K5-FDC"
preload_share = "5 %"
{key}

[lubricant]
name = "mineral ISO VG 68"

[operation]
speed = "100 rpm"
temperature = "40 degC"
{study}
"""


def test_not_given_leaves_the_default_ratio() -> None:
    case = parse_case(CASE.format(key="", study=""))
    assert case.contact_angle_scatter is None
    assert "ball_train" not in case.parameters_for("complete")


def test_given_in_degrees_it_reaches_the_complete_model_in_radians() -> None:
    case = parse_case(CASE.format(key='contact_angle_scatter = "0.3 deg"', study=""))
    params = case.parameters_for("complete")
    assert params["contact_angle_scatter"] == pytest.approx(math.radians(0.3), rel=1e-12)
    assert params["ball_train"] == "tolerance"
    assert set(params) <= set(get_model("complete").parameters)
    assert case.parameters_for("olaru") == {}


def test_the_study_parameters_win_over_the_screw_key() -> None:
    study = '[study.model_parameters.complete]\nball_train = "ratio"'
    case = parse_case(CASE.format(key='contact_angle_scatter = "0.3 deg"', study=study))
    assert case.parameters_for("complete")["ball_train"] == "ratio"


@pytest.mark.parametrize("value", ['"-0.1 deg"', '"20 deg"'])
def test_an_implausible_scatter_is_refused_with_its_name(value: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(CASE.format(key=f"contact_angle_scatter = {value}", study=""))
    assert info.value.field == "screw.contact_angle_scatter"
