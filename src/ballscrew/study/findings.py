"""The study's findings in words, computed from its series.

:func:`study_findings` states where each model lies against the measured
torque band, which model is closest, how much the preload and the lubricant
temperature change the simplified model's torque, and the complete model's
loss budget; for the study's own case each statement is set beside what the
study found.
"""

from __future__ import annotations

import math

import numpy as np

from ..io.case import Case
from .series import Figure, Series

__all__ = ["study_findings"]


def _span(s: Series) -> str:
    return f"{float(np.min(s.torque)):.3g} to {float(np.max(s.torque)):.3g} N·m"


def _relation(s: Series, lo: float, hi: float) -> str:
    """Where a series lies against the measured band, in words computed from its values."""
    t = np.asarray(s.torque, dtype=float)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return "no measured band to compare with"
    if float(np.max(t)) < lo:
        return (
            f"below the measured band at every speed (at most {float(np.max(t)) / lo:.2g} times "
            "its lower end)"
        )
    if float(np.min(t)) > hi:
        return (
            f"above the measured band at every speed (at least {float(np.min(t)) / hi:.2g} times "
            "its upper end)"
        )
    share = float(np.mean((t >= lo) & (t <= hi)))
    if share == 1.0:
        return "inside the measured band at every speed"
    return f"inside the measured band at {share:.0%} of the speeds"


def _distance(s: Series, lo: float, hi: float) -> float:
    """Median |log10| distance of a series from the middle of the band (geometric mean)."""
    t = np.maximum(np.asarray(s.torque, dtype=float), 1e-300)
    return float(np.median(np.abs(np.log10(t / math.sqrt(lo * hi)))))


def study_findings(
    case: Case,
    figures: list[Figure],
    preloads: dict[float, float],
    lubricant_temperatures: dict[str, tuple[float, ...]],
    reproduction: bool,
) -> list[str]:
    """Statements computed from the series; for the study's own case, set beside its findings."""
    lo, hi = (
        (min(case.measured_range), max(case.measured_range))
        if case.measured_range
        else (math.nan, math.nan)
    )
    by_key = {f.key: f for f in figures}
    models = {s.model: s for s in by_key["fig9_all_models"].series}
    return [
        *_model_statements(models, lo, hi, reproduction),
        _preload_statement(by_key["fig7_simplified_preload"].series, preloads, reproduction),
        *_lubricant_statements(
            by_key["fig8_lubricants"].series, lubricant_temperatures, reproduction
        ),
        _budget_statement(by_key["fig11_complete_budget"].series),
    ]


def _model_statements(
    models: dict[str, Series], lo: float, hi: float, reproduction: bool
) -> list[str]:
    """Each model's span and place in the band; which comes closest (beside the study's)."""
    out = []
    banded = math.isfinite(lo) and math.isfinite(hi)
    for name in ("olaru", "viscoelastic", "harris-simplified", "complete"):
        where = f", {_relation(models[name], lo, hi)}" if banded else ""
        out.append(f"{name}: {_span(models[name])}{where}.")
    if math.isfinite(lo) and math.isfinite(hi) and not reproduction:
        overall = min(
            (m for m in models if m != "catalog"), key=lambda m: _distance(models[m], lo, hi)
        )
        out.append(
            f"Of the physical models, {overall} is the closest to the measured band (median "
            f"distance from its middle: a factor {10 ** _distance(models[overall], lo, hi):.2g})."
        )
    if math.isfinite(lo) and math.isfinite(hi) and reproduction:
        study = ("olaru", "viscoelastic", "harris-simplified")
        closest = min(study, key=lambda m: _distance(models[m], lo, hi))
        # The catalogue value is left out: the case's preload was derived from it.
        overall = min(
            (m for m in models if m != "catalog"), key=lambda m: _distance(models[m], lo, hi)
        )
        agree = "agrees" if closest == "harris-simplified" else "does not agree"
        out.append(
            f"The study found the simplified model the closest of its three to the measurement, "
            f"but low. Of the three, {closest} is the closest here (median distance from the "
            f"band's middle: a factor {10 ** _distance(models[closest], lo, hi):.2g}), which "
            f"{agree} with the study; the simplified model is "
            f"{_relation(models['harris-simplified'], lo, hi)}. Of all the physical models, "
            f"{overall} is the closest (a factor {10 ** _distance(models[overall], lo, hi):.2g})."
        )
        visco = models["viscoelastic"]
        out.append(
            f"The study found the viscoelastic model too low and without the offset of the "
            f"measurement; here it starts from {float(visco.torque[0]):.3g} N·m at the lowest "
            f"speed and is {_relation(visco, lo, hi)}."
        )
    return out


def _preload_statement(
    pre: tuple[Series, ...], preloads: dict[float, float], reproduction: bool
) -> str:
    """The drag torques' preloads and how much the simplified model's torque follows them."""
    ratio = float(np.mean(pre[-1].torque / pre[0].torque))
    forces = ", ".join(f"{f:.0f} N" for f in preloads.values())
    return (
        f"Preload: the drag torques {', '.join(f'{t:.3g}' for t in preloads)} N·m correspond to "
        f"preloads of {forces} (catalogue formula); between the lowest and highest the simplified "
        f"model's torque changes by a factor {ratio:.2f} on average."
        + (" The study found the preload to dominate the uncertainty." if reproduction else "")
    )


def _lubricant_statements(
    lub_series: tuple[Series, ...],
    lubricant_temperatures: dict[str, tuple[float, ...]],
    reproduction: bool,
) -> list[str]:
    """How each lubricant's torque changes from its lowest to its highest temperature."""
    out = []
    for name in lubricant_temperatures:
        mine = [s for s in lub_series if s.lubricant == name]
        if len(mine) >= 2:
            change = float(np.mean(mine[-1].torque / mine[0].torque) - 1.0) * 100
            verdict = "agrees with" if change < 0.0 else "does not agree with"
            text = (
                f"{name}: from {mine[0].temperature:g} to {mine[-1].temperature:g} °C the "
                f"simplified model's torque changes by {change:+.1f} % on average"
            )
            if reproduction:
                text += (
                    f", which {verdict} the study's finding that rising temperature lowers the "
                    "friction slightly"
                )
            out.append(text + ".")
    return out


def _budget_statement(budget: tuple[Series, ...]) -> str:
    """The complete model's loss budget, averaged over the speeds."""
    total = sum(float(np.mean(b.torque)) for b in budget)
    shares = ", ".join(f"{b.label} {float(np.mean(b.torque)) / total:.0%}" for b in budget)
    return f"Loss budget of the complete model, averaged over the speeds: {shares}."
