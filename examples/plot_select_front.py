"""
Choosing the screw: the Pareto front of energy against stiffness
================================================================

``ballscrew select`` on the example vertical axis (``examples/vertical_32x5.toml``: a
120 kg Z slide, fixed-supported over 900 mm, P5) over a 500 mm move at 12 m/min with
1.5 kN of process force: HIWIN's 32 and 40 mm nuts of 10 and 20 mm lead at the light
and medium preload classes (3 and 5 % of C_a), the double nuts also at the heavy one (8 %:
HIWIN keeps single nuts within 5 %). Every candidate runs the
whole axis check; the rejected ones are crossed, the front over friction energy per
cycle and least axis stiffness is ringed, the recommendation starred. The same as
``ballscrew select --case examples/vertical_32x5.toml --move ... --diameter "32..40 mm"
--lead "10..20 mm" --maker HIWIN --preload light --preload medium --preload heavy
--objective energy --objective stiffness``.
"""

from pathlib import Path

import matplotlib.pyplot as plt

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.io.case import load_case
from ballscrew.select import run_select

here = Path(".") if Path("vertical_32x5.toml").exists() else Path("examples")
move = parse_move("stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, "
                  "force_from=100 mm, force_to=400 mm, dwell=3 s")  # fmt: skip
result = run_select(
    load_case(here / "vertical_32x5.toml"), profile_from_move(move, 1),
    objectives=["energy", "stiffness"], diameter=(0.032, 0.040), lead=(0.010, 0.020),
    makers=["HIWIN"], preloads=["light", "medium", "heavy"], move=move,
)  # fmt: skip

fig, ax = plt.subplots(figsize=(6.4, 4.4), layout="constrained")
markers = {"light": "o", "medium": "s", "heavy": "D"}
for cls, marker in markers.items():
    for feasible, colour in ((True, "#3a7d44"), (False, "#b00020")):
        pts = [e for e in result.evaluated
               if e.candidate.preload_class == cls and e.feasible == feasible
               and e.figures["energy_J"] == e.figures["energy_J"]]  # fmt: skip
        if not pts:
            continue
        ax.scatter([e.figures["energy_J"] for e in pts],
                   [e.figures["stiffness_N_per_um"] for e in pts], marker=marker,
                   facecolors=colour if feasible else "none", edgecolors=colour, alpha=0.8,
                   label=f"{cls} ({'feasible' if feasible else 'rejected'})")  # fmt: skip
front = sorted(result.front, key=lambda i: result.evaluated[i].figures["energy_J"])
ax.plot([result.evaluated[i].figures["energy_J"] for i in front],
        [result.evaluated[i].figures["stiffness_N_per_um"] for i in front], "k--", lw=1,
        label="Pareto front")  # fmt: skip
best = result.evaluated[result.recommended]
ax.scatter([best.figures["energy_J"]], [best.figures["stiffness_N_per_um"]], marker="*",
           s=260, color="#c58b00", edgecolors="black", zorder=5, label="recommended")  # fmt: skip
ax.set_xlabel("friction energy per cycle [J]")
ax.set_ylabel("least axis stiffness [N/µm]")
ax.legend(fontsize="small", ncol=2)
ax.set_title("Choose the screw: energy against stiffness", fontsize="medium")
print(
    f"{len(result.evaluated)} candidates, {len(result.feasible)} feasible, "
    f"{len(result.front)} on the front"
)
print("recommended:", best.name)
print("why:", result.reason)
plt.show()
