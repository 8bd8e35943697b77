"""The friction map over speed, load and temperature, and the files drives and simulators read."""

from __future__ import annotations

import csv
import io
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import RegularGridInterpolator
from scipy.io import loadmat

from ballscrew import friction_torque
from ballscrew.axis.energy import reverse_efficiency
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case
from ballscrew.io.numbers import significant_digits
from ballscrew.report.friction_files import FORMATS, MAP_DIGITS, write_map
from ballscrew.servo.friction_map import LoadForm, fit_load_form, friction_map, load_form
from cli_runner import run

CASE = load_case(None)  # the bundled study case
SPEEDS = np.geomspace(1.0, 300.0, 12)  # rad/s
LOADS = np.array([-3000.0, -1500.0, 0.0, 1500.0, 3000.0])
TEMPS = np.array([20.0, 40.0])


@pytest.fixture(scope="module")
def fmap():  # type: ignore[no-untyped-def]
    return friction_map(CASE, "complete", speeds=SPEEDS, loads=LOADS, temperatures=TEMPS,
                        gear_ratio=2.0)  # fmt: skip


def test_the_map_is_the_models_torque_signed_like_the_speed(fmap) -> None:  # type: ignore[no-untyped-def]
    w = np.concatenate([-SPEEDS[::-1], SPEEDS])
    np.testing.assert_array_equal(fmap.speeds, w)
    for i, t in enumerate(TEMPS):
        for j, f in enumerate(LOADS):
            direct = friction_torque(CASE.screw, CASE.lubricant, speed=w, temperature=t,
                                     axial_load=f, model="complete").total  # fmt: skip
            # The same computation on a broadcast grid: equal to rounding.
            np.testing.assert_allclose(fmap.torque[i, j], np.sign(w) * direct, rtol=1e-12)
    # Table side: F_f = 2 pi T_f / l; motor side: torque / i, speed * i.
    np.testing.assert_allclose(fmap.force, fmap.torque * 2 * math.pi / CASE.screw.lead)
    np.testing.assert_allclose(fmap.motor_torque * 2.0, fmap.torque)
    np.testing.assert_allclose(fmap.motor_speeds, 2.0 * w)


def test_driving_and_back_driving_as_the_models_two_efficiencies(fmap) -> None:  # type: ignore[no-untyped-def]
    # At w > 0 a load F < 0 resists the motion (the motor drives), F > 0 back-drives.
    k = int(np.searchsorted(fmap.speeds, SPEEDS[5]))
    f, lead = 3000.0, CASE.screw.lead
    drive = fmap.torque[1, 0, k]  # F = -3 kN
    back = fmap.torque[1, -1, k]  # F = +3 kN
    work = f * lead / (2 * math.pi)  # the load's torque on the screw
    r = friction_torque(CASE.screw, CASE.lubricant, speed=SPEEDS[5], temperature=40.0,
                        axial_load=f, model="complete")  # fmt: skip
    # Forward: the motor supplies F l/2pi + T_f; eta = (F l/2pi) / that.
    assert work / (work + drive) == pytest.approx(float(r.efficiency), rel=1e-12)
    # Back-driving: the load's torque less T_f reaches the motor; eta' = that / (F l/2pi).
    assert (work - back) / work == pytest.approx(float(reverse_efficiency(r, lead)), rel=1e-12)


def test_the_compact_form_recovers_known_coefficients_exactly() -> None:
    truth = LoadForm(c0=0.3, c1=4e-5, c2=-6e-6, b=2e-4, k_c=0.004, k_b=0.025,
                     reference_temperature=20.0, rms_error=0.0, max_error=0.0)  # fmt: skip
    w = np.concatenate([-SPEEDS[::-1], SPEEDS])
    t = np.array([20.0, 35.0, 50.0])
    torque = load_form(w[None, None, :], LOADS[None, :, None], t[:, None, None], truth)
    fit = fit_load_form(w, LOADS, t, torque)
    for name in ("c0", "c1", "c2", "b", "k_c", "k_b"):
        # Linear least squares on exact data, then an exact log-linear line: rounding only.
        assert getattr(fit, name) == pytest.approx(getattr(truth, name), rel=1e-8), name
    assert fit.max_error < 1e-12


def test_direction_term_is_zero_for_a_model_symmetric_in_the_power_flow(fmap) -> None:  # type: ignore[no-untyped-def]
    # The complete model dissipates the same at +F and -F: c2 vanishes. Its least-squares
    # value is rounding (1e-21 N*m/N, of a different sign on each path through the model),
    # so it is printed as exactly 0 and the same in every run.
    assert fmap.form.c2 == 0.0 and all(p["c2_Nm_per_N"] == 0.0
                                       for p in fmap.form.per_temperature)  # fmt: skip
    assert any("agrees to" in n for n in fmap.notes)


def test_the_form_never_drives_the_motion_and_states_its_error(fmap) -> None:  # type: ignore[no-untyped-def]
    assert fmap.form.c0 > 0.0 and fmap.form.c1 >= 0.0 and fmap.form.b >= 0.0
    err = fmap.form.torque(fmap.speeds[None, None, :], fmap.loads[None, :, None],
                           fmap.temperatures[:, None, None]) - fmap.torque  # fmt: skip
    assert fmap.form.max_error == pytest.approx(float(np.max(np.abs(err))), rel=1e-12)
    assert fmap.form.rms_error == pytest.approx(float(np.sqrt(np.mean(err**2))), rel=1e-12)


def test_csv_read_back(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "map.csv"
    write_map(fmap, path, "test")
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("# ballscrew test: friction map of complete")
    assert any("conventions:" in line for line in lines)
    rows = list(csv.DictReader(io.StringIO("\n".join(x for x in lines if x[:1] != "#"))))
    assert len(rows) == fmap.torque.size
    # The map's CSV carries 6 significant digits (MAP_DIGITS): each value within half a
    # unit of its 6th digit, 5e-6 of it, far below the compact form's and the model's error.
    back = np.array([float(r["motor friction torque [N*m]"]) for r in rows])
    np.testing.assert_allclose(back.reshape(fmap.torque.shape), fmap.motor_torque, rtol=5e-6)
    force = np.array([float(r["friction force [N]"]) for r in rows])
    np.testing.assert_allclose(force.reshape(fmap.torque.shape), fmap.force, rtol=5e-6)
    v = np.array([float(r["table speed [m/s]"]) for r in rows]).reshape(fmap.torque.shape)
    np.testing.assert_allclose(v[0, 0], fmap.speeds * CASE.screw.lead / (2 * math.pi), rtol=5e-6)
    assert all(significant_digits(x) <= MAP_DIGITS for r in rows for x in r.values())


def test_mat_read_back_as_a_lookup_table(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "map.mat"
    write_map(fmap, path, "test")
    m = loadmat(path)
    axes = (m["motor_speed_rad_s"].ravel(), m["axial_load_N"].ravel(), m["temperature_C"].ravel())
    table = m["motor_friction_torque_Nm"]
    assert table.shape == (fmap.speeds.size, fmap.loads.size, fmap.temperatures.size)
    lookup = RegularGridInterpolator(axes, table)
    # At the nodes the lookup gives the model's torque back.
    w, f, t = np.meshgrid(*axes, indexing="ij")
    got = lookup(np.stack([w.ravel(), f.ravel(), t.ravel()], axis=-1)).reshape(w.shape)
    np.testing.assert_allclose(np.transpose(got, (2, 1, 0)), fmap.motor_torque, rtol=1e-14)
    assert "conventions" in str(m["description"])
    assert m["__header__"] == b"MATLAB 5.0 MAT-file, written by ballscrew test"


def test_two_exports_of_one_map_are_the_same_bytes(  # type: ignore[no-untyped-def]
    fmap, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Issue 35: scipy puts the clock's time in the MAT-file's text; two runs must not differ,
    # even a second apart (the clock made to tick at every call).
    ticks = iter(range(1_000_000))
    monkeypatch.setattr("time.asctime", lambda *a: f"tick {next(ticks)}")
    for suffix in FORMATS:
        one, two = tmp_path / f"one{suffix}", tmp_path / f"two{suffix}"
        write_map(fmap, one, "test")
        write_map(fmap, two, "test")
        assert one.read_bytes() == two.read_bytes(), suffix


def test_modelica_record_and_tables(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "map.mo"
    write_map(fmap, path, "test")
    text = path.read_text(encoding="utf-8")
    assert text.startswith("package BallScrewFriction_complete") and text.rstrip().endswith(
        "end BallScrewFriction_complete;"
    )
    value = {k: float(v) for k, v in re.findall(r"parameter Real (\w+)\([^)]*\) = ([^;]+);", text)}
    assert value["c0"] == pytest.approx(fmap.form.c0 / 2.0, rel=1e-9)
    assert value["b"] == pytest.approx(fmap.form.b / 4.0, rel=1e-9)
    table = re.search(r"table_40degC\[(\d+), (\d+)\] = \[([^\]]+)\]", text)
    assert table is not None
    rows = [[float(x) for x in r.split(",")] for r in table.group(3).split(";")]
    matrix = np.array(rows)
    np.testing.assert_allclose(matrix[0, 1:], fmap.loads)
    np.testing.assert_allclose(matrix[1:, 0], fmap.motor_speeds, rtol=1e-9)
    np.testing.assert_allclose(matrix[1:, 1:], fmap.motor_torque[1].T, rtol=1e-9)


def _c_program(header: Path, points: np.ndarray) -> str:
    call = '    printf("%.17g\\n", bs_friction_torque({!r}, {!r}, {!r}));'
    calls = "\n".join(call.format(*(float(x) for x in p)) for p in points)
    head = f'#include <stdio.h>\n#include "{header}"\n'
    return head + f"int main(void) {{\n{calls}\n    return 0;\n}}\n"


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler: the parse test covers it")
def test_c_header_compiles_and_interpolates_like_scipy(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    header = tmp_path / "map.h"
    write_map(fmap, header, "test")
    axes = (fmap.temperatures, fmap.loads, fmap.motor_speeds)
    rng = np.random.default_rng(3)
    inside = np.column_stack([rng.uniform(a.min(), a.max(), 25) for a in axes[::-1]])
    outside = np.array([[1e4, 5000.0, 60.0], [-1e4, -5000.0, 0.0]])
    points = np.vstack([inside, outside])  # (motor speed, load, temperature)
    source = tmp_path / "main.c"
    source.write_text(_c_program(header, points), encoding="utf-8")
    exe = tmp_path / "main"
    subprocess.run(["cc", "-std=c99", "-Wall", "-Werror", "-O1", "-o", str(exe), str(source)],
                   check=True, capture_output=True)  # fmt: skip
    got = np.array(subprocess.run([str(exe)], check=True, capture_output=True, text=True)
                   .stdout.split(), dtype=float)  # fmt: skip
    # An independent trilinear interpolation (scipy), clamped as the header documents.
    lookup = RegularGridInterpolator(axes, fmap.motor_torque)
    clamped = np.column_stack([np.clip(points[:, 2], *axes[0][[0, -1]]),
                               np.clip(points[:, 1], *axes[1][[0, -1]]),
                               np.clip(points[:, 0], *axes[2][[0, -1]])])  # fmt: skip
    np.testing.assert_allclose(got, lookup(clamped), rtol=1e-12, atol=1e-15)


def test_c_header_arrays_parse_back(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    header = tmp_path / "map.h"
    write_map(fmap, header, "test")
    text = header.read_text(encoding="utf-8")
    arrays = {n: np.array(v.split(","), dtype=float) for n, v in
              re.findall(r"static const double (\w+)\[\d+\] = \{([^}]*)\};", text)}  # fmt: skip
    np.testing.assert_array_equal(arrays["BS_FRICTION_TORQUE_NM"], fmap.motor_torque.ravel())
    np.testing.assert_array_equal(arrays["BS_MOTOR_SPEED_RAD_S"], fmap.motor_speeds)


def test_bad_inputs_name_the_field(fmap, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(BallScrewInputError, match="--out"):
        write_map(fmap, tmp_path / "map.xlsx", "test")
    with pytest.raises(BallScrewInputError, match="--speed"):
        friction_map(CASE, "complete", speeds=[0.0, 5.0], loads=[0.0], temperatures=[40.0])
    with pytest.raises(BallScrewInputError, match="gear_ratio"):
        friction_map(CASE, "complete", speeds=SPEEDS, loads=[0.0], temperatures=[40.0],
                     gear_ratio=0.0)  # fmt: skip
    assert set(FORMATS) == {".csv", ".mat", ".mo", ".h", ".fmu"}


def test_cli_load_map(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "f.mat"
    code, stdout, err = run(["export-friction", "--form", "load-map", "--axial-load", "-2..2:5 kN",
                             "--temperature", "20, 40 degC", "--speed", "1..3000:12 rpm",
                             "--out", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    words = " ".join(stdout.split())  # the table's title wraps at the table's width
    assert "load map of" in words and "fit error over the grid" in words
    assert loadmat(out)["axial_load_N"].ravel().tolist() == [-2000.0, -1000.0, 0.0, 1000.0, 2000.0]
    code, _, err = run(["export-friction", "--form", "load-map", "--out", str(tmp_path / "f.txt")],
                       capsys)  # fmt: skip
    assert code == 2 and "--out" in err
    code, _, err = run(["export-friction", "--form", "load-map"], capsys)
    assert code == 0 and "c1 and c2 are not identified" in err


def test_the_three_sides_of_the_compact_form(fmap) -> None:  # type: ignore[no-untyped-def]
    # Independent conversions: F = 2 pi T / l; v = l w / 2 pi, so a viscous torque per
    # rad/s b becomes b (2 pi / l)^2 N per m/s; the motor side through i = 2: T / i and,
    # per motor rad/s, b / i^2.
    doc = fmap.form.as_drive_dict(CASE.screw.lead, 2.0)
    k = 2 * math.pi / CASE.screw.lead
    for name in ("c0", "c1", "c2", "b"):
        screw = doc["screw_side"][name]["value"]
        assert screw == getattr(fmap.form, name)
        assert doc["table_side"][name]["value"] == pytest.approx(
            screw * (k * k if name == "b" else k), rel=1e-12
        )
        assert doc["motor_side"][name]["value"] == pytest.approx(
            screw / (4.0 if name == "b" else 2.0), rel=1e-12
        )
    assert doc["k_c"]["value"] == fmap.form.k_c and doc["k_b"]["value"] == fmap.form.k_b
    assert doc["reference_temperature"]["value"] == 20.0
    rows = fmap.rows()
    t, f, w = np.meshgrid(TEMPS, LOADS, fmap.speeds, indexing="ij")
    got = {key: np.array([r[key] for r in rows]).reshape(t.shape) for key in rows[0]}
    np.testing.assert_array_equal(got["temperature [degC]"], t)
    np.testing.assert_array_equal(got["axial load [N]"], f)
    np.testing.assert_allclose(got["table speed [m/s]"], w / k, rtol=1e-14)
    np.testing.assert_allclose(got["motor speed [rad/s]"], 2.0 * w, rtol=1e-14)
    np.testing.assert_allclose(got["motor speed [rpm]"], 2.0 * w * 60 / (2 * math.pi), rtol=1e-12)
    np.testing.assert_allclose(got["friction force [N]"], fmap.torque * k, rtol=1e-14)
    np.testing.assert_array_equal(got["back-driving [-]"], np.sign(f * w))
    np.testing.assert_allclose(fmap.table_speeds, fmap.speeds / k, rtol=1e-14)


def test_an_inclined_axis_names_its_weight() -> None:
    from ballscrew.io.case import parse_case

    text = ('title = "z"\n[screw]\ndesignation = "40x10 double 2.5x2 6.35"\npreload = "2 kN"\n'
            '[lubricant]\nname = "mineral ISO VG 68"\n[axis]\nmoving_mass = "100 kg"\n'
            'incline = "30 deg"\n')  # fmt: skip
    m = friction_map(parse_case(text), "catalog", speeds=SPEEDS[:3], loads=[0.0],
                     temperatures=[40.0])  # fmt: skip
    # 100 kg g sin 30 deg = 490.3 N.
    assert any("its weight adds 490.3 N" in n for n in m.notes)


def test_every_side_of_a_form_with_a_direction_term() -> None:
    form = LoadForm(c0=0.3, c1=4e-5, c2=-6e-6, b=2e-4, k_c=0.004, k_b=0.025,
                    reference_temperature=20.0, rms_error=0.0, max_error=0.0)  # fmt: skip
    lead, i = 0.01, 3.0
    k = 2 * math.pi / lead
    doc = form.as_drive_dict(lead, i)
    assert doc["table_side"]["c2"]["value"] == pytest.approx(-6e-6 * k, rel=1e-12)
    assert doc["motor_side"]["c2"]["value"] == pytest.approx(-2e-6, rel=1e-12)
    assert doc["motor_side"]["b"]["value"] == pytest.approx(2e-4 / 9.0, rel=1e-12)
    plain = form.as_drive_dict(lead)  # no gear: the motor is the screw
    assert {n: v["value"] for n, v in plain["motor_side"].items()} == {
        n: v["value"] for n, v in plain["screw_side"].items()
    }
