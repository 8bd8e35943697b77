"""The command line imports a command's module when the command is used (issue 51).

``ballscrew --help`` still lists every command with its one-line help, and a command run
from the lazy group prints what it printed when every command was imported at start-up.
"""

from __future__ import annotations

import subprocess
import sys

import click
from click.testing import CliRunner

from ballscrew.cli.group import COMMANDS, cli

RUN_TORQUE = (
    "import sys\n"
    "from ballscrew.cli.group import COMMANDS, cli, main\n"
    "if sys.argv[1] == 'eager':\n"
    "    for name in COMMANDS:\n"
    "        cli.get_command(None, name)\n"
    "try:\n"
    "    main(['torque', '--speed', '0..3000:4 rpm', '--temperature', '20, 40 degC',\n"
    "          '--model', 'complete', '--model', 'catalog'])\n"
    "except SystemExit:\n"
    "    pass\n"
    "print(sorted(m for m in sys.modules if m.startswith('ballscrew.cli.')), file=sys.stderr)\n"
)


def _torque(mode: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", RUN_TORQUE, mode], capture_output=True,
                          text=True, check=True)  # fmt: skip


def test_help_lists_every_command_with_its_one_line_help() -> None:
    out = CliRunner().invoke(cli, ["--help"], terminal_width=200)
    assert out.exit_code == 0, out.output
    listed = out.output.split("Commands:\n", 1)[1].splitlines()
    assert [line.split()[0] for line in listed if line.strip()] == sorted(COMMANDS)
    for line in listed:
        name, shown = line.split(None, 1)
        command = cli.get_command(click.Context(cli), name)
        assert command is not None
        assert shown.strip().removesuffix("...") in (command.help or ""), name


def test_a_command_prints_the_same_loaded_alone_or_with_every_other() -> None:
    lazy, eager = _torque("lazy"), _torque("eager")
    assert lazy.stdout == eager.stdout and "complete" in lazy.stdout
    loaded = eval(lazy.stderr.strip().splitlines()[-1])  # the list printed last
    assert "ballscrew.cli.torque" in loaded
    assert not {"ballscrew.cli.study", "ballscrew.cli.serve", "ballscrew.cli.sweep"} & set(loaded)
