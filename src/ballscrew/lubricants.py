"""The bundled lubricant library.

The data live in ``data/lubricants.csv`` (units in the column names), one row
per oil or grease, each stating its source or that its numbers are typical
values. A grease is described by its base oil (viscosities, density,
pressure-viscosity) with its thickener, NLGI grade and base oil type; pour and
flash points are given where a data sheet gives them. :func:`get` returns a
:class:`~ballscrew.lubricant.Lubricant` by name, :func:`greases` the greases.

Examples
--------
>>> from ballscrew import lubricants
>>> oil = lubricants.get("PAO ISO VG 68")
>>> round(oil.nu40 * 1e6, 1)
68.0
>>> "SAE 20" in lubricants.names()
True
>>> grease = lubricants.get("SKF LGHP 2")
>>> grease.kind, grease.thickener, grease.nlgi_grade, round(grease.nu40 * 1e6, 1)
('grease', 'polyurea', '2-3', 96.0)
"""

from __future__ import annotations

import csv
import functools
from importlib import resources

from .errors import BallScrewInputError
from .lubricant import Lubricant

__all__ = ["all_lubricants", "get", "greases", "names"]

_COLUMNS = {
    "name": ("name", str, 1.0),
    "nu40_mm2_per_s": ("nu40", float, 1e-6),
    "nu100_mm2_per_s": ("nu100", float, 1e-6),
    "density15_kg_per_m3": ("density15", float, 1.0),
    "pressure_viscosity_per_GPa": ("pressure_viscosity", float, 1e-9),
    "limiting_shear_stress_MPa": ("limiting_shear_stress", float, 1e6),
    "limiting_shear_coefficient": ("limiting_shear_coefficient", float, 1.0),
    "source": ("source", str, 1.0),
}
"""Columns every row fills: field of :class:`~ballscrew.lubricant.Lubricant`, type, scale to SI."""

_OPTIONAL = {
    "kind": ("kind", str),
    "thickener": ("thickener", str),
    "nlgi_grade": ("nlgi_grade", str),
    "base_oil": ("base_oil", str),
    "pour_point_degC": ("pour_point", float),
    "flash_point_degC": ("flash_point", float),
}
"""Columns a row may leave empty (an oil, or a value its data sheet does not give)."""


def _key(name: str) -> str:
    return " ".join(name.lower().split())


@functools.cache
def _library() -> dict[str, Lubricant]:
    text = resources.files("ballscrew").joinpath("data/lubricants.csv").read_text("utf-8")
    rows = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    result: dict[str, Lubricant] = {}
    for row in csv.DictReader(rows):
        kwargs: dict[str, object] = {}
        for column, (field, kind, scale) in _COLUMNS.items():
            raw = row[column].strip()
            kwargs[field] = raw if kind is str else float(raw) * scale
        for column, (field, kind) in _OPTIONAL.items():
            raw = (row.get(column) or "").strip()
            if raw:
                kwargs[field] = raw if kind is str else float(raw)
        oil = Lubricant(**kwargs)  # type: ignore[arg-type]
        result[_key(oil.name)] = oil
    return result


def names() -> list[str]:
    """Names of the bundled lubricants."""
    return [oil.name for oil in _library().values()]


def all_lubricants() -> list[Lubricant]:
    """All bundled lubricants, in the order of the data file."""
    return list(_library().values())


def greases() -> list[Lubricant]:
    """The bundled greases (``kind == "grease"``), in the order of the data file."""
    return [oil for oil in _library().values() if oil.kind == "grease"]


def get(name: str) -> Lubricant:
    """A bundled lubricant by name (case and extra spaces are ignored).

    Raises
    ------
    BallScrewInputError
        If no bundled lubricant has that name; the message lists the names.
    """
    try:
        return _library()[_key(str(name))]
    except KeyError:
        raise BallScrewInputError("lubricant", name, f"one of {names()}") from None
