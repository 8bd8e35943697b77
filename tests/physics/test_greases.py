"""Greases in the lubricant library: rows with their base-oil data, the new Lubricant fields."""

from __future__ import annotations

import math

import pytest

from ballscrew import BallScrewInputError, Lubricant, lubricants
from ballscrew.lubricant import NLGI_GRADES

# Each bundled grease with the numbers its data sheet prints (the row's source names the
# sheet): base-oil viscosity at 40 and 100 degC [mm^2/s], thickener, NLGI grade, base oil,
# pour and flash points [degC] (None where the sheet gives none).
SHEETS = {
    "SKF LGHP 2": (96.0, 10.5, "polyurea", "2-3", "mineral", None, 210.0),
    "Mobil Polyrex EM": (115.0, 12.2, "polyurea", "2", "", None, None),
}


def test_the_library_holds_the_greases_of_the_sheets() -> None:
    assert {g.name for g in lubricants.greases()} == set(SHEETS)
    assert all(g.kind == "grease" for g in lubricants.greases())
    names = lubricants.names()
    assert all(name in names for name in SHEETS)


@pytest.mark.parametrize("name", sorted(SHEETS))
def test_each_grease_row_loads_with_its_sheet_values(name: str) -> None:
    nu40, nu100, thickener, grade, base_oil, pour, flash = SHEETS[name]
    grease = lubricants.get(name)
    assert (grease.kind, grease.thickener, grease.nlgi_grade) == ("grease", thickener, grade)
    assert (grease.base_oil, grease.pour_point, grease.flash_point) == (base_oil, pour, flash)
    assert grease.source and "typical" in grease.source  # density, alpha: said to be typical
    # The Walther (ASTM D341) fit runs through its two points: exact at 40 and 100 degC.
    assert float(grease.kinematic_viscosity(40.0)) * 1e6 == pytest.approx(nu40, rel=1e-12)
    assert float(grease.kinematic_viscosity(100.0)) * 1e6 == pytest.approx(nu100, rel=1e-12)


def test_the_oil_rows_are_oils_with_nothing_new_given() -> None:
    for oil in lubricants.all_lubricants():
        if oil.name in SHEETS:
            continue
        assert oil.kind == "oil"
        assert (oil.thickener, oil.nlgi_grade, oil.pour_point, oil.flash_point) == (
            "",
            "",
            None,
            None,
        )


def test_existing_constructor_calls_keep_working() -> None:
    positional = Lubricant("oil", 68e-6, 10e-6, 850.0, 1.7e-8, 4e6, 0.04, 6.5e-4, "astm_d341", "s")
    assert positional.kind == "oil" and positional.source == "s"
    assert Lubricant.from_viscosities("mine", 68e-6, 10e-6, 850.0).kind == "oil"


def test_a_grease_of_ones_own() -> None:
    grease = Lubricant.from_viscosities(
        "my grease", 100e-6, 11e-6, 880.0, kind="grease", thickener=" lithium  complex ",
        nlgi_grade="1.5", base_oil="mineral", pour_point=-24.0, flash_point=230.0,
    )  # fmt: skip
    assert grease.thickener == "lithium complex"  # spaces tidied
    assert (grease.pour_point, grease.flash_point) == (-24.0, 230.0)
    assert isinstance(grease.flash_point, float)


@pytest.mark.parametrize("grade", [*NLGI_GRADES, "1.5", "2-3", "00-0"])
def test_nlgi_grades_as_data_sheets_write_them(grade: str) -> None:
    assert lubricants.get("SKF LGHP 2").replace(nlgi_grade=grade).nlgi_grade == grade


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"kind": "paste"}, "kind"),
        ({"thickener": "lithium"}, "thickener"),  # an oil has no thickener
        ({"nlgi_grade": "2"}, "nlgi_grade"),  # nor a consistency grade
        ({"kind": "grease", "nlgi_grade": "7"}, "nlgi_grade"),
        ({"kind": "grease", "nlgi_grade": "soft"}, "nlgi_grade"),
        ({"kind": "grease", "nlgi_grade": 2}, "nlgi_grade"),
        ({"base_oil": 3}, "base_oil"),
        ({"pour_point": math.nan}, "pour_point"),
        ({"flash_point": "hot"}, "flash_point"),
        ({"pour_point": -300.0}, "pour_point"),
        ({"pour_point": 20.0, "flash_point": 10.0}, "flash_point"),
    ],
)
def test_bad_grease_fields_are_refused_naming_the_field(
    changes: dict[str, object], field: str
) -> None:
    with pytest.raises(BallScrewInputError) as info:
        lubricants.get("PAO ISO VG 68").replace(**changes)
    assert info.value.field == field
