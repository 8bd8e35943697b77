"""Write ``tests/data/speed_reference.json``: numbers the speed work of issue 51 must keep.

Run with ``.venv/bin/python scripts/speed_reference.py`` on the sources whose numbers are
to be kept (it was run once before the changes of issue 51). It stores, for seeded operating
points (numpy's ``default_rng``, whose stream is stable across versions):

- harris-simplified on 40 000 scattered points (more than one block of its shear-stress
  kernel) and on a 20 x 5 x 30 grid: each component's exact sum and every 397th value;
- the complete model on 40 new screws (the many-screws path) x 50 speeds: the same.

``tests/friction/test_speed_reference.py`` recomputes them and holds them to 1e-12.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew import BallScrew, friction_torque, friction_torques, lubricants, reference_screw

OUT = Path(__file__).resolve().parents[1] / "tests" / "data" / "speed_reference.json"
STEP = 397


def scattered_points(n: int = 40_000, seed: int = 51) -> dict[str, Any]:
    """``n`` unrelated points: speed 1-314 rad/s, 20-45 degC, -4 to 4 kN."""
    rng = np.random.default_rng(seed)
    return {"speed": rng.uniform(1.0, 314.0, n), "temperature": rng.uniform(20.0, 45.0, n),
            "axial_load": rng.uniform(-4000.0, 4000.0, n)}  # fmt: skip


def grid_points() -> dict[str, Any]:
    """A 20 x 5 x 30 outer product of speed, temperature and axial load."""
    return {"speed": np.linspace(1.0, 314.0, 20)[:, None, None],
            "temperature": np.linspace(20.0, 45.0, 5)[None, :, None],
            "axial_load": np.linspace(-4000.0, 4000.0, 30)[None, None, :]}  # fmt: skip


def new_screws(count: int = 40, seed: int = 51) -> list[BallScrew]:
    """Screws of every size, as ``benchmarks/bench_many_screws.py`` draws them."""
    rng = np.random.default_rng(seed)
    base = reference_screw()
    screws = []
    for i in range(count):
        d = rng.uniform(0.016, 0.063)
        ball = rng.uniform(0.09, 0.16) * d
        screws.append(
            base.replace(
                pitch_diameter=d, ball_diameter=ball, lead=rng.uniform(1.1 * ball, 0.04),
                preload=rng.uniform(200.0, 5000.0),
                nut="single-4point" if i % 3 == 2 else "double",
                conformity_screw=rng.uniform(0.52, 0.57), conformity_nut=rng.uniform(0.52, 0.57),
                contact_angle=math.radians(rng.uniform(40.0, 50.0)),
            )
        )  # fmt: skip
    return screws


def summary(components: dict[str, Any]) -> dict[str, Any]:
    """Each component's exact sum and every ``STEP``-th value (C order)."""
    return {
        name: {"sum": math.fsum(np.ravel(v).tolist()), "sample": np.ravel(v)[::STEP].tolist()}
        for name, v in sorted(components.items())
    }


def compute() -> dict[str, Any]:
    """The stored figures, computed by the sources on the path."""
    warnings.simplefilter("ignore")
    oil = lubricants.get("PAO ISO VG 68")
    screw = reference_screw()
    out: dict[str, Any] = {}
    for name, points in (("scattered", scattered_points()), ("grid", grid_points())):
        r = friction_torque(screw, oil, model="harris-simplified", **points)
        out[f"harris-simplified {name}"] = summary({**r.components, "total": r.total})
    speeds = np.linspace(1.0, 314.0, 50)
    rs = friction_torques(new_screws(), oil, speed=speeds, temperature=40.0, axial_load=1500.0,
                          warn=False)  # fmt: skip
    out["complete many screws"] = summary({**rs.components, "total": rs.total})
    return out


if __name__ == "__main__":
    OUT.write_text(json.dumps(compute(), indent=0) + "\n", encoding="utf-8")
    print(f"wrote {OUT}")
