"""The ISO 3408-2 sizes a selection tries (select.pool.ISO_SIZES), against outside numbers.

Nominal diameters and leads of metric ball screws are preferred numbers: the rounded R10
series of ISO 3 (1, 1.25, 1.6, 2, 2.5, 3.2, 4, 5, 6.3, 8 times a power of ten). Each size
names where its ball and circuits come from: a HIWIN nut, whose designation
``R<diameter>-<lead>K<circuits>`` states its size and circuits, or the nearest bundled
size; the ball must be that bundled row's (data/catalog_screws.csv).
"""

from __future__ import annotations

import math
import re

from ballscrew.io.designation import catalog_screws
from ballscrew.select.pool import ISO_SIZES, iso_rows

R10 = (1.0, 1.25, 1.6, 2.0, 2.5, 3.2, 4.0, 5.0, 6.3, 8.0)


def _preferred(value: float) -> bool:
    mantissa = value / 10.0 ** math.floor(math.log10(value))
    return any(math.isclose(mantissa, r, rel_tol=1e-9) for r in R10)


def test_every_diameter_and_lead_is_a_preferred_number() -> None:
    for d, lead, *_ in ISO_SIZES:
        assert _preferred(d) and _preferred(lead), (d, lead)


def test_each_size_takes_the_ball_and_circuits_of_the_hiwin_nut_it_names() -> None:
    hiwin = [r for r in catalog_screws() if r.maker == "HIWIN" and r.ball_diameter is not None]
    for d, lead, ball, circuits, where in ISO_SIZES:
        assert isinstance(circuits, int) and circuits >= 1, where
        nut = re.search(r"HIWIN R(\d+)-(\d+)K(\d+)", where)
        if nut:  # that nut itself: its designation gives diameter, lead and circuits
            assert (d, lead, circuits) == tuple(int(g) for g in nut.groups()), where
            named = [r for r in hiwin if r.designation.startswith(nut.group(0)[6:])]
        else:  # the nearest bundled size, 'HIWIN <diameter>x<lead>': its ball
            size = re.search(r"HIWIN (\d+)x(\d+)", where)
            assert size, where
            named = [r for r in hiwin if (round(r.nominal_diameter * 1e3), round(r.lead * 1e3))
                     == (int(size.group(1)), int(size.group(2)))]  # fmt: skip
        assert named, where
        assert any(
            math.isclose(ball, (r.ball_diameter or 0.0) * 1e3, rel_tol=1e-9) for r in named
        ), where


def test_every_iso_size_has_one_loaded_turn_per_circuit() -> None:
    # The module's table: circuits of one loaded turn each (internal recirculation).
    assert [r.loaded_turns for r in iso_rows()] == [1.0] * len(ISO_SIZES)
