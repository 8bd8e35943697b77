"""Energy of a feed axis over a motion profile: checks computed another way."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import Profile, back_and_forth, move
from ballscrew.materials import STANDARD_GRAVITY
from shared import PAO

OIL = PAO
FAST = 150_000.0  # d·n limit of a high-speed nut [mm·rpm]: 0.5 m/s on a 10 mm lead is 3000 rpm


def _axis_case(folder: object, more: str) -> Path:
    """The 40 x 10 mm screw in mineral oil as a case file in ``folder``, with ``more`` tables."""
    case = Path(str(folder)) / "axis.toml"
    case.write_text(
        '[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "6.35 mm"\n'
        'preload = "2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n' + more
    )
    return case


def _steady_run() -> Profile:
    """2 s at a constant 0.25 m/s against 1.5 kN (1500 rpm on a 10 mm lead)."""
    t = np.linspace(0.0, 2.0, 11)
    v = np.full_like(t, 0.25)
    zero = np.zeros_like(t)
    return Profile(t, v * t, v, zero, zero + 1500.0)


def test_constant_speed_energy_is_torque_times_speed_times_time() -> None:
    # 2 s at 0.25 m/s (1500 rpm on a 10 mm lead) and 1.5 kN: E = T omega t.
    p = _steady_run()
    s = reference_screw()
    r = axis_cycle(p, s, OIL, Axis(moving_mass=0.0))
    omega = 2 * math.pi * 0.25 / s.lead
    torque = float(friction_torque(s, OIL, speed=omega, temperature=40.0, axial_load=1500.0).total)
    assert r.friction_energy == pytest.approx(torque * omega * 2.0, rel=1e-12)
    assert r.friction_energy_back == 0.0
    # The nut pushes the process force over 0.5 m.
    assert r.load_work == pytest.approx(1500.0 * 0.5, rel=1e-12)


def test_symmetric_cycle_does_no_net_work_on_a_horizontal_load() -> None:
    c = back_and_forth(0.3, 0.5, 2.0, dwell_time=0.2, cycles=2)
    r = axis_cycle(c, reference_screw(), OIL, Axis(moving_mass=200.0, dn_limit=FAST))
    peak = 200.0 * 2.0 * 0.0625  # kinetic energy at the feed: 25 J
    assert abs(r.load_work) < 1e-9 * peak
    # Out and back are mirror images: the same friction energy each way.
    assert r.friction_energy_out == pytest.approx(r.friction_energy_back, rel=1e-9)
    assert r.friction_energy == pytest.approx(
        r.friction_energy_out + r.friction_energy_back, rel=1e-12
    )


def test_rms_and_peak_motor_torque_of_a_frictionless_inertial_move() -> None:
    # No friction (catalogue rule with no preload and mu = 0): the motor only
    # accelerates the mass, T = m a l / 2 pi during 2 t_a of the move, 0 while
    # cruising, so RMS = T sqrt(2 t_a / t). Sampled steps: error ~ dt / t_a.
    s = reference_screw().replace(nut="single", preload=0.0)
    p = move(0.3, 0.5, 2.0, sample_time=1e-4)
    r = axis_cycle(p, s, OIL, Axis(moving_mass=200.0, dn_limit=FAST), model="catalog",
                   friction_coefficient=0.0)  # fmt: skip
    t_acc = 200.0 * 2.0 * s.lead / (2 * math.pi)
    assert r.peak_motor_torque == pytest.approx(t_acc, rel=1e-12)
    assert r.rms_motor_torque == pytest.approx(t_acc * math.sqrt(2 * 0.25 / 0.85), rel=1e-3)
    assert r.friction_energy == 0.0


def test_gravity_gear_and_inertias_enter_the_motor_torque() -> None:
    # A vertical axis at rest: the motor holds m g l / 2 pi / i (friction is
    # 0 at rest in the catalogue rule's direction sign); inertias add
    # (J_s + J_c) alpha / i + J_m i alpha while accelerating.
    s = reference_screw().replace(nut="single", preload=0.0)
    t = np.linspace(0.0, 1.0, 5)
    zero = np.zeros_like(t)
    rest = Profile(t, zero, zero, zero, zero)
    axis = Axis(moving_mass=50.0, gear_ratio=2.0, incline=math.pi / 2)
    r = axis_cycle(rest, s, OIL, axis, model="catalog")
    hold = 50.0 * STANDARD_GRAVITY * s.lead / (2 * math.pi) / 2.0
    np.testing.assert_allclose(r.motor_torque, hold, rtol=1e-12)
    acc = Profile(t, zero, zero, zero + 1.0, zero)
    axis = Axis(moving_mass=0.0, screw_inertia=1e-3, coupling_inertia=2e-4, motor_inertia=5e-4,
                gear_ratio=2.0)  # fmt: skip
    r = axis_cycle(acc, s, OIL, axis, model="catalog", friction_coefficient=0.0)
    alpha = 2 * math.pi / s.lead
    np.testing.assert_allclose(r.motor_torque, 1.2e-3 * alpha / 2 + 5e-4 * 2 * alpha, rtol=1e-12)


def test_energy_command_json_and_errors(
    tmp_path: object, capsys: pytest.CaptureFixture[str]
) -> None:
    import json

    from ballscrew.cli import main

    case = _axis_case(
        tmp_path,
        '[operation]\ntemperature = "40 degC"\n[axis]\nmoving_mass = "200 kg"\n'
        'dn_limit = "150000 mm*rpm"\n',
    )
    move_text = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--move", move_text, "--cycles", "2", "--json", "-"])
    assert info.value.code == 0
    payload = json.loads(capsys.readouterr().out)
    r = payload["models"]["complete"]
    # The same as the API on the same cycle.
    c = back_and_forth(0.3, 0.5, 2.0, cycles=2, process_force=2000.0)
    from ballscrew.io.case import load_case

    loaded = load_case(case)
    api = axis_cycle(c, loaded.screw, loaded.lubricant, Axis(moving_mass=200.0, dn_limit=FAST))
    assert r["friction_energy_J"] == pytest.approx(api.friction_energy, rel=1e-12)
    assert r["load_work_J"] == pytest.approx(2 * 2000.0 * 0.3, rel=1e-3)
    for bad, words in [("stroke=300, feed=30 m/min, acceleration=2 m/s^2", "bare number"),
                       ("stroke=300 mm, feed=30 m/min", "acceleration"),
                       ("stroke=300 mm, speed=1 m/s, acceleration=2 m/s^2", "keys")]:  # fmt: skip
        with pytest.raises(SystemExit) as info:
            main(["energy", "--case", str(case), "--move", bad])
        assert info.value.code == 2 and words in capsys.readouterr().err


@pytest.mark.parametrize(("lead_mm", "mu"), [(10.0, 0.003), (10.0, 0.01), (5.0, 0.1), (20.0, 0.1)])
def test_back_driving_decided_as_the_catalogue_does(lead_mm: float, mu: float) -> None:
    # THK's reverse efficiency tan(beta - rho)/tan(beta) (rho = atan mu): with the
    # catalogue model and no preload, 1 - 2 pi T/(F l) = 2 - 1/eta agrees to
    # first order in mu (difference ~ mu^2 / tan^2 beta), and both call the
    # screw self-locking when the lead angle is below the friction angle.
    from ballscrew.axis.energy import reverse_efficiency

    ball = 3.175e-3 if lead_mm < 6.35 else 6.35e-3  # smaller than the lead
    s = reference_screw().replace(nut="single", preload=0.0, lead=lead_mm * 1e-3,
                                  ball_diameter=ball)  # fmt: skip
    r = friction_torque(s, OIL, speed=10.0, temperature=40.0, axial_load=3000.0,
                        model="catalog", friction_coefficient=mu)  # fmt: skip
    beta, rho = s.lead_angle, math.atan(mu)
    thk = math.tan(beta - rho) / math.tan(beta)
    ours = float(reverse_efficiency(r, s.lead))
    assert ours == pytest.approx(thk, abs=2 * (mu / math.tan(beta)) ** 2)
    assert (ours > 0) == (thk > 0) == (beta > rho)


def test_energy_command_reports_the_temperature_and_takes_a_profile(
    tmp_path: object, capsys: pytest.CaptureFixture[str]
) -> None:
    import json

    from ballscrew.axis.thermal import ThermalNode, steady_temperature
    from ballscrew.cli import main

    case = _axis_case(
        tmp_path, '[axis]\nmoving_mass = "200 kg"\nscrew_length = "1 m"\nnut_mass = "3 kg"\n'
    )
    profile = tmp_path / "p.csv"  # type: ignore[operator]
    profile.write_text("time [s],speed [m/min]\n0,0\n0.25,30\n0.85,30\n1.1,0\n")
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), "--profile", str(profile), "--run-time", "2 h",
              "--json", "-"])  # fmt: skip
    assert info.value.code == 0
    r = json.loads(capsys.readouterr().out)["models"]["complete"]
    # Two hours is many time constants: the node has reached its steady temperature.
    from ballscrew.axis.motion import read_trajectory
    from ballscrew.io.case import load_case

    loaded = load_case(case)
    steady = steady_temperature(read_trajectory(profile.read_text()), loaded.screw,
                                loaded.lubricant, Axis(moving_mass=200.0),
                                ThermalNode(screw_length=1.0, nut_mass=3.0))  # fmt: skip
    assert r["final_temperature_C"] == pytest.approx(steady.temperature, abs=0.05)
    assert r["steady_temperature_C"] == pytest.approx(steady.temperature, rel=1e-9)
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case)])
    assert info.value.code == 2 and "exactly one of --move and --profile" in capsys.readouterr().err


def test_support_bearing_friction_is_reported_and_driven() -> None:
    # SKF's simplified estimate, M = mu P d / 2 (angular-contact single row:
    # mu = 0.002): at 0.25 m/s and 1.5 kN for 2 s on a 25 mm bore,
    # E = 0.5 * 0.002 * 1500 * 0.025 * omega * 2 s, and the motor supplies it.
    p = _steady_run()
    s = reference_screw()
    without = axis_cycle(p, s, OIL, Axis(moving_mass=0.0))
    with_b = axis_cycle(p, s, OIL, Axis(moving_mass=0.0, bearing_bore=0.025))
    omega = 2 * math.pi * 0.25 / s.lead
    m_b = 0.5 * 0.002 * 1500.0 * 0.025
    assert with_b.bearing_energy == pytest.approx(m_b * omega * 2.0, rel=1e-12)
    assert without.bearing_energy == 0.0
    np.testing.assert_allclose(with_b.motor_torque - without.motor_torque, m_b, rtol=1e-12)
    assert with_b.friction_energy == without.friction_energy  # the screw's, reported apart


@pytest.mark.slow
def test_energy_report_files_are_complete_and_reproducible(
    tmp_path: object, capsys: pytest.CaptureFixture[str]
) -> None:
    from ballscrew.cli import main

    case = _axis_case(tmp_path, '[axis]\nmoving_mass = "200 kg"\nbearing_bore = "30 mm"\n')
    outputs = []
    for k in range(2):
        out = tmp_path / f"r{k}"  # type: ignore[operator]
        with pytest.raises(SystemExit) as info:
            move = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"
            main(["energy", "--case", str(case), "--move", move, "--out", str(out),
                  "--steady-speeds", "1000, 2000 rpm"])  # fmt: skip
        assert info.value.code == 0
        files = sorted(p.relative_to(out) for p in out.rglob("*") if p.is_file())
        outputs.append({f: (out / f).read_bytes() for f in files})
    assert outputs[0] == outputs[1]
    names = {str(f) for f in outputs[0]}
    for key in ("motion", "power", "energy"):
        assert {f"figures/{key}.png", f"figures/{key}.svg", f"data/{key}.csv"} <= names
    report = outputs[0][Path("report.md")].decode()
    # Every file the Markdown links exists.
    import re

    for link in re.findall(r"\]\(([^)]+)\)", report):
        assert link in names, link
    # The steady table has its own CSV; no Python repr of it leaks into the report.
    steady = outputs[0][Path("data/steady.csv")].decode().splitlines()
    assert steady[0] == "model,speed [rpm],steady temperature [degC],torque [N*m],power [W]"
    assert len(steady) == 3
    assert "{" not in report and "{" not in outputs[0][Path("data/summary.csv")].decode()
    # Issue 40: the steady running is in the report too, as a table and a figure.
    assert "## Continuous running" in report and "figures/steady.png" in names
    assert report.count("| complete | 1000 |") == 1 and report.count("| complete | 2000 |") == 1
    # The summary names its quantities in words with units: no key, no nan, no False.
    from ballscrew.report.energy import SUMMARY

    summary = report[report.index("| quantity |") : report.index("![")]
    for key, label, _ in SUMMARY:
        assert key not in summary and label in summary, key
    assert "peak motor torque [N*m]" in summary
    assert not re.search(r"\bnan\b|\bNone\b|\bTrue\b|\bFalse\b", summary), summary
    # A horizontal axis has no weight to hold: said in words.
    assert "not applicable (no weight to hold" in summary


def _energy_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], axis_line: str, args: list[str]
) -> tuple[Path, dict[str, Any], Any]:
    """Run ``ballscrew energy --json -`` on the 40 x 10 axis with one more [axis] line."""
    import json

    from ballscrew.cli import main

    case = _axis_case(tmp_path, f'[axis]\nmoving_mass = "200 kg"\n{axis_line}\n')
    with pytest.raises(SystemExit) as info:
        main(["energy", "--case", str(case), *args, "--json", "-"])
    assert info.value.code == 0
    captured = capsys.readouterr()
    return case, json.loads(captured.out), captured


def test_energy_json_has_the_documented_keys_and_states_its_assumptions(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from ballscrew.axis.thermal import estimated_screw_length

    case, payload, captured = _energy_json(
        tmp_path, capsys, 'bearing_bore = "30 mm"',
        ["--move", "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2", "--steady-speeds",
         "500, 1500 rpm"],
    )  # fmt: skip
    for key in ("friction_energy_J", "bearing_energy_J", "constant_efficiency_energy_J",
                "peak_motor_torque_Nm", "rms_motor_torque_Nm", "forward_efficiency",
                "reverse_efficiency", "final_temperature_C"):  # fmt: skip
        assert payload[key] == payload["models"]["complete"][key], key
    assert payload["bearing_energy_J"] > 0.0
    # The split by mechanism adds up to the screw friction energy (the trapezoidal rule is
    # linear in the integrand, so to round-off).
    parts = payload["friction_energy_by_mechanism_J"]
    assert {"rolling", "helix_slip", "ball_ball"} <= set(parts)
    assert sum(parts.values()) == pytest.approx(payload["friction_energy_J"], rel=1e-9)
    assert parts["helix_slip"] > 0.0
    # No screw length given: the heat balance uses the estimate and says so.
    from ballscrew.io.case import load_case

    assert payload["thermal"]["screw_length"] == pytest.approx(
        estimated_screw_length(load_case(case).screw, 0.3), rel=1e-12
    )
    assert "axis.screw_length" in captured.err and "estimated" in captured.err
    # 30 m/min is 3000 rpm, d·n 120 000: past the default limit, said once.
    assert captured.err.count("d·n = 120,000") == 1
    steady = payload["models"]["complete"]["steady_at_speed"]
    assert steady["speed_rpm"] == pytest.approx([500.0, 1500.0])
    assert steady["temperature_C"][1] > steady["temperature_C"][0] > 20.0


def test_heat_balance_takes_the_bearing_span_as_the_screw_length(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    _, payload, captured = _energy_json(
        tmp_path, capsys, 'bearing_span = "1.2 m"',
        ["--move", "stroke=300 mm, feed=10 m/min, acceleration=2 m/s^2"],
    )  # fmt: skip
    # The screw between its supports is at least the span: a 0.6 m estimate from the stroke
    # would halve the cooled surface of a screw the user has described.
    assert payload["thermal"]["screw_length"] == 1.2
    assert "screw_length = 1200 mm (the bearing span" in captured.err


def test_load_work_of_a_vertical_lift_is_the_force_times_speed_integral() -> None:
    # A vertical axis accelerating up from rest at 1 m/s² for 0.5 s while cutting against
    # 300 N: the work on the load, computed another way as the integral of F v dt with
    # F = m (a + g) + F_p (g = 9.80665 m/s², standard gravity) on a fine grid, equals
    # 1/2 m v^2 + m g h + F_p h. Tolerance: the fine grid's trapezoidal error (1e-8).
    from ballscrew.axis.energy import reverse_efficiency

    t = np.linspace(0.0, 0.5, 5001)
    a = np.ones_like(t)
    p = Profile(t, 0.5 * t**2, t, a, np.full_like(t, 300.0))
    axis = Axis(moving_mass=20.0, incline=math.pi / 2, dn_limit=FAST)
    r = axis_cycle(p, reference_screw(), OIL, axis, model="catalog")
    f = 20.0 * (1.0 + 9.80665) + 300.0
    by_force = float(np.sum(0.5 * (f * t[1:] + f * t[:-1]) * np.diff(t)))
    closed = 0.5 * 20.0 * 0.5**2 + 20.0 * 9.80665 * 0.125 + 300.0 * 0.125
    assert r.load_work == pytest.approx(closed, rel=1e-12)
    assert r.load_work == pytest.approx(by_force, rel=1e-8)
    np.testing.assert_allclose(r.axial_force, f, rtol=1e-12)
    # No axial load: no back-driving efficiency to speak of.
    idle = Profile(t, 0.5 * t**2, t, a, np.zeros_like(t))
    still = axis_cycle(idle, reference_screw(), OIL, Axis(moving_mass=0.0, dn_limit=FAST),
                       model="catalog")  # fmt: skip
    assert np.isnan(reverse_efficiency(still.friction, reference_screw().lead)).all()
    # A load of 0.5 N is still a load: its back-driving efficiency is a (very negative)
    # number, 1 - 2 pi T / (F l), not "no load".
    light = Profile(t, 0.5 * t**2, t, a, np.full_like(t, 0.5))
    weak = axis_cycle(light, reference_screw(), OIL, Axis(moving_mass=0.0, dn_limit=FAST),
                      model="catalog")  # fmt: skip
    eta = reverse_efficiency(weak.friction, reference_screw().lead)
    expected = 1.0 - 2 * math.pi * weak.friction.total / (0.5 * reference_screw().lead)
    np.testing.assert_allclose(eta, expected, rtol=1e-12)


def test_load_work_of_a_lift_caught_in_motion() -> None:
    # The same lift recorded from t = 0.25 s to 0.5 s: it starts at 0.25 m/s and 31.25 mm,
    # and ends at 0.5 m/s and 125 mm. The work on the load is the change of kinetic and
    # potential energy plus the process force's work, 1/2 m (v1^2 - v0^2) + (m g + F_p)
    # (x1 - x0); computed another way as the integral of F v dt (tolerance: the fine
    # grid's trapezoidal error, 1e-8).
    t = np.linspace(0.25, 0.5, 5001)
    p = Profile(t, 0.5 * t**2, t, np.ones_like(t), np.full_like(t, 300.0))
    axis = Axis(moving_mass=20.0, incline=math.pi / 2, dn_limit=FAST)
    r = axis_cycle(p, reference_screw(), OIL, axis, model="catalog")
    f = 20.0 * (1.0 + 9.80665) + 300.0
    by_force = float(np.sum(0.5 * (f * t[1:] + f * t[:-1]) * np.diff(t)))
    closed = 0.5 * 20.0 * (0.25 - 0.0625) + (20.0 * 9.80665 + 300.0) * (0.125 - 0.03125)
    assert r.load_work == pytest.approx(closed, rel=1e-12)
    assert r.load_work == pytest.approx(by_force, rel=1e-8)


def test_slow_moves_split_their_energy_by_direction_and_gear_the_motor_speed() -> None:
    # 1 mm/s out then back on a 10 mm lead: omega = 0.63 rad/s, below 1 rad/s. Every joule
    # is out or back; the motor turns i times the screw.
    t = np.linspace(0.0, 2.0, 201)
    v = np.where(t < 1.0, 1e-3, -1e-3)
    zero = np.zeros_like(t)
    p = Profile(t, np.cumsum(v) * 0.01, v, zero, zero)
    r = axis_cycle(p, reference_screw(), OIL, Axis(moving_mass=0.0, gear_ratio=3.0))
    assert r.friction_energy_out > 0.0 and r.friction_energy_back > 0.0
    assert r.friction_energy_out + r.friction_energy_back == pytest.approx(
        r.friction_energy, rel=1e-12
    )
    np.testing.assert_allclose(r.motor_speed, 3.0 * 2 * math.pi * v / 0.01, rtol=1e-12)


@pytest.mark.parametrize("incline, ok", [(math.pi / 2, True), (-math.pi / 2, True),
                                         (1.58, False), (-1.58, False)])  # fmt: skip
def test_incline_from_straight_down_to_straight_up(incline: float, ok: bool) -> None:
    from ballscrew.errors import BallScrewInputError

    if ok:
        assert Axis(moving_mass=1.0, incline=incline).incline == incline
    else:
        with pytest.raises(BallScrewInputError, match="incline"):
            Axis(moving_mass=1.0, incline=incline)
