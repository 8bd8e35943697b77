"""``ballscrew contour`` says a loop that cannot run, and bounds its work (issue 52's reproducers).

The numbers checked come from outside the code: the motor speed and the
centripetal acceleration of the feed from the case's lead and the circle
(v/l, v^2/R), the samples from the circle's length over the feed and the
sampling time, the verdicts from the margins' signs.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from ballscrew.io.case import load_case
from ballscrew.servo import contour_samples, run_contour
from ballscrew.servo.verdict import MAX_SAMPLES, Check, verdict
from cli_runner import run
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"
BASE = ["contour", "--case", str(EXAMPLE)]


def _refused(args: list[str], capsys: pytest.CaptureFixture[str], tmp_path: Path) -> dict:  # type: ignore[type-arg]
    """Run, expect exit 2 with one error line and no circle; return the JSON."""
    out_json = tmp_path / "c.json"
    code, out, err = run([*BASE, *args, "--json", str(out_json)], capsys)
    assert code == 2, err
    errors = [line for line in err.splitlines() if line.startswith("error:")]
    assert len(errors) == 1 and "NOT OK, no circle drawn" in errors[0], err
    assert "Circular test" not in out  # no circle printed
    doc = json.loads(out_json.read_text())
    assert doc["verdict"] == "NOT OK" and doc["circles"] == [] and doc["reversals"] == []
    return doc  # type: ignore[no-any-return]


def test_an_unstable_position_loop_is_not_drawn(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    # k_v = 2000 1/s puts the position loop's crossover above the velocity loop's
    # bandwidth: a negative phase margin, an unstable loop (issue 52: G = 102 um, exit 0).
    doc = _refused(["--kv", "2000 1/s", "--direction", "CCW"], capsys, tmp_path)
    pm = [c for c in doc["checks"] if c["check"] == "position-loop phase margin"]
    assert pm and all(c["verdict"] == "NOT OK" and c["value"] < 0 for c in pm)
    assert pm[0]["value"] == pytest.approx(doc["axes"]["x"]["loops"]["position_phase_margin_deg"])


def test_a_sampling_time_too_long_for_the_loop_is_not_drawn(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    # 50 ms: 20 Hz of sampling for loops of several Hz (issue 52: G = 4 000 000 um).
    doc = _refused(["--sampling-time", "50 ms", "--direction", "CCW"], capsys, tmp_path)
    ratio = [c for c in doc["checks"] if c["check"].startswith("sampling frequency")]
    assert any(c["verdict"] != "OK" and c["value"] < 10 for c in ratio)


def test_a_feed_past_the_motor_is_not_drawn(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    # 2 m/s on a 10 mm lead is 200 rev/s = 12 000 rpm against the case's 3000 rpm, and
    # v^2/R = 4/0.05 = 80 m/s^2 on the 50 mm circle (issue 52: G = 13.6 um, exit 0).
    doc = _refused(["--feed", "2 m/s"], capsys, tmp_path)
    checks = {(c["axis"], c["check"]): c for c in doc["checks"]}
    speed = checks[("x", "motor speed at the feed")]
    assert speed["value"] == pytest.approx(12000.0, rel=1e-9) and speed["limit"] == 3000.0
    acc = checks[("x", "peak acceleration of the path (start-up ramp, v^2/R)")]
    assert acc["value"] == pytest.approx(80.0, rel=1e-3) and acc["verdict"] == "NOT OK"
    assert checks[("x", "peak motor torque")]["verdict"] == "NOT OK"


def test_a_negative_guide_friction_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run([*BASE, "--guide-friction", "-40 N"], capsys)
    assert code == 2 and "--guide-friction" in err and "-40 N" in err, err


def test_a_kilometre_circle_is_refused_with_its_estimate(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # 2 pi 1000 m at 2 m/min is 188 496 s, 7.5e8 samples of 250 us per revolution.
    code, _, err = run([*BASE, "--radius", "1 km"], capsys)
    assert code == 2, err
    assert "(estimated)" in err and "--max-samples" in err and "MemoryError" not in err
    revolution = 2 * math.pi * 1000.0 / (2.0 / 60.0) / 250e-6
    shown = int(err.split("'")[1].split(" ")[0].replace(",", ""))
    assert shown > 8 * revolution  # four circles, both axes


def test_the_estimate_counts_the_samples_a_circle_runs() -> None:
    # One circle of two axes: the estimate equals the samples of the traces (plus nothing).
    case = load_case(EXAMPLE)
    result = run_contour([case], radius=0.005, feed=1.0 / 60.0, directions=("CCW",),
                         compensate=False)  # fmt: skip
    circle = result.circles[0]
    simulated = circle.x.time.size + circle.y.time.size
    estimate = contour_samples(0.005, 1.0 / 60.0, 250e-6, 40.0, circles=1, reversals=0)
    assert estimate == simulated


def test_the_limit_can_be_lowered_and_is_the_documented_one(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, _, err = run([*BASE, "--radius", "10 mm", "--max-samples", "1000"], capsys)
    assert code == 2 and "at most 1,000" in err, err
    code, out, _ = run(["contour", "--help"], capsys)
    assert f"{MAX_SAMPLES:,}" in " ".join(out.split())


def test_check_statuses_and_the_worst_verdict() -> None:
    # A phase margin of 20 deg: past the stated 30, short of instability (0): CHECK.
    low = Check("x", "phase margin", 20.0, 30.0, "deg", True, "", 0.0)
    unstable = Check("x", "phase margin", -1.0, 30.0, "deg", True, "", 0.0)
    fast = Check("x", "motor speed", 3500.0, 3000.0, "rpm", False, "")
    fine = Check("x", "motor speed", 100.0, 3000.0, "rpm", False, "")
    assert [c.status for c in (low, unstable, fast, fine)] == ["CHECK", "NOT OK", "NOT OK", "OK"]
    assert verdict([fine, low]) == "CHECK" and verdict([low, fast]) == "NOT OK"
    assert verdict([fine]) == "OK" and fast.margin == -500.0
    nan = Check("x", "sampling", math.nan, 10.0, "x", True, "", 2.0)
    assert nan.status == "NOT OK"


def test_a_poorly_damped_loop_is_drawn_with_check(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    # At 1 ms the tuned velocity loop keeps a phase margin between 0 and 30 deg: it runs,
    # poorly damped. The circle is drawn, a warning names the margin, the JSON says CHECK.
    out_json = tmp_path / "c.json"
    code, _, err = run([*BASE, "--radius", "10 mm", "--feed", "1 m/min", "--direction", "CCW",
                        "--sampling-time", "1 ms", "--json", str(out_json)], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out_json.read_text())
    assert doc["verdict"] == "CHECK" and len(doc["circles"]) == 2
    low = [c for c in doc["checks"] if c["verdict"] == "CHECK"]
    assert low and all(0 < c["value"] < 30 for c in low if c["unit"] == "deg")
    assert "warning: CHECK x: velocity-loop phase margin" in err


def test_a_zero_position_gain_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run([*BASE, "--kv", "0 1/s"], capsys)
    assert code == 2 and "--kv" in err and "internal error" not in err, err
