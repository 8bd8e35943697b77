"""Test-wide settings: Hypothesis is derandomized on CI, random on a developer's machine."""

from __future__ import annotations

import os

from hypothesis import settings

# CI must be deterministic (a failure there must repeat); a local run explores new examples.
# Choose with HYPOTHESIS_PROFILE=ci|dev; CI sets CI=true.
settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))
