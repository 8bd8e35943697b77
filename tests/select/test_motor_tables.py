"""The edges of the motor and screw price tables' rules (ballscrew.io.motors).

Each check is one sentence of docs/selection.md or the module's docstring at its
boundary: a value just inside the rule is read, one just outside refused naming the
line and the column. (The tables' ordinary reading is in test_pool.py.)
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.motors import parse_motors, parse_prices

HEADER = "name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], rotor_inertia [kg*cm^2]"


def _rows(n: int) -> str:
    return "".join(f"M{i}, 2.4, 7.2, 3000, 3.1\n" for i in range(n))


def test_a_motor_table_holds_at_most_a_thousand_motors() -> None:
    # MAX_MOTORS: at most 1000 rows (a maker's whole range is about 100), the header apart.
    assert len(parse_motors(f"{HEADER}\n{_rows(1000)}")) == 1000
    with pytest.raises(BallScrewInputError) as refused:
        parse_motors(f"{HEADER}\n{_rows(1001)}")
    assert (refused.value.value, refused.value.allowed) == ("1001 motors", "at most 1000")


def test_a_peak_torque_equal_to_the_rated_one_is_read_and_a_zero_refused() -> None:
    # "a peak torque below the rated one" is refused: equal is allowed (a motor without
    # overload capacity); "a value not above zero" is refused, zero included.
    (motor,) = parse_motors(f"{HEADER}\nM1, 2.4, 2.4, 3000, 3.1\n")
    assert motor.peak_torque == motor.rated_torque == 2.4
    with pytest.raises(BallScrewInputError, match="> 0") as refused:
        parse_motors(f"{HEADER}\nM1, 0, 7.2, 3000, 3.1\n", source="m.csv")
    assert refused.value.field == "m.csv: line 2, column 'rated_torque [N*m]'"


def test_a_table_without_a_name_column_is_refused_naming_it_first() -> None:
    # The missing columns are listed in the header's order: name, then the numbers.
    with pytest.raises(BallScrewInputError) as refused:
        parse_motors("rated_torque [N*m], peak_torque [N*m], max_speed [1/min]\n2.4, 7.2, 3000\n")
    assert refused.value.allowed.endswith("missing: name, rotor_inertia")


def test_a_row_too_short_for_its_name_is_refused_naming_the_column() -> None:
    # The name in the last column, the row stopping before it: an empty name.
    text = ("rated_torque [N*m], peak_torque [N*m], max_speed [1/min], rotor_inertia [kg*cm^2], "
            "name\n2.4, 7.2, 3000, 3.1\n")  # fmt: skip
    with pytest.raises(BallScrewInputError, match="a name") as refused:
        parse_motors(text, source="m.csv")
    assert refused.value.field == "m.csv: line 2, column 'name'"


def test_a_price_table_skips_comments_and_reads_a_price_below_one() -> None:
    # "a price that is not a positive number" is refused: 0.5 is one, 0 is not.
    text = "# prices of 2026\ndesignation, price [EUR]\nISO 25x20-3.969, 0.5\n"
    assert parse_prices(text) == ({"ISO 25x20-3.969": 0.5}, "EUR")
    with pytest.raises(BallScrewInputError, match="> 0") as refused:
        parse_prices("designation, price [EUR]\nA, 0\n", source="p.csv")
    assert refused.value.field == "p.csv: line 2, column 'price [EUR]'"


@pytest.mark.parametrize(
    ("text", "column", "value"),
    [
        ("price [EUR], designation\n3\n", "designation", "(empty)"),
        ("designation, price [EUR]\nA\n", "price [EUR]", "(empty)"),
    ],
)
def test_a_price_row_too_short_is_refused_naming_the_column(
    text: str, column: str, value: str
) -> None:
    with pytest.raises(BallScrewInputError) as refused:
        parse_prices(text, source="p.csv")
    assert (refused.value.field, refused.value.value) == (f"p.csv: line 2, column '{column}'",
                                                          value)  # fmt: skip


@pytest.mark.parametrize("reader", ["read_motors", "read_prices"])
def test_a_table_that_is_no_regular_file_is_refused_by_name(reader: str, tmp_path: Path) -> None:
    # '--motors /dev/zero' read until the process was killed (it never ends): the tables go
    # through the package's one input reader, as case files do, which refuses devices and pipes.
    import os

    from ballscrew.io import motors

    fifo = tmp_path / "table.csv"
    os.mkfifo(fifo)
    flag = "--motors" if reader == "read_motors" else "--screw-prices"
    for path in ("/dev/zero", fifo):
        with pytest.raises(BallScrewInputError, match="a regular file") as info:
            getattr(motors, reader)(path)
        assert info.value.field == flag
