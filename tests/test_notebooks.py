"""The worked notebooks of docs/notebooks are stored without outputs (the docs build runs
them, myst-nb with ``nb_execution_mode = "force"``) and are listed in the docs' contents."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "docs" / "notebooks").glob("*.ipynb"))


def test_the_three_worked_notebooks_are_there() -> None:
    names = {p.stem for p in NOTEBOOKS}
    assert names == {"size-an-axis", "fit-and-export-friction", "monitor-a-screw"}
    index = (ROOT / "docs" / "index.md").read_text("utf-8")
    assert all(f"notebooks/{name}\n" in index for name in names)
    conf = (ROOT / "docs" / "conf.py").read_text("utf-8")
    assert '"myst_nb"' in conf and 'nb_execution_mode = "force"' in conf


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_a_notebook_is_stored_without_outputs(path: Path) -> None:
    cells = json.loads(path.read_text("utf-8"))["cells"]
    code = [c for c in cells if c["cell_type"] == "code"]
    assert code and all(not c["outputs"] and c["execution_count"] is None for c in code)
    assert cells[0]["cell_type"] == "markdown" and cells[0]["source"][0].startswith("# ")
