"""The C allocator's policy for a long run of many array calls of one size.

On Linux, glibc's ``malloc`` gives an array above its mmap threshold (128 kB at
first, raised to the largest one freed) fresh pages from the system and returns them
when the array is freed: arrays of one size allocated and freed again and again (a
chunk of points, a group of screws) are faulted in anew each time, which is system
time (benchmarks/README.md, "System time: the allocator"). :func:`keep_freed_memory`
fixes the thresholds for the rest of the process, so that freed arrays are kept for
the next ones. A command that makes many such calls (``ballscrew select``) calls it;
the library itself never does.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

__all__ = ["MMAP_THRESHOLD", "TRIM_THRESHOLD", "keep_freed_memory"]

MMAP_THRESHOLD = 32 << 20
"""Arrays below this many bytes come from the heap [B] (glibc's ``M_MMAP_THRESHOLD``)."""

TRIM_THRESHOLD = 256 << 20
"""Free memory at the heap's top kept for later arrays up to this many bytes [B]
(glibc's ``M_TRIM_THRESHOLD``): the process may hold this much more than it uses."""

_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # glibc's malloc.h


def keep_freed_memory() -> bool:
    """Keep freed arrays of up to :data:`MMAP_THRESHOLD` bytes for later ones (glibc only).

    Returns whether the policy was set: False on another system or C library, where
    nothing changes. Every number is the same either way; only the system time differs.
    """
    if not sys.platform.startswith("linux"):
        return False
    name = ctypes.util.find_library("c")
    try:
        libc = ctypes.CDLL(name or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):  # not glibc (musl has no mallopt)
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    return bool(mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD)) and bool(
        mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD)
    )
