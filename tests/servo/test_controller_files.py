"""Controller tables against the controllers' documented syntax, and the FMU run by FMPy."""

from __future__ import annotations

import io
import re
import shutil
import zipfile
from pathlib import Path

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.fit.friction_map import friction_map
from ballscrew.io.case import load_case
from ballscrew.report.controller_tables import TABLE_WRITERS
from ballscrew.report.friction_files import c_header
from ballscrew.report.friction_fmu import fmu_bytes
from ballscrew.servo.tables import controller_table
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"


@pytest.fixture(scope="module")
def case():  # type: ignore[no-untyped-def]
    return load_case(EXAMPLE)


def test_lincurve_follows_the_man_page(case) -> None:  # type: ignore[no-untyped-def]
    # lincurve(9): "loadrt lincurve ... personality=P", parameters x-val-NN and y-val-NN
    # set with setp, at most 16 points, x ascending (the input is located on the x axis).
    t = controller_table(case, "complete", "lincurve", speed_range=5 / 60)
    text = TABLE_WRITERS["lincurve"](t, "test")
    assert re.search(r"^loadrt lincurve count=1 personality=16$", text, re.M)
    xs = [float(v) for v in re.findall(r"^setp lincurve\.0\.x-val-(?:\d\d) (\S+)$", text, re.M)]
    ys = re.findall(r"^setp lincurve\.0\.y-val-(\d\d) \S+$", text, re.M)
    assert len(xs) == len(ys) == 16
    assert ys == [f"{k:02d}" for k in range(16)]
    assert np.all(np.diff(xs) > 0)
    assert all(line.startswith(("#", "loadrt", "addf", "setp")) for line in text.splitlines())
    for word in ("formula", "units", "sign", "RMS"):
        assert word in text


def test_frict_comp_follows_the_twincat_parameters(case) -> None:  # type: ignore[no-untyped-def]
    # TF5200 friction compensation: frict_comp.mode 3, table_entries <= 20 (P-COMP-00042),
    # table[i].in the speed in um/s, ascending and >= 0 (P-COMP-00046), table[i].out the
    # motor current (P-COMP-00047).
    with pytest.raises(BallScrewInputError, match="torque-constant"):
        controller_table(case, "complete", "frict-comp", speed_range=5 / 60)
    t = controller_table(case, "complete", "frict-comp", speed_range=5 / 60, torque_constant=1.1)
    text = TABLE_WRITERS["frict-comp"](t, "test")
    assert re.search(r"^frict_comp\.mode\s+3$", text, re.M)
    entries = int(re.search(r"^frict_comp\.table_entries\s+(\d+)$", text, re.M).group(1))
    ins = [float(v) for v in re.findall(r"^frict_comp\.table\[\d+\]\.in\s+(\S+)$", text, re.M)]
    outs = [float(v) for v in re.findall(r"^frict_comp\.table\[\d+\]\.out\s+(\S+)$", text, re.M)]
    assert entries == len(ins) == len(outs) <= 20
    assert ins[0] == 0.0 and np.all(np.diff(ins) > 0)
    assert ins[-1] == pytest.approx(5 / 60 * 1e6)
    # out is the current: the force through the lead and K_t, in mA.
    force = t.table.force[-1]
    assert outs[-1] == pytest.approx(force * 0.01 / (2 * np.pi) / 1.1 * 1e3, rel=1e-5)


def test_charcurve_follows_the_codesys_block(case) -> None:  # type: ignore[no-untyped-def]
    # Util CHARCURVE: P is ARRAY[0..10] OF POINT (X, Y: INT), 2 <= N <= 11, X ascending.
    t = controller_table(case, "complete", "charcurve", speed_range=5 / 60)
    text = TABLE_WRITERS["charcurve"](t, "test")
    assert "ARRAY[0..10] OF POINT" in text
    pairs = [(int(a), int(b)) for a, b in re.findall(r"\(X:=(-?\d+), Y:=(-?\d+)\)", text)]
    assert 2 <= len(pairs) <= 11
    xs = [p[0] for p in pairs]
    assert np.all(np.diff(xs) > 0)
    assert all(abs(v) <= 32767 for p in pairs for v in p)
    assert f"N := {len(pairs)}" in text


def test_more_points_fit_better(case) -> None:  # type: ignore[no-untyped-def]
    # The same curve in 11, 16 and 20 (one-sided) points: the error falls.
    errors = [controller_table(case, "complete", target, speed_range=5 / 60,
                               torque_constant=1.0).table.rms_error
              for target in ("charcurve", "lincurve", "frict-comp")]  # fmt: skip
    assert errors[0] > errors[1] > errors[2]


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake builds the FMU's binary")
def test_the_fmu_equals_the_map_at_its_nodes(case, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    from fmpy import simulate_fmu
    from fmpy.build import build_platform_binary

    m = friction_map(case, "complete", speeds=np.geomspace(1.0, 300.0, 6),
                     loads=[-2000.0, 0.0, 2000.0], temperatures=[20.0, 40.0])  # fmt: skip
    folder = tmp_path / "fmu"
    with zipfile.ZipFile(io.BytesIO(fmu_bytes(m, "test", c_header(m, "test")))) as z:
        z.extractall(folder)
    (tmp_path / "build").mkdir()
    build_platform_binary(folder, build_dir=tmp_path / "build")
    speeds = m.motor_speeds
    for t_index, f_index in ((0, 0), (1, 2), (1, 1)):
        n = speeds.size
        # Inputs held over each unit interval; FMPy records the output at the end of the
        # step, so the sample at time k + 1 belongs to the node k.
        names = ("time", "motor_speed", "axial_load", "temperature")
        inputs = np.zeros(2 * n, dtype=[(name, float) for name in names])
        inputs["time"] = np.repeat(np.arange(n, dtype=float), 2) + np.tile([0.0, 0.999], n)
        inputs["motor_speed"] = np.repeat(speeds, 2)
        inputs["axial_load"] = m.loads[f_index]
        inputs["temperature"] = m.temperatures[t_index]
        result = simulate_fmu(folder, start_time=0.0, stop_time=float(n), output_interval=1.0,
                              input=inputs, output=["friction_torque"])  # fmt: skip
        got = result["friction_torque"][1:]
        expected = m.motor_torque[t_index, f_index, :]
        # 1e-6 relative: the header prints the table with 17 digits, so the FMU's
        # interpolation at a node returns the node's value to rounding.
        assert got == pytest.approx(expected, rel=1e-6)
