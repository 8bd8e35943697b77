"""The package's version: the one place it is written.

``pyproject.toml`` reads it from here (``[tool.setuptools.dynamic]``), so the installed
metadata (``importlib.metadata.version("ballscrew")``), ``ballscrew.__version__`` and
``ballscrew --version`` agree; CHANGELOG.md and CITATION.cff name it for each release.
"""

from __future__ import annotations

__all__ = ["__version__"]

__version__ = "0.3.0"
