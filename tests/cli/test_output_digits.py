"""No CSV or terminal number shows more than its stated significant digits (issue 40).

The rule (docs/guide.md, "Numbers in outputs"; :mod:`ballscrew.io.numbers`): 4 on the
terminal; in CSV files by the column's unit (times and positions 7, speeds 6, the rest
4); the friction map's lookup table 6. Each command that prints or writes CSV is run
on the shipped examples, and every number of its standard output and of every CSV it
wrote is counted.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import pytest

from ballscrew.io.numbers import TERMINAL_DIGITS, column_digits, significant_digits
from ballscrew.report.friction_files import MAP_DIGITS
from cli_runner import run

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
VERTICAL = str(EXAMPLES / "vertical_32x5.toml")
XY = str(EXAMPLES / "xy_table_32x10.toml")
MOVE = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"

# A number standing alone: not part of a word, a version (0.2.0), a designation
# (R40-10K5), a path, a ratio written a/b or a standard's number (ISO 14253-1).
NUMBER = re.compile(r"(?<![\w.,/:-])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w./-])")
STANDARD = re.compile(r"\b(?:ISO|JIS [A-Z]|DIN|PUB MP/P8) \d+")

COMMANDS = {
    "torque": ["torque", "--speed", "0..3000:7 rpm", "--table", "full", "--csv", "{out}/t.csv"],
    "torque-pivot": ["torque", "--csv", "{out}/t.csv", "--csv-layout", "wide"],
    "energy": ["energy", "--case", XY, "--move", MOVE, "--steady-speeds", "500..3000:3 rpm",
               "--out", "{out}/report"],
    "check": ["check", "--case", VERTICAL, "--move", MOVE, "--out", "{out}/report"],
    "export-friction": ["export-friction", "--case", VERTICAL, "--out", "{out}/stribeck.csv"],
    "export-table": ["export-friction", "--case", VERTICAL, "--form", "table", "--out",
                     "{out}/table.csv"],
    "export-load-map": ["export-friction", "--case", VERTICAL, "--form", "load-map",
                        "--axial-load", "-2..2:3 kN", "--out", "{out}/map.csv"],
    "export-lincurve": ["export-friction", "--case", VERTICAL, "--form", "lincurve", "--speed",
                        "5 m/min", "--out", "{out}/f.hal"],
    "monitor": ["monitor", "--case", VERTICAL, "--measured",
                str(EXAMPLES / "drag_torque_series.csv")],
    "acceptance": ["acceptance", "--case", VERTICAL, "--tolerance", "40 %", "--torque",
                   "0.080, 0.092, 0.086 N*m"],
    "demo": ["demo"],
    "case": ["case", "--check", VERTICAL],
    "lubricants": ["lubricants"],
    "screws": ["screws"],
    "models": ["models"],
    "program": ["program", str(EXAMPLES / "pocket_contour_drill.nc"), "--machine",
                str(EXAMPLES / "machine_vmc.toml"), "--out", "{out}/report"],
    "contour": ["contour", "--case", XY, "--radius", "50 mm", "--feed", "2 m/min",
                "--out", "{out}/report"],
    "select": ["select", "--case", VERTICAL, "--move", "stroke=500 mm, feed=12 m/min, "
               "acceleration=3 m/s^2, force=1.5 kN, force_from=100 mm, force_to=400 mm, dwell=3 s",
               "--diameter", "32..40 mm", "--lead", "20 mm", "--objective", "energy",
               "--objective", "life", "--out", "{out}/report"],
    "fit": ["fit", "--case", "{out}/s.toml", "--measured", "{out}/run.csv", "--free", "preload",
            "--out", "{out}/report"],
    "sweep": ["sweep", str(EXAMPLES / "sweep_preload.toml"), "--out", "{out}/p.zarr"],
    "validate": ["validate", "--model", "catalog", "--model", "complete", "--out",
                 "{out}/report"],
    "study": ["study", "--out", "{out}/report"],
}  # fmt: skip
EXTRA = {"program": "ruckig", "contour": "control", "select": "pymoo", "sweep": "xarray"}
SLOW = {"select", "sweep", "study"}


def _measured_run(folder: Path) -> None:
    """A case and a drag torque curve for ``fit``: the model's own, 10 % up, to full precision."""
    from ballscrew import friction_torque
    from ballscrew.io.case import load_case

    case = folder / "s.toml"
    case.write_text('[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\n'
                    'ball_diameter = "6.35 mm"\npreload = "2 kN"\n'
                    '[lubricant]\nname = "PAO ISO VG 68"\n', encoding="utf-8")  # fmt: skip
    loaded = load_case(case)
    speeds = [10.0, 30.0, 100.0, 200.0, 300.0]  # rad/s
    truth = friction_torque(loaded.screw, loaded.lubricant, speed=speeds, temperature=30.0)
    body = "".join(f"{w!r},30.0,{float(t) * 1.1!r}\n" for w, t in zip(speeds, truth.total,
                                                                    strict=True))  # fmt: skip
    (folder / "run.csv").write_text("speed [rad/s],temperature [degC],torque [N*m]\n" + body)


def _too_long_on_terminal(out: str) -> list[tuple[str, str]]:
    found = []
    for line in STANDARD.sub("", out).splitlines():
        for m in NUMBER.finditer(line):
            if significant_digits(m.group()) > TERMINAL_DIGITS:
                found.append((m.group(), line.strip()))
    return found


def _too_long_in_csv(path: Path) -> list[tuple[str, str]]:
    lines = [x for x in path.read_text("utf-8").splitlines() if not x.startswith("#")]
    rows = list(csv.reader(lines))
    found = []
    for row in rows[1:]:
        for header, cell in zip(rows[0], row, strict=False):
            try:
                float(cell)
            except ValueError:
                continue
            allowed = MAP_DIGITS if path.name == "map.csv" else column_digits(header)
            if significant_digits(cell) > allowed:
                found.append((header, cell))
    return found


@pytest.mark.parametrize(
    "name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n for n in COMMANDS]
)
def test_every_printed_and_csv_number_keeps_to_its_digits(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    if name in EXTRA:
        pytest.importorskip(EXTRA[name])
    monkeypatch.setenv("COLUMNS", "400")  # a row on one line: a number is never split
    if name == "fit":
        _measured_run(tmp_path)
    args = COMMANDS[name]
    code, out, err = run([a.format(out=tmp_path) for a in args], capsys)
    assert code == 0, err
    assert _too_long_on_terminal(out + err) == []  # standard output and error (notes)
    written = sorted(p for p in tmp_path.rglob("*.csv") if p.name != "run.csv")  # not the input
    # A report folder or a .csv file holds CSV.
    expected = any(
        a.startswith("{out}") and a.endswith(("/report", ".csv")) for a in COMMANDS[name]
    )
    assert bool(written) == expected
    for path in written:
        assert _too_long_in_csv(path) == [], path


def test_the_count_catches_the_numbers_issue_40_quotes() -> None:
    # The checks above would fail on the outputs the issue found.
    out = "│ complete │ -3000.0000000000005 │ 0.30259790342381945 │"
    assert [n for n, _ in _too_long_on_terminal(out)] == ["-3000.0000000000005",
                                                          "0.30259790342381945"]  # fmt: skip
    assert _too_long_on_terminal("ballscrew 0.2.0, R40-10K5-FDC, ISO 14253-1, 0.9478 / 0.945") == []
