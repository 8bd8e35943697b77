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

import warnings
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .. import lubricants
from ..chain import FrictionResult
from ..chain import friction_torque as chain_friction_torque
from ..design.catalog_formulas import preload_from_drag_torque
from ..errors import BallScrewValidityWarning
from ..io.case import Case
from ..io.measured import MeasuredCurve, error_metrics
from ..kinematics import rad_s_to_rpm, rpm_to_rad_s
from ..lubricant import Lubricant
from ..validity import ValidityIssue
from .findings import study_findings
from .sensitivity import (
    StudySensitivity,
    UncertainInput,
    sensitivity_finding,
    study_sensitivity,
)
from .series import Figure, Series

__all__ = ["Figure", "Series", "StudyResult", "StudySensitivity", "UncertainInput", "run_study"]


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

    def as_dict(self) -> dict[str, Any]:
        """The study's numbers: figures and their series, findings, metrics, validity."""
        return {
            "case": self.case.title,
            "reproduction": self.reproduction,
            "axial_load_N": self.axial_load,
            "preloads_N": {str(k): v for k, v in self.preloads.items()},
            "figures": [f.as_dict() for f in self.figures],
            "viscosity": [list(row) for row in self.viscosity_table],
            "findings": list(self.findings),
            "measured": None if self.measured is None else self.measured.source,
            "metrics": self.metrics,
            "validity": list(self.validity),
            "sensitivity": None if self.sensitivity is None else self.sensitivity.as_dict(),
        }


def _controller_figure(model_curve: Series, at: str) -> Figure:
    """The complete model's curve and the Stribeck curve a controller would take from it."""
    from ..servo.controller import stribeck, stribeck_torque

    w = rpm_to_rad_s(model_curve.speed_rpm)
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
        f"{rad_s_to_rpm(p['stribeck_speed']):.3g} rpm, exponent {p['stribeck_exponent']:.2f}"
        if not fit.notes
        else "no Stribeck drop in the model's curve (static = Coulomb)"
    )
    return Figure(
        "fig12_controller",
        "Friction for a controller",
        f"The complete model, {at}, and the Stribeck curve fitted to it over both "
        f"directions (ballscrew export-friction): Coulomb {p['coulomb_torque']:.4g} N·m, "
        f"viscous {float(rpm_to_rad_s(p['viscous_coefficient'])) * 1e3:.4g} N·m per 1000 "
        f"rpm, {drop}; fit "
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
    from ..design.catalog_formulas import preload_torque

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


@dataclass
class _Context:
    """What every figure of the study is computed from, and how a series is computed."""

    case: Case
    preloads: dict[float, float]
    issues: list[ValidityIssue]
    table: list[tuple[str, float, float]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.screw = self.case.screw
        self.ref_preload = self.screw.preload
        self.ref_label = f"{self.ref_preload:.0f} N"
        self.speed = self.case.speed
        self.speed_rpm = rad_s_to_rpm(self.speed)
        self.temperature = self.case.study_temperature
        self.oil = self.case.lubricant
        self.load = float(self.case.axial_load.flat[0])
        self.at = f"{self.oil.name} at {self.temperature:g} °C" + (
            f", axial load {self.load:g} N" if self.load else ""
        )
        self.lubricant_temperatures = self.case.lubricant_temperatures or {
            self.oil.name: (20.0, 30.0, 40.0, 50.0)
        }

    def friction_torque(self, *args: Any, **kwargs: Any) -> FrictionResult:
        """The chain's, recording each call's validity issues."""
        result = chain_friction_torque(*args, **kwargs)
        self.issues.extend(result.warnings)
        return result

    def lubricant(self, name: str | None) -> Lubricant:
        return self.oil if name is None or name == self.oil.name else lubricants.get(name)

    def series(self, model: str, preload: float, label: str, lubricant_name: str | None = None,
               temperature: float | None = None, **extra: Any) -> Series:  # fmt: skip
        """One model's torque over the case's speeds."""
        lub = self.lubricant(lubricant_name)
        t = self.temperature if temperature is None else temperature
        params = self.case.parameters_for(model) | extra
        result = self.friction_torque(
            self.screw.replace(preload=preload), lub, speed=self.speed, temperature=t,
            axial_load=self.load, model=model, **params,
        )  # fmt: skip
        return Series(label, model, self.speed_rpm, result.total, preload, t, lub.name, params)

    def at_reference(self, model: str, label: str, **extra: Any) -> Series:
        return self.series(model, self.ref_preload, label, **extra)

    def at_preloads(self, model: str) -> tuple[Series, ...]:
        """The model at each preload derived from the study's drag torques."""
        return tuple(
            self.series(model, f, f"{f:.0f} N ({t:g} N·m drag)") for t, f in self.preloads.items()
        )


ALL_MODELS = ("catalog", "complete", "olaru", "viscoelastic", "harris-simplified", "harris-full")
"""The models of Fig. 9, in its legend's order."""


def _lubricant_series(c: _Context) -> tuple[Series, ...]:
    """The simplified model for each lubricant and temperature; fills the viscosity table."""
    out = []
    for name, temps in c.lubricant_temperatures.items():
        for t in temps:
            out.append(c.series("harris-simplified", c.ref_preload, f"{name}, {t:g} °C",
                                lubricant_name=name, temperature=t))  # fmt: skip
            c.table.append((name, t, float(c.lubricant(name).kinematic_viscosity(t))))
    return tuple(out)


def _budget_series(c: _Context) -> tuple[Series, ...]:
    """The complete model's components, one series each (those that are not zero)."""
    params = c.case.parameters_for("complete")
    budget = c.friction_torque(c.screw, c.oil, speed=c.speed, temperature=c.temperature,
                               axial_load=c.load, model="complete", **params)  # fmt: skip
    return tuple(
        Series(name.replace("_", "-"), "complete", c.speed_rpm, value, c.ref_preload,
               c.temperature, c.oil.name, params)
        for name, value in budget.components.items()
        if float(np.max(value)) > 0.0
    )  # fmt: skip


@dataclass(frozen=True)
class FigureSpec:
    """One figure of the study: its step, key, title, caption and how its series are made."""

    step: str
    key: str
    title: str
    caption: Callable[[_Context], str]
    series: Callable[[_Context], tuple[Series, ...]]
    log_y: bool = False
    stacked: bool = False

    def build(self, c: _Context) -> Figure:
        return Figure(self.key, self.title, self.caption(c), self.series(c), self.log_y,
                      self.stacked)  # fmt: skip


# fmt: off
FIGURES: tuple[FigureSpec, ...] = (
    FigureSpec(
        "Fig. 3: Olaru's model", "fig3_olaru", "Olaru's model (Fig. 3)",
        lambda c: f"Olaru et al.'s model at the reference preload ({c.ref_label}), {c.at}.",
        lambda c: (c.at_reference("olaru", f"Olaru, {c.ref_label}"),),
    ),
    FigureSpec(
        "Figs. 4 and 5: viscoelastic model", "fig4_viscoelastic", "Viscoelastic model (Fig. 4)",
        lambda c: "Viscoelastic model with the study's k, m, gamma at the reference preload.",
        lambda c: (c.at_reference("viscoelastic", f"viscoelastic, {c.ref_label}"),),
    ),
    FigureSpec(
        "Figs. 4 and 5: viscoelastic model", "fig5_viscoelastic_preload",
        "Viscoelastic model: preload (Fig. 5)",
        lambda c: "Viscoelastic model at the preloads of the measured drag torques.",
        lambda c: c.at_preloads("viscoelastic"),
    ),
    FigureSpec(
        "Figs. 6 and 7: simplified model", "fig6_simplified", "Simplified model (Fig. 6)",
        lambda c: f"The study's simplified model at the reference preload, {c.at}.",
        lambda c: (c.at_reference("harris-simplified", f"simplified, {c.ref_label}"),),
    ),
    FigureSpec(
        "Figs. 6 and 7: simplified model", "fig7_simplified_preload",
        "Simplified model: preload (Fig. 7)",
        lambda c: "Simplified model at the preloads of the measured drag torques.",
        lambda c: c.at_preloads("harris-simplified"),
    ),
    FigureSpec(
        "Fig. 8: lubricants and temperatures", "fig8_lubricants",
        "Simplified model: lubricants and temperatures (Fig. 8, Table 1)",
        lambda c: f"Simplified model at the reference preload ({c.ref_label}) for each "
        "lubricant and temperature of the table below.",
        _lubricant_series,
    ),
    FigureSpec(
        "All models and the catalogue formula", "fig9_all_models",
        "All models and the catalogue drag torque",
        lambda c: f"Every model at the reference preload ({c.ref_label}), {c.at}; logarithmic "
        "torque axis.",
        lambda c: tuple(c.at_reference(m, m) for m in ALL_MODELS),
        log_y=True,
    ),
    FigureSpec(
        "Simplified model against the complete model", "fig10_simplified_vs_complete",
        "The study's simplified model against the complete model",
        lambda c: "The simplified model charges asperity friction and saturated lubricant "
        "shear at the rolling speed; the complete model adds up EHL rolling resistance, spin "
        "and Heathcote sliding, the slip the helix forces across the groove, hysteresis, "
        "ball-ball sliding and the recirculation push.",
        lambda c: (
            c.at_reference("harris-simplified", "simplified (study's reading)"),
            c.at_reference("harris-simplified", "simplified, sliding speed in the shear rate",
                           shear_velocity="sliding"),
            c.at_reference("complete", "complete model"),
        ),
        log_y=True,
    ),
    FigureSpec(
        "Loss budget of the complete model", "fig11_complete_budget",
        "Loss budget of the complete model",
        lambda c: f"The complete model's torque split by mechanism, stacked, at the reference "
        f"preload ({c.ref_label}), {c.at}.",
        _budget_series,
        stacked=True,
    ),
)
# fmt: on
"""The study's figures, in order (Fig. 12, the controller's fit, is made from Fig. 10's
complete-model curve by :func:`_controller_figure`)."""


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
        Called with a short description as each step starts.

    Returns
    -------
    StudyResult
    """
    step = progress or (lambda _text: None)
    c = _Context(case, _preloads(case), found if found is not None else [])
    figures: list[Figure] = []
    for k, spec in enumerate(FIGURES):
        if k == 0 or spec.step != FIGURES[k - 1].step:
            step(spec.step)
        figures.append(spec.build(c))
    step("Fig. 12: friction for a controller")
    compared = next(f for f in figures if f.key == "fig10_simplified_vs_complete")
    figures.append(_controller_figure(compared.series[-1], c.at))
    step("Sensitivity: Sobol indices of the complete model")
    sensitivity = study_sensitivity(case, c.preloads, c.temperature, c.load)
    metrics: dict[str, dict[str, float]] = {}
    if measured is not None:
        step("Measured curve")
        for model in ALL_MODELS:
            model_torque = c.friction_torque(
                c.screw, c.oil, speed=measured.speed, temperature=c.temperature,
                axial_load=c.load, model=model, **case.parameters_for(model),
            ).total  # fmt: skip
            metrics[model] = error_metrics(model_torque, measured.torque)
    reproduction = reproduces_study(case)
    findings = study_findings(case, figures, c.preloads, c.lubricant_temperatures, reproduction)
    if sensitivity is not None:
        findings.append(sensitivity_finding(sensitivity, reproduction))
    return StudyResult(
        case=case, preloads=c.preloads, figures=tuple(figures), viscosity_table=tuple(c.table),
        findings=tuple(findings), measured=measured, metrics=metrics,
        reproduction=reproduction, axial_load=c.load, sensitivity=sensitivity,
    )  # fmt: skip
