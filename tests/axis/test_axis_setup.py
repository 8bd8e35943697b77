"""What a case's [axis] section leaves out, and whether a weight back-drives the screw."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.axis.energy import Axis, weight_back_driving
from ballscrew.axis.setup import axis_setup, shaft_inertia
from ballscrew.materials import STANDARD_GRAVITY
from shared import PAO

OIL = PAO


def test_shaft_inertia_is_the_integral_of_r_squared_dm() -> None:
    # J = integral of r^2 dm over a solid cylinder, dm = rho L 2 pi r dr, integrated
    # numerically on 20001 radii (trapezoidal error ~ (R/n)^2, 1e-8 relative), for three
    # shafts at once (broadcast over diameter and length).
    d = np.array([0.016, 0.04, 0.08])
    length = np.array([0.5, 1.0, 2.5])
    r = np.linspace(0.0, 1.0, 20001)[None, :] * (d[:, None] / 2)
    integrand = r**2 * 7850.0 * length[:, None] * 2 * math.pi * r
    numeric = np.sum(0.5 * (integrand[:, 1:] + integrand[:, :-1]) * np.diff(r, axis=1), axis=1)
    np.testing.assert_allclose(shaft_inertia(d, length), numeric, rtol=1e-7)
    # The density is a parameter: aluminium (2700 kg/m³) scales it linearly.
    assert float(shaft_inertia(0.04, 1.0, 2700.0)) == pytest.approx(
        float(shaft_inertia(0.04, 1.0)) * 2700.0 / 7850.0, rel=1e-14
    )


def test_setup_fills_the_gaps_and_says_so() -> None:
    s = reference_screw()
    # Nothing given: the length is estimated from the travel, the inertia from that length,
    # the bearings are left out; a note for each.
    bare = axis_setup(s, {"moving_mass": 200.0}, {}, 0.3)
    assert bare.node.screw_length == pytest.approx(0.6, abs=1e-3)  # see estimated_screw_length
    # 40 mm over 0.6 m of steel: pi 7850 0.6 0.04^4 / 32 = 1.184e-3 kg m^2.
    assert bare.axis.screw_inertia == pytest.approx(1.184e-3, rel=1e-3)
    text = "\n".join(bare.notes)
    assert "axis.screw_length = 600 mm (estimated" in text
    assert (
        "axis.screw_inertia = 0.00118 kg*m^2 (a solid steel shaft of the pitch diameter "
        "40 mm over 600 mm" in text
    )
    assert "support bearings: not counted" in text
    assert "machine_resistance: none" in text
    # The bearing span is the length when given; a given inertia and length are kept.
    spanned = axis_setup(s, {"moving_mass": 1.0, "bearing_span": 1.2}, {}, 0.3)
    assert spanned.node.screw_length == 1.2
    assert "axis.screw_length = 1200 mm (the bearing span" in spanned.notes[0]
    assert spanned.axis.screw_inertia == pytest.approx(2 * 1.184e-3, rel=1e-3)
    given = axis_setup(
        s, {"moving_mass": 1.0, "screw_inertia": 0.0, "bearing_bore": 0.03},
        {"screw_length": 0.9, "machine_resistance": 2.0}, 0.3,
    )  # fmt: skip
    assert given.axis.screw_inertia == 0.0 and given.node.screw_length == 0.9
    assert given.node.machine_resistance == 2.0
    assert not any("screw_inertia" in n or "screw_length" in n for n in given.notes)
    assert any("SKF's simplified estimate" in n for n in given.notes)
    palmgren = axis_setup(
        s, {"moving_mass": 1.0, "bearing_bore": 0.03, "bearing_outer_diameter": 0.062,
            "bearing_static_rating": 4e4, "bearing_type": "screw-support (ZKLN, ZKLF)"},
        {"screw_length": 0.9}, 0.3,
    )  # fmt: skip
    assert any("Palmgren's model (screw-support (ZKLN, ZKLF)" in n for n in palmgren.notes)


@pytest.mark.parametrize("mass", [10.0, 50.0, 500.0])
def test_a_weight_back_drives_when_its_torque_beats_the_friction(mass: float) -> None:
    # Motor off, a vertical axis: the weight m g pushes the nut, which turns the screw with
    # the torque m g l / 2 pi; it does when that torque exceeds the screw's friction torque
    # at a creep speed under that load. 10 kg (0.16 N m) is held by the 2 kN preload's drag
    # (about 0.58 N m); 500 kg (7.8 N m) is not.
    s = reference_screw()
    axis = Axis(moving_mass=mass, incline=math.pi / 2)
    eta = weight_back_driving(s, OIL, axis, temperature=20.0)
    weight = mass * STANDARD_GRAVITY
    friction = float(friction_torque(s, OIL, speed=0.1, temperature=20.0, axial_load=weight).total)
    drive = weight * s.lead / (2 * math.pi)
    assert (eta > 0.0) == (drive > friction)
    assert eta == pytest.approx((drive - friction) / drive, rel=1e-9)
    if mass == 10.0:
        assert eta < 0.0
    if mass == 500.0:
        assert eta > 0.0
    # Hanging the other way (the axis inclined down) is the same weight on the nut.
    down = weight_back_driving(s, OIL, Axis(moving_mass=mass, incline=-math.pi / 2),
                               temperature=20.0)  # fmt: skip
    assert down == pytest.approx(eta, rel=1e-12)


def test_no_weight_along_the_axis_means_no_verdict() -> None:
    s = reference_screw()
    assert math.isnan(weight_back_driving(s, OIL, Axis(moving_mass=200.0)))
    assert math.isnan(weight_back_driving(s, OIL, Axis(moving_mass=0.0, incline=1.0)))
    # A 50 g slide still has a weight (0.49 N): the screw holds it, a number, not NaN.
    assert weight_back_driving(s, OIL, Axis(moving_mass=0.05, incline=math.pi / 2)) < -10.0


@pytest.mark.slow
def test_energy_command_states_the_gaps_and_the_weight(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from ballscrew.cli import main

    case = tmp_path / "z.toml"
    base = (
        '[screw]\npitch_diameter = "32 mm"\nlead = "5 mm"\nball_diameter = "3.175 mm"\n'
        'preload = "1.2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
        '[operation]\ntemperature = "25 degC"\n[axis]\nmoving_mass = "120 kg"\n'
        'screw_length = "800 mm"\ndn_limit = "150000 mm*rpm"\n'
    )
    move_text = "stroke=400 mm, feed=15 m/min, acceleration=3 m/s^2"
    case.write_text(base + 'incline = "90 deg"\n', "utf-8")
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--move", move_text, "--json", "-"])
    assert info.value.code == 0
    captured = capsys.readouterr()
    payload = json.loads(captured.out)
    assert payload["axis"]["screw_inertia"] == pytest.approx(float(shaft_inertia(0.032, 0.8)))
    assert "axis.screw_inertia = 0.000646 kg*m^2" in captured.err
    assert payload["weight_reverse_efficiency"] > 0.0
    assert "hold the axis with a brake" in captured.err  # the table goes to stderr with -
    # Horizontal: no verdict, written as null (strict JSON has no NaN).
    case.write_text(base, "utf-8")
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--move", move_text, "--json", "-"])
    out = capsys.readouterr().out

    def refuse(word: str) -> None:
        raise AssertionError(f"{word} in strict JSON")

    flat = json.loads(out, parse_constant=refuse)
    assert flat["weight_reverse_efficiency"] is None


def test_a_light_weight_is_held_but_the_screw_is_not_self_locking(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 27: 5 kg on a vertical 32 x 5 axis was called "self-locking". The preload's
    # drag holds it (the reverse efficiency is negative), but the lead angle (2.8 deg)
    # is far above a ball screw's friction angle: a heavier load turns the screw.
    from ballscrew.cli import main

    case = tmp_path / "v.toml"
    case.write_text(
        '[screw]\npitch_diameter = "32 mm"\nlead = "5 mm"\nball_diameter = "3.175 mm"\n'
        'preload = "1,2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
        '[axis]\nmoving_mass = "5 kg"\nincline = "90 deg"\nscrew_length = "800 mm"\n',
        "utf-8",
    )
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--move",
              "stroke=200 mm, feed=10 m/min, acceleration=2 m/s^2", "--json", "-"])  # fmt: skip
    assert info.value.code == 0
    captured = capsys.readouterr()
    payload = json.loads(captured.out)
    assert payload["weight_reverse_efficiency"] < 0.0 and payload["self_locking"] is False
    assert "holds at this load" in captured.err and "keep a brake" in captured.err
    assert "Not self-locking" in captured.err and "; self-locking" not in captured.err


@pytest.mark.parametrize(("lead_mm", "mu"), [(10.0, 0.003), (5.0, 0.1), (20.0, 0.1), (2.0, 0.05)])
def test_self_locking_is_the_friction_angle_against_the_lead_angle(
    lead_mm: float, mu: float
) -> None:
    # The catalogue model's load term is F l/2pi (1/eta - 1) with THK's eta: self-locking
    # exactly when rho = atan(mu) reaches the lead angle beta, whatever the preload.
    from ballscrew.axis.energy import self_locking

    # A ball smaller than the lead (1/16 in on 2 mm, 1/8 in on 5 mm): the rule needs no ball.
    ball = {2.0: 1.5875e-3, 5.0: 3.175e-3}.get(lead_mm, 6.35e-3)
    screw = reference_screw().replace(lead=lead_mm * 1e-3, ball_diameter=ball)
    beta, rho = screw.lead_angle, math.atan(mu)
    got = self_locking(screw, "PAO ISO VG 68", model="catalog", friction_coefficient=mu)
    assert got == (rho >= beta)


def test_a_reversed_or_too_long_force_window_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 27: force_from=250 mm, force_to=50 mm silently dropped the process force.
    from ballscrew.cli import main

    case = tmp_path / "h.toml"
    case.write_text(
        '[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "6.35 mm"\n'
        'preload = "2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
        '[axis]\nmoving_mass = "200 kg"\n',
        "utf-8",
    )
    move = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"
    for window, words in (
        ("force_from=250 mm, force_to=50 mm", "force never acts"),
        ("force_from=50 mm, force_to=350 mm", "inside the stroke, 300 mm"),
    ):
        with pytest.raises(SystemExit) as info:
            main(["energy", "--case", str(case), "--move", f"{move}, {window}"])
        err = capsys.readouterr().err
        assert info.value.code == 2 and "--move force_from, force_to" in err and words in err


def test_energy_prints_the_half_nut_lift_off(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 27: the lift-off during acceleration was only in --json and the report.
    from ballscrew.cli import main

    case = tmp_path / "l.toml"
    case.write_text(
        '[screw]\npitch_diameter = "32 mm"\nlead = "5 mm"\nball_diameter = "3.175 mm"\n'
        'preload = "1 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
        '[axis]\nmoving_mass = "200 kg"\nscrew_length = "800 mm"\n',
        "utf-8",
    )
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--model", "catalog", "--move",
              "stroke=200 mm, feed=10 m/min, acceleration=20 m/s^2"])  # fmt: skip
    err = capsys.readouterr().err
    # 200 kg at 20 m/s^2 is 4 kN against 2^1.5 x 1 kN = 2.83 kN: lift-off, said once.
    assert info.value.code == 0 and err.count("lifts off") == 1
