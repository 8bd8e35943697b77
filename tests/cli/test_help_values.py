"""Every option's help names what its value means, not click's type (issue 40, item 4)."""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner

from ballscrew.cli.group import COMMANDS, cli

GENERIC = re.compile(r"^\s+(-\w, )?--[\w-]+ (TEXT|FLOAT|INTEGER|INTEGER RANGE|FILENAME|PATH|FILE "
                     r"RANGE)\b", re.MULTILINE)  # fmt: skip


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_no_option_shows_a_bare_type(name: str) -> None:
    out = CliRunner().invoke(cli, [name, "--help"], terminal_width=200)
    assert out.exit_code == 0, out.output
    assert not GENERIC.findall(out.output), out.output
    assert "[OPTIONS] TEXT" not in out.output


def test_the_issues_examples_read_as_asked() -> None:
    # The issue's own examples: '--json FILE|-' and '--temperature DEGC'.
    out = CliRunner().invoke(cli, ["torque", "--help"], terminal_width=200).output
    assert "--json FILE|-" in out and "--temperature DEGC" in out
    assert "--out STORE" in CliRunner().invoke(cli, ["sweep", "--help"]).output
