"""``[lubricant] lubrication``: the lubrication method as a case input."""

from __future__ import annotations

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case

BASE = """
[screw]
designation = "40x10 double 2.5x2 6.35"
preload = "2 kN"
[lubricant]
name = "{name}"
{line}
[operation]
speed = "1000 rpm"
temperature = "20 degC"
{study}
"""


def _case(line: str, name: str = "mineral ISO VG 68", study: str = ""):  # type: ignore[no-untyped-def]
    return parse_case(BASE.format(line=line, name=name, study=study))


def test_the_method_reaches_the_complete_model_only() -> None:
    case = _case('lubrication = "flooded"')
    assert case.lubrication == "flooded"
    assert case.parameters_for("complete")["lubrication"] == "flooded"
    assert "lubrication" not in case.parameters_for("olaru")
    assert case.sources["lubricant.lubrication"] == "given"


def test_left_out_the_model_chooses() -> None:
    case = _case("")
    assert case.lubrication is None
    assert "lubrication" not in case.parameters_for("complete")
    assert case.sources["lubricant.lubrication"] == "default"


@pytest.mark.parametrize(
    ("line", "name", "study", "field", "words"),
    [
        ('lubrication = "bath"', "mineral ISO VG 68", "", "lubricant.lubrication", "flooded"),
        ('lubrication = "flooded"', "SKF LGHP 2", "", "lubricant.lubrication", "grease"),
        ('lubrication = "flooded"', "mineral ISO VG 68",
         '[study]\nmodel_parameters = { complete = { lubrication = "drip" } }',
         "study.model_parameters.complete.lubrication", "[lubricant] lubrication"),
    ],
)  # fmt: skip
def test_a_method_that_cannot_be_is_refused(
    line: str, name: str, study: str, field: str, words: str
) -> None:
    with pytest.raises(BallScrewInputError) as err:
        _case(line, name, study)
    assert err.value.field == field
    assert words in str(err.value)
