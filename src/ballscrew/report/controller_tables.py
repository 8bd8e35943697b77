"""Friction compensation tables in the formats controllers load.

Each file begins with comment lines giving the formula, the units, the sign
convention, the case, the model, the load and temperature, and the table's
interpolation error against the model (:mod:`ballscrew.servo.tables`):

* ``lincurve``: LinuxCNC HAL lines for the ``lincurve`` component (up to 16
  points, ``x-val-NN`` ascending, ``y-val-NN``; the component holds the end
  values beyond the ends and does not extrapolate): input the axis speed in
  mm/s, output the motor torque in N·m, both directions in one table;
  The instance is named after the axis (``names=x-friction``), and a machine's
  axes share one ``loadrt`` line (:func:`merge_lincurve`), since HAL loads a
  component once;
* ``frict-comp``: a TwinCAT CNC (ISG kernel) axis compensation list: the
  ``kopf.*`` header, ``frict_comp.mode 3`` (additive current from the
  commanded speed), ``scaling_factor 1000`` (100 %), ``table[i].in`` in µm/s
  ascending from 0 and ``.out`` in the unit the drive reports its torque in
  (:func:`frict_comp_text` cites each field); the controller applies the sign
  of the motion;
* ``charcurve``: a CODESYS function block in Structured Text around the Util
  library's ``CHARCURVE``: ``ARRAY[0..10] OF POINT`` with INT coordinates,
  scaled by powers of ten that the header states, the speed clamped to the
  points (the block reports an input outside them as an error).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..servo.tables import CONTROLLERS, ControllerTable

__all__ = [
    "DECIMAL_BUILDS", "TABLE_WRITERS", "FileOptions", "build_number", "charcurve_text",
    "frict_comp_text", "lincurve_text", "merge_lincurve", "takes_decimals",
]  # fmt: skip

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


@dataclass(frozen=True)
class FileOptions:
    """What a controller file needs besides the table: the axis it is for, and the CNC build.

    ``axis`` names the axis (LinuxCNC: the ``lincurve`` instance ``<axis>-friction``;
    TwinCAT: ``kopf.log_achs_name``; CODESYS: the variables' suffix); ``axis_number``
    is TwinCAT's logical axis number ``kopf.achs_nr``; ``cnc_build`` a TwinCAT CNC
    build such as "V3.1.3132.0" (from it on, the table takes decimals).
    """

    axis: str | None = None
    axis_number: int | None = None
    cnc_build: str | None = None

    def __post_init__(self) -> None:
        if self.axis is not None and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,15}", self.axis):
            raise BallScrewInputError(
                "--axis", self.axis,
                "an axis name of 1 to 16 letters, digits or '_', starting with a letter, e.g. 'X'",
            )  # fmt: skip
        if self.axis_number is not None and not 0 < self.axis_number < 65535:
            # P-COMP-00001 kopf.achs_nr: UNS16, 0 < achs_nr < MAX(UNS16)
            raise BallScrewInputError("--axis-number", self.axis_number,
                                      "the logical axis number, 1 to 65534")  # fmt: skip
        if self.cnc_build is not None:
            build_number(self.cnc_build)

    @property
    def instance(self) -> str:
        """The ``lincurve`` instance: ``<axis>-friction`` (lower case), or ``friction``."""
        return f"{self.axis.lower()}-friction" if self.axis else "friction"


DECIMAL_BUILDS = ((3, 1, 3132, 0), (4, 29, 0))
"""TwinCAT CNC builds from which ``frict_comp.table[i].in`` and ``.out`` are REAL64
(P-COMP-00046, P-COMP-00047: "As of V3.1.3132.0 and/or V4.29.0"); SGN32 before."""


def build_number(text: str) -> tuple[int, ...]:
    """A CNC build "V3.1.3132.0" as numbers (3, 1, 3132, 0)."""
    m = re.fullmatch(r"\s*[Vv]?(\d+(?:\.\d+){1,3})\s*", str(text))
    if m is None:
        raise BallScrewInputError("--cnc-build", text, "a TwinCAT CNC build such as "
                                  "'V3.1.3132.0' or 'V4.29.0'")  # fmt: skip
    return tuple(int(v) for v in m.group(1).split("."))


def takes_decimals(build: str | None) -> bool:
    """Whether the CNC build reads decimals in the friction table (:data:`DECIMAL_BUILDS`)."""
    if build is None:
        return False
    b = build_number(build)
    if b[0] >= 4:
        return b >= DECIMAL_BUILDS[1]
    return b >= DECIMAL_BUILDS[0]


LINCURVE_MARK = "# === lincurve "
"""The line that opens one axis' block in a HAL file, followed by the instance name."""


def lincurve_text(t: ControllerTable, version: str, options: FileOptions | None = None) -> str:
    """LinuxCNC HAL lines for the ``lincurve`` instance of the axis (:class:`FileOptions`).

    The file loads its instances by name in one ``loadrt`` line (lincurve(9):
    ``loadrt lincurve names=a,b personality=16,16``); HAL loads a component
    once, so the axes of a machine share that line: :func:`merge_lincurve`
    adds an axis to a file.
    """
    opts = options or FileOptions()
    name = opts.instance
    x = t.table.speed * 1e3
    y = t.motor_torque()
    units = "x-val: axis speed [mm/s]; y-val: motor torque [N*m] (scale it to your amplifier)"
    head = _header(t, version, "#", units, _errors(t, t.motor_torque, "N*m"))
    lines = [f"{LINCURVE_MARK}{name} (axis {opts.axis or 'unnamed'}) ===", *head,
             f"addf {name} servo-thread"]  # fmt: skip
    lines += [f"setp {name}.x-val-{k:02d} {v:.9g}" for k, v in enumerate(x)]
    lines += [f"setp {name}.y-val-{k:02d} {v:.9g}" for k, v in enumerate(y)]
    lines += ["# for example:",
              f"#   net {name}-vel joint.N.vel-cmd => {name}.in",
              f"#   net {name}-out {name}.out => (a sum into the torque command)"]  # fmt: skip
    return _lincurve_file(version, {name: (x.size, lines)})


def _lincurve_file(version: str, blocks: dict[str, tuple[int, list[str]]]) -> str:
    """The HAL file of the instances ``blocks`` (name -> points, lines), one ``loadrt``."""
    names = ",".join(blocks)
    personality = ",".join(str(n) for n, _ in blocks.values())
    out = [f"# ballscrew {version}: friction compensation tables for LinuxCNC's lincurve, "
           f"{len(blocks)} {'axes' if len(blocks) > 1 else 'axis'}",
           "# HAL loads a component once: this line loads every axis' instance; add an axis "
           "with 'ballscrew export-friction --form lincurve --axis Y --append --out THIS_FILE'",
           "# (if your configuration loads lincurve already, merge these names into its line)",
           f"loadrt lincurve names={names} personality={personality}"]  # fmt: skip
    for _, lines in blocks.values():
        out += lines
    return "\n".join(out) + "\n"


def _lincurve_blocks(text: str, where: str) -> dict[str, tuple[int, list[str]]]:
    """The instance blocks of a HAL file that :func:`lincurve_text` wrote."""
    blocks: dict[str, tuple[int, list[str]]] = {}
    current: list[str] | None = None
    for line in text.splitlines():
        if line.startswith(LINCURVE_MARK):
            name = line[len(LINCURVE_MARK) :].split()[0]
            current = [line]
            blocks[name] = (0, current)
        elif current is not None:
            current.append(line)
    if not blocks:
        raise BallScrewInputError("--append", where, "a HAL file that 'ballscrew export-"
                                  "friction --form lincurve' wrote (none of its axis blocks "
                                  f"'{LINCURVE_MARK.strip()} NAME' found)")  # fmt: skip
    return {name: (sum(1 for ln in lines if re.match(rf"setp {re.escape(name)}\.x-val-", ln)),
                   lines) for name, (_, lines) in blocks.items()}  # fmt: skip


def merge_lincurve(existing: str, new: str, version: str, where: str = "the file") -> str:
    """``existing`` HAL text with the axes of ``new`` added (an axis of the same name replaced).

    Both as :func:`lincurve_text` writes them; one ``loadrt`` line loads all.
    """
    blocks = _lincurve_blocks(existing, where)
    blocks.update(_lincurve_blocks(new, "the new table"))
    return _lincurve_file(version, blocks)


def frict_comp_text(t: ControllerTable, version: str, options: FileOptions | None = None) -> str:
    """A TwinCAT CNC axis compensation list: the ``kopf.*`` header and ``frict_comp.*``.

    Beckhoff TF5200 (TwinCAT 3 CNC), axis compensation, friction compensation:

    * ``kopf.achs_nr`` (P-COMP-00001): the logical axis number, UNS16, 0 not allowed;
    * ``kopf.log_achs_name`` (P-COMP-00002): the axis name, at most 16 characters;
    * ``frict_comp.mode`` 3 (P-COMP-00041): an additive current from the commanded speed;
    * ``frict_comp.table_entries`` (P-COMP-00042): at most 20 by default;
    * ``frict_comp.scaling_factor`` (P-COMP-00045): in 0.1 %, 1000 = 100 %;
    * ``frict_comp.table[i].in`` (P-COMP-00046): speed in µm/s, ascending, >= 0;
    * ``frict_comp.table[i].out`` (P-COMP-00047): in the unit of the drive's
      ``dig_drv.act_torque``, stated by the user (:class:`~ballscrew.servo.tables.DriveUnit`);

    ``in`` and ``out`` are SGN32 integers before CNC build V3.1.3132.0 (V4.29.0),
    REAL64 from it on (:func:`takes_decimals`).
    """
    opts = options or FileOptions()
    if opts.axis_number is None:
        raise BallScrewInputError(
            "--axis-number", None, "the axis' logical axis number for kopf.achs_nr (P-COMP-"
            "00001; the CNC refuses a list whose number differs from the start-up list's)",
        )  # fmt: skip
    unit = t.drive_unit
    if unit is None:
        raise BallScrewInputError("--drive-unit", None, "the unit of the drive's torque")
    decimals = takes_decimals(opts.cnc_build)
    x = t.table.speed * 1e6
    out = t.drive_values()
    if not decimals:
        x = np.asarray(_ascending(x), dtype=float)
        out = np.round(out)
    if np.max(np.abs(out)) >= 2**31 - 1 or np.max(x) >= 2**31 - 1:
        raise BallScrewInputError("--drive-unit", unit.text, "a unit in which the table's "
                                  "values fit a 32-bit integer")  # fmt: skip
    per = unit.value if unit.kind == "torque" else unit.value * (t.torque_constant or 1.0)
    what = "motor torque" if unit.kind == "torque" else "motor current"
    kt = f", K_t = {t.torque_constant:g} N*m/A" if unit.kind == "current" else ""
    fmt = "{:.6g}" if decimals else "{:.0f}"
    head = _header(t, version, "#", f"in: commanded axis speed [um/s], ascending from 0; out: "
                   f"{what} in the drive's unit of act_torque, 1 = {unit.text}{kt} "
                   f"(= {per:.6g} N*m of motor torque)",
                   _errors(t, lambda f: t.drive_values(f), "units"))  # fmt: skip
    rounding = float(np.max(np.abs(out - t.drive_values())))
    form = (f"decimals (REAL64, CNC build {opts.cnc_build})" if decimals else "integers (SGN32, "
            "as CNC builds before V3.1.3132.0 read them; --cnc-build for decimals)")  # fmt: skip
    lines = [*head,
             f"# written as {form}; largest rounding at the points {rounding:.3g} units",
             "# activate with lr_param.frict_comp 1 in the axis parameters (P-AXIS-00522)",
             f"kopf.achs_nr                    {opts.axis_number}"]  # fmt: skip
    if opts.axis:
        lines.append(f"kopf.log_achs_name              {opts.axis}")
    lines += ["frict_comp.mode                 3",
              f"frict_comp.table_entries        {x.size}",
              "frict_comp.scaling_factor       1000"]  # fmt: skip
    for k, (a, b) in enumerate(zip(x, out, strict=True)):
        lines.append(f"frict_comp.table[{k}].in{'':<{10 - len(str(k))}}{fmt.format(a)}")
        lines.append(f"frict_comp.table[{k}].out{'':<{9 - len(str(k))}}{fmt.format(b)}")
    return "\n".join(lines) + "\n"


def _ascending(values: FloatArray) -> list[int]:
    """Rounded to integers and kept strictly ascending from the first (a nudge of one unit)."""
    out = [round(float(v)) for v in values]
    for j in range(1, len(out)):
        out[j] = max(out[j], out[j - 1] + 1)
    return out


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


def charcurve_text(t: ControllerTable, version: str, options: FileOptions | None = None) -> str:
    """A CODESYS function block (Structured Text) around the Util library's ``CHARCURVE``.

    ``FB_Friction<axis>``: input ``Speed`` and output ``Torque`` (INT, in the
    scaled units the header states), ``Error`` the block's ``ERR``; the speed is
    clamped to the points' range first, since ``CHARCURVE`` reports an input
    outside them as an error (its ``IN``, ``N``, ``P``, ``OUT`` and ``ERR`` as the
    CODESYS Util documentation gives them).
    """
    suffix = (options or FileOptions()).axis or ""
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
    comment = [line[3:].replace("(*", "( *").replace("*)", "* )") for line in head]
    lines = ["(*", *comment, "*)", f"FUNCTION_BLOCK FB_Friction{suffix}",
             "VAR_INPUT", f"    Speed : INT; (* axis speed [{unit_x}] *)", "END_VAR",
             "VAR_OUTPUT", f"    Torque : INT; (* motor torque [{unit_y}] *)",
             "    Error : BYTE; (* CHARCURVE.ERR: 0 no error *)", "END_VAR",
             "VAR", "    FrictionCurve : CHARCURVE;",
             f"    FrictionPoints : ARRAY[0..10] OF POINT := [{points}];", "END_VAR",
             f"FrictionCurve(IN := LIMIT({xs[0]}, Speed, {xs[-1]}), N := {len(xs)}, "
             "P := FrictionPoints);",
             "Torque := FrictionCurve.OUT;", "Error := FrictionCurve.ERR;",
             "END_FUNCTION_BLOCK"]  # fmt: skip
    return "\n".join(lines) + "\n"


TABLE_WRITERS: dict[str, Callable[[ControllerTable, str, FileOptions | None], str]] = {
    "lincurve": lincurve_text, "frict-comp": frict_comp_text, "charcurve": charcurve_text,
}  # fmt: skip
"""Controller -> writer of its file's text."""
