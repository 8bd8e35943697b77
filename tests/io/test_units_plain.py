"""The units read without pint (``PLAIN_FACTORS``) give pint's numbers to the last bit.

Issue 51: the command line reads the commonest units as one product so that a one-point
``ballscrew torque`` need not import pint. Each entry is checked here against the full path
through pint (the table emptied) on numbers of every size and sign, for exact equality: the
table must change no number anywhere, not even in the last bit.
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.io import units


def _through_pint(
    monkeypatch: pytest.MonkeyPatch, unit_text: str, unit: str | None, x: float
) -> float:
    with monkeypatch.context() as m:
        m.setattr(units, "PLAIN_FACTORS", {})
        notes: list[units.Reading] = []
        value = float(units._convert("field", f"{x} {unit_text}", x, unit_text, unit, notes))
        assert notes == []  # nothing in the table is read with a note
        return value


NUMBERS = [
    0.0,
    1.0,
    -1.0,
    3.0,
    0.1,
    7.25,
    1e-9,
    123456.789,
    -40.0,
    2.0**0.5,
    1e12,
    *np.random.default_rng(51).uniform(-1e4, 1e4, 40),
]


@pytest.mark.parametrize(
    ("unit_text", "unit"), [*sorted(units.PLAIN_FACTORS, key=str), ("degC", "degC")]
)
def test_plain_factor_is_pints_to_the_last_bit(
    monkeypatch: pytest.MonkeyPatch, unit_text: str, unit: str | None
) -> None:
    factor = units.PLAIN_FACTORS.get((unit_text, unit), 1.0)
    if unit_text != "degC":
        assert _through_pint(monkeypatch, unit_text, unit, 1.0) == factor
    for x in NUMBERS:
        assert float(units._convert("field", "", float(x), unit_text, unit, [])) == _through_pint(
            monkeypatch, unit_text, unit, float(x)
        ), x


def test_a_one_point_torque_reads_its_units_without_pint() -> None:
    # The bundled case and '--speed "100 rpm"' in a fresh process: pint is never imported.
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from ballscrew.cli import main\n"
        "try:\n    main(['torque', '--speed', '100 rpm', '--model', 'complete'])\n"
        "except SystemExit:\n    pass\n"
        "print('pint' in sys.modules, file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stderr.strip().splitlines()[-1] == "False", done.stderr
