"""``torque`` and the load map refuse a grid that would not fit, before it runs.

Issue 52: a 1e8-point load map ended in ``MemoryError``. The counts checked are the
grids' own (speeds x loads, both directions for a map); the refusal comes before any
point is computed (the run takes a second, not the hours the grid would).
"""

from __future__ import annotations

import time

import pytest

import ballscrew.io.resources as resources
from ballscrew.servo.friction_map import MAX_MAP_POINTS
from cli_runner import run


def test_a_torque_grid_past_the_memory_is_refused_whatever_max_points_says(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(resources, "available_memory", lambda: 2_000_000_000)
    start = time.monotonic()
    code, _, err = run(["torque", "--speed", "1..3000:10000 rpm", "--axial-load",
                        "0..4:10000 kN", "--max-points", "100000000", "--json", "-"],
                       capsys)  # fmt: skip
    assert code == 2, err
    assert "'100,000,000'" in err and "fit in memory" in err and "2 GB available" in err
    assert time.monotonic() - start < 30  # refused before the grid is computed


def test_a_torque_grid_that_fits_runs(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(resources, "available_memory", lambda: 2_000_000_000)
    code, _, err = run(["torque", "--speed", "100, 1000 rpm", "--table", "none"], capsys)
    assert code == 0, err


def test_without_a_memory_figure_nothing_is_refused_here(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(resources, "available_memory", lambda: None)
    resources.check_memory("points", 10**15, 1e3, "points", "take fewer")


def test_a_load_map_past_its_limit_is_refused_with_its_size(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # 1000 speeds, each both ways, x 1000 loads: 2,000,000 points, twice the limit.
    code, _, err = run(["export-friction", "--form", "load-map", "--speed",
                        "0.1..3000:1000 rpm", "--axial-load", "-4..4:1000 kN"], capsys)  # fmt: skip
    assert code == 2, err
    assert "2,000,000 (1000 speeds both ways x 1000 loads x 1 temperatures)" in err
    assert f"at most {MAX_MAP_POINTS:,}" in err and "MemoryError" not in err
