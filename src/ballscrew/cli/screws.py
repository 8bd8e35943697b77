"""``ballscrew screws``: the catalogue nuts a case can name."""

from __future__ import annotations

import click
from rich.table import Table

from .common import stdout

__all__ = ["screws_command"]


@click.command("screws")
def screws_command() -> None:
    """List the bundled catalogue nuts a case file's designation can name.

    \b
    Example:
      ballscrew screws
      then in a case file:  designation = "HIWIN R40-10K5-FDC"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..io.designation import catalog_screws

    table = Table(title="Catalogue ball screw nuts (values as printed; - = not printed)")
    for column in ("designation", "nut", "d x lead [mm]", "ball [mm]", "turns x circuits",
                   "C_a [kN]", "page"):  # fmt: skip
        table.add_column(column, no_wrap=column == "designation")
    for s in catalog_screws():
        turns = f"{s.loaded_turns:g}" if s.loaded_turns is not None else "-"
        if s.loaded_turns is not None and not s.turns_status.startswith("read"):
            turns += "*"
        table.add_row(
            s.name,
            s.nut,
            f"{s.nominal_diameter * 1e3:g} x {s.lead * 1e3:g}",
            f"{s.ball_diameter * 1e3:g}" if s.ball_diameter is not None else "-",
            f"{turns} x {s.circuits}",
            f"{s.dynamic_load_rating / 1e3:g}" if s.dynamic_load_rating is not None else "-",
            s.page,
        )
    console = stdout()
    console.print(table)
    console.print(
        "* turns per circuit not printed: derived or assumed (see ballscrew case --check)"
    )
    for maker, source in {s.maker: s.source for s in catalog_screws()}.items():
        console.print(f"{maker}: {source}", highlight=False)
