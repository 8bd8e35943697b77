"""Fuzzing of the input loaders: mutated case files and measured-data CSVs.

The only outcomes allowed are a correct result or the package's input error
(:class:`ballscrew.BallScrewInputError`; exit status 2 and one line from the
CLI). Anything else is a finding.

Run a larger campaign with::

    .venv/bin/python tests/fuzz_inputs.py --n 5000 --seed 1

The test suite runs a bounded number (tests/cli/test_fuzz.py).
"""

from __future__ import annotations

import argparse
import random
import re
import traceback
import warnings
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.errors import BallScrewReadingWarning
from ballscrew.io.case import parse_case
from ballscrew.io.measured import parse_measured

BASE_CASE = (Path(__file__).resolve().parent / "data" / "small_case.toml").read_text()
BASE_CSV = "speed [rpm],torque [N*m]\n10,0.21\n100,0.25\n1000,0.31\n3000,0.42\n"

ODD_VALUES = [
    '""',
    '"nan mm"',
    '"inf kN"',
    '"-1 mm"',
    '"1e308 m"',
    '"1e-320 m"',
    '"abc"',
    '"32 kg"',
    '"32"',
    "32",
    "-5",
    "0",
    "1e999",
    '"45 rad"',
    '"200 deg"',
    '"0.5"',
    "0.5",
    "true",
    "[]",
    "{}",
    '"1 N*m"',
    '"10..1 rpm"',
    '"1..2:0 rpm"',
    '"1..2:99999999 rpm"',
    '"-300 degC"',
    '"5 parsec"',
    '"1/0 m"',
    '"3 mm mm"',
    '"   "',
    '"1,2,3"',
    '"1..2..3 rpm"',
    '"0 N"',
    '"1e6 rpm"',
    '"single"',
    '"triple"',
    '{ value = "1 mm" }',
    '{ assumed = "x" }',
    # shop-floor notation (issue 40): fractions, inch marks, g, C and F
    '"1/4 in"',
    "'3/8\"'",
    "'1.329\"'",
    '"1 1/4 in"',
    '"1-1/4 in"',
    '"1/0 in"',
    '"2\'"',
    '"0.3 g"',
    '"40 C"',
    '"104 F"',
    '"5 lbf"',
    '"10 lbf*in"',
    '"5 KN"',
]
ODD_CELLS = [
    "",
    "nan",
    "inf",
    "-inf",
    "abc",
    "1e400",
    "1,5",
    "0x10",
    "--1",
    " ",
    "1e-400",
    "-0",
    "3000000000",
    "\u00e9",
    "1 2",
]
ODD_HEADERS = [
    "speed [rpm],torque [N*m]",
    "speed,torque",
    "speed [kg],torque [N*m]",
    "speed [mm/s],torque [mN*m]",
    "speed [rpm]",
    "torque [N*m],speed [rad/s]",
    "speed [Hz],torque [N*m]",
    "speed [rpm],torque [N]",
    "[rpm],[N*m]",
    "speed [rpm],torque [N*m],extra [K]",
    "speed [rpm;torque [N*m]",
    "",
]


def mutate_case(rng: random.Random, base: str = BASE_CASE) -> str:
    """One randomly mutated case text (or another TOML text, ``base``: a machine file)."""
    text = base
    for _ in range(rng.randint(1, 3)):
        kind = rng.randrange(6)
        lines = text.splitlines()
        if kind == 0:  # replace a value
            idx = [i for i, line in enumerate(lines) if re.match(r"^\s*[\w\"-][^=]*=", line)]
            if idx:
                i = rng.choice(idx)
                key = lines[i].split("=", 1)[0]
                lines[i] = f"{key}= {rng.choice(ODD_VALUES)}"
        elif kind == 1 and lines:  # delete a line
            del lines[rng.randrange(len(lines))]
        elif kind == 2 and lines:  # duplicate a line
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
        elif kind == 3:  # insert a junk line
            lines.insert(
                rng.randrange(len(lines) + 1),
                rng.choice(["x = 1", "[screw]", "= =", "[[a]]", "leed = '1 mm'", "\x00"]),
            )
        elif kind == 4:  # truncate
            text = text[: rng.randrange(len(text) + 1)]
            continue
        else:  # swap a unit
            text = text.replace(
                rng.choice(["mm", "deg", "N*m", "um", "rpm", "degC"]),
                rng.choice(["kg", "s", "K", "m", "rad", "", "%"]),
                1,
            )
            continue
        text = "\n".join(lines)
    return text


# (section, key, TOML value, how to read it from the case, the SI value meant or None for a
# refusal, words the value or the refusal must carry). The value meant is worked out from
# the definitions (1 in = 25.4 mm, 1 lbf = 4.4482216152605 N), not by the code under test.
SHOP_FLOOR: list[tuple[str, str, str, Callable[[Any], float], float | None, str]] = [
    ("screw", "ball_diameter", "'5/32\"'", lambda c: c.screw.ball_diameter, 5 / 32 * 0.0254, ""),
    ("screw", "ball_diameter", '"0.15625 in"', lambda c: c.screw.ball_diameter,
     0.15625 * 0.0254, ""),
    ("screw", "ball_diameter", "'0.156\"'", lambda c: c.screw.ball_diameter, 0.156 * 0.0254, ""),
    ("screw", "pitch_diameter", '"1 1/4 in"', lambda c: c.screw.pitch_diameter, 1.25 * 0.0254, ""),
    ("screw", "pitch_diameter", '"1\u00bc in"', lambda c: c.screw.pitch_diameter, 1.25 * 0.0254,
     ""),
    ("screw", "lead", "'0.787\"'", lambda c: c.screw.lead, 0.787 * 0.0254, ""),
    ("operation", "temperature", '"68 F"', lambda c: c.temperature[0], 20.0, "farad"),
    ("operation", "temperature", '"20 C"', lambda c: c.temperature[0], 20.0, "coulomb"),
    ("operation", "axial_load", '"1/4 kN"', lambda c: c.axial_load[0], 250.0, ""),
    ("operation", "axial_load", '"50 lbf"', lambda c: c.axial_load[0], 50 * 4.4482216152605, ""),
    ("screw", "ball_diameter", "\"0.15'\"", lambda c: 0.0, None, "a foot to some"),
    ("screw", "ball_diameter", '"4 g"', lambda c: 0.0, None,
     "'g' (gram) is a mass; this field is a length"),
    ("operation", "temperature", '"20 c"', lambda c: 0.0, None, "speed of light"),
    ("screw", "pitch_diameter", '"1-1/4 in"', lambda c: 0.0, None, "in shop notation"),
    ("screw", "pitch_diameter", '"32 MM"', lambda c: 0.0, None, "did you mean 'mm'?"),
    ("operation", "axial_load", '"50 lb"', lambda c: 0.0, None, "'lbf'"),
    ("screw", "lead", '"20 mn"', lambda c: 0.0, None, "did you mean"),
    ("screw", "lead", '"20"', lambda c: 0.0, None, "a bare number has no unit"),
]  # fmt: skip


def shop_floor_case(section: str, key: str, value: str) -> str:
    """The base case with ``section.key`` set to the TOML ``value``."""
    start = BASE_CASE.index(f"[{section}]")
    head, tail = BASE_CASE[:start], BASE_CASE[start:]
    tail, n = re.subn(rf"(?m)^{key} = .*$", lambda _: f"{key} = {value}", tail, count=1)
    assert n == 1, (section, key)
    return head + tail


def shop_floor_findings() -> list[str]:
    """Each SHOP_FLOOR value read as meant (with its note) or refused with the reason."""
    import math

    findings = []
    for section, key, value, read, meant, words in SHOP_FLOOR:
        text = shop_floor_case(section, key, value)
        try:
            case = parse_case(text)
        except BallScrewInputError as exc:
            if meant is not None or words not in str(exc) or f"{section}.{key}" not in str(exc):
                findings.append(f"{section}.{key} = {value}: {exc}")
            continue
        notes = " ".join(str(a) for a in case.assumptions)
        # The conversions are exact rationals times pint's defined factors: 1e-12.
        if meant is None or not math.isclose(read(case), meant, rel_tol=1e-12):
            findings.append(f"{section}.{key} = {value}: read as {read(case)!r}, meant {meant}")
        elif words and words not in notes:
            findings.append(f"{section}.{key} = {value}: no note saying {words!r}")
    return findings


def mutate_csv(rng: random.Random) -> str:
    """One randomly generated or mutated measured-data CSV."""
    header = rng.choice(ODD_HEADERS) if rng.random() < 0.3 else "speed [rpm],torque [N*m]"
    rows = []
    for _ in range(rng.randrange(0, 8)):
        cells = [f"{rng.uniform(-1e4, 1e4):.6g}", f"{rng.uniform(-2, 2):.6g}"]
        if rng.random() < 0.3:
            cells[rng.randrange(2)] = rng.choice(ODD_CELLS)
        if rng.random() < 0.1:
            cells = cells[:1]
        rows.append(",".join(cells))
    text = "\n".join([header, *rows]) + "\n"
    if rng.random() < 0.1:
        text = BASE_CSV[: rng.randrange(len(BASE_CSV))]
    return text


def classify(func: Callable[[], object]) -> str:
    """'ok', 'input-error', or 'FAIL: ...' for anything else.

    A note of how an ambiguous unit was read (a speed in Hz) is an answer, not a failure.
    """
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewReadingWarning)
            func()
    except BallScrewInputError:
        return "input-error"
    except Exception as exc:
        return f"FAIL: {type(exc).__name__}: {exc}\n{traceback.format_exc(limit=3)}"
    return "ok"


def campaign(n: int, seed: int) -> Counter[str]:
    """Run ``n`` case-file and ``n`` CSV inputs; count the outcomes."""
    rng = random.Random(seed)
    screw = reference_screw()
    counts: Counter[str] = Counter()
    for _ in range(n):
        text = mutate_case(rng)
        counts["case " + classify(lambda t=text: parse_case(t)).split("\n")[0]] += 1
        data = mutate_csv(rng)
        counts["csv " + classify(lambda d=data: parse_measured(d, screw)).split("\n")[0]] += 1
    return counts


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--n", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    counts = campaign(args.n, args.seed)
    total = sum(counts.values())
    print(f"{total} inputs tried ({args.n} case files, {args.n} CSVs, seed {args.seed})")
    for key, value in sorted(counts.items()):
        print(f"{value:>7}  {key}")
    failures = sum(v for k, v in counts.items() if "FAIL" in k)
    shop = shop_floor_findings()
    print(f"shop-floor notation: {len(SHOP_FLOOR) - len(shop)} of {len(SHOP_FLOOR)} as meant")
    for line in shop:
        print(f"  {line}")
    failures += len(shop)
    print(f"findings: {failures}")
    raise SystemExit(1 if failures else 0)


if __name__ == "__main__":
    main()
