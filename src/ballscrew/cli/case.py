"""``ballscrew case``: write a case-file template, check a case file, list its keys."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import click
from rich.table import Table

from ..io.numbers import text as num
from .common import stdout, writing

__all__ = ["case_command"]


@click.command("case")
@click.option("--template", "want_template", is_flag=True, help="Write a commented template.")
@click.option(
    "--out",
    "out_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="File for --template or --reference (default: print it).",
)
@click.option(
    "--check",
    "check_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="Validate a case file and print its resolved values in SI and usual units.",
)
@click.option("--reference", "want_reference", is_flag=True, help="Every key as a Markdown table.")
def case_command(
    want_template: bool, out_file: str | None, check_file: str | None, want_reference: bool
) -> None:
    """Write, check or document case files (TOML with units).

    \b
    Examples:
      ballscrew case --template --out my_screw.toml   # every key, commented
      ballscrew case --check my_screw.toml            # resolved values, or the error
      ballscrew torque --case my_screw.toml --speed "100, 1000 rpm"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..io.files import atomic_write
    from ..io.schema import reference_markdown, template

    if sum([want_template, want_reference, check_file is not None]) != 1:
        raise click.UsageError("give exactly one of --template, --check FILE, --reference")
    if want_template or want_reference:
        text = template() if want_template else reference_markdown()
        if out_file:
            with writing("--out", out_file):
                atomic_write(Path(out_file), text.encode("utf-8"))
            if out_file.strip() != "-":
                click.echo(f"wrote {out_file}", err=True)
        else:
            click.echo(text, nl=False)
        return
    assert check_file is not None
    _print_resolved(check_file)


class _Notes:
    """Numbered notes under the table: a value's source or how it was estimated, each once.

    A row shows its value and the note's number (``56.4 kN [2]``); two rows from one
    source (C_a and C_0a from one catalogue row) share a number. The table stays
    within 100 columns, the notes wrap as lines.
    """

    def __init__(self) -> None:
        self.texts: dict[str, int] = {}

    def __call__(self, value: str, note: str) -> str:
        """``value`` with the number of ``note`` (a new number for a new note).

        No note, or one that only names the case file's own key (a rating given in
        the file is sourced ``screw.dynamic_load_rating``): the value alone.
        """
        if not note or note.startswith("screw."):
            return value
        number = self.texts.setdefault(note, len(self.texts) + 1)
        return f"{value} [{number}]"


def _print_resolved(path: str) -> None:
    """Print a case as the models will use it: each value, its source, the assumptions.

    The table's cited notes are numbered in the order the rows are made (the
    designation's first) and printed below it; the plausibility findings go to
    stderr as warnings.
    """
    from ..design.ratings import plausibility, raise_errors
    from ..io.case import load_case
    from ..kinematics import rad_s_to_rpm

    case = load_case(path)
    ratings = case.load_ratings()
    found = raise_errors(plausibility(case.screw, ratings, case.axial_load))
    cite = _Notes()  # numbered in the order the rows are made: the designation's first
    rows = _screw_rows(case, ratings, cite)
    rows += _lubricant_rows(case, cite)
    rows += [
        ("operation", "speeds", _span(rad_s_to_rpm(case.speed), "rpm")),
        ("operation", "temperatures", _span(case.temperature, "degC")),
        ("operation", "axial loads", _span(case.axial_load, "N")),
    ]
    rows += _axis_rows(case, cite)
    rows += _check_rows(case)
    table = Table(title=f"{case.title}: resolved from {path}")
    for column in ("section", "quantity", "value"):
        table.add_column(column)
    for row in rows:
        table.add_row(*row)
    console = stdout()
    console.print(table)
    for note, number in cite.texts.items():
        console.print(f"[{number}] {note}", highlight=False)
    _print_assumptions(console, case)
    for finding in found:
        click.echo(f"warning: {finding}", err=True)
    console.print("case file OK", style="bold green")


def _screw_rows(case: Any, ratings: Any, cite: _Notes) -> list[tuple[str, str, str]]:
    """The ``[screw]`` section's rows: designation, geometry, ratings (cited), preload."""
    s = case.screw
    named = [("screw", "designation", cite(case.designation, case.screw_source))]
    named = named if case.designation else []
    wants = "; ballscrew check needs it: give screw.{}"
    static = f"{num(ratings.static / 1e3)} kN"
    if ratings.dynamic is None:
        dynamic = cite("not known", "the preload is not checked against it"
                       + wants.format("dynamic_load_rating"))  # fmt: skip
    else:
        dynamic = cite(f"{num(ratings.dynamic / 1e3)} kN", ratings.dynamic_source)
    if ratings.static_estimated:
        estimate = ratings.static_source.split("; give ")[0]
        static = cite(f"{static} (estimated)", estimate + wants.format("static_load_rating"))
    else:
        static = cite(static, ratings.static_source)
    return [
        *named,
        ("screw", "pitch diameter", f"{num(s.pitch_diameter * 1e3)} mm"),
        ("screw", "lead", f"{num(s.lead * 1e3)} mm"),
        ("screw", "ball diameter", f"{num(s.ball_diameter * 1e3)} mm"),
        ("screw", "contact angle", f"{num(math.degrees(s.contact_angle))} deg"),
        ("screw", "conformity screw / nut", f"{num(s.conformity_screw)} / {num(s.conformity_nut)}"),
        ("screw", "loaded turns x circuits", f"{s.loaded_turns:g} x {s.circuits}"),
        ("screw", "nut", s.nut),
        ("screw", "balls kept apart by", s.ball_separation),
        ("screw", "preload", f"{num(s.preload)} N"),
        ("screw", "dynamic load rating C_a", dynamic),
        ("screw", "static load rating C_0a", static),
        ("screw", "lead angle", f"{num(math.degrees(s.lead_angle))} deg"),
        ("screw", "loaded balls per nut", f"{s.balls_per_nut}"),
        ("screw", "gamma = D_w cos(alpha) / d_m", f"{num(s.gamma)}"),
        (
            "screw",
            "roughness ball / screw / nut",
            f"{s.roughness_ball * 1e6:.3g} / {s.roughness_screw * 1e6:.3g} / "
            f"{s.roughness_nut * 1e6:.3g} um",
        ),
        *([("screw", "wiper drag", f"{num(case.wiper_drag)} N*m")] if case.wiper_drag else []),
    ]


def _lubricant_rows(case: Any, cite: _Notes) -> list[tuple[str, str, str]]:
    """The ``[lubricant]`` section's rows: name, grease (cited), viscosities."""
    oil = case.lubricant
    return [
        ("lubricant", "name", oil.name),
        *(
            [("lubricant", "grease", cite(_grease(oil), "viscosities: the base oil's"))]
            if oil.kind == "grease"
            else []
        ),
        (
            "lubricant",
            "viscosity at 40 / 100 degC",
            f"{num(oil.nu40 * 1e6)} / {num(oil.nu100 * 1e6)} cSt",
        ),
        ("lubricant", "pressure-viscosity alpha", f"{num(oil.pressure_viscosity * 1e9)} 1/GPa"),
    ]


def _print_assumptions(console: Any, case: Any) -> None:
    """The case's assumed values, then those read one way, each with its reason."""
    from ..io.case import READ_AS

    read = [a for a in case.assumptions if a.reason.startswith(READ_AS)]
    assumed = [a for a in case.assumptions if not a.reason.startswith(READ_AS)]
    for group, header in ((assumed, "marked as assumed"), (read, "read one way, as given")):
        if group:
            console.print(f"{len(group)} value(s) {header}:")
        for a in group:
            console.print(f"  {a.field} = {a.value}: {a.reason}", highlight=False)


def _axis_rows(case: Any, cite: _Notes) -> list[tuple[str, str, str]]:
    """The ``[axis]`` section as ``ballscrew energy`` will use it (none if the file has none)."""
    import tomllib

    if "axis" not in tomllib.loads(case.text):
        return []
    from ..axis.setup import axis_setup

    axis_setup(case.screw, case.axis, case.thermal, 0.0)  # what energy checks, before it runs
    a, th = case.axis, case.thermal
    later = "(estimated by ballscrew energy)"

    def given(value: float | None, scale: float, unit: str, missing: str = later) -> str:
        return missing if value is None else f"{num(value * scale)} {unit}"

    bearings = (
        "not counted (no bearing_bore)"
        if a.get("bearing_bore") is None
        else f"{a['bearing_type']}, bore {num(a['bearing_bore'] * 1e3)} mm"
    )
    bearing_friction = (
        []
        if a.get("bearing_bore") is None
        else [("axis", "support bearing friction",
               "SKF's simplified estimate" if a.get("bearing_outer_diameter") is None
               else f"Palmgren's model ({a['bearing_lubrication']})")]
    )  # fmt: skip
    length = th.get("screw_length", a.get("bearing_span"))
    inertia = later
    if length is not None:
        from ..axis.setup import shaft_inertia

        j = float(shaft_inertia(case.screw.pitch_diameter, length))
        inertia = cite(f"{j:.3g} kg*m^2 (estimated)",
                       f"a solid steel shaft of the pitch diameter over {length * 1e3:.0f} mm, "
                       "as ballscrew energy takes it; give axis.screw_inertia from the "
                       "catalogue")  # fmt: skip
    return [
        ("axis", "moving mass", f"{num(a['moving_mass'])} kg"),
        ("axis", "screw inertia", given(a.get("screw_inertia"), 1.0, "kg*m^2", inertia)),
        ("axis", "coupling / motor inertia",
         f"{num(a['coupling_inertia'])} / {num(a['motor_inertia'])} kg*m^2"),
        ("axis", "gear ratio", f"{a['gear_ratio']:g}"),
        ("axis", "incline", f"{num(math.degrees(a['incline']))} deg"),
        ("axis", "support bearings", bearings),
        *bearing_friction,
        ("axis", "span, mounting", given(a.get("bearing_span"), 1e3, "mm",
                                         "none (critical speed not checked)")
         + f", {a['support']}"),
        ("axis", "d*n limit", f"{a['dn_limit']:,.0f} mm*rpm"),
        ("axis", "feed, acceleration limits",
         given(a.get("max_feed"), 1.0, "m/s", "none") + ", "
         + given(a.get("max_acceleration"), 1.0, "m/s^2", "none")),
        ("axis", "screw length in the air",
         given(th.get("screw_length"), 1e3, "mm",
               "the bearing span" if a.get("bearing_span") is not None else later)),
        ("axis", "ambient, machine resistance",
         f"{th['ambient']:g} degC, "
         + given(th.get("machine_resistance"), 1.0, "K/W", "none (convection only)")),
    ]  # fmt: skip


def _check_rows(case: Any) -> list[tuple[str, str, str]]:
    """``[motor]`` and ``[check]`` as ``ballscrew check`` will use them (the ratings: above)."""
    from ..kinematics import rad_s_to_rpm

    c = case.check
    rows = []
    m = case.motor
    for key in ("rated_torque", "peak_torque", "rated_speed", "torque_constant",
                "torque_constant_at_rated_speed"):  # fmt: skip
        if key in m:
            rpm = key == "rated_speed"
            unit = "rpm" if rpm else "N*m/A" if key.startswith("torque_constant") else "N*m"
            shown = float(rad_s_to_rpm(m[key])) if rpm else float(m[key])
            rows.append(("motor", key.replace("_", " "), f"{num(shown)} {unit}"))
    if "torque_constant" not in m:
        rows.append(("motor", "torque constant", "none (copper loss not computed)"))
    rows.append(("motor", "winding resistance",
                 "none (copper loss not computed)" if "winding_resistance" not in m
                 else f"{num(m['winding_resistance'])} ohm, {m['resistance_kind']}"
                 + (" (line to line: phase = half)" if m["resistance_kind"] == "terminal"
                    else "")))  # fmt: skip
    if "iron_loss" in m:
        unit = "N*m" if m["iron_loss_kind"] == "torque" else "W at the rated speed"
        rows.append(("motor", "iron and friction loss", f"{num(m['iron_loss'])} {unit}"))
    life = c.get("required_life")
    rows += [
        ("check", "required life",
         "20000 h (default)" if life is None else f"{num(life / 3600)} h"),
        ("check", "reliability, least static safety",
         f"{c['reliability']:.0%}, {c['static_safety']:g}"),
        ("check", "accuracy grade", c.get("accuracy_grade", "none (thermal error not judged)")),
        ("check", "thrust bearing stiffness",
         "rigid (not given)" if c.get("support_stiffness") is None
         else f"{num(c['support_stiffness'] / 1e6)} N/um"),
        ("check", "pre-tension absorbs", f"{c['pretension_temperature']:g} K"),
    ]  # fmt: skip
    return rows


def _grease(oil: Any) -> str:
    """A grease's thickener, NLGI grade and base oil, those its data give."""
    made = [oil.thickener, f"NLGI {oil.nlgi_grade}" if oil.nlgi_grade else "", oil.base_oil]
    return ", ".join(p for p in made if p)


def _span(values: object, unit: str) -> str:
    import numpy as np

    v = np.asarray(values, dtype=float)
    if v.size == 1:
        return f"{num(float(v[0]))} {unit}"
    return f"{v.size} values, {num(float(v.min()))} to {num(float(v.max()))} {unit}"
