"""The life with the makers' load factor f_w: catalogue examples and issue 34's X axis."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.axis.check import run_check
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.design.sizing import LOAD_FACTORS, life_hours, nominal_life
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case, parse_case

X_AXIS = Path(__file__).resolve().parents[1] / "data" / "x_axis_bnfn3210a5.toml"
X_MOVE = {"stroke": 0.8, "feed": 20.0 / 60.0, "acceleration": 2.0, "force": 3000.0,
          "dwell": 0.85}  # fmt: skip


def _x_check(text: str | None = None):  # type: ignore[no-untyped-def]
    case = load_case(X_AXIS) if text is None else parse_case(text)
    run = run_energy(case, profile_from_move(X_MOVE, 1), ["catalog"], run_time=600.0,
                     move=X_MOVE)  # fmt: skip
    return run_check(run)


def _life_row(result):  # type: ignore[no-untyped-def]
    return next(c for c in result.criteria if c.name.startswith("fatigue life"))


def test_misumi_worked_example_with_its_load_factor() -> None:
    # MISUMI Economy Series e-catalog 2025, "Selection of Ball Screws" (p. 1676): BSS1520,
    # C = 4400 N, mean axial load 250 N, f_w = 1.2, mean speed 2118 rpm: 24 824 h printed.
    hours = float(life_hours(nominal_life(4400.0, 250.0, load_factor=1.2), 2118.0))
    assert hours == pytest.approx(24_824, rel=2e-4)  # the print rounds (4400/300)^3


def test_load_factor_ranges_are_the_catalogues() -> None:
    # THK A15-40: smooth 1.0-1.2, normal 1.2-1.5, impact or vibration 1.5-3.0.
    assert LOAD_FACTORS == {"smooth": (1.0, 1.2), "normal": (1.2, 1.5), "impact": (1.5, 3.0)}
    with pytest.raises(BallScrewInputError, match="load_factor"):
        nominal_life(1e4, 1e3, load_factor=0.9)


def _hand_life_hours(f_w: float) -> float:
    """ISO 3408-5 over the move's six phases, by hand (no sampling of the cycle)."""
    fpr, ca, mass, accel, feed = 2360.0, 47_200.0, 500.0, 2.0, 20.0 / 60.0
    ramp = feed**2 / (2 * accel)  # distance of each ramp [m]
    cruise = 0.8 - 2 * ramp
    # (axial force on the nut, distance): out with the cut, back without it.
    phases = [(mass * accel + 3000, ramp), (3000.0, cruise), (3000 - mass * accel, ramp),
              (-mass * accel, ramp), (0.0, cruise), (mass * accel, ramp)]  # fmt: skip
    halves: list[list[float]] = [[], []]
    dist = [d for _, d in phases]
    for f, _ in phases:
        loaded = fpr * (1 + abs(f) / (2**1.5 * fpr)) ** 1.5 if abs(f) < 2**1.5 * fpr else abs(f)
        relieved = loaded - abs(f)
        halves[0].append(loaded if f >= 0 else relieved)
        halves[1].append(relieved if f >= 0 else loaded)
    lives = []
    for h in halves:
        fm = (sum(x**3 * d for x, d in zip(h, dist, strict=True)) / sum(dist)) ** (1 / 3)
        lives.append((ca / (f_w * fm)) ** 3 * 1e6)
    revs = sum(v ** (-10 / 9) for v in lives) ** -0.9
    cycle_time = 2 * (0.8 / feed + feed / accel) + 2 * 0.85
    rpm = 2 * 0.8 / 0.01 / cycle_time * 60
    return revs / rpm / 60


def test_x_axis_life_with_f_w_12_is_not_ok() -> None:
    # Issue 34: THK BNFN3210A-5, 500 kg, 1.2 m fixed-supported, 3 kN cut: 26 447 h OK
    # without f_w becomes 15 305 h NOT OK with f_w = 1.2.
    result = _x_check()
    row = _life_row(result)
    hand = _hand_life_hours(1.2)
    # 1 %: the cycle is sampled (ramps of 28 mm between samples), the hand spectrum is exact.
    assert row.value == pytest.approx(hand, rel=1e-2)
    assert row.value == pytest.approx(15_300, rel=5e-3)
    assert row.verdict == "NOT OK" and row.limit == 20_000
    assert "f_w = 1.2 (given" in row.source and "A15-40" in row.source
    assert result.life["load_factor"] == 1.2 and result.life["load_factor_source"] == "given"


def test_x_axis_without_f_w_takes_normal_running_and_says_so() -> None:
    # Without the key the life is sized at f_w = 1.2, where THK's normal running begins
    # (A15-40), not at ISO's own (optimistic) life: the X axis is NOT OK either way.
    text = X_AXIS.read_text(encoding="utf-8").replace("load_factor = 1.2\n", "")
    result = _x_check(text)
    row = _life_row(result)
    assert row.value == pytest.approx(_hand_life_hours(1.2), rel=1e-2)
    assert row.verdict == "NOT OK" and "f_w = 1.2 (default" in row.source
    assert any("load factor f_w = 1.2 (default" in a and "check.load_factor" in a
               for a in result.assumptions)  # fmt: skip
    assert result.life["load_factor_source"] == "default"
    # ISO's own life, f_w = 1 given: 1.2^3 longer, the 26 447 h.
    iso = _life_row(_x_check(X_AXIS.read_text(encoding="utf-8").replace(
        "load_factor = 1.2", "load_factor = 1")))  # fmt: skip
    assert iso.value == pytest.approx(_hand_life_hours(1.0), rel=1e-2)
    assert iso.value == pytest.approx(26_447, rel=5e-3)
    assert iso.value / row.value == pytest.approx(1.2**3, rel=1e-9)


@pytest.mark.parametrize("bad", ["0.8", "3.5", "nan"])
def test_load_factor_out_of_range_is_refused(bad: str) -> None:
    text = X_AXIS.read_text(encoding="utf-8").replace("load_factor = 1.2", f"load_factor = {bad}")
    with pytest.raises(BallScrewInputError, match=r"check\.load_factor"):
        parse_case(text)


def test_assumed_load_factor_is_labelled_assumed() -> None:
    text = X_AXIS.read_text(encoding="utf-8").replace(
        "load_factor = 1.2", 'load_factor = { value = 1.3, assumed = "normal running" }'
    )
    row = _life_row(_x_check(text))
    assert "f_w = 1.3 (assumed" in row.source
    assert math.isfinite(row.value) and np.isfinite(row.utilisation)
