"""The fields a sweep may vary: their owners, units and checks, and how one point applies them.

A field is ``speed``, ``temperature`` or ``axial_load`` (the operating points),
``screw.KEY`` or ``lubricant.KEY`` (a case key), or ``MODEL.PARAMETER``.
:func:`field_unit` says where a field lives and its SI unit; :func:`resolve`
builds the screw, lubricant and model parameters of one point;
:func:`check_value` builds them at once for a single value, so that a bad
one is named while the sweep file is read.
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping, Sequence
from typing import Any

from .. import lubricants
from ..errors import BallScrewInputError
from ..friction import MODELS
from ..geometry import NUT_ARRANGEMENTS, BallScrew
from ..io.case import LUBRICANT_UNITS, SCREW_UNITS, Case
from ..lubricant import Lubricant

__all__ = ["DERIVED", "OPERATING", "check_value", "field_unit", "hint", "resolve", "unknown_keys"]

OPERATING: dict[str, str] = {"speed": "rad/s", "temperature": "degC", "axial_load": "N"}
"""The operating-point axes and their units: broadcast in one friction call per chunk."""

DERIVED: dict[str, str] = {
    "lubricant.viscosity_scale": "factor on the data-sheet viscosities nu40 and nu100",
}
"""Sweep-only fields that are not case keys, with what they do."""

_CASE_FIELDS: dict[str, dict[str, str]] = {
    "screw": {"preload": "N", "nut": "-", **SCREW_UNITS},
    "lubricant": {"name": "-", "viscosity_scale": "", **LUBRICANT_UNITS},
}
"""The case keys a sweep may vary and their SI units ("-": text values)."""


def field_unit(name: str, models: Sequence[str], where: str = "") -> tuple[str, str | None]:
    """Where a varied field lives (``screw``, ``lubricant`` or a model) and its SI unit.

    The unit is None for a model parameter (numbers in SI, or quantities
    converted to SI base units) and ``"-"`` for a field of text values.
    ``where`` names the key in errors (default: ``axes.NAME``).
    """
    where = where or f"axes.{name}"
    owner, _, key = name.partition(".")
    if owner in _CASE_FIELDS:
        units = _CASE_FIELDS[owner]
        if key in units:
            return owner, units[key]
        allowed = list(units)
    elif owner in MODELS:
        if owner not in models:
            raise BallScrewInputError(
                where, name, f"a parameter of a model in models ({list(models)})"
            )
        if key in MODELS[owner].parameters:
            return owner, None
        allowed = sorted(MODELS[owner].parameters)
    else:
        raise BallScrewInputError(
            where,
            name,
            "speed, temperature, axial_load, screw.KEY, lubricant.KEY or MODEL.PARAMETER "
            f"(models: {sorted(MODELS)})",
        )
    raise BallScrewInputError(
        where,
        name,
        f"one of {', '.join(f'{owner}.{k}' for k in allowed)}{hint(key, allowed, owner)}",
    )


def hint(key: str, allowed: Sequence[str], prefix: str = "") -> str:
    """'; did you mean X?' for a misspelt or shortened key, else ''."""
    close = difflib.get_close_matches(key, list(allowed), n=1)
    close = close or [k for k in allowed if key and k.startswith(key)][:1]
    dotted = f"{prefix}." if prefix else ""
    return f"; did you mean {dotted}{close[0]}?" if close else ""


def resolve(
    case: Case, model: str, parameters: Mapping[str, Any], point: Mapping[str, Any]
) -> tuple[BallScrew, Lubricant, dict[str, Any]]:
    """The screw, lubricant and model parameters at one outer point.

    ``point`` maps field names (``screw.preload``, ``lubricant.name``,
    ``complete.ball_train_constant``) to SI values; a model parameter of
    another model than ``model`` is ignored.
    """
    screw_changes: dict[str, Any] = {}
    lub_changes: dict[str, Any] = {}
    params = dict(parameters)
    lubricant = case.lubricant
    scale = 1.0
    for name, value in point.items():
        owner, _, key = name.partition(".")
        if owner == "screw":
            screw_changes[key] = int(value) if key == "circuits" else value
        elif owner == "lubricant":
            if key == "name":
                lubricant = lubricants.get(str(value))
            elif key == "viscosity_scale":
                scale = float(value)
            else:
                lub_changes[key] = value
        elif owner == model:
            params[key] = value
    try:
        screw = case.screw.replace(**screw_changes) if screw_changes else case.screw
    except BallScrewInputError as exc:
        raise BallScrewInputError(f"screw.{exc.field}", exc.value, exc.allowed) from None
    if scale != 1.0:
        lub_changes.setdefault("nu40", lubricant.nu40)
        lub_changes.setdefault("nu100", lubricant.nu100)
        lub_changes["nu40"] *= scale
        lub_changes["nu100"] *= scale
    try:
        lubricant = lubricant.replace(**lub_changes) if lub_changes else lubricant
    except BallScrewInputError as exc:
        raise BallScrewInputError(f"lubricant.{exc.field}", exc.value, exc.allowed) from None
    return screw, lubricant, params


def check_value(case: Case, models: Sequence[str], where: str, name: str, value: Any) -> None:
    """Build the screw and lubricant with one value, so that a bad one is named now."""
    try:
        resolve(case, models[0], {}, {name: value})
    except BallScrewInputError as exc:
        raise BallScrewInputError(where, value, exc.allowed) from None
    if name == "screw.circuits" and value != int(value):
        raise BallScrewInputError(where, value, "a whole number >= 1")
    if name == "screw.nut" and value not in NUT_ARRANGEMENTS:
        raise BallScrewInputError(where, value, f"one of {list(NUT_ARRANGEMENTS)}")


def unknown_keys(where: str, given: Mapping[str, Any], allowed: Sequence[str]) -> None:
    """Refuse a key of ``given`` that is not ``allowed``, with the likely intended one."""
    for key in given:
        if key not in allowed:
            raise BallScrewInputError(
                f"{where}{key}", given[key], f"one of the keys {list(allowed)}{hint(key, allowed)}"
            )
