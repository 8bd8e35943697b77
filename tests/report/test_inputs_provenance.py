"""Every output carries its inputs: each given value with its unit, each derived one with how.

A newcomer's trial of 0.3.0: ``energy --json`` listed ``axis.screw_length`` and
``operation.temperature`` as null though the file gave them (the thermal keys and the
operating points were looked up where they are not kept), the share a preload was given
as was null too, no value had its unit, and the screw's inertia the run estimated was
called "default". The expected values here come from the file's text converted by pint
directly and from the closed form of a solid cylinder, not from the package's reader.
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path
from typing import Any

import pint
import pytest

from cli_runner import run
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"
MOVE = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"
UREG = pint.UnitRegistry()
PINT_NAMES = {"": "dimensionless", "%": "percent", "degC": "degree_Celsius"}


def _written(text: str) -> dict[str, Any]:
    """Each ``section.key`` the file writes in the sections a run reads, as written."""
    raw = tomllib.loads(text)
    out = {}
    for section in ("screw", "operation", "axis", "motor", "check"):
        for key, value in raw.get(section, {}).items():
            out[f"{section}.{key}"] = value["value"] if isinstance(value, dict) else value
    return out


def _energy_inputs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, Any]:
    out = tmp_path / "e.json"
    code, _, err = run(["energy", "--case", str(EXAMPLE), "--move", MOVE, "--model", "catalog",
                        "--run-time", "10 min", "--json", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    inputs: dict[str, Any] = json.loads(out.read_text(encoding="utf-8"))["inputs"]
    return inputs


def test_each_value_the_file_gives_is_in_the_json_with_its_unit(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    values = {v["key"]: v for v in _energy_inputs(tmp_path, capsys)["case"]["values"]}
    written = _written(EXAMPLE.read_text(encoding="utf-8"))
    checked = 0
    for key, text in written.items():
        if key in ("screw.designation",):  # a name, resolved into the catalogue's keys
            continue
        entry = values[key]
        assert entry["value"] is not None and entry["source"] != "not given", entry
        assert "unit" in entry, entry
        if isinstance(text, str) and any(c.isdigit() for c in text):
            # The file's "1100 mm", "25 degC", "6 %", "3000 rpm": pint's own conversion.
            number_text, _, unit_text = text.partition(" ")
            unit_text = PINT_NAMES.get(unit_text, unit_text)
            expected = UREG.Quantity(float(number_text), unit_text)
            unit = PINT_NAMES.get(entry["unit"], entry["unit"])
            number = expected.to(unit).magnitude
            got = entry["value"][0] if isinstance(entry["value"], list) else entry["value"]
            assert got == pytest.approx(number, rel=1e-12), key
            checked += 1
        else:
            assert entry["value"] == text, key
    assert checked == 13  # every number the example writes with its unit
    assert values["axis.screw_length"]["value"] == pytest.approx(1.1, rel=1e-12)
    assert values["operation.temperature"]["value"] == [25.0]
    assert values["screw.preload_share"] == {"key": "screw.preload_share", "value": 0.06,
                                             "unit": "", "source": "assumed"}  # fmt: skip
    # A null is never a value someone gave: it is "not given", and says what stands in.
    for entry in values.values():
        if entry["value"] is None:
            assert entry["source"] == "not given", entry
    load_factor = values["check.load_factor"]
    assert load_factor["value"] is None and load_factor["how"].startswith("1.2")
    # What stands in is the schema's "(none: ...)" of the key, whole: up to its own bracket.
    from ballscrew.io.schema import SECTIONS

    for entry in values.values():
        if entry.get("how") and entry["value"] is None:
            section, key = entry["key"].split(".", 1)
            described = SECTIONS[section].model_fields[key].description or ""
            how = entry["how"]
            assert how.count("(") == how.count(")") and f"none: {how})" in described, entry


def test_the_estimated_screw_inertia_says_how_with_its_value(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    inputs = _energy_inputs(tmp_path, capsys)
    j = next(v for v in inputs["case"]["values"] if v["key"] == "axis.screw_inertia")
    assert j["source"] == "estimated" and j["unit"] == "kg*m**2"
    assert j["how"].startswith("from the screw's geometry")
    assert "32 mm" in j["how"] and "1100 mm" in j["how"]
    # A solid steel cylinder of the pitch diameter 32 mm over the screw length 1.1 m:
    # m = rho pi r^2 L, J = m r^2 / 2, steel 7850 kg/m^3; to the density's 4 digits.
    r, length = 0.016, 1.1
    mass = 7850.0 * math.pi * r**2 * length
    assert j["value"] == pytest.approx(mass * r**2 / 2, rel=1e-3)


def test_torque_and_energy_write_their_inputs_by_one_list(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    energy = {v["key"]: v for v in _energy_inputs(tmp_path, capsys)["case"]["values"]}
    out = tmp_path / "t.json"
    code, _, err = run(["torque", "--case", str(EXAMPLE), "--speed", "1000 rpm", "--model",
                        "catalog", "--json", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out.read_text(encoding="utf-8"))
    torque = {v["key"]: v for v in doc["provenance"]["case"]["values"]}
    assert torque.keys() == energy.keys()
    # The same entries, but for what the energy run filled from the geometry.
    differ = {k for k in torque if torque[k] != energy[k]}
    assert differ == {"axis.screw_inertia"}
    assert torque["axis.screw_inertia"]["source"] == "not given"


def test_the_energy_report_lists_units_and_how(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    report = tmp_path / "report"
    code, _, err = run(["energy", "--case", str(EXAMPLE), "--move", MOVE, "--model", "catalog",
                        "--run-time", "10 min", "--out", str(report)], capsys)  # fmt: skip
    assert code == 0, err
    md = (report / "report.md").read_text(encoding="utf-8")
    assert "| key | value (SI) | unit | source |" in md
    line = next(x for x in md.splitlines() if x.startswith("| axis.screw_inertia "))
    assert "kg*m**2" in line and "estimated: from the screw's geometry" in line
    assert next(x for x in md.splitlines() if x.startswith("| axis.screw_length ")).count("1.1")
