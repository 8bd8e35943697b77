"""An unreliable fit is written as such into fitted-case.toml, and check and energy repeat it."""

from __future__ import annotations

import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.fit.calibration import UNRELIABLE_FIT
from ballscrew.io.case import parse_case
from cli_runner import run

OIL = "PAO ISO VG 68"
W = np.geomspace(10.0, 3000.0, 12) * np.pi / 30
TEMPS = np.array([20.0, 40.0])


def _fit(tmp_path: Path, capsys: pytest.CaptureFixture[str], hump: float) -> Path:
    """Fit the preload to the model's curve with a low-speed hump the model cannot follow."""
    w, t = (a.ravel() for a in np.meshgrid(W, TEMPS))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        torque = friction_torque(reference_screw().replace(preload=1500.0), OIL, speed=w,
                                 temperature=t, ball_train_constant=0.03).total  # fmt: skip
    csv = tmp_path / "run.csv"
    csv.write_text("speed [rad/s],temperature [degC],torque [N*m]\n" + "".join(
        f"{a:.17g},{b:.17g},{c:.17g}\n" for a, b, c in zip(
            w, t, torque * (1.0 + hump * np.exp(-w / 20.0)), strict=True)))  # fmt: skip
    case = tmp_path / "s.toml"
    case.write_text('[screw]\ndesignation = "HIWIN R40-10K5-FDC"\npreload = "2 kN"\n'
                    '[lubricant]\nname = "PAO ISO VG 68"\n[axis]\nmoving_mass = "100 kg"\n'
                    'bearing_span = "1000 mm"\n')  # fmt: skip
    out = tmp_path / f"fit{hump:g}"
    code, _, err = run(["fit", "--case", str(case), "--measured", str(csv), "--free", "preload",
                        "--out", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    return out / "fitted-case.toml"


def test_an_absurd_fit_is_flagged_in_the_file_and_repeated(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 34: the terminal said "unreliable", the file did not, and it fed check. A
    # low-speed friction hump the model cannot follow leaves structured residuals.
    fitted = _fit(tmp_path, capsys, 1.5)
    text = fitted.read_text(encoding="utf-8")
    assert text.startswith(f"# WARNING: {UNRELIABLE_FIT}.")
    data = tomllib.loads(text)
    assert data["description"].startswith(UNRELIABLE_FIT)
    assert data["screw"]["preload"]["assumed"].startswith(UNRELIABLE_FIT)
    case = parse_case(text)
    assert any(a.field == "screw.preload" and a.reason.startswith(UNRELIABLE_FIT)
               for a in case.assumptions)  # fmt: skip
    move = "stroke=200 mm, feed=5 m/min, acceleration=1 m/s^2"
    for command in ("energy", "check"):
        code, out, err = run([command, "--case", str(fitted), "--move", move, "--model",
                              "catalog", "--run-time", "10 min"], capsys)  # fmt: skip
        assert code == 0, err
        said = out + err
        assert "WARNING: this case comes from an unreliable fit (screw.preload)" in said, command


def test_a_sound_fit_is_written_plainly(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    text = _fit(tmp_path, capsys, 0.0).read_text(encoding="utf-8")
    assert UNRELIABLE_FIT not in text
    assert isinstance(tomllib.loads(text)["screw"]["preload"], str)
