"""No input holds a parser (issue 35): the worst shapes of 1 MB are read or refused at once.

0.2.0's pre-check of a TOML file went back over every start inside a long key (a 65 kB key
held the server 40 s, 1 MB about 1.7 h), and a designation followed by a long run of
spaces backtracked through the size pattern's optional parts. Each shape below is timed
in CPU seconds of this process; 1 s is the issue's bound (the runs take about 0.1 s, so
the bound is no measure of speed on a busy machine but of linear against quadratic).
"""

from __future__ import annotations

import time
from collections.abc import Callable

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import MAX_TOML_CHARS, parse_case, parse_toml
from ballscrew.io.designation import resolve

MB = 1_000_000


def _cpu(call: Callable[[], object]) -> float:
    start = time.process_time()
    try:
        call()
    except BallScrewInputError:
        pass
    return time.process_time() - start


@pytest.mark.parametrize(
    "text",
    [
        "k" * (MAX_TOML_CHARS - 10) + " = 1",  # one long key
        ("a" * 30 + ".") * (MAX_TOML_CHARS // 31),  # many dotted parts
        'a = "' + "x" * (MAX_TOML_CHARS - 10),  # an unterminated string
        '"' * MAX_TOML_CHARS,
        "[" * MAX_TOML_CHARS,
        "a." * (MAX_TOML_CHARS // 2),
    ],
    ids=["long-key", "dotted", "unterminated", "quotes", "brackets", "dots"],
)
def test_a_toml_text_of_the_worst_shape_is_read_or_refused_at_once(text: str) -> None:
    assert _cpu(lambda: parse_toml(text, "case")) < 1.0
    assert _cpu(lambda: parse_case(text)) < 1.0


@pytest.mark.parametrize(
    "text",
    ["40x10 double" + " " * MB + "x", "40x10" + " " * MB, "40x10 " + "1 " * (MB // 2), "x" * MB],
    ids=["spaces-then-word", "trailing-spaces", "many-numbers", "one-word"],
)
def test_a_designation_of_the_worst_shape_is_refused_at_once(text: str) -> None:
    assert _cpu(lambda: resolve(text)) < 1.0
    with pytest.raises(BallScrewInputError, match=r"designation.*at most 200 characters"):
        resolve(text)


def test_blanks_inside_a_size_are_still_read() -> None:
    got = resolve("40 x 10   double  2.5 x 2   6.35").geometry
    assert got["lead"] == pytest.approx(0.010) and got["ball_diameter"] == pytest.approx(6.35e-3)
