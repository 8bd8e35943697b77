"""Write src/ballscrew/data/validation_cases.csv from the catalogue geometry table.

    .venv/bin/python scripts/make_validation_cases.py

Every case row carries its source. The grid: each screw of data/reference_screws.csv, as a
double nut and as a 4-point single nut, at preloads of 2, 5 and 10 % of its dynamic load
rating, at the catalogues' drag torque test conditions (100 rpm, ISO VG 68 mineral oil, no
wiper; the temperature is not stated: 20 °C assumed); Jungnickel's law at 1000 and 3000 rpm
and 40 °C for the double nuts at 5 %; and THK's worked example.

Training rows (the only ones the ball-train constant is fitted on): double nuts at 5 %
preload of every other screw of the table (rows 0, 2, 4, ...).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from ballscrew.files import atomic_write
from ballscrew.friction.catalog import preload_torque
from ballscrew.lubricants import get
from ballscrew.validation import jungnickel_loss_torque, screw_from_row

ROOT = Path(__file__).resolve().parents[1] / "src" / "ballscrew" / "data"
PRELOADS = (0.02, 0.05, 0.10)
CONFORMITY = 0.55  # typical gothic-arch and circular-arc grooves: 0.52-0.56 (not in catalogues)
CATALOG_SOURCE = (
    "catalogue formula Tp = 0.05/sqrt(tan b) Fpr l/2pi (THK; NSK; HIWIN catalogues) at 100 rpm "
    "ISO VG 68 without wiper; band +-30 % (drag torque variation allowed by the precision "
    "grades; JIS B1192-3 / ISO 3408-3)"
)
JUNGNICKEL_SOURCE = (
    "Jungnickel (2010) empirical ball screw loss law as implemented in Thermca "
    "(ball_screw.py); band: factor 1.5 either way"
)
COLUMNS = [
    "case", "kind", "training", "nominal_diameter_mm", "lead_mm", "ball_diameter_mm",
    "pitch_diameter_mm", "contact_angle_deg", "conformity", "circuits", "turns_per_circuit",
    "nut", "preload_N", "lubricant", "speed_rpm", "temperature_C", "axial_load_N",
    "reference_Nm", "reference_low_Nm", "reference_high_Nm", "source",
]  # fmt: skip


def main() -> None:
    """Run the script."""
    table = [
        row
        for row in csv.DictReader(
            line for line in (ROOT / "reference_screws.csv").read_text().splitlines()
            if line and not line.startswith("#")
        )
    ]  # fmt: skip
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
                        "reference_low_Nm": round(0.7 * tp, 5),
                        "reference_high_Nm": round(1.3 * tp, 5),
                        "source": f"{CATALOG_SOURCE}; geometry: {g['source']}",
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
                    "reference_low_Nm": round(tj / 1.5, 5),
                    "reference_high_Nm": round(tj * 1.5, 5),
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
