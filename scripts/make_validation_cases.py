"""Write src/ballscrew/data/validation_cases.csv from the bundled catalogue table.

    .venv/bin/python scripts/make_validation_cases.py

Every case row carries its source. The geometries are the distinct screws of
data/catalog_screws.csv whose catalogue row gives the ball diameter, the circuits and the
load rating (HIWIN's ground nuts; the nominal diameter stands for the pitch diameter and one
loaded turn per circuit is assumed, as the designation lookup does). Each screw as a double
nut and as a 4-point single nut, at preloads of 2, 5 and 10 % of its dynamic load rating, at
the catalogues' drag torque test conditions (100 rpm, ISO VG 68 mineral oil, no wiper; the
temperature is not stated: 20 °C assumed); Jungnickel's law at 1000 and 3000 rpm and 40 °C for
the double nuts at 5 %.

Training rows (the only ones the ball-train constant is fitted on): double nuts at 5 %
preload of every other screw (rows 0, 2, 4, ...).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from ballscrew.design.catalog_formulas import preload_torque
from ballscrew.io.files import atomic_write
from ballscrew.lubricants import get
from ballscrew.study.validation import (
    FOUR_POINT_RATIO,
    FOUR_POINT_SOURCE,
    acceptance_band,
    jungnickel_loss_torque,
    screw_from_row,
)

ROOT = Path(__file__).resolve().parents[1] / "src" / "ballscrew" / "data"
PRELOADS = (0.02, 0.05, 0.10)
CONFORMITY = 0.55  # typical gothic-arch and circular-arc grooves: 0.52-0.56 (not in catalogues)
CATALOG_SOURCE = (
    "THK's preload torque formula Tp = 0.05/sqrt(tan b) Fpr l/2pi (THK General Catalog, A-688) "
    "under HIWIN's test conditions for drag torque: 100 rpm, ISO VG 68, no wiper (HIWIN GmbH "
    "catalogue, 3.6.3); band: the makers' tolerance of the preload torque at its level, grade "
    "C3 (THK A-688 Table 13: +-45 % at 0.2-0.4 N*m, 35 % to 0.6, 30 % to 1.0, 25 % to 2.5, "
    "20 % to 6.3; below 0.2 N*m the first row's 45 %)"
)
JUNGNICKEL_SOURCE = (
    "Jungnickel (2010) empirical ball screw loss law as implemented in Thermca "
    "(ball_screw.py); band: factor 2 either way (its double-nut convention is not documented)"
)
COLUMNS = [
    "case", "kind", "training", "nominal_diameter_mm", "lead_mm", "ball_diameter_mm",
    "pitch_diameter_mm", "contact_angle_deg", "conformity", "circuits", "turns_per_circuit",
    "nut", "preload_N", "lubricant", "speed_rpm", "temperature_C", "axial_load_N",
    "reference_Nm", "reference_low_Nm", "reference_high_Nm", "source",
]  # fmt: skip


def _table() -> list[dict[str, str]]:
    """One row per distinct geometry with ball diameter, turns and rating, in file order."""
    from ballscrew.io.designation import catalog_screws

    seen: set[tuple[float, ...]] = set()
    table = []
    for s in catalog_screws():
        if None in (s.ball_diameter, s.loaded_turns, s.dynamic_load_rating):
            continue
        key = (s.nominal_diameter, s.lead, s.ball_diameter, s.circuits)  # type: ignore[assignment]
        if key in seen:
            continue
        seen.add(key)  # type: ignore[arg-type]
        table.append(
            {
                "designation": s.name,
                "nominal_diameter_mm": f"{s.nominal_diameter * 1e3:g}",
                "lead_mm": f"{s.lead * 1e3:g}",
                "ball_diameter_mm": f"{s.ball_diameter * 1e3:g}",  # type: ignore[operator]
                "pitch_diameter_mm": f"{(s.pitch_diameter or s.nominal_diameter) * 1e3:g}",
                "circuits": str(s.circuits),
                "turns_per_circuit": f"{s.loaded_turns:g}",
                "dynamic_load_rating_kN": f"{s.dynamic_load_rating / 1e3:g}",  # type: ignore[operator]
                "contact_angle_deg": "45",
                "source": f"{s.source}, {s.page}; {s.turns_status}; pitch diameter = nominal",
            }
        )
    return table


def main() -> None:
    """Run the script."""
    table = _table()
    rows: list[dict[str, object]] = []
    for index, g in enumerate(table):
        dm = float(g["pitch_diameter_mm"])
        lead = float(g["lead_mm"])
        beta = math.atan(lead / (math.pi * dm))
        base = {
            "nominal_diameter_mm": g["nominal_diameter_mm"],
            "lead_mm": g["lead_mm"],
            "ball_diameter_mm": g["ball_diameter_mm"],
            "pitch_diameter_mm": g["pitch_diameter_mm"],
            "contact_angle_deg": g["contact_angle_deg"],
            "conformity": CONFORMITY,
            "circuits": g["circuits"],
            "turns_per_circuit": g["turns_per_circuit"],
            "lubricant": "mineral ISO VG 68",
            "axial_load_N": 0.0,
        }
        for nut in ("double", "single-4point"):
            for share in PRELOADS:
                fpr = round(share * float(g["dynamic_load_rating_kN"]) * 1e3, 1)
                tp = float(preload_torque(fpr, lead * 1e-3, beta))
                source = CATALOG_SOURCE
                if nut == "single-4point":  # the rule times the measured 4-point ratio
                    tp *= FOUR_POINT_RATIO
                    source = f"{CATALOG_SOURCE}; {FOUR_POINT_SOURCE}"
                band = acceptance_band(tp)
                rows.append(
                    base
                    | {
                        "case": f"{g['designation']} {nut} {share:.0%} Ca, 100 rpm",
                        "kind": "catalog",
                        "training": "yes" if nut == "double" and share == 0.05 and index % 2 == 0
                        else "no",
                        "nut": nut,
                        "preload_N": fpr,
                        "speed_rpm": 100.0,
                        "temperature_C": 20.0,
                        "reference_Nm": round(tp, 5),
                        "reference_low_Nm": round((1.0 - band) * tp, 5),
                        "reference_high_Nm": round((1.0 + band) * tp, 5),
                        "source": f"{source}; geometry: {g['source']}",
                    }
                )  # fmt: skip
        fpr = round(0.05 * float(g["dynamic_load_rating_kN"]) * 1e3, 1)
        for rpm in (1000.0, 3000.0):
            screw = screw_from_row({**base, "nut": "double", "preload_N": fpr})  # type: ignore[dict-item]
            oil = get("mineral ISO VG 68")
            tj = float(jungnickel_loss_torque(screw, oil, rpm * 2 * math.pi / 60, 40.0))
            rows.append(
                base
                | {
                    "case": f"{g['designation']} double 5% Ca, {rpm:.0f} rpm (Jungnickel)",
                    "kind": "jungnickel",
                    "training": "no",
                    "nut": "double",
                    "preload_N": fpr,
                    "speed_rpm": rpm,
                    "temperature_C": 40.0,
                    "reference_Nm": round(tj, 5),
                    "reference_low_Nm": round(tj / 2.0, 5),
                    "reference_high_Nm": round(tj * 2.0, 5),
                    "source": f"{JUNGNICKEL_SOURCE}; geometry: {g['source']}",
                }
            )
    out = io.StringIO()
    out.write("# Validation cases of ballscrew; written by scripts/make_validation_cases.py.\n")
    out.write(
        "# Every row names its source; reference values in N*m, bands in reference_low/high.\n"
    )
    writer = csv.DictWriter(out, COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    atomic_write(ROOT / "validation_cases.csv", out.getvalue().encode())
    print(f"{len(rows)} cases written to {ROOT / 'validation_cases.csv'}")


if __name__ == "__main__":
    main()
