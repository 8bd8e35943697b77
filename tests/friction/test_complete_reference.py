"""The one-point speed work of issue 51 keeps the numbers: stored values before it.

``tests/data/complete_reference.json`` was written by ``scripts/complete_reference.py`` on
commit 6edc5b1, before the one-point fast path: every component, total, power loss and
efficiency of the complete model (both ball-train rules, a flooded nut, a 4-point nut, a
grease, another Hertz method) and of the other models at six operating points, each point
one scalar call and the six together one array call. Each is recomputed here.

Tolerance 1e-12 relative: the same equations on the same numbers, evaluated on scalars
rather than arrays, may differ by the rounding of a few operations done in another order
(a few ulp); 1e-12 leaves three orders of margin and is a millionth of what a change of
equation does. A value stored as 0 must stay 0 (no absolute slack).
"""

from __future__ import annotations

import importlib.util
import json

import numpy as np
import pytest

from shared import DATA, ROOT

_spec = importlib.util.spec_from_file_location(
    "complete_reference", ROOT / "scripts" / "complete_reference.py"
)
assert _spec is not None and _spec.loader is not None
complete_reference = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(complete_reference)

STORED = json.loads((DATA / "complete_reference.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def computed() -> dict[str, dict[str, object]]:
    result: dict[str, dict[str, object]] = complete_reference.compute()
    return result


@pytest.mark.parametrize("key", sorted(STORED))
def test_numbers_equal_the_stored_ones(key: str, computed: dict[str, dict[str, object]]) -> None:
    now, stored = computed[key], STORED[key]
    assert now["points"] == stored["points"]
    for how in ("scalar", "array"):
        assert sorted(now[how]) == sorted(stored[how]), how  # type: ignore[call-overload]
        for name, values in stored[how].items():
            np.testing.assert_allclose(
                now[how][name],
                values,
                rtol=1e-12,
                atol=0.0,
                err_msg=f"{how} {name}",  # type: ignore[index]
            )
