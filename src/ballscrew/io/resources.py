"""The machine's free memory, and a refusal of work whose estimated memory does not fit.

A command that builds one array or one row per point estimates its memory from
the points and a measured cost per point before it starts
(:func:`check_memory`). It refuses when the estimate exceeds
:data:`MEMORY_SHARE` of the memory the system says is available (Linux's
``MemAvailable``; elsewhere the physical memory), with the estimate and how to
lower it, instead of running until the system kills it or Python raises
``MemoryError``. Where neither figure can be read nothing is refused here (the
command's own point limit still holds).
"""

from __future__ import annotations

import os

from ..errors import BallScrewInputError

__all__ = ["MEMORY_SHARE", "available_memory", "check_memory"]

MEMORY_SHARE = 0.5
"""The share of the available memory one run may plan to take [-]: the rest is the
system's, the other programs' and the estimate's error."""


def available_memory() -> int | None:
    """Bytes of memory available to a new process, or None when the system does not say."""
    try:
        with open("/proc/meminfo", encoding="ascii") as info:
            for line in info:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_PHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return None


def _size(n: float) -> str:
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if n >= scale:
            return f"{n / scale:.3g} {unit}"
    return f"{n / 1e3:.3g} kB"


def check_memory(field: str, count: int, per_item: float, what: str, lower: str) -> None:
    """Refuse ``count`` items of ``per_item`` bytes each when they do not fit in memory.

    ``field`` and ``what`` name the quantity ("operating points"); ``lower`` says how
    to take fewer. The limit is :data:`MEMORY_SHARE` of :func:`available_memory`.
    """
    free = available_memory()
    need = count * per_item
    if free is None or need <= MEMORY_SHARE * free:
        return
    raise BallScrewInputError(
        field, f"{count:,}",
        f"{what} that fit in memory: these need about {_size(need)} by estimate "
        f"({_size(per_item)} each), more than {MEMORY_SHARE:.0%} of the {_size(free)} "
        f"available; {lower}",
    )  # fmt: skip
