"""A friction map in the files that drives and simulators read.

Each file states its formula, its axes, units and sign conventions in a header
(:mod:`ballscrew.servo.friction_map` defines them):

* ``.csv``: one row per grid point, table side (m/s, N) and motor side
  (rad/s, N·m), after ``#`` comment lines (``numpy.loadtxt`` and pandas'
  ``comment="#"`` skip them);
* ``.mat``: a MATLAB file (written by :func:`scipy.io.savemat`) with the
  breakpoint vectors and the tables indexed ``[speed, load, temperature]``,
  the order of a Simulink n-D Lookup Table's breakpoints;
* ``.mo``: a Modelica package with a record of the compact form's parameters
  and, per temperature, a matrix laid out for ``Modelica.Blocks.Tables.CombiTable2Ds``
  (first row the loads, first column the motor speeds);
* ``.h``: a C header with the axes and the table as constant arrays and a
  trilinear interpolation function, clamped at the edges, for drive firmware;
* ``.fmu``: an FMU (FMI 2.0 co-simulation) around that header, for
  simulators, with its sources and, where a C compiler is found, the binary of
  the platform it is written on (:mod:`ballscrew.report.friction_fmu`).
"""

from __future__ import annotations

import io
from collections.abc import Callable
from pathlib import Path

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..io.files import atomic_write
from ..servo.friction_map import FrictionMap
from .friction_fmu import fmu_build
from .outputs import csv_text

__all__ = [
    "FORMATS", "MAP_DIGITS", "c_header", "csv_file", "fmu_file", "map_file", "mat_file",
    "modelica_file", "write_map",
]  # fmt: skip

CONVENTIONS = (
    "speed > 0 moves the nut towards +x; axial load = force of the load on the nut along x; "
    "load*speed > 0: the load back-drives the screw, < 0: the motor drives the load; "
    "friction torque and force are signed like the speed (what the motor adds against friction); "
    "motor side = screw torque / gear ratio, screw speed * gear ratio (gear losses left out)"
)


def _header_lines(m: FrictionMap, version: str) -> list[str]:
    fit = m.form
    return [
        f"ballscrew {version}: friction map of {m.model} for '{m.case_title}'",
        f"lead {m.lead * 1e3:g} mm, gear ratio {m.gear_ratio:g} (motor turns per screw turn)",
        "conventions: " + CONVENTIONS,
        "compact form: T_f = sgn(w) (c0 exp(-k_c (T - T_r)) + c1 |F| + c2 d |F|) "
        "+ b exp(-k_b (T - T_r)) w, d = sgn(F w)",
        f"  screw side: c0 = {fit.c0:.6g} N*m, c1 = {fit.c1:.6g} N*m/N, c2 = {fit.c2:.6g} N*m/N, "
        f"b = {fit.b:.6g} N*m*s/rad, k_c = {fit.k_c:.6g} 1/K, k_b = {fit.k_b:.6g} 1/K, "
        f"T_r = {fit.reference_temperature:g} degC",
        f"  fit error over the grid: RMS {fit.rms_error:.3g} N*m, max {fit.max_error:.3g} N*m",
    ]


MAP_DIGITS = 6
"""Significant digits of every number in the map's CSV: a lookup table a drive loads,
within 5e-6 of the model at its nodes, far below the compact form's fit error."""


def csv_file(m: FrictionMap, version: str) -> bytes:
    """The map as CSV after ``#`` header lines, numbers to :data:`MAP_DIGITS` digits."""
    head = "".join(f"# {line}\n" for line in _header_lines(m, version))
    return (head + csv_text(m.rows(), digits=MAP_DIGITS)).encode("utf-8")


def mat_file(m: FrictionMap, version: str) -> bytes:
    """The map as a MATLAB file: breakpoints and tables ``[speed, load, temperature]``."""
    from scipy.io import savemat

    def table(a: FloatArray) -> FloatArray:
        result: FloatArray = np.ascontiguousarray(np.transpose(a, (2, 1, 0)))
        return result

    buffer = io.BytesIO()
    savemat(buffer, {
        "description": "\n".join(_header_lines(m, version)),
        "screw_speed_rad_s": m.speeds, "table_speed_m_s": m.table_speeds,
        "motor_speed_rad_s": m.motor_speeds, "axial_load_N": m.loads,
        "temperature_C": m.temperatures,
        "screw_friction_torque_Nm": table(m.torque), "friction_force_N": table(m.force),
        "motor_friction_torque_Nm": table(m.motor_torque),
        "lead_m": m.lead, "gear_ratio": m.gear_ratio,
    }, do_compression=True, oned_as="column")  # fmt: skip
    # The file's first 116 bytes are free text; scipy writes the clock's time there, which
    # would make two exports of the same map differ. The same text without the time:
    text = f"MATLAB 5.0 MAT-file, written by ballscrew {version}".encode("ascii")
    return (
        text.ljust(_MAT_DESCRIPTION, b" ")[:_MAT_DESCRIPTION] + buffer.getvalue()[_MAT_DESCRIPTION:]
    )


_MAT_DESCRIPTION = 116
"""Length of a MAT-file version 5's descriptive text [bytes] (MathWorks, MAT-File Format)."""


def _identifier(text: str) -> str:
    word = "".join(c if c.isalnum() else "_" for c in text)
    return word if word[:1].isalpha() else "m_" + word


def _modelica_matrix(rows: list[list[float]]) -> str:
    return "[" + "; ".join(", ".join(f"{v:.10g}" for v in r) for r in rows) + "]"


def modelica_file(m: FrictionMap, version: str) -> bytes:
    """A Modelica package: the compact form as a record, CombiTable2Ds matrices per temperature."""
    fit = m.form
    name = "BallScrewFriction_" + _identifier(m.model)
    lines = [f"package {name}", "  /* " + "\n     ".join(_header_lines(m, version)) + " */"]
    lines += [
        '  record Parameters "compact friction form, motor side"',
        f'    parameter Real c0(unit="N.m") = {fit.c0 / m.gear_ratio:.10g};',
        f'    parameter Real c1(unit="N.m/N") = {fit.c1 / m.gear_ratio:.10g};',
        f'    parameter Real c2(unit="N.m/N") = {fit.c2 / m.gear_ratio:.10g};',
        f'    parameter Real b(unit="N.m.s/rad") = {fit.b / m.gear_ratio**2:.10g};',
        f'    parameter Real k_c(unit="1/K") = {fit.k_c:.10g};',
        f'    parameter Real k_b(unit="1/K") = {fit.k_b:.10g};',
        f'    parameter Real T_r(unit="degC") = {fit.reference_temperature:.10g};',
        "  end Parameters;",
    ]
    for k, t in enumerate(m.temperatures):
        rows = [[0.0, *m.loads.tolist()]]
        rows += [[float(w), *m.motor_torque[k, :, j].tolist()]
                 for j, w in enumerate(m.motor_speeds)]  # fmt: skip
        label = f"{t:g}".replace("-", "minus").replace(".", "p")
        lines.append(
            f"  constant Real table_{label}degC[{len(rows)}, {len(rows[0])}] = "
            f'{_modelica_matrix(rows)} "motor friction torque [N.m] at {t:g} degC: '
            'first row axial load [N], first column motor speed [rad/s]";'
        )
    lines.append(f"end {name};")
    return ("\n".join(lines) + "\n").encode("utf-8")


def _c_array(name: str, values: FloatArray) -> str:
    body = ", ".join(f"{v:.17g}" for v in np.ravel(values))
    return f"static const double {name}[{values.size}] = {{{body}}};"


def c_header(m: FrictionMap, version: str) -> bytes:
    """A C header: axes, the motor-side table and a clamped trilinear interpolation."""
    guard = "BALLSCREW_FRICTION_MAP_H"
    nt, nf, nw = m.torque.shape
    comment = "\n".join(f" * {line}" for line in _header_lines(m, version))
    text = f"""/*
{comment}
 *
 * BS_FRICTION_TORQUE_NM[(t * BS_N_LOAD + f) * BS_N_SPEED + w] is the motor-side friction
 * torque [N*m] at BS_TEMPERATURE_C[t] [degC], BS_LOAD_N[f] [N], BS_MOTOR_SPEED_RAD_S[w]
 * [rad/s]. bs_friction_torque() interpolates it linearly along each axis; outside the
 * grid it holds the edge value (no extrapolation).
 */
#ifndef {guard}
#define {guard}

#define BS_N_TEMPERATURE {nt}
#define BS_N_LOAD {nf}
#define BS_N_SPEED {nw}
{_c_array("BS_TEMPERATURE_C", m.temperatures)}
{_c_array("BS_LOAD_N", m.loads)}
{_c_array("BS_MOTOR_SPEED_RAD_S", m.motor_speeds)}
{_c_array("BS_FRICTION_TORQUE_NM", m.motor_torque)}

/* Interval index i and weight s of x on axis[0..n-1]: x = axis[i] + s (axis[i+1] - axis[i]). */
static inline int bs_locate(const double *axis, int n, double x, double *s)
{{
    int i = 0;
    if (n < 2 || x <= axis[0]) {{ *s = 0.0; return 0; }}
    if (x >= axis[n - 1]) {{ *s = 1.0; return n - 2; }}
    while (i < n - 2 && x > axis[i + 1]) i++;
    *s = (x - axis[i]) / (axis[i + 1] - axis[i]);
    return i;
}}

static inline double bs_friction_torque(double motor_speed, double load, double temperature)
{{
    double st, sf, sw, value = 0.0;
    int it = bs_locate(BS_TEMPERATURE_C, BS_N_TEMPERATURE, temperature, &st);
    int jf = bs_locate(BS_LOAD_N, BS_N_LOAD, load, &sf);
    int kw = bs_locate(BS_MOTOR_SPEED_RAD_S, BS_N_SPEED, motor_speed, &sw);
    for (int a = 0; a < 2; a++) for (int b = 0; b < 2; b++) for (int c = 0; c < 2; c++) {{
        int t = BS_N_TEMPERATURE > 1 ? it + a : 0, f = BS_N_LOAD > 1 ? jf + b : 0;
        double weight = (a ? st : 1.0 - st) * (b ? sf : 1.0 - sf) * (c ? sw : 1.0 - sw);
        if ((BS_N_TEMPERATURE < 2 && a) || (BS_N_LOAD < 2 && b)) continue;
        value += weight * BS_FRICTION_TORQUE_NM[(t * BS_N_LOAD + f) * BS_N_SPEED + kw + c];
    }}
    return value;
}}

#endif /* {guard} */
"""
    return text.encode("utf-8")


def fmu_file(m: FrictionMap, version: str) -> bytes:
    """An FMU (FMI 2.0) around :func:`c_header`, with this platform's binary if it builds.

    The binary needs a C compiler (:func:`ballscrew.report.friction_fmu.fmu_build`).
    """
    return fmu_build(m, version, c_header(m, version)).data


FORMATS: dict[str, Callable[[FrictionMap, str], bytes]] = {
    ".csv": csv_file, ".mat": mat_file, ".mo": modelica_file, ".h": c_header, ".fmu": fmu_file,
}  # fmt: skip
"""File suffix -> writer."""


def map_file(m: FrictionMap, path: Path, version: str) -> tuple[bytes, list[str]]:
    """The map's bytes in the format ``path``'s suffix names (:data:`FORMATS`), and notes.

    The notes are for the user (for an FMU: whether it carries a binary, built by which
    compiler).
    """
    writer = FORMATS.get(path.suffix.lower())
    if writer is None:
        raise BallScrewInputError("--out", str(path), "a file ending in " + ", ".join(FORMATS))
    if path.suffix.lower() == ".fmu":
        build = fmu_build(m, version, c_header(m, version))
        return build.data, [f"{path.name}: {build.note}"]
    return writer(m, version), []


def write_map(m: FrictionMap, path: Path, version: str) -> list[str]:
    """Write the map in the format its suffix names (:data:`FORMATS`), atomically.

    Returns the notes of :func:`map_file`.
    """
    data, notes = map_file(m, path, version)
    atomic_write(path, data)
    return notes
