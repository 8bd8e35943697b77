"""The unit system of printed results (ballscrew.io.display), checked without the CLI.

The commands reach :func:`unit_system` only with a system click or the case schema has
already checked, so its own refusal is tested here directly.
"""

from __future__ import annotations

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.display import unit_system


def test_an_unknown_unit_system_is_refused_naming_the_field_the_value_and_the_choices() -> None:
    with pytest.raises(BallScrewInputError) as refused:
        unit_system("--units", "metric")
    assert refused.value.field == "--units" and refused.value.value == "metric"
    assert str(refused.value).endswith("one of si, imperial")
