"""ballscrew sweep: the same arrays in every execution mode, equal to direct calls, resumable."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from ballscrew import friction_torque
from ballscrew.io.case import load_case
from ballscrew.sweep.execute import plan_sweep, run_sweep
from ballscrew.sweep.spec import parse_sweep
from ballscrew.sweep.store import partial_path, progress_path
from cli_runner import run
from shared import DATA, ROOT

CASE = DATA / "small_case.toml"

# Two models, a screw axis, a model-parameter axis and a lubricant axis; chunk_points
# small enough that the grid is cut into many chunks, some holding several screws.
SWEEP = f"""
case = "{CASE.as_posix()}"
models = ["complete", "catalog"]
outputs = ["torque", "efficiency", "power_loss", "components"]
chunk_points = 60

[axes]
speed = "10..3000:7 rpm"
temperature = "20, 40 degC"
axial_load = "0, 1.5 kN"
"screw.preload" = "0.8, 1.6 kN"
"lubricant.name" = ["PAO ISO VG 68", "mineral ISO VG 68"]
"complete.ball_train_constant" = [0.03, 0.0474]
"""

OUTPUTS = ("torque", "efficiency", "power_loss", "components")


def _arrays(path: Path) -> dict[str, np.ndarray]:
    with xr.open_zarr(path) as ds:
        return {name: ds[name].values for name in OUTPUTS}


@pytest.fixture(scope="module")
def in_process(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("sweep") / "in_process.zarr"
    run_sweep(parse_sweep(SWEEP), out)
    return out


@pytest.mark.slow
def test_three_execution_modes_give_identical_arrays(in_process: Path, tmp_path: Path) -> None:
    from distributed import LocalCluster

    reference = _arrays(in_process)
    assert all(np.isfinite(reference[k]).all() for k in ("torque", "efficiency", "power_loss"))
    local = tmp_path / "local.zarr"
    report = run_sweep(parse_sweep(SWEEP), local, workers=2)
    assert len(report.peak_rss) == 2  # the chunks really ran in two worker processes
    # A cluster started apart (threads, loopback TCP) reached by its address only.
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, protocol="tcp",
        host="127.0.0.1", dashboard_address="127.0.0.1:0",
    ) as cluster:  # fmt: skip
        remote = tmp_path / "remote.zarr"
        run_sweep(parse_sweep(SWEEP), remote, scheduler=cluster.scheduler_address)
    for other in (local, remote):
        found = _arrays(other)
        for name in OUTPUTS:
            # Bit for bit: each chunk is computed by the same function on the same inputs.
            assert np.array_equal(found[name], reference[name], equal_nan=True), name


def test_values_equal_direct_friction_calls(in_process: Path) -> None:
    case = load_case(CASE)
    rng = np.random.default_rng(7)
    with xr.open_zarr(in_process) as ds:
        for _ in range(6):
            pick = {dim: int(rng.integers(ds.sizes[dim])) for dim in ds["torque"].dims}
            at = ds.isel(pick)
            model = str(at["model"].values)
            params = {}
            if model == "complete":
                params["ball_train_constant"] = float(at["complete.ball_train_constant"])
            from ballscrew import lubricants

            r = friction_torque(
                case.screw.replace(preload=float(at["screw.preload"])),
                lubricants.get(str(at["lubricant.name"].values)),
                speed=float(at["speed"]), temperature=float(at["temperature"]),
                axial_load=float(at["axial_load"]), model=model, **params,
            )  # fmt: skip
            # One point alone and the same point inside a broadcast grid go through the
            # same elementwise operations: equal to rounding.
            rtol = 1e-12
            assert float(at["torque"]) == pytest.approx(float(r.total), rel=rtol)
            assert float(at["power_loss"]) == pytest.approx(float(r.power_loss), rel=rtol)
            assert float(at["efficiency"]) == pytest.approx(float(r.efficiency), rel=rtol, abs=0)
            for name, value in r.components.items():
                stored = float(at["components"].sel(component=name))
                assert stored == pytest.approx(float(value), rel=rtol, abs=1e-300)
            missing = set(ds["component"].values) - set(r.components)
            for name in missing:  # a mechanism this model does not have
                assert np.isnan(float(at["components"].sel(component=name)))


def test_store_carries_inputs_units_parameters_and_version(in_process: Path) -> None:
    import ballscrew

    with xr.open_zarr(in_process) as ds:
        assert ds.attrs["sweep_toml"] == SWEEP
        assert ds.attrs["case_toml"] == CASE.read_text("utf-8")
        assert ds.attrs["ballscrew_version"] == ballscrew.__version__
        assert ds.attrs["model_parameters"]["complete"]["boundary_friction"] == 0.1
        assert ds["torque"].attrs["units"] == "N*m"
        assert ds["speed"].attrs["units"] == "rad/s"
        assert ds["screw.preload"].attrs["units"] == "N"
        assert ds.attrs["units"]["power_loss"] == "W"
        assert ds.sizes["speed"] == 7 and list(ds["model"].values) == ["complete", "catalog"]


def test_chunks_group_the_work_by_screw() -> None:
    plan = plan_sweep(parse_sweep(SWEEP))
    # The operating grid (7 x 2 x 2 = 28 points) fits a chunk of 60 whole; the chunk
    # then takes two points of the innermost outer axis (two screws, one friction call
    # each), and one model.
    assert plan.chunks == (1, 1, 1, 2, 7, 2, 2)
    assert plan.n_chunks == 2 * 2 * 2 * 1


def test_interrupted_run_resumes_in_process(tmp_path: Path, in_process: Path) -> None:
    out = tmp_path / "r.zarr"
    spec = parse_sweep(SWEEP)

    def stop_after(done: int, total: int) -> None:
        if done == 3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(spec, out, progress=stop_after)
    assert not out.exists()  # nothing at the target until the store is complete
    told: list[str] = []
    report = run_sweep(spec, out, notify=told.append)
    assert report.resumed == 3 and report.computed == report.plan.n_chunks - 3
    assert any(t.startswith("resuming: 3 of") for t in told)
    assert not partial_path(out).exists()
    found, reference = _arrays(out), _arrays(in_process)
    assert all(np.array_equal(found[k], reference[k], equal_nan=True) for k in OUTPUTS)


def test_changed_sweep_restarts_instead_of_resuming(tmp_path: Path) -> None:
    out = tmp_path / "r.zarr"

    def stop_after(done: int, total: int) -> None:
        if done == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(parse_sweep(SWEEP), out, progress=stop_after)
    told: list[str] = []
    changed = parse_sweep(SWEEP.replace('"0.8, 1.6 kN"', '"0.9, 1.6 kN"'))
    report = run_sweep(changed, out, notify=told.append)
    assert report.resumed == 0 and any(t.startswith("restarting") for t in told)
    with xr.open_zarr(out) as ds:
        assert list(ds["screw.preload"].values) == [900.0, 1600.0]


def _markers(out: Path) -> int:
    folder = progress_path(partial_path(out))
    return len(list(folder.glob("*.json"))) if folder.exists() else 0


def _interrupted(
    args: list[str], out: Path, sig: int, after: int
) -> subprocess.CompletedProcess[str]:
    """Start a real run; signal it once ``after`` more chunks are marked done."""
    before = _markers(out)
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    began = time.monotonic()
    while time.monotonic() < began + 60 and proc.poll() is None:
        if _markers(out) >= before + after:
            break
        time.sleep(0.005)
    if proc.poll() is None:
        proc.send_signal(sig)
    stdout, stderr = proc.communicate(timeout=60)
    return subprocess.CompletedProcess(args, proc.returncode, stdout, stderr)


@pytest.mark.slow
def test_killed_cli_run_leaves_no_store_and_reruns_resume(tmp_path: Path) -> None:
    sweep = tmp_path / "s.toml"
    # Many small chunks of the complete model: long enough to be interrupted twice.
    sweep.write_text(
        f'case = "{CASE.as_posix()}"\nchunk_points = 64\n[axes]\nspeed = "10..3000:64 rpm"\n'
        '"screw.preload" = "0.5..2 kN:40"\n',
        encoding="utf-8",
    )
    out = tmp_path / "big.zarr"
    args = [sys.executable, "-m", "ballscrew", "sweep", str(sweep), "--out", str(out)]
    first = _interrupted(args, out, signal.SIGTERM, after=3)
    if first.returncode == 0:  # pragma: no cover - the machine outran the signal
        pytest.skip("the run finished before the signal arrived")
    assert first.returncode == 130, first.stderr
    assert "Traceback" not in first.stderr and "run the same command again" in first.stderr
    assert not out.exists()
    kept = _markers(out)
    second = _interrupted(args, out, signal.SIGINT, after=3)
    assert second.returncode in (0, 130), second.stderr
    assert f"resuming: {kept} of 40 chunks" in second.stderr
    assert not out.exists() or second.returncode == 0
    third = subprocess.run(args, capture_output=True, text=True, check=False)
    assert third.returncode == 0, third.stderr
    with xr.open_zarr(out) as ds:
        torque = ds["torque"].values
    assert np.isfinite(torque).all() and torque.shape == (1, 40, 64, 1, 1)
    # The resumed store holds what an uninterrupted run computes, chunk for chunk.
    clean = tmp_path / "clean.zarr"
    run_sweep(parse_sweep(sweep.read_text("utf-8")), clean)
    with xr.open_zarr(clean) as ds:
        assert np.array_equal(ds["torque"].values, torque)


BAD = [
    ('[axes]\nspeed = "10..3000:5"\n', "axes.speed"),
    ('[axes]\n"screw.preload" = "1, 2"\n', "axes.screw.preload"),
    ('[axes]\n"screw.pitch" = "30 mm"\n', "did you mean screw.pitch_diameter"),
    ('[axes]\n"screw.conformity_nut" = [0.45]\n', "axes.screw.conformity_nut"),
    ('[axes]\n"olaru.ball_ball_friction" = [0.1]\n', "axes.olaru.ball_ball_friction"),
    ('models = ["complet"]\n', "models"),
    ('outputs = ["torq"]\n', "outputs"),
    ("axis = 3\n", "did you mean axes"),
    ('case = "no_such_case.toml"\n', "case"),
    (
        '[uncertainty]\nsamples = 100\nsensitivity = "sobol"\n[uncertainty.inputs]\n'
        '"screw.preload" = { distribution = "uniform", low = "1 kN", high = "2 kN" }\n'
        '"lubricant.viscosity_scale" = { distribution = "uniform", low = 0.9, high = 1.1 }\n',
        "uncertainty.samples",
    ),
    (
        '[uncertainty.inputs]\n"screw.preload" = { distribution = "normal", mean = "1 kN" }\n',
        "uncertainty.inputs.screw.preload.std",
    ),
    (
        '[uncertainty.inputs]\n"screw.preload" = { distribution = "gauss", mean = "1 kN" }\n',
        "uncertainty.inputs.screw.preload.distribution",
    ),
]


@pytest.mark.parametrize(("text", "named"), BAD)
def test_bad_sweep_file_is_one_line_naming_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, named: str
) -> None:
    sweep = tmp_path / "bad.toml"
    sweep.write_text(f'case = "{CASE.as_posix()}"\n' * ("case =" not in text) + text, "utf-8")
    code, _, err = run(["sweep", str(sweep), "--out", str(tmp_path / "x.zarr")], capsys)
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and named in lines[0], err
    assert not (tmp_path / "x.zarr").exists()


def test_cli_refuses_to_replace_what_is_not_a_sweep_store(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "keep.txt").write_text("mine", "utf-8")
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'case = "{CASE.as_posix()}"\n', "utf-8")
    code, _, err = run(["sweep", str(sweep), "--out", str(folder)], capsys)
    assert code == 2 and "--out" in err
    assert (folder / "keep.txt").read_text("utf-8") == "mine"


def test_cli_prints_a_summary_and_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sweep = tmp_path / "s.toml"
    sweep.write_text(
        f'case = "{CASE.as_posix()}"\n[axes]\nspeed = "100, 1000 rpm"\naxial_load = "1 kN"\n',
        "utf-8",
    )
    out = tmp_path / "s.zarr"
    code, stdout, err = run(["sweep", str(sweep), "--out", str(out), "--json", "-"], capsys)
    assert code == 0, err
    data = json.loads(stdout)
    with xr.open_zarr(out) as ds:
        torque = ds["torque"].values
    s = data["summary"]["torque"]["complete"]
    assert s["max"] == pytest.approx(float(torque.max()), rel=1e-15)
    assert s["max_at"]["speed"] == pytest.approx(1000 * np.pi / 30)
    assert "Sweep summary" in err and "store:" in err


@pytest.mark.parametrize("name", ["sweep_preload.toml", "sweep_uncertainty.toml"])
def test_example_sweep_files_are_valid(name: str) -> None:
    from ballscrew.sweep.spec import load_sweep

    path = ROOT / "examples" / name
    plan = plan_sweep(load_sweep(path))  # every grid point is checked here
    assert plan.points > 0 and plan.dims[-3:] == ("speed", "temperature", "axial_load")


def test_uneven_chunks_hold_every_point_of_a_direct_grid(tmp_path: Path) -> None:
    # chunk_points = 8 cuts the 7 speeds of the operating grid (7 x 2 x 2) into pieces of
    # two (the last of one), starting at non-zero offsets; the whole store equals one
    # broadcast friction
    # call per preload, assembled here independently of the chunking.
    text = (
        f'case = "{CASE.as_posix()}"\nmodels = ["complete"]\nchunk_points = 8\n[axes]\n'
        'speed = "10..3000:7 rpm"\ntemperature = "20, 40 degC"\naxial_load = "0, 1 kN"\n'
        '"screw.preload" = "0.8, 1.2, 1.6 kN"\n'
    )
    out = tmp_path / "uneven.zarr"
    report = run_sweep(parse_sweep(text), out)
    assert report.plan.chunks == (1, 1, 2, 2, 2) and report.plan.n_chunks == 3 * 4
    case = load_case(CASE)
    w = np.linspace(10.0, 3000.0, 7) * np.pi / 30
    with xr.open_zarr(out) as ds:
        stored = ds["torque"].values
    for k, preload in enumerate((800.0, 1200.0, 1600.0)):
        direct = friction_torque(
            case.screw.replace(preload=preload), case.lubricant, speed=w[:, None, None],
            temperature=np.array([20.0, 40.0])[None, :, None],
            axial_load=np.array([0.0, 1000.0])[None, None, :],
        ).total  # fmt: skip
        np.testing.assert_allclose(stored[0, k], direct, rtol=1e-12)


def test_chunk_report_time_and_memory() -> None:
    # The report's seconds lie within the wall time of the call; its peak memory is the
    # process's high-water mark (Linux: VmHWM of /proc/self/status, in kB).
    from ballscrew.sweep.compute import compute_chunk

    plan = plan_sweep(parse_sweep(SWEEP))
    began = time.perf_counter()
    _, report = compute_chunk(plan.chunk(0))
    wall = time.perf_counter() - began
    assert 0.0 < report.seconds <= wall
    status = Path("/proc/self/status")
    if status.exists():
        line = next(x for x in status.read_text().splitlines() if x.startswith("VmHWM:"))
        hwm = int(line.split()[1]) * 1024
        # Both are the same high-water mark; memory touched between the two reads moves it.
        assert report.peak_rss == pytest.approx(hwm, rel=0.05)


def test_a_huge_sweep_is_refused_with_its_size_before_it_starts(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 27: a sweep of 1e13 points started and grew to 3.2 GB in 60 s with no word.
    sweep = tmp_path / "big.toml"
    sweep.write_text(
        f'case = "{DATA / "small_case.toml"}"\nmodels = ["complete", "catalog"]\n[axes]\n'
        'speed = "1..3000:100000 rpm"\ntemperature = "10..60:1000 degC"\n'
        'axial_load = "0..5 kN:1000"\n',
        "utf-8",
    )
    code, _, err = run(["sweep", str(sweep), "--out", str(tmp_path / "s.zarr")], capsys)
    # 2 models x 1e5 x 1e3 x 1e3 = 2e11 points; torque, efficiency and power loss by
    # default, 8 bytes each: 4.8e12 bytes.
    assert code == 2 and "200,000,000,000 points" in err and "4.8 TB" in err
    assert not (tmp_path / "s.zarr").exists()


@pytest.mark.slow
def test_two_sweeps_into_one_store_one_runs_the_other_is_refused(tmp_path: Path) -> None:
    # Issue 28: two sweeps into one --out corrupted it (all-NaN torques, or one sweep's data
    # under the other's temperatures) while exiting 0. Now the second is refused at once.
    import subprocess
    import sys

    sweep = tmp_path / "s.toml"
    sweep.write_text(
        f'case = "{DATA / "small_case.toml"}"\nmodels = ["complete"]\n[axes]\n'
        'speed = "10..3000:4000 rpm"\ntemperature = "20..60:40 degC"\n',
        "utf-8",
    )
    out = tmp_path / "one.zarr"
    command = [sys.executable, "-m", "ballscrew", "sweep", str(sweep), "--out", str(out)]
    runs = [subprocess.Popen(command, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    results = [(p.wait(timeout=600), p.communicate()[1]) for p in runs]
    codes = sorted(code for code, _ in results)
    assert codes == [0, 2], results
    refused = next(err for code, err in results if code == 2)
    assert "--out" in refused and "no other sweep is writing" in refused
    assert "internal error" not in "".join(err for _, err in results)
    import xarray as xr

    with xr.open_zarr(out) as ds:
        assert ds["torque"].shape[-3:] == (4000, 40, 1)
        assert bool(np.isfinite(ds["torque"].values).all())
        assert ds["temperature"].values[-1] == pytest.approx(60.0)
    assert not list(tmp_path.glob(".one.zarr*"))  # no lock, no partial folder left
