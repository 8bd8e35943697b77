"""Friction at standstill: a measured axis at rest holds instead of chattering by ±T_f."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import back_and_forth, read_trajectory
from ballscrew.axis.standstill import noise_scatter, regularised_sign, standstill_speed
from ballscrew.errors import BallScrewInputError
from ballscrew.materials import STANDARD_GRAVITY
from cli_runner import run
from shared import PAO

RATE = 0.02  # 50 Hz, the sampling of a drive trace
NOISE = 1e-6  # 1 µm of position noise


def test_ramp_is_the_sign_outside_its_width_zero_below_half_and_linear_between() -> None:
    v = np.linspace(-3.0, 3.0, 601)
    s = regularised_sign(v, 0.5)
    outside = np.abs(v) >= 0.5
    assert np.array_equal(s[outside], np.sign(v[outside]))
    held = np.abs(v) <= 0.25
    assert np.all(s[held] == 0.0)
    between = ~outside & ~held  # from 0 at 0.25 to 1 at 0.5: 4 |v| - 1
    assert np.allclose(s[between], np.sign(v[between]) * (4.0 * np.abs(v[between]) - 1.0),
                       rtol=0, atol=1e-15)  # fmt: skip
    with pytest.raises(BallScrewInputError, match="standstill width"):
        regularised_sign(v, -1.0)


def test_noise_of_a_jerk_limited_move_is_found_beside_the_motion() -> None:
    # A move whose jerk phases are a minority of the samples: the third differences of the
    # motion vanish elsewhere, so the median sees the noise alone. 3000 samples: the MAD's
    # sampling error is about 1.65/sqrt(n) = 3 %; 8 % allows 2.5 of those.
    rng = np.random.default_rng(7)
    p = back_and_forth(0.3, 0.2, 2.0, jerk=40.0, dwell_time=1.0, cycles=4, sample_time=RATE)
    x = p.position + rng.normal(0.0, NOISE, p.time.size)
    assert noise_scatter(x) == pytest.approx(NOISE, rel=0.08)


def test_positions_on_a_grid_have_at_least_the_quantisation_noise() -> None:
    # An axis at rest on one encoder count with an occasional flip to the next: the median
    # finds no noise, the steps are whole counts of 0.1 µm: q / sqrt(12).
    x = np.zeros(200)
    x[50] = x[120] = 1e-7
    assert noise_scatter(x) == pytest.approx(1e-7 / math.sqrt(12.0), rel=1e-9)


def _noisy_vertical_trace() -> tuple[str, np.ndarray]:
    """A vertical axis: moves up and down with long dwells, 50 Hz positions with 1 µm noise."""
    rng = np.random.default_rng(3)
    p = back_and_forth(0.2, 0.1, 1.0, jerk=20.0, dwell_time=3.0, cycles=2, sample_time=RATE)
    t = np.arange(0.0, p.time[-1], RATE)
    x = np.interp(t, p.time, p.position) + rng.normal(0.0, NOISE, t.size)
    still = np.interp(t, p.time, np.abs(p.speed)) == 0.0
    # At rest, and so are both neighbours on either side: the central differences of the
    # samples beside a move see the move.
    rest = still.copy()
    for k in (1, 2):
        rest[k:] &= still[:-k]
        rest[:-k] &= still[k:]
    lines = ["time [s],position [mm]"] + [
        f"{a:.4f},{b * 1e3:.7f}" for a, b in zip(t, x, strict=True)
    ]
    return "\n".join(lines), rest


def test_torque_at_rest_stays_at_the_holding_torque_within_the_noise() -> None:
    text, rest = _noisy_vertical_trace()
    screw = reference_screw()
    axis = Axis(moving_mass=100.0, incline=math.pi / 2)
    hold = 100.0 * STANDARD_GRAVITY * screw.lead / (2.0 * math.pi)  # m g l / 2 pi = 1.56 N m
    t_f = float(friction_torque(screw, PAO, speed=0.0, temperature=40.0,
                                axial_load=100.0 * STANDARD_GRAVITY).total)  # fmt: skip
    ramped = read_trajectory(text, "trace")
    exact = read_trajectory(text, "trace", standstill_speed=0.0)
    # 1 µm at 50 Hz through the central difference: sigma_v = 35 µm/s, the width 8 x that.
    assert ramped.standstill_speed == pytest.approx(8 * NOISE / math.sqrt(2) / RATE, rel=0.1)
    at_rest = {}
    for name, profile in (("ramped", ramped), ("exact", exact)):
        r = axis_cycle(profile, screw, PAO, axis, model="catalog")
        at_rest[name] = np.abs(r.motor_torque[rest] - hold)
    # No friction below half the width, 4 sigma_v: the noise passes it at 6e-5 of the samples
    # (none of these 600), and then by little. What is left is the inertia of the noise,
    # m (l/2 pi)^2 ... = 1e-3 N m: 2 % of T_f bounds both.
    assert float(np.max(at_rest["ramped"])) < 0.02 * t_f
    # The exact sign books the full friction, one way or the other, at every sample at rest:
    # the chattering the ramp removes.
    assert float(np.mean(at_rest["exact"])) > 0.9 * t_f


def test_a_planned_profile_keeps_the_exact_sign() -> None:
    # A move is exact (no noise): its standstill width is 0, and the energy is T_f |omega|.
    p = back_and_forth(0.3, 0.2, 2.0, dwell_time=0.2)
    assert p.standstill_speed == 0.0
    r = axis_cycle(p, reference_screw(), PAO, Axis(moving_mass=50.0), model="catalog")
    drag = r.friction_torque * np.abs(r.screw_speed)
    assert np.array_equal(r.friction_power, drag)


def test_width_of_a_trace_too_short_to_tell_noise_is_zero() -> None:
    assert standstill_speed([0.0, 1e-6, 0.0], [0.0, 0.02, 0.04]) == 0.0


def test_energy_profile_says_the_width_it_took(
    tmp_path: object, capsys: pytest.CaptureFixture[str]
) -> None:
    from pathlib import Path

    text, _ = _noisy_vertical_trace()
    trace = Path(str(tmp_path)) / "trace.csv"
    trace.write_text(text)
    code, _, err = run(["energy", "--profile", str(trace), "--model", "catalog"], capsys)
    assert code == 0, err
    assert "standstill: no friction below half, the full friction from" in err
    code, _, err = run(["energy", "--profile", str(trace), "--model", "catalog",
                        "--standstill-speed", "-1 mm/s"], capsys)  # fmt: skip
    assert code == 2 and "--standstill-speed" in err
