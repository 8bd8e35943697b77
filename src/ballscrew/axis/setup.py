r"""An axis and its heat balance from a case file's ``[axis]`` section, gaps filled and stated.

A case file may leave out what a designer often does not know yet: the
screw's length in the air, its moment of inertia, the support bearings. This
module fills each gap with a stated rule (or leaves a term out) and returns a
note for every choice, so that the command line, the web page and the API
agree on what they assumed.

The screw's inertia, when not given, is that of a solid steel cylinder of the
pitch diameter :math:`d_m` over the screw length :math:`L` (the same cylinder
whose heat capacity the heat balance uses):

.. math:: J = \frac{\pi}{32}\,\rho\,L\,d_m^4

the moment of inertia of a solid cylinder about its axis,
:math:`\tfrac12 m r^2` with :math:`m = \rho\pi d_m^2 L/4` and
:math:`r = d_m/2`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray
from ..geometry import BallScrew
from ..materials import STEEL_DENSITY
from .energy import Axis
from .thermal import ThermalNode, estimated_screw_length

__all__ = ["AxisSetup", "axis_setup", "shaft_inertia"]


def shaft_inertia(
    diameter: npt.ArrayLike, length: npt.ArrayLike, density: float = STEEL_DENSITY
) -> FloatArray:
    r"""Moment of inertia of a solid shaft about its axis [kg·m²].

    :math:`J = \pi\rho L d^4/32`, with ``diameter`` :math:`d` [m], ``length``
    :math:`L` [m] and ``density`` :math:`\rho` [kg/m³] (steel by default).

    Examples
    --------
    A steel shaft of 40 mm over 1 m: 1.97e-3 kg·m².

    >>> print(f"{float(shaft_inertia(0.04, 1.0)):.3g}")
    0.00197
    """
    d = np.asarray(diameter, dtype=float)
    return np.asarray(math.pi * density * np.asarray(length, dtype=float) * d**4 / 32.0)


@dataclass(frozen=True)
class AxisSetup:
    """The axis, the thermal node, and one note per assumption made to build them."""

    axis: Axis
    node: ThermalNode
    notes: tuple[str, ...]
    derived: dict[str, tuple[float, str]] = field(default_factory=dict)
    """Each value the case left out and the setup filled, by ``axis.key``: its SI value and
    how it was found (for the outputs' inputs, :meth:`ballscrew.io.case.Case.input_values`)."""


SERVO_KEYS = ("pre_rolling_length",)
"""``[axis]`` keys only the servo model reads (:func:`ballscrew.servo.plant.axis_dynamics`)."""


def axis_setup(
    screw: BallScrew,
    axis_values: Mapping[str, Any],
    thermal_values: Mapping[str, float],
    travel: float,
) -> AxisSetup:
    """Build the axis and thermal node of a case, filling what it leaves out.

    ``axis_values`` and ``thermal_values`` are the case's resolved ``[axis]``
    keys (SI), holding only what the file gave (and the text keys);
    ``travel`` [m] is the nut's travel of the motion (0 when there is none).

    - screw length: the bearing span if given, else
      :func:`ballscrew.axis.thermal.estimated_screw_length`;
    - screw inertia: :func:`shaft_inertia` of the pitch diameter over that length;
    - support bearings: left out without a bore; SKF's load term without an
      outside diameter; Palmgren's model with it;
    - no machine resistance: convection only (the warmest case).
    """
    notes: list[str] = []
    derived: dict[str, tuple[float, str]] = {}
    thermal = dict(thermal_values)
    span = axis_values.get("bearing_span")
    if "screw_length" not in thermal and span is not None:
        thermal["screw_length"] = float(span)
        derived["axis.screw_length"] = (float(span), "from the bearing span, taken as it")
        notes.append(
            f"axis.screw_length = {span * 1e3:.0f} mm (the bearing span; give screw_length "
            "for a real heat balance)"
        )
    elif "screw_length" not in thermal:
        thermal["screw_length"] = estimated_screw_length(screw, travel)
        derived["axis.screw_length"] = (
            thermal["screw_length"],
            f"from the travel {travel * 1e3:.4g} mm, the nut and 4 pitch diameters",
        )
        notes.append(
            f"axis.screw_length = {thermal['screw_length'] * 1e3:.0f} mm (estimated: travel, "
            "nut and 4 diameters; give it for a real heat balance)"
        )
    # The servo model's own keys of [axis] (ballscrew.servo.plant), not the energy axis'.
    values = {k: v for k, v in axis_values.items() if k not in SERVO_KEYS}
    if "screw_inertia" not in values:
        j = float(shaft_inertia(screw.pitch_diameter, thermal["screw_length"]))
        values["screw_inertia"] = j
        shaft = (f"a solid steel shaft of the pitch diameter {screw.pitch_diameter * 1e3:g} mm "
                 f"over {thermal['screw_length'] * 1e3:.0f} mm")  # fmt: skip
        derived["axis.screw_inertia"] = (
            j, f"from the screw's geometry, {shaft} (pi rho L d^4 / 32)"
        )  # fmt: skip
        notes.append(f"axis.screw_inertia = {j:.3g} kg*m^2 ({shaft}; give the catalogue value)")
    if values.get("bearing_bore") is None:
        notes.append(
            "support bearings: not counted (give axis.bearing_bore, and for Palmgren's model "
            "bearing_outer_diameter and bearing_static_rating)"
        )
    elif values.get("bearing_outer_diameter") is None:
        notes.append(
            "support bearings: SKF's simplified estimate, load term only (no drag rising with "
            "speed); give axis.bearing_outer_diameter and bearing_static_rating for Palmgren's"
        )
    else:
        notes.append(
            f"support bearings: Palmgren's model ({values.get('bearing_type')}, "
            f"{values.get('bearing_lubrication')}), with the lubricant's viscosity at the "
            "cycle's temperature and without the bearings' own preload"
        )
    if "machine_resistance" not in thermal:
        notes.append("axis.machine_resistance: none (convection only, the warmest case)")
    try:
        return AxisSetup(Axis(**values), ThermalNode(**thermal), tuple(notes), derived)
    except BallScrewInputError as exc:
        # Named as the case file names it: every key of both comes from [axis].
        field = exc.field if exc.field.startswith("axis.") else f"axis.{exc.field}"
        raise BallScrewInputError(field, exc.value, exc.allowed) from None
