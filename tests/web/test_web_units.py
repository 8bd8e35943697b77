"""The web calculator's results in imperial units: the command line's ``--units``, on the page.

The page's choice (``units`` in the request, ``?units=`` in its address) changes only what
the page shows (``display`` in the answer), through :mod:`ballscrew.io.display` as the
command line prints it; the answer's figures stay SI. The torque is checked against
``ballscrew torque --units imperial`` for the same case, and against the conversion worked
out from the definitions, not by pint: 1 lbf = 0.45359237 kg x 9.80665 m/s^2 and
1 in = 0.0254 m, so 1 N*m = 1 / (4.4482216152605 x 0.0254) = 8.8507458 lbf*in.
"""

from __future__ import annotations

import json
import tomllib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from starlette.testclient import TestClient

from ballscrew.web import create_app
from cli_runner import run
from shared import reference_case_toml

LBF = 0.45359237 * 9.80665  # N, by definition
LBF_IN_PER_NM = 1.0 / (LBF * 0.0254)  # 8.8507458...
CASE_TOML = reference_case_toml(
    "web units", speed="100, 1000 rpm", axial_load="1 kN", more='[axis]\nmoving_mass = "200 kg"\n'
)
CASE = tomllib.loads(CASE_TOML)
MOVE = {"stroke": "300 mm", "feed": "15 m/min", "acceleration": "2 m/s**2"}
# The command line prints 4 significant digits: half a unit of the 4th is at most 5e-4.
PRINTED = 5e-4


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    with TestClient(create_app(allowed_hosts=["testserver"], processes=0)) as c:
        yield c


def evaluate(client: TestClient, **payload: Any) -> dict[str, Any]:
    response = client.post("/api/evaluate", json={"case": CASE, "models": ["complete"], **payload})
    assert response.status_code == 200, response.text
    data: dict[str, Any] = response.json()
    return data


def printed_rows(out: str) -> list[dict[str, str]]:
    """The rows of the command line's table, as header -> cell."""
    lines = out.splitlines()
    header = next(line for line in lines if line.startswith("┃"))
    names = [c.strip() for c in header.strip("┃").split("┃")]
    return [
        dict(zip(names, (c.strip() for c in line.strip("│").split("│")), strict=True))
        for line in lines
        if line.startswith("│")
    ]


def test_the_pages_imperial_torque_is_the_commands(
    client: TestClient, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    data = evaluate(client, units="imperial")
    path = tmp_path / "case.toml"
    path.write_text(data["case_toml"], encoding="utf-8")
    # The command the page gives for its results, with the table printed in full.
    command = data["command"].split()
    assert command[-2:] == ["--units", "imperial"]
    code, out, err = run(["torque", "--case", str(path), "--model", "complete", "--model",
                          "catalog", "--units", "imperial", "--table", "full"], capsys)  # fmt: skip
    assert code == 0, err
    printed = {(r["model"], float(r["speed [rpm]"])): r for r in printed_rows(out)}
    assert len(printed) == 4  # 2 models x 2 speeds
    for curve, shown in zip(data["curves"], data["display"]["curves"], strict=True):
        for speed, torque in zip(curve["speed_rpm"], shown["torque"], strict=True):
            row = printed[(curve["model"], speed)]
            assert torque == pytest.approx(float(row["torque [lbf*in]"]), rel=PRINTED)
        assert shown["axial_load"] == pytest.approx(float(row["axial load [lbf]"]), rel=PRINTED)
        assert shown["temperature"] == pytest.approx(float(row["temperature [degF]"]))
    assert data["display"]["units"]["torque"] == "lbf·in"


def test_one_newton_metre_is_8_8507_pound_force_inches(client: TestClient) -> None:
    data = evaluate(client, units="imperial", move=MOVE)
    shown = data["display"]
    # The conversion is pint's with its definitions, which are these exactly: equal to the
    # last digits a double carries (1e-12 relative).
    for curve, imperial in zip(data["curves"], shown["curves"], strict=True):
        for si, lbf_in in zip(curve["torque_Nm"], imperial["torque"], strict=True):
            assert lbf_in == pytest.approx(si * LBF_IN_PER_NM, rel=1e-12)
            assert lbf_in / si == pytest.approx(8.8507, abs=5e-5)  # the four digits of the brief
        assert imperial["axial_load"] == pytest.approx(1000.0 / LBF, rel=1e-12)  # 224.81 lbf
        assert imperial["temperature"] == pytest.approx(40.0 * 9 / 5 + 32)  # 104 degF
    e = data["energy"]
    assert shown["energy"]["peak_motor_torque"] == pytest.approx(
        e["peak_motor_torque_Nm"] * LBF_IN_PER_NM, rel=1e-12
    )
    assert shown["screw"]["lead"] == pytest.approx(10.0 / 25.4, rel=1e-12)  # 10 mm in inches
    assert shown["screw"]["preload"] == pytest.approx(2000.0 / LBF, rel=1e-12)
    budget = data["budget"]["components"]
    for name, parts in shown["budget"]["components"].items():
        assert parts == pytest.approx([v * LBF_IN_PER_NM for v in budget[name]], rel=1e-12)
    # The check's rows as `ballscrew check --units imperial` prints them: a force in lbf,
    # the lead accuracy's 300 mm named in inches beside it; speeds stay in rpm.
    rows = {r["name"]: r for r in shown["check"]}
    criteria = {r["name"]: r for r in e["check"]["criteria"]}
    assert rows["buckling load"]["unit"] == "lbf"
    buckling = criteria["buckling load"]
    newtons = {"N": 1.0, "kN": 1e3}[buckling["unit"]]
    assert rows["buckling load"]["value"] == pytest.approx(
        buckling["value"] * newtons / LBF, rel=1e-12
    )
    assert "thermal lead error per 11.81 in (300 mm)" in rows
    assert rows["speed / critical speed"]["unit"] == "rpm"


def test_the_answer_stays_si_and_records_the_choice(client: TestClient) -> None:
    si = evaluate(client, move=MOVE)
    imperial = evaluate(client, units="imperial", move=MOVE)
    # The machine's figures are the same whatever the page shows; only `display` differs.
    for key in ("curves", "budget", "screw", "csv", "case_toml"):
        assert imperial[key] == si[key], key
    assert si["units"] == "si" and imperial["units"] == "imperial"
    assert si["display"]["curves"][0]["torque"] == si["curves"][0]["torque_Nm"]
    assert si["display"]["units"]["torque"] == "N·m"
    assert "--units" not in si["command"] and "--units" not in si["energy"]["command"]
    for command in (imperial["command"], imperial["energy"]["command"],
                    imperial["energy"]["check"]["command"]):  # fmt: skip
        assert command.endswith("--units imperial"), command
    meta = json.loads(imperial["provenance"])["provenance"]
    assert meta["command"][-2:] == ["--units", "imperial"]
    assert meta["display_units"].startswith("units: imperial")
    assert "JSON and CSV files stay SI" in meta["display_units"]


def test_the_case_files_output_units_is_the_default_and_the_page_overrides_it(
    client: TestClient,
) -> None:
    case = {**CASE, "output": {"units": "imperial"}}
    told = client.post("/api/evaluate", json={"case": case, "models": ["complete"]}).json()
    assert told["units"] == "imperial" and "--units" not in told["command"]
    si = client.post(
        "/api/evaluate", json={"case": case, "models": ["complete"], "units": "si"}
    ).json()
    assert si["units"] == "si" and si["command"].endswith("--units si")


@pytest.mark.parametrize("value", ["metric", "", "SI units", 3])
def test_a_bad_units_value_is_refused_naming_the_field(client: TestClient, value: Any) -> None:
    response = client.post(
        "/api/evaluate", json={"case": CASE, "models": ["complete"], "units": value}
    )
    assert response.status_code == 422
    assert response.json() == {
        "error": f"units = {value!r} is not allowed: one of si, imperial",
        "field": "units",
    }


def test_the_page_opens_in_the_units_its_address_names(client: TestClient) -> None:
    imperial = client.get("/?units=imperial")
    assert imperial.status_code == 200
    assert '<option value="imperial" selected>' in imperial.text
    assert '<option value="si" selected>' in client.get("/").text
    assert '<option value="imperial" selected>' in client.get("/?units=Imperial").text
    bad = client.get("/?units=metric")
    assert bad.status_code == 400
    assert "units = &#x27;metric&#x27; is not allowed: one of si, imperial" in bad.text


def test_imperial_inputs_are_read_as_on_the_command_line(client: TestClient) -> None:
    # A quarter-inch lead, a load in pound-force and a feed in inches per minute, as an
    # American user types them (the page sends a text that carries its unit as typed).
    case = {
        **CASE,
        "screw": {**{k: v for k, v in CASE["screw"].items() if k != "designation"},
                  "pitch_diameter": "1.5 in", "lead": "1/4 in", "ball_diameter": "5/32 in",
                  "contact_angle": "45 deg", "loaded_turns": 2.5, "circuits": 2,
                  "conformity_screw": 0.55, "conformity_nut": 0.55, "nut": "double"},
        "operation": {**CASE["operation"], "axial_load": "200 lbf"},
    }  # fmt: skip
    move = {"stroke": "12 in", "feed": "600 in/min", "acceleration": "2 m/s**2"}
    data = evaluate(client, case=case, move=move, units="imperial")
    assert data["screw"]["lead_mm"] == pytest.approx(6.35, rel=1e-12)
    assert data["display"]["screw"]["lead"] == pytest.approx(0.25, rel=1e-12)
    assert data["curves"][0]["axial_load_N"] == pytest.approx(200 * LBF, rel=1e-6)
    assert data["display"]["curves"][0]["axial_load"] == pytest.approx(200.0, rel=1e-6)
    assert data["energy"]["move"] == "stroke=12 in, feed=600 in/min, acceleration=2 m/s**2"
    # 600 in/min = 0.254 m/s: the move out and back takes 2 (0.3048 / 0.254 + 0.254 / 2) s.
    assert data["energy"]["duration_s"] == pytest.approx(2 * (0.3048 / 0.254 + 0.254 / 2), rel=1e-3)
