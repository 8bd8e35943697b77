"""The candidates of a selection: catalogue nut x preload class x nut kind x oil.

Each candidate is the user's case with its ``[screw]`` (and, when an oil is
chosen, its ``[lubricant]``) replaced, kept as the case file's text, so that
any one of them can be written out and checked alone with ``ballscrew check``
and give the same numbers.

Preload classes are shares of the dynamic load rating C_a. The makers cap the
preload at 10 % of C_a (THK General Catalog, ball screw technical description,
"maximum preload"); within that the package takes three classes: light 3 %
(the 2 to 5 % a light 4-point preload is sold at), medium 5 % and heavy 8 %.
They are this package's round choices inside the makers' range, not one
maker's table: give the shares you buy with ``preload_shares``.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from ..errors import BallScrewInputError
from ..io.designation import CatalogScrew, catalog_screws

__all__ = ["PRELOAD_CLASSES", "Candidate", "candidates", "case_text"]

PRELOAD_CLASSES: dict[str, float] = {"none": 0.0, "light": 0.03, "medium": 0.05, "heavy": 0.08}
"""Preload classes as shares of C_a (module docstring; "none": a single nut with play)."""

DEFAULT_PRELOADS: tuple[str, ...] = ("light", "medium", "heavy")
"""The classes a selection tries unless told otherwise."""

_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\"' -]+?)\s*\]\]?\s*(#.*)?$")
_CARRIED = ("contact_angle", "ball_separation")


@dataclass(frozen=True)
class Candidate:
    """One screw to try: a catalogue nut, its nut kind, preload class and oil.

    ``text`` is the whole case file of the candidate (TOML).
    """

    row: CatalogScrew
    nut: str
    preload_class: str
    preload_share: float
    oil: str
    text: str

    @property
    def name(self) -> str:
        """E.g. ``"HIWIN R32-10K5-FSC single-4point light, PAO ISO VG 68"``."""
        return f"{self.row.name} {self.nut} {self.preload_class}, {self.oil}"


def _sections(text: str) -> list[tuple[str, list[str]]]:
    """The case file's lines grouped by table header ("" for the lines before the first)."""
    out: list[tuple[str, list[str]]] = [("", [])]
    for line in text.splitlines():
        match = _HEADER.match(line)
        if match and not line.lstrip().startswith("#"):
            out.append((match.group(1).strip().strip("\"'"), [line]))
        else:
            out[-1][1].append(line)
    return out


def _carried(lines: list[str]) -> list[str]:
    """The lines of the old ``[screw]`` that describe no catalogue value (contact angle)."""
    return [line for line in lines[1:] if line.split("=")[0].strip() in _CARRIED]


def case_text(text: str, row: CatalogScrew, nut: str, share: float, oil: str | None) -> str:
    """``text`` (a case file) with its screw replaced by ``row`` as ``nut`` at ``share`` of C_a.

    With ``oil``, the ``[lubricant]`` table is replaced by that named lubricant.
    """
    kept: list[str] = []
    carried: list[str] = []
    for name, lines in _sections(text):
        top = name.split(".")[0]
        if top == "screw":
            carried += _carried(lines) if name == "screw" else []
            continue
        if top == "lubricant" and oil is not None:
            continue
        kept += lines
    screw = ["[screw]", f'designation = "{row.name}"', f'nut = "{nut}"']
    if nut != "single":
        screw.append(f'preload_share = "{share * 100:g} %"')
    else:
        screw.append('preload = "0 N"')
    screw += carried
    extra = ["", *screw]
    if oil is not None:
        extra += ["", "[lubricant]", f'name = "{oil}"']
    return "\n".join(kept).rstrip("\n") + "\n" + "\n".join(extra) + "\n"


def _kinds(row: CatalogScrew, preload: str) -> list[str]:
    """The nut kinds a catalogue row allows at a preload class."""
    if row.nut == "double":
        return [] if preload == "none" else ["double"]
    return ["single"] if preload == "none" else ["single-4point"]


def _inside(value: float, bounds: tuple[float, float] | None) -> bool:
    return bounds is None or bounds[0] * (1 - 1e-9) <= value <= bounds[1] * (1 + 1e-9)


def rows(
    diameter: tuple[float, float] | None = None,
    lead: tuple[float, float] | None = None,
    makers: Sequence[str] = (),
) -> list[CatalogScrew]:
    """The catalogue rows inside the diameter and lead ranges [m] from the makers given."""
    wanted = {m.upper() for m in makers}
    return [
        r
        for r in catalog_screws()
        if _inside(r.nominal_diameter, diameter)
        and _inside(r.lead, lead)
        and (not wanted or r.maker.upper() in wanted)
        and r.dynamic_load_rating is not None
    ]


def candidates(
    text: str,
    *,
    diameter: tuple[float, float] | None = None,
    lead: tuple[float, float] | None = None,
    makers: Sequence[str] = (),
    preloads: Sequence[str] = DEFAULT_PRELOADS,
    oils: Sequence[str | None] = (None,),
    default_oil: str = "",
) -> list[Candidate]:
    """Every candidate of the filters on the case file ``text`` (module docstring).

    Raises :class:`~ballscrew.errors.BallScrewInputError` for an unknown
    preload class or maker, and when no catalogue row passes the filters
    (naming the closest rows).
    """
    for p in preloads:
        if p not in PRELOAD_CLASSES:
            raise BallScrewInputError("--preload", p, f"one of {', '.join(PRELOAD_CLASSES)}")
    known = sorted({r.maker for r in catalog_screws()})
    for m in makers:
        if m.upper() not in {k.upper() for k in known}:
            raise BallScrewInputError("--maker", m, f"one of {', '.join(known)}")
    found = rows(diameter, lead, makers)
    if not found:
        raise BallScrewInputError(
            "--diameter/--lead/--maker",
            _shown(diameter, lead, makers),
            "filters some catalogue row passes; closest: " + _closest(diameter, lead),
        )
    out = []
    for row in found:
        for p in preloads:
            for nut in _kinds(row, p):
                for oil in oils:
                    new = case_text(text, row, nut, PRELOAD_CLASSES[p], oil)
                    out.append(Candidate(row, nut, p, PRELOAD_CLASSES[p], oil or default_oil, new))
    if not out:
        raise BallScrewInputError(
            "--preload", ", ".join(preloads),
            "a class the rows allow ('none' needs a single nut): "
            + ", ".join(f"{r.name} ({r.nut})" for r in found[:3]),
        )  # fmt: skip
    return out


def _shown(
    diameter: tuple[float, float] | None, lead: tuple[float, float] | None, makers: Sequence[str]
) -> str:
    parts = []
    for name, b in (("diameter", diameter), ("lead", lead)):
        if b is not None:
            parts.append(f"{name} {b[0] * 1e3:g}..{b[1] * 1e3:g} mm")
    if makers:
        parts.append("maker " + ", ".join(makers))
    return "; ".join(parts) or "(none)"


def _gap(value: float, bounds: tuple[float, float] | None) -> float:
    if bounds is None:
        return 0.0
    low, high = bounds
    return max(low - value, value - high, 0.0) / max(high, 1e-9)


def _closest(diameter: tuple[float, float] | None, lead: tuple[float, float] | None) -> str:
    ranked = sorted(
        catalog_screws(),
        key=lambda r: _gap(r.nominal_diameter, diameter) + _gap(r.lead, lead),
    )
    return ", ".join(
        f"{r.name} ({r.nominal_diameter * 1e3:g} x {r.lead * 1e3:g} mm)" for r in ranked[:3]
    )
