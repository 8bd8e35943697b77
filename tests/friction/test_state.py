"""Tests of ballscrew.state: composition of the physical layers at operating points."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.contact import hertz
from ballscrew.ehl import hamrock_dowson_1977_minimum
from ballscrew.state import operating_state
from shared import PAO

OIL = PAO


def test_grid_broadcasting_and_finite_values() -> None:
    speed = np.linspace(0.0, 300.0, 7)[:, None, None]
    temp = np.array([20.0, 30.0, 45.0])[None, :, None]
    load = np.array([-3000.0, 0.0, 1000.0, 8000.0])[None, None, :]
    st = operating_state(reference_screw(), OIL, speed=speed, temperature=temp, axial_load=load)
    for c in st.contacts:
        for name in ("load", "film_minimum", "film_central", "film_parameter", "asperity_share"):
            value = getattr(c, name)
            assert value.shape == (7, 3, 4), name
            assert np.all(np.isfinite(value)), name


def test_contact_states_repeat_the_layers() -> None:
    # The composition must hand each layer the right arguments: recompute the
    # screw-1 contact directly from the layer functions.
    s = reference_screw()
    st = operating_state(s, OIL, speed=100.0, temperature=35.0, hertz_method="exact")
    c = st.contacts[0]
    assert (c.side, c.family, c.balls) == ("screw", 1, s.balls_per_nut)
    hz = hertz(c.load, s.rx_screw, s.ry_screw, s.reduced_modulus, method="exact")
    assert float(c.hertz.a) == float(hz.a)
    eta = OIL.dynamic_viscosity(35.0)
    u = eta * c.entrainment_speed / (s.reduced_modulus * s.rx_screw)
    w = c.load / (s.reduced_modulus * s.rx_screw**2)
    g = OIL.pressure_viscosity * s.reduced_modulus
    h = hamrock_dowson_1977_minimum(s.rx_screw, u, g, w, hz.ellipticity)
    assert float(c.film_minimum) == pytest.approx(float(h), rel=1e-14)
    assert float(c.film_parameter) == pytest.approx(float(h) / s.composite_roughness_screw)


def test_film_rises_with_speed_and_falls_with_temperature() -> None:
    st = operating_state(
        reference_screw(),
        OIL,
        speed=np.array([10.0, 100.0, 300.0])[:, None],
        temperature=np.array([20.0, 45.0])[None, :],
    )
    h = st.contacts[0].film_minimum
    assert np.all(np.diff(h, axis=0) > 0)
    assert np.all(h[:, 0] > h[:, 1])
    share = st.contacts[0].asperity_share
    assert np.all(np.diff(share, axis=0) < 0)


def test_unloaded_contacts_report_zero_film() -> None:
    st = operating_state(reference_screw(), OIL, speed=50.0, temperature=40.0, axial_load=9000.0)
    relieved = [c for c in st.contacts if c.family == 2]
    assert bool(st.loads.lifted_off)
    for c in relieved:
        assert float(c.load) == 0.0
        assert float(c.film_minimum) == 0.0 and float(c.asperity_share) == 0.0
    single = reference_screw().replace(nut="single", preload=0.0)
    st = operating_state(single, OIL, speed=50.0, temperature=40.0, axial_load=500.0)
    assert all(c.balls == 0 for c in st.contacts if c.family == 2)


def test_bad_operating_point() -> None:
    with pytest.raises(BallScrewInputError, match="temperature"):
        operating_state(reference_screw(), OIL, speed=1.0, temperature=float("inf"))
    with pytest.raises(BallScrewInputError, match="method"):
        operating_state(reference_screw(), OIL, speed=1.0, temperature=20.0, hertz_method="x")
