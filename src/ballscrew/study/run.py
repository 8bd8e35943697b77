"""Reproduction of Sušeň's study: the series behind its Figs. 3 to 8 and Table 1.

:func:`run_study` evaluates the friction models of the study for a case (the
bundled :func:`ballscrew.io.case.load_case` reproduces the study's set-up) and
returns every plotted series with its inputs, plus two comparisons the study
lacks (all models with the catalogue drag torque; the simplified model against
the complete model; the complete model's loss budget). The findings are
computed from the series and set beside what the study found
(:mod:`ballscrew.study.findings`). Plotting and report writing live in
:mod:`ballscrew.report.plotting` and :mod:`ballscrew.report.study`.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .. import lubricants
from ..chain import FrictionResult
from ..chain import friction_torque as chain_friction_torque
from ..errors import BallScrewValidityWarning, FloatArray
from ..friction.catalog import preload_from_drag_torque
from ..io.case import Case
from ..io.measured import MeasuredCurve, error_metrics
from ..lubricant import Lubricant
from ..validity import ValidityIssue
from .findings import study_findings
from .sensitivity import (
    StudySensitivity,
    UncertainInput,
    sensitivity_finding,
    study_sensitivity,
)

__all__ = ["Figure", "Series", "StudyResult", "StudySensitivity", "UncertainInput", "run_study"]

RPM = 2.0 * math.pi / 60.0


@dataclass(frozen=True)
class Series:
    """One plotted curve: friction torque against screw speed."""

    label: str
    model: str
    speed_rpm: FloatArray
    torque: FloatArray
    preload: float
    temperature: float
    lubricant: str
    parameters: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Figure:
    """A figure of the study (or one it lacks) with its series."""

    key: str
    title: str
    caption: str
    series: tuple[Series, ...]
    log_y: bool = False
    stacked: bool = False


@dataclass(frozen=True)
class StudyResult:
    """Everything the report shows."""

    case: Case
    preloads: dict[float, float]
    figures: tuple[Figure, ...]
    viscosity_table: tuple[tuple[str, float, float], ...]
    findings: tuple[str, ...]
    measured: MeasuredCurve | None
    metrics: dict[str, dict[str, float]]
    validity: tuple[str, ...] = ()
    reproduction: bool = False
    axial_load: float = 0.0
    sensitivity: StudySensitivity | None = None


def _params(case: Case, model: str) -> dict[str, Any]:
    return dict(case.model_parameters.get(model, {}))


def _controller_figure(model_curve: Series, at: str) -> Figure:
    """The complete model's curve and the Stribeck curve a controller would take from it."""
    from ..fit.controller import stribeck, stribeck_torque

    w = model_curve.speed_rpm * RPM
    keep = w > 0.0
    both = np.concatenate([-w[keep][::-1], w[keep]])
    torque = np.concatenate([-model_curve.torque[keep][::-1], model_curve.torque[keep]])
    fit = stribeck(both, torque)
    p = fit.parameters
    curve = stribeck_torque(w, **p)
    m = model_curve
    shown = Series("Stribeck fit", "stribeck", m.speed_rpm, np.abs(curve), m.preload,
                   m.temperature, m.lubricant, p)  # fmt: skip
    drop = (
        f"static {p['static_torque']:.4g} N·m, Stribeck speed "
        f"{p['stribeck_speed'] / RPM:.3g} rpm, exponent {p['stribeck_exponent']:.2f}"
        if not fit.notes
        else "no Stribeck drop in the model's curve (static = Coulomb)"
    )
    return Figure(
        "fig12_controller",
        "Friction for a controller",
        f"The complete model, {at}, and the Stribeck curve fitted to it over both "
        f"directions (ballscrew export-friction): Coulomb {p['coulomb_torque']:.4g} N·m, "
        f"viscous {p['viscous_coefficient'] * RPM * 1e3:.4g} N·m per 1000 rpm, {drop}; fit "
        f"error RMS {fit.rms_error:.3g} N·m, max {fit.max_error:.3g} N·m.",
        (model_curve, shown),
    )


def reproduces_study(case: Case) -> bool:
    """True for the study's own case (the bundled file, unchanged).

    Only then does the report compare with the study's findings and its
    measured band; any other case gets a study of its own screw.
    """
    from ..io.case import default_case_path

    return case.text == default_case_path().read_text(encoding="utf-8")


def _preloads(case: Case) -> dict[float, float]:
    """Catalogue drag torque -> preload of the compared preloads.

    The case's ``drag_torques`` if given; otherwise the case's own preload
    times 0.5, 1 and 1.5, keyed by their catalogue drag torque.
    """
    from ..friction.catalog import preload_torque

    screw = case.screw
    if case.drag_torques:
        return {t: float(preload_from_drag_torque(t, screw)) for t in sorted(case.drag_torques)}
    forces = [screw.preload * k for k in (0.5, 1.0, 1.5)] if screw.preload > 0 else [0.0]
    return {float(preload_torque(f, screw.lead, screw.lead_angle, 0.05)): f for f in forces}


def run_study(
    case: Case,
    measured: MeasuredCurve | None = None,
    progress: Callable[[str], None] | None = None,
) -> StudyResult:
    """Compute all series of the study for ``case`` (see :func:`_run`).

    The validity-range warnings of all the model calls are collected (each
    message once, in order) into ``StudyResult.validity`` instead of being
    raised.
    """
    found: list[ValidityIssue] = []
    with warnings.catch_warnings():
        # Collected from every result (recorded there whether or not the chain
        # told them in this session), not from the warnings, which may be quiet.
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        result = _run(case, measured, progress, found)
    worst: dict[str, ValidityIssue] = {}
    for issue in found:
        if issue.quantity not in worst or issue.excess > worst[issue.quantity].excess:
            worst[issue.quantity] = issue
    # One line per quantity: its most extreme value over all the study's model calls.
    return replace(result, validity=tuple(issue.note() for issue in worst.values()))


def _run(
    case: Case,
    measured: MeasuredCurve | None = None,
    progress: Callable[[str], None] | None = None,
    found: list[ValidityIssue] | None = None,
) -> StudyResult:
    """Compute all series of the study for ``case``.

    Parameters
    ----------
    case : Case
        The ball screw case; its ``drag_torques`` give the preloads compared
        (the middle one is the reference), ``study_temperature`` the
        temperature of Figs. 3 to 7 and ``lubricant_temperatures`` Fig. 8.
    measured : MeasuredCurve, optional
        A measured torque-speed curve to compare with.
    progress : callable, optional
        Called with a short description as each figure starts.

    Returns
    -------
    StudyResult
    """
    step = progress or (lambda _text: None)
    issues = found if found is not None else []

    def friction_torque(*args: Any, **kwargs: Any) -> FrictionResult:
        """The chain's, recording each call's validity issues."""
        result = chain_friction_torque(*args, **kwargs)
        issues.extend(result.warnings)
        return result

    screw0 = case.screw
    preloads = _preloads(case)
    ref_preload = screw0.preload
    speed = case.speed
    speed_rpm = speed / RPM
    temp = case.study_temperature
    oil = case.lubricant
    load = float(case.axial_load.flat[0])
    at = f"{oil.name} at {temp:g} °C" + (f", axial load {load:g} N" if load else "")
    lubricant_temperatures = case.lubricant_temperatures or {oil.name: (20.0, 30.0, 40.0, 50.0)}

    def lubricant_named(name: str) -> Lubricant:
        return oil if name == oil.name else lubricants.get(name)

    def series(
        model: str,
        preload: float,
        label: str,
        lubricant_name: str | None = None,
        temperature: float | None = None,
        **extra: Any,
    ) -> Series:
        lub = oil if lubricant_name is None else lubricant_named(lubricant_name)
        t = temp if temperature is None else temperature
        params = _params(case, model)
        params.update(extra)
        result = friction_torque(
            screw0.replace(preload=preload),
            lub,
            speed=speed,
            temperature=t,
            axial_load=load,
            model=model,
            **params,
        )
        return Series(label, model, speed_rpm, result.total, preload, t, lub.name, params)

    def preload_series(model: str) -> tuple[Series, ...]:
        """The model at each preload derived from the study's drag torques."""
        return tuple(series(model, f, f"{f:.0f} N ({t:g} N·m drag)") for t, f in preloads.items())

    figures: list[Figure] = []
    ref_label = f"{ref_preload:.0f} N"

    step("Fig. 3: Olaru's model")
    figures.append(
        Figure(
            "fig3_olaru",
            "Olaru's model (Fig. 3)",
            f"Olaru et al.'s model at the reference preload ({ref_label}), {at}.",
            (series("olaru", ref_preload, f"Olaru, {ref_label}"),),
        )
    )
    step("Figs. 4 and 5: viscoelastic model")
    figures.append(
        Figure(
            "fig4_viscoelastic",
            "Viscoelastic model (Fig. 4)",
            "Viscoelastic model with the study's k, m, gamma at the reference preload.",
            (series("viscoelastic", ref_preload, f"viscoelastic, {ref_label}"),),
        )
    )
    figures.append(
        Figure(
            "fig5_viscoelastic_preload",
            "Viscoelastic model: preload (Fig. 5)",
            "Viscoelastic model at the preloads of the measured drag torques.",
            preload_series("viscoelastic"),
        )
    )
    step("Figs. 6 and 7: simplified model")
    figures.append(
        Figure(
            "fig6_simplified",
            "Simplified model (Fig. 6)",
            f"The study's simplified model at the reference preload, {at}.",
            (series("harris-simplified", ref_preload, f"simplified, {ref_label}"),),
        )
    )
    figures.append(
        Figure(
            "fig7_simplified_preload",
            "Simplified model: preload (Fig. 7)",
            "Simplified model at the preloads of the measured drag torques.",
            preload_series("harris-simplified"),
        )
    )
    step("Fig. 8: lubricants and temperatures")
    lub_series = []
    table: list[tuple[str, float, float]] = []
    for name, temps in lubricant_temperatures.items():
        lub = lubricant_named(name)
        for t in temps:
            lub_series.append(
                series(
                    "harris-simplified",
                    ref_preload,
                    f"{name}, {t:g} °C",
                    lubricant_name=name,
                    temperature=t,
                )
            )
            table.append((name, t, float(lub.kinematic_viscosity(t))))
    figures.append(
        Figure(
            "fig8_lubricants",
            "Simplified model: lubricants and temperatures (Fig. 8, Table 1)",
            f"Simplified model at the reference preload ({ref_label}) for each lubricant and "
            "temperature of the table below.",
            tuple(lub_series),
        )
    )
    step("All models and the catalogue formula")
    all_series = tuple(
        series(m, ref_preload, m)
        for m in (
            "catalog",
            "complete",
            "olaru",
            "viscoelastic",
            "harris-simplified",
            "harris-full",
        )
    )
    figures.append(
        Figure(
            "fig9_all_models",
            "All models and the catalogue drag torque",
            f"Every model at the reference preload ({ref_label}), {at}; logarithmic torque axis.",
            all_series,
            log_y=True,
        )
    )
    step("Simplified model against the complete model")
    compare_series = (
        series("harris-simplified", ref_preload, "simplified (study's reading)"),
        series(
            "harris-simplified",
            ref_preload,
            "simplified, sliding speed in the shear rate",
            shear_velocity="sliding",
        ),
        series("complete", ref_preload, "complete model"),
    )
    figures.append(
        Figure(
            "fig10_simplified_vs_complete",
            "The study's simplified model against the complete model",
            "The simplified model charges asperity friction and saturated lubricant shear at the "
            "rolling speed; the complete model adds up EHL rolling resistance, spin and "
            "Heathcote sliding, the slip the helix forces across the groove, hysteresis, "
            "ball-ball sliding and the recirculation push.",
            compare_series,
            log_y=True,
        )
    )
    step("Loss budget of the complete model")
    params = _params(case, "complete")
    budget = friction_torque(
        screw0, oil, speed=speed, temperature=temp, axial_load=load, model="complete", **params
    )
    budget_series = tuple(
        Series(name.replace("_", "-"), "complete", speed_rpm, value, ref_preload, temp, oil.name,
               params)
        for name, value in budget.components.items()
        if float(np.max(value)) > 0.0
    )  # fmt: skip
    figures.append(
        Figure(
            "fig11_complete_budget",
            "Loss budget of the complete model",
            f"The complete model's torque split by mechanism, stacked, at the reference preload "
            f"({ref_label}), {at}.",
            budget_series,
            stacked=True,
        )
    )

    step("Fig. 12: friction for a controller")
    figures.append(_controller_figure(series("complete", ref_preload, "complete model"), at))

    step("Sensitivity: Sobol indices of the complete model")
    sensitivity = study_sensitivity(case, preloads, temp, load)

    metrics: dict[str, dict[str, float]] = {}
    if measured is not None:
        step("Measured curve")
        for s in all_series:
            params = _params(case, s.model)
            model_torque = friction_torque(
                screw0,
                oil,
                speed=measured.speed,
                temperature=temp,
                axial_load=load,
                model=s.model,
                **params,
            ).total
            metrics[s.model] = error_metrics(model_torque, measured.torque)

    reproduction = reproduces_study(case)
    findings = study_findings(case, figures, preloads, lubricant_temperatures, reproduction)
    if sensitivity is not None:
        findings.append(sensitivity_finding(sensitivity, reproduction))
    return StudyResult(
        case=case,
        preloads=preloads,
        figures=tuple(figures),
        viscosity_table=tuple(table),
        findings=tuple(findings),
        measured=measured,
        metrics=metrics,
        reproduction=reproduction,
        axial_load=load,
        sensitivity=sensitivity,
    )
