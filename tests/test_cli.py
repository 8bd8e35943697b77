"""Tests of the command-line interface."""

from __future__ import annotations

import subprocess
import sys

from click.testing import CliRunner

from ballscrew import __version__
from ballscrew.cli import cli


def test_demo_prints_contact_and_lubricant_summary() -> None:
    result = CliRunner().invoke(cli, ["demo"])
    assert result.exit_code == 0, result.output
    for text in (
        "Reference ball screw",
        "Hertz contact",
        "exact",
        "houpert",
        "PAO ISO VG 68",
        "SAE 20",
        "h_min [µm]",
        "Λ",
    ):
        assert text in result.output


def test_demo_bad_lubricant_exits_2_with_one_line() -> None:
    result = CliRunner().invoke(cli, ["demo", "--lubricant", "castor oil"])
    assert result.exit_code == 2
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1
    assert "lubricant" in lines[0] and "castor oil" in lines[0]


def test_demo_bad_temperature_exits_2() -> None:
    result = CliRunner().invoke(cli, ["demo", "--temperature", "-400"])
    assert result.exit_code == 2
    assert "temperature" in result.output


def test_console_script_version() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "ballscrew", "--version"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert __version__ in out.stdout
