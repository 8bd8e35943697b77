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


def mutate_case(rng: random.Random) -> str:
    """One randomly mutated case text."""
    text = BASE_CASE
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
    print(f"findings: {failures}")
    raise SystemExit(1 if failures else 0)


if __name__ == "__main__":
    main()
