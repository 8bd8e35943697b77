"""The ``ballscrew`` command: the group and ``main`` (:mod:`.group`), one module per command.

Each command module parses its options, calls the wing that computes, and formats; nothing
is computed here.
"""

from __future__ import annotations

from .group import cli, main

__all__ = ["cli", "main"]
