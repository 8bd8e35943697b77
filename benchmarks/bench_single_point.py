"""Cost of one operating point through ``friction_torque``, per model [ms].

Run with ``.venv/bin/python benchmarks/bench_single_point.py``: 200 calls at
one point (reference screw, PAO ISO VG 68, 100 rad/s, 40 °C, 500 N) after a
warm-up call, and the mean time per call.
"""

from __future__ import annotations

import time
import warnings

from ballscrew import friction_torque, lubricants, models, reference_screw


def main() -> None:
    """Run the benchmark."""
    warnings.simplefilter("ignore")
    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    kw = {"speed": 100.0, "temperature": 40.0, "axial_load": 500.0}
    print(f"{'model':<19}{'ms per point':>13}")
    for spec in models():
        friction_torque(screw, oil, model=spec.name, **kw)  # type: ignore[arg-type]
        n = 200
        start = time.perf_counter()
        for _ in range(n):
            friction_torque(screw, oil, model=spec.name, **kw)  # type: ignore[arg-type]
        print(f"{spec.name:<19}{(time.perf_counter() - start) / n * 1e3:>13.3f}")


if __name__ == "__main__":
    main()
