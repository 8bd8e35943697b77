"""``ballscrew demo``: a contact and lubricant summary of the bundled reference screw."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import click
from rich.console import Console
from rich.table import Table

if TYPE_CHECKING:
    from ..geometry import BallScrew
    from ..lubricant import Lubricant

__all__ = ["demo"]


@click.command()
@click.option(
    "--lubricant",
    "lubricant_name",
    default="PAO ISO VG 68",
    show_default=True,
    help="Name of a bundled lubricant.",
)
@click.option(
    "--temperature",
    default=40.0,
    show_default=True,
    type=float,
    help="Lubricant temperature for the film table [°C].",
)
def demo(lubricant_name: str, temperature: float) -> None:
    """Print a contact and lubricant summary for the bundled reference screw.

    \b
    Examples:
      ballscrew demo
      ballscrew demo --lubricant "SAE 20" --temperature 30
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from .. import lubricants
    from ..geometry import reference_screw

    console = Console(width=110, markup=False)
    screw = reference_screw()
    oil = lubricants.get(lubricant_name)
    console.print("demo: the bundled reference screw (the study's, not yours: `ballscrew torque "
                  "--case FILE` computes your case)")  # fmt: skip
    console.print(_geometry_table(screw))
    console.print(_hertz_table(screw, oil, temperature))
    console.print(_viscosity_table())
    console.print(_film_table(screw, oil, temperature))


def _geometry_table(screw: BallScrew) -> Table:
    """The screw's dimensions, preload, loaded balls and reduced modulus."""
    geo = Table(title="Reference ball screw (bundled example)", show_header=False)
    rows = [
        ("pitch diameter", f"{screw.pitch_diameter * 1e3:.4g} mm"),
        ("lead / lead angle", f"{screw.lead * 1e3:.4g} mm / {math.degrees(screw.lead_angle):.4g}°"),
        ("ball diameter", f"{screw.ball_diameter * 1e3:.4g} mm"),
        ("contact angle", f"{math.degrees(screw.contact_angle):.1f}°"),
        ("conformity screw / nut", f"{screw.conformity_screw:.4g} / {screw.conformity_nut:.4g}"),
        ("nut / preload", f"{screw.nut} / {screw.preload:.0f} N"),
        ("loaded balls per (half-)nut", f"{screw.balls_per_nut}"),
        ("reduced modulus E'", f"{screw.reduced_modulus / 1e9:.4g} GPa"),
    ]
    for key, value in rows:
        geo.add_row(key, value)
    return geo


def _hertz_table(screw: BallScrew, oil: Lubricant, temperature: float) -> Table:
    """Each contact by every Hertz method at the preload's ball load."""
    from ..contact import HERTZ_METHODS, hertz
    from ..state import operating_state

    state0 = operating_state(screw, oil, speed=0.0, temperature=temperature)
    q = float(state0.loads.normal_load_1)
    ht = Table(title=f"Hertz contact at the preload, Q = {q:.4g} N per ball")
    for col in ("contact", "method", "a [mm]", "b [mm]", "a/b", "p_max [GPa]", "approach [µm]"):
        ht.add_column(col, justify="right")
    for side, rx, ry in (
        ("screw", screw.rx_screw, screw.ry_screw),
        ("nut", screw.rx_nut, screw.ry_nut),
    ):
        for method in HERTZ_METHODS:
            c = hertz(q, rx, ry, screw.reduced_modulus, method=method)
            ht.add_row(
                side,
                method,
                f"{float(c.a) * 1e3:.4g}",
                f"{float(c.b) * 1e3:.4g}",
                f"{float(c.ellipticity):.4g}",
                f"{float(c.p_max) / 1e9:.4g}",
                f"{float(c.approach) * 1e6:.4g}",
            )
    return ht


def _viscosity_table() -> Table:
    """Every bundled lubricant's kinematic viscosity at six temperatures and its α."""
    import numpy as np

    from .. import lubricants

    temps = np.array([20.0, 30.0, 40.0, 45.0, 60.0, 100.0])
    vt = Table(title="Bundled lubricants: kinematic viscosity [mm²/s] (ASTM D341)")
    vt.add_column("lubricant")
    for t in temps:
        vt.add_column(f"{t:g} °C", justify="right")
    vt.add_column("α [1/GPa]", justify="right")
    for lub in lubricants.all_lubricants():
        nu = lub.kinematic_viscosity(temps) * 1e6
        vt.add_row(lub.name, *(f"{v:.4g}" for v in nu), f"{lub.pressure_viscosity * 1e9:.3g}")
    return vt


def _film_table(screw: BallScrew, oil: Lubricant, temperature: float) -> Table:
    """The EHL film of the screw's and the nut's contacts at four speeds."""
    import numpy as np

    from ..kinematics import rpm_to_rad_s
    from ..state import operating_state

    speeds_rpm = np.array([10.0, 100.0, 1000.0, 3000.0])
    st = operating_state(screw, oil, speed=rpm_to_rad_s(speeds_rpm), temperature=temperature)
    ft = Table(title=f"EHL film of {oil.name} at {temperature:g} °C (Hamrock-Dowson 1977)")
    for col in ("contact", "speed [rpm]", "u [m/s]", "h_min [µm]", "h_c [µm]", "Λ", "A_c/A_0"):
        ft.add_column(col, justify="right")
    for contact in st.contacts[:2]:
        for i, n in enumerate(speeds_rpm):
            ft.add_row(
                contact.name,
                f"{n:g}",
                f"{contact.entrainment_speed[i]:.4g}",
                f"{contact.film_minimum[i] * 1e6:.4g}",
                f"{contact.film_central[i] * 1e6:.4g}",
                f"{contact.film_parameter[i]:.4g}",
                f"{contact.asperity_share[i]:.4g}",
            )
    return ft
