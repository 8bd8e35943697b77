"""No silent default screw (issue 34, item 2): commands that judge or fit YOUR screw need --case."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_runner import run

SERIES = Path(__file__).resolve().parents[2] / "examples" / "drag_torque_series.csv"


@pytest.fixture
def curve(tmp_path: Path) -> Path:
    data = tmp_path / "m.csv"
    rows = "\n".join(f"{s},{0.3 + s * 1e-5}" for s in range(100, 3000, 300))
    data.write_text(f"speed [rpm],torque [N*m]\n{rows}\n", "utf-8")
    return data


@pytest.mark.parametrize(
    "args",
    [
        ["acceptance", "--torque", "0.30 N*m"],
        ["monitor", "--measured", str(SERIES), "--threshold", "50 %"],
        ["export-friction", "--measured", "{curve}", "--form", "stribeck"],
        ["fit", "--measured", "{curve}", "--free", "preload"],
    ],
)
def test_judging_or_fitting_without_a_case_is_refused(
    args: list[str], curve: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run([a.format(curve=curve) for a in args], capsys)
    assert code == 2, (out, err)
    assert "--case" in err and "bundled study screw" in err
    assert not out.strip()  # no verdict printed


def test_export_friction_of_the_model_keeps_the_bundled_case(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # Without --measured the command exports the model's friction: no measurement to misjudge.
    code, _, err = run(["export-friction", "--form", "coulomb-viscous"], capsys)
    assert code == 0, err


def test_demo_says_it_shows_the_bundled_screw(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(["demo"], capsys)
    assert code == 0
    assert out.splitlines()[0].startswith("demo: the bundled reference screw")


def test_study_says_it_runs_the_bundled_case(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    in_the_way = tmp_path / "a-file"
    in_the_way.write_text("mine", "utf-8")
    # An --out that cannot be made stops the study before it computes, after its first line.
    code, _, err = run(["study", "--out", str(in_the_way / "r")], capsys)
    assert code == 2
    assert err.splitlines()[0].startswith("study: the bundled case")
