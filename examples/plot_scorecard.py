"""
The scorecard: predicted against the makers' drag torque
========================================================

``ballscrew validate`` runs every model on 120 catalogue cases (HIWIN ground nuts,
14 to 63 mm, leads 5 to 40 mm, double and 4-point nuts at 2, 5 and 10 % of their
load rating, 100 rpm). Here the complete model and the catalogue rule, each point a
case, against the reference drag torque, with the makers' tolerance band (THK A-688
Table 13, grade C3) around the diagonal.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew.study.validation import ACCEPTANCE_BANDS, score

rows = [r for r in score(["complete", "catalog"], trends=False) if r.kind == "catalog"]

fig, ax = plt.subplots(figsize=(6.0, 5.0), layout="constrained")
edges = np.geomspace(0.05, 10.0, 200)
tol = np.array([next((t for upper, t in ACCEPTANCE_BANDS if x <= upper), 0.2) for x in edges])
ax.fill_between(edges, edges * (1 - tol), edges * (1 + tol), color="0.85", label="makers' band")
ax.plot(edges, edges, "k-", lw=0.8)
series = [("complete", "double", dict(marker="o", color="C0")),
          ("complete", "single-4point", dict(marker="o", facecolors="none", edgecolors="C3")),
          ("catalog", None, dict(marker="x", color="k"))]  # fmt: skip
for model, nut, style in series:
    pts = [(r.reference, r.predicted) for r in rows if r.model == model and nut in (None, r.nut)]
    ref, pred = np.array(pts).T
    ax.scatter(ref, pred, s=22, label=f"{model}, {nut or 'every nut'}", **style)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("reference drag torque (catalogue rule) [N·m]")
ax.set_ylabel("predicted [N·m]")
ax.legend(fontsize="small", loc="upper left")
plt.show()
