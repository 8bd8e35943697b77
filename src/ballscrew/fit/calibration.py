r"""Calibration: the uncertain inputs of a friction model that explain a measured curve.

This module is long on purpose: the fit, its linearised uncertainty, the checks of
its residuals (runs test, lag-1 autocorrelation, absurd values) and the fitted
case file all read one fit's private state (``_Fit``), and the method is stated
here once in full.

:func:`fit_parameters` adjusts the chosen parameters :math:`\theta` (the screw's
preload, a model's coefficients) to minimise the squared residuals
:math:`r_i = T_{model}(\omega_i, T_i, F_i; \theta) - T_{meas,i}` [N·m] by bounded
nonlinear least squares (scipy's trust-region reflective ``least_squares``),
in log space for parameters that span decades.

Uncertainty: at the optimum the covariance of the transformed parameters is
:math:`s^2 (J^T J)^{-1}` with :math:`s^2 = \sum r_i^2/(n-p)` and :math:`J` the
Jacobian of the residuals, and the 95 % interval is :math:`\hat\theta \pm
t_{0.975,\,n-p}\,\sigma` (Student's t), mapped back through the exponential
for log parameters (so intervals are asymmetric there). This is the usual
linearised interval (e.g. Seber and Wild, *Nonlinear Regression*, 1989,
§5.1); it is accurate when the model is close to linear over the interval.

Robustness:

* outliers: a first fit's residuals give a robust scale
  :math:`\hat\sigma = 1.4826\,\mathrm{MAD}`; points beyond :math:`4\hat\sigma`
  are reported and left out of the final fit (after a soft-L1 refit that keeps
  them from steering the estimate);
* identifiability: a parameter whose 95 % interval spans more than a factor
  100 (log parameters) or the whole allowed range (others) cannot be
  identified from the data; it is held at its start value, the others are
  refitted, and a warning says so. Pairs with :math:`|\rho| > 0.95` get a
  warning that the data cannot separate them;
* too few points (:math:`n \le p`) is an error.

Absurd fits (:func:`absurdity_notes`): each of these gives a warning and marks
the intervals unreliable (``FitResult.reliable``), since the linearised
interval assumes a model that fits and residuals that are noise:

* a fitted screw the plausibility rules refuse, such as a preload above the
  static rating (:func:`ballscrew.ratings.plausibility`);
* a constant more than :data:`SCATTER_SIGMAS` log-standard deviations from the
  scatter of its training cases (:data:`TRAINING_SCATTER`);
* residuals with structure: ordered by speed, their signs form fewer runs
  than chance gives (Wald and Wolfowitz's runs test, :func:`runs_test`, one-sided
  p below :data:`RUNS_P_LIMIT`), reported with their lag-1 autocorrelation
  (:func:`lag1_autocorrelation`);
* measured torques more than :data:`MAGNITUDE_LIMIT` times larger or smaller
  than the model gives at the start values: a unit slip (N·mm under an N·m
  header is a factor 1000) is the likely cause.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..chain import friction_torque
from ..design.ratings import Ratings, plausibility, static_rating_estimate
from ..errors import BallScrewInputError, FloatArray
from ..friction import get_model
from ..friction.complete import BALL_TRAIN_SCATTER
from ..geometry import BallScrew
from ..io.case import Case
from ..io.measured import MeasuredCurve
from ..lubricant import Lubricant
from ..lubricants import get as get_lubricant

Index = npt.NDArray[np.intp]

__all__ = [
    "FITTABLE",
    "TRAINING_SCATTER",
    "Estimate",
    "FitResult",
    "FreeParameter",
    "RunsTest",
    "absurdity_notes",
    "fit_parameters",
    "lag1_autocorrelation",
    "run_fit",
    "runs_test",
]


@dataclass(frozen=True)
class FreeParameter:
    """A parameter calibration may adjust: where it lives, its unit and bounds."""

    name: str
    where: str  # "screw", or "model"
    unit: str
    low: float
    high: float
    log: bool
    description: str


FITTABLE: dict[str, FreeParameter] = {
    p.name: p
    for p in (
        FreeParameter("preload", "screw", "N", 1.0, 1e6, True, "the nut's axial preload"),
        FreeParameter("limiting_shear_coefficient", "model", "-", 1e-3, 0.5, True,
                      "pressure slope gamma_L of the lubricant's limiting shear stress"),
        FreeParameter("limiting_shear_stress", "model", "Pa", 1e4, 1e8, True,
                      "limiting shear stress tau_0 at ambient pressure"),
        FreeParameter("ball_train_constant", "model", "-", 1e-5, 1.0, True,
                      "ball-to-ball friction constant c_B of the complete model"),
        FreeParameter("boundary_friction", "model", "-", 1e-3, 0.5, True,
                      "boundary (asperity) friction coefficient"),
        FreeParameter("hysteresis_loss_factor", "model", "-", 1e-5, 0.2, True,
                      "elastic hysteresis loss factor"),
        FreeParameter("seal_torque", "model", "N*m", 0.0, 100.0, False,
                      "drag torque of wipers or seals"),
        FreeParameter("friction_coefficient", "model", "-", 1e-5, 0.5, True,
                      "the catalogue rule's friction coefficient"),
        FreeParameter("preload_coefficient", "model", "-", 1e-4, 1.0, True,
                      "the catalogue rule's preload torque coefficient"),
    )
}  # fmt: skip
"""Parameters :func:`fit_parameters` may free, with their bounds."""

CORRELATION_LIMIT = 0.95
"""|correlation| above which a pair is reported as not separable."""

OUTLIER_SCALE = 4.0
"""Robust standard deviations beyond which a point is an outlier."""

MAX_OUTLIER_SHARE = 0.2
"""Largest share of the points that may be left out as outliers."""

TRAINING_SCATTER: dict[str, tuple[float, float, str]] = {
    "ball_train_constant": (
        *BALL_TRAIN_SCATTER,
        "the complete model's training cases (ballscrew.friction.complete.BALL_TRAIN_SCATTER)",
    ),
}
"""16th and 84th percentiles of a constant over its training cases, and their source."""

SCATTER_SIGMAS = 3.0
"""Log-standard deviations from the training scatter's centre beyond which a constant is absurd.

The 16th and 84th percentiles are one standard deviation either side of the
centre of a log-normal scatter; three of them leave 0.3 % of such cases out.
"""

RUNS_P_LIMIT = 0.01
"""One-sided p-value of the runs test below which the residuals have structure."""

MAGNITUDE_LIMIT = 30.0
"""Ratio of measured to start-value torques beyond which a unit slip is suspected."""

STRUCTURE_FLOOR = 1e-3
"""Relative RMS residual below which the residuals' pattern is not tested (a near-exact fit)."""


@dataclass(frozen=True)
class Estimate:
    """A fitted parameter: value and 95 % interval (None when not identified)."""

    name: str
    value: float
    low: float | None
    high: float | None
    start: float
    unit: str
    identified: bool = True

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {
            "value": self.value,
            "low": self.low,
            "high": self.high,
            "start": self.start,
            "unit": self.unit,
            "identified": self.identified,
        }


@dataclass(frozen=True)
class FitResult:
    """Everything a calibration computes (SI; torques in N·m)."""

    model: str
    estimates: dict[str, Estimate]
    correlation: FloatArray
    correlation_names: tuple[str, ...]
    screw: BallScrew
    model_parameters: dict[str, Any]
    speed: FloatArray
    temperature: FloatArray
    axial_load: FloatArray
    measured: FloatArray
    fitted: FloatArray
    outliers: tuple[int, ...]
    rms_residual: float
    warnings: tuple[str, ...] = field(default=())
    reliable: bool = True
    """False when :func:`absurdity_notes` found the fit absurd: the intervals do not hold."""
    structure: dict[str, float] = field(default_factory=dict)
    """The runs test of the residual signs ordered by speed and their lag-1 autocorrelation."""

    @property
    def residuals(self) -> FloatArray:
        """Model minus measurement at every point [N·m]."""
        out: FloatArray = self.fitted - self.measured
        return out

    def as_dict(self) -> dict[str, Any]:
        """The JSON object of ``ballscrew fit --json``."""
        return {
            "model": self.model,
            "parameters": {k: e.as_dict() for k, e in self.estimates.items()},
            "rms_residual_Nm": self.rms_residual,
            "points": int(self.measured.size),
            # Rows of the measured file, counted from 1 as the warning and the CSV do.
            "outlier_rows": [i + 1 for i in self.outliers],
            "correlation": {
                "names": list(self.correlation_names),
                "matrix": self.correlation.tolist(),
            },
            "warnings": list(self.warnings),
            "intervals_reliable": self.reliable,
            "residual_structure": dict(self.structure),
        }


def _spec(name: str, model: str) -> FreeParameter:
    if name not in FITTABLE:
        raise BallScrewInputError("--free", name, f"one of {sorted(FITTABLE)}")
    spec = FITTABLE[name]
    if spec.where == "model":
        get_model(model).check_names({name: 0.0})
    return spec


def _start(
    spec: FreeParameter, screw: BallScrew, lubricant: Lubricant, model: str,
    parameters: dict[str, Any],
) -> float:  # fmt: skip
    if spec.where == "screw":
        value = float(getattr(screw, spec.name))
    elif parameters.get(spec.name) is not None:
        value = float(parameters[spec.name])
    else:
        default = get_model(model).parameters.get(spec.name)
        value = float(getattr(lubricant, spec.name) if default is None else default)
    if spec.log and value <= 0.0:
        raise BallScrewInputError(
            spec.name, value, f"a positive start value for a fit in log space ({spec.unit})"
        )
    return min(max(value, spec.low), spec.high)


def _to_theta(spec: FreeParameter, value: float) -> float:
    return math.log(value) if spec.log else value


def _from_theta(spec: FreeParameter, theta: float) -> float:
    return math.exp(theta) if spec.log else theta


def fit_parameters(
    screw: BallScrew,
    lubricant: Lubricant | str,
    measured: MeasuredCurve,
    free: Sequence[str],
    *,
    model: str = "complete",
    temperature: float = 20.0,
    axial_load: float = 0.0,
    parameters: dict[str, Any] | None = None,
    start: dict[str, float] | None = None,
    ratings: Ratings | None = None,
) -> FitResult:
    """Fit ``free`` parameters of ``model`` to a measured torque curve.

    Parameters
    ----------
    screw, lubricant
        The screw and oil; the screw's fields in ``free`` are start values.
    measured : MeasuredCurve
        Speeds [rad/s], torques [N·m]; its columns win over ``temperature``, ``axial_load``.
    free : sequence of str
        Names from :data:`FITTABLE`.
    parameters : dict, optional
        The model's other parameters (held fixed).
    start : dict, optional
        Start values by name (SI), instead of the screw's or the model's.
    ratings : Ratings, optional
        Load ratings the fitted screw is checked against (:func:`absurdity_notes`).

    Returns
    -------
    FitResult
    """
    oil = get_lubricant(lubricant) if isinstance(lubricant, str) else lubricant
    fixed = dict(parameters or {})
    names = list(dict.fromkeys(free))
    if not names:
        raise BallScrewInputError("--free", "(none)", f"one or more of {sorted(FITTABLE)}")
    specs = [_spec(n, model) for n in names]
    starts = _start_values(specs, screw, oil, model, fixed, start)
    speed, torque, temp, load = _columns(measured, temperature, axial_load)
    n = speed.size
    if n <= len(names):
        raise BallScrewInputError(
            "measured", f"{n} points", f"more points than free parameters ({len(names)})"
        )

    predict = _predictor(screw, oil, fixed, model, speed, temp, load)
    everything = np.arange(n)
    fit = _fit_identifiable(specs, starts, predict, torque, everything)
    estimates, values = _estimates(fit, starts)
    fit.notes.extend([*_correlation_notes(fit.active, fit.corr),
                      *_data_notes(fit.outliers, fit.resid.size - len(fit.active))])  # fmt: skip
    fitted_screw, model_values = _apply(screw, fixed, values)
    fitted = predict(values, everything)
    inliers = np.setdiff1d(everything, np.asarray(fit.outliers, dtype=int))
    validity = _validity_notes(screw, oil, fixed, values, speed, temp, load, model)
    absurd, structure = absurdity_notes(fitted_screw, ratings, values, speed[inliers],
                                        load[inliers], torque[inliers], fitted[inliers],
                                        predict(starts, inliers))  # fmt: skip
    return FitResult(
        model=model,
        estimates={n: estimates[n] for n in names},
        correlation=fit.corr,
        correlation_names=tuple(s.name for s in fit.active),
        screw=fitted_screw,
        model_parameters=model_values,
        speed=speed,
        temperature=temp,
        axial_load=load,
        measured=torque,
        fitted=fitted,
        outliers=fit.outliers,
        rms_residual=float(np.sqrt(np.mean((fitted[inliers] - torque[inliers]) ** 2))),
        warnings=(*fit.notes, *validity, *absurd),
        reliable=not absurd,
        structure=structure,
    )


def run_fit(
    case: Case,
    measured: MeasuredCurve,
    free: Sequence[str],
    *,
    model: str = "complete",
    start: dict[str, float] | None = None,
    temperature: float | None = None,
    axial_load: float | None = None,
) -> FitResult:
    """``ballscrew fit``: :func:`fit_parameters` of a case's screw, oil and model parameters.

    ``temperature`` [°C] and ``axial_load`` [N] are used where the measured curve
    has no such column; by default the case's first. The fitted screw is checked
    against the case's load ratings.
    """
    name = get_model(model).name
    temp = float(case.temperature.flat[0]) if temperature is None else temperature
    load = float(case.axial_load.flat[0]) if axial_load is None else axial_load
    return fit_parameters(
        case.screw, case.lubricant, measured, free, model=name, temperature=temp,
        axial_load=load, parameters=case.parameters_for(name), start=start,
        ratings=case.load_ratings(),
    )  # fmt: skip


def _predictor(
    screw: BallScrew, oil: Lubricant, fixed: dict[str, Any], model: str,
    speed: FloatArray, temp: FloatArray, load: FloatArray,
) -> Callable[[dict[str, float], Index], FloatArray]:  # fmt: skip
    """The model's torque [N·m] at the measured rows for given values of the free parameters."""

    def predict(values: dict[str, float], rows: Index) -> FloatArray:
        s, kwargs = _apply(screw, fixed, values)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = friction_torque(
                s, oil, speed=speed[rows], temperature=temp[rows], axial_load=load[rows],
                model=model, **kwargs,
            ).total  # fmt: skip
        return np.asarray(out, dtype=float)

    return predict


def _validity_notes(
    screw: BallScrew, oil: Lubricant, fixed: dict[str, Any], values: dict[str, float],
    speed: FloatArray, temp: FloatArray, load: FloatArray, model: str,
) -> list[str]:  # fmt: skip
    """The model's validity issues at the fitted values that change a result's meaning.

    Those every ball screw has (``routine``: the film formulas' ranges) are left
    out; a half-nut lifting off, a temperature outside the viscosity fit or the
    lubricant's pour and flash points are told, as ``ballscrew torque`` tells them.
    """
    s, kwargs = _apply(screw, fixed, values)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        issues = friction_torque(s, oil, speed=speed, temperature=temp, axial_load=load,
                                 model=model, **kwargs).warnings  # fmt: skip
    return [f"model validity at the fitted values: {i}" for i in issues if not i.routine]


@dataclass(frozen=True)
class RunsTest:
    """Wald and Wolfowitz's runs test of a sequence of signs."""

    runs: int
    expected: float
    z: float
    p_fewer: float
    """One-sided p-value of so few runs or fewer (normal approximation)."""


def runs_test(values: npt.ArrayLike) -> RunsTest:
    r"""Runs of the signs of ``values`` (zeros dropped) against their number by chance.

    With :math:`n_1` positive and :math:`n_2` negative values, :math:`n =
    n_1 + n_2`, the number of runs :math:`R` has mean :math:`\mu = 2n_1n_2/n +
    1` and variance :math:`\sigma^2 = 2n_1n_2(2n_1n_2 - n)/(n^2(n-1))` when the
    order is random; :math:`z = (R - \mu)/\sigma` is about normal, and few
    runs (residuals that stay on one side over stretches of speed) mean a
    model that misses the curve's shape. Wald and Wolfowitz, Ann. Math.
    Statist. 11 (1940) 147-162; NIST/SEMATECH e-Handbook, 1.3.5.13.

    Examples
    --------
    Eight above then eight below in blocks of four: 4 runs where 9 are expected.

    >>> r = runs_test([1, 1, 1, 1, -1, -1, -1, -1] * 2)
    >>> r.runs, r.expected, round(r.z, 3)
    (4, 9.0, -2.588)
    """
    from scipy.stats import norm

    x = np.asarray(values, dtype=float).ravel()
    signs = np.sign(x[x != 0.0])
    n1, n2 = int(np.count_nonzero(signs > 0)), int(np.count_nonzero(signs < 0))
    n = n1 + n2
    runs = 1 + int(np.count_nonzero(signs[1:] != signs[:-1])) if n else 0
    if n1 == 0 or n2 == 0 or n < 3:
        return RunsTest(runs, float(runs), 0.0, 1.0)
    mean = 2.0 * n1 * n2 / n + 1.0
    var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0))
    z = (runs - mean) / math.sqrt(var) if var > 0.0 else 0.0
    return RunsTest(runs, mean, z, float(norm.cdf(z)))


def lag1_autocorrelation(values: npt.ArrayLike) -> float:
    r"""Lag-1 autocorrelation of a sequence (residuals ordered by speed).

    :math:`r_1 = \sum (x_i - \bar x)(x_{i+1} - \bar x)/\sum (x_i - \bar x)^2`.

    Near 0 for noise, near 1 for residuals that drift with the order (Box and
    Jenkins, *Time Series Analysis*, 1976, eq. 2.1.12). NaN for fewer than 3 values or
    no variation.

    Examples
    --------
    >>> round(lag1_autocorrelation([1.0, 2.0, 3.0, 4.0]), 3)
    0.25
    """
    x = np.asarray(values, dtype=float).ravel()
    d = x - x.mean()
    den = float(d @ d)
    if x.size < 3 or den == 0.0:
        return math.nan
    return float(d[1:] @ d[:-1]) / den


def absurdity_notes(
    screw: BallScrew,
    ratings: Ratings | None,
    values: dict[str, float],
    speed: FloatArray,
    axial_load: FloatArray,
    measured: FloatArray,
    fitted: FloatArray,
    at_start: FloatArray,
) -> tuple[list[str], dict[str, float]]:
    """Warnings that a fit is absurd (module docstring), and the residuals' structure.

    ``screw`` and ``values`` are the fitted screw and parameters; ``measured``,
    ``fitted`` and ``at_start`` the torques of the points fitted [N·m]
    (``at_start``: the model at the start values).
    """
    notes: list[str] = []
    if ratings is None:
        ratings = Ratings(None, "", static_rating_estimate(screw), "estimated from the geometry")
    for f in plausibility(screw, ratings, axial_load, load_field="measured axial load"):
        if f.error:
            notes.append(f"the fitted {f}: no such screw carries it, so the fit is absurd")
    for name, (p16, p84, source) in TRAINING_SCATTER.items():
        if name not in values:
            continue
        centre, sd = math.sqrt(p16 * p84), math.log(p84 / p16) / 2.0
        z = math.log(values[name] / centre) / sd
        if abs(z) > SCATTER_SIGMAS:
            notes.append(
                f"{name} = {values[name]:.4g} is {abs(z):.1f} log-standard deviations from the "
                f"scatter of its training cases (16th to 84th percentile {p16:g} to {p84:g}, "
                f"{source}); more than {SCATTER_SIGMAS:g} means the model misses something "
                "the constant is made to absorb"
            )
    structure: dict[str, float] = {}
    resid = fitted - measured
    scale = float(np.median(np.abs(measured))) or 1.0
    if resid.size >= 8 and math.sqrt(float(np.mean(resid**2))) > STRUCTURE_FLOOR * scale:
        ordered = resid[np.argsort(speed, kind="stable")]
        runs = runs_test(ordered)
        r1 = lag1_autocorrelation(ordered)
        structure = {"runs": runs.runs, "expected_runs": runs.expected, "z": runs.z,
                     "p_fewer_runs": runs.p_fewer, "lag1_autocorrelation": r1}  # fmt: skip
        if runs.p_fewer < RUNS_P_LIMIT:
            notes.append(
                f"the residuals have structure: ordered by speed their signs form {runs.runs} "
                f"runs where chance gives {runs.expected:.3g} (runs test, p = {runs.p_fewer:.2g} "
                f"< {RUNS_P_LIMIT:g}; lag-1 autocorrelation {r1:.2f}): the model misses the "
                "curve's shape (e.g. a low-speed friction drop), so the intervals understate "
                "the error"
            )
    ratio = float(np.median(np.abs(measured))) / max(float(np.median(np.abs(at_start))), 1e-300)
    if ratio > MAGNITUDE_LIMIT or ratio < 1.0 / MAGNITUDE_LIMIT:
        power = round(math.log10(ratio))
        hint = (
            "; a torque in N*mm under an N*m header is 1000 times too large: check the torque "
            "column's unit"
            if power == 3
            else "; a torque in N*m under an N*mm header is 1000 times too small"
            if power == -3
            else "; check the torque column's unit and the case"
        )
        notes.append(
            f"the measured torques (median {np.median(np.abs(measured)):.4g} N*m) are "
            f"{ratio:.3g} times what the model gives for this screw at the start values "
            f"(median {np.median(np.abs(at_start)):.4g} N*m), about 10^{power}{hint}"
        )
    return notes, structure


def _start_values(
    specs: list[FreeParameter], screw: BallScrew, oil: Lubricant, model: str,
    fixed: dict[str, Any], start: dict[str, float] | None,
) -> dict[str, float]:  # fmt: skip
    """Start values by name: the screw's or the model's, replaced by ``start``'s.

    A start value the user gives outside the parameter's bounds is refused, naming it
    (a defaulted one is brought inside them): moving it to the bound would fit from a
    value nobody typed.
    """
    starts = {s.name: _start(s, screw, oil, model, fixed) for s in specs}
    for key, value in (start or {}).items():
        spec = _spec(key, model)
        value = float(value)
        if not (math.isfinite(value) and spec.low <= value <= spec.high):
            unit = "" if spec.unit == "-" else f" {spec.unit}"
            raise BallScrewInputError(
                f"start {key}", f"{value:g}{unit}",
                f"a start value from {spec.low:g} to {spec.high:g}{unit} ({spec.description})",
            )  # fmt: skip
        starts[key] = value
    return starts


def _columns(
    measured: MeasuredCurve, temperature: float, axial_load: float
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Speed, torque, temperature and axial load at every measured point."""
    speed = np.asarray(measured.speed, dtype=float)
    torque = np.asarray(measured.torque, dtype=float)
    n = speed.size
    temp = (
        np.full(n, float(temperature))
        if measured.temperature is None
        else np.asarray(measured.temperature, dtype=float)
    )
    load = (
        np.full(n, float(axial_load))
        if measured.axial_load is None
        else np.asarray(measured.axial_load, dtype=float)
    )
    return speed, torque, temp, load


def _apply(
    screw: BallScrew, fixed: dict[str, Any], values: dict[str, float]
) -> tuple[BallScrew, dict[str, Any]]:
    """The screw and the model parameters with ``values`` written in."""
    out = screw
    kwargs = dict(fixed)
    for name, value in values.items():
        if FITTABLE[name].where == "screw":
            out = out.replace(**{name: value})
        else:
            kwargs[name] = value
    return out, kwargs


@dataclass
class _Fit:
    """The last solve: the parameters still free, those held, and what the fit gave."""

    active: list[FreeParameter]
    held: dict[str, float]
    theta: FloatArray
    sigma: FloatArray
    corr: FloatArray
    resid: FloatArray
    rows: Index
    outliers: tuple[int, ...]
    notes: list[str]


def _fit_identifiable(
    specs: list[FreeParameter],
    starts: dict[str, float],
    predict: Any,
    torque: FloatArray,
    everything: Index,
) -> _Fit:
    """Solve, holding unidentifiable parameters at their starts one at a time."""
    notes: list[str] = []
    active = list(specs)
    held: dict[str, float] = {}
    theta = np.array([_to_theta(s, starts[s.name]) for s in active])
    for _ in range(len(specs) + 1):
        theta, jac, resid, rows, outliers = _solve(active, theta, held, predict, torque, everything)
        sigma, corr = _covariance(jac, resid, len(active))
        loose = [s for s, sd in zip(active, sigma, strict=True) if _unidentified(s, sd, resid.size)]
        if not loose:
            break
        worst = _least_identified(loose, active, sigma, jac)
        held[worst.name] = starts[worst.name]
        notes.append(
            f"{worst.name} cannot be identified from these data (its 95 % interval spans more "
            f"than {'a factor 100' if worst.log else 'its allowed range'}): held at its start "
            f"value {starts[worst.name]:.4g} {worst.unit}; measure where it matters, or leave it "
            "out of --free"
        )
        keep = [i for i, s in enumerate(active) if s != worst]
        active = [active[i] for i in keep]
        theta = theta[keep]
        if not active:
            sigma, corr = np.zeros(0), np.zeros((0, 0))
            resid = predict(held, rows) - torque[rows]
            break
    return _Fit(active, held, theta, sigma, corr, resid, rows, outliers, notes)


def _least_identified(
    loose: list[FreeParameter], active: list[FreeParameter], sigma: FloatArray, jac: FloatArray
) -> FreeParameter:
    """The parameter to hold: the widest interval relative to the allowed one.

    One at a time, the worst first: a direction the data cannot see often
    leans on a parameter they can, which is identified once the other is held.
    Ties (several unseen) go to the parameter the torque is least sensitive to.
    """
    norms = np.linalg.norm(jac, axis=0)
    width = {
        s.name: (sd / _allowed_sd(s), -norm)
        for s, sd, norm in zip(active, sigma, norms, strict=True)
    }
    return max(loose, key=lambda s: width[s.name])


def _estimates(fit: _Fit, starts: dict[str, float]) -> tuple[dict[str, Estimate], dict[str, float]]:
    """Estimates with their 95 % intervals, and the values of all parameters.

    Appends a note to ``fit.notes`` for every estimate on its bound.
    """
    t_q = _t_quantile(fit.resid.size - len(fit.active))
    estimates: dict[str, Estimate] = {}
    values = dict(fit.held)
    for s, th, sd in zip(fit.active, fit.theta, fit.sigma, strict=True):
        value = _from_theta(s, float(th))
        values[s.name] = value
        low = _from_theta(s, float(th - t_q * sd)) if math.isfinite(sd) else None
        high = _from_theta(s, float(th + t_q * sd)) if math.isfinite(sd) else None
        estimates[s.name] = Estimate(s.name, value, low, high, starts[s.name], s.unit)
        if value in (s.low, s.high) or math.isclose(value, s.low) or math.isclose(value, s.high):
            fit.notes.append(
                f"{s.name} = {value:.4g} {s.unit} sits on its bound [{s.low:g}, {s.high:g}]: "
                "the model cannot reach the data with it; check the case or free another "
                "parameter"
            )
    for name, value in fit.held.items():
        spec = FITTABLE[name]
        estimates[name] = Estimate(name, value, None, None, value, spec.unit, identified=False)
    return estimates, values


def _correlation_notes(active: list[FreeParameter], corr: FloatArray) -> list[str]:
    """A warning for every pair of parameters the data barely separate."""
    notes = []
    for i in range(len(active)):
        for j in range(i + 1, len(active)):
            if abs(corr[i, j]) > CORRELATION_LIMIT:
                notes.append(
                    f"{active[i].name} and {active[j].name} are correlated (rho = "
                    f"{corr[i, j]:+.3f}): the data barely separate them, so each is known less "
                    "well than their combination; measurements at other loads or "
                    "temperatures would separate them"
                )
    return notes


def _data_notes(outliers: tuple[int, ...], dof: int) -> list[str]:
    """Warnings about the data: outliers left out, few degrees of freedom."""
    notes = []
    if outliers:
        notes.append(
            f"{len(outliers)} point(s) more than {OUTLIER_SCALE:g} robust standard deviations "
            f"from the fit left out: rows {', '.join(str(i + 1) for i in outliers)}"
        )
    if 0 < dof < 3:
        notes.append(
            f"only {dof} degree(s) of freedom: the intervals are wide and rest on few points"
        )
    return notes


def _solve(
    active: list[FreeParameter],
    theta0: FloatArray,
    held: dict[str, float],
    predict: Any,
    torque: FloatArray,
    everything: Index,
) -> tuple[FloatArray, FloatArray, FloatArray, Index, tuple[int, ...]]:
    """Fit, find outliers, refit robustly, then fit the inliers by plain least squares."""
    from scipy.optimize import least_squares

    lower = np.array([_to_theta(s, s.low) if s.log else s.low for s in active])
    upper = np.array([_to_theta(s, s.high) if s.log else s.high for s in active])

    def residual(theta: FloatArray, rows: Index) -> FloatArray:
        values = dict(held)
        values.update(
            {s.name: _from_theta(s, float(t)) for s, t in zip(active, theta, strict=True)}
        )
        out: FloatArray = predict(values, rows) - torque[rows]
        return out

    def run(theta: FloatArray, rows: Index, **kw: Any) -> Any:
        return least_squares(
            residual, np.clip(theta, lower, upper), bounds=(lower, upper), args=(rows,),
            x_scale="jac", **kw,
        )  # fmt: skip

    first = run(theta0, everything)
    # A floor on the scale: data the model reproduces to rounding have no outliers.
    floor = 1e-6 * float(np.median(np.abs(torque)))
    scale = max(1.4826 * float(np.median(np.abs(first.fun - np.median(first.fun)))), floor)
    rows = everything
    theta = first.x
    if np.any(np.abs(first.fun) > OUTLIER_SCALE * scale):
        robust = run(first.x, everything, loss="soft_l1", f_scale=scale)
        r = robust.fun
        scale = max(1.4826 * float(np.median(np.abs(r - np.median(r)))), floor)
        bad = np.abs(r) > OUTLIER_SCALE * scale
        # Outliers are a few points; if many points miss, the model misses the
        # data's shape, and dropping them would hide it.
        if 0 < np.count_nonzero(bad) <= MAX_OUTLIER_SHARE * torque.size:
            rows = everything[~bad]
            theta = robust.x
    final = run(theta, rows, jac="3-point")
    outliers = tuple(int(i) for i in np.setdiff1d(everything, rows))
    return final.x, final.jac, final.fun, rows, outliers


def _covariance(jac: FloatArray, resid: FloatArray, p: int) -> tuple[FloatArray, FloatArray]:
    """Standard deviations of the transformed parameters and their correlation matrix."""
    n = resid.size
    s2 = float(resid @ resid) / max(n - p, 1)
    norms = np.linalg.norm(jac, axis=0)
    scaled = jac / np.where(norms > 0.0, norms, 1.0)
    _, sv, vt = np.linalg.svd(scaled, full_matrices=False)
    # Directions the data do not constrain (a column of zeros, or columns that
    # move together): infinite variance for the parameters in them, where a
    # pseudo-inverse would report zero.
    weak = sv <= 1e-7 * max(float(sv[0]), 1e-300)
    inv = (vt[~weak].T / sv[~weak] ** 2) @ vt[~weak]
    unseen = (norms <= 1e-12 * max(float(np.linalg.norm(jac)), 1e-300)) | np.any(
        np.abs(vt[weak]) > 0.1, axis=0
    )
    with np.errstate(divide="ignore", invalid="ignore"):
        sigma = np.sqrt(s2 * np.clip(np.diag(inv), 0.0, None)) / norms
        corr = inv / np.sqrt(np.outer(np.diag(inv), np.diag(inv)))
    sigma = np.where(unseen, math.inf, sigma)
    corr = np.where(np.isfinite(corr), corr, 0.0)
    np.fill_diagonal(corr, 1.0)
    return sigma, corr


def _allowed_sd(spec: FreeParameter) -> float:
    """Largest standard deviation of an identified parameter (transformed space).

    Beyond it the 95 % interval (±1.96 sd) spans more than a factor 100 (log
    parameters) or the whole allowed range (others).
    """
    if spec.log:
        return math.log(100.0) / 2 / 1.96
    return (spec.high - spec.low) / 2 / 1.96


def _unidentified(spec: FreeParameter, sd: float, n: int) -> bool:
    return not math.isfinite(sd) or sd > _allowed_sd(spec)


def _t_quantile(dof: int) -> float:
    from scipy.stats import t

    return float(t.ppf(0.975, max(dof, 1)))


UNRELIABLE_FIT = "UNRELIABLE FIT"
"""The mark a fitted case file carries when its fit was absurd (:attr:`FitResult.reliable`):
in its description, in each fitted screw value's ``assumed`` reason and in its header."""


def fitted_case_toml(case_text: str, result: FitResult, *, note: str = "") -> str:
    """The case file's TOML with the fitted values written in (comments kept).

    The screw's fitted fields replace its own (a fitted preload replaces
    ``preload_share`` or ``preload_drag_torque``); fitted model parameters go
    to ``[study.model_parameters.<model>]`` in SI. Each carries its 95 %
    interval as a comment; parameters the data could not identify are left
    as they were. An unreliable fit (:attr:`FitResult.reliable` False) is
    written as such: a warning in the file's header, the :data:`UNRELIABLE_FIT`
    mark in its description, and each fitted screw value marked ``assumed``
    with the reason, so that ``check`` and ``energy`` repeat it when they read
    the file.
    """
    import tomlkit

    doc = tomlkit.parse(case_text)
    if "title" in doc:
        doc["title"] = f"{doc['title']} (fitted)"
    why = "; ".join(result.warnings) or "the fit is absurd"
    if not result.reliable:
        text = f"{UNRELIABLE_FIT} ({result.model}): {why}"
        old = str(doc.get("description", "")).strip()
        doc["description"] = text + (f" | {old}" if old else "")
    for name, e in result.estimates.items():
        if not e.identified:
            continue
        spec = FITTABLE[name]
        unit = "" if spec.unit == "-" else f" {spec.unit}"
        span = f"95 % interval {e.low:.4g} to {e.high:.4g}{unit}" if e.low is not None else ""
        comment = f"fitted by ballscrew fit ({result.model}); {span}{note}"
        if not result.reliable:
            comment += f"; {UNRELIABLE_FIT}"
        if spec.where == "screw":
            screw = doc["screw"]
            assert isinstance(screw, dict)
            if name == "preload":
                for other in ("preload_share", "preload_drag_torque"):
                    if other in screw:
                        del screw[other]
            item: Any
            if result.reliable:
                item = tomlkit.item(f"{e.value:.6g} {spec.unit}")
            else:
                flagged = tomlkit.inline_table()
                flagged.update({"value": f"{e.value:.6g} {spec.unit}",
                                "assumed": f"{UNRELIABLE_FIT} by ballscrew fit "
                                f"({result.model}): {why}"})  # fmt: skip
                item = flagged
            item.comment(comment)
            screw[name] = item
        else:
            study = doc.setdefault("study", tomlkit.table())
            params = study.setdefault("model_parameters", tomlkit.table())
            table = params.setdefault(result.model, tomlkit.table())
            number = tomlkit.item(float(f"{e.value:.6g}"))
            number.comment(comment)
            table[name] = number
    body = tomlkit.dumps(doc)
    if result.reliable:
        return body
    header = "".join(f"# {line}\n" for line in (
        f"WARNING: {UNRELIABLE_FIT}. This file was written by ballscrew fit from a fit whose "
        "intervals do not hold:", *(f"  {w}" for w in result.warnings),
        "Its fitted values are marked assumed; check and energy repeat this warning."))  # fmt: skip
    return header + body
