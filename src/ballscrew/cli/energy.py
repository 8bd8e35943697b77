"""``ballscrew energy``: friction energy, motor torques of a feed axis over a motion cycle."""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import click
from rich.console import Console
from rich.table import Table

__all__ = ["energy_command", "parse_move"]

_MOVE_KEYS = {
    "stroke": ("m", True),
    "feed": ("m/s", True),
    "acceleration": ("m/s**2", True),
    "jerk": ("m/s**3", False),
    "dwell": ("s", False),
    "force": ("N", False),
    "force_from": ("m", False),
    "force_to": ("m", False),
}


def parse_move(text: str) -> dict[str, float]:
    """``"stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"`` to SI values by key.

    Keys: stroke, feed, acceleration (required); jerk, dwell, force (the
    process force on the way out), force_from, force_to (its window, distances
    from the start).
    """
    from ..errors import BallScrewInputError
    from ..units import to_si

    out: dict[str, float] = {}
    for part in (p.strip() for p in text.split(",") if p.strip()):
        key, sep, value = part.partition("=")
        key = key.strip()
        if not sep or key not in _MOVE_KEYS:
            raise BallScrewInputError(
                "--move", part, f"key=value with a unit; keys: {', '.join(_MOVE_KEYS)}"
            )
        out[key] = to_si(f"--move {key}", value.strip().replace("^", "**"), _MOVE_KEYS[key][0])
    missing = [k for k, (_, needed) in _MOVE_KEYS.items() if needed and k not in out]
    if missing:
        raise BallScrewInputError("--move", text, f"also {', '.join(missing)} (with units)")
    return out


@click.command("energy")
@click.option("--case", "case_file", type=click.Path(dir_okay=False), default=None,
              help="Case file with an [axis] section (default: the bundled case).")  # fmt: skip
@click.option(
    "--move",
    "move_text",
    default=None,
    help="e.g. 'stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, "
    "force_from=50 mm, force_to=250 mm' (also jerk, dwell).",
)
@click.option("--cycles", default=1, show_default=True, type=click.IntRange(1, 100_000),
              help="Back-and-forth cycles (out, dwell, back, dwell).")  # fmt: skip
@click.option("--model", "model_names", multiple=True, default=["complete"], show_default=True,
              help="Friction model; repeat for several.")  # fmt: skip
@click.option("--temperature", default=None, help="Lubricant temperature, e.g. '40 degC' "
              "(default: the case's first).")  # fmt: skip
@click.option("--profile", "profile_file", type=click.Path(dir_okay=False), default=None,
              help="A trajectory CSV (time, position or speed, force; units in the header) "
              "instead of --move.")  # fmt: skip
@click.option("--run-time", default="1 h", show_default=True,
              help="How long the cycle repeats, for the temperature reached.")  # fmt: skip
@click.option("--steady-speeds", default=None,
              help="Also the steady temperature and torque of continuous running at these "
              "speeds, e.g. '500..3000:6 rpm' (under the move's process force).")  # fmt: skip
@click.option("--out", "out_dir", type=click.Path(file_okay=False), default=None,
              help="Write a report (Markdown, HTML, plots, CSV) into this folder.")  # fmt: skip
@click.option("--json", "json_file", default=None,
              help="Write the results as JSON to FILE ('-' for standard output).")  # fmt: skip
def energy_command(
    case_file: str | None,
    move_text: str | None,
    cycles: int,
    model_names: tuple[str, ...],
    temperature: str | None,
    profile_file: str | None,
    run_time: str,
    out_dir: str | None,
    json_file: str | None,
    steady_speeds: str | None = None,
) -> None:
    """Friction energy and motor torques of the case's axis over back-and-forth cycles.

    \b
    Example:
      ballscrew energy --case my_axis.toml --cycles 10 \\
        --move "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, \\
                force_from=50 mm, force_to=250 mm"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    import warnings

    import numpy as np

    from .. import __version__
    from ..axis.energy import axis_cycle, weight_back_driving
    from ..axis.motion import back_and_forth, chain, read_trajectory
    from ..axis.setup import axis_setup
    from ..axis.thermal import steady_at_speeds, steady_temperature, temperature_history
    from ..io.case import load_case
    from ..report.outputs import json_document
    from ..units import parse_range, to_si
    from .common import write_json

    case = load_case(case_file)
    if (move_text is None) == (profile_file is None):
        raise click.UsageError("give exactly one of --move and --profile")
    m: dict[str, float] = {}
    if move_text is not None:
        m = parse_move(move_text)
        window = None
        if "force_from" in m or "force_to" in m:
            window = (m.get("force_from", 0.0), m.get("force_to", abs(m["stroke"])))
        profile = back_and_forth(
            m["stroke"], m["feed"], m["acceleration"], jerk=m.get("jerk"),
            dwell_time=m.get("dwell", 0.0), cycles=cycles, process_force=m.get("force", 0.0),
            force_window=window,
        )  # fmt: skip
    else:
        assert profile_file is not None
        one = read_trajectory(Path(profile_file).read_text(encoding="utf-8"), profile_file)
        profile = chain(*([one] * cycles))
    hours = to_si("--run-time", run_time, "s")
    speeds = None if steady_speeds is None else parse_range("--steady-speeds", steady_speeds,
                                                              "rad/s")  # fmt: skip
    temp = (
        to_si("--temperature", temperature, "degC")
        if temperature
        else float(case.temperature.flat[0])
    )
    setup = axis_setup(case.screw, case.axis, case.thermal, float(np.ptp(profile.position)))
    axis, node, assumptions = setup.axis, setup.node, list(setup.notes)
    thermal = {k: getattr(node, k) for k in ("screw_length", "ambient", "machine_resistance",
                                              "nut_mass")}  # fmt: skip
    results: dict[str, Any] = {}
    cycles_by_model: dict[str, Any] = {}
    histories: dict[str, Any] = {}
    steady_tables: dict[str, Any] = {}
    speed_warnings: list[str] = []
    for name in model_names:
        params = dict(case.model_parameters.get(name, {}))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the speed limits are kept in the result
            r = axis_cycle(profile, case.screw, case.lubricant, axis, temperature=temp,
                           model=name, **params)  # fmt: skip
        speed_warnings = list(r.speed_warnings)
        cycles_by_model[name] = r
        results[name] = {
            "friction_energy_J": r.friction_energy,
            "friction_energy_per_cycle_J": r.friction_energy / cycles,
            "friction_energy_out_J": r.friction_energy_out,
            "friction_energy_back_J": r.friction_energy_back,
            "friction_energy_by_mechanism_J": r.friction_energy_by_mechanism,
            "bearing_energy_J": r.bearing_energy,
            "constant_efficiency_energy_J": r.constant_efficiency_energy,
            "load_work_J": r.load_work,
            "peak_motor_torque_Nm": r.peak_motor_torque,
            "rms_motor_torque_Nm": r.rms_motor_torque,
            "forward_efficiency": r.forward_efficiency,
            "reverse_efficiency": r.reverse_efficiency,
            "self_locking": r.reverse_efficiency <= 0.0,
            "weight_reverse_efficiency": weight_back_driving(
                case.screw, case.lubricant, axis, temperature=temp, model=name, **params
            ),
            "duration_s": profile.duration,
            "warnings": [str(issue) for issue in r.friction.warnings] + list(r.speed_warnings),
        }
        steady = steady_temperature(profile, case.screw, case.lubricant, axis, node,
                                    model=name, **params)  # fmt: skip
        times, history = temperature_history(
            profile, case.screw, case.lubricant, axis, node, hours, model=name, points=50,
            **params,
        )  # fmt: skip
        histories[name] = (times, history)
        results[name]["steady_temperature_C"] = steady.temperature
        results[name]["final_temperature_C"] = float(history[-1])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            warm = axis_cycle(profile, case.screw, case.lubricant, axis,
                              temperature=float(history[-1]), model=name, **params)  # fmt: skip
        results[name]["friction_energy_at_final_temperature_J"] = warm.friction_energy
        if speeds is not None:
            at = steady_at_speeds(case.screw, case.lubricant, node, speeds,
                                  axial_load=m.get("force", 0.0), model=name,
                                  **params)  # fmt: skip
            steady_tables[name] = at
            results[name]["steady_at_speed"] = {
                "speed_rpm": (at.speed * 30 / np.pi).tolist(),
                "temperature_C": at.temperature.tolist(),
                "torque_Nm": at.torque.tolist(),
                "power_W": at.power.tolist(),
            }
    for line in speed_warnings:
        click.echo(f"warning: {line}", err=True)
    for line in assumptions:
        click.echo(f"note: {line}", err=True)
    table = Table(title=f"{case.title}: {cycles} cycle(s), {profile.duration:.4g} s, {temp:g} °C")
    for column in ("model", "friction energy [J]", "per cycle [J]", "catalogue rule [J]",
                   "bearings [J]", "efficiency fwd / back", "peak motor torque [N*m]",
                   "RMS motor torque [N*m]",
                   f"temperature after {run_time} [degC]"):  # fmt: skip
        table.add_column(column, justify="right")
    for name, v in results.items():
        table.add_row(
            name,
            f"{v['friction_energy_J']:.4g}",
            f"{v['friction_energy_per_cycle_J']:.4g}",
            f"{v['constant_efficiency_energy_J']:.4g}",
            f"{v['bearing_energy_J']:.4g}",
            f"{v['forward_efficiency']:.3f} / {v['reverse_efficiency']:.3f}",
            f"{v['peak_motor_torque_Nm']:.4g}",
            f"{v['rms_motor_torque_Nm']:.4g}",
            f"{v['final_temperature_C']:.3g}",
        )
    probe = Console()
    wide = probe.is_terminal or "COLUMNS" in os.environ
    out = Console(stderr=json_file == "-", markup=False, width=None if wide else 200)
    out.print(table)
    for name, v in results.items():
        eta = v["weight_reverse_efficiency"]
        if not math.isnan(eta):
            # The catalogue's test: a load back-drives the screw when the reverse
            # efficiency is positive.
            verdict = (
                "it turns the screw: hold the axis with a brake"
                if eta > 0.0
                else "the screw holds it (self-locking)"
            )
            out.print(
                f"{name}: the weight along the axis ({math.degrees(axis.incline):g} deg), motor "
                f"off: reverse efficiency {eta:.3f}; {verdict}"
            )
    for name, at in steady_tables.items():
        st = Table(title=f"{name}: continuous running at {m.get('force', 0.0):g} N")
        for column in ("speed [rpm]", "steady temperature [degC]", "torque [N*m]", "power [W]"):
            st.add_column(column, justify="right")
        for w, tc, tq, pw in zip(at.speed, at.temperature, at.torque, at.power, strict=True):
            st.add_row(f"{w * 30 / np.pi:.4g}", f"{tc:.3g}", f"{tq:.4g}", f"{pw:.4g}")
        out.print(st)
    if out_dir:
        from ..report.energy import write_energy_report

        files = write_energy_report(out_dir, case.title, profile, cycles_by_model, results,
                                    histories or None)  # fmt: skip
        click.echo(f"report: {Path(out_dir) / 'report.html'} ({len(files)} files)", err=True)
    if json_file:
        first = results[model_names[0]]
        payload = {
            "ballscrew": __version__,
            "case": case.title,
            "model": model_names[0],
            **{k: v for k, v in first.items() if k != "steady_at_speed"},
            "move": m,
            "cycles": cycles,
            "temperature_C": temp,
            "axis": {k: getattr(axis, k) for k in axis.__dataclass_fields__},
            "thermal": thermal,
            "assumptions": assumptions,
            "models": results,
        }
        write_json(json_file, json_document(payload))
