"""The candidate pool's rules at their edges (ballscrew.select.pool), against its documentation.

The preload classes are docs/selection.md's shares of C_a (light 3 %, medium 5 %, heavy 8 %,
"none" a single nut without preload), the single nut kept within HIWIN's 5 %; a refusal
names the filters as typed and the closest screws; the scatter of the estimates is the
table docs/selection.md prints.
"""

from __future__ import annotations

import math
import re

import pytest

from ballscrew.design.ratings import RATING_CONFORMITY, dynamic_rating_estimate
from ballscrew.errors import BallScrewInputError
from ballscrew.geometry import BallScrew
from ballscrew.io.designation import catalog_screws
from ballscrew.select.pool import candidates, length_range, rating_scatter
from shared import ROOT

TEXT = (ROOT / "examples" / "vertical_32x5.toml").read_text(encoding="utf-8")


def test_each_preload_class_is_its_share_of_c_a_on_the_nuts_it_suits() -> None:
    # An ISO size is tried as every nut kind; a single nut (4-point, spacer balls) up to 5 %
    # of C_a (medium included), heavy (8 %) on a double nut only, "none" a single nut with
    # play (no preload).
    found = candidates(TEXT, diameter=(0.032, 0.032), lead=(0.01, 0.01), sources=["iso"],
                       preloads=["none", "light", "medium", "heavy"])  # fmt: skip
    kinds = {(c.preload_class, c.nut) for c in found}
    singles = {"double", "single-4point", "spacer-balls"}
    assert kinds == {("none", "single"), ("heavy", "double")} | {
        (p, n) for p in ("light", "medium") for n in singles
    }
    share = {"light": "3 %", "medium": "5 %", "heavy": "8 %"}
    for c in found:
        if c.preload_class == "none":
            assert c.preload_share == 0.0 and 'preload = "0 N"' in c.text
        else:
            assert f'preload_share = "{share[c.preload_class]}"' in c.text


def test_a_length_range_from_zero_is_refused() -> None:
    # Lengths > 0: a diameter range from 0 mm is no screw's.
    with pytest.raises(BallScrewInputError, match="lengths > 0") as refused:
        length_range("--diameter", "0..40 mm")
    assert refused.value.field == "--diameter"


def test_no_screw_passing_is_refused_naming_the_filters_as_typed() -> None:
    with pytest.raises(BallScrewInputError) as refused:
        candidates(TEXT, diameter=(0.100, 0.120), lead=(0.007, 0.007), makers=["HIWIN"])
    assert refused.value.value == "diameter 100..120 mm; lead 7..7 mm; maker HIWIN"


@pytest.mark.parametrize(
    ("diameter", "lead", "first"),
    [
        # 40 x 11 mm: the 40 x 10 nuts are 1/11 off in lead, anything else further.
        ((0.040, 0.040), (0.011, 0.011), ["R40-10K5-FSC (40 x 10 mm)",
                                          "R40-10K5-FDC (40 x 10 mm)",
                                          "R40-10T4-FSI (40 x 10 mm)"]),
        # 63 x 40 mm: 40 x 40 is 23/63 = 0.37 off in diameter, 63 x 20 20/40 = 0.5 in lead,
        # 32 x 32 31/63 + 8/40 = 0.69: distances relative to the size asked for.
        ((0.063, 0.063), (0.040, 0.040), ["R40-40K2-FSC (40 x 40 mm)",
                                          "R63-20K5-FSC (63 x 20 mm)",
                                          "R32-32K2-FSC (32 x 32 mm)"]),
    ],
)  # fmt: skip
def test_the_refusal_names_the_closest_screws(
    diameter: tuple[float, float], lead: tuple[float, float], first: list[str]
) -> None:
    with pytest.raises(BallScrewInputError) as refused:
        candidates(TEXT, diameter=diameter, lead=lead)
    closest = refused.value.allowed.split("closest: ")[1]
    assert re.findall(r"HIWIN (\S+ \([^)]*\))", closest) == first


@pytest.mark.parametrize(
    ("lead", "named", "more"), [((0.005, 0.020), 5, False), ((0.005, 0.040), 5, True)]
)
def test_a_price_table_missing_screws_names_five_and_says_when_there_are_more(
    lead: tuple[float, float], named: int, more: bool
) -> None:
    # HIWIN's 40 mm nuts: five of leads 5 to 20 mm, six up to 40 mm (R40-40K2).
    with pytest.raises(BallScrewInputError) as refused:
        candidates(TEXT, diameter=(0.040, 0.040), lead=lead, makers=["HIWIN"], screw_prices={})
    missing = refused.value.allowed.split("missing: ")[1]
    assert len(re.findall(r"HIWIN R40", missing)) == named
    assert missing.endswith(", ...") == more


def test_the_scatter_is_the_table_the_documentation_prints() -> None:
    # docs/selection.md: C_a median 0.96, 16 to 84 % 0.95 to 0.99, range 0.94 to 1.35;
    # C_0a 1.01, 1.00 to 1.09, 0.96 to 2.24 (two decimals).
    doc = (ROOT / "docs" / "selection.md").read_text(encoding="utf-8")
    s = rating_scatter()
    for name, key in (("C_a", "dynamic"), ("C_0a", "static")):
        pair = r"([\d.]+) to ([\d.]+)"
        row = re.search(rf"^\| {name} +\| ([\d.]+) \| {pair} \| {pair} \|", doc, re.MULTILINE)
        assert row, name
        got = [s[key][k] for k in ("median", "p16", "p84", "min", "max")]
        assert [f"{v:.2f}" for v in got] == list(row.groups()), name


def test_the_scatter_s_percentiles_are_the_16th_50th_and_84th() -> None:
    # The percentile by its definition (linear between the sorted values, at rank
    # q (n - 1)), over the ratios estimated / printed built here from each row's geometry
    # with the documented 45 deg and the makers' groove (RATING_CONFORMITY).
    ratios = []
    for r in catalog_screws():
        if None in (r.ball_diameter, r.loaded_turns, r.dynamic_load_rating,
                    r.static_load_rating):  # fmt: skip
            continue
        screw = BallScrew(r.pitch_diameter or r.nominal_diameter, r.lead, r.ball_diameter or 0.0,
                          math.radians(45.0), RATING_CONFORMITY, RATING_CONFORMITY,
                          r.loaded_turns or 1.0, r.circuits,
                          "single")  # fmt: skip
        ratios.append(dynamic_rating_estimate(screw) / (r.dynamic_load_rating or 1.0))
    ratios.sort()

    def percentile(q: float) -> float:
        rank = q * (len(ratios) - 1)
        low = math.floor(rank)
        return ratios[low] + (rank - low) * (ratios[low + 1] - ratios[low])

    s = rating_scatter()["dynamic"]
    for key, q in (("p16", 0.16), ("median", 0.50), ("p84", 0.84)):
        assert s[key] == pytest.approx(percentile(q), rel=1e-12), key
