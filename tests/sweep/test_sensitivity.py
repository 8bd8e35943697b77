"""Sobol indices and Monte Carlo percentiles against functions whose answers are known."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from scipy import stats

from ballscrew import friction_torque
from ballscrew.io.case import load_case
from ballscrew.sweep.execute import run_sweep
from ballscrew.sweep.sensitivity import sample, sobol_indices
from ballscrew.sweep.spec import Distribution, parse_sweep
from cli_runner import run
from shared import SMALL_CASE

CASE = SMALL_CASE


def test_sobol_indices_of_the_ishigami_function() -> None:
    # Ishigami & Homma (1990), a = 7, b = 0.1, X_i uniform on [-pi, pi]; analytic indices
    # from Sobol' & Levitan (1999) as tabulated by Saltelli et al. (2008), ch. 4.
    a, b = 7.0, 0.1
    inputs = [Distribution(f"x{i}", "uniform", -math.pi, math.pi, "") for i in (1, 2, 3)]
    x = sample(inputs, 4096, seed=11, sobol=True)
    assert x.shape == (4096 * 5, 3)  # Saltelli's N (D + 2) rows
    y = np.sin(x[:, 0]) + a * np.sin(x[:, 1]) ** 2 + b * x[:, 2] ** 4 * np.sin(x[:, 0])
    s = sobol_indices(inputs, y, seed=11)
    first = np.array([0.3139, 0.4424, 0.0])
    total = np.array([0.5576, 0.4424, 0.2437])
    # The conf values are bootstrap 95 % half-widths (about 2 standard errors); the seeded
    # estimate must lie within two of them (about 4 standard errors), and they must be
    # tight enough (< 0.05) for the check to mean something.
    assert np.all(s.first_conf < 0.05) and np.all(s.total_conf < 0.05)
    assert np.all(np.abs(s.first - first) <= 2 * s.first_conf), (s.first, s.first_conf)
    assert np.all(np.abs(s.total - total) <= 2 * s.total_conf), (s.total, s.total_conf)
    assert s.ranking() == [0, 1, 2]


SWEEP = f"""
case = "{CASE.as_posix()}"
models = ["catalog"]
[axes]
speed = "100, 1000 rpm"
axial_load = "1 kN"
[uncertainty]
samples = {{samples}}
seed = 5
sensitivity = "{{sensitivity}}"
percentiles = [5, 50, 95]
[uncertainty.inputs]
"screw.preload" = {{{{ distribution = "normal", mean = "1.5 kN", std = "0.2 kN" }}}}
"lubricant.viscosity_scale" = {{{{ distribution = "uniform", low = 0.9, high = 1.1 }}}}
"""


def _linear_law() -> tuple[float, float]:
    """The catalogue torque is linear in the preload: its slope and intercept, found directly."""
    screw = load_case(CASE).screw
    lo, hi = (
        float(friction_torque(screw.replace(preload=f), "PAO ISO VG 68", speed=10.0,
                              temperature=20.0, axial_load=1000.0, model="catalog").total)
        for f in (1000.0, 2000.0)
    )  # fmt: skip
    return (hi - lo) / 1000.0, 2.0 * lo - hi


def test_monte_carlo_percentiles_of_a_linear_law(tmp_path: Path) -> None:
    n = 2000
    spec = parse_sweep(SWEEP.format(samples=n, sensitivity="none"))
    run_sweep(spec, tmp_path / "mc.zarr")
    slope, intercept = _linear_law()
    with xr.open_zarr(tmp_path / "mc.zarr") as ds:
        found = ds["torque_percentile"].sel(model="catalog").isel(temperature=0, axial_load=0)
        found = found.values  # percentile x speed
    for k, p in enumerate((5.0, 50.0, 95.0)):
        z = stats.norm.ppf(p / 100.0)
        expected = intercept + slope * (1500.0 + z * 200.0)
        # Standard error of a sample percentile of n independent draws:
        # sqrt(p(1-p)/n) / pdf(z) in units of the spread; a Latin hypercube does better.
        # Allowed: 3 of them.
        se = math.sqrt(p / 100 * (1 - p / 100) / n) / stats.norm.pdf(z) * 200.0 * slope
        assert found[k] == pytest.approx(np.full(2, expected), abs=3 * se)


def test_sobol_through_a_sweep_finds_the_only_input_that_matters(tmp_path: Path) -> None:
    # The catalogue rule depends on the preload and not on the viscosity: S_T = 1 and 0.
    spec = parse_sweep(SWEEP.format(samples=64, sensitivity="sobol"))
    report = run_sweep(spec, tmp_path / "s.zarr")
    s = report.sobol["catalog"]
    assert s.names == ("screw.preload", "lubricant.viscosity_scale")
    assert s.total[1] == 0.0 and s.first[1] == pytest.approx(0.0, abs=1e-12)
    assert s.total[0] == pytest.approx(1.0, abs=2 * s.total_conf[0])
    with xr.open_zarr(tmp_path / "s.zarr") as ds:
        assert ds["sobol_total"].sel(model="catalog", input="screw.preload") == s.total[0]
        assert ds.sizes["sample"] == 64 * (2 + 2)


def test_cli_writes_the_sensitivity_figure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    sweep = tmp_path / "u.toml"
    sweep.write_text(SWEEP.format(samples=32, sensitivity="sobol"), "utf-8")
    code, out, err = run(["sweep", str(sweep), "--out", str(tmp_path / "u.zarr")], capsys)
    assert code == 0, err
    png = tmp_path / "u.zarr.sensitivity-catalog.png"
    assert png.read_bytes().startswith(b"\x89PNG")
    assert "Sobol indices of the mean torque: catalog" in out and "P95" in out


def test_smallest_sobol_sample_and_a_constant_output() -> None:
    # N = 2 is the smallest power of two Saltelli's scheme takes: 2 (D + 2) rows. An output
    # that does not vary has every index 0; outputs of the wrong count are named with D + 2.
    from ballscrew.errors import BallScrewInputError

    inputs = [
        Distribution("a", "uniform", 0.0, 1.0, ""),
        Distribution("b", "uniform", 0.0, 1.0, ""),
    ]
    rows = sample(inputs, 2, 1, sobol=True)
    assert rows.shape == (2 * (2 + 2), 2)
    flat = sobol_indices(inputs, np.full(rows.shape[0], 3.0), 1)
    assert not np.any(flat.total) and not np.any(flat.first)
    with pytest.raises(BallScrewInputError, match="multiple of D \\+ 2 = 4"):
        sobol_indices(inputs, np.ones(7), 1)
