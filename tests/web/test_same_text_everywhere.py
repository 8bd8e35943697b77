"""The web form, the case file and the command line read the same text the same way.

Each text goes through all three faces: ``ballscrew torque --axial-load TEXT``, a case
file's ``[operation] axial_load = TEXT`` and the web API's ``axial_load``; for a single
value, a case file's and the web form's ``[screw] preload``. Either all three read the
same numbers, or all three refuse it naming the field.
"""

from __future__ import annotations

import json
import math
import tomllib
import warnings
from collections.abc import Iterator
from pathlib import Path

import pytest
from starlette.testclient import TestClient

from ballscrew import BallScrewInputError
from ballscrew.errors import BallScrewReadingWarning
from ballscrew.io.case import parse_case
from ballscrew.web import create_app
from cli_runner import run
from shared import SMALL_CASE, reference_case_toml

BASE = reference_case_toml("same text", speed="100 rpm", axial_load="0 N")

LOADS = [  # texts for a list field (axial load), with the loads meant [N] or None: refused
    ("1 200 N", [1200.0]),
    ("1 000, 2 000 N", [1000.0, 2000.0]),
    ("1,2; 2,5 kN", [1200.0, 2500.0]),
    ("0,5..1,5:3 kN", [500.0, 1000.0, 1500.0]),
    ("−1 kN", [-1000.0]),
    ("1,2 kN", None),  # a list of two or a decimal comma?
    ("1 20 N", None),
    ("10**10**8 N", None),
    ("2 kN*m", None),
    # shop-floor notation (issue 40): a fraction is one number; 1 lbf = 4.4482216152605 N
    ("1/4 kN", [250.0]),
    ("1/4, 1/2 kN", [250.0, 500.0]),
    ("1 1/2 kN", [1500.0]),
    ("100 lbf", [444.82216152605]),
    ("1-1/2 kN", None),  # 1.5 to a machinist, 0.5 to arithmetic
    ("100 lb", None),  # a mass: 'lbf' is the force
]
PRELOADS = [  # a single value: a comma is a decimal comma
    ("1,2 kN", 1200.0),
    ("2,5 kN", 2500.0),
    ("1 200 N", 1200.0),
    ("1.200,5 N", 1200.5),
    ("1,200 N", None),
    ("2", None),
]


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    with TestClient(create_app(allowed_hosts=["testserver"])) as c:
        yield c


def _case_file(key: str, value: str) -> str:
    old = 'axial_load = "0 N"' if key == "axial_load" else 'preload = "2 kN"'
    return BASE.replace(old, f"{key} = {json.dumps(value, ensure_ascii=False)}")


@pytest.mark.parametrize(("text", "meant"), LOADS)
def test_an_axial_load_reads_the_same_in_all_three(
    text: str,
    meant: list[float] | None,
    client: TestClient,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    out = tmp_path / "t.json"
    code, _, err = run(
        ["torque", "--case", str(SMALL_CASE), "--model", "catalog", "--speed", "100 rpm",
         "--axial-load", text, "--json", str(out)],
        capsys,
    )  # fmt: skip
    response = client.post(
        "/api/torque", json={**tomllib.loads(BASE), "model": "catalog", "axial_load": text}
    )
    if meant is None:
        assert code == 2 and "--axial-load = " in err, err
        assert response.status_code == 422 and "axial_load = " in response.json()["error"]
        with pytest.raises(BallScrewInputError, match=r"operation\.axial_load"):
            parse_case(_case_file("axial_load", text))
        return
    assert code == 0, err
    cli = [row["axial load [N]"] for row in json.loads(out.read_text())["rows"]]
    case = parse_case(_case_file("axial_load", text)).axial_load.tolist()
    assert response.status_code == 200, response.text
    web = response.json()["axial_load_N"]
    assert cli == pytest.approx(meant, rel=1e-12)
    assert case == pytest.approx(meant, rel=1e-12) and web == pytest.approx(meant, rel=1e-12)


@pytest.mark.parametrize(("text", "meant"), PRELOADS)
def test_a_preload_reads_the_same_in_the_case_file_and_the_web_form(
    text: str, meant: float | None, client: TestClient
) -> None:
    fields = tomllib.loads(BASE)
    fields["screw"]["preload"] = text
    response = client.post("/api/torque", json={**fields, "model": "catalog"})
    if meant is None:
        assert response.status_code == 422 and "screw.preload = " in response.json()["error"]
        with pytest.raises(BallScrewInputError, match=r"screw\.preload"):
            parse_case(_case_file("preload", text))
        return
    assert response.status_code == 200, response.text
    assert parse_case(_case_file("preload", text)).screw.preload == pytest.approx(meant)
    # The page gets the catalogue torque of that preload: the same as the case file's.
    expected = parse_case(_case_file("preload", text))
    from ballscrew import friction_torque

    torque = friction_torque(expected.screw, expected.lubricant, speed=10.47, temperature=40.0,
                             model="catalog")  # fmt: skip
    assert response.json()["torque_Nm"][0] == pytest.approx(float(torque.total), rel=1e-3)


SPEEDS = [  # speeds as catalogues write them [rpm meant], or None: refused
    ("3000 1/min", [3000.0]),
    ("3000 min^-1", [3000.0]),
    ("3000 rev/min", [3000.0]),
    ("3000 U/min", [3000.0]),
    ("50 Hz", [3000.0]),  # revolutions per second, with a note
    ("1 000, 2 000 rpm", [1000.0, 2000.0]),
    ("3000", None),
    ("10 m/min", [1000.0]),  # a feed: the screw speed at the case's lead of 10 mm, with a note
    ("10 kg", None),
]


@pytest.mark.parametrize(("text", "meant"), SPEEDS)
def test_a_speed_reads_the_same_in_all_three(
    text: str,
    meant: list[float] | None,
    client: TestClient,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    out = tmp_path / "t.json"
    same = tmp_path / "same.toml"  # the web's case, so that a feed meets the same lead
    same.write_text(BASE, encoding="utf-8")
    with warnings.catch_warnings():
        # How a speed in Hz was read: a 'warning:' line on the command line (the tests
        # otherwise turn warnings into errors).
        warnings.simplefilter("always", BallScrewReadingWarning)
        code, _, err = run(
            ["torque", "--case", str(same), "--model", "catalog", "--speed", text,
             "--json", str(out)],
            capsys,
        )  # fmt: skip
        response = client.post(
            "/api/torque", json={**tomllib.loads(BASE), "model": "catalog", "speed": text}
        )
    if meant is None:
        assert code == 2 and "--speed = " in err, err
        assert response.status_code == 422 and "speed = " in response.json()["error"]
        with pytest.raises(BallScrewInputError, match=r"operation\.speed"):
            parse_case(BASE.replace('speed = "100 rpm"', f"speed = {json.dumps(text)}"))
        return
    assert code == 0, err
    cli = [row["speed [rpm]"] for row in json.loads(out.read_text())["rows"]]
    case = parse_case(BASE.replace('speed = "100 rpm"', f"speed = {json.dumps(text)}"))
    assert response.status_code == 200, response.text
    assert cli == pytest.approx(meant, rel=1e-12)
    assert response.json()["speed_rpm"] == pytest.approx(meant, rel=1e-12)
    assert (case.speed * 30.0 / math.pi).tolist() == pytest.approx(meant, rel=1e-12)
    # A speed in Hz says how it was read, in all three.
    hertz = "Hz" in text
    assert ("read as 50 revolutions per second" in err) == hertz
    assert any("revolutions per second" in w for w in response.json()["warnings"]) == hertz
    assert any("revolutions per second" in a.reason for a in case.assumptions) == hertz
    # A feed says at which lead it was read, in all three.
    feed = "m/min" in text
    assert ("is read as 1000 rpm at lead 10 mm" in err) == feed
    assert any("at lead 10 mm" in w for w in response.json()["warnings"]) == feed
    assert any("at lead 10 mm" in a.reason for a in case.assumptions) == feed
