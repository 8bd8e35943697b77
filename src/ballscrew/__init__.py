"""ballscrew: friction torque, efficiency and power loss of ball screws.

The package is built in layers, one module per physical layer:

- :mod:`ballscrew.geometry` - the :class:`BallScrew` description and derived geometry;
- :mod:`ballscrew.loads` - normal load per ball from preload and axial load;
- :mod:`ballscrew.kinematics` - rolling, spin, orbital and table speeds;
- :mod:`ballscrew.contact` - Hertz point contact (exact, Houpert, Hamrock-Brewe);
- :mod:`ballscrew.lubricant` - viscosity against temperature and pressure, density;
- :mod:`ballscrew.lubricants` - the bundled lubricant library;
- :mod:`ballscrew.ehl` - EHL film thickness, film parameter, asperity share;
- :mod:`ballscrew.rheology` - lubricant shear stress laws.

SI units throughout (m, N, Pa, Pa·s, m²/s, rad/s); temperatures in °C.
"""

from __future__ import annotations

from . import _moved, contact, ehl, friction, kinematics, loads, lubricants, rheology
from ._version import __version__
from .chain import FrictionResult, friction_torque, friction_torques, models
from .errors import BallScrewInputError
from .geometry import BallScrew, reference_screw
from .lubricant import Lubricant

_moved.install()  # old module paths, for one release

__all__ = [
    "BallScrew",
    "BallScrewInputError",
    "FrictionResult",
    "Lubricant",
    "__version__",
    "contact",
    "ehl",
    "friction",
    "friction_torque",
    "friction_torques",
    "kinematics",
    "loads",
    "lubricants",
    "models",
    "reference_screw",
    "rheology",
]
