"""The selection's rule on constructed candidate sets whose answer is known by hand.

Each candidate's check is replaced by stated figures (energy, life, largest
utilisation, P(NOT OK)), so that the feasibility with its confidence, the front,
the tie on utilisation, the undecided case and the message of a selection nothing
passes are checked against what one reads off the table, not against the code.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import pytest

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case
from ballscrew.io.designation import find
from ballscrew.select import NoFeasibleCandidateError, SelectResult, choose, run_select
from ballscrew.select.choose import FIGURES, Evaluated, parse_confidence
from ballscrew.select.pool import Candidate
from shared import ROOT

pytest.importorskip("pymoo")

CASE = ROOT / "examples" / "vertical_32x5.toml"
MOVE = "stroke=300 mm, feed=6 m/min, acceleration=2 m/s^2"


def _candidate(name: str) -> Candidate:
    return Candidate(find("HIWIN R32-10K5-FSC"), "single-4point", name, 0.03, "oil", "")


def _set(
    monkeypatch: pytest.MonkeyPatch, table: Sequence[tuple[str, float, float, float, float]],
    failing: dict[str, tuple[str, ...]] | None = None,
) -> list[Candidate]:  # fmt: skip
    """Candidates named by their preload class, each with (energy J, life h, largest
    utilisation, P(NOT OK)) instead of its check; a utilisation above 1 fails nominally."""
    pool = [_candidate(row[0]) for row in table]
    by_name = {c.name: row for c, row in zip(pool, table, strict=True)}

    def evaluate(candidate: Candidate, *args: Any, confidence: float = 0.95,
                 **kwargs: Any) -> tuple[Evaluated, None]:  # fmt: skip
        _, energy, life, u, p = by_name[candidate.name]
        figures = {k: math.nan for k in FIGURES}
        figures |= {"energy_J": energy, "L10_h": life, "max_utilisation": u,
                    "p_not_ok": math.nan if u > 1.0 else p}  # fmt: skip
        nominal = u <= 1.0
        return Evaluated(candidate, figures, nominal and p <= 1.0 - confidence,
                         f"thermal lead error per 300 mm (P5) ({u:.0%})", nominal,
                         (failing or {}).get(candidate.preload_class, ()),
                         f"thermal lead error per 300 mm (P5) ({p:.1%})"), None  # fmt: skip

    monkeypatch.setattr(choose, "evaluate", evaluate)
    monkeypatch.setattr(choose, "_prepared", lambda found, *a: [(None, None)] * len(found))
    return pool


def _select(pool: list[Candidate], **kwargs: Any) -> SelectResult:
    m = parse_move(MOVE)
    return run_select(load_case(CASE), profile_from_move(m, 1), move=m, pool=pool, **kwargs)


def _pick(result: SelectResult) -> str:
    return result.evaluated[result.recommended].candidate.preload_class


def test_a_nominal_best_too_likely_to_fail_is_passed_over(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # 'a' is best on energy and life and all utilisations under 80 %: the nominal pick.
    # Its P(NOT OK) of 14 % is above 5 %: 'b', the only candidate sure at 95 %, is picked.
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.78, 0.14),
                              ("b", 150.0, 40_000.0, 0.70, 0.02),
                              ("c", 90.0, 60_000.0, 1.20, 0.0)])  # fmt: skip
    result = _select(pool)
    assert _pick(result) == "b" and not result.undecided
    assert [result.evaluated[i].candidate.preload_class for i in result.front] == ["b"]
    assert "P(NOT OK) = 2.0%" in result.reason
    assert "the pick would be HIWIN R32-10K5-FSC single-4point a" in result.reason
    assert "14.0%" in result.reason
    # at 80 % confidence (20 % allowed) 'a' passes and, dominating 'b', is picked
    assert _pick(_select(pool, confidence=0.80)) == "a"


def test_no_candidate_sure_enough_is_undecided_with_its_probability(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.93, 0.44),
                              ("b", 150.0, 60_000.0, 0.85, 0.29),
                              ("c", 90.0, 60_000.0, 1.20, 0.0)])  # fmt: skip
    result = _select(pool)
    assert result.undecided and result.feasible == []
    # both pass at nominal values and neither dominates the other: the front is both,
    # and the one least likely to fail, 'b' (29 % against 44 %), is named
    assert _pick(result) == "b" and len(result.front) == 2
    assert result.reason.startswith("undecided: no candidate passes with 95% confidence")
    assert "P(NOT OK) = 29.0%" in result.reason
    assert result.as_dict()["undecided"] is True


def test_a_tie_on_utilisation_goes_to_the_first_objective(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The reproducer: two screws equally bound (92.0 and 92.5 %, within 1 %), the
    # first in the list at 264 J, the other at 168 J: the 168 J one is recommended.
    pool = _set(monkeypatch, [("a", 264.0, 90_000.0, 0.920, 0.0),
                              ("b", 168.0, 50_000.0, 0.925, 0.0),
                              ("c", 120.0, 30_000.0, 0.960, 0.0)])  # fmt: skip
    result = _select(pool)
    assert _pick(result) == "b"
    assert "tied within 1% of utilisation" in result.reason and "168 J" in result.reason
    # outside the band the least largest utilisation still decides: 'c' at 96 % is not tied
    assert result.evaluated[2].figures["max_utilisation"] - 0.920 > choose.TIE_BAND
    # with life first the tie goes to 'a' (90 000 h against 50 000 h)
    assert _pick(_select(pool, objectives=["life", "energy"])) == "a"


def test_below_80_percent_the_first_objective_picks(monkeypatch: pytest.MonkeyPatch) -> None:
    pool = _set(monkeypatch, [("a", 200.0, 90_000.0, 0.50, 0.0),
                              ("b", 150.0, 50_000.0, 0.70, 0.0)])  # fmt: skip
    assert _pick(_select(pool)) == "b"  # least energy
    assert _pick(_select(pool, objectives=["life", "energy"])) == "a"  # longest life


def test_nothing_passing_names_the_closest_rows_and_by_how_much(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    life = "fatigue life L10: 15100 h against a limit of 20000 h (132%)"
    lift = "lift-off F_max / (2^1.5 F_pr): 2677 N against a limit of 1400 N (191%)"
    pool = _set(monkeypatch, [("a", 100.0, 15_100.0, 1.91, 0.0),
                              ("b", 100.0, 15_100.0, 1.32, 0.0),
                              ("c", 100.0, 9_000.0, 2.50, 0.0),
                              ("d", 100.0, 9_000.0, 3.00, 0.0)],
                failing={"a": (lift, life), "b": (life,), "c": ("x",), "d": ("y",)})  # fmt: skip
    with pytest.raises(NoFeasibleCandidateError) as info:
        _select(pool)
    text = str(info.value)
    # the three closest, most nearly passing first, each row with its value and limit
    assert text.startswith("no candidate passes the check over stroke=300 mm")
    assert text.index("b, oil fails " + life) < text.index("a, oil fails " + lift + "; " + life)
    assert "c, oil fails x" in text and "d, oil" not in text
    assert "is not allowed" not in text and "--move" not in text
    assert info.value.result.reason == text


def test_a_failing_row_reads_value_against_limit() -> None:
    from ballscrew.axis.check import Criterion

    # a life of 15 100 h against 20 000 h asked: utilisation 20 000 / 15 100 = 1.3245
    row = Criterion("fatigue life L10", 15_100.0, 20_000.0, "h", 20_000 / 15_100, "NOT OK", "")
    assert choose._against(row) == "fatigue life L10: 15100 h against a limit of 20000 h (132%)"


def test_a_confidence_is_read_as_typed() -> None:
    assert parse_confidence("95 %") == parse_confidence("95%") == parse_confidence(0.95) == 0.95
    for bad in ("95", "120 %", "abc", "40 %"):
        with pytest.raises(BallScrewInputError, match=r"from 50 % to 99\.9 %"):
            parse_confidence(bad)


# Pins written from the mutation run of 2026-12-05 (docs/mutation.md).


def test_a_confidence_of_50_and_of_99_9_percent_are_the_range_s_ends() -> None:
    # The documented range, "from 50 % to 99.9 %", includes both ends; 100 % is beyond it.
    assert (parse_confidence("50 %"), parse_confidence("99.9 %")) == (0.5, 0.999)
    with pytest.raises(BallScrewInputError, match=r"from 50 % to 99\.9 %"):
        parse_confidence("100 %")


def test_the_sentences_name_what_is_allowed_and_where_the_doubt_comes_from(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # At 95 % confidence, 1 - 0.95 = 5 % is allowed. 'b' is picked with 2 %; 'a', the nominal
    # pick, has 14 % > 5 %; both doubts come from their binding row (the same row here).
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.78, 0.14),
                              ("b", 150.0, 40_000.0, 0.70, 0.02)])  # fmt: skip
    reason = _select(pool).reason
    assert "P(NOT OK) = 2.0% (at most 5% allowed), most likely from its binding row" in reason
    assert "its P(NOT OK) is 14.0%, above the 5% allowed, most likely from its binding row" in (
        reason
    )
    # undecided: the sentence names the 5 % too, and the binding row once
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.93, 0.44),
                              ("b", 150.0, 60_000.0, 0.85, 0.29)])  # fmt: skip
    reason = _select(pool).reason
    assert "(P(NOT OK) at most 5%); 2 of 2 pass at their nominal values" in reason
    assert reason.endswith("P(NOT OK) = 29.0%, most likely from its binding row, "
                           "thermal lead error per 300 mm (P5) (85%)")  # fmt: skip
    # A pick that never fails in the draws (P = 0) has no row to blame.
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.5, 0.0)])
    reason = _select(pool).reason
    assert reason.endswith("P(NOT OK) = 0.0% (at most 5% allowed)")


def test_a_doubt_from_another_row_than_the_binding_one_names_both(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.93, 0.44),
                              ("b", 150.0, 60_000.0, 0.85, 0.29)])  # fmt: skip
    stated = choose.evaluate

    def other_row(candidate: Candidate, *args: Any, **kwargs: Any) -> tuple[Evaluated, None]:
        e, _ = stated(candidate, *args, **kwargs)
        return Evaluated(e.candidate, e.figures, e.feasible, "fatigue life L10 (85%)",
                         e.nominal, e.failing, e.doubtful), None  # fmt: skip

    monkeypatch.setattr(choose, "evaluate", other_row)
    reason = _select(pool).reason
    assert reason.endswith("P(NOT OK) = 29.0%, most likely from thermal lead error per 300 mm "
                           "(P5) (29.0%); its binding row: fatigue life L10 (85%)")  # fmt: skip


def test_the_pick_says_how_many_were_below_80_percent_and_ties_only_when_tied(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Two members at or below 80 % (neither dominates: less energy against longer life).
    pool = _set(monkeypatch, [("a", 200.0, 90_000.0, 0.50, 0.0),
                              ("b", 150.0, 50_000.0, 0.70, 0.0)])  # fmt: skip
    assert "among the 2 candidates of the front whose every utilisation is at most 80%" in (
        _select(pool).reason
    )
    pool = _set(monkeypatch, [("a", 200.0, 90_000.0, 0.50, 0.0)])
    assert "among the one candidate of the front whose every" in _select(pool).reason
    # Above 80 %, one member alone at the least utilisation: no tie is told.
    pool = _set(monkeypatch, [("a", 200.0, 90_000.0, 0.90, 0.0),
                              ("b", 150.0, 50_000.0, 0.95, 0.0)])  # fmt: skip
    result = _select(pool)
    assert _pick(result) == "a" and "tied" not in result.reason


def test_the_first_objective_decides_the_undecided_tie_and_the_passed_over_pick(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Undecided, 'a' and 'b' equally likely to fail (30 %): the first objective breaks the
    # tie, energy to 'a' (100 J), life to 'b' (60 000 h).
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.7, 0.30),
                              ("b", 150.0, 60_000.0, 0.7, 0.30)])  # fmt: skip
    assert _pick(_select(pool)) == "a"
    assert _pick(_select(pool, objectives=["life", "energy"])) == "b"
    # 'b' alone is sure at 95 %; on nominal verdicts the pick would be the best of the
    # three on the first objective: 'a' on energy (100 J), 'd' on life (90 000 h).
    pool = _set(monkeypatch, [("a", 100.0, 40_000.0, 0.78, 0.14),
                              ("b", 150.0, 45_000.0, 0.70, 0.02),
                              ("d", 200.0, 90_000.0, 0.70, 0.20)])  # fmt: skip
    assert "the pick would be HIWIN R32-10K5-FSC single-4point a," in _select(pool).reason
    result = _select(pool, objectives=["life", "energy"])
    assert _pick(result) == "b"
    assert "the pick would be HIWIN R32-10K5-FSC single-4point d," in result.reason


def test_an_objective_the_inputs_cannot_give_is_refused_with_what_they_can(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pool = _set(monkeypatch, [("a", 100.0, 50_000.0, 0.5, 0.0)])
    with pytest.raises(BallScrewInputError) as info:
        _select(pool, objectives=["price"])
    assert info.value.allowed.endswith("or a --screw-prices table; neither was given")
    # The stated figures are energy and life only: no motor margin, and said which are.
    with pytest.raises(BallScrewInputError) as info:
        _select(pool, objectives=["motor_margin"])
    assert info.value.allowed == (
        "an objective computed for some feasible candidate (the case has no [motor] and no "
        "--motors table was given); computed: energy, life"
    )
