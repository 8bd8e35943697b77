"""Bounded fuzzing of case files, measured CSVs and the CLI (larger runs: tests/fuzz_inputs.py)."""

from __future__ import annotations

import math
import random
from pathlib import Path

import numpy as np
import pytest

from ballscrew import BallScrewInputError, friction_torque
from ballscrew.cli import main
from ballscrew.io.case import load_case, parse_case
from ballscrew.io.measured import read_measured
from fuzz_inputs import SHOP_FLOOR, campaign, mutate_case, shop_floor_findings
from shared import SMALL_CASE


def test_loaders_only_succeed_or_raise_the_input_error() -> None:
    counts = campaign(300, seed=12345)
    assert sum(counts.values()) == 600
    assert not [k for k in counts if "FAIL" in k], counts
    # Both outcomes occur: the mutations reach past the parser.
    assert counts["case ok"] > 0 and counts["case input-error"] > 0
    assert counts["csv ok"] > 0 and counts["csv input-error"] > 0


def test_shop_floor_notation_in_case_files_is_read_as_meant_or_refused_with_the_reason() -> None:
    # issue 40: fractions, inch marks, C and F on temperatures, pounds; each refusal says why.
    assert len(SHOP_FLOOR) >= 15
    assert shop_floor_findings() == []


def test_accepted_mutated_cases_compute_finite_torques() -> None:
    rng = random.Random(7)
    accepted = 0
    for _ in range(300):
        try:
            case = parse_case(mutate_case(rng))
        except BallScrewInputError:
            continue
        accepted += 1
        for model in ("catalog", "harris-simplified"):
            r = friction_torque(
                case.screw,
                case.lubricant,
                speed=np.array([0.0, 50.0]),
                temperature=30.0,
                model=model,
            )
            assert np.all(np.isfinite(r.total)) and np.all(r.total >= 0)
    assert accepted > 10


def test_cli_on_mutated_cases_exits_0_or_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rng = random.Random(99)
    codes: list[int] = []
    for i in range(25):
        case = tmp_path / f"case{i}.toml"
        case.write_text(mutate_case(rng))
        with pytest.raises(SystemExit) as info:
            main(["torque", "--case", str(case), "--speed", "100, 1000 rpm"])
        err = capsys.readouterr().err
        code = info.value.code
        assert code in (0, 2), err
        if code == 2:
            errors = [line for line in err.splitlines() if line.startswith("error:")]
            assert len(errors) == 1 and "Traceback" not in err
        codes.append(int(code))  # type: ignore[arg-type]
    assert 2 in codes


@pytest.mark.parametrize(
    "payload",
    [b"", b"\xff\xfe\x00garbage", b"title = 'x'\n\x80\x81", "é".encode("latin-1")],
)
def test_binary_and_empty_files(tmp_path: Path, payload: bytes) -> None:
    bad = tmp_path / "bad"
    bad.write_bytes(payload)
    with pytest.raises(BallScrewInputError):
        load_case(bad)
    with pytest.raises(BallScrewInputError):
        read_measured(bad, load_case().screw)


def test_huge_and_tiny_values_are_refused_or_finite() -> None:
    base = (SMALL_CASE).read_text()
    for value in ("1e300 m", "1e-300 m", "1e-9 mm"):
        text = base.replace('"3.969 mm"', f'"{value}"')
        try:
            case = parse_case(text)
        except BallScrewInputError:
            continue
        r = friction_torque(case.screw, case.lubricant, speed=10.0, temperature=20.0)
        assert math.isfinite(float(r.total))


def test_the_machine_file_loads_or_is_refused_naming_the_key() -> None:
    # Issue 52: the machine file joins the fuzzed inputs. Values replaced by odd ones, lines
    # deleted, doubled or added, the text cut, units swapped: the loader answers with a
    # machine or an input error, never another exception.
    from ballscrew.io.machine import example_machine_text, parse_machine
    from fuzz_inputs import classify

    rng = random.Random(2026)
    base = example_machine_text()
    counts: dict[str, int] = {}
    for _ in range(1000):
        text = mutate_case(rng, base)
        outcome = classify(lambda t=text: parse_machine(t, folder=None)).split("\n")[0]
        assert not outcome.startswith("FAIL"), (outcome, text)
        counts[outcome] = counts.get(outcome, 0) + 1
    assert counts.get("ok", 0) > 0 and counts.get("input-error", 0) > 0, counts
