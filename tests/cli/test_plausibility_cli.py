"""Plausibility against the screw, as a user meets it: torque, case --check, energy, the web.

Issue 27: "Nothing is checked against the screw: a 500 kN axial load on a 32 mm
screw, a 12 kN preload on a 56 kN-rated nut, a 5 m stroke on a 1.3 m screw all
pass; contact pressures far past what bearing steel carries give numbers."
"""

from __future__ import annotations

import json
import re
import tomllib
from collections.abc import Iterator
from pathlib import Path

import pytest
from starlette.testclient import TestClient

from ballscrew.web import create_app
from cli_runner import run

SCREW_32 = """
title = "32 mm screw"
[screw]
pitch_diameter = "32 mm"
lead = "10 mm"
ball_diameter = "6.35 mm"
preload = "2 kN"
[lubricant]
name = "PAO ISO VG 68"
[operation]
speed = "1000 rpm"
temperature = "40 degC"
"""

HIWIN = """
title = "HIWIN nut"
[screw]
designation = "HIWIN R32-10K5-FDC"
preload = "{preload}"
[lubricant]
name = "PAO ISO VG 68"
[operation]
speed = "1000 rpm"
temperature = "40 degC"
"""


def _case(tmp_path: Path, text: str) -> str:
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_500_kN_on_a_32_mm_screw_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = _case(tmp_path, SCREW_32)
    code, out, err = run(["torque", "--case", case, "--axial-load", "500 kN"], capsys)
    assert code == 2 and out == ""
    line = err.strip().splitlines()[-1]
    for part in ("--axial-load = '500 kN", "C_0a = 94.36 kN", "estimated", "ISO 3408-5"):
        assert part in line, line
    # The same load in the case file names the case's field.
    code, _, err = run(
        ["torque", "--case", _case(tmp_path, SCREW_32 + 'axial_load = "500 kN"\n')], capsys
    )
    assert code == 2 and "operation.axial_load = '500 kN" in err


def test_12_kN_preload_on_a_56_kN_nut_is_refused_by_case_check(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(["case", "--check", _case(tmp_path, HIWIN.format(preload="12 kN"))], capsys)
    assert code == 2
    assert "screw.preload = '12 kN (21.3% of C_a)'" in err
    assert "20% of C_a = 56.4 kN (the HIWIN R32-10K5-FDC catalogue row)" in err
    assert "THK" in err


def test_case_check_shows_the_ratings_and_warns_near_a_limit(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run(["case", "--check", _case(tmp_path, HIWIN.format(preload="6 kN"))], capsys)
    assert code == 0, err
    shown = re.search(r"56\.4 kN \[(\d+)\]", out)  # the source in a note under the table
    assert shown and f"[{shown[1]}] the HIWIN R32-10K5-FDC catalogue row" in out
    assert "144.8 kN" in out
    assert "warning: screw.preload = 6000 N (10.6% of C_a) is above 10% of C_a" in err


def test_torque_prints_and_records_the_warnings(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = _case(tmp_path, HIWIN.format(preload="3 kN"))
    out_json = tmp_path / "t.json"
    args = ["torque", "--case", case, "--axial-load", "60 kN", "--json", str(out_json)]
    code, _, err = run(args, capsys)
    assert code == 0, err
    assert "warning: --axial-load = 60 kN (rating life 8.31e+05 revolutions)" in err
    assert "is above the dynamic rating C_a = 56.4 kN" in err
    record = json.loads(out_json.read_text())["provenance"]["plausibility"]
    assert record["static_load_rating_N"] == 144800.0
    assert record["static_load_rating_estimated"] is False
    assert any("rating life" in w for w in record["warnings"])


def test_a_5_m_stroke_on_a_1_3_m_screw_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = SCREW_32 + '[axis]\nmoving_mass = "50 kg"\nscrew_length = "1.3 m"\n'
    case = _case(tmp_path, text)
    move = "stroke=5 m, feed=0.5 m/s, acceleration=2 m/s^2"
    code, _, err = run(["energy", "--case", case, "--move", move], capsys)
    assert code == 2
    assert "--move stroke = '5000 mm' is not allowed: at most axis.screw_length = 1300 mm" in err
    move = "stroke=1.25 m, feed=0.5 m/s, acceleration=2 m/s^2"
    code, out, err = run(["energy", "--case", case, "--move", move, "--json", "-"], capsys)
    assert code == 0, err
    assert "warning: --move stroke = 1250 mm is above axis.screw_length = 1300 mm less" in err
    assert any("less the nut" in w for w in json.loads(out)["plausibility"])


def test_a_process_force_past_the_static_rating_is_refused_by_energy(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = _case(tmp_path, SCREW_32 + '[axis]\nmoving_mass = "50 kg"\n')
    move = "stroke=0.3 m, feed=0.5 m/s, acceleration=2 m/s^2, force=200 kN"
    code, _, err = run(["energy", "--case", case, "--move", move], capsys)
    assert code == 2 and "--move (axial force of the cycle) = '200.1 kN" in err
    assert "C_0a" in err


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    with TestClient(create_app(allowed_hosts=["testserver"])) as c:
        yield c


def test_the_web_refuses_the_same_load_with_the_same_words(
    client: TestClient, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    fields = tomllib.loads(SCREW_32)
    response = client.post("/api/torque", json={**fields, "axial_load": "500 kN"})
    assert response.status_code == 422
    body = response.json()
    assert body["field"] == "axial_load"
    _, _, err = run(["torque", "--case", _case(tmp_path, SCREW_32), "--axial-load", "500 kN"],
                    capsys)  # fmt: skip
    cli = err.strip().splitlines()[-1]
    assert body["error"].split(" is not allowed: ")[1] == cli.split(" is not allowed: ")[1]
    near = client.post("/api/torque", json={**fields, "axial_load": "50 kN"}).json()
    assert any("half the static rating" in w for w in near["warnings"])


AXIS_LIMITS = (
    '[axis]\nmoving_mass = "50 kg"\nmax_feed = "0.4 m/s"\nmax_acceleration = "1.5 m/s**2"\n'
)


@pytest.mark.parametrize(
    ("move", "expected"),
    [
        ("stroke=0.3 m, feed=0.5 m/s, acceleration=1 m/s^2",
         "--move feed = '0.5 m/s (30 m/min)' is not allowed: at most axis.max_feed = 0.4 m/s "
         "(24 m/min)"),
        ("stroke=0.3 m, feed=24 m/min, acceleration=2 m/s^2",
         "--move acceleration = '2 m/s^2' is not allowed: at most axis.max_acceleration = 1.5"),
        ("stroke=0.3 m, feed=0.4 m/s, acceleration=1.5 m/s^2", ""),
    ],
)  # fmt: skip
def test_a_move_beyond_the_axis_limits_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], move: str, expected: str
) -> None:
    case = _case(tmp_path, SCREW_32 + AXIS_LIMITS)
    code, _, err = run(["energy", "--case", case, "--move", move], capsys)
    assert (code == 2) == bool(expected), err
    assert expected in err


def test_a_trajectory_beyond_the_axis_speed_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # 0 -> 0.3 m in 0.5 s at constant speed: 0.6 m/s, above the axis' 0.4 m/s.
    profile = tmp_path / "p.csv"
    rows = "".join(f"{i * 0.05:.2f},{i * 30.0:.1f}\n" for i in range(11))
    profile.write_text("time [s],position [mm]\n" + rows)
    case = _case(tmp_path, SCREW_32 + AXIS_LIMITS.replace('"1.5 m/s**2"', '"100 m/s**2"'))
    code, _, err = run(["energy", "--case", case, "--profile", str(profile)], capsys)
    assert code == 2
    # 0.6 m/s is 36 m/min, 0.4 m/s 24 m/min: both in the unit machine tools give feeds in
    assert (
        "--profile speed = '0.6 m/s (36 m/min)' is not allowed: at most axis.max_feed = "
        "0.4 m/s (24 m/min)"
    ) in err
