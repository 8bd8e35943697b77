"""Helpers shared by the command-line modules: consoles, progress bars, file options."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any, TypeVar

import click
from rich.console import Console
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

__all__ = ["case_option", "file_option", "progress", "stdout", "write_json"]

F = TypeVar("F", bound=Callable[..., Any])


def stdout(json_file: str | None = None) -> Console:
    """Console for tables on standard output (standard error when JSON goes there).

    The terminal's width; when the output is not a terminal (files, pipes) 200
    columns, unless ``COLUMNS`` says otherwise. Without markup: unit headers
    such as ``[rpm]`` print as written.
    """
    probe = Console()
    fixed = probe.is_terminal or "COLUMNS" in os.environ
    return Console(markup=False, width=None if fixed else 200, stderr=json_file == "-")


def write_json(json_file: str, text: str) -> None:
    """Write JSON text to ``json_file`` atomically, or to standard output for ``-``."""
    import sys
    from pathlib import Path

    from ..files import atomic_write

    if json_file == "-":
        sys.stdout.write(text)
    else:
        atomic_write(Path(json_file), text.encode("utf-8"))


def progress(console: Console) -> Progress:
    """A transient progress bar on ``console`` (spinner, description, bar, elapsed time)."""
    return Progress(
        SpinnerColumn(),
        TextColumn("{task.description}"),
        BarColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
    )


case_option = click.option(
    "--case",
    "case_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="Case file (TOML with units); the bundled study case when omitted.",
)


def file_option(flag: str, dest: str, text: str) -> Callable[[F], F]:
    """A ``--flag FILE`` option for an output or input file."""
    return click.option(flag, dest, type=click.Path(dir_okay=False), default=None, help=text)
