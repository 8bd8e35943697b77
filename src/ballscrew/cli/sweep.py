"""``ballscrew sweep``: a design-space or uncertainty sweep into a Zarr store."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import click
from rich.console import Console
from rich.table import Table

from ..io.extras import require
from ..io.numbers import text as num
from .common import file_option, folder_only, progress, stdout, write_outputs, writing

__all__ = ["sweep_command"]


def _point(where: dict[str, Any], units: dict[str, str]) -> str:
    """A grid point in words, with units people read."""
    parts = []
    for key, value in where.items():
        if key == "speed":
            from ..kinematics import rad_s_to_rpm

            parts.append(f"{num(rad_s_to_rpm(value))} rpm")
        elif key == "temperature":
            parts.append(f"{value:g} °C")
        elif key == "axial_load":
            parts.append(f"{value:g} N load")
        elif key == "sample":
            parts.append(f"sample {value}")
        elif isinstance(value, float):
            unit = units.get(key, "1")
            parts.append(f"{key} {num(value)}" + (f" {unit}" if unit not in ("1", "") else ""))
        else:
            parts.append(f"{key} {value}")
    return ", ".join(parts)


def _summary_table(report: Any) -> Table:
    table = Table(title=f"Sweep summary: {report.plan.points:,} points")
    for col in ("output", "model", "min", "mean", "max", "max at"):
        table.add_column(col, justify="left" if col in ("output", "model", "max at") else "right")
    from ..sweep.spec import SCALAR_OUTPUTS

    fields = {a.name: a.unit for a in report.plan.spec.axes}
    if report.plan.spec.uncertainty is not None:
        fields |= {d.name: d.unit for d in report.plan.spec.uncertainty.inputs}
    for o in SCALAR_OUTPUTS:
        for model, s in report.summary.get(o.name, {}).items():
            table.add_row(
                f"{o.name} [{o.shown_unit}]", model, f"{num(s['min'])}", f"{num(s['mean'])}",
                f"{num(s['max'])}", _point(s["max_at"], fields),
            )  # fmt: skip
    return table


def _percentile_table(p: Any) -> Table:
    from ..kinematics import rad_s_to_rpm

    table = Table(title="Monte Carlo: friction torque percentiles [N·m]")
    table.add_column("model")
    table.add_column("speed [rpm]", justify="right")
    for q in p.percentiles:
        table.add_column(f"P{float(q):g}", justify="right")
    speeds = p.speeds
    picks = sorted({0, len(speeds) // 2, len(speeds) - 1})
    for model, values in p.torque.items():
        for i in picks:
            table.add_row(str(model), f"{num(rad_s_to_rpm(speeds[i]))}",
                          *(f"{num(v)}" for v in values[i]))  # fmt: skip
    return table


def _sobol_table(model: str, s: Any) -> Table:
    table = Table(title=f"Sobol indices of the mean torque: {model} (95 % half-widths)")
    for col in ("input", "total S_T", "first-order S_1"):
        table.add_column(col, justify="left" if col == "input" else "right")
    for i in s.ranking():
        table.add_row(
            s.names[i], f"{s.total[i]:.3f} ± {s.total_conf[i]:.3f}",
            f"{s.first[i]:.3f} ± {s.first_conf[i]:.3f}",
        )  # fmt: skip
    return table


def _figures(out: Path, report: Any) -> list[tuple[Path, bytes]]:
    """The sensitivity ranking figure of each model, to be written beside the store."""
    from ..report.plotting import figure_bytes, sensitivity_figure
    from ..sweep.store import figure_path

    drawn = []
    for model, s in report.sobol.items():
        fig = sensitivity_figure(s, f"Share of the torque variance: {model}")
        for kind in ("png", "svg"):
            drawn.append((figure_path(out, model, kind), figure_bytes(fig, kind)))
    return drawn


@click.command(name="sweep")
@click.argument("sweep_file", type=click.Path(dir_okay=False))
@click.option(
    "--out",
    "out",
    type=click.Path(),
    required=True,
    callback=folder_only,
    help="Zarr store to write (an earlier sweep store there is replaced when done).",
)
@click.option(
    "--workers", type=int, default=None, help="Run on a local Dask cluster of N processes."
)
@click.option(
    "--scheduler",
    default=None,
    help="Run on a running Dask cluster, e.g. tcp://10.0.0.5:8786 (its workers must see --out).",
)
@click.option(
    "--restart", is_flag=True, help="Discard the chunks an interrupted run left, start again."
)
@click.option(
    "--max-points",
    type=click.IntRange(min=1),
    default=None,
    help="Run a sweep of more points than the default limit (100,000,000); the size, store "
    "and time are estimated and printed before it starts.",
)
@file_option("--json", "json_file", "Write the summary as JSON to FILE ('-' for standard output).")
def sweep_command(
    sweep_file: str,
    out: str,
    workers: int | None,
    scheduler: str | None,
    restart: bool,
    max_points: int | None,
    json_file: str | None,
) -> None:
    """Sweep a design space or propagate uncertainty; the result is a Zarr store.

    The sweep file names a base case, the axes (operating points, case fields,
    model parameters), the models and outputs, and optionally uncertain inputs
    (Monte Carlo percentiles, Sobol indices). See docs/sweeps.md.

    \b
    Examples:
      ballscrew sweep examples/sweep_preload.toml --out preload.zarr
      ballscrew sweep examples/sweep_uncertainty.toml --out mc.zarr --workers 2
      ballscrew sweep big.toml --out big.zarr --scheduler tcp://127.0.0.1:8786
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    require("sweep", "ballscrew sweep")
    from ..io.files import signal_received
    from ..sweep.execute import run_sweep
    from ..sweep.store import partial_path

    target = Path(out)
    console = Console(stderr=True)
    counts = [0, 0]
    with progress(console) as bar:
        task = bar.add_task("chunks", total=None)

        def step(done: int, total: int) -> None:
            counts[:] = [done, total]
            bar.update(task, completed=done, total=total, description=f"chunks {done}/{total}")

        try:
            with writing("--out", out):
                report = run_sweep(
                    sweep_file, target, max_points=max_points, workers=workers,
                    scheduler=scheduler, restart=restart, progress=step,
                    notify=lambda text: console.print(text, highlight=False),
                    companions=[Path(json_file)] if json_file and json_file != "-" else [],
                )  # fmt: skip
        except (KeyboardInterrupt, Exception) as exc:
            if not isinstance(exc, KeyboardInterrupt) and not signal_received():
                raise
            click.echo(
                f"interrupted: {counts[0]} of {counts[1]} chunks are kept in "
                f"{partial_path(target.absolute())}; run the same command again to resume "
                f"(--restart to start over); {target} was not written",
                err=True,
            )
            raise KeyboardInterrupt from exc
    console_out = stdout(json_file)
    console_out.print(_summary_table(report))
    if report.percentiles is not None:
        console_out.print(_percentile_table(report.percentiles))
    for model, s in report.sobol.items():
        console_out.print(_sobol_table(model, s))
    drawn = _figures(target, report)
    summary = json.dumps(report.as_dict(), indent=2, ensure_ascii=False) + "\n"
    # The figures and the JSON are put in place together, or none of them. The store, which
    # a run can resume, is swapped in by run_sweep when its last chunk is written, and the
    # earlier run's figures and JSON are moved aside with the store they came from: a run
    # stopped in between leaves the new store alone, never beside the old figures.
    write_outputs(
        [("--out", str(path), data) for path, data in drawn]
        + [("--json", json_file, summary.encode("utf-8") if json_file else b"")]
    )
    for line in report.issues:  # "warning: ..." or, for routine ranges, "note: ..."
        click.echo(line, err=True)
    shown = _store_line(report, [path for path, _ in drawn])
    click.echo(f"store: {target} {shown}", err=json_file == "-")


def _store_line(report: Any, figures: list[Path]) -> str:
    """What the run did, its rate and the figures it drew, for the closing line."""
    rate = report.points_per_second
    parts = [f"{report.plan.points:,} points in {report.plan.n_chunks} chunks",
             f"{report.computed} computed {report.mode}"]  # fmt: skip
    if report.resumed:
        parts.append(f"{report.resumed} resumed")
    if math.isfinite(rate):
        parts.append(f"{rate:.3g} points/s")
    pngs = [str(p) for p in figures if p.suffix == ".png"]
    shown = f"; figures: {', '.join(pngs)}" if pngs else ""
    return f"({'; '.join(parts)}){shown}"
