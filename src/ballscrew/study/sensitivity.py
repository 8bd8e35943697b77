"""Uncertainty of the study's case: which inputs the complete model's torque is sensitive to.

:func:`study_sensitivity` draws the case's uncertain inputs
(:func:`uncertain_inputs`, each with the source of its range) by Saltelli's
scheme, evaluates the complete model's torque averaged over a few of the
case's speeds for each sample, and returns the Sobol indices
(:mod:`ballscrew.sweep.sensitivity`); :func:`sensitivity_finding` puts the ranking
into words, including whether the preload leads it, as the study found with
its simplified model.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..chain import friction_torque as chain_friction_torque
from ..io.case import Case
from ..io.extras import MissingExtraWarning, missing
from ..kinematics import rad_s_to_rpm
from ..sweep.sensitivity import SobolIndices
from ..sweep.uncertainty import Distribution

__all__ = [
    "SOBOL_BASE_SAMPLES",
    "StudySensitivity",
    "UncertainInput",
    "sensitivity_finding",
    "study_sensitivity",
    "uncertain_inputs",
]


@dataclass(frozen=True)
class UncertainInput:
    """An uncertain input of the study's sensitivity analysis, and where its range comes from."""

    distribution: Distribution
    label: str
    source: str


@dataclass(frozen=True)
class StudySensitivity:
    """Sobol indices of the complete model's torque (averaged over the study's speeds)."""

    inputs: tuple[UncertainInput, ...]
    indices: SobolIndices
    base_samples: int
    evaluations: int
    spread: tuple[float, float, float]
    speeds: tuple[float, float]
    n_speeds: int

    def as_dict(self) -> dict[str, Any]:
        """The inputs (label, distribution, source), the indices and the sample's size."""
        return {
            "inputs": [{"name": i.distribution.name, "label": i.label,
                        "distribution": i.distribution.describe(), "source": i.source}
                       for i in self.inputs],
            "indices": self.indices.as_dict(),
            "base_samples": self.base_samples, "evaluations": self.evaluations,
            "spread_Nm": list(self.spread), "speeds_rad_s": list(self.speeds),
            "n_speeds": self.n_speeds,
        }  # fmt: skip

    def indices_labelled(self) -> SobolIndices:
        """The indices with the inputs' labels for names (for figures)."""
        return replace(self.indices, names=tuple(i.label for i in self.inputs))


SOBOL_BASE_SAMPLES = 256
"""Base samples N of the study's Sobol analysis: N (D + 2) model calls (2816 for 9 inputs,
about 12 s on one core); the report gives each index's 95 % half-width."""

SOBOL_SPEEDS = 12
"""Speeds, evenly picked from the case's, over which the torque is averaged."""

SOBOL_SEED = 20_240_613
"""Seed of the study's Sobol sample, so that a rerun gives the same report."""


def uncertain_inputs(case: Case, preloads: dict[float, float]) -> tuple[UncertainInput, ...]:
    """The study case's uncertain inputs, their ranges and where each range comes from."""
    from ..friction.complete import BALL_TRAIN_CONSTANT, BALL_TRAIN_SCATTER

    screw = case.screw
    forces = sorted(f for f in preloads.values() if f > 0.0)
    found: list[UncertainInput] = []
    if screw.preload > 0.0:
        if len(forces) >= 2 and case.drag_torques:
            low, high = forces[0], forces[-1]
            why = (
                f"the preloads the catalogue rule gives for the case's drag torques "
                f"{min(case.drag_torques):g} to {max(case.drag_torques):g} N·m "
                "(the study's own preload uncertainty)"
            )
        else:
            low, high = 0.5 * screw.preload, 1.5 * screw.preload
            why = "the case's preload ± 50 % (the spread of catalogue preload classes)"
        found.append(UncertainInput(
            Distribution("screw.preload", "uniform", low, high, "N"), "preload", why))  # fmt: skip
    found += [
        UncertainInput(
            Distribution("lubricant.viscosity_scale", "uniform", 0.9, 1.1, ""),
            "viscosity (factor on nu40 and nu100)",
            "ISO 3448: a viscosity grade allows ±10 % of its mid-point viscosity at 40 °C",
        ),
        *(
            UncertainInput(
                Distribution(f"screw.conformity_{side}", "uniform", 0.52, 0.56, ""),
                f"conformity of the {side} groove",
                "the usual 0.52 to 0.56 of ball screw grooves (the case's assumption)",
            )
            for side in ("screw", "nut")
        ),
        *(
            UncertainInput(
                Distribution(
                    f"screw.roughness_{side}",
                    "uniform",
                    0.5 * getattr(screw, f"roughness_{side}"),
                    1.5 * getattr(screw, f"roughness_{side}"),
                    "m",
                ),
                f"roughness of the {side} groove",
                "the case's value ± 50 % (assumed: ground grooves of 0.1 to 0.4 µm RMS)",
            )
            for side in ("screw", "nut")
        ),
        UncertainInput(
            Distribution("complete.boundary_friction", "uniform", 0.07, 0.15, ""),
            "boundary friction coefficient",
            "from below the study's mu_0 = 0.1 to the 0.15 of SKF's bearing model",
        ),
        UncertainInput(
            Distribution(
                "complete.ball_train_constant",
                "lognormal",
                BALL_TRAIN_CONSTANT,
                math.log(BALL_TRAIN_SCATTER[1] / BALL_TRAIN_SCATTER[0]) / 2.0,
                "",
            ),
            "ball-train constant c_B",
            f"its fit: the values matching single training cases span "
            f"{BALL_TRAIN_SCATTER[0]:.4f} to {BALL_TRAIN_SCATTER[1]:.4f} (16 to 84 %), a "
            f"lognormal about the fitted {BALL_TRAIN_CONSTANT}",
        ),
        UncertainInput(
            Distribution("lubricant.limiting_shear_coefficient", "uniform", 0.03, 0.08, ""),
            "limiting shear coefficient gamma_L",
            "PAO's 0.04 (unverified) to the 0.06 to 0.08 of Bair and Winer for mineral oils",
        ),
    ]
    return tuple(found)


_SENSITIVITY_CACHE: dict[str, StudySensitivity] = {}
"""Results by their inputs: a report drawn again in the same session reuses them."""


def study_sensitivity(
    case: Case, preloads: dict[float, float], temperature: float, load: float
) -> StudySensitivity | None:
    """Sobol indices of the complete model's torque, averaged over the case's speeds.

    The inputs of :func:`uncertain_inputs` are sampled by Saltelli's scheme
    (:mod:`ballscrew.sweep.sensitivity`); each sample is one screw, lubricant and
    parameter set, evaluated over every speed in one friction call.

    Without SALib (the ``sweep`` extra) the analysis is left out: a
    :class:`~ballscrew.extras.MissingExtraWarning` says so and the result is ``None``.
    """
    if missing("sweep", ("SALib",)) is not None:
        warnings.warn(
            "the study's uncertainty section (Sobol indices) needs the sweep extra (SALib is "
            "not installed): pip install 'ballscrew[sweep]'; the report leaves it out",
            MissingExtraWarning,
            stacklevel=2,
        )
        return None
    from ..sweep.fields import resolve
    from ..sweep.sensitivity import sample, sobol_indices

    inputs = uncertain_inputs(case, preloads)
    dists = [i.distribution for i in inputs]
    key = repr((case.text, case.screw, case.lubricant, case.speed.tolist(), temperature, load,
                dists, case.model_parameters.get("complete")))  # fmt: skip
    if key in _SENSITIVITY_CACHE:
        return _SENSITIVITY_CACHE[key]
    rows = sample(dists, SOBOL_BASE_SAMPLES, SOBOL_SEED, sobol=True)
    params = case.parameters_for("complete")
    picks = np.unique(np.linspace(0, case.speed.size - 1, SOBOL_SPEEDS).round().astype(int))
    speed = case.speed[picks]
    y = np.empty(rows.shape[0])
    for k, row in enumerate(rows):  # one screw per row; the speeds in one call
        point = {d.name: float(v) for d, v in zip(dists, row, strict=True)}
        screw, lub, used = resolve(case, "complete", params, point)
        torque = chain_friction_torque(
            screw,
            lub,
            speed=speed,
            temperature=temperature,
            axial_load=load,
            model="complete",
            warn=False,
            **used,
        )
        y[k] = float(np.mean(torque.total))  # fmt: skip
    indices = sobol_indices(dists, y, SOBOL_SEED)
    p5, p50, p95 = (float(v) for v in np.percentile(y, [5.0, 50.0, 95.0]))
    rpm = (float(rad_s_to_rpm(speed.min())), float(rad_s_to_rpm(speed.max())))
    result = StudySensitivity(inputs, indices, SOBOL_BASE_SAMPLES, rows.shape[0],
                              (p5, p50, p95), rpm, int(speed.size))  # fmt: skip
    _SENSITIVITY_CACHE[key] = result
    return result


def sensitivity_finding(s: StudySensitivity, reproduction: bool) -> str:
    """The ranking of the uncertain inputs, and what it says of the preload, in words."""
    idx = s.indices
    order = idx.ranking()
    label = {i: s.inputs[i].label for i in range(len(s.inputs))}

    def shown(i: int) -> str:
        return f"{label[i]} (S_T = {idx.total[i]:.2f} ± {idx.total_conf[i]:.2f})"

    text = (
        f"Uncertainty of the complete model's torque (averaged over {s.speeds[0]:.4g} to "
        f"{s.speeds[1]:.4g} rpm; Sobol indices from {s.evaluations} evaluations): the inputs "
        f"with the largest shares of its variance are {shown(order[0])}, {shown(order[1])} and "
        f"{shown(order[2])}; its 5 to 95 % range is {s.spread[0]:.3g} to {s.spread[2]:.3g} N·m."
    )
    pre = next((i for i, u in enumerate(s.inputs) if u.distribution.name == "screw.preload"), None)
    if pre is None:
        return text
    rank = order.index(pre) + 1

    def ahead(i: int, j: int) -> bool:
        """Input i's total index is above input j's beyond both 95 % intervals."""
        return bool(idx.total[i] - idx.total_conf[i] > idx.total[j] + idx.total_conf[j])

    top = order[0]
    if top == pre:
        runner = order[1]
        dominant = ahead(pre, runner)
        verdict = (
            "The preload is the leading uncertainty"
            if dominant
            else f"The preload ranks first, but not clearly ahead of the {label[runner]} "
            "(their 95 % intervals overlap)"
        )
    else:
        dominant = False
        verdict = (
            f"The preload is not the leading uncertainty (rank {rank} of {len(s.inputs)}, "
            f"S_T = {idx.total[pre]:.2f} ± {idx.total_conf[pre]:.2f}): the {label[top]} "
            + ("is" if ahead(top, pre) else "ranks above it, though their 95 % intervals overlap")
        )
    if reproduction:
        verdict += (
            ", as the study found with its simplified model"
            if dominant
            else "; the study, with its simplified model, found the preload to dominate"
        )
    return f"{text} {verdict}."
