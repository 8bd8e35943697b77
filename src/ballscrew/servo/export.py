"""Friction for a servo drive, fitted to a model's torque-speed curve.

What ``ballscrew export-friction`` computes.

:func:`export_friction` evaluates a model over a speed range in both
directions at each temperature, and either fits a friction form to it
(:func:`ballscrew.servo.controller.fit_form`) or keeps the curve as a lookup
table; :meth:`FrictionExport.as_dict` is the command's JSON document and
:attr:`FrictionExport.rows` its CSV.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..axis.energy import Axis
from ..axis.setup import axis_setup
from ..chain import friction_torque
from ..errors import BallScrewInputError, FloatArray
from ..friction import get_model
from ..io.case import Case
from ..io.measured import MeasuredCurve
from ..io.units import Reading, parse_speed_range
from ..kinematics import rad_s_to_rpm
from ..materials import STANDARD_GRAVITY
from .controller import FrictionForm, fit_form, form_curve, with_intervals
from .friction_map import FrictionMap, friction_map

__all__ = [
    "FrictionExport", "axis_inertia", "export_friction", "log_speeds", "run_export_friction",
]  # fmt: skip


def log_speeds(
    text: str, lead: float | None = None, notes: list[Reading] | None = None
) -> FloatArray:
    """Positive screw speeds [rad/s]; a range 'a..b:n unit' is spaced logarithmically.

    With the screw's ``lead`` [m], feeds are taken too, as the screw speeds they need
    (:func:`ballscrew.io.units.parse_speed_range`), the reading told in ``notes``.
    """
    values = np.asarray(parse_speed_range("--speed", text, lead, notes=notes), dtype=float)
    example = "e.g. '0.1..3000:60 rpm'" + (" or '0.1..30 m/min:60'" if lead else "")
    low = int(np.sum(values <= 0.0))
    if low:
        raise BallScrewInputError(
            "--speed", text,
            f"speeds above 0 only ({low} of the {values.size} given "
            f"{'is' if low == 1 else 'are'} 0 or below): the curve is fitted on a "
            f"logarithmic speed scale and taken both ways of turning, so start a range "
            f"above 0, {example}",
        )  # fmt: skip
    if values.size < 3:
        raise BallScrewInputError(
            "--speed", text, f"3 or more speeds to fit a curve to ({values.size} given), {example}"
        )
    if ".." in text:
        values = np.geomspace(values.min(), values.max(), values.size)
    result: FloatArray = np.unique(values)
    return result


def axis_inertia(axis: Axis, lead: float) -> float:
    """Inertia at the screw [kg·m²]: screw, coupling, motor through the gear, and the table."""
    return float(axis.screw_inertia + axis.coupling_inertia
                 + axis.motor_inertia * axis.gear_ratio**2
                 + axis.moving_mass * (lead / (2 * math.pi)) ** 2)  # fmt: skip


@dataclass
class FrictionExport:
    """The curve (or fitted form) of one model at each temperature."""

    case: Case
    model: str
    form: str
    temperatures: list[float]
    speeds: FloatArray
    axial_load: float
    fitted: list[tuple[float, FrictionForm]] = field(default_factory=list)
    rows: list[dict[str, Any]] = field(default_factory=list)
    gear_ratio: float = 1.0
    notes: list[str] = field(default_factory=list)
    measured: str | None = None

    @property
    def lead(self) -> float:
        """The screw's lead [m]."""
        return self.case.screw.lead

    def as_dict(self) -> dict[str, Any]:
        """The JSON of ``ballscrew export-friction --json`` (the writer adds the version)."""
        payload: dict[str, Any] = {"case": self.case.title,
                                   "model": self.model, "form": self.form,
                                   "lead_m": self.lead, "notes": list(self.notes)}  # fmt: skip
        if self.measured is not None:
            payload["fitted_to"] = self.measured
        if self.form == "table":
            payload["table"] = self.rows
            return payload
        fits = [{"temperature_C": t, "axial_load_N": self.axial_load,
                 **f.as_drive_dict(self.lead, self.gear_ratio)}
                for t, f in self.fitted]  # fmt: skip
        payload["fits"] = fits
        payload |= {k: v for k, v in fits[0].items() if k in ("parameters", "rms_error_Nm")}
        return payload


def export_friction(
    case: Case,
    model: str,
    form: str,
    *,
    temperatures: Sequence[float] | None = None,
    speeds: FloatArray,
    axial_load: float | None = None,
    inertia: float | None = None,
    bristle_stiffness: float | None = None,
    bristle_damping: float | None = None,
    measured: MeasuredCurve | None = None,
) -> FrictionExport:
    """A model's curve over ``speeds`` both ways at each temperature, fitted to ``form``.

    With ``measured``, the form is fitted to the measured curve instead, with
    95 % intervals (:func:`with_intervals`). Motor-side parameters follow
    ``[axis] gear_ratio``; an inclined axis' weight joins the axial load (noted).

    Parameters
    ----------
    case : Case
        Screw, lubricant, model parameters, ``[axis]`` (for LuGre's inertia).
    model : str
        Friction model.
    form : {"coulomb-viscous", "stribeck", "lugre", "table"}
        The form, or the table itself.
    temperatures : sequence of float, optional
        [°C]; default the case's first.
    speeds : array_like
        Positive screw speeds [rad/s]; mirrored to negative ones.
    axial_load : float, optional
        [N]; default the case's first.
    inertia, bristle_stiffness, bristle_damping : float, optional
        LuGre's inputs (default: from the case's axis and the nut's stiffness).
    measured : MeasuredCurve, optional
        A measured curve to fit instead of the model's.
    """
    name = get_model(model).name
    temps = list(temperatures) if temperatures is not None else [float(case.temperature.flat[0])]
    load = float(case.axial_load.flat[0]) if axial_load is None else axial_load
    lead = case.screw.lead
    axis = axis_setup(case.screw, case.axis, case.thermal, 0.0).axis
    j = inertia if inertia else axis_inertia(axis, lead)
    notes = []
    weight = axis.moving_mass * STANDARD_GRAVITY * math.sin(axis.incline)
    if weight and measured is None:
        load += weight
        notes.append(f"the axis is inclined: the weight's component along the screw, "
                     f"{weight:.4g} N, is added to the axial load ({load:.4g} N)")  # fmt: skip
    w = np.concatenate([-speeds[::-1], speeds])
    params = case.parameters_for(name)
    out = FrictionExport(case, name, form, temps, speeds, load, gear_ratio=axis.gear_ratio,
                         notes=notes)  # fmt: skip
    lugre: dict[str, Any] = {"screw": case.screw, "inertia": j or None,
                             "bristle_stiffness": bristle_stiffness,
                             "bristle_damping": bristle_damping}  # fmt: skip
    if measured is not None:
        return _fit_measured(out, measured, lugre)
    for temp in temps:
        with warnings.catch_warnings():  # validity warnings are the torque command's business
            warnings.simplefilter("ignore")
            torque = friction_torque(case.screw, case.lubricant, speed=w, temperature=temp,
                                     axial_load=load, model=name, **params).total  # fmt: skip
        signed = np.sign(w) * torque
        if form == "table":
            out.rows += _table_rows(w, signed, temp, lead)
            continue
        fitted = fit_form(form, w, signed, **lugre)
        out.fitted.append((temp, fitted))
        curve = form_curve("stribeck" if form == "lugre" else form, w, fitted.parameters)
        out.rows += [
            {"speed [rpm]": float(rad_s_to_rpm(v)), "temperature [degC]": temp,
             f"torque {name} [N*m]": float(a), f"torque {form} [N*m]": float(b)}
            for v, a, b in zip(w, signed, curve, strict=True)
        ]  # fmt: skip
    return out


def _table_rows(
    w: FloatArray, signed: FloatArray, temp: float, lead: float
) -> list[dict[str, Any]]:
    """The lookup table's rows at one temperature: screw side and table side."""
    return [
        {"speed [rad/s]": float(v), "speed [rpm]": float(rad_s_to_rpm(v)),
         "temperature [degC]": temp, "torque [N*m]": float(tq),
         "table speed [m/s]": float(v * lead / (2 * math.pi)),
         "force [N]": float(tq * 2 * math.pi / lead)}
        for v, tq in zip(w, signed, strict=True)
    ]  # fmt: skip


def _fit_measured(
    out: FrictionExport, measured: MeasuredCurve, lugre: dict[str, Any]
) -> FrictionExport:
    """Fit ``out.form`` to a measured curve, with intervals; rows of measured and fitted torque.

    A curve measured at several temperatures (the file's temperature column) is fitted at
    each of them, as the model's curves are: pooled, the oil's change with temperature would
    be read as a change with speed. A reading whose residual is past
    :data:`OUTLIER_SCALE` robust standard deviations is named in a note (kept in the fit).
    """
    if out.form == "table":
        raise BallScrewInputError("--form", "table", "a fitted form with --measured (the "
                                  "measured curve is its own table)")  # fmt: skip
    w_all = np.asarray(measured.speed, dtype=float)
    temps = (np.asarray(measured.temperature, dtype=float) if measured.temperature is not None
             else np.full(w_all.shape, out.temperatures[0]))  # fmt: skip
    out.temperatures, out.speeds, out.measured = [], np.unique(np.abs(w_all)), measured.source
    for temp in np.unique(temps):
        rows = np.flatnonzero(temps == temp)
        w = w_all[rows]
        signed = np.sign(w) * np.asarray(measured.torque, dtype=float)[rows]
        if np.unique(np.abs(w)).size < 4:
            raise BallScrewInputError(
                "--measured", measured.source,
                f"at least 4 speeds at each temperature to fit a {out.form} curve "
                f"({np.unique(np.abs(w)).size} at {temp:g} degC)",
            )  # fmt: skip
        fitted = with_intervals(fit_form(out.form, w, signed, **lugre), w, signed)
        out.temperatures.append(float(temp))
        out.fitted.append((float(temp), fitted))
        curve = form_curve("stribeck" if out.form == "lugre" else out.form, w,
                           fitted.parameters)  # fmt: skip
        out.rows += [
            {"speed [rpm]": float(rad_s_to_rpm(v)), "temperature [degC]": float(temp),
             "torque measured [N*m]": float(a), f"torque {out.form} [N*m]": float(b)}
            for v, a, b in zip(w, signed, curve, strict=True)
        ]  # fmt: skip
        # With few readings beyond the form's parameters the residuals say little of one
        # reading: a form fits n <= p + 3 points too closely for a robust scale.
        enough = rows.size >= len(fitted.parameters) + 4
        far = ([int(rows[i]) + 1 for i in _doubtful(out.form, w, signed, lugre,
                                                     len(fitted.parameters))]
               if enough else [])  # fmt: skip
        if not enough:
            out.notes.append(
                f"at {temp:g} degC, {rows.size} readings for {len(fitted.parameters)} "
                "parameters: too few to tell a doubtful reading from the curve"
            )
        if far:
            out.notes.append(
                f"at {temp:g} degC, data row(s) {', '.join(map(str, far))} lie more than "
                f"{OUTLIER_SCALE:g} robust standard deviations off the fitted curve: check "
                "them (they are kept in the fit)"
            )
    if len(out.temperatures) > 1:
        out.notes.append(
            f"the measured curve has {len(out.temperatures)} temperatures: one fit at each"
        )
    if not (np.any(w_all > 0.0) and np.any(w_all < 0.0)):  # a reading at rest turns neither way
        out.notes.append("the measured curve turns one way: the form is taken as odd in the "
                         "speed (the same friction both ways)")  # fmt: skip
    return out


OUTLIER_SCALE = 4.0
"""Robust standard deviations (1.4826 times the median absolute deviation) past which a
measured reading is named as doubtful."""


def _doubtful(
    form: str, w: FloatArray, signed: FloatArray, lugre: dict[str, Any], parameters: int
) -> list[int]:
    """Indices of the readings far off the curve the others give, most doubtful first.

    The reading farthest off the current fit is fitted without: it is doubtful when its
    residual from that fit passes :data:`OUTLIER_SCALE` robust standard deviations of the
    others' residuals (so that one bad reading cannot hide itself by pulling the curve,
    nor make the good ones look bad). Repeated while at least ``parameters`` + 3 readings
    remain, for at most a fifth of them.
    """
    curve_form = "stribeck" if form == "lugre" else form
    keep = np.ones(w.size, dtype=bool)
    floor = 1e-9 * float(np.max(np.abs(signed)))
    far: list[int] = []
    while len(far) < max(1, w.size // 5) and keep.sum() - 1 >= parameters + 3:
        fit = fit_form(form, w[keep], signed[keep], **lugre)
        resid = np.where(keep, signed - form_curve(curve_form, w, fit.parameters), 0.0)
        worst = int(np.argmax(np.abs(resid)))
        rest = keep.copy()
        rest[worst] = False
        refit = fit_form(form, w[rest], signed[rest], **lugre)
        others = signed[rest] - form_curve(curve_form, w[rest], refit.parameters)
        scale = max(1.4826 * float(np.median(np.abs(others - np.median(others)))), floor)
        off = abs(float(signed[worst] - form_curve(curve_form, w[worst:worst + 1],
                                                   refit.parameters)[0]))  # fmt: skip
        if off <= OUTLIER_SCALE * scale:
            break
        far.append(worst)
        keep = rest
    return far


def run_export_friction(
    case: Case,
    model: str,
    form: str,
    *,
    speeds: FloatArray,
    temperatures: Sequence[float] | None = None,
    axial_load: float | None = None,
    loads: Sequence[float] | None = None,
    inertia: float | None = None,
    bristle_stiffness: float | None = None,
    bristle_damping: float | None = None,
    measured: MeasuredCurve | None = None,
) -> FrictionExport | FrictionMap:
    """``ballscrew export-friction``: a fitted form (:func:`export_friction`) or a load map.

    For ``form="load-map"`` the map over ``speeds``, the signed ``loads`` [N]
    (default: the case's loads, mirrored, and 0) and ``temperatures`` [°C]
    (default: the case's first), with its compact form
    (:func:`ballscrew.servo.friction_map.friction_map`).
    """
    if form != "load-map":
        return export_friction(
            case, model, form, temperatures=temperatures, speeds=speeds, axial_load=axial_load,
            inertia=inertia, bristle_stiffness=bristle_stiffness,
            bristle_damping=bristle_damping, measured=measured,
        )  # fmt: skip
    if loads is None:
        given = np.abs(np.ravel(case.axial_load))
        grid = np.unique(np.concatenate([-given, [0.0], given]))
    else:
        grid = np.asarray(loads, dtype=float)
    temps = np.ravel(case.temperature)[:1] if temperatures is None else temperatures
    return friction_map(case, model, speeds=speeds, loads=grid, temperatures=temps)
