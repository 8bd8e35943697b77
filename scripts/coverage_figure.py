"""Draw docs/img/coverage_reliability.png, the reliability diagram of the check's P(NOT OK).

    .venv/bin/python scripts/coverage_figure.py

The reliability diagram of the axis check's uncertainty (ballscrew.study.coverage): 2000
synthetic cases per curve with a known truth, binned by the check's P(NOT OK) (ten bins of
0.1), against the share of them that are truly NOT OK, with two binomial standard errors;
on a calibrated check the points lie on the diagonal. Curves: the fatigue life and the
thermal lead error with their truths drawn from the distributions the check states, and the
thermal row with the true friction taken from the scorecard's printed rows (complete model,
double and 4-point nuts below 1 N*m). The legend gives the share of truths inside the 95 %
interval.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ballscrew.study.coverage import coverage

CURVES = (
    ("fatigue life, stated", {"criterion": "life"}, "C0", "o"),
    ("thermal, stated", {"criterion": "thermal"}, "C1", "s"),
    ("thermal, printed rows, double", {"criterion": "thermal", "friction": "rows"}, "C2", "^"),
    ("thermal, printed rows, 4-point",
     {"criterion": "thermal", "friction": "rows", "nut": "single-4point"}, "C3", "v"),
)  # fmt: skip


def draw() -> Figure:
    """The figure (scripts/docs_figures.py writes it with the version at each docs build)."""
    fig = Figure(figsize=(5.6, 5.0), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.subplots()
    ax.plot([0.0, 1.0], [0.0, 1.0], color="0.6", linestyle="--", linewidth=1.0,
            label="calibrated")  # fmt: skip
    for name, kwargs, color, marker in CURVES:
        c = coverage(cases=2000, **kwargs)  # type: ignore[arg-type]
        mean_p, observed, count = c.reliability()
        used = count >= 10
        se = np.sqrt(np.clip(mean_p * (1.0 - mean_p), 1e-4, None) / np.maximum(count, 1.0))
        ax.errorbar(mean_p[used], observed[used], yerr=2.0 * se[used], color=color,
                    marker=marker, markersize=4, linewidth=1.0, capsize=2,
                    label=f"{name}: {c.held():.1%} in the 95 % band")  # fmt: skip
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(0.0, 1.0)
    ax.set_xlabel("P(NOT OK) the check prints (bin mean)")
    ax.set_ylabel("share of the cases truly NOT OK")
    ax.set_title("Reliability of the check's P(NOT OK), 2000 cases per curve", fontsize=10)
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(True, linewidth=0.4, color="0.85")
    return fig


if __name__ == "__main__":
    out = Path(__file__).resolve().parents[1] / "docs" / "img" / "coverage_reliability.png"
    draw().savefig(out, dpi=120)
    print(out)
