"""The allocator's policy of a long run: freed arrays are kept for the next ones.

Measured by the page faults of a child process that allocates three 6 MB arrays and frees
them, 50 times (a model's temporaries over a chunk of points): glibc's default gives the
freed memory back to the system and faults it in again each round (about 1000 pages a
round); with the policy the heap keeps it (the first round's 4600 pages, once).
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from ballscrew.numerics.allocator import keep_freed_memory

CHILD = """
import resource, sys
import numpy as np
if sys.argv[1] == "keep":
    from ballscrew.numerics.allocator import keep_freed_memory
    assert keep_freed_memory()
before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
for _ in range(50):
    a = [np.ones(786432) for _ in range(3)]  # 6 MB each, above glibc's mmap threshold
    del a
print(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)
"""


def _faults(mode: str) -> int:
    env = {"PATH": "", "PYTHONPATH": ":".join(sys.path)}
    out = subprocess.run([sys.executable, "-c", CHILD, mode], capture_output=True, text=True,
                         check=True, env=env)  # fmt: skip
    return int(out.stdout.split()[-1])


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc's mallopt")
def test_freed_arrays_are_kept_for_the_next_ones() -> None:
    if not keep_freed_memory():  # another C library (musl): nothing to keep
        pytest.skip("no glibc mallopt")
    # Kept: the first round's 3 x 1536 pages once, and slack; given back: about 1000 pages
    # a round at least (measured 50 000 in all), ten times the kept figure and more.
    kept, default = _faults("keep"), _faults("default")
    assert kept < 6000
    assert default > 10 * kept
