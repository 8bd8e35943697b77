"""The study report: figures, CSV data, Markdown and HTML pages, and the run record.

:func:`write_report` writes into one folder:

* ``figures/<key>.png`` and ``.svg`` for every figure;
* ``data/<key>.csv`` with every plotted series, units in the column names;
* ``report.md`` and ``report.html`` (self-contained: figures embedded);
* ``run.json``, the run record: package version, the case file's text and
  the measured curve's text, from which :func:`regenerate` writes the same
  report again, byte for byte.

Every file is written atomically (a temporary file in the same folder, then
renamed), so an interrupted run leaves each file either complete or as it was.
"""

from __future__ import annotations

import inspect
import json
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from .._version import __version__
from ..contact import hertz
from ..errors import BallScrewInputError
from ..friction import get_model
from ..io.case import Case, parse_case
from ..io.files import atomic_write, read_input_text, sweep_temporaries
from ..io.measured import MeasuredCurve, parse_measured
from ..kinematics import rad_s_to_rpm, rpm_to_rad_s
from ..loads import ball_loads
from ..study.reproduce import StudyResult, StudySensitivity, run_study
from .document import Block, html_page, markdown
from .outputs import csv_bytes
from .plotting import figure_bytes, render, sensitivity_figure

__all__ = ["regenerate", "write_report"]

RECORD_NAME = "run.json"
SENSITIVITY_KEY = "fig13_sensitivity"


def _fmt(x: float, digits: int = 4) -> str:
    return "n/a" if not math.isfinite(x) else f"{x:.{digits}g}"


def _title(result: StudyResult) -> str:
    return f"Ball screw friction study: {result.case.title}"


def _opening(result: StudyResult) -> list[Block]:
    """The title and the paragraph that says what was computed, by which version."""
    case = result.case
    return [
        Block("h1", _title(result)),
        Block(
            "p",
            (
                "Reproduction of J. Sušeň, 'A Study on the Ball Screw Friction Torque', "
                if result.reproduction
                else "The friction models of J. Sušeň's study ('A Study on the Ball Screw "
                "Friction Torque') and the complete model, applied to this case, "
            )
            + f"computed by ballscrew {__version__}. {' '.join(case.description.split())}".strip(),
        ),
    ]


def _findings(result: StudyResult) -> list[Block]:
    return [Block("ul", list(result.findings))]


def _input_rows(result: StudyResult) -> list[tuple[str, str, str]]:
    """The inputs table's rows: quantity, value and the case field it comes from."""
    case = result.case
    s = case.screw
    return [
        ("pitch diameter", f"{s.pitch_diameter * 1e3:g} mm", "screw.pitch_diameter"),
        ("lead", f"{s.lead * 1e3:g} mm", "screw.lead"),
        ("ball diameter", f"{s.ball_diameter * 1e3:g} mm", "screw.ball_diameter"),
        ("contact angle", f"{math.degrees(s.contact_angle):g}°", "screw.contact_angle"),
        (
            "conformity screw / nut",
            f"{s.conformity_screw:g} / {s.conformity_nut:g}",
            "screw.conformity_screw",
        ),
        ("loaded turns x circuits", f"{s.loaded_turns:g} x {s.circuits}", "screw.loaded_turns"),
        ("nut", s.nut, "screw.nut"),
        ("reference preload", f"{s.preload:.0f} N", "screw.preload_drag_torque"),
        (
            "roughness ball / screw / nut",
            f"{s.roughness_ball * 1e6:g} / {s.roughness_screw * 1e6:g} / "
            f"{s.roughness_nut * 1e6:g} µm",
            "screw.roughness_ball",
        ),
        ("lubricant", case.lubricant.name, "lubricant.name"),
        (
            "speed range",
            f"{rad_s_to_rpm(case.speed.min()):g} to {rad_s_to_rpm(case.speed.max()):g} rpm",
            "operation.speed",
        ),
        ("temperature (Figs. 3-7)", f"{case.study_temperature:g} °C", "study.temperature"),
        ("axial load", f"{result.axial_load:g} N", "operation.axial_load"),
    ]


def _inputs(result: StudyResult) -> list[Block]:
    """The inputs, each given, from the catalogue, a default or assumed (with the reason)."""
    assumed = {a.field: a.reason for a in result.case.assumptions}
    sources = result.case.sources
    rows = [
        (q, v, "assumed: " + assumed[f] if f in assumed else sources.get(f, "given"))
        for q, v, f in _input_rows(result)
    ]
    oil = result.case.lubricant
    return [
        Block("table", (["quantity", "value", "status"], rows)),
        Block(
            "p",
            f"Lubricant {oil.name}: ν40 = {oil.nu40 * 1e6:g} mm²/s, "
            f"ν100 = {oil.nu100 * 1e6:g} mm²/s, ρ15 = {oil.density15:g} kg/m³, "
            f"α = {oil.pressure_viscosity * 1e9:g} 1/GPa; source: {oil.source}.",
        ),
    ]


def _preload_rows(result: StudyResult) -> list[tuple[str, ...]]:
    """Per preload: drag torque, preload, ball load and the Hertz contact at the screw."""
    s = result.case.screw
    rows: list[tuple[str, ...]] = []
    for torque, force in result.preloads.items():
        q = float(ball_loads(s.replace(preload=force)).normal_load_1)
        c = hertz(q, s.rx_screw, s.ry_screw, s.reduced_modulus, method="exact")
        rows.append(
            (
                f"{torque:g}",
                f"{force:.0f}",
                f"{q:.2f}",
                f"{float(c.a) * 1e3:.3f}",
                f"{float(c.b) * 1e3:.4f}",
                f"{float(c.p_max) / 1e9:.3f}",
            )
        )
    return rows


def _derived(result: StudyResult) -> list[Block]:
    """Lead angle and loaded balls, the preloads' contacts, and Table 1's viscosities."""
    s = result.case.screw
    preload_header = ["drag torque [N·m]", "preload [N]", "ball load [N]", "a [mm]", "b [mm]",
                      "p_max [GPa]"]  # fmt: skip
    return [
        Block(
            "p",
            f"Lead angle {math.degrees(s.lead_angle):.2f}°, "
            f"{s.balls_per_nut} loaded balls per half-nut. Preloads from the "
            "catalogue drag torque formula, as in the study; Hertz values at "
            "the ball-screw contact (exact method).",
        ),
        Block("table", (preload_header, _preload_rows(result))),
        Block(
            "p",
            "Table 1 of the study: temperatures of Fig. 8 and the kinematic "
            "viscosity there (ASTM D341).",
        ),
        Block(
            "table",
            (
                ["lubricant", "temperature [°C]", "viscosity [mm²/s]"],
                [(n, f"{t:g}", f"{v * 1e6:.1f}") for n, t, v in result.viscosity_table],
            ),
        ),
    ]


def _figures(result: StudyResult) -> list[Block]:
    """Each figure with a table of its series at a few speeds."""
    blocks = []
    for fig in result.figures:
        blocks.append(Block("img", (fig.key, f"{fig.title}. {fig.caption}")))
        picks = _pick_speeds(fig.series[0].speed_rpm)
        header = ["series"] + [f"{fig.series[0].speed_rpm[i]:.0f} rpm [N·m]" for i in picks]
        rows = [[se.label] + [_fmt(float(se.torque[i])) for i in picks] for se in fig.series]
        blocks.append(Block("table", (header, rows)))
    return blocks


def _sensitivity(result: StudyResult) -> list[Block] | None:
    return None if result.sensitivity is None else _sensitivity_blocks(result.sensitivity)


def _against_measured(result: StudyResult) -> list[Block] | None:
    """The models' errors against the measured curve; none without one."""
    if result.measured is None:
        return None
    rows = [
        (m, _fmt(v["rmse"]), _fmt(v["mean_relative"], 3), _fmt(v["max_relative"], 3))
        for m, v in result.metrics.items()
    ]
    return [
        Block(
            "p",
            f"Measured curve: {result.measured.source} "
            f"({result.measured.speed.size} points); models at the "
            "reference preload and study temperature.",
        ),
        Block("table", (["model", "RMSE [N·m]", "mean |rel. error|", "max |rel. error|"], rows)),
    ]


def _validity(result: StudyResult) -> list[Block]:
    return [Block("ul", list(result.validity) or ["none: every input within the stated ranges"])]


def _assumptions(result: StudyResult) -> list[Block]:
    """The case's assumptions and, in the reproduction, the note on the measured curve."""
    notes = [f"{a.field} = {a.value}: {a.reason}" for a in result.case.assumptions]
    if result.reproduction:
        notes.append(
            "Kamalzadeh's measured curve is not public as numbers; the report "
            "shows the range the study states (grey band) and overlays a "
            "measured curve only when one is given (--measured)."
        )
    return [Block("ul", notes)]


_DOC_PARAMETER = re.compile(r"^([a-z_][a-z0-9_, ]*) : [^\n]*\n((?:    [^\n]*\n)+)", re.M)


def parameter_units(model: str) -> dict[str, str]:
    """Each parameter's unit as the model's docstring gives it.

    The Parameters section's ``name : type`` lines, then the units in brackets in
    the order of the names; a parameter whose description has none is left out.
    """
    doc = inspect.getdoc(get_model(model).function) or ""
    units: dict[str, str] = {}
    for names, text in _DOC_PARAMETER.findall(doc + "\n"):
        found = re.findall(r"\[([^\]]+)\]", text)
        keys = [n.strip() for n in names.split(",")]
        if len(found) >= len(keys):
            units.update(zip(keys, found[: len(keys)], strict=True))
    return units


def _shown(value: object, unit: str | None) -> str:
    """A parameter's value with its unit, numbers to 4 significant digits."""
    text = f"{value:.4g}" if isinstance(value, float) else str(value)
    return f"{text} {unit}" if unit and unit != "-" and not isinstance(value, str) else text


def _model_parameters(result: StudyResult) -> list[Block]:
    rows = []
    for m, p in sorted(result.case.model_parameters.items()):
        units = parameter_units(m)
        rows.append(
            (m, ", ".join(f"{k} = {_shown(v, units.get(k))}" for k, v in sorted(p.items())))
        )
    return [
        Block("table", (["model", "parameters"], rows)),
        Block(
            "p",
            "Every other parameter has the model's documented default; see "
            "each model's docstring (ballscrew.friction) for its equations, "
            "references and the readings taken where the sources are unclear.",
        ),
    ]


_Section = tuple[str | None, Callable[[StudyResult], list[Block] | None]]

_TEMPLATE: tuple[_Section, ...] = (
    (None, _opening),
    ("Findings", _findings),
    ("Inputs", _inputs),
    ("Derived quantities", _derived),
    ("Figures", _figures),
    ("Uncertainty: which input dominates the complete model's torque?", _sensitivity),
    ("Against the measured curve", _against_measured),
    ("Validity warnings", _validity),
    ("Assumptions", _assumptions),
    ("Model parameters", _model_parameters),
)
"""The study report's template: each section's heading (h2; None: none) and the function
that renders its blocks from the study's result (None: the section is left out)."""


def _document(result: StudyResult) -> list[Block]:
    """The report as blocks: the template's sections in order, each under its heading."""
    blocks: list[Block] = []
    for heading, section in _TEMPLATE:
        body = section(result)
        if body is None:
            continue
        if heading is not None:
            blocks.append(Block("h2", heading))
        blocks += body
    return blocks


def _sensitivity_blocks(s: StudySensitivity) -> list[Block]:
    """The uncertainty section: inputs and their ranges, Sobol indices, the ranking figure."""
    idx = s.indices
    d = len(s.inputs)
    rows = [
        (
            s.inputs[i].label,
            s.inputs[i].distribution.describe(),
            f"{idx.total[i]:.3f} ± {idx.total_conf[i]:.3f}",
            f"{idx.first[i]:.3f} ± {idx.first_conf[i]:.3f}",
            s.inputs[i].source,
        )
        for i in idx.ranking()
    ]
    return [
        Block(
            "p",
            f"Global sensitivity of the complete model's torque, averaged over {s.n_speeds} "
            f"speeds from {s.speeds[0]:g} to {s.speeds[1]:g} rpm, to {d} uncertain inputs: "
            f"Sobol indices (Saltelli's sampling, SALib) from N (D + 2) = {s.base_samples} x "
            f"{d + 2} = {s.evaluations} evaluations, with 95 % bootstrap half-widths. The total "
            "index S_T is the share of the torque's variance that an input causes alone or "
            "together with others; S_1 the share it causes alone. The ball-train constant, the "
            "boundary friction coefficient and the preload all scale the model's ball-ball "
            "sliding term. The torque's 5, 50 and 95 % points over the sample: "
            f"{s.spread[0]:.3g}, {s.spread[1]:.3g} and {s.spread[2]:.3g} N·m.",
        ),
        Block(
            "table",
            (["input", "distribution (SI)", "S_T", "S_1", "where the range comes from"], rows),
        ),
        Block("img", (SENSITIVITY_KEY, "The inputs ranked by their total Sobol index.")),
    ]


def _sensitivity_csv(s: StudySensitivity) -> bytes:
    header = ["input", "field", "distribution (SI)", "S_T [-]", "S_T 95 % half-width [-]",
              "S_1 [-]", "S_1 95 % half-width [-]", "source"]  # fmt: skip
    idx = s.indices
    rows: list[list[object]] = []
    for i in idx.ranking():
        u = s.inputs[i]
        numbers = (idx.total[i], idx.total_conf[i], idx.first[i], idx.first_conf[i])
        rows.append([u.label, u.distribution.name, u.distribution.describe(),
                     *(float(x) for x in numbers), u.source])  # fmt: skip
    return csv_bytes(header, rows)


def _pick_speeds(speed_rpm: np.ndarray) -> list[int]:
    targets = [speed_rpm.min(), 100.0, 1000.0, speed_rpm.max()]
    picks: list[int] = []
    for t in targets:
        i = int(np.argmin(np.abs(speed_rpm - t)))
        if i not in picks:
            picks.append(i)
    return picks


def _csv(fig_series: Any) -> bytes:
    first = fig_series[0]
    header = ["speed [rpm]", "speed [rad/s]", *(f"{s.label}: torque [N*m]" for s in fig_series)]
    rows = [
        [float(first.speed_rpm[i]), float(rpm_to_rad_s(first.speed_rpm[i])),
         *(float(s.torque[i]) for s in fig_series)]
        for i in range(first.speed_rpm.size)
    ]  # fmt: skip
    return csv_bytes(header, rows)


def _write_figure(folder: Path, key: str, drawing: Any, table: bytes, written: list[Path]) -> bytes:
    """Write a figure as PNG and SVG and its data as CSV; return the PNG for the HTML."""
    png = figure_bytes(drawing, "png")
    for path, data in (
        (folder / "figures" / f"{key}.png", png),
        (folder / "figures" / f"{key}.svg", figure_bytes(drawing, "svg")),
        (folder / "data" / f"{key}.csv", table),
    ):
        atomic_write(path, data)
        written.append(path)
    return png


def write_report(
    result: StudyResult,
    out: str | Path,
    measured_text: str | None = None,
    progress: Callable[[str], None] | None = None,
    written: list[Path] | None = None,
) -> list[Path]:
    """Write the report of ``result`` into ``out``; returns the files written.

    ``written``, when given, is filled as the files are completed, so that a
    caller interrupted part-way can say which files are new.
    """
    step = progress or (lambda _text: None)
    folder = Path(out)
    written = [] if written is None else written
    for sub in (folder, folder / "figures", folder / "data"):
        sweep_temporaries(sub)  # left by an earlier run that was killed outright
    images: dict[str, bytes] = {}
    for fig in result.figures:
        step(f"drawing {fig.key}")
        band_source = "Kamalzadeh, via the study" if result.reproduction else "given in the case"
        drawing = render(fig, result.case.measured_range, result.measured, band_source)
        images[fig.key] = _write_figure(folder, fig.key, drawing, _csv(fig.series), written)
    if result.sensitivity is not None:
        step(f"drawing {SENSITIVITY_KEY}")
        drawing = sensitivity_figure(result.sensitivity.indices_labelled(), "Uncertainty of the "
                                     "complete model's torque: share of its variance")  # fmt: skip
        images[SENSITIVITY_KEY] = _write_figure(
            folder, SENSITIVITY_KEY, drawing, _sensitivity_csv(result.sensitivity), written
        )
    step("writing the report")
    blocks = _document(result)
    title = _title(result)  # same as the h1
    for path, text in (
        (folder / "report.md", markdown(blocks)),
        (folder / "report.html", html_page(blocks, title, images)),
    ):
        atomic_write(path, text.encode("utf-8"))
        written.append(path)
    record = {
        "package": "ballscrew",
        "version": __version__,
        "case_toml": result.case.text,
        "measured_csv": measured_text,
        "measured_source": None if result.measured is None else result.measured.source,
    }
    path = folder / RECORD_NAME
    atomic_write(path, (json.dumps(record, indent=2, ensure_ascii=False) + "\n").encode("utf-8"))
    written.append(path)
    return written


def load_record(path: str | Path) -> tuple[Case, MeasuredCurve | None, str | None]:
    """Read a run record; return its case, measured curve and the measured text."""
    file = Path(path)
    try:  # read as a regular file: no pipe, no device
        record = json.loads(read_input_text("record", file))
    except json.JSONDecodeError as exc:
        raise BallScrewInputError(
            "record", str(file), f"a run record written by ballscrew ({exc})"
        ) from None
    if not isinstance(record, dict) or "case_toml" not in record:
        raise BallScrewInputError("record", str(file), "a run record with a 'case_toml' entry")
    case = parse_case(str(record["case_toml"]), source=f"{file}: case_toml")
    text = record.get("measured_csv")
    measured = None
    if text is not None:
        measured = parse_measured(
            str(text), case.screw, source=str(record.get("measured_source") or "measured")
        )
    return case, measured, text


def regenerate(record: str | Path, out: str | Path) -> list[Path]:
    """Write the report of a run record again into ``out`` (byte-identical for one version)."""
    case, measured, text = load_record(record)
    return write_report(run_study(case, measured), out, text)
