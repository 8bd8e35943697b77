"""Fit the catalogue level of the nut stiffness once, and show it against the test nuts.

Run with ``.venv/bin/python scripts/fit_nut_rigidity.py``. For every nut of
``src/ballscrew/data/catalog_rigidity.csv`` (rigidity printed by THK and HIWIN
for preloaded double nuts, at a preload of 10 % of the dynamic load rating) it
prints the ideal contact stiffness (:func:`ballscrew.design.stiffness.nut_axial_stiffness`
with the package's default conformity 0.55 and contact angle 45°), the printed
value and their ratio; the median ratio over the training rows (THK) is the
constant :data:`ballscrew.design.stiffness.CATALOGUE_RIGIDITY_RATIO`, and the test rows
(HIWIN) show how well it carries to another maker.
"""

from __future__ import annotations

import csv
import statistics
from importlib import resources

from ballscrew import reference_screw
from ballscrew.design.stiffness import CATALOGUE_RIGIDITY_RATIO, nut_axial_stiffness
from ballscrew.geometry import BallScrew


def rows() -> list[dict[str, str]]:
    """The printed rigidities, one dict per nut."""
    text = resources.files("ballscrew").joinpath("data/catalog_rigidity.csv").read_text("utf-8")
    return list(csv.DictReader(text.splitlines()))


def screw_of(row: dict[str, str]) -> BallScrew:
    """The nut of a row as a BallScrew, preloaded to 10 % of its dynamic load rating."""
    base = reference_screw()
    return BallScrew(
        pitch_diameter=float(row["pitch_diameter_mm"]) * 1e-3,
        lead=float(row["lead_mm"]) * 1e-3,
        ball_diameter=float(row["ball_diameter_mm"]) * 1e-3,
        contact_angle=base.contact_angle,
        conformity_screw=base.conformity_screw,
        conformity_nut=base.conformity_nut,
        loaded_turns=float(row["loaded_turns"]),
        circuits=int(row["circuits"]),
        nut="double",
        preload=0.1 * float(row["dynamic_load_rating_kN"]) * 1e3,
    )


def ratios() -> dict[str, list[float]]:
    """Model over printed rigidity, by role (training, test)."""
    out: dict[str, list[float]] = {"training": [], "test": []}
    for row in rows():
        model = nut_axial_stiffness(screw_of(row)) / 1e6
        out[row["role"]].append(model / float(row["rigidity_N_per_um"]))
    return out


def main() -> None:
    """Print every nut's ratio and the medians by role."""
    print(f"{'maker':<7}{'nut':<15}{'role':<10}{'model':>8}{'printed':>9}{'ratio':>7}  N/um")
    for row in rows():
        model = nut_axial_stiffness(screw_of(row)) / 1e6
        printed = float(row["rigidity_N_per_um"])
        print(f"{row['maker']:<7}{row['designation']:<15}{row['role']:<10}{model:8.0f}"
              f"{printed:9.0f}{model / printed:7.2f}")  # fmt: skip
    r = ratios()
    for role, values in r.items():
        print(f"{role}: median {statistics.median(values):.3f}, "
              f"{min(values):.2f} to {max(values):.2f} ({len(values)} nuts)")  # fmt: skip
    print(f"constant in the package: {CATALOGUE_RIGIDITY_RATIO}")


if __name__ == "__main__":
    main()
