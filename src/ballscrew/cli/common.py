"""Helpers shared by the command-line modules: consoles, progress bars, file options."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click
from rich.console import Console

if TYPE_CHECKING:
    from rich.progress import Progress

__all__ = [
    "OUTPUT_OPTIONS",
    "case_option",
    "check_speeds",
    "echo_readings",
    "file_option",
    "folder_only",
    "motion",
    "own_case_option",
    "progress",
    "refuse_shared_outputs",
    "require_case",
    "result_document",
    "run_time_si",
    "stdout",
    "units_option",
    "write_json",
    "write_outputs",
    "write_result",
    "writing",
]  # fmt: skip

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


@contextlib.contextmanager
def writing(option: str, path: str | Path) -> Iterator[None]:
    """A file-system error while the block writes ``path``: an input error naming ``option``.

    A folder that cannot be made (a file is in the way), a place that takes no
    files, a full disk, no permission: the user gets the option and the path,
    with the system's reason, and exit status 2, not an internal error naming a
    temporary file. Another run holding the output keeps its own message.
    """
    from ..errors import BallScrewInputError
    from ..io.files import OutputInUseError

    try:
        yield
    except OutputInUseError:
        raise
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise BallScrewInputError(
            option, str(path), f"a path where the output can be written ({reason})"
        ) from None


def write_json(json_file: str, text: str, option: str = "--json") -> None:
    """Write JSON text to ``json_file`` atomically, or to standard output for ``-``."""
    import sys

    from ..io.files import atomic_write

    if json_file == "-":
        sys.stdout.write(text)
    else:
        with writing(option, json_file):
            atomic_write(Path(json_file), text.encode("utf-8"))


def result_document(document: Mapping[str, Any]) -> bytes:
    """A result's :meth:`as_dict` as the command's JSON bytes, the package version first."""
    from .._version import __version__
    from ..report.outputs import json_document

    return json_document({"ballscrew": __version__, **document}).encode("utf-8")


def write_result(json_file: str, document: Mapping[str, Any], option: str = "--json") -> None:
    """Write a result's :meth:`as_dict` as the command's JSON, the package version first."""
    from .._version import __version__
    from ..report.outputs import json_document

    write_json(json_file, json_document({"ballscrew": __version__, **document}), option)


def progress(console: Console) -> Progress:
    """A transient progress bar on ``console`` (spinner, description, bar, elapsed time)."""
    from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    return Progress(
        SpinnerColumn(),
        TextColumn("{task.description}"),
        BarColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
    )


def _case_option(text: str) -> Callable[[F], F]:
    return click.option("--case", "case_file", type=click.Path(dir_okay=False), default=None,
                        metavar="FILE", help=text)  # fmt: skip


case_option = _case_option("Case file (TOML with units); the bundled study case when omitted.")
"""``--case`` of a command that may show the bundled study case."""

own_case_option = _case_option(
    "Case file (TOML with units) of YOUR screw or axis: required, the command works on it "
    "(no bundled default)."
)
"""``--case`` of a command that judges or fits the user's own screw (no bundled default)."""


units_option = click.option(
    "--units", "units", type=click.Choice(["si", "imperial"], case_sensitive=False),
    default=None, metavar="si|imperial",
    help="Units of the printed results: si, or imperial (lbf, in, lbf*in, in/min, degF; rpm, "
    "W and J kept). Default: the case's [output] units, else si. JSON and CSV stay SI.",
)  # fmt: skip
"""``--units``: the unit system of a command's printed results (:mod:`ballscrew.io.display`)."""


def echo_readings(case: Any) -> None:
    """Say on standard error how the case file's texts that read two ways were read.

    A speed in Hz, a temperature in ``C`` (coulomb to pint): one ``note:`` line each,
    naming the field, as the command line's own options get (their warnings).
    """
    for a in case.assumptions:
        if a.reason.startswith("read as "):
            click.echo(f"note: {a.field} = {a.value!r} is {a.reason}", err=True)


def check_speeds(flag: str, text: str, speeds: Any) -> None:
    """Refuse screw ``speeds`` [rad/s] read from ``flag``'s ``text`` past the models' bound.

    Named by the flag, with the value as typed (the models' own check names ``speed`` in
    rad/s, which is not what the user wrote).
    """
    import math

    import numpy as np

    from ..design.limits import MAX_SPEED
    from ..errors import BallScrewInputError

    if np.any(np.abs(np.asarray(speeds, dtype=float)) > MAX_SPEED):
        raise BallScrewInputError(
            flag, text, f"screw speeds below {MAX_SPEED * 30.0 / math.pi:,.0f} rpm "
            f"({MAX_SPEED:g} rad/s) either way, past any ball screw",
        )  # fmt: skip


def run_time_si(text: str) -> float:
    """``--run-time`` [s], refused as typed unless more than 0 and at most the longest run.

    (The run's own check names the value in hours: '0 s' was refused as '0 h'.)
    """
    from ..axis.duty import MAX_RUN_TIME
    from ..errors import BallScrewInputError
    from ..io.units import to_si

    seconds = to_si("--run-time", text, "s")
    if not 0.0 < seconds <= MAX_RUN_TIME:
        raise BallScrewInputError(
            "--run-time", text, f"more than 0 and at most {MAX_RUN_TIME / 3600.0:,.0f} h"
        )
    return seconds


def require_case(case_file: str | None, command: str, why: str) -> str:
    """``case_file``, or a usage error (exit status 2) naming ``--case`` when it is missing.

    A command that judges or fits the user's screw must not fall back on the
    bundled study screw (20 mm lead): its lead, preload and ratings would give
    another screw's numbers without a word.
    """
    if case_file is None:
        raise click.UsageError(
            f"{command} needs --case FILE: {why}; without it the bundled study screw "
            "(20 mm lead) would be judged instead of yours (`ballscrew case --template` "
            "writes a case to fill in)"
        )
    return case_file


def folder_only(ctx: click.Context, param: click.Parameter, value: str | None) -> str | None:
    """A click callback: a report folder option refuses ``-`` (standard output is one file).

    Every single-file option (``--json``, ``--csv``, a file's ``--out``, ``--plot``)
    takes ``-`` for standard output; a report is a folder of files and has none.
    """
    del ctx
    if value is not None and value.strip() == "-":
        raise click.BadParameter(
            "'-' is standard output, which takes one file; this option writes a report "
            "folder (figures, CSV, Markdown, HTML): give a folder name",
            param=param,
        )
    return value


def folder_option(text: str, default: str | None = None) -> Callable[[F], F]:
    """``--out FOLDER``: a report folder (``-`` refused: standard output takes one file)."""
    return click.option("--out", "out_dir", type=click.Path(file_okay=False),
                        callback=folder_only, default=default, show_default=default is not None,
                        metavar="FOLDER", help=text)  # fmt: skip


def json_option(text: str = "Write the result as JSON to FILE ('-' for standard output).") -> (
    Callable[[F], F]
):  # fmt: skip
    """``--json FILE|-``: the result as JSON, to a file or standard output."""
    return click.option("--json", "json_file", default=None, metavar="FILE|-", help=text)


def verbose() -> bool:
    """Whether ``ballscrew --verbose`` asked for the validity notes in full."""
    ctx = click.get_current_context(silent=True)
    return bool(ctx is not None and ctx.find_root().params.get("verbose"))


def write_report(out_dir: str, write: Callable[[Path], list[Path]]) -> None:
    """A command's report written whole into ``out_dir`` (``--out``) by ``write(folder)``.

    The folder is swapped in when every file is written (:func:`ballscrew.io.files.
    atomic_folder`); an error names ``--out``; the report's page is said on stderr.
    """
    from ..io.files import atomic_folder

    with writing("--out", out_dir), atomic_folder(Path(out_dir)) as folder:
        files = write(folder)
    click.echo(f"report: {Path(out_dir) / 'report.html'} ({len(files)} files)", err=True)


def write_outputs(
    files: Sequence[tuple[str, str | None, bytes]] = (),
    report: tuple[str | None, Callable[[Path], list[Path]]] | None = None,
    said: Callable[[Path, int], str] | None = None,
) -> None:
    """A command's outputs put in place together (:class:`ballscrew.io.files.OutputSet`).

    ``files``: (option, path or None, bytes) each; ``report``: (``--out`` folder or None,
    ``write(folder)``). Nothing is in place until all are written: a run stopped on the
    way leaves every earlier output as it was. An output that cannot be written names its
    option and path, as :func:`writing` does. The report is then said on stderr,
    ``said(folder, files)`` when given, else its page and its count of files.
    """
    from ..io.files import OutputSet

    count: list[int] = []
    with OutputSet() as out:
        for option, path, data in files:
            if path:
                with writing(option, path):
                    out.file(path, data)
        if report is not None and report[0]:
            write = report[1]
            with writing("--out", report[0]):
                out.folder(report[0], lambda folder: count.append(len(write(folder))))
    if count and report is not None:
        folder = Path(str(report[0]))
        line = said(folder, count[0]) if said else f"report: {folder / 'report.html'}"
        click.echo(line if said else f"{line} ({count[0]} files)", err=True)


def motion_options(function: F) -> F:
    """``--move TEXT``, ``--profile FILE`` and ``--cycles N``: the duty of an axis command."""
    options = [
        click.option("--move", "move_text", default=None, metavar="KEY=VALUE,...",
                     help="e.g. 'stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, "
                     "force_from=50 mm, force_to=250 mm' (also jerk, dwell)."),
        click.option("--profile", "profile_file", type=click.Path(dir_okay=False), default=None,
                     metavar="FILE", help="A trajectory CSV (time, position or speed, force; "
                     "units in the header) instead of --move."),
        click.option("--cycles", default=1, show_default=True, type=click.IntRange(1, 100_000),
                     help="Back-and-forth cycles (out, dwell, back, dwell)."),
    ]  # fmt: skip
    for option in reversed(options):
        function = option(function)
    return function


def file_option(flag: str, dest: str, text: str) -> Callable[[F], F]:
    """A ``--flag FILE`` option for an output or input file."""
    return click.option(flag, dest, type=click.Path(dir_okay=False), default=None, help=text)


def motion(
    move_text: str | None, profile_file: str | None, cycles: int,
    standstill_speed: float | None = None,
) -> tuple[Any, dict[str, float]]:  # fmt: skip
    """The motion profile of ``--move`` or ``--profile`` (exactly one), and the move's fields.

    ``standstill_speed`` [m/s]: the width of the friction's sign near rest of a
    ``--profile`` (None: from its positions' noise); a ``--move`` is exact.
    """
    from ..axis.duty import profile_from_file, profile_from_move

    if (move_text is None) == (profile_file is None):
        raise click.UsageError("give exactly one of --move and --profile")
    if move_text is None:
        assert profile_file is not None
        return profile_from_file(profile_file, cycles, standstill_speed), {}
    from ..axis.motion import parse_move

    m = parse_move(move_text)
    return profile_from_move(m, cycles), m


OUTPUT_OPTIONS = ("--out", "--json", "--csv", "--plot")
"""The options through which a command writes a file or a report folder (``-``: standard
output)."""


def refuse_shared_outputs(command: click.Command, values: Mapping[str, Any]) -> None:
    """A usage error when two output options of one run name one place.

    ``--out x.fmu --json x.fmu`` would leave only the last written; a file inside
    a report folder (``--out rep --json rep/r.json``) is lost when the folder is
    replaced; two outputs on standard output (``-``) would be mixed. Paths are
    compared after following symbolic links.
    """
    given: list[tuple[str, str]] = []
    for param in command.params:
        flag = param.opts[0] if param.opts else ""
        value = values.get(param.name or "")
        if flag in OUTPUT_OPTIONS and isinstance(value, str | os.PathLike):
            given.append((flag, os.fspath(value)))
            path = given[-1][1]
            csv = flag == "--csv" or (flag == "--out" and path.lower().endswith(".csv"))
            if csv and path != "-":  # its provenance beside it
                given.append((f"{flag}'s provenance", path + ".meta.json"))
    for k, (flag_a, a) in enumerate(given):
        for flag_b, b in given[k + 1 :]:
            if a == "-" or b == "-":
                if a == b:
                    raise click.UsageError(
                        f"{flag_a} and {flag_b} both write to standard output ('-'): "
                        "give one of them a file"
                    )
                continue
            pa, pb = Path(os.path.realpath(a)), Path(os.path.realpath(b))
            if pa == pb:
                raise click.UsageError(
                    f"{flag_a} {a!r} and {flag_b} {b!r} are one file: the second would "
                    "replace the first; give each output its own path"
                )
            for outer, inner, flag_o, flag_i in ((pa, pb, flag_a, flag_b),
                                                 (pb, pa, flag_b, flag_a)):  # fmt: skip
                if outer in inner.parents:
                    raise click.UsageError(
                        f"{flag_i} {str(inner)!r} lies inside {flag_o} {str(outer)!r}: "
                        f"writing {flag_o} replaces it; give {flag_i} a path outside"
                    )
