"""``ballscrew models`` gives each parameter its unit and meaning (issue 40, item 4)."""

from __future__ import annotations

import re

import pytest

from ballscrew.chain import models
from ballscrew.friction import NONE_MEANS, PARAMETER_UNITS
from cli_runner import run


def test_every_model_parameter_has_a_unit_and_a_meaning() -> None:
    for spec in models():
        for name, default in spec.parameters.items():
            assert name in PARAMETER_UNITS, (spec.name, name)
            assert PARAMETER_UNITS[name][1], (spec.name, name)
            # A default of None must say what it stands for.
            assert default is not None or name in NONE_MEANS, (spec.name, name)


def test_the_listing_shows_units_and_no_bare_none(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("COLUMNS", "300")
    code, out, err = run(["models"], capsys)
    assert code == 0, err
    assert "= None" not in out
    line = next(x for x in out.splitlines() if x.strip().startswith("limiting_shear_stress ="))
    assert "(the lubricant's) [Pa]" in line and "limiting shear stress" in line
    assert re.search(r"seal_torque = 0 \[N\*m\]: drag torque", out)
    assert re.search(r"stiffness = 2\.1e\+18 \[N/m\^3\]", out)


def test_the_units_agree_with_the_models_page() -> None:
    # docs/models.md gives each model's parameters in a table written from the papers
    # (| `name` | default | unit | meaning |): the listing's units must be the page's.
    from pathlib import Path

    page = (Path(__file__).resolve().parents[2] / "docs" / "models.md").read_text("utf-8")
    rows = re.findall(r"^\| ((?:`[a-z_0-9]+`(?:, )?)+) \| [^|]* \| ([^|]*) \|", page, re.M)
    checked = set()
    for names, units in rows:
        keys = re.findall(r"`([a-z_0-9]+)`", names)
        shown = [u.strip() for u in units.split(",")]
        shown = shown if len(shown) == len(keys) else shown[:1] * len(keys)
        for key, unit in zip(keys, shown, strict=True):
            doc = unit.replace("·", "*").replace("³", "^3").replace("²", "^2")
            assert (PARAMETER_UNITS[key][0] or "-") == doc, key
            checked.add(key)
    assert checked == {k for spec in models() for k in spec.parameters}
