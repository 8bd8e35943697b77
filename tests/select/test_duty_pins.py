"""The move a refusal names, written back as ``--move`` is typed (select.choose._duty).

Found by mutation of select/choose.py's newest lines (docs/mutation.md, "The candidate
pool"): test_select.py reads the sentence up to the force, so the units of the jerk, the
force's span and the dwell were not checked. Each value below is converted by hand from
the SI the move is held in.
"""

from __future__ import annotations

from ballscrew.axis.motion import MOVE_KEYS, parse_move
from ballscrew.select.choose import _SHOWN, _duty


def test_every_key_of_a_move_is_named_in_the_unit_it_is_typed_in() -> None:
    move = parse_move("stroke=0.5 m, feed=0.2 m/s, acceleration=3 m/s^2, jerk=40 m/s^3, "
                      "force=1.5 kN, force_from=0.1 m, force_to=0.4 m, dwell=3000 ms")  # fmt: skip
    # 0.5 m = 500 mm; 0.2 m/s x 60 s/min = 12 m/min; 1.5 kN = 1500 N;
    # 0.1 m and 0.4 m = 100 and 400 mm; 3000 ms = 3 s.
    assert _duty(move) == (
        "stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, jerk=40 m/s^3, force=1500 N, "
        "force_from=100 mm, force_to=400 mm, dwell=3 s"
    )


def test_a_key_no_move_has_is_named_with_its_number_alone() -> None:
    # A library caller's own key (no unit known): its value as given.
    assert _duty({"cycles": 2.0}) == "cycles=2"
    assert _duty(None) == _duty({}) == "the profile's duty"


def test_every_key_a_move_may_hold_has_its_typed_unit() -> None:
    # A key of MOVE_KEYS without a typed unit would be named by its SI number and no unit.
    assert set(_SHOWN) == set(MOVE_KEYS)
