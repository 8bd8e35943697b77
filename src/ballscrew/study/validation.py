r"""The validation scorecard: every model against every public number, judged as makers do.

The bundled file ``data/validation_cases.csv`` lists reference cases, each
with its source and the band a prediction should fall in:

``catalog``
    The manufacturers' preload drag torque :math:`T_p = 0.05/\sqrt{\tan\beta}
    \cdot F_{pr}l/2\pi` at their test conditions (100 rpm, ISO VG 68, no
    wiper) over the 20 HIWIN ground nuts of the bundled catalogue table
    (nominal diameters 14 to 63 mm, leads 5 to 40 mm; preloads 2, 5 and 10 %
    of the dynamic load rating, double nuts and 4-point single nuts), with the
    band the makers themselves accept around that reference torque
    (:func:`acceptance_band`: THK's tolerance of the preload drag torque, by
    torque level, for accuracy grade C3). The rule is a maker's target for
    setting the preload, not a measurement, so a model is judged against it
    only within that band, and double and 4-point nuts are scored apart.
``jungnickel``
    Jungnickel's empirical loss law, fitted to measured losses of machine-tool
    ball screws, at 1000 and 3000 rpm for the double nuts of the grid, with a
    band of a factor 2 either way (its double-nut convention is not
    documented: up to a factor 2 in the level).

Computed from those, per model (:func:`score`):

``exponent``
    Per screw of the Jungnickel set, the speed exponent from 1000 to 3000 rpm
    and the preload exponent from 2 to 10 % of the load rating at 1000 rpm,
    each within a factor 1.5 of Jungnickel's 0.5.
``no-trend``
    Over the catalogue cases of each nut kind, the partial slopes of
    :math:`\ln(T_{model}/T_{rule})` against :math:`\ln\tan\beta`,
    :math:`\ln d_0` and :math:`\ln F_{pr}` (one least-squares fit on the
    three, with 95 % intervals): below 0.2 in magnitude. A model whose
    error follows the lead angle, the size or the preload fails here even if
    its average is right.
``trend``
    On the project's reference screw (:func:`ballscrew.reference_screw`):
    :math:`T(20\,°C)/T(40\,°C)` at 100 rpm (0.8 to 1.3) and, for a nut
    running flooded (``lubrication="flooded"`` of the models that take it), at
    100 rpm (0.8 to 1.3) and 1000 rpm (1.3 to 2.2), the speed exponents from
    100 to 1000 and from 1000 to 3000 rpm (and the latter flooded), the
    preload exponent (1 to 4 kN at 1000 rpm) and the ratio of a 4-point single
    nut to a double nut with the same balls.
``reported``
    Computed, not judged: :math:`T(20\,°C)/T(40\,°C)` at 1000 rpm of an
    oil-air nut (no bulk oil), whose viscous share is the rolling term alone.

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
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, replace
from importlib import resources
from typing import Any

import numpy as np
import numpy.typing as npt

from ..chain import friction_torque, models
from ..design.catalog_formulas import DRAG_TORQUE_TOLERANCE
from ..errors import BallScrewValidityWarning, FloatArray
from ..friction import get_model
from ..geometry import BallScrew, reference_screw
from ..kinematics import rpm_to_rad_s
from ..lubricant import Lubricant
from ..lubricants import get as get_lubricant

__all__ = [
    "ACCEPTANCE_BANDS",
    "FOUR_POINT_RATIO",
    "FOUR_POINT_SOURCE",
    "ModelScore",
    "ReferenceCase",
    "ScoreRow",
    "Scorecard",
    "acceptance_band",
    "bundled_summary",
    "jungnickel_loss_torque",
    "load_cases",
    "run_validate",
    "score",
    "screw_from_row",
    "summarise",
]

CASES_FILE = "validation_cases.csv"
SUMMARY_FILE = "scorecard_summary.csv"

ACCEPTANCE_BANDS: tuple[tuple[float, float], ...] = tuple(
    (upper, tolerance) for _, upper, tolerance in DRAG_TORQUE_TOLERANCE["C3"]
)
"""(upper reference torque [N·m], tolerance [-]) of each row of the makers' table.

THK General Catalog, ball screw section, A-688, Table 13 ("tolerance on the
preload torque"; JIS B 1192 / ISO 3408-3 give the same permitted variation of the
dynamic preload drag torque), accuracy grade C3, thread length up to 40 times the
diameter: ±45 % for a reference torque of 0.2 to 0.4 N·m, ±35 % to 0.6, ±30 % to
1.0, ±25 % to 2.5 and ±20 % to 6.3 N·m.
"""


def acceptance_band(reference_torque: float) -> float:
    """The makers' tolerance of a preload drag torque at its reference value [-].

    From :data:`ACCEPTANCE_BANDS` (THK A-688 Table 13, grade C3). The table
    begins at 0.2 N·m; below it the first row's ±45 % is applied (the small
    screws of the grid, stated in the cases' source); above 6.3 N·m the last
    row's ±20 %.

    >>> [acceptance_band(t) for t in (0.1, 0.3, 0.5, 0.8, 2.0, 5.0)]
    [0.45, 0.45, 0.35, 0.3, 0.25, 0.2]
    """
    for upper, tolerance in ACCEPTANCE_BANDS:
        if reference_torque <= upper:
            return tolerance
    return ACCEPTANCE_BANDS[-1][1]


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
    interval: tuple[float, float] = (math.nan, math.nan)
    """95 % interval of a fitted value (the slopes of the no-trend rows), else NaN."""
    nut: str = ""
    """Nut arrangement of the case's screw ("" for rows of the reference screw's trends)."""

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
            speed=rpm_to_rad_s(case.speed_rpm),
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
    a, b, nu40 = _vogel_cameron(lubricant)
    g = 1.29e-7 * nu40**0.204 * e
    k, c = (0.4936, 0.5) if screw.nut == "single-4point" else (0.512, 0.516)
    sets = 2.0 if screw.nut == "double" else 1.0
    rho = float(lubricant.density(40.0))
    omega = np.abs(np.asarray(speed, dtype=float))
    nu = a * np.exp(b / (np.asarray(temperature, dtype=float) + 95.0))
    group = rho * nu * omega * dm / (2.0 * e * dw * cos_l)
    result: FloatArray = sets * 9.16 * z * q * dm / (2.0 * cos_l) * g**-0.2 * w**-c * group**k
    return result


def _vogel_cameron(lubricant: Lubricant) -> tuple[float, float, float]:
    """Jungnickel's ``nu = A exp(B/(T + 95))`` through the oil's 20 and 40 °C viscosities.

    Returns A [m²/s], B [°C] and the 40 °C viscosity [m²/s].
    """
    nu20 = float(lubricant.kinematic_viscosity(20.0))
    nu40 = float(lubricant.kinematic_viscosity(40.0))
    b = math.log(nu20 / nu40) / (1.0 / 115.0 - 1.0 / 135.0)
    a = nu40 / math.exp(b / 135.0)
    return a, b, nu40


FOUR_POINT_RATIO = 1.25
r"""Drag torque of a 4-point single nut over a double nut's at equal preload [-].

The makers print one preload drag-torque rule for every way of preloading
(THK General Catalog A-688; HIWIN), but THK says that preload by oversize
balls raises the torque through the balls' differential slip and spin
(A-768). Two published figures put a number on it:

- SKF's constant friction coefficients for bearings under normal conditions
  are 0.0024 for a four-point contact ball bearing and 0.0020 for a
  single-row angular contact ball bearing (SKF, *Rolling bearings*, the
  frictional-moment chapter): 1.2;
- Jungnickel's loss law fitted to measured ball screw losses (TU Dresden
  2010, eq. 9.49) gives a 4-point nut 1.25 to 1.32 times what one set of
  preloaded balls of a double nut loses, over the scorecard's sizes at
  1000 rpm (its separate exponents for 4-point contact; this package counts
  both halves of a double nut, :func:`jungnickel_loss_torque`, which halves
  that figure).

So the scorecard judges a 4-point nut against 1.25 times the rule, inside
the makers' band at that level, and a double nut against the rule itself.
"""

FOUR_POINT_SOURCE = (
    "4-point nuts: 1.25 x the rule (THK A-768: oversize-ball preload adds differential slip "
    "and spin; SKF's constant friction coefficients 0.0024/0.0020 = 1.2 for four-point over "
    "angular contact bearings; Jungnickel's law 1.25-1.32 per preloaded ball set)"
)

TREND_SOURCE = (
    "measured drag torque rises with speed; roughly linear in preload (Zhou et al. 2016; "
    "catalogue formula); 4-point/double: FOUR_POINT_RATIO's sources, 1.2 to 1.32. T20/T40: "
    "0.8-1.3 at 100 rpm (SKF's bearing model gives 0.82-0.94 on an angular-contact bearing of "
    "this size at 2 kN: cold oil lifts the contacts out of boundary friction); 1.3-2.2 at "
    "1000 rpm for a nut running flooded (SKF's model 1.5-1.7 from its viscous rolling term, "
    "Jungnickel's purely viscous law about 1.8); oil-air, drip and grease nuts reported"
)
FLOODED_PARAMETERS: dict[str, Any] = {"lubrication": "flooded"}
"""The parameters of a nut running flooded, for the models that take a lubrication method
(the others do not tell the methods apart and are run as they are)."""
REPORTED_PARAMETERS: dict[str, Any] = {"lubrication": "oil-air"}
"""The parameters of a nut with no bulk oil (oil-air), whose T20/T40 is reported, not judged."""
EXPONENT_SOURCE = (
    "Jungnickel (2010) loss law (as implemented in Thermca): torque ~ (eta n)^0.512 and "
    "~ preload^0.484 for double nuts; band: a factor 1.5 either way"
)
SLOPE_SOURCE = (
    "no systematic error against the catalogue rule: partial slope of ln(model/rule) on "
    "ln tan(lead angle), ln d0 and ln preload (least squares on the catalogue cases of one "
    "nut kind, 95 % interval), below 0.2 in magnitude"
)
SLOPE_LIMIT = 0.2
"""Largest magnitude of a no-trend slope that passes [-]."""


def _lubrication_parameters(model: str, parameters: dict[str, Any]) -> dict[str, Any]:
    """``parameters`` if ``model`` takes a lubrication method, else none."""
    return parameters if "lubrication" in get_model(model).parameters else {}


def _trend_rows(model: str) -> list[ScoreRow]:
    screw = reference_screw()
    oil = get_lubricant("mineral ISO VG 68")
    flooded = _lubrication_parameters(model, FLOODED_PARAMETERS)
    reported = _lubrication_parameters(model, REPORTED_PARAMETERS)

    def t(s: BallScrew, rpm: float, temp: float, params: dict[str, Any] | None = None) -> float:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            return float(
                friction_torque(
                    s, oil, speed=rpm_to_rad_s(rpm), temperature=temp, model=model,
                    **(params or {}),
                ).total
            )  # fmt: skip

    def ratio(a: float, b: float) -> float:
        return a / b if b > 0 else math.nan

    def exponent(a: float, b: float, span: float) -> float:
        return math.log(a / b) / math.log(span) if a > 0 and b > 0 else math.nan

    t100, t1000, t3000 = (t(screw, n, 40.0) for n in (100.0, 1000.0, 3000.0))
    lo, hi = (t(screw.replace(preload=f), 1000.0, 40.0) for f in (1000.0, 4000.0))
    four = t(screw.replace(nut="single-4point"), 1000.0, 40.0)
    f1000, f3000 = (t(screw, n, 40.0, flooded) for n in (1000.0, 3000.0))
    specs = [
        ("trend: T(20 C)/T(40 C) at 100 rpm", 1.0, 0.8, 1.3, ratio(t(screw, 100.0, 20.0), t100)),
        ("trend: T(20 C)/T(40 C) at 100 rpm, flooded", 1.0, 0.8, 1.3,
         ratio(t(screw, 100.0, 20.0, flooded), t(screw, 100.0, 40.0, flooded))),
        ("trend: T(20 C)/T(40 C) at 1000 rpm, flooded", 1.6, 1.3, 2.2,
         ratio(t(screw, 1000.0, 20.0, flooded), f1000)),
        ("trend: speed exponent 100-1000 rpm", 0.3, 0.05, 0.6, exponent(t1000, t100, 10.0)),
        ("trend: speed exponent 1000-3000 rpm", 0.5, 0.1, 0.7, exponent(t3000, t1000, 3.0)),
        ("trend: speed exponent 1000-3000 rpm, flooded", 0.5, 0.1, 0.7,
         exponent(f3000, f1000, 3.0)),
        ("trend: preload exponent 1-4 kN", 0.8, 0.5, 1.1, exponent(hi, lo, 4.0)),
        ("trend: 4-point/double nut", FOUR_POINT_RATIO, 1.0, 1.6, ratio(four, t1000)),
    ]  # fmt: skip
    rows = [
        ScoreRow(name, "trend", TREND_SOURCE, ref, low, high, "-", model, value, False)
        for name, ref, low, high, value in specs
    ]
    oil_air = ratio(t(screw, 1000.0, 20.0, reported), t(screw, 1000.0, 40.0, reported))
    rows.append(
        ScoreRow("reported: T(20 C)/T(40 C) at 1000 rpm, oil-air (no bulk oil)", "reported",
                 TREND_SOURCE, math.nan, -math.inf, math.inf, "-", model, oil_air, False)
    )  # fmt: skip
    return rows


def _exponent_rows(model: str, cases: list[ReferenceCase], torque: list[float]) -> list[ScoreRow]:
    """Speed and preload exponents of each Jungnickel screw, against the law's own."""
    oil = get_lubricant("mineral ISO VG 68")
    pairs: dict[str, dict[float, tuple[ReferenceCase, float]]] = {}
    for case, value in zip(cases, torque, strict=True):
        if case.kind == "jungnickel":
            label = case.case.split(",")[0]
            pairs.setdefault(label, {})[case.speed_rpm] = (case, value)
    rows = []
    for label, by_speed in pairs.items():
        if not {1000.0, 3000.0} <= set(by_speed):
            continue
        (case, t1), (_, t3) = by_speed[1000.0], by_speed[3000.0]
        w = rpm_to_rad_s(1000.0)
        law = [
            float(jungnickel_loss_torque(case.screw, oil, rpm_to_rad_s(n), case.temperature))
            for n in (1000.0, 3000.0)
        ]
        # 2 and 10 % of the load rating: the case's 5 % preload times 0.4 and 2.
        light, heavy = (case.screw.replace(preload=case.screw.preload * f) for f in (0.4, 2.0))
        law_pre = [
            float(jungnickel_loss_torque(s, oil, w, case.temperature)) for s in (light, heavy)
        ]
        mine = [_torque(replace(case, screw=s, speed_rpm=1000.0), model) for s in (light, heavy)]
        for what, ref, value in (
            ("speed exponent 1000-3000 rpm", math.log(law[1] / law[0]) / math.log(3.0),
             math.log(t3 / t1) / math.log(3.0) if t1 > 0 and t3 > 0 else math.nan),
            ("preload exponent 2-10 % Ca at 1000 rpm", math.log(law_pre[1] / law_pre[0])
             / math.log(5.0), math.log(mine[1] / mine[0]) / math.log(5.0)
             if min(mine) > 0 else math.nan),
        ):  # fmt: skip
            rows.append(
                ScoreRow(f"{label}: {what}", "exponent", EXPONENT_SOURCE, ref, ref / 1.5,
                         ref * 1.5, "-", model, value, False, nut=case.screw.nut)
            )  # fmt: skip
    return rows


SLOPE_VARIABLES: tuple[tuple[str, Callable[[BallScrew], float]], ...] = (
    ("ln tan(lead angle)", lambda s: math.log(math.tan(s.lead_angle))),
    ("ln d0", lambda s: math.log(s.pitch_diameter)),
    ("ln preload", lambda s: math.log(s.preload)),
)
"""The variables of the no-trend check and how each is read off a screw."""


def trend_slopes(screws: list[BallScrew], ratios: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Partial slopes of :math:`\ln r` on :data:`SLOPE_VARIABLES`, with 95 % half-widths.

    Ordinary least squares of :math:`\ln r = c_0 + \sum_k s_k x_k` over the
    screws; the half-width is Student's :math:`t_{0.975}` times the standard
    error of each slope (:math:`n - 4` degrees of freedom). NaN where fewer
    than five positive ratios are given.

    >>> from ballscrew import reference_screw
    >>> s = [reference_screw().replace(lead=l, preload=p) for l, p in
    ...      ((8e-3, 1e3), (1e-2, 2e3), (2e-2, 1e3), (4e-2, 3e3), (1e-2, 5e3), (8e-3, 4e3))]
    >>> r = [math.tan(x.lead_angle) ** 0.3 for x in s]  # ratio grows as tan^0.3 exactly
    >>> slopes, half = trend_slopes(s, r)
    >>> [round(float(v), 6) + 0.0 for v in slopes]
    [0.3, 0.0, 0.0]
    """
    from scipy import stats

    r = np.asarray(ratios, dtype=float)
    good = np.isfinite(r) & (r > 0.0)
    nan = np.full(len(SLOPE_VARIABLES), math.nan)
    if good.sum() < len(SLOPE_VARIABLES) + 2:
        return nan, nan
    chosen = [s for s, g in zip(screws, good, strict=True) if g]
    columns = [[f(s) for s in chosen] for _, f in SLOPE_VARIABLES]
    x = np.column_stack([np.ones(len(chosen)), *columns])
    y = np.log(r[good])
    coef, *_ = np.linalg.lstsq(x, y, rcond=None)
    dof = len(y) - x.shape[1]
    resid = y - x @ coef
    rank = np.linalg.matrix_rank(x)
    if dof <= 0 or rank < x.shape[1]:
        return coef[1:], nan
    cov = float(resid @ resid) / dof * np.linalg.inv(x.T @ x)
    half: FloatArray = float(stats.t.ppf(0.975, dof)) * np.sqrt(np.diag(cov))[1:]
    slopes: FloatArray = coef[1:]
    return slopes, half


RATIO_SOURCE = (
    "4-point over double nut at equal preload, size by size on the catalogue cases (100 rpm, "
    "20 C): each within 1.0-1.6, their median within 1.15-1.40 (SKF 1.2; Jungnickel's law "
    "1.25-1.32 per preloaded ball set; THK A-768)"
)


def _four_point_rows(model: str, cases: list[ReferenceCase], torque: list[float]) -> list[ScoreRow]:
    """The model's 4-point over double nut of every catalogue size and preload, and their median."""
    double = {c.case: v for c, v in zip(cases, torque, strict=True)
              if c.kind == "catalog" and c.screw.nut == "double"}  # fmt: skip
    rows = []
    for case, value in zip(cases, torque, strict=True):
        if case.kind != "catalog" or case.screw.nut != "single-4point":
            continue
        partner = double.get(case.case.replace(" single-4point ", " double "))
        if partner is None:
            continue
        r = value / partner if partner > 0 else math.nan
        rows.append(
            ScoreRow(f"{case.case.replace(' single-4point', '')}: 4-point/double", "ratio",
                     RATIO_SOURCE, FOUR_POINT_RATIO, 1.0, 1.6, "-", model, r, False,
                     nut="single-4point")
        )  # fmt: skip
    if rows:
        values = [r.predicted for r in rows]
        median = float(np.median(values)) if all(map(math.isfinite, values)) else math.nan
        rows.append(
            ScoreRow("median 4-point/double over the catalogue sizes", "ratio-median",
                     RATIO_SOURCE, FOUR_POINT_RATIO, 1.15, 1.40, "-", model, median, False,
                     nut="single-4point")
        )  # fmt: skip
    return rows


def _slope_rows(model: str, cases: list[ReferenceCase], torque: list[float]) -> list[ScoreRow]:
    rows = []
    for nut, label in (("double", "double nuts"), ("single-4point", "4-point nuts")):
        mine = [(c, v) for c, v in zip(cases, torque, strict=True)
                if c.kind == "catalog" and c.screw.nut == nut]  # fmt: skip
        if not mine:
            continue
        slopes, half = trend_slopes([c.screw for c, _ in mine], [v / c.reference for c, v in mine])
        for (name, _), slope, h in zip(SLOPE_VARIABLES, slopes, half, strict=True):
            rows.append(
                ScoreRow(
                    f"no trend: ln(model/rule) on {name}, {label}", "no-trend", SLOPE_SOURCE,
                    0.0, -SLOPE_LIMIT, SLOPE_LIMIT, "-", model, float(slope), False,
                    interval=(float(slope - h), float(slope + h)), nut=nut,
                )
            )  # fmt: skip
    return rows


def score(
    model_names: list[str] | None = None,
    cases: list[ReferenceCase] | None = None,
    *,
    trends: bool = True,
    progress: Callable[[str], object] | None = None,
) -> list[ScoreRow]:
    """Run every model on every case; one :class:`ScoreRow` per model and case.

    With ``trends`` (the default) each model also gets its computed rows: the
    exponents against Jungnickel's law, the no-trend slopes over the catalogue
    cases and the trends of the reference screw (module docstring).
    """
    names = model_names or [m.name for m in models()]
    cases = load_cases() if cases is None else cases
    rows: list[ScoreRow] = []
    for name in names:
        torque = [_torque(case, name) for case in cases]
        for case, value in zip(cases, torque, strict=True):
            rows.append(
                ScoreRow(case.case, case.kind, case.source, case.reference, case.low, case.high,
                         "N*m", name, value, case.training, nut=case.screw.nut)
            )  # fmt: skip
        if trends:
            rows.extend(_exponent_rows(name, cases, torque))
            rows.extend(_slope_rows(name, cases, torque))
            rows.extend(_four_point_rows(name, cases, torque))
            rows.extend(_trend_rows(name))
        if progress is not None:
            progress(name)
    return rows


SCORE_GROUPS: tuple[tuple[str, Callable[[ScoreRow], bool]], ...] = (
    ("double nuts in makers' band", lambda r: r.kind == "catalog" and r.nut == "double"),
    ("of which training rows", lambda r: r.kind == "catalog" and r.nut == "double" and r.training),
    ("of which test rows", lambda r: r.kind == "catalog" and r.nut == "double" and not r.training),
    ("4-point nuts in makers' band", lambda r: r.kind == "catalog" and r.nut == "single-4point"),
    ("4-point/double per size (1.0-1.6)", lambda r: r.kind == "ratio"),
    ("median 4-point/double (1.15-1.40)", lambda r: r.kind == "ratio-median"),
    ("Jungnickel level (factor 2)", lambda r: r.kind == "jungnickel"),
    ("Jungnickel exponents (factor 1.5)", lambda r: r.kind == "exponent"),
    ("no trend (|slope| < 0.2)", lambda r: r.kind == "no-trend"),
    ("trends met", lambda r: r.kind == "trend"),
)
"""The scorecard's groups of rows, by name, as the summary counts them."""


@dataclass(frozen=True)
class ModelScore:
    """Summary of one model's scorecard."""

    model: str
    cases: int
    within: int
    median_abs_log10: float
    groups: dict[str, tuple[int, int]]


def summarise(rows: list[ScoreRow]) -> list[ModelScore]:
    """Per model: the reference cases inside their band, median ``|log10 ratio|``, each group."""
    out = []
    for name in dict.fromkeys(r.model for r in rows):
        mine = [r for r in rows if r.model == name]
        cases = [r for r in mine if r.kind in ("catalog", "jungnickel")]
        logs = [abs(math.log10(r.ratio)) for r in cases if r.ratio > 0 and math.isfinite(r.ratio)]
        groups = {}
        for label, member in SCORE_GROUPS:
            chosen = [r for r in mine if member(r)]
            if chosen:
                groups[label] = (sum(r.within for r in chosen), len(chosen))
        out.append(
            ModelScore(
                model=name,
                cases=len(cases),
                within=sum(r.within for r in cases),
                median_abs_log10=float(np.median(logs)) if logs else math.nan,
                groups=groups,
            )
        )
    return out


@dataclass(frozen=True)
class Scorecard:
    """Every model's rows on the reference cases and trends, and each model's summary."""

    rows: tuple[ScoreRow, ...]
    scores: tuple[ModelScore, ...]

    def as_dict(self) -> dict[str, Any]:
        """The rows (with their ratio and whether inside the band) and the summaries."""
        return {
            "rows": [{**asdict(r), "ratio": r.ratio, "within": r.within} for r in self.rows],
            "scores": [asdict(s) for s in self.scores],
        }


def run_validate(
    model_names: Sequence[str] | None = None,
    *,
    progress: Callable[[str], object] | None = None,
) -> Scorecard:
    """``ballscrew validate``: every model (or those named) on every bundled reference case.

    ``progress`` is called with each model's name as it is scored.
    """
    names = [get_model(name).name for name in model_names or ()] or None
    rows = score(names, progress=progress)
    return Scorecard(tuple(rows), tuple(summarise(rows)))


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
