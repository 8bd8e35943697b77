"""The transverse slip of the helix: its integrals, the one-ball balance and the model's share."""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest
from scipy import integrate

from ballscrew import friction_torque, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.helix import SlipContact, ball_slip_balance, transverse_slip_loss
from ballscrew.kinematics import differential_sliding, kinematics
from ballscrew.state import operating_state
from shared import MINERAL

OIL = MINERAL
RPM = 2.0 * math.pi / 60.0


# --- the integrals ------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("kappa", "beta", "sigma"),
    [(0.0, 0.2, 0.1), (0.0, 0.2, 1.0), (0.35, 0.19, 0.6), (0.5, 0.6, 2.0), (0.0, 1.0, 0.3)],
)
def test_spin_slip_integrals_against_adaptive_quadrature(
    kappa: float, beta: float, sigma: float
) -> None:
    # The same integrals by scipy's adaptive dblquad over the disk (Cartesian, independent of
    # the polar rule). Where the pivot lies inside the ellipse (sigma < beta) |v| has a cone
    # point and v_y/|v| turns round it; the 12 x 96 rule then errs by up to 3e-3 in G for a
    # circle (3e-4 for the thin ellipses of ball screw contacts, beta ~ 0.2), 1e-4 in J.
    def speed(y: float, x: float) -> float:
        return math.hypot(kappa * y * y + y, beta * x + sigma)

    def weight(y: float, x: float) -> float:
        return math.sqrt(max(1 - x * x - y * y, 0.0))

    def lateral(y: float, x: float) -> float:
        v = speed(y, x)
        return weight(y, x) * (beta * x + sigma) / v if v > 0 else 0.0

    def bounds(x: float) -> float:
        return math.sqrt(1 - x * x)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        j_ref, _ = integrate.dblquad(
            lambda y, x: weight(y, x) * speed(y, x), -1, 1, lambda x: -bounds(x), bounds,
            epsabs=1e-10,
        )  # fmt: skip
        g_ref, _ = integrate.dblquad(lateral, -1, 1, lambda x: -bounds(x), bounds, epsabs=1e-10)
    j, g = rl.spin_slip_integrals(kappa, beta, sigma)
    assert float(j) == pytest.approx(j_ref, rel=5e-4)
    assert float(g) == pytest.approx(g_ref * 1.5 / math.pi, abs=3.5e-3 if beta == 1.0 else 5e-4)


def test_spin_slip_integrals_limits() -> None:
    # No slip: the spin integral and no net transverse force (odd in X). A slip far above
    # the spin's sliding: the whole contact slides one way, G -> 1 and J -> (2 pi / 3) sigma
    # (the integral of the Hertz weight over the disk), i.e. F = mu Q and P = mu Q dv.
    j0, g0 = rl.spin_slip_integrals(0.3, 0.25, 0.0)
    assert float(j0) == pytest.approx(float(rl.spin_sliding_integral(0.3, 0.25)), rel=1e-12)
    assert abs(float(g0)) < 1e-12
    j, g = rl.spin_slip_integrals(0.3, 0.25, 1e5)
    assert float(g) == pytest.approx(1.0, abs=1e-8)
    assert float(j) / 1e5 == pytest.approx(2 * math.pi / 3, rel=1e-8)
    # The force grows with the slip, monotonically, from 0 to 1.
    _, gs = rl.spin_slip_integrals(0.0, 0.2, np.linspace(0.0, 20.0, 81))
    assert np.all(np.diff(gs) > 0.0) and gs[-1] < 1.0


# --- the one-ball balance -----------------------------------------------------------------
def _reference_contacts(lead: float = 0.010, rpm: float = 100.0) -> tuple[list[SlipContact], float]:
    s = reference_screw().replace(lead=lead)
    st = operating_state(s, OIL, speed=rpm * RPM, temperature=40.0, hertz_method="exact")
    unit = kinematics(s, 1.0)
    c_s, c_n = differential_sliding(s, 1.0)
    spin = {"screw": float(unit.spin_screw), "nut": float(unit.spin_nut)}
    curv = {"screw": float(c_s), "nut": float(c_n)}
    contacts = []
    for c in st.contacts[:2]:  # family 1: one ball's screw and nut contact
        mu = float(rl.mixed_friction_coefficient(c.asperity_share, 0.1, 0.073))
        contacts.append(SlipContact(
            c.side, mu, float(c.load), float(c.hertz.a), float(c.hertz.b / c.hertz.a),
            spin[c.side], curv[c.side] / spin[c.side],
        ))  # fmt: skip
    return contacts, float(unit.transverse_slip)


@pytest.mark.parametrize("lead", [0.008, 0.010, 0.020, 0.040])
def test_vectorised_share_agrees_with_the_one_ball_reference(lead: float) -> None:
    # The stated error of the tabulated model, almost all from Heathcote sliding left out
    # of the increment (with it left out of the reference too they agree to 1e-6): within
    # 1 % of the reference's power (measured 0.3 % for 40 x 8, 0.02 % for 40 x 40) and 0.01
    # in the share of the slip at the screw (measured 0.0065 for 40 x 40).
    contacts, slip = _reference_contacts(lead)
    ref = ball_slip_balance(contacts, slip)
    fast = transverse_slip_loss(contacts, slip)
    assert float(fast.power) == pytest.approx(ref.power, rel=1e-2)
    assert float(fast.screw_share) == pytest.approx(ref.screw_share, abs=1e-2)
    assert float(fast.force) == pytest.approx(ref.force, rel=1e-2)
    no_heathcote = [dataclasses.replace(c, curvature=0.0) for c in contacts]
    ref0 = ball_slip_balance(no_heathcote, slip)
    # Interpolation and the root finder alone: 1e-5 (tables of 513 nodes, linear).
    assert float(fast.power) == pytest.approx(ref0.power, rel=1e-5)
    assert float(fast.screw_share) == pytest.approx(ref0.screw_share, abs=1e-5)
    # The balance holds in the reference: the screw side's force equals the nut side's.
    mu_q = [float(c.friction) * float(c.load) for c in contacts]  # type: ignore[arg-type]
    g = []
    for c, share in zip(contacts, (ref.screw_share, 1 - ref.screw_share), strict=True):
        sigma = share * slip / (c.spin * float(c.semi_axis))  # type: ignore[arg-type]
        g.append(float(rl.spin_slip_integrals(c.curvature * float(c.semi_axis), c.aspect,  # type: ignore[arg-type]
                                              sigma)[1]))  # fmt: skip
    assert mu_q[0] * g[0] == pytest.approx(mu_q[1] * g[1], rel=2e-3)
    # Each contact's normal force tilts by asin(F/Q), with F = mu Q G its traction, G from
    # the integrals computed above (not the reference's rule): F/Q = mu G, to 2e-3.
    for tilt, c, gj in zip(ref.tilt, contacts, g, strict=True):
        assert math.sin(tilt) == pytest.approx(float(c.friction) * gj, rel=2e-3)  # type: ignore[arg-type]


def test_without_spin_the_weaker_contact_takes_all_the_slip() -> None:
    # Spin negligible against the slip: plain Coulomb sliding. The moment balance caps the
    # common force at the weaker contact's mu Q, which then slides over the whole slip; the
    # other contact sticks. Dissipation min(mu Q) * slip.
    strong = SlipContact("screw", 0.1, 30.0, 0.26e-3, 0.2, 1e-6)
    weak = SlipContact("nut", 0.08, 30.0, 0.26e-3, 0.2, 1e-6)
    r = transverse_slip_loss([strong, weak], 2.5e-4)
    assert float(r.screw_share) == pytest.approx(0.0, abs=1e-4)
    assert float(r.force) == pytest.approx(0.08 * 30.0, rel=1e-4)
    assert float(r.power) == pytest.approx(0.08 * 30.0 * 2.5e-4, rel=1e-3)


def test_coulomb_limit_holds_however_small_the_spin() -> None:
    # Spin -> 0 (1e-20 of the screw speed): slip ratios sigma ~ 1e20, beyond the last node of
    # the tables (sigma / (1 + sigma) rounds to 1). The limit is plain Coulomb sliding: the
    # weaker contact (mu Q = 2.4 N) takes the whole slip and dissipates 2.4 N x slip. The
    # residual is a step here (G jumps from 0 to 1 within a share of 1e-20), which the solver
    # resolves to its bracket, 1e-9 of the share: tolerance 1e-8 on the share, and on the
    # power (the stronger contact's 3 N over 1e-9 of the slip adds 1.25e-9 of it). The force
    # then lies between the two capacities, which the step cannot tell apart.
    strong = SlipContact("screw", 0.1, 30.0, 0.26e-3, 0.2, 1e-20)
    weak = SlipContact("nut", 0.08, 30.0, 0.26e-3, 0.2, 1e-20)
    r = transverse_slip_loss([strong, weak], 2.5e-4)
    assert float(r.screw_share) == pytest.approx(0.0, abs=1e-8)
    assert float(r.power) == pytest.approx(0.08 * 30.0 * 2.5e-4, rel=1e-8)
    assert 0.08 * 30.0 * (1 - 1e-12) <= float(r.force) <= 0.1 * 30.0 * (1 + 1e-12)


@pytest.mark.parametrize("points", [1, 256])
@pytest.mark.parametrize("spin", [1e-20, 1e-200])
def test_coulomb_limit_with_exact_capacities_and_overflowing_slip_ratios(
    points: int, spin: float
) -> None:
    # The Coulomb limit again, with capacities exact in binary (0.125 x 24 N = 3 N on the
    # screw, 0.125 x 16 N = 2 N on the nut): fully sliding, the residual is 3 N - 2 N = 1 N
    # exactly, which must not stop the solver. With a spin of 1e-200 the slip ratios pass
    # 1e154, where (1 + sigma)^2 overflows to infinity (ignored here: it is meant to) and
    # the residual's slope vanishes: the solver must bisect. One point (the kernel as plain
    # Python) and 256 (compiled, with numba). Tolerances as in the test above: the nut takes
    # the slip to 1e-8 and dissipates 2 N x slip to 1e-8.
    contacts = [SlipContact("screw", np.full(points, 0.125), 24.0, 0.26e-3, 0.2, spin),
                SlipContact("nut", 0.125, 16.0, 0.26e-3, 0.2, spin)]  # fmt: skip
    with np.errstate(over="ignore"):
        r = transverse_slip_loss(contacts, 2.5e-4)
    np.testing.assert_allclose(r.screw_share, 0.0, rtol=0.0, atol=1e-8)
    np.testing.assert_allclose(r.power, 2.0 * 2.5e-4, rtol=1e-8)
    assert np.all((2.0 <= r.force) & (r.force <= 3.0 * (1 + 1e-12)))


@pytest.mark.parametrize("spins", [(0.35, 0.30), (0.02, 0.05), (1e-3, 2e-3), (5e-3, 2e-3)])
def test_contacts_equal_but_for_their_spin_share_at_equal_slip_ratios(
    spins: tuple[float, float],
) -> None:
    # Equal mu Q and equal b/a: both transverse forces are mu Q G(sigma) with the same G,
    # increasing in sigma, so the moment balance holds at equal slip ratios
    # sigma = share s / (|omega_s| a): the screw takes |w_s| / (|w_s| + |w_n|) of the slip,
    # exactly. From slips comparable to the spin's sliding (sigma ~ 1) to near-Coulomb
    # sliding (sigma ~ 300, where G is flat: 1 - G falls as 1/sigma^2).
    # Tolerance: the solver stops once |F_s - F_n| <= 1e-9 (mu Q_s + mu Q_n), or the share
    # moves by less than 1e-9. Where G is flat the force tolerance admits share errors of
    # 1e-9 x 2 mu Q / (dF/dx), dF/dx = mu Q G'(sigma) sigma (1/x + 1/(1 - x)) with G' from
    # the integrals themselves (central difference): allowed 4 times that, and 1e-9.
    mu, load, a, aspect, slip = 0.09, 30.0, 0.26e-3, 0.2, 2.5e-4
    w_s, w_n = spins
    c = [SlipContact("screw", mu, load, a, aspect, w_s),
         SlipContact("nut", mu, load, a, aspect, w_n)]  # fmt: skip
    x = w_s / (w_s + w_n)
    sigma = x * slip / (w_s * a)
    h = 1e-3 * sigma
    g_hi, g_lo = (
        float(rl.spin_slip_integrals(0.0, aspect, sig)[1]) for sig in (sigma + h, sigma - h)
    )
    rate = mu * load * (g_hi - g_lo) / (2 * h) * sigma * (1 / x + 1 / (1 - x))
    tolerance = 4 * 1e-9 * 2 * mu * load / rate + 1e-9
    r = transverse_slip_loss(c, slip)
    assert float(r.screw_share) == pytest.approx(x, abs=tolerance)


def test_share_does_not_depend_on_the_force_scale() -> None:
    # The balance mu Q_s G(sigma_s) = mu Q_n G(sigma_n) is homogeneous in the loads (the
    # semi-axes, hence the slip ratios, held): scaling both loads by 1e-6 (a ball near
    # lift-off), 1e-12 or 1e4 leaves the share, and scales the power and the force by the
    # same factor. The solver's force tolerance is relative to mu Q (1e-9 of 5 pN at 1e-12,
    # no absolute floor), so the scaled problems take the same steps: equal to rounding,
    # 1e-9 allowed.
    def pair(scale: float) -> list[SlipContact]:
        return [SlipContact("screw", 0.092, 30.0 * scale, 0.26e-3, 0.19, 0.39),
                SlipContact("nut", 0.080, 30.0 * scale, 0.25e-3, 0.22, 0.31)]  # fmt: skip

    base = transverse_slip_loss(pair(1.0), 1e-4)
    assert 0.05 < float(base.screw_share) < 0.95
    for scale in (1e-12, 1e-6, 1e4):
        r = transverse_slip_loss(pair(scale), 1e-4)
        assert float(r.screw_share) == pytest.approx(float(base.screw_share), abs=1e-9)
        assert float(r.power) == pytest.approx(scale * float(base.power), rel=1e-9)
        assert float(r.force) == pytest.approx(scale * float(base.force), rel=1e-9)


def test_without_curvature_only_the_slip_ratio_matters() -> None:
    # Without Heathcote sliding (no curvature given) a contact enters the balance through
    # sigma = share s / (|omega_s| a) alone, and its power as mu Q |omega_s| a J(sigma):
    # growing the semi-axes and the slip together by 1000 leaves the share and the force and
    # multiplies the power by 1000, in the reference and in the tables. Both solve the same
    # dimensionless problem: equal to their tolerances (1e-13 Brent, 1e-9 Newton); 1e-9.
    def pair(size: float) -> list[SlipContact]:
        return [SlipContact("screw", 0.092, 30.0, 0.26e-3 * size, 0.19, 0.39),
                SlipContact("nut", 0.080, 30.0, 0.25e-3 * size, 0.22, 0.31)]  # fmt: skip

    for solve in (ball_slip_balance, transverse_slip_loss):
        small, large = solve(pair(1.0), 1e-4), solve(pair(1e3), 1e-1)
        assert float(large.screw_share) == pytest.approx(float(small.screw_share), abs=1e-9)
        assert float(large.force) == pytest.approx(float(small.force), rel=1e-9)
        assert float(large.power) == pytest.approx(1e3 * float(small.power), rel=1e-9)


def test_equal_contacts_share_equally_and_the_force_lies_below_coulomb() -> None:
    c = [SlipContact(side, 0.09, 30.0, 0.26e-3, 0.2, 0.35) for side in ("screw", "nut")]
    r = transverse_slip_loss(c, 2.5e-4)
    assert float(r.screw_share) == pytest.approx(0.5, abs=1e-9)
    assert 0.0 < float(r.force) < 0.09 * 30.0
    # The slip also lowers the spin's own dissipation: less than the Coulomb bound.
    assert 0.0 < float(r.power) < 0.09 * 30.0 * 2.5e-4


def test_four_point_ball_with_equal_families_is_two_two_point_balls() -> None:
    # Four contacts, one slip per member: with both families equal, the moment balance sums
    # twice the same forces; the share is the 2-point one and the power doubles.
    contacts, slip = _reference_contacts()
    two = transverse_slip_loss(contacts, slip)
    four = transverse_slip_loss(contacts + contacts, slip)
    assert float(four.screw_share) == pytest.approx(float(two.screw_share), abs=1e-9)
    assert float(four.power) == pytest.approx(2 * float(two.power), rel=1e-9)


def test_arrays_equal_point_by_point_and_unloaded_balls_add_nothing() -> None:
    mus = np.array([0.06, 0.09, 0.1])
    loads = np.array([[10.0], [0.0], [60.0]])  # (3, 1) against (3,): a 3 x 3 grid
    axes = 0.26e-3 * (loads / 30.0) ** (1 / 3)
    contacts = [
        SlipContact("screw", mus, loads, axes, 0.19, 0.39),
        SlipContact("nut", 0.085, loads, axes, 0.22, 0.31),
    ]
    grid = transverse_slip_loss(contacts, 2.5e-4)
    assert grid.power.shape == (3, 3)
    for i in range(3):
        for j in range(3):
            alone = transverse_slip_loss(
                [SlipContact("screw", mus[j], loads[i, 0], axes[i, 0], 0.19, 0.39),
                 SlipContact("nut", 0.085, loads[i, 0], axes[i, 0], 0.22, 0.31)], 2.5e-4,
            )  # fmt: skip
            assert float(grid.power[i, j]) == pytest.approx(float(alone.power), rel=1e-9)
    assert np.all(grid.power[1] == 0.0) and np.all(grid.force[1] == 0.0)


def test_a_contact_that_carries_nothing_takes_the_slip_for_free() -> None:
    # Screw contact loaded, nut contact unloaded (and the reverse): no transverse force can
    # be balanced, so the ball slips at the free contact and nothing is dissipated.
    loaded = SlipContact("screw", 0.09, 30.0, 0.26e-3, 0.2, 0.39)
    free = SlipContact("nut", 0.09, 0.0, 0.0, 0.2, 0.31)
    r = transverse_slip_loss([loaded, free], 2.5e-4)
    assert float(r.screw_share) == 0.0 and float(r.power) == 0.0 and float(r.force) == 0.0
    pair = [SlipContact("screw", 0.09, 0.0, 0.0, 0.2, 0.39),
            SlipContact("nut", 0.09, 30.0, 0.26e-3, 0.2, 0.31)]  # fmt: skip
    r = transverse_slip_loss(pair, 2.5e-4)
    assert float(r.screw_share) == 1.0 and float(r.power) == 0.0


@pytest.mark.parametrize("load", [0.4, 3.0, 300.0])
def test_light_and_heavy_balls_share_as_the_reference_does(load: float) -> None:
    # The balance does not depend on the force scale: from a ball that carries a fraction of
    # a newton to a heavily loaded one, the share follows the reference (the tables' linear
    # interpolation errs most, 1.5e-5, where the slip ratio is near the ellipse's b/a).
    a = 0.26e-3 * (load / 30.0) ** (1 / 3)
    c = [SlipContact("screw", 0.092, load, a, 0.19, 0.39),
         SlipContact("nut", 0.080, load, 0.97 * a, 0.22, 0.31)]  # fmt: skip
    ref, fast = ball_slip_balance(c, 1e-4), transverse_slip_loss(c, 1e-4)
    assert float(fast.screw_share) == pytest.approx(ref.screw_share, abs=3e-5)
    assert float(fast.power) == pytest.approx(ref.power, rel=3e-5)
    assert 0.05 < ref.screw_share < 0.95


def test_reference_without_heathcote_by_default_equals_the_tables() -> None:
    # A contact given without its Heathcote coefficient has none: the reference solver and
    # the tabulated one then solve the same balance (1e-5: interpolation and tolerances).
    c = [SlipContact("screw", 0.092, 29.0, 0.265e-3, 0.19, 0.39),
         SlipContact("nut", 0.089, 29.0, 0.257e-3, 0.22, 0.31)]  # fmt: skip
    ref, fast = ball_slip_balance(c, 1e-4), transverse_slip_loss(c, 1e-4)
    assert float(fast.power) == pytest.approx(ref.power, rel=1e-5)
    assert float(fast.screw_share) == pytest.approx(ref.screw_share, abs=1e-5)


def test_bad_contacts_are_refused() -> None:
    c = SlipContact("screw", 0.1, 30.0, 0.26e-3, 0.2, 0.35)
    with pytest.raises(ValueError, match="screw and one nut"):
        transverse_slip_loss([c, c], 2.5e-4)
    with pytest.raises(ValueError, match="slip"):
        transverse_slip_loss([c, SlipContact("nut", 0.1, 30.0, 0.26e-3, 0.2, 0.35)], -1.0)


# --- in the complete model ----------------------------------------------------------------
@pytest.mark.parametrize("nut", ["double", "single-4point"])
def test_model_component_is_the_reference_balance_over_the_balls(nut: str) -> None:
    # The helix_slip torque equals the balls times the one-ball reference power, with each
    # contact's mixed-film coefficient recomputed from its state (tolerance: the stated
    # 1 % of the tabulated share).
    s = reference_screw().replace(nut=nut)
    w, temp = 300 * RPM, 40.0
    r = friction_torque(s, OIL, speed=w, temperature=temp, axial_load=500.0)
    st = operating_state(s, OIL, speed=w, temperature=temp, axial_load=500.0,
                         hertz_method="exact")  # fmt: skip
    unit = kinematics(s, 1.0)
    c_s, c_n = differential_sliding(s, 1.0)
    if nut == "double":
        spin = {"screw": float(unit.spin_screw), "nut": float(unit.spin_nut)}
    else:
        from ballscrew.kinematics import four_point_spin

        s4, n4 = four_point_spin(s, 1.0)
        spin = {"screw": abs(float(s4)), "nut": abs(float(n4))}
    curv = {"screw": float(c_s), "nut": float(c_n)}
    contacts = {}
    for c in st.contacts:
        p_mean = 2 / 3 * float(c.hertz.p_max)
        mu_ehl = OIL.limiting_shear_coefficient + OIL.limiting_shear_stress / p_mean
        share = float(c.asperity_share)
        contacts[c.name] = SlipContact(
            c.side, share * 0.1 + (1 - share) * mu_ehl, float(c.load), float(c.hertz.a),
            float(c.hertz.b / c.hertz.a), spin[c.side], curv[c.side] / spin[c.side],
        )  # fmt: skip
    slip = float(unit.transverse_slip)
    if nut == "double":
        expected = sum(
            st.contacts[2 * f].balls
            * ball_slip_balance([contacts[f"screw-{f + 1}"], contacts[f"nut-{f + 1}"]], slip).power
            for f in (0, 1)
        )
    else:
        expected = st.contacts[0].balls * ball_slip_balance(list(contacts.values()), slip).power
    assert float(r.components["helix_slip"]) == pytest.approx(expected, rel=1e-2)


def test_helix_slip_vanishes_with_the_lead_angle_and_grows_with_it() -> None:
    # 1/16 in balls, which fit between the turns of every lead from 2 mm (lambda 0.9 deg).
    s = reference_screw().replace(ball_diameter=1.5875e-3)
    kw = {"speed": 100 * RPM, "temperature": 40.0}
    values = [
        float(friction_torque(s.replace(lead=lead), OIL, **kw).components["helix_slip"])  # type: ignore[arg-type]
        for lead in (2e-3, 5e-3, 10e-3, 20e-3, 40e-3)
    ]
    # At least linear in tan(lambda) towards 0 (quadratic while the spin dominates).
    assert values[0] / values[2] < 2e-3 / 10e-3
    assert np.all(np.diff(values) > 0.0)
    # Large slip: towards the Coulomb bound mu F_pr D_w tan(lambda) / sin(alpha) of the
    # double nut, never above it (mu <= 0.1 here).
    lam = s.replace(lead=40e-3).lead_angle
    bound = 0.1 * s.preload * s.ball_diameter * math.tan(lam) / math.sin(s.contact_angle)
    assert 0.5 * bound < values[-1] < bound


@pytest.mark.parametrize("aspect", [0.12, 0.5, 1.0])
def test_table_slope_is_the_derivative_of_the_transverse_force(aspect: float) -> None:
    # The root finder's slope of G(sigma) comes from the table's intervals times
    # dt/dsigma = 1/(1+sigma)^2. Against a central difference of G evaluated directly by
    # the quadrature (no table): a chord slope over one interval differs from the tangent
    # by the curvature over half an interval, under 2 % at 513 nodes where G bends most.
    from ballscrew.helix import _lookup_g

    sigma = np.array([0.02, 0.1, 0.4, 1.0, 3.0, 12.0])
    h = 1e-4 * (1.0 + sigma) ** 2
    _, g_plus = rl.spin_slip_integrals(0.0, aspect, sigma + h)
    _, g_minus = rl.spin_slip_integrals(0.0, aspect, sigma - h)
    exact = (g_plus - g_minus) / (2.0 * h)
    g, slope = _lookup_g(aspect, sigma)
    np.testing.assert_allclose(slope, exact, rtol=0.02)
    np.testing.assert_allclose(g, rl.spin_slip_integrals(0.0, aspect, sigma)[1], rtol=2e-3)


def test_tables_across_aspects_match_tables_built_at_the_aspect() -> None:
    # The tables at an aspect between the nodes come from a cubic through four node tables;
    # against the quadrature rule at the aspect itself they err by at most 5e-7 in G and
    # 1e-8 of J over [0.02, 1] (scanned on 120 aspects; ASPECT_NODES states 6e-7 and 2e-8),
    # far below the linear interpolation in t (1.5e-5 of a share).
    from ballscrew import helix

    rng = np.random.default_rng(7)
    for aspect in (*rng.uniform(0.02, 1.0, 5), 0.02, 0.021, 0.999):
        _, j, g = helix._tables(float(aspect))
        j_exact, g_exact = helix._exact_tables(float(aspect))
        assert np.max(np.abs(g - g_exact)) < 6e-7, aspect
        assert np.max(np.abs(j / j_exact - 1.0)) < 2e-8, aspect
    # On a node, the node's own table; outside [0.02, 1], a table of its own.
    node = 51 / (helix.ASPECT_NODES - 1)
    np.testing.assert_array_equal(helix._tables(node)[2], helix._exact_tables(node)[1])
    for outside in (1.3, 0.0199):
        np.testing.assert_array_equal(helix._tables(outside)[1], helix._exact_tables(outside)[0])


def test_a_new_aspect_costs_only_the_node_tables_around_it(monkeypatch: pytest.MonkeyPatch) -> None:
    # ASPECT_NODES: a new screw costs no table of its own, only the nodes around its
    # contacts' aspects. From 0.02 to 1 (both included) every table the quadrature builds
    # is a node's, at k / (ASPECT_NODES - 1) inside [0, 1], four at most (the cubic's
    # stencil; one on a node). The nodes are multiples of a power of two apart: 1e-9 only
    # allows for the rounding of k.
    from ballscrew import helix

    built: list[float] = []
    real = helix._exact_tables

    def spy(aspect: float) -> tuple[np.ndarray, np.ndarray]:
        built.append(aspect)
        return real(aspect)

    monkeypatch.setattr(helix, "_exact_tables", spy)
    try:
        # With the stored node tables (the package's file): no quadrature at all.
        helix._tables.cache_clear()
        helix._node_tables.cache_clear()
        helix._tables(0.3131)
        assert built == []
        # Without them: the nodes around the aspect, built.
        monkeypatch.setattr(helix, "TABLES_FILE", helix.TABLES_FILE.with_name("missing.npz"))
        helix._stored_tables.cache_clear()
        for aspect in (0.02, 0.021, 0.3131, 0.999, 1.0):
            built.clear()
            helix._tables.cache_clear()
            helix._node_tables.cache_clear()
            helix._tables(aspect)
            assert 1 <= len(built) <= 4, aspect
            for node in built:
                k = node * (helix.ASPECT_NODES - 1)
                assert abs(k - round(k)) < 1e-9 and 0.0 <= node <= 1.0, (aspect, node)
    finally:
        helix._tables.cache_clear()
        helix._node_tables.cache_clear()
        helix._stored_tables.cache_clear()


def test_stored_node_tables_are_the_rules_own() -> None:
    # The file of node tables (scripts/build_helix_tables.py) must be what the package's
    # quadrature gives at those aspects: a file left from another rule, node count or
    # integrand fails here (1e-13: the rule's sums rounded by another numpy build).
    from ballscrew import helix

    stored = helix._stored_tables()
    assert stored is not None, "rebuild src/ballscrew/data/helix_tables.npz"
    for node in (0, 5, 51, 128, 200, helix.ASPECT_NODES - 1):
        j, g = helix._exact_tables(node / (helix.ASPECT_NODES - 1))
        np.testing.assert_allclose(stored[0][node], j, rtol=1e-13, atol=0.0)
        np.testing.assert_allclose(stored[1][node], g, rtol=1e-13, atol=1e-300)


def test_without_the_stored_tables_the_nodes_are_built(monkeypatch: pytest.MonkeyPatch) -> None:
    from ballscrew import helix

    monkeypatch.setattr(helix, "TABLES_FILE", helix.TABLES_FILE.with_name("missing.npz"))
    helix._stored_tables.cache_clear()
    helix._node_tables.cache_clear()
    try:
        assert helix._stored_tables() is None
        j, g = helix._node_tables(77)
        j_exact, g_exact = helix._exact_tables(77 / (helix.ASPECT_NODES - 1))
        np.testing.assert_array_equal(j, j_exact)
        np.testing.assert_array_equal(g, g_exact)
    finally:
        helix._stored_tables.cache_clear()
        helix._node_tables.cache_clear()
