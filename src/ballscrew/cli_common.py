"""Helpers shared by the command-line modules: consoles, progress bars, file options."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any, TypeVar

import click
from rich.console import Console
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

__all__ = ["case_option", "file_option", "progress", "stdout"]

F = TypeVar("F", bound=Callable[..., Any])


def stdout() -> Console:
    """Console for tables on standard output.

    The terminal's width; when the output is not a terminal (files, pipes) 200
    columns, unless ``COLUMNS`` says otherwise.
    """
    probe = Console()
    fixed = probe.is_terminal or "COLUMNS" in os.environ
    return Console(markup=False, width=None if fixed else 200)


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
