"""Write ``tests/data/complete_reference.json``: one-point numbers the scalar path must keep.

Run with ``.venv/bin/python scripts/complete_reference.py`` on the sources whose numbers
are to be kept. It was run once, on commit 6edc5b1 (before the one-point speed work of
issue 51), and the file it wrote is the reference. It stores, at a handful of operating
points (scalars, each one call of :func:`ballscrew.friction_torque`, and the same points as
one array), for the reference screw, a 4-point nut, a small screw with spacer balls and a
grease, every component, the total, the power loss and the efficiency of the complete
model (both ball-train rules, and a flooded nut), and the totals of the other models.
Floats are written by ``repr`` (JSON keeps every bit).

``tests/friction/test_complete_reference.py`` recomputes them and holds them to 1e-12.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew import BallScrew, friction_torque, reference_screw

OUT = Path(__file__).resolve().parents[1] / "tests" / "data" / "complete_reference.json"

POINTS: tuple[tuple[float, float, float], ...] = (
    (100.0, 40.0, 500.0),  # the benchmarks' point
    (1.0, 20.0, 0.0),  # creeping, no load
    (-250.0, 60.0, -3000.0),  # fast, hot, both signs reversed
    (31.4, 35.0, 8000.0),  # a load well past the preload's lift-off
    (0.0, 40.0, 1000.0),  # standstill
    (600.0, 25.0, 150.0),  # high speed, cool
)
"""(speed [rad/s], temperature [degC], axial load [N])."""


def screws() -> dict[str, BallScrew]:
    """The screws of the reference: the reference screw and three others."""
    base = reference_screw()
    return {
        "reference": base,
        "4-point": base.replace(nut="single-4point", preload=800.0),
        "small spacer": base.replace(
            pitch_diameter=0.016,
            ball_diameter=0.002381,
            lead=0.005,
            preload=300.0,
            ball_separation="spacer-balls",
        ),
        "large lead": base.replace(
            pitch_diameter=0.05, ball_diameter=0.00794, lead=0.04, contact_angle=math.radians(42.0)
        ),
    }


CASES: tuple[tuple[str, str, str, dict[str, Any]], ...] = (
    ("reference", "PAO ISO VG 68", "complete", {}),
    ("reference", "mineral ISO VG 32", "complete", {"ball_train": "tolerance"}),
    ("reference", "mineral ISO VG 100", "complete", {"lubrication": "flooded"}),
    ("4-point", "PAO ISO VG 68", "complete", {}),
    ("small spacer", "SKF LGHP 2", "complete", {}),
    ("large lead", "mineral ISO VG 46", "complete", {"hertz_method": "hamrock_brewe"}),
    ("reference", "PAO ISO VG 68", "harris-simplified", {}),
    ("reference", "PAO ISO VG 68", "olaru", {}),
    ("reference", "PAO ISO VG 68", "viscoelastic", {}),
    ("reference", "PAO ISO VG 68", "catalog", {}),
)
"""(screw, lubricant, model, parameters)."""


def _floats(x: Any) -> list[float]:
    return [float(v) for v in np.ravel(x)]


def _figures(r: Any) -> dict[str, list[float]]:
    out = {f"component {k}": _floats(v) for k, v in sorted(r.components.items())}
    out |= {"total": _floats(r.total), "power_loss": _floats(r.power_loss),
            "efficiency": _floats(r.efficiency)}  # fmt: skip
    return out


def compute() -> dict[str, Any]:
    """The stored figures, computed by the sources on the path."""
    warnings.simplefilter("ignore")
    table = screws()
    out: dict[str, Any] = {}
    for screw_name, oil, model, params in CASES:
        key = f"{model} | {screw_name} | {oil} | {json.dumps(params, sort_keys=True)}"
        try_points = [p for p in POINTS if not (model == "harris-full" and p[0] == 0.0)]
        one: dict[str, list[float]] = {}
        for w, t, fa in try_points:
            r = friction_torque(table[screw_name], oil, speed=w, temperature=t, axial_load=fa,
                                model=model, **params)  # fmt: skip
            for name, values in _figures(r).items():
                one.setdefault(name, []).extend(values)
        w, t, fa = (np.array(c) for c in zip(*try_points, strict=True))
        r = friction_torque(table[screw_name], oil, speed=w, temperature=t, axial_load=fa,
                            model=model, **params)  # fmt: skip
        out[key] = {"points": [list(p) for p in try_points], "scalar": one,
                    "array": _figures(r)}  # fmt: skip
    return out


if __name__ == "__main__":
    OUT.write_text(json.dumps(compute(), indent=1) + "\n", encoding="utf-8")
    print(f"wrote {OUT}")
