"""Paths and inputs that many test modules share (imported as ``from shared import ...``)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from ballscrew import friction_torque, lubricants, models, reference_screw

#: The project's root (the folder holding ``pyproject.toml``).
ROOT = Path(__file__).resolve().parents[1]
#: The tests' own input files.
DATA = Path(__file__).resolve().parent / "data"
#: A small case file: one screw, a few speeds, quick to run.
SMALL_CASE = DATA / "small_case.toml"
#: The lubricant of Kamalzadeh's measurements.
PAO = lubricants.get("PAO ISO VG 68")
#: The lubricant of the study's reference case.
MINERAL = lubricants.get("mineral ISO VG 68")
#: The six models the package ships (the registry may hold more: see conftest.py).
BUILT_IN_MODELS = (
    "catalog",
    "complete",
    "harris-full",
    "harris-simplified",
    "olaru",
    "viscoelastic",
)
#: Every registered model, the built-in ones and any a test run added.
ALL_MODELS = sorted(m.name for m in models())


def reference_case_toml(title: str, speed: str, axial_load: str, more: str = "") -> str:
    """A case file of the README's reference double nut in PAO ISO VG 68 at 40 degC.

    ``more`` is appended: further tables, e.g. ``[axis]``.
    """
    return f"""\
title = "{title}"
[screw]
designation = "40x10 double 2.5x2 6.35"
preload = "2 kN"
[lubricant]
name = "PAO ISO VG 68"
[operation]
speed = "{speed}"
temperature = "40 degC"
axial_load = "{axial_load}"
{more}"""


# A 32 x 10 mm nut (C_a 20 kN, C_0a 50 kN) on a 200 kg horizontal axis, 1.2 m
# between the supports: the axis check's tests fill in nut, preload, support and sections.
AXIS_CASE = """
title = "check test"
[screw]
pitch_diameter = "32 mm"
lead = "10 mm"
ball_diameter = "6.35 mm"
loaded_turns = 2.5
circuits = 2
nut = "{nut}"
preload = "{preload}"
dynamic_load_rating = "20 kN"
static_load_rating = "50 kN"
[lubricant]
name = "PAO ISO VG 68"
[operation]
temperature = "20 degC"
[axis]
moving_mass = "200 kg"
bearing_span = "1200 mm"
root_diameter = "26 mm"
support = "{support}"
{axis_extra}
{sections}
"""

# THK's worked acceptance example: BNFN4010-5, 3 kN preload (reference 865 N*mm).
BNFN4010 = """title = "THK BNFN4010-5"
[screw]
designation = "40x10 double 2.5x2 6.35"
pitch_diameter = "41.75 mm"
preload = "3 kN"
[lubricant]
name = "mineral ISO VG 68"
"""


def synthetic_drag_curve(
    preload: float = 1500.0, ball_train_constant: float = 0.03
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The complete model's torque on the reference screw at 12 speeds from 10 to 3000 rpm
    and 20 and 40 degC in PAO ISO VG 68: (speed [rad/s], temperature [degC], torque [N*m]),
    the "measurement" whose true parameters the fits' tests know."""
    w, t = (a.ravel() for a in np.meshgrid(np.geomspace(10.0, 3000.0, 12) * np.pi / 30,
                                           np.array([20.0, 40.0])))  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        screw = reference_screw().replace(preload=preload)
        torque = friction_torque(screw, PAO, speed=w, temperature=t,
                                 ball_train_constant=ball_train_constant).total  # fmt: skip
    return w, t, np.asarray(torque)
