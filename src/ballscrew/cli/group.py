"""Command-line interface: ``ballscrew COMMAND``.

Exit status: 0 on success, 2 on bad input (one line naming the field), 1 on
an internal error.
"""

from __future__ import annotations

import functools
import importlib
import os
import signal
import sys
import warnings
from typing import Any

import click

from .._version import __version__
from ..errors import BallScrewInputError
from ..io.extras import MissingExtraError
from ..io.files import record_signal, signal_received
from .common import refuse_shared_outputs

__all__ = ["COMMANDS", "main"]

COMMANDS: dict[str, tuple[str, str]] = {
    "demo": ("demo", "demo"),
    "study": ("study", "study"),
    "validate": ("validate", "validate"),
    "models": ("models", "models_command"),
    "lubricants": ("lubricants", "lubricants_command"),
    "torque": ("torque", "torque"),
    "case": ("case", "case_command"),
    "screws": ("screws", "screws_command"),
    "energy": ("energy", "energy_command"),
    "check": ("check", "check_command"),
    "fit": ("fit", "fit_command"),
    "export-friction": ("export_friction", "export_friction_command"),
    "monitor": ("monitor", "monitor_command"),
    "acceptance": ("acceptance", "acceptance_command"),
    "serve": ("serve", "serve_command"),
    "sweep": ("sweep", "sweep_command"),
    "program": ("program", "program_command"),
    "contour": ("contour", "contour_command"),
    "select": ("select", "select_command"),
    "identify": ("identify", "identify_command"),
}
"""Each command's name, the module of :mod:`ballscrew.cli` that defines it and its name there.

A command's module is imported when the command is looked up (click's lazy subcommands): a
one-point ``ballscrew torque`` loads what torque needs, not the report, the sweep or the
web server; ``ballscrew --help`` loads them all to list each with its one-line help."""


class _LazyGroup(click.Group):
    """The group of :data:`COMMANDS`, each imported, guarded and named on first use."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*COMMANDS, *self.commands})

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name not in self.commands and cmd_name in COMMANDS:
            module, name = COMMANDS[cmd_name]
            command = getattr(importlib.import_module(f"{__package__}.{module}"), name)
            self.add_command(_name_values(cmd_name, _one_owner(command)), cmd_name)
        return self.commands.get(cmd_name)


@click.group(cls=_LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="ballscrew")
@click.option("--verbose", is_flag=True, default=False,
              help="Validity notes in full: each range left, its formulas and why.")  # fmt: skip
def cli(verbose: bool = False) -> None:
    """Ball screw friction torque, efficiency and power loss.

    \b
    Examples:
      ballscrew study --out report          # reproduce the study (bundled case)
      ballscrew case --template --out my_screw.toml
      ballscrew torque --case my_screw.toml --speed "0..3000 rpm" --model complete --model catalog
      ballscrew energy --case my_axis.toml --move "stroke=0.3 m, feed=0.5 m/s, acceleration=2 m/s^2"
      ballscrew check --case my_axis.toml --move "stroke=0.3 m, feed=0.5 m/s, acceleration=2 m/s^2"
      ballscrew fit --case my_screw.toml --measured run.csv --free preload,ball_train_constant
      ballscrew export-friction --case my_screw.toml --form stribeck --temperature "20, 40 degC"
      ballscrew contour --case x.toml --case y.toml --radius "50 mm" --feed "2 m/min"
      ballscrew monitor --case my_screw.toml --measured drag_torque.csv --threshold "50 %"
      ballscrew sweep examples/sweep_preload.toml --out preload.zarr --workers 2
      ballscrew program part.nc --machine examples/machine_vmc.toml --out part-report
      ballscrew select --case my_axis.toml --move "stroke=0.3 m, feed=0.5 m/s" --objective energy
      ballscrew identify trace.csv --machine examples/machine_vmc.toml --out identified
      ballscrew models
      ballscrew lubricants
      ballscrew serve                       # the web calculator on http://127.0.0.1:8050/
    """  # noqa: D301 - click needs the literal \b to keep the example lines


def _one_owner(command: click.Command) -> click.Command:
    """``command`` refusing, before it runs, two of its outputs on one path."""
    callback = command.callback
    if callback is None:
        return command

    @functools.wraps(callback)
    def guarded(*args: Any, **kwargs: Any) -> Any:
        _refuse_empty_values(command)
        refuse_shared_outputs(command, kwargs)
        return callback(*args, **kwargs)

    command.callback = guarded
    return command


KEEPS_EMPTY = frozenset({"host"})
"""Options whose empty value means something (``serve --host ""``: every interface)."""


def _refuse_empty_values(command: click.Command) -> None:
    """Refuse an option typed with an empty value (``--speed ""``, ``--json ""``).

    A shell variable left empty gives one; the commands took it as the option left out
    (the case's speeds, no JSON written) without a word.
    """
    ctx = click.get_current_context()
    for param in command.params:
        if not isinstance(param, click.Option) or param.name in KEEPS_EMPTY or not param.name:
            continue
        if ctx.get_parameter_source(param.name) is not click.core.ParameterSource.COMMANDLINE:
            continue
        value = ctx.params.get(param.name)
        values = value if isinstance(value, tuple) else (value,)
        for v in values:
            if isinstance(v, str) and not v.strip():
                raise BallScrewInputError(
                    param.opts[0], v, "a value: an empty text is none (leave the option out "
                    "for its default)",
                )  # fmt: skip


VALUE_NAMES: dict[str, str] = {
    "--axial-load": "FORCE",
    "--axis": "AXIS",
    "--axis-number": "N",
    "--bristle-damping": "DAMPING",
    "--bristle-stiffness": "STIFFNESS",
    "--case": "FILE",
    "--check": "FILE",
    "--cnc-build": "BUILD",
    "--confidence": "SHARE",
    "--csv": "FILE|-",
    "--cycles": "N",
    "--diameter": "LENGTHS",
    "--drive-unit": "UNIT",
    "--feed": "SPEED",
    "--free": "NAME,...",
    "--grade": "GRADE",
    "--guide-friction": "FORCE",
    "--host": "ADDRESS",
    "--inertia": "INERTIA",
    "--json": "FILE|-",
    "--kv": "GAIN",
    "--lead": "LENGTHS",
    "--lubricant": "NAME",
    "--machine": "FILE",
    "--maker": "MAKER",
    "--nut": "KIND",
    "--max-points": "N",
    "--measured": "FILE",
    "--model": "MODEL",
    "--objective": "OBJECTIVE",
    "--oil": "NAME",
    "--out": "FILE|-",
    "--phase-margin": "ANGLE",
    "--plot": "FILE",
    "--port": "PORT",
    "--pre-rolling": "LENGTH",
    "--preload": "CLASS",
    "--radius": "LENGTH",
    "--record": "FILE",
    "--reference": "TORQUE",
    "--run-time": "TIME",
    "--sampling-time": "TIME",
    "--smoothing": "TIME",
    "--validate": "FILE",
    "--calibrated": "FILE",
    "--seed": "N",
    "--scheduler": "ADDRESS",
    "--speed": "SPEEDS",
    "--start": "NAME=VALUE,...",
    "--standstill-speed": "SPEED",
    "--steady-speeds": "SPEEDS",
    "--temperature": "DEGC",
    "--threshold": "SHARE|TORQUE",
    "--tolerance": "SHARE",
    "--torque": "TORQUE",
    "--torque-constant": "TORQUE/CURRENT",
    "--uncertainty": "TORQUE",
    "--wiper-drag": "TORQUE",
    "--workers": "N",
}
"""What each option's value means, shown in the help where click would say TEXT or FLOAT;
an option that names its own (``--out FOLDER``, ``--json FILE|-``) keeps it."""

STORE_OPTIONS = {("sweep", "--out"): "STORE"}
"""Options whose value means something else in one command."""


def _name_values(name: str, command: click.Command) -> click.Command:
    """``command`` with every option and argument without a metavar naming what it takes."""
    for param in command.params:
        if param.metavar is not None or getattr(param, "is_flag", False):
            continue
        if isinstance(param, click.Argument):
            param.metavar = f"{param.name.split('_')[0].upper()}_FILE" if param.name else None
            continue
        if isinstance(param.type, click.Choice):
            continue  # click lists the choices
        flag = param.opts[0]
        param.metavar = STORE_OPTIONS.get((name, flag)) or VALUE_NAMES.get(flag)
    return command


def _terminate(signum: int, frame: object) -> None:
    """Treat SIGTERM like Ctrl-C: unwind, keep only complete files, exit 130.

    The signal is also recorded: a library that turns the KeyboardInterrupt
    raised inside its own code into another exception (numpy does, in a
    comparison of structured arrays) must still end the run as interrupted,
    not as an internal error.
    """
    record_signal(signum)
    raise KeyboardInterrupt


def _show_warning(
    message: Warning | str,
    category: type[Warning],
    filename: str,
    lineno: int,
    file: object = None,
    line: str | None = None,
) -> None:
    """A warning of the package as one plain ``warning:`` line on stderr, each text once."""
    text = str(message)
    if text not in _TOLD:
        _TOLD.add(text)
        click.echo(f"warning: {text}", err=True)


_TOLD: set[str] = set()


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``ballscrew`` command.

    Exit status: 0 on success, 2 on bad input (one line on stderr naming the
    field and the problem) or a missing extra (one line naming it), 1 on an
    internal error, 130 when interrupted.
    Warnings that reach the command line (a unit read one of two ways, a
    validity range left) are printed as plain ``warning:`` lines, once each.
    """
    record_signal(None)
    _TOLD.clear()
    warnings.showwarning = _show_warning
    previous = signal.signal(signal.SIGTERM, _terminate)
    previous_int = signal.signal(signal.SIGINT, _terminate)
    try:
        status = cli.main(args=argv, prog_name="ballscrew", standalone_mode=False)
    except (BallScrewInputError, MissingExtraError) as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(2)
    except click.exceptions.UsageError as exc:
        click.echo(f"error: {exc.format_message()} (see 'ballscrew --help')", err=True)
        sys.exit(2)
    except (click.exceptions.Abort, KeyboardInterrupt):
        click.echo(
            "interrupted: files already written are complete; nothing is half-written", err=True
        )
        sys.exit(130)
    except click.exceptions.ClickException as exc:
        click.echo(f"error: {exc.format_message()}", err=True)
        sys.exit(exc.exit_code)
    except Exception as exc:
        if signal_received():  # the interrupt, turned into another exception on its way up
            click.echo(
                "interrupted: files already written are complete; nothing is half-written",
                err=True,
            )
            sys.exit(130)
        if os.environ.get("BALLSCREW_TRACEBACK"):
            import traceback

            traceback.print_exc()
        click.echo(f"internal error: {type(exc).__name__}: {exc}", err=True)
        sys.exit(1)
    finally:
        signal.signal(signal.SIGTERM, previous)
        signal.signal(signal.SIGINT, previous_int)
    sys.exit(status if isinstance(status, int) else 0)
