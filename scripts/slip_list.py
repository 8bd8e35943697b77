"""Run issue 35's slip list against the importable ballscrew and count what held.

    PYTHONPATH=src python scripts/slip_list.py            # this tree
    PYTHONPATH=/path/to/0.2.0/src python scripts/slip_list.py

Every slip of items 1 to 4 of the issue's Why (tests/faces/slips.py) goes through each
face it reaches (the library, the command line, the web API): it *held* when it was read
as meant or refused (or warned) naming its field, it *broke* otherwise (a wrong number, a
foreign exception, another field). The hostile inputs of items 5 to 7 run one per
process with a time limit, so a release that hangs on one is counted, not waited for.
Prints the tried / held / broke counts of both lists and each broken entry.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "faces"))

LIMIT = 60.0
"""Seconds a hostile input's process may take before it is counted as broken (a hang)."""


def _one_hostile(name: str) -> None:
    """Run one hostile probe in this process and print its outcome as JSON."""
    import slips

    face, probe = {**slips.HOSTILE, **slips.SLOW_HOSTILE}[name]
    with tempfile.TemporaryDirectory() as folder:
        try:
            if face == "web":
                with slips.web_client() as client:
                    got = probe(Path(folder), client)
            else:
                got = probe(Path(folder), None)
        except slips.NotTriedError as why:
            print(json.dumps({"held": None, "how": f"not tried: {why}"}))
            return
    print(json.dumps({"held": got.held, "how": got.how}))


def _hostile(name: str) -> tuple[bool | None, str]:
    start = time.perf_counter()
    try:
        done = subprocess.run(
            [sys.executable, __file__, "--hostile", name],
            capture_output=True, text=True, timeout=LIMIT, check=False,
        )  # fmt: skip
    except subprocess.TimeoutExpired:
        return False, f"no answer in {LIMIT:g} s"
    lines = done.stdout.strip().splitlines()
    try:
        got = json.loads(lines[-1])
    except (IndexError, json.JSONDecodeError):
        tail = (done.stderr.strip().splitlines() or ["(nothing)"])[-1]
        return False, f"the probe failed: {tail}"[:200]
    held = None if got["held"] is None else bool(got["held"])
    return held, f"{got['how']} ({time.perf_counter() - start:.1f} s)"


def main() -> int:
    """Count the slip list and the hostile inputs (``--hostile NAME``: run one, print JSON)."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hostile", help=argparse.SUPPRESS)
    parser.add_argument("--verbose", action="store_true", help="print every entry")
    args = parser.parse_args()
    if args.hostile:
        _one_hostile(args.hostile)
        return 0
    warnings.simplefilter("ignore")
    import slips

    import ballscrew

    print(f"ballscrew {ballscrew.__version__} from {Path(ballscrew.__file__).parent}")
    tried = held = 0
    broken: list[str] = []
    with slips.web_client() as client:
        for name, slip in slips.SLIPS.items():
            for face in slips.FACES:
                with tempfile.TemporaryDirectory() as folder:
                    try:
                        got = slips.outcome(slip, face, folder=Path(folder), client=client)
                    except Exception as exc:  # the probe itself met a missing API: broke
                        got = slips.Outcome(False, f"{type(exc).__name__}: {exc}"[:200])
                if got is None:
                    continue
                tried += 1
                held += got.held
                line = f"{'held ' if got.held else 'BROKE'} {name} [{face}]: {got.how}"
                if not got.held:
                    broken.append(line)
                if args.verbose:
                    print(line)
    print(f"slip list (issue 35, items 1-4): tried {tried}, held {held}, broke {tried - held}")
    for line in broken:
        print("  " + line)
    h_tried = h_held = 0
    h_broken: list[str] = []
    for name in [*slips.HOSTILE, *slips.SLOW_HOSTILE]:
        ok, how = _hostile(name)
        if ok is None:
            print(f"  not tried: {name}: {how}")
            continue
        h_tried += 1
        h_held += ok
        line = f"{'held ' if ok else 'BROKE'} {name}: {how}"
        if not ok:
            h_broken.append(line)
        if args.verbose:
            print(line)
    print(f"hostile inputs (items 5-7): tried {h_tried}, held {h_held}, broke {h_tried - h_held}")
    for line in h_broken:
        print("  " + line)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
