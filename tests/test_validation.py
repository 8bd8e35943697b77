"""The validation cases, the scorecard and the validate command."""

from __future__ import annotations

import csv
import math
import subprocess
import sys
from pathlib import Path

import pytest

from ballscrew import lubricants, reference_screw
from ballscrew.validation import (
    bundled_summary,
    jungnickel_loss_torque,
    load_cases,
    score,
    summarise,
)
from ballscrew.validation_report import summary_table

CASES = load_cases()


@pytest.mark.parametrize(
    ("rpm", "temperature", "expected"),
    [(100, 40, 0.073), (1000, 40, 0.236), (3000, 40, 0.414), (100, 20, 0.134),
     (1000, 20, 0.436), (3000, 20, 0.765)],
)  # fmt: skip
def test_jungnickel_law_matches_the_public_implementation(
    rpm: float, temperature: float, expected: float
) -> None:
    # One half-nut of the reference screw (5 loaded turns, 2 kN, unsealed), computed with the
    # open-source Thermca implementation of the law and its own mineral ISO VG 68 data. Our
    # oil's viscosities and density differ from Thermca's by a few per cent, which moves the
    # torque as (rho nu)^0.5: 3 % tolerance.
    half = jungnickel_loss_torque(
        reference_screw(), lubricants.get("mineral ISO VG 68"), rpm * math.pi / 30, temperature
    )
    assert float(half) / 2.0 == pytest.approx(expected, rel=0.03)


def test_every_case_names_its_source_and_a_band_around_its_reference() -> None:
    assert len(CASES) >= 100
    for c in CASES:
        assert c.source.strip(), c.case
        assert 0.0 < c.low < c.reference < c.high, c.case


def test_catalog_cases_hold_the_catalogue_formula() -> None:
    # Independent form of T_p = 0.05/sqrt(tan b) F l/2pi: with l = pi d_m tan b it is
    # 0.025 F d_m sqrt(tan b) (rounded to 5 decimals in the file); the band is +-30 %.
    for c in (c for c in CASES if c.kind == "catalog"):
        tan_b = math.tan(c.screw.lead_angle)
        expected = 0.025 * c.screw.preload * c.screw.pitch_diameter * math.sqrt(tan_b)
        assert c.reference == pytest.approx(expected, abs=6e-6), c.case
        assert c.low == pytest.approx(0.7 * c.reference, abs=2e-5)  # each rounded to 1e-5
        assert c.high == pytest.approx(1.3 * c.reference, abs=2e-5)


def test_grid_spans_the_sizes_the_issue_asks_for() -> None:
    catalog = [c for c in CASES if c.kind == "catalog"]
    diameters = {round(c.screw.pitch_diameter * 1e3) for c in catalog}
    leads = {round(c.screw.lead * 1e3) for c in catalog}
    assert min(diameters) <= 16 and max(diameters) >= 60
    assert min(leads) <= 5 and max(leads) >= 32
    assert {c.screw.nut for c in catalog} == {"double", "single-4point"}
    assert any(c.training for c in catalog) and not all(c.training for c in catalog)


def test_catalog_model_scores_itself_perfectly_and_summary_counts() -> None:
    rows = score(["catalog"], [c for c in CASES if c.kind == "catalog"], trends=False)
    (s,) = summarise(rows)
    assert s.within == s.cases == len(rows)
    assert s.median_abs_log10 < 1e-4


def test_bundled_scorecard_summary_is_current() -> None:
    # `ballscrew models` shows data/scorecard_summary.csv; recompute it so it cannot go stale
    # (after a model change run scripts/update_scorecard.py).
    header, rows = summary_table(summarise(score()))
    fresh = {row[0]: dict(zip(header, row, strict=True)) for row in rows}
    assert bundled_summary() == fresh


def test_validate_command_writes_the_scorecard(tmp_path: Path) -> None:
    out = tmp_path / "card"
    run = subprocess.run(
        [sys.executable, "-m", "ballscrew", "validate", "--model", "catalog", "--model",
         "complete", "--out", str(out)],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert "complete" in run.stdout and "inside band" in run.stdout
    with (out / "validation.csv").open() as f:
        table = list(csv.DictReader(f))
    for column in ("case", "source", "reference_low", "reference_high", "model", "predicted",
                   "ratio", "within"):  # fmt: skip
        assert column in table[0]
    assert {r["model"] for r in table} == {"catalog", "complete"}
    for name in ("report.md", "report.html", "predicted_vs_reference.png", "summary.csv"):
        assert (out / name).stat().st_size > 0
    assert (out / "report.html").read_text().count("data:image/png;base64,") == 1
