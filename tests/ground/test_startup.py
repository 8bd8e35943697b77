"""A one-point command imports only what it uses (issue 25), with the same numbers.

Start-up is not timed here (a timed test fails on a loaded machine; the figures
are in benchmarks/bench_single_point.py): what is tested is what a fresh
interpreter imports for ``ballscrew torque`` at one point, and that the pieces
put in place of the costly imports give the same values.
"""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
from scipy import special

from ballscrew.numerics.elliptic import carlson_rd, carlson_rf, complete_integrals

_PROBE = """
import json, sys
from ballscrew.cli import main
try:
    main(["torque", "--speed", "100 rpm"])
except SystemExit:
    pass
print(json.dumps(sorted(sys.modules)))
"""


def test_one_point_torque_imports_neither_dask_nor_scipy_special_nor_numba() -> None:
    out = subprocess.run(
        [sys.executable, "-c", _PROBE], capture_output=True, text=True, check=True, timeout=120
    ).stdout
    loaded = set(json.loads(out.splitlines()[-1]))
    # The speed's rpm converts as one multiplication (io.units.PLAIN_FACTORS): no pint.
    assert "pint" not in loaded
    # numba: the helix's compiled kernel is for many points; one point takes numpy's path.
    for costly in ("dask", "scipy.special", "numba"):
        assert costly not in loaded, costly


def test_dask_imports_as_usual_after_the_units() -> None:
    probe = (
        "import ballscrew.io.units, sys; assert 'dask' not in sys.modules;"
        "import dask.array as da; print(float(da.ones(4).sum().compute()))"
    )
    out = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=120
    ).stdout
    assert out.strip() == "4.0"


# --- the elliptic integrals without scipy.special: to a few units of the last place ----------
ULPS = 8 * np.finfo(float).eps


def test_complete_integrals_match_scipy() -> None:
    rng = np.random.default_rng(2)
    k = np.concatenate(
        [[1.0, 1.0 + 1e-12, 1.001, 5.0, 72.0, 1e8], np.exp(rng.uniform(0, 12, 4000))]
    )
    p = 1.0 / k**2
    big_k, big_e = complete_integrals(k)
    np.testing.assert_allclose(big_k, special.ellipkm1(p), rtol=ULPS, atol=0.0)
    np.testing.assert_allclose(big_e, special.ellipe(1.0 - p), rtol=ULPS, atol=0.0)
    # One axis ratio (the cached path of one geometry) gives the batch's bits.
    for i in range(0, 4006, 97):
        one_k, one_e = complete_integrals(k[i : i + 1])
        assert one_k[0] == big_k[i] and one_e[0] == big_e[i], k[i]


def test_carlson_integrals_match_scipy() -> None:
    rng = np.random.default_rng(3)
    x, y, z = rng.uniform(0.0, 10.0, (3, 4000))
    x[:100] = 0.0
    np.testing.assert_allclose(carlson_rf(x, y, z), special.elliprf(x, y, z), rtol=ULPS)
    np.testing.assert_allclose(carlson_rd(x, y, z), special.elliprd(x, y, z), rtol=ULPS)
    # Each element stops at its own step, and one point takes the same steps on Python
    # floats: a value does not depend on its neighbours, to the bit.
    for f in (carlson_rf, carlson_rd):
        batch = f(x[:200], y[:200], z[:200])
        one = [float(f(a, b, c)) for a, b, c in zip(x[:200], y[:200], z[:200], strict=True)]
        assert np.array_equal(batch, one), f.__name__
