"""Whether the load ramps at a circuit's ends give the ball train a force linear in preload.

Research for issue 38, not part of the model. Run from the repository root with
``PYTHONPATH=src .venv/bin/python scripts/ball_train_ramp.py`` (about eight minutes).

The tolerance train (``ball_train="tolerance"``) grows as Q^(2/3) with the ball load Q,
so the screw torque's preload exponent is 0.73 where the makers' rule needs about 1. This tries
a load-dependent offset: the elastic shift of the contact angle. Two grooves whose
curvature centres are A = (f_s + f_n - 1) D_w apart (unloaded) and keep their radial
separation A cos(alpha0) while the nut is pushed along the axis give a ball with normal
approach delta (both contacts) the contact angle

    cos(alpha) = cos(alpha0) * A / (A + delta)

(Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2007, vol. 1, ch. 7, the
thrust-loaded bearing: delta = A (cos(alpha0)/cos(alpha) - 1)). The balls of the bulk of
a circuit carry the load Q; over a lead-in ("ramp") of m balls at each end of the loaded
zone the load rises linearly, q_j = Q j/(m + 1), j = 1..m, so those balls lie at smaller
contact angles and want a different orbital speed (k = dln(omega_m)/d(alpha),
``ballscrew.ball_train.orbital_sensitivity``). A train of N = 49 balls is solved ball by
ball with the nonlinear creep law of ``ballscrew.ball_train`` (``rolling_creep_integrals``
tables), each ball with its own load, contact size, mixed-film coefficient and so its
own creep stiffness; ``train_by_ball`` gives every ball the same two contacts, so this
script carries its own solver, generalised to per-ball contacts and vectorised over
draws, and checks it against ``train_by_ball`` on uniform contacts.

It prints, on the reference screw (40 x 10 mm, 6.35 mm balls, double nut, mineral ISO
VG 68, 40 C):

1. the Hertz approach of the loaded ball and the contact-angle shift at 1, 2, 4 kN;
2. for m = 5 at 2 kN: the largest creep ratio v_c k |d alpha| / (|omega_s| a) of a ramp
   ball (saturation needs about 1), and the ramp alone with the offsets' sign reversed
   (a lead-in made by deepening the groove radially instead of shifting it along the axis
   turns the angle the other way; the mean compression must not change);
3. for m = 0 (no ramp), 1, 2, 4, 5 (about a quarter turn here) and 10 with the random
   contact-angle scatter (the fitted 0.286 deg, 300 common draws), and for m = 1 to 24
   (24: the whole train a ramp, the largest the mechanism can give) without it: the mean
   compression between neighbours, the ball-ball dissipation and the train's whole
   dissipation (ball-ball sliding plus groove creep) of the screw as a torque, their
   ratio to the random-only train, and the preload exponents from 1 to 4 kN, at 10 and
   100 rpm;
4. two variants at 100 rpm: the random train with the ramp balls' loads but without their
   angle shift (how much the soft ramp balls alone take away), and a lead-in whose relief
   is fixed in micrometres (linear in approach over m = 5, 10, 20 balls, as deep as 1 to 3
   times the bulk's approach at 2 kN; the balls' loads balance the preload), so that the
   number of loaded balls grows with the preload: the train torque at 2 kN against the
   train without ramps, the preload exponents of the train torque with and without the
   angle shift, and of the whole screw torque (the complete model's other mechanisms
   added) from 1 to 4 and 4 to 8 kN.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.ball_train import _creep_table, orbital_sensitivity, train_by_ball
from ballscrew.friction._common import limiting_shear, model_state
from ballscrew.friction.complete import CONTACT_ANGLE_SCATTER, ball_ball_friction
from ballscrew.kinematics import kinematics, neighbour_sliding, rpm_to_rad_s

BALLS = 49
RAMPS = (0, 1, 2, 4, 5, 10)  # with the random scatter
RAMPS_ALONE = (1, 2, 4, 5, 10, 24)  # 24: the whole train of 49 is ramps, the upper bound
PRELOADS = (1000.0, 2000.0, 4000.0)
SPEEDS = (10.0, 100.0)
DRAWS = 300
MU_BL = 0.1
SLIDING = float(neighbour_sliding(reference_screw(), 1.0))  # ball-ball sliding per screw speed


@dataclass(frozen=True)
class Ball:
    """One ball's contacts at a load: screw and nut, per unit screw speed."""

    load: float  # [N]
    approach: float  # both contacts [m]
    capacity: tuple[float, float]  # mu Q [N]
    scale: tuple[float, float]  # |omega_s| a / omega [m]
    aspect: tuple[float, float]


def loaded_angle(alpha0: float, spread: float, approach: float) -> float:
    """Contact angle of a ball with normal approach ``approach`` (Harris & Kotzalas, ch. 7)."""
    return math.acos(math.cos(alpha0) * spread / (spread + approach))


def ball_at(screw, oil, rpm: float, preload: float):  # type: ignore[no-untyped-def]
    """A ball of the reference nut at the load a preload gives (the model's own contacts)."""
    state = model_state(screw.replace(preload=preload), oil, rpm_to_rad_s(rpm), 40.0, 0.0,
                        hertz_method="exact", asperity_b=1.42, asperity_c=0.8,
                        state=None)  # fmt: skip
    tau0, gamma_l = limiting_shear(oil, None, None)
    unit = kinematics(screw, 1.0)
    spin = {"screw": abs(float(unit.spin_screw)), "nut": abs(float(unit.spin_nut))}
    by_name = {c.name: c for c in state.contacts}
    cap, scale, aspect, approach = [], [], [], 0.0
    for name in ("screw-1", "nut-1"):
        c = by_name[name]
        q = float(np.ravel(c.load)[0])
        p_mean = 2.0 / 3.0 * float(np.ravel(c.hertz.p_max)[0])
        mu = float(np.ravel(rl.mixed_friction_coefficient(
            c.asperity_share, MU_BL, rl.limiting_traction_coefficient(tau0, gamma_l, p_mean)
        ))[0])  # fmt: skip
        cap.append(mu * q)
        scale.append(spin[c.side] * float(np.ravel(c.hertz.a)[0]))
        aspect.append(1.0 / float(np.ravel(c.hertz.ellipticity)[0]))
        approach += float(np.ravel(c.hertz.approach)[0])
    ball = Ball(q, approach, (cap[0], cap[1]), (scale[0], scale[1]), (aspect[0], aspect[1]))
    return ball, state, by_name["screw-1"], tau0, gamma_l


def ramp_train(screw, oil, rpm: float, preload: float, m: int, bulk: Ball,  # type: ignore[no-untyped-def]
               relief: float | None = None, shift: bool = True):  # fmt: skip
    """Contact-angle offsets from the bulk [rad] and the contacts (2, N) of a train with ramps.

    The ramp's loads rise linearly, q_j = Q j/(m + 1), the bulk at the model's ball load Q.
    With ``relief`` [m] the groove is relieved instead by a fixed depth profile,
    r_j = relief (1 - j/(m + 1)) at the j-th ball from an end: the nut's common axial
    displacement gives every ball the approach delta_b - r_j, with delta_b such that the
    loads (Hertz, q proportional to approach^(3/2)) still carry the preload of N balls at
    the model's Q; a ball left without approach is unloaded and leaves the train.
    ``shift=False`` keeps the ramp balls' loads but not their angle shift.
    """
    from scipy.optimize import brentq

    alpha0 = screw.contact_angle
    spread = (screw.conformity_screw + screw.conformity_nut - 1.0) * screw.ball_diameter
    ends = [min(i + 1, BALLS - i) for i in range(BALLS)]  # position from the nearer end
    if relief is None:
        balls = [
            ball_at(screw, oil, rpm, preload * j / (m + 1))[0] if j <= m else bulk for j in ends
        ]
        a_bulk = loaded_angle(alpha0, spread, bulk.approach)
    else:
        r = np.array([relief * (1.0 - j / (m + 1)) if j <= m else 0.0 for j in ends])
        d0 = bulk.approach
        d_b = brentq(
            lambda d: float(np.sum(np.clip(d - r, 0.0, None) ** 1.5)) - BALLS * d0**1.5,
            d0, d0 + relief,
        )  # fmt: skip
        top = ball_at(screw, oil, rpm, preload * (d_b / d0) ** 1.5)[0]
        balls = [
            ball_at(screw, oil, rpm, preload * ((d_b - x) / d0) ** 1.5)[0] if x > 0.0 else top
            for x in r
            if d_b - x > 0.0
        ]
        a_bulk = loaded_angle(alpha0, spread, top.approach)
    offset = np.array([loaded_angle(alpha0, spread, x.approach) - a_bulk for x in balls])
    cap = np.array([[x.capacity[s] for x in balls] for s in (0, 1)])
    sc = np.array([[x.scale[s] for x in balls] for s in (0, 1)])
    return offset * (1.0 if shift else 0.0), cap, sc


def train_torque(natural, cap, sc, bulk, state, contact, tau0, gamma_l):  # type: ignore[no-untyped-def]
    """Mean compression [N], ball-ball and whole train torque of the screw [N m]."""
    comp, creep = solve(natural, cap, sc, bulk.aspect)
    mean = float(comp.mean())
    mu_bb = float(np.ravel(ball_ball_friction(
        state, contact, np.array(mean), MU_BL, tau0, gamma_l, asperity_b=1.42, asperity_c=0.8,
    ))[0])  # fmt: skip
    trains = 2 * state.screw.circuits  # a double nut: one train per circuit of each half
    bb = trains * mu_bb * float(comp.sum(axis=1).mean()) * SLIDING
    return mean, bb, bb + trains * float(creep.mean())


def solve(natural: np.ndarray, capacity: np.ndarray, scale: np.ndarray, aspect: tuple):  # type: ignore[no-untyped-def,type-arg]
    """Trains ball by ball: natural speeds (draws, N); capacity, scale (2, N) per contact.

    Returns the compressions (draws, N - 1) and each draw's creep power over the screw
    speed [N m]. The same steps as ``train_by_ball`` (bisection for the split of each
    ball's creep between its contacts, then the common speed), with per-ball contacts and
    a bisection over the common speed for all draws at once.
    """
    tables = [_creep_table(a) for a in aspect]

    def force(side: int, creep: np.ndarray) -> np.ndarray:  # type: ignore[type-arg]
        s, _, g = tables[side]
        return np.sign(creep) * capacity[side] * np.interp(np.abs(creep) / scale[side], s, g)

    def split(total: np.ndarray) -> np.ndarray:  # type: ignore[type-arg]
        lo, hi = np.minimum(total, 0.0), np.maximum(total, 0.0)
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            excess = force(0, mid) - force(1, total - mid)
            lo, hi = np.where(excess > 0.0, lo, mid), np.where(excess > 0.0, mid, hi)
        return 0.5 * (lo + hi)

    def traction(speed: np.ndarray):  # type: ignore[no-untyped-def,type-arg]
        total = 2.0 * (speed[:, None] - natural)
        creep = split(total)
        return -2.0 * force(0, creep), creep, total

    span = 2.0 * np.ptp(natural, axis=1) + 1e-30
    lo, hi = natural.mean(axis=1) - span, natural.mean(axis=1) + span
    for _ in range(50):  # the summed traction falls as the common speed rises
        mid = 0.5 * (lo + hi)
        up = traction(mid)[0].sum(axis=1) > 0.0
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
    t, creep, total = traction(0.5 * (lo + hi))
    t = t - t.mean(axis=1, keepdims=True)  # the residual of the bisection, spread evenly
    sums = np.concatenate((np.zeros((t.shape[0], 1)), np.cumsum(t, axis=1)), axis=1)
    sums[:, -1] = 0.0
    compression = sums[:, 1:-1] - sums.min(axis=1, keepdims=True)
    power = np.zeros(t.shape[0])
    for side, dv in enumerate((creep, total - creep)):
        s, j, _ = tables[side]
        sigma = np.abs(dv) / scale[side]
        power += np.sum(capacity[side] * 1.5 / math.pi * scale[side]
                        * (np.interp(sigma, s, j) - j[0]), axis=1)  # fmt: skip
    return compression, power


def main() -> None:
    """Run the study and print its tables."""
    warnings.simplefilter("ignore")
    screw = reference_screw()
    oil = lubricants.get("mineral ISO VG 68")
    alpha0 = screw.contact_angle
    spread = (screw.conformity_screw + screw.conformity_nut - 1.0) * screw.ball_diameter
    k = orbital_sensitivity(screw.ball_diameter, screw.pitch_diameter, alpha0)
    unit = kinematics(screw, 1.0)
    centre = float(unit.orbital_speed) * 0.5 * screw.pitch_diameter / math.cos(screw.lead_angle)
    rng = np.random.default_rng(20261127)
    unit_draws = rng.standard_normal((DRAWS, BALLS))

    print("1. Elastic contact-angle shift, cos(alpha) = cos(alpha0) A/(A + delta), "
          f"A = {spread * 1e3:.4f} mm, alpha0 = {math.degrees(alpha0):.1f} deg")  # fmt: skip
    print("   preload  Q [N]  delta [um]  alpha(Q) [deg]  alpha(Q)-alpha0 [deg]  "
          "linear delta/(A tan alpha) [deg]")  # fmt: skip
    for f in PRELOADS:
        b = ball_at(screw, oil, 100.0, f)[0]
        a_q = loaded_angle(alpha0, spread, b.approach)
        print(f"   {f / 1e3:4.0f} kN  {b.load:6.2f}  {b.approach * 1e6:9.3f}  "
              f"{math.degrees(a_q):13.4f}  {math.degrees(a_q - alpha0):20.4f}  "
              f"{math.degrees(b.approach / (spread * math.tan(alpha0))):20.4f}")  # fmt: skip

    # Check the per-ball solver against train_by_ball on uniform contacts.
    b, *_ = ball_at(screw, oil, 100.0, 2000.0)
    natural = centre * (1.0 + k * CONTACT_ANGLE_SCATTER * unit_draws[:3])
    cap = np.array([[b.capacity[0]] * BALLS, [b.capacity[1]] * BALLS])
    sc = np.array([[b.scale[0]] * BALLS, [b.scale[1]] * BALLS])
    mine, _ = solve(natural, cap, sc, b.aspect)
    ref = [train_by_ball(v, tuple(zip(b.capacity, b.scale, b.aspect, strict=True))).compression
           for v in natural]  # type: ignore[arg-type]  # fmt: skip
    worst = max(float(np.max(np.abs(m - r)) / np.max(r)) for m, r in zip(mine, ref, strict=True))
    print(f"\nsolver check against train_by_ball (uniform contacts, 3 draws): largest "
          f"difference {worst:.1e} of the largest compression")  # fmt: skip

    # 2. The ramp balls' creep, and the sign of the offsets.
    offset, cap, sc = ramp_train(screw, oil, 100.0, 2000.0, 5, b)
    ratio = centre * k * np.abs(offset) / sc.min(axis=0)
    print("\n2. m = 5 at 2 kN: ramp balls' offsets [deg] "
          + " ".join(f"{math.degrees(x):.3f}" for x in offset[:5])
          + f"; largest creep ratio v_c k|d alpha|/(|omega_s| a) {ratio.max():.3f}")  # fmt: skip
    pair = [float(solve(centre * (1.0 + k * sign * offset[None, :]), cap, sc, b.aspect)[0].mean())
            for sign in (1.0, -1.0)]  # fmt: skip
    print(f"   ramp alone, mean compression {pair[0]:.4f} N; offsets reversed {pair[1]:.4f} N")

    for rpm in SPEEDS:
        print(f"\n3. Train of {BALLS} balls at {rpm:.0f} rpm, 40 C; per preload: mean compression "
              "[N], ball-ball torque and whole train torque (ball-ball + creep) of the screw "
              "[N m], ratios to the random-only train (m = 0)")  # fmt: skip
        results: dict[tuple[str, int, float], tuple[float, float, float]] = {}
        for f in PRELOADS:
            bulk, state, contact, tau0, gamma_l = ball_at(screw, oil, rpm, f)
            for m in sorted(set(RAMPS) | set(RAMPS_ALONE)):
                offset, cap, sc = ramp_train(screw, oil, rpm, f, m, bulk)
                for label, scatter in (("random", CONTACT_ANGLE_SCATTER), ("ramp only", 0.0)):
                    if (scatter > 0.0 and m not in RAMPS) or (scatter == 0.0 and m == 0):
                        continue
                    draws = unit_draws if scatter > 0.0 else unit_draws[:1]
                    natural = centre * (1.0 + k * (offset + scatter * draws))
                    mean, bb, whole = train_torque(natural, cap, sc, bulk, state, contact, tau0,
                                                   gamma_l)  # fmt: skip
                    results[(label, m, f)] = (mean, bb, whole)
        for label in ("random", "ramp only"):
            name = "with random scatter 0.286 deg" if label == "random" else "ramp alone"
            print(f"   {name}:")
            print("    m   " + "".join(f"  P@{f / 1e3:.0f}kN  T_bb   T_tr" for f in PRELOADS)
                  + "  | P/P0 T/T0 @2kN | exponent P  T_bb  T_tr")  # fmt: skip
            for m in RAMPS if label == "random" else RAMPS_ALONE:
                row = [results[(label, m, f)] for f in PRELOADS]
                base = results[("random", 0, 2000.0)]
                cells = "".join(f"  {p:6.3f} {bb:5.3f} {w:5.3f}" for p, bb, w in row)
                expo = [math.log(row[2][i] / row[0][i]) / math.log(4.0) for i in range(3)]
                print(f"   {m:3d}  {cells}  | {row[1][0] / base[0]:5.2f} {row[1][2] / base[2]:5.2f}"
                      f"     |        {expo[0]:5.2f} {expo[1]:5.2f} {expo[2]:5.2f}")  # fmt: skip

    variants(screw, oil, centre, k, unit_draws)


def other_torque(screw, oil, rpm: float, preload: float) -> float:  # type: ignore[no-untyped-def]
    """The complete model's torque less its ball-ball term [N m] (the tolerance train's run)."""
    r = friction_torque(screw.replace(preload=preload), oil, speed=rpm_to_rad_s(rpm),
                        temperature=40.0, axial_load=0.0, ball_train="tolerance")  # fmt: skip
    return float(r.total) - float(r.components["ball_ball"])


def variants(screw, oil, centre: float, k: float, unit_draws: np.ndarray) -> None:  # type: ignore[no-untyped-def,type-arg]
    """Section 4: the ramps' softness alone, and a relief fixed in micrometres."""
    rpm = 100.0
    print(f"\n4. Variants at {rpm:.0f} rpm, 40 C")
    bulk, state, contact, tau0, gamma_l = ball_at(screw, oil, rpm, 2000.0)
    args = (bulk, state, contact, tau0, gamma_l)
    scatter = CONTACT_ANGLE_SCATTER
    offset, cap, sc = ramp_train(screw, oil, rpm, 2000.0, 0, bulk)
    base = train_torque(centre * (1.0 + k * scatter * unit_draws), cap, sc, *args)[0]
    for m in (5, 10):
        offset, cap, sc = ramp_train(screw, oil, rpm, 2000.0, m, bulk, shift=False)
        soft = train_torque(centre * (1.0 + k * scatter * unit_draws), cap, sc, *args)[0]
        print(
            f"   random scatter, ramp loads of m = {m:2d} without their angle shift, 2 kN: "
            f"mean compression {soft:.3f} N = {soft / base:.3f} of the train without ramps"
        )
    print(
        "   relief fixed in micrometres: approach less than the bulk's by r_j = depth (1 - j/(m+1))"
    )
    print("   at the j-th ball from an end (depth in multiples of the bulk approach at 2 kN, the")
    print("   loads balancing the preload); loaded balls at 1, 2, 4, 8 kN; train torque at 2 kN")
    print("   over the train without ramps; preload exponents of the train torque with random")
    print("   scatter, with and without the angle shift (1-4 kN), and of the whole screw torque")
    print("    m  depth [um]   loaded balls    T/T0 | train 1-4  no shift | whole 1-4  whole 4-8")
    loads = (*PRELOADS, 8000.0)
    others = {f: other_torque(screw, oil, rpm, f) for f in loads}
    flat0: dict[float, float] = {}
    for f in loads:
        bulk_f, state_f, contact_f, *_ = ball_at(screw, oil, rpm, f)
        _, cap, sc = ramp_train(screw, oil, rpm, f, 0, bulk_f)
        natural = centre * (1.0 + k * scatter * unit_draws)
        flat0[f] = train_torque(natural, cap, sc, bulk_f, state_f, contact_f, tau0, gamma_l)[2]
    for m in (5, 10, 20):
        for depth in (1.0, 2.0, 3.0):
            torque, plain, loaded = {}, {}, {}
            for f in loads:
                bulk_f, state_f, contact_f, *_ = ball_at(screw, oil, rpm, f)
                a = (bulk_f, state_f, contact_f, tau0, gamma_l)
                relief = depth * bulk.approach
                offset, cap, sc = ramp_train(screw, oil, rpm, f, m, bulk_f, relief=relief)
                n = loaded[f] = offset.size
                natural = centre * (1.0 + k * (offset + scatter * unit_draws[:, :n]))
                torque[f] = train_torque(natural, cap, sc, *a)[2]
                natural = centre * (1.0 + k * scatter * unit_draws[:, :n])
                plain[f] = train_torque(natural, cap, sc, *a)[2]

            def slope(t: dict[float, float], lo: float, hi: float, add: bool = False) -> float:
                extra = others if add else dict.fromkeys(loads, 0.0)
                return math.log((t[hi] + extra[hi]) / (t[lo] + extra[lo])) / math.log(hi / lo)

            print(f"   {m:2d}  {depth * bulk.approach * 1e6:8.1f}  "
                  + " ".join(f"{loaded[f]:2d}" for f in loads)
                  + f"  {torque[2000.0] / flat0[2000.0]:6.2f} |"
                  f"  {slope(torque, 1000.0, 4000.0):8.2f}  {slope(plain, 1000.0, 4000.0):8.2f} |"
                  f"  {slope(torque, 1000.0, 4000.0, True):8.2f}"
                  f"  {slope(torque, 4000.0, 8000.0, True):9.2f}")  # fmt: skip
    whole = [math.log((others[hi] + flat0[hi]) / (others[lo] + flat0[lo])) / math.log(hi / lo)
             for lo, hi in ((1000.0, 4000.0), (4000.0, 8000.0))]  # fmt: skip
    print(f"   without ramps: the whole screw torque's exponents {whole[0]:.2f} (1-4 kN), "
          f"{whole[1]:.2f} (4-8 kN); the other mechanisms [N m] "
          + ", ".join(f"{others[f]:.3f}" for f in loads))  # fmt: skip


if __name__ == "__main__":
    main()
