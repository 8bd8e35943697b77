"""Numerical methods the physics needs and no library gives in the form it needs.

- :mod:`.roots` - bracketing root finders that iterate whole arrays at once;
- :mod:`.elliptic` - Carlson's symmetric elliptic integrals and the complete
  integrals K and E, without importing ``scipy.special``.
"""

from __future__ import annotations

from .roots import Index, illinois, newton_bracketed

__all__ = ["Index", "illinois", "newton_bracketed"]
