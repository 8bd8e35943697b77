"""The bundled lubricant library.

The data live in ``data/lubricants.csv`` (units in the column names), one row
per oil, each stating its source or that its numbers are typical values.
:func:`get` returns a :class:`~ballscrew.lubricant.Lubricant` by name.

Examples
--------
>>> from ballscrew import lubricants
>>> oil = lubricants.get("PAO ISO VG 68")
>>> round(oil.nu40 * 1e6, 1)
68.0
>>> "SAE 20" in lubricants.names()
True
"""

from __future__ import annotations

import csv
import functools
from importlib import resources

from .errors import BallScrewInputError
from .lubricant import Lubricant

__all__ = ["all_lubricants", "get", "names"]

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
        oil = Lubricant(**kwargs)  # type: ignore[arg-type]
        result[_key(oil.name)] = oil
    return result


def names() -> list[str]:
    """Names of the bundled lubricants."""
    return [oil.name for oil in _library().values()]


def all_lubricants() -> list[Lubricant]:
    """All bundled lubricants, in the order of the data file."""
    return list(_library().values())


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
