"""Validity-range warnings: named, once per quantity per call, recorded in the result."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.friction import MODELS, register
from ballscrew.friction.olaru import SPIN_PARAMETER_RANGE
from ballscrew.validity import RANGES, ValidityIssue, ValidityRange, outside
from shared import PAO

OIL = PAO


def _messages(**kwargs: object) -> list[str]:
    from ballscrew import chain

    chain._NOTED.clear()  # routine issues are told once per session: start afresh
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        r = friction_torque(reference_screw(), OIL, **kwargs)  # type: ignore[arg-type]
    told = [w.message for w in caught if isinstance(w.message, BallScrewValidityWarning)]
    assert [w.issue for w in told] == list(r.warnings)  # each warning holds its issue
    found = [str(w) for w in told]
    model = kwargs.get("model", "complete")
    assert all(issue.model == model for issue in r.warnings)
    # Each message names its model first, then the quantity.
    assert all(m.startswith(f"{model}: ") for m in found)
    return [m.split(": ", 1)[1] for m in found]


def test_inside_every_range_no_warning() -> None:
    assert _messages(speed=10.0, temperature=40.0, model="catalog") == []


@pytest.mark.parametrize(
    ("kwargs", "quantity"),
    [
        ({"speed": 600.0, "model": "catalog"}, "speed factor d_m*n"),
        ({"speed": 10.0, "temperature": -20.0, "model": "complete"}, "temperature"),
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
    ranges = {**RANGES, SPIN_PARAMETER_RANGE.quantity: SPIN_PARAMETER_RANGE}
    r = ranges[next(k for k in ranges if k.startswith(quantity))]
    assert f"{r.low:.4g} to {r.high:.4g}" in found[0]
    assert "=" in found[0]


def test_a_routine_range_warns_in_one_short_line_and_says_why_on_request() -> None:
    # A newcomer's trial of 0.3.0: the README's first call printed two warnings of about
    # 400 characters each, where the command line prints one short note. A library user
    # still gets each warning (a range left is never hidden), in one line naming the
    # quantity, its value and the range; the source and the reason are one call away.
    from ballscrew import chain

    chain._NOTED.clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        r = friction_torque(reference_screw(), "mineral ISO VG 68", speed=[10.5, 105.0],
                            temperature=40.0, axial_load=1000.0)  # fmt: skip
    told = [w.message for w in caught if isinstance(w.message, BallScrewValidityWarning)]
    assert {w.issue.quantity for w in told} == {"dimensionless speed U", "dimensionless load W"}
    for w in told:
        text, issue = str(w), w.issue
        assert "\n" not in text and len(text) <= 170, text
        assert f"{issue.value:.4g}" in text and f"{issue.low:.4g} to {issue.high:.4g}" in text
        assert issue.quantity in text and "extrapolated" in text and ".issue.note()" in text
        assert issue.routine in issue.note() and issue.source in issue.note()
    assert len(r.warnings) == 2  # and the result records both


def test_one_warning_per_quantity_however_many_points() -> None:
    found = _messages(speed=np.linspace(500.0, 900.0, 1000), temperature=40.0, model="catalog")
    assert len([m for m in found if m.startswith("speed factor")]) == 1
    # The value named is the worst one: 40 mm * 900 rad/s * 60 / 2 pi.
    assert "3.438e+05" in found[0]


def test_the_warning_points_at_the_line_that_called_friction_torque() -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        friction_torque(reference_screw(), OIL, speed=900.0, temperature=40.0, model="catalog")
    assert caught and {w.filename for w in caught} == {__file__}


def test_the_warning_points_at_the_caller_also_from_the_memo_and_for_many_screws() -> None:
    # A result given again from a friction_memo block warns again, at its caller's line too;
    # and friction_torques (many screws) points at its own caller.
    from ballscrew.chain import friction_memo, friction_torques

    with friction_memo(), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for _ in range(2):  # the second call is answered from the memo
            friction_torque(reference_screw(), OIL, speed=900.0, temperature=40.0,
                            model="catalog")  # fmt: skip
    assert len(caught) >= 2 and {w.filename for w in caught} == {__file__}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        friction_torques([reference_screw()], OIL, speed=900.0, temperature=40.0,
                         model="catalog")  # fmt: skip
    assert caught and {w.filename for w in caught} == {__file__}


def test_ellipticity_range_of_the_film_formulas() -> None:
    tight = reference_screw().replace(conformity_screw=0.505, conformity_nut=0.505)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        friction_torque(tight, OIL, speed=10.0, temperature=40.0, model="harris-full")
    assert any("ellipticity k (Hamrock-Dowson)" in str(w.message) for w in caught)


def test_a_toy_model_is_one_function_and_one_registration_with_its_own_range() -> None:
    # A new model: one function, one @register line with its own validity check; nothing
    # else is edited. It is then reachable through friction_torque and warns on its range.
    toy_range = ValidityRange("toy speed [rad/s]", 0.0, 50.0, "the toy model", "by decree")

    def toy_check(screw, lubricant, speed, temperature, axial_load, params):  # type: ignore[no-untyped-def]
        return outside(toy_range, [float(np.max(np.abs(speed)))])

    @register("toy", title="toy", reference="none", validity="speeds to 50 rad/s",
              purpose="testing", checks=(toy_check,))  # fmt: skip
    def toy(screw, lubricant, speed, temperature, axial_load, *, c=0.01):  # type: ignore[no-untyped-def]
        return {"viscous": c * np.abs(speed)}

    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", BallScrewValidityWarning)
            r = friction_torque(reference_screw(), OIL, speed=[10.0, 80.0], temperature=40.0,
                                model="toy", c=0.02)  # fmt: skip
        np.testing.assert_allclose(r.total, [0.2, 1.6])
        (issue,) = [w.message.issue for w in caught if w.category is BallScrewValidityWarning]
        assert isinstance(issue, ValidityIssue)
        assert (issue.quantity, issue.value, issue.model) == ("toy speed [rad/s]", 80.0, "toy")
    finally:
        MODELS.pop("toy")


def test_models_that_ignore_the_oil_do_not_warn_about_its_temperature() -> None:
    # The viscoelastic model and the catalogue formula take no lubricant data.
    # The catalogue rule warns about its own range instead (it has no temperature term).
    for model in ("viscoelastic", "catalog"):
        found = _messages(speed=10.0, temperature=-20.0, model=model)
        assert not [m for m in found if m.startswith("temperature [degC] =")]
    (own,) = _messages(speed=10.0, temperature=-20.0, model="catalog")
    assert own.startswith("temperature [degC] (catalogue rule) = -20 is outside 0 to 60")


def test_point_by_point_warnings_are_those_of_the_array_call() -> None:
    # The film checks are cached on the operating range's extremes; a loop
    # over single points must warn about the same quantities, and the worst
    # value over the loop must be the array call's worst value.
    import warnings

    import numpy as np

    from ballscrew import friction_torque, reference_screw

    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    speeds = np.array([1.0, 30.0, 300.0])
    loads = np.array([0.0, 5e3, 2e4])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        whole = friction_torque(screw, oil, speed=speeds, temperature=-10.0, axial_load=loads)
        single = [
            friction_torque(screw, oil, speed=w, temperature=-10.0, axial_load=f)
            for w, f in zip(speeds, loads, strict=True)
        ]
    assert whole.warnings, "the case was chosen to leave several ranges"
    by_quantity: dict[str, list[float]] = {}
    for r in single:
        for issue in r.warnings:
            by_quantity.setdefault(issue.quantity, []).append(issue.value)
    assert set(by_quantity) == {i.quantity for i in whole.warnings}
    for issue in whole.warnings:
        assert any(v == issue.value for v in by_quantity[issue.quantity])


def test_routine_film_ranges_are_told_once_and_recorded_every_time() -> None:
    # Every ordinary ball screw leaves the film formulas' U and W ranges: the
    # first call tells it as a note with the reason, later calls stay quiet,
    # and every result still records the issue with its value.
    from ballscrew import chain

    chain._NOTED.clear()
    results, told = [], []
    for rpm in (500.0, 1000.0):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", BallScrewValidityWarning)
            results.append(friction_torque(reference_screw(), OIL, speed=rpm * np.pi / 30,
                                           temperature=40.0))  # fmt: skip
        told.append([str(w.message) for w in caught])
    assert any("dimensionless speed U" in m and "usual for ball screws" in m for m in told[0])
    assert not any("dimensionless speed U" in m for m in told[1])
    speeds = [i.value for r in results for i in r.warnings if i.quantity == "dimensionless speed U"]
    assert len(speeds) == 2 and speeds[1] == pytest.approx(2 * speeds[0], rel=1e-9)
