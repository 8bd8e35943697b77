r"""The state of every ball contact at an operating point.

This composes the physical layers (geometry, loads, kinematics, Hertz
contact, lubricant, EHL film) into what each friction model needs, so that a
model only adds its own friction law. Arrays broadcast over the operating
point: screw speed, temperature and axial load.

A ball screw has up to four kinds of contact: the screw and the nut contacts
of each of the two contact-line families of :mod:`ballscrew.loads`.

Examples
--------
>>> from ballscrew import lubricants, reference_screw
>>> st = operating_state(reference_screw(), lubricants.get("PAO ISO VG 68"),
...                      speed=104.72, temperature=40.0)
>>> [c.name for c in st.contacts]
['screw-1', 'nut-1', 'screw-2', 'nut-2']
>>> round(float(st.contacts[0].film_minimum) * 1e6, 3)  # µm at 1000 rpm
0.19
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

from . import ehl
from .contact import HertzContact, hertz
from .design.limits import check_operating_bounds
from .errors import FloatArray, broadcast_inputs, check_positive
from .geometry import ScrewGeometry, screw_derived
from .kinematics import Kinematics, kinematics
from .loads import BallLoads, ball_loads
from .lubricant import Lubricant
from .numerics.single import broadcast_shape, broadcast_to, where

__all__ = ["ContactState", "OperatingState", "operating_points", "operating_state"]


@dataclass(frozen=True)
class ContactState:
    r"""One kind of ball contact (screw or nut side, family 1 or 2) at the operating points.

    Attributes
    ----------
    side : {"screw", "nut"}
        Which member the ball touches.
    family : {1, 2}
        Contact-line family of :mod:`ballscrew.loads` (1 = loaded by a positive axial load).
    balls : int or numpy.ndarray
        Number of balls with this contact [-] (one per screw for many screws,
        :class:`~ballscrew.geometry.ScrewArray`).
    load : numpy.ndarray
        Normal load per contact :math:`Q` [N].
    rx, ry : float or numpy.ndarray
        Effective radii of curvature, rolling direction and across the groove [m].
    radius : float or numpy.ndarray
        Distance of the contact from the screw axis [m].
    hertz : HertzContact
        Contact ellipse and pressure.
    entrainment_speed : numpy.ndarray
        Mean rolling speed [m/s] (sign of the screw speed).
    viscosity : numpy.ndarray
        Dynamic viscosity at ambient pressure at the temperature [Pa·s].
    speed_parameter, materials_parameter, load_parameter : numpy.ndarray
        Hamrock-Dowson :math:`U`, :math:`G`, :math:`W` [-].
    film_minimum, film_central : numpy.ndarray
        :math:`h_{min}`, :math:`h_c` [m].
    roughness : float
        Composite RMS roughness [m].
    film_parameter : numpy.ndarray
        :math:`\Lambda = h_{min}/\sigma` [-].
    asperity_share : numpy.ndarray
        :math:`A_c/A_0` [-].

    Where a contact carries no load, its film, film parameter and asperity
    share are 0.
    """

    side: Literal["screw", "nut"]
    family: int
    balls: int | npt.NDArray[np.intp]
    load: FloatArray
    rx: float | FloatArray
    ry: float | FloatArray
    radius: float | FloatArray
    hertz: HertzContact
    entrainment_speed: FloatArray
    viscosity: FloatArray
    speed_parameter: FloatArray
    materials_parameter: FloatArray
    load_parameter: FloatArray
    film_minimum: FloatArray
    roughness: float | FloatArray
    film_parameter: FloatArray
    asperity_share: FloatArray

    @functools.cached_property
    def film_central(self) -> FloatArray:
        """Central film thickness :math:`h_c` [m] (Hamrock-Dowson), 0 where unloaded.

        Computed on first use: most models need only :math:`h_{min}`.
        """
        loaded = self.load_parameter > 0.0
        w_safe = np.where(loaded, self.load_parameter, 1.0)
        h_c = ehl.hamrock_dowson_1977_central(
            self.rx,
            self.speed_parameter,
            self.materials_parameter,
            w_safe,
            self.hertz.ellipticity,
        )
        result: FloatArray = np.where(loaded, h_c, 0.0)
        return result

    @functools.cached_property
    def name(self) -> str:
        """Label such as ``"screw-1"``."""
        return f"{self.side}-{self.family}"


@dataclass(frozen=True)
class OperatingState:
    """Kinematics, ball loads and all contact states at the operating points.

    ``shape`` is the broadcast shape of the operating points; unless the
    state was built with ``broadcast=False``, every array has it.
    ``kinematic_viscosity`` is the oil's at ``temperature`` [m²/s] (None in a
    state built without it).
    """

    screw: ScrewGeometry
    lubricant: Lubricant
    temperature: FloatArray
    kinematics: Kinematics
    loads: BallLoads
    contacts: tuple[ContactState, ...]
    shape: tuple[int, ...] = ()
    kinematic_viscosity: FloatArray | None = None


def operating_points(
    speed: npt.ArrayLike,
    temperature: npt.ArrayLike,
    axial_load: npt.ArrayLike,
    *,
    broadcast: bool = True,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Validate speed [rad/s], temperature [°C] and axial load [N]; broadcast them together.

    With ``broadcast=False`` the arrays keep their own shapes (which must
    broadcast against each other): each layer then works on the values it
    depends on (the viscosity on the temperatures, the ball loads on the
    axial loads), and a grid given as an outer product is not expanded
    before the quantities that need every combination.
    """
    w, t, fa = check_operating_bounds(speed, temperature, axial_load)
    arrays = {"speed": w, "temperature": t, "axial_load": fa}
    if broadcast:
        w, t, fa = broadcast_inputs(**arrays)
        return w, t, fa
    try:
        broadcast_shape(*(a.shape for a in arrays.values()))
    except ValueError:
        broadcast_inputs(**arrays)  # raises the error naming the shapes
    return arrays["speed"], arrays["temperature"], arrays["axial_load"]


def operating_state(
    screw: ScrewGeometry,
    lubricant: Lubricant,
    *,
    speed: npt.ArrayLike,
    temperature: npt.ArrayLike,
    axial_load: npt.ArrayLike = 0.0,
    hertz_method: str = "houpert",
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    broadcast: bool = True,
) -> OperatingState:
    r"""Compose the physical layers at the given operating points.

    Parameters
    ----------
    screw : BallScrew or ScrewArray
        Geometry, preload, materials and roughness; many screws of one nut
        arrangement as broadcast arrays (:class:`ballscrew.geometry.ScrewArray`,
        first axis the screws) give a state whose arrays carry the screw axis first.
    lubricant : Lubricant
        The oil.
    speed : array_like
        Screw angular speed [rad/s].
    temperature : array_like
        Lubricant temperature [°C].
    axial_load : array_like
        External axial load on the nut [N].
    hertz_method : str
        Method of :func:`ballscrew.contact.hertz`; default ``"houpert"`` as in the study.
    asperity_b, asperity_c : float
        Constants of :func:`ballscrew.ehl.asperity_share`.
    broadcast : bool
        Broadcast the operating points against each other first (default).
        ``False`` leaves each quantity with the shape of what it depends on
        (see :func:`operating_points`); the friction models use this.

    Returns
    -------
    OperatingState
        ``speed``, ``temperature`` and ``axial_load`` broadcast against each other.
    """
    w, t, fa = operating_points(speed, temperature, axial_load, broadcast=broadcast)
    return operating_state_unchecked(
        screw, lubricant, w, t, fa, hertz_method=hertz_method, asperity_b=asperity_b,
        asperity_c=asperity_c,
    )  # fmt: skip


def operating_state_unchecked(
    screw: ScrewGeometry,
    lubricant: Lubricant,
    w: FloatArray,
    t: FloatArray,
    fa: FloatArray,
    *,
    hertz_method: str,
    asperity_b: float,
    asperity_c: float,
) -> OperatingState:
    """:func:`operating_state` at operating points the caller has checked.

    ``w``, ``t``, ``fa``: speed [rad/s], temperature [°C] and axial load [N] as
    :func:`operating_points` returns them (float arrays within their bounds, of shapes
    that broadcast); the chain checks them once for the call and composes the state here.
    """
    asperity = (check_positive("b", asperity_b), check_positive("c", asperity_c))
    kin = kinematics(screw, w)
    bl = ball_loads(screw, fa)
    nu, eta = lubricant.viscosities(t)  # one evaluation of the oil's fit for both
    ep = screw.reduced_modulus
    g = ehl.dimensionless_materials(lubricant.pressure_viscosity, ep)
    contacts: list[ContactState] = []
    for family, q, balls in ((1, bl.normal_load_1, bl.balls_1), (2, bl.normal_load_2, bl.balls_2)):
        for side, curvature in _sides(screw).items():
            contacts.append(
                _contact_state(side, family, q, balls, curvature, kin, eta, g, ep, hertz_method,
                               asperity)
            )  # fmt: skip
    return OperatingState(
        screw=screw,
        lubricant=lubricant,
        temperature=t,
        kinematics=kin,
        loads=bl,
        contacts=tuple(contacts),
        shape=broadcast_shape(w.shape, t.shape, fa.shape, np.shape(screw.lead)),
        kinematic_viscosity=nu,
    )


def _sides(screw: ScrewGeometry) -> dict[str, tuple[float, float, float, float]]:
    """Each side's radii of curvature, contact radius and composite roughness [m] (kept)."""
    return screw_derived(screw, "state.sides", lambda: _side_geometry(screw))


def _side_geometry(screw: ScrewGeometry) -> dict[str, tuple[float, float, float, float]]:
    """What :func:`_sides` keeps, read from the screw."""
    return {
        "screw": (
            screw.rx_screw,
            screw.ry_screw,
            screw.contact_radius_screw,
            screw.composite_roughness_screw,
        ),
        "nut": (
            screw.rx_nut,
            screw.ry_nut,
            screw.contact_radius_nut,
            screw.composite_roughness_nut,
        ),
    }


def _contact_state(
    side: str,
    family: int,
    q: FloatArray,
    balls: int | npt.NDArray[np.intp],
    curvature: tuple[float, float, float, float],
    kin: Kinematics,
    eta: FloatArray,
    g: FloatArray,
    ep: float,
    hertz_method: str,
    asperity: tuple[FloatArray, FloatArray],
) -> ContactState:
    """One ball contact of a family on one side: Hertz, the film and the asperity share."""
    rx, ry, radius, sigma = curvature
    hz = hertz(q, rx, ry, ep, method=hertz_method)
    # The film's inputs follow from checked ones (the operating points, the screw, the
    # oil at a temperature it takes, Hertz's ellipticity >= 1; the asperity constants
    # were checked by operating_state): the formulas without their checks.
    u_par = ehl.dimensionless_speed_unchecked(eta, kin.entrainment_speed, ep, rx)
    w_par = ehl.dimensionless_load_unchecked(q, ep, rx)
    # An unloaded contact (single-nut family 2, lift-off) has no film:
    # film, film parameter and asperity share are reported as 0 there
    # (the fits would otherwise diverge as W**-0.07 at W -> 0).
    loaded = w_par > 0.0
    w_safe = where(loaded, w_par, 1.0)
    h_min = where(
        loaded,
        ehl.hamrock_dowson_1977_minimum_unchecked(rx, u_par, g, w_safe, hz.ellipticity),
        0.0,
    )
    lam = ehl.lambda_ratio_unchecked(h_min, sigma)
    share = where(loaded, ehl.asperity_share_unchecked(lam, *asperity), 0.0)
    return ContactState(
        side=side,  # type: ignore[arg-type]
        family=family,
        balls=balls,
        load=q,
        rx=rx,
        ry=ry,
        radius=radius,
        hertz=hz,
        entrainment_speed=kin.entrainment_speed,
        viscosity=eta,
        speed_parameter=u_par,
        materials_parameter=broadcast_to(g, q.shape),
        load_parameter=w_par,
        film_minimum=h_min,
        roughness=sigma,
        film_parameter=lam,
        asperity_share=share,
    )
