"""ballscrew identify: synthetic drive traces of known axes, recovered; the baselines; the CLI."""

from __future__ import annotations

import json
import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from ballscrew.axis.motion import Profile, back_and_forth, chain
from ballscrew.errors import BallScrewInputError
from ballscrew.fit.identify import (
    AxisInputs,
    TrueAxis,
    axis_inputs,
    axis_torque,
    calibrated_machine_text,
    fit_axis,
    identify,
    regressors,
    shaft_energy,
    synthetic_trace,
)
from ballscrew.io.machine import load_machine, parse_machine
from ballscrew.io.trace import Trace
from cli_runner import run

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TRUTH = TrueAxis(torque_constant=1.2, offset=0.05, moving_mass=450.0, screw_scale=1.0,
                 guide_coulomb=60.0, guide_viscous=200.0)  # fmt: skip


@cache
def _x_axis() -> AxisInputs:
    """Axis X of the example machine (HIWIN R40-10, 450 kg, complete model)."""
    return axis_inputs(load_machine(EXAMPLES / "machine_vmc.toml"), "X", travel=0.4)


def _program(jerk: float, parts: tuple[tuple[float, float, float, float], ...]) -> Profile:
    """Back-and-forth moves (stroke, feed, acceleration, dwell), jerk limited, twice each."""
    return chain(*(back_and_forth(s, f, a, jerk=jerk * a / 2.0, dwell_time=d, cycles=2)
                   for s, f, a, d in parts))  # fmt: skip


PROGRAM_A = ((0.3, 0.25, 2.0, 1.0), (0.1, 0.05, 1.0, 0.5), (0.2, 0.4, 3.0, 0.5))
PROGRAM_B = ((0.25, 0.15, 1.5, 0.8), (0.05, 0.02, 1.0, 0.5), (0.3, 0.3, 2.5, 0.4))


def test_noise_at_standstill_is_explained_not_chattered() -> None:
    # 50 Hz, 1 µm of position noise through long dwells, 0.05 A of current noise: the fitted
    # model explains the current with R² >= 0.95 (the target), and at rest predicts
    # the holding current (here the offset) steadily. With the exact sign the noise at rest
    # flips the friction at every sample: the prediction at rest chatters and the fit is worse.
    profile = _program(4.0, ((0.2, 0.1, 1.0, 3.0), (0.3, 0.2, 2.0, 2.0)))
    trace = synthetic_trace({"X": profile}, {"X": _x_axis()}, {"X": TRUTH}, sample_time=0.02,
                            signal_noise=0.05, seed=3)  # fmt: skip
    ax = trace.axes["X"]
    still = np.interp(trace.time, profile.time, np.abs(profile.speed)) == 0.0
    rest = still.copy()  # and three samples either side, beyond the filter's reach
    for k in (1, 2, 3):
        rest[k:] &= still[:-k]
        rest[:-k] &= still[k:]
    ramped = fit_axis(ax, trace.time, _x_axis(), replicates=200)
    exact = fit_axis(ax, trace.time, _x_axis(), replicates=200, standstill_speed=0.0)
    assert ramped.score.r2 >= 0.95
    assert ramped.score.r2 > exact.score.r2
    # At rest: steady to a fifth of the current's noise with the ramp; the exact sign
    # chatters by more than the noise itself (about T_f/K_t/sqrt(filter) = 0.06 A).
    assert float(np.std(ramped.predicted[rest])) < 0.01
    assert float(np.std(exact.predicted[rest])) > 0.04
    # The baselines on the same signal: sign(v) alone misses the inertia.
    assert ramped.baselines["sign(v) alone"].r2 < 0.5
    assert ramped.score.r2 >= ramped.baselines["Coulomb + viscous + inertia"].r2


def _true_energy(profile: Profile, inputs: AxisInputs, params: dict[str, float]) -> float:
    reg = regressors(profile, inputs, params["moving_mass"])
    return shaft_energy(axis_torque(reg, params), reg.motor_speed, profile.time)


def test_a_trace_of_one_program_predicts_another_programs_energy() -> None:
    # Fit on program A's trace; the calibrated axis runs program B's planned motion. Its
    # energy is the truth's within the fit's uncertainty: 10 % is the target, the
    # sampling error of these fits is below 1 %.
    inputs = _x_axis()
    a = synthetic_trace({"X": _program(20.0, PROGRAM_A)}, {"X": inputs}, {"X": TRUTH},
                        sample_time=0.004, signal_noise=0.1, seed=1)  # fmt: skip
    fit = fit_axis(a.axes["X"], a.time, inputs, replicates=200)
    b = _program(20.0, PROGRAM_B)
    fitted = {k: p.value for k, p in fit.parameters.items()}
    predicted = _true_energy(b, inputs, fitted)
    true = _true_energy(b, inputs, TRUTH.as_parameters())
    assert predicted == pytest.approx(true, rel=0.10)


def test_a_known_torque_constant_lets_the_mass_be_fitted() -> None:
    # K_t from the data sheet holds the torque scale; the moving mass is then free.
    inputs = _x_axis()
    held = AxisInputs(inputs.letter, inputs.case, inputs.axis, inputs.model, inputs.temperature,
                      inputs.parameters, torque_constant=1.2)  # fmt: skip
    truth = TrueAxis(moving_mass=380.0)  # the case says 450 kg: the fit must not keep it
    trace = synthetic_trace({"X": _program(20.0, PROGRAM_A)}, {"X": held}, {"X": truth},
                            sample_time=0.004, signal_noise=0.1, seed=5)  # fmt: skip
    fit = fit_axis(trace.axes["X"], trace.time, held, replicates=300)
    mass = fit.parameters["moving_mass"]
    assert fit.held == "torque_constant" and mass.fitted
    assert mass.low <= 380.0 <= mass.high
    assert mass.high - mass.low < 20.0  # the inertia tells the mass to a few kg


def test_a_current_trace_needs_a_mass_or_a_torque_constant() -> None:
    inputs = _x_axis()
    massless = AxisInputs(inputs.letter, inputs.case, inputs.axis.__class__(moving_mass=0.0),
                          inputs.model, inputs.temperature)  # fmt: skip
    t = np.arange(0.0, 4.0, 0.02)
    trace = synthetic_trace({"X": _program(4.0, ((0.1, 0.1, 1.0, 0.5),))}, {"X": inputs},
                            {"X": TRUTH}, sample_time=0.02)  # fmt: skip
    with pytest.raises(BallScrewInputError, match="moving_mass"):
        fit_axis(trace.axes["X"], trace.time, massless)
    del t


def test_gaps_in_the_sampling_are_refused_with_the_sample() -> None:
    trace = synthetic_trace({"X": _program(4.0, ((0.1, 0.1, 1.0, 0.5),))}, {"X": _x_axis()},
                            {"X": TRUTH}, sample_time=0.02)  # fmt: skip
    keep = np.ones(trace.time.size, dtype=bool)
    keep[40] = False
    ax = trace.axes["X"]
    cut = ax.__class__("X", ax.position[keep], ax.signal[keep], ax.kind)
    with pytest.raises(BallScrewInputError, match=r"sample 41 .*uniform sampling"):
        fit_axis(cut, trace.time[keep], _x_axis())


@pytest.mark.slow
def test_parameters_are_recovered_within_their_intervals_in_90_of_100_traces() -> None:
    # 100 traces of one program, each with its own noise (250 Hz, 1 µm, AR(1) current noise
    # of 0.1 A, rho 0.5): every fitted parameter inside its 95 % interval in at least 90 of
    # them. With 95 % intervals the expected count is 95; 90 is 2.3 binomial standard
    # deviations below it (the block bootstrap is known to run a little narrow).
    inputs = _x_axis()
    profile = _program(20.0, PROGRAM_A)
    hits: dict[str, int] = {}
    for seed in range(100):
        trace = synthetic_trace({"X": profile}, {"X": inputs}, {"X": TRUTH},
                                sample_time=0.004, signal_noise=0.1, seed=seed)  # fmt: skip
        fit = fit_axis(trace.axes["X"], trace.time, inputs, seed=seed)
        for name, p in fit.parameters.items():
            if p.fitted:
                hits[name] = hits.get(name, 0) + (p.low <= getattr(TRUTH, name) <= p.high)
    assert set(hits) == {"torque_constant", "offset", "screw_scale", "guide_coulomb",
                         "guide_viscous"}  # fmt: skip
    assert min(hits.values()) >= 90, hits


def _write(trace: Trace, path: Path) -> None:
    ax = trace.axes["X"]
    rows = [f"{t:.4f},{x * 1e3:.5f},{y:.4f}"
            for t, x, y in zip(trace.time, ax.position, ax.signal, strict=True)]  # fmt: skip
    path.write_text("time [s],X position [mm],X current [A]\n" + "\n".join(rows) + "\n")


def test_identify_command_fits_validates_and_writes_a_machine_program_reads(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    inputs = _x_axis()
    for name, program, seed in (("a", PROGRAM_A, 1), ("b", PROGRAM_B, 2)):
        trace = synthetic_trace({"X": _program(20.0, program)}, {"X": inputs}, {"X": TRUTH},
                                sample_time=0.004, signal_noise=0.1, seed=seed)  # fmt: skip
        _write(trace, tmp_path / f"{name}.csv")
    calibrated = tmp_path / "calibrated.toml"
    code, out, err = run(["identify", str(tmp_path / "a.csv"), "--machine",
                          str(EXAMPLES / "machine_vmc.toml"), "--validate",
                          str(tmp_path / "b.csv"), "--calibrated", str(calibrated),
                          "--out", str(tmp_path / "report"), "--json",
                          str(tmp_path / "fit.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert "current-to-torque scale K_t" in out and "Coulomb + viscous + inertia" in out
    doc = json.loads((tmp_path / "fit.json").read_text())
    x = doc["axes"]["X"]
    kt = x["parameters"]["torque_constant"]
    assert kt["low_95"] <= 1.2 <= kt["high_95"]
    # Program B's energy from program A's fit: within 10 % (the target).
    assert abs(doc["validation"]["axes"]["X"]["model"]["energy_error"]) < 0.10
    assert (tmp_path / "report" / "report.html").is_file()
    assert (tmp_path / "report" / "figures" / "fit_X.png").is_file()
    machine = parse_machine(calibrated.read_text(), folder=EXAMPLES)
    assert machine.axes["X"].case.axis["moving_mass"] == pytest.approx(450.0)
    assert "K_t = 1.2" in calibrated.read_text()


def test_calibrated_machine_carries_a_fitted_mass(tmp_path: Path) -> None:
    machine = load_machine(EXAMPLES / "machine_vmc.toml")
    inputs = _x_axis()
    held = AxisInputs(inputs.letter, inputs.case, inputs.axis, inputs.model, inputs.temperature,
                      inputs.parameters, torque_constant=1.2)  # fmt: skip
    trace = synthetic_trace({"X": _program(20.0, PROGRAM_A)}, {"X": held},
                            {"X": TrueAxis(moving_mass=400.0)}, sample_time=0.004,
                            signal_noise=0.1, seed=4)  # fmt: skip
    result = identify(trace, machine, torque_constants={"X": 1.2}, replicates=200)
    text = calibrated_machine_text(machine, result)
    again = parse_machine(text, folder=EXAMPLES)
    mass = result.fits["X"].parameters["moving_mass"]
    assert again.axes["X"].case.axis["moving_mass"] == pytest.approx(mass.value, rel=1e-4)
    assert math.isclose(mass.value, 400.0, rel_tol=0.02)


def test_a_torque_trace_has_its_scale_and_fits_the_mass() -> None:
    # A drive that reports torque: no K_t to find, the moving mass is free (400 kg where
    # the case says 450).
    truth = TrueAxis(moving_mass=400.0, kind="torque")
    trace = synthetic_trace({"X": _program(20.0, PROGRAM_A)}, {"X": _x_axis()}, {"X": truth},
                            sample_time=0.004, signal_noise=0.1, seed=1)  # fmt: skip
    fit = fit_axis(trace.axes["X"], trace.time, _x_axis(), replicates=300)
    assert fit.held == "signal" and not fit.parameters["torque_constant"].fitted
    mass = fit.parameters["moving_mass"]
    assert mass.low <= 400.0 <= mass.high
    assert fit.parameters["offset"].low <= 0.05 <= fit.parameters["offset"].high
