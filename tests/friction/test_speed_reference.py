"""The speed work of issue 51 keeps the numbers: stored values of the sources before it.

``tests/data/speed_reference.json`` was written by ``scripts/speed_reference.py`` on the
sources before issue 51 (harris-simplified's shear stress in cache-sized blocks, the many-
screws path without its per-screw look-ups). Each is recomputed here. Tolerance 1e-12
relative: the same equations on the same numbers, only evaluated in other slices of the
arrays, may differ by the rounding of a product (BLAS) summed in another order, a few ulp;
1e-12 leaves three orders of margin and is a millionth of anything a change of equation does.
"""

from __future__ import annotations

import importlib.util
import json
import math

import numpy as np
import pytest

from shared import DATA, ROOT

_spec = importlib.util.spec_from_file_location(
    "speed_reference", ROOT / "scripts" / "speed_reference.py"
)
assert _spec is not None and _spec.loader is not None
speed_reference = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(speed_reference)

STORED = json.loads((DATA / "speed_reference.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def computed() -> dict[str, dict[str, dict[str, object]]]:
    result: dict[str, dict[str, dict[str, object]]] = speed_reference.compute()
    return result


@pytest.mark.parametrize("key", sorted(STORED))
def test_numbers_equal_the_stored_ones(
    key: str, computed: dict[str, dict[str, dict[str, object]]]
) -> None:
    assert sorted(computed[key]) == sorted(STORED[key])
    for component, stored in STORED[key].items():
        now = computed[key][component]
        assert math.isclose(now["sum"], stored["sum"], rel_tol=1e-12, abs_tol=1e-300), component  # type: ignore[arg-type]
        np.testing.assert_allclose(
            now["sample"], stored["sample"], rtol=1e-12, atol=0.0, err_msg=component
        )  # type: ignore[arg-type]
        assert len(now["sample"]) == len(stored["sample"])  # type: ignore[arg-type]
