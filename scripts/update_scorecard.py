"""Recompute the scorecard summary that ``ballscrew models`` shows (data/scorecard_summary.csv).

    .venv/bin/python scripts/update_scorecard.py

tests/study/test_validation.py recomputes it too and fails when the bundled file is stale.
"""

from __future__ import annotations

from pathlib import Path

from ballscrew.io.files import atomic_write
from ballscrew.report.validation import summary_csv
from ballscrew.study.validation import SUMMARY_FILE, score, summarise

if __name__ == "__main__":
    target = Path(__file__).resolve().parents[1] / "src" / "ballscrew" / "data" / SUMMARY_FILE
    atomic_write(target, summary_csv(summarise(score())))
    print(target.read_text())
