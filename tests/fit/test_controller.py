"""Friction forms for controllers: each checked against its definition."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from ballscrew import friction_torque, reference_screw
from ballscrew.errors import BallScrewInputError
from ballscrew.servo.controller import (
    coulomb_viscous,
    fit_form,
    lugre_rate,
    nut_axial_stiffness,
    stribeck,
    stribeck_torque,
)

W = np.concatenate([-np.geomspace(0.01, 300.0, 40)[::-1], np.geomspace(0.01, 300.0, 40)])


def test_a_pure_coulomb_viscous_curve_is_recovered_exactly() -> None:
    torque = 0.42 * np.sign(W) + 2.5e-3 * W
    f = coulomb_viscous(W, torque)
    assert f.parameters["coulomb_torque"] == pytest.approx(0.42, rel=1e-12)
    assert f.parameters["viscous_coefficient"] == pytest.approx(2.5e-3, rel=1e-12)
    assert f.rms_error < 1e-14


def test_coulomb_viscous_stays_physical_on_a_falling_curve() -> None:
    # Torque that falls with speed: an unconstrained fit gives b < 0; the
    # bounded one stops at b = 0 and T_c the mean torque.
    torque = np.sign(W) * (0.5 - 1e-3 * np.abs(W))
    f = coulomb_viscous(W, torque)
    assert f.parameters["viscous_coefficient"] == 0.0
    assert f.parameters["coulomb_torque"] == pytest.approx(float(np.mean(np.abs(torque))))


def test_a_stribeck_curve_is_recovered_with_its_static_torque_above_coulomb() -> None:
    true = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
            "stribeck_exponent": 1.3, "viscous_coefficient": 1e-3}  # fmt: skip
    f = stribeck(W, stribeck_torque(W, **true))
    for key, value in true.items():
        assert f.parameters[key] == pytest.approx(value, rel=1e-6), key
    # A curve with no drop: T_s = T_c by construction, never below.
    g = stribeck(W, 0.4 * np.sign(W) + 1e-3 * W)
    assert g.parameters["static_torque"] >= g.parameters["coulomb_torque"]
    assert g.parameters["static_torque"] == pytest.approx(0.4, rel=1e-6)
    assert any("no Stribeck drop" in n for n in g.notes)


def test_stribeck_definition_at_the_stribeck_speed_and_far_beyond() -> None:
    # Excess over Coulomb falls to 1/e at omega_s (any exponent), and to 0 far away.
    for delta in (0.5, 1.0, 2.0):
        t = float(stribeck_torque(2.0, 0.3, 0.5, 2.0, delta, 0.0))
        assert t == pytest.approx(0.3 + 0.2 / math.e, rel=1e-12)
    assert float(stribeck_torque(-1e4, 0.3, 0.5, 2.0, 1.0, 0.0)) == pytest.approx(-0.3)


def test_lugre_at_constant_speed_settles_on_the_stribeck_curve() -> None:
    # Integrate the bristle ODE at a constant speed: its steady torque must be
    # the Stribeck curve, sigma_2 = b (the defining property of LuGre).
    p = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
         "stribeck_exponent": 1.0, "viscous_coefficient": 1e-3, "bristle_stiffness": 3000.0,
         "bristle_damping": 5.0}  # fmt: skip
    for w in (-5.0, 0.5, 3.0):
        sol = solve_ivp(lambda _t, z, w=w: lugre_rate(z, w, p)[0], (0.0, 1.0), [0.0],
                        rtol=1e-10, atol=1e-14, method="LSODA")  # fmt: skip
        _, torque = lugre_rate(sol.y[0, -1], w, p)
        keys = ("coulomb_torque", "static_torque", "stribeck_speed", "stribeck_exponent",
                "viscous_coefficient")  # fmt: skip
        expected = stribeck_torque(w, *(p[k] for k in keys))
        assert float(torque) == pytest.approx(float(expected), rel=1e-6)


def test_nut_stiffness_follows_hertz() -> None:
    # A single nut: delta ~ Q^(2/3), so K = dF/dx = 1.5 F/x. A double nut at
    # no external load: each half takes half of a small load (preload_split),
    # so K = 2 K_half at the preload.
    single = reference_screw().replace(nut="single", preload=0.0)
    k1, k2 = nut_axial_stiffness(single, 1000.0), nut_axial_stiffness(single, 2000.0)
    # K ~ F^(1/3): doubling the load multiplies it by 2^(1/3) (to the finite step).
    assert k2 / k1 == pytest.approx(2 ** (1 / 3), rel=1e-4)
    double = reference_screw()  # 2 kN preload
    assert nut_axial_stiffness(double) == pytest.approx(2 * k2, rel=1e-3)
    with pytest.raises(BallScrewInputError, match="single nut"):
        nut_axial_stiffness(single, 0.0)
    # A double nut set to 0 N has no preloaded contacts either: no stiffness at rest.
    with pytest.raises(BallScrewInputError, match="any nut without preload"):
        nut_axial_stiffness(reference_screw().replace(preload=0.0), 0.0)
    # Any preload, however small, is preloaded contacts, stiff at rest: 0.5 N, K = 2 K_half
    # with each half at 0.5 N, K_half ~ F^(1/3) from the single nut's 1000 N above.
    tiny = nut_axial_stiffness(reference_screw().replace(preload=0.5), 0.0)
    assert tiny == pytest.approx(2 * k1 * (0.5 / 1000.0) ** (1 / 3), rel=1e-3)


def test_lugre_rules_and_table_side_units() -> None:
    screw = reference_screw()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        torque = np.sign(W) * friction_torque(screw, "PAO ISO VG 68", speed=W,
                                              temperature=40.0).total  # fmt: skip
    f = fit_form("lugre", W, torque, screw=screw, inertia=4e-3)
    # One nut stiffness for the bristles, the axis check and the servo model: the Hertz
    # contacts' brought to the catalogue level (1/1.48) times THK's 80 % allowance.
    k = 0.8 * nut_axial_stiffness(screw) / 1.48
    assert f.parameters["bristle_stiffness"] == pytest.approx(k * (0.01 / (2 * math.pi)) ** 2)
    assert f.parameters["bristle_damping"] == pytest.approx(
        2 * math.sqrt(f.parameters["bristle_stiffness"] * 4e-3)
    )
    side = f.as_drive_dict(lead=0.01)["table_side"]
    # F = 2 pi T / l; c = b (2 pi / l)^2.
    assert side["coulomb_force"]["value"] == pytest.approx(
        f.parameters["coulomb_torque"] * 2 * math.pi / 0.01
    )
    assert side["viscous_table_coefficient"]["value"] == pytest.approx(
        f.parameters["viscous_coefficient"] * (2 * math.pi / 0.01) ** 2
    )
    with pytest.raises(BallScrewInputError, match="inertia"):
        fit_form("lugre", W, torque, screw=screw)
    with pytest.raises(BallScrewInputError, match="form"):
        fit_form("dahl", W, torque)


def test_export_friction_command(tmp_path: object, capsys: pytest.CaptureFixture[str]) -> None:
    import json
    from pathlib import Path

    from ballscrew.cli import main

    out = Path(str(tmp_path)) / "table.csv"
    with pytest.raises(SystemExit) as info:
        main(["export-friction", "--form", "table", "--temperature", "20, 40 degC",
              "--speed", "10, 100, 1000 rpm", "--out", str(out)])  # fmt: skip
    assert info.value.code == 0
    lines = out.read_text().splitlines()
    assert lines[0].startswith("speed [rad/s],speed [rpm],temperature [degC],torque [N*m]")
    assert len(lines) == 1 + 2 * 6  # both directions, two temperatures
    capsys.readouterr()
    with pytest.raises(SystemExit) as info:
        main(["export-friction", "--form", "coulomb-viscous", "--json", "-"])
    assert info.value.code == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["parameters"]["viscous_coefficient"]["value"] >= 0.0
    assert payload["parameters"]["coulomb_torque"]["unit"] == "N*m"
    assert payload["rms_error_Nm"] >= 0.0


def test_single_nut_stiffness_from_hertz_by_hand() -> None:
    # Built here from the definitions: Q = F/(Z sin(alpha) cos(lambda)), the nut moves
    # x = (delta_screw + delta_nut)/(sin(alpha) cos(lambda)), and Hertz's delta ~ Q^(2/3) makes
    # K = dF/dx = 1.5 F/x exactly. The code's finite difference (step 1e-4 F) is within
    # 1e-4 of that.
    from ballscrew.contact import hertz

    s = reference_screw().replace(nut="single", preload=0.0)
    f = 1500.0
    sa = math.sin(s.contact_angle) * math.cos(s.lead_angle)
    q = f / (s.balls_per_nut * sa)
    delta = (hertz(q, s.rx_screw, s.ry_screw, s.reduced_modulus).approach
             + hertz(q, s.rx_nut, s.ry_nut, s.reduced_modulus).approach)  # fmt: skip
    x = float(delta) / sa
    assert nut_axial_stiffness(s, f) == pytest.approx(1.5 * f / x, rel=1e-4)


def test_every_table_side_quantity_follows_the_lead() -> None:
    # Table side by hand, l = 5 mm: F = T 2 pi/l, v = omega l/2 pi, and a rate or
    # stiffness per radian becomes one per metre with (2 pi/l)^2.
    p = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
         "stribeck_exponent": 1.3, "viscous_coefficient": 1e-3, "bristle_stiffness": 3000.0,
         "bristle_damping": 5.0}  # fmt: skip
    from ballscrew.servo.controller import FrictionForm

    lead = 0.005
    k = 2 * math.pi / lead
    side = FrictionForm("lugre", p, 0.0, 0.0).as_drive_dict(lead=lead)["table_side"]
    expected = {
        "coulomb_force": (0.3 * k, "N"),
        "static_force": (0.5 * k, "N"),
        "stribeck_table_speed": (2.0 / k, "m/s"),
        "viscous_table_coefficient": (1e-3 * k**2, "N*s/m"),
        "bristle_table_stiffness": (3000.0 * k**2, "N/m"),
        "bristle_table_damping": (5.0 * k**2, "N*s/m"),
    }
    assert set(side) == set(expected)
    for name, (value, unit) in expected.items():
        assert side[name]["value"] == pytest.approx(value, rel=1e-12), name
        assert side[name]["unit"] == unit, name


def test_lugre_bristle_equations_away_from_steady_state() -> None:
    # From the LuGre definition: with the bristles relaxed (z = 0) the rate is the speed
    # itself and the torque sigma_1 w + sigma_2 w; at z = g/sigma_0 (steady, w > 0) the rate
    # is 0. g uses the exponent 1.5 at |w/w_s| = 3, where it matters (3^1.5 = 5.196, while
    # 3 x 1.5 = 4.5; at 2.25 the two would coincide).
    p = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
         "stribeck_exponent": 1.5, "viscous_coefficient": 1e-3, "bristle_stiffness": 3000.0,
         "bristle_damping": 5.0}  # fmt: skip
    dz, torque = lugre_rate(0.0, 6.0, p)
    assert float(dz) == pytest.approx(6.0) and float(torque) == pytest.approx((5.0 + 1e-3) * 6.0)
    g = 0.3 + 0.2 * math.exp(-(3.0**1.5))
    dz, torque = lugre_rate(g / 3000.0, 6.0, p)
    assert float(dz) == pytest.approx(0.0, abs=1e-12)
    assert float(torque) == pytest.approx(g + 1e-3 * 6.0, rel=1e-12)


def test_stribeck_bounds_and_the_no_drop_note() -> None:
    # The documented bounds: 0.5 <= delta <= 2 and omega_s <= 0.05 of the fastest speed.
    # Curves built beyond them come back at the bound.
    base = {"coulomb_torque": 0.3, "static_torque": 0.5, "viscous_coefficient": 1e-3}
    steep = stribeck(W, stribeck_torque(W, stribeck_speed=2.0, stribeck_exponent=3.0, **base))
    assert steep.parameters["stribeck_exponent"] == pytest.approx(2.0)
    flat = stribeck(W, stribeck_torque(W, stribeck_speed=2.0, stribeck_exponent=0.3, **base))
    assert flat.parameters["stribeck_exponent"] == pytest.approx(0.5)
    wide = stribeck(W, stribeck_torque(W, stribeck_speed=60.0, stribeck_exponent=1.0, **base))
    assert wide.parameters["stribeck_speed"] == pytest.approx(0.05 * 300.0, rel=1e-6)
    # A drop of 2 % of the Coulomb torque is a drop; one of 0.5 % is noted as none.
    for excess, noted in ((0.02, False), (0.005, True)):
        t = stribeck_torque(W, 0.4, 0.4 * (1 + excess), 2.0, 1.0, 1e-3)
        f = stribeck(W, t)
        assert any("no Stribeck drop" in n for n in f.notes) is noted, excess
    # A curve through standstill (omega = 0, torque 0) fits as well.
    w0 = np.concatenate([W, [0.0]])
    f0 = stribeck(w0, stribeck_torque(w0, stribeck_speed=2.0, stribeck_exponent=1.3, **base))
    assert f0.parameters["stribeck_speed"] == pytest.approx(2.0, rel=1e-6)


def test_lugre_damping_rule_with_its_ratio_and_a_refused_inertia() -> None:
    p = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
         "stribeck_exponent": 1.0, "viscous_coefficient": 1e-3}  # fmt: skip
    torque = stribeck_torque(W, **p)
    f = fit_form("lugre", W, torque, bristle_stiffness=2000.0, inertia=4e-3, damping_ratio=0.7)
    # sigma_1 = 2 zeta sqrt(sigma_0 J)
    assert f.parameters["bristle_damping"] == pytest.approx(2 * 0.7 * math.sqrt(2000.0 * 4e-3))
    for bad in (0.0, -1.0):
        with pytest.raises(BallScrewInputError, match="inertia"):
            fit_form("lugre", W, torque, bristle_stiffness=2000.0, inertia=bad)
    screw = reference_screw()
    g = fit_form("lugre", W, torque, screw=screw, bristle_damping=1.0)
    # The note gives the nut's design stiffness in N/um: the check's value, 0.8/1.48 of
    # the ideal contacts' (design/stiffness.py's catalogue level and THK's allowance).
    note = next(n for n in g.notes if "N/um" in n)
    shown = float(note.split("design stiffness ")[1].split(" N/um")[0])
    assert shown == pytest.approx(0.8 / 1.48 * nut_axial_stiffness(screw) * 1e-6, rel=1e-3)
