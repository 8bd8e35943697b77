"""Draw docs/img/friction_signs.png: the sign conventions of the friction export.

    .venv/bin/python scripts/friction_sign_figure.py

The study case's complete-model friction over signed screw speed at three axial loads
(the load resisting the motion, none, the load pushing along it), and the motor torque
F l/2pi + T_f that each needs: friction always opposes the speed; the load adds its own
torque, which the motor supplies when driving and the load supplies when back-driving.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ballscrew.io.case import load_case
from ballscrew.kinematics import rad_s_to_rpm
from ballscrew.report.plotting import figure_bytes
from ballscrew.servo.friction_map import friction_map


def draw() -> Figure:
    """The figure (scripts/docs_figures.py writes it with the version at each docs build)."""
    case = load_case(None)
    load = 2000.0
    m = friction_map(case, "complete", speeds=np.geomspace(1.0, 300.0, 40),
                     loads=[-load, 0.0, load], temperatures=[40.0])  # fmt: skip
    rpm = rad_s_to_rpm(m.speeds)
    fig = Figure(figsize=(8.0, 3.6), layout="constrained")
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    styles = {0: ("C0", "-"), 1: ("k", "--"), 2: ("C3", ":")}
    names = {0: f"F = -{load:g} N", 1: "F = 0", 2: f"F = +{load:g} N"}
    for j in range(3):
        color, style = styles[j]
        left.plot(rpm, m.torque[0, j], color=color, linestyle=style, label=names[j])
        motor = m.loads[j] * m.lead / (2 * math.pi) * -1.0 + m.torque[0, j]
        right.plot(rpm, motor, color=color, linestyle=style, label=names[j])
    left.set_title("friction torque T_f: signed like the speed", fontsize=9)
    left.set_xlabel("screw speed [rpm] (> 0: nut towards +x)")
    left.set_ylabel("T_f [N*m]")
    right.set_title("motor torque -F l/2pi + T_f\n(F: the load's force on the nut along x)",
                    fontsize=9)  # fmt: skip
    right.set_xlabel("screw speed [rpm]")
    right.set_ylabel("motor torque [N*m]")
    right.annotate("w > 0, F w < 0:\nthe motor drives\nthe load", (300, 3.4),
                   fontsize=7, color="C0")  # fmt: skip
    right.annotate("w < 0, F w > 0:\nthe load back-drives,\nthe motor brakes",
                   (-2900, 3.4), fontsize=7, color="C0")  # fmt: skip
    for ax in (left, right):
        ax.axhline(0.0, color="0.6", linewidth=0.6)
        ax.axvline(0.0, color="0.6", linewidth=0.6)
        ax.grid(alpha=0.3)
    left.legend(fontsize=7, loc="lower right")
    right.legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 0.15))
    return fig


def main() -> None:
    """Draw and write the figure."""
    out = Path(__file__).resolve().parents[1] / "docs" / "img" / "friction_signs.png"
    out.write_bytes(figure_bytes(draw(), "png"))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
