"""Controller tables against the controllers' documented syntax, and the FMU run by FMPy."""

from __future__ import annotations

import io
import os
import re
import shutil
import subprocess
import tempfile
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case
from ballscrew.report.controller_tables import (
    TABLE_WRITERS,
    FileOptions,
    merge_lincurve,
    takes_decimals,
)
from ballscrew.report.friction_files import c_header, write_map
from ballscrew.report.friction_fmu import find_compiler, fmi_platform, fmu_build, fmu_bytes
from ballscrew.servo.friction_map import friction_map
from ballscrew.servo.tables import DriveUnit, controller_table
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"


@pytest.fixture(scope="module")
def case():  # type: ignore[no-untyped-def]
    return load_case(EXAMPLE)


HALRUN = shutil.which("halrun")
needs_halrun = pytest.mark.skipif(
    HALRUN is None and not os.environ.get("CI"),
    reason="no halrun on this machine (make test installs Debian's linuxcnc-uspace); on CI "
    "this test runs",
)


def halrun(script: str, files: dict[str, str]) -> str:
    """Run a HAL ``script`` with ``files`` beside it in a real ``halrun``; its output.

    halrun refuses root, so as root the session runs as the unprivileged user ``nobody``
    (``runuser``), in a folder that user can read, with a HOME of its own.
    """
    assert HALRUN is not None, "CI needs halrun: make test installs linuxcnc-uspace"
    folder = Path(tempfile.mkdtemp(prefix="ballscrew-hal-"))
    try:
        for name, text in {**files, "test.hal": script}.items():
            (folder / name).write_text(text, "utf-8")
        command = [HALRUN, "-f", "test.hal"]
        env = {**os.environ, "HOME": str(folder)}
        if os.geteuid() == 0:
            runuser = shutil.which("runuser")
            if runuser is None:
                pytest.skip("halrun refuses root and runuser is missing to drop it")
            os.chmod(folder, 0o777)
            for path in folder.iterdir():
                os.chmod(path, 0o644)
            command = [runuser, "-u", "nobody", "--", "env", f"HOME={folder}", *command]
        done = subprocess.run(command, cwd=folder, env=env, capture_output=True, text=True,
                              timeout=120, check=False)  # fmt: skip
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout
    finally:
        shutil.rmtree(folder, ignore_errors=True)


@needs_halrun
def test_two_axes_lincurve_files_load_together_in_halrun(case, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    # Two axes' tables, the second appended to the first's file as the CLI does with
    # --append, loaded in one real HAL session (LinuxCNC's halrun): the component is
    # loaded once with both names, and each instance's out at a few inputs equals the
    # package's table (clamped beyond its ends, lincurve(9)).
    vertical = load_case(ROOT / "examples" / "vertical_32x5.toml")
    tx = controller_table(case, "complete", "lincurve", speed_range=5 / 60)
    ty = controller_table(vertical, "complete", "lincurve", speed_range=3 / 60)
    x_text = TABLE_WRITERS["lincurve"](tx, "test", FileOptions(axis="X"))
    y_text = TABLE_WRITERS["lincurve"](ty, "test", FileOptions(axis="Y"))
    both = merge_lincurve(x_text, y_text, "test")
    assert re.search(r"^loadrt lincurve names=x-friction,y-friction personality=16,16$",
                     both, re.M)  # fmt: skip
    # Replacing an axis keeps one block of it.
    assert merge_lincurve(both, y_text, "test") == both
    inputs = [-200.0, -40.0, -0.05, 0.0, 0.05, 7.3, 83.333, 200.0]  # mm/s
    lines = ["loadrt threads name1=servo-thread period1=1000000", "source friction.hal"]
    for v in inputs:
        lines += [f"setp x-friction.in {v}", f"setp y-friction.in {v}", "start",
                  "loadusr -w sleep 0.02", "stop", "getp x-friction.out",
                  "getp y-friction.out"]  # fmt: skip
    out = halrun("\n".join(lines) + "\n", {"friction.hal": both})
    got = np.array([float(v) for v in re.findall(r"^\s*(-?[\d.]+(?:e[-+]?\d+)?)\s*$", out,
                                                  re.M)]).reshape(-1, 2)  # fmt: skip
    for column, t in enumerate((tx, ty)):
        x = t.table.speed * 1e3
        expected = np.interp(inputs, x, t.motor_torque())
        # getp prints 7 significant digits: 1e-6 relative, 1e-7 N*m absolute near 0.
        assert got[:, column] == pytest.approx(expected, rel=1e-6, abs=1e-7)


def test_two_lincurve_loads_fail_so_the_axes_share_one(case) -> None:  # type: ignore[no-untyped-def]
    # Each file alone loads the component with its own name; merging gives one loadrt
    # line, and a file that is not ours is refused with the option's name.
    t = controller_table(case, "complete", "lincurve", speed_range=5 / 60)
    text = TABLE_WRITERS["lincurve"](t, "test", FileOptions(axis="Z"))
    assert len(re.findall(r"^loadrt ", text, re.M)) == 1
    assert "names=z-friction personality=16" in text
    xs = [float(v) for v in re.findall(r"^setp z-friction\.x-val-\d\d (\S+)$", text, re.M)]
    assert len(xs) == 16 and np.all(np.diff(xs) > 0)
    assert all(line.startswith(("#", "loadrt", "addf", "setp")) for line in text.splitlines())
    for word in ("formula", "units", "sign", "RMS"):
        assert word in text
    with pytest.raises(BallScrewInputError, match="--append"):
        merge_lincurve("loadrt lincurve count=1\n", text, "test")
    with pytest.raises(BallScrewInputError, match="--axis"):
        FileOptions(axis="x friction")


def _frict_comp(text: str) -> dict[str, str]:
    """The list's parameters: name -> value (comment lines '# ' skipped)."""
    out = {}
    for line in text.splitlines():
        if line.startswith("# ") or not line.strip():
            continue
        name, value = line.split()
        out[name] = value
    return out


def test_frict_comp_follows_the_twincat_parameters(case) -> None:  # type: ignore[no-untyped-def]
    # Beckhoff TF5200 axis compensation: kopf.achs_nr (P-COMP-00001) and
    # kopf.log_achs_name (P-COMP-00002) head the list; frict_comp.mode 3 (P-COMP-00041);
    # table_entries <= 20 (P-COMP-00042); scaling_factor in 0.1 %, 1000 = 100 %
    # (P-COMP-00045); table[i].in in um/s ascending from 0 (P-COMP-00046); table[i].out in
    # the drive's act_torque unit (P-COMP-00047); SGN32 before build V3.1.3132.0.
    with pytest.raises(BallScrewInputError, match="--drive-unit"):
        controller_table(case, "complete", "frict-comp", speed_range=5 / 60)
    with pytest.raises(BallScrewInputError, match="--torque-constant"):
        controller_table(case, "complete", "frict-comp", speed_range=5 / 60,
                         drive_unit=DriveUnit.parse("1 mA"))  # fmt: skip
    unit = DriveUnit.parse("0.1 % of 3.2 N*m")  # CiA 402 0x6077: per thousand of M0
    t = controller_table(case, "complete", "frict-comp", speed_range=5 / 60, drive_unit=unit)
    with pytest.raises(BallScrewInputError, match="--axis-number"):
        TABLE_WRITERS["frict-comp"](t, "test", FileOptions(axis="X"))
    text = TABLE_WRITERS["frict-comp"](t, "test", FileOptions(axis="X", axis_number=1))
    p = _frict_comp(text)
    assert list(p)[:2] == ["kopf.achs_nr", "kopf.log_achs_name"]
    assert p["kopf.achs_nr"] == "1" and p["kopf.log_achs_name"] == "X"
    assert p["frict_comp.mode"] == "3" and p["frict_comp.scaling_factor"] == "1000"
    n = int(p["frict_comp.table_entries"])
    ins = [p[f"frict_comp.table[{k}].in"] for k in range(n)]
    outs = [p[f"frict_comp.table[{k}].out"] for k in range(n)]
    assert n == 20 and len(p) == 5 + 2 * n
    assert all(re.fullmatch(r"-?\d+", v) for v in ins + outs)  # SGN32: integers
    speeds = np.array(ins, dtype=float)
    assert speeds[0] == 0.0 and np.all(np.diff(speeds) > 0)
    assert speeds[-1] == round(5 / 60 * 1e6)
    # out: the table's force through the lead to the motor torque [N*m], over one unit
    # of 3.2 mN*m, rounded; the last point's force read from the table independently.
    force = t.table(5 / 60)
    assert float(outs[-1]) == round(float(force) * 0.010 / (2 * np.pi) / 0.0032)
    # A current unit goes through K_t; a build from V3.1.3132.0 takes decimals.
    t_a = controller_table(case, "complete", "frict-comp", speed_range=5 / 60,
                           drive_unit=DriveUnit.parse("1 mA"), torque_constant=1.1)  # fmt: skip
    options = FileOptions(axis_number=2, cnc_build="V3.1.3132.0")
    text = TABLE_WRITERS["frict-comp"](t_a, "test", options)
    p = _frict_comp(text)
    assert "kopf.log_achs_name" not in p
    last = float(p["frict_comp.table[19].out"])
    assert last == pytest.approx(float(force) * 0.010 / (2 * np.pi) / 1.1 * 1e3, rel=1e-5)
    assert not re.fullmatch(r"-?\d+", p["frict_comp.table[19].out"])
    assert not takes_decimals("V3.1.3131.9") and takes_decimals("V4.29.0")
    assert not takes_decimals("V4.28.9") and not takes_decimals(None)


def _points(node: Any) -> list[list[int]]:
    """The (X, Y) of every structure initialisation under a blark array initialisation."""
    if type(node).__name__ == "StructureInitialization":
        return [[int(str(e.value)) for e in node.elements]]
    children = getattr(node, "elements", None) or [getattr(node, "element", None)]
    return [p for child in children if child is not None for p in _points(child)]


def test_charcurve_parses_as_iec_61131_3_and_matches_the_table(case) -> None:  # type: ignore[no-untyped-def]
    # The file is parsed by blark (a Lark grammar of IEC 61131-3 Structured Text); the
    # points are read from the parse tree, not from the text, and scaled back with the
    # powers of ten the header states.
    blark = pytest.importorskip("blark")
    t = controller_table(case, "complete", "charcurve", speed_range=5 / 60)
    text = TABLE_WRITERS["charcurve"](t, "test", FileOptions(axis="X"))
    parsed = blark.parse_source_code(text)
    assert parsed.exception is None, parsed.exception
    block = parsed.transform().items[0]
    assert str(block.name) == "FB_FrictionX"
    points = next(item for decl in block.declarations for item in decl.items
                  if str(item.variables[0].name) == "FrictionPoints")  # fmt: skip
    pairs = _points(points.init.value)
    assert 2 <= len(pairs) <= 11 and all(abs(v) <= 32767 for p in pairs for v in p)
    xs, ys = np.array(pairs, dtype=float).T
    assert np.all(np.diff(xs) > 0) and f"N := {len(pairs)}" in text
    kx = int(re.search(r"X: axis speed \[1e(-?\d+) mm/s\]", text).group(1))
    ky = int(re.search(r"Y: motor torque \[1e(-?\d+) mN\*m\]", text).group(1))
    speed = xs * 10.0**kx * 1e-3  # m/s
    torque = ys * 10.0**ky * 1e-3  # N*m
    # CHARCURVE interpolates the points linearly (its documentation): that curve against
    # the package's table over the range. The INT rounding is half a unit of ~8000 on each
    # axis (6e-5); the breakpoint next to zero speed moves by up to half a speed unit,
    # which shifts the jump through zero, so the largest deviation is taken outside the
    # first interval and the RMS over the whole range. Both within 0.24 % of the largest
    # torque (the figure for this file; the table's own interpolation error
    # against the model is 0.17 % RMS).
    v = np.linspace(-5 / 60, 5 / 60, 4001)
    curve = np.interp(v, speed, torque)
    table = t.motor_torque(t.table(v))
    largest = float(np.max(np.abs(table)))
    outside = np.abs(v) > max(speed[speed > 0][0], t.table.speed[t.table.speed > 0][0])
    assert np.max(np.abs(curve - table)[outside]) / largest < 0.0024
    assert np.sqrt(np.mean((curve - table) ** 2)) / largest < 0.0024


def test_more_points_fit_better(case) -> None:  # type: ignore[no-untyped-def]
    # The same curve in 11, 16 and 20 (one-sided) points: the error falls.
    errors = [controller_table(case, "complete", target, speed_range=5 / 60,
                               drive_unit=DriveUnit.parse("1 mN*m")).table.rms_error
              for target in ("charcurve", "lincurve", "frict-comp")]  # fmt: skip
    assert errors[0] > errors[1] > errors[2]


@pytest.fixture(scope="module")
def friction_map_small(case):  # type: ignore[no-untyped-def]
    return friction_map(case, "complete", speeds=np.geomspace(1.0, 300.0, 6),
                        loads=[-2000.0, 0.0, 2000.0], temperatures=[20.0, 40.0])  # fmt: skip


def _at_the_nodes(m, fmu: Path) -> None:  # type: ignore[no-untyped-def]
    """Simulate ``fmu`` (a file or an extracted folder) at the map's nodes with FMPy."""
    from fmpy import simulate_fmu

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
        result = simulate_fmu(str(fmu), start_time=0.0, stop_time=float(n),
                              output_interval=1.0, input=inputs,
                              output=["friction_torque"])  # fmt: skip
        got = result["friction_torque"][1:]
        expected = m.motor_torque[t_index, f_index, :]
        # 1e-6 relative: the header prints the table with 17 digits, so the FMU's
        # interpolation at a node returns the node's value to rounding.
        assert got == pytest.approx(expected, rel=1e-6)


@pytest.mark.skipif(find_compiler() is None, reason="no C compiler: the FMU is written "
                    "without a binary (the export says so)")  # fmt: skip
def test_the_fmu_validates_and_simulates_as_written(friction_map_small, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    # The file the CLI writes, as it is: FMPy's validation finds no problem (among its
    # checks: ModelStructure/InitialUnknowns, FMI 2.0 section 2.2.8), the archive holds
    # the sources and this platform's binary, and FMPy simulates the .fmu itself.
    from fmpy.validation import validate_fmu

    m = friction_map_small
    path = tmp_path / "friction.fmu"
    notes = write_map(m, path, "test")
    assert validate_fmu(str(path)) == []
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        xml = z.read("modelDescription.xml").decode()
    platform = fmi_platform()
    assert {"sources/ballscrew_friction_map.h", "sources/ballscrew_friction_fmu.c"} <= names
    assert any(n.startswith(f"binaries/{platform}/BallScrewFriction.") for n in names)
    assert re.search(r"<InitialUnknowns>\s*<Unknown index=\"4\" dependencies=\"1 2 3\"/>", xml)
    assert len(notes) == 1 and f"binary for {platform} compiled with" in notes[0]
    _at_the_nodes(m, path)


def test_without_a_compiler_the_fmu_is_the_sources_with_a_note(
    friction_map_small, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setenv("CC", "no-such-compiler-ballscrew")
    build = fmu_build(friction_map_small, "test", c_header(friction_map_small, "test"))
    assert build.platform is None and build.compiler is None
    assert "no C compiler found" in build.note and "fmpy compile" in build.note
    with zipfile.ZipFile(io.BytesIO(build.data)) as z:
        assert not any(n.startswith("binaries/") for n in z.namelist())


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake builds the FMU's binary")
def test_the_source_fmu_builds_elsewhere_and_equals_the_map(
    friction_map_small, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    # The sources alone, compiled as an importer does it (FMPy with CMake and the FMI 2.0
    # headers it ships, not the package's own declarations), give the map at its nodes.
    from fmpy.build import build_platform_binary

    m = friction_map_small
    folder = tmp_path / "fmu"
    with zipfile.ZipFile(io.BytesIO(fmu_bytes(m, "test", c_header(m, "test")))) as z:
        z.extractall(folder)
    (tmp_path / "build").mkdir()
    build_platform_binary(folder, build_dir=tmp_path / "build")
    _at_the_nodes(m, folder)


def test_the_cli_writes_two_axes_and_a_twincat_list_as_typed(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    # As a commissioning engineer types it: X, then Y appended to the same HAL file, then
    # X again (replaced, said in a note); the TwinCAT list with the drive's unit.
    from cli_runner import run

    hal = tmp_path / "friction.hal"
    base = ["export-friction", "--case", str(EXAMPLE), "--speed", "5 m/min"]
    code, _, err = run([*base, "--form", "lincurve", "--axis", "X", "--out", str(hal)], capsys)
    assert code == 0, err
    vertical = str(ROOT / "examples" / "vertical_32x5.toml")
    code, _, err = run(["export-friction", "--case", vertical, "--speed", "5 m/min",
                        "--form", "lincurve", "--axis", "Y", "--append", "--out", str(hal)],
                       capsys)  # fmt: skip
    assert code == 0, err
    text = hal.read_text("utf-8")
    assert "loadrt lincurve names=x-friction,y-friction personality=16,16" in text
    code, _, err = run([*base, "--form", "lincurve", "--axis", "X", "--append", "--out",
                        str(hal)], capsys)  # fmt: skip
    assert code == 0 and "x-friction replaced" in err
    assert hal.read_text("utf-8").count("setp x-friction.x-val-00 ") == 1
    # Options of one form refused on another, with their names.
    code, _, err = run([*base, "--form", "charcurve", "--append", "--out", str(hal)], capsys)
    assert code == 2 and "--append" in err
    code, _, err = run([*base, "--form", "stribeck", "--axis", "X"], capsys)
    assert code == 2 and "--axis" in err
    lis = tmp_path / "x.lis"
    twincat = [*base, "--form", "frict-comp", "--axis", "X", "--axis-number", "1"]
    code, _, err = run([*twincat, "--out", str(lis)], capsys)
    assert code == 2 and "--drive-unit" in err
    code, _, err = run([*twincat, "--drive-unit", "0.1 % of 4.5 A", "--out", str(lis)], capsys)
    assert code == 2 and "--torque-constant" in err
    code, _, err = run([*twincat, "--drive-unit", "0.1 % of 4.5 A", "--torque-constant",
                        "0.71 N*m/A", "--cnc-build", "V3.1.3132.0", "--out", str(lis)],
                       capsys)  # fmt: skip
    assert code == 0, err
    p = _frict_comp(lis.read_text("utf-8"))
    assert p["frict_comp.scaling_factor"] == "1000" and p["kopf.log_achs_name"] == "X"
    assert "." in p["frict_comp.table[19].out"]  # decimals from V3.1.3132.0
