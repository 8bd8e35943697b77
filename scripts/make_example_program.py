"""Write examples/pocket_contour_drill.nc: a realistic part program of over 500 blocks.

A 200 x 140 mm plate on the table of examples/machine_vmc.toml (top face at
Z = -150 mm), machined in three operations, as CAM output looks:

1. a rectangular pocket 120 x 80 mm with 20 mm corner radii, 6 mm deep in three
   steps of 2 mm, cleared by concentric loops 4 mm apart (lines and G3 corner
   arcs);
2. the outer contour of the part: straight sides, two corner arcs and a wavy
   edge written as short G1 segments (a spline as a CAM system linearises it),
   in two depth passes;
3. a grid of 5 x 4 drilled holes 20 mm deep, each a G0 over the hole, a G1 down
   with a dwell at the bottom and a G0 out (no canned cycle: ``ballscrew
   program`` refuses those).

    python scripts/make_example_program.py [--repeat N] [OUT]

``--repeat N`` writes the three operations N times.
"""

from __future__ import annotations

import argparse
import math
import re
from pathlib import Path

TOP = -150.0  # Z of the plate's top face [mm]
SAFE = TOP + 10.0
X0, Y0 = 250.0, 150.0  # the plate's corner on the table [mm]


def _f(v: float) -> str:
    return f"{v:.3f}".rstrip("0").rstrip(".")


def pocket(lines: list[str]) -> None:
    """Concentric rounded rectangles from the outside in, three depths."""
    cx, cy = X0 + 100.0, Y0 + 70.0
    lines.append("(pocket 120 x 80 x 6, R20 corners, 16 mm end mill)")
    lines.append(f"G0 X{_f(cx)} Y{_f(cy)}")
    lines.append(f"G0 Z{_f(TOP + 2)}")
    for depth in (2.0, 4.0, 6.0):
        lines.append(f"G1 Z{_f(TOP - depth)} F300")
        for inset in (8.0, 12.0, 16.0, 20.0, 24.0, 28.0, 32.0, 36.0):
            hw, hh, r = 60.0 - inset, 40.0 - inset, max(20.0 - inset, 2.0)
            if hh <= r:
                break
            lines.append(f"G1 X{_f(cx + hw - r)} Y{_f(cy - hh)} F2400")
            lines.append(f"G3 X{_f(cx + hw)} Y{_f(cy - hh + r)} I0 J{_f(r)}")
            lines.append(f"G1 Y{_f(cy + hh - r)}")
            lines.append(f"G3 X{_f(cx + hw - r)} Y{_f(cy + hh)} I{_f(-r)} J0")
            lines.append(f"G1 X{_f(cx - hw + r)}")
            lines.append(f"G3 X{_f(cx - hw)} Y{_f(cy + hh - r)} I0 J{_f(-r)}")
            lines.append(f"G1 Y{_f(cy - hh + r)}")
            lines.append(f"G3 X{_f(cx - hw + r)} Y{_f(cy - hh)} I{_f(r)} J0")
        lines.append(f"G1 X{_f(cx)} Y{_f(cy)}")
    lines.append(f"G0 Z{_f(SAFE)}")


def contour(lines: list[str]) -> None:
    """The part's outline: a wavy top edge in short segments, two arcs, straight sides."""
    lines.append("(outer contour, wavy edge linearised, two depth passes)")
    lines.append(f"G0 X{_f(X0 - 10)} Y{_f(Y0)}")
    for depth in (5.0, 10.0):
        lines.append(f"G0 Z{_f(TOP + 2)}")
        lines.append(f"G1 Z{_f(TOP - depth)} F300")
        lines.append(f"G1 X{_f(X0)} Y{_f(Y0)} F1800")
        lines.append(f"G1 X{_f(X0 + 185)}")
        lines.append(f"G3 X{_f(X0 + 200)} Y{_f(Y0 + 15)} I0 J15")
        lines.append(f"G1 Y{_f(Y0 + 125)}")
        lines.append(f"G3 X{_f(X0 + 185)} Y{_f(Y0 + 140)} I-15 J0")
        for k in range(1, 181):  # the wavy edge, from right to left
            x = X0 + 185 - 185 * k / 180
            y = Y0 + 140 + 4.0 * math.sin(2 * math.pi * 3 * k / 180)
            lines.append(f"G1 X{_f(x)} Y{_f(y)}")
        lines.append(f"G1 Y{_f(Y0)}")
        lines.append(f"G0 Z{_f(SAFE)}")
        lines.append(f"G0 X{_f(X0 - 10)} Y{_f(Y0)}")


def drill(lines: list[str]) -> None:
    """A grid of holes: G0 over, G1 down, dwell, G0 out."""
    lines.append("(drilling 5 x 4 holes, 8 mm drill, 20 mm deep)")
    lines.append("S3000 M3")
    for j in range(4):
        xs = range(5) if j % 2 == 0 else range(4, -1, -1)
        for i in xs:
            x, y = X0 + 20 + 40 * i, Y0 + 15 + 36.7 * j
            if 35 < x - X0 < 165 and 25 < y - Y0 < 115:
                continue  # inside the pocket
            lines.append(f"G0 X{_f(x)} Y{_f(y)}")
            lines.append(f"G0 Z{_f(TOP + 2)}")
            lines.append(f"G1 Z{_f(TOP - 20)} F250")
            lines.append("G4 P0.3")
            lines.append(f"G0 Z{_f(SAFE)}")


def _scaled_feeds(line: str, scale: float) -> str:
    return re.sub(r"F(\d+)", lambda m: f"F{int(m.group(1)) * scale:.1f}", line)


def program(repeat: int = 1, vary: bool = False) -> str:
    """The program text; ``vary``: each repetition at feeds 0.3 % apart (for the benchmark)."""
    lines = ["%", "O1000 (pocket, contour and drilled holes on a 200 x 140 plate)",
             "G21 G90 G17 G40 G49 G80", "T1", "S8000 M3", "M8",
             f"G0 Z{_f(SAFE)}"]  # fmt: skip
    for k in range(repeat):
        chunk: list[str] = []
        pocket(chunk)
        contour(chunk)
        drill(chunk)
        if vary:
            chunk = [_scaled_feeds(line, 1.0 + 0.003 * (k % 100)) for line in chunk]
        lines += chunk
    lines += ["G0 Z-10", "G0 X0 Y0", "M5 M9", "M30", "%"]
    numbered = []
    n = 0
    for line in lines:
        if line.startswith(("%", "O", "(")):
            numbered.append(line)
        else:
            n += 10
            numbered.append(f"N{n} {line}")
    return "\n".join(numbered) + "\n"


def main() -> None:
    """Write the program."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("out", nargs="?", default="examples/pocket_contour_drill.nc")
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    Path(args.out).write_text(program(args.repeat), encoding="utf-8")


if __name__ == "__main__":
    main()
