"""Friction compensation tables in the formats controllers load.

Each file begins with comment lines giving the formula, the units, the sign
convention, the case, the model, the load and temperature, and the table's
interpolation error against the model (:mod:`ballscrew.servo.tables`):

* ``lincurve``: LinuxCNC HAL lines for the ``lincurve`` component (up to 16
  points, ``x-val-NN`` ascending, ``y-val-NN``; the component holds the end
  values beyond the ends and does not extrapolate): input the axis speed in
  mm/s, output the motor torque in N·m, both directions in one table;
* ``frict-comp``: a TwinCAT CNC (ISG kernel) axis compensation list,
  ``frict_comp.mode 3`` (additive current from the commanded speed),
  ``frict_comp.table_entries``, ``frict_comp.table[i].in`` in µm/s ascending
  from 0 and ``.out`` the motor current in mA (I = T/K_t); the controller
  applies the sign of the motion;
* ``charcurve``: CODESYS Structured Text for the Util library's
  ``CHARCURVE``: ``ARRAY[0..10] OF POINT`` with INT coordinates, scaled by
  powers of ten that the header states (the block reports an error for an
  input outside the points, so clamp the speed first).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..errors import FloatArray
from ..servo.tables import CONTROLLERS, ControllerTable

__all__ = ["TABLE_WRITERS", "charcurve_text", "frict_comp_text", "lincurve_text"]

INT_LIMIT = 30000
"""Largest magnitude written into a 16-bit INT (32767) with a margin."""


def _header(t: ControllerTable, version: str, prefix: str, output: str, error: str) -> list[str]:
    tab = t.table
    current = f"; motor current I = T / K_t, K_t = {t.torque_constant:g} N*m/A" if (
        t.torque_constant) else ""  # fmt: skip
    return [
        f"{prefix} ballscrew {version}: friction compensation for {CONTROLLERS[t.target][3]}",
        f"{prefix} case '{t.case_title}', model {t.model}, axial load {t.axial_load:.6g} N, "
        f"temperature {t.temperature:g} degC",
        f"{prefix} formula: friction force F(v) of the screw at table speed v, piecewise linear "
        "through the points below;",
        f"{prefix}   motor torque T = F l / (2 pi i), lead l = {t.lead * 1e3:g} mm, gear ratio "
        f"i = {t.gear_ratio:g} (motor turns per screw turn)" + current,
        f"{prefix} units: {output}",
        f"{prefix} sign: v > 0 moves the table towards +x; the value is what the motor adds to "
        "overcome friction, signed like the speed (feed it forward at the commanded speed)",
        f"{prefix} breakpoints chosen to minimise the RMS interpolation error over "
        f"+-{tab.speed_range * 1e3:g} mm/s: {error}; beyond the last point the value is held",
        f"{prefix} guideway friction, seals and support bearings are not included",
    ]


def _errors(t: ControllerTable, scale: Callable[[FloatArray], FloatArray], unit: str) -> str:
    tab = t.table
    rms = float(scale(np.array([tab.rms_error]))[0])
    mx = float(scale(np.array([tab.max_error]))[0])
    return (f"RMS {tab.rms_error:.3g} N ({rms:.3g} {unit}), largest {tab.max_error:.3g} N "
            f"({mx:.3g} {unit})")  # fmt: skip


def lincurve_text(t: ControllerTable, version: str, index: int = 0) -> str:
    """LinuxCNC HAL lines for ``lincurve.INDEX``."""
    name = f"lincurve.{index}"
    x = t.table.speed * 1e3
    y = t.motor_torque()
    units = "x-val: axis speed [mm/s]; y-val: motor torque [N*m] (scale it to your amplifier)"
    lines = _header(t, version, "#", units, _errors(t, t.motor_torque, "N*m"))
    lines += [f"loadrt lincurve count={index + 1} personality={x.size}",
              f"addf {name} servo-thread"]  # fmt: skip
    lines += [f"setp {name}.x-val-{k:02d} {v:.9g}" for k, v in enumerate(x)]
    lines += [f"setp {name}.y-val-{k:02d} {v:.9g}" for k, v in enumerate(y)]
    lines += ["# for example:",
              f"#   net x-vel-cmd joint.0.vel-cmd => {name}.in",
              f"#   net x-friction {name}.out => (a sum into the torque command)"]  # fmt: skip
    return "\n".join(lines) + "\n"


def frict_comp_text(t: ControllerTable, version: str) -> str:
    """A TwinCAT CNC axis compensation list (``frict_comp.*``)."""
    x = t.table.speed * 1e6
    out = t.motor_current() * 1e3
    lines = _header(t, version, "#", "in: commanded speed [um/s], ascending from 0; out: motor "
                    "current [mA] (match the drive's act_torque unit with scaling_factor)",
                    _errors(t, lambda f: t.motor_current(f) * 1e3, "mA"))  # fmt: skip
    lines += ["# activate with lr_param.frict_comp 1 in the axis parameters (P-AXIS-00522)",
              "frict_comp.mode                 3",
              f"frict_comp.table_entries        {x.size}",
              "frict_comp.scaling_factor       1"]  # fmt: skip
    for k, (a, b) in enumerate(zip(x, out, strict=True)):
        lines.append(f"frict_comp.table[{k}].in{'':<{10 - len(str(k))}}{a:.3f}")
        lines.append(f"frict_comp.table[{k}].out{'':<{9 - len(str(k))}}{b:.3f}")
    return "\n".join(lines) + "\n"


def _power_of_ten(largest: float) -> int:
    """The largest k with ``largest * 10**k <= INT_LIMIT``."""
    k = 0
    while largest * 10.0 ** (k + 1) <= INT_LIMIT and k < 9:
        k += 1
    while largest * 10.0**k > INT_LIMIT and k > -9:
        k -= 1
    return k


def _strict(values: FloatArray) -> list[int]:
    """Rounded to integers and kept strictly ascending (a nudge of one unit where needed)."""
    out = [round(float(v)) for v in values]
    middle = len(out) // 2
    for j in range(middle + 1, len(out)):
        out[j] = max(out[j], out[j - 1] + 1)
    for j in range(middle - 1, -1, -1):
        out[j] = min(out[j], out[j + 1] - 1)
    return out


def charcurve_text(t: ControllerTable, version: str) -> str:
    """CODESYS Structured Text declaring the points of a ``CHARCURVE``."""
    mm_s = t.table.speed * 1e3
    nmm = t.motor_torque() * 1e3
    kx = _power_of_ten(float(np.max(np.abs(mm_s))))
    ky = _power_of_ten(float(np.max(np.abs(nmm))))
    xs = _strict(mm_s * 10.0**kx)
    ys = [round(float(v)) for v in nmm * 10.0**ky]
    unit_x = f"1e{-kx} mm/s" if kx else "mm/s"
    unit_y = f"1e{-ky} mN*m" if ky else "mN*m"
    head = _header(t, version, "//", f"X: axis speed [{unit_x}]; Y: motor torque [{unit_y}] "
                   "(INT)", _errors(t, lambda f: t.motor_torque(f) * 1e3, "mN*m"))  # fmt: skip
    points = ", ".join(f"(X:={a}, Y:={b})" for a, b in zip(xs, ys, strict=True))
    lines = ["(*", *(line[3:] for line in head), "*)", "VAR",
             "    FrictionCurve : CHARCURVE;",
             f"    FrictionPoints : ARRAY[0..10] OF POINT := [{points}];", "END_VAR",
             "(* clamp the speed to the points' range, then:",
             f"   FrictionCurve(IN := speed, N := {len(xs)}, P := FrictionPoints);",
             "   torque := FrictionCurve.OUT; *)"]  # fmt: skip
    return "\n".join(lines) + "\n"


TABLE_WRITERS: dict[str, Callable[[ControllerTable, str], str]] = {
    "lincurve": lincurve_text, "frict-comp": frict_comp_text, "charcurve": charcurve_text,
}  # fmt: skip
"""Controller -> writer of its file's text."""
