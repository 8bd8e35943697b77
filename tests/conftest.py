"""Test-wide settings.

Hypothesis is derandomized on CI and random on a developer's machine. Extra
friction models named in ``BALLSCREW_TEST_EXTRA_MODELS`` (paths of Python
files, separated by ``os.pathsep``) are registered before the tests are
collected, so that every test parametrized over the registered models runs
them too (tests/friction/test_new_model.py does so with a toy model).
"""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path

from hypothesis import settings

# tests/data holds inputs, not tests: its toy model must register only when asked for.
collect_ignore = ["data"]

# CI must be deterministic (a failure there must repeat); a local run explores new examples.
# Choose with HYPOTHESIS_PROFILE=ci|dev; CI sets CI=true.
settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))


def _register_extra_models() -> None:
    for path in filter(None, os.environ.get("BALLSCREW_TEST_EXTRA_MODELS", "").split(os.pathsep)):
        spec = importlib.util.spec_from_file_location(Path(path).stem, path)
        assert spec is not None and spec.loader is not None, path
        spec.loader.exec_module(importlib.util.module_from_spec(spec))


_register_extra_models()
