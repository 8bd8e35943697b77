"""The figure of ``ballscrew acceptance``: the readings against the makers' band."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure as MplFigure

from ..fit.acceptance import Acceptance

__all__ = ["acceptance_figure"]


def acceptance_figure(
    a: Acceptance, torque: npt.ArrayLike, speed: npt.ArrayLike | None = None
) -> MplFigure:
    """Each reading [N·m] by speed (or by its number), each speed's band, the band ± U."""
    fig = MplFigure(figsize=(7.0, 4.2), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    values = np.abs(np.atleast_1d(np.asarray(torque, dtype=float))).ravel()
    if speed is None:
        x = np.arange(1, values.size + 1, dtype=float)
        ax.set_xlabel("reading")
    else:
        x = np.abs(np.asarray(speed, dtype=float).ravel()) * 30.0 / math.pi
        ax.set_xlabel("screw speed [rpm]")
    ax.plot(x, values, "o", color="C0", markersize=3, label="readings")
    span = float(np.ptp(x)) or 1.0
    for k, v in enumerate(a.speeds):
        xs = (np.array([x.min(), x.max()]) if math.isnan(v.speed)
              else v.speed * 30.0 / math.pi + np.array([-0.03, 0.03]) * span)  # fmt: skip
        first = k == 0
        ax.fill_between(xs, v.low, v.high, color="C2", alpha=0.25,
                        label="band" if first else None)  # fmt: skip
        if a.uncertainty > 0.0:
            for edge in (v.low + a.uncertainty, v.high - a.uncertainty):
                ax.plot(xs, [edge, edge], color="C2", linestyle=":",
                        label="band narrowed by U" if first and edge == v.low + a.uncertainty
                        else None)  # fmt: skip
            for edge in (v.low - a.uncertainty, v.high + a.uncertainty):
                ax.plot(xs, [edge, edge], color="C3", linestyle=":",
                        label="band widened by U" if first and edge == v.low - a.uncertainty
                        else None)  # fmt: skip
        ax.plot(xs, [v.mean, v.mean], color="C1", linewidth=2,
                label="mean" if first else None)  # fmt: skip
    ax.set_ylabel("drag torque [N*m]")
    ax.set_ylim(bottom=0.0)
    ax.set_title(f"Drag torque against grade {a.grade}: {a.decision}", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return fig
