"""A 4-point ball derived again from rigid-body motion, independently of the closed forms.

Nothing here uses the package's kinematics to set up the motion. The screw, seen from the
nut, turns about z and advances by its lead; its surface velocity at any point is the central
difference of that point's position over +-dt. The ball centre moves along the pitch helix at
speed V; the ball has angular velocity W (nut frame). Contacts sit at +-alpha in the normal
plane of the helix, two on the screw and two on the nut.

1. **The kinematic constraint.** "No slip along the groove at the four contact centres" is
   four linear equations in (V, W). They turn out to be consistent (rank 3, zero residual):
   pure rolling at all four centres is possible, with W having no radial component; the
   component of W along the groove is free (it moves the helix's transverse slip between
   the screw and the nut contacts). Spins and orbital speed follow, and are compared with
   :func:`ballscrew.kinematics.four_point_spin` and :func:`ballscrew.kinematics.kinematics`.
2. **The best-fitting motion.** With Coulomb friction on Hertz ellipses and fixed normal
   loads, a free ball's quasi-static motion makes the friction power stationary over its
   four velocity unknowns, and that power is convex in them: the ball runs at the minimum.
   The power is minimised directly on a grid over the four ellipses, the contact surface
   curved across the groove at the pressed radius 2fD_w/(2f+1), and compared with what the
   complete model charges a 4-point ball (spin and Heathcote sliding at the spins of
   :func:`four_point_spin`, plus the helix's transverse slip shared by
   :func:`ballscrew.helix.transverse_slip_loss`).
3. **Neighbouring balls.** Two neighbours turn alike; at their contact, on the line of
   centres along the groove, their surfaces slide at D_w |(W - w_m e_z) x t|.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest
from scipy.optimize import minimize

from ballscrew import reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.contact import hertz
from ballscrew.geometry import BallScrew
from ballscrew.helix import SlipContact, transverse_slip_loss
from ballscrew.kinematics import (
    differential_sliding,
    four_point_spin,
    kinematics,
    neighbour_sliding,
)

GEOMETRIES = [  # pitch diameter, lead, ball [mm]
    (40.0, 10.0, 6.35),
    (32.0, 5.0, 3.175),
    (25.0, 25.0, 3.969),
]
OMEGA = 10.0  # screw speed [rad/s]; every speed here is linear in it


def _screw(dm: float, lead: float, dw: float) -> BallScrew:
    return reference_screw().replace(
        pitch_diameter=dm * 1e-3, lead=lead * 1e-3, ball_diameter=dw * 1e-3,
        contact_angle=math.radians(45.0),
    )  # fmt: skip


@dataclass(frozen=True)
class _Contact:
    member: str  # "screw" or "nut"
    normal: np.ndarray  # unit vector from the ball centre to the contact


@dataclass(frozen=True)
class _Frame:
    rm: float
    lead: float
    radius: float
    lam: float
    t: np.ndarray  # rolling direction (helix tangent) at the ball centre
    centre: np.ndarray
    contacts: tuple[_Contact, ...]  # screw +, screw -, nut +, nut -


def _frame(screw: BallScrew) -> _Frame:
    rm, lead, alpha = screw.pitch_diameter / 2, screw.lead, screw.contact_angle
    lam = math.atan(lead / (2 * math.pi * rm))
    e_r, e_th, e_z = np.eye(3)
    t = math.cos(lam) * e_th + math.sin(lam) * e_z
    b = -math.sin(lam) * e_th + math.cos(lam) * e_z  # axial-like direction of the normal plane
    contacts = tuple(
        _Contact(member, side * math.cos(alpha) * e_r + sign * math.sin(alpha) * b)
        for member, side in (("screw", -1.0), ("nut", 1.0))
        for sign in (1.0, -1.0)
    )
    return _Frame(rm, lead, screw.ball_diameter / 2, lam, t, rm * e_r, contacts)


def _member_velocity(member: str, points: np.ndarray, lead: float) -> np.ndarray:
    """Surface velocity of the screw (or the nut, at rest) at ``points`` [m/s], nut frame."""
    if member == "nut":
        return np.zeros_like(points)
    dt = 1e-6  # central difference of a rigid screw motion: O(dt^2) ~ 1e-12 relative

    def position(time: float) -> np.ndarray:
        c, s = math.cos(OMEGA * time), math.sin(OMEGA * time)
        rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        return np.asarray(
            points @ rot.T + np.array([0.0, 0.0, OMEGA * time * lead / (2 * math.pi)])
        )

    return (position(dt) - position(-dt)) / (2 * dt)


def _rolling_solution(f: _Frame) -> tuple[np.ndarray, float, int]:
    """(V, W) with no slip along t at all four contact centres; the residual and the rank."""
    rows, rhs = [], []
    for c in f.contacts:
        lever = f.radius * c.normal
        v_member = _member_velocity(c.member, (f.centre + lever)[None, :], f.lead)[0]
        row = [1.0] + [float(np.cross(e, lever) @ f.t) for e in np.eye(3)]
        rows.append(row)
        rhs.append(float(v_member @ f.t))
    a, y = np.array(rows), np.array(rhs)
    sol, _, rank, _ = np.linalg.lstsq(a, y, rcond=None)
    w = sol[1:] - (sol[1:] @ f.t) * f.t  # the free component along t set to 0
    q = np.concatenate([[sol[0]], w])
    return q, float(np.max(np.abs(a @ q - y))), int(rank)


def _spin(f: _Frame, q: np.ndarray, c: _Contact) -> float:
    member_rate = OMEGA * np.eye(3)[2] if c.member == "screw" else np.zeros(3)
    return float((q[1:] - member_rate) @ c.normal)


def _orbital(f: _Frame, q: np.ndarray) -> float:
    return float(q[0] * math.cos(f.lam) / f.rm)


@pytest.mark.parametrize(("dm", "lead", "dw"), GEOMETRIES)
def test_four_contacts_can_all_roll_and_their_spins_are_four_point_spins(
    dm: float, lead: float, dw: float
) -> None:
    s = _screw(dm, lead, dw)
    f = _frame(s)
    q, residual, rank = _rolling_solution(f)
    # Four rolling conditions, rank 3: consistent, with one exact solution for (V, W_r, W_b).
    # The entrainment speed is ~1 m/s at this speed: 1e-12 m/s is rounding.
    assert rank == 3
    assert residual < 1e-12
    assert abs(float(q[1:] @ np.array([1.0, 0.0, 0.0]))) < 1e-9 * np.linalg.norm(q[1:])  # W_r = 0
    k = kinematics(s, OMEGA)
    s4, n4 = four_point_spin(s, OMEGA)
    # Central differences over 1e-6 s and a least-squares solve: 1e-8 relative is generous.
    assert _orbital(f, q) == pytest.approx(float(k.orbital_speed), rel=1e-8)
    spins = [_spin(f, q, c) for c in f.contacts]
    assert [abs(x) for x in spins] == pytest.approx(
        [float(s4), float(s4), float(n4), float(n4)], rel=1e-8
    )
    # The two contacts of a member spin in opposite senses about their own normals.
    assert spins[0] * spins[1] < 0 and spins[2] * spins[3] < 0
    # Against 2-point contact at the same orbital speed, each 4-point spin is about ten
    # times larger: the ball turns about the screw axis, tilted by alpha from its 2-point
    # axis, so that w_b tan(alpha) lies along every normal.
    assert float(s4) > 5 * float(k.spin_screw)


def _two_point_solution(f: _Frame) -> np.ndarray:
    """A 2-point ball on the line screw+ / nut-, with no spin about that line relative to the
    frame that follows its centre (the stated assumption of the package's 2-point kinematics)."""
    screw_c, nut_c = f.contacts[0], f.contacts[3]
    rows, rhs = [], []
    for c in (screw_c, nut_c):
        lever = f.radius * c.normal
        v_member = _member_velocity(c.member, (f.centre + lever)[None, :], f.lead)[0]
        rows.append([1.0] + [float(np.cross(e, lever) @ f.t) for e in np.eye(3)])
        rhs.append(float(v_member @ f.t))
    e_z = np.eye(3)[2]
    rows.append([-math.cos(f.lam) / f.rm * float(e_z @ screw_c.normal), *screw_c.normal])
    rhs.append(0.0)
    rows.append([0.0, *f.t])  # the free rotation about t set to 0
    rhs.append(0.0)
    return np.asarray(np.linalg.solve(np.array(rows), np.array(rhs)))


@pytest.mark.parametrize(("dm", "lead", "dw"), GEOMETRIES)
def test_two_point_spins_and_rolling_speed_match_kinematics(
    dm: float, lead: float, dw: float
) -> None:
    s = _screw(dm, lead, dw)
    f = _frame(s)
    q = _two_point_solution(f)
    k = kinematics(s, OMEGA)
    om_m = _orbital(f, q)
    assert om_m == pytest.approx(float(k.orbital_speed), rel=1e-8)
    assert abs(_spin(f, q, f.contacts[0])) == pytest.approx(float(k.spin_screw), rel=1e-8)
    assert abs(_spin(f, q, f.contacts[3])) == pytest.approx(float(k.spin_nut), rel=1e-8)
    w_rel = q[1:] - om_m * np.eye(3)[2]
    assert float(np.linalg.norm(np.cross(w_rel, f.t))) == pytest.approx(
        float(k.ball_speed), rel=1e-8
    )


@pytest.mark.parametrize(("dm", "lead", "dw"), GEOMETRIES)
def test_neighbouring_balls_slide_at_the_rigid_body_speed(
    dm: float, lead: float, dw: float
) -> None:
    # Neighbours turn alike and touch on their line of centres (along t): their surfaces
    # there slide at D_w |(W - w_m e_z) x t|, with W from the rolling solutions above.
    s = _screw(dm, lead, dw)
    f = _frame(s)
    e_z = np.eye(3)[2]
    for q, nut in ((_rolling_solution(f)[0], "single-4point"), (_two_point_solution(f), "double")):
        w_rel = q[1:] - _orbital(f, q) * e_z
        rigid = s.ball_diameter * float(np.linalg.norm(np.cross(w_rel, f.t)))
        # Central differences and a linear solve: 1e-8 relative is generous.
        assert float(neighbour_sliding(s.replace(nut=nut), OMEGA)) == pytest.approx(rigid, rel=1e-8)
    # The 4-point ball turns faster, by 1/cos(alpha): its axis is tilted by alpha from the
    # 2-point axis, and its contact points, R cos(alpha) from it, keep the rolling speed.
    four = float(neighbour_sliding(s.replace(nut="single-4point"), OMEGA))
    two = float(neighbour_sliding(s, OMEGA))
    assert four / two == pytest.approx(math.sqrt(2.0), rel=1e-12)


# --- the best-fitting motion: minimum Coulomb dissipation of a free ball ------------------
GRID = 200  # midpoint cells per unit-disk diameter on each ellipse


@dataclass(frozen=True)
class _Patch:
    points: np.ndarray  # (n, 3) material points of the contact surface
    normals: np.ndarray  # (n, 3) local unit normals
    surface: np.ndarray  # (n, 3) the member's surface velocity there
    weight: np.ndarray  # (n,) pressure times area [N]


def _patches(s: BallScrew, f: _Frame, load: float, four: bool) -> list[_Patch]:
    g = (np.arange(GRID) + 0.5) / GRID * 2.0 - 1.0
    gx, gy = np.meshgrid(g, g, indexing="ij")
    inside = gx**2 + gy**2 < 1.0
    x_unit, y_unit = gx[inside], gy[inside]
    # Hertz pressure 3Q/(2 pi a b) sqrt(1 - X^2 - Y^2) over cells of area a b (2/GRID)^2.
    weight = 3.0 * load / (2.0 * math.pi) * np.sqrt(1.0 - x_unit**2 - y_unit**2) * (2 / GRID) ** 2
    chosen = f.contacts if four else (f.contacts[0], f.contacts[3])
    out = []
    for c in chosen:
        side = c.member
        rx = s.rx_screw if side == "screw" else s.rx_nut
        ry = s.ry_screw if side == "screw" else s.ry_nut
        conformity = s.conformity_screw if side == "screw" else s.conformity_nut
        hz = hertz(load, rx, ry, s.reduced_modulus)
        a, b = float(hz.a), float(hz.b)  # a across the groove, b along it
        pressed = 2 * conformity * s.ball_diameter / (2 * conformity + 1)
        m = np.cross(c.normal, f.t)
        x, y = x_unit * b, y_unit * a
        points = (
            f.centre + f.radius * c.normal + np.outer(x, f.t) + np.outer(y, m)
            - np.outer(y**2 / (2 * pressed), c.normal)
        )  # fmt: skip
        normals = c.normal[None, :] - np.outer(y / pressed, m)
        normals /= np.linalg.norm(normals, axis=1)[:, None]
        out.append(_Patch(points, normals, _member_velocity(side, points, f.lead), weight))
    return out


def _power(q: np.ndarray, f: _Frame, patches: list[_Patch], mu: float) -> float:
    total = 0.0
    for p in patches:
        v = q[0] * f.t + np.cross(q[1:], p.points - f.centre) - p.surface
        v -= np.sum(v * p.normals, axis=1)[:, None] * p.normals  # tangential part
        total += mu * float(np.sum(p.weight * np.sqrt(np.sum(v * v, axis=1))))
    return total


def _minimum(f: _Frame, patches: list[_Patch], q0: np.ndarray, mu: float) -> float:
    scale = np.array([abs(q0[0])] + [float(np.linalg.norm(q0[1:]))] * 3)

    def power(z: np.ndarray) -> float:
        return _power(q0 + z * scale, f, patches, mu)

    p0 = power(np.zeros(4))
    result = minimize(power, np.zeros(4), method="Nelder-Mead",
                      options={"xatol": 1e-10, "fatol": 1e-12 * p0, "maxfev": 6000})  # fmt: skip
    result = minimize(power, result.x, method="Nelder-Mead",
                      options={"xatol": 1e-11, "fatol": 1e-13 * p0, "maxfev": 6000})  # fmt: skip
    return float(result.fun)


def _model_power(s: BallScrew, load: float, mu: float, four: bool) -> float:
    """What the complete model charges one ball [W]: spin + Heathcote sliding at each contact
    (rolling_losses.spin_sliding_integral) plus the helix slip's increment (helix)."""
    k = kinematics(s, OMEGA)
    c_s, c_n = differential_sliding(s, OMEGA)
    if four:
        s4, n4 = four_point_spin(s, OMEGA)
        spin = {"screw": abs(float(s4)), "nut": abs(float(n4))}
    else:
        spin = {"screw": abs(float(k.spin_screw)), "nut": abs(float(k.spin_nut))}
    curvature = {"screw": abs(float(c_s)), "nut": abs(float(c_n))}
    per_side = 2 if four else 1
    total = 0.0
    slips = []
    for side in ("screw", "nut"):
        rx = s.rx_screw if side == "screw" else s.rx_nut
        ry = s.ry_screw if side == "screw" else s.ry_nut
        hz = hertz(load, rx, ry, s.reduced_modulus)
        a, b = float(hz.a), float(hz.b)
        kappa = curvature[side] * a / spin[side]
        integral = float(rl.spin_sliding_integral(kappa, b / a))
        total += per_side * mu * 1.5 / math.pi * load * spin[side] * a * integral
        slips += [SlipContact(side, mu, load, a, b / a, spin[side] / OMEGA)] * per_side
    helix = transverse_slip_loss(slips, float(k.transverse_slip) / OMEGA)
    return total + float(helix.power) * OMEGA


@pytest.mark.slow
@pytest.mark.parametrize(("dm", "lead", "dw"), GEOMETRIES)
def test_a_free_four_point_ball_dissipates_what_the_model_charges(
    dm: float, lead: float, dw: float
) -> None:
    s = _screw(dm, lead, dw)
    f = _frame(s)
    load, mu = 30.0, 0.1
    q0, _, _ = _rolling_solution(f)
    minimum = _minimum(f, _patches(s, f, load, True), q0, mu)
    model = _model_power(s, load, mu, True)
    # Measured 0.08-0.22 %: the 200-cell midpoint rule (~0.1 % on the square-root pressure
    # edge), the zero-net-traction shift the model leaves out (second order in the creep), and
    # the Heathcote term the helix increment omits (helix.py: up to 0.6 %). 1 % bounds them.
    assert minimum == pytest.approx(model, rel=0.01)


@pytest.mark.slow
@pytest.mark.parametrize(("dm", "lead", "dw"), GEOMETRIES)
def test_a_free_two_point_ball_dissipates_about_what_the_model_charges(
    dm: float, lead: float, dw: float
) -> None:
    s = _screw(dm, lead, dw)
    f = _frame(s)
    load, mu = 30.0, 0.1
    minimum = _minimum(f, _patches(s, f, load, False), _two_point_solution(f), mu)
    model = _model_power(s, load, mu, False)
    # The model fixes the 2-point ball's spin about its contact line (axis normal to that
    # line); the free ball chooses it, putting more of the spin on the contact with the
    # smaller spin moment. The power is linear in that choice, and the two contacts' spin
    # moments differ by their ellipse sizes: measured -1.1 to +0.4 % here (the model's helix
    # increment also leaves Heathcote sliding out), hence 2 %.
    assert minimum == pytest.approx(model, rel=0.02)
