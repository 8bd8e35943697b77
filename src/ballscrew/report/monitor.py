"""The figure of ``ballscrew monitor``: preload over time, its trend and the threshold."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure as MplFigure

from ..fit.monitor import MonitorResult
from .plotting import new_figure

__all__ = ["monitor_figure"]


def monitor_figure(r: MonitorResult) -> MplFigure:
    """Preload per measurement (95 % intervals), the trend with its band, the threshold."""
    fig = new_figure(7.0, 4.2, layout="constrained")
    ax = fig.add_subplot()
    t = r.series.time
    end = t[-1]
    if r.limit is not None and math.isfinite(r.crossing) and r.crossing > end:
        end = min(r.crossing * 1.1, t[-1] + 5.0 * (t[-1] - t[0]))
    grid = np.linspace(t[0], end, 400)
    mean, low, high = r.band(grid)
    ax.fill_between(grid, low, high, color="C0", alpha=0.2, label="trend, 95 % band")
    ax.plot(grid, mean, color="C0", linestyle="-", label=f"{r.trend_kind} trend")
    ax.errorbar(t, r.preload, yerr=[r.preload - r.preload_low, r.preload_high - r.preload],
                fmt="o", color="C1", markersize=4, capsize=2,
                label=f"preload read by {r.model} (95 %)")  # fmt: skip
    if r.limit is not None:
        ax.axhline(r.limit.value, color="C3", linestyle="--", label=f"threshold: {r.limit.text}")
        if math.isfinite(r.crossing):
            lo, hi = r.crossing_low, r.crossing_high
            ax.axvspan(lo if math.isfinite(lo) else grid[0], hi if math.isfinite(hi) else grid[-1],
                       color="C3", alpha=0.08, label="crossing, 95 % interval")  # fmt: skip
            ax.axvline(r.crossing, color="C3", linestyle=":", label=f"crossing {r.crossing:.0f} h")
    ax.set_xlabel("time [h]")
    ax.set_ylabel("preload [N]")
    ax.set_ylim(bottom=0.0)
    ax.set_title(f"Preload over the life: {Path(r.series.source).name}", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return fig
