"""Module paths that moved, kept importable for one release with a DeprecationWarning.

Code written against an older layout (``import ballscrew.sizing``, ``from
ballscrew.case import load_case``, ``from ballscrew.fit.friction_map import
friction_map``) keeps working: a finder on ``sys.meta_path``
answers for the old name with the module at its new place, and warns once per
name. The aliases are removed in the release after the one that moved them
(see CHANGELOG.md).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import warnings
from collections.abc import Mapping
from types import ModuleType
from typing import Any

__all__ = ["MOVED", "install", "renamed"]

MOVED: dict[str, str] = {
    # 0.4.0: friction for controllers joined the servo wing (fit/ is the measurements')
    "fit.controller": "servo.controller",
    "fit.export": "servo.export",
    "fit.friction_map": "servo.friction_map",
    # 0.3.0: the design rules and the plumbing left the package's top
    "ratings": "design.ratings",
    "sizing": "design.sizing",
    "stiffness": "design.stiffness",
    "limits": "design.limits",
    "catalog_formulas": "design.catalog_formulas",
    "units": "io.units",
    "files": "io.files",
    "extras": "io.extras",
    "examples": "geometry",
    # 0.2.0: the wings and the readers became folders
    "case": "io.case",
    "case_schema": "io.schema",
    "designation": "io.designation",
    "measured": "io.measured",
    "energy": "axis.energy",
    "motion": "axis.motion",
    "thermal": "axis.thermal",
    "axis_setup": "axis.setup",
    "calibration": "fit.calibration",
    "controller": "servo.controller",
    "validation": "study.validation",
}
"""Old module name below ``ballscrew`` -> its place now."""


class _Alias(importlib.abc.Loader):
    """Loads an old name as the module at its new place."""

    def __init__(self, old: str, new: str) -> None:
        self.old, self.new = old, new
        self.spec: importlib.machinery.ModuleSpec | None = None

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        warnings.warn(
            f"{self.old} moved to {self.new}; the old name goes in the next release",
            DeprecationWarning,
            stacklevel=2,
        )
        module = importlib.import_module(self.new)
        self.spec = module.__spec__
        return module

    def exec_module(self, module: ModuleType) -> None:
        # The import system stamped the alias's spec on the real module: give it back its own.
        module.__spec__ = self.spec


class _Finder(importlib.abc.MetaPathFinder):
    """Answers ``find_spec`` for the old names of :data:`MOVED` only."""

    def find_spec(
        self, fullname: str, path: object = None, target: object = None
    ) -> importlib.machinery.ModuleSpec | None:
        head, _, name = fullname.partition(".")
        if head != "ballscrew" or name not in MOVED:
            return None
        new = f"ballscrew.{MOVED[name]}"
        return importlib.machinery.ModuleSpec(fullname, _Alias(fullname, new))


def install() -> None:
    """Put the finder on ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _Finder) for f in sys.meta_path):
        sys.meta_path.append(_Finder())


def renamed(module: str, name: str, renames: Mapping[str, Any]) -> Any:
    """A module's ``__getattr__`` for names that were renamed: the object, with a warning.

    ``renames`` maps each old name in ``module`` to the object it is now (named
    by its ``__name__`` in the warning); any other ``name`` is an AttributeError.
    """
    if name not in renames:
        raise AttributeError(f"module {module!r} has no attribute {name!r}")
    new = renames[name]
    warnings.warn(
        f"{module}.{name} is now {new.__name__}; the old name goes in the next release",
        DeprecationWarning,
        stacklevel=3,
    )
    return new
