r"""What a ball screw can carry: its load ratings, its contact pressure and the rules a case obeys.

Every case is checked against the screw before anything is computed
(:func:`plausibility`), each rule with its limit and its source; beyond a
limit the finding is an error, near it a warning:

=====================  ===================================  =============================
quantity               error beyond                         warning beyond
=====================  ===================================  =============================
preload                20 % of C_a                          10 % of C_a (catalogues)
axial load             C_0a (on the loaded half-nut)        C_0a / 2, and C_a
contact pressure       4200 MPa                             4200 MPa / 2^(1/3) = 3334 MPa
stroke (``energy``)    the screw length                     the screw length less the nut
=====================  ===================================  =============================

**Static rating and contact pressure.** ISO 3408-5:2006 (section 5.1), as
ISO 76:2006 for ball bearings, defines the basic static axial load rating
:math:`C_{0a}` as the axial load that produces 4200 MPa at the centre of the
most heavily loaded ball contact, a permanent dent of about 1/10 000 of the
ball diameter. The pressure of a contact is Hertz's,
:math:`p_{max} = 3Q/(2\pi a b)` (:func:`ballscrew.contact.hertz`), and the
ball load :math:`Q` is the loaded family's axial force shared equally by its
:math:`z` balls, :math:`Q = F/(z\sin\alpha\cos\varphi)`
(:func:`ballscrew.loads.ball_loads`). Since :math:`p_{max}\propto Q^{1/3}`,
the load that reaches the limit is :math:`Q_0 = (4200\,\mathrm{MPa}/p_1)^3`
with :math:`p_1` the pressure under 1 N, and

.. math:: C_{0a} = Q_0\,z\,\sin\alpha\,\cos\varphi

is the rating that definition gives from the geometry
(:func:`static_rating_estimate`), used when neither the case nor the
designation's catalogue row gives one, and then stated as estimated. The
estimate counts :math:`z` as both rating estimates do, on the ball circle
(:func:`rating_balls_per_circuit`; "Balls of a turn" below), while the
contact pressure rule shares the load among the balls the helix holds, up to
:math:`1/\cos\varphi` more: at an estimated :math:`C_{0a}` the pressure is
4200 MPa times the cube root of the ratio of the two counts (where they
differ by one ball, 15 and 16 a turn at a lead angle of 17.7 deg: 4111 MPa),
so the rating's rule refuses first. The definition is the bearings' one: at
ISO 76's thrust-bearing grooves (radius 0.54 of the ball) this function
gives 0.972 of ISO 76's tabulated :math:`f_0` at every ball-position ratio
from 0.05 to 0.20. What it cannot know is the groove: :math:`Q_0` goes as
:math:`p_1^{-3}`, and from conformity 0.55 to 0.52 the rating grows 1.76
times. A case is estimated at its own conformity (the package's default 0.55
gives about 0.66 of what the makers print: on the safe side); the sizes no
catalogue prints are estimated at :data:`RATING_CONFORMITY`, the makers'
grooves.

**Dynamic rating.** :math:`C_a` gives a rating life of :math:`10^6`
revolutions, :math:`L_{10} = (C_a/F)^3\cdot 10^6` (ISO 3408-5, section 7.2):
an axial load above it is warned about (a life below a million turns). A case
without a rating from the file or the catalogue is not given one silently
(the preload rule is then not applied, the contact pressure rule still is);
where a rating must be had for a screw no catalogue prints, ``ballscrew
select``'s ISO-series candidates, :func:`dynamic_rating_estimate` gives the
rating by ISO 3408-5's scheme (each loaded turn a row of a thrust
angular-contact ball bearing rated as ISO 281 rates it, the loaded turns to
the power 0.86 and the lead angle's :math:`(\cos\varphi)^{1.3}`), stated as
estimated.

**One groove for both estimates.** At :data:`RATING_CONFORMITY` (0.525,
fitted once on ten catalogue rows, :data:`RATING_CONFORMITY` says how) the 25
bundled catalogue rows with a printed ball diameter get 0.962 of their printed
:math:`C_a` and 1.01 of their printed :math:`C_{0a}` (medians;
``ballscrew.select.pool.rating_scatter`` gives the spread). Fitted alone, each
rating asks nearly the same groove (0.5234 for :math:`C_a`, 0.5259 for
:math:`C_{0a}`): the fitted number is a groove, not a correction. Two of
the 25, HIWIN's internal-recirculation nuts (T4), get about 1.3 of their
printed :math:`C_a` and 1.56 of their :math:`C_{0a}` (their return takes part
of each turn, so fewer balls carry than a full turn holds); without them the
median of :math:`C_a` is 0.961.

**Balls of a turn.** Each loaded turn is rated as ISO 281 rates a row of a
thrust ball bearing, whose :math:`Z` balls lie on its pitch circle (a full
row holds :math:`\pi d_m/D_w`); the estimates count a turn's balls so,
:math:`\pi d_m/D_w` (:func:`rating_balls_per_circuit`), although the helix
of a turn is :math:`1/\cos\varphi` longer and holds that many more (5 % more
where the lead equals the diameter). The friction and the load share keep
the balls that really roll
(:attr:`~ballscrew.geometry.BallScrew.balls_per_circuit`); only the ratings
count on the circle. The makers' ratings ask for it: among HIWIN's cassette
single nuts of one size and ball (9 rows in 4 groups), the printed ratings
per turn (:math:`C_a/k^{0.86}`, :math:`C_{0a}/k`) fall with the lead angle
as :math:`\cos^{1.88}\varphi` and :math:`\cos^{1.33}\varphi`; the estimates
fall as :math:`\cos^{1.3}` and :math:`\cos^{1}` with the circle's count, and
only as :math:`\cos^{0.60}` and :math:`\cos^{-0.05}` with the helix's
(``tests/select/test_rating_estimates.py``). The printed ratings still fall
faster, by :math:`\cos^{0.58}` and :math:`\cos^{0.33}`: the count explains
about half the makers' fall with the lead angle for :math:`C_a` and 3/4 for
:math:`C_{0a}`, not all of it. Whether ISO 3408-5 counts a turn's balls so
could not be checked: its text was not at hand.

**Turns and lead angle.** The ratio estimated/printed has no trend with the
number of loaded turns: slopes in ln k of -0.016 for :math:`C_a` and +0.014
for :math:`C_{0a}` (with the helix's count -0.052 and -0.041; with ISO 281's
turn exponent 0.7 the one of :math:`C_a` is -0.18). Across the catalogue the
turns and the lead angle go together (the rows of two turns are all of 16 to
40 mm lead; over the single nuts ln k and ln cos of the lead angle correlate
at 0.96), so a trend with the turns was a trend with the lead angle: at one
geometry nuts that differ only in their circuits print :math:`C_a` in the
ratio of the circuits to the power 0.86 within 0.2 % (HIWIN's ground FSI
nuts, 17 pairs of 3 to 6 circuits, *Ballscrews & Accessories*
BS-08-2-EN-1704-K, Table 6.6; THK's BIF4010-5 against BNFN4010-5, one and
two circuits of 2.5 turns), and :math:`C_{0a}` in the ratio of the circuits:
the turn exponent is the makers' own (:data:`TURN_EXPONENT`).

**Preload.** Ball screw catalogues keep the preload within 10 % of
:math:`C_a` (THK, *General Catalog*, ball screws, "Preload"; HIWIN,
*Ballscrews*, "Preload"): above it a warning; above twice that, the bound
``preload_share`` also has, an error.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ..contact import hertz
from ..errors import BallScrewInputError, FloatArray, check_finite
from ..geometry import BallScrew
from ..loads import ball_loads

__all__ = [
    "LEAST_STATIC_OVER_DYNAMIC",
    "PRELOAD_SHARE_LIMIT",
    "PRELOAD_SHARE_SOURCE",
    "RATING_CONFORMITY",
    "STATIC_PRESSURE",
    "STATIC_RATING_SOURCE",
    "THRUST_ROW_FACTOR",
    "Finding",
    "Ratings",
    "dynamic_rating_estimate",
    "max_contact_pressure",
    "plausibility",
    "raise_errors",
    "rating_balls_per_circuit",
    "static_rating_estimate",
    "stroke_findings",
    "thrust_row_reduction",
]

STATIC_PRESSURE = 4200e6
"""The contact pressure that defines the static load rating [Pa] (ISO 3408-5, ISO 76)."""

STATIC_RATING_SOURCE = (
    "ISO 3408-5:2006 5.1, as ISO 76: C_0a is the axial load giving 4200 MPa at the most loaded "
    "ball contact, a permanent dent of 1/10 000 of the ball's diameter"
)
"""Where the static rating and the pressure limit come from."""

NEAR_STATIC = 0.5
"""Share of the static rating above which a load is warned about: a static safety factor below 2.

Ball screw catalogues (THK, HIWIN) ask for a static safety factor
:math:`C_{0a}/F_{max}` of 1 to 3 by duty.
"""

LEAST_STATIC_OVER_DYNAMIC = 1.10
"""The least C_0a/C_a of the bundled catalogue rows (35 rows: 1.10 to 3.84, median 2.57):
where a case gives no C_a, C_0a over it is the largest C_a the screw could have, so a
preload judged against it is never refused wrongly."""

PRELOAD_SHARE_LIMIT = 0.10
"""Share of C_a above which a preload is warned about [-] (twice it is refused)."""

PRELOAD_SHARE_SOURCE = (
    "ball screw catalogues keep the preload within 10 % of C_a (THK General Catalog and HIWIN "
    "Ballscrews, 'Preload'); twice that is refused, as for preload_share"
)
"""Where the preload rule comes from."""

TURN_EXPONENT = 0.86
"""Exponent of the number of loaded turns in a ball screw's dynamic rating [-], as ISO 3408-5
(5.2) is cited for it; ISO 281 combines the equal rows of a bearing to the power 0.7. A ball
screw's turns follow one another along one helix and share the load more evenly than a
bearing's rows. The standard's text (paywalled) was not at hand; the makers' printed ratings
confirm the number where nothing but the turns changes: HIWIN's ground FSI nuts of one size
and lead with 3 to 6 circuits (BS-08-2-EN-1704-K, Table 6.6, 17 pairs) and THK's BIF4010-5
and BNFN4010-5 (one and two circuits) print C_a in the ratio of the circuits to the power
0.86 within 0.2 % (with 0.7 they would miss by 4.7 to 11.7 %)."""

LEAD_ANGLE_EXPONENT = 1.3
"""Exponent of the cosine of the lead angle in the dynamic rating [-], as ISO 3408-5 (5.2) is
cited for it: the balls' axial share, cos(phi), and the longer rolling path per turn of a steep
helix. Not confirmed from the standard's text: at one size and ball the makers' ratings per
turn fall faster with the lead angle (cos^1.88) than this with the ball circle's count of a
turn's balls gives (cos^1.3; module docstring, "Balls of a turn")."""

THRUST_ROW_FACTOR = 0.947
r"""The constant of ISO 281's rating of a thrust ball bearing row over Lundberg and Palmgren's
capacity [-] (with :math:`\eta = 1 - \sin\alpha/3`, :func:`thrust_row_reduction`).

ISO 281's table of :math:`f_c` for thrust ball bearings (ANSI/ABMA 9 prints the same;
reprinted in *Machinery's Handbook*, 31st ed., "Values of f_c for Thrust Ball Bearings") is,
at 45, 60 and 75 deg and every ball-position ratio from 0.01 to 0.10, Lundberg and Palmgren's
capacity (:data:`LP_CONSTANT`, grooves of 0.54 ball diameter) times
:math:`0.947\,(1 - \sin\alpha/3)` within 0.1 % (``tests/select/test_rating_estimates.py``
checks it): the reductions the standard applies to the capacity of a thrust row.
ISO 281:2007 multiplies the table by :math:`b_m = 1.3` for contemporary steel; ISO 3408-5
(2006) is not taken to, since with it no single groove gives both the makers' C_a and C_0a
(at ISO 76's 0.54: C_a 1.05, C_0a 0.78 of the printed values)."""

RATING_CONFORMITY = 0.525
"""Groove conformity (radius over ball diameter, screw and nut) of the makers' ball screws,
fitted [-]: the conformity at which :func:`static_rating_estimate` and
:func:`dynamic_rating_estimate` reproduce printed ratings. No catalogue prints its grooves, and
physics does not give them, so the number was fitted once: the conformity minimising the sum
of squared ln(estimated/printed) of C_a and C_0a over the training rows, HIWIN's ten cassette
single nuts (FSC) of 14 to 32 mm (BS-08-2-EN-1704-K, Table 6.4), gives 0.5251, kept as 0.525
(fitted with a turn's balls counted on the ball circle, :func:`rating_balls_per_circuit`; with
the helix's count it was 0.5263). On them C_a is 0.974 (0.94 to 1.02) and C_0a 1.01 (0.96 to
1.08) of the printed values (medians, ranges; standard deviation of ln: 0.021 and 0.040).
Held out, HIWIN's eight FSC nuts of 40 to 63 mm: C_a 0.960 (0.95 to 0.99), C_0a 1.01 (0.98 to
1.10); standard deviation of ln 0.012 and 0.040. Fitted to one rating alone the rows ask
0.5234 (C_a) and 0.5259 (C_0a). The value lies between the grooves ISO 281 rates radial ball
bearings at (0.52 inner, 0.53 outer) and ISO 76's 0.54 for thrust bearings, closer than the
package's friction default 0.55 (:mod:`ballscrew.geometry`)."""

DYNAMIC_RATING_SOURCE = (
    "ISO 3408-5:2006, 5.2: Lundberg & Palmgren's contact capacities (Acta Polytech. Mech. Eng. "
    "Ser. 1, 1947) per loaded turn, its balls counted on the ball circle as a bearing row's, "
    "(cos phi)^1.3 for the lead angle, (loaded turns)^0.86"
)
"""Where the dynamic rating estimate comes from."""

LIFE_SOURCE = (
    "ISO 3408-5:2006, 7.2: rating life L10 = (C_a/F)^3 million revolutions, so a load above C_a "
    "gives less than a million turns"
)
"""Where the dynamic rating rule comes from."""


@dataclass(frozen=True)
class Ratings:
    """The load ratings a case is checked against [N], each with where it comes from.

    ``dynamic`` (:math:`C_a`) may be None (not given, not in the catalogue);
    ``static`` (:math:`C_{0a}`) is always known: given, from the catalogue, or
    estimated (:func:`static_rating_estimate`, ``static_estimated`` True).
    """

    dynamic: float | None
    dynamic_source: str
    static: float
    static_source: str
    static_estimated: bool = False


@dataclass(frozen=True)
class Finding:
    """One rule a case breaks or comes near: the field, its value, the limit and its source."""

    field: str
    value: str
    limit: str
    source: str
    error: bool

    def __str__(self) -> str:
        return f"{self.field} = {self.value} is above {self.limit} ({self.source})"

    def as_error(self) -> BallScrewInputError:
        """The finding as the input error it raises."""
        return BallScrewInputError(self.field, self.value, f"at most {self.limit} ({self.source})")


def _unit_pressure(screw: BallScrew) -> float:
    """Largest Hertz pressure of a ball's screw and nut contacts under a normal load of 1 N [Pa]."""
    return max(
        float(hertz(1.0, rx, ry, screw.reduced_modulus).p_max)
        for rx, ry in ((screw.rx_screw, screw.ry_screw), (screw.rx_nut, screw.ry_nut))
    )


def max_contact_pressure(screw: BallScrew, axial_load: npt.ArrayLike) -> FloatArray:
    r"""Hertz pressure at the centre of the most loaded ball contact [Pa], per axial load.

    :math:`p_{max} = p_1 Q^{1/3}` with :math:`Q` the normal load of a ball of
    the loaded family (preload and external load shared by
    :func:`ballscrew.loads.ball_loads`, the balls equally) and :math:`p_1` the
    larger pressure of the screw and nut contacts under 1 N (exact Hertz,
    :math:`p_{max} = 3Q/2\pi ab`, scaling as :math:`Q^{1/3}`).

    Examples
    --------
    The reference screw with its 2 kN preload and no load, 29 N per ball:

    >>> from ballscrew import reference_screw
    >>> print(f"{float(max_contact_pressure(reference_screw(), 0.0)) / 1e6:.0f} MPa")
    1061 MPa
    """
    fa = check_finite("axial_load", axial_load)
    q = ball_loads(screw, fa).normal_load_1
    result: FloatArray = _unit_pressure(screw) * np.cbrt(q)
    return result


def rating_balls_per_circuit(screw: BallScrew) -> int:
    r"""Balls of a circuit's loaded turns as the rating estimates count them, on the ball circle.

    .. math:: Z_i = \left\lfloor \frac{i\,\pi d_m}{D_w} \right\rfloor

    with :math:`i` the loaded turns of a circuit and :math:`d_m` the pitch
    diameter, rounded down (with spacer balls, every other place: half of
    that, rounded up). Each loaded turn is rated as ISO 281 rates a row of a
    thrust ball bearing, whose balls lie on its pitch circle; the helix of a
    turn is :math:`1/\cos\varphi` longer and holds that many more balls
    (:attr:`~ballscrew.geometry.BallScrew.balls_per_circuit`, the balls that
    really roll, which the friction and the load share count). Only the two
    rating estimates count on the circle: the makers' printed ratings fall
    with the lead angle faster than the helix's count lets the estimates
    fall, and the circle's count brings both ratings' trend with the loaded
    turns under 0.05 in ln k (module docstring, "Balls of a turn"). Whether
    ISO 3408-5 counts so could not be checked: its text was not at hand.

    Examples
    --------
    A 32 mm screw of 32 mm lead (17.7 deg) with 6.35 mm balls: 15 balls on a
    turn's ball circle, 16 along its helix:

    >>> import math
    >>> s = BallScrew(0.032, 0.032, 0.00635, math.radians(45), 0.525, 0.525, 1.0, 2, "single")
    >>> rating_balls_per_circuit(s), s.balls_per_circuit
    (15, 16)
    """
    places = math.floor(screw.loaded_turns * math.pi * screw.pitch_diameter / screw.ball_diameter
                        + 1e-9)  # fmt: skip
    balls = (places + 1) // 2 if screw.ball_separation == "spacer-balls" else places
    if balls < 1:
        raise BallScrewInputError(
            "loaded_turns",
            screw.loaded_turns,
            f"enough turns to hold one ball on the ball circle (a turn holds "
            f"{math.pi * screw.pitch_diameter / screw.ball_diameter:.3g}) for a rating estimate",
        )
    return balls


def static_rating_estimate(screw: BallScrew) -> float:
    r"""The static axial rating :math:`C_{0a}` the standard's definition gives [N]: an estimate.

    :math:`C_{0a} = (4200\,\mathrm{MPa}/p_1)^3 z \sin\alpha\cos\varphi`, the
    axial load on one flank whose equal share per ball reaches 4200 MPa at the
    more curved of the screw and nut contacts (module docstring; ISO 3408-5,
    5.1), with :math:`z` the balls of the nut's loaded turns counted on the
    ball circle (:func:`rating_balls_per_circuit` times the circuits). An
    estimate at the screw's own grooves: :math:`Q_0` goes as
    :math:`p_1^{-3}`, so the conformity sets it (module docstring).

    Examples
    --------
    HIWIN R40-10K5 (40 mm, 6.35 mm balls, 5 circuits of one turn, 95 balls),
    catalogue 184 kN; at the makers' grooves (:data:`RATING_CONFORMITY`) about
    184 kN, at the package's default 0.55 about 120 kN:

    >>> import math
    >>> s = BallScrew(0.04, 0.01, 0.00635, math.radians(45), 0.525, 0.525, 1.0, 5, "single")
    >>> round(static_rating_estimate(s) / 1e3), round(static_rating_estimate(
    ...     s.replace(conformity_screw=0.55, conformity_nut=0.55)) / 1e3)
    (184, 120)
    """
    q0 = (STATIC_PRESSURE / _unit_pressure(screw)) ** 3
    z = screw.circuits * rating_balls_per_circuit(screw)
    return q0 * z * math.sin(screw.contact_angle) * math.cos(screw.lead_angle)


def _kn(value: float) -> str:
    return f"{value / 1e3:.4g} kN"


def _force(value: float) -> str:
    """A force as typed: N below 10 kN, kN above."""
    return f"{value:.4g} N" if abs(value) < 1e4 else _kn(value)


def plausibility(
    screw: BallScrew,
    ratings: Ratings,
    axial_load: npt.ArrayLike,
    *,
    load_field: str = "operation.axial_load",
    preload_field: str = "screw.preload",
) -> list[Finding]:
    """The preload and the largest axial load against the ratings and the pressure limit.

    Returns the findings (errors first); :func:`raise_errors` raises the first
    error. See the module docstring for the rules.

    Examples
    --------
    500 kN on a 32 mm screw with 6.35 mm balls (static rating estimated at 91 kN):

    >>> import math
    >>> s = BallScrew(0.032, 0.01, 0.00635, math.radians(45), 0.55, 0.55, 1.0, 5, "single")
    >>> r = Ratings(None, "", static_rating_estimate(s), "estimated")
    >>> [f.field for f in plausibility(s, r, [0.0, 500e3]) if f.error]
    ['operation.axial_load', 'operation.axial_load']
    """
    fa = np.abs(np.ravel(check_finite("axial_load", axial_load)))
    f_max = float(fa.max()) if fa.size else 0.0
    found: list[Finding] = []
    dynamic, dynamic_source = ratings.dynamic, ratings.dynamic_source
    if dynamic is None:  # no C_a given: the largest it could be, from C_0a
        dynamic = ratings.static / LEAST_STATIC_OVER_DYNAMIC
        dynamic_source = (
            f"estimated as the largest it could be: C_0a ({ratings.static_source}) over "
            f"{LEAST_STATIC_OVER_DYNAMIC:g}, the least C_0a/C_a of the bundled catalogue rows; "
            "give screw.dynamic_load_rating"
        )
    if screw.preload > 0.0:
        share = screw.preload / dynamic
        refused = share > 2.0 * PRELOAD_SHARE_LIMIT
        bound = (2.0 if refused else 1.0) * PRELOAD_SHARE_LIMIT
        limit = f"{bound:.0%} of C_a = {_kn(dynamic)} ({dynamic_source})"
        if share > PRELOAD_SHARE_LIMIT:
            found.append(Finding(preload_field, f"{_force(screw.preload)} ({share:.1%} of C_a)",
                                 limit, PRELOAD_SHARE_SOURCE, refused))  # fmt: skip
    loaded = float(ball_loads(screw, f_max).axial_force_1)
    field = load_field if f_max > 0.0 else preload_field
    shown = _force(f_max if f_max > 0.0 else screw.preload)
    if loaded != f_max and f_max > 0.0:
        shown += f" ({_force(loaded)} on the loaded half-nut with the preload)"
    c0 = ratings.static
    c0_text = f"C_0a = {_kn(c0)} ({ratings.static_source})"
    if loaded > c0:
        found.append(Finding(field, shown, f"the static rating {c0_text}", STATIC_RATING_SOURCE,
                             True))  # fmt: skip
    elif loaded > NEAR_STATIC * c0:
        limit = f"half the static rating {c0_text}, a static safety factor of 2"
        found.append(Finding(field, shown, limit, "catalogues ask 1 to 3 by duty", False))
    if ratings.dynamic is not None and f_max > ratings.dynamic:
        life = (ratings.dynamic / f_max) ** 3 * 1e6
        found.append(Finding(load_field, f"{_force(f_max)} (rating life {life:.3g} revolutions)",
                             f"the dynamic rating C_a = {_kn(ratings.dynamic)} "
                             f"({ratings.dynamic_source})", LIFE_SOURCE, False))  # fmt: skip
    p = float(max_contact_pressure(screw, f_max))
    near = STATIC_PRESSURE / 2.0 ** (1.0 / 3.0)
    if p > STATIC_PRESSURE:
        found.append(Finding(field, f"{shown}: contact pressure {p / 1e6:.4g} MPa",
                             f"{STATIC_PRESSURE / 1e6:.0f} MPa for bearing steel",
                             STATIC_RATING_SOURCE, True))  # fmt: skip
    elif p > near:
        found.append(Finding(field, f"{shown}: contact pressure {p / 1e6:.4g} MPa",
                             f"{near / 1e6:.0f} MPa, the pressure of half the static load "
                             f"(4200 MPa / 2^(1/3))", STATIC_RATING_SOURCE, False))  # fmt: skip
    return sorted(found, key=lambda f: not f.error)


def stroke_findings(
    travel: float, length: float, nut_length: float, *, field: str, length_field: str
) -> list[Finding]:
    """The nut's travel [m] against the screw's length [m] (an error) and less the nut (a warning).

    The nut runs on the thread: its travel cannot exceed the screw's length,
    and with the nut's own length it should fit between the ends.

    Examples
    --------
    >>> [f.error for f in stroke_findings(5.0, 1.3, 0.1, field="--move stroke",
    ...                                   length_field="axis.screw_length")]
    [True]
    >>> stroke_findings(0.3, 1.3, 0.1, field="--move stroke", length_field="axis.screw_length")
    []
    """
    source = "the nut runs on the screw's thread"
    if travel > length:
        return [Finding(field, f"{travel * 1e3:.4g} mm",
                        f"{length_field} = {length * 1e3:.4g} mm", source, True)]  # fmt: skip
    if travel + nut_length > length:
        return [Finding(field, f"{travel * 1e3:.4g} mm",
                        f"{length_field} = {length * 1e3:.4g} mm less the nut's "
                        f"{nut_length * 1e3:.3g} mm", source, False)]  # fmt: skip
    return []


def raise_errors(findings: Sequence[Finding]) -> list[Finding]:
    """Raise the first error among ``findings``; return the warnings."""
    for f in findings:
        if f.error:
            raise f.as_error()
    return [f for f in findings if not f.error]


LP_CONSTANT = 98.1
"""Lundberg and Palmgren's constant of a ball-raceway contact's basic capacity [N/mm^1.8]
(Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., 2007, the chapters on fatigue life)."""


def thrust_row_reduction(contact_angle: npt.ArrayLike) -> FloatArray:
    r"""ISO 281's rating of a thrust ball bearing row over Lundberg and Palmgren's capacity [-].

    .. math:: \lambda\eta = 0.947\,(1 - \sin\alpha/3)

    with :math:`\alpha` the contact angle [rad] (:data:`THRUST_ROW_FACTOR` gives where it
    comes from: ISO 281's :math:`f_c` table for thrust ball bearings is Lundberg and
    Palmgren's capacity times this, within 0.1 %).

    Examples
    --------
    >>> import math
    >>> round(float(thrust_row_reduction(math.radians(45.0))), 4)
    0.7238
    """
    alpha = check_finite("contact_angle", contact_angle)
    result: FloatArray = THRUST_ROW_FACTOR * (1.0 - np.sin(alpha) / 3.0)
    return result


def dynamic_rating_estimate(screw: BallScrew) -> float:
    r"""The basic dynamic axial rating :math:`C_a` of one loaded flank [N]: Lundberg-Palmgren.

    Each loaded turn is taken as the row of a thrust angular-contact bearing
    whose :math:`Z` balls share the axial load equally, as ISO 3408-5 takes
    it, with :math:`Z` counted as a bearing row's, on the ball circle
    (:func:`rating_balls_per_circuit` over the turns of a circuit). The basic
    capacity of the screw (inner, upper signs) and nut (outer, lower signs)
    contacts, with :math:`D_w` in mm,

    .. math::

        Q_c = 98.1\left(\frac{2f}{2f-1}\right)^{0.41}
              \frac{(1\mp\gamma)^{1.39}}{(1\pm\gamma)^{1/3}}
              \left(\frac{\gamma}{\cos\alpha}\right)^{0.3} D_w^{1.8} Z^{-1/3},

    combine over the two raceways as lives do (Weibull slope 10/9),
    :math:`Q_{c,turn} = (Q_{c,s}^{-10/3} + Q_{c,n}^{-10/3})^{-3/10}`; a turn
    carries :math:`C_1 = \lambda\eta\,Q_{c,turn}\,Z\sin\alpha\,(\cos\varphi)^{1.3}`
    axially, with ISO 281's reduction of a thrust row :math:`\lambda\eta`
    (:func:`thrust_row_reduction`, 0.724 at 45 deg) and :math:`\varphi` the lead
    angle, and :math:`k` loaded turns (turns per circuit times circuits)
    :math:`C_a = k^{0.86}C_1`: ISO 3408-5:2006, 5.2 (:data:`TURN_EXPONENT`,
    :data:`LEAD_ANGLE_EXPONENT`; ISO 281 combines a bearing's equal rows as
    :math:`k^{0.7}`). Lundberg & Palmgren (1947); Harris & Kotzalas (2007).

    An estimate, at the screw's own grooves: at :data:`RATING_CONFORMITY`,
    the makers', the bundled catalogue rows get 0.962 of their printed value
    (median; the module docstring gives the spread).

    Examples
    --------
    HIWIN R40-10K5 (40 mm, 6.35 mm balls, 5 circuits of one turn), catalogue 63.4 kN:

    >>> import math
    >>> s = BallScrew(0.04, 0.01, 0.00635, math.radians(45), 0.525, 0.525, 1.0, 5, "single")
    >>> round(dynamic_rating_estimate(s) / 1e3, 1)
    60.4
    """
    d_w = screw.ball_diameter * 1e3
    alpha = screw.contact_angle
    gamma = screw.gamma
    z = rating_balls_per_circuit(screw) / screw.loaded_turns
    signs = np.array([1.0, -1.0])
    f = np.array([screw.conformity_screw, screw.conformity_nut])
    q_c = (
        LP_CONSTANT
        * (2 * f / (2 * f - 1)) ** 0.41
        * (1 - signs * gamma) ** 1.39
        / (1 + signs * gamma) ** (1 / 3)
        * (gamma / math.cos(alpha)) ** 0.3
        * d_w**1.8
        * z ** (-1 / 3)
    )
    q_turn = float(np.sum(q_c ** (-10 / 3)) ** -0.3) * float(thrust_row_reduction(alpha))
    c_1 = q_turn * z * math.sin(alpha) * math.cos(screw.lead_angle) ** LEAD_ANGLE_EXPONENT
    return float(c_1 * (screw.loaded_turns * screw.circuits) ** TURN_EXPONENT)
