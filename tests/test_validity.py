"""Validity-range warnings: named, once per quantity per call, recorded in the result."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.validity import RANGES

OIL = lubricants.get("PAO ISO VG 68")


def _messages(**kwargs: object) -> list[str]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        r = friction_torque(reference_screw(), OIL, **kwargs)  # type: ignore[arg-type]
    found = [str(w.message) for w in caught if issubclass(w.category, BallScrewValidityWarning)]
    assert found == list(r.warnings)
    return found


def test_inside_every_range_no_warning() -> None:
    assert _messages(speed=10.0, temperature=40.0, model="catalog") == []


@pytest.mark.parametrize(
    ("kwargs", "quantity"),
    [
        ({"speed": 600.0, "model": "catalog"}, "speed factor d_m*n"),
        ({"speed": 10.0, "temperature": -20.0, "model": "viscoelastic"}, "temperature"),
        ({"speed": 10.0, "axial_load": 7000.0, "model": "catalog"}, "axial load / preload"),
        ({"speed": 10.0, "model": "harris-simplified"}, "radius ratio Ry/Rx (Houpert fits)"),
        ({"speed": 300.0, "model": "harris-full"}, "dimensionless speed U"),
        ({"speed": 10.0, "model": "olaru"}, "spin parameter E (Olaru)"),
    ],
)
def test_each_range_warns_with_quantity_value_and_range(
    kwargs: dict[str, object], quantity: str
) -> None:
    args: dict[str, object] = {"temperature": 40.0}
    args.update(kwargs)
    found = [m for m in _messages(**args) if m.startswith(quantity)]
    assert len(found) == 1, found
    r = RANGES[next(k for k in RANGES if k.startswith(quantity))]
    assert f"{r.low:.4g} to {r.high:.4g}" in found[0]
    assert "=" in found[0]


def test_one_warning_per_quantity_however_many_points() -> None:
    found = _messages(speed=np.linspace(500.0, 900.0, 1000), temperature=40.0, model="catalog")
    assert len([m for m in found if m.startswith("speed factor")]) == 1
    # The value named is the worst one: 40 mm * 900 rad/s * 60 / 2 pi.
    assert "3.438e+05" in found[0]


def test_ellipticity_range_of_the_film_formulas() -> None:
    tight = reference_screw().replace(conformity_screw=0.505, conformity_nut=0.505)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        friction_torque(tight, OIL, speed=10.0, temperature=40.0, model="harris-full")
    assert any("ellipticity k (Hamrock-Dowson)" in str(w.message) for w in caught)
