"""select's figures of one candidate (``evaluate``), against bounds known without the code."""

from __future__ import annotations

import math
import time
from typing import Any

import pytest

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.select import candidates, evaluate
from shared import ROOT

CASE = ROOT / "examples" / "vertical_32x5.toml"


@pytest.mark.parametrize("force", ["1 kN", "1000 kN"])
def test_a_candidates_seconds_are_the_cpu_time_it_took(force: str) -> None:
    # The seconds figure is the processor time spent on the candidate: more than 0 and at
    # most the time the whole call took, whether it passes through the check (1 kN) or is
    # refused by an input error (1000 kN, far above the nut's static rating).
    m = parse_move(f"stroke=300 mm, feed=10 m/min, acceleration=2 m/s^2, force={force}")
    found = candidates(CASE.read_text("utf-8"), diameter=(0.032, 0.032), lead=(0.010, 0.010),
                       makers=["HIWIN"], preloads=["light"])  # fmt: skip
    before = time.process_time()
    e, check = evaluate(found[0], profile_from_move(m, 1), move=m)
    took = time.process_time() - before
    assert (check is None) is (force == "1000 kN")
    assert 0.0 < e.figures["seconds"] <= took


def test_the_functions_defaults_are_the_commands() -> None:
    # Called from Python, evaluate and run_select run what `ballscrew select` runs without
    # options: one cycle, repeated for --run-time's "1 h" = 3600 s.
    import inspect

    from ballscrew.cli.select import select_command
    from ballscrew.io.units import to_si
    from ballscrew.select import run_select

    options = {p.name: p.default for p in select_command.params}
    assert options["cycles"] == 1 and to_si("--run-time", options["run_time"], "s") == 3600.0
    for function in (evaluate, run_select):
        parameters = inspect.signature(function).parameters
        assert parameters["cycles"].default == 1
        assert parameters["run_time"].default == 3600.0


def _row(key: str, utilisation: float, p: float = 0.0) -> Any:
    from ballscrew.axis.check import Criterion
    from ballscrew.axis.uncertainty import VerdictUncertainty

    verdict = "NOT OK" if utilisation > 1.0 else "OK"
    u = VerdictUncertainty(p, utilisation, utilisation, verdict)
    return Criterion(f"row {key}", 1.0, 1.0, "-", utilisation, verdict, "", uncertainty=u,
                     key=key)  # fmt: skip


def test_a_candidates_figures_from_a_check_set_by_hand() -> None:
    # Rows by hand: a static safety of infinity (no load: utilisation limit/inf = 0), the
    # peak torque at 60 %, the RMS torque at 30 %, the motor speed at 0 %, the life at 50 %.
    # Two cycles of 60 J of friction and 180 J of work on the load: 30 J per cycle, a share
    # of 60/240 = 0.25.
    from types import SimpleNamespace

    from ballscrew.select import choose

    rows = [_row("static_safety", 0.0), _row("peak_torque", 0.6, 0.01),
            _row("rms_torque", 0.3), _row("motor_speed", 0.0), _row("life", 0.5, 0.02)]  # fmt: skip
    check: Any = SimpleNamespace(
        criteria=rows, thermal={}, life={}, p_not_ok=0.02,
        row=lambda key: next((r for r in rows if r.key == key), None),
    )  # fmt: skip
    energy: Any = SimpleNamespace(cycle=SimpleNamespace(friction_energy=60.0), cycles=2,
                             as_dict=lambda: {"load_work_J": -180.0})  # fmt: skip
    run: Any = SimpleNamespace(results={"complete": energy})
    f = choose._figures(check, run, "complete", 1.5)
    assert f["energy_J"] == 30.0 and f["friction_share"] == pytest.approx(0.25, rel=1e-15)
    assert f["motor_margin"] == pytest.approx(0.4, rel=1e-15)  # 1 - the peak torque's 0.6
    assert f["max_utilisation"] == 0.6 and f["p_not_ok"] == 0.02
    # the binding row is the peak torque (60 %), not the unloaded safety's 0 %
    assert choose._binding(check) == "row peak_torque (60%)"
    assert choose._against(rows[0]).endswith("(0%)")
    # the doubt comes from the life (2 %), before the peak torque (1 %)
    assert choose._doubtful(check) == "row life (2.0%)"
    # a friction and a work of 0.1 J and 0.3 J: the share is still a quarter; none at all: NaN
    energy.cycle.friction_energy, energy.cycles = 0.2, 2
    energy.as_dict = lambda: {"load_work_J": 0.6}
    assert choose._figures(check, run, "complete", 1.0)["friction_share"] == pytest.approx(
        0.25, rel=1e-15
    )
    energy.cycle.friction_energy = 0.0
    energy.as_dict = lambda: {"load_work_J": 0.0}
    assert math.isnan(choose._figures(check, run, "complete", 1.0)["friction_share"])


def test_failing_rows_are_told_most_utilised_first() -> None:
    from types import SimpleNamespace

    from ballscrew.select import choose

    rows = [_row("static_safety", 0.0), _row("life", 1.2), _row("peak_torque", 1.5)]
    check: Any = SimpleNamespace(criteria=rows)
    failing = choose._failing(check)
    assert [t.split(":")[0] for t in failing] == ["row peak_torque", "row life"]


@pytest.mark.parametrize(("p", "feasible"), [(0.1, True), (0.10025, False)])
def test_a_probability_of_exactly_one_minus_the_confidence_passes(
    monkeypatch: pytest.MonkeyPatch, p: float, feasible: bool
) -> None:
    # At 90 % confidence 10 % is allowed ("at most"): 400 of 4000 draws NOT OK passes, 401
    # does not. The candidate's energy run and check are replaced by a check set by hand.
    from types import SimpleNamespace

    from ballscrew.select import choose

    rows = [_row("peak_torque", 0.6, p)]
    check: Any = SimpleNamespace(criteria=rows, thermal={}, life={}, p_not_ok=p, verdict="OK",
                                 row=lambda key: None)  # fmt: skip
    energy: Any = SimpleNamespace(cycle=SimpleNamespace(friction_energy=1.0), cycles=1,
                                  as_dict=lambda: {"load_work_J": 1.0})  # fmt: skip
    monkeypatch.setattr(choose, "run_energy", lambda *a, **k: SimpleNamespace(
        results={"complete": energy}))  # fmt: skip
    monkeypatch.setattr(choose, "run_check", lambda *a, **k: check)
    candidate: Any = SimpleNamespace(price=None)
    e, _ = choose.evaluate(candidate, None, parsed=object(), confidence=0.9)  # type: ignore[arg-type]
    assert e.feasible is feasible and e.nominal


def test_rows_of_no_utilisation_bind_and_doubt_only_when_alone() -> None:
    # An unloaded row (0 %) is bound only when every row is at 0 %; among rows that never
    # fail in the draws (P = 0), the doubt goes to the most utilised, not to the 0 % one.
    from types import SimpleNamespace

    from ballscrew.select import choose

    alone: Any = SimpleNamespace(criteria=[_row("static_safety", 0.0)])
    assert choose._binding(alone) == "row static_safety (0%)"
    both: Any = SimpleNamespace(criteria=[_row("static_safety", 0.0), _row("peak_torque", 0.6)])
    assert choose._doubtful(both) == "row peak_torque (0.0%)"
