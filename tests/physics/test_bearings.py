"""Support-bearing friction: Palmgren's model against the catalogue's own units and limits."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import lubricants, reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import Profile
from ballscrew.bearings import (
    PALMGREN_BEARINGS,
    palmgren_bearing_torque,
    palmgren_drag_torque,
    palmgren_load_torque,
)
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case

RPM = math.pi / 30.0


def _catalogue_m0(f0: float, nu_cst: float, n_rpm: float, dm_mm: float) -> float:
    """Schaeffler HR 1, p. 55, in its own units: N·mm from mm²/s, 1/min and mm; here N·m."""
    if nu_cst * n_rpm >= 2000.0:
        return f0 * 1e-7 * (nu_cst * n_rpm) ** (2.0 / 3.0) * dm_mm**3 / 1000.0
    return 160e-7 * f0 * dm_mm**3 / 1000.0


@pytest.mark.parametrize("n_rpm", [5.0, 20.0, 29.0, 30.0, 500.0, 3000.0])
@pytest.mark.parametrize("nu_cst", [68.0, 22.0])
def test_drag_torque_in_the_catalogues_units(n_rpm: float, nu_cst: float) -> None:
    # SI in and out of the library; the catalogue's formula in mm, 1/min and mm²/s here.
    # Both branches are reached (nu n = 110 to 204 000); 1e-12: only rounding differs.
    got = palmgren_drag_torque(n_rpm * RPM, nu_cst * 1e-6, 0.046, 4.0)
    assert float(got) == pytest.approx(_catalogue_m0(4.0, nu_cst, n_rpm, 46.0), rel=1e-12)


def test_the_two_branches_meet_at_nu_n_2000() -> None:
    # 2000^(2/3) = 158.74 against the low-speed constant 160: within 1 %, and the
    # drag rises as (nu n)^(2/3) above it.
    below = float(palmgren_drag_torque(1999.0 / 68.0 * RPM, 68e-6, 0.05, 2.0))
    above = float(palmgren_drag_torque(2000.0 / 68.0 * RPM, 68e-6, 0.05, 2.0))
    assert above / below == pytest.approx(2000.0 ** (2 / 3) / 160.0, rel=1e-12)
    assert abs(above / below - 1.0) < 0.01
    fast = float(palmgren_drag_torque(16000.0 / 68.0 * RPM, 68e-6, 0.05, 2.0))
    assert fast / above == pytest.approx(8.0 ** (2 / 3), rel=1e-12)


def test_load_torque_of_each_type() -> None:
    # M1 = z (Fa/C0)^y * c Fa * dM with the printed factors of each type (HR 1, pp. 58-60):
    # angular contact 0.001, 0.33; thrust ball 0.0012, 0.33; P1 = Fa, 1.4 Fa or 1.5 Fa.
    printed = {
        "angular-contact ball, single row": (0.001, 1.0),
        "angular-contact ball, double row": (0.001, 1.4),
        "four-point contact ball": (0.001, 1.5),
        "thrust ball": (0.0012, 1.0),
        "screw-support (ZKLN, ZKLF)": (0.001, 1.4),
    }
    assert set(printed) == set(PALMGREN_BEARINGS)
    for name, (z, c) in printed.items():
        m1 = float(palmgren_load_torque(-3000.0, 0.05, 50e3, name))
        assert m1 == pytest.approx(z * (3000.0 / 50e3) ** 0.33 * c * 3000.0 * 0.05, rel=1e-12)


def test_bearing_torque_adds_drag_and_load_with_the_lubrication_factor() -> None:
    # ZKLN 3062-like support: d = 30 mm, D = 62 mm (dM = 46 mm), C0 = 40 kN, printed
    # f0 = 4 with grease and 6 with oil.
    w = np.array([10.0, 3000.0]) * RPM
    for lubrication, f0 in (("grease", 4.0), ("oil", 6.0)):
        m = palmgren_bearing_torque(w, 1500.0, 46e-6, bore=0.03, outer_diameter=0.062,
                                    static_rating=40e3, lubrication=lubrication)  # fmt: skip
        m0 = [_catalogue_m0(f0, 46.0, n, 46.0) for n in (10.0, 3000.0)]
        m1 = 0.001 * (1500.0 / 40e3) ** 0.33 * 1.4 * 1500.0 * 0.046
        np.testing.assert_allclose(m, np.array(m0) + m1, rtol=1e-12)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"bearing_type": "deep-groove ball"}, "bearing_type"),
        ({"lubrication": "water"}, "bearing_lubrication"),
        ({"outer_diameter": 0.03}, "bearing_outer_diameter"),
        ({"static_rating": -1.0}, "static_rating"),
    ],
)
def test_bad_bearing_inputs_name_their_field(kwargs: dict[str, object], field: str) -> None:
    args: dict[str, object] = {"bore": 0.03, "outer_diameter": 0.062, "static_rating": 40e3}
    args.update(kwargs)
    with pytest.raises(BallScrewInputError, match=field):
        palmgren_bearing_torque(100.0, 1000.0, 46e-6, **args)  # type: ignore[arg-type]


def test_axis_with_palmgren_bearings_rises_with_speed() -> None:
    # Constant speed for 2 s at 1.5 kN: the bearing energy is (M0 + M1) omega t with the
    # lubricant's viscosity at the cycle's temperature; per revolution it grows with speed,
    # which SKF's simplified estimate (load term only) cannot show.
    oil = lubricants.get("mineral ISO VG 68")
    s = reference_screw()
    axis = Axis(moving_mass=0.0, bearing_bore=0.03, bearing_outer_diameter=0.062,
                bearing_static_rating=40e3, bearing_type="screw-support (ZKLN, ZKLF)",
                dn_limit=150_000.0)  # fmt: skip
    per_turn = []
    for v in (0.05, 0.5):
        t = np.linspace(0.0, 2.0, 11)
        zero = np.zeros_like(t)
        p = Profile(t, v * t, np.full_like(t, v), zero, zero + 1500.0)
        r = axis_cycle(p, s, oil, axis, temperature=40.0)
        omega = 2 * math.pi * v / s.lead
        expected = float(palmgren_bearing_torque(omega, 1500.0, oil.kinematic_viscosity(40.0),
                                                 bore=0.03, outer_diameter=0.062,
                                                 static_rating=40e3))  # fmt: skip
        assert r.bearing_energy == pytest.approx(expected * omega * 2.0, rel=1e-12)
        per_turn.append(r.bearing_energy / (omega * 2.0))
    assert per_turn[1] > 1.5 * per_turn[0]


@pytest.mark.parametrize(
    "axis, field",
    [
        ({"bearing_bore": 0.03, "bearing_outer_diameter": 0.062}, "bearing_static_rating"),
        ({"bearing_outer_diameter": 0.062, "bearing_static_rating": 4e4}, "bearing_bore"),
        ({"bearing_bore": 0.03, "bearing_type": "screw-support (ZKLN, ZKLF)"}, "bearing_type"),
        ({"bearing_bore": 0.03, "bearing_lubrication": "dry"}, "bearing_lubrication"),
    ],
)
def test_axis_refuses_incomplete_bearing_data(axis: dict[str, object], field: str) -> None:
    with pytest.raises(BallScrewInputError, match=field):
        Axis(moving_mass=0.0, **axis)  # type: ignore[arg-type]


def test_case_file_bearing_keys_reach_the_axis() -> None:
    case = parse_case(
        '[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "6.35 mm"\n'
        'preload = "2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
        '[axis]\nbearing_bore = "30 mm"\nbearing_outer_diameter = "62 mm"\n'
        'bearing_static_rating = "40 kN"\nbearing_type = "screw-support (ZKLN, ZKLF)"\n'
        'bearing_lubrication = "oil"\n'
    )
    axis = Axis(**case.axis)
    assert (axis.bearing_outer_diameter, axis.bearing_static_rating) == (0.062, 40e3)
    assert axis.bearing_lubrication == "oil"


def test_factor_tables_are_the_printed_ones() -> None:
    # Transcribed from the catalogues: SKF's mu (Rolling bearings, "estimating the frictional
    # moment") and Schaeffler HR 1's f0 for grease / oil (pp. 57-59).
    from ballscrew.bearings import SKF_FRICTION_COEFFICIENTS

    assert SKF_FRICTION_COEFFICIENTS == {
        "deep-groove ball": 0.0015,
        "angular-contact ball, single row": 0.0020,
        "angular-contact ball, double row": 0.0024,
        "four-point contact ball": 0.0024,
        "thrust ball": 0.0013,
    }
    printed = {
        "angular-contact ball, single row": (2.0, 3.0),
        "angular-contact ball, double row": (4.0, 6.0),
        "four-point contact ball": (2.7, 4.0),
        "thrust ball": (1.0, 1.5),
        "screw-support (ZKLN, ZKLF)": (4.0, 6.0),
    }
    for name, (grease, oil) in printed.items():
        spec = PALMGREN_BEARINGS[name]
        assert (spec.f0_grease, spec.f0_oil) == (grease, oil), name
