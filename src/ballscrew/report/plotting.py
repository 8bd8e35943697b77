"""Figures of the study report (matplotlib, no global state, reproducible bytes).

Each figure is drawn on its own :class:`matplotlib.figure.Figure` with the Agg
canvas (no display needed) and saved as PNG and SVG with the date and
software metadata removed and a fixed SVG hash salt, so that the same inputs
give byte-identical files.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any, Literal

import matplotlib as mpl
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure as MplFigure
from matplotlib.ticker import FuncFormatter

from ..io.measured import MeasuredCurve
from ..kinematics import rad_s_to_rpm
from ..study.series import Figure
from ..sweep.sensitivity import SobolIndices

__all__ = [
    "figure_bytes",
    "new_figure",
    "render",
    "sensitivity_figure",
]

_LINESTYLES = ("-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1, 1, 1)))
_MARKERS = ("o", "s", "^", "v", "D", "x", "P", "*", "<", ">")

_STYLE: dict[str, Any] = {
    "svg.hashsalt": "ballscrew",
    "font.size": 9.0,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "figure.dpi": 100,
}


def new_figure(
    width: float, height: float, *, layout: Literal["constrained"] | None = None
) -> MplFigure:
    """A Matplotlib figure of ``width`` x ``height`` inches on its own Agg canvas.

    Figures are drawn without pyplot (no global state, safe in threads and workers), so
    each needs a canvas attached before it is drawn or saved.
    """
    fig = MplFigure(figsize=(width, height), layout=layout)
    FigureCanvasAgg(fig)
    return fig


def render(
    fig: Figure,
    measured_range: tuple[float, ...] = (),
    measured: MeasuredCurve | None = None,
    band_source: str = "given in the case",
) -> MplFigure:
    """Draw one study figure: torque against screw speed, measured band and curve."""
    with mpl.rc_context(_STYLE):  # type: ignore[arg-type]
        out = new_figure(7.5, 5.2, layout="constrained")
        ax = out.add_subplot(1, 1, 1)
        if len(measured_range) >= 2:
            lo, hi = min(measured_range), max(measured_range)
            ax.axhspan(
                lo,
                hi,
                color="0.85",
                zorder=0,
                label=f"measured range {lo:g} to {hi:g} N·m ({band_source})",
            )
        if fig.stacked:
            ax.stackplot(
                fig.series[0].speed_rpm,
                *(s.torque for s in fig.series),
                labels=[s.label for s in fig.series],
                alpha=0.85,
            )
        else:
            # Told apart by line style and marker as well as colour (printed in grey, or
            # read by someone who does not see colours apart).
            for k, s in enumerate(fig.series):
                ax.plot(s.speed_rpm, s.torque, lw=1.6, label=s.label,
                        linestyle=_LINESTYLES[k % len(_LINESTYLES)],
                        marker=_MARKERS[k % len(_MARKERS)], markersize=4,
                        markevery=max(1, len(s.speed_rpm) // 8))  # fmt: skip
        if measured is not None:
            ax.plot(
                rad_s_to_rpm(measured.speed),
                measured.torque,
                "k.",
                ms=4,
                label=f"measured ({measured.source.rsplit('/', 1)[-1]})",
            )
        ax.set_xlabel("screw speed [rpm]")
        ax.set_ylabel("friction torque [N·m]")
        ax.set_title(fig.title)
        if fig.log_y:
            ax.set_yscale("log")
            # Plain numbers on the log axis (0.02, 0.1, 2), not 2x10^0.
            plain = FuncFormatter(lambda v, _: f"{v:g}")
            ax.yaxis.set_major_formatter(plain)
            ax.yaxis.set_minor_formatter(FuncFormatter(
                lambda v, _: f"{v:g}" if f"{v:.1e}"[0] in "25" else ""))  # fmt: skip
        else:
            top = (
                float(np.max(sum(s.torque for s in fig.series)))
                if fig.stacked
                else max(float(np.max(s.torque)) for s in fig.series)
            )
            if len(measured_range) >= 2:
                top = max(top, max(measured_range))
            ax.set_ylim(0.0, 1.1 * top if top > 0 else 1.0)
        ax.set_xlim(left=0.0)
        # Below the axes, in columns: no data hidden and no third of the figure left blank.
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14),
                  ncols=min(3, len(ax.get_legend_handles_labels()[0])), frameon=False)  # fmt: skip
    return out


def sensitivity_figure(indices: SobolIndices, title: str) -> MplFigure:
    """The inputs ranked by their total Sobol index, with first-order indices beside.

    Horizontal bars, largest share of the variance at the top; the whiskers
    are the 95 % bootstrap half-widths.
    """
    order = indices.ranking()[::-1]  # barh draws from the bottom up
    y = np.arange(len(order), dtype=float)
    with mpl.rc_context(_STYLE):  # type: ignore[arg-type]
        out = new_figure(7.5, 0.45 * len(order) + 1.6)
        ax = out.add_subplot(1, 1, 1)
        ax.barh(y + 0.2, indices.total[order], height=0.38, xerr=indices.total_conf[order],
                label="total index S_T", color="C0", capsize=2)  # fmt: skip
        ax.barh(y - 0.2, indices.first[order], height=0.38, xerr=indices.first_conf[order],
                label="first-order index S_1", color="C1", capsize=2)  # fmt: skip
        ax.set_yticks(y, [indices.names[i] for i in order])
        ax.set_xlabel("share of the variance of the torque (averaged over the operating points)")
        ax.set_xlim(left=min(0.0, float(np.min(indices.first - indices.first_conf))))
        ax.set_title(title)
        ax.legend(fontsize=7, loc="lower right")
        out.tight_layout()
    return out


def figure_bytes(figure: MplFigure, kind: str) -> bytes:
    """The figure as PNG or SVG bytes, without date or software metadata."""
    buffer = io.BytesIO()
    with mpl.rc_context(_STYLE):  # type: ignore[arg-type]
        if kind == "png":
            figure.savefig(buffer, format="png", dpi=120, metadata={"Software": None})
        elif kind == "svg":
            figure.savefig(buffer, format="svg", metadata={"Date": None, "Creator": None})
        else:  # pragma: no cover - internal use only
            raise ValueError(kind)
    return buffer.getvalue()


def write_figures(
    folder: Path, figures: dict[str, MplFigure]
) -> tuple[list[Path], dict[str, bytes]]:
    """Write each figure as ``folder/figures/KEY.png`` and ``.svg`` (atomically, no dates).

    Returns the paths written and the PNG bytes by key (for an HTML page).
    """
    from ..io.files import atomic_write

    (folder / "figures").mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    images: dict[str, bytes] = {}
    with mpl.rc_context({"svg.hashsalt": "ballscrew"}):
        for key, fig in figures.items():
            images[key] = figure_bytes(fig, "png")
            for kind in ("png", "svg"):
                path = folder / "figures" / f"{key}.{kind}"
                atomic_write(path, images[key] if kind == "png" else figure_bytes(fig, "svg"))
                written.append(path)
    return written, images
