"""Absurd and impossible inputs are refused naming the field (issue 28).

Before, a 12 mm ball on a 10 mm lead gave a plausible torque, a preload of 1e300 N
gave ``inf``, the viscoelastic model gave negative torques above about 1.7e6 rpm
(-33 N·m through the web API) and a temperature of 40 K was refused as
``viscosity = nan``. Every input here is refused, through the library, a case file,
a sweep and the command line, with the field the user wrote.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ballscrew import BallScrew, friction_torque, reference_screw
from ballscrew.chain import _check_solved
from ballscrew.errors import BallScrewInputError
from ballscrew.friction import register
from ballscrew.friction._registry import MODELS
from ballscrew.io.case import parse_case
from ballscrew.io.schema import template
from cli_runner import run
from shared import ALL_MODELS, BUILT_IN_MODELS, PAO, SMALL_CASE

RPM = math.pi / 30.0


def _refused(field: str, **kwargs: Any) -> BallScrewInputError:
    with pytest.raises(BallScrewInputError) as info:
        friction_torque(reference_screw(), PAO, **{"speed": 100.0, "temperature": 40.0, **kwargs})
    assert info.value.field == field, info.value
    return info.value


# The library: each bound names its field.


def test_a_preload_of_1e300_newtons_is_refused() -> None:
    with pytest.raises(BallScrewInputError) as info:
        reference_screw().replace(preload=1e300)
    assert info.value.field == "preload" and "1e8 N" in str(info.value)
    reference_screw().replace(preload=1e8)  # the bound itself is taken


@pytest.mark.parametrize("speed", [1.01e5, -1.01e5, 1.7e6 * RPM, 1e30])
def test_a_speed_past_1e5_rad_s_is_refused(speed: float) -> None:
    assert "rad/s" in str(_refused("speed", speed=speed))


@pytest.mark.parametrize("temperature", [500.5, 1e6])
def test_a_temperature_above_500_degc_is_refused(temperature: float) -> None:
    assert "500" in str(_refused("temperature", temperature=temperature))


@pytest.mark.parametrize("load", [1.01e8, -1.01e8, 1e300])
def test_an_axial_load_above_100_meganewtons_is_refused(load: float) -> None:
    assert "100 MN" in str(_refused("axial_load", axial_load=load))


@pytest.mark.parametrize("model", BUILT_IN_MODELS)
def test_40_kelvin_names_the_temperature_not_a_viscosity(model: str) -> None:
    # -233 °C: the oil's ASTM D341 fit overflows; before, 'viscosity = nan' for the
    # models that use the viscosity (and a numpy warning on the way).
    err = _refused("temperature", temperature=40.0 - 273.15, model=model)
    assert "PAO ISO VG 68" in str(err)


def test_the_viscoelastic_model_at_1_7e6_rpm_is_refused_by_the_speed_bound() -> None:
    # Issue 28: -33 N·m through the web API at this speed.
    err = _refused("speed", speed=1.7e6 * RPM, axial_load=1000.0, model="viscoelastic")
    assert err.value == pytest.approx(1.7e6 * RPM)


def test_the_viscoelastic_model_below_the_bound_but_past_its_equations_names_the_point() -> None:
    # Unloaded at 9.99e4 rad/s (954 000 rpm), inside the speed bound, the model's torque
    # turns negative: refused as a point the model cannot solve, not given out.
    with pytest.raises(BallScrewInputError) as info:
        friction_torque(
            reference_screw(), PAO, speed=[100.0, 9.99e4], temperature=40.0, model="viscoelastic"
        )
    err = info.value
    assert err.field == "operating point"
    assert "speed 953975 rpm, temperature 40 degC, axial_load 0 N" in str(err)
    assert "'viscoelastic'" in str(err) and ">= 0" in str(err)


def test_harris_full_where_its_film_gives_nan_names_the_point() -> None:
    # A pull of 99.9 MN on a thin oil with a large pressure-viscosity coefficient (2 mm²/s,
    # 99 /GPa: Roelands' index Z = 5.9): the local viscosity at the contact's 1e11 Pa
    # overflows, the model's contact integrals give NaN (numpy says so).
    from ballscrew import Lubricant

    oil = Lubricant.from_viscosities("thin", 2e-6, 1e-6, 850.0, 9.9e-8)
    with pytest.raises(BallScrewInputError) as info, warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        friction_torque(
            reference_screw(), oil, speed=1e4, temperature=40.0, axial_load=-9.99e7,
            model="harris-full",
        )  # fmt: skip
    assert info.value.field == "operating point"
    assert "axial_load -9.99e+07 N" in str(info.value)


@pytest.mark.parametrize("model", ALL_MODELS)
def test_every_model_gives_finite_nonnegative_torques_or_says_which_point_it_cannot_solve(
    model: str,
) -> None:
    # The corners of the accepted ranges: each component is a finite torque >= 0, or the
    # call is an input error naming the point; never a NaN, a negative torque or another
    # exception.
    speeds = np.array([-9.99e4, -1.0, 0.0, 1e-6, 1e3, 9.99e4])
    temperatures = np.array([-40.0, 40.0, 499.0])
    loads = np.array([-9.99e7, -1e4, 0.0, 1e4, 9.99e7])
    for t in temperatures:
        for w in speeds:
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", RuntimeWarning)  # numpy's, on the way
                    r = friction_torque(
                        reference_screw(), PAO, speed=w, temperature=t, axial_load=loads,
                        model=model,
                    )  # fmt: skip
            except BallScrewInputError as exc:
                assert exc.field == "operating point", exc
                assert f"{t:g} degC" in str(exc)
                continue
            for value in r.components.values():
                assert np.all(np.isfinite(value)) and np.all(value >= 0.0)


def test_the_output_check_names_the_first_bad_point_and_the_component() -> None:
    w = np.array([[1.0, 2.0], [3.0, 4.0]])
    t = np.full((2, 2), 40.0)
    fa = np.zeros((2, 2))
    _check_solved("m", {"a": np.ones((2, 2))}, w, t, fa)  # all fine: nothing raised
    bad = np.array([[1.0, 1.0], [-2.0, np.nan]])
    with pytest.raises(BallScrewInputError) as info:
        _check_solved("m", {"a": np.ones((2, 2)), "b": bad}, w, t, fa)
    text = str(info.value)
    assert info.value.field == "operating point"
    assert f"speed {3 * 30 / math.pi:g} rpm" in text and "'b' torque there is -2" in text
    assert "(2 of 4 points)" in text


@pytest.fixture
def failing_model() -> Any:
    """A model whose numerics raise where it cannot solve (a RuntimeError, say)."""

    @register("fails-toy", title="fails", reference="none", validity="none")
    def fails(
        screw: BallScrew, lubricant: object, speed: Any, temperature: Any, axial_load: Any
    ) -> dict[str, Any]:
        raise RuntimeError("the root bracket failed")

    yield "fails-toy"
    del MODELS["fails-toy"]


def test_a_model_that_cannot_solve_says_so_as_an_input_error(failing_model: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        friction_torque(reference_screw(), PAO, speed=[10.0, 20.0], temperature=40.0,
                        model=failing_model)  # fmt: skip
    err = info.value
    assert err.field == "operating point" and "RuntimeError: the root bracket failed" in str(err)
    assert isinstance(err.__cause__, RuntimeError)  # the original kept for a debugger


# Case files, sweeps and the command line: exit 2, the user's key named.


def _case(*edits: tuple[str, str]) -> str:
    text = template()
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


@pytest.mark.parametrize(
    ("edits", "field"),
    [
        ([('ball_diameter = "6.35 mm"', 'ball_diameter = "12 mm"')], "screw.ball_diameter"),
        ([('ball_diameter = "6.35 mm"', 'ball_diameter = "10 mm"')], "screw.ball_diameter"),
        ([('preload = "2 kN"', 'preload = "1e300 N"')], "screw.preload"),
        ([("[operation]", '[operation]\nspeed = "1.7e6 rpm"')], "operation.speed"),
        ([("[operation]", '[operation]\ntemperature = "600 degC"')], "operation.temperature"),
        ([("[operation]", '[operation]\ntemperature = "40 K"')], "operation.temperature"),
        ([("[operation]", '[operation]\naxial_load = "0, 2e8 N"')], "operation.axial_load"),
    ],
)
def test_a_case_file_with_an_absurd_value_names_its_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], edits: list[tuple[str, str]], field: str
) -> None:
    text = _case(*edits)
    with pytest.raises(BallScrewInputError) as info:
        parse_case(text)
    assert info.value.field == field, info.value
    file = tmp_path / "absurd.toml"
    file.write_text(text, "utf-8")
    # case --check refuses what torque refuses, with the same message.
    for args in (["case", "--check", str(file)], ["torque", "--case", str(file)]):
        code, _, err = run(args, capsys)
        assert code == 2 and f"error: {field} = " in err and "internal error" not in err, err


def test_a_ball_as_large_as_the_lead_is_refused_in_a_sweep(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    sweep = tmp_path / "s.toml"
    sweep.write_text(
        f'case = "{SMALL_CASE.as_posix()}"\n[axes]\n"screw.ball_diameter" = "3, 25 mm"\n',
        "utf-8",
    )
    out = tmp_path / "s.zarr"
    code, _, err = run(["sweep", str(sweep), "--out", str(out)], capsys)
    assert code == 2, err
    assert "error: axes.screw.ball_diameter = " in err and "smaller than the lead (20 mm)" in err
    assert not out.exists()


@pytest.mark.parametrize(
    ("option", "value", "field"),
    [
        ("--speed", "1.7e6 rpm", "--speed"),  # as typed, naming the option
        # Refused as read, naming the option and the text as typed (no machine is there).
        ("--temperature", "501 degC", "--temperature"),
        ("--temperature", "40 K", "--temperature"),
        # The plausibility rules refuse it first, against the static rating, naming the option.
        ("--axial-load", "1e9 N", "--axial-load"),
    ],
)
def test_the_command_line_refuses_absurd_operating_points(
    capsys: pytest.CaptureFixture[str], option: str, value: str, field: str
) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no numpy warning on the way
        code, _, err = run(["torque", "--case", str(SMALL_CASE), option, value], capsys)
    assert code == 2 and f"error: {field} = " in err, err
    assert "warning" not in err and "internal error" not in err


@pytest.mark.parametrize(
    ("axis", "field"),
    [('speed = "2e6 rpm"', "axes.speed"), ('temperature = "40 K"', "axes.temperature"),
     ('axial_load = "0, 2e8 N"', "axes.axial_load")],
)  # fmt: skip
def test_a_sweep_names_its_operating_axis(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], axis: str, field: str
) -> None:
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'case = "{SMALL_CASE.as_posix()}"\n[axes]\n{axis}\n', "utf-8")
    code, _, err = run(["sweep", str(sweep), "--out", str(tmp_path / "s.zarr")], capsys)
    assert code == 2 and f"error: {field} = " in err, err


def test_an_input_error_crosses_to_a_worker_process_and_back_whole() -> None:
    # Sweeps on a Dask cluster and the web page's workers pickle what a computation raised.
    import pickle

    err = BallScrewInputError("operating point", "speed 1 rpm", "a point the model can solve")
    back = pickle.loads(pickle.dumps(err))
    assert type(back) is BallScrewInputError and str(back) == str(err)
    assert (back.field, back.value, back.allowed) == (err.field, err.value, err.allowed)
