r"""The validation scorecard: every model against every public number.

The bundled file ``data/validation_cases.csv`` lists reference cases, each
with its source and the band a prediction should fall in:

``catalog``
    The manufacturers' preload drag torque :math:`T_p = 0.05/\sqrt{\tan\beta}
    \cdot F_{pr}l/2\pi` at their test conditions (100 rpm, ISO VG 68, no
    wiper) over the 20 HIWIN ground nuts of the bundled catalogue table
    (nominal diameters 14 to 63 mm, leads 5 to 40 mm; preloads 2, 5 and 10 %
    of the dynamic load rating, double nuts and 4-point single nuts), with the ±30 % band that
    the precision grades allow for the drag torque itself.
``jungnickel``
    Jungnickel's empirical loss law, fitted to measured losses of machine-tool
    ball screws, at 1000 and 3000 rpm for the double nuts of the grid, with a
    band of a factor 1.5 either way.

Trends are checked on the project's reference screw
(:func:`ballscrew.reference_screw`) and scored as rows of their own: the
speed exponent from 100 to 1000 rpm, :math:`T(20\,°C)/T(40\,°C)` at 1000 rpm,
the preload exponent (1 to 4 kN at 1000 rpm) and the ratio of a 4-point
single nut to a double nut with the same balls.

The cases file is written by ``scripts/make_validation_cases.py`` from the
bundled catalogue table ``data/catalog_screws.csv`` (the 20 distinct HIWIN
ground nuts whose rows give ball diameter, circuits and load rating, each
with its catalogue page); the rows marked ``training`` are the only ones the ball-train
constant of :mod:`ballscrew.friction.complete` was fitted on
(``scripts/fit_ball_train.py``).
"""

from __future__ import annotations

import csv
import io
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from importlib import resources
from typing import Any

import numpy as np
import numpy.typing as npt

from .chain import friction_torque, models
from .errors import BallScrewValidityWarning, FloatArray
from .examples import reference_screw
from .geometry import BallScrew
from .lubricant import Lubricant
from .lubricants import get as get_lubricant

__all__ = [
    "ReferenceCase",
    "ScoreRow",
    "bundled_summary",
    "jungnickel_loss_torque",
    "load_cases",
    "score",
    "screw_from_row",
    "summarise",
]

CASES_FILE = "validation_cases.csv"
SUMMARY_FILE = "scorecard_summary.csv"
RPM = 2.0 * math.pi / 60.0


@dataclass(frozen=True)
class ReferenceCase:
    """One reference case: a screw at an operating point, and the band it should fall in."""

    case: str
    kind: str
    source: str
    screw: BallScrew
    lubricant: str
    speed_rpm: float
    temperature: float
    axial_load: float
    reference: float
    low: float
    high: float
    training: bool


@dataclass(frozen=True)
class ScoreRow:
    """One model's prediction for one case (or trend)."""

    case: str
    kind: str
    source: str
    reference: float
    low: float
    high: float
    unit: str
    model: str
    predicted: float
    training: bool

    @property
    def ratio(self) -> float:
        """Predicted over reference value [-]."""
        return self.predicted / self.reference if self.reference else math.nan

    @property
    def within(self) -> bool:
        """Whether the prediction lies inside the band."""
        return self.low <= self.predicted <= self.high


def screw_from_row(row: dict[str, str]) -> BallScrew:
    """The screw of a cases-file row (lengths in mm, angle in degrees)."""
    return BallScrew(
        pitch_diameter=float(row["pitch_diameter_mm"]) * 1e-3,
        lead=float(row["lead_mm"]) * 1e-3,
        ball_diameter=float(row["ball_diameter_mm"]) * 1e-3,
        contact_angle=math.radians(float(row["contact_angle_deg"])),
        conformity_screw=float(row["conformity"]),
        conformity_nut=float(row["conformity"]),
        loaded_turns=float(row["turns_per_circuit"]),
        circuits=int(row["circuits"]),
        nut=row["nut"],  # type: ignore[arg-type]
        preload=float(row["preload_N"]),
    )


def load_cases(text: str | None = None) -> list[ReferenceCase]:
    """The reference cases (the bundled file, or ``text`` in its format)."""
    if text is None:
        text = resources.files("ballscrew").joinpath("data", CASES_FILE).read_text("utf-8")
    lines = [line for line in text.splitlines() if line and not line.startswith("#")]
    cases = []
    for row in csv.DictReader(io.StringIO("\n".join(lines))):
        cases.append(
            ReferenceCase(
                case=row["case"],
                kind=row["kind"],
                source=row["source"],
                screw=screw_from_row(row),
                lubricant=row["lubricant"],
                speed_rpm=float(row["speed_rpm"]),
                temperature=float(row["temperature_C"]),
                axial_load=float(row["axial_load_N"]),
                reference=float(row["reference_Nm"]),
                low=float(row["reference_low_Nm"]),
                high=float(row["reference_high_Nm"]),
                training=row["training"].strip().lower() == "yes",
            )
        )
    return cases


def _torque(case: ReferenceCase, model: str, **params: Any) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw,
            get_lubricant(case.lubricant),
            speed=case.speed_rpm * RPM,
            temperature=case.temperature,
            axial_load=case.axial_load,
            model=model,
            **params,
        )
    return float(r.total)


JUNGNICKEL_MODULUS = 2.31e11
"""Reduced modulus of steel on steel used in Jungnickel's law [Pa]."""


def jungnickel_loss_torque(
    screw: BallScrew, lubricant: Lubricant, speed: npt.ArrayLike, temperature: npt.ArrayLike
) -> FloatArray:
    r"""Jungnickel's empirical loss torque of a preloaded ball screw [N·m].

    Jungnickel [1]_ fitted the losses he measured on machine-tool ball screws
    with a law built on the EHL rolling resistance of the balls (his eq. 9.49).
    Per set of :math:`Z` balls that carries the preload (one half-nut of a
    double nut, or a 4-point single nut), with :math:`\lambda` the lead angle,
    :math:`Q = F_{pr}/(Z\sin\alpha\cos\lambda)`, :math:`W = Q/(E'r_b^2)`,
    :math:`r_b = D_w/2`, :math:`G = \alpha_p E'`,
    :math:`\alpha_p = 1.29\cdot10^{-7}\nu_{40}^{0.204}` (:math:`\nu_{40}` in
    mm²/s) and the Vogel-Cameron viscosity :math:`\nu = A\exp(B/(T + 95))`
    through :math:`\nu_{20}` and :math:`\nu_{40}`:

    .. math::
        T = 9.16\,Z\,Q\,\frac{d_m}{2\cos\lambda}\,G^{-0.2}W^{-c}
            \left(\frac{\rho_{40}\,\nu(T)\,\omega\,d_m}{2E'D_w\cos\lambda}\right)^{k}

    with :math:`k = 0.512`, :math:`c = 0.516` for 2-point (double nut)
    contact and :math:`k = 0.4936`, :math:`c = 0.5` for 4-point single nuts,
    :math:`E' = 2.31\cdot10^{11}` Pa. The torque grows as
    :math:`(\eta\omega)^{0.5}` and has no speed-independent part. It is a
    loss per loaded ball, so a double nut, whose two halves each carry the
    preload with their own balls, loses twice what one half does; this is how
    it is applied here (Jungnickel's own convention for double nuts is not
    given in the public implementation, so the double-nut values are
    uncertain by up to that factor 2). Wiper losses (a factor 2 in that
    implementation when the nut is sealed) are left out, as in the catalogue
    drag torques. The law as coded in the open-source Thermca package
    (``thermca/lib/ball_screw.py``, ``cont_loss``) was read to check the
    constants; this is an independent implementation.

    Parameters
    ----------
    screw : BallScrew
        ``nut`` "double" or "single-4point"; ``loaded_turns * circuits`` per
        (half-)nut.
    lubricant : Lubricant
        Its viscosities at 20 and 40 °C and density at 40 °C are used.
    speed : array_like
        Screw speed [rad/s].
    temperature : array_like
        [°C].

    References
    ----------
    .. [1] T. Jungnickel, *Thermisches Verhalten von Kugelgewindetrieben*
       (thermal behaviour of ball screw drives), doctoral thesis, TU Dresden,
       2010, eq. 9.49.

    Examples
    --------
    The reference screw (40 x 10 mm, 6.35 mm balls, 2 x 2.5 turns per half,
    2 kN) with mineral ISO VG 68 at 40 °C, 1000 rpm, both halves:

    >>> from ballscrew import lubricants
    >>> round(float(jungnickel_loss_torque(reference_screw(),
    ...     lubricants.get("mineral ISO VG 68"), 104.72, 40.0)), 3)
    0.467
    """
    e = JUNGNICKEL_MODULUS
    dm, dw = screw.pitch_diameter, screw.ball_diameter
    cos_l = math.cos(screw.lead_angle)
    z = screw.loaded_turns * screw.circuits * math.pi * dm / (cos_l * dw)
    q = screw.preload / (z * math.sin(screw.contact_angle) * cos_l)
    w = q / (e * (dw / 2.0) ** 2)
    nu20 = float(lubricant.kinematic_viscosity(20.0))
    nu40 = float(lubricant.kinematic_viscosity(40.0))
    b = math.log(nu20 / nu40) / (1.0 / 115.0 - 1.0 / 135.0)
    a = nu40 / math.exp(b / 135.0)
    g = 1.29e-7 * nu40**0.204 * e
    k, c = (0.4936, 0.5) if screw.nut == "single-4point" else (0.512, 0.516)
    sets = 2.0 if screw.nut == "double" else 1.0
    rho = float(lubricant.density(40.0))
    omega = np.abs(np.asarray(speed, dtype=float))
    nu = a * np.exp(b / (np.asarray(temperature, dtype=float) + 95.0))
    group = rho * nu * omega * dm / (2.0 * e * dw * cos_l)
    result: FloatArray = sets * 9.16 * z * q * dm / (2.0 * cos_l) * g**-0.2 * w**-c * group**k
    return result


TREND_SOURCE = (
    "targets of the complete model (issue 8): measured drag torque rises with speed and falls "
    "with temperature (Jungnickel 2010: T ~ (eta n)^0.5; T20/T40 of his law about 1.8); roughly "
    "linear in preload (Zhou et al. 2016; catalogue formula); 4-point/double from Jungnickel's "
    "law about 1.3"
)


def _trend_rows(model: str) -> list[ScoreRow]:
    screw = reference_screw()
    oil = get_lubricant("mineral ISO VG 68")

    def t(s: BallScrew, rpm: float, temp: float) -> float:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            return float(
                friction_torque(s, oil, speed=rpm * RPM, temperature=temp, model=model).total
            )

    t100, t1000 = t(screw, 100.0, 40.0), t(screw, 1000.0, 40.0)
    speed_exp = math.log(t1000 / t100) / math.log(10.0) if t100 > 0 and t1000 > 0 else math.nan
    t20 = t(screw, 1000.0, 20.0)
    lo, hi = (
        t(screw.replace(preload=1000.0), 1000.0, 40.0),
        t(screw.replace(preload=4000.0), 1000.0, 40.0),
    )
    pre_exp = math.log(hi / lo) / math.log(4.0) if lo > 0 and hi > 0 else math.nan
    four = t(screw.replace(nut="single-4point"), 1000.0, 40.0)
    specs = [
        ("trend: speed exponent 100-1000 rpm", 0.3, 0.05, 0.6, speed_exp),
        ("trend: T(20 C)/T(40 C) at 1000 rpm", 1.8, 1.1, 2.5, t20 / t1000 if t1000 else math.nan),
        ("trend: preload exponent 1-4 kN", 0.8, 0.5, 1.1, pre_exp),
        ("trend: 4-point/double nut", 1.3, 1.0, 1.6, four / t1000 if t1000 else math.nan),
    ]
    return [
        ScoreRow(name, "trend", TREND_SOURCE, ref, low, high, "-", model, value, False)
        for name, ref, low, high, value in specs
    ]


def score(
    model_names: list[str] | None = None,
    cases: list[ReferenceCase] | None = None,
    *,
    trends: bool = True,
    progress: Callable[[str], object] | None = None,
) -> list[ScoreRow]:
    """Run every model on every case; one :class:`ScoreRow` per model and case (and trend)."""
    names = model_names or [m.name for m in models()]
    cases = load_cases() if cases is None else cases
    rows: list[ScoreRow] = []
    for name in names:
        for case in cases:
            rows.append(
                ScoreRow(
                    case.case,
                    case.kind,
                    case.source,
                    case.reference,
                    case.low,
                    case.high,
                    "N*m",
                    name,
                    _torque(case, name),
                    case.training,
                )
            )
        if trends:
            rows.extend(_trend_rows(name))
        if progress is not None:
            progress(name)
    return rows


@dataclass(frozen=True)
class ModelScore:
    """Summary of one model's scorecard."""

    model: str
    cases: int
    within: int
    median_abs_log10: float
    by_kind: dict[str, tuple[int, int]]
    trends_within: int
    trends: int

    @property
    def share_within(self) -> float:
        """Share of the (non-trend) cases inside their band [-]."""
        return self.within / self.cases if self.cases else math.nan


def summarise(rows: list[ScoreRow]) -> list[ModelScore]:
    """Per model: cases inside their band, median |log10 ratio|, by kind, and trends met."""
    out = []
    for name in dict.fromkeys(r.model for r in rows):
        mine = [r for r in rows if r.model == name and r.kind != "trend"]
        trend = [r for r in rows if r.model == name and r.kind == "trend"]
        logs = [abs(math.log10(r.ratio)) for r in mine if r.ratio > 0 and math.isfinite(r.ratio)]
        kinds: dict[str, tuple[int, int]] = {}
        for r in mine:
            n_in, n = kinds.get(r.kind, (0, 0))
            kinds[r.kind] = (n_in + int(r.within), n + 1)
        out.append(
            ModelScore(
                model=name,
                cases=len(mine),
                within=sum(r.within for r in mine),
                median_abs_log10=float(np.median(logs)) if logs else math.nan,
                by_kind=kinds,
                trends_within=sum(r.within for r in trend),
                trends=len(trend),
            )
        )
    return out


def bundled_summary() -> dict[str, dict[str, str]]:
    """The scorecard summary shipped with the package, by model (empty if absent).

    Written by ``scripts/update_scorecard.py``; a test recomputes it, so it
    cannot go stale.
    """
    path = resources.files("ballscrew").joinpath("data", SUMMARY_FILE)
    if not path.is_file():
        return {}
    rows = csv.DictReader(io.StringIO(path.read_text("utf-8")))
    return {row["model"]: dict(row) for row in rows}
