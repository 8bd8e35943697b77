r"""Ball screw geometry: the validated, immutable :class:`BallScrew` description.

The ball screw is treated like an angular-contact ball bearing whose inner
ring is the screw and whose outer ring is the nut (Harris & Kotzalas [1]_,
ch. 1-2; Olaru et al. [2]_). Each ball touches the screw groove and the nut
groove along one contact line inclined at the contact angle :math:`\alpha` to
the plane normal to the screw axis. With :math:`d_m` the pitch (ball-centre)
diameter, :math:`D_w` the ball diameter and :math:`\gamma = D_w\cos\alpha/d_m`:

.. math::
    R_{x,s} = \tfrac{D_w}{2}(1-\gamma),\qquad
    R_{x,n} = \tfrac{D_w}{2}(1+\gamma),\qquad
    R_{y,j} = \frac{f_j D_w}{2 f_j - 1}

are the effective radii of curvature of the ball-screw (s) and ball-nut (n)
contacts in the rolling direction (x, along the groove) and transverse to it
(y, across the groove), with :math:`f_j` the groove conformity (groove radius
over ball diameter). The helix makes the rolling-direction curvature differ
from the ring's by a factor of order :math:`\cos^2\lambda`; it is neglected,
as by Olaru et al. (the exact treatment is Wei & Lin [3]_): for lead angles
below 6° the error in :math:`R_x` is under 1 %.

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 2.
.. [2] D. Olaru, G. C. Puiu, L. C. Balan, V. Puiu, "A new model to estimate
   friction torque in a ball screw system", in *Product Engineering*,
   Springer, 2005, doi:10.1007/1-4020-2933-0_20.
.. [3] C. C. Wei, J. F. Lin, "Kinematic analysis of the ball screw mechanism
   considering variable contact angles and elastic deformations", J. Mech.
   Des. 125 (2003) 717-733, doi:10.1115/1.1623761.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, fields, replace
from typing import Any, Literal, TypeVar, get_args

import numpy as np
import numpy.typing as npt

from .errors import BallScrewInputError, check_in_range, check_nonnegative, check_positive
from .materials import (
    STEEL_POISSON_RATIO,
    STEEL_YOUNGS_MODULUS,
    composite_roughness,
    reduced_modulus,
)
from .plausible import check_ball_diameter, check_loaded_turns

__all__ = [
    "BALL_SEPARATIONS",
    "MAX_PRELOAD",
    "NUT_ARRANGEMENTS",
    "BallScrew",
    "BallSeparation",
    "NutArrangement",
    "ScrewArray",
    "ScrewGeometry",
    "nut_length",
    "reference_screw",
]

NutArrangement = Literal["double", "single", "single-4point"]
NUT_ARRANGEMENTS: tuple[str, ...] = get_args(NutArrangement)
"""Allowed values of :attr:`BallScrew.nut`:

``"double"``
    two half-nuts preloaded against each other, 2-point contact (also models
    a single nut preloaded by a lead offset);
``"single"``
    one nut with 2-point contact and no preload (a backlash nut);
``"single-4point"``
    one nut with oversize balls, each ball touching screw and nut twice
    (gothic-arch grooves, 4-point contact).
"""

BallSeparation = Literal["none", "spacer-balls", "cage"]
BALL_SEPARATIONS: tuple[str, ...] = get_args(BallSeparation)
"""Allowed values of :attr:`BallScrew.ball_separation`: how the balls are kept apart.

``"none"``
    a full ball train: neighbouring balls touch and slide on each other (most
    nuts);
``"spacer-balls"``
    a smaller spacer ball between every two load balls: the spacers turn the
    other way and roll on their neighbours; half the places of a turn hold
    load balls;
``"cage"``
    a ball retainer (caged-ball nuts): the balls sit in separate pockets and
    do not touch; the loaded balls are counted as for ``"none"`` (the
    retainer's thin separators are not subtracted: give ``loaded_turns`` to
    match the catalogue's ball count if it differs).
"""

_STEEL_E = STEEL_YOUNGS_MODULUS
_STEEL_NU = STEEL_POISSON_RATIO

PLAUSIBLE_SIZES: tuple[tuple[str, float, float, str], ...] = (
    ("pitch_diameter", 2e-3, 0.5, "ball screws are made from about 4 mm to 200 mm"),
    ("lead", 2e-4, 0.5, "leads run from about 0.5 mm to 100 mm"),
    ("ball_diameter", 2e-4, 0.1, "balls of ball screws run from about 0.8 mm to 25 mm"),
    ("roughness_ball", 1e-9, 1e-5, "RMS roughness of ground or lapped surfaces is 0.01-2 µm"),
    ("roughness_screw", 1e-9, 1e-5, "RMS roughness of ground or lapped surfaces is 0.01-2 µm"),
    ("roughness_nut", 1e-9, 1e-5, "RMS roughness of ground or lapped surfaces is 0.01-2 µm"),
)
"""Sizes [m] outside which a :class:`BallScrew` is refused as implausible
(name, low, high, why): generous bounds around every made screw, so that a
value given in the wrong unit (40 for 40 mm) is caught with a hint."""

PLAUSIBLE_MODULI: tuple[tuple[str, float, float, str], ...] = (
    ("youngs_modulus_ball", 5e10, 7e11, "balls are bearing steel (about 210 GPa), silicon "
     "nitride (310 GPa) or cemented carbide (up to 650 GPa)"),
    ("youngs_modulus_races", 5e10, 7e11, "screws and nuts are steel (about 210 GPa)"),
)  # fmt: skip
"""Young's moduli [Pa] outside which a :class:`BallScrew` is refused (name, low, high, why):
'210 MPa' for 210 GPa gave 7.5 times the torque in 0.2.0."""

MAX_CIRCUITS = 20
"""The most circuits per nut (or half-nut) a :class:`BallScrew` takes: makers build 1 to 10."""

MAX_LOADED_TURNS = 10.0
"""The most loaded turns per circuit a :class:`BallScrew` takes: makers build 1.5 to 5 (a
designation's '25x2' read as 25 turns was a slip for 2.5)."""


MAX_PRELOAD = 1e8
"""The largest preload a :class:`BallScrew` takes [N] (100 MN: far past any ball screw)."""


@dataclass(frozen=True)
class BallScrew:
    r"""Geometry, preload and materials of a ball screw and nut (immutable, validated).

    Parameters
    ----------
    pitch_diameter : float
        Diameter of the circle through the ball centres, :math:`d_m` [m].
    lead : float
        Axial advance of the nut per screw revolution, :math:`l` [m].
    ball_diameter : float
        :math:`D_w` [m].
    contact_angle : float
        Nominal contact angle :math:`\alpha` [rad], in (0, π/2); 45° is usual.
    conformity_screw, conformity_nut : float
        Groove radius over ball diameter, :math:`f_s`, :math:`f_n` [-], > 0.5
        (0.51 to 0.56 is usual).
    loaded_turns : float
        Loaded turns per circuit, :math:`i` [-].
    circuits : int
        Ball circuits per nut; for ``nut="double"`` per half-nut.
    nut : {"double", "single", "single-4point"}
        Nut arrangement, see :data:`NUT_ARRANGEMENTS`.
    ball_separation : {"none", "spacer-balls", "cage"}
        How the balls are kept apart, see :data:`BALL_SEPARATIONS`; default
        ``"none"``.
    preload : float
        Axial preload force :math:`F_{pr}` [N], >= 0. For ``"double"`` the
        force with which the two half-nuts are pressed against each other; for
        ``"single-4point"`` the axial force on each of the two contact-line
        families. Must be 0 for ``"single"``.
    youngs_modulus_ball, youngs_modulus_races : float
        Young's moduli of the balls and of the screw and nut [Pa]; default
        210 GPa (bearing steel).
    poisson_ratio_ball, poisson_ratio_races : float
        Poisson's ratios [-]; default 0.3 (bearing steel).
    roughness_ball, roughness_screw, roughness_nut : float
        RMS surface roughness [m], > 0; defaults 0.08 µm (ground balls) and
        0.3 µm (ground grooves), the values of the public code of Olaru's
        model.

    Examples
    --------
    >>> import math
    >>> s = BallScrew(pitch_diameter=0.040, lead=0.010, ball_diameter=6.35e-3,
    ...               contact_angle=math.radians(45), conformity_screw=0.55,
    ...               conformity_nut=0.55, loaded_turns=2.5, circuits=2,
    ...               nut="double", preload=2000.0)
    >>> round(math.degrees(s.lead_angle), 3)
    4.55
    >>> s.balls_per_nut
    98
    """

    pitch_diameter: float
    lead: float
    ball_diameter: float
    contact_angle: float
    conformity_screw: float
    conformity_nut: float
    loaded_turns: float
    circuits: int
    nut: NutArrangement = "double"
    preload: float = 0.0
    ball_separation: BallSeparation = "none"
    youngs_modulus_ball: float = _STEEL_E
    youngs_modulus_races: float = _STEEL_E
    poisson_ratio_ball: float = _STEEL_NU
    poisson_ratio_races: float = _STEEL_NU
    roughness_ball: float = 0.08e-6
    roughness_screw: float = 0.3e-6
    roughness_nut: float = 0.3e-6

    def _plausible(self) -> None:
        """Refuse sizes and moduli no ball screw has: most often a unit slip (mm given as m)."""
        for name, low, high, made in PLAUSIBLE_SIZES:
            value = float(getattr(self, name))
            if low <= value <= high:
                continue
            hint = ""
            for factor, unit in ((1e-3, "mm"), (1e-6, "µm"), (1e3, "km")):
                if low <= value * factor <= high:
                    hint = f"; {value:g} looks like {unit}: {value:g} {unit} = {value * factor:g} m"
                    break
            raise BallScrewInputError(name, value, f"{low:g} to {high:g} m ({made}){hint}")
        for name, low, high, made in PLAUSIBLE_MODULI:
            value = float(getattr(self, name))
            if not low <= value <= high:
                hint = f"; {value:g} Pa looks like GPa given as MPa" if 5e7 <= value <= 7e8 else ""
                raise BallScrewInputError(name, value, f"{low:g} to {high:g} Pa ({made}){hint}")
        if self.circuits > MAX_CIRCUITS:
            raise BallScrewInputError(
                "circuits", self.circuits, f"1 to {MAX_CIRCUITS} (makers build 1 to 10 per nut)"
            )
        if self.loaded_turns > MAX_LOADED_TURNS:
            raise BallScrewInputError(
                "loaded_turns", self.loaded_turns,
                f"at most {MAX_LOADED_TURNS:g} per circuit (makers build 1.5 to 5; "
                "a designation's '2.5x2' is 2.5 turns in each of 2 circuits)",
            )  # fmt: skip

    def __post_init__(self) -> None:
        """Validate every field (refusing what cannot be built) and warn on the unusual.

        Scalars are checked and stored as floats, the choices and the circuits
        next, then what plausibility holds, and last that the ball fits the pitch
        circle and the lead and that the nut holds at least one ball per circuit.
        """
        self._check_scalars()
        self._check_choices()
        self._plausible()
        self._check_fit()
        # Inside what can be built, but perhaps not what makers build: warned, used as given.
        check_ball_diameter("ball_diameter", self.ball_diameter)
        check_loaded_turns("loaded_turns", self.loaded_turns)

    def _check_scalars(self) -> None:
        """The real-number fields: each a single number in its range, stored as float."""
        for name in ("pitch_diameter", "lead", "ball_diameter", "loaded_turns"):
            self._scalar(name, check_positive)
        for name in ("youngs_modulus_ball", "youngs_modulus_races"):
            self._scalar(name, check_positive)
        for name in ("roughness_ball", "roughness_screw", "roughness_nut"):
            self._scalar(name, check_positive)
        self._scalar("preload", check_nonnegative)
        if self.preload > MAX_PRELOAD:
            raise BallScrewInputError(
                "preload", self.preload, "at most 1e8 N (100 MN): no ball screw carries more"
            )
        self._scalar(
            "contact_angle",
            lambda f, v: check_in_range(f, v, 0.0, math.pi / 2, unit="rad (0° to 90°)"),
        )
        for name in ("conformity_screw", "conformity_nut"):
            self._scalar(
                name,
                lambda f, v: check_in_range(
                    f, v, 0.5, np.inf, unit="(groove radius / ball diameter must exceed 0.5)"
                ),
            )
        for name in ("poisson_ratio_ball", "poisson_ratio_races"):
            self._scalar(name, lambda f, v: check_in_range(f, v, 0.0, 0.5, inclusive=(True, False)))

    def _check_choices(self) -> None:
        """The whole circuits, the nut and ball separation chosen, a preload the nut holds."""
        if isinstance(self.circuits, bool) or not isinstance(self.circuits, int | np.integer):
            raise BallScrewInputError("circuits", self.circuits, "a whole number >= 1")
        if self.circuits < 1:
            raise BallScrewInputError("circuits", self.circuits, "a whole number >= 1")
        object.__setattr__(self, "circuits", int(self.circuits))
        if self.nut not in NUT_ARRANGEMENTS:
            raise BallScrewInputError("nut", self.nut, f"one of {list(NUT_ARRANGEMENTS)}")
        if self.ball_separation not in BALL_SEPARATIONS:
            raise BallScrewInputError(
                "ball_separation", self.ball_separation, f"one of {list(BALL_SEPARATIONS)}"
            )
        if self.nut == "single" and self.preload > 0.0:
            raise BallScrewInputError(
                "preload",
                self.preload,
                '0 N for nut="single" (a 2-point single nut cannot hold a preload; '
                'use nut="double" for double or lead-offset nuts, "single-4point" '
                "for oversize balls)",
            )

    def _check_fit(self) -> None:
        """The ball fits the pitch circle and the lead, the lead angle is below 45°.

        And the loaded turns hold between one and a million balls per circuit.
        """
        if self.ball_diameter >= self.pitch_diameter:
            raise BallScrewInputError(
                "ball_diameter",
                self.ball_diameter,
                f"a ball smaller than the pitch diameter ({self.pitch_diameter!r} m); "
                "a larger ball does not fit the pitch circle (no screw core would remain)",
            )
        if self.ball_diameter >= self.lead:
            raise BallScrewInputError(
                "ball_diameter",
                self.ball_diameter,
                f"a ball smaller than the lead ({self.lead * 1e3:g} mm): a larger ball does not "
                "fit between neighbouring turns of the groove (a multi-start thread's pitch is "
                "smaller still)",
            )
        if self.lead >= math.pi * self.pitch_diameter:
            raise BallScrewInputError(
                "lead",
                self.lead,
                f"lead < pi * pitch_diameter ({math.pi * self.pitch_diameter:.6g} m), "
                "i.e. a lead angle below 45°",
            )
        per_circuit = (
            self.loaded_turns * math.pi * self.pitch_diameter / math.cos(self.lead_angle)
        ) / self.ball_diameter
        if not math.isfinite(per_circuit) or per_circuit > 1e6:
            raise BallScrewInputError(
                "loaded_turns",
                self.loaded_turns,
                f"a value giving fewer than a million balls per circuit (with ball_diameter = "
                f"{self.ball_diameter!r} m it gives {per_circuit:.3g})",
            )
        if self.balls_per_circuit < 1:
            raise BallScrewInputError(
                "loaded_turns", self.loaded_turns, "enough turns to hold at least one ball"
            )

    def _scalar(self, name: str, check: Any) -> None:
        value = getattr(self, name)
        if np.ndim(value) != 0 or isinstance(value, bool):
            raise BallScrewInputError(name, value, "a single real number")
        object.__setattr__(self, name, float(check(name, value)))

    def replace(self, **changes: Any) -> BallScrew:
        """Return a copy with some fields changed (validated again)."""
        known = {f.name for f in fields(self)}
        for key in changes:
            if key not in known:
                raise BallScrewInputError(
                    key, changes[key], f"a field of BallScrew: {sorted(known)}"
                )
        return replace(self, **changes)

    # --- derived quantities -------------------------------------------------
    @property
    def lead_angle(self) -> float:
        r"""Lead (helix) angle at the pitch diameter, :math:`\arctan(l/\pi d_m)` [rad]."""
        return math.atan(self.lead / (math.pi * self.pitch_diameter))

    @property
    def gamma(self) -> float:
        r"""Ball-position ratio :math:`\gamma = D_w\cos\alpha/d_m` [-]."""
        return self.ball_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    @property
    def balls_per_circuit(self) -> int:
        r"""Load balls of a circuit's loaded turns, :math:`\lfloor i\pi d_m/D_w\cos\lambda\rfloor`.

        The helix length of the loaded turns divided by the ball diameter,
        rounded down (balls touch each other; the return path is not counted);
        with spacer balls, every other place: half of that, rounded up.
        """
        length = self.loaded_turns * math.pi * self.pitch_diameter / math.cos(self.lead_angle)
        places = math.floor(length / self.ball_diameter + 1e-9)
        return (places + 1) // 2 if self.ball_separation == "spacer-balls" else places

    @property
    def balls_per_nut(self) -> int:
        """Loaded balls of one nut (of one half-nut for ``nut="double"``) [-]."""
        return self.circuits * self.balls_per_circuit

    @property
    def contact_radius_screw(self) -> float:
        r"""Ball-screw contact distance from the axis, :math:`(d_m - D_w\cos\alpha)/2` [m]."""
        return 0.5 * (self.pitch_diameter - self.ball_diameter * math.cos(self.contact_angle))

    @property
    def contact_radius_nut(self) -> float:
        r"""Ball-nut contact distance from the axis, :math:`(d_m + D_w\cos\alpha)/2` [m]."""
        return 0.5 * (self.pitch_diameter + self.ball_diameter * math.cos(self.contact_angle))

    @property
    def rx_screw(self) -> float:
        r"""Ball-screw effective radius, rolling direction, :math:`\tfrac{D_w}{2}(1-\gamma)` [m]."""
        return 0.5 * self.ball_diameter * (1.0 - self.gamma)

    @property
    def rx_nut(self) -> float:
        r"""Ball-nut effective radius, rolling direction, :math:`\tfrac{D_w}{2}(1+\gamma)` [m]."""
        return 0.5 * self.ball_diameter * (1.0 + self.gamma)

    @property
    def ry_screw(self) -> float:
        r"""Ball-screw effective radius across the groove, :math:`f_sD_w/(2f_s-1)` [m]."""
        f = self.conformity_screw
        return f * self.ball_diameter / (2.0 * f - 1.0)

    @property
    def ry_nut(self) -> float:
        r"""Ball-nut effective radius across the groove, :math:`f_nD_w/(2f_n-1)` [m]."""
        f = self.conformity_nut
        return f * self.ball_diameter / (2.0 * f - 1.0)

    @property
    def deformed_radius_screw(self) -> float:
        r"""Deformed ball-screw contact radius across the groove, :math:`2f_sD_w/(2f_s+1)` [m].

        The harmonic mean of the ball radius and the groove radius: the
        transverse radius of the pressed contact surface, which sets the
        differential (Heathcote) sliding (Harris & Kotzalas, ch. 5).
        """
        f = self.conformity_screw
        return 2.0 * f * self.ball_diameter / (2.0 * f + 1.0)

    @property
    def deformed_radius_nut(self) -> float:
        r"""Deformed ball-nut contact radius across the groove, :math:`2f_nD_w/(2f_n+1)` [m]."""
        f = self.conformity_nut
        return 2.0 * f * self.ball_diameter / (2.0 * f + 1.0)

    @functools.cached_property
    def reduced_modulus(self) -> float:
        """Reduced modulus :math:`E'` of ball against screw and nut [Pa]."""
        return float(
            reduced_modulus(
                self.youngs_modulus_ball,
                self.poisson_ratio_ball,
                self.youngs_modulus_races,
                self.poisson_ratio_races,
            )
        )

    @functools.cached_property
    def composite_roughness_screw(self) -> float:
        r"""Composite RMS roughness at the screw, :math:`\sqrt{\sigma_b^2+\sigma_s^2}` [m]."""
        return float(composite_roughness(self.roughness_ball, self.roughness_screw))

    @functools.cached_property
    def composite_roughness_nut(self) -> float:
        r"""Composite RMS roughness, ball-nut contact, :math:`\sqrt{\sigma_b^2+\sigma_n^2}` [m]."""
        return float(composite_roughness(self.roughness_ball, self.roughness_nut))


_ARRAY_FIELDS: tuple[str, ...] = (
    "pitch_diameter", "lead", "ball_diameter", "contact_angle", "conformity_screw",
    "conformity_nut", "loaded_turns", "preload", "youngs_modulus_ball", "youngs_modulus_races",
    "poisson_ratio_ball", "poisson_ratio_races", "roughness_ball", "roughness_screw",
    "roughness_nut",
)  # fmt: skip
"""The numeric fields of :class:`BallScrew` that :class:`ScrewArray` holds as arrays."""

_DERIVED: tuple[str, ...] = (
    "lead_angle", "gamma", "contact_radius_screw", "contact_radius_nut", "rx_screw", "rx_nut",
    "ry_screw", "ry_nut", "deformed_radius_screw", "deformed_radius_nut", "reduced_modulus",
    "composite_roughness_screw", "composite_roughness_nut",
)  # fmt: skip
"""The derived quantities of :class:`BallScrew` that :class:`ScrewArray` holds as arrays."""


@dataclass(frozen=True, eq=False)
class ScrewArray:
    r"""Many screws of one nut arrangement, their geometry as broadcast arrays.

    What a :class:`BallScrew` gives as numbers, for a table of screws: every
    numeric field and derived quantity is an array whose first axis runs over
    the screws and whose other axes have length 1 (``shape`` ``(n, 1, ..., 1)``),
    so that it broadcasts against operating points of ``ndim - 1`` axes and
    every physics layer works on all screws at once. The values are read from
    the validated screws themselves (:meth:`of`), so each screw's entry has the
    same bits as the screw's own attribute. The categorical fields (``nut``,
    ``ball_separation``) are shared by all screws of an array.

    Examples
    --------
    >>> base = reference_screw()
    >>> arr = ScrewArray.of([base, base.replace(lead=0.02)], ndim=2)
    >>> arr.lead.shape, arr.balls_per_nut.ravel().tolist()
    ((2, 1), [98, 100])
    """

    screws: tuple[BallScrew, ...]
    nut: NutArrangement
    ball_separation: BallSeparation
    values: dict[str, npt.NDArray[Any]]

    @classmethod
    def of(cls, screws: Sequence[BallScrew], ndim: int = 1) -> ScrewArray:
        """The screws (one nut arrangement and ball separation) as arrays of ``ndim`` axes."""
        screws = tuple(screws)
        if not screws:
            raise BallScrewInputError("screws", screws, "at least one BallScrew")
        kinds = {(s.nut, s.ball_separation) for s in screws}
        if len(kinds) != 1:
            raise BallScrewInputError(
                "screws", sorted(kinds), "screws of one nut arrangement and ball separation"
            )
        shape = (len(screws),) + (1,) * (max(ndim, 1) - 1)
        values: dict[str, npt.NDArray[Any]] = {}
        for name in _ARRAY_FIELDS + _DERIVED:
            values[name] = np.array([getattr(s, name) for s in screws], dtype=float).reshape(shape)
        for name in ("circuits", "balls_per_circuit", "balls_per_nut"):
            values[name] = np.array([getattr(s, name) for s in screws], dtype=np.intp).reshape(
                shape
            )
        return cls(screws, screws[0].nut, screws[0].ball_separation, values)

    def __len__(self) -> int:
        return len(self.screws)

    def with_ndim(self, ndim: int) -> ScrewArray:
        """The same screws, their arrays shaped ``(n, 1, ..., 1)`` with ``ndim`` axes."""
        shape = (len(self.screws),) + (1,) * (max(ndim, 1) - 1)
        values = {k: v.reshape(shape) for k, v in self.values.items()}
        return ScrewArray(self.screws, self.nut, self.ball_separation, values)

    def __getattr__(self, name: str) -> Any:
        values = self.__dict__.get("values")
        if values is not None and name in values:
            return values[name]
        raise AttributeError(name)


ScrewGeometry = BallScrew | ScrewArray
"""One screw, or many of one nut arrangement as broadcast arrays (:class:`ScrewArray`)."""

_T = TypeVar("_T")


def screw_derived(screw: ScrewGeometry, key: str, compute: Callable[[], _T]) -> _T:
    """``compute()``: a quantity of the screw alone, computed once per screw object and kept.

    A :class:`BallScrew` is frozen (validated fields that never change) and a
    :class:`ScrewArray`'s arrays are its screws' values, so what follows from the geometry
    alone (the kinematics per unit speed, say) is the same at every call: the layers
    that need it at every operating point ask for it here, by a ``key`` naming the
    quantity and its module. The value is kept on the object (not among its fields: not
    compared, not shown) and must not be changed in place by the caller.
    """
    kept: dict[str, Any] = screw.__dict__.setdefault("_derived", {})
    try:
        return kept[key]  # type: ignore[no-any-return]
    except KeyError:
        value = kept[key] = compute()
        return value


def cos(x: Any) -> Any:
    """Cosine of a screw's angle: the math module's for one screw (a number), numpy's else."""
    return math.cos(x) if isinstance(x, float) else np.cos(x)


def sin(x: Any) -> Any:
    """Sine of a screw's angle: the math module's for one screw (a number), numpy's else."""
    return math.sin(x) if isinstance(x, float) else np.sin(x)


def tan(x: Any) -> Any:
    """Tangent of a screw's angle: the math module's for one screw (a number), numpy's else."""
    return math.tan(x) if isinstance(x, float) else np.tan(x)


def reference_screw() -> BallScrew:
    """A 40 mm x 10 mm lead double-nut ball screw with 6.35 mm balls and 2 kN preload.

    A typical machine-tool feed-drive screw, used as the project's reference
    case: pitch diameter 40 mm, lead 10 mm, ball diameter 6.35 mm (1/4 in),
    contact angle 45°, conformity 0.55 on screw and nut, 2.5 loaded turns per
    circuit, 2 circuits per half-nut, 2 kN preload, steel. These are
    representative catalogue values, not one manufacturer's part.

    Examples
    --------
    >>> reference_screw().balls_per_nut
    98
    """
    return BallScrew(
        pitch_diameter=0.040,
        lead=0.010,
        ball_diameter=6.35e-3,
        contact_angle=math.radians(45.0),
        conformity_screw=0.55,
        conformity_nut=0.55,
        loaded_turns=2.5,
        circuits=2,
        nut="double",
        preload=2000.0,
    )


def nut_length(screw: BallScrew) -> float:
    """Threaded length of the nut [m]: its loaded turns plus a return turn per circuit.

    Twice that for a double nut.

    Examples
    --------
    >>> from ballscrew import reference_screw
    >>> round(nut_length(reference_screw()), 3)  # (2.5 + 1) x 2 circuits x 10 mm, twice
    0.14
    """
    s = screw
    return (s.loaded_turns + 1.0) * s.circuits * s.lead * (2.0 if s.nut == "double" else 1.0)
