"""A ball screw by its catalogue designation or a short size notation.

Two ways to name a screw instead of typing its geometry:

* a catalogue nut, e.g. ``"HIWIN R40-10K5-FDC"`` or ``"THK BIF4010-5"`` (the
  maker may be left out): looked up in the bundled table
  ``data/catalog_screws.csv``, transcribed from the makers' catalogues with
  the catalogue and page of every row (:func:`catalog_screws`);
* the size notation of the trade, in millimetres: ``"40x10 double 2.5x2
  6.35"`` = nominal diameter x lead, nut arrangement, loaded turns x
  circuits, ball diameter (:func:`parse_size`). The numbers of this notation
  are millimetres by definition, as in every catalogue; nothing else in the
  package takes a length without its unit.

:func:`resolve` turns either into the geometry of a
:class:`~ballscrew.geometry.BallScrew` (SI), the dynamic load rating where
the catalogue prints one, and notes on every value that was not printed.
"""

from __future__ import annotations

import csv
import difflib
import functools
import re
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

from ..errors import BallScrewInputError
from ..geometry import NUT_ARRANGEMENTS

__all__ = ["CatalogScrew", "ResolvedDesignation", "catalog_screws", "parse_size", "resolve"]


@dataclass(frozen=True)
class CatalogScrew:
    """One nut of the bundled catalogue table (lengths in m, forces in N).

    ``pitch_diameter`` is the ball centre diameter where the catalogue prints
    it, else None; ``ball_diameter`` and ``loaded_turns`` are None where not
    printed; ``turns_status`` says whether the turns were printed, derived
    from the recirculation type, or assumed.
    """

    maker: str
    designation: str
    nut: str
    nominal_diameter: float
    pitch_diameter: float | None
    lead: float
    ball_diameter: float | None
    circuits: int
    loaded_turns: float | None
    turns_status: str
    dynamic_load_rating: float | None
    static_load_rating: float | None
    source: str
    page: str
    notes: str

    @property
    def name(self) -> str:
        """Maker and designation, e.g. ``"HIWIN R40-10K5-FDC"``."""
        return f"{self.maker} {self.designation}"


def _mm(text: str) -> float | None:
    return float(text) * 1e-3 if text.strip() else None


@functools.cache
def catalog_screws() -> tuple[CatalogScrew, ...]:
    """The bundled catalogue nuts, in the order of the data file."""
    text = resources.files("ballscrew").joinpath("data/catalog_screws.csv").read_text("utf-8")
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    out = []
    for row in csv.DictReader(lines):
        out.append(
            CatalogScrew(
                maker=row["maker"],
                designation=row["designation"],
                nut=row["nut"],
                nominal_diameter=float(row["nominal_diameter_mm"]) * 1e-3,
                pitch_diameter=_mm(row["pitch_diameter_mm"]),
                lead=float(row["lead_mm"]) * 1e-3,
                ball_diameter=_mm(row["ball_diameter_mm"]),
                circuits=int(row["circuits"]),
                loaded_turns=float(row["turns_per_circuit"]) if row["turns_per_circuit"] else None,
                turns_status=row["turns_status"],
                dynamic_load_rating=float(row["dynamic_load_rating_N"])
                if row["dynamic_load_rating_N"]
                else None,
                static_load_rating=float(row["static_load_rating_N"])
                if row["static_load_rating_N"]
                else None,
                source=row["source"],
                page=row["page"],
                notes=row["notes"],
            )
        )
    return tuple(out)


def _key(text: str) -> str:
    return re.sub(r"\s+", " ", text.strip()).upper()


def find(designation: str) -> CatalogScrew:
    """The catalogue nut named ``designation`` (maker optional, case ignored)."""
    wanted = _key(designation)
    for screw in catalog_screws():
        if wanted in (_key(screw.name), _key(screw.designation)):
            return screw
    names = [s.name for s in catalog_screws()]
    close = difflib.get_close_matches(designation.strip(), names, n=3, cutoff=0.5)
    hint = f"; closest: {', '.join(close)}" if close else ""
    raise BallScrewInputError(
        "designation",
        designation,
        "a bundled catalogue nut (ballscrew screws lists them) or a size such as "
        f"'40x10 double 2.5x2 6.35' (mm){hint}",
    )


MAX_DESIGNATION = 200
"""The longest designation read [characters] (a catalogue part number is about 30)."""

_NUMBER = r"(\d+(?:\.\d+)?)"
_SIZE = re.compile(
    rf"^\s*{_NUMBER}\s*[xX×]\s*{_NUMBER}"  # nominal diameter x lead
    r"(?:\s+(?P<nut>[a-z0-9-]+))?"  # nut arrangement
    rf"(?:\s+(?P<turns>\d+(?:\.\d+)?)\s*[xX×]\s*(?P<circuits>\d+))?"  # turns x circuits
    rf"(?:\s+(?P<ball>\d+(?:\.\d+)?))?\s*(?:mm)?\s*$"  # ball diameter
)


def _bounded(text: str) -> str:
    """``text`` with each run of blanks as one space, refused past :data:`MAX_DESIGNATION`.

    The size pattern's optional parts, each led by blanks, backtrack over a long run of
    them (100 kB of spaces held a request for minutes); one blank each keeps it linear.
    """
    if len(text) > MAX_DESIGNATION:
        shown = f"{text[:20]}... ({len(text)} characters)"
        raise BallScrewInputError("designation", shown, f"at most {MAX_DESIGNATION} characters")
    return " ".join(text.split())


def parse_size(text: str) -> dict[str, Any]:
    """Geometry from the size notation ``"d x lead [nut] [turns x circuits] [ball]"`` (mm).

    Examples
    --------
    >>> g = parse_size("40x10 double 2.5x2 6.35")
    >>> round(g["pitch_diameter"], 6), round(g["lead"], 6), g["nut"], g["circuits"]
    (0.04, 0.01, 'double', 2)
    >>> parse_size("25x5")["lead"]
    0.005
    """
    match = _SIZE.match(_bounded(text))
    if not match:
        raise BallScrewInputError(
            "designation",
            text,
            "'d x lead [nut] [turns x circuits] [ball]' in mm, e.g. '40x10 double 2.5x2 6.35'",
        )
    out: dict[str, Any] = {
        "pitch_diameter": float(match.group(1)) * 1e-3,
        "lead": float(match.group(2)) * 1e-3,
    }
    nut = match.group("nut")
    if nut is not None:
        if nut not in NUT_ARRANGEMENTS:
            raise BallScrewInputError("designation", text, f"a nut among {list(NUT_ARRANGEMENTS)}")
        out["nut"] = nut
    if match.group("turns") is not None:
        out["loaded_turns"] = float(match.group("turns"))
        out["circuits"] = int(match.group("circuits"))
    if match.group("ball") is not None:
        out["ball_diameter"] = float(match.group("ball")) * 1e-3
    return out


@dataclass(frozen=True)
class ResolvedDesignation:
    """What a designation gives: BallScrew keyword values (SI), load ratings and notes."""

    geometry: dict[str, Any]
    dynamic_load_rating: float | None = None
    notes: dict[str, str] = field(default_factory=dict)
    source: str = ""
    static_load_rating: float | None = None


def resolve(designation: str) -> ResolvedDesignation:
    """Geometry, dynamic load rating and notes of a catalogue nut or a size notation.

    ``notes`` maps a BallScrew field to why its value was not printed (the
    pitch diameter taken as the nominal one, assumed turns per circuit).

    Examples
    --------
    >>> r = resolve("HIWIN R40-10K5-FDC")
    >>> r.geometry["ball_diameter"], r.geometry["circuits"], r.dynamic_load_rating
    (0.00635, 5, 63400.0)
    """
    if _SIZE.match(_bounded(designation)):
        return ResolvedDesignation(parse_size(designation), source="size notation (mm)")
    screw = find(designation)
    geometry: dict[str, Any] = {
        "pitch_diameter": screw.pitch_diameter or screw.nominal_diameter,
        "lead": screw.lead,
        "circuits": screw.circuits,
        "nut": screw.nut,
    }
    notes: dict[str, str] = {}
    if screw.pitch_diameter is None:
        notes["pitch_diameter"] = (
            "the catalogue prints no ball centre diameter: the nominal diameter is used "
            "(they differ by about 1 mm)"
        )
    if screw.ball_diameter is not None:
        geometry["ball_diameter"] = screw.ball_diameter
    if screw.loaded_turns is not None:
        geometry["loaded_turns"] = screw.loaded_turns
        if not screw.turns_status.startswith("read"):
            notes["loaded_turns"] = screw.turns_status
    source = f"{screw.source}, {screw.page}" + (f" ({screw.notes})" if screw.notes else "")
    return ResolvedDesignation(
        geometry, screw.dynamic_load_rating, notes, source, screw.static_load_rating
    )
